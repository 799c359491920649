//! A ray's chord set up for slab tests in `f32`, four boxes at a time, that
//! never reject a box holding a point of the ray the exact tests can hit.
//!
//! The chord is `k(λ) = P + λ V` in Klein coordinates ([`KleinRay`]). Its
//! slab parameter on the plane `x_i = c` is `t = (c - P_i)/V_i = c a + b`
//! with `a = 1/V_i` and `b = -P_i a`. Computing that in `f32` rounds `a`,
//! `b`, the product and the sum; the test stays conservative by computing
//! entries with `b` lowered, and exits with `b` raised, by a margin `M`
//! larger than all of those roundings together:
//!
//! - **Scale.** `V` is divided by the power of two `p` at most its largest
//!   component (exact), so `1 <= max |V_i| < 2`, and `λ` is multiplied by
//!   `p` (exact). Every point the exact tests can hit lies in the ball, and
//!   `|k - P| = |λ| |V| >= |λ|`, so such points have `|λ| < 2` (the arc's
//!   ends themselves may be larger, even infinite, far out).
//! - **Nearly parallel axes.** A component below `2^-40` is raised to
//!   `±2^-40`: over `|λ| < 2` that moves the chord by less than `2^-39`
//!   (`2e-12`) in Klein coordinates, far inside the `1e-9` padding that
//!   keeps every hit inside its box ([`hgeom::klein_box::PAD`]), as
//!   [`KleinRay::new`] does for zero components: a box the turned chord
//!   misses may be one the exact chord grazes, never one holding a hit. So
//!   `0.5 < |a| <= 2^40`, and with corners `|c| <= 2` (boxes are clamped
//!   there; every hit has `|k| <= 1`) no `f32` product overflows. The empty
//!   box of an absent child (`+inf` below, `-inf` above) gives `±inf`
//!   without NaN for either sign of `a` (never 0 or infinite), entry
//!   `+inf` and exit `-inf`: always rejected.
//! - **The margin.** With `u = 2^-24`: `a` is rounded in `f64` and then to
//!   `f32`, `ã = a (1 + δ1)` with `|δ1| <= 1.01 u`; the product and the sum
//!   are each rounded once more, so the computed `t̃` of `c ã + b̃` differs
//!   from `c a + b̃` by at most `|c a| 3.05 u + |b̃| u <= 6.1 u |a| + u |b̃|`.
//!   The entry's `b̃` is `b - M` rounded to the nearest `f32`,
//!   `M = 32 u (|a| + |b|)`, so `b̃ <= b - M + u (|b| + M)`, and then
//!   `t̃ <= t - M (1 - 2u - u^2) + (2u + u^2) |b| + 6.1 u |a| < t`; the exit
//!   is the mirror image (`b` itself, `-P_i a` in `f64`, is a few `f64`
//!   ulps off, far inside the slack). A fused multiply-add rounds less. Rounding to nearest
//!   and a margin twice as wide need no branch, where rounding down would
//!   need one per value, taken at random.
//! - **The arc.** Its ends are widened by `4u` of their size (and the
//!   least normal `f32`) before rounding to nearest, which keeps them
//!   outside the exact ends by the same argument. An end that is NaN (far
//!   out, `λ` of an inward ray can overflow and the padding then gives
//!   `inf - inf`) is taken as unbounded: `-inf` for the start, `+inf` for
//!   the end, never a NaN that SIMD `min`/`max` would treat differently on
//!   different targets.
//!
//! In Klein coordinates the margin widens every box by `M/|a| <= 2^-18`
//! (at most `4e-6`, and `2e-6` for rays from near the origin): it costs
//! culling only for objects smaller than that, which `f32` boxes (whose
//! corners are `6e-8` apart near the absolute) already blur.

use hgeom::KleinRay;
use hgeom::glam::Vec4;

/// `2^-40`: the least chord component kept (after scaling).
const LEAST_COMPONENT: f64 = 9.094_947_017_729_282e-13;

/// `32 u`, `u = 2^-24`: the margin per unit of `|a| + |b|`.
const MARGIN: f64 = 1.907_348_632_812_5e-6;

/// `4 u`: the relative widening of the arc's ends.
const ARC_MARGIN: f64 = 2.384_185_791_015_625e-7;

/// The largest box coordinate the slab test sees; boxes are clamped to
/// `[-CORNER, CORNER]`, which holds the ball and every arc.
pub(super) const CORNER: f32 = 2.0;

