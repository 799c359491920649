//! The unlimited `{4,3,5}` honeycomb against POV-Ray (docs/performance.md,
//! "The honeycomb"): issue 15 asks that the whole order-5 cubic honeycomb
//! with edges, at 1000x1000, one light, recursion depth 0, cost at most
//! twice the CPU time of POV-Ray rendering the thesis's 16-sphere scene at
//! 1000x1000.
//!
//! ```text
//! cargo bench --bench honeycomb                    # 1000x1000
//! cargo bench --bench honeycomb -- --resolution 400
//! cargo bench --bench honeycomb -- --threads 1 --json
//! cargo bench --bench honeycomb -- --runs 1        # one run of each, not three
//! ```
//!
//! The renders run as measured child processes (`common::measure`: CPU
//! time user + system from `wait4`, wall time from the clock): `hscene
//! render` on the honeycomb scene twice, with its light at the eye (a
//! headlight: the renderer skips shadow rays it knows to be clear) and off
//! the eye (every lit hit walks a shadow ray), and POV-Ray on the Euclidean
//! twin of the thesis's "16 h-spheres, 1 light, recursion 0" scene
//! (`common::thesis_scenes`, the `thesis` bench's own). The ratios are
//! hscene's CPU time over POV-Ray's. The three run `--runs` times (3 by
//! default) in turn, and each keeps its least CPU and least wall time
//! (`Measured::best`): this VM's noise only ever adds time.
//!
//! In-process, on a 64x64 grid of the same primary rays (net 0, the
//! scene's camera), walked to the renderer's pixel horizon, the walk
//! reports how many cells each ray crosses (one step each): the mean number
//! of cells crossed per ray is the cost the walk pays instead of the number
//! of cells in the scene. Rays per second are the rays traced over
//! hscene's CPU time: the image's primary rays, plus with the light off
//! the eye one shadow ray per primary hit. The drift is the walk's
//! accuracy: the hyperbolic distance between the f64 walk's local ray
//! origin (`RegularHoneycomb::walk_steps`) and a 320-bit walk's through the
//! same faces after `N` cells, and the difference of their arc lengths
//! along the original ray (the arc length is what places a hit: the hit
//! point is the original ray's point there), the worst over rays from the
//! base cell's centre in 64 directions.

use std::fmt::Write as _;
use std::process::ExitCode;

use hgeom::glam::DVec3;
use hgeom::{HoneycombStyle, Ray, RegularHoneycomb};
use hrender::PixelNet;
use hscene_lang::ir::{Net, Resolution, Scene, Shape};
use hscene_test_support::reference::{R, V4, distance_h, ldot};

#[allow(dead_code)]
mod common;
use common::thesis_scenes::{Case, Kind, pov_source};
use common::{Measured, Probe, hscene_binary, povray_installed};

/// Rays per side of the in-process grid.
const GRID: u32 = 64;
/// The edges' radius: the language's default.
const EDGE_RADIUS: f64 = 0.02;
/// Reflections after which the drift is measured, and the rays measured.
const DRIFT_STEPS: [u32; 4] = [3, 5, 10, 15];
const DRIFT_RAYS: u32 = 64;

/// Where the one light is: at the eye (a headlight, whose shadow rays the
/// renderer knows to be clear without tracing them), or off the eye inside
/// the base cube, where every lit hit walks a shadow ray back to it.
const LIGHT_AT_EYE: &str = "(0, 0, 0)";
const LIGHT_OFF_EYE: &str = "(0.15, 0.1, -0.05)";

/// The honeycomb scene: the eye at the centre of the base cube, looking at
/// the middle of a face, tilted so that no edge points straight at it;
/// one light at `light`.
fn scene_source(resolution: u32, light: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "// The unlimited {{4,3,5}} honeycomb, edges only: the honeycomb bench.\n\
         Globals {{ resolution = ({resolution}, {resolution}); to = (0.1, 0.13, 0.4); fov = 90; \
         background = (0, 0, 0); ambient = (0.4, 0.4, 0.4); recursion_depth = 0; }}\n\
         BRDFs {{ edge: ambient = (0.4, 0.3, 0.2), diffuse = (0.9, 0.75, 0.45), \
         specular = (1, 1, 1), shininess = 40; }}\n\
         Lights {{ {light}, (6, 6, 6), (4, 4, 4); }}\n\
         Objects {{ Honeycomb {{4,3,5}}, #edge, edges = {EDGE_RADIUS}; }}"
    );
    s
}

/// The thesis's 16-sphere case: 1 light, recursion 0.
fn sixteen_spheres() -> Case {
    Case {
        kind: Kind::Spheres,
        count: 16,
        lights: 1,
        depth: 0,
        thesis_s: 22.0,
    }
}

