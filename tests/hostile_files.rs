//! Hostile input, round three: files that are not what they seem (FIFOs,
//! links, read-only, hard-linked, too-long names, inputs named as outputs),
//! failures that used to come late (a frame of an animation, a light too
//! far from the eye), and limits whose messages and code disagreed. Each
//! case runs the real binary with a wall-clock kill, and passes when it
//! ends by itself without a panic and says what it should.

#![cfg(unix)]

use std::fs;
use std::os::unix::fs::PermissionsExt;
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

use crate::limited_run::{Limit, run_hscene};

const WALL_LIMIT: Duration = Duration::from_secs(60);

struct Outcome {
    code: i32,
    /// stderr, then stdout.
    stderr: String,
}

/// Runs `hscene args` in `dir`; `file_size_blocks` sets `ulimit -f`.
fn run_limited(dir: &Path, args: &[&str], file_size_blocks: Option<u64>) -> Outcome {
    run_with_limits(
        dir,
        args,
        file_size_blocks.map(|b| (libc::RLIMIT_FSIZE, b * 512)),
    )
}

/// Runs `hscene args` in `dir` under one resource limit (`setrlimit`).
fn run_with_limits(dir: &Path, args: &[&str], limit: Option<Limit>) -> Outcome {
    let done = run_hscene(dir, args, limit.as_slice(), WALL_LIMIT);
    // What it said, on either stream (`check` reports on stdout).
    Outcome {
        code: done.code,
        stderr: done.stderr + &done.stdout,
    }
}

fn run(dir: &Path, args: &[&str]) -> Outcome {
    run_limited(dir, args, None)
}

fn mkfifo(path: &Path) {
    let c = std::ffi::CString::new(path.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a NUL-terminated path, a mode.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
}

/// Files of a directory whose names start with a dot (temporary files).
fn hidden(dir: &Path) -> Vec<String> {
    fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.'))
        .collect()
}

const SCENE: &str = "Points { eye = (0,0,0); t = (0.5,0,0); }\n\
    Globals { from = %eye; to = %t; fov = 60; resolution = (16, 16); }\n\
    BRDFs { m: diffuse = (1,1,1); }\n\
    Objects { Sphere %t, 0.2, #m; }\n\
    Lights { (0,0.3,0), (1,1,1), (0,0,0); }\n";

const UNFORMATTED: &str = "Points{eye=(0,0,0);}\n";

#[test]
fn check_of_a_fifo_with_no_writer_does_not_hang() {
    let dir = tempfile::tempdir().unwrap();
    mkfifo(&dir.path().join("scene.hsc"));
    let out = run(dir.path(), &["check", "scene.hsc"]);
    // An empty scene: whatever it reports, it ended by itself.
    assert!(out.code <= 1, "{}", out.stderr);
}

#[test]
fn fmt_refuses_a_fifo_without_reading_it() {
    let dir = tempfile::tempdir().unwrap();
    mkfifo(&dir.path().join("scene.hsc"));
    let out = run(dir.path(), &["fmt", "scene.hsc"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("not a regular file"), "{}", out.stderr);
    assert!(hidden(dir.path()).is_empty());
}

#[test]
fn fmt_formats_the_file_a_link_names_and_keeps_the_link() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("real")).unwrap();
    fs::write(dir.path().join("real/scene.hsc"), UNFORMATTED).unwrap();
    std::os::unix::fs::symlink("real/scene.hsc", dir.path().join("link.hsc")).unwrap();
    let out = run(dir.path(), &["fmt", "link.hsc"]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let link = fs::symlink_metadata(dir.path().join("link.hsc")).unwrap();
    assert!(link.file_type().is_symlink(), "the link is still a link");
    let formatted = fs::read_to_string(dir.path().join("real/scene.hsc")).unwrap();
    assert_ne!(formatted, UNFORMATTED);
    assert!(hidden(dir.path()).is_empty() && hidden(&dir.path().join("real")).is_empty());
}

#[test]
fn fmt_treats_read_only_and_hard_linked_files_as_render_does() {
    let dir = tempfile::tempdir().unwrap();
    let ro = dir.path().join("ro.hsc");
    fs::write(&ro, UNFORMATTED).unwrap();
    fs::set_permissions(&ro, fs::Permissions::from_mode(0o444)).unwrap();
    // Root may write anything; the permission bits are what is checked.
    let out = run(dir.path(), &["fmt", "ro.hsc"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("read-only"), "{}", out.stderr);
    assert_eq!(fs::read_to_string(&ro).unwrap(), UNFORMATTED);
    let out = run(dir.path(), &["fmt", "--force", "ro.hsc"]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_ne!(fs::read_to_string(&ro).unwrap(), UNFORMATTED);
    assert_eq!(
        fs::metadata(&ro).unwrap().permissions().mode() & 0o777,
        0o444,
        "permissions kept"
    );

    let a = dir.path().join("a.hsc");
    fs::write(&a, UNFORMATTED).unwrap();
    fs::hard_link(&a, dir.path().join("b.hsc")).unwrap();
    let out = run(dir.path(), &["fmt", "a.hsc"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("hard links"), "{}", out.stderr);
    assert_eq!(
        fs::read_to_string(dir.path().join("b.hsc")).unwrap(),
        UNFORMATTED
    );
    assert!(hidden(dir.path()).is_empty());
}

#[test]
fn a_file_size_limit_during_a_write_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("s.hsc"), SCENE).unwrap();
    fs::write(dir.path().join("out.tif"), b"earlier").unwrap();
    // 16 x 16 float TIFF is 3 KiB and more: past a limit of 2 blocks.
    let out = run_limited(
        dir.path(),
        &["render", "s.hsc", "-o", "out.tif", "--depth", "32f"],
        Some(2),
    );
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert_eq!(fs::read(dir.path().join("out.tif")).unwrap(), b"earlier");
    assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
}

#[test]
fn output_names_too_long_are_refused_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("s.hsc"), SCENE).unwrap();
    let long = format!("{}.png", "x".repeat(252));
    let out = run(dir.path(), &["render", "s.hsc", "-o", &long]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("at most 255"), "{}", out.stderr);
    // Frame names pushed past the limit by their number.
    let anim = SCENE.replace("fov = 60;", "fov = 60; frames = 2;")
        + "Transformations { axis: hline((0,0,0), (0,0.5,0)); @camera->Rotate(%axis, 0.1), animate; }\n";
    fs::write(dir.path().join("a.hsc"), anim).unwrap();
    let near = format!("{}.png", "y".repeat(248));
    let out = run(dir.path(), &["render", "a.hsc", "-o", &near]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("at most 255"), "{}", out.stderr);
    assert!(!out.stderr.contains("frame 1/"));
}

