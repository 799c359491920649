//! Exposure: how a render's linear radiance is scaled before it is stored.
//! A fixed number of stops, or one chosen from the image's log-average
//! luminance (Reinhard et al. 2002, "Photographic tone reproduction"): the
//! exposure that maps the geometric mean of the luminance onto the key
//! value, a photographer's 18 % mid-grey.

use crate::display::DisplayTransform;
use crate::image::Image;

/// How a render's radiance is scaled before it is stored
/// (`RenderOptions::exposure`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Exposure {
    /// Fixed stops (EV): each pixel's radiance is multiplied by `2^ev` as it
    /// is computed, so every output format, the floating-point ones
    /// included, sees the scaled values.
    Stops(f64),
    /// Chosen from the finished image ([`auto_exposure`]) and applied to it;
    /// the render reports the stops it chose
    /// ([`Rendered::auto_exposure`](crate::Rendered::auto_exposure)).
    Auto,
    /// Stops chosen automatically for an earlier image (an animation's first
    /// frame), applied as [`Exposure::Auto`] applies its own, so that every
    /// frame of an animation is exposed alike.
    AutoKept(f64),
}

impl Default for Exposure {
    /// No correction.
    fn default() -> Exposure {
        Exposure::Stops(0.0)
    }
}

impl Exposure {
    /// The stops given, if any (`None` for [`Exposure::Auto`]).
    pub fn given_stops(self) -> Option<f64> {
        match self {
            Exposure::Stops(ev) | Exposure::AutoKept(ev) => Some(ev),
            Exposure::Auto => None,
        }
    }

    /// The factor applied to each pixel's radiance while rendering.
    pub(crate) fn render_scale(self) -> f64 {
        match self {
            Exposure::Stops(ev) => ev.exp2(),
            Exposure::Auto | Exposure::AutoKept(_) => 1.0,
        }
    }

    /// Apply the automatic part to a finished image: the stops applied,
    /// `None` for fixed stops (already applied while rendering).
    pub(crate) fn finish(self, image: &mut Image) -> Option<f64> {
        let ev = match self {
            Exposure::Stops(_) => return None,
            Exposure::Auto => auto_exposure(image),
            Exposure::AutoKept(ev) => ev,
        };
        image.expose(ev);
        Some(ev)
    }
}

/// Largest exposure correction, in stops, either way: `2^64` already maps
/// the faintest visible radiance onto the brightest.
pub const MAX_EXPOSURE: f64 = 64.0;

/// The luminance the log-average is mapped to.
pub const AUTO_KEY: f64 = 0.18;

/// Added to each luminance before its logarithm, as a share of the image's
/// brightest luminance, so that a nearly black pixel cannot drag the mean
/// to minus infinity. Relative, so that the exposure chosen does not depend
/// on how bright the scene is: a scene a million times darker gets exactly
/// `log2(1e6)` more stops (an absolute floor of `1e-4` decided the mean of
/// dark scenes by itself and left them dark).
const LOG_FLOOR: f64 = 1e-4;

/// The linear level the exposure suggested for an almost black image
/// brings its bright pixels to (about sRGB level 188 when clipped).
const SUGGESTED_LEVEL: f64 = 0.5;

/// Among the lit pixels, the share that may be brighter than the level
/// that decides "almost black": a few fireflies or a tiny highlight do not
/// make a dark picture bright.
const BRIGHT_QUANTILE: f64 = 0.99;

/// Rec. 709 / sRGB luminance weights of linear R, G, B.
pub(crate) const LUMA: [f64; 3] = [0.2126, 0.7152, 0.0722];

/// The luminance of a linear pixel; negative channels count as 0.
#[inline]
pub fn luminance(p: [f32; 3]) -> f64 {
    (0..3).map(|k| LUMA[k] * f64::from(p[k]).max(0.0)).sum()
}

/// The exposure in stops that maps the log-average luminance of the
/// pixels that see anything (luminance above 0: the black of an empty
/// background would otherwise decide the exposure of a small object) to
/// [`AUTO_KEY`]: `log2(0.18 / exp(mean(ln(1e-4 Y_max + Y))))`. An image with no
/// such pixel gets 0. The result never scales a finite sample past the
/// largest f32 and stays within +-[`MAX_EXPOSURE`].
pub fn auto_exposure(image: &Image) -> f64 {
    let (mut peak, mut brightest) = (0.0f64, 0.0f64);
    for p in image.pixels() {
        peak = p.iter().fold(peak, |m, c| m.max(f64::from(c.abs())));
        brightest = brightest.max(luminance(*p));
    }
    let floor = LOG_FLOOR * brightest;
    let (mut sum, mut n) = (0.0, 0u64);
    for p in image.pixels() {
        let y = luminance(*p);
        if y > 0.0 {
            sum += (floor + y).ln();
            n += 1;
        }
    }
    if n == 0 {
        return 0.0;
    }
    let average = (sum / n as f64).exp();
    let ev = (AUTO_KEY / average).log2();
    // Keep a stop of headroom below f32::MAX for the brightest sample.
    let ceiling = (f64::from(f32::MAX) / peak).log2() - 1.0;
    ev.min(ceiling).clamp(-MAX_EXPOSURE, MAX_EXPOSURE)
}

