//! Every picture of the docs, remade small from its scene and compared
//! with the published one.
//!
//! docs/pictures.txt is the one list of which scene makes which picture
//! (docs/remake-pictures.sh reads it too). Each `render` picture is
//! rendered again at 96 pixels wide (its own aspect) and a quarter of
//! its samples (at least 4), and both pictures are reduced to 16 x 16 by
//! averaging their light (a blur that noise and aliasing do not survive).
//! They must agree in mean colour to [`MEAN_TOLERANCE`] per channel and in mean absolute
//! difference of the reduced pictures to [`BLUR_TOLERANCE`] (of 1, sRGB
//! values): a black or wrongly lit picture is 0.2 or more away, a remake
//! of the same scene a few hundredths.

use std::path::Path;
use std::process::Command;

use image::{AnimationDecoder, RgbImage};

use super::{hscene, root};

/// The largest difference of a channel's mean.
const MEAN_TOLERANCE: f32 = 0.06;
/// The largest mean absolute difference of the 16 x 16 reductions.
const BLUR_TOLERANCE: f32 = 0.08;
/// The side of the reduction.
const GRID: u32 = 16;

/// One line of docs/pictures.txt.
struct Listed {
    line: usize,
    kind: String,
    picture: String,
    scene: String,
    options: Vec<String>,
}

/// docs/pictures.txt's entries.
fn listed() -> Vec<Listed> {
    let text =
        std::fs::read_to_string(root().join("docs/pictures.txt")).expect("docs/pictures.txt");
    let mut out = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split_whitespace().collect();
        if words.is_empty() || words[0].starts_with('#') {
            continue;
        }
        assert!(
            words.len() >= 3,
            "docs/pictures.txt:{}: KIND PICTURE SCENE [OPTIONS]",
            k + 1
        );
        out.push(Listed {
            line: k + 1,
            kind: words[0].to_owned(),
            picture: words[1].to_owned(),
            scene: words[2].to_owned(),
            options: words[3..].iter().map(|w| (*w).to_owned()).collect(),
        });
    }
    out
}

/// The pictures under `dir` (relative to the root), recursively.
fn pictures_under(dir: &Path, out: &mut Vec<String>) {
    for entry in std::fs::read_dir(root().join(dir)).expect("a readable folder") {
        let path = entry.expect("an entry").path();
        let relative = path
            .strip_prefix(root())
            .expect("under the root")
            .to_path_buf();
        if path.is_dir() {
            pictures_under(&relative, out);
        } else if path.extension().is_some_and(|e| e == "png" || e == "gif") {
            out.push(relative.to_string_lossy().into_owned());
        }
    }
}

/// A picture as 8-bit RGB: a PNG, or a GIF's first frame.
fn load(path: &Path) -> RgbImage {
    if path.extension().is_some_and(|e| e == "gif") {
        let file = std::io::BufReader::new(std::fs::File::open(path).expect("the GIF opens"));
        let decoder = image::codecs::gif::GifDecoder::new(file).expect("a GIF");
        let first = decoder
            .into_frames()
            .next()
            .expect("a frame")
            .expect("a decodable frame");
        return image::DynamicImage::ImageRgba8(first.into_buffer()).to_rgb8();
    }
    image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8()
}

/// The picture reduced to `GRID` x `GRID` cells, each the mean of the
/// pixels whose centre falls in it, averaged as light (sRGB decoded, the
/// mean encoded again; values in [0, 1]): the mean of a noisy picture's
/// pixels is then the mean of its light, as it is with more samples,
/// where averaging the encoded values would darken it.
fn reduced(image: &RgbImage) -> Vec<[f32; 3]> {
    let (w, h) = image.dimensions();
    let mut sums = vec![([0.0f32; 3], 0u32); (GRID * GRID) as usize];
    for (x, y, p) in image.enumerate_pixels() {
        let cell = ((y * GRID / h) * GRID + x * GRID / w) as usize;
        for c in 0..3 {
            sums[cell].0[c] += to_linear(f32::from(p[c]) / 255.0);
        }
        sums[cell].1 += 1;
    }
    sums.into_iter()
        .map(|(s, n)| s.map(|v| to_srgb(v / n.max(1) as f32)))
        .collect()
}

/// The sRGB transfer function's inverse.
fn to_linear(v: f32) -> f32 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// The sRGB transfer function.
fn to_srgb(v: f32) -> f32 {
    if v <= 0.003_130_8 {
        v * 12.92
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    }
}

/// The largest difference of a channel's mean and the mean absolute
/// difference of the reductions of `a` and `b`.
fn distance(a: &RgbImage, b: &RgbImage) -> (f32, f32) {
    let (ra, rb) = (reduced(a), reduced(b));
    let n = ra.len() as f32;
    let mut means = [0.0f32; 3];
    let mut blurred = 0.0;
    for (p, q) in ra.iter().zip(&rb) {
        for c in 0..3 {
            means[c] += (p[c] - q[c]) / n;
            blurred += (p[c] - q[c]).abs() / (3.0 * n);
        }
    }
    (means.iter().fold(0.0f32, |m, d| m.max(d.abs())), blurred)
}

