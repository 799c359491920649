//! Keeping tangent vectors on the hyperboloid honest: the checks and the
//! renormalisation every integrator applies to the directions it makes.
//! (Hit points and arriving tangents are kept honest by hgeom itself:
//! `hgeom::on_hyperboloid`, `Ray::tangent_arriving_at`.)

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

    /// A chord of a sphere of radius 6 about the eye, as in a closed
    /// mirror: from a point 6 out, back past the eye to the far side. The
    /// arriving direction is a unit tangent at the hit, pointing along the
    /// geodesic away from the origin (`<d, X> = -sinh t`), to the rounding
    /// of the points; `tests/closed_mirrors.rs` shows what it mends.
    #[test]
    fn the_arriving_direction_of_a_long_segment_is_the_chords() {
        let t = 12.0;
        let u = DVec3::new(0.3, -0.2, 0.9).normalize();
        let near =
            hgeom::Ray::from_origin_unchecked((-u + DVec3::new(0.0005, 0.001, 0.0)).normalize());
        let out = Point::at_distance_from_origin(u, 6.0).unwrap();
        let m = hgeom::Isometry::transvection_from_origin(out).to_lorentz();
        let origin = hgeom::on_hyperboloid(m * near.origin);
        let ray = hgeom::Ray {
            origin,
            dir: renormalize(origin, m * near.dir),
        };
        let p = hgeom::on_hyperboloid(ray.at(t));
        let d = ray.tangent_arriving_at(t, p);
        assert!((lorentz::dot(d, d) - 1.0).abs() < 1e-9);
        assert!(lorentz::dot(d, p).abs() < 1e-9 * p.w);
        let away = lorentz::dot(d, ray.origin) / -t.sinh();
        assert!((away - 1.0).abs() < 1e-6, "{away}");
    }
}