/// A chord in slab-test form, in `f32`: see the module docs.
#[derive(Clone, Copy, Debug)]
pub(super) struct Chord32 {
    /// Per axis, `ã = 1/V_i` splatted across the four lanes.
    a: [Vec4; 3],
    /// Per axis, `b = -P_i ã` rounded down by the margin: for entries.
    b_enter: [Vec4; 3],
    /// Per axis, `b` rounded up by the margin: for exits.
    b_leave: [Vec4; 3],
    /// Per axis, which corner of a box the chord meets first: 0 for the
    /// least (`V_i > 0`), 1 for the greatest.
    pub near: [usize; 3],
    /// The scale `p` from the chord's `λ` to this one's.
    scale: f64,
}

impl Chord32 {
    /// The chord of a finite ray ([`KleinRay::is_finite`]).
    #[inline]
    pub fn new(chord: &KleinRay) -> Chord32 {
        let v = chord.dir();
        let largest = v.abs().max_element();
        // The power of two at most `largest`: its exponent bits alone
        // (`largest >= 1e-200` is normal).
        let scale = f64::from_bits(largest.to_bits() & 0x7ff0_0000_0000_0000);
        // Components below LEAST_COMPONENT (after scaling) are raised to
        // it; scaled by a power of two, that is `|v_i| < least`, exactly.
        let least = LEAST_COMPONENT * scale;
        let origin = chord.origin();
        let mut a = [Vec4::ZERO; 3];
        let mut b_enter = [Vec4::ZERO; 3];
        let mut b_leave = [Vec4::ZERO; 3];
        let mut near = [0; 3];
        for i in 0..3 {
            // `1 / (v_i / scale)` is `scale / v_i` rounded once, as dividing
            // by a power of two is exact: one division on the way instead
            // of two.
            let ai = if v[i].abs() < least {
                1.0 / LEAST_COMPONENT.copysign(v[i])
            } else {
                scale / v[i]
            };
            let bi = -origin[i] * ai;
            let margin = MARGIN * (ai.abs() + bi.abs());
            a[i] = Vec4::splat(ai as f32);
            b_enter[i] = Vec4::splat((bi - margin) as f32);
            b_leave[i] = Vec4::splat((bi + margin) as f32);
            near[i] = usize::from(ai < 0.0);
        }
        Chord32 {
            a,
            b_enter,
            b_leave,
            near,
            scale,
        }
    }

    /// Which corner of a box the chord meets first, as three bits (bit
    /// `i` set when it runs towards `-x_i`): 0 to 7.
    #[inline]
    pub fn octant(&self) -> usize {
        self.near[0] | (self.near[1] << 1) | (self.near[2] << 2)
    }

    /// The chord's `λ` (of [`KleinRay`]) in this chord's units, at most
    /// `lambda` (`-inf` if that is NaN): for the start of an arc.
    #[inline]
    pub fn lambda_below(&self, lambda: f64) -> f32 {
        let x = lambda * self.scale;
        let below = (x - (ARC_MARGIN * x.abs() + f64::from(f32::MIN_POSITIVE))) as f32;
        if below.is_nan() {
            f32::NEG_INFINITY
        } else {
            below
        }
    }

    /// As [`Chord32::lambda_below`], at least `lambda` (`+inf` if that is
    /// NaN): for the end of an arc.
    #[inline]
    pub fn lambda_above(&self, lambda: f64) -> f32 {
        let x = lambda * self.scale;
        let above = (x + (ARC_MARGIN * x.abs() + f64::from(f32::MIN_POSITIVE))) as f32;
        if above.is_nan() { f32::INFINITY } else { above }
    }

    /// Lower bounds of the slab parameters of the four corner coordinates
    /// `near` on axis `i`: each at most the exact entry into that slab.
    #[inline(always)]
    pub fn enter(&self, i: usize, near: Vec4) -> Vec4 {
        near * self.a[i] + self.b_enter[i]
    }

