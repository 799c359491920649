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

/// The mirror direction at `p` for the arriving unit tangent `d`:
/// reflected about the normal `n` ([`hgeom::ray::reflect_at`], which keeps
/// the angle far from the eye), or about `g` where that would leave the
/// result on the wrong side of `g` (a smoothed mesh's shading normal `n`
/// against its true normal `g`; on every other surface they are one).
/// Whitted's mirror rays and the path tracer's specular lobes both bounce
/// here. A degenerate input gives a non-finite direction, which the next
/// trace counts as a failure.
#[inline]
pub fn mirrored(p: DVec4, d: DVec4, n: DVec4, g: DVec4) -> DVec4 {
    let m = reflected(p, d, n);
    if n == g || lorentz::tangent_dot(p, m, g) > 0.0 {
        m
    } else {
        reflected(p, d, g)
    }
}

/// [`hgeom::ray::reflect_at`], non-finite for a degenerate input.
#[inline]
pub fn reflected(p: DVec4, d: DVec4, n: DVec4) -> DVec4 {
    hgeom::ray::reflect_at(p, d, n).unwrap_or(DVec4::splat(f64::NAN))
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

    /// The law of cosines' chord of a sphere of radius `r` from a point on
    /// it at angle `theta` to the inward normal, `2 atanh(tanh r cos θ)`,
    /// without cancellation: `1 - tanh r cos θ = 2 sin²(θ/2) + cos θ (1 -
    /// tanh r)` with `1 - tanh r = 2 / (e^{2r} + 1)`.
    fn chord(r: f64, theta: f64) -> f64 {
        let y = r.tanh() * theta.cos();
        let below = 2.0 * (0.5 * theta).sin().powi(2) + theta.cos() * 2.0 / ((2.0 * r).exp() + 1.0);
        ((1.0 + y) / below).ln()
    }

    /// A thousand bounces inside a mirror sphere of radius 14 about the
    /// origin along the renderer's own path (Whitted's and the path
    /// tracer's): the hit put on the hyperboloid,
    /// [`hgeom::Ray::tangent_arriving_at`], the normal turned to the ray's
    /// side, [`mirrored`]. From a point on the sphere at angles 0 (through
    /// the centre, chords of 28), 0.3, 1 and 1.5 to the inward normal,
    /// along an axis and along a generic direction. Every hit is on the
    /// sphere (distance from the centre 14 to 1e-12; measured 0), the
    /// arriving direction a unit tangent (to `4 eps cosh 14`, 5e-10;
    /// measured 7.6e-11), the angle of incidence the first one (cosine to
    /// 1e-8; measured 1.5e-11 along the axis, 2.1e-9 along the generic
    /// direction), so every chord is the law of cosines'
    /// `2 atanh(tanh 14 cos θ)`: to 1e-9 along the axis (measured 3.4e-10),
    /// 1e-7 along the generic direction (whose rounding turns it by
    /// `eps cosh 14` a bounce; measured 2.4e-8) and 1e-5 through the
    /// centre (where `dL/dθ` grows as `θ` walks off 0; measured 4.2e-8).
    /// The ray never escapes and never stalls. With `reflect` and
    /// `renormalize` ([`lorentz::dot`], `eps cosh² 14 = 4e-5` a bounce)
    /// and the arriving chord formed from `<p, X - p>` (on this sphere
    /// root-finder), the generic ray through the centre left the sphere at
    /// its fourth hit, the axis one lost the chord's direction at its
    /// second, and at angles 0.3 to 1.5 the angle drifted by 2e-3 to 1.4e-2
    /// and the chords by up to 0.19.
    #[test]
    fn a_thousand_renderer_bounces_in_a_mirror_sphere_of_radius_14() {
        let r: f64 = 14.0;
        let s = hgeom::HSphere::new(Point::ORIGIN, r).unwrap();
        let generic = DVec3::new(0.3, -0.4, 0.8).normalize();
        for axis in [DVec3::X, generic] {
            let other = if axis.x.abs() < 0.9 {
                DVec3::X
            } else {
                DVec3::Y
            };
            let across = axis.cross(other).normalize();
            for theta in [0.0f64, 0.3, 1.0, 1.5] {
                let start = Point::at_distance_from_origin(axis, r).unwrap();
                let w = -axis * theta.cos() + across * theta.sin();
                let mut ray = hgeom::Ray::from_ball(&start, w).unwrap();
                let law = chord(r, theta);
                let bound = match (axis == DVec3::X, theta == 0.0) {
                    (true, _) => 1e-9,
                    (false, false) => 1e-7,
                    (false, true) => 1e-5,
                };
                let mut worst = [0.0f64; 4];
                for i in 0..1000 {
                    let Some(hit) = s.intersect(&ray, crate::scene::T_MIN, f64::INFINITY) else {
                        panic!("axis {axis} θ {theta}: escaped at bounce {i}");
                    };
                    // The renderer's bounce (`integrator/whitted.rs`,
                    // `integrator/path.rs` with `bsdf.rs`).
                    let p = hgeom::on_hyperboloid(hit.point);
                    let d = ray.tangent_arriving_at(hit.t, p);
                    assert!(is_unit(d), "axis {axis} θ {theta}: lost at bounce {i}");
                    let entering = lorentz::dot(d, hit.normal) < 0.0;
                    let n = if entering { hit.normal } else { -hit.normal };
                    let dir = mirrored(p, d, n, n);
                    let cos = lorentz::tangent_dot(p, d, hit.normal)
                        / lorentz::tangent_dot(p, hit.normal, hit.normal).sqrt();
                    worst[0] = worst[0].max((hit.t - law).abs());
                    worst[1] = worst[1].max((p.truncate().length().asinh() - r).abs());
                    worst[2] = worst[2].max((cos - theta.cos()).abs());
                    worst[3] = worst[3].max((lorentz::tangent_dot(p, d, d) - 1.0).abs());
                    assert!(!entering, "axis {axis} θ {theta}: outside at bounce {i}");
                    ray = hgeom::Ray { origin: p, dir };
                }
                let [t, off, cos, unit] = worst;
                eprintln!(
                    "axis {axis} θ {theta}: chord {law}, worst |t - L| {t:e}, \
                     |d - 14| {off:e}, |cos - cos θ| {cos:e}, |<d,d> - 1| {unit:e}"
                );
                assert!(t < bound, "axis {axis} θ {theta}: chord off by {t:e}");
                assert!(
                    off < 1e-12,
                    "axis {axis} θ {theta}: off the sphere by {off:e}"
                );
                assert!(cos < 1e-8, "axis {axis} θ {theta}: angle off by {cos:e}");
                assert!(unit < 5e-10, "axis {axis} θ {theta}: not unit by {unit:e}");
            }
        }
    }
}
