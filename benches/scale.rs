//! Speed at scale: scenes of thousands of objects rendered by the `hscene`
//! binary and, next to it, by POV-Ray rendering their Euclidean twins
//! (docs/performance.md).
//!
//! ```text
//! cargo bench --bench scale                      # N = 1000, 5000, 20000 at 800x800
//! cargo bench --bench scale -- --n 1000,20000    # choose N
//! cargo bench --bench scale -- --resolution 200  # quicker, smaller
//! cargo bench --bench scale -- --threads 1       # both renderers on one thread
//! cargo bench --bench scale -- --tessellation 2,6 --json
//! cargo bench --bench scale -- --n 1000 --mesh 20480,1310720   # triangle meshes
//! cargo bench --bench scale -- --n 1000 --write-scenes /tmp/s  # keep the scenes and twins
//! cargo bench --bench scale -- --runs 1          # one run of each program, not three
//! ```
//!
//! Each scene (`spheres-N`, `rods-N`, `tessellation-D`, `mesh-N`; 2 point lights,
//! recursion depth 1, net 0, the eye at the origin looking along +z with a
//! 60 degree field of view) is written to a temporary directory and rendered
//! by `hscene render` as a child process, whose CPU time (user + system)
//! and peak resident memory come from `wait4`, its wall time from the clock.
//! The binary is the one Cargo builds for this bench (`CARGO_BIN_EXE_hscene`,
//! `target/release/hscene` under `cargo bench`); failing that, the `hscene`
//! two directories above this bench's executable (`target/release/deps/..`).
//! POV-Ray (`povray` on the PATH; its columns stay empty without it)
//! renders the twin the same way. Each program runs `--runs` times (3 by
//! default), the two in turn, and each keeps its least CPU and least wall
//! time (and its largest peak memory): this VM's noise only ever adds time,
//! and turn about gives both programs the same machine.
//!
//! `mesh-N` is one `Mesh` of N triangles (N = 20 * 4^k, default 20,480 and
//! 1,310,720): a geodesic icosphere subdivided k times, written as a binary
//! PLY file next to the scene, laid out with size 1.5 and moved in front of
//! the eye; its row also gives the peak memory per triangle (`B/tri`). Its
//! POV-Ray twin is a `mesh2` with each vertex at its Klein coordinates: seen
//! from the ball's centre a Poincaré point and its Klein image lie on one
//! ray, and the flat triangle through the Klein images of an h-triangle's
//! vertices is the h-triangle in the Klein model, so the silhouettes agree.
//!
//! The error columns come from the same scene compiled in-process: on a
//! 32x32 grid of primary rays, the max and median hyperbolic distance
//! between the renderer's hit and the 320-bit recomputation on the surface
//! hit, and the number of rays whose nearest hit through the bounding
//! hierarchy differs from an exhaustive f64 search over every object
//! (`misses`: a hierarchy that loses objects shows here).

use std::fmt::Write as _;
use std::path::Path;
use std::process::ExitCode;

use hgeom::glam::DVec3;
use hgeom::{HSphere, Ray, Rod, Vertex};
use hscene_lang::Options;
use hscene_lang::ir::{Scene, Shape};
use hscene_test_support::SplitMix64;

mod common;
mod mesh_case;
use common::{Measured, Probe, hscene_binary, povray_installed, v};
use mesh_case::{icosphere, ply_bytes, pov_mesh, subdivisions};

/// Horizontal (and, the image being square, vertical) field of view.
const FOV_DEGREES: f64 = 60.0;
/// Rays per side of the error grid.
const GRID: u32 = 32;
const SEED: u64 = 14;
const RECURSION: u32 = 1;
/// Runs of each program per scene, without `--runs`.
const RUNS: usize = 3;
/// Ball coordinates of the two point lights, near the eye.
const LIGHTS: [DVec3; 2] = [DVec3::new(-0.15, 0.15, 0.0), DVec3::new(0.15, 0.1, -0.05)];
/// Intensity of each light: 1/(4 pi sinh^2 r) leaves about 0.2 of it at
/// distance 2.
const LIGHT_INTENSITY: f64 = 30.0;
/// Hyperbolic distances from the eye of the random objects.
const NEAR: f64 = 0.5;
const FAR: f64 = 4.0;
/// Rod radius of the tessellation's edges.
const EDGE_RADIUS: f64 = 0.015;
/// The mesh file of a `mesh-N` case, next to its scene.
fn mesh_file(n: usize) -> String {
    format!("icosphere-{n}.ply")
}
/// The hyperbolic radius of the mesh (its `size`).
const MESH_SIZE: f64 = 1.5;
/// Where the mesh's centre is moved (`at`), in ball coordinates:
/// `tanh(2.32 / 2)`, 2.32 from the eye, where a ball of radius 1.5 subtends
/// a half-angle of 25 degrees (`sinh 1.5 / sinh 2.32`), within the 30 of
/// the picture.
const MESH_AT: f64 = 0.821;

