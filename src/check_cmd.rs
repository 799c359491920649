//! `hscene check`: lint scenes for editors and CI, and emit their IR.

use std::io::{IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;

use crate::cli::{CheckArgs, ColorChoice, Emit, Format};
use crate::exit::{EXIT_SCENE_ERRORS, EXIT_USAGE_OR_IO};
use crate::frames::frame_past_end;
use crate::input::{compile_options, read_scene_reported as read_scene};
use crate::{emit, report};

pub fn run(args: &CheckArgs, color: ColorChoice) -> ExitCode {
    // With `--emit ir` stdout carries only JSON; the diagnostics go to stderr.
    let emit_ir = args.emit == Some(Emit::Ir);
    let diag_tty = if emit_ir {
        std::io::stderr().is_terminal()
    } else {
        std::io::stdout().is_terminal()
    };
    // The full report (with every `help:`) whether or not the output is a
    // terminal, as rustc and ruff do; only colour depends on the terminal.
    let format = args.format.unwrap_or(Format::Human);
    let mut any_errors = false;
    let mut io_failure = false;
    let mut out = std::io::stdout().lock();
    for path in &args.scenes {
        let read = read_scene(path, format);
        // A scene from stdin takes the name (and mesh directory) given for it.
        let stdin_name = Path::new("<stdin>");
        let path = if path == Path::new("-") {
            args.stdin_filename.as_deref().unwrap_or(stdin_name)
        } else {
            path
        };
        let source = match read {
            Ok(s) => s,
            Err(message) => {
                report_failure(&mut out, format, emit_ir, &message);
                io_failure = true;
                continue;
            }
        };
        let compiled = hscene_lang::compile_with(&source, &compile_options(path, args.frame));
        any_errors |=
            compiled.has_errors() || (args.deny_warnings && !compiled.diagnostics.is_empty());
        // The same rule as `render --frame`: no frame past the last.
        if let Some(scene) = &compiled.scene
            && args.frame >= scene.settings.frames
        {
            let message = frame_past_end(args.frame, scene.settings.frames);
            let message = match format {
                Format::Json => format!(
                    "{}\n",
                    serde_json::json!({"file": path.display().to_string(), "severity": "error", "message": message})
                ),
                Format::Human | Format::Short => format!("error: {message}\n"),
            };
            report_failure(&mut out, format, emit_ir, &message);
            io_failure = true;
            continue;
        }
        let text = report::format_diagnostics(
            path,
            &source,
            &compiled.diagnostics,
            compiled.omitted,
            format,
            color.enabled(diag_tty),
        );
        if emit_ir {
            diag!("{text}");
            // A scene with errors has no IR (`compiled.scene` is `None`).
            if let Some(scene) = &compiled.scene
                && emit::write_scene_json(&mut out, path, scene).is_err()
            {
                return ExitCode::from(EXIT_USAGE_OR_IO);
            }
        } else if out.write_all(text.as_bytes()).is_err() {
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    }
    if io_failure {
        ExitCode::from(EXIT_USAGE_OR_IO)
    } else if any_errors {
        ExitCode::from(EXIT_SCENE_ERRORS)
    } else {
        ExitCode::SUCCESS
    }
}

/// A failure of `check` that is not a diagnostic (an unreadable file, a
/// frame past the end). Machine-readable output stays on the stream it is
/// read from: JSON goes to stdout unless stdout carries the IR.
fn report_failure(out: &mut impl Write, format: Format, emit_ir: bool, message: &str) {
    if format == Format::Json && !emit_ir {
        let _ = out.write_all(message.as_bytes());
    } else {
        diag!("{message}");
    }
}
