//! Render the programmatic test scenes to PNG files and print timings.
//!
//! `cargo run --release -p hrender --example gallery -- OUT_DIR [SIZE]`
//!
//! Used to look at the scenes the integration tests build (rods, cylinders,
//! polyhedra, wireframes, horospheres) and to time the renderer on a scene
//! with many rods.

use std::path::PathBuf;
use std::time::Instant;

use hrender::{RenderOptions, SampleDepth, render, write_image};
use hscene_ir::{Net, Scene};
use hscene_test_support::scenes;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let dir = PathBuf::from(args.next().unwrap_or_else(|| "/tmp".into()));
    let size: u32 = args.next().map_or(Ok(300), |s| s.parse())?;
    let only = args.next();
    let scenes: Vec<(&str, Scene)> = vec![
        ("many-rods", scenes::many_rods_scene(300, size)),
        ("many-cells", scenes::many_cells_scene(6, size)),
        ("mixed", scenes::mixed_scene(Net::Euclidean, size, 0.2)),
        ("mixed-net2", scenes::mixed_scene(Net::GreatDisk, size, 0.6)),
        (
            "mixed-net4",
            scenes::mixed_scene(Net::EquidistantInterpolated, size, 0.6),
        ),
        ("solids", scenes::solids_scene(Net::Euclidean, size, 0.3)),
    ];
    for (name, scene) in scenes {
        if only.as_deref().is_some_and(|o| o != name) {
            continue;
        }
        let started = Instant::now();
        let out = render(&scene, &RenderOptions::default(), &|_| {})?;
        let secs = started.elapsed().as_secs_f64();
        let path = dir.join(format!("{name}.png"));
        write_image(&out.image, &path, SampleDepth::Eight)?;
        println!(
            "{name}: {size}x{size}, {} objects, {} rays, {} numeric failures, {secs:.3} s -> {}",
            scene.objects.len(),
            out.stats.rays,
            out.stats.numeric_failures,
            path.display()
        );
    }
    Ok(())
}
