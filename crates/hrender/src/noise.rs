//! How much noise is left in a pixel, from its own samples, and adaptive
//! sampling: a pixel takes samples until that noise is low enough.
//!
//! A pixel's value is the mean of its samples' radiance; its noise is the
//! relative standard error of that mean, measured on the luminance: with
//! `n` samples of mean `m` and sample variance `s²`, `sqrt(s² / n) / m`.
//! It is the usual Monte Carlo error estimate: a render with four times
//! the samples has about half of it.

use hscene_ir::Rgb;

use crate::error::RenderError;
use crate::exposure::LUMA;

/// Rec. 709 luminance of a linear colour; negative channels count as 0
/// ([`crate::luminance`] in f64, without the round trip through f32).
#[inline]
fn luminance_of(c: Rgb) -> f64 {
    LUMA[0] * c.r.max(0.0) + LUMA[1] * c.g.max(0.0) + LUMA[2] * c.b.max(0.0)
}

/// Samples an adaptive pixel takes between two looks at its noise, and
/// at least: fewer would judge the noise from too small a sample (a pixel
/// whose first few paths all miss the light looks noiseless).
pub const ADAPTIVE_BATCH: u32 = 16;

/// The running mean and variance of a pixel's sample luminances
/// (Welford's update, stable for any number of samples).
#[derive(Clone, Copy, Debug, Default)]
pub struct PixelNoise {
    n: u32,
    mean: f64,
    /// The sum of squared deviations from the mean.
    m2: f64,
}

impl PixelNoise {
    /// Count one sample.
    #[inline]
    pub fn add(&mut self, c: Rgb) {
        let y = luminance_of(c);
        self.n += 1;
        let delta = y - self.mean;
        self.mean += delta / f64::from(self.n);
        self.m2 += delta * (y - self.mean);
    }

    /// Samples counted.
    pub fn count(&self) -> u32 {
        self.n
    }

    /// The relative standard error of the mean luminance; `None` with
    /// fewer than two samples or a black mean (nothing to be relative to).
    pub fn relative_error(&self) -> Option<f64> {
        if self.n < 2 || !(self.mean > 0.0) {
            return None;
        }
        let variance = self.m2 / f64::from(self.n - 1);
        Some((variance / f64::from(self.n)).sqrt() / self.mean)
    }
}

/// Adaptive sampling: samples in batches of [`ADAPTIVE_BATCH`] until the
/// pixel's relative standard error is at most `noise`, or `max_samples`.
/// A pixel whose batch saw no light at all (a black mean) stops after its
/// first batch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adaptive {
    /// The relative standard error to reach, in `(0, 1]`.
    pub noise: f64,
    /// The most samples a pixel takes, a multiple of the batch from
    /// [`ADAPTIVE_BATCH`] to [`MAX_SAMPLES`](crate::MAX_SAMPLES).
    pub max_samples: u32,
}

impl Adaptive {
    /// The most samples per pixel without `--max-samples`.
    pub const DEFAULT_MAX_SAMPLES: u32 = 1024;

    /// Check the ranges.
    pub fn validate(&self) -> Result<(), RenderError> {
        if !(self.noise > 0.0 && self.noise <= 1.0) {
            return Err(RenderError::InvalidOption(format!(
                "the noise target must be above 0 and at most 1, not {}",
                self.noise
            )));
        }
        let max = crate::MAX_SAMPLES;
        if !(ADAPTIVE_BATCH..=max).contains(&self.max_samples)
            || !self.max_samples.is_multiple_of(ADAPTIVE_BATCH)
        {
            return Err(RenderError::InvalidOption(format!(
                "the most samples of adaptive sampling must be a multiple of {ADAPTIVE_BATCH} from {ADAPTIVE_BATCH} to {max}, not {}",
                self.max_samples
            )));
        }
        Ok(())
    }

    /// True when a pixel with this noise so far takes no more samples
    /// (the cap itself is the sampler's count).
    #[inline]
    pub fn is_done(&self, noise: &PixelNoise) -> bool {
        let n = noise.count();
        if !n.is_multiple_of(ADAPTIVE_BATCH) {
            return false;
        }
        match noise.relative_error() {
            Some(e) => e <= self.noise,
            None => true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::SampleStream;

    /// The running estimate agrees with the two-pass formula, and the
    /// relative error of a uniform variable on [0, 2) halves when the
    /// samples quadruple.
    #[test]
    fn relative_error_falls_as_one_over_root_n() {
        let mut stream = SampleStream::new(5);
        let grey = |v: f64| Rgb::new(v, v, v);
        let draws: Vec<f64> = (0..4096).map(|_| 2.0 * stream.next_unit()).collect();
        let at = |n: usize| {
            let mut p = PixelNoise::default();
            draws[..n].iter().for_each(|&v| p.add(grey(v)));
            p
        };
        let p = at(100);
        let ys: Vec<f64> = draws[..100]
            .iter()
            .map(|&v| luminance_of(grey(v)))
            .collect();
        let mean = ys.iter().sum::<f64>() / 100.0;
        let var = ys.iter().map(|y| (y - mean).powi(2)).sum::<f64>() / 99.0;
        let two_pass = (var / 100.0).sqrt() / mean;
        assert!((p.relative_error().unwrap() - two_pass).abs() < 1e-12);
        let ratio = at(256).relative_error().unwrap() / at(4096).relative_error().unwrap();
        assert!((ratio - 4.0).abs() < 0.4, "{ratio}");
        assert_eq!(PixelNoise::default().relative_error(), None);
        let mut black = PixelNoise::default();
        black.add(Rgb::BLACK);
        black.add(Rgb::BLACK);
        assert_eq!(black.relative_error(), None);
    }

    /// Adaptive sampling stops only at the end of a batch, when the noise
    /// is reached or nothing was seen.
    #[test]
    fn stops_at_batches() {
        let a = Adaptive {
            noise: 0.05,
            max_samples: 64,
        };
        let mut flat = PixelNoise::default();
        for k in 1..=ADAPTIVE_BATCH {
            flat.add(Rgb::new(0.5, 0.5, 0.5));
            assert_eq!(a.is_done(&flat), k == ADAPTIVE_BATCH);
        }
        let mut noisy = PixelNoise::default();
        for k in 0..ADAPTIVE_BATCH {
            noisy.add(if k % 2 == 0 {
                Rgb::BLACK
            } else {
                Rgb::new(1.0, 1.0, 1.0)
            });
        }
        assert!(!a.is_done(&noisy));
        assert!(a.validate().is_ok());
        for bad in [(0.0, 64), (0.01, 8), (0.01, 100), (f64::NAN, 64)] {
            let b = Adaptive {
                noise: bad.0,
                max_samples: bad.1,
            };
            assert!(b.validate().is_err(), "{bad:?}");
        }
    }
}
