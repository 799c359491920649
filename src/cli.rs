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
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene to a PNG or TIFF image.
    Render(RenderArgs),
    /// Check scenes for errors and warnings without rendering.
    Check(CheckArgs),
}

#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    /// The scene file.
    pub scene: PathBuf,
    /// Output image: .png, .tif or .tiff.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Pixel net 0-4, overriding the scene's `net_type`.
    #[arg(long, value_parser = clap::value_parser!(u8).range(0..=4))]
    pub net: Option<u8>,
    /// Resolution WIDTHxHEIGHT, overriding the scene's.
    #[arg(long, value_parser = parse_resolution)]
    pub resolution: Option<(u32, u32)>,
    /// Sample depth of the output: 8, 16, or 32f (float TIFF, unclamped HDR).
    #[arg(long, default_value = "8")]
    pub depth: Depth,
    /// Worker threads, 1 to 1024 (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=hrender::MAX_THREADS as i64))]
    pub threads: Option<u16>,
    /// Replace an existing output even when it is read-only.
    #[arg(long)]
    pub force: bool,
    /// Samples per pixel for anti-aliasing, overriding the scene's
    /// `samples` (default 1 = the pixel centre; a square number is
    /// stratified, any other jittered; box-filtered).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=i64::from(hrender::MAX_SAMPLES)))]
    pub samples: Option<u32>,
    /// Seed of the sample jitter; the same seed gives the same image.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Exposure correction in stops: radiance is multiplied by 2^EV before
    /// quantisation (and in float TIFF output).
    #[arg(long, value_name = "EV", default_value_t = 0.0, allow_negative_numbers = true, value_parser = parse_exposure)]
    pub exposure: f64,
    /// Render only this animation frame (0-based) to exactly OUTPUT. Without
    /// it, a scene with `frames = N` (N > 1) renders every frame to
    /// OUTPUT-0000.png, OUTPUT-0001.png, ...
    #[arg(long, value_name = "K")]
    pub frame: Option<u32>,
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

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// Scene files to check.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
    /// Output format (default: human on a terminal, short otherwise).
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

fn parse_exposure(s: &str) -> Result<f64, String> {
    let ev: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("expected a number of stops, e.g. 2 or -1.5, not `{s}`"))?;
    let max = hrender::MAX_EXPOSURE;
    if !(ev.is_finite() && ev.abs() <= max) {
        return Err(format!("exposure must be from -{max} to {max} stops"));
    }
    Ok(ev)
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
