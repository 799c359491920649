//! Sub-pixel sample positions for anti-aliasing.
//!
//! Positions come from a counter-based hash of `(seed, x, y, sample)`, not
//! from a random-number stream, so a pixel's samples do not depend on which
//! thread renders it or in which order: the same seed gives the same image.
//! The same hash seeds a [`SampleStream`] per pixel sample, which shading
//! draws from (the points sampled on area lights), so those are just as
//! independent of the thread count.

/// Where the samples of a pixel fall.
#[derive(Clone, Copy, Debug)]
pub struct Sampler {
    seed: u64,
    samples: u32,
    /// `sqrt(samples)` when `samples` is a perfect square (stratified).
    strata: Option<u32>,
}

impl Sampler {
    /// `samples >= 1` per pixel. One sample sits at the pixel centre (the
    /// thesis's unjittered net); a perfect square `m^2` is stratified on an
    /// `m x m` grid with one jittered sample per cell; any other count is
    /// jittered uniformly over the pixel.
    pub fn new(samples: u32, seed: u64) -> Sampler {
        let samples = samples.max(1);
        let m = (f64::from(samples).sqrt().round()) as u32;
        Sampler {
            seed,
            samples,
            strata: (m * m == samples).then_some(m),
        }
    }

    /// Up to `samples` per pixel, every one jittered uniformly over the
    /// pixel (none at the centre, no strata): for adaptive sampling, which
    /// may stop after any batch, so every prefix of the samples must cover
    /// the pixel evenly.
    pub fn jittered(samples: u32, seed: u64) -> Sampler {
        Sampler {
            seed,
            samples: samples.max(2),
            strata: None,
        }
    }

    /// Samples per pixel.
    pub fn count(&self) -> u32 {
        self.samples
    }

    /// The offset of sample `k` inside pixel `(x, y)`, both coordinates in
    /// `[0, 1)` from the pixel's top-left corner.
    #[inline]
    pub fn offset(&self, x: u32, y: u32, k: u32) -> (f64, f64) {
        if self.samples == 1 {
            return (0.5, 0.5);
        }
        let (u, v) = uniform_pair(self.seed, x, y, k);
        match self.strata {
            Some(m) => {
                let (cx, cy) = (k % m, k / m);
                let inv = 1.0 / f64::from(m);
                ((f64::from(cx) + u) * inv, (f64::from(cy) + v) * inv)
            }
            None => (u, v),
        }
    }
}

impl Sampler {
    /// The stream of uniforms that shading draws from for sample `k` of
    /// pixel `(x, y)`: seeded by the same hash of `(seed, x, y, k)` as the
    /// sample's position (a different output of it), so it depends on
    /// nothing else.
    #[inline]
    pub fn stream(&self, x: u32, y: u32, k: u32) -> SampleStream {
        SampleStream(mix(hash(self.seed, x, y, k) ^ STREAM_SALT))
    }

    /// The stream for a net-4 node `(a, b)` of the equidistant lattice:
    /// nodes are shared by neighbouring pixels (and traced once per row),
    /// so their stream depends on the node, not on the pixel asking.
    #[inline]
    pub fn node_stream(&self, a: i64, b: i64) -> SampleStream {
        // Bit patterns of the indices; the hash does not care about signs.
        let h = mix(mix(mix(self.seed ^ NODE_SALT) ^ a as u64) ^ b as u64);
        SampleStream(mix(h ^ STREAM_SALT))
    }
}

/// Separates the shading streams from the sample positions.
const STREAM_SALT: u64 = 0x5EED_0FA5_EA11_C7D3;
/// Separates net-4 node keys from pixel keys.
const NODE_SALT: u64 = 0x0DE5_0F4E_7400_0004;

/// A deterministic stream of uniforms for one pixel sample (SplitMix64 from
/// a hashed seed). Tracing is deterministic, so the `n`-th draw of a
/// sample's path is always the same number, on any number of threads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SampleStream(u64);

impl SampleStream {
    /// A stream from a seed (used where no pixel is known; the renderer
    /// takes its streams from [`Sampler::stream`]).
    pub const fn new(seed: u64) -> SampleStream {
        SampleStream(seed)
    }

