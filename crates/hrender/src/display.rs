//! The display transform of integer outputs: linear radiance (already
//! exposed) -> tone curve -> transfer function -> 8- or 16-bit levels.
//!
//! Radiance stays linear everywhere inside the renderer and in the float
//! outputs; only 8- and 16-bit files pass through this module.
//! `docs/rendering.md#colour` documents the curves and the choices.

/// How radiance above 1 is brought into the displayable range.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ToneMap {
    /// Clamp each channel to `[0, 1]` (the thesis's behaviour).
    #[default]
    Clip,
    /// Reinhard's `x / (1 + x)` per channel: never saturates, compresses
    /// highlights, darkens mid-tones (0.214 becomes 0.176).
    Reinhard,
    /// Narkowicz's fit of the ACES filmic curve (RRT + ODT) per channel:
    /// with `y = 0.6 x` (his scale, which puts the fit on the reference
    /// curve), `y (2.51 y + 0.03) / (y (2.43 y + 0.59) + 0.14)` clamped to
    /// `[0, 1]`: a toe, more contrast in the mid-tones, a soft shoulder that
    /// reaches white near `x = 12.1`.
    Aces,
}

impl ToneMap {
    /// The tone curve at `x >= 0`, in `[0, 1]`. Negative radiance (which
    /// only an exposure of a signed test image can produce) maps to 0.
    #[inline]
    pub fn apply(self, x: f64) -> f64 {
        let x = x.max(0.0);
        match self {
            ToneMap::Clip => x.min(1.0),
            ToneMap::Reinhard => x / (1.0 + x),
            ToneMap::Aces => {
                let y = 0.6 * x;
                (y * (2.51 * y + 0.03) / (y * (2.43 * y + 0.59) + 0.14)).min(1.0)
            }
        }
    }
}

/// The transfer function between (tone-mapped) linear values and the
/// stored levels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Encoding {
    /// The sRGB transfer function (IEC 61966-2-1), and the file is tagged
    /// sRGB: what every viewer expects of an untagged or sRGB image.
    #[default]
    Srgb,
    /// Linear values stored as they are, untagged: the thesis's convention
    /// (the image looks darker than the scene's radiance suggests).
    Linear,
}

/// The sRGB opto-electronic transfer function, exact: `12.92 x` below
/// `0.0031308`, `1.055 x^(1/2.4) - 0.055` above; `x` in `[0, 1]`.
#[inline]
pub fn srgb_encode(x: f64) -> f64 {
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// The inverse of [`srgb_encode`]: stored value -> linear.
#[inline]
pub fn srgb_decode(v: f64) -> f64 {
    hscene_ir::srgb_to_linear(v)
}

/// Tone curve and transfer function together.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct DisplayTransform {
    /// The tone curve.
    pub tone: ToneMap,
    /// The transfer function (and the colour tag written with it).
    pub encoding: Encoding,
}

impl DisplayTransform {
    /// A linear channel value -> the stored value in `[0, 1]`.
    #[inline]
    pub fn apply(self, c: f32) -> f64 {
        let t = self.tone.apply(f64::from(c));
        match self.encoding {
            Encoding::Srgb => srgb_encode(t),
            Encoding::Linear => t,
        }
    }

    /// Every sample through the transform, quantised to 8 bits (nearest
    /// level), interleaved RGB.
    pub fn to_rgb8(self, pixels: &[[f32; 3]]) -> Vec<u8> {
        let mut levels = Recent::new(|c| (self.apply(c) * 255.0).round() as u8);
        interleaved(pixels, |c| levels.get(c))
    }

    /// Every sample through the transform, quantised to 16 bits.
    pub fn to_rgb16(self, pixels: &[[f32; 3]]) -> Vec<u16> {
        let mut levels = Recent::new(|c| (self.apply(c) * 65535.0).round() as u16);
        interleaved(pixels, |c| levels.get(c))
    }
}

