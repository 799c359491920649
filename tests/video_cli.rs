//! Animations written as one video file: GIF and APNG natively, MP4 and
//! WebM through ffmpeg; read back by an independent decoder (ffprobe).
//! Without ffmpeg installed the decoding checks say they were skipped,
//! unless `HSCENE_REQUIRE_FFMPEG` is set (`.ci/run` installs ffmpeg and
//! sets it).

use std::fs;
use std::path::Path;
use std::process::Command as Process;

use assert_cmd::Command;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

const SCENE: &str = "Globals { frames = 6; resolution = (33, 25); from = %eye; to = %centre; }\n\
     BRDFs { paint: ambient = (0.3, 0.3, 0.3), diffuse = (0.9, 0.3, 0.1); }\n\
     Points { eye = (0, 0, 0); centre = (0, 0, 0.5); above = (0, 0.3, 0.5); }\n\
     Lights { (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }\n\
     Objects { Cube 0.4, #paint, at = %centre; }\n\
     Transformations { vertical: hline (%centre, %above); @camera->Rotate(%vertical, 5.2), animate; }\n";

fn ffprobe() -> bool {
    let found = Process::new("ffprobe")
        .arg("-version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        assert!(
            std::env::var_os("HSCENE_REQUIRE_FFMPEG").is_none(),
            "HSCENE_REQUIRE_FFMPEG is set but ffprobe is missing"
        );
        eprintln!("skipped the decoding checks: ffmpeg is not installed");
    }
    found
}

/// The frame count and size ffprobe reads.
fn probe(path: &Path) -> String {
    let out = Process::new("ffprobe")
        .args(["-v", "error", "-count_frames", "-select_streams", "v:0"])
        .args([
            "-show_entries",
            "stream=nb_read_frames,width,height",
            "-of",
            "csv=p=0",
        ])
        .arg(path)
        .output()
        .unwrap();
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

#[test]
fn every_video_format_holds_every_frame() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(&scene, SCENE).unwrap();
    let decode = ffprobe();
    let mut formats = vec!["gif", "apng"];
    if decode {
        formats.extend(["mp4", "webm"]);
    }
    for ext in formats {
        let out = dir.path().join(format!("film.{ext}"));
        hscene()
            .args([
                "render",
                scene.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ])
            .args(["--fps", "12"])
            .assert()
            .success();
        assert!(fs::metadata(&out).unwrap().len() > 0, "{ext}");
        if decode {
            // MP4 and WebM pad odd sizes to even ones.
            let size = if matches!(ext, "mp4" | "webm") {
                "34,26"
            } else {
                "33,25"
            };
            assert_eq!(probe(&out), format!("{size},6"), "{ext}");
        }
    }
    // Only the videos: no per-frame images, no temporary files.
    let mut names: Vec<String> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n != "s.hsc")
        .collect();
    names.sort();
    assert!(names.iter().all(|n| n.starts_with("film.")), "{names:?}");
}

#[test]
fn videos_refuse_what_they_cannot_hold_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(&scene, SCENE).unwrap();
    let s = scene.to_str().unwrap();
    for (args, message) in [
        (vec!["-o", "f.gif", "--frame", "2"], "drop --frame"),
        (vec!["-o", "f.gif", "--depth", "16"], "8 bits"),
        (vec!["-o", "f.gif", "--fps", "0"], "--fps"),
    ] {
        hscene()
            .current_dir(dir.path())
            .args(["render", s])
            .args(&args)
            .assert()
            .code(2)
            .stderr(predicates::str::contains(message));
    }
    // Without ffmpeg on the PATH, MP4 is refused naming the package, and
    // the earlier file stays.
    let empty = tempfile::tempdir().unwrap();
    let mp4 = dir.path().join("f.mp4");
    fs::write(&mp4, b"earlier").unwrap();
    hscene()
        .env("PATH", empty.path())
        .args(["render", s, "-o", mp4.to_str().unwrap()])
        .assert()
        .code(2)
        .stderr(predicates::str::contains("apt-get install ffmpeg"));
    assert_eq!(fs::read(&mp4).unwrap(), b"earlier");
    let left: Vec<_> = fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(left.len(), 2);
}

/// GIF delays are whole hundredths of a second: 24 frames a second is
/// 4.1667 each, which one delay cannot hold. Read back by the `image`
/// crate's decoder, every frame starts within half a hundredth of
/// `k / 24` s (the delays alternate 4, 4, 5, ...), the six frames last a
/// quarter of a second exactly, and no rounding is reported.
#[test]
fn a_gif_at_24_fps_keeps_the_rate_frame_by_frame() {
    use image::AnimationDecoder;
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.hsc");
    fs::write(&scene, SCENE).unwrap();
    let out = dir.path().join("film.gif");
    let run = hscene()
        .args(["render", scene.to_str().unwrap(), "-o"])
        .arg(&out)
        .args(["--fps", "24"])
        .output()
        .unwrap();
    assert!(run.status.success(), "{run:?}");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!stderr.contains("plays at"), "{stderr}");
    let file = std::io::BufReader::new(fs::File::open(&out).unwrap());
    let frames = image::codecs::gif::GifDecoder::new(file)
        .unwrap()
        .into_frames()
        .collect_frames()
        .unwrap();
    assert_eq!(frames.len(), 6);
    let mut start_ms = 0.0;
    for (k, frame) in frames.iter().enumerate() {
        let want = k as f64 * 1000.0 / 24.0;
        assert!(
            (start_ms - want).abs() <= 5.0 + 1e-9,
            "frame {k} starts at {start_ms} ms, not {want}"
        );
        let (num, den) = frame.delay().numer_denom_ms();
        start_ms += f64::from(num) / f64::from(den);
    }
    assert!(
        (start_ms - 250.0).abs() < 1e-9,
        "six frames last {start_ms} ms"
    );
}
