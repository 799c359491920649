//! End-to-end tests of the `hscene` binary.

use std::fs;
use std::path::Path;

use assert_cmd::Command;
use predicates::prelude::*;

const APPENDIX: &str = include_str!("../scenes/thesis-appendix-a.hsc");

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

fn read_f32_tiff(path: &Path) -> (u32, u32, Vec<f32>) {
    let mut dec = tiff::decoder::Decoder::new(fs::File::open(path).unwrap()).unwrap();
    let (w, h) = dec.dimensions().unwrap();
    match dec.read_image().unwrap() {
        tiff::decoder::DecodingResult::F32(v) => (w, h, v),
        _ => panic!("expected float samples"),
    }
}

#[test]
fn renders_the_appendix_scene_without_nan() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("appendix.tif");
    hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "48x48",
            "--depth",
            "32f",
            "-o",
        ])
        .arg(&out)
        .assert()
        .success();
    let (w, h, samples) = read_f32_tiff(&out);
    assert_eq!((w, h), (48, 48));
    assert!(samples.iter().all(|s| s.is_finite() && *s >= 0.0));
    // The view is through the dodecahedron around the eye: nothing is pure background.
    let lit = samples
        .chunks(3)
        .filter(|p| p.iter().any(|c| *c > 0.01))
        .count();
    assert_eq!(lit, 48 * 48);
}

#[test]
fn renders_png_at_the_scene_resolution_by_default() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("small.hsc");
    fs::write(
        &scene,
        APPENDIX.replace("resolution = (1200,1200);", "resolution = (40,30);"),
    )
    .unwrap();
    let out = dir.path().join("small.png");
    hscene()
        .arg("render")
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    let bytes = fs::read(&out).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    // IHDR width and height, big-endian, at byte 16.
    assert_eq!(u32::from_be_bytes(bytes[16..20].try_into().unwrap()), 40);
    assert_eq!(u32::from_be_bytes(bytes[20..24].try_into().unwrap()), 30);
}

#[test]
fn check_accepts_the_appendix_scene() {
    hscene()
        .args(["check", "--format", "short", "scenes/thesis-appendix-a.hsc"])
        .assert()
        .code(0)
        .stdout(predicate::str::contains("[HSC1006]"))
        .stdout(predicate::str::contains(": error:").not());
}

#[test]
fn check_points_at_a_point_outside_the_absolute() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("bad.hsc");
    fs::write(&scene, APPENDIX.replace("(0,0,0.16);", "(0,0,1.2);")).unwrap();
    let line = APPENDIX
        .lines()
        .position(|l| l.contains("(0,0,0.16);"))
        .unwrap()
        + 1;
    let col = APPENDIX.lines().nth(line - 1).unwrap().find('(').unwrap() + 1;
    hscene()
        .args(["check", "--format", "short"])
        .arg(&scene)
        .assert()
        .code(1)
        .stdout(predicate::str::contains(format!(
            "bad.hsc:{line}:{col}: error: point lies outside the absolute"
        )))
        .stdout(predicate::str::contains("[HSC0301]"));
}

#[test]
fn check_json_has_the_documented_fields() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("bad.hsc");
    fs::write(&scene, "Objects { Sphere %1, 0.1, #1; }").unwrap();
    let out = hscene()
        .args(["check", "--format", "json"])
        .arg(&scene)
        .assert()
        .code(1)
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    let first: serde_json::Value = serde_json::from_str(text.lines().next().unwrap()).unwrap();
    for key in [
        "file",
        "line",
        "column",
        "end_line",
        "end_column",
        "severity",
        "code",
        "message",
        "help",
    ] {
        assert!(first.get(key).is_some(), "missing {key} in {first}");
    }
    assert_eq!(first["code"], "HSC0201");
    assert_eq!(first["line"], 1);
    assert_eq!(first["column"], 18);
}