#[derive(Clone, Copy)]
enum Case {
    Spheres(usize),
    Rods(usize),
    Tessellation(u32),
    /// An icosphere of this many triangles (`20 * 4^k`).
    Mesh(usize),
}

impl Case {
    fn name(self) -> String {
        match self {
            Case::Spheres(n) => format!("spheres-{n}"),
            Case::Rods(n) => format!("rods-{n}"),
            Case::Tessellation(d) => format!("tessellation-{d}"),
            Case::Mesh(n) => format!("mesh-{n}"),
        }
    }
}

/// A direction from the eye uniformly spread over the square picture.
fn in_view(rng: &mut SplitMix64) -> DVec3 {
    let t = (0.5 * FOV_DEGREES).to_radians().tan();
    DVec3::new(t * rng.range(-1.0, 1.0), t * rng.range(-1.0, 1.0), 1.0).normalize()
}

/// The point at hyperbolic distance `d` from the eye along `dir`, in ball
/// coordinates.
fn at_distance(dir: DVec3, d: f64) -> DVec3 {
    dir * (0.5 * d).tanh()
}

/// The radius of an h-sphere at distance `d` that subtends the angle
/// `theta` from its centre's direction (`sin theta = sinh r / sinh d`).
fn radius_for(d: f64, theta: f64) -> f64 {
    (d.sinh() * theta.sin()).asinh()
}

/// The mean apparent radius for `n` objects each covering about `area`
/// times its radius squared (in steradians): the picture's solid angle
/// covered about 1.2 times over, so much of the background still shows.
fn apparent_radius(n: usize, area: f64) -> f64 {
    let t = (0.5 * FOV_DEGREES).to_radians().tan();
    let view = 4.0 * t * t;
    (1.2 * view / (area * n as f64)).sqrt()
}

fn globals(resolution: u32) -> String {
    format!(
        "Globals {{ recursion_depth = {RECURSION}; resolution = ({resolution}, {resolution}); fov = {FOV_DEGREES}; net_type = 0; background = (0.05, 0.05, 0.1); ambient = (0.2, 0.2, 0.2); }}\n"
    )
}

fn lights() -> String {
    let mut s = String::from("Lights {\n");
    for p in LIGHTS {
        let i = LIGHT_INTENSITY;
        let _ = writeln!(s, "  {}, ({i}, {i}, {i}), (1, 1, 1);", v(p));
    }
    s.push_str("}\n");
    s
}

fn material(rng: &mut SplitMix64) -> String {
    let c = DVec3::new(
        rng.range(0.2, 1.0),
        rng.range(0.2, 1.0),
        rng.range(0.2, 1.0),
    );
    format!(
        "  ambient = {}, diffuse = {}, specular = (0.3, 0.3, 0.3), shininess = 20, alpha = 0.2;\n",
        v(c * 0.5),
        v(c)
    )
}

