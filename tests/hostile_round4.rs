//! The fourth hostile-input pass (issue 49): videos cut short or
//! interrupted, stderr that cannot be written, textures, the viewer's
//! inputs, late frames, long animated translations, OBJ pairs.
//!
//! Tests that need ffmpeg say they were skipped without it, unless
//! `HSCENE_REQUIRE_FFMPEG` is set (as in tests/video_cli.rs).

use std::fs;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn hscene() -> Command {
    Command::new(env!("CARGO_BIN_EXE_hscene"))
}

const SCENE: &str = "Globals { frames = 12; resolution = (64, 48); from = %eye; to = %centre; }\n\
     BRDFs { paint: ambient = (0.3, 0.3, 0.3), diffuse = (0.9, 0.3, 0.1); }\n\
     Points { eye = (0, 0, 0); centre = (0, 0, 0.5); above = (0, 0.3, 0.5); }\n\
     Lights { (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }\n\
     Objects { Cube 0.4, #paint, at = %centre; }\n\
     Transformations { vertical: hline (%centre, %above); @camera->Rotate(%vertical, 5.2), animate; }\n";

fn ffmpeg() -> bool {
    let found = ["ffmpeg", "ffprobe"].iter().all(|t| {
        Command::new(t)
            .arg("-version")
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    });
    if !found {
        assert!(
            std::env::var_os("HSCENE_REQUIRE_FFMPEG").is_none(),
            "HSCENE_REQUIRE_FFMPEG is set but ffmpeg is missing"
        );
        eprintln!("skipped: ffmpeg is not installed");
    }
    found
}

/// The hidden files left in `dir` (temporary outputs).
fn hidden(dir: &Path) -> Vec<String> {
    fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.'))
        .collect()
}

fn frames_in(path: &Path) -> String {
    let out = Command::new("ffprobe")
        .args(["-v", "error", "-count_packets", "-select_streams", "v:0"])
        .args(["-show_entries", "stream=nb_read_packets", "-of", "csv=p=0"])
        .arg(path)
        .output()
        .unwrap();
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// Class 1: past `ulimit -f` ffmpeg fails writing its trailer yet exits
/// 0; hscene verifies the file, exits 2 and keeps the earlier video.
#[test]
fn a_video_cut_short_by_the_file_size_limit_keeps_the_earlier_one() {
    if !ffmpeg() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("s.hsc"), SCENE).unwrap();
    for name in ["film.mp4", "film.webm"] {
        let status = hscene()
            .args(["render", "s.hsc", "-o", name, "--resolution", "160x120"])
            .current_dir(dir.path())
            .stderr(Stdio::null())
            .status()
            .unwrap();
        assert!(status.success(), "{name}");
        let good = fs::read(dir.path().join(name)).unwrap();
        assert_eq!(frames_in(&dir.path().join(name)), "12", "{name}");
        // Half the video, in sh's blocks of 512 bytes: cut, not empty.
        let blocks = good.len() / 1024;
        assert!(blocks >= 1, "{name} is {} bytes", good.len());
        let out = Command::new("sh")
            .arg("-c")
            .arg(format!(
                "ulimit -f {blocks}; exec '{}' render s.hsc -o {name} --resolution 160x120",
                env!("CARGO_BIN_EXE_hscene")
            ))
            .current_dir(dir.path())
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
        assert!(stderr.contains("ffmpeg failed"), "{name}: {stderr}");
        assert!(!stderr.contains(".hscene-"), "{name}: {stderr}");
        assert_eq!(fs::read(dir.path().join(name)).unwrap(), good, "{name}");
        assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
    }
}

/// Class 10: a size the codec refuses is reported in ffmpeg's words
/// before any frame is rendered.
#[test]
fn ffmpegs_own_reason_is_shown_before_the_first_frame() {
    if !ffmpeg() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("s.hsc"), SCENE).unwrap();
    let out = hscene()
        .args([
            "render",
            "s.hsc",
            "-o",
            "wide.mp4",
            "--resolution",
            "20000x2",
        ])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("invalid width"), "{stderr}");
    assert!(!stderr.contains("Broken pipe"), "{stderr}");
    assert!(!stderr.contains("frame 1/"), "{stderr}");
    assert!(!dir.path().join("wide.mp4").exists());
    assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
}

