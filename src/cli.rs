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
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
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
