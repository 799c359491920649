//! Compensated floating-point kernels.
//!
//! Near the absolute the naive `1 - |x|^2` cancels catastrophically: for
//! `1 - |x| = 1e-15` it keeps about one significant digit. These kernels use
//! error-free transformations (FMA-based products, Knuth's two-sum) so the gap
//! is correct to a few ulps of itself, which is what keeps distances accurate
//! out to the limit of f64 (about 37 from the origin).

use glam::DVec3;

/// `a * b = p + e` exactly (for finite, non-overflowing inputs).
///
/// # Accuracy
///
/// Exact (an error-free transformation through one FMA), provided `a * b`
/// neither overflows nor underflows (products below ~1e-292 lose low bits
/// of `e`; ball coordinates never come near that).
#[inline]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// `a + b = s + e` exactly (Knuth's branch-free two-sum).
///
/// # Accuracy
///
/// Exact for all finite inputs whose sum does not overflow.
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `|v|^2` as an unevaluated sum `hi + lo`, correct to about 2^-104 relative.
///
/// # Accuracy
///
/// The three products and two sums are error-free; only the five error
/// terms are added in plain f64, so `hi + lo` is within a few units of
/// `2^-106 |v|^2` of the exact `|v|^2`.
#[inline]
pub fn norm_sq_dd(v: DVec3) -> (f64, f64) {
    let (px, ex) = two_prod(v.x, v.x);
    let (py, ey) = two_prod(v.y, v.y);
    let (pz, ez) = two_prod(v.z, v.z);
    let (s1, e1) = two_sum(px, py);
    let (s2, e2) = two_sum(s1, pz);
    (s2, ex + ey + ez + e1 + e2)
}

/// `1 - |v|^2`, correct to a few ulps of the result even when `|v|` is within
/// one ulp of 1.
///
/// For `|v|^2 >= 1/2` the subtraction `1 - hi` is exact (Sterbenz lemma), so
/// the only rounding left is the final one.
///
/// # Accuracy
///
/// Absolute error below `2^-104 |v|^2 + ulp(result)`: relative error of a
/// few ulps for every `|v| < 1` down to `1 - |v| = 2^-53`
/// (`gap_is_accurate_next_to_the_absolute` in this module: 1e-15 relative
/// at `1 - |v| = 2^-52`). The naive `1 - |v|^2` has absolute error
/// ~`2^-53`, i.e. relative error ~`2^-53 / gap`: all digits gone at
/// `gap ~ 1e-16`.
#[inline]
pub fn one_minus_norm_sq(v: DVec3) -> f64 {
    let (hi, lo) = norm_sq_dd(v);
    if hi >= 0.5 {
        (1.0 - hi) - lo
    } else {
        1.0 - (hi + lo)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_prod_is_exact_on_representable_case() {
        let a = 1.0 + f64::EPSILON;
        let (p, e) = two_prod(a, a);
        // (1+e)^2 = 1 + 2e + e^2; e^2 is lost by p and recovered by e.
        assert_eq!(p, 1.0 + 2.0 * f64::EPSILON);
        assert_eq!(e, f64::EPSILON * f64::EPSILON);
    }

    #[test]
    fn gap_is_accurate_next_to_the_absolute() {
        // x = 1 - 2^-52 exactly; 1 - x^2 = 2^-51 - 2^-104.
        let x = 1.0 - f64::EPSILON;
        let gap = one_minus_norm_sq(DVec3::new(x, 0.0, 0.0));
        let exact = 2.0 * f64::EPSILON - f64::EPSILON * f64::EPSILON;
        assert!(
            ((gap - exact) / exact).abs() < 1e-15,
            "gap {gap:e} exact {exact:e}"
        );
    }

    #[test]
    fn gap_of_small_vectors_is_plain() {
        let v = DVec3::new(0.1, 0.2, 0.3);
        assert!((one_minus_norm_sq(v) - (1.0 - 0.14)).abs() < 1e-16);
    }
}
