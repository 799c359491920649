//! End-to-end tests of the colour pipeline through the binary: tagged sRGB
//! PNGs by default, raw linear values on request, OpenEXR output, tone
//! curves and automatic exposure.

use std::fs;
use std::path::Path;

use assert_cmd::Command;
use predicates::prelude::PredicateBooleanExt;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

/// Render the Appendix A scene at 24x24 with extra arguments to `name`.
fn render(dir: &Path, name: &str, extra: &[&str]) -> std::path::PathBuf {
    let out = dir.join(name);
    hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "24x24",
        ])
        .args(extra)
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    out
}

/// The chunk types of a PNG file, in order.
fn png_chunks(bytes: &[u8]) -> Vec<String> {
    let mut at = 8;
    let mut names = Vec::new();
    while at + 8 <= bytes.len() {
        let len = u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        names.push(String::from_utf8_lossy(&bytes[at + 4..at + 8]).into_owned());
        at += 12 + len;
    }
    names
}

fn srgb_encode(x: f64) -> f64 {
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// The default PNG is tagged sRGB and holds the sRGB encoding of the
/// linear radiance that `--depth 32f` writes; `--encoding linear` holds
/// the radiance itself, untagged.
#[test]
fn default_png_is_tagged_srgb_of_the_linear_radiance() {
    let dir = tempfile::tempdir().unwrap();
    let png = render(dir.path(), "a.png", &[]);
    assert!(png_chunks(&fs::read(&png).unwrap()).contains(&"sRGB".to_string()));
    let lin = render(dir.path(), "lin.png", &["--encoding", "linear"]);
    assert!(!png_chunks(&fs::read(&lin).unwrap()).contains(&"sRGB".to_string()));
    let hdr = render(dir.path(), "a.tif", &["--depth", "32f"]);
    let mut dec = tiff::decoder::Decoder::new(fs::File::open(&hdr).unwrap()).unwrap();
    let tiff::decoder::DecodingResult::F32(radiance) = dec.read_image().unwrap() else {
        panic!("expected float samples");
    };
    let srgb = image::open(&png).unwrap().into_rgb8().into_raw();
    let linear = image::open(&lin).unwrap().into_rgb8().into_raw();
    let mut brighter = 0;
    for ((&x, &s), &l) in radiance.iter().zip(&srgb).zip(&linear) {
        let x = f64::from(x).clamp(0.0, 1.0);
        assert_eq!(s, (srgb_encode(x) * 255.0).round() as u8);
        assert_eq!(l, (x * 255.0).round() as u8);
        brighter += usize::from(s > l);
    }
    assert!(brighter > radiance.len() / 2, "sRGB lifts the mid-tones");
}

/// `-o out.exr` writes 32-bit float OpenEXR with the same unclamped
/// values as the float TIFF; an 8-bit EXR is refused before rendering.
#[test]
fn exr_output_holds_the_float_radiance() {
    use exr::prelude::{ReadChannels, ReadLayers};
    let dir = tempfile::tempdir().unwrap();
    let exr_path = render(dir.path(), "a.exr", &[]);
    let hdr = render(dir.path(), "a.tif", &["--depth", "32f"]);
    let mut dec = tiff::decoder::Decoder::new(fs::File::open(&hdr).unwrap()).unwrap();
    let tiff::decoder::DecodingResult::F32(radiance) = dec.read_image().unwrap() else {
        panic!("expected float samples");
    };
    let read = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .rgb_channels(
            |size, _| vec![0.0f32; 3 * size.width() * size.height()],
            |v: &mut Vec<f32>, p, (r, g, b): (f32, f32, f32)| {
                let at = 3 * (p.y() * 24 + p.x());
                v[at..at + 3].copy_from_slice(&[r, g, b]);
            },
        )
        .first_valid_layer()
        .all_attributes()
        .from_file(&exr_path)
        .unwrap();
    assert_eq!(read.layer_data.channel_data.pixels, radiance);
    hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--depth",
            "8",
            "-o",
        ])
        .arg(dir.path().join("b.exr"))
        .assert()
        .code(2)
        .stderr(predicates::str::contains(
            "OpenEXR output does not support 8-bit",
        ));
}

/// The tone curves differ from clip only where they should: Reinhard
/// darkens every lit pixel, and `--exposure auto` reports the stops it
/// chose and brightens this dim scene.
#[test]
fn tone_curves_and_auto_exposure() {
    let dir = tempfile::tempdir().unwrap();
    let clip = image::open(render(dir.path(), "c.png", &[]))
        .unwrap()
        .into_rgb8();
    let reinhard = image::open(render(dir.path(), "r.png", &["--tonemap", "reinhard"]))
        .unwrap()
        .into_rgb8();
    for (c, r) in clip.as_raw().iter().zip(reinhard.as_raw()) {
        assert!(r <= c);
    }
    assert_ne!(clip, reinhard);
    let out = dir.path().join("auto.png");
    let assert = hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "24x24",
        ])
        .args(["--exposure", "auto", "-o"])
        .arg(&out)
        .assert()
        .success();
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    let ev: f64 = stderr
        .split("--exposure auto chose ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse().ok())
        .expect("the chosen exposure is reported");
    assert!(ev > 0.0, "{stderr}");
    let auto = image::open(&out).unwrap().into_rgb8();
    let sum = |i: &image::RgbImage| i.as_raw().iter().map(|&v| u64::from(v)).sum::<u64>();
    assert!(sum(&auto) > sum(&clip));
}

