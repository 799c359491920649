//! Render errors.

use std::path::PathBuf;

use thiserror::Error;

/// Why a render or an image write failed.
#[derive(Debug, Error)]
pub enum RenderError {
    /// The camera's view and up directions do not define the canonical frame.
    #[error("the camera's view and up directions are degenerate")]
    DegenerateCamera,
    /// Something is too far from the eye for f64 to represent in the
    /// canonical frame.
    #[error("{what} is too far from the eye (beyond distance ~37) to be represented in f64")]
    OutOfRange {
        /// Which object or light.
        what: String,
    },
    /// The scene violates an invariant of the IR (a bug in whatever built it).
    #[error("invalid scene: {0}")]
    InvalidScene(String),
    /// A render option is out of range.
    #[error("invalid render option: {0}")]
    InvalidOption(String),
    /// The output extension is not one we write.
    #[error(
        "unsupported output format `{0}`: use .png, .tif, .tiff or .exr (an animation: also .gif, .apng, .mp4 or .webm)"
    )]
    UnsupportedFormat(String),
    /// The requested sample depth does not exist for the output format.
    #[error("{format} output does not support {depth}")]
    UnsupportedDepth {
        /// Output format.
        format: &'static str,
        /// Requested depth.
        depth: &'static str,
    },
    /// Creating, writing or renaming the output failed.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file being written.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The encoder failed.
    #[error("cannot encode {path}: {message}")]
    Encode {
        /// The file being written.
        path: PathBuf,
        /// Encoder message.
        message: String,
    },
    /// The output names the file being read (also through a link).
    #[error("the output {0} is the input file; choose another output name")]
    OutputIsInput(PathBuf),
    /// The output exists and its permissions forbid writing it.
    #[error("the output {0} exists and is read-only; pass --force to replace it")]
    ReadOnlyOutput(PathBuf),
    /// Memory for a buffer could not be had.
    #[error("cannot allocate {bytes} bytes for {what}: not enough memory")]
    OutOfMemory {
        /// What the memory was for.
        what: &'static str,
        /// How much was asked for.
        bytes: usize,
    },
    /// The output's file name is longer than file systems hold.
    #[error(
        "the output {path} has a file name of {bytes} bytes; file systems hold at most 255: choose a shorter name"
    )]
    OutputNameTooLong {
        /// The output asked for.
        path: PathBuf,
        /// The length of its last component, in bytes.
        bytes: usize,
    },
    /// The output has other hard links, which replacing it would leave
    /// with the old content.
    #[error(
        "the output {path} has {links} hard links; replacing it would split them (the others keep the old content): pass --force to replace it anyway"
    )]
    OutputHardLinked {
        /// The output asked for.
        path: PathBuf,
        /// Its link count.
        links: u64,
    },
    /// The output belongs to another user; replacing it would make it ours.
    #[error(
        "the output {0} belongs to another user; replacing it would make it yours: pass --force to replace it anyway"
    )]
    OutputOwnedByOther(PathBuf),
    /// The output is another user's file in a sticky directory (`/tmp`),
    /// which no one but its owner may replace.
    #[error(
        "the output {0} belongs to another user in a sticky directory (like /tmp), where only its owner may replace it: choose another output name"
    )]
    OutputInStickyDirectory(PathBuf),
    /// The file changed on disk between being read and being replaced
    /// (`hscene fmt` while an editor saves): left as it is now.
    #[error("{0} changed while it was being formatted; it was left as it is now: run again")]
    ChangedMeanwhile(PathBuf),
    /// The output exists and is not a regular file (a directory, a device).
    #[error("the output {0} exists and is not a regular file")]
    OutputNotAFile(PathBuf),
    /// The output's directory does not exist or cannot be written.
    #[error("cannot write into the directory of {path}: {source}")]
    OutputDirectory {
        /// The output asked for.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// Denoising failed or its library is missing.
    #[error(transparent)]
    Denoise(#[from] crate::denoise::DenoiseError),
    /// Building the worker pool failed.
    #[error("cannot start worker threads: {0}")]
    Threads(String),
    /// A video format that needs ffmpeg, without ffmpeg on the `PATH`.
    #[error(
        "writing {0} needs ffmpeg and ffprobe on the PATH (Debian and Ubuntu: apt-get install ffmpeg; \
         macOS: brew install ffmpeg); .gif and .apng need nothing"
    )]
    NoFfmpeg(PathBuf),
    /// ffmpeg refused the video or failed writing it, in its own words.
    #[error("cannot write {path}: ffmpeg failed: {reason}")]
    Ffmpeg {
        /// The output asked for.
        path: PathBuf,
        /// ffmpeg's reason, on one line.
        reason: String,
    },
    /// ffmpeg reported success but its file holds fewer frames than were
    /// sent (a write cut short: a full disk, `ulimit -f`).
    #[error("cannot write {path}: the video ffmpeg wrote holds {counted} of its {frames} frames")]
    VideoIncomplete {
        /// The output asked for.
        path: PathBuf,
        /// Frames sent.
        frames: u32,
        /// Frames ffprobe counts in the file.
        counted: u64,
    },
    /// The caller asked the render to stop (Ctrl-C in Python): no image.
    #[error("the render was cancelled")]
    Cancelled,
}
