//! Rendering from Python: the keyword overrides as `hrender::RenderOptions`
//! (the same fields `hscene render`'s flags set), and a render that
//! releases the GIL and stops on Ctrl-C.
//!
//! Why a thread of its own: Python delivers SIGINT by setting a flag that
//! only the main thread, holding the GIL, turns into `KeyboardInterrupt`.
//! The render runs on its own thread (and rayon's pool, every core) with
//! the GIL released; the calling thread waits in slices of
//! [`POLL`], taking the GIL between them to ask `check_signals`. On an
//! interrupt it sets the render's cancel flag (`hrender::
//! render_region_cancellable`), waits for the workers to finish the pixels
//! they are on, and raises the `KeyboardInterrupt`.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{RecvTimeoutError, channel};
use std::sync::{Arc, Mutex, PoisonError, mpsc};
use std::time::Duration;

use hrender::{Aov, AovLayers, Exposure, RenderError, RenderOptions, Rendered};
use hscene_ir::{IntegratorKind, Net, Resolution, Scene};
use pyo3::exceptions::{PyMemoryError, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;

/// How often a waiting render looks for Ctrl-C.
const POLL: Duration = Duration::from_millis(50);

/// The render keywords shared by `Scene.render`, `Scene.picture` and
/// `Scene.save`, as Python gave them.
#[derive(Default)]
pub struct Overrides {
    pub resolution: Option<(i64, i64)>,
    pub samples: Option<i64>,
    pub integrator: Option<String>,
    pub net: Option<i64>,
    pub exposure: Option<ExposureArg>,
    pub seed: u64,
    pub threads: Option<i64>,
}

/// `exposure=`: stops, or `"auto"`.
#[derive(FromPyObject)]
pub enum ExposureArg {
    Stops(f64),
    Word(String),
}

impl Overrides {
    /// The renderer's options, every value checked.
    pub fn options(&self) -> PyResult<RenderOptions> {
        let resolution = match self.resolution {
            None => None,
            Some((w, h)) => {
                let side = |x: i64| u32::try_from(x).ok();
                match (side(w), side(h)) {
                    (Some(w), Some(h))
                        if u64::from(w) * u64::from(h) > hscene_ir::limits::MAX_PIXELS =>
                    {
                        return Err(PyValueError::new_err(format!(
                            "resolution {w} x {h} has more than the {} pixels a picture may have",
                            hscene_ir::limits::MAX_PIXELS
                        )));
                    }
                    (Some(w), Some(h)) => Some(Resolution::new(w, h).ok_or_else(|| {
                        PyValueError::new_err(format!(
                            "resolution must be at least 1 x 1, not {w} x {h}"
                        ))
                    })?),
                    _ => {
                        return Err(PyValueError::new_err(format!(
                            "resolution must be two positive whole numbers, not ({w}, {h})"
                        )));
                    }
                }
            }
        };
        let samples = match self.samples {
            None => None,
            Some(n) => Some(u32::try_from(n).ok().filter(|n| *n >= 1).ok_or_else(|| {
                PyValueError::new_err(format!(
                    "samples must be from 1 to {}, not {n}",
                    hrender::MAX_SAMPLES
                ))
            })?),
        };
        let integrator = match &self.integrator {
            None => None,
            Some(name) => Some(IntegratorKind::from_name(name).ok_or_else(|| {
                PyValueError::new_err(format!(
                    "unknown integrator {name:?}: the integrators are {}",
                    IntegratorKind::names()
                ))
            })?),
        };
        let net =
            match self.net {
                None => None,
                Some(n) => Some(u64::try_from(n).ok().and_then(Net::from_index).ok_or_else(
                    || {
                        PyValueError::new_err(format!(
                            "net must be from 0 to {}, not {n}",
                            Net::ALL.len() - 1
                        ))
                    },
                )?),
            };
        let exposure = match &self.exposure {
            None => Exposure::Stops(0.0),
            Some(ExposureArg::Stops(ev)) => Exposure::Stops(*ev),
            Some(ExposureArg::Word(w)) if w == "auto" => Exposure::Auto,
            Some(ExposureArg::Word(w)) => {
                return Err(PyValueError::new_err(format!(
                    "exposure is a number of stops or \"auto\", not {w:?}"
                )));
            }
        };
        let threads = match self.threads {
            None => None,
            Some(n) => Some(usize::try_from(n).map_err(|_| {
                PyValueError::new_err(format!("threads must be at least 1, not {n}"))
            })?),
        };
        let options = RenderOptions {
            net,
            resolution,
            threads,
            samples,
            seed: self.seed,
            exposure,
            integrator,
            ..RenderOptions::default()
        };
        // The renderer's own checks (sample and exposure ranges), as
        // ValueErrors before any work.
        options.validate().map_err(render_error)?;
        Ok(options)
    }
}

/// The pixel layers named by `aov=`.
pub fn aov_list(names: &[String]) -> PyResult<Vec<Aov>> {
    Aov::parse_list(&names.join(",")).map_err(PyValueError::new_err)
}

/// A render failure as the Python exception that fits it.
pub fn render_error(e: RenderError) -> PyErr {
    match e {
        RenderError::InvalidOption(_)
        | RenderError::UnsupportedFormat(_)
        | RenderError::UnsupportedDepth { .. }
        | RenderError::DegenerateCamera
        | RenderError::OutOfRange { .. } => PyValueError::new_err(e.to_string()),
        RenderError::OutOfMemory { .. } => PyMemoryError::new_err(e.to_string()),
        RenderError::Io { .. }
        | RenderError::OutputIsInput(_)
        | RenderError::ReadOnlyOutput(_)
        | RenderError::OutputNameTooLong { .. } => PyOSError::new_err(e.to_string()),
        _ => PyRuntimeError::new_err(e.to_string()),
    }
}

/// Runs `work` on a thread of its own with the GIL released, looking for
/// Ctrl-C every [`POLL`] (module docs); on one, sets `cancel`, waits for
/// `work` to return and raises the `KeyboardInterrupt`.
fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    cancel: Arc<AtomicBool>,
    work: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    let (tx, rx): (mpsc::Sender<T>, mpsc::Receiver<T>) = channel();
    std::thread::Builder::new()
        .name("hscene-render".into())
        .spawn(move || {
            // The receiver gone (the caller raised) is no error here.
            let _ = tx.send(work());
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start the render thread: {e}")))?;
    // A Receiver is not Sync; behind a mutex it may be waited on from the
    // detached closures below.
    let rx = Mutex::new(rx);
    let wait = |timeout: Option<Duration>| {
        let rx = rx.lock().unwrap_or_else(PoisonError::into_inner);
        match timeout {
            Some(t) => rx.recv_timeout(t),
            None => rx.recv().map_err(|_| RecvTimeoutError::Disconnected),
        }
    };
    loop {
        match py.detach(|| wait(Some(POLL))) {
            Ok(value) => return Ok(value),
            Err(RecvTimeoutError::Timeout) => {
                if let Err(interrupt) = py.check_signals() {
                    cancel.store(true, Ordering::Relaxed);
                    // The workers stop after their current pixels: waiting
                    // for them keeps the cores free for what comes next.
                    let _ = py.detach(|| wait(None));
                    return Err(interrupt);
                }
            }
            // The thread ended without a result: it panicked (a bug; the
            // panic message went to stderr).
            Err(RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "the render failed unexpectedly (a bug in hscene: please report it)",
                ));
            }
        }
    }
}

/// The picture of `scene` with `options`, interruptible by Ctrl-C.
pub fn render(py: Python<'_>, scene: Arc<Scene>, options: RenderOptions) -> PyResult<Rendered> {
    let cancel = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&cancel);
    let result = interruptible(py, cancel, move || {
        hrender::render_region_cancellable(&scene, &options, None, &|_| {}, &flag)
    })?;
    result.map_err(render_error)
}

/// The pixel layers `which` of the picture of `scene`, with the GIL
/// released (one ray a pixel: no cancellation needed).
pub fn render_aovs(
    py: Python<'_>,
    scene: &Scene,
    options: &RenderOptions,
    which: &[Aov],
) -> PyResult<AovLayers> {
    py.detach(|| hrender::render_aovs(scene, options, None, which))
        .map_err(render_error)
}
