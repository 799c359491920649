//! The temporary files of outputs being written, so that an interrupted
//! process (Ctrl-C, SIGTERM) can remove them before it exits: a temporary
//! file's own cleanup runs on drop, which a signal skips.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// A list of temporary files now being written.
pub(crate) struct Registry(Mutex<Vec<PathBuf>>);

/// The process's temporary outputs.
pub(crate) static LIVE: Registry = Registry(Mutex::new(Vec::new()));

impl Registry {
    fn list(&self) -> MutexGuard<'_, Vec<PathBuf>> {
        // A panic elsewhere must not stop the cleanup: the list stays valid.
        self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Lists `path` until the returned guard is dropped or finished.
    pub(crate) fn register(&self, path: &Path) -> Registered<'_> {
        self.list().push(path.to_path_buf());
        Registered {
            registry: self,
            path: path.to_path_buf(),
        }
    }

    fn remove_all(&self) {
        for path in self.list().drain(..) {
            let _ = std::fs::remove_file(path);
        }
    }
}

/// Removes every temporary file of an output being written. Meant for a
/// signal handler (run on an ordinary thread, as the `ctrlc` crate does),
/// followed by the process's exit; an output renamed into place is final
/// and no longer listed.
pub fn remove_unfinished_outputs() {
    LIVE.remove_all();
}

/// A listed temporary file; dropping it takes it off the list.
pub(crate) struct Registered<'r> {
    registry: &'r Registry,
    path: PathBuf,
}

impl Registered<'_> {
    /// Runs the final rename with the list locked, so that a cleanup never
    /// sees a file half-way between temporary and final.
    pub(crate) fn finish<T>(self, rename: impl FnOnce() -> T) -> T {
        let mut list = self.registry.list();
        let result = rename();
        list.retain(|p| *p != self.path);
        result
    }
}

impl Drop for Registered<'_> {
    fn drop(&mut self) {
        self.registry.list().retain(|p| *p != self.path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cleanup_removes_listed_files_only() {
        let registry = Registry(Mutex::new(Vec::new()));
        let dir = tempfile::tempdir().unwrap();
        let a = dir.path().join("a.part");
        std::fs::write(&a, b"x").unwrap();
        let reg = registry.register(&a);
        registry.remove_all();
        assert!(!a.exists());
        drop(reg);
        let b = dir.path().join("b.part");
        std::fs::write(&b, b"x").unwrap();
        registry.register(&b).finish(|| ());
        registry.remove_all();
        assert!(b.exists());
        assert!(registry.list().is_empty());
    }
}
