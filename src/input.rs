//! Reading scene files: bounded, decoded, and with errors in the format the
//! user asked for.

use std::io::Read;
use std::path::Path;

use crate::cli::Format;

/// Largest scene file read, in bytes (16 MiB): thousands of times the
/// largest real scene, small enough to index and report on at once.
pub const MAX_SCENE_BYTES: u64 = 16 << 20;

/// Why a scene file could not be read.
#[derive(Debug)]
pub enum InputError {
    Io(std::io::Error),
    TooLarge,
    NotUtf8(hscene_lang::source::InvalidUtf8),
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            InputError::Io(e) => write!(f, "{e}"),
            InputError::TooLarge => write!(
                f,
                "the file is larger than the limit of {MAX_SCENE_BYTES} bytes"
            ),
            InputError::NotUtf8(e) => write!(f, "{e}"),
        }
    }
}

/// Reads at most [`MAX_SCENE_BYTES`] (a device or a pipe may never end) and
/// decodes them as scene text (BOM skipped, any line ends). The path `-`
/// is standard input.
pub fn read_scene(path: &Path) -> Result<String, InputError> {
    if path == Path::new("-") {
        return read_bounded(std::io::stdin().lock());
    }
    read_bounded(open(path).map_err(InputError::Io)?)
}

/// Opens `path` for reading without waiting: opening a FIFO blocks until a
/// writer opens it too, which may never happen. Opened non-blocking, a FIFO
/// with no writer reads as empty; one with a writer (`check <(cmd)`) is
/// then read as usual, blocking until the writer is done.
#[cfg(unix)]
fn open(path: &Path) -> std::io::Result<std::fs::File> {
    use std::os::fd::AsRawFd;
    use std::os::unix::fs::OpenOptionsExt;
    let file = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)?;
    // SAFETY: fcntl on a descriptor this function owns, with flags read
    // from it; no memory is passed.
    unsafe {
        let flags = libc::fcntl(file.as_raw_fd(), libc::F_GETFL);
        if flags >= 0 {
            libc::fcntl(file.as_raw_fd(), libc::F_SETFL, flags & !libc::O_NONBLOCK);
        }
    }
    Ok(file)
}

#[cfg(not(unix))]
fn open(path: &Path) -> std::io::Result<std::fs::File> {
    std::fs::File::open(path)
}

fn read_bounded(input: impl Read) -> Result<String, InputError> {
    let mut bytes = Vec::new();
    input
        .take(MAX_SCENE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(InputError::Io)?;
    if bytes.len() as u64 > MAX_SCENE_BYTES {
        return Err(InputError::TooLarge);
    }
    // The text is kept for the whole run (messages quote it); reading grew
    // the buffer by doubling, up to twice its length.
    bytes.shrink_to_fit();
    hscene_lang::source::decode(bytes).map_err(InputError::NotUtf8)
}

/// The message for a scene that cannot be read, as one line of the chosen
/// format (JSON objects carry `"severity": "error"` and no position).
pub fn describe_failure(path: &Path, error: &InputError, format: Format) -> String {
    let message = format!("cannot read {}: {error}", path.display());
    match format {
        Format::Json => {
            let mut obj = serde_json::json!({
                "file": path.display().to_string(),
                "severity": "error",
                "message": message,
            });
            if let InputError::NotUtf8(e) = error {
                obj["byte_offset"] = e.offset.into();
            }
            format!("{obj}\n")
        }
        Format::Human | Format::Short => format!("error: {message}\n"),
    }
}

/// Mesh, image and space files are found relative to the scene file.
pub fn compile_options(scene: &Path, frame: u32) -> hscene_lang::Options {
    hscene_lang::Options {
        base_dir: scene.parent().map(Path::to_path_buf),
        frame,
        ..Default::default()
    }
}

/// [`compile_options`] sharing `files`: an animation's frames compile
/// against the meshes and images read for its first, which a pinned cache
/// keeps whatever happens to the files meanwhile.
pub fn compile_options_sharing(
    scene: &Path,
    frame: u32,
    files: &hscene_lang::FileCache,
) -> hscene_lang::Options {
    hscene_lang::Options {
        files: files.clone(),
        ..compile_options(scene, frame)
    }
}

/// [`read_scene`], its failure already worded in `format`.
pub fn read_scene_reported(path: &Path, format: Format) -> Result<String, String> {
    read_scene(path).map_err(|e| describe_failure(path, &e, format))
}