/// The hscene source of a case.
fn scene_source(case: Case, resolution: u32) -> String {
    let mut rng = SplitMix64::new(SEED);
    let mut s = format!("// {}\n{}{}", case.name(), globals(resolution), lights());
    let mut materials = String::from("BRDFs {\n");
    let mut objects = String::from("Objects {\n");
    match case {
        Case::Spheres(n) => {
            let theta0 = apparent_radius(n, 1.08 * std::f64::consts::PI);
            for k in 1..=n {
                materials.push_str(&material(&mut rng));
                let d = rng.range(NEAR, FAR);
                let centre = at_distance(in_view(&mut rng), d);
                let r = radius_for(d, theta0 * rng.range(0.5, 1.5));
                let _ = writeln!(objects, "  Sphere {}, {r}, #{k};", v(centre));
            }
        }
        Case::Rods(n) => {
            // A rod is about 6 apparent radii long: 12 + pi radii squared.
            let theta0 = apparent_radius(n, 1.08 * 15.1);
            for k in 1..=n {
                materials.push_str(&material(&mut rng));
                let d = rng.range(NEAR, FAR);
                let dir = in_view(&mut rng);
                let theta = theta0 * rng.range(0.5, 1.5);
                let across = dir.cross(rng.direction()).normalize() * (3.0 * theta).tan();
                let (da, db) = (d + rng.range(-0.25, 0.25), d + rng.range(-0.25, 0.25));
                let a = at_distance((dir - across).normalize(), da);
                let b = at_distance((dir + across).normalize(), db);
                let r = radius_for(da.min(db), theta);
                let _ = writeln!(objects, "  Rod {}, {}, {r}, #{k};", v(a), v(b));
            }
        }
        Case::Tessellation(depth) => {
            materials.push_str(&material(&mut rng));
            let _ = writeln!(
                objects,
                "  Tessellation435 {depth}, #1, wireframe = {EDGE_RADIUS};"
            );
        }
        Case::Mesh(n) => {
            materials.push_str(&material(&mut rng));
            let _ = writeln!(
                objects,
                "  Mesh \"{}\", {MESH_SIZE}, #1, at = (0, 0, {MESH_AT});",
                mesh_file(n)
            );
        }
    }
    materials.push_str("}\n");
    objects.push_str("}\n");
    s.push_str(&materials);
    s.push_str(&objects);
    s
}

/// The Euclidean twin for POV-Ray: the same camera, lights and colours;
/// each h-sphere as the Euclidean sphere it is in the ball (the same
/// silhouette), each rod as the Euclidean spheres of its caps joined by a
/// cone (the tube's silhouette approximately), each mesh as a `mesh2` with
/// its vertices at their Klein coordinates (the same silhouette from the
/// eye at the centre, see the module docs). Returns the source and the
/// number of objects it leaves out (rods with ideal ends, other shapes).
fn pov_source(scene: &Scene) -> (String, usize) {
    let mut s = String::from("#version 3.7;\n");
    let _ = writeln!(
        s,
        "global_settings {{ max_trace_level {} assumed_gamma 1 }}",
        RECURSION + 1
    );
    // The eye looks along +z with +x to the right, as hscene's does.
    let _ = writeln!(
        s,
        "camera {{ perspective location <0,0,0> direction <0,0,1> right <1,0,0> up <0,1,0> angle {FOV_DEGREES} }}"
    );
    let _ = writeln!(s, "background {{ color rgb <0.05,0.05,0.1> }}");
    for p in LIGHTS {
        let _ = writeln!(
            s,
            "light_source {{ <{},{},{}> color rgb <1,1,1> }}",
            p.x, p.y, p.z
        );
    }
    for (k, m) in scene.materials.iter().enumerate() {
        let _ = writeln!(
            s,
            "#declare T{k} = texture {{ pigment {{ color rgb <{},{},{}> }} finish {{ ambient 0.1 diffuse 0.8 specular 0.3 roughness 0.05 reflection {} }} }}",
            m.diffuse.r, m.diffuse.g, m.diffuse.b, m.reflection
        );
    }
    let mut left_out = 0;
    let pov = |c: DVec3| format!("<{},{},{}>", c.x, c.y, c.z);
    let rod = |s: &mut String, rod: &Rod, tex: usize| -> bool {
        let (Vertex::Interior(a), Vertex::Interior(b)) = (rod.start(), rod.end()) else {
            return false;
        };
        let (Ok(ca), Ok(cb)) = (HSphere::new(a, rod.radius()), HSphere::new(b, rod.radius()))
        else {
            return false;
        };
        let ((ea, ra), (eb, rb)) = (ca.euclidean(), cb.euclidean());
        let _ = writeln!(
            s,
            "union {{ sphere {{ {}, {ra} }} sphere {{ {}, {rb} }} cone {{ {}, {ra}, {}, {rb} }} texture {{ T{tex} }} }}",
            pov(ea),
            pov(eb),
            pov(ea),
            pov(eb)
        );
        true
    };
    for o in &scene.objects {
        let tex = o.material.index();
        let drawn = match &o.shape {
            Shape::Sphere(sphere) => {
                let (c, r) = sphere.euclidean();
                let _ = writeln!(s, "sphere {{ {}, {r} texture {{ T{tex} }} }}", pov(c));
                true
            }
            Shape::Rod(r) => rod(&mut s, r, tex),
            Shape::Wireframe(rods) => rods.iter().all(|r| rod(&mut s, r, tex)),
            Shape::Mesh(m) => {
                pov_mesh(&mut s, m, tex);
                true
            }
            _ => false,
        };
        if !drawn {
            left_out += 1;
        }
    }
    (s, left_out)
}

