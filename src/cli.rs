//! Command-line interface definition.

use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};
use hscene_lang::MAX_PIXELS;

/// Ray tracing in the Poincaré ball model of hyperbolic space.
#[derive(Debug, Parser)]
#[command(name = "hscene", version, about)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// When to colour diagnostics: `auto` colours a terminal unless the
    /// NO_COLOR environment variable is set and not empty.
    #[arg(long, global = true, value_name = "WHEN", default_value = "auto")]
    pub color: ColorChoice,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    Auto,
    Always,
    Never,
}

impl ColorChoice {
    /// Whether to colour output going to a stream that is (or is not) a terminal.
    pub fn enabled(self, is_terminal: bool) -> bool {
        match self {
            ColorChoice::Always => true,
            ColorChoice::Never => false,
            ColorChoice::Auto => {
                is_terminal && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
            }
        }
    }
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene to a PNG, TIFF or OpenEXR image.
    Render(RenderArgs),
    /// Check scenes for errors and warnings without rendering.
    Check(CheckArgs),
    /// Export the scene's objects as a mesh of the Poincaré ball: STL or
    /// 3MF (millimetres, for printing), OBJ or glTF binary (metres).
    Export(ExportArgs),
    /// Open a live window onto the scene: fly with the keys, watch it
    /// refine, edit the file and see it follow (`--headless` for scripts).
    View(ViewArgs),
    /// Format scenes in the canonical layout (in place, or `-` from stdin to stdout).
    Fmt(FmtArgs),
    /// Run the language server on stdin/stdout (for editors).
    Lsp,
    /// Print the documentation of a diagnostic code, e.g. `hscene explain HSC0305`.
    Explain {
        /// The code, e.g. HSC0305 (the `HSC` may be left out).
        code: String,
    },
    /// Print a shell completion script to stdout.
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// Print the man page (roff) to stdout.
    Man,
}

#[derive(Debug, clap::Args)]
pub struct ViewArgs {
    /// The scene file.
    pub scene: PathBuf,
    /// The picture's size WIDTHxHEIGHT (default: the scene's, at most 960
    /// wide).
    #[arg(long, value_parser = parse_resolution)]
    pub resolution: Option<(u32, u32)>,
    /// Pixel net 0-4, overriding the scene's `net_type`.
    #[arg(long, value_parser = clap::value_parser!(u8).range(0..=4))]
    pub net: Option<u8>,
    /// How light is computed, overriding the scene's `integrator`: whitted
    /// or path.
    #[arg(long, value_name = "NAME", value_parser = parse_integrator)]
    pub integrator: Option<hrender::IntegratorKind>,
    /// The samples per pixel a still view converges to (default: the
    /// scene's, at least 16).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub samples: Option<u32>,
    /// Exposure in stops.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub exposure: f64,
    /// Denoise the converged still view (as the scene's `denoise = true;`)
    /// where Intel Open Image Denoise is installed; without it the view
    /// stays noisy and says so once.
    #[arg(long)]
    pub denoise: bool,
    /// The hyperbolic distance one key press flies (Shift: five times).
    #[arg(long, default_value_t = 0.05)]
    pub step: f64,
    /// Worker threads (default: every core).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=1024))]
    pub threads: Option<u64>,
    /// No window: fly a path (`--path`, or a gentle default flight of
    /// `--frames` moves), let the last view converge, print the times.
    #[arg(long)]
    pub headless: bool,
    /// Moves of the default headless flight (at most 10,000).
    #[arg(long, default_value_t = 24, requires = "headless",
          value_parser = clap::value_parser!(u32).range(0..=i64::from(hview::MAX_FLIGHT_MOVES)))]
    pub frames: u32,
    /// A flight path for `--headless`: one move a line, `forward 0.05`,
    /// `yaw 2`, ... (README, "View").
    #[arg(long, requires = "headless")]
    pub path: Option<PathBuf>,
    /// With `--headless`, write the last, converged view here (PNG).
    #[arg(short, long, requires = "headless")]
    pub output: Option<PathBuf>,
}

