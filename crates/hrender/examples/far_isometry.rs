//! The far-isometry table: a scene with every kind of object, moved with its
//! eye and lights by translations of length 10, 15, 20, 25 and 30 in several
//! directions, rendered on every pixel net and compared with the unmoved
//! picture (`hscene_test_support::far`).
//!
//! `cargo run --release -p hrender --example far_isometry -- [--size N]
//! [--dirs K] [--seed S] [--distances 10,15,20,25,30] [--out DIR]`
//!
//! Prints, per distance and net, the worst fraction of pixels within 1/255
//! of the unmoved image over the `K` directions, whether `check` drew the
//! same warnings, and the numeric failures counted. With `--out` the unmoved
//! and the worst moved image of each net are written there to look at.

use std::path::PathBuf;

use hgeom::glam::DVec3;
use hrender::{SampleDepth, write_image};
use hscene_test_support::SplitMix64;
use hscene_test_support::far::{self, NETS, far_case, far_scene_source, render_source};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut size = 48u32;
    let mut dirs = 3usize;
    let mut distances = vec![10.0, 15.0, 20.0, 25.0, 30.0];
    let mut out: Option<PathBuf> = None;
    let mut seed = 12u64;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = || args.next().ok_or(format!("{a} needs a value"));
        match a.as_str() {
            "--size" => size = value()?.parse()?,
            "--dirs" => dirs = value()?.parse()?,
            "--distances" => {
                distances = value()?
                    .split(',')
                    .map(str::parse)
                    .collect::<Result<_, _>>()?
            }
            "--out" => out = Some(PathBuf::from(value()?)),
            "--seed" => seed = value()?.parse()?,
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    let mut rng = SplitMix64::new(seed);
    let directions: Vec<DVec3> = (0..dirs).map(|_| rng.direction()).collect();
    println!("worst fraction of pixels within 1/255 over {dirs} directions, {size}x{size}");
    println!("| d | net 0 | net 1 | net 2 | net 3 | net 4 | same warnings | failures |");
    println!("|---|---|---|---|---|---|---|---|");
    let bases: Vec<_> = (0..NETS.len())
        .map(|net| render_source(&far_scene_source(net, size, 0.0, DVec3::Z)))
        .collect::<Result<_, _>>()?;
    if let Some(dir) = &out {
        for (net, (img, _)) in bases.iter().enumerate() {
            write_image(
                img,
                &dir.join(format!("far-net{net}-base.png")),
                SampleDepth::Eight,
            )?;
        }
    }
    for &d in &distances {
        let mut row = format!("| {d} |");
        let mut warnings_ok = true;
        let mut failures = 0;
        let mut errors = std::collections::BTreeSet::new();
        for (net, (base, _)) in bases.iter().enumerate() {
            let mut worst = (f64::INFINITY, DVec3::Z);
            for &dir in &directions {
                let case = far_case(net, size, d, dir, base);
                warnings_ok &= case.same_warnings;
                failures += case.failures;
                for (line, w) in &case.moved_warnings {
                    errors.insert(format!("net {net}: line {line}: {w}"));
                }
                if let Some(e) = &case.error {
                    errors.insert(e.clone());
                }
                if case.share < worst.0 {
                    worst = (case.share, dir);
                }
            }
            row.push_str(&format!(" {:.4} |", worst.0));
            if let Some(dir) = &out {
                let src = far_scene_source(net, size, d, worst.1);
                std::fs::write(dir.join(format!("far-net{net}-d{d}.hsc")), &src)?;
                if let Ok((img, _)) = render_source(&src) {
                    write_image(
                        &img,
                        &dir.join(format!("far-net{net}-d{d}.png")),
                        SampleDepth::Eight,
                    )?;
                    // Where they differ, white: to see which object moved.
                    let diff: Vec<[f32; 3]> = img
                        .pixels()
                        .iter()
                        .zip(base.pixels())
                        .map(|(p, q)| {
                            let bad = (0..3).any(|c| (p[c] - q[c]).abs() > 1.0 / 255.0);
                            if bad { [1.0; 3] } else { [0.0; 3] }
                        })
                        .collect();
                    let diff = hrender::Image::from_pixels(img.width(), img.height(), diff);
                    write_image(
                        &diff,
                        &dir.join(format!("far-net{net}-d{d}-diff.png")),
                        SampleDepth::Eight,
                    )?;
                }
            }
        }
        row.push_str(&format!(
            " {} | {failures} |",
            if warnings_ok { "yes" } else { "no" }
        ));
        println!("{row}");
        for e in errors {
            eprintln!("  d {d}: {e}");
        }
        if !warnings_ok {
            let base = far::warnings(&far_scene_source(0, size, 0.0, DVec3::Z));
            eprintln!("  unmoved warnings: {base:?}");
        }
    }
    Ok(())
}
