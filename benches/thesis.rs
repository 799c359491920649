//! The thesis's speed tables (thesis §8.5, Tables 2 and 3; docs/gallery.md), measured
//! on our renderer next to the error of the hits, and optionally next to
//! POV-Ray rendering the Euclidean twin of each scene.
//!
//! ```text
//! cargo bench --bench thesis                 # the table
//! cargo bench --bench thesis -- --json       # the same as JSON
//! cargo bench --bench thesis -- --povray     # add POV-Ray 3.7 timings (needs `povray`)
//! cargo bench --bench thesis -- --resolution 400   # quicker, smaller
//! ```
//!
//! Scenes ("h-spheres": 1..16 spheres with 1 light / recursion 0, 5 lights /
//! recursion 0, 5 lights / recursion 1; "h-cylinders": 1..8 h-cylinders with
//! 1 and 5 lights) are generated as scene text, compiled by hscene-lang and
//! rendered through net 0 at 1000x1000, as in the thesis. The error column is
//! the max and median hyperbolic distance between the renderer's primary hit
//! points and a 320-bit recomputation, on a 48x48 grid of pixels.

use std::process::ExitCode;
use std::time::Instant;

use hrender::RenderOptions;
use hscene_lang::ir::{Net, Resolution};

// The scale bench uses all of it, this one a part: CPU time and peak memory
// of POV-Ray are not in the thesis's tables.
#[allow(dead_code)]
mod common;
use common::thesis_scenes::{Case, cases, pov_source, scene_source};

/// Wall time of POV-Ray rendering the twin, if `povray` runs.
fn povray_seconds(c: &Case, resolution: u32) -> Option<f64> {
    common::povray(&pov_source(c, resolution), resolution, None)
        .ok()
        .map(|m| m.wall_s)
}

struct Row {
    name: String,
    count: usize,
    lights: usize,
    depth: u32,
    thesis_s: f64,
    seconds: f64,
    mrays_per_s: f64,
    max_error: f64,
    median_error: f64,
    sampled: usize,
    povray_s: Option<f64>,
}

fn main() -> ExitCode {
    common::measure_child_if_asked();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let json = args.iter().any(|a| a == "--json");
    let povray = args.iter().any(|a| a == "--povray");
    let resolution: u32 = common::arg_value(&args, "--resolution")
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let mut rows = Vec::new();
    for c in cases() {
        let source = scene_source(&c, resolution);
        let compiled = hscene_lang::compile(&source);
        let Some(scene) = compiled.scene else {
            eprintln!("scene for {} x{} does not compile:", c.kind.name(), c.count);
            for d in compiled.diagnostics {
                eprintln!("  {}", d.message);
            }
            return ExitCode::FAILURE;
        };
        let options = RenderOptions {
            net: Some(Net::Euclidean),
            resolution: Resolution::new(resolution, resolution),
            ..RenderOptions::default()
        };
        let start = Instant::now();
        let rendered = match hrender::render(&scene, &options, &|_| {}) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("render failed: {e}");
                return ExitCode::FAILURE;
            }
        };
        let seconds = start.elapsed().as_secs_f64();
        let errors = match common::Probe::new(&scene, 48) {
            Ok(probe) => common::hit_errors(&scene, &probe),
            Err(e) => {
                eprintln!("error measurement failed: {e}");
                return ExitCode::FAILURE;
            }
        };
        rows.push(Row {
            name: c.kind.name().to_string(),
            count: c.count,
            lights: c.lights,
            depth: c.depth,
            thesis_s: c.thesis_s,
            seconds,
            mrays_per_s: rendered.stats.rays as f64 / seconds / 1e6,
            max_error: errors.max,
            median_error: errors.median,
            sampled: errors.sampled,
            povray_s: if povray {
                povray_seconds(&c, resolution)
            } else {
                None
            },
        });
    }
    let povray_cell = |r: &Row, none: &str, digits: usize| {
        r.povray_s
            .map_or(none.to_string(), |s| format!("{s:.digits$}"))
    };
    if json {
        let items: Vec<String> = rows
            .iter()
            .map(|r| {
                format!(
                    "{{\"scene\": \"{}\", \"objects\": {}, \"lights\": {}, \"recursion\": {}, \"resolution\": {resolution}, \"thesis_s\": {}, \"seconds\": {:.4}, \"mrays_per_s\": {:.3}, \"hit_error_max\": {:e}, \"hit_error_median\": {:e}, \"hit_error_unit\": \"hyperbolic distance\", \"hits_sampled\": {}, \"povray_s\": {}}}",
                    r.name,
                    r.count,
                    r.lights,
                    r.depth,
                    r.thesis_s,
                    r.seconds,
                    r.mrays_per_s,
                    r.max_error,
                    r.median_error,
                    r.sampled,
                    povray_cell(r, "null", 4)
                )
            })
            .collect();
        println!("[\n  {}\n]", items.join(",\n  "));
    } else {
        println!(
            "{resolution}x{resolution}, net 0, {} threads; errors: hyperbolic distance of primary hits vs 320-bit reference",
            rayon_threads()
        );
        println!(
            "{:<12} {:>4} {:>6} {:>5} {:>10} {:>9} {:>9} {:>10} {:>10} {:>5} {:>10}",
            "scene",
            "n",
            "lights",
            "depth",
            "thesis s",
            "ours s",
            "Mrays/s",
            "err max",
            "err median",
            "hits",
            "POV-Ray s"
        );
        for r in &rows {
            println!(
                "{:<12} {:>4} {:>6} {:>5} {:>10.1} {:>9.3} {:>9.2} {:>10.1e} {:>10.1e} {:>5} {:>10}",
                r.name,
                r.count,
                r.lights,
                r.depth,
                r.thesis_s,
                r.seconds,
                r.mrays_per_s,
                r.max_error,
                r.median_error,
                r.sampled,
                povray_cell(r, "-", 3)
            );
        }
    }
    ExitCode::SUCCESS
}

fn rayon_threads() -> usize {
    std::thread::available_parallelism().map_or(1, usize::from)
}
