//! The signals that end hscene cleanly: the temporary outputs are removed
//! (and an ffmpeg encoder is stopped and waited for first, since it would
//! otherwise create its file again) before the process exits with status
//! 128 + the signal's number (130 for Ctrl-C).
//!
//! Covered: SIGINT (Ctrl-C), SIGTERM (`kill`, `timeout`), SIGHUP (the
//! terminal closed), SIGALRM (`alarm`), SIGUSR1 and SIGUSR2 (whose default
//! is to end the process), SIGXCPU (`ulimit -t`: sent at the soft limit; a
//! hard limit reached too is SIGKILL, which no process can catch). Not
//! covered: SIGKILL and SIGSTOP (uncatchable), SIGQUIT (kept for a core
//! dump), SIGXFSZ (ignored in `main`, so a write past `ulimit -f` fails as
//! an ordinary error), SIGPIPE (ignored by Rust's runtime).
//!
//! The handler only writes the signal's number to a pipe; a thread of its
//! own reads it and does the cleanup, which takes locks and waits for a
//! child, neither of which a signal handler may do.

use std::sync::atomic::{AtomicI32, Ordering};

/// The signals covered (module docs).
#[cfg(unix)]
pub const CLEANED_UP: [libc::c_int; 7] = [
    libc::SIGINT,
    libc::SIGTERM,
    libc::SIGHUP,
    libc::SIGALRM,
    libc::SIGUSR1,
    libc::SIGUSR2,
    libc::SIGXCPU,
];

/// The pipe's writing end, for the handler.
static PIPE_WRITE: AtomicI32 = AtomicI32::new(-1);

#[cfg(unix)]
extern "C" fn on_signal(signal: libc::c_int) {
    let fd = PIPE_WRITE.load(Ordering::Relaxed);
    let byte = u8::try_from(signal).unwrap_or(u8::MAX);
    // SAFETY: write(2) is async-signal-safe; a full pipe (a flood of
    // signals) loses the extra ones, and one is enough.
    unsafe {
        libc::write(fd, (&raw const byte).cast(), 1);
    }
}

/// Installs the cleanup for the covered signals. Called once, first thing
/// in `main`; if the pipe or thread cannot be had, the signals keep their
/// default action.
#[cfg(unix)]
pub fn clean_up_on_signals() {
    let mut fds = [0 as libc::c_int; 2];
    // SAFETY: pipe2 fills the two descriptors it is given.
    if unsafe { libc::pipe2(fds.as_mut_ptr(), libc::O_CLOEXEC) } != 0 {
        return;
    }
    let read_end = fds[0];
    let started = std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            let mut byte = 0u8;
            loop {
                // SAFETY: reading one byte into a local.
                let n = unsafe { libc::read(read_end, (&raw mut byte).cast(), 1) };
                if n == 1 {
                    break;
                }
                if n == 0 {
                    return;
                }
            }
            hrender::remove_unfinished_outputs();
            std::process::exit(128 + i32::from(byte));
        });
    if started.is_err() {
        return;
    }
    PIPE_WRITE.store(fds[1], Ordering::Relaxed);
    for signal in CLEANED_UP {
        // SAFETY: a zeroed sigaction with a handler that only writes to a
        // pipe; SA_RESTART so that reads and writes elsewhere go on.
        unsafe {
            let mut action: libc::sigaction = std::mem::zeroed();
            action.sa_sigaction = on_signal as *const () as libc::sighandler_t;
            action.sa_flags = libc::SA_RESTART;
            libc::sigemptyset(&mut action.sa_mask);
            libc::sigaction(signal, &action, std::ptr::null_mut());
        }
    }
}

#[cfg(not(unix))]
pub fn clean_up_on_signals() {}