#[derive(Debug, clap::Args)]
pub struct ExportArgs {
    /// The scene file.
    pub scene: PathBuf,
    /// Output mesh: .stl, .3mf, .obj (with a .mtl beside it) or .glb.
    #[arg(short, long)]
    pub output: PathBuf,
    /// The ball's diameter in the file: 100mm, 10cm, 0.1m, 4in.
    #[arg(long, default_value = "100mm")]
    pub size: String,
    /// The thinnest part kept: thinner tubes are cut there (or thickened
    /// with --thicken), thinner balls and plates left out.
    #[arg(long, default_value = "0.8mm")]
    pub min_feature: String,
    /// How far a triangle may lie from the exact surface.
    #[arg(long, default_value = "0.05mm")]
    pub tolerance: String,
    /// Thicken tubes (edges, rods) to the minimum feature where they are
    /// thinner, instead of cutting them there.
    #[arg(long)]
    pub thicken: bool,
    /// The hyperbolic thickness that polygons and honeycomb faces are
    /// printed with (a render draws them with none).
    #[arg(long, default_value_t = 0.1)]
    pub face_thickness: f64,
    /// The most triangles to write (at most 20000000).
    #[arg(long, default_value_t = hexport::DEFAULT_MAX_TRIANGLES)]
    pub max_triangles: usize,
    /// The animation frame (0-based) to export; default 0.
    #[arg(long, default_value_t = 0)]
    pub frame: u32,
    /// Replace a read-only output.
    #[arg(long)]
    pub force: bool,
}

#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    /// The scene file.
    pub scene: PathBuf,
    /// Output image: .png, .tif, .tiff or .exr; for an animation also a
    /// video: .gif, .apng, .mp4 or .webm (the last two through ffmpeg).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Pixel net 0-4, overriding the scene's `net_type`.
    #[arg(long, value_parser = clap::value_parser!(u8).range(0..=4))]
    pub net: Option<u8>,
    /// Resolution WIDTHxHEIGHT, overriding the scene's.
    #[arg(long, value_parser = parse_resolution)]
    pub resolution: Option<(u32, u32)>,
    /// Sample depth of the output: 8, 16, or 32f (float TIFF or OpenEXR,
    /// linear, unclamped HDR). Default: 8, and 32f for .exr.
    #[arg(long)]
    pub depth: Option<Depth>,
    /// Transfer function of 8- and 16-bit samples: srgb (tagged as such) or
    /// linear (raw linear values, untagged, as the thesis wrote them).
    /// Float outputs are always linear.
    #[arg(long, value_name = "CURVE", default_value = "srgb")]
    pub encoding: EncodingArg,
    /// Tone curve of 8- and 16-bit samples: clip (clamp to 1), reinhard
    /// (x/(1+x)) or aces (filmic). Float outputs are never tone-mapped.
    #[arg(long, value_name = "CURVE", default_value = "clip")]
    pub tonemap: ToneMapArg,
    /// How hard a PNG output is deflated: zlib level 0 (stored) to 9
    /// (smallest). The default, 3, writes files about a seventh larger than
    /// level 6 in about half the time.
    #[arg(long, value_name = "0-9", default_value_t = hrender::PngLevel::DEFAULT.get(),
          value_parser = clap::value_parser!(u8).range(0..=i64::from(hrender::PngLevel::MAX)))]
    pub png_level: u8,
    /// Pixel layers written beside the colour, as extra channels of an
    /// `.exr` output: a comma-separated list of `depth` (channel Z, the
    /// hyperbolic distance along the pixel's central ray), `normal` (N.X,
    /// N.Y, N.Z, in the scene's ball coordinates), `id` (the object's
    /// number), `cell` (cell.rank, cell.class of a honeycomb's cell) and
    /// `word` (word.length, word.1..word.8: the faces crossed in a space),
    /// `albedo` (albedo.R, .G, .B: the first hit's reflectance, the
    /// denoiser's guide) and `noisy` (noisy.R, .G, .B: the picture before
    /// --denoise).
    #[arg(long, value_name = "LAYERS", value_parser = parse_aovs)]
    pub aov: Option<AovList>,
    /// Denoise the picture with Intel Open Image Denoise (as the scene's
    /// `denoise = true;`), guided by the first hit's albedo and normal;
    /// refused where the library is not installed (`python3 -m pip install
    /// oidn`; or HSCENE_OIDN=/path/to/libOpenImageDenoise.so).
    #[arg(long)]
    pub denoise: bool,
    /// Worker threads, 1 to 1024 (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=hrender::MAX_THREADS as i64))]
    pub threads: Option<u16>,
    /// Replace an existing output even when it is read-only.
    #[arg(long)]
    pub force: bool,
    /// Samples per pixel, overriding the scene's `samples` (default 1 = the
    /// pixel centre; a square number is stratified, any other jittered;
    /// box-filtered). `auto` samples each pixel until its noise (relative
    /// standard error) is at most `--noise`.
    #[arg(long, value_name = "N|auto", value_parser = parse_samples)]
    pub samples: Option<SamplesArg>,
    /// With `--samples auto`: the relative standard error each pixel stops
    /// at (default 0.01, one per cent).
    #[arg(long, value_name = "FRACTION")]
    pub noise: Option<f64>,
    /// With `--samples auto`: the most samples a pixel takes, a multiple of
    /// 16 (default 1024).
    #[arg(long, value_name = "N")]
    pub max_samples: Option<u32>,
    /// How light is computed, overriding the scene's `integrator`: whitted
    /// (the thesis's recursive ray tracing) or path (an unbiased path
    /// tracer: light bouncing between surfaces, emissive surfaces, glass
    /// with Fresnel).
    #[arg(long, value_name = "NAME", value_parser = parse_integrator)]
    pub integrator: Option<hrender::IntegratorKind>,
    /// Seed of the sample jitter; the same seed gives the same image.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Exposure correction in stops: radiance is multiplied by 2^EV before
    /// tone mapping and quantisation (and in float outputs). `auto` maps the
    /// log-average luminance of the lit pixels to 0.18 (the first frame's
    /// exposure is kept for the whole animation).
    #[arg(long, value_name = "EV|auto", default_value = "0", allow_negative_numbers = true, value_parser = parse_exposure)]
    pub exposure: ExposureArg,
    /// Frames per second of a video output (.gif, .apng, .mp4, .webm).
    #[arg(long, default_value_t = 24.0)]
    pub fps: f64,
    /// Render only this animation frame (0-based) to exactly OUTPUT. Without
    /// it, a scene with `frames = N` (N > 1) renders every frame to
    /// OUTPUT-0000.png, OUTPUT-0001.png, ...
    #[arg(long, value_name = "K")]
    pub frame: Option<u32>,
    /// Render only the rectangle of W x H pixels whose top-left pixel is
    /// (X, Y) of the whole image; tiles put side by side give the whole
    /// image exactly (docs/distributed.md).
    #[arg(long, value_name = "X,Y,W,H", value_parser = parse_crop)]
    pub crop: Option<hrender::Region>,
}