    /// Upper bounds of the slab parameters of `far` on axis `i`.
    #[inline(always)]
    pub fn leave(&self, i: usize, far: Vec4) -> Vec4 {
        far * self.a[i] + self.b_leave[i]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;
    use hgeom::{Point, Ray};

    /// The entry and exit of the exact chord into the box, in the chord's
    /// own `λ` and in `f64` arithmetic over exact (`f32`) corners.
    fn exact(chord: &KleinRay, lo: DVec3, hi: DVec3) -> (f64, f64) {
        let (p, inv) = (chord.origin(), chord.inv_dir());
        let (x, y) = ((lo - p) * inv, (hi - p) * inv);
        (x.min(y).max_element(), x.max(y).min_element())
    }

    /// On random rays from near the origin and far from it, nearly
    /// parallel to an axis or not, and random boxes (tiny ones, ones
    /// touching the chord), the `f32` entry is never after the exact one
    /// and the `f32` exit never before it.
    #[test]
    fn f32_slabs_contain_the_exact_ones() {
        let mut rng = hscene_test_support::SplitMix64::new(11);
        let mut rnd = move || rng.range(-1.0, 1.0);
        let mut checked = 0;
        for k in 0..20_000 {
            let r = [0.0, 0.5, 0.99, 0.999_999][k % 4];
            let start = DVec3::new(rnd(), rnd(), rnd()).normalize_or_zero() * r * rnd().abs();
            let mut dir = DVec3::new(rnd(), rnd(), rnd());
            if k % 3 == 0 {
                dir[k % 3] *= 1e-14;
            }
            let Ok(start) = Point::from_coords(start) else {
                continue;
            };
            let ray = Ray::from_ball_unchecked(&start, dir);
            let chord = KleinRay::new(&ray);
            let c32 = Chord32::new(&chord);
            // A box around a point of the chord, of random size down to
            // 1e-9, or one anywhere.
            let on = chord.origin() + chord.dir() * chord.lambda(rnd().abs() * 5.0);
            let half = DVec3::new(rnd(), rnd(), rnd()).abs() * 10f64.powf(-9.0 * rnd().abs());
            let centre = if k % 2 == 0 {
                on
            } else {
                DVec3::new(rnd(), rnd(), rnd())
            };
            let (lo, hi) = hgeom::round_outward_f32(centre - half, centre + half);
            let (lo, hi) = (
                DVec3::from(lo.map(f64::from)),
                DVec3::from(hi.map(f64::from)),
            );
            let (enter, leave) = exact(&chord, lo, hi);
            for i in 0..3 {
                let (near, far) = if c32.near[i] == 1 {
                    (hi[i], lo[i])
                } else {
                    (lo[i], hi[i])
                };
                let e = f64::from(c32.enter(i, Vec4::splat(near as f32)).x);
                let l = f64::from(c32.leave(i, Vec4::splat(far as f32)).x);
                // The chord as `Chord32` sees it: scaled, and turned where
                // nearly parallel to the axis (module docs).
                let mut vi = chord.dir()[i] / c32.scale;
                if vi.abs() < LEAST_COMPONENT {
                    vi = LEAST_COMPONENT.copysign(vi);
                }
                let exact_e = (near - chord.origin()[i]) / vi;
                let exact_l = (far - chord.origin()[i]) / vi;
                let slack = |x: f64| 1e-12 * x.abs() + 1e-300;
                assert!(
                    e <= exact_e + slack(exact_e),
                    "ray {k} axis {i}: {e} > {exact_e}"
                );
                assert!(
                    l >= exact_l - slack(exact_l),
                    "ray {k} axis {i}: {l} < {exact_l}"
                );
            }
            if enter <= leave {
                checked += 1;
            }
        }
        assert!(checked > 5000, "{checked}");
    }

    /// The arc's ends in `f32` stay outside the exact ones, from zero and
    /// the least normals to the far end of a chord.
    #[test]
    fn arc_ends_round_outwards() {
        let ray = Ray::from_origin_unchecked(DVec3::new(0.3, -0.2, 0.9));
        let c32 = Chord32::new(&KleinRay::new(&ray));
        let mut x = 1e-300;
        while x < 10.0 {
            for v in [x, -x, x * 1.000_000_1, 0.0] {
                let exact = v * c32.scale;
                assert!(f64::from(c32.lambda_below(v)) <= exact, "{v}");
                assert!(f64::from(c32.lambda_above(v)) >= exact, "{v}");
            }
            x *= 1.37;
        }
        // Unbounded where the arc's end is not a number or infinite.
        assert_eq!(c32.lambda_below(f64::NAN), f32::NEG_INFINITY);
        assert_eq!(c32.lambda_above(f64::NAN), f32::INFINITY);
        assert_eq!(c32.lambda_below(f64::INFINITY), f32::NEG_INFINITY);
        assert_eq!(c32.lambda_above(f64::NEG_INFINITY), f32::INFINITY);
        assert_eq!(c32.lambda_above(f64::INFINITY), f32::INFINITY);
    }
}
