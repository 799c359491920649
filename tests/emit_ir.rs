//! End-to-end tests of `hscene check --emit ir` (schema in
//! `docs/ir-schema.md`) and of rendering the example scenes that use the
//! language's extensions.

use std::fs;

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

/// The example scenes written with the extended syntax.
const SCENES: [&str; 5] = [
    "scenes/rods.hsc",
    "scenes/cylinders.hsc",
    "scenes/platonic-wireframe.hsc",
    "scenes/polygons.hsc",
    "scenes/honeycomb-435.hsc",
];

fn emit(path: &std::path::Path) -> Value {
    let out = hscene()
        .args(["check", "--emit", "ir", "--format", "short"])
        .arg(path)
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(text.lines().count(), 1, "one line per scene: {text}");
    serde_json::from_str(&text).unwrap()
}

#[test]
fn emit_ir_prints_the_lowered_scene() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(
        &scene,
        "Points { o = (0,0,0); z = (0,0,0.2); c = (0.1,0,0.3); i = (0,1,0); }
         BRDFs { red: diffuse = (1,0,0); }
         Lights { sun: (0,0.2,0), (1,1,1), (1,1,1); }
         Objects { ball: Sphere %c, 0.05, #red; Rod %c, %i, 0.01, #1; Cube 0.1, #1, edges = 0.005, at = (0,0,0.6); }
         Transformations { l: hline (%o, %z); @ball->Translate(%l); }",
    )
    .unwrap();
    let v = emit(&scene);
    assert_eq!(v["schema"], 1);
    assert_eq!(v["file"], scene.display().to_string());
    assert_eq!(v["settings"]["net_type"], 0);
    assert_eq!(v["camera"]["from"], serde_json::json!([0.0, 0.0, 0.0]));
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 4);
    assert_eq!(points[3]["name"], "i");
    assert_eq!(points[3]["ideal"], true);
    assert_eq!(v["materials"][0]["name"], "red");
    assert_eq!(v["lights"][0]["name"], "sun");
    let objects = v["objects"].as_array().unwrap();
    let kinds: Vec<&str> = objects
        .iter()
        .map(|o| o["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["sphere", "rod", "polyhedron", "wireframe"]);
    // The ball was translated along the z axis by d(0, 0.2): its centre is
    // (0,0,0.2) (+) (0.1,0,0.3) (Möbius addition).
    let (u, w) = ([0.0, 0.0, 0.2f64], [0.1, 0.0, 0.3f64]);
    let uw: f64 = u.iter().zip(&w).map(|(a, b)| a * b).sum();
    let u2: f64 = u.iter().map(|a| a * a).sum();
    let w2: f64 = w.iter().map(|a| a * a).sum();
    let den = 1.0 + 2.0 * uw + u2 * w2;
    for k in 0..3 {
        let expected = ((1.0 + 2.0 * uw + w2) * u[k] + (1.0 - u2) * w[k]) / den;
        let got = objects[0]["center"][k].as_f64().unwrap();
        assert!((got - expected).abs() < 1e-15, "{got} vs {expected}");
    }
    assert_eq!(objects[0]["name"], "ball");
    assert_eq!(objects[0]["radius"], 0.05);
    assert_eq!(objects[1]["end"]["ideal"], true);
    assert_eq!(objects[2]["faces"].as_array().unwrap().len(), 6);
    assert_eq!(objects[3]["rods"].as_array().unwrap().len(), 12);
    assert_eq!(objects[3]["material"], 1);
}

#[test]
fn emit_ir_of_a_scene_with_errors_prints_diagnostics_only() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("bad.hsc");
    fs::write(&scene, "Objects { Rodd %1, %2, 0.01, #1; }").unwrap();
    hscene()
        .args(["check", "--emit", "ir", "--format", "short"])
        .arg(&scene)
        .assert()
        .code(1)
        .stdout(predicate::str::is_empty())
        .stderr(predicate::str::contains("[HSC0105]"));
}

#[test]
fn emit_ir_writes_one_line_per_clean_scene() {
    let out = hscene()
        .args(["check", "--emit", "ir"])
        .args(SCENES)
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    let files: Vec<String> = text
        .lines()
        .map(|l| {
            let v: Value = serde_json::from_str(l).unwrap();
            v["file"].as_str().unwrap().to_string()
        })
        .collect();
    assert_eq!(files, SCENES);
}

#[test]
fn example_scenes_check_clean_and_render() {
    let dir = tempfile::tempdir().unwrap();
    for scene in SCENES {
        hscene()
            .args(["check", "--format", "short", scene])
            .assert()
            .code(0)
            .stdout(predicate::str::is_empty());
        let out = dir.path().join("x.png");
        hscene()
            .args(["render", scene, "--resolution", "24x16", "-o"])
            .arg(&out)
            .assert()
            .success();
        assert!(fs::metadata(&out).unwrap().len() > 0, "{scene}");
    }
}

/// `fov` and fog appear in the settings (`null` when not set); a light
/// given by `irradiance_at` shows its resulting intensity.
#[test]
fn emit_ir_shows_fov_fog_and_light_intensity() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("fog.hsc");
    fs::write(
        &path,
        "Globals { fov = 60; fog_color = (0.1, 0.2, 0.3); fog_distance = 2.5; }
         Points { (0, 0, 0.3); (0, 0.3, 0); }
         BRDFs { diffuse = (1, 1, 1); }
         Lights { %2, (1, 1, 1), (0, 0, 0), irradiance_at = 1; }
         Objects { Sphere %1, 0.05, #1; }",
    )
    .unwrap();
    let v = emit(&path);
    assert_eq!(v["settings"]["fov"], 60.0);
    assert_eq!(v["settings"]["fog"]["distance"], 2.5);
    assert_eq!(v["settings"]["fog"]["color"][2], 0.3);
    let i = v["lights"][0]["diffuse"][0].as_f64().unwrap();
    let expect = 4.0 * std::f64::consts::PI * 1f64.sinh().powi(2);
    assert!((i - expect).abs() < 1e-12, "{i}");
    let plain = emit(std::path::Path::new("scenes/thesis-appendix-a.hsc"));
    assert!(plain["settings"]["fov"].is_null() && plain["settings"]["fog"].is_null());
}
