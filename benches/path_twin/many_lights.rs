//! The many-light twins of the path bench: the flat Cornell box (no
//! glowing ball) lit by 1 or 64 point lights, or by 1 or 64 emissive
//! triangles just under the ceiling, each rendered by hscene and by its
//! Euclidean twin in Mitsuba 3 with the independent and the stratified
//! sampler. Every renderer's error is measured against its own converged
//! reference (16x the samples), so the comparison is of noise alone; the
//! twins' mean luminances are printed beside it as a check that they are
//! the same scene.

use std::path::Path;

use super::{
    Box3, Run, cornell, cornell_hsc, cornell_json, equal_error_cpu, hscene_run, line, mean,
    mitsuba_installed, mitsuba_run, relative_error,
};

/// The flat scale, as the Cornell box's flat limit.
const FLAT: f64 = 1e-3;

/// The total radiant intensity of the point lights (W/sr, Euclidean):
/// about the glowing ball's of the Cornell box.
const INTENSITY: [f64; 3] = [2.0, 1.87, 1.6];

/// The radiance of the emissive triangles.
const RADIANCE: [f64; 3] = [12.0, 11.0, 10.0];

/// The box without its glowing ball.
fn dark_box() -> Box3 {
    let mut b = cornell();
    b.spheres.retain(|s| s.emission == [0.0; 3]);
    b
}

/// `count` point lights (1, or a 4x4x4 grid) sharing [`INTENSITY`], in
/// slightly different colours.
fn points(count: u32) -> Box3 {
    let mut b = dark_box();
    if count == 1 {
        b.points.push(([0.0, 0.7, 2.0], INTENSITY));
        return b;
    }
    let n = f64::from(count);
    for k in 0..count {
        let (i, j, l) = (k % 4, (k / 4) % 4, k / 16);
        let at = |g: u32, lo: f64, hi: f64| lo + (hi - lo) * f64::from(g) / 3.0;
        let tint = [
            1.0 + 0.3 * f64::from(k % 3),
            1.0,
            1.0 + 0.3 * f64::from(k % 2),
        ];
        b.points.push((
            [at(i, -0.7, 0.7), at(j, 0.0, 0.8), at(l, 1.3, 2.7)],
            [0, 1, 2].map(|c| INTENSITY[c] * tint[c] / n),
        ));
    }
    b
}

/// `count` emissive triangles facing down under the ceiling: one large,
/// or the halves of an 8x8 grid of cells (half the triangles of 4x8).
fn triangles(count: u32) -> Box3 {
    let mut b = dark_box();
    let y = 0.98;
    // Winding (a, c, b) so that (b - a) x (c - a) points down (-y).
    let tri = |x0: f64, z0: f64, s: f64, flip: bool| {
        if flip {
            [[x0 + s, y, z0 + s], [x0, y, z0 + s], [x0 + s, y, z0]]
        } else {
            [[x0, y, z0], [x0 + s, y, z0], [x0, y, z0 + s]]
        }
    };
    if count == 1 {
        b.emitters.push((tri(-0.6, 1.4, 1.2, false), RADIANCE));
        return b;
    }
    // 64 triangles: a 4x8 grid of cells, each cut in two.
    let s = 1.2 / 8.0;
    for k in 0..count {
        let cell = k / 2;
        let (i, j) = (cell % 8, cell / 8);
        let (x0, z0) = (-0.6 + s * f64::from(i), 1.4 + 2.0 * s * f64::from(j));
        b.emitters.push((tri(x0, z0, s, k % 2 == 1), RADIANCE));
    }
    b
}

/// One scene's five runs and their errors.
struct Twins {
    hscene: (Run, f64),
    independent: (Run, f64),
    stratified: (Run, f64),
}