/// Class 10: a GIF cannot play faster than 50 frames a second, and says so.
#[test]
fn a_gif_says_the_rate_it_plays_at() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("s.hsc"),
        SCENE.replace("frames = 12", "frames = 2"),
    )
    .unwrap();
    let out = hscene()
        .args(["render", "s.hsc", "-o", "f.gif", "--fps", "240"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("plays at 50.000 frames a second"),
        "{stderr}"
    );
    let out = hscene()
        .args(["render", "s.hsc", "-o", "f.apng", "--fps", "23.976"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains("plays at"), "{stderr}");
}

/// Waits (without a deadline that decides the test) until `dir` holds a
/// temporary output, or the process has ended.
fn wait_for_part(dir: &Path, child: &mut std::process::Child) {
    let start = Instant::now();
    while hidden(dir).is_empty() && child.try_wait().unwrap().is_none() {
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "no temporary file"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Class 2: every covered signal, landing while the first frame renders
/// (ffmpeg started, its file not yet opened), stops and reaps ffmpeg,
/// removes the temporary file and keeps the earlier video.
#[test]
fn a_signal_during_a_video_leaves_no_temporary_file() {
    if !ffmpeg() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("s.hsc"), SCENE).unwrap();
    let video = dir.path().join("film.mp4");
    fs::write(&video, b"earlier").unwrap();
    for signal in [
        libc::SIGINT,
        libc::SIGTERM,
        libc::SIGHUP,
        libc::SIGALRM,
        libc::SIGUSR1,
        libc::SIGUSR2,
        libc::SIGXCPU,
    ] {
        let mut child = hscene()
            .args(["render", "s.hsc", "-o", "film.mp4"])
            .args(["--resolution", "1600x1200", "--samples", "16"])
            .current_dir(dir.path())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        wait_for_part(dir.path(), &mut child);
        // SAFETY: a signal to our own child.
        unsafe { libc::kill(child.id() as libc::pid_t, signal) };
        let status = child.wait().unwrap();
        assert_eq!(status.code(), Some(128 + signal), "signal {signal}");
        // ffmpeg was reaped before hscene exited: nothing can recreate
        // the file now.
        assert!(
            hidden(dir.path()).is_empty(),
            "signal {signal}: {:?}",
            hidden(dir.path())
        );
        assert_eq!(fs::read(&video).unwrap(), b"earlier");
    }
}

/// Class 4: a warning that cannot be printed (stderr is /dev/full) does
/// not stop `render`, `export` or `view`, nor make them panic.
#[test]
fn an_unwritable_stderr_loses_the_messages_not_the_work() {
    let dir = tempfile::tempdir().unwrap();
    // No lights: "the image is black" is printed after the render.
    let dark = SCENE.replace("frames = 12", "frames = 1").replace(
        "Lights { (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }\n",
        "",
    );
    fs::write(dir.path().join("s.hsc"), &dark).unwrap();
    let full = || {
        fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap()
    };
    for args in [
        vec!["render", "s.hsc", "-o", "dark.png"],
        vec!["export", "s.hsc", "-o", "m.stl"],
        vec![
            "view",
            "s.hsc",
            "--headless",
            "--frames",
            "1",
            "-o",
            "v.png",
        ],
    ] {
        let status = hscene()
            .args(&args)
            .current_dir(dir.path())
            .stdout(full())
            .stderr(full())
            .status()
            .unwrap();
        assert_eq!(status.code(), Some(0), "{args:?}");
        let out = args[args.len() - 1];
        assert!(dir.path().join(out).exists(), "{args:?}");
    }
    // And stderr in a file past `ulimit -f`.
    let status = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -f 0; exec '{}' render s.hsc -o again.png 2>>log",
            env!("CARGO_BIN_EXE_hscene")
        ))
        .current_dir(dir.path())
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(2), "the image too is past the limit");
    assert!(!dir.path().join("again.png").exists());
    assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
}

