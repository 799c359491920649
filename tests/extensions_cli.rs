//! End-to-end tests of the language extensions beyond the thesis through the binary: meshes
//! found relative to the scene file, animations written frame by frame, and
//! the new fields of `check --emit ir`.

use std::fs;
use std::path::Path;

use assert_cmd::Command;
use predicates::prelude::PredicateBooleanExt;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

/// An animated scene: a sphere moved along the x axis by `animate`, and the
/// camera still.
const ANIMATED: &str = "\
Globals { frames = 3; resolution = (24, 24); window_size = (0.3, 0.3); to = (0, 0, 0.2); ambient = (1, 1, 1); }
Points  { o = (0, 0, 0); x = (0.2, 0, 0); }
BRDFs   { ambient = (1, 1, 1); }
Objects { ball: Sphere (-0.1, 0, 0.3), 0.04, #1; }
Transformations { right: hline (%o, %x); @ball->Translate(%right), animate; }
";

fn decode(path: &Path) -> image::RgbImage {
    image::open(path).expect("a PNG").to_rgb8()
}

/// The mean column of the lit pixels.
fn centre_column(img: &image::RgbImage) -> f64 {
    let (mut sum, mut n) = (0.0, 0.0);
    for (x, _, p) in img.enumerate_pixels() {
        if p[0] > 128 {
            sum += f64::from(x);
            n += 1.0;
        }
    }
    assert!(n > 0.0, "the sphere is visible");
    sum / n
}

#[test]
fn an_animation_writes_one_numbered_image_per_frame() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("anim.hsc");
    fs::write(&scene, ANIMATED).unwrap();
    let out = dir.path().join("anim.png");
    hscene()
        .args(["render"])
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    assert!(
        !out.exists(),
        "frames are numbered; the bare name is not written"
    );
    let columns: Vec<f64> = (0..3)
        .map(|k| centre_column(&decode(&dir.path().join(format!("anim-{k:04}.png")))))
        .collect();
    assert!(!dir.path().join("anim-0003.png").exists());
    // The sphere moves right at constant hyperbolic speed; seen from the
    // eye its image moves right in every frame.
    assert!(
        columns[0] < columns[1] && columns[1] < columns[2],
        "{columns:?}"
    );

    // `--frame K` renders that frame alone, to exactly the given name, and
    // it is the same image as the frame of the whole sequence.
    let one = dir.path().join("one.png");
    hscene()
        .args(["render"])
        .arg(&scene)
        .args(["--frame", "1", "-o"])
        .arg(&one)
        .assert()
        .success();
    assert_eq!(
        fs::read(&one).unwrap(),
        fs::read(dir.path().join("anim-0001.png")).unwrap()
    );
    // Past the last frame is a usage error.
    hscene()
        .args(["render"])
        .arg(&scene)
        .args(["--frame", "3", "-o"])
        .arg(&one)
        .assert()
        .code(2)
        .stderr(predicates::str::contains("last frame"));
}

#[test]
fn check_emits_the_requested_frame() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("anim.hsc");
    // The sphere's centre on the x axis, translated along it.
    fs::write(&scene, ANIMATED.replace("(-0.1, 0, 0.3)", "(-0.1, 0, 0)")).unwrap();
    let centre_x = |frame: &str| -> f64 {
        let out = hscene()
            .args(["check", "--emit", "ir", "--frame", frame])
            .arg(&scene)
            .output()
            .unwrap();
        assert!(out.status.success());
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["settings"]["frames"], 3);
        assert_eq!(v["frame"].as_u64().unwrap().to_string(), frame);
        v["objects"][0]["center"][0].as_f64().unwrap()
    };
    let (a, b, c) = (centre_x("0"), centre_x("1"), centre_x("2"));
    // Along a diameter the ball radius is tanh(distance / 2).
    let start = 2.0 * (-0.1f64).atanh();
    let d = 2.0 * 0.2f64.atanh();
    assert!((a - -0.1).abs() < 1e-15, "frame 0 is the start: {a}");
    let halfway = ((start + d / 2.0) / 2.0).tanh();
    assert!((b - halfway).abs() < 1e-12, "{b} vs {halfway}");
    let end = ((start + d) / 2.0).tanh();
    assert!(
        (c - end).abs() < 1e-12,
        "the last frame is the whole translation: {c} vs {end}"
    );
}

