//! What the scene benchmarks (`thesis`, `scale`) share: command-line values,
//! renderers run as measured child processes (POV-Ray among them), and the
//! error of primary hits against the 320-bit reference.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use hgeom::glam::DVec3;
use hgeom::{HCylinder, HSphere, Ray, Rod, Vertex};
use hrender::{Nearest, PixelNet, PreparedScene, Sample};
use hscene_ir::view::CanonicalFrame;
use hscene_lang::ir::{Net, Resolution, Scene, Shape};
use hscene_test_support::reference::{self as r, R, V4};

// The thesis and honeycomb benches use these; the scale bench does not.
#[allow(dead_code)]
pub mod thesis_scenes;

/// The `hscene` binary Cargo built for this bench (`CARGO_BIN_EXE_hscene`);
/// failing that, the one two directories above the bench's executable
/// (`target/release/deps/..`).
pub fn hscene_binary() -> Option<PathBuf> {
    if let Some(path) = option_env!("CARGO_BIN_EXE_hscene") {
        return Some(path.into());
    }
    let exe = std::env::current_exe().ok()?;
    let path = exe.parent()?.parent()?.join("hscene");
    path.is_file().then_some(path)
}

/// Whether `povray` is on the PATH.
pub fn povray_installed() -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join("povray").is_file()))
}

/// The value after `--name` on the command line.
pub fn arg_value<'a>(args: &'a [String], name: &str) -> Option<&'a str> {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map(String::as_str)
}

/// A point or vector as scene text.
pub fn v(p: DVec3) -> String {
    format!("({}, {}, {})", p.x, p.y, p.z)
}

/// What one run of a child process cost.
#[derive(Clone, Copy, Debug)]
pub struct Measured {
    /// User plus system CPU time of the child, in seconds.
    pub cpu_s: f64,
    /// Wall-clock time from spawning to reaping, in seconds.
    pub wall_s: f64,
    /// The child's peak resident set, in MiB.
    pub peak_mib: f64,
}

impl Measured {
    /// The better of two runs of one command: the least CPU and the least
    /// wall time, each on its own (a VM's neighbours, the scheduler and
    /// the page cache only ever slow a run down, so the least is the
    /// estimate with the least of that noise in it), and the larger peak
    /// memory (the conservative one).
    pub fn best(self, other: Measured) -> Measured {
        Measured {
            cpu_s: self.cpu_s.min(other.cpu_s),
            wall_s: self.wall_s.min(other.wall_s),
            peak_mib: self.peak_mib.max(other.peak_mib),
        }
    }
}

/// `--runs N`: how many times each program is run (the measurements kept
/// are the best of them, [`Measured::best`]); `default` without the flag.
pub fn runs_arg(args: &[String], default: usize) -> Result<usize, String> {
    match arg_value(args, "--runs") {
        None => Ok(default),
        Some(s) => s
            .parse()
            .ok()
            .filter(|&n: &usize| n > 0)
            .ok_or(format!("--runs: `{s}` is not a positive whole number")),
    }
}

/// The flag under which a bench executable runs as the measuring parent of
/// one command (see [`measure`]).
const MEASURE_FLAG: &str = "--measure-child";

/// `hscene render SCENE -o OUT [--threads T]`, the command every bench
/// measures.
pub fn render_command(hscene: &Path, scene: &Path, out: &Path, threads: Option<usize>) -> Command {
    let mut cmd = Command::new(hscene);
    cmd.arg("render").arg(scene).arg("-o").arg(out);
    if let Some(t) = threads {
        cmd.arg(format!("--threads={t}"));
    }
    cmd
}

/// Run `cmd` with its output going to `log`, and measure it.
///
/// The command runs under a fresh copy of this bench executable
/// ([`measure_child_if_asked`]), which reaps it with `wait4` and prints its
/// rusage. Forking the command from this process instead would report this
/// process's own peak memory for it (Linux carries the peak resident set of
/// the forking process over `exec`), and reading `RUSAGE_CHILDREN` would mix
/// in every earlier child.
pub fn measure(cmd: &Command, log: &Path) -> Result<Measured, String> {
    let me =
        std::env::current_exe().map_err(|e| format!("cannot find the bench executable: {e}"))?;
    let out = std::fs::File::create(log).map_err(|e| format!("{}: {e}", log.display()))?;
    let err = out
        .try_clone()
        .map_err(|e| format!("{}: {e}", log.display()))?;
    let mut wrapper = Command::new(me);
    wrapper
        .arg(MEASURE_FLAG)
        .arg(cmd.get_program())
        .args(cmd.get_args());
    if let Some(dir) = cmd.get_current_dir() {
        wrapper.current_dir(dir);
    }
    let start = Instant::now();
    let output = wrapper
        .stdin(Stdio::null())
        .stderr(err)
        .stdout(Stdio::piped())
        .spawn()
        .and_then(|child| {
            drop(out);
            child.wait_with_output()
        })
        .map_err(|e| format!("cannot start {:?}: {e}", cmd.get_program()))?;
    let wall_s = start.elapsed().as_secs_f64();
    let text = String::from_utf8_lossy(&output.stdout);
    let fields: Vec<f64> = text
        .lines()
        .last()
        .unwrap_or_default()
        .split_whitespace()
        .filter_map(|f| f.parse().ok())
        .collect();
    match (output.status.success(), fields.as_slice()) {
        (true, [cpu_s, peak_kib]) => Ok(Measured {
            cpu_s: *cpu_s,
            wall_s,
            peak_mib: peak_kib / 1024.0,
        }),
        _ => {
            let text = std::fs::read_to_string(log).unwrap_or_default();
            let tail: String = text.lines().rev().take(5).collect::<Vec<_>>().join(" | ");
            Err(format!(
                "{:?} failed ({}): {tail}",
                cmd.get_program(),
                output.status
            ))
        }
    }
}

