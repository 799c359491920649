//! The path integrator: speed against error, and the flat limit against
//! Mitsuba 3.
//!
//! ```sh
//! pip install mitsuba numpy                 # once: the Euclidean reference renderer
//! cargo bench --bench path                  # 64x64, 256 samples per pixel
//! cargo bench --bench path -- --resolution 96 --samples 1024
//! cargo bench --bench path -- --threads 1
//! cargo bench --bench path -- --keep /tmp/p   # keep the scenes, twins and images
//! cargo bench --bench path -- --scenes cornell-flat   # some of the scenes
//! cargo bench --bench path -- --no-many       # without the many-light twins
//! ```
//!
//! Three scenes, each rendered by `hscene render --integrator path` as a
//! measured child process (CPU time user+sys, wall time), and its relative
//! error printed next to its speed: the RMS difference of the pixel
//! luminances from a converged reference (the same renderer at sixteen
//! times the samples), over the mean luminance.
//!
//! - `cornell-flat`: a Cornell box (red and green walls, two spheres, an
//!   emitting sphere as the light), a thousandth of a unit across around
//!   the eye: Euclidean to within `r²/6 ≈ 2e-7` (docs/geometry.md, "The
//!   flat limit"). Its Euclidean twin, the same box a thousand times larger,
//!   is rendered by Mitsuba 3 (`scalar_rgb`, `path` integrator, box
//!   filter) at the same resolution and samples, timed the same way. The
//!   bench checks that the two agree: Mitsuba's image differs from hscene's
//!   converged reference by noise alone (every 8x8 block's mean within
//!   five standard errors, the image mean within four). It exits 1 if
//!   they do not.
//! - `cornell-h3`: the same box at a scale of 0.7, where hyperbolic geometry
//!   changes it (no Euclidean twin).
//! - `honeycomb-glass`: the `{4,3,5}` honeycomb walked with glass faces
//!   (index 1.3, Fresnel) and emissive vertices.
//!
//! - many lights (`path_twin/many_lights.rs`): the flat box lit by 1 or 64
//!   point lights, or by 1 or 64 emissive triangles under the ceiling,
//!   each against its Mitsuba twin with the independent and the
//!   stratified sampler; every renderer's error against its own converged
//!   reference; CPU time for equal error, and the cost of a sample at 1
//!   and at 64 lights.
//!
//! Samples per second are pixel samples (camera paths) per CPU second.

// POV-Ray and the hit errors are the scene benches'; this one measures light.
#[allow(dead_code)]
mod common;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use common::{Measured, arg_value, hscene_binary, measure};

#[path = "path_twin/many_lights.rs"]
mod many_lights;

/// A Cornell box in Euclidean units: the eye at the origin looking along
/// +z, the box `x, y ∈ [-1, 1]`, `z ∈ [1, 3]`, open towards the eye.
struct Box3 {
    /// Triangles (three corners) with their albedo.
    triangles: Vec<([[f64; 3]; 3], [f64; 3])>,
    /// Quads (four corners in order) with their albedo, for the twin.
    quads: Vec<([[f64; 3]; 4], [f64; 3])>,
    spheres: Vec<Ball>,
    /// Point lights: position and Euclidean radiant intensity (W/sr).
    points: Vec<([f64; 3], [f64; 3])>,
    /// Emissive triangles (three corners) with their radiance, emitting
    /// towards `(b - a) × (c - a)` in the twin (one-sided in Mitsuba).
    emitters: Vec<([[f64; 3]; 3], [f64; 3])>,
}

/// A sphere of the box.
struct Ball {
    centre: [f64; 3],
    radius: f64,
    albedo: [f64; 3],
    emission: [f64; 3],
}

/// The scale of the hyperbolic box: one hyperbolic unit per 1/0.7 of the
/// Euclidean box's, where the walls already bow in (its geodesic triangles
/// lie nearer the eye than the flat ones) and the light falls off as
/// `1 / sinh² r`.
const H3_SCALE: f64 = 0.7;

const WHITE: [f64; 3] = [0.75, 0.75, 0.75];
const RED: [f64; 3] = [0.7, 0.15, 0.12];
const GREEN: [f64; 3] = [0.15, 0.6, 0.2];
const LIGHT: [f64; 3] = [30.0, 28.0, 24.0];

