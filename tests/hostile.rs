//! The hostile corpus: inputs a hostile user would try, run through the real
//! binary under limits the harness enforces (address space and CPU time via
//! `setrlimit` in the child, and a wall-clock kill far above any honest
//! run). A case passes when the process ends by itself with exit status 0,
//! 1 or 2 (never a panic's 101, never a signal) and says what it should.
//! Files live in `tests/hostile/`; large inputs are generated here.

#![cfg(unix)]

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

use crate::limited_run::run_hscene;

/// Address space of a hostile run: a few times what an honest check or a
/// small render needs.
const MEMORY_LIMIT: u64 = 4 << 30;
/// CPU seconds of a hostile run.
const CPU_LIMIT: u64 = 120;
/// Wall-clock kill, for inputs that block rather than compute.
const WALL_LIMIT: Duration = Duration::from_secs(300);

struct Outcome {
    code: i32,
    stdout: String,
    stderr: String,
}

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/hostile")
}

/// Runs `hscene args` in `dir` under the limits; panics if it is killed,
/// crashes or panics.
fn run_in(dir: &Path, args: &[&str]) -> Outcome {
    let limits = [
        (libc::RLIMIT_AS, MEMORY_LIMIT),
        (libc::RLIMIT_CPU, CPU_LIMIT),
    ];
    let done = run_hscene(dir, args, &limits, WALL_LIMIT);
    Outcome {
        code: done.code,
        stdout: done.stdout,
        stderr: done.stderr,
    }
}

fn run(args: &[&str]) -> Outcome {
    run_in(&corpus(), args)
}

/// Writes a generated input into a fresh directory.
fn generated(name: &str, text: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    fs::write(&path, text).unwrap();
    (dir, path)
}

#[test]
fn columns_past_65535_do_not_panic_the_graphical_report() {
    let (dir, _) = generated("wide.hsc", &format!("{}@\n", " ".repeat(70_000)));
    for cmd in ["check", "render"] {
        let mut args = vec![cmd, "wide.hsc"];
        if cmd == "render" {
            args.extend(["-o", "wide.png"]);
        }
        args.extend(if cmd == "check" {
            &["--format", "human"][..]
        } else {
            &[][..]
        });
        let o = run_in(dir.path(), &args);
        assert_eq!(o.code, 1);
        assert!((o.stdout.clone() + &o.stderr).contains("wide.hsc:1:70001: error"));
    }
}

#[test]
fn many_errors_are_reported_linearly_and_capped() {
    let text = format!("Points {{\n{}}}\n", "(0,0,@);\n".repeat(100_000));
    let (dir, _) = generated("errors.hsc", &text);
    for format in ["human", "short", "json"] {
        let o = run_in(dir.path(), &["check", "--format", format, "errors.hsc"]);
        assert_eq!(o.code, 1);
        assert!(
            o.stdout.contains("99900 more diagnostic(s) not shown"),
            "{format}"
        );
    }
    let (dir, _) = generated("semis.hsc", &format!("Points {{{}}}\n", ";".repeat(40_000)));
    let o = run_in(dir.path(), &["check", "--format", "human", "semis.hsc"]);
    assert!(o.stdout.contains("more diagnostic(s) not shown"));
}

#[test]
fn the_ray_tree_is_bounded_and_the_cut_reported() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("exp.png");
    let scene = corpus().join("exponential-rays.hsc");
    let o = run(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--threads",
        "2",
    ]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(
        o.stderr.contains("their ray trees were cut short"),
        "{}",
        o.stderr
    );
    assert!(out.exists());
}

#[test]
fn mesh_paths_that_never_end_are_refused_without_reading() {
    let dir = tempfile::tempdir().unwrap();
    std::os::unix::fs::symlink("/dev/zero", dir.path().join("zero.obj")).unwrap();
    let fifo = std::ffi::CString::new(dir.path().join("fifo.ply").to_str().unwrap()).unwrap();
    // SAFETY: a valid NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(fifo.as_ptr(), 0o600) }, 0);
    let sparse = fs::File::create(dir.path().join("huge.obj")).unwrap();
    sparse.set_len(2 << 30).unwrap();
    fs::write(
        dir.path().join("s.hsc"),
        "BRDFs { diffuse = (1,0,0); }\nObjects { Mesh \"zero.obj\", 0.5, #1; Mesh \"fifo.ply\", 0.5, #1; Mesh \"huge.obj\", 0.5, #1; }\n",
    )
    .unwrap();
    let o = run_in(dir.path(), &["check", "--format", "short", "s.hsc"]);
    assert_eq!(o.code, 1);
    assert_eq!(
        o.stdout.matches("not a regular file").count(),
        2,
        "{}",
        o.stdout
    );
    assert!(
        o.stdout.contains("more than the limit of 67108864"),
        "{}",
        o.stdout
    );
}