/// If this process was started by [`measure`], run the command it names,
/// print `cpu_seconds peak_kib` of that command on standard output, and
/// exit (with failure if the command failed); otherwise return. Every bench
/// that uses [`measure`] calls this first in `main`.
pub fn measure_child_if_asked() {
    let args: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    if args.first().is_none_or(|a| a != MEASURE_FLAG) {
        return;
    }
    let code = match args.get(1) {
        None => {
            eprintln!("{MEASURE_FLAG}: no command");
            2
        }
        Some(program) => match reap_measured(Command::new(program).args(&args[2..])) {
            Ok((ok, cpu_s, peak_kib)) => {
                println!("{cpu_s} {peak_kib}");
                if ok { 0 } else { 1 }
            }
            Err(e) => {
                eprintln!("{e}");
                2
            }
        },
    };
    std::process::exit(code);
}

/// Spawn `cmd` (inheriting this process's output), reap it with `wait4`,
/// and return whether it succeeded, its CPU seconds and peak KiB.
fn reap_measured(cmd: &mut Command) -> Result<(bool, f64, f64), String> {
    let child = cmd
        .stdin(Stdio::null())
        .spawn()
        .map_err(|e| format!("cannot start {:?}: {e}", cmd.get_program()))?;
    let pid = child.id() as libc::pid_t;
    let mut status: libc::c_int = 0;
    // SAFETY: an all-zero `rusage` is a valid value of that plain C struct.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    loop {
        // SAFETY: `pid` is our own unreaped child; both out-pointers are
        // valid for the call.
        let got = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
        if got == pid {
            break;
        }
        let e = std::io::Error::last_os_error();
        if e.kind() != std::io::ErrorKind::Interrupted {
            return Err(format!("wait4: {e}"));
        }
    }
    // Reaped above; dropping the handle neither waits nor kills.
    drop(child);
    let secs = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    let ok = libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0;
    // Linux reports kilobytes.
    Ok((
        ok,
        secs(usage.ru_utime) + secs(usage.ru_stime),
        usage.ru_maxrss as f64,
    ))
}

/// Render the POV-Ray source `pov` at `resolution` squared, without
/// anti-aliasing, with `threads` worker threads (all cores when `None`).
/// Runs in a temporary directory: POV-Ray's default I/O restrictions allow
/// writing only below the working directory.
pub fn povray(pov: &str, resolution: u32, threads: Option<usize>) -> Result<Measured, String> {
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    std::fs::write(dir.path().join("twin.pov"), pov).map_err(|e| e.to_string())?;
    let mut cmd = Command::new("povray");
    cmd.current_dir(dir.path()).args([
        "+Itwin.pov".to_string(),
        "+Otwin.png".into(),
        format!("+W{resolution}"),
        format!("+H{resolution}"),
        "-D".into(),
        "-A".into(),
        "-GA".into(),
        "+FN".into(),
    ]);
    if let Some(t) = threads {
        cmd.arg(format!("+WT{t}"));
    }
    measure(&cmd, &dir.path().join("povray.log"))
}

/// The primary rays of a `k x k` grid of pixel centres, and the scene as the
/// renderer prepares it for them.
pub struct Probe {
    /// The camera's frame.
    pub camera: CanonicalFrame,
    /// The scene in that frame.
    pub prepared: PreparedScene,
    /// Ray directions from the eye, in that frame.
    pub dirs: Vec<DVec3>,
}

impl Probe {
    /// The probe of `scene` through net 0.
    pub fn new(scene: &Scene, k: u32) -> Result<Probe, String> {
        let camera = hrender::canonical_frame(&scene.camera).map_err(|e| e.to_string())?;
        let prepared = PreparedScene::for_camera(scene, &camera).map_err(|e| e.to_string())?;
        let window = match scene.settings.fov {
            None => scene.settings.window,
            Some(fov) => {
                let res = Resolution::new(k, k).ok_or("an empty grid")?;
                hscene_lang::view::fov_window(fov, Net::Euclidean, res, camera.view_distance)
                    .map_err(|e| format!("fov {fov}: {e:?}"))?
            }
        };
        let net = PixelNet::new(Net::Euclidean, window, camera.view_distance);
        let mut dirs = Vec::new();
        for j in 0..k {
            for i in 0..k {
                let sx = (f64::from(i) + 0.5) / f64::from(k) - 0.5;
                let sy = 0.5 - (f64::from(j) + 0.5) / f64::from(k);
                if let Sample::Ray(dir) = net.sample(sx, sy) {
                    dirs.push(dir);
                }
            }
        }
        Ok(Probe {
            camera,
            prepared,
            dirs,
        })
    }
}

