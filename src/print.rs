//! Printing that never panics: `diag!`/`diagln!` for stderr and `outln!`
//! for stdout, through `exit::to_stderr`/`to_stdout`, which drop what
//! cannot be written (a full disk, `ulimit -f`, a closed pipe) so that the
//! work a message is about goes on.

/// `eprint!` that never panics: a diagnostic that cannot be written
/// (stderr on a full disk, past `ulimit -f`, closed) is dropped, and the
/// work it was about goes on.
macro_rules! diag {
    ($($arg:tt)*) => {
        $crate::exit::to_stderr(format_args!($($arg)*))
    };
}

/// `eprintln!` that never panics (see [`diag!`]).
macro_rules! diagln {
    () => {
        $crate::exit::to_stderr(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::exit::to_stderr(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// `println!` that never panics: a report to a closed or full stdout is
/// lost, not the work (`print_bytes` treats whole-text outputs).
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::exit::to_stdout(format_args!("{}\n", format_args!($($arg)*)))
    };
}