fn cornell() -> Box3 {
    let quads = vec![
        // left, right, floor, ceiling, back
        (
            [
                [-1.0, -1.0, 1.0],
                [-1.0, -1.0, 3.0],
                [-1.0, 1.0, 3.0],
                [-1.0, 1.0, 1.0],
            ],
            RED,
        ),
        (
            [
                [1.0, -1.0, 1.0],
                [1.0, 1.0, 1.0],
                [1.0, 1.0, 3.0],
                [1.0, -1.0, 3.0],
            ],
            GREEN,
        ),
        (
            [
                [-1.0, -1.0, 1.0],
                [1.0, -1.0, 1.0],
                [1.0, -1.0, 3.0],
                [-1.0, -1.0, 3.0],
            ],
            WHITE,
        ),
        (
            [
                [-1.0, 1.0, 1.0],
                [-1.0, 1.0, 3.0],
                [1.0, 1.0, 3.0],
                [1.0, 1.0, 1.0],
            ],
            WHITE,
        ),
        (
            [
                [-1.0, -1.0, 3.0],
                [1.0, -1.0, 3.0],
                [1.0, 1.0, 3.0],
                [-1.0, 1.0, 3.0],
            ],
            WHITE,
        ),
    ];
    let triangles = quads
        .iter()
        .flat_map(|(q, c)| [([q[0], q[1], q[2]], *c), ([q[0], q[2], q[3]], *c)])
        .collect();
    Box3 {
        triangles,
        quads,
        spheres: vec![
            Ball {
                centre: [-0.4, -0.6, 2.3],
                radius: 0.4,
                albedo: WHITE,
                emission: [0.0; 3],
            },
            Ball {
                centre: [0.45, -0.65, 1.8],
                radius: 0.35,
                albedo: WHITE,
                emission: [0.0; 3],
            },
            Ball {
                centre: [0.0, 0.5, 2.0],
                radius: 0.15,
                albedo: [0.0; 3],
                emission: LIGHT,
            },
        ],
        points: Vec::new(),
        emitters: Vec::new(),
    }
}

/// The ball coordinates of the point at hyperbolic distance `scale |p|`
/// from the origin in the direction of `p` (geodesic polar coordinates, so
/// that the box is `scale` times its Euclidean self to first order).
fn ball(p: [f64; 3], scale: f64) -> String {
    let len = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    let k = (scale * len / 2.0).tanh() / len;
    format!("({:.17e}, {:.17e}, {:.17e})", p[0] * k, p[1] * k, p[2] * k)
}

fn rgb(c: [f64; 3]) -> String {
    format!("({}, {}, {})", c[0], c[1], c[2])
}

/// The box at `scale` as an hscene scene.
fn cornell_hsc(b: &Box3, scale: f64, size: u32, fov: f64) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Globals {{ resolution = ({size}, {size}); fov = {fov}; integrator = path; \
         background = (0, 0, 0); }}"
    );
    s.push_str("BRDFs {\n");
    let mut materials = Vec::new();
    let mut material = |albedo: [f64; 3], emission: [f64; 3], s: &mut String| {
        let k = materials.len() + 1;
        materials.push(k);
        let _ = writeln!(
            s,
            "  m{k}: diffuse = {}, emission = {};",
            rgb(albedo),
            rgb(emission)
        );
        k
    };
    let mut objects = String::new();
    for (t, c) in &b.triangles {
        let k = material(*c, [0.0; 3], &mut s);
        let _ = writeln!(
            objects,
            "  Polygon ({}, {}, {}), #m{k};",
            ball(t[0], scale),
            ball(t[1], scale),
            ball(t[2], scale)
        );
    }
    for sphere in &b.spheres {
        let k = material(sphere.albedo, sphere.emission, &mut s);
        let _ = writeln!(
            objects,
            "  Sphere {}, {}, #m{k};",
            ball(sphere.centre, scale),
            sphere.radius * scale
        );
    }
    for (t, e) in &b.emitters {
        let k = material([0.0; 3], *e, &mut s);
        let _ = writeln!(
            objects,
            "  Polygon ({}, {}, {}), #m{k};",
            ball(t[0], scale),
            ball(t[1], scale),
            ball(t[2], scale)
        );
    }
    if !b.points.is_empty() {
        // A point light of colour Φ gives `Φ / (4 sinh² r)` at hyperbolic
        // distance `r = scale r_e`: Euclidean intensity `I` is `Φ = 4 I
        // scale²` to first order.
        s.push_str("}\nLights {\n");
        for (p, i) in &b.points {
            let k = 4.0 * scale * scale;
            let _ = writeln!(
                s,
                "  {}, ({:e}, {:e}, {:e}), (0, 0, 0);",
                ball(*p, scale),
                i[0] * k,
                i[1] * k,
                i[2] * k
            );
        }
    }
    s.push_str("}\nObjects {\n");
    s.push_str(&objects);
    s.push_str("}\n");
    s
}

