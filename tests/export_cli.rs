//! `hscene export` end to end: the files it writes, and what it refuses
//! before meshing anything.

use std::fs;
use std::path::Path;

use assert_cmd::Command;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

const SCENE: &str = "BRDFs { red: diffuse = (0.8, 0.1, 0.1); }\n\
                     Objects { Sphere (0.2, 0.1, 0), 0.4, #red; Rod (-0.5, 0, 0), (0.5, 0.1, 0), 0.06, #red; }\n";

fn write_scene(dir: &Path) -> std::path::PathBuf {
    let scene = dir.join("s.hsc");
    fs::write(&scene, SCENE).unwrap();
    scene
}

/// Nothing but the outputs is left in the directory: no temporary files.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn every_format_is_written_with_its_summary() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path());
    for name in ["m.stl", "m.3mf", "m.obj", "m.glb"] {
        let out = dir.path().join(name);
        let result = hscene()
            .args([
                "export",
                scene.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ])
            .assert()
            .success();
        let stderr = String::from_utf8_lossy(&result.get_output().stderr).into_owned();
        assert!(
            stderr.contains("2 shells") && stderr.contains("triangles"),
            "{stderr}"
        );
        assert!(fs::metadata(&out).unwrap().len() > 0);
    }
    let stl = fs::read(dir.path().join("m.stl")).unwrap();
    let count = u32::from_le_bytes(stl[80..84].try_into().unwrap()) as usize;
    assert_eq!(stl.len(), 84 + 50 * count);
    assert_eq!(&fs::read(dir.path().join("m.glb")).unwrap()[..4], b"glTF");
    assert_eq!(&fs::read(dir.path().join("m.3mf")).unwrap()[..2], b"PK");
    let obj = fs::read_to_string(dir.path().join("m.obj")).unwrap();
    assert!(obj.contains("mtllib m.mtl") && obj.contains("usemtl red"));
    assert!(
        fs::read_to_string(dir.path().join("m.mtl"))
            .unwrap()
            .contains("newmtl red")
    );
    assert_eq!(
        names(dir.path()),
        ["m.3mf", "m.glb", "m.mtl", "m.obj", "m.stl", "s.hsc"]
    );
}

#[test]
fn bad_outputs_and_options_are_refused_before_meshing() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path());
    let s = scene.to_str().unwrap();
    let cases: [(&[&str], &str); 5] = [
        (&["-o", "x.ply"], "cannot tell the format"),
        (&["-o", s], "cannot tell the format"),
        (&["-o", "x.stl", "--size", "ten"], "is not a length"),
        (
            &["-o", "x.stl", "--tolerance", "2mm"],
            "tolerance must be smaller",
        ),
        (&["-o", "no/such/dir/x.stl"], "x.stl"),
    ];
    for (args, message) in cases {
        let result = hscene()
            .current_dir(dir.path())
            .arg("export")
            .arg(s)
            .args(args)
            .assert()
            .failure();
        let stderr = String::from_utf8_lossy(&result.get_output().stderr).into_owned();
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
    // The scene is never an output, whatever its name says.
    let copy = dir.path().join("scene.stl");
    fs::write(&copy, SCENE).unwrap();
    hscene()
        .args([
            "export",
            copy.to_str().unwrap(),
            "-o",
            copy.to_str().unwrap(),
        ])
        .assert()
        .failure();
    assert_eq!(fs::read_to_string(&copy).unwrap(), SCENE);
    assert_eq!(names(dir.path()), ["s.hsc", "scene.stl"]);
}

#[test]
fn a_failed_export_leaves_the_earlier_file() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path());
    let out = dir.path().join("m.stl");
    fs::write(&out, b"earlier").unwrap();
    hscene()
        .args([
            "export",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .args(["--max-triangles", "10"])
        .assert()
        .failure()
        .stderr(predicates::str::contains("--max-triangles"));
    assert_eq!(fs::read(&out).unwrap(), b"earlier");
    assert_eq!(names(dir.path()), ["m.stl", "s.hsc"]);
}

/// A scene in a quotient space has no one shape in the ball: the export
/// says so and writes nothing.
#[test]
fn a_scene_in_a_space_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(
        &scene,
        format!("Globals {{ space = seifert_weber; }}\n{SCENE}"),
    )
    .unwrap();
    let out = dir.path().join("m.stl");
    let result = hscene()
        .args([
            "export",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .assert()
        .failure();
    let stderr = String::from_utf8_lossy(&result.get_output().stderr).into_owned();
    assert!(stderr.contains("seifert_weber"), "{stderr}");
    assert!(!out.exists());
    assert_eq!(names(dir.path()), ["s.hsc"]);
}

/// A print has no camera: the eye inside a ball (`HSC1006`) is not worth a
/// maker's time, an unused material (`HSC1002`) still is; two balls that
/// touch nothing are each named as a loose part.
#[test]
fn export_leaves_out_camera_lints_and_warns_of_floating_parts() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(
        &scene,
        "BRDFs { red: diffuse = (0.8, 0.1, 0.1); spare: diffuse = (1, 1, 1); }\n\
         Objects { Sphere (0, 0, 0), 0.2, #red; moon: Sphere (0.6, 0, 0), 0.1, #red; }\n",
    )
    .unwrap();
    let check = hscene().arg("check").arg(&scene).output().unwrap();
    let said = String::from_utf8_lossy(&[check.stdout, check.stderr].concat()).into_owned();
    assert!(said.contains("HSC1006"), "check still says it: {said}");
    let run = hscene()
        .arg("export")
        .arg(&scene)
        .arg("-o")
        .arg(dir.path().join("m.3mf"))
        .output()
        .unwrap();
    assert!(run.status.success(), "{run:?}");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!stderr.contains("HSC1006"), "{stderr}");
    assert!(stderr.contains("HSC1002"), "{stderr}");
    assert!(
        stderr.contains("warning: object 1 touches no other object"),
        "{stderr}"
    );
    assert!(
        stderr.contains("warning: object 2 (\"moon\") touches no other object"),
        "{stderr}"
    );
}