fn parse_crop(s: &str) -> Result<hrender::Region, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let [x, y, w, h] = parts.as_slice() else {
        return Err("expected X,Y,WIDTH,HEIGHT in pixels, e.g. 0,0,600,400".into());
    };
    let n = |v: &str, what: &str| {
        v.parse::<u32>()
            .map_err(|_| format!("bad {what} `{v}`: expected a whole number of pixels"))
    };
    let region = hrender::Region {
        x: n(x, "X")?,
        y: n(y, "Y")?,
        width: n(w, "width")?,
        height: n(h, "height")?,
    };
    if region.width == 0 || region.height == 0 {
        return Err("the crop must be at least 1x1 pixels".into());
    }
    Ok(region)
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Depth {
    #[value(name = "8")]
    Eight,
    #[value(name = "16")]
    Sixteen,
    #[value(name = "32f")]
    Float32,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum EncodingArg {
    /// The sRGB transfer function, tagged.
    Srgb,
    /// Raw linear values, untagged.
    Linear,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum ToneMapArg {
    /// Clamp to [0, 1].
    Clip,
    /// x / (1 + x).
    Reinhard,
    /// The ACES filmic curve (Narkowicz's fit).
    Aces,
}

/// `--samples`: a count, or adaptive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SamplesArg {
    /// This many per pixel.
    Count(u32),
    /// Until the noise target.
    Auto,
}

fn parse_samples(s: &str) -> Result<SamplesArg, String> {
    if s.trim() == "auto" {
        return Ok(SamplesArg::Auto);
    }
    let max = hrender::MAX_SAMPLES;
    match s.trim().parse::<u32>() {
        Ok(n) if (1..=max).contains(&n) => Ok(SamplesArg::Count(n)),
        _ => Err(format!(
            "expected a number of samples from 1 to {max}, or `auto`, not `{s}`"
        )),
    }
}

fn parse_integrator(s: &str) -> Result<hrender::IntegratorKind, String> {
    hrender::IntegratorKind::from_name(s.trim()).ok_or_else(|| {
        format!(
            "unknown integrator `{s}`: integrators are {}",
            hrender::IntegratorKind::names()
        )
    })
}

/// `--exposure`: fixed stops or chosen from the image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ExposureArg {
    /// This many stops.
    Stops(f64),
    /// From the log-average luminance.
    Auto,
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// Scene files to check; `-` reads a scene from stdin.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
    /// The file name to show in messages for a scene read from stdin (`-`);
    /// its directory is where relative mesh file names are found.
    #[arg(long, value_name = "PATH")]
    pub stdin_filename: Option<PathBuf>,
    /// Exit with status 1 when there are warnings, as for errors (for CI).
    #[arg(long)]
    pub deny_warnings: bool,
    /// Output format (default: human, in colour on a terminal only).
    #[arg(long)]
    pub format: Option<Format>,
    /// Also print the lowered scene: `ir` writes one JSON object per error-free
    /// scene to stdout (schema: docs/ir-schema.md); diagnostics then go to stderr.
    #[arg(long, value_name = "WHAT")]
    pub emit: Option<Emit>,
    /// The animation frame (0-based) to check and emit; default 0.
    #[arg(long, value_name = "K", default_value_t = 0)]
    pub frame: u32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Emit {
    /// The lowered IR as JSON, one line per scene.
    Ir,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// miette's graphical report.
    Human,
    /// `path:line:col: severity: message [CODE]`, one per line.
    Short,
    /// One JSON object per diagnostic, one per line.
    Json,
}

fn parse_exposure(s: &str) -> Result<ExposureArg, String> {
    if s.trim() == "auto" {
        return Ok(ExposureArg::Auto);
    }
    let ev: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("expected a number of stops, e.g. 2 or -1.5, or `auto`, not `{s}`"))?;
    let max = hrender::MAX_EXPOSURE;
    if !(ev.is_finite() && ev.abs() <= max) {
        return Err(format!("exposure must be from -{max} to {max} stops"));
    }
    Ok(ExposureArg::Stops(ev))
}

