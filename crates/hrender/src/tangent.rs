//! Keeping tangent vectors on the hyperboloid honest: the checks and the
//! renormalisation every integrator applies to the directions it makes.

use hgeom::glam::DVec4;
use hgeom::lorentz;

/// How far `<v,v>` may stray from 1 before a tangent vector counts as lost.
const UNIT_TOLERANCE: f64 = 1e-2;

/// True if the tangent vector's Lorentz norm is 1 up to a tolerance far
/// above the rounding of any resolvable vector (which grows like
/// `1e-16 cosh^2` of the distance from the eye: 3e-4 at distance 15).
#[inline]
pub fn is_unit(v: DVec4) -> bool {
    (lorentz::dot(v, v) - 1.0).abs() <= UNIT_TOLERANCE
}

/// Restore `<v,v> = 1`, `<p,v> = 0` after floating-point arithmetic on a
/// tangent vector, so rounding never accumulates along a path. A degenerate
/// input gives a non-finite ray, which the next trace counts as a failure.
#[inline]
pub fn renormalize(p: DVec4, v: DVec4) -> DVec4 {
    let t = v + lorentz::dot(p, v) * p;
    t / lorentz::norm(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::Point;
    use hgeom::glam::DVec3;

    /// A vector pushed off the tangent space and off unit length comes back
    /// tangent and unit; a lost one is told apart from a unit one.
    #[test]
    fn renormalised_vectors_are_unit_tangents() {
        let p = Point::at_distance_from_origin(DVec3::new(0.3, -0.2, 0.9), 2.0)
            .unwrap()
            .to_hyperboloid();
        let v = renormalize(p, DVec4::new(0.4, 1.0, -0.3, 0.2) + 0.01 * p);
        assert!((lorentz::dot(v, v) - 1.0).abs() < 1e-12);
        assert!(lorentz::dot(p, v).abs() < 1e-12);
        assert!(is_unit(v) && is_unit(v * 1.004));
        assert!(!is_unit(v * 1.1) && !is_unit(DVec4::splat(f64::NAN)));
    }
}
