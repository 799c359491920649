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

/// Added to each luminance before its logarithm, so that a nearly black
/// pixel cannot drag the mean to minus infinity.
const LOG_FLOOR: f64 = 1e-4;

/// Rec. 709 / sRGB luminance weights of linear R, G, B.
const LUMA: [f64; 3] = [0.2126, 0.7152, 0.0722];

/// The luminance of a linear pixel; negative channels count as 0.
#[inline]
pub fn luminance(p: [f32; 3]) -> f64 {
    (0..3).map(|k| LUMA[k] * f64::from(p[k]).max(0.0)).sum()
}

/// The exposure in stops that maps the log-average luminance of the
/// pixels that see anything (luminance above 0: the black of an empty
/// background would otherwise decide the exposure of a small object) to
/// [`AUTO_KEY`]: `log2(0.18 / exp(mean(ln(1e-4 + Y))))`. An image with no
/// such pixel gets 0. The result never scales a finite sample past the
/// largest f32 and stays within +-[`MAX_EXPOSURE`].
pub fn auto_exposure(image: &Image) -> f64 {
    let (mut sum, mut n, mut peak) = (0.0, 0u64, 0.0f64);
    for p in image.pixels() {
        let y = luminance(*p);
        if y > 0.0 {
            sum += (LOG_FLOOR + y).ln();
            n += 1;
        }
        peak = p.iter().fold(peak, |m, c| m.max(f64::from(c.abs())));
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

/// True when the image would look almost black: fewer than 1 % of its
/// pixels have a channel at or above [`DARK_LEVEL`] once tone-mapped and
/// encoded by `display`. A cheap, documented criterion for the render
/// warning; an empty image is not "almost black".
pub fn is_almost_black(image: &Image, display: DisplayTransform) -> bool {
    let pixels = image.pixels();
    // The answer is known once 1 % are found lit: a normal image stops
    // after its first few hundred pixels instead of encoding every channel.
    let enough = pixels.len().div_ceil(100);
    let lit = pixels
        .iter()
        .filter(|p| p.iter().any(|&c| display.apply(c) >= DARK_LEVEL))
        .take(enough)
        .count();
    !pixels.is_empty() && lit * 100 < pixels.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A uniform image of luminance Y gets `log2(0.18 / (1e-4 + Y))`; black
    /// pixels do not count; an all-black image keeps its exposure.
    #[test]
    fn maps_the_log_average_to_the_key() {
        let grey = |v: f32| [v, v, v];
        let img = Image::from_pixels(3, 1, vec![grey(0.02), grey(0.0), grey(0.02)]);
        let expect = (0.18f64 / (1e-4 + luminance(grey(0.02)))).log2();
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

    /// sRGB level 16 is linear 0.0052; under 1 % of pixels above it is
    /// "almost black", and so is the same image stored linearly (level 16
    /// there is 0.063).
    #[test]
    fn almost_black_needs_one_percent_of_visible_pixels() {
        let srgb = DisplayTransform::default();
        let mut px = vec![[0.004f32; 3]; 200];
        assert!(is_almost_black(
            &Image::from_pixels(200, 1, px.clone()),
            srgb
        ));
        px[0] = [0.006, 0.0, 0.0];
        assert!(is_almost_black(
            &Image::from_pixels(200, 1, px.clone()),
            srgb
        ));
        px[1] = [0.0, 0.0, 0.5];
        assert!(!is_almost_black(
            &Image::from_pixels(200, 1, px.clone()),
            srgb
        ));
        let linear = DisplayTransform {
            encoding: crate::Encoding::Linear,
            ..srgb
        };
        assert!(is_almost_black(
            &Image::from_pixels(200, 1, vec![[0.05; 3]; 200]),
            linear
        ));
        assert!(!is_almost_black(&Image::from_pixels(0, 0, vec![]), srgb));
    }

    #[test]
    fn never_overflows_f32() {
        let img = Image::from_pixels(2, 1, vec![[1e-30, 0.0, 0.0], [3e37, 0.0, 0.0]]);
        let ev = auto_exposure(&img);
        assert!((3e37 * ev.exp2()) < f64::from(f32::MAX));
    }
}