/// Rays of the probe whose nearest hit through the renderer's hierarchy
/// differs from the nearest over every object, tried one by one.
fn hierarchy_misses(probe: &Probe) -> usize {
    let objects = &probe.prepared.objects;
    probe
        .dirs
        .iter()
        .filter(|&&dir| {
            let ray = Ray::from_origin_unchecked(dir);
            let found = match probe.prepared.nearest(&ray, 0.0) {
                hrender::Nearest::Hit(hit, _) => Some(hit.t),
                _ => None,
            };
            let exhaustive = objects
                .iter()
                .filter_map(|o| o.intersect(&ray, 0.0, f64::INFINITY))
                .map(|h| h.t)
                .min_by(f64::total_cmp);
            match (found, exhaustive) {
                (None, None) => false,
                (Some(a), Some(b)) => (a - b).abs() > 1e-9 * a.max(1.0),
                _ => true,
            }
        })
        .count()
}

/// The `hscene` binary this bench measures.
struct Row {
    name: String,
    objects: usize,
    primitives: usize,
    /// The triangles of a mesh case, for its bytes per triangle.
    mesh_triangles: Option<usize>,
    hscene: Measured,
    povray: Option<Measured>,
    pov_left_out: usize,
    mrays_per_s: f64,
    errors: common::HitErrors,
    misses: usize,
}

impl Row {
    /// The peak resident memory of the hscene process per mesh triangle,
    /// all of it counted (`peak MiB * 2^20 / N`).
    fn bytes_per_triangle(&self) -> Option<f64> {
        self.mesh_triangles
            .map(|n| self.hscene.peak_mib * f64::from(1u32 << 20) / n as f64)
    }
}

fn print_header(resolution: u32, threads: Option<usize>, runs: usize) {
    let all = std::thread::available_parallelism().map_or(1, usize::from);
    println!(
        "{resolution}x{resolution}, net 0, 2 lights, recursion {RECURSION}, {} threads ({all} cores), \
         best of {runs} runs each; \
         error: hyperbolic distance of primary hits vs 320-bit reference on a {GRID}x{GRID} grid; \
         misses: rays whose hierarchy hit differs from an exhaustive f64 search",
        threads.unwrap_or(all)
    );
    println!(
        "{:<17} {:>6} {:>7} {:>8} {:>8} {:>8} {:>8} {:>6} {:>6} {:>7} {:>7} {:>7} {:>6} {:>8} {:>8} {:>5} {:>6}",
        "scene",
        "objs",
        "prims",
        "hs cpu",
        "hs wall",
        "pov cpu",
        "pov wal",
        "cpu x",
        "wall x",
        "Mray/s",
        "hs MiB",
        "pov MiB",
        "B/tri",
        "err max",
        "err med",
        "hits",
        "misses"
    );
}

fn print_row(r: &Row) {
    let pov = |f: fn(&Measured) -> f64, digits: usize| {
        r.povray
            .as_ref()
            .map_or("-".to_string(), |m| format!("{:.digits$}", f(m)))
    };
    let ratio = |f: fn(&Measured) -> f64| {
        r.povray
            .as_ref()
            .map_or("-".to_string(), |m| format!("{:.2}", f(&r.hscene) / f(m)))
    };
    // No sampled hits (a mesh: the reference has no triangles) is no
    // error figure, not an error of 0.
    let error = |e: f64| {
        if r.errors.sampled > 0 {
            format!("{e:.1e}")
        } else {
            "-".to_string()
        }
    };
    println!(
        "{:<17} {:>6} {:>7} {:>8.3} {:>8.3} {:>8} {:>8} {:>6} {:>6} {:>7.2} {:>7.1} {:>7} {:>6} {:>8} {:>8} {:>5} {:>6}",
        r.name,
        r.objects,
        r.primitives,
        r.hscene.cpu_s,
        r.hscene.wall_s,
        pov(|m| m.cpu_s, 3),
        pov(|m| m.wall_s, 3),
        ratio(|m| m.cpu_s),
        ratio(|m| m.wall_s),
        r.mrays_per_s,
        r.hscene.peak_mib,
        pov(|m| m.peak_mib, 1),
        r.bytes_per_triangle()
            .map_or("-".to_string(), |b| format!("{b:.0}")),
        error(r.errors.max),
        error(r.errors.median),
        r.errors.sampled,
        r.misses
    );
}