/// The box as Mitsuba twin JSON (benches/path_twin/mitsuba_twin.py).
fn cornell_json(b: &Box3, size: u32, fov: f64, spp: u32, seed: u64, sampler: &str) -> String {
    let v = |p: [f64; 3]| format!("[{}, {}, {}]", p[0], p[1], p[2]);
    let spheres: Vec<String> = b
        .spheres
        .iter()
        .map(|b| {
            format!(
                "{{\"center\": {}, \"radius\": {}, \"albedo\": {}, \"emission\": {}}}",
                v(b.centre),
                b.radius,
                v(b.albedo),
                v(b.emission)
            )
        })
        .collect();
    let quads: Vec<String> = b
        .quads
        .iter()
        .map(|(q, a)| {
            let corners: Vec<String> = q.iter().map(|p| v(*p)).collect();
            format!(
                "{{\"corners\": [{}], \"albedo\": {}, \"emission\": [0, 0, 0]}}",
                corners.join(", "),
                v(*a)
            )
        })
        .collect();
    let points: Vec<String> = b
        .points
        .iter()
        .map(|(p, i)| format!("{{\"position\": {}, \"intensity\": {}}}", v(*p), v(*i)))
        .collect();
    let triangles: Vec<String> = b
        .emitters
        .iter()
        .map(|(t, e)| {
            format!(
                "{{\"corners\": [{}, {}, {}], \"emission\": {}}}",
                v(t[0]),
                v(t[1]),
                v(t[2]),
                v(*e)
            )
        })
        .collect();
    format!(
        "{{\"resolution\": [{size}, {size}], \"fov\": {fov}, \"spp\": {spp}, \"seed\": {seed}, \
         \"sampler\": \"{sampler}\", \"max_depth\": -1, \"spheres\": [{}], \"quads\": [{}], \
         \"points\": [{}], \"triangles\": [{}]}}",
        spheres.join(", "),
        quads.join(", "),
        points.join(", "),
        triangles.join(", ")
    )
}

/// The `{4,3,5}` honeycomb from inside a cell: glass faces, gold edges,
/// emissive vertices.
fn honeycomb_hsc(size: u32) -> String {
    format!(
        "Globals {{ resolution = ({size}, {size}); from = (0.02, 0.03, 0.01); to = (0.06, 0.09, 0.4);
                    fov = 100; integrator = path; background = (0.02, 0.02, 0.03); }}
         BRDFs {{ glass: diffuse = (0.02, 0.04, 0.08), trans = 0.9, refraction = 1.3;
                  gold: diffuse = (0.9, 0.7, 0.35), specular = (0.3, 0.3, 0.3), shininess = 40;
                  lamp: diffuse = (0.5, 0.5, 0.5), emission = (6, 5, 4); }}
         Objects {{ Honeycomb {{4,3,5}}, #gold, edges = 0.025, vertices = 0.06, faces = #glass,
                    colors = (#gold, #lamp); }}"
    )
}

/// Pixel luminances of an OpenEXR image.
fn luminances(path: &Path) -> Result<Vec<f64>, String> {
    use exr::prelude::*;
    let image = read_first_rgba_layer_from_file(
        path,
        |resolution, _| vec![vec![[0f32; 3]; resolution.width()]; resolution.height()],
        |pixels, position, (r, g, b, _a): (f32, f32, f32, f32)| {
            pixels[position.y()][position.x()] = [r, g, b];
        },
    )
    .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(image
        .layer_data
        .channel_data
        .pixels
        .iter()
        .flatten()
        .map(|p| (f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2])) / 3.0)
        .collect())
}

/// RMS of `a - reference` over the mean of the reference.
fn relative_error(a: &[f64], reference: &[f64]) -> f64 {
    let n = reference.len() as f64;
    let mean = reference.iter().sum::<f64>() / n;
    let rms = (a
        .iter()
        .zip(reference)
        .map(|(x, r)| (x - r).powi(2))
        .sum::<f64>()
        / n)
        .sqrt();
    rms / mean
}

