//! `hscene render`: a scene to an image, a numbered series of frames or a
//! video.

use std::io::IsTerminal;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use hrender::{DisplayTransform, Encoding, Exposure, RenderOptions, SampleDepth, ToneMap};
use hscene_ir::{Net, Resolution};

use crate::cli::{
    ColorChoice, Depth, EncodingArg, ExposureArg, Format, RenderArgs, SamplesArg, ToneMapArg,
};
use crate::exit::{EXIT_SCENE_ERRORS, EXIT_USAGE_OR_IO};
use crate::frames::{self, frame_past_end, frame_path};
use crate::input::{compile_options_sharing, read_scene_reported as read_scene};
use crate::report;

/// The relative standard error `--samples auto` stops at without `--noise`.
const DEFAULT_NOISE: f64 = 0.01;

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
            diagln!("error: {e}");
            return Err(ExitCode::from(EXIT_USAGE_OR_IO));
        }
    }
    Ok(())
}

pub fn run(args: &RenderArgs, color: ColorChoice) -> ExitCode {
    let source = match read_scene(&args.scene, Format::Short) {
        Ok(s) => s,
        Err(message) => {
            diag!("{message}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    };
    let video = hrender::VideoFormat::from_path(&args.output);
    if let Err(message) = check_arguments(args, video.is_some()) {
        diagln!("error: {message}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    // Refuse a bad output before spending time on the scene.
    if let Err(code) = check_outputs(args, std::slice::from_ref(&args.output), &[]) {
        return code;
    }
    let stderr_tty = std::io::stderr().is_terminal();
    let first = args.frame.unwrap_or(0);
    // Every file the animation needs is read once, by this compile and the
    // checks of every frame below, before the first frame is written.
    let files = hscene_lang::FileCache::pinned();
    let options = |k| compile_options_sharing(&args.scene, k, &files);
    let compiled = hscene_lang::compile_with(&source, &options(first));
    let show = |diagnostics: &[hscene_lang::Diagnostic], omitted: hscene_lang::Omitted| {
        // The full report whether or not stderr is a terminal; colour only
        // on one.
        diag!(
            "{}",
            report::format_diagnostics(
                &args.scene,
                &source,
                diagnostics,
                omitted,
                Format::Human,
                color.enabled(stderr_tty)
            )
        );
    };
    if !compiled.diagnostics.is_empty() || compiled.omitted.total() > 0 {
        show(&compiled.diagnostics, compiled.omitted);
    }
    let Some(scene) = compiled.scene else {
        return ExitCode::from(EXIT_SCENE_ERRORS);
    };
    if args.integrator == Some(hrender::IntegratorKind::Path)
        && scene.settings.integrator != hrender::IntegratorKind::Path
        && scene.reflects_ambient()
    {
        diagln!(
            "warning: `ambient` has no meaning under the path integrator, which computes the light bouncing between surfaces instead; surfaces lit only by ambient light come out darker [HSC1010]"
        );
    }
    // Refuse a denoised render before its rays are spent when the library
    // is missing.
    if (args.denoise || scene.settings.denoise)
        && let Err(e) = hrender::denoiser()
    {
        diagln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    let frames = scene.settings.frames;
    if let Some(k) = args.frame
        && k >= frames
    {
        diagln!("error: {}", frame_past_end(k, frames));
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
    let compile = |k| hscene_lang::compile_with(&source, &options(k));
    let show_errors =
        |diagnostics: &[hscene_lang::Diagnostic]| show(diagnostics, Default::default());
    // Every frame is checked before the first is written; the frames the
    // check builds are the ones rendered.
    let mut later = frames::LaterFrames::new(&compile, &show_errors);
    if args.frame.is_none()
        && frames > 1
        && let Err(code) = later.check_every_frame(&scene, frames)
    {
        return code;
    }
    // `--exposure auto` is measured on the first frame rendered and kept.
    let auto_ev = std::cell::Cell::new(None);
    if (args.frame.is_some() || frames == 1) && video.is_none() {
        return render_frame(
            args,
            &scene,
            FrameSink::File(&args.output),
            stderr_tty,
            &auto_ev,
        );
    }
    if let Some(format) = video {
        note_played_rate(format, args.fps);
    }
    let mut writer = match video {
        Some(_) => match open_video(args, &scene) {
            Ok(w) => Some(w),
            Err(e) => {
                diagln!("error: {e}");
                return ExitCode::from(EXIT_USAGE_OR_IO);
            }
        },
        None => None,
    };
    let code = render_every_frame(
        args,
        &scene,
        &mut later,
        writer.as_mut(),
        stderr_tty,
        &auto_ev,
    );
    if code != ExitCode::SUCCESS {
        return code;
    }
    if let Some(w) = writer
        && let Err(e) = w.finish()
    {
        diagln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    ExitCode::SUCCESS
}

/// The combinations of arguments that clap cannot refuse on its own.
fn check_arguments(args: &RenderArgs, video: bool) -> Result<(), &'static str> {
    if args.samples != Some(SamplesArg::Auto)
        && (args.noise.is_some() || args.max_samples.is_some())
    {
        return Err("--noise and --max-samples go with --samples auto");
    }
    if args.aov.is_some()
        && !matches!(
            hrender::ImageFormat::from_path(&args.output),
            Ok(hrender::ImageFormat::Exr)
        )
    {
        return Err("--aov writes its layers as channels of an OpenEXR file: give an .exr output");
    }
    if video {
        if args.frame.is_some() {
            return Err("a video holds every frame: drop --frame, or render the frame to an image");
        }
        if !matches!(args.depth, None | Some(Depth::Eight)) {
            return Err("videos are 8 bits a channel: drop --depth");
        }
        if !(args.fps.is_finite() && (0.1..=240.0).contains(&args.fps)) {
            return Err("--fps must be from 0.1 to 240");
        }
    }
    Ok(())
}

/// Says when the format cannot hold the rate asked for (GIF's delays are
/// at least 2 hundredths of a second; below 50 frames a second they
/// alternate to keep the rate), with the rate it plays at.
fn note_played_rate(format: hrender::VideoFormat, fps: f64) {
    let played = hrender::played_fps(format, fps);
    if (played - fps).abs() > 1e-6 * fps {
        diagln!(
            "warning: {} plays at {played:.3} frames a second, not {fps}{}",
            match format {
                hrender::VideoFormat::Gif => "a GIF",
                hrender::VideoFormat::Apng => "an APNG",
                _ => "the video",
            },
            match format {
                hrender::VideoFormat::Gif =>
                    " (its frame delays are at least 2 hundredths of a second); use .apng, .mp4 or .webm for this rate",
                _ => " (its frame delays are exact to a thousandth of a frame a second)",
            }
        );
    }
}

/// The video writer for the whole animation, at the picture's size.
fn open_video(
    args: &RenderArgs,
    scene: &hscene_ir::Scene,
) -> Result<hrender::VideoWriter, hrender::RenderError> {
    let (width, height) = args.crop.map_or_else(
        || {
            let r = args
                .resolution
                .and_then(|(w, h)| Resolution::new(w, h))
                .unwrap_or(scene.settings.resolution);
            (r.width(), r.height())
        },
        |c| (c.width, c.height),
    );
    hrender::VideoWriter::create(
        &args.output,
        width,
        height,
        scene.settings.frames,
        args.fps,
        display_transform(args),
    )
}

/// Renders frames `0..frames` in order, each to its numbered file or as
/// the next frame of `video`.
///
/// The scene was compiled once: every frame comes from it
/// (`Scene::frame`), except in a scene whose animated transformations
/// move points, where what is built from them changes shape and each
/// frame is compiled on its own. Diagnostics were shown for frame 0;
/// those of later frames are shown only if they are errors.
fn render_every_frame(
    args: &RenderArgs,
    scene: &hscene_ir::Scene,
    later: &mut frames::LaterFrames<'_>,
    mut video: Option<&mut hrender::VideoWriter>,
    stderr_tty: bool,
    auto_ev: &std::cell::Cell<Option<f64>>,
) -> ExitCode {
    let frames = scene.settings.frames;
    for k in 0..frames {
        let built;
        let frame_scene = if k == 0 {
            scene
        } else {
            match later.take(scene, k) {
                Ok(s) => {
                    built = s;
                    &built
                }
                Err(code) => return code,
            }
        };
        let path = frame_path(&args.output, k);
        let sink = match video.as_deref_mut() {
            Some(w) => FrameSink::Video(w),
            None => FrameSink::File(&path),
        };
        if stderr_tty && frames > 1 {
            diagln!("frame {}/{frames}", k + 1);
        }
        let code = render_frame(args, frame_scene, sink, stderr_tty, auto_ev);
        if code != ExitCode::SUCCESS {
            return code;
        }
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
    has_background: bool,
) {
    let bright_level = match hrender::darkness(image, display) {
        hrender::Darkness::Visible => return,
        hrender::Darkness::AlmostBlack { bright_level } => bright_level,
        hrender::Darkness::Black => {
            // A scene with a background whose picture is black hides it
            // behind its objects: adding one is no fix.
            let background = if has_background {
                "; the scene's background is hidden behind its objects everywhere"
            } else {
                ", or a `background`"
            };
            diagln!(
                "warning: the image is black: no pixel receives any light; add a light (`Lights`), an `ambient` colour to the materials (with the global `ambient`), `emission`{background}"
            );
            return;
        }
    };
    let hint = match hrender::exposure_for_level(bright_level, current) {
        Some(ev) if !auto => format!(
            "; try --exposure {ev:.1} (or --exposure auto), brighter lights or `irradiance_at`"
        ),
        _ => String::new(),
    };
    diagln!(
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
    let options = render_options(args, auto_ev.get());
    let height = args.crop.map_or_else(
        || {
            options
                .resolution
                .unwrap_or(scene.settings.resolution)
                .height()
        },
        |c| c.height,
    );
    let bar = stderr_tty.then(|| progress_bar(height));
    let started = Instant::now();
    let progress = |rows: u32| {
        if let Some(bar) = &bar {
            bar.set_position(u64::from(rows));
        }
    };
    let mut rendered = match hrender::render_region(scene, &options, args.crop, &progress) {
        Ok(r) => r,
        Err(e) => {
            diagln!("error: {e}");
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
    let noisy = if args.denoise || scene.settings.denoise {
        match denoise(scene, &options, args.crop, &rendered.image) {
            Ok(denoised) => Some(std::mem::replace(&mut rendered.image, denoised)),
            Err(e) => {
                diagln!("error: {e}");
                return ExitCode::from(EXIT_USAGE_OR_IO);
            }
        }
    } else {
        None
    };
    // `--exposure auto` is chosen on the first frame and kept for the rest.
    if rendered.auto_exposure.is_some() {
        auto_ev.set(rendered.auto_exposure);
    }
    let output = match write_frame(args, scene, &options, &rendered, noisy.as_ref(), sink) {
        Ok(output) => output,
        Err(e) => {
            diagln!("error: {e}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    };
    report_frame(args, scene, &rendered);
    if stderr_tty {
        let secs = started.elapsed().as_secs_f64();
        diagln!(
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

/// `image` (the picture of `scene` with `options`, cropped to `crop`)
/// denoised, guided by its albedo and normal layers.
fn denoise(
    scene: &hscene_ir::Scene,
    options: &RenderOptions,
    crop: Option<hrender::Region>,
    image: &hrender::Image,
) -> Result<hrender::Image, hrender::RenderError> {
    let guides = hrender::render_guides(scene, options, crop)?;
    Ok(hrender::denoiser()?.denoise(image, &guides, options.threads)?)
}

/// The renderer's options from the command line; `auto_ev` is the
/// exposure `--exposure auto` chose on an earlier frame.
fn render_options(args: &RenderArgs, auto_ev: Option<f64>) -> RenderOptions {
    RenderOptions {
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
        exposure: match (args.exposure, auto_ev) {
            (ExposureArg::Stops(ev), _) => Exposure::Stops(ev),
            (ExposureArg::Auto, None) => Exposure::Auto,
            (ExposureArg::Auto, Some(ev)) => Exposure::AutoKept(ev),
        },
        integrator: args.integrator,
    }
}

/// The progress bar of one frame, counted in rows.
fn progress_bar(height: u32) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(u64::from(height));
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{spinner} rendering [{bar:40}] {pos}/{len} rows, {eta} left",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    bar
}

/// Writes a rendered frame where `sink` says (its own file, with the pixel
/// layers when asked, or the video's next frame) and returns the path
/// written.
fn write_frame(
    args: &RenderArgs,
    scene: &hscene_ir::Scene,
    options: &RenderOptions,
    rendered: &hrender::Rendered,
    noisy: Option<&hrender::Image>,
    sink: FrameSink,
) -> Result<std::path::PathBuf, hrender::RenderError> {
    match sink {
        FrameSink::File(output) => {
            let depth = sample_depth(args.depth, hrender::ImageFormat::from_path(output)?);
            // The CLI parser bounds the level to 0..=9.
            let png = hrender::PngLevel::new(args.png_level).unwrap_or_default();
            match &args.aov {
                Some(aovs) => {
                    let mut layers = hrender::render_aovs(scene, options, args.crop, &aovs.0)?;
                    // Without denoising, the noisy layer is the picture.
                    layers.add_picture(noisy.unwrap_or(&rendered.image));
                    hrender::write_exr_with_layers(&rendered.image, &layers, output)?;
                }
                None => hrender::write_image_with(
                    &rendered.image,
                    output,
                    depth,
                    display_transform(args),
                    png,
                )?,
            }
            Ok(output.to_path_buf())
        }
        FrameSink::Video(video) => {
            video.push(&rendered.image)?;
            Ok(args.output.clone())
        }
    }
}

/// The notes and warnings about a rendered frame: failed pixels, the
/// exposure chosen, the noise left, a black picture, cut ray trees.
fn report_frame(args: &RenderArgs, scene: &hscene_ir::Scene, rendered: &hrender::Rendered) {
    if rendered.stats.numeric_failures > 0 {
        diagln!(
            "warning: {} pixel(s) had a numeric failure; their failing rays show the background",
            rendered.stats.numeric_failures
        );
    }
    let auto = rendered.auto_exposure;
    if let Some(ev) = auto {
        diagln!("note: --exposure auto chose {ev:.2} stops");
    }
    let path =
        args.integrator.unwrap_or(scene.settings.integrator) == hrender::IntegratorKind::Path;
    if path || args.samples == Some(SamplesArg::Auto) {
        let pixels = u64::from(rendered.image.width()) * u64::from(rendered.image.height());
        let per_pixel = rendered.stats.samples as f64 / pixels.max(1) as f64;
        match rendered.stats.noise {
            Some(e) => diagln!(
                "note: noise left {:.2} % (mean relative standard error of the lit pixels), {per_pixel:.1} samples per pixel",
                100.0 * e
            ),
            // Without an estimate either each pixel had one sample, or no
            // pixel saw any light (nothing to be relative to).
            None if per_pixel < 2.0 => diagln!(
                "note: {per_pixel:.1} samples per pixel; the noise left cannot be estimated from one sample (use --samples 16 or more, or --samples auto)"
            ),
            None => diagln!(
                "note: {per_pixel:.1} samples per pixel; no pixel received light, so there is no noise to estimate"
            ),
        }
    }
    let current = match args.exposure {
        ExposureArg::Stops(ev) => ev,
        ExposureArg::Auto => auto.unwrap_or(0.0),
    };
    let settings = &scene.settings;
    let has_background = !settings.background.is_black() || settings.sky.is_some();
    warn_if_almost_black(
        &rendered.image,
        display_transform(args),
        current,
        auto.is_some(),
        has_background,
    );
    if rendered.stats.cut_trees > 0 {
        diagln!(
            "warning: {} primary ray(s) reached the budget of {} reflected and transmitted rays; their ray trees were cut short",
            rendered.stats.cut_trees,
            hrender::MAX_SECONDARY_RAYS
        );
    }
}
