//! `hscene view`: the scene file as a `hview::SceneSource` (compiled with
//! hscene-lang, its diagnostics formatted as `check` prints them, watched
//! by modification time and size), and the window or the headless flight.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::SystemTime;

use hscene_ir::{Net, Resolution, Scene};
use hview::{FlightPath, SceneSource, ViewOptions};

use crate::cli::{ColorChoice, Format, ViewArgs};
use crate::exit::{EXIT_SCENE_ERRORS, EXIT_USAGE_OR_IO};
use crate::report;

/// The widest default picture: scenes written for print resolutions would
/// make a window too slow to fly in.
const MAX_DEFAULT_WIDTH: u32 = 960;

/// The fewest samples a still view converges to by default.
const MIN_DEFAULT_SAMPLES: u32 = 16;

struct SceneFile {
    path: PathBuf,
    color: bool,
    stamp: Option<(SystemTime, u64)>,
}

fn stamp(path: &Path) -> Option<(SystemTime, u64)> {
    let m = std::fs::metadata(path).ok()?;
    Some((m.modified().ok()?, m.len()))
}

impl SceneSource for SceneFile {
    fn load(&mut self) -> Result<Scene, String> {
        self.stamp = stamp(&self.path);
        let source = crate::input::read_scene_reported(&self.path, Format::Short)?;
        let compiled =
            hscene_lang::compile_with(&source, &crate::input::compile_options(&self.path, 0));
        let shown = || {
            report::format_diagnostics(
                &self.path,
                &source,
                &compiled.diagnostics,
                compiled.omitted,
                Format::Human,
                self.color,
            )
        };
        match compiled.scene {
            Some(scene) => {
                if !compiled.diagnostics.is_empty() {
                    diag!("{}", shown());
                }
                Ok(scene)
            }
            None => Err(shown()),
        }
    }

    fn changed(&mut self) -> bool {
        let now = stamp(&self.path);
        now.is_some() && now != self.stamp
    }

    fn name(&self) -> String {
        self.path.display().to_string()
    }
}

fn options(args: &ViewArgs, scene: &Scene) -> Result<ViewOptions, String> {
    let resolution = match args.resolution {
        Some((w, h)) => Resolution::new(w, h).ok_or("the resolution must be at least 1x1")?,
        None => {
            let r = scene.settings.resolution;
            if r.width() > MAX_DEFAULT_WIDTH {
                let h = (u64::from(r.height()) * u64::from(MAX_DEFAULT_WIDTH)
                    / u64::from(r.width()))
                .max(1);
                Resolution::new(MAX_DEFAULT_WIDTH, h as u32).ok_or("bad resolution")?
            } else {
                r
            }
        }
    };
    Ok(ViewOptions {
        resolution,
        net: args.net.and_then(|n| Net::from_index(u64::from(n))),
        integrator: args.integrator,
        samples: args
            .samples
            .unwrap_or(scene.settings.samples.max(MIN_DEFAULT_SAMPLES)),
        coarse: 4,
        exposure: args.exposure,
        threads: args.threads.map(|t| t as usize),
        denoise: args.denoise || scene.settings.denoise,
    })
}

fn ms(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1000.0
}

fn headless(args: &ViewArgs, scene: &Scene, options: ViewOptions) -> ExitCode {
    let path = match &args.path {
        Some(p) => match FlightPath::read(p) {
            Ok(path) => path,
            Err(e) => {
                diagln!("error: cannot fly {}: {e}", p.display());
                return ExitCode::from(EXIT_USAGE_OR_IO);
            }
        },
        None => FlightPath::default_flight(args.frames),
    };
    if let Some(out) = &args.output
        && let Err(e) = hrender::check_output(
            out,
            hrender::SampleDepth::Eight,
            &[&args.scene],
            hrender::Overwrite::Writable,
        )
    {
        diagln!("error: {e}");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    let report = match hview::run_headless(scene, options, &path) {
        Ok(r) => r,
        Err(e) => {
            diagln!("error: {e}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    };
    if report.moves == 0 {
        // No move flown: no time per move to report (dividing by zero
        // moves printed "1000000000000.0 fps").
        outln!(
            "0 moves at {}x{}: nothing flown",
            options.resolution.width(),
            options.resolution.height(),
        );
    } else {
        let moves = report.moves as f64;
        let coarse = ms(report.to_coarse) / moves;
        let full = ms(report.full_pass) / moves;
        let worst = ms(report.worst_coarse);
        outln!(
            "{} moves at {}x{}: move to coarse frame {coarse:.1} ms (worst {worst:.1} ms); full-resolution pass {full:.1} ms; moving {:.1} fps (coarse + full pass), {:.1} fps (coarse only)",
            report.moves,
            options.resolution.width(),
            options.resolution.height(),
            1000.0 / (coarse + full).max(1e-9),
            1000.0 / coarse.max(1e-9),
        );
    }
    outln!(
        "still: converged to {} samples per pixel in {:.1} ms",
        report.last.samples,
        ms(report.converge)
    );
    if report.refused > 0 {
        outln!(
            "{} moves refused (the eye would leave f64's range)",
            report.refused
        );
    }
    if let Some(c) = report.pose.camera() {
        crate::exit::to_stdout(format_args!("{}", hview::camera_lines(&c)));
    }
    if let Some(out) = &args.output {
        let pixels: Vec<[f32; 3]> = report
            .last
            .pixels
            .iter()
            .map(|p| {
                // Back to linear so the writer's sRGB curve gives the same bytes.
                [16, 8, 0].map(|s| srgb_to_linear(((p >> s) & 0xff) as u8))
            })
            .collect();
        let image = hrender::Image::from_pixels(report.last.width, report.last.height, pixels);
        if let Err(e) = hrender::write_image(&image, out, hrender::SampleDepth::Eight) {
            diagln!("error: {e}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    }
    ExitCode::SUCCESS
}

/// The linear value whose sRGB encoding rounds to `v`.
fn srgb_to_linear(v: u8) -> f32 {
    hscene_ir::srgb_to_linear(f64::from(v) / 255.0) as f32
}

pub fn run(args: &ViewArgs, color: ColorChoice) -> ExitCode {
    if !(args.step > 0.0 && args.step <= 10.0) {
        diagln!("error: --step must be a distance above 0 and at most 10");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    if !(args.exposure.is_finite() && args.exposure.abs() <= 64.0) {
        diagln!("error: --exposure must be from -64 to 64 stops");
        return ExitCode::from(EXIT_USAGE_OR_IO);
    }
    let mut source = SceneFile {
        path: args.scene.clone(),
        color: color.enabled(std::io::stderr().is_terminal()),
        stamp: None,
    };
    let scene = match source.load() {
        Ok(s) => s,
        Err(message) => {
            diag!("{message}");
            return ExitCode::from(EXIT_SCENE_ERRORS);
        }
    };
    let options = match options(args, &scene) {
        Ok(o) => o,
        Err(e) => {
            diagln!("error: {e}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    };
    if options.denoise
        && let Err(e) = hrender::denoiser()
    {
        diagln!("warning: {e}; the view is shown without denoising");
    }
    if args.headless {
        return headless(args, &scene, options);
    }
    let save_dir = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    match hview::run_window(&mut source, options, args.step, save_dir) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            diagln!("error: {e}");
            ExitCode::from(EXIT_USAGE_OR_IO)
        }
    }
}