#[test]
fn malformed_meshes_never_echo_their_content() {
    let o = run(&["check", "--format", "short", "mesh-leaks.hsc"]);
    assert_eq!(o.code, 1);
    assert!(
        !o.stdout.contains("root") && !o.stdout.contains("daemon"),
        "{}",
        o.stdout
    );
    // One line per diagnostic, with the mesh line numbers.
    assert_eq!(o.stdout.lines().count(), 2, "{}", o.stdout);
    assert!(
        o.stdout.contains("line 11: not a valid PLY file"),
        "{}",
        o.stdout
    );
    assert!(
        o.stdout
            .contains("line 4: a vertex coordinate is not a number"),
        "{}",
        o.stdout
    );
}

#[test]
fn outputs_are_never_inputs_and_read_only_ones_need_force() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.png");
    fs::copy(corpus().join("frames.hsc"), &scene).unwrap();
    let before = fs::read(&scene).unwrap();
    let o = run_in(
        dir.path(),
        &["render", "s.png", "-o", "s.png", "--frame", "0"],
    );
    assert_eq!(o.code, 2);
    assert!(o.stderr.contains("is the input file"), "{}", o.stderr);
    std::os::unix::fs::symlink("s.png", dir.path().join("link.png")).unwrap();
    let o = run_in(
        dir.path(),
        &["render", "s.png", "-o", "link.png", "--frame", "0"],
    );
    assert!(o.stderr.contains("is the input file"), "{}", o.stderr);
    assert_eq!(fs::read(&scene).unwrap(), before);

    let locked = dir.path().join("locked.png");
    fs::write(&locked, b"keep").unwrap();
    let mut perms = fs::metadata(&locked).unwrap().permissions();
    perms.set_readonly(true);
    fs::set_permissions(&locked, perms).unwrap();
    let o = run_in(
        dir.path(),
        &["render", "s.png", "-o", "locked.png", "--frame", "1"],
    );
    assert_eq!(o.code, 2);
    assert!(o.stderr.contains("read-only; pass --force"), "{}", o.stderr);
    assert_eq!(fs::read(&locked).unwrap(), b"keep");
    let o = run_in(
        dir.path(),
        &[
            "render",
            "s.png",
            "-o",
            "locked.png",
            "--frame",
            "1",
            "--force",
        ],
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_ne!(fs::read(&locked).unwrap(), b"keep");
}

#[test]
fn output_problems_are_found_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    let scene = corpus().join("exponential-rays.hsc");
    let scene = scene.to_str().unwrap();
    // Each would take the whole (bounded but long) render to find out late.
    for (output, extra, says) in [
        (
            "a.png",
            "32f",
            "PNG output does not support 32-bit float samples",
        ),
        (
            "no/such/dir/a.png",
            "8",
            "cannot write into the directory of",
        ),
        ("a.bmp", "8", "unsupported output format"),
    ] {
        let o = run_in(
            dir.path(),
            &["render", scene, "-o", output, "--depth", extra],
        );
        assert_eq!(o.code, 2);
        assert!(o.stderr.contains(says), "{}", o.stderr);
        assert!(!o.stderr.contains("cut short") && !o.stderr.contains(".hscene-"));
    }
    for threads in ["0", "100000"] {
        let o = run_in(
            dir.path(),
            &["render", scene, "-o", "a.png", "--threads", threads],
        );
        assert_eq!(o.code, 2, "{}", o.stderr);
    }
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn a_terminated_render_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let scene = corpus().join("frames.hsc");
    // Big enough to be caught mid-way most of the time; the assertion holds
    // wherever the signal lands.
    let mut child = Command::new(env!("CARGO_BIN_EXE_hscene"))
        .args([
            "render",
            scene.to_str().unwrap(),
            "-o",
            "big.tif",
            "--frame",
            "0",
        ])
        .args([
            "--resolution",
            "4000x4000",
            "--depth",
            "32f",
            "--threads",
            "2",
        ])
        .current_dir(dir.path())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(1500));
    // SAFETY: signalling our own child.
    unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGTERM) };
    let status = child.wait().unwrap();
    let left: Vec<_> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".part") || n.starts_with(".hscene"))
        .collect();
    assert!(left.is_empty(), "{left:?} left after {status}");
}

