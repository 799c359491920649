//! `hscene view`: a live window onto a scene. The camera flies by exact
//! isometries (`pose`), each view is refined by the renderer itself
//! (`progressive`: a coarse frame, then full-resolution passes that average
//! to what `hscene render --samples N` gives), shown through winit and
//! softbuffer (`window`), or driven by a recorded path without a window
//! (`headless`). The window renders on worker threads (`worker`), so it
//! answers keys at once whatever renders. The scene comes from the caller,
//! which recompiles it when its file changes (`SceneSource`).

/// `eprint!` that never panics: a message that cannot be written (stderr
/// closed, on a full disk) is dropped and the viewer goes on.
macro_rules! diag {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = std::io::stderr().lock().write_fmt(format_args!($($arg)*));
    }};
}

/// `eprintln!` that never panics (see [`diag!`]).
macro_rules! diagln {
    ($($arg:tt)*) => {
        diag!("{}\n", format_args!($($arg)*))
    };
}

mod headless;
mod keys;
mod pose;
mod progressive;
mod window;
mod worker;

pub use headless::{
    FlightError, FlightPath, HeadlessReport, MAX_FLIGHT_FILE_BYTES, MAX_FLIGHT_MOVES, run_headless,
};
pub use keys::{Action, action_for_key};
pub use pose::{Axis, Move, Pose, camera_lines};
pub use progressive::{Frame, Progressive, ViewOptions};
pub use window::{ViewError, run_window};

/// Where the viewer gets its scene and learns of changes.
pub trait SceneSource {
    /// The scene now, compiled; `Err` carries the diagnostics as `check`
    /// prints them.
    fn load(&mut self) -> Result<hscene_ir::Scene, String>;

    /// True if the scene's file (or what it reads) changed since the last
    /// `load`.
    fn changed(&mut self) -> bool;

    /// A name for the window title.
    fn name(&self) -> String;
}