fn json_row(r: &Row, resolution: u32, threads: Option<usize>, runs: usize) -> String {
    let pov = |f: fn(&Measured) -> f64| r.povray.as_ref().map(f);
    let ratio = |f: fn(&Measured) -> f64| r.povray.as_ref().map(|m| f(&r.hscene) / f(m));
    serde_json::json!({
        "scene": r.name,
        "objects": r.objects,
        "primitives": r.primitives,
        "resolution": resolution,
        "threads": threads,
        "runs": runs,
        "recursion": RECURSION,
        "hscene_cpu_s": r.hscene.cpu_s,
        "hscene_wall_s": r.hscene.wall_s,
        "hscene_peak_mib": r.hscene.peak_mib,
        "povray_cpu_s": pov(|m| m.cpu_s),
        "povray_wall_s": pov(|m| m.wall_s),
        "povray_peak_mib": pov(|m| m.peak_mib),
        "mesh_triangles": r.mesh_triangles,
        "hscene_peak_bytes_per_triangle": r.bytes_per_triangle(),
        "povray_objects_left_out": r.povray.as_ref().map(|_| r.pov_left_out),
        "cpu_ratio": ratio(|m| m.cpu_s),
        "wall_ratio": ratio(|m| m.wall_s),
        "mrays_per_s": r.mrays_per_s,
        // No sampled hits (a mesh: the reference has no triangles) is no
        // error figure, not an error of 0.
        "hit_error_max": (r.errors.sampled > 0).then_some(r.errors.max),
        "hit_error_median": (r.errors.sampled > 0).then_some(r.errors.median),
        "hit_error_unit": "hyperbolic distance",
        "hit_error_reference": "320-bit",
        "hits_sampled": r.errors.sampled,
        "hierarchy_misses": r.misses,
        "rays_probed": GRID * GRID,
    })
    .to_string()
}

/// A comma-separated list after `--name`, or `default`.
fn list<T: std::str::FromStr + Clone>(
    args: &[String],
    name: &str,
    default: &[T],
) -> Result<Vec<T>, String> {
    match common::arg_value(args, name) {
        None => Ok(default.to_vec()),
        Some(s) => s
            .split(',')
            .filter(|p| !p.trim().is_empty())
            .map(|p| {
                p.trim()
                    .parse()
                    .map_err(|_| format!("{name}: `{p}` is not a whole number"))
            })
            .collect(),
    }
}

/// How a bench run measures: its resolution, threads, runs per program,
/// whether POV-Ray is there, and where to keep the scenes.
struct Setup<'a> {
    hscene: &'a Path,
    resolution: u32,
    threads: Option<usize>,
    runs: usize,
    povray: bool,
    keep: Option<&'a Path>,
}