#[test]
fn a_mesh_is_found_next_to_its_scene_and_rendered() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("meshes")).unwrap();
    fs::write(
        dir.path().join("meshes/tetra.obj"),
        "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n",
    )
    .unwrap();
    let scene = dir.path().join("tetra.hsc");
    fs::write(
        &scene,
        "Globals { resolution = (24, 24); window_size = (0.3, 0.3); to = (0, 0, 0.4); ambient = (1, 1, 1); }\n\
         BRDFs { ambient = (1, 0, 0); }\n\
         Objects { t: Mesh \"meshes/tetra.obj\", 0.3, #1, at = (0, 0, 0.4); }\n",
    )
    .unwrap();
    let out = dir.path().join("tetra.png");
    // Run from elsewhere: the mesh is found relative to the scene file.
    hscene()
        .current_dir(std::env::temp_dir())
        .arg("render")
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    let img = decode(&out);
    assert_eq!(
        img.get_pixel(12, 12).0,
        [255, 0, 0],
        "the mesh is in the middle"
    );
    assert_ne!(img.get_pixel(0, 0).0, [255, 0, 0], "and not everywhere");

    let json = hscene()
        .current_dir(std::env::temp_dir())
        .args(["check", "--emit", "ir"])
        .arg(&scene)
        .output()
        .unwrap();
    assert!(json.status.success());
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let mesh = &v["objects"][0];
    assert_eq!(mesh["kind"], "mesh");
    assert_eq!(mesh["triangles"].as_array().unwrap().len(), 4);
    assert_eq!(mesh["vertices"].as_array().unwrap().len(), 4);
    assert_eq!(mesh["dropped_triangles"], 0);
    // `at` is the mesh's frame: its local origin goes to the centre.
    let t = &mesh["frame"]["translation"];
    assert!((t[2].as_f64().unwrap() - 0.4).abs() < 1e-15);

    // A missing mesh file is an error of the scene (exit 1), reported at
    // the file name.
    fs::remove_file(dir.path().join("meshes/tetra.obj")).unwrap();
    hscene()
        .args(["check", "--format", "short"])
        .arg(&scene)
        .assert()
        .code(1)
        .stdout(predicates::str::contains(
            "3:19: error: cannot read the mesh file",
        ))
        .stdout(predicates::str::contains("[HSC0501]"));
}

#[test]
fn every_shipped_scene_checks_clean() {
    // Scenes that use meshes name them relative to their own directory;
    // `check` must find them from any working directory.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scenes = Vec::new();
    for dir in ["scenes", "scenes/thesis"] {
        for entry in fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "hsc") {
                scenes.push(path);
            }
        }
    }
    assert!(scenes.len() > 30);
    hscene()
        .current_dir(std::env::temp_dir())
        .args(["check", "--format", "short"])
        .args(&scenes)
        .assert()
        .success()
        .stdout(predicates::str::contains("error").not());
}

#[test]
fn the_scenes_samples_setting_anti_aliases_and_the_option_overrides_it() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("aa.hsc");
    let source = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/thesis-appendix-a.hsc"),
    )
    .unwrap();
    fs::write(&scene, format!("{source}\nGlobals {{ samples = 4; }}\n")).unwrap();
    let render = |scene: &Path, name: &str, extra: &[&str]| -> Vec<u8> {
        let out = dir.path().join(name);
        hscene()
            .arg("render")
            .arg(scene)
            .args(["--resolution", "24x24"])
            .args(extra)
            .arg("-o")
            .arg(&out)
            .assert()
            .success();
        fs::read(out).unwrap()
    };
    let original = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/thesis-appendix-a.hsc");
    let from_scene = render(&scene, "a.png", &[]);
    let from_option = render(&original, "b.png", &["--samples", "4"]);
    assert_eq!(from_scene, from_option, "`samples = 4` is `--samples 4`");
    let overridden = render(&scene, "c.png", &["--samples", "1"]);
    let plain = render(&original, "d.png", &[]);
    assert_eq!(overridden, plain, "`--samples 1` overrides the scene");
    assert_ne!(from_scene, plain);
}

/// A scene copied from the docs names its mesh from where that scene was;
/// run from elsewhere, the error names the folder the name led to (the
/// scene's, not the current one) and says how to fix it.
#[test]
fn a_missing_mesh_names_the_folder_it_was_looked_for_in() {
    let dir = tempfile::tempdir().unwrap();
    let mine = dir.path().join("mine");
    fs::create_dir(&mine).unwrap();
    fs::write(
        mine.join("bunny.hsc"),
        "BRDFs { clay: diffuse = (0.8, 0.6, 0.45); }\n\
         Objects { Mesh \"scenes/meshes/bunny.ply\", 0.5, #clay; }\n",
    )
    .unwrap();
    let run = hscene()
        .current_dir(dir.path())
        .args(["check", "mine/bunny.hsc"])
        .output()
        .unwrap();
    assert!(!run.status.success());
    // The report goes to either stream, its help wrapped to a width:
    // compared with its runs of white space as one space.
    let both = [run.stdout, run.stderr].concat();
    let stderr = String::from_utf8_lossy(&both)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    let folder = std::path::absolute(mine.join("scenes/meshes")).unwrap();
    assert!(stderr.contains("HSC0501"), "{stderr}");
    assert!(
        stderr.contains(&format!("looked in the folder `{}`", folder.display())),
        "{stderr}"
    );
    assert!(
        stderr.contains("taken from the scene file's folder"),
        "{stderr}"
    );
    assert!(
        stderr.contains("copy the mesh beside your scene"),
        "{stderr}"
    );
}
