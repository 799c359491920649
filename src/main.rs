//! The `hscene` command: glue between the scene language, the renderer and
//! the terminal. Only this crate knows about clap, JSON and terminals.

mod cli;
mod emit;
mod explain;
mod fmt_cmd;
mod lsp;
mod report;

use std::io::{IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use hrender::{DisplayTransform, Encoding, RenderOptions, SampleDepth, ToneMap};
use hscene_lang::ir::{Net, Resolution};

use cli::{
    CheckArgs, Cli, ColorChoice, Command, Depth, Emit, EncodingArg, ExposureArg, Format,
    RenderArgs, ToneMapArg,
};

/// Exit status: the scene has errors.
const EXIT_SCENE_ERRORS: u8 = 1;
/// Exit status: usage or I/O error.
const EXIT_USAGE_OR_IO: u8 = 2;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let color = cli.color;
    match cli.command {
        Command::Render(args) => render(&args, color),
        Command::Check(args) => check(&args, color),
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

/// Writes to stdout; a reader that stops early (`| head`) is not an error.
fn print_bytes(bytes: &[u8]) -> ExitCode {
    match std::io::stdout().lock().write_all(bytes) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(_) => ExitCode::from(EXIT_USAGE_OR_IO),
    }
}

/// Mesh files are found relative to the scene file.
fn compile_options(scene: &Path, frame: u32) -> hscene_lang::Options {
    hscene_lang::Options {
        base_dir: scene.parent().map(Path::to_path_buf),
        frame,
    }
}

fn read_scene(path: &Path) -> Result<String, ExitCode> {
    let read = if path == Path::new("-") {
        std::io::read_to_string(std::io::stdin())
    } else {
        std::fs::read_to_string(path)
    };
    read.map_err(|e| {
        eprintln!("error: cannot read {}: {e}", path.display());
        ExitCode::from(EXIT_USAGE_OR_IO)
    })
}

fn check(args: &CheckArgs, color: ColorChoice) -> ExitCode {
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
        let read = read_scene(path);
        // A scene from stdin takes the name (and mesh directory) given for it.
        let stdin_name = Path::new("<stdin>");
        let path = if path == Path::new("-") {
            args.stdin_filename.as_deref().unwrap_or(stdin_name)
        } else {
            path
        };
        let source = match read {
            Ok(s) => s,
            Err(_) => {
                io_failure = true;
                continue;
            }
        };
        let compiled = hscene_lang::compile_with(&source, &compile_options(path, args.frame));
        any_errors |=
            compiled.has_errors() || (args.deny_warnings && !compiled.diagnostics.is_empty());
        let text = report::format_diagnostics(
            path,
            &source,
            &compiled.diagnostics,
            format,
            color.enabled(diag_tty),
        );
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

fn render(args: &RenderArgs, color: ColorChoice) -> ExitCode {
    let source = match read_scene(&args.scene) {
        Ok(s) => s,
        Err(code) => return code,
    };
    // Refuse a bad output name or depth before spending time on the render.
    if let Err(e) = hrender::ImageFormat::from_path(&args.output)
        .and_then(|f| hrender::check_depth(f, sample_depth(args.depth, f)))
    {
        eprintln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    // `--exposure auto` is measured on the first frame rendered and kept.
    let auto_ev = std::cell::Cell::new(None);
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
            report::format_diagnostics(
                &args.scene,
                &source,
                diagnostics,
                format,
                color.enabled(stderr_tty)
            )
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
        eprintln!(
            "error: --frame {k} is past the scene's last frame ({} of `frames = {frames}`, counted from 0)",
            frames - 1
        );
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    if args.frame.is_some() || frames == 1 {
        return render_frame(args, &scene, &args.output, stderr_tty, &auto_ev);
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
        let code = render_frame(
            args,
            &scene,
            &frame_path(&args.output, k),
            stderr_tty,
            &auto_ev,
        );
        if code != ExitCode::SUCCESS {
            return code;
        }
    }
    ExitCode::SUCCESS
}

/// The lint for an image that would come out almost black (fewer than 1 %
/// of its pixels at sRGB level 16 or above), with the exposure that would
/// fix it.
fn warn_if_almost_black(image: &hrender::Image, display: DisplayTransform, auto: bool) {
    if !hrender::is_almost_black(image, display) {
        return;
    }
    let ev = hrender::auto_exposure(image);
    let hint = if auto || ev <= 0.0 {
        String::new()
    } else {
        format!("; try --exposure {ev:.1} (or --exposure auto), brighter lights or `irradiance_at`")
    };
    eprintln!(
        "warning: the image is almost black: under 1 % of its pixels reach level 16 of 255{hint}"
    );
}

/// The depth asked for, or the format's own default.
fn sample_depth(depth: Option<Depth>, format: hrender::ImageFormat) -> SampleDepth {
    match depth {
        Some(Depth::Eight) => SampleDepth::Eight,
        Some(Depth::Sixteen) => SampleDepth::Sixteen,
        Some(Depth::Float32) => SampleDepth::Float32,
        None => format.default_depth(),
    }
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
    auto_ev: &std::cell::Cell<Option<f64>>,
) -> ExitCode {
    let options = RenderOptions {
        net: args.net.and_then(|n| Net::from_index(u64::from(n))),
        resolution: args
            .resolution
            .map(|(width, height)| Resolution { width, height }),
        threads: args.threads,
        samples: args.samples,
        seed: args.seed,
        exposure: match args.exposure {
            ExposureArg::Stops(ev) => ev,
            ExposureArg::Auto => 0.0,
        },
    };
    let height = args.crop.map_or_else(
        || {
            options
                .resolution
                .unwrap_or(scene.settings.resolution)
                .height
        },
        |c| c.height,
    );
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
    let mut rendered = match hrender::render_region(scene, &options, args.crop, &progress) {
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
    let auto = (args.exposure == ExposureArg::Auto).then(|| {
        let ev = auto_ev
            .get()
            .unwrap_or_else(|| hrender::auto_exposure(&rendered.image));
        auto_ev.set(Some(ev));
        rendered.image.expose(ev);
        ev
    });
    let depth = match hrender::ImageFormat::from_path(output) {
        Ok(format) => sample_depth(args.depth, format),
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    };
    let display = DisplayTransform {
        tone: match args.tonemap {
            ToneMapArg::Clip => ToneMap::Clip,
            ToneMapArg::Reinhard => ToneMap::Reinhard,
            ToneMapArg::Aces => ToneMap::Aces,
        },
        encoding: match args.encoding {
            EncodingArg::Srgb => Encoding::Srgb,
            EncodingArg::Linear => Encoding::Linear,
        },
    };
    if let Err(e) = hrender::write_image_with(&rendered.image, output, depth, display) {
        eprintln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    if rendered.stats.numeric_failures > 0 {
        eprintln!(
            "warning: {} pixel(s) had a numeric failure; their failing rays show the background",
            rendered.stats.numeric_failures
        );
    }
    if let Some(ev) = auto {
        eprintln!("note: --exposure auto chose {ev:.2} stops");
    }
    warn_if_almost_black(&rendered.image, display, auto.is_some());
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