/// The error of the renderer's primary hits.
pub struct HitErrors {
    /// Largest hyperbolic distance to the 320-bit hit.
    pub max: f64,
    /// Median of the same.
    pub median: f64,
    /// Hits measured (those on spheres, h-cylinders, rods and wireframes).
    pub sampled: usize,
}

/// A surface as the zero set of a 320-bit function of hyperboloid points.
type Implicit = Box<dyn Fn(&V4) -> R>;

/// One surface in the camera's frame, as the reference knows it.
enum Part {
    Sphere(HSphere),
    Cylinder(HCylinder),
    Rod(Box<Rod>),
}

impl Part {
    fn intersect(&self, ray: &Ray) -> Option<f64> {
        let hit = match self {
            Part::Sphere(s) => s.intersect(ray, 0.0, f64::INFINITY),
            Part::Cylinder(c) => c.intersect(ray, 0.0, f64::INFINITY),
            Part::Rod(rod) => rod.intersect(ray, 0.0, f64::INFINITY),
        };
        hit.map(|h| h.t)
    }

    /// The surface's implicit function; `None` where the reference cannot
    /// express it (ideal ends).
    fn implicit(&self) -> Option<Implicit> {
        match self {
            Part::Sphere(s) => {
                let c = r::hyperboloid(s.center().coords());
                let k = R::f(s.radius()).cosh();
                Some(Box::new(move |x: &V4| -r::ldot(x, &c) - &k))
            }
            Part::Cylinder(cyl) => {
                let line = cyl.line();
                let (a, b) = (line.point_at(0.0).ok()?, line.point_at(1.0).ok()?);
                let (ah, bh) = (r::hyperboloid(a.coords()), r::hyperboloid(b.coords()));
                let sh = R::f(cyl.radius()).sinh();
                let s2 = &sh * &sh;
                Some(Box::new(move |x: &V4| r::sinh2_to_line(x, &ah, &bh) - &s2))
            }
            Part::Rod(rod) => {
                let (Vertex::Interior(a), Vertex::Interior(b)) = (rod.start(), rod.end()) else {
                    return None;
                };
                let (ah, bh) = (r::hyperboloid(a.coords()), r::hyperboloid(b.coords()));
                let sh = R::f(rod.radius()).sinh();
                let s2 = &sh * &sh;
                Some(Box::new(move |x: &V4| {
                    r::sinh2_to_segment(x, &ah, &bh) - &s2
                }))
            }
        }
    }
}

/// Max and median hyperbolic distance between the primary hit points and
/// their 320-bit recomputation, over the probe's rays. In a wireframe the
/// rod whose own f64 hit lies nearest the renderer's is the one measured.
pub fn hit_errors(scene: &Scene, probe: &Probe) -> HitErrors {
    let stages = &probe.camera.stages;
    let mut errors = Vec::new();
    for &dir in &probe.dirs {
        let ray = Ray::from_origin_unchecked(dir);
        let Nearest::Hit(hit, index) = probe.prepared.nearest(&ray, 0.0) else {
            continue;
        };
        let move_rod = |rod: &Rod| stages.iter().fold(rod.clone(), |r, iso| r.transformed(iso));
        let part = match &scene.objects[index].shape {
            Shape::Sphere(s) => Part::Sphere(stages.iter().fold(*s, |s, iso| s.transformed(iso))),
            Shape::Cylinder(c) => {
                Part::Cylinder(stages.iter().fold(**c, |c, iso| c.transformed(iso)))
            }
            Shape::Rod(rod) => Part::Rod(Box::new(move_rod(rod))),
            Shape::Wireframe(rods) => {
                let nearest = rods
                    .iter()
                    .map(|rod| Part::Rod(Box::new(move_rod(rod))))
                    .filter_map(|p| p.intersect(&ray).map(|t| ((t - hit.t).abs(), p)))
                    .min_by(|a, b| a.0.total_cmp(&b.0));
                let Some((_, part)) = nearest else {
                    continue;
                };
                part
            }
            _ => continue,
        };
        let Some(f) = part.implicit() else {
            continue;
        };
        if let Some(t_ref) = r::root_near(hit.t, |t| f(&r::from_origin(dir, t))) {
            errors.push((R::f(hit.t) - t_ref).abs().to_f64());
        }
    }
    errors.sort_by(f64::total_cmp);
    HitErrors {
        max: errors.last().copied().unwrap_or(0.0),
        median: errors.get(errors.len() / 2).copied().unwrap_or(0.0),
        sampled: errors.len(),
    }
}