/// A scene lit only by a faint light far away.
const DARK_SCENE: &str = "Globals { resolution = (32, 32); }
         Points { (0, 0, 0.9); (0, 0.5, 0); }
         BRDFs { diffuse = (1, 1, 1), ambient = (0, 0, 0); }
         Lights { %2, (0.01, 0.01, 0.01), (0, 0, 0); }
         Objects { Sphere %1, 0.5, #1; }";

/// A scene lit by a faint light far away warns that it is almost black and
/// names the exposure that would fix it; the Appendix A scene does not.
#[test]
fn an_almost_black_image_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("dark.hsc");
    fs::write(&scene, DARK_SCENE).unwrap();
    hscene()
        .arg("render")
        .arg(&scene)
        .arg("-o")
        .arg(dir.path().join("dark.png"))
        .assert()
        .success()
        .stderr(
            predicates::str::contains("the image is almost black")
                .and(predicates::str::contains("try --exposure")),
        );
    let assert = hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "24x24",
            "-o",
        ])
        .arg(dir.path().join("a.png"))
        .assert()
        .success();
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert!(!stderr.contains("almost black"), "{stderr}");
}

/// The trap of the almost-black warning: it must not fire on a small lit
/// object on black (language.md's smallest useful scene), and its hint
/// must be absolute and idempotent: the hint made at `--exposure 0` and at
/// `--exposure 5` is the same number, and following it gives a picture
/// that no longer warns.
#[test]
fn the_almost_black_hint_is_absolute_and_followed() {
    let dir = tempfile::tempdir().unwrap();
    let small = dir.path().join("small.hsc");
    fs::write(
        &small,
        "BRDFs   { diffuse = (0.8, 0.2, 0.2), specular = (0.5, 0.5, 0.5), shininess = 20; }
         Points  { (0, 0, 0.3); (0.1, 0.2, 0); }
         Lights  { %2, (1, 1, 1), (1, 1, 1); }
         Objects { Sphere %1, 0.05, #1; }",
    )
    .unwrap();
    let run = |scene: &std::path::Path, ev: &str| {
        let out = hscene()
            .arg("render")
            .arg(scene)
            .args(["--resolution", "64x64", "--exposure", ev, "-o"])
            .arg(dir.path().join("x.png"))
            .assert()
            .success();
        String::from_utf8_lossy(&out.get_output().stderr).into_owned()
    };
    let stderr = run(&small, "0");
    assert!(!stderr.contains("almost black"), "{stderr}");
    // A scene with nothing lit at all (the light forgotten) is black, and
    // says so, with what to add.
    let unlit = dir.path().join("unlit.hsc");
    fs::write(
        &unlit,
        "BRDFs { diffuse = (1, 1, 1); } Objects { Sphere (0, 0, 0.2), 0.05, #1; }",
    )
    .unwrap();
    let stderr = run(&unlit, "0");
    assert!(stderr.contains("the image is black"), "{stderr}");
    assert!(stderr.contains("add a light"), "{stderr}");
    let dark = dir.path().join("dark.hsc");
    fs::write(&dark, DARK_SCENE).unwrap();
    let hint = |stderr: &str| -> f64 {
        stderr
            .split("try --exposure ")
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("no hint in {stderr}"))
    };
    let at0 = hint(&run(&dark, "0"));
    let at5 = hint(&run(&dark, "5"));
    assert!((at0 - at5).abs() <= 0.1, "{at0} vs {at5}");
    assert!(at0 > 5.0, "{at0}");
    let followed = run(&dark, &format!("{at0}"));
    assert!(!followed.contains("almost black"), "{followed}");
}

/// `--png-level` changes only the compressed bytes: levels 0 (stored), 3
/// (the default) and 9 hold the same samples, in files no larger as the
/// level rises; a level past 9 is a usage error, before any rendering.
#[test]
fn png_level_changes_the_bytes_not_the_samples() {
    let dir = tempfile::tempdir().unwrap();
    let stored = render(dir.path(), "l0.png", &["--png-level", "0"]);
    let default = render(dir.path(), "l3.png", &[]);
    let smallest = render(dir.path(), "l9.png", &["--png-level", "9"]);
    let three = render(dir.path(), "l3b.png", &["--png-level", "3"]);
    assert_eq!(fs::read(&default).unwrap(), fs::read(&three).unwrap());
    let samples = |p: &Path| image::open(p).unwrap().into_rgb8().into_raw();
    assert_eq!(samples(&stored), samples(&default));
    assert_eq!(samples(&smallest), samples(&default));
    let size = |p: &Path| fs::metadata(p).unwrap().len();
    assert!(size(&stored) > size(&default), "level 0 stores the rows");
    assert!(size(&smallest) <= size(&default));
    hscene()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--png-level",
            "10",
        ])
        .arg("-o")
        .arg(dir.path().join("bad.png"))
        .assert()
        .code(2)
        .stderr(predicates::str::contains("--png-level"));
    assert!(!dir.path().join("bad.png").exists());
}