/// The honeycomb of `scene`, in the camera's frame.
fn honeycomb_in(scene: &Scene, probe: &Probe) -> Option<RegularHoneycomb> {
    let mut shape = scene.objects.first()?.shape.clone();
    for stage in &probe.camera.stages {
        shape = shape.transformed(stage);
    }
    match shape {
        Shape::Honeycomb(h) => Some(h.surface),
        _ => None,
    }
}

/// The honeycomb walked as the renderer walks it at `resolution`: to where
/// its cells shrink below the smallest angle between neighbouring pixels,
/// and each primary ray to where they shrink below its own pixel.
fn render_horizon(
    h: &RegularHoneycomb,
    scene: &Scene,
    probe: &Probe,
    resolution: u32,
) -> Result<RegularHoneycomb, String> {
    let res = Resolution::new(resolution, resolution).ok_or("an empty picture")?;
    let window = match scene.settings.fov {
        None => scene.settings.window,
        Some(fov) => {
            hscene_lang::view::fov_window(fov, Net::Euclidean, res, probe.camera.view_distance)
                .map_err(|e| format!("fov {fov}: {e:?}"))?
        }
    };
    let net = PixelNet::new(Net::Euclidean, window, probe.camera.view_distance);
    let footprint =
        hrender::pixel_footprint(&net, resolution, resolution).ok_or("no pixel sees the scene")?;
    h.clone()
        .for_pixels(footprint.smallest, footprint.plane)
        .map_err(|e| e.to_string())
}

/// Walk counts over the probe's primary rays.
struct Walks {
    rays: u64,
    hits: u64,
    cells: u64,
    max_cells: u32,
}

fn walks(h: &RegularHoneycomb, probe: &Probe) -> Walks {
    let mut w = Walks {
        rays: 0,
        hits: 0,
        cells: 0,
        max_cells: 0,
    };
    for dir in &probe.dirs {
        let ray = Ray::from_origin_unchecked(*dir);
        let (hit, stats) = h.intersect_with_stats(&ray, 0.0, f64::INFINITY);
        w.rays += 1;
        w.hits += u64::from(hit.is_some());
        w.cells += u64::from(stats.cells);
        w.max_cells = w.max_cells.max(stats.cells);
    }
    w
}

/// The hyperbolic distance between the f64 walk's local ray origin and a
/// 320-bit walk's after each of `steps` (1-based) reflections, for the ray
/// from the base cell's centre along `dir`. The 320-bit walk crosses the
/// same walls (the f64 walk's choices: here the faces of the base cube,
/// one cell per step) with the same f64 normals, so the difference is the
/// walk's own rounding: the exit point (`tanh τ = -<O,n>/<D,n>`), the
/// re-basing and the reflection, step after step.
fn drift_of(h: &RegularHoneycomb, dir: DVec3, steps: &[u32]) -> Vec<(f64, f64)> {
    let last = steps.iter().copied().max().unwrap_or(0) as usize;
    let ray = Ray::from_origin_unchecked(dir.normalize());
    let walk = h.walk_steps(&ray, last);
    let n: Vec<V4> = h.walls().iter().map(|n| V4::from_f64(*n)).collect();
    let one = R::f(1.0);
    let two = R::f(2.0);
    let mut o = V4::from_f64(ray.origin);
    let mut d = V4::from_f64(ray.dir);
    // Exactly unit, so the 320-bit walk has no rounding of its own to carry.
    o = o.scale(&(one.clone() / (-ldot(&o, &o)).sqrt()));
    d = d.scale(&(one.clone() / ldot(&d, &d).sqrt()));
    let mut out = Vec::new();
    let mut arc = R::f(0.0);
    for (k, step) in walk.iter().enumerate() {
        let m = &n[step.wall];
        let s = -(ldot(&o, m) / ldot(&d, m));
        arc = arc + ((one.clone() + &s) / (one.clone() - &s)).ln() * R::f(0.5);
        let c = one.clone() / (one.clone() - &s * &s).sqrt();
        let sh = &s * &c;
        let at = o.scale(&c).add(&d.scale(&sh));
        let along = o.scale(&sh).add(&d.scale(&c));
        let mm = ldot(m, m);
        let reflect = |x: &V4| x.sub(&m.scale(&(&two * &ldot(x, m) / &mm)));
        o = reflect(&at);
        d = reflect(&along);
        if steps.contains(&((k + 1) as u32)) {
            let place = distance_h(&o, &V4::from_f64(step.origin)).to_f64();
            out.push((place, (arc.clone() - R::f(step.t)).abs().to_f64()));
        }
    }
    out
}