#[test]
fn an_output_may_be_no_file_the_scene_names() {
    let dir = tempfile::tempdir().unwrap();
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    fs::write(dir.path().join("m.obj"), tri).unwrap();
    let texture = image::RgbImage::from_pixel(2, 2, image::Rgb([200, 100, 50]));
    texture.save(dir.path().join("t.png")).unwrap();
    let png = fs::read(dir.path().join("t.png")).unwrap();
    let scene = SCENE
        .replace(
            "BRDFs { m: diffuse = (1,1,1); }",
            "BRDFs { m: diffuse = (1,1,1), texture = \"t.png\"; }",
        )
        .replace(
            "Objects { Sphere %t, 0.2, #m; }",
            "Objects { Sphere %t, 0.2, #m; Mesh \"m.obj\", 0.2, #m; }",
        );
    fs::write(dir.path().join("s.hsc"), scene).unwrap();
    for args in [
        vec!["render", "s.hsc", "-o", "t.png"],
        vec!["export", "s.hsc", "-o", "m.obj"],
    ] {
        let out = run(dir.path(), &args);
        assert_eq!(out.code, 2, "{args:?}: {}", out.stderr);
        assert!(out.stderr.contains("input"), "{args:?}: {}", out.stderr);
    }
    assert_eq!(fs::read_to_string(dir.path().join("m.obj")).unwrap(), tri);
    assert_eq!(fs::read(dir.path().join("t.png")).unwrap(), png);
}