/// A pixel is dark when every channel, as stored by `display`, is below
/// this (level 16 of 255: black to most eyes on most screens).
pub const DARK_LEVEL: f64 = 16.0 / 255.0;

/// The brightness that stands for the picture: among the pixels that see
/// anything (a channel above 0), the 99th percentile of their brightest
/// channel, linear. `None` when no pixel sees anything.
pub fn bright_level(image: &Image) -> Option<f64> {
    let mut lit: Vec<f32> = image
        .pixels()
        .iter()
        .map(|p| p.iter().fold(0.0f32, |m, c| m.max(*c)))
        .filter(|c| *c > 0.0)
        .collect();
    if lit.is_empty() {
        return None;
    }
    let k = ((lit.len() - 1) as f64 * BRIGHT_QUANTILE) as usize;
    let (_, v, _) = lit.select_nth_unstable_by(k, f32::total_cmp);
    Some(f64::from(*v))
}

/// How a picture looks once displayed, judged by one measure: its
/// [`bright_level`] against the level `display` stores as [`DARK_LEVEL`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Darkness {
    /// No pixel sees anything: every channel of every pixel is 0 (there is
    /// nothing to expose).
    Black,
    /// Its bright pixels stay below [`DARK_LEVEL`] once tone-mapped and
    /// encoded: at most 1 % of the pixels that see anything reach it. A
    /// small object on a black background is not dark (its own pixels are
    /// bright). Carries the bright level, for [`suggested_exposure`].
    AlmostBlack {
        /// The picture's [`bright_level`], linear.
        bright_level: f64,
    },
    /// Neither.
    Visible,
}

/// The [`Darkness`] of `image` shown through `display` (an empty image is
/// [`Darkness::Visible`]: there is nothing to warn about).
pub fn darkness(image: &Image, display: DisplayTransform) -> Darkness {
    if image.pixels().is_empty() {
        return Darkness::Visible;
    }
    match bright_level(image) {
        None => Darkness::Black,
        Some(v) if v < f64::from(dark_threshold(display)) => {
            Darkness::AlmostBlack { bright_level: v }
        }
        Some(_) => Darkness::Visible,
    }
}

/// True when the picture would look almost black ([`Darkness::AlmostBlack`]).
pub fn is_almost_black(image: &Image, display: DisplayTransform) -> bool {
    matches!(darkness(image, display), Darkness::AlmostBlack { .. })
}

/// True when no pixel sees anything: every channel of every pixel is 0.
pub fn is_black(image: &Image) -> bool {
    image.pixels().iter().all(|p| !p.iter().any(|c| *c > 0.0))
}

