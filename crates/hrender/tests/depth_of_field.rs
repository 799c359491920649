//! Depth of field: a thin lens at the eye (`aperture`, `focus`). A small
//! glowing ball on the view axis is drawn as the disc its circle of
//! confusion predicts (`hscene_ir::Lens`): sharp at the focus distance,
//! spread by the derived angle elsewhere.

use hrender::RenderOptions;
use hscene_ir::{Scene, confusion_angle};

const SIZE: u32 = 64;
const FOV_DEGREES: f64 = 4.0;

/// The angle between neighbouring pixels in the middle of the picture.
fn pixel() -> f64 {
    FOV_DEGREES.to_radians() / f64::from(SIZE)
}

/// The radius of a ball at distance `d` that subtends `pixels` pixels.
fn ball(d: f64, pixels: f64) -> f64 {
    ((pixels * pixel()).sin() * d.sinh()).asinh()
}

/// A ball of radius `r` glowing white at distance `d` on the axis, seen
/// through a lens of radius `aperture` focused at `focus`.
fn scene(d: f64, r: f64, aperture: f64, focus: f64) -> Scene {
    let z = (d / 2.0).tanh();
    let source = format!(
        "Globals {{ resolution = ({SIZE}, {SIZE}); from = (0, 0, 0); to = (0, 0, 0.3); \
         fov = {FOV_DEGREES}; background = (0, 0, 0); ambient = (0, 0, 0); \
         aperture = {aperture}; focus = {focus}; }}\n\
         BRDFs {{ glow: ambient = (0, 0, 0), diffuse = (0, 0, 0), specular = (0, 0, 0), \
         emission = (1, 1, 1); }}\n\
         Objects {{ Sphere (0, 0, {z}), {r}, #glow; }}\n"
    );
    let out = hscene_lang::compile(&source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

/// The intensity-weighted mean of the squared angle from the view axis
/// over the picture (pinhole net 0: a pixel at screen offset `(sx, sy)`
/// looks at `atan(2 tan(fov/2) |(sx, sy)|)`).
fn second_moment(scene: &Scene) -> f64 {
    let options = RenderOptions {
        samples: Some(400),
        ..RenderOptions::default()
    };
    let image = hrender::render(scene, &options, &|_| {})
        .expect("renders")
        .image;
    let half = (FOV_DEGREES.to_radians() / 2.0).tan();
    let (mut sum, mut weighted) = (0.0, 0.0);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let i = f64::from(image.get(x, y)[0]);
            let sx = (f64::from(x) + 0.5) / f64::from(SIZE) - 0.5;
            let sy = (f64::from(y) + 0.5) / f64::from(SIZE) - 0.5;
            let angle = (2.0 * half * sx.hypot(sy)).atan();
            sum += i;
            weighted += i * angle * angle;
        }
    }
    assert!(sum > 0.0, "the ball is seen");
    weighted / sum
}

/// The mean of `θ(a)²` over a lens of radius `aperture` (`a = A √ξ`, `ξ`
/// uniform), plus the ball's own disc of radius `r` (angular radius `s`,
/// mean square `s²/2`).
fn predicted(d: f64, r: f64, aperture: f64, focus: f64) -> f64 {
    let n = 4000;
    let lens: f64 = (0..n)
        .map(|k| {
            let xi = (f64::from(k) + 0.5) / f64::from(n);
            confusion_angle(aperture * xi.sqrt(), d, focus).powi(2)
        })
        .sum::<f64>()
        / f64::from(n);
    let s = (r.sinh() / d.sinh()).asin();
    lens + s * s / 2.0
}

/// Nearer and farther than the focus, the spread is the derived one to
/// 5 % (rms radius). The ball subtends 2 pixels, so that enough lens
/// samples meet it for the spread to be measured.
#[test]
fn the_circle_of_confusion_has_the_derived_size() {
    let pixel = pixel();
    let (aperture, focus) = (0.05, 1.0);
    for d in [0.6, 2.0, 4.0] {
        let r = ball(d, 2.0);
        let got = second_moment(&scene(d, r, aperture, focus));
        let want = predicted(d, r, aperture, focus);
        let rim = confusion_angle(aperture, d, focus).abs() / pixel;
        assert!(
            rim > 5.0,
            "d = {d}: a circle of {rim} pixels is too small to measure"
        );
        assert!(
            (got.sqrt() / want.sqrt() - 1.0).abs() < 0.05,
            "d = {d}: rms radius {} pixels, derived {} (rim {rim} pixels)",
            got.sqrt() / pixel,
            want.sqrt() / pixel
        );
    }
}

/// At the focus distance a ball of a fifth of a pixel stays sharp: its
/// spread is the pixel's, under one pixel rms, with the same lens.
#[test]
fn the_focus_distance_is_sharp() {
    let pixel = pixel();
    let got = second_moment(&scene(2.0, ball(2.0, 0.2), 0.05, 2.0));
    assert!(
        got.sqrt() < pixel,
        "rms radius {} pixels",
        got.sqrt() / pixel
    );
}