#[test]
fn an_animation_that_fails_at_a_later_frame_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    // The eye 30 from the origin, the light running 36 the other way over
    // 10 frames (4 a frame): past what f64 holds from the eye at frame 2.
    let scene = SCENE
        .replace("fov = 60;", "fov = 60; frames = 10;")
        .replace(
            "Lights { (0,0.3,0), (1,1,1), (0,0,0); }",
            "Lights { l: (0,0.3,0), (1,1,1), (0,0,0); }",
        )
        + "Transformations { axis: hline((0,0,0), (0,0.5,0)); %eye->Translate(%axis, -30); @l->Translate(%axis, 36), animate; }\n";
    fs::write(dir.path().join("s.hsc"), &scene).unwrap();
    let out = run(dir.path(), &["render", "s.hsc", "-o", "f.png"]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("nothing was written"), "{}", out.stderr);
    assert!(out.stderr.contains("s.hsc:"), "located: {}", out.stderr);
    let written: Vec<_> = fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".png"))
        .collect();
    assert!(written.is_empty(), "{written:?}");
}

#[test]
fn a_light_or_object_too_far_from_the_eye_fails_check() {
    let dir = tempfile::tempdir().unwrap();
    for (name, moved) in [("light", "@l"), ("object", "@b")] {
        let scene = SCENE
            .replace("Lights { (", "Lights { l: (")
            .replace("Objects { Sphere", "Objects { b: Sphere")
            + &format!(
                "Transformations {{ x: hline((0,0,0), (0,0.5,0)); {moved}->Translate(%x, 36); %eye->Translate(%x, -5); }}\n"
            );
        let file = format!("{name}.hsc");
        fs::write(dir.path().join(&file), scene).unwrap();
        let out = run(dir.path(), &["check", &file]);
        assert_eq!(out.code, 1, "{name}: {}", out.stderr);
        assert!(out.stderr.contains("HSC0308"), "{name}: {}", out.stderr);
        assert!(
            out.stderr.contains("too far from the eye"),
            "{name}: {}",
            out.stderr
        );
    }
}

#[test]
fn limits_and_messages_agree() {
    let dir = tempfile::tempdir().unwrap();
    let check = |name: &str, text: String| {
        fs::write(dir.path().join(name), text).unwrap();
        run(dir.path(), &["check", name])
    };
    // Honeycomb `edges` is a length, bounded like `vertices`.
    let out = check(
        "edges.hsc",
        SCENE.replace(
            "Objects { Sphere %t, 0.2, #m; }",
            "Objects { Honeycomb {4,3,5}, #m, edges = 40; }",
        ),
    );
    assert!(
        out.stderr.contains("HSC0403") && out.stderr.contains("at most 36"),
        "{}",
        out.stderr
    );
    // A negative entry is a bad symbol, not an unclosed section.
    let out = check(
        "neg.hsc",
        SCENE.replace(
            "Objects { Sphere %t, 0.2, #m; }",
            "Objects { Honeycomb {-4,3,5}, #m; }",
        ),
    );
    assert!(!out.stderr.contains("not closed"), "{}", out.stderr);
    assert!(
        out.stderr.contains("{-4,3,5}") || out.stderr.contains("-4"),
        "{}",
        out.stderr
    );
    // Figures up to the documented size 36.
    for size in [19, 25, 30, 36] {
        let out = check(
            "fig.hsc",
            SCENE.replace(
                "Objects { Sphere %t, 0.2, #m; }",
                &format!("Objects {{ Cube {size}, #m; Tetrahedron {size}, #m; Octahedron {size}, #m; Dodecahedron {size}, #m; Icosahedron {size}, #m; }}"),
            ),
        );
        assert!(
            !out.stderr.contains("coincide") && !out.stderr.contains("collinear"),
            "size {size}: {}",
            out.stderr
        );
    }
    // A polygon of ideal vertices moved far along its own plane: three of
    // its four vertices within 1e-9 of each other in the ball, told apart
    // by f64 all the same.
    for d in [20, 30] {
        let out = check(
            "ideal.hsc",
            format!(
                "Points {{ eye = (0,0,0); t = (0.5,0,0); a = (1,0,0); b = (0,1,0); c = (-1,0,0); e = (0,-1,0); }}\n\
                 Globals {{ from = %eye; to = %t; fov = 60; }}\n\
                 BRDFs {{ m: diffuse = (1,1,1); }}\n\
                 Objects {{ Polygon (%a, %b, %c, %e), #m; }}\n\
                 Transformations {{ x: hline((0,0,0), (0.5,0,0)); %a->Translate(%x, {d}); %b->Translate(%x, {d}); %c->Translate(%x, {d}); %e->Translate(%x, {d}); }}\n"
            ),
        );
        assert_eq!(out.code, 0, "moved {d}: {}", out.stderr);
    }
    // Meshes of any finite extent.
    for (name, a) in [("tiny.obj", "1e-200"), ("huge.obj", "1e308")] {
        fs::write(
            dir.path().join(name),
            format!("v -{a} 0 0\nv {a} 0 0\nv 0 {a} 0\nf 1 2 3\n"),
        )
        .unwrap();
        let out = check(
            "mesh.hsc",
            SCENE.replace(
                "Objects { Sphere %t, 0.2, #m; }",
                &format!("Objects {{ Mesh \"{name}\", 0.2, #m; }}"),
            ),
        );
        assert!(!out.stderr.contains("coincide"), "{name}: {}", out.stderr);
        assert_eq!(out.code, 0, "{name}: {}", out.stderr);
    }
    // A one-face OBJ whose fan would pass what a scene holds is refused as
    // it is read (it used to be fanned whole first: 1.1 GB for 64 MiB).
    let face: String = (0..2_000_100).map(|i| format!(" {}", i % 3 + 1)).collect();
    fs::write(
        dir.path().join("fan.obj"),
        format!("v 0 0 0\nv 1 0 0\nv 0 1 0\nf{face}\n"),
    )
    .unwrap();
    let out = check(
        "fan.hsc",
        SCENE.replace(
            "Objects { Sphere %t, 0.2, #m; }",
            "Objects { Mesh \"fan.obj\", 0.2, #m; }",
        ),
    );
    assert!(
        out.stderr.contains("HSC0502") && out.stderr.contains("2000000 triangles"),
        "{}",
        out.stderr
    );
    // Numbers in messages are short, whatever was written.
    let out = check("fov.hsc", SCENE.replace("fov = 60", "fov = 1e308"));
    assert!(out.stderr.contains("1e308"), "{}", out.stderr);
    assert!(!out.stderr.contains("0000000000"), "{}", out.stderr);
}

