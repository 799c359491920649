//! The `hscene` command: glue between the scene language, the renderer and
//! the terminal. Only this crate knows about clap, JSON and terminals.

mod cli;
mod emit;
mod input;
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

/// Mesh files are found relative to the scene file.
fn compile_options(scene: &Path, frame: u32) -> hscene_lang::Options {
    hscene_lang::Options {
        base_dir: scene.parent().map(Path::to_path_buf),
        frame,
    }
}

fn read_scene(path: &Path, format: Format) -> Result<String, String> {
    input::read_scene(path).map_err(|e| input::describe_failure(path, &e, format))
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
        let source = match read_scene(path, format) {
            Ok(s) => s,
            Err(message) => {
                // Machine-readable output stays on the stream it is read from.
                if format == Format::Json && !emit_ir {
                    let _ = out.write_all(message.as_bytes());
                } else {
                    eprint!("{message}");
                }
                io_failure = true;
                continue;
            }
        };
        let compiled = hscene_lang::compile_with(&source, &compile_options(path, args.frame));
        any_errors |= compiled.has_errors();
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
            if format == Format::Json && !emit_ir {
                let _ = out.write_all(message.as_bytes());
            } else {
                eprint!("{message}");
            }
            io_failure = true;
            continue;
        }
        let text =
            report::format_diagnostics(path, &source, &compiled.diagnostics, format, diag_tty);
        if emit_ir {
            eprint!("{text}");
            // A scene with errors has no IR (`compiled.scene` is `None`).
            if let Some(scene) = &compiled.scene {
                if emit::write_scene_json(&mut out, path, scene).is_err() {
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

/// The message for a frame number past the animation's end.
fn frame_past_end(k: u32, frames: u32) -> String {
    format!(
        "--frame {k} is past the scene's last frame ({} of `frames = {frames}`, counted from 0)",
        frames.saturating_sub(1)
    )
}

/// Everything about the outputs is checked before the first ray.
fn check_outputs(args: &RenderArgs, outputs: &[std::path::PathBuf]) -> Result<(), ExitCode> {
    let overwrite = if args.force {
        hrender::Overwrite::Force
    } else {
        hrender::Overwrite::Writable
    };
    for output in outputs {
        if let Err(e) = hrender::check_output(output, depth(args), &[&args.scene], overwrite) {
            eprintln!("error: {e}");
            return Err(ExitCode::from(EXIT_USAGE_OR_IO));
        }
    }
    Ok(())
}

fn depth(args: &RenderArgs) -> SampleDepth {
    match args.depth {
        Depth::Eight => SampleDepth::Eight,
        Depth::Sixteen => SampleDepth::Sixteen,
        Depth::Float32 => SampleDepth::Float32,
    }
}

fn render(args: &RenderArgs) -> ExitCode {
    // An interrupted render leaves no temporary file behind.
    let _ = ctrlc::set_handler(|| {
        hrender::remove_unfinished_outputs();
        std::process::exit(130);
    });
    let source = match read_scene(&args.scene, Format::Short) {
        Ok(s) => s,
        Err(message) => {
            eprint!("{message}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    };
    // Refuse a bad output before spending time on the scene.
    if let Err(code) = check_outputs(args, std::slice::from_ref(&args.output)) {
        return code;
    }
    let stderr_tty = std::io::stderr().is_terminal();
    let first = args.frame.unwrap_or(0);
    let compiled = hscene_lang::compile_with(&source, &compile_options(&args.scene, first));
    let show = |diagnostics: &[hscene_lang::Diagnostic]| {
        let format = if stderr_tty {
            Format::Human
        } else {
            Format::Short
        };
        eprint!(
            "{}",
            report::format_diagnostics(&args.scene, &source, diagnostics, format, stderr_tty)
        );
    };
    if !compiled.diagnostics.is_empty() {
        show(&compiled.diagnostics);
    }
    let Some(scene) = compiled.scene else {
        return ExitCode::from(EXIT_SCENE_ERRORS);
    };
    let frames = scene.settings.frames;
    if let Some(k) = args.frame
        && k >= frames
    {
        eprintln!("error: {}", frame_past_end(k, frames));
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    if args.frame.is_none() && frames > 1 {
        let outputs: Vec<_> = (0..frames).map(|k| frame_path(&args.output, k)).collect();
        if let Err(code) = check_outputs(args, &outputs) {
            return code;
        }
    }
    if args.frame.is_some() || frames == 1 {
        return render_frame(args, &scene, &args.output, stderr_tty);
    }
    // Every frame, each compiled on its own: the animated transformations
    // are applied per frame. Diagnostics were shown for frame 0; those of
    // later frames are shown only if they are errors.
    for k in 0..frames {
        let scene = if k == 0 {
            scene.clone()
        } else {
            let compiled = hscene_lang::compile_with(&source, &compile_options(&args.scene, k));
            match compiled.scene {
                Some(s) => s,
                None => {
                    eprintln!("error: frame {k} of the animation has errors:");
                    show(&compiled.diagnostics);
                    return ExitCode::from(EXIT_SCENE_ERRORS);
                }
            }
        };
        let code = render_frame(args, &scene, &frame_path(&args.output, k), stderr_tty);
        if code != ExitCode::SUCCESS {
            return code;
        }
    }
    ExitCode::SUCCESS
}

/// `out.png` -> `out-0007.png` for frame 7 (at least four digits).
fn frame_path(output: &Path, frame: u32) -> std::path::PathBuf {
    let stem = output
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = match output.extension() {
        Some(ext) => format!("{stem}-{frame:04}.{}", ext.to_string_lossy()),
        None => format!("{stem}-{frame:04}"),
    };
    output.with_file_name(name)
}

fn render_frame(
    args: &RenderArgs,
    scene: &hscene_lang::ir::Scene,
    output: &Path,
    stderr_tty: bool,
) -> ExitCode {
    let options = RenderOptions {
        net: args.net.and_then(|n| Net::from_index(u64::from(n))),
        resolution: args
            .resolution
            .map(|(width, height)| Resolution { width, height }),
        threads: args.threads.map(usize::from),
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
    let rendered = match hrender::render(scene, &options, &progress) {
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
    if let Err(e) = hrender::write_image(&rendered.image, output, depth(args)) {
        eprintln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    if rendered.stats.numeric_failures > 0 {
        eprintln!(
            "warning: {} pixel(s) had a numeric failure; their failing rays show the background",
            rendered.stats.numeric_failures
        );
    }
    if rendered.stats.cut_trees > 0 {
        eprintln!(
            "warning: {} primary ray(s) reached the budget of {} reflected and transmitted rays; their ray trees were cut short",
            rendered.stats.cut_trees,
            hrender::MAX_SECONDARY_RAYS
        );
    }
    if stderr_tty {
        let secs = started.elapsed().as_secs_f64();
        eprintln!(
            "wrote {} ({}x{}, {} rays in {secs:.2} s)",
            output.display(),
            rendered.image.width(),
            rendered.image.height(),
            rendered.stats.rays
        );
    }
    ExitCode::SUCCESS
}