    /// The next uniform in `[0, 1)` (53 bits).
    #[inline]
    pub fn next_unit(&mut self) -> f64 {
        // A Weyl sequence through the finaliser (SplitMix64 with the
        // increment applied once more inside `mix`).
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        (mix(self.0) >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }
}

/// SplitMix64's finaliser: a bijective mix of 64 bits with good avalanche.
#[inline]
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The chained hash of `(seed, x, y, k)`.
#[inline]
fn hash(seed: u64, x: u32, y: u32, k: u32) -> u64 {
    mix(mix(mix(seed) ^ ((u64::from(x) << 32) | u64::from(y))) ^ u64::from(k))
}

/// Two independent uniforms in `[0, 1)` for `(seed, x, y, k)`: the high and
/// low 32 bits of a chained hash (32 bits resolve a pixel finely enough).
#[inline]
fn uniform_pair(seed: u64, x: u32, y: u32, k: u32) -> (f64, f64) {
    let h = hash(seed, x, y, k);
    const SCALE: f64 = 1.0 / 4_294_967_296.0;
    ((h >> 32) as f64 * SCALE, (h & 0xFFFF_FFFF) as f64 * SCALE)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sample_is_the_centre() {
        assert_eq!(Sampler::new(1, 9).offset(3, 4, 0), (0.5, 0.5));
        assert_eq!(Sampler::new(0, 9).count(), 1);
    }

    #[test]
    fn square_counts_are_stratified() {
        let s = Sampler::new(16, 5);
        let mut cells = [false; 16];
        for k in 0..16 {
            let (u, v) = s.offset(10, 20, k);
            assert!((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v));
            cells[(v * 4.0) as usize * 4 + (u * 4.0) as usize] = true;
        }
        assert!(cells.iter().all(|c| *c), "one sample in every cell");
    }

    #[test]
    fn deterministic_and_seed_dependent() {
        let a = Sampler::new(5, 1);
        let b = Sampler::new(5, 1);
        let c = Sampler::new(5, 2);
        for k in 0..5 {
            assert_eq!(a.offset(7, 8, k), b.offset(7, 8, k));
        }
        assert_ne!(a.offset(7, 8, 0), c.offset(7, 8, 0));
        // Neighbouring pixels and samples differ.
        assert_ne!(a.offset(7, 8, 0), a.offset(8, 8, 0));
        assert_ne!(a.offset(7, 8, 0), a.offset(7, 8, 1));
    }

    #[test]
    fn streams_are_deterministic_and_distinct() {
        let s = Sampler::new(1, 3);
        let draw = |mut st: SampleStream| [st.next_unit(), st.next_unit()];
        assert_eq!(draw(s.stream(4, 5, 0)), draw(s.stream(4, 5, 0)));
        assert_ne!(draw(s.stream(4, 5, 0)), draw(s.stream(5, 4, 0)));
        assert_ne!(draw(s.stream(4, 5, 0)), draw(s.stream(4, 5, 1)));
        assert_ne!(
            draw(s.stream(4, 5, 0)),
            draw(Sampler::new(1, 4).stream(4, 5, 0))
        );
        assert_eq!(draw(s.node_stream(-3, 7)), draw(s.node_stream(-3, 7)));
        assert_ne!(draw(s.node_stream(-3, 7)), draw(s.node_stream(7, -3)));
        let mut st = s.stream(1, 2, 3);
        let n = 20_000;
        let mean = (0..n).map(|_| st.next_unit()).sum::<f64>() / f64::from(n);
        assert!((mean - 0.5).abs() < 0.01, "{mean}");
    }

    #[test]
    fn uniforms_have_the_right_mean() {
        let s = Sampler::new(3, 0);
        let n = 30_000u32;
        let mean: f64 = (0..n)
            .map(|k| s.offset(k % 100, k / 100, k % 3).0)
            .sum::<f64>()
            / f64::from(n);
        // Standard error of the mean of U(0,1) is 0.29/sqrt(n) = 0.0017.
        assert!((mean - 0.5).abs() < 0.01, "{mean}");
    }
}
