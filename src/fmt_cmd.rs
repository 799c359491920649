//! `hscene fmt`: the canonical layout (`hscene_lang::format`) applied to
//! files in place, checked (`--check`), or from stdin to stdout (`-`).

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
            file(path, args.check, color)
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
            eprint!(
                "{}",
                report::format_diagnostics(name, source, &diagnostics, format, color.enabled(tty))
            );
            eprintln!(
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
            eprintln!("error: cannot read stdin: {e}");
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

fn file(path: &Path, check: bool, color: ColorChoice) -> Outcome {
    let source = match crate::input::read_scene(path) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: cannot read {}: {e}", path.display());
            return Outcome::Io;
        }
    };
    let Some(text) = formatted(path, &source, color) else {
        return Outcome::SyntaxErrors;
    };
    if text == source {
        return Outcome::Unchanged;
    }
    if check {
        println!("would reformat {}", path.display());
        return Outcome::Changed;
    }
    match write_atomically(path, &text) {
        Ok(()) => {
            eprintln!("formatted {}", path.display());
            Outcome::Changed
        }
        Err(e) => {
            eprintln!("error: cannot write {}: {e}", path.display());
            Outcome::Io
        }
    }
}

/// Writes a temporary file beside `path` and renames it over `path`, so a
/// failure leaves the original whole. The original's permissions are kept.
fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::NamedTempFile::new_in(dir)?;
    tmp.write_all(text.as_bytes())?;
    tmp.as_file().sync_all()?;
    if let Ok(meta) = std::fs::metadata(path) {
        tmp.as_file().set_permissions(meta.permissions())?;
    }
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}
