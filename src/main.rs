//! The `hscene` command: glue between the scene language, the renderer and
//! the terminal. Only this crate knows about clap, JSON and terminals.

mod cli;
mod emit;
mod report;

use std::io::{IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use hrender::{RenderOptions, SampleDepth};
use hscene_lang::ir::{Net, Resolution};

use cli::{CheckArgs, Cli, Command, Depth, Emit, Format, RenderArgs};

/// Exit status: the scene has errors.
const EXIT_SCENE_ERRORS: u8 = 1;
/// Exit status: usage or I/O error.
const EXIT_USAGE_OR_IO: u8 = 2;

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Render(args) => render(&args),
        Command::Check(args) => check(&args),
    }
}

fn read_scene(path: &Path) -> Result<String, ExitCode> {
    std::fs::read_to_string(path).map_err(|e| {
        eprintln!("error: cannot read {}: {e}", path.display());
        ExitCode::from(EXIT_USAGE_OR_IO)
    })
}

fn check(args: &CheckArgs) -> ExitCode {
    // With `--emit ir` stdout carries only JSON; the diagnostics go to stderr.
    let emit_ir = args.emit == Some(Emit::Ir);
    let diag_tty = if emit_ir {
        std::io::stderr().is_terminal()
    } else {
        std::io::stdout().is_terminal()
    };
    let format = args.format.unwrap_or(if diag_tty {
        Format::Human
    } else {
        Format::Short
    });
    let mut any_errors = false;
    let mut io_failure = false;
    let mut out = std::io::stdout().lock();
    for path in &args.scenes {
        let source = match read_scene(path) {
            Ok(s) => s,
            Err(_) => {
                io_failure = true;
                continue;
            }
        };
        let compiled = hscene_lang::compile(&source);
        any_errors |= compiled.has_errors();
        let text =
            report::format_diagnostics(path, &source, &compiled.diagnostics, format, diag_tty);
        if emit_ir {
            eprint!("{text}");
            // A scene with errors has no IR (`compiled.scene` is `None`).
            if let Some(scene) = &compiled.scene {
                let line = format!("{}\n", emit::scene_to_json(path, scene));
                if out.write_all(line.as_bytes()).is_err() {
                    return ExitCode::from(EXIT_USAGE_OR_IO);
                }
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

fn render(args: &RenderArgs) -> ExitCode {
    let source = match read_scene(&args.scene) {
        Ok(s) => s,
        Err(code) => return code,
    };
    // Refuse a bad output name before spending time on the render.
    if let Err(e) = hrender::ImageFormat::from_path(&args.output) {
        eprintln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    let stderr_tty = std::io::stderr().is_terminal();
    let compiled = hscene_lang::compile(&source);
    if !compiled.diagnostics.is_empty() {
        let format = if stderr_tty {
            Format::Human
        } else {
            Format::Short
        };
        eprint!(
            "{}",
            report::format_diagnostics(
                &args.scene,
                &source,
                &compiled.diagnostics,
                format,
                stderr_tty
            )
        );
    }
    let Some(scene) = compiled.scene else {
        return ExitCode::from(EXIT_SCENE_ERRORS);
    };
    let options = RenderOptions {
        net: args.net.and_then(|n| Net::from_index(u64::from(n))),
        resolution: args
            .resolution
            .map(|(width, height)| Resolution { width, height }),
        threads: args.threads,
        samples: args.samples,
        seed: args.seed,
        exposure: args.exposure,
    };
    let height = options
        .resolution
        .unwrap_or(scene.settings.resolution)
        .height;
    let bar = stderr_tty.then(|| {
        let bar = indicatif::ProgressBar::new(u64::from(height));
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} rendering [{bar:40}] {pos}/{len} rows, {eta} left",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        bar
    });
    let started = Instant::now();
    let progress = |rows: u32| {
        if let Some(bar) = &bar {
            bar.set_position(u64::from(rows));
        }
    };
    let rendered = match hrender::render(&scene, &options, &progress) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            // Geometry the renderer cannot represent is a problem of the scene.
            let scene_problem = matches!(
                e,
                hrender::RenderError::OutOfRange { .. } | hrender::RenderError::DegenerateCamera
            );
            return ExitCode::from(if scene_problem {
                EXIT_SCENE_ERRORS
            } else {
                EXIT_USAGE_OR_IO
            });
        }
    };
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let depth = match args.depth {
        Depth::Eight => SampleDepth::Eight,
        Depth::Sixteen => SampleDepth::Sixteen,
        Depth::Float32 => SampleDepth::Float32,
    };
    if let Err(e) = hrender::write_image(&rendered.image, &args.output, depth) {
        eprintln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    if rendered.stats.numeric_failures > 0 {
        eprintln!(
            "warning: {} pixel(s) had a numeric failure; their failing rays show the background",
            rendered.stats.numeric_failures
        );
    }
    if stderr_tty {
        let secs = started.elapsed().as_secs_f64();
        eprintln!(
            "wrote {} ({}x{}, {} rays in {secs:.2} s)",
            args.output.display(),
            rendered.image.width(),
            rendered.image.height(),
            rendered.stats.rays
        );
    }
    ExitCode::SUCCESS
}
