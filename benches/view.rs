//! `hscene view`'s speed (README, "View"): a fixed flight through the
//! honeycomb view scene and the bunny-garden still life, with the viewer's
//! own pipeline (`hview::run_headless`: each move's coarse frame, then its
//! first full-resolution pass; at the end the still view converged).
//!
//! ```text
//! cargo bench --bench view                          # 480x270, 24 moves, 16 spp
//! cargo bench --bench view -- --resolution 960x540 --moves 48 --samples 16
//! ```
//!
//! It prints, per scene: frames per second while moving (coarse frames
//! only, as the window shows while keys are held, and coarse plus a full
//! pass), the time from a move to its coarse frame (mean and worst), and
//! the time for the still view to converge. The pictures are the
//! renderer's, so their error is the renderer's (docs/performance.md).

use std::process::ExitCode;
use std::time::Duration;

use hscene_lang::ir::Resolution;
use hview::{FlightPath, ViewOptions};

const SCENES: [&str; 2] = [
    "scenes/view/honeycomb-435.hsc",
    "scenes/showcase/bunny-garden.hsc",
];

fn ms(d: &Duration) -> f64 {
    d.as_secs_f64() * 1000.0
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| {
        args.iter()
            .position(|a| a == name)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let (w, h) = value("--resolution")
        .and_then(|r| {
            let (w, h) = r.split_once('x')?;
            Some((w.parse().ok()?, h.parse().ok()?))
        })
        .unwrap_or((480u32, 270u32));
    let moves: u32 = value("--moves").and_then(|m| m.parse().ok()).unwrap_or(24);
    let samples: u32 = value("--samples")
        .and_then(|m| m.parse().ok())
        .unwrap_or(16);
    let Some(resolution) = Resolution::new(w, h) else {
        eprintln!("bad --resolution");
        return ExitCode::FAILURE;
    };
    println!(
        "hscene view, {w}x{h}, {moves} moves, still to {samples} spp, {} threads",
        std::thread::available_parallelism().map_or(1, |n| n.get())
    );
    println!(
        "| scene | moving fps (coarse) | moving fps (coarse + full pass) | move to coarse frame, mean / worst | still to {samples} spp |"
    );
    println!("|---|---|---|---|---|");
    for path in SCENES {
        let Ok(source) = std::fs::read_to_string(path) else {
            eprintln!("{path}: not found (run from the repository root)");
            return ExitCode::FAILURE;
        };
        let options = hscene_lang::Options {
            base_dir: std::path::Path::new(path).parent().map(|p| p.to_path_buf()),
            frame: 0,
            ..Default::default()
        };
        let Some(scene) = hscene_lang::compile_with(&source, &options).scene else {
            eprintln!("{path}: does not compile");
            return ExitCode::FAILURE;
        };
        let view = ViewOptions {
            resolution,
            net: None,
            integrator: None,
            samples,
            coarse: 4,
            exposure: 0.0,
            threads: None,
            denoise: false,
        };
        let report = match hview::run_headless(&scene, view, &FlightPath::default_flight(moves)) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("{path}: {e}");
                return ExitCode::FAILURE;
            }
        };
        let n = report.moves.max(1) as f64;
        let coarse = ms(&report.to_coarse) / n;
        let full = ms(&report.full_pass) / n;
        let worst = ms(&report.worst_coarse);
        println!(
            "| {path} | {:.1} | {:.1} | {coarse:.1} / {worst:.1} ms | {:.0} ms |",
            1000.0 / coarse.max(1e-9),
            1000.0 / (coarse + full).max(1e-9),
            ms(&report.converge)
        );
    }
    ExitCode::SUCCESS
}
