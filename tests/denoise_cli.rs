//! `render --denoise` and the scene's `denoise = true;`: refused with the
//! command that installs the library where it is missing (forced here by
//! pointing `HSCENE_OIDN` at a missing file), checked by `hscene check`,
//! and, where Intel Open Image Denoise is installed, a denoised picture
//! with its noisy layer beside it. Without the library that last check
//! says it was skipped, unless `HSCENE_REQUIRE_OIDN` is set.

use std::fs;
use std::path::Path;

use assert_cmd::Command;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

/// A small path-traced box: a lit sphere on a floor, noisy at 2 samples.
fn scene(dir: &Path, globals: &str) -> std::path::PathBuf {
    let path = dir.join("s.hsc");
    fs::write(
        &path,
        format!(
            "Globals {{ resolution = (12, 10); to = (0, 0, 0.3); integrator = path; samples = 2; {globals} }}\n\
             BRDFs {{ white: diffuse = (0.8, 0.8, 0.8); lamp: emission = (4, 4, 4); }}\n\
             Objects {{ Sphere (0, 0, 0.5), 0.2, #white; Sphere (0, 0.4, 0.4), 0.1, #lamp; }}\n"
        ),
    )
    .unwrap();
    path
}

/// The refusal, for the option and for the setting: before any ray, the
/// install command named, nothing written.
#[test]
fn a_missing_library_refuses_the_render_with_the_install_command() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.png");
    let missing = dir.path().join("no-such-libOpenImageDenoise.so");
    for (globals, extra) in [("", &["--denoise"][..]), ("denoise = true;", &[][..])] {
        let s = scene(dir.path(), globals);
        let refused = hscene()
            .env("HSCENE_OIDN", &missing)
            .arg("render")
            .arg(&s)
            .args(extra)
            .arg("-o")
            .arg(&out)
            .assert()
            .failure()
            .code(2);
        let stderr = String::from_utf8_lossy(&refused.get_output().stderr).into_owned();
        assert!(stderr.contains("python3 -m pip install oidn"), "{stderr}");
        assert!(stderr.contains("HSCENE_OIDN"), "{stderr}");
        assert!(
            stderr.contains("no-such-libOpenImageDenoise.so"),
            "{stderr}"
        );
        assert!(!out.exists());
    }
}

/// `check` accepts `denoise = true;` and `false`, refuses anything else
/// with HSC0403; the IR says it.
#[test]
fn the_setting_is_checked() {
    let dir = tempfile::tempdir().unwrap();
    for value in ["true", "false"] {
        let s = scene(dir.path(), &format!("denoise = {value};"));
        let ok = hscene()
            .args(["check", "--emit", "ir"])
            .arg(&s)
            .assert()
            .success();
        let ir = String::from_utf8_lossy(&ok.get_output().stdout).into_owned();
        assert!(ir.contains(&format!("\"denoise\":{value}")), "{ir}");
    }
    for (value, says) in [("yes", "`yes`"), ("1", "a number")] {
        let s = scene(dir.path(), &format!("denoise = {value};"));
        let refused = hscene().arg("check").arg(&s).assert().failure();
        let out = refused.get_output();
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(text.contains("HSC0403"), "{text}");
        assert!(text.contains(says), "{text}");
        assert!(text.contains("`true` or `false`"), "{text}");
    }
}

/// With the library: the denoised picture and its `noisy`, `albedo` and
/// `normal` layers in one OpenEXR file.
#[test]
fn a_denoised_render_keeps_its_noisy_layer() {
    let dir = tempfile::tempdir().unwrap();
    let s = scene(dir.path(), "");
    let exr = dir.path().join("out.exr");
    let run = hscene()
        .arg("render")
        .arg(&s)
        .args(["--denoise", "--aov", "noisy,albedo,normal", "-o"])
        .arg(&exr)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr).into_owned();
    if !run.status.success() && stderr.contains("python3 -m pip install oidn") {
        assert!(
            std::env::var_os("HSCENE_REQUIRE_OIDN").is_none(),
            "HSCENE_REQUIRE_OIDN is set but the denoiser is missing: {stderr}"
        );
        eprintln!("skipped: Intel Open Image Denoise is not installed");
        return;
    }
    assert!(run.status.success(), "{stderr}");
    let bytes = fs::read(&exr).unwrap();
    for channel in [
        "noisy.R", "noisy.G", "noisy.B", "albedo.R", "N.X", "R", "G", "B",
    ] {
        let needle = format!("{channel}\0");
        assert!(
            bytes.windows(needle.len()).any(|w| w == needle.as_bytes()),
            "channel {channel} in the header"
        );
    }
}