/// The least linear value that `display` stores at [`DARK_LEVEL`] or above
/// (every tone curve and encoding is monotone), by bisection.
fn dark_threshold(display: DisplayTransform) -> f32 {
    let (mut lo, mut hi) = (0.0f32, 1.0f32);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if display.apply(mid) >= DARK_LEVEL {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// The `--exposure` (absolute stops) that brings the bright pixels of an
/// image rendered at `current` stops to linear 0.5 (about level 188 of 255
/// when clipped): following it, the picture is no longer almost black, so
/// the suggestion is the same whether it was made at 0 or at 5 stops. `None`
/// when nothing is lit.
pub fn suggested_exposure(image: &Image, current: f64) -> Option<f64> {
    exposure_for_level(bright_level(image)?, current)
}

/// The `--exposure` that takes a picture of [`bright_level`] `v`, rendered
/// at `current` stops, to linear 0.5 ([`suggested_exposure`]).
pub fn exposure_for_level(v: f64, current: f64) -> Option<f64> {
    let ev = current + (SUGGESTED_LEVEL / v).log2();
    ev.is_finite()
        .then(|| ev.clamp(-MAX_EXPOSURE, MAX_EXPOSURE))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A uniform image of luminance Y gets `log2(0.18 / (Y + 1e-4 Y))`;
    /// black pixels do not count; an all-black image keeps its exposure.
    #[test]
    fn maps_the_log_average_to_the_key() {
        let grey = |v: f32| [v, v, v];
        let img = Image::from_pixels(3, 1, vec![grey(0.02), grey(0.0), grey(0.02)]);
        let y = luminance(grey(0.02));
        let expect = (0.18f64 / (y + 1e-4 * y)).log2();
        assert!((auto_exposure(&img) - expect).abs() < 1e-12);
        // Geometric, not arithmetic, mean: 0.01 and 1.0 average to 0.1.
        let img = Image::from_pixels(2, 1, vec![grey(0.01 - 1e-4), grey(1.0 - 1e-4)]);
        let y = luminance(grey(1.0));
        assert!((y - 1.0).abs() < 1e-6);
        assert!((auto_exposure(&img) - (0.18f64 / 0.1).log2()).abs() < 1e-5);
        assert_eq!(
            auto_exposure(&Image::from_pixels(1, 1, vec![grey(0.0)])),
            0.0
        );
    }

    /// A dark scene: the exposure chosen for it brings it where a bright
    /// one goes. Scaling every pixel by 1e-6 adds exactly log2(1e6) stops
    /// (the floor of the logarithm is relative), so the darkest scenes are
    /// exposed like the brightest.
    #[test]
    fn auto_exposure_is_scale_invariant() {
        let pixels: Vec<[f32; 3]> = (0..64)
            .map(|k| {
                let v = 0.002 * (1.0 + (k % 9) as f32);
                [v, 0.7 * v, 0.2 * v]
            })
            .chain([[0.0; 3]; 16])
            .collect();
        let bright = Image::from_pixels(80, 1, pixels.clone());
        let dark = Image::from_pixels(80, 1, pixels.iter().map(|p| p.map(|c| c * 1e-6)).collect());
        let gained = auto_exposure(&dark) - auto_exposure(&bright);
        assert!((gained - 1e6f64.log2()).abs() < 1e-3, "{gained}");
    }

    /// "Almost black" is decided by the bright pixels, not by coverage: a
    /// small bright object on black is not dark; a dim image is, whatever
    /// its coverage, and so is the same image stored linearly (level 16
    /// there is 0.063); an image that sees nothing is not.
    #[test]
    fn almost_black_is_about_brightness() {
        let srgb = DisplayTransform::default();
        let mut small = vec![[0.0f32; 3]; 10_000];
        small[..20].fill([0.6, 0.5, 0.4]);
        assert!(!is_almost_black(&Image::from_pixels(100, 100, small), srgb));
        let dim = Image::from_pixels(200, 1, vec![[0.004; 3]; 200]);
        assert!(is_almost_black(&dim, srgb));
        let linear = DisplayTransform {
            encoding: crate::Encoding::Linear,
            ..srgb
        };
        assert!(is_almost_black(
            &Image::from_pixels(200, 1, vec![[0.05; 3]; 200]),
            linear
        ));
        assert!(!is_almost_black(
            &Image::from_pixels(2, 1, vec![[0.0; 3]; 2]),
            srgb
        ));
        // One firefly does not make a dim picture bright.
        let mut fly = vec![[0.002f32; 3]; 400];
        fly[7] = [50.0, 50.0, 50.0];
        assert!(is_almost_black(&Image::from_pixels(400, 1, fly), srgb));
    }

    /// The suggested exposure is absolute and idempotent: made at any
    /// current exposure it names the same stops, and an image exposed by
    /// them is no longer almost black.
    #[test]
    fn the_suggested_exposure_is_absolute_and_idempotent() {
        let srgb = DisplayTransform::default();
        let base: Vec<[f32; 3]> = (0..100).map(|k| [0.0001 * (1 + k % 5) as f32; 3]).collect();
        let at = |ev: f64| {
            let mut img = Image::from_pixels(100, 1, base.clone());
            img.expose(ev);
            img
        };
        let s0 = suggested_exposure(&at(0.0), 0.0).unwrap();
        for current in [2.0, 5.0, 7.5] {
            let s = suggested_exposure(&at(current), current).unwrap();
            assert!((s - s0).abs() < 1e-4, "{s} vs {s0} from {current}");
        }
        let followed = at(s0);
        assert!(!is_almost_black(&followed, srgb));
        assert!((bright_level(&followed).unwrap() - 0.5).abs() < 1e-3);
        assert!((suggested_exposure(&followed, s0).unwrap() - s0).abs() < 1e-4);
    }

    #[test]
    fn never_overflows_f32() {
        let img = Image::from_pixels(2, 1, vec![[1e-30, 0.0, 0.0], [3e37, 0.0, 0.0]]);
        let ev = auto_exposure(&img);
        assert!((3e37 * ev.exp2()) < f64::from(f32::MAX));
    }
}
