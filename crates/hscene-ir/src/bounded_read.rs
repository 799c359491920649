//! Reading a file a scene or a command names (an image, a space's
//! pairings, a viewer's flight path) without trusting it: it must be a regular file (a FIFO is never opened, as
//! opening one for reading blocks until a writer comes), and no more than
//! a limit is ever read, even from a file that grows while it is read.

use std::io::Read;
use std::path::Path;

/// Why a named file was not read.
#[derive(Debug)]
pub enum BoundedReadError {
    /// Not a regular file.
    NotAFile,
    /// Larger than the limit (its size, or what was read past it).
    TooLarge(u64),
    /// Reading failed.
    Io(std::io::Error),
}

impl From<std::io::Error> for BoundedReadError {
    fn from(e: std::io::Error) -> BoundedReadError {
        BoundedReadError::Io(e)
    }
}

/// The bytes of the regular file at `path`, at most `max` of them.
pub fn read_regular_file(path: &Path, max: u64) -> Result<Vec<u8>, BoundedReadError> {
    let meta = std::fs::metadata(path)?;
    if !meta.is_file() {
        return Err(BoundedReadError::NotAFile);
    }
    if meta.len() > max {
        return Err(BoundedReadError::TooLarge(meta.len()));
    }
    let file = std::fs::File::open(path)?;
    if !file.metadata()?.is_file() {
        return Err(BoundedReadError::NotAFile);
    }
    let mut bytes = Vec::new();
    file.take(max + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > max {
        return Err(BoundedReadError::TooLarge(bytes.len() as u64));
    }
    Ok(bytes)
}