/// The options of a listed picture for its small remake.
fn small_options(entry: &Listed, width: u32, height: u32) -> Vec<String> {
    let mut out = Vec::new();
    let mut samples = 4;
    let mut words = entry.options.iter();
    while let Some(w) = words.next() {
        match w.as_str() {
            "--resolution" => {
                words.next();
            }
            // A quarter of the published samples, at least 4: a noisy
            // path-traced picture's fireflies, clipped at white, would
            // otherwise darken the few-sample remake.
            "--samples" => {
                let n: u32 = words.next().and_then(|n| n.parse().ok()).unwrap_or(4);
                samples = (n / 4).max(4);
            }
            _ => out.push(w.clone()),
        }
    }
    out.extend([
        "--resolution".to_owned(),
        format!("{width}x{height}"),
        "--samples".to_owned(),
        samples.to_string(),
    ]);
    if entry.picture.ends_with(".gif") {
        out.extend(["--frame".to_owned(), "0".to_owned()]);
    }
    out
}

/// Every picture under docs/ is in docs/pictures.txt, and every listed
/// one exists, made from a scene that exists.
#[test]
fn every_picture_in_the_docs_is_listed() {
    let mut found = Vec::new();
    pictures_under(Path::new("docs"), &mut found);
    let entries = listed();
    for picture in &found {
        assert!(
            entries.iter().any(|e| &e.picture == picture),
            "{picture} is not in docs/pictures.txt: add the scene that makes it"
        );
    }
    for e in &entries {
        assert!(
            root().join(&e.picture).is_file(),
            "docs/pictures.txt:{}: no {}",
            e.line,
            e.picture
        );
        assert!(
            root().join(&e.scene).is_file(),
            "docs/pictures.txt:{}: no {}",
            e.line,
            e.scene
        );
        assert!(
            matches!(e.kind.as_str(), "render" | "export"),
            "docs/pictures.txt:{}: kind {}",
            e.line,
            e.kind
        );
    }
}

/// Every `render` picture remade small is near the published one; every
/// `export` picture's scene exports (its picture is Mitsuba's).
#[test]
fn every_picture_in_the_docs_is_remade_from_its_scene() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut report = Vec::new();
    let mut failures = Vec::new();
    for (k, e) in listed().into_iter().enumerate() {
        let out = dir.path().join(format!(
            "{k}.{}",
            if e.kind == "export" { "glb" } else { "png" }
        ));
        let published = load(&root().join(&e.picture));
        let (w, h) = published.dimensions();
        let width = 96;
        let height = (width * h / w).max(1);
        let args: Vec<String> = if e.kind == "export" {
            e.options.clone()
        } else {
            small_options(&e, width, height)
        };
        let result = Command::new(hscene())
            .arg(if e.kind == "export" {
                "export"
            } else {
                "render"
            })
            .arg(&e.scene)
            .arg("-o")
            .arg(&out)
            .args(&args)
            .args(if e.kind == "export" {
                &[][..]
            } else {
                &["--threads", "2"][..]
            })
            .current_dir(root())
            .output()
            .expect("hscene starts");
        if !result.status.success() {
            failures.push(format!(
                "{}: {}",
                e.picture,
                String::from_utf8_lossy(&result.stderr)
            ));
            continue;
        }
        if e.kind == "export" {
            continue;
        }
        let (mean, blurred) = distance(&load(&out), &published);
        report.push(format!(
            "{:50} mean {mean:.3} blurred {blurred:.3}",
            e.picture
        ));
        if mean > MEAN_TOLERANCE || blurred > BLUR_TOLERANCE {
            failures.push(format!(
                "{}: remade from {} it is mean {mean:.3} / blurred {blurred:.3} from the published \
                 picture (tolerances {MEAN_TOLERANCE} / {BLUR_TOLERANCE}); if the change is meant, \
                 docs/remake-pictures.sh {}",
                e.picture, e.scene, e.picture
            ));
        }
    }
    println!("{}", report.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_black_picture_is_far_and_a_copy_is_near() {
    let lit = RgbImage::from_fn(64, 48, |x, y| {
        image::Rgb([(x * 4) as u8, (y * 5) as u8, 128])
    });
    let black = RgbImage::new(64, 48);
    let (mean, blurred) = distance(&lit, &lit);
    assert!(mean == 0.0 && blurred == 0.0);
    let (mean, blurred) = distance(&lit, &black);
    assert!(
        mean > MEAN_TOLERANCE && blurred > BLUR_TOLERANCE,
        "{mean} {blurred}"
    );
}
