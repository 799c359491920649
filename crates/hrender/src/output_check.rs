//! Everything about an output that can be known before rendering, checked
//! before rendering: a render of hours must not end in "cannot write".
//!
//! The rules (stated for users in `docs/limits.md` and `docs/rendering.md`):
//! the extension names a format we write, in the sample depth asked for; the
//! output is not one of the inputs (same device and inode, so links count);
//! an existing output is a regular file, and one that is read-only is
//! replaced only when the caller forces it; and a file can be created in
//! the output's directory (tried, not guessed from permission bits).

use std::path::Path;

use crate::error::RenderError;
use crate::output::{ImageFormat, SampleDepth, check_depth, output_dir, output_target};

/// Whether an existing read-only output may be replaced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overwrite {
    /// Refuse a read-only output.
    Writable,
    /// Replace it anyway (`--force`).
    Force,
}

/// Checks that `path` can receive an image of `depth`, and that it is none
/// of `inputs`. Nothing is written: a probe file is created in the
/// directory and removed at once.
pub fn check_output(
    path: &Path,
    depth: SampleDepth,
    inputs: &[&Path],
    overwrite: Overwrite,
) -> Result<ImageFormat, RenderError> {
    let format = ImageFormat::from_path(path)?;
    check_depth(format, depth)?;
    check_output_file(path, inputs, overwrite)?;
    Ok(format)
}

/// The longest file name (one component of a path) the usual file systems
/// hold, in bytes (ext4, XFS, Btrfs, APFS, NTFS: 255).
pub const MAX_FILE_NAME_BYTES: usize = 255;

/// The checks of [`check_output`] that hold for any file, whatever its
/// format: a file name the file system holds, not an input, a regular file
/// if it exists, one this process may replace (not read-only, not hard
/// linked elsewhere, not another user's, unless forced; never where a
/// sticky directory forbids it), and a directory a file can be created in.
pub fn check_output_file(
    path: &Path,
    inputs: &[&Path],
    overwrite: Overwrite,
) -> Result<(), RenderError> {
    let target = output_target(path);
    for name in [path, target.as_path()] {
        let bytes = name.file_name().map_or(0, |n| n.as_encoded_bytes().len());
        if bytes > MAX_FILE_NAME_BYTES {
            return Err(RenderError::OutputNameTooLong {
                path: path.to_path_buf(),
                bytes,
            });
        }
    }
    if inputs.iter().any(|input| same_file(path, input)) {
        return Err(RenderError::OutputIsInput(path.to_path_buf()));
    }
    if let Ok(existing) = std::fs::metadata(&target) {
        if !existing.is_file() {
            return Err(RenderError::OutputNotAFile(path.to_path_buf()));
        }
        if existing.permissions().readonly() && overwrite == Overwrite::Writable {
            return Err(RenderError::ReadOnlyOutput(path.to_path_buf()));
        }
        replaceable(path, &target, &existing, overwrite)?;
    }
    let dir_error = |source| RenderError::OutputDirectory {
        path: path.to_path_buf(),
        source,
    };
    let dir = output_dir(&target);
    if !std::fs::metadata(dir).map_err(dir_error)?.is_dir() {
        return Err(dir_error(std::io::ErrorKind::NotADirectory.into()));
    }
    // The probe's own name must not appear in the message: keep the kind.
    // It is listed like an output's temporary file, so that a signal while
    // it exists removes it too.
    let (probe, listed) = crate::unfinished::LIVE
        .create(|| {
            tempfile::Builder::new()
                .prefix(".hscene-probe-")
                .tempfile_in(dir)
        })
        .map_err(|e| dir_error(e.kind().into()))?;
    drop(probe);
    drop(listed);
    Ok(())
}

/// An output is replaced by renaming a new file over it: the new file has
/// one link and belongs to this process's user. Refused unless forced: a
/// file with other hard links (they would keep the old content) or
/// another user's (it would become ours). Refused always: another user's
/// file in a sticky directory this user does not own (the rename fails).
#[cfg(unix)]
fn replaceable(
    path: &Path,
    target: &Path,
    existing: &std::fs::Metadata,
    overwrite: Overwrite,
) -> Result<(), RenderError> {
    use std::os::unix::fs::MetadataExt;
    // SAFETY: geteuid has no preconditions and cannot fail.
    let me = unsafe { libc::geteuid() };
    let theirs = me != 0 && existing.uid() != me;
    if theirs
        && let Ok(dir) = std::fs::metadata(output_dir(target))
        && dir.mode() & 0o1000 != 0
        && dir.uid() != me
    {
        return Err(RenderError::OutputInStickyDirectory(path.to_path_buf()));
    }
    if overwrite == Overwrite::Force {
        return Ok(());
    }
    if existing.nlink() > 1 {
        return Err(RenderError::OutputHardLinked {
            path: path.to_path_buf(),
            links: existing.nlink(),
        });
    }
    if theirs {
        return Err(RenderError::OutputOwnedByOther(path.to_path_buf()));
    }
    Ok(())
}

#[cfg(not(unix))]
fn replaceable(_: &Path, _: &Path, _: &std::fs::Metadata, _: Overwrite) -> Result<(), RenderError> {
    Ok(())
}

/// Whether two paths name the same file (after following links).
#[cfg(unix)]
fn same_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

#[cfg(not(unix))]
fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_input_is_never_an_output_even_through_a_link() {
        let dir = tempfile::tempdir().unwrap();
        let scene = dir.path().join("s.png");
        std::fs::write(&scene, b"Points {}").unwrap();
        let err = check_output(&scene, SampleDepth::Eight, &[&scene], Overwrite::Force);
        assert!(matches!(err, Err(RenderError::OutputIsInput(_))), "{err:?}");
        #[cfg(unix)]
        {
            let link = dir.path().join("l.png");
            std::os::unix::fs::symlink(&scene, &link).unwrap();
            let err = check_output(&link, SampleDepth::Eight, &[&scene], Overwrite::Force);
            assert!(matches!(err, Err(RenderError::OutputIsInput(_))), "{err:?}");
        }
    }

    #[test]
    fn late_problems_are_found_early() {
        let dir = tempfile::tempdir().unwrap();
        let png = dir.path().join("a.png");
        assert!(matches!(
            check_output(&png, SampleDepth::Float32, &[], Overwrite::Writable),
            Err(RenderError::UnsupportedDepth { .. })
        ));
        let missing = dir.path().join("no/such/dir/a.png");
        assert!(matches!(
            check_output(&missing, SampleDepth::Eight, &[], Overwrite::Writable),
            Err(RenderError::OutputDirectory { .. })
        ));
        let sub = dir.path().join("d.png");
        std::fs::create_dir(&sub).unwrap();
        assert!(matches!(
            check_output(&sub, SampleDepth::Eight, &[], Overwrite::Writable),
            Err(RenderError::OutputNotAFile(_))
        ));
        assert!(check_output(&png, SampleDepth::Sixteen, &[], Overwrite::Writable).is_ok());
        // The probe leaves nothing behind.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn a_read_only_output_needs_force() {
        let dir = tempfile::tempdir().unwrap();
        let png = dir.path().join("keep.png");
        std::fs::write(&png, b"old").unwrap();
        let mut perms = std::fs::metadata(&png).unwrap().permissions();
        perms.set_readonly(true);
        std::fs::set_permissions(&png, perms).unwrap();
        assert!(matches!(
            check_output(&png, SampleDepth::Eight, &[], Overwrite::Writable),
            Err(RenderError::ReadOnlyOutput(_))
        ));
        assert!(check_output(&png, SampleDepth::Eight, &[], Overwrite::Force).is_ok());
    }
}