/// SIGTERM or SIGINT at any moment of `fmt`: the file is the old one or
/// the whole formatted one, and no temporary file is left.
#[test]
fn a_signal_during_fmt_leaves_the_file_whole_and_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.hsc");
    let text = format!("Points{{{}}}\n", "p=(0.1,0.2,0.3);".repeat(200_000));
    let formatted = {
        fs::write(&path, &text).unwrap();
        let out = run(dir.path(), &["fmt", "big.hsc"]);
        assert_eq!(out.code, 0, "{}", out.stderr);
        fs::read_to_string(&path).unwrap()
    };
    for (signal, delays) in [
        (libc::SIGTERM, [20u64, 80, 200, 500]),
        (libc::SIGINT, [30, 120, 300, 700]),
    ] {
        for delay in delays {
            fs::write(&path, &text).unwrap();
            let mut child = Command::new(env!("CARGO_BIN_EXE_hscene"))
                .args(["fmt", "big.hsc"])
                .current_dir(dir.path())
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .unwrap();
            std::thread::sleep(Duration::from_millis(delay));
            // SAFETY: a signal to our own child.
            unsafe {
                libc::kill(child.id() as libc::pid_t, signal);
            }
            let status = child.wait().unwrap();
            let now = fs::read_to_string(&path).unwrap();
            assert!(
                now == text || now == formatted,
                "signal {signal} after {delay} ms ({status}): the file is neither old nor new"
            );
            assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
        }
    }
}