/// Class 6: an animation whose points move is compiled per frame, yet
/// reads its texture and mesh once, before the first frame is written: a
/// texture deleted once frame 0 is on disk changes nothing.
#[test]
fn files_deleted_mid_animation_were_read_up_front() {
    let dir = tempfile::tempdir().unwrap();
    let texture = image::RgbImage::from_pixel(4, 4, image::Rgb([200, 100, 50]));
    texture.save(dir.path().join("t.png")).unwrap();
    fs::write(
        dir.path().join("m.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let scene = "Globals { frames = 8; resolution = (640, 480); samples = 4; from = (0, 0, 0); to = (0, 0, 0.5); }\n\
        BRDFs { m: ambient = (0.3, 0.3, 0.3), diffuse = (1, 1, 1), texture = \"t.png\"; }\n\
        Points { p = (0, 0, 0.5); }\n\
        Lights { (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }\n\
        Objects { Sphere %p, 0.2, #m; Mesh \"m.obj\", 0.2, #m, at = %p; }\n\
        Transformations { ax: hline((0, 0, 0), (0.5, 0, 0)); %p->Translate(%ax, 0.3), animate; }\n";
    fs::write(dir.path().join("s.hsc"), scene).unwrap();
    let mut child = hscene()
        .args(["render", "s.hsc", "-o", "f.png"])
        .current_dir(dir.path())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let first = dir.path().join("f-0000.png");
    let start = Instant::now();
    while !first.exists() && child.try_wait().unwrap().is_none() {
        assert!(start.elapsed() < Duration::from_secs(120), "no first frame");
        std::thread::sleep(Duration::from_millis(5));
    }
    fs::remove_file(dir.path().join("t.png")).unwrap();
    fs::remove_file(dir.path().join("m.obj")).unwrap();
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    for k in 0..8 {
        assert!(
            dir.path().join(format!("f-{k:04}.png")).exists(),
            "frame {k}"
        );
    }
}

/// Class 7: `Translate(%ax, 24), animate` over 3 frames: the middle frame
/// (12 along) is built as surely as the last (24), for an object and for
/// the points it is built from.
#[test]
fn a_long_animated_translation_is_built_at_every_frame() {
    let dir = tempfile::tempdir().unwrap();
    for target in ["@s", "%p"] {
        let scene = format!(
            "Globals {{ frames = 3; resolution = (32, 24); from = (0, 0, 0); to = (0, 0, 0.5); }}\n\
             BRDFs {{ paint: diffuse = (0.9, 0.3, 0.1); }}\n\
             Points {{ p = (0, 0, 0.5); }}\n\
             Lights {{ (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }}\n\
             Objects {{ s: Sphere %p, 0.2, #paint; }}\n\
             Transformations {{ ax: hline((0, 0, 0), (0.5, 0, 0)); {target}->Translate(%ax, 24), animate; }}\n"
        );
        fs::write(dir.path().join("s.hsc"), scene).unwrap();
        for k in ["0", "1", "2"] {
            let out = hscene()
                .args(["check", "s.hsc", "--format", "short", "--frame", k])
                .current_dir(dir.path())
                .output()
                .unwrap();
            let text = String::from_utf8_lossy(&out.stdout);
            assert_eq!(out.status.code(), Some(0), "{target} frame {k}: {text}");
            assert!(!text.contains("HSC0308"), "{target} frame {k}: {text}");
        }
    }
}

/// Class 5: `view --headless` reads only a bounded regular file as its
/// path (a FIFO or a device is refused unopened), bounds `--frames`, and
/// says a huge number shortly.
#[test]
fn the_viewers_inputs_are_bounded() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("s.hsc"),
        SCENE.replace("frames = 12; resolution = (64, 48)", "resolution = (8, 6)"),
    )
    .unwrap();
    let fifo = dir.path().join("fifo");
    let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    // SAFETY: a valid C string naming a new file in our directory.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    fs::write(dir.path().join("big.path"), "yaw 1\n".repeat(200_000)).unwrap();
    fs::write(dir.path().join("many.path"), "yaw 1\n".repeat(10_001)).unwrap();
    fs::write(dir.path().join("huge.path"), "forward 1e300\n").unwrap();
    fs::write(dir.path().join("bom.path"), "\u{feff}yaw 1\n").unwrap();
    let view = |extra: &[&str]| {
        hscene()
            .args(["view", "s.hsc", "--headless", "--samples", "1"])
            .args(extra)
            .current_dir(dir.path())
            .output()
            .unwrap()
    };
    for (extra, says) in [
        (vec!["--path", "/dev/zero"], "not a regular file"),
        (vec!["--path", "fifo"], "not a regular file"),
        (vec!["--path", "big.path"], "more than the 1048576"),
        (vec!["--path", "many.path"], "more than 10000 moves"),
        (vec!["--path", "huge.path"], "1e300 is out of range"),
        (vec!["--frames", "4294967295"], "--frames"),
        (vec!["--frames", "10001"], "--frames"),
    ] {
        let out = view(&extra);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {stderr}");
        assert!(stderr.contains(says), "{extra:?}: {stderr}");
    }
    let out = view(&["--path", "bom.path"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("1 moves"));
}

/// Class 8: a line break in an OBJ's name is refused before meshing (it
/// would inject lines through `mtllib`), and an OBJ and its MTL are
/// written together: when the OBJ cannot be written, the old MTL stays.
#[test]
fn an_obj_and_its_mtl_are_written_together_or_not_at_all() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("s.hsc"),
        "BRDFs { red: diffuse = (0.8, 0.1, 0.1); }\n\
         Objects { Sphere (0.2, 0.1, 0), 0.4, #red; Rod (-0.5, 0, 0), (0.5, 0.1, 0), 0.06, #red; }\n",
    )
    .unwrap();
    let out = hscene()
        .args(["export", "s.hsc", "-o", "a\nv 1 2 3\nb.obj"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("mtllib"), "{stderr}");
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
    let status = hscene()
        .args(["export", "s.hsc", "-o", "m.obj"])
        .current_dir(dir.path())
        .stderr(Stdio::null())
        .status()
        .unwrap();
    assert!(status.success());
    let (obj, mtl) = (
        fs::metadata(dir.path().join("m.obj")).unwrap().len(),
        fs::metadata(dir.path().join("m.mtl")).unwrap().len(),
    );
    // Room for the MTL, not for the OBJ (sh's blocks are 512 bytes).
    let blocks = mtl / 512 + 1;
    assert!(blocks * 512 < obj, "{mtl} / {obj}");
    fs::write(dir.path().join("m.obj"), b"old obj").unwrap();
    fs::write(dir.path().join("m.mtl"), b"old mtl").unwrap();
    let status = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -f {blocks}; exec '{}' export s.hsc -o m.obj 2>/dev/null",
            env!("CARGO_BIN_EXE_hscene")
        ))
        .current_dir(dir.path())
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(2));
    assert_eq!(fs::read(dir.path().join("m.obj")).unwrap(), b"old obj");
    assert_eq!(fs::read(dir.path().join("m.mtl")).unwrap(), b"old mtl");
    assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
}

