//! The exact test of a geodesic against a triangle: the triangle projected
//! along the geodesic onto the quotient plane, where the geodesic is the
//! origin and the test is three 2-D cross products with an exact sign (the
//! `mesh` module docs derive it).

use glam::DVec4;

use crate::accurate::two_prod;
use crate::lorentz;
use crate::ray::Ray;

/// The projection along a ray's geodesic onto the quotient plane
/// `R^{3,1} / span(X, V)`.
pub(super) struct Projection {
    /// `<F,.>` and `<G,.>` vanish on `X` and `V`.
    f: DVec4,
    g: DVec4,
}

impl Projection {
    /// The projection along a local ray's geodesic; `None` for a non-finite
    /// ray, or one whose complement f64 cannot normalise.
    pub(super) fn new(local: &Ray) -> Option<Projection> {
        let (x, v) = (local.origin, local.dir);
        if !(x.is_finite() && v.is_finite()) {
            return None;
        }
        // A basis of the Lorentz complement of span(X, V): the complement of
        // (X, V, e) for the coordinate vector e that gives the longest one,
        // then the vector orthogonal to X, V and that.
        let mut f = DVec4::ZERO;
        let mut best = 0.0;
        for e in [DVec4::X, DVec4::Y, DVec4::Z, DVec4::W] {
            let c = lorentz::orthogonal_complement(x, v, e);
            let q = lorentz::dot(c, c);
            if q > best {
                best = q;
                f = c;
            }
        }
        if !(best > 0.0 && best.is_finite()) {
            return None;
        }
        let f = f / best.sqrt();
        let g = lorentz::orthogonal_complement(x, v, f);
        let gn = lorentz::norm(g);
        if !(gn > 0.0 && gn.is_finite()) {
            return None;
        }
        let g = g / gn;
        Some(Projection { f, g })
    }

    /// The vertex projected along the geodesic.
    #[inline]
    fn project(&self, a: DVec4) -> (f64, f64) {
        (lorentz::dot(self.f, a), lorentz::dot(self.g, a))
    }

    /// Whether the geodesic meets the triangle: the origin of the quotient
    /// plane lies in the projected triangle (closed), i.e. the three cross
    /// products agree in sign (zeros agree with both).
    #[inline]
    pub(super) fn crosses(&self, corners: [DVec4; 3]) -> bool {
        let [a, b, c] = corners.map(|p| self.project(p));
        let u = cross(a, b);
        let v = cross(b, c);
        let w = cross(c, a);
        (u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0)
    }
}

/// `a.x b.y - a.y b.x` with the exact sign (or zero) of that expression in
/// the given floats, and exactly antisymmetric: `cross(b, a) == -cross(a, b)`.
///
/// The plain difference is returned when it exceeds its rounding
/// (`4 eps (|p| + |q|)`); otherwise `p` and `q` are within a factor 2 of each
/// other, so `p - q` is exact (Sterbenz), and the low parts of the products
/// (error-free, [`two_prod`]) decide. Rounding can only turn a nonzero value
/// into zero, never flip its sign.
#[inline]
fn cross(a: (f64, f64), b: (f64, f64)) -> f64 {
    let p = a.0 * b.1;
    let q = a.1 * b.0;
    let d = p - q;
    if d.abs() > 4.0 * f64::EPSILON * (p.abs() + q.abs()) {
        return d;
    }
    let (p, ep) = two_prod(a.0, b.1);
    let (q, eq) = two_prod(a.1, b.0);
    (p - q) + (ep - eq)
}

#[cfg(test)]
mod tests {
    use super::*;
    use hscene_test_support::SplitMix64;

    #[test]
    fn cross_is_exactly_antisymmetric_and_exact_in_sign() {
        let mut rng = SplitMix64::new(5);
        for _ in 0..10_000 {
            let a = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            // Nearly parallel vectors: the naive difference cancels.
            let s = rng.range(0.5, 2.0);
            let b = (a.0 * s + rng.range(-1e-16, 1e-16), a.1 * s);
            assert_eq!(cross(a, b), -cross(b, a));
            assert_eq!(cross(a, a), 0.0);
        }
        // 3 * (1 + 2^-52) - (3 + 2^-51) * 1 = 3 * 2^-52 - 2^-51 = 2^-52 > 0.
        let e = f64::EPSILON;
        assert!(cross((3.0, 1.0), (1.0, 1.0 + e)) > 0.0);
        assert!(cross((1.0 + e, 1.0 + e), (1.0 - e, 1.0 - e)) == 0.0);
    }
}