/// Runs `hscene args` in `dir` as the user `nobody` (uid and gid 65534),
/// from a copy of the binary in `dir`'s parent (the build directory may be
/// closed to other users).
fn run_as_nobody(dir: &Path, args: &[&str]) -> Outcome {
    let exe = dir.parent().unwrap().join("hscene");
    if !exe.exists() {
        fs::copy(env!("CARGO_BIN_EXE_hscene"), &exe).unwrap();
        fs::set_permissions(&exe, fs::Permissions::from_mode(0o755)).unwrap();
    }
    let mut cmd = Command::new(&exe);
    cmd.args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // SAFETY: setgid/setuid are async-signal-safe and touch only the child.
    unsafe {
        cmd.pre_exec(|| {
            if libc::setgid(65534) != 0 || libc::setuid(65534) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let out = cmd.output().expect("the binary starts as nobody");
    let stderr =
        String::from_utf8_lossy(&out.stderr).into_owned() + &String::from_utf8_lossy(&out.stdout);
    assert!(!stderr.contains("panicked"), "{stderr}");
    Outcome {
        code: out.status.code().expect("not killed"),
        stderr,
    }
}

/// Another user's file: replacing it would make it ours, so it needs
/// `--force`; in a sticky directory (as /tmp) only its owner may replace
/// it, so it is refused even then, before anything is written. Run as
/// root, which can make a file another user's and then be that user.
#[test]
fn another_users_file_is_replaced_only_with_force_and_never_in_a_sticky_directory() {
    // SAFETY: geteuid has no preconditions.
    if unsafe { libc::geteuid() } != 0 {
        // Without root no file of another user can be made: what can be
        // checked is that our own file is replaced without `--force`.
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("s.hsc"), UNFORMATTED).unwrap();
        assert_eq!(run(dir.path(), &["fmt", "s.hsc"]).code, 0);
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (sub, mode) in [("open", 0o777), ("sticky", 0o1777)] {
        let d = dir.path().join(sub);
        fs::create_dir(&d).unwrap();
        fs::set_permissions(&d, fs::Permissions::from_mode(mode)).unwrap();
        let file = d.join("s.hsc");
        fs::write(&file, UNFORMATTED).unwrap();
        fs::set_permissions(&file, fs::Permissions::from_mode(0o666)).unwrap();
    }
    fs::set_permissions(dir.path(), fs::Permissions::from_mode(0o755)).unwrap();
    let open = dir.path().join("open");
    let out = run_as_nobody(&open, &["fmt", "s.hsc"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("another user"), "{}", out.stderr);
    assert_eq!(fs::read_to_string(open.join("s.hsc")).unwrap(), UNFORMATTED);
    let out = run_as_nobody(&open, &["fmt", "--force", "s.hsc"]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_ne!(fs::read_to_string(open.join("s.hsc")).unwrap(), UNFORMATTED);

    let sticky = dir.path().join("sticky");
    let out = run_as_nobody(&sticky, &["fmt", "--force", "s.hsc"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("sticky"), "{}", out.stderr);
    assert_eq!(
        fs::read_to_string(sticky.join("s.hsc")).unwrap(),
        UNFORMATTED
    );
    assert!(hidden(&sticky).is_empty() && hidden(&open).is_empty());
}

/// Out of memory (an address-space limit): the image, allocated fallibly
/// before the first ray, is refused with its size; any other allocation
/// ends the process with one line and status 2 (not an abort), and no
/// temporary file is left.
#[test]
fn running_out_of_memory_ends_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("s.hsc"), SCENE).unwrap();
    fs::write(dir.path().join("out.tif"), b"earlier").unwrap();
    let limit = Some((libc::RLIMIT_AS, 768u64 << 20));
    let out = run_with_limits(
        dir.path(),
        &[
            "render",
            "s.hsc",
            "--resolution",
            "12000x11000",
            "--depth",
            "32f",
            "-o",
            "out.tif",
        ],
        limit,
    );
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(
        out.stderr
            .contains("cannot allocate 1584000000 bytes for the image"),
        "{}",
        out.stderr
    );
    assert_eq!(fs::read(dir.path().join("out.tif")).unwrap(), b"earlier");
    // A 16 MiB scene whose syntax tree needs about 400 MB, under a limit of
    // 256 MiB of address space.
    let big = format!("Points {{ {} }}", "p = (1,1,1); ".repeat((16 << 20) / 14));
    fs::write(dir.path().join("big.hsc"), big).unwrap();
    let small_limit = Some((libc::RLIMIT_AS, 256u64 << 20));
    let out = run_with_limits(dir.path(), &["check", "big.hsc"], small_limit);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("out of memory"), "{}", out.stderr);
    assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
}
