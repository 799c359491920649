//! The `hscene` command: glue between the scene language, the renderer and
//! the terminal. Only this crate knows about clap, JSON and terminals.

mod allocator;
mod cli;
mod emit;
mod exit;
mod explain;
mod export_cmd;
mod fmt_cmd;
mod frames;
mod input;
mod lsp;
mod report;
mod view_cmd;

use std::io::{IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use hrender::{DisplayTransform, Encoding, Exposure, RenderOptions, SampleDepth, ToneMap};
use hscene_ir::{Net, Resolution};

use exit::{EXIT_SCENE_ERRORS, EXIT_USAGE_OR_IO, print_bytes};
use frames::frame_path;

use cli::{
    CheckArgs, Cli, ColorChoice, Command, Depth, Emit, EncodingArg, ExposureArg, Format,
    RenderArgs, SamplesArg, ToneMapArg,
};

/// The relative standard error `--samples auto` stops at without `--noise`.
const DEFAULT_NOISE: f64 = 0.01;

#[global_allocator]
static ALLOCATOR: allocator::Allocator = allocator::Allocator;

fn main() -> ExitCode {
    ignore_file_size_signal();
    let cli = Cli::parse();
    let color = cli.color;
    match cli.command {
        Command::Render(args) => render(&args, color),
        Command::Check(args) => check(&args, color),
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

/// Mesh files are found relative to the scene file.
pub(crate) fn compile_options(scene: &Path, frame: u32) -> hscene_lang::Options {
    hscene_lang::Options {
        base_dir: scene.parent().map(Path::to_path_buf),
        frame,
        ..Default::default()
    }
}

pub(crate) fn read_scene(path: &Path, format: Format) -> Result<String, String> {
    input::read_scene(path).map_err(|e| input::describe_failure(path, &e, format))
}

fn check(args: &CheckArgs, color: ColorChoice) -> ExitCode {
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
            eprint!("{text}");
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
        eprint!("{message}");
    }
}

/// The message for a frame number past the animation's end.
fn frame_past_end(k: u32, frames: u32) -> String {
    format!(
        "--frame {k} is past the scene's last frame ({} of `frames = {frames}`, counted from 0)",
        frames.saturating_sub(1)
    )
}

/// Everything about the outputs is checked before the first ray; none may
/// be the scene file or a file the scene names (`inputs`).
fn check_outputs(
    args: &RenderArgs,
    outputs: &[std::path::PathBuf],
    inputs: &[std::path::PathBuf],
) -> Result<(), ExitCode> {
    let mut all: Vec<&Path> = vec![&args.scene];
    all.extend(inputs.iter().map(std::path::PathBuf::as_path));
    let overwrite = if args.force {
        hrender::Overwrite::Force
    } else {
        hrender::Overwrite::Writable
    };
    for output in outputs {
        let checked = if hrender::VideoFormat::from_path(output).is_some() {
            hrender::check_video(output)
                .and_then(|_| hrender::check_output_file(output, &all, overwrite))
        } else {
            hrender::ImageFormat::from_path(output).and_then(|format| {
                let depth = sample_depth(args.depth, format);
                hrender::check_output(output, depth, &all, overwrite).map(drop)
            })
        };
        if let Err(e) = checked {
            eprintln!("error: {e}");
            return Err(ExitCode::from(EXIT_USAGE_OR_IO));
        }
    }
    Ok(())
}

fn render(args: &RenderArgs, color: ColorChoice) -> ExitCode {
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
    if args.samples != Some(SamplesArg::Auto)
        && (args.noise.is_some() || args.max_samples.is_some())
    {
        eprintln!("error: --noise and --max-samples go with --samples auto");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    let video = hrender::VideoFormat::from_path(&args.output);
    if args.aov.is_some()
        && !matches!(
            hrender::ImageFormat::from_path(&args.output),
            Ok(hrender::ImageFormat::Exr)
        )
    {
        eprintln!(
            "error: --aov writes its layers as channels of an OpenEXR file: give an .exr output"
        );
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    if video.is_some() {
        if args.frame.is_some() {
            eprintln!(
                "error: a video holds every frame: drop --frame, or render the frame to an image"
            );
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
        if !matches!(args.depth, None | Some(Depth::Eight)) {
            eprintln!("error: videos are 8 bits a channel: drop --depth");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
        if !(args.fps.is_finite() && (0.1..=240.0).contains(&args.fps)) {
            eprintln!("error: --fps must be from 0.1 to 240");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    }
    // Refuse a bad output before spending time on the scene.
    if let Err(code) = check_outputs(args, std::slice::from_ref(&args.output), &[]) {
        return code;
    }
    // `--exposure auto` is measured on the first frame rendered and kept.
    let auto_ev = std::cell::Cell::new(None);
    let stderr_tty = std::io::stderr().is_terminal();
    let first = args.frame.unwrap_or(0);
    let compiled = hscene_lang::compile_with(&source, &compile_options(&args.scene, first));
    let show = |diagnostics: &[hscene_lang::Diagnostic]| {
        // The full report whether or not stderr is a terminal; colour only
        // on one.
        let format = Format::Human;
        eprint!(
            "{}",
            report::format_diagnostics(
                &args.scene,
                &source,
                diagnostics,
                Default::default(),
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
    if args.integrator == Some(hrender::IntegratorKind::Path)
        && scene.settings.integrator != hrender::IntegratorKind::Path
        && scene.reflects_ambient()
    {
        eprintln!(
            "warning: `ambient` has no meaning under the path integrator, which computes the light bouncing between surfaces instead; surfaces lit only by ambient light come out darker [HSC1010]"
        );
    }
    let frames = scene.settings.frames;
    if let Some(k) = args.frame
        && k >= frames
    {
        eprintln!("error: {}", frame_past_end(k, frames));
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    let outputs: Vec<_> = if args.frame.is_none() && frames > 1 && video.is_none() {
        (0..frames).map(|k| frame_path(&args.output, k)).collect()
    } else {
        vec![args.output.clone()]
    };
    if let Err(code) = check_outputs(args, &outputs, &compiled.inputs) {
        return code;
    }
    // Every frame is checked before the first is written.
    if args.frame.is_none()
        && frames > 1
        && let Err(code) = frames::check_every_frame(
            &scene,
            frames,
            &|k| hscene_lang::compile_with(&source, &compile_options(&args.scene, k)),
            &show,
        )
    {
        return code;
    }
    if (args.frame.is_some() || frames == 1) && video.is_none() {
        return render_frame(
            args,
            &scene,
            FrameSink::File(&args.output),
            stderr_tty,
            &auto_ev,
        );
    }
    let mut writer = match video {
        Some(_) => {
            let size = args.crop.map_or_else(
                || {
                    let r = args
                        .resolution
                        .and_then(|(w, h)| Resolution::new(w, h))
                        .unwrap_or(scene.settings.resolution);
                    (r.width(), r.height())
                },
                |c| (c.width, c.height),
            );
            match hrender::VideoWriter::create(
                &args.output,
                size.0,
                size.1,
                frames,
                args.fps,
                display_transform(args),
            ) {
                Ok(w) => Some(w),
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(EXIT_USAGE_OR_IO);
                }
            }
        }
        None => None,
    };
    // The scene was compiled once: every frame comes from it
    // (`Scene::frame`), except in a scene whose animated transformations
    // move points, where what is built from them changes shape and each
    // frame is compiled on its own. Diagnostics were shown for frame 0;
    // those of later frames are shown only if they are errors.
    for k in 0..frames {
        let later;
        let frame_scene = if k == 0 {
            &scene
        } else if !scene.animation.moves_points {
            match scene.frame(k) {
                Ok(s) => {
                    later = s;
                    &later
                }
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(EXIT_SCENE_ERRORS);
                }
            }
        } else {
            let compiled = hscene_lang::compile_with(&source, &compile_options(&args.scene, k));
            match compiled.scene {
                Some(s) => {
                    later = s;
                    &later
                }
                None => {
                    eprintln!("error: frame {k} of the animation has errors:");
                    show(&compiled.diagnostics);
                    return ExitCode::from(EXIT_SCENE_ERRORS);
                }
            }
        };
        let path = frame_path(&args.output, k);
        let sink = match writer.as_mut() {
            Some(w) => FrameSink::Video(w),
            None => FrameSink::File(&path),
        };
        if stderr_tty && frames > 1 {
            eprintln!("frame {}/{frames}", k + 1);
        }
        let code = render_frame(args, frame_scene, sink, stderr_tty, &auto_ev);
        if code != ExitCode::SUCCESS {
            return code;
        }
    }
    if let Some(w) = writer
        && let Err(e) = w.finish()
    {
        eprintln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    ExitCode::SUCCESS
}

/// The lint for an image that is black (nothing lit: a forgotten light) or
/// would come out almost black (even its bright pixels below level 16 of
/// 255), with the absolute exposure that would fix it: following the hint
/// gives a picture this lint passes.
fn warn_if_almost_black(
    image: &hrender::Image,
    display: DisplayTransform,
    current: f64,
    auto: bool,
) {
    if !image.pixels().is_empty() && hrender::is_black(image) {
        eprintln!(
            "warning: the image is black: no pixel receives any light; add a light (`Lights`), an `ambient` colour to the materials (with the global `ambient`), `emission`, or a `background`"
        );
        return;
    }
    if !hrender::is_almost_black(image, display) {
        return;
    }
    let hint = match hrender::suggested_exposure(image, current) {
        Some(ev) if !auto => format!(
            "; try --exposure {ev:.1} (or --exposure auto), brighter lights or `irradiance_at`"
        ),
        _ => String::new(),
    };
    eprintln!(
        "warning: the image is almost black: even its bright pixels stay below level 16 of 255{hint}"
    );
}

/// The tone curve and transfer function asked for.
fn display_transform(args: &RenderArgs) -> DisplayTransform {
    DisplayTransform {
        tone: match args.tonemap {
            ToneMapArg::Clip => ToneMap::Clip,
            ToneMapArg::Reinhard => ToneMap::Reinhard,
            ToneMapArg::Aces => ToneMap::Aces,
        },
        encoding: match args.encoding {
            EncodingArg::Srgb => Encoding::Srgb,
            EncodingArg::Linear => Encoding::Linear,
        },
    }
}

/// Where a rendered frame goes: its own image file, or the next frame of
/// a video.
enum FrameSink<'a> {
    File(&'a Path),
    Video(&'a mut hrender::VideoWriter),
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

fn render_frame(
    args: &RenderArgs,
    scene: &hscene_ir::Scene,
    sink: FrameSink,
    stderr_tty: bool,
    auto_ev: &std::cell::Cell<Option<f64>>,
) -> ExitCode {
    let options = RenderOptions {
        net: args.net.and_then(|n| Net::from_index(u64::from(n))),
        resolution: args
            .resolution
            // The parser refused empty sides.
            .and_then(|(width, height)| Resolution::new(width, height)),
        threads: args.threads.map(usize::from),
        samples: match args.samples {
            Some(SamplesArg::Count(n)) => Some(n),
            _ => None,
        },
        adaptive: (args.samples == Some(SamplesArg::Auto)).then(|| hrender::Adaptive {
            noise: args.noise.unwrap_or(DEFAULT_NOISE),
            max_samples: args
                .max_samples
                .unwrap_or(hrender::Adaptive::DEFAULT_MAX_SAMPLES),
        }),
        sample_range: None,
        seed: args.seed,
        exposure: match (args.exposure, auto_ev.get()) {
            (ExposureArg::Stops(ev), _) => Exposure::Stops(ev),
            (ExposureArg::Auto, None) => Exposure::Auto,
            (ExposureArg::Auto, Some(ev)) => Exposure::AutoKept(ev),
        },
        integrator: args.integrator,
    };
    let height = args.crop.map_or_else(
        || {
            options
                .resolution
                .unwrap_or(scene.settings.resolution)
                .height()
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
    let rendered = match hrender::render_region(scene, &options, args.crop, &progress) {
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
    // `--exposure auto` is chosen on the first frame and kept for the rest.
    let auto = rendered.auto_exposure;
    if auto.is_some() {
        auto_ev.set(auto);
    }
    let display = display_transform(args);
    let output = match sink {
        FrameSink::File(output) => {
            let depth = match hrender::ImageFormat::from_path(output) {
                Ok(format) => sample_depth(args.depth, format),
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(EXIT_USAGE_OR_IO);
                }
            };
            // The CLI parser bounds the level to 0..=9.
            let png = hrender::PngLevel::new(args.png_level).unwrap_or_default();
            let written = match &args.aov {
                Some(aovs) => {
                    hrender::render_aovs(scene, &options, args.crop, &aovs.0).and_then(|layers| {
                        hrender::write_exr_with_layers(&rendered.image, &layers, output)
                    })
                }
                None => hrender::write_image_with(&rendered.image, output, depth, display, png),
            };
            if let Err(e) = written {
                eprintln!("error: {e}");
                return ExitCode::from(EXIT_USAGE_OR_IO);
            }
            output.to_path_buf()
        }
        FrameSink::Video(video) => {
            if let Err(e) = video.push(&rendered.image) {
                eprintln!("error: {e}");
                return ExitCode::from(EXIT_USAGE_OR_IO);
            }
            args.output.clone()
        }
    };
    if rendered.stats.numeric_failures > 0 {
        eprintln!(
            "warning: {} pixel(s) had a numeric failure; their failing rays show the background",
            rendered.stats.numeric_failures
        );
    }
    if let Some(ev) = auto {
        eprintln!("note: --exposure auto chose {ev:.2} stops");
    }
    let path =
        args.integrator.unwrap_or(scene.settings.integrator) == hrender::IntegratorKind::Path;
    if path || args.samples == Some(SamplesArg::Auto) {
        let pixels = u64::from(rendered.image.width()) * u64::from(rendered.image.height());
        let per_pixel = rendered.stats.samples as f64 / pixels.max(1) as f64;
        match rendered.stats.noise {
            Some(e) => eprintln!(
                "note: noise left {:.2} % (mean relative standard error of the lit pixels), {per_pixel:.1} samples per pixel",
                100.0 * e
            ),
            None => eprintln!(
                "note: {per_pixel:.1} samples per pixel; the noise left cannot be estimated from one sample (use --samples 16 or more, or --samples auto)"
            ),
        }
    }
    let current = match args.exposure {
        ExposureArg::Stops(ev) => ev,
        ExposureArg::Auto => auto.unwrap_or(0.0),
    };
    warn_if_almost_black(&rendered.image, display, current, auto.is_some());
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
            "{} {} ({}x{}, {} rays in {secs:.2} s)",
            if args.output == output && hrender::VideoFormat::from_path(&output).is_some() {
                "added a frame to"
            } else {
                "wrote"
            },
            output.display(),
            rendered.image.width(),
            rendered.image.height(),
            rendered.stats.rays
        );
    }
    ExitCode::SUCCESS
}