#[test]
fn human_format_names_the_code_and_the_source() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("bad.hsc");
    fs::write(&scene, "Points { (0,0,1.5); }\n").unwrap();
    hscene()
        .args(["check", "--format", "human"])
        .arg(&scene)
        .assert()
        .code(1)
        .stdout(predicate::str::contains("HSC0301"))
        .stdout(predicate::str::contains("(0,0,1.5)"));
}

#[test]
fn usage_and_io_errors_exit_2() {
    hscene()
        .args(["check", "no/such/file.hsc"])
        .assert()
        .code(2);
    hscene()
        .args(["render", "no/such/file.hsc", "-o", "x.png"])
        .assert()
        .code(2);
    hscene().arg("frobnicate").assert().code(2);
    let dir = tempfile::tempdir().unwrap();
    hscene()
        .args(["render", "scenes/thesis-appendix-a.hsc", "-o"])
        .arg(dir.path().join("out.bmp"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("unsupported output format"));
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn a_failed_render_leaves_the_old_image_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("keep.png");
    fs::write(&out, b"previous image").unwrap();
    let scene = dir.path().join("bad.hsc");
    fs::write(&scene, "Objects { Sphere %9, 0.1, #1; }").unwrap();
    hscene()
        .arg("render")
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(1);
    // A format that cannot hold the requested depth fails after rendering, before writing.
    hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "8x8",
            "--depth",
            "32f",
            "-o",
        ])
        .arg(&out)
        .assert()
        .code(2);
    assert_eq!(fs::read(&out).unwrap(), b"previous image");
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
}

#[test]
fn every_net_renders() {
    let dir = tempfile::tempdir().unwrap();
    for net in 0..=4 {
        let out = dir.path().join(format!("net{net}.tif"));
        hscene()
            .args([
                "render",
                "scenes/thesis-appendix-a.hsc",
                "--resolution",
                "24x24",
                "--depth",
                "32f",
                "--net",
            ])
            .arg(net.to_string())
            .arg("-o")
            .arg(&out)
            .assert()
            .success();
        let (_, _, samples) = read_f32_tiff(&out);
        assert!(samples.iter().all(|s| s.is_finite()), "net {net}");
    }
}

/// Piped (as in CI, or `| less`), `check` and `render` keep the full
/// report, every `help:` line included, and drop only the colour; `--format
/// short` still gives one line per diagnostic.
#[test]
fn piped_output_keeps_the_help_and_drops_the_colour() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("typo.hsc");
    fs::write(&scene, "Globals { resolutoin = (8, 8); }").unwrap();
    let out = hscene().arg("check").arg(&scene).assert().failure();
    let text = String::from_utf8_lossy(&out.get_output().stdout).into_owned();
    assert!(text.contains("help:") || text.contains("help"), "{text}");
    assert!(text.contains("did you mean `resolution`"), "{text}");
    assert!(!text.contains('\u{1b}'), "colour in a pipe: {text:?}");
    let out = hscene()
        .args(["render", "-o"])
        .arg(dir.path().join("x.png"))
        .arg(&scene)
        .assert()
        .failure();
    let text = String::from_utf8_lossy(&out.get_output().stderr).into_owned();
    assert!(text.contains("did you mean `resolution`"), "{text}");
    assert!(!text.contains('\u{1b}'), "colour in a pipe: {text:?}");
    let out = hscene()
        .args(["check", "--format", "short"])
        .arg(&scene)
        .assert()
        .failure();
    let text = String::from_utf8_lossy(&out.get_output().stdout).into_owned();
    assert_eq!(text.lines().count(), 1, "{text}");
}

/// `hscene explain` takes a code as a user types it: `313`, `0313`,
/// `hsc0313` and `HSC0313` are the same code.
#[test]
fn explain_accepts_short_codes() {
    for code in ["313", "0313", "hsc0313", "HSC0313"] {
        hscene()
            .args(["explain", code])
            .assert()
            .success()
            .stdout(predicate::str::contains("HSC0313"));
    }
    hscene().args(["explain", "99999"]).assert().failure();
}