/// For each 8x8 block of a `size` x `size` image of differences, how many
/// standard errors its mean is from 0, the standard error from the block's
/// own spread (bright blocks are noisier than dark ones).
fn block_z_scores(d: &[f64], size: u32) -> Vec<f64> {
    let size = size as usize;
    let blocks = size.div_ceil(8);
    let mut groups = vec![Vec::new(); blocks * blocks];
    for (k, v) in d.iter().enumerate() {
        groups[(k / size / 8) * blocks + (k % size) / 8].push(*v);
    }
    groups
        .iter()
        .filter(|g| g.len() > 1)
        .map(|g| {
            let n = g.len() as f64;
            let m = g.iter().sum::<f64>() / n;
            let rms = (g.iter().map(|v| v * v).sum::<f64>() / n).sqrt();
            if rms > 0.0 {
                m.abs() * n.sqrt() / rms
            } else {
                0.0
            }
        })
        .collect()
}

fn mean(a: &[f64]) -> f64 {
    a.iter().sum::<f64>() / a.len() as f64
}

struct Run {
    measured: Measured,
    image: Vec<f64>,
}

fn hscene_run(
    hscene: &Path,
    dir: &Path,
    name: &str,
    samples: u32,
    seed: u64,
    threads: Option<usize>,
) -> Result<Run, String> {
    let scene = dir.join(format!("{name}.hsc"));
    let out = dir.join(format!("{name}-{samples}-{seed}.exr"));
    let mut cmd = common::render_command(hscene, &scene, &out, threads);
    cmd.arg(format!("--samples={samples}"))
        .arg(format!("--seed={seed}"));
    let measured = measure(&cmd, &dir.join(format!("{name}.log")))?;
    Ok(Run {
        measured,
        image: luminances(&out)?,
    })
}

fn mitsuba_run(dir: &Path, json: &str, name: &str) -> Result<Run, String> {
    let spec = dir.join(format!("{name}.json"));
    std::fs::write(&spec, json).map_err(|e| e.to_string())?;
    let out = dir.join(format!("{name}.exr"));
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/path_twin/mitsuba_twin.py");
    let mut cmd = Command::new("python3");
    cmd.arg(script).arg(&spec).arg(&out);
    let measured = measure(&cmd, &dir.join(format!("{name}.log")))?;
    Ok(Run {
        measured,
        image: luminances(&out)?,
    })
}

fn mitsuba_installed() -> bool {
    Command::new("python3")
        .args(["-c", "import mitsuba, numpy"])
        .output()
        .is_ok_and(|o| o.status.success())
}

fn line(name: &str, who: &str, spp: u32, pixels: u32, run: &Run, error: f64) {
    let samples = f64::from(spp) * f64::from(pixels);
    println!(
        "{name:<16} {who:<8} {spp:>6} {:>8.2} {:>8.2} {:>12.0} {:>10.4}",
        run.measured.cpu_s,
        run.measured.wall_s,
        samples / run.measured.cpu_s,
        error
    );
}

