//! End-to-end tests of `hscene render`'s anti-aliasing, seed and exposure
//! options, and of its atomic output.

use std::fs;
use std::path::Path;

use assert_cmd::Command;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

fn read_f32_tiff(path: &Path) -> Vec<f32> {
    let mut dec = tiff::decoder::Decoder::new(fs::File::open(path).unwrap()).unwrap();
    match dec.read_image().unwrap() {
        tiff::decoder::DecodingResult::F32(v) => v,
        _ => panic!("expected float samples"),
    }
}

/// Render the Appendix A scene at 32x32 with extra arguments; returns the
/// output file's bytes.
fn render_bytes(dir: &Path, name: &str, extra: &[&str]) -> Vec<u8> {
    let out = dir.join(name);
    hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "32x32",
        ])
        .args(extra)
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    fs::read(&out).unwrap()
}

#[test]
fn samples_and_seed_are_deterministic() {
    let dir = tempfile::tempdir().unwrap();
    let a = render_bytes(dir.path(), "a.png", &["--samples", "4", "--seed", "3"]);
    let b = render_bytes(
        dir.path(),
        "b.png",
        &["--samples", "4", "--seed", "3", "--threads", "1"],
    );
    let c = render_bytes(dir.path(), "c.png", &["--samples", "4", "--seed", "4"]);
    assert_eq!(a, b, "same seed, same image, whatever the threads");
    assert_ne!(a, c, "another seed moves the jitter");
    // One sample is the default: the pixel centres.
    let one = render_bytes(dir.path(), "d.png", &["--samples", "1"]);
    let default = render_bytes(dir.path(), "e.png", &[]);
    assert_eq!(one, default);
    // Net 4 samples too.
    render_bytes(dir.path(), "f.png", &["--samples", "5", "--net", "4"]);
}

#[test]
fn exposure_scales_the_float_output() {
    let dir = tempfile::tempdir().unwrap();
    render_bytes(dir.path(), "base.tif", &["--depth", "32f"]);
    render_bytes(dir.path(), "up.tif", &["--depth", "32f", "--exposure", "2"]);
    render_bytes(
        dir.path(),
        "down.tif",
        &["--depth", "32f", "--exposure", "-1.5"],
    );
    let base = read_f32_tiff(&dir.path().join("base.tif"));
    let up = read_f32_tiff(&dir.path().join("up.tif"));
    let down = read_f32_tiff(&dir.path().join("down.tif"));
    assert!(base.iter().any(|v| *v > 0.0));
    for ((b, u), d) in base.iter().zip(&up).zip(&down) {
        assert_eq!(b * 4.0, *u);
        assert!((b * 2f32.powf(-1.5) - d).abs() <= 1e-6 * b.max(1e-30));
    }
    // 8-bit output is clamped after exposure: brighter, never darker.
    let png0 = render_bytes(dir.path(), "base.png", &[]);
    let png2 = render_bytes(dir.path(), "up.png", &["--exposure", "2"]);
    assert_ne!(png0, png2);
}

#[test]
fn bad_option_values_are_usage_errors() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["--samples", "0"][..],
        &["--samples", "100000"],
        &["--samples", "-3"],
        &["--exposure", "nan"],
        &["--exposure", "1000"],
        &["--exposure", "bright"],
        &["--seed", "-1"],
    ] {
        hscene()
            .args(["render", "scenes/thesis-appendix-a.hsc", "-o"])
            .arg(dir.path().join("x.png"))
            .args(args)
            .assert()
            .code(2);
    }
    assert_eq!(
        fs::read_dir(dir.path()).unwrap().count(),
        0,
        "nothing written"
    );
}

/// A failed render never touches an existing image and leaves no temporary
/// file: a scene with errors (exit 1) and an output in a missing directory
/// (exit 2).
#[test]
fn failed_renders_leave_existing_output_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("keep.png");
    fs::write(&out, b"precious").unwrap();
    let broken = dir.path().join("broken.hsc");
    fs::write(&broken, "Objects { Sphere %7, 0.1, #1; }\n").unwrap();
    hscene()
        .arg("render")
        .arg(&broken)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(1);
    assert_eq!(fs::read(&out).unwrap(), b"precious");
    hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "8x8",
            "-o",
        ])
        .arg(dir.path().join("missing/out.png"))
        .assert()
        .code(2);
    let mut names: Vec<_> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["broken.hsc", "keep.png"]);
}

/// `--aov` writes the pixel layers as channels of the `.exr` output, and
/// refuses any other output before rendering.
#[test]
fn aov_layers_go_into_an_exr_and_nowhere_else() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(
        &scene,
        "Globals { resolution = (9, 9); to = (0, 0, 0.3); }\n\
         BRDFs { diffuse = (1, 1, 1); }\n\
         Lights { (0, 0, 0), (1, 1, 1), (1, 1, 1); }\n\
         Objects { Sphere (0, 0, 0.5), 0.3, #1; }\n",
    )
    .unwrap();
    let exr = dir.path().join("out.exr");
    hscene()
        .arg("render")
        .arg(&scene)
        .args(["--aov", "depth,normal,id,cell", "-o"])
        .arg(&exr)
        .assert()
        .success();
    let bytes = fs::read(&exr).unwrap();
    for channel in ["N.X", "N.Y", "N.Z", "Z", "id", "cell.rank", "cell.class"] {
        let needle = format!("{channel}\0");
        assert!(
            bytes.windows(needle.len()).any(|w| w == needle.as_bytes()),
            "channel {channel} in the header"
        );
    }
    let png = dir.path().join("out.png");
    let refused = hscene()
        .arg("render")
        .arg(&scene)
        .args(["--aov", "depth", "-o"])
        .arg(&png)
        .assert()
        .failure();
    let stderr = String::from_utf8_lossy(&refused.get_output().stderr).into_owned();
    assert!(stderr.contains(".exr"), "{stderr}");
    assert!(!png.exists());
    let unknown = hscene()
        .arg("render")
        .arg(&scene)
        .args(["--aov", "depht", "-o"])
        .arg(&exr)
        .assert()
        .failure();
    let stderr = String::from_utf8_lossy(&unknown.get_output().stderr).into_owned();
    assert!(
        stderr.contains("the layers are depth, normal, id, cell"),
        "{stderr}"
    );
}

/// A picture black because the scene's objects hide its background
/// everywhere (the eye inside an unlit sphere): the warning does not tell
/// the user to add the background the scene has; and after many samples
/// of no light the note says there is no noise to estimate, not that it
/// cannot be estimated from one sample.
#[test]
fn a_black_picture_hiding_its_background_is_told_so() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let scene = dir.path().join("inside.hsc");
    fs::write(
        &scene,
        "Globals { resolution = (8, 8); integrator = path; background = (0.5, 0.6, 0.9); }\n\
         BRDFs { clay: diffuse = (0.8, 0.6, 0.4); }\n\
         Objects { Sphere (0, 0, 0), 0.5, #clay; }",
    )
    .expect("temporary directory is writable");
    let out = hscene()
        .arg("render")
        .arg(&scene)
        .args(["--samples", "16", "-o"])
        .arg(dir.path().join("inside.png"))
        .output()
        .expect("hscene runs");
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("the image is black"), "{stderr}");
    assert!(
        stderr.contains("background is hidden behind its objects"),
        "{stderr}"
    );
    assert!(!stderr.contains("or a `background`"), "{stderr}");
    assert!(stderr.contains("no pixel received light"), "{stderr}");
    assert!(!stderr.contains("from one sample"), "{stderr}");
}
