//! Sub-pixel sample positions and the numbers that shading draws.
//!
//! Every number of a pixel sample is a coordinate of an Owen-scrambled
//! Sobol point (Burley 2020, the `sobol_burley` crate): sample `k` of pixel
//! `(x, y)` is point `k` of a sequence scrambled by a hash of `(seed, x,
//! y)`. Dimensions 0-1 place the sample in the pixel, 2-3 on the lens, and
//! each bounce of a path owns the next [`BOUNCE_DIMENSIONS`] (light choice,
//! point on the light, the lobes' three, roulette): *padded* per bounce,
//! so a vertex that draws fewer numbers does not shift the next one's.
//! Each dimension's first `2^m` samples are stratified in `2^m` intervals
//! (and pairs of dimensions in 2-D), which lowers the noise of every
//! smooth integrand against independent numbers. Past what the layout
//! covers (Whitted's area-light samples, bounces beyond the table, more
//! than 2^16 samples), a counter-based hash takes over.
//!
//! Nothing depends on which thread renders a pixel or in which order: the
//! same seed gives the same image.

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
    /// `[0, 1)` from the pixel's top-left corner: the Sobol point's first
    /// two dimensions, for a sample count that is a power of two (every
    /// prefix of `2^m` samples covers the pixel evenly); a perfect square
    /// that is not is stratified on its `m x m` grid instead.
    #[inline]
    pub fn offset(&self, x: u32, y: u32, k: u32) -> (f64, f64) {
        if self.samples == 1 {
            return (0.5, 0.5);
        }
        match self.strata {
            Some(m) if !self.samples.is_power_of_two() => {
                let (u, v) = uniform_pair(self.seed, x, y, k);
                let (cx, cy) = (k % m, k / m);
                let inv = 1.0 / f64::from(m);
                ((f64::from(cx) + u) * inv, (f64::from(cy) + v) * inv)
            }
            _ => {
                let [x, y, _, _] = SobolPoint::new(self.seed, x, y, k).four(0);
                (f64::from(x), f64::from(y))
            }
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
        SampleStream {
            state: mix(hash(self.seed, x, y, k) ^ STREAM_SALT),
            sobol: Some(Cursor::new(
                SobolPoint::new(self.seed, x, y, k),
                LENS_DIMENSION,
                LENS_DIMENSION + 2,
            )),
        }
    }

    /// The stream for a net-4 node `(a, b)` of the equidistant lattice:
    /// nodes are shared by neighbouring pixels (and traced once per row),
    /// so their stream depends on the node, not on the pixel asking.
    #[inline]
    pub fn node_stream(&self, a: i64, b: i64) -> SampleStream {
        // Bit patterns of the indices; the hash does not care about signs.
        let h = mix(mix(mix(self.seed ^ NODE_SALT) ^ a as u64) ^ b as u64);
        SampleStream::new(mix(h ^ STREAM_SALT))
    }
}

/// The first of the lens's two dimensions (the pixel has 0 and 1).
const LENS_DIMENSION: u32 = 2;

/// The dimensions each bounce of a path owns: the light unit, two for the
/// point on it, three for the lobes, one for roulette, one spare.
pub const BOUNCE_DIMENSIONS: u32 = 8;

/// One point of the scrambled Sobol sequence of a pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct SobolPoint {
    /// Its index in the sequence (below 2^16, the crate's limit).
    index: u32,
    /// The pixel's scramble (with the block of 2^16 samples mixed in).
    seed: u64,
}

impl SobolPoint {
    fn new(seed: u64, x: u32, y: u32, k: u32) -> SobolPoint {
        // The pixel's sequence does not depend on k, except past 2^16
        // samples, where each block of 2^16 gets a sequence of its own.
        SobolPoint {
            index: k & 0xFFFF,
            seed: mix(hash(seed, x, y, k >> 16) ^ SOBOL_SALT),
        }
    }

    /// Its coordinates in dimensions `4 set .. 4 set + 4`, computed together
    /// (the crate's four-lane form: the same numbers as one dimension at a
    /// time, for about a quarter of the work; one at a time, the scrambles
    /// were 15 % of a path-traced Cornell box's instructions). The crate has
    /// 256 dimensions, and each further 256 take another scramble
    /// (independent of the first).
    #[inline]
    fn four(&self, set: u32) -> [f32; 4] {
        let (block, set_in_block) = (set / 64, set % 64);
        let seed = if block == 0 {
            self.seed
        } else {
            mix(self.seed ^ u64::from(block))
        };
        sobol_burley::sample_4d(self.index, set_in_block, seed as u32)
    }
}

/// Separates the Sobol scrambles from the other hashes.
const SOBOL_SALT: u64 = 0x50B0_1B0B_5EED_F00D;