fn run_case(case: Case, setup: &Setup<'_>) -> Result<Row, String> {
    let Setup {
        hscene,
        resolution,
        threads,
        runs,
        povray,
        keep,
    } = *setup;
    let source = scene_source(case, resolution);
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    if let Case::Mesh(n) = case {
        let (verts, faces) = icosphere(subdivisions(n)?);
        let ply = ply_bytes(&verts, &faces);
        std::fs::write(dir.path().join(mesh_file(n)), &ply).map_err(|e| e.to_string())?;
        if let Some(keep) = keep {
            std::fs::write(keep.join(mesh_file(n)), &ply)
                .map_err(|e| format!("--write-scenes: {e}"))?;
        }
    }
    let options = Options {
        base_dir: Some(dir.path().to_path_buf()),
        ..Options::default()
    };
    let compiled = hscene_lang::compile_with(&source, &options);
    let Some(scene) = compiled.scene else {
        let messages: Vec<String> = compiled
            .diagnostics
            .into_iter()
            .map(|d| d.message)
            .collect();
        return Err(format!("does not compile: {}", messages.join("; ")));
    };
    let scene_file = dir.path().join(format!("{}.hsc", case.name()));
    std::fs::write(&scene_file, &source).map_err(|e| e.to_string())?;
    if let Some(keep) = keep {
        std::fs::write(keep.join(format!("{}.hsc", case.name())), &source)
            .map_err(|e| format!("--write-scenes: {e}"))?;
    }
    let cmd = common::render_command(hscene, &scene_file, &dir.path().join("out.png"), threads);
    let (pov, pov_left_out) = pov_source(&scene);
    if let Some(keep) = keep {
        std::fs::write(keep.join(format!("{}.pov", case.name())), &pov)
            .map_err(|e| format!("--write-scenes: {e}"))?;
    }
    // The two programs in turn, each keeping its best run.
    let mut measured: Option<Measured> = None;
    let mut povray_best: Option<Measured> = None;
    let mut povray_runs = povray;
    for _ in 0..runs {
        let m = common::measure(&cmd, &dir.path().join("hscene.log"))?;
        measured = Some(measured.map_or(m, |b| b.best(m)));
        if povray_runs {
            match common::povray(&pov, resolution, threads) {
                Ok(m) => povray_best = Some(povray_best.map_or(m, |b| b.best(m))),
                Err(e) => {
                    eprintln!("{}: POV-Ray: {e}", case.name());
                    (povray_best, povray_runs) = (None, false);
                }
            }
        }
    }
    let measured = measured.ok_or("no run")?;
    let povray = povray_best;
    let probe = Probe::new(&scene, GRID)?;
    let primitives = scene
        .objects
        .iter()
        .map(|o| match &o.shape {
            Shape::Wireframe(rods) => rods.len(),
            Shape::Mesh(m) => m.triangle_count(),
            _ => 1,
        })
        .sum();
    Ok(Row {
        name: case.name(),
        objects: scene.objects.len(),
        primitives,
        mesh_triangles: matches!(case, Case::Mesh(_)).then_some(primitives),
        hscene: measured,
        povray,
        pov_left_out,
        mrays_per_s: f64::from(resolution) * f64::from(resolution) / measured.wall_s / 1e6,
        errors: common::hit_errors(&scene, &probe),
        misses: hierarchy_misses(&probe),
    })
}

fn main() -> ExitCode {
    common::measure_child_if_asked();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let json = args.iter().any(|a| a == "--json");
    let parsed = (|| -> Result<_, String> {
        let resolution: u32 = match common::arg_value(&args, "--resolution") {
            None => 800,
            Some(s) => s.parse().ok().filter(|&r| r > 0).ok_or(format!(
                "--resolution: `{s}` is not a positive whole number"
            ))?,
        };
        let threads: Option<usize> = match common::arg_value(&args, "--threads") {
            None => None,
            Some(s) => Some(
                s.parse()
                    .ok()
                    .filter(|&t| t > 0)
                    .ok_or(format!("--threads: `{s}` is not a positive whole number"))?,
            ),
        };
        let counts: Vec<usize> = list(&args, "--n", &[1000, 5000, 20000])?;
        let depths: Vec<u32> = list(&args, "--tessellation", &[2, 6])?;
        let meshes: Vec<usize> = list(&args, "--mesh", &[20480, 1_310_720])?;
        for &n in &meshes {
            subdivisions(n)?;
        }
        let runs = common::runs_arg(&args, RUNS)?;
        Ok((resolution, threads, counts, depths, meshes, runs))
    })();
    let (resolution, threads, counts, depths, meshes, runs) = match parsed {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::FAILURE;
        }
    };
    let Some(hscene) = hscene_binary() else {
        eprintln!("cannot find the hscene binary: run through `cargo bench --bench scale`");
        return ExitCode::FAILURE;
    };
    let keep = common::arg_value(&args, "--write-scenes").map(Path::new);
    let povray = povray_installed();
    if !povray {
        eprintln!("povray is not on the PATH: its columns stay empty");
    }
    let mut cases: Vec<Case> = Vec::new();
    for &n in &counts {
        cases.push(Case::Spheres(n));
        cases.push(Case::Rods(n));
    }
    cases.extend(depths.iter().map(|&d| Case::Tessellation(d)));
    cases.extend(meshes.iter().map(|&n| Case::Mesh(n)));
    if !json {
        print_header(resolution, threads, runs);
    }
    let setup = Setup {
        hscene: &hscene,
        resolution,
        threads,
        runs,
        povray,
        keep,
    };
    for case in cases {
        match run_case(case, &setup) {
            Ok(row) if json => println!("{}", json_row(&row, resolution, threads, runs)),
            Ok(row) => print_row(&row),
            Err(e) => {
                eprintln!("{}: {e}", case.name());
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}
