//! The `hscene` command: glue between the scene language, the renderer and
//! the terminal. Only this crate knows about clap, JSON and terminals.

// Declared first, so that every module sees its macros.
#[macro_use]
mod print;

mod allocator;
mod check_cmd;
mod cli;
mod emit;
mod exit;
mod explain;
mod export_cmd;
mod fmt_cmd;
mod frames;
mod input;
mod lsp;
mod render_cmd;
mod report;
mod signals;
mod view_cmd;

use std::process::ExitCode;

use clap::Parser;
use cli::{Cli, Command};
use exit::{EXIT_USAGE_OR_IO, print_bytes};

#[global_allocator]
static ALLOCATOR: allocator::Allocator = allocator::Allocator;

fn main() -> ExitCode {
    allocator::share_one_arena();
    ignore_file_size_signal();
    // An interrupted command leaves no temporary file behind.
    signals::clean_up_on_signals();
    let cli = Cli::parse();
    let color = cli.color;
    match cli.command {
        Command::Render(args) => render_cmd::run(&args, color),
        Command::Check(args) => check_cmd::run(&args, color),
        Command::Export(args) => export_cmd::run(&args, color),
        Command::View(args) => view_cmd::run(&args, color),
        Command::Fmt(args) => fmt_cmd::run(&args, color),
        Command::Lsp => lsp::run(),
        Command::Explain { code } => explain::run(&code),
        Command::Completions { shell } => {
            // Generated into memory: clap_complete panics on a write error
            // (`| head` closing the pipe).
            let mut script = Vec::new();
            let mut cmd = <Cli as clap::CommandFactory>::command();
            clap_complete::generate(shell, &mut cmd, "hscene", &mut script);
            print_bytes(&script)
        }
        Command::Man => {
            let mut page = Vec::new();
            let man = clap_mangen::Man::new(<Cli as clap::CommandFactory>::command());
            match man.render(&mut page) {
                Ok(()) => print_bytes(&page),
                Err(_) => ExitCode::from(EXIT_USAGE_OR_IO),
            }
        }
    }
}

/// A write past the file-size limit (`ulimit -f`) raises SIGXFSZ, whose
/// default action kills the process before it can remove its temporary
/// file. Ignored, the write fails with `EFBIG` instead, an I/O error like
/// any other: reported, and the temporary file removed.
fn ignore_file_size_signal() {
    #[cfg(unix)]
    // SAFETY: setting a signal's disposition to SIG_IGN runs no handler
    // code; done first, before any thread starts.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
}
