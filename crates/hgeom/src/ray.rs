//! Geodesic rays, and moving tangent directions between the ball and the
//! hyperboloid.

use glam::{DVec3, DVec4};

use crate::lorentz;
use crate::point::Point;

/// A geodesic ray `t -> cosh t X + sinh t V`, parametrised by hyperbolic arc
/// length `t >= 0`.
///
/// Invariants: `origin` is on the hyperboloid (`<X,X> = -1`, future), and
/// `dir` is a unit tangent at it (`<X,V> = 0`, `<V,V> = 1`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// The start point `X` on the hyperboloid.
    pub origin: DVec4,
    /// The unit tangent `V` at `X`.
    pub dir: DVec4,
}

/// A ray-surface intersection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Hyperbolic distance along the ray.
    pub t: f64,
    /// The hit point on the hyperboloid.
    pub point: DVec4,
    /// Unit normal of the surface at the hit, a tangent vector at `point`,
    /// on the surface's outer (positive) side.
    pub normal: DVec4,
}

impl Hit {
    /// The hit point in the ball.
    pub fn ball_point(&self) -> Option<Point> {
        Point::from_hyperboloid(self.point)
    }
}

impl Ray {
    /// A ray from the origin along a (not necessarily unit) ball direction.
    pub fn from_origin(dir: DVec3) -> Ray {
        Ray {
            origin: DVec4::W,
            dir: dir.normalize().extend(0.0),
        }
    }

    /// A ray from an h-point along a ball tangent direction.
    pub fn from_ball(p: &Point, dir: DVec3) -> Ray {
        Ray {
            origin: p.to_hyperboloid(),
            dir: hyperboloid_direction(p, dir),
        }
    }

    /// The point at arc length `t`.
    #[inline]
    pub fn at(&self, t: f64) -> DVec4 {
        lorentz::geodesic_point(self.origin, self.dir, t)
    }

    /// The unit tangent of the ray at arc length `t`.
    #[inline]
    pub fn tangent_at(&self, t: f64) -> DVec4 {
        t.sinh() * self.origin + t.cosh() * self.dir
    }
}

/// Mirror reflection of the unit tangent `d` about the unit normal `n` in the
/// tangent space (both tangent at the same point): `d - 2<d,n> n`.
#[inline]
pub fn reflect(d: DVec4, n: DVec4) -> DVec4 {
    d - 2.0 * lorentz::dot(d, n) * n
}

/// Snell refraction of the unit tangent `d` through a surface with unit normal
/// `n` (either orientation), going from index `n1` to index `n2`.
///
/// Returns `None` on total internal reflection.
pub fn refract(d: DVec4, n: DVec4, n1: f64, n2: f64) -> Option<DVec4> {
    let mut cos_i = -lorentz::dot(d, n);
    let mut normal = n;
    if cos_i < 0.0 {
        cos_i = -cos_i;
        normal = -n;
    }
    let eta = n1 / n2;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(eta * d + (eta * cos_i - cos_t) * normal)
}

/// The unit hyperboloid tangent at `p` for a ball direction `w` at `p`.
///
/// The differential of `p -> ((1+|p|^2), 2p)/(1-|p|^2)` maps `w` to
/// `(2 g w + 4 (p.w) p, 4 p.w) / g^2` with `g = 1 - |p|^2`, of Lorentz length
/// `2|w|/g` (the conformal factor). Dividing by that exact length, rather
/// than by a computed Lorentz norm that cancels far from the origin, keeps
/// the result a unit tangent to rounding.
pub fn hyperboloid_direction(p: &Point, w: DVec3) -> DVec4 {
    let c = p.coords();
    let g = p.gap();
    let pw = c.dot(w);
    let v = (2.0 * g * w + 4.0 * pw * c).extend(4.0 * pw);
    v / (2.0 * g * w.length())
}

/// The unit ball direction at `x`'s ball point for the hyperboloid tangent `v`.
///
/// The differential of `X -> x/(1 + x0)` maps `V` to
/// `v/(1+x0) - x v0/(1+x0)^2`; we normalise it (the model is conformal, so the
/// direction is all that matters).
pub fn ball_direction(x: DVec4, v: DVec4) -> DVec3 {
    let k = 1.0 + x.w;
    let d = v.truncate() * k - x.truncate() * v.w;
    d.normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangent_round_trip() {
        let p = Point::try_new(DVec3::new(0.3, -0.2, 0.5)).unwrap();
        let w = DVec3::new(0.2, 0.9, -0.1).normalize();
        let v = hyperboloid_direction(&p, w);
        let x = p.to_hyperboloid();
        assert!(lorentz::dot(x, v).abs() < 1e-14);
        assert!((lorentz::dot(v, v) - 1.0).abs() < 1e-14);
        assert!((ball_direction(x, v) - w).length() < 1e-14);
    }

    #[test]
    fn ray_stays_on_hyperboloid_at_unit_speed() {
        let p = Point::try_new(DVec3::new(0.3, -0.2, 0.5)).unwrap();
        let r = Ray::from_ball(&p, DVec3::new(1.0, 1.0, 0.0));
        for t in [0.0, 0.5, 3.0] {
            let x = r.at(t);
            assert!((lorentz::dot(x, x) + 1.0).abs() < 1e-12);
            assert!((lorentz::distance(r.origin, x) - t).abs() < 1e-12);
        }
    }

    #[test]
    fn refraction_obeys_snell_and_total_internal_reflection() {
        let n = DVec4::new(0.0, 0.0, 1.0, 0.0);
        let theta = 0.5f64;
        let d = DVec4::new(theta.sin(), 0.0, -theta.cos(), 0.0);
        let t = refract(d, n, 1.0, 1.5).unwrap();
        let sin_t = t.x;
        assert!((sin_t - theta.sin() / 1.5).abs() < 1e-15);
        assert!((lorentz::dot(t, t) - 1.0).abs() < 1e-15);
        // From glass to air beyond the critical angle asin(1/1.5) = 0.7297.
        let steep = 0.8f64;
        let d2 = DVec4::new(steep.sin(), 0.0, -steep.cos(), 0.0);
        assert!(refract(d2, n, 1.5, 1.0).is_none());
        assert!(refract(d2, n, 1.5, 1.0 * 1.5).is_some());
    }

    #[test]
    fn reflection_is_an_involution() {
        let n = DVec4::new(0.0, 0.6, 0.8, 0.0);
        let d = DVec4::new(0.3, -0.4, 0.2, 0.0).normalize();
        let r = reflect(d, n);
        assert!((reflect(r, n) - d).length() < 1e-15);
        assert!((lorentz::dot(r, n) + lorentz::dot(d, n)).abs() < 1e-15);
    }
}