/// The worst drift after each of [`DRIFT_STEPS`] reflections, over rays
/// from the base cell's centre in directions spread over the sphere (rays
/// that leave by the horizon before a step count are left out of it).
fn drift() -> Vec<Drift> {
    let Ok(symbol) = hgeom::Schlafli::new(4, 3, 5) else {
        return Vec::new();
    };
    let style = HoneycombStyle {
        edges: None,
        faces: false,
        vertices: None,
        depth: None,
        cell_classes: 1,
    };
    let Ok(h) = RegularHoneycomb::new(symbol, style) else {
        return Vec::new();
    };
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let mut worst = vec![(0.0f64, 0.0f64, 0usize); DRIFT_STEPS.len()];
    for i in 0..DRIFT_RAYS {
        let z = 1.0 - 2.0 * (f64::from(i) + 0.5) / f64::from(DRIFT_RAYS);
        let rho = (1.0 - z * z).sqrt();
        let a = golden * f64::from(i);
        let dir = DVec3::new(rho * a.cos(), rho * a.sin(), z);
        for (k, (place, arc)) in drift_of(&h, dir, &DRIFT_STEPS).into_iter().enumerate() {
            worst[k].0 = worst[k].0.max(place);
            worst[k].1 = worst[k].1.max(arc);
            worst[k].2 += 1;
        }
    }
    DRIFT_STEPS
        .iter()
        .zip(worst)
        .map(|(&steps, (place, arc, rays))| Drift {
            steps,
            place,
            arc,
            rays,
        })
        .collect()
}

/// The worst drift after `steps` reflections: of the walk's local ray
/// origin (hyperbolic distance) and of its arc length along the original
/// ray (which places a hit), over the `rays` still walking.
struct Drift {
    steps: u32,
    place: f64,
    arc: f64,
    rays: usize,
}

struct Report {
    resolution: u32,
    hscene: Measured,
    /// The same render with the light off the eye.
    hscene_off_eye: Measured,
    povray: Option<Measured>,
    walks: Walks,
    drift: Vec<Drift>,
}

impl Report {
    fn ratio(&self, hscene: &Measured) -> Option<f64> {
        self.povray.map(|p| hscene.cpu_s / p.cpu_s)
    }

    /// Rays traced per CPU second: the primary rays, plus with the light
    /// off the eye one shadow ray per primary hit (estimated from the
    /// grid's hit share).
    fn rays_per_second(&self, off_eye: bool) -> f64 {
        let primary = f64::from(self.resolution) * f64::from(self.resolution);
        if !off_eye {
            return primary / self.hscene.cpu_s;
        }
        let hit_share = self.walks.hits as f64 / self.walks.rays.max(1) as f64;
        primary * (1.0 + hit_share) / self.hscene_off_eye.cpu_s
    }

    fn mean(&self, total: u64) -> f64 {
        total as f64 / self.walks.rays.max(1) as f64
    }

    fn json(&self, threads: Option<usize>) -> String {
        serde_json::json!({
            "scene": "{4,3,5} edges, unlimited",
            "resolution": self.resolution,
            "threads": threads,
            "hscene_cpu_s": self.hscene.cpu_s,
            "hscene_wall_s": self.hscene.wall_s,
            "hscene_peak_mib": self.hscene.peak_mib,
            "hscene_light_off_eye_cpu_s": self.hscene_off_eye.cpu_s,
            "hscene_light_off_eye_wall_s": self.hscene_off_eye.wall_s,
            "povray_16_spheres_cpu_s": self.povray.map(|p| p.cpu_s),
            "povray_16_spheres_wall_s": self.povray.map(|p| p.wall_s),
            "cpu_ratio": self.ratio(&self.hscene),
            "cpu_ratio_light_off_eye": self.ratio(&self.hscene_off_eye),
            "rays_per_cpu_s": self.rays_per_second(false),
            "rays_per_cpu_s_light_off_eye": self.rays_per_second(true),
            "mean_cells_per_ray": self.mean(self.walks.cells),
            "max_cells_per_ray": self.walks.max_cells,
            "hit_share": self.walks.hits as f64 / self.walks.rays.max(1) as f64,
            "drift": self.drift.iter().map(|d| serde_json::json!({"steps": d.steps, "max": d.place, "max_arc": d.arc, "rays": d.rays})).collect::<Vec<_>>(),
        })
        .to_string()
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let r = self.resolution;
        let _ = writeln!(
            s,
            "{{4,3,5}} unlimited, edges {EDGE_RADIUS}, {r}x{r}, 1 light, depth 0"
        );
        let _ = writeln!(
            s,
            "  hscene, light at the eye   CPU {:6.2} s   wall {:6.2} s   peak {:6.1} MiB",
            self.hscene.cpu_s, self.hscene.wall_s, self.hscene.peak_mib
        );
        let _ = writeln!(
            s,
            "  hscene, light off the eye  CPU {:6.2} s   wall {:6.2} s   peak {:6.1} MiB",
            self.hscene_off_eye.cpu_s, self.hscene_off_eye.wall_s, self.hscene_off_eye.peak_mib
        );
        match self.povray {
            Some(p) => {
                let _ = writeln!(
                    s,
                    "  POV-Ray 16 h-spheres       CPU {:6.2} s   wall {:6.2} s",
                    p.cpu_s, p.wall_s
                );
            }
            None => s.push_str("  POV-Ray: not installed\n"),
        }
        for (hscene, light, off_eye) in [
            (&self.hscene, "at the eye", false),
            (&self.hscene_off_eye, "off the eye", true),
        ] {
            if let Some(ratio) = self.ratio(hscene) {
                let verdict = if ratio <= 2.0 { "within" } else { "beyond" };
                let _ = writeln!(
                    s,
                    "  light {light}: CPU ratio {ratio:.2} ({verdict} the 2x target), {:.2} M rays per CPU second",
                    self.rays_per_second(off_eye) / 1e6
                );
            }
        }
        let _ = writeln!(
            s,
            "  per primary ray: {:.1} cells crossed (max {}); {:.0} % hit",
            self.mean(self.walks.cells),
            self.walks.max_cells,
            100.0 * self.walks.hits as f64 / self.walks.rays.max(1) as f64
        );
        for d in &self.drift {
            let _ = writeln!(
                s,
                "  drift after {:3} cells (face reflections): {:.1e}, arc length {:.1e} (max over the {} of {DRIFT_RAYS} rays still walking)",
                d.steps, d.place, d.arc, d.rays
            );
        }
        s
    }
}