fn parse_resolution(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or("expected WIDTHxHEIGHT, e.g. 800x600")?;
    let w: u32 = w.trim().parse().map_err(|_| format!("bad width `{w}`"))?;
    let h: u32 = h.trim().parse().map_err(|_| format!("bad height `{h}`"))?;
    if w == 0 || h == 0 || w > 32_768 || h > 32_768 {
        return Err("each side must be from 1 to 32768 pixels".into());
    }
    if u64::from(w) * u64::from(h) > MAX_PIXELS {
        return Err(format!("at most {MAX_PIXELS} pixels in all"));
    }
    Ok((w, h))
}

/// `hscene fmt`: the canonical layout of scenes (docs/formatting.md).
#[derive(Debug, clap::Args)]
pub struct FmtArgs {
    /// Scene files to format in place; `-` formats stdin to stdout.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
    /// Change nothing; list the files that are not formatted (for stdin,
    /// print nothing) and exit with status 1 if there are any.
    #[arg(long)]
    pub check: bool,
    /// The file name to show in messages for a scene read from stdin (`-`).
    #[arg(long, value_name = "PATH")]
    pub stdin_filename: Option<PathBuf>,
    /// Replace a file that is read-only, has other hard links or belongs
    /// to another user (refused without it, as `render` refuses).
    #[arg(long)]
    pub force: bool,
}

/// The pixel layers of `--aov`, each once, in the order given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AovList(pub Vec<hrender::Aov>);

/// `--aov depth,normal`.
fn parse_aovs(list: &str) -> Result<AovList, String> {
    hrender::Aov::parse_list(list).map(AovList)
}