/// Render `name` (the box `b`) by hscene and its twins; prints the lines.
fn twins(
    hscene: &Path,
    dir: &Path,
    name: &str,
    b: &Box3,
    (size, spp, fov): (u32, u32, f64),
    threads: Option<usize>,
) -> Result<Twins, String> {
    std::fs::write(
        dir.join(format!("{name}.hsc")),
        cornell_hsc(b, FLAT, size, fov),
    )
    .map_err(|e| e.to_string())?;
    let pixels = size * size;
    let reference = hscene_run(hscene, dir, name, spp * 16, 7, threads)?;
    let run = hscene_run(hscene, dir, name, spp, 1, threads)?;
    let error = relative_error(&run.image, &reference.image);
    line(name, "hscene", spp, pixels, &run, error);
    let json = |spp: u32, seed: u64, sampler: &str| cornell_json(b, size, fov, spp, seed, sampler);
    let twin_ref = mitsuba_run(
        dir,
        &json(spp * 16, 7, "independent"),
        &format!("{name}-mi-ref"),
    )?;
    let mut runs = Vec::new();
    for sampler in ["independent", "stratified"] {
        let r = mitsuba_run(dir, &json(spp, 1, sampler), &format!("{name}-mi-{sampler}"))?;
        let e = relative_error(&r.image, &twin_ref.image);
        let who = if sampler == "independent" {
            "mi-indep"
        } else {
            "mi-strat"
        };
        line(name, who, spp, pixels, &r, e);
        runs.push((r, e));
    }
    let (m_h, m_m) = (mean(&reference.image), mean(&twin_ref.image));
    let stratified = runs.pop().ok_or("no stratified run")?;
    let independent = runs.pop().ok_or("no independent run")?;
    println!(
        "{name:<16} equal-error CPU hscene/mitsuba: {:.2}x (independent), {:.2}x (stratified); mean luminance hscene {m_h:.5}, mitsuba {m_m:.5} ({:+.1} %)",
        equal_error_cpu(&run, error, &independent.0, independent.1),
        equal_error_cpu(&run, error, &stratified.0, stratified.1),
        100.0 * (m_h / m_m - 1.0)
    );
    Ok(Twins {
        hscene: (run, error),
        independent,
        stratified,
    })
}

/// CPU seconds per pixel sample.
fn per_sample(run: &Run, samples: f64) -> f64 {
    run.measured.cpu_s / samples
}

/// The many-light section of the bench; `Ok(true)` (it checks no
/// agreement: the twins differ where the triangles' top sides light the
/// ceiling in hscene, which emits from both sides).
pub fn run(
    hscene: &Path,
    dir: &Path,
    size: u32,
    spp: u32,
    threads: Option<usize>,
) -> Result<bool, String> {
    if !mitsuba_installed() {
        println!("many lights: mitsuba not installed (pip install mitsuba numpy)");
        return Ok(true);
    }
    println!(
        "many lights, {size}x{size}, {spp} samples per pixel; each renderer's error against its own reference (16x the samples)"
    );
    let shape = (size, spp, 70.0);
    let samples = f64::from(spp) * f64::from(size * size);
    for (kind, make) in [
        ("points", points as fn(u32) -> Box3),
        ("triangles", triangles),
    ] {
        let one = twins(hscene, dir, &format!("{kind}-1"), &make(1), shape, threads)?;
        let many = twins(
            hscene,
            dir,
            &format!("{kind}-64"),
            &make(64),
            shape,
            threads,
        )?;
        let growth =
            |a: &(Run, f64), b: &(Run, f64)| per_sample(&b.0, samples) / per_sample(&a.0, samples);
        println!(
            "{kind}: CPU per sample at 64 lights over 1: hscene {:.2}x, mitsuba {:.2}x (independent), {:.2}x (stratified); hscene {:.2} us per sample at 64",
            growth(&one.hscene, &many.hscene),
            growth(&one.independent, &many.independent),
            growth(&one.stratified, &many.stratified),
            1e6 * per_sample(&many.hscene.0, samples)
        );
    }
    Ok(true)
}