fn main() -> ExitCode {
    common::measure_child_if_asked();
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("path bench: {e}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<bool, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number = |name: &str, default: u32| -> Result<u32, String> {
        arg_value(&args, name).map_or(Ok(default), |s| {
            s.parse()
                .ok()
                .filter(|n| *n > 0)
                .ok_or(format!("{name}: `{s}` is not a positive whole number"))
        })
    };
    let size = number("--resolution", 64)?;
    let spp = number("--samples", 256)?;
    let threads = arg_value(&args, "--threads").and_then(|s| s.parse().ok());
    let hscene = hscene_binary().ok_or("cannot find the hscene binary: run through cargo bench")?;
    let temp = tempfile::tempdir().map_err(|e| e.to_string())?;
    let dir: PathBuf = match arg_value(&args, "--keep") {
        Some(keep) => {
            std::fs::create_dir_all(keep).map_err(|e| format!("--keep: {e}"))?;
            PathBuf::from(keep)
        }
        None => temp.path().to_path_buf(),
    };
    let fov = 70.0;
    let b = cornell();
    std::fs::write(
        dir.join("cornell-flat.hsc"),
        cornell_hsc(&b, 1e-3, size, fov),
    )
    .map_err(|e| e.to_string())?;
    std::fs::write(
        dir.join("cornell-h3.hsc"),
        cornell_hsc(&b, H3_SCALE, size, fov),
    )
    .map_err(|e| e.to_string())?;
    std::fs::write(dir.join("honeycomb-glass.hsc"), honeycomb_hsc(size))
        .map_err(|e| e.to_string())?;

    let pixels = size * size;
    println!(
        "{size}x{size}, {spp} samples per pixel, path integrator; error: RMS luminance difference from a converged reference (16x the samples) over its mean"
    );
    println!(
        "{:<16} {:<8} {:>6} {:>8} {:>8} {:>12} {:>10}",
        "scene", "renderer", "spp", "cpu s", "wall s", "samples/cpu s", "rel error"
    );
    let mut agrees = true;
    // CI runs the flat limit alone (`--scenes cornell-flat`): the check
    // against Mitsuba, without the figures only a benchmark run needs.
    let chosen = arg_value(&args, "--scenes").map(|s| s.split(',').collect::<Vec<_>>());
    for name in ["cornell-flat", "cornell-h3", "honeycomb-glass"] {
        if chosen.as_ref().is_some_and(|c| !c.contains(&name)) {
            continue;
        }
        let reference = hscene_run(&hscene, &dir, name, spp * 16, 7, threads)?;
        let run = hscene_run(&hscene, &dir, name, spp, 1, threads)?;
        let own_error = relative_error(&run.image, &reference.image);
        line(name, "hscene", spp, pixels, &run, own_error);
        if name != "cornell-flat" {
            continue;
        }
        if !mitsuba_installed() {
            println!("{name:<16} mitsuba  (not installed: pip install mitsuba numpy)");
            continue;
        }
        let twin = mitsuba_run(
            &dir,
            &cornell_json(&b, size, fov, spp, 1, "independent"),
            "cornell-twin",
        )?;
        let twin_error = relative_error(&twin.image, &reference.image);
        line(name, "mitsuba", spp, pixels, &twin, twin_error);
        // Agreement: the difference from hscene's converged reference is
        // noise, not bias. Mitsuba's noise per pixel is the RMS of that
        // difference; averaged over a block of 8x8 pixels it shrinks
        // eightfold, where a bias would not: every block's mean must agree
        // within five of its standard errors, and the image mean within four.
        let (m_ref, m_twin) = (mean(&reference.image), mean(&twin.image));
        let sigma_pixel = twin_error * m_ref;
        let difference: Vec<f64> = twin
            .image
            .iter()
            .zip(&reference.image)
            .map(|(t, r)| t - r)
            .collect();
        let worst = block_z_scores(&difference, size)
            .into_iter()
            .fold(0.0, f64::max);
        let sigma_mean = sigma_pixel / f64::from(pixels).sqrt();
        let same_mean = (m_twin - m_ref).abs() <= 4.0 * sigma_mean;
        let same_blocks = worst <= 5.0;
        println!(
            "flat limit: mean luminance hscene {m_ref:.5}, mitsuba {m_twin:.5} ({:.2} standard errors apart); worst 8x8 block {worst:.2} standard errors: {}",
            (m_twin - m_ref).abs() / sigma_mean,
            if same_mean && same_blocks {
                "agree"
            } else {
                "DISAGREE"
            }
        );
        let same_noise = same_blocks;
        agrees &= same_noise && same_mean;
        // Error falls as 1/sqrt(samples): CPU time x error² is the cost of
        // a given error, whatever the sample count.
        println!(
            "speed: hscene takes {:.2}x Mitsuba's CPU time, {:.2}x its wall time, for {:.2}x its error; CPU time for equal error {:.2}x Mitsuba's",
            run.measured.cpu_s / twin.measured.cpu_s,
            run.measured.wall_s / twin.measured.wall_s,
            own_error / twin_error,
            equal_error_cpu(&run, own_error, &twin, twin_error)
        );
        let stratified = mitsuba_run(
            &dir,
            &cornell_json(&b, size, fov, spp, 1, "stratified"),
            "cornell-twin-stratified",
        )?;
        let strat_error = relative_error(&stratified.image, &reference.image);
        line(name, "mi-strat", spp, pixels, &stratified, strat_error);
        println!(
            "speed: CPU time for equal error {:.2}x Mitsuba's with its stratified sampler",
            equal_error_cpu(&run, own_error, &stratified, strat_error)
        );
    }
    if !arg_flag(&args, "--no-many") {
        agrees &= many_lights::run(&hscene, &dir, size, spp, threads)?;
    }
    Ok(agrees)
}

/// hscene's CPU time for the error of `b` over `b`'s: error falls as
/// `1/sqrt(samples)`, so CPU time x error² is the cost of a given error,
/// whatever the sample count.
fn equal_error_cpu(a: &Run, a_error: f64, b: &Run, b_error: f64) -> f64 {
    (a.measured.cpu_s * a_error * a_error) / (b.measured.cpu_s * b_error * b_error)
}

/// Whether `--name` is on the command line.
fn arg_flag(args: &[String], name: &str) -> bool {
    args.iter().any(|a| a == name)
}
