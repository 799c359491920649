//! `hscene view --headless`: the viewer's pipeline without a window.

use std::fs;

use assert_cmd::Command;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

const SCENE: &str = "Globals { resolution = (64, 48); fov = 70; from = (0, 0, 0); to = (0, 0, 0.3); }\n\
     BRDFs { paint: ambient = (0.2, 0.2, 0.2), diffuse = (0.9, 0.3, 0.1); }\n\
     Lights { (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }\n\
     Objects { Sphere (0, 0, 0.45), 0.3, #paint; Sphere (0.25, -0.1, 0.3), 0.12, #paint; }\n";

/// Still, the converged view is `render --samples N`, within one level.
#[test]
fn the_converged_view_is_the_render() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(&scene, SCENE).unwrap();
    let (viewed, rendered) = (dir.path().join("v.png"), dir.path().join("r.png"));
    hscene()
        .args([
            "view",
            scene.to_str().unwrap(),
            "--headless",
            "--frames",
            "0",
        ])
        .args(["--samples", "4", "-o", viewed.to_str().unwrap()])
        .assert()
        .success()
        .stdout(predicates::str::contains(
            "converged to 4 samples per pixel",
        ));
    hscene()
        .args(["render", scene.to_str().unwrap(), "--samples", "4"])
        .args(["-o", rendered.to_str().unwrap()])
        .assert()
        .success();
    let (a, b) = (
        image::open(&viewed).unwrap().to_rgb8(),
        image::open(&rendered).unwrap().to_rgb8(),
    );
    let worst = a
        .as_raw()
        .iter()
        .zip(b.as_raw())
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap();
    assert!(worst <= 1, "{worst} levels apart");
}

/// A flight there and back ends where it started; a bad path line is
/// refused with its line number.
#[test]
fn paths_fly_and_bad_paths_are_located() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(&scene, SCENE).unwrap();
    let path = dir.path().join("flight.txt");
    fs::write(
        &path,
        "# there\nforward 0.2\nyaw 30\n\n# and back\nyaw -30\nback 0.2\n",
    )
    .unwrap();
    let out = hscene()
        .args([
            "view",
            scene.to_str().unwrap(),
            "--headless",
            "--samples",
            "1",
        ])
        .args(["--path", path.to_str().unwrap()])
        .assert()
        .success();
    let stdout = String::from_utf8_lossy(&out.get_output().stdout).into_owned();
    assert!(stdout.contains("4 moves"), "{stdout}");
    let from = stdout.lines().find(|l| l.starts_with("from")).unwrap();
    let coords: Vec<f64> = from
        .trim_start_matches("from = (")
        .trim_end_matches(");")
        .split(", ")
        .map(|c| c.parse().unwrap())
        .collect();
    assert!(coords.iter().all(|c| c.abs() < 1e-14), "{from}");
    fs::write(&path, "forward 0.1\nsideways 3\n").unwrap();
    hscene()
        .args(["view", scene.to_str().unwrap(), "--headless"])
        .args(["--path", path.to_str().unwrap()])
        .assert()
        .code(2)
        .stderr(predicates::str::contains("line 2"));
}

/// `--frames 0` flies nothing: the report says so instead of dividing by
/// zero moves (it printed "1000000000000.0 fps"), and the still view still
/// converges.
#[test]
fn no_moves_reports_nothing_flown() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(&scene, SCENE).unwrap();
    let out = hscene()
        .arg("view")
        .arg(&scene)
        .args([
            "--headless",
            "--frames",
            "0",
            "--samples",
            "2",
            "--resolution",
            "16x12",
        ])
        .assert()
        .success();
    let stdout = String::from_utf8_lossy(&out.get_output().stdout).into_owned();
    assert!(
        stdout.contains("0 moves at 16x12: nothing flown"),
        "{stdout}"
    );
    assert!(!stdout.contains("fps"), "{stdout}");
    assert!(
        stdout.contains("converged to 2 samples per pixel"),
        "{stdout}"
    );
}