/// Class 10: `check --emit ir` carries the space, its domain and light
/// reach (the default filled in), and the lens.
#[test]
fn the_ir_carries_space_domain_reach_and_lens() {
    let dir = tempfile::tempdir().unwrap();
    let scene = "Globals { space = seifert_weber; domain = 0.01, #paint; aperture = 0.05; focus = 0.4; }\n\
        BRDFs { paint: diffuse = (0.9, 0.3, 0.1); }\n\
        Lights { (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }\n\
        Objects { Sphere (0, 0, 0.3), 0.1, #paint; }\n";
    fs::write(dir.path().join("s.hsc"), scene).unwrap();
    let out = hscene()
        .args(["check", "s.hsc", "--emit", "ir"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text} {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let ir: serde_json::Value = serde_json::from_str(&text).unwrap();
    let s = &ir["settings"];
    assert_eq!(s["aperture"], 0.05, "{s}");
    assert_eq!(s["focus"], 0.4, "{s}");
    assert_eq!(s["space"]["light_reach"], 2.5, "{s}");
    assert_eq!(s["space"]["domain"]["width"], 0.01, "{s}");
    assert_eq!(s["space"]["domain"]["material"], 1, "{s}");
    assert!(s["space"]["name"].is_string(), "{s}");
}

/// Class 10: with net 0, a `to` far from the eye still shows the whole
/// `fov`: inside a sphere every pixel sees the sphere, none the red
/// background past the window's edge.
#[test]
fn net_0_honours_fov_whatever_the_distance_to_to() {
    let dir = tempfile::tempdir().unwrap();
    let scene = "Globals { resolution = (32, 24); from = (0, 0, 0); to = (0, 0, 0.999); fov = 120; background = (1, 0, 0); ambient = (1, 1, 1); }\n\
        BRDFs { paint: ambient = (0, 0.6, 0), diffuse = (0, 0.3, 0); }\n\
        Lights { (0.1, 0.1, 0.1), (1, 1, 1), (0, 0, 0); }\n\
        Objects { Sphere (0, 0, 0), 3, #paint; }\n";
    fs::write(dir.path().join("s.hsc"), scene).unwrap();
    let out = hscene()
        .args(["render", "s.hsc", "-o", "v.png"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let img = image::open(dir.path().join("v.png")).unwrap().to_rgb8();
    let red = img.pixels().filter(|p| p.0[0] > p.0[1]).count();
    assert_eq!(red, 0, "{red} pixels show the background");
}

/// Class 7: in a closed space the viewer folds the eye into the domain
/// after each move: 60 units of flight are all flown, none refused, and
/// the eye ends near the origin.
#[test]
fn the_viewer_folds_the_eye_in_a_closed_space() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("s.hsc"),
        "Globals { space = seifert_weber; resolution = (8, 6); from = (0, 0, 0); to = (0, 0, 0.3); }\n\
         BRDFs { paint: diffuse = (0.9, 0.3, 0.1); }\n\
         Lights { (0.2, 0.1, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }\n\
         Objects { Sphere (0, 0, 0.3), 0.1, #paint; }\n",
    )
    .unwrap();
    fs::write(dir.path().join("fly.path"), "forward 1\n".repeat(60)).unwrap();
    let out = hscene()
        .args([
            "view",
            "s.hsc",
            "--headless",
            "--path",
            "fly.path",
            "--samples",
            "1",
        ])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.starts_with("60 moves"), "{stdout}");
    assert!(!stdout.contains("refused"), "{stdout}");
    let from = stdout.lines().find(|l| l.starts_with("from = (")).unwrap();
    let coords: Vec<f64> = from["from = (".len()..from.len() - 2]
        .split(", ")
        .map(|c| c.parse().unwrap())
        .collect();
    let norm = coords.iter().map(|c| c * c).sum::<f64>().sqrt();
    assert!(norm < 0.9, "the eye is at {from}");
}

/// Class 7: `render` of a camera flown 30 along a line through a closed
/// space: every frame renders (the camera is carried home whole,
/// `space_prepare.rs`), none with a failed pixel, each showing the space's
/// edges and ball (at least a tenth of the pixels; beyond the horizon the
/// space's average appearance shows, as at the origin, not the
/// background: `space_fill.rs`).
#[test]
fn a_camera_flown_far_through_a_closed_space_renders_every_frame() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("fly.hsc"),
        "Globals { space = seifert_weber; domain = 0.03, #brass; frames = 3; resolution = (24, 24);\n\
                   to = (0.1, 0.03, 0.3); fov = 100; background = (0, 0, 1); ambient = (0.3, 0.3, 0.3); }\n\
         Points { o = (0, 0, 0); d = (0.1, 0.03, 0.3); }\n\
         BRDFs { brass: ambient = (0.5, 0.4, 0.2), diffuse = (0.8, 0.6, 0.3); red: ambient = (0.5, 0.1, 0.1), diffuse = (0.9, 0.2, 0.15); }\n\
         Lights { (0.05, 0.1, -0.1), (1, 1, 1), (0.5, 0.5, 0.5), irradiance_at = 0.6; }\n\
         Transformations { axis: hline(%o, %d); @camera->Translate(%axis, 30), animate; }\n\
         Objects { Sphere (0.25, 0, 0.1), 0.12, #red; }\n",
    )
    .unwrap();
    let out = hscene()
        .args(["render", "fly.hsc", "-o", "fly.png"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains("numeric failure"), "{stderr}");
    for k in 0..3 {
        let img = image::open(dir.path().join(format!("fly-{k:04}.png")))
            .unwrap()
            .to_rgb8();
        let background = img.pixels().filter(|p| p.0 == [0, 0, 255]).count();
        assert!(
            background * 10 < img.pixels().len() * 9,
            "frame {k}: {background} of {} pixels show the background",
            img.pixels().len()
        );
    }
}