/// Where a stream stands in its sample's Sobol point: the next dimension
/// to hand out and the end of the run it may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Cursor {
    point: SobolPoint,
    next: u32,
    end: u32,
    /// The dimension set whose four coordinates `four` holds (as bits, so
    /// that the stream stays `Eq`); `u32::MAX` before the first.
    set: u32,
    four: [u32; 4],
}

impl Cursor {
    fn new(point: SobolPoint, next: u32, end: u32) -> Cursor {
        Cursor {
            point,
            next,
            end,
            set: u32::MAX,
            four: [0; 4],
        }
    }

    /// The point's coordinate in dimension `d`, its set of four computed
    /// once for the draws that follow (a bounce's dimensions are two sets).
    #[inline]
    fn coordinate(&mut self, d: u32) -> f64 {
        let set = d / 4;
        if self.set != set {
            self.four = self.point.four(set).map(f32::to_bits);
            self.set = set;
        }
        f64::from(f32::from_bits(self.four[(d % 4) as usize]))
    }
}

/// Separates the shading streams from the sample positions.
const STREAM_SALT: u64 = 0x5EED_0FA5_EA11_C7D3;
/// Separates net-4 node keys from pixel keys.
const NODE_SALT: u64 = 0x0DE5_0F4E_7400_0004;

/// A deterministic stream of uniforms for one pixel sample: the sample's
/// Sobol coordinates while the current run of dimensions lasts (the lens's,
/// or a bounce's after [`SampleStream::begin_bounce`]), else SplitMix64
/// from a hashed seed. Tracing is deterministic, so the `n`-th draw of a
/// sample's path is always the same number, on any number of threads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SampleStream {
    state: u64,
    sobol: Option<Cursor>,
}

impl SampleStream {
    /// A stream of independent uniforms from a seed (used where no pixel
    /// is known; the renderer takes its streams from [`Sampler::stream`]).
    pub const fn new(seed: u64) -> SampleStream {
        SampleStream {
            state: seed,
            sobol: None,
        }
    }

    /// The next uniform in `[0, 1)`: a Sobol coordinate (24 bits) inside
    /// the current run, else 53 random bits.
    #[inline]
    pub fn next_unit(&mut self) -> f64 {
        if let Some(c) = &mut self.sobol
            && c.next < c.end
        {
            let d = c.next;
            c.next += 1;
            return c.coordinate(d);
        }
        // A Weyl sequence through the finaliser (SplitMix64 with the
        // increment applied once more inside `mix`).
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        (mix(self.state) >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }

    /// Start bounce `bounce` of a path: the next draws are its
    /// [`BOUNCE_DIMENSIONS`] Sobol dimensions (a stream without a Sobol
    /// point stays random).
    #[inline]
    pub fn begin_bounce(&mut self, bounce: u32) {
        if let Some(c) = &mut self.sobol {
            c.next = LENS_DIMENSION + 2 + bounce.saturating_mul(BOUNCE_DIMENSIONS);
            c.end = c.next.saturating_add(BOUNCE_DIMENSIONS);
        }
    }

    /// Skip to dimension `offset` of the current bounce, so each decision
    /// keeps its own dimensions whether or not the ones before were drawn.
    #[inline]
    pub fn seek(&mut self, offset: u32) {
        if let Some(c) = &mut self.sobol {
            let start = c.end.saturating_sub(BOUNCE_DIMENSIONS);
            c.next = c.next.max(start.saturating_add(offset)).min(c.end);
        }
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

    /// Each bounce dimension of a pixel's first 16 streams is stratified:
    /// one number in each sixteenth of [0, 1); the bounces are padded, so
    /// a skipped draw does not shift the next decision's dimension.
    #[test]
    fn bounce_dimensions_are_stratified_and_padded() {
        let s = Sampler::new(16, 5);
        for bounce in [0, 1, 7] {
            for dim in 0..BOUNCE_DIMENSIONS {
                let mut cells = [false; 16];
                for k in 0..16 {
                    let mut st = s.stream(3, 4, k);
                    st.begin_bounce(bounce);
                    st.seek(dim);
                    let u = st.next_unit();
                    assert!((0.0..1.0).contains(&u));
                    cells[(u * 16.0) as usize] = true;
                }
                assert!(cells.iter().all(|c| *c), "bounce {bounce} dim {dim}");
            }
        }
        let mut a = s.stream(3, 4, 0);
        a.begin_bounce(2);
        a.seek(3);
        let mut b = s.stream(3, 4, 0);
        b.begin_bounce(2);
        for _ in 0..3 {
            b.next_unit();
        }
        assert_eq!(a.next_unit(), b.next_unit());
        // Past its run a stream is random, not a repeat of the next bounce.
        let mut c = s.stream(3, 4, 0);
        c.begin_bounce(0);
        for _ in 0..BOUNCE_DIMENSIONS {
            c.next_unit();
        }
        let mut d = s.stream(3, 4, 0);
        d.begin_bounce(1);
        assert_ne!(c.next_unit(), d.next_unit());
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
