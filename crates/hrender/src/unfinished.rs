//! The temporary files of outputs being written, so that an interrupted
//! process (Ctrl-C, SIGTERM) can remove them before it exits: a temporary
//! file's own cleanup runs on drop, which a signal skips.

use std::path::PathBuf;
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
    #[cfg(test)]
    pub(crate) fn register(&self, path: &std::path::Path) -> Registered<'_> {
        self.list().push(path.to_path_buf());
        Registered {
            registry: self,
            path: path.to_path_buf(),
        }
    }

    /// Creates a temporary file and lists it with the list locked, so that
    /// a cleanup runs either before the file exists or after it is listed:
    /// a signal can never land between the two.
    pub(crate) fn create(
        &self,
        create: impl FnOnce() -> std::io::Result<tempfile::NamedTempFile>,
    ) -> std::io::Result<(tempfile::NamedTempFile, Registered<'_>)> {
        let mut list = self.list();
        let file = create()?;
        list.push(file.path().to_path_buf());
        let path = file.path().to_path_buf();
        Ok((
            file,
            Registered {
                registry: self,
                path,
            },
        ))
    }

    /// Removes every listed file; the list stays locked while the guard
    /// lives.
    fn remove_all(&self) -> MutexGuard<'_, Vec<PathBuf>> {
        let mut list = self.list();
        for path in list.drain(..) {
            let _ = std::fs::remove_file(path);
        }
        list
    }
}

/// Removes every temporary file of an output being written. Meant for a
/// signal handler (run on an ordinary thread, as the binary's `signals` module does),
/// followed by the process's exit; an output renamed into place is final
/// and no longer listed.
pub fn remove_unfinished_outputs() {
    // Encoders first: ffmpeg opens its output only when the first frame
    // arrives, so one still running could create the file after it was
    // removed. Both lists stay locked for good: the process exits next,
    // and nothing new can start between this cleanup and the exit.
    std::mem::forget(stop_children());
    std::mem::forget(LIVE.remove_all());
}

/// The encoders (ffmpeg) now running, by process id.
static CHILDREN: Mutex<Vec<u32>> = Mutex::new(Vec::new());

fn children() -> MutexGuard<'static, Vec<u32>> {
    CHILDREN.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Kills every listed encoder and waits for it to end.
fn stop_children() -> MutexGuard<'static, Vec<u32>> {
    let mut list = children();
    for pid in list.drain(..) {
        kill_and_reap(pid);
    }
    list
}

#[cfg(unix)]
fn kill_and_reap(pid: u32) {
    let Ok(pid) = libc::pid_t::try_from(pid) else {
        return;
    };
    // SAFETY: the process is our own child, listed until it has been
    // waited for (`ListedChild::done` runs before it is reaped), so the id
    // cannot name another process.
    unsafe {
        libc::kill(pid, libc::SIGKILL);
        libc::waitpid(pid, std::ptr::null_mut(), 0);
    }
}

#[cfg(not(unix))]
fn kill_and_reap(_: u32) {}

/// Spawns `cmd` and lists the child with the list locked, so that a
/// cleanup either runs before the child exists or stops it.
pub(crate) fn spawn_listed(
    cmd: &mut std::process::Command,
) -> std::io::Result<(std::process::Child, ListedChild)> {
    let mut list = children();
    let child = cmd.spawn()?;
    list.push(child.id());
    let pid = child.id();
    Ok((child, ListedChild { pid: Some(pid) }))
}

/// A listed child process.
pub(crate) struct ListedChild {
    pid: Option<u32>,
}

impl ListedChild {
    /// Waits until the child has ended, without reaping it, and takes it
    /// off the list: from then on a cleanup leaves it (and its id) alone,
    /// and the owner reaps it.
    pub(crate) fn done(&mut self) {
        let Some(pid) = self.pid.take() else {
            return;
        };
        wait_without_reaping(pid);
        children().retain(|p| *p != pid);
    }
}

#[cfg(unix)]
fn wait_without_reaping(pid: u32) {
    let id: libc::id_t = pid;
    // SAFETY: a zeroed siginfo_t is a valid out-parameter; WNOWAIT leaves
    // the child to be reaped by its `Child`.
    unsafe {
        let mut info: libc::siginfo_t = std::mem::zeroed();
        while libc::waitid(libc::P_PID, id, &mut info, libc::WEXITED | libc::WNOWAIT) != 0 {
            if std::io::Error::last_os_error().kind() != std::io::ErrorKind::Interrupted {
                break;
            }
        }
    }
}

#[cfg(not(unix))]
fn wait_without_reaping(_: u32) {}

/// [`remove_unfinished_outputs`] for a process that is out of memory and
/// about to exit: it does nothing when the list is locked (the allocation
/// that failed may be the one adding to it, on this very thread, and
/// waiting would never end). Returns whether the cleanup ran.
pub fn try_remove_unfinished_outputs() -> bool {
    let mut list = match LIVE.0.try_lock() {
        Ok(list) => list,
        Err(std::sync::TryLockError::Poisoned(e)) => e.into_inner(),
        Err(std::sync::TryLockError::WouldBlock) => return false,
    };
    if let Ok(mut pids) = CHILDREN.try_lock() {
        for pid in pids.drain(..) {
            kill_and_reap(pid);
        }
        std::mem::forget(pids);
    }
    for path in list.drain(..) {
        let _ = std::fs::remove_file(path);
    }
    std::mem::forget(list);
    true
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
        drop(registry.remove_all());
        assert!(!a.exists());
        drop(reg);
        let b = dir.path().join("b.part");
        std::fs::write(&b, b"x").unwrap();
        registry.register(&b).finish(|| ());
        drop(registry.remove_all());
        assert!(b.exists());
        assert!(registry.list().is_empty());
    }

    #[test]
    fn created_files_are_listed_until_dropped() {
        let registry = Registry(Mutex::new(Vec::new()));
        let dir = tempfile::tempdir().unwrap();
        let (file, reg) = registry
            .create(|| tempfile::Builder::new().tempfile_in(dir.path()))
            .unwrap();
        let path = file.path().to_path_buf();
        assert_eq!(*registry.list(), vec![path.clone()]);
        drop(registry.remove_all());
        assert!(!path.exists());
        drop(reg);
        drop(file);
        assert!(registry.list().is_empty());
    }
}