/// The 8-bit levels of a [`DisplayTransform`] as a table: for each level
/// above that of 0, the least positive `f32` that reaches it. A sample's
/// level is then a binary search of 255 thresholds, no power, and the
/// same for every sample as [`DisplayTransform::to_rgb8`]'s (the tests
/// compare every `f32` from `2^-13` to 1, and the thresholds' neighbours).
///
/// Why a table is exact: the transform is a non-decreasing function of
/// its `f32` input. The tone curves are monotone and `powf` in `f64` errs
/// by an ulp of `2^-52`, while two `f32`s differ by at least `2^-24` of
/// themselves, so no rounding can reorder them; `* 255`, `round` and the
/// other correctly rounded steps never reorder. Non-finite samples (which
/// a rendered image never holds) take the computed path.
#[derive(Clone, Debug)]
pub struct Levels8 {
    transform: DisplayTransform,
    /// The level of 0 and of every non-positive sample.
    base: u8,
    /// `thresholds[k]`: the least positive `f32` whose level is at least
    /// `base + 1 + k`; levels no finite sample reaches are left out.
    thresholds: Vec<f32>,
}

impl Levels8 {
    /// The table of `transform`.
    pub fn new(transform: DisplayTransform) -> Levels8 {
        let level = |c: f32| (transform.apply(c) * 255.0).round() as u8;
        let base = level(0.0);
        let mut thresholds = Vec::with_capacity(255);
        let top = f32::MAX.to_bits();
        for b in base.saturating_add(1)..=255 {
            if base == 255 || level(f32::MAX) < b {
                break;
            }
            // The least bit pattern of a positive finite f32 with level
            // >= b: positive floats order as their bits do.
            let (mut lo, mut hi) = (1u32, top);
            while lo < hi {
                let mid = lo + (hi - lo) / 2;
                if level(f32::from_bits(mid)) >= b {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            thresholds.push(f32::from_bits(lo));
        }
        Levels8 {
            transform,
            base,
            thresholds,
        }
    }

    /// The 8-bit level of the sample `c`.
    #[inline]
    pub fn level(&self, c: f32) -> u8 {
        if !c.is_finite() {
            return (self.transform.apply(c) * 255.0).round() as u8;
        }
        if !(c > 0.0) {
            return self.base;
        }
        // At most 255 levels above the base, so the count fits.
        self.base + self.thresholds.partition_point(|t| *t <= c) as u8
    }

    /// Every sample's level, interleaved RGB, rows in parallel on the
    /// current rayon pool: the same bytes as
    /// [`DisplayTransform::to_rgb8`].
    pub fn to_rgb8_parallel(&self, pixels: &[[f32; 3]]) -> Vec<u8> {
        use rayon::prelude::*;
        let mut out = vec![0u8; 3 * pixels.len()];
        // Chunks of a few thousand pixels: enough work per task to pay
        // for its scheduling.
        const CHUNK: usize = 4096;
        out.par_chunks_mut(3 * CHUNK)
            .zip(pixels.par_chunks(CHUNK))
            .for_each(|(out, pixels)| {
                for (o, p) in out.chunks_exact_mut(3).zip(pixels) {
                    for k in 0..3 {
                        o[k] = self.level(p[k]);
                    }
                }
            });
        out
    }
}

/// `level` of every sample, interleaved: a plain loop into a buffer of the
/// known size (a `flat_map` over the pixels' arrays compiled to twice the
/// instructions per pixel in some builds and not in others).
fn interleaved<T>(pixels: &[[f32; 3]], mut level: impl FnMut(f32) -> T) -> Vec<T> {
    let mut out = Vec::with_capacity(3 * pixels.len());
    for p in pixels {
        for &c in p {
            out.push(level(c));
        }
    }
    out
}

/// Slots of [`Recent`]: a power of two.
const RECENT_SLOTS: usize = 256;

/// A function of a sample, remembering its latest results by the sample's
/// bits: the same bits give the same level, so the output is the
/// function's own, and a picture's many equal samples (its background, an
/// unlit flat colour) pay the transfer function's power once instead of
/// once per pixel.
struct Recent<T, F> {
    f: F,
    slots: [Option<(u32, T)>; RECENT_SLOTS],
}

impl<T: Copy, F: Fn(f32) -> T> Recent<T, F> {
    fn new(f: F) -> Recent<T, F> {
        Recent {
            f,
            slots: [None; RECENT_SLOTS],
        }
    }

    #[inline]
    fn get(&mut self, c: f32) -> T {
        let bits = c.to_bits();
        // Fibonacci hashing: the top bits of the product mix every bit of
        // the sample, mantissa and exponent alike.
        let slot = (bits.wrapping_mul(0x9E37_79B9) >> 24) as usize % RECENT_SLOTS;
        match self.slots[slot] {
            Some((b, level)) if b == bits => level,
            _ => {
                let level = (self.f)(c);
                self.slots[slot] = Some((bits, level));
                level
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Mid-grey: sRGB stores 50 % at linear `((0.5 + 0.055) / 1.055)^2.4
    /// = 0.214041`, which is stored as 128 of 255 (127.5 rounded half up);
    /// the linear value of level 128 itself, 0.215861, too. The commonly
    /// quoted "0.214" is that point to three digits and sits 0.5e-4 below
    /// it: 127.489 of 255, stored as 127. The ends stay where they are.
    #[test]
    fn srgb_puts_mid_grey_at_128() {
        let d = DisplayTransform::default();
        let half = srgb_decode(0.5);
        assert!((half - 0.214_041).abs() < 1e-6);
        assert!((srgb_encode(half) * 255.0 - 127.5).abs() < 1e-9);
        assert_eq!(d.to_rgb8(&[[0.214_05, 0.0, 1.0]]), vec![128, 0, 255]);
        assert_eq!(
            d.to_rgb8(&[[0.215_861, 0.2141, 0.214]]),
            vec![128, 128, 127]
        );
        assert_eq!(d.to_rgb8(&[[0.5, 0.18, 2.0]]), vec![188, 118, 255]);
        let k = 0.003_130_8;
        assert!((12.92 * k - (1.055 * f64::powf(k, 1.0 / 2.4) - 0.055)).abs() < 1e-7);
        for i in 0..=100 {
            let x = f64::from(i) / 100.0;
            assert!((srgb_decode(srgb_encode(x)) - x).abs() < 1e-12, "{x}");
        }
    }

    /// Remembered levels are the transform's own: a run of repeated and
    /// colliding samples, in every order, gives what `apply` gives each.
    #[test]
    fn remembered_levels_equal_computed_ones() {
        let d = DisplayTransform::default();
        let mut samples: Vec<f32> = (0..5000).map(|i| (i as f32 * 0.37).fract() * 1.2).collect();
        samples.extend_from_within(..);
        samples.extend([0.0, -0.0, 1.0, 0.05, 0.05, 0.1, 0.05, f32::MIN_POSITIVE]);
        let pixels: Vec<[f32; 3]> = samples
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect();
        let expect8: Vec<u8> = pixels
            .iter()
            .flat_map(|p| p.map(|c| (d.apply(c) * 255.0).round() as u8))
            .collect();
        let expect16: Vec<u16> = pixels
            .iter()
            .flat_map(|p| p.map(|c| (d.apply(c) * 65535.0).round() as u16))
            .collect();
        assert_eq!(d.to_rgb8(&pixels), expect8);
        assert_eq!(d.to_rgb16(&pixels), expect16);
    }

    /// The table gives the computed level of every `f32` from `2^-13` to
    /// 1 (below, every level is 0 both ways; the thresholds' neighbours
    /// are checked too), for the viewer's transform; and the thresholds'
    /// neighbours for every transform.
    #[test]
    fn level_table_equals_the_computed_levels() {
        use rayon::prelude::*;
        let d = DisplayTransform::default();
        let table = Levels8::new(d);
        let exact = |c: f32| (d.apply(c) * 255.0).round() as u8;
        let (lo, hi) = ((2.0f32).powi(-13).to_bits(), 1.0f32.to_bits());
        // Blocks of 2^16 bit patterns, in parallel.
        let bad: usize = (lo >> 16..=hi >> 16)
            .into_par_iter()
            .map(|block| {
                (block << 16..=(block << 16 | 0xffff))
                    .filter(|bits| (lo..=hi).contains(bits))
                    .filter(|bits| {
                        let c = f32::from_bits(*bits);
                        table.level(c) != exact(c)
                    })
                    .count()
            })
            .sum();
        assert_eq!(bad, 0);
        // Below, every level is 0 both ways: the least level above 0 needs
        // 12.92 x 255 >= 0.5, x >= 1.5e-4.
        assert_eq!(exact(2.0f32.powi(-13)), 0);
        assert!(table.thresholds[0] > 2.0f32.powi(-13));
        for tone in [ToneMap::Clip, ToneMap::Reinhard, ToneMap::Aces] {
            for encoding in [Encoding::Srgb, Encoding::Linear] {
                let d = DisplayTransform { tone, encoding };
                let table = Levels8::new(d);
                let exact = |c: f32| (d.apply(c) * 255.0).round() as u8;
                for t in table.thresholds.iter().copied() {
                    for c in [
                        t,
                        f32::from_bits(t.to_bits() - 1),
                        f32::from_bits(t.to_bits() + 1),
                    ] {
                        assert_eq!(table.level(c), exact(c), "{d:?} at {c}");
                    }
                }
                for c in [
                    0.0,
                    -0.0,
                    -1.0,
                    1.0,
                    2.0,
                    1e30,
                    f32::MAX,
                    f32::NAN,
                    f32::INFINITY,
                ] {
                    assert_eq!(table.level(c), exact(c), "{d:?} at {c}");
                }
                let pixels = [[0.5, 0.18, 2.0], [0.0, 0.2141, 1e-3]];
                assert_eq!(table.to_rgb8_parallel(&pixels), d.to_rgb8(&pixels));
            }
        }
    }

    #[test]
    fn linear_encoding_stores_values_as_they_are() {
        let d = DisplayTransform {
            tone: ToneMap::Clip,
            encoding: Encoding::Linear,
        };
        assert_eq!(d.to_rgb8(&[[0.25, 0.5, 3.0]]), vec![64, 128, 255]);
        assert_eq!(d.to_rgb16(&[[0.25, -1.0, 0.125]]), vec![16384, 0, 8192]);
    }

    /// The tone curves: monotone, 0 at 0, in [0, 1]; Reinhard reaches 1/2
    /// at 1 and never saturates; ACES saturates near 11 and keeps black.
    #[test]
    fn tone_curves() {
        for t in [ToneMap::Clip, ToneMap::Reinhard, ToneMap::Aces] {
            assert_eq!(t.apply(0.0), 0.0);
            assert_eq!(t.apply(-3.0), 0.0);
            let mut last = 0.0;
            for i in 1..2000 {
                let y = t.apply(f64::from(i) * 0.01);
                assert!(y >= last && y <= 1.0, "{t:?} at {i}");
                last = y;
            }
        }
        assert_eq!(ToneMap::Reinhard.apply(1.0), 0.5);
        assert!(ToneMap::Reinhard.apply(1e6) < 1.0);
        assert_eq!(ToneMap::Aces.apply(12.5), 1.0);
        assert!(ToneMap::Aces.apply(11.5) < 1.0);
        // Mid-grey 0.18 comes out near 0.14: the filmic curve is darker
        // than clip in the mid-tones and keeps the highlights.
        assert!((ToneMap::Aces.apply(0.18) - 0.1402).abs() < 1e-3);
    }
}