fn run(resolution: u32, threads: Option<usize>, runs: usize) -> Result<Report, String> {
    let source = scene_source(resolution, LIGHT_AT_EYE);
    let compiled = hscene_lang::compile(&source);
    let scene = compiled.scene.ok_or_else(|| {
        format!(
            "the bench scene does not compile: {:?}",
            compiled.diagnostics
        )
    })?;
    let probe = Probe::new(&scene, GRID)?;
    let honeycomb = honeycomb_in(&scene, &probe).ok_or("the scene's object is not a honeycomb")?;
    let honeycomb = render_horizon(&honeycomb, &scene, &probe, resolution)?;
    let walks = walks(&honeycomb, &probe);

    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let path = dir.path().join("honeycomb.hsc");
    std::fs::write(&path, &source).map_err(|e| e.to_string())?;
    let bin = hscene_binary().ok_or("no hscene binary next to the bench")?;
    let cmd = common::render_command(&bin, &path, &dir.path().join("honeycomb.png"), threads);
    let off_eye = dir.path().join("off-eye.hsc");
    std::fs::write(&off_eye, scene_source(resolution, LIGHT_OFF_EYE)).map_err(|e| e.to_string())?;
    let cmd_off_eye =
        common::render_command(&bin, &off_eye, &dir.path().join("off-eye.png"), threads);
    let pov = pov_source(&sixteen_spheres(), resolution);
    // The three in turn, `runs` times, each keeping its best run.
    let mut best: Option<(Measured, Measured, Option<Measured>)> = None;
    for _ in 0..runs {
        let at_eye = common::measure(&cmd, &dir.path().join("hscene.log"))?;
        let off = common::measure(&cmd_off_eye, &dir.path().join("off-eye.log"))?;
        let pov = if povray_installed() {
            Some(common::povray(&pov, resolution, threads)?)
        } else {
            None
        };
        best = Some(match best {
            None => (at_eye, off, pov),
            Some((a, o, p)) => (
                a.best(at_eye),
                o.best(off),
                p.zip(pov).map(|(p, q)| p.best(q)),
            ),
        });
    }
    let (hscene, hscene_off_eye, povray) = best.ok_or("no run")?;
    Ok(Report {
        resolution,
        hscene,
        hscene_off_eye,
        povray,
        walks,
        drift: drift(),
    })
}

fn main() -> ExitCode {
    common::measure_child_if_asked();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let json = args.iter().any(|a| a == "--json");
    let resolution: u32 = common::arg_value(&args, "--resolution")
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let threads: Option<usize> = common::arg_value(&args, "--threads").and_then(|s| s.parse().ok());
    let runs = match common::runs_arg(&args, 3) {
        Ok(n) => n,
        Err(e) => {
            eprintln!("honeycomb bench: {e}");
            return ExitCode::FAILURE;
        }
    };
    match run(resolution, threads, runs) {
        Ok(report) if json => {
            println!("{}", report.json(threads));
            ExitCode::SUCCESS
        }
        Ok(report) => {
            print!("{}", report.table());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("honeycomb bench: {e}");
            ExitCode::FAILURE
        }
    }
}