#[test]
fn encodings_line_ends_and_invisible_characters() {
    let o = run(&["check", "--format", "short", "bom.hsc"]);
    assert_eq!(o.code, 0, "{}", o.stdout);
    // The comment ends at the CR; the later error is found on line 4.
    let o = run(&["check", "--format", "short", "cr-only.hsc"]);
    assert!(o.stdout.contains("cr-only.hsc:4:"), "{}", o.stdout);
    let o = run(&["check", "--format", "short", "nbsp.hsc"]);
    assert!(o.stdout.contains("<U+00A0>"), "{}", o.stdout);
    let o = run(&["check", "--format", "json", "invalid-utf8.hsc"]);
    assert_eq!(o.code, 2);
    let v: serde_json::Value = serde_json::from_str(o.stdout.trim()).unwrap();
    assert_eq!(v["byte_offset"], 21);
    let o = run(&["check", "--format", "json", "no-such-file.hsc"]);
    let v: serde_json::Value = serde_json::from_str(o.stdout.trim()).unwrap();
    assert_eq!(v["severity"], "error");
}

#[test]
fn numbers_and_ranges_have_one_rule() {
    let o = run(&["check", "--format", "short", "numbers.hsc"]);
    assert_eq!(o.code, 1);
    for says in [
        "colour components must be at most 1e18",
        "`NaN` is not a number here",
        "got -1e300",
        "number `1e-400` is too small",
        "the sphere radius must be at most 36, got 1e300",
        "the sphere radius must be at most 36, got 400",
        "the sphere radius must be at most 36, got 711",
    ] {
        assert!(o.stdout.contains(says), "{says}:\n{}", o.stdout);
    }
    assert!(o.stdout.lines().all(|l| l.len() < 200), "{}", o.stdout);
    // Past the last frame: refused by check as by render.
    let o = run(&["check", "--frame", "3", "frames.hsc"]);
    assert_eq!(o.code, 2);
    assert!(
        o.stderr.contains("past the scene's last frame"),
        "{}",
        o.stderr
    );
}

#[test]
fn primitive_amplification_is_refused_before_allocating() {
    let text = format!(
        "BRDFs {{ diffuse = (1,1,1); }}\nObjects {{\n{}}}\n",
        "Tessellation435 7, #1;\n".repeat(10)
    );
    let (dir, _) = generated("t.hsc", &text);
    let o = run_in(
        dir.path(),
        &["check", "--format", "short", "--emit", "ir", "t.hsc"],
    );
    assert_eq!(o.code, 1);
    assert!(o.stderr.contains("[HSC0601]"), "{}", o.stderr);
    assert!(o.stdout.is_empty());
}

/// Errors whose hints search the declared names ("did you mean") and lints
/// comparing every light with every object stay linear: the hint search is
/// skipped for long name lists, and lights are capped.
#[test]
fn hints_and_lints_stay_linear_in_the_scene_size() {
    let n = 20_000;
    let points: String = (0..n).map(|i| format!("p{i} = (0,0,0.1);\n")).collect();
    let objects: String = (0..n)
        .map(|i| format!("Sphere %q{i}, 0.1, #1;\n"))
        .collect();
    let lights: String = (0..2_000)
        .map(|_| "(0,0.2,0), (1,1,1), (1,1,1);\n")
        .collect();
    let text = format!(
        "Points {{\n{points}}}\nLights {{\n{lights}}}\nBRDFs {{ diffuse = (1,0,0); }}\nObjects {{\n{objects}}}\n"
    );
    let (dir, _) = generated("names.hsc", &text);
    let o = run_in(dir.path(), &["check", "--format", "short", "names.hsc"]);
    assert_eq!(o.code, 1);
    assert!(o.stdout.contains("at most 1000 lights"), "{}", o.stdout);
    assert!(o.stdout.contains("more diagnostic(s) not shown"));
}

/// Every scene of the corpus, in every diagnostics format, ends by itself
/// within the limits with status 0, 1 or 2, and every line of the short
/// format is one diagnostic (no file content spills over lines).
#[test]
fn every_corpus_scene_replays_within_the_limits() {
    let mut scenes = 0;
    for entry in fs::read_dir(corpus()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "hsc") {
            continue;
        }
        scenes += 1;
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        for format in ["human", "short", "json"] {
            let o = run(&["check", "--format", format, &name]);
            if format == "short" {
                let prefix = format!("{name}:");
                assert!(
                    o.stdout.lines().all(|l| l.starts_with(&prefix)),
                    "{}",
                    o.stdout
                );
            }
        }
    }
    assert!(scenes >= 8, "{scenes} scenes in {}", corpus().display());
}
