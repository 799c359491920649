//! `hscene fmt`: the canonical layout (`hscene_lang::format`) applied to
//! files in place, checked (`--check`), or from stdin to stdout (`-`).
//!
//! A file is written the way `render` writes an output (hrender's
//! `replace_file`): atomically and signal-safely, through a symbolic link
//! to the file it names, keeping permissions and owner; a FIFO or device is
//! refused before it is read; a read-only, hard-linked or another user's
//! file only with `--force`; and a file that changed on disk while it was
//! being formatted (an editor saving) is left as it is now.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::cli::{ColorChoice, FmtArgs, Format};
use crate::exit::{EXIT_SCENE_ERRORS, EXIT_USAGE_OR_IO};
use crate::report;

/// What became of one file.
enum Outcome {
    /// Already in the canonical layout.
    Unchanged,
    /// Reformatted (or, with `--check`, would be).
    Changed,
    /// Syntax errors (reported); left alone.
    SyntaxErrors,
    /// Could not be read or written (reported).
    Io,
}

pub fn run(args: &FmtArgs, color: ColorChoice) -> ExitCode {
    let mut worst = ExitCode::SUCCESS;
    let mut unformatted = false;
    let mut errors = false;
    for path in &args.scenes {
        let outcome = if path == Path::new("-") {
            let name = args
                .stdin_filename
                .clone()
                .unwrap_or_else(|| PathBuf::from("<stdin>"));
            stdin(&name, args.check, color)
        } else {
            file(path, args, color)
        };
        match outcome {
            Outcome::Unchanged => {}
            Outcome::Changed => unformatted |= args.check,
            Outcome::SyntaxErrors => errors = true,
            Outcome::Io => worst = ExitCode::from(EXIT_USAGE_OR_IO),
        }
    }
    if worst != ExitCode::SUCCESS {
        worst
    } else if errors || unformatted {
        ExitCode::from(EXIT_SCENE_ERRORS)
    } else {
        ExitCode::SUCCESS
    }
}

/// Formats, or reports the syntax errors that prevent it on stderr.
fn formatted(name: &Path, source: &str, color: ColorChoice) -> Option<String> {
    match hscene_lang::format(source) {
        Ok(text) => Some(text),
        Err(hscene_lang::FormatError::Syntax(diagnostics)) => {
            let tty = std::io::stderr().is_terminal();
            let format = if tty { Format::Human } else { Format::Short };
            diag!(
                "{}",
                report::format_diagnostics(
                    name,
                    source,
                    &diagnostics,
                    Default::default(),
                    format,
                    color.enabled(tty)
                )
            );
            diagln!(
                "error: {} not formatted: it has syntax errors",
                name.display()
            );
            None
        }
    }
}

fn stdin(name: &Path, check: bool, color: ColorChoice) -> Outcome {
    // Bounded and decoded as `check` reads scenes (docs/limits.md).
    let source = match crate::input::read_scene(Path::new("-")) {
        Ok(s) => s,
        Err(e) => {
            diagln!("error: cannot read stdin: {e}");
            return Outcome::Io;
        }
    };
    let Some(text) = formatted(name, &source, color) else {
        return Outcome::SyntaxErrors;
    };
    if check {
        return if text == source {
            Outcome::Unchanged
        } else {
            Outcome::Changed
        };
    }
    if std::io::stdout().write_all(text.as_bytes()).is_err() {
        return Outcome::Io;
    }
    if text == source {
        Outcome::Unchanged
    } else {
        Outcome::Changed
    }
}

fn file(path: &Path, args: &FmtArgs, color: ColorChoice) -> Outcome {
    let fail = |e: &dyn std::fmt::Display| {
        diagln!("error: {e}");
        Outcome::Io
    };
    // Links are followed: the file they name is formatted, the link stays.
    let target = hrender::output_target(path);
    match std::fs::metadata(&target) {
        Ok(m) if !m.is_file() => {
            return fail(&format!(
                "{} is not a regular file; format a stream with `hscene fmt -`",
                path.display()
            ));
        }
        Ok(_) => {}
        Err(e) => return fail(&format!("cannot read {}: {e}", path.display())),
    }
    let stamp = match hrender::FileStamp::of(&target) {
        Ok(s) => s,
        Err(e) => return fail(&format!("cannot read {}: {e}", path.display())),
    };
    let source = match crate::input::read_scene(&target) {
        Ok(s) => s,
        Err(e) => return fail(&format!("cannot read {}: {e}", path.display())),
    };
    let Some(text) = formatted(path, &source, color) else {
        return Outcome::SyntaxErrors;
    };
    if text == source {
        return Outcome::Unchanged;
    }
    if args.check {
        outln!("would reformat {}", path.display());
        return Outcome::Changed;
    }
    let overwrite = if args.force {
        hrender::Overwrite::Force
    } else {
        hrender::Overwrite::Writable
    };
    if let Err(e) = hrender::check_output_file(&target, &[], overwrite) {
        return fail(&e);
    }
    let written = hrender::replace_file(&target, Some(&stamp), |out| {
        out.write_all(text.as_bytes())
            .map_err(|source| hrender::RenderError::Io {
                path: path.to_path_buf(),
                source,
            })
    });
    match written {
        Ok(()) => {
            diagln!("formatted {}", path.display());
            Outcome::Changed
        }
        Err(e) => fail(&e),
    }
}
