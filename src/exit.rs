//! How a command ends: the exit statuses, and the one write to stdout of
//! the commands that print a single text. A leaf: every command uses it,
//! and it uses none of them.

use std::io::Write;
use std::process::ExitCode;

/// Exit status: the scene has errors.
pub const EXIT_SCENE_ERRORS: u8 = 1;
/// Exit status: usage or I/O error.
pub const EXIT_USAGE_OR_IO: u8 = 2;

/// Writes to stdout; a reader that stops early (`| head`) is not an error.
pub fn print_bytes(bytes: &[u8]) -> ExitCode {
    match std::io::stdout().lock().write_all(bytes) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(_) => ExitCode::from(EXIT_USAGE_OR_IO),
    }
}

/// Writes a diagnostic to stderr, ignoring a failure: `diag!` panics
/// when stderr cannot be written (`2>/dev/full`, `ulimit -f` with stderr
/// in a file), which would end a render for the sake of a warning.
pub fn to_stderr(args: std::fmt::Arguments) {
    let _ = std::io::stderr().lock().write_fmt(args);
}

/// Writes a line of a command's report to stdout, ignoring a failure (as
/// [`to_stderr`] does).
pub fn to_stdout(args: std::fmt::Arguments) {
    let _ = std::io::stdout().lock().write_fmt(args);
}
