//! `render --crop`: tiles of an image rendered apart, put side by side, are
//! the whole image byte for byte (so a huge still can be split across cores
//! or machines like an animation's frames).

use std::path::Path;

use assert_cmd::Command;
use predicates::prelude::*;

fn render(dir: &Path, name: &str, extra: &[&str]) -> image::RgbImage {
    let out = dir.join(name);
    Command::cargo_bin("hscene")
        .unwrap()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "48x36",
            "-o",
        ])
        .arg(&out)
        .args(extra)
        .assert()
        .success();
    image::open(&out).unwrap().to_rgb8()
}

fn stitched_equals_whole(extra: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let whole = render(dir.path(), "whole.png", extra);
    assert_eq!(whole.dimensions(), (48, 36));
    // Uneven tiles: a left column, and the right part cut in two.
    let tiles = [(0, 0, 20, 36), (20, 0, 28, 17), (20, 17, 28, 19)];
    let mut stitched = image::RgbImage::new(48, 36);
    for (k, (x, y, w, h)) in tiles.into_iter().enumerate() {
        let crop = format!("{x},{y},{w},{h}");
        let mut args = extra.to_vec();
        args.extend(["--crop", &crop]);
        let tile = render(dir.path(), &format!("tile{k}.png"), &args);
        assert_eq!(tile.dimensions(), (w, h));
        for (i, j, p) in tile.enumerate_pixels() {
            stitched.put_pixel(x + i, y + j, *p);
        }
    }
    assert!(
        whole.as_raw() == stitched.as_raw(),
        "tiles differ from the whole image"
    );
    // Not a blank image: the comparison means something.
    assert!(whole.pixels().any(|p| p.0 != whole.get_pixel(0, 0).0));
}

#[test]
fn tiles_stitch_to_the_whole_image() {
    stitched_equals_whole(&[]);
}

#[test]
fn tiles_stitch_with_jittered_samples_and_the_interpolated_net() {
    stitched_equals_whole(&["--samples", "3", "--seed", "7", "--net", "4"]);
}

#[test]
fn a_crop_outside_the_image_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    Command::cargo_bin("hscene")
        .unwrap()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--resolution",
            "48x36",
            "--crop",
            "40,0,10,10",
            "-o",
        ])
        .arg(dir.path().join("x.png"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("not inside the 48x36 image"));
    Command::cargo_bin("hscene")
        .unwrap()
        .args([
            "render",
            "scenes/thesis-appendix-a.hsc",
            "--crop",
            "0,0,0,5",
            "-o",
        ])
        .arg(dir.path().join("x.png"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("at least 1x1"));
    assert!(!dir.path().join("x.png").exists());
}
