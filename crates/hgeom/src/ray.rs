//! Geodesic rays, and moving tangent directions between the ball and the
//! hyperboloid.

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::lorentz;
use crate::point::Point;

/// A geodesic ray `t -> cosh t X + sinh t V`, parametrised by hyperbolic arc
/// length `t >= 0`.
///
/// Invariants: `origin` is on the hyperboloid (`<X,X> = -1`, future), and
/// `dir` is a unit tangent at it (`<X,V> = 0`, `<V,V> = 1`), both to
/// rounding (about `eps |X|^2`). The fields are public for speed; the
/// constructors below establish the invariants, and code that fills the
/// fields itself is responsible for them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// The start point `X` on the hyperboloid.
    pub origin: DVec4,
    /// The unit tangent `V` at `X`.
    pub dir: DVec4,
}

/// A ray-surface intersection.
///
/// Invariants (for hits returned by hgeom): `t` finite and inside the
/// caller's `(t_min, t_max)`; `point` is the ray's point at `t`; `normal` is
/// a unit tangent at `point`, all to rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Hyperbolic distance along the ray.
    pub t: f64,
    /// The hit point on the hyperboloid.
    pub point: DVec4,
    /// Unit normal of the surface at the hit, a tangent vector at `point`,
    /// on the surface's outer (positive) side.
    pub normal: DVec4,
    /// The unit normal to shade with, a tangent vector at `point` on the
    /// same side as `normal`: `normal` itself except on smoothed meshes,
    /// where it is interpolated from vertex normals
    /// ([`TriangleMesh::smoothed`](crate::TriangleMesh::smoothed)). Only
    /// lighting uses it; ray offsets and inside/outside use `normal`.
    pub shading: DVec4,
    /// Which part of a composite surface was hit: for a
    /// [`RegularHoneycomb`](crate::RegularHoneycomb) the kind of part
    /// (edge, face, vertex) and the class of its cell, read with
    /// [`decode_honeycomb_part`](crate::decode_honeycomb_part); for a
    /// [`TriangleMesh`](crate::TriangleMesh) the index of the triangle
    /// (into its `triangles()`, saturating at `u32::MAX`); 0 for every
    /// other shape.
    pub part: u32,
}

impl Hit {
    /// The hit of a surface with one normal (its shading normal too) and no
    /// parts.
    #[inline]
    pub(crate) fn on_surface(t: f64, point: DVec4, normal: DVec4) -> Hit {
        Hit {
            t,
            point,
            normal,
            shading: normal,
            part: 0,
        }
    }

    /// The hit point in the ball.
    ///
    /// # Accuracy
    ///
    /// [`Point::from_hyperboloid`] of the hit point: as accurate as the hit
    /// itself (2 ulps on top of the hit point's own rounding); `None` only
    /// if the hit is beyond what the ball can hold.
    pub fn ball_point(&self) -> Option<Point> {
        Point::from_hyperboloid(self.point)
    }

    /// The unit normal at the hit as a Euclidean direction in the ball
    /// (the model is conformal, so it is also the hyperbolic normal's
    /// direction there): [`ball_direction`] of `normal` at `point`.
    ///
    /// # Accuracy
    ///
    /// As [`ball_direction`]: about `eps |X|^2` in direction (1e-14 for
    /// hits within ~2 of the origin).
    ///
    /// ```
    /// use hgeom::{HSphere, Point, Ray};
    /// // A ray from the origin along +z hits the sphere about (0,0,0.5) head on:
    /// // the outward normal there points back at the eye.
    /// let s = HSphere::new(Point::new(0.0, 0.0, 0.5)?, 0.2)?;
    /// let hit = s.intersect(&Ray::from_origin(glam::DVec3::Z)?, 0.0, f64::INFINITY).unwrap();
    /// assert!((hit.ball_normal() - -glam::DVec3::Z).length() < 1e-14);
    /// # Ok::<(), hgeom::GeomError>(())
    /// ```
    pub fn ball_normal(&self) -> DVec3 {
        ball_direction(self.point, self.normal)
    }
}

impl Ray {
    /// A ray from the origin along a (not necessarily unit) ball direction.
    ///
    /// The hot-path form of [`Ray::from_origin`]: nothing is checked.
    /// Precondition: `dir` finite and non-zero (a zero direction gives a NaN
    /// ray).
    ///
    /// # Accuracy
    ///
    /// The origin is exactly `(0,0,0,1)`; the direction is `dir/|dir|`, a
    /// unit vector to 2 ulps (so the invariants hold to a few ulps).
    pub fn from_origin_unchecked(dir: DVec3) -> Ray {
        Ray {
            origin: DVec4::W,
            dir: dir.normalize().extend(0.0),
        }
    }

    /// A ray from the origin along a ball direction, checked.
    ///
    /// Errors: [`GeomError::BadDirection`] for a zero or non-finite `dir`.
    ///
    /// # Accuracy
    ///
    /// As [`Ray::from_origin_unchecked`], and identical to it on valid input
    /// (`tests/constructors.rs`).
    pub fn from_origin(dir: DVec3) -> Result<Ray, GeomError> {
        let len = dir.length();
        if !(len.is_finite() && len > 0.0) {
            return Err(GeomError::BadDirection);
        }
        Ok(Ray::from_origin_unchecked(dir))
    }

    /// A ray from an h-point along a ball tangent direction.
    ///
    /// The hot-path form of [`Ray::from_ball`]: nothing is checked.
    /// Preconditions: `dir` finite and non-zero, `p` representable
    /// ([`Point::is_representable`]).
    ///
    /// # Accuracy
    ///
    /// The origin is [`Point::to_hyperboloid`] (2 ulps per component); the
    /// direction is [`hyperboloid_direction`], normalised by the exact
    /// conformal factor, so `<V,V> = 1` to about `eps |X|^2`
    /// (`ray_direction_is_a_unit_tangent` in `tests/properties.rs` bounds
    /// the relative error of `V` by 1e-12 out to depth 12).
    pub fn from_ball_unchecked(p: &Point, dir: DVec3) -> Ray {
        Ray {
            origin: p.to_hyperboloid(),
            dir: hyperboloid_direction(p, dir),
        }
    }

    /// A ray from an h-point along a ball tangent direction, checked.
    ///
    /// Errors: [`GeomError::BadDirection`] for a zero or non-finite `dir`,
    /// [`GeomError::NotInBall`] for a point that fails
    /// [`Point::is_representable`].
    ///
    /// # Accuracy
    ///
    /// As [`Ray::from_ball_unchecked`], and identical to it on valid input
    /// (`tests/constructors.rs`).
    pub fn from_ball(p: &Point, dir: DVec3) -> Result<Ray, GeomError> {
        let len = dir.length();
        if !(len.is_finite() && len > 0.0) {
            return Err(GeomError::BadDirection);
        }
        if !p.is_representable() {
            return Err(GeomError::NotInBall {
                norm: p.coords().length(),
            });
        }
        Ok(Ray::from_ball_unchecked(p, dir))
    }

    /// The point at arc length `t`.
    ///
    /// # Accuracy
    ///
    /// `cosh t X + sinh t V`: each component within a few ulps of
    /// `cosh t |X| + sinh t |V|`, i.e. absolute error about
    /// `eps e^t |X|`. The sum cancels down to `|X(t)|`, so the relative
    /// error of the point grows with how far the ray runs back towards the
    /// origin; for rays from near the origin it is a few ulps
    /// (`ray_stays_on_hyperboloid_at_unit_speed` in this module).
    #[inline]
    pub fn at(&self, t: f64) -> DVec4 {
        lorentz::geodesic_point(self.origin, self.dir, t)
    }

    /// The unit tangent of the ray at arc length `t`.
    ///
    /// # Accuracy
    ///
    /// `sinh t X + cosh t V` carries the rounding of `<X,V> = 0` and
    /// `<X,X> = -1` multiplied by `sinh 2t` and `sinh² t`: a ray 12 long
    /// from a point 6 from the origin would arrive 3-8 % off unit, and off
    /// in direction by as much; inside a closed mirror the defect would
    /// compound bounce after bounce. Past [`CHORD_FROM`] the tangent is
    /// instead the chord's (the direction at the point away from the
    /// origin, [`Ray::tangent_arriving_at`]), unit to a few `eps` and
    /// pointing along the geodesic to 1e-13 at any length
    /// (`long_segments_keep_unit_tangents` in this module).
    #[inline]
    pub fn tangent_at(&self, t: f64) -> DVec4 {
        if t > CHORD_FROM {
            self.tangent_arriving_at(t, on_hyperboloid(self.at(t)))
        } else {
            t.sinh() * self.origin + t.cosh() * self.dir
        }
    }

    /// The unit tangent with which the ray arrives at `p`, its point at arc
    /// length `t` as a surface computed it (on the hyperboloid, e.g. by
    /// [`on_hyperboloid`]): past [`CHORD_FROM`] the direction at `p` away
    /// from the ray's origin, else [`Ray::tangent_at`]'s closed form. The
    /// tracers use it with a hit's own point, so the bounce starts exactly
    /// where the hit is.
    ///
    /// # Accuracy
    ///
    /// Past [`CHORD_FROM`] the direction away from the origin `X` is
    /// `cosh t p - X` (as `<p,X> = -cosh t`), made a unit tangent by
    /// [`lorentz::unit_tangent_at`] from its space part alone: no Lorentz
    /// product of the far points is formed, so it is unit to a few `eps`
    /// and points along the chord to the rounding of `p` across `X`
    /// (about `eps cosh d` at a point `d` from the origin) plus the error
    /// of `t` itself, which tilts it by as many radians. Where it took
    /// `<p, X - p>` and divided by [`lorentz::norm`] its direction and
    /// length were `eps cosh^2 d` off (3e-5 at 14): a ray in a mirror
    /// sphere of radius 14 then left it within 150 bounces
    /// (`a_thousand_renderer_bounces_in_a_mirror_sphere_of_radius_14` in
    /// hrender's `tangent.rs`).
    #[inline]
    pub fn tangent_arriving_at(&self, t: f64, p: DVec4) -> DVec4 {
        if t > CHORD_FROM
            && let Some(away) = lorentz::unit_tangent_at(p, t.cosh() * p - self.origin)
        {
            return away;
        }
        t.sinh() * self.origin + t.cosh() * self.dir
    }
}

/// Arc length past which [`Ray::tangent_at`] takes the chord: there
/// `eps |X|^2 / sinh t` (the chord's error) is below `eps |X|^2 e^{2t}`
/// (the closed form's).
pub const CHORD_FROM: f64 = 0.5;

/// The point `p` put back on the hyperboloid `<p,p> = -1`, `w > 0`, by
/// recomputing its time coordinate from its space part. A hit point is
/// `cosh t X + sinh t V`, off the hyperboloid by the rounding of the ray's
/// origin and direction times `e^{2t}`; a ray started from it carries that
/// off to its own hit, times `e^{2t}` again, so inside a closed mirror the
/// defect compounds bounce after bounce (`e^{2·chord}` a bounce: inside a
/// mirror sphere of radius 2 it lost the unit tangents at the fifth).
/// Started from the projected point, every bounce begins with the rounding
/// of one step only. `w` from `1 + |x|^2` has a relative error of an ulp,
/// where `-<p,p>` would cancel for a far point.
#[inline]
pub fn on_hyperboloid(p: DVec4) -> DVec4 {
    let x = p.truncate();
    x.extend((1.0 + x.length_squared()).sqrt())
}

/// Mirror reflection of the unit tangent `d` about the unit normal `n` in the
/// tangent space (both tangent at the same point): `d - 2<d,n> n`.
///
/// # Accuracy
///
/// A few ulps of `|d| + 2|<d,n>| |n|` per component; for unit inputs the
/// result is unit to the inputs' own rounding (`reflection_is_an_involution`
/// in this module: an involution to 1e-15).
#[inline]
pub fn reflect(d: DVec4, n: DVec4) -> DVec4 {
    d - 2.0 * lorentz::dot(d, n) * n
}

/// Mirror reflection of the tangent `d` about the normal `n` in the tangent
/// space at the point `p` of the hyperboloid, made a unit tangent:
/// `d - 2 (<d,n> / <n,n>) n`, its products by [`lorentz::tangent_dot`] and
/// its length by [`lorentz::unit_tangent_at`]. The tracers' one mirror
/// bounce (`None` for a zero or non-finite result).
///
/// # Accuracy
///
/// Exact reflection (the normal's length is divided out, not assumed):
/// only the space parts are read, so the products carry no `eps cosh^2 d`
/// cancellation at a point `d` from the origin; the result is unit to a
/// few `eps` and the angle to the normal is kept to the rounding of the
/// inputs' space parts across `p` (about `eps cosh d`: 1000 bounces in a
/// mirror sphere of radius 14 keep the angle of incidence to 1e-8,
/// `a_thousand_renderer_bounces_in_a_mirror_sphere_of_radius_14` in
/// hrender's `tangent.rs`). [`reflect`] with [`lorentz::dot`] turns it by
/// `eps cosh^2 d` (4e-5 at 14) a bounce.
#[inline]
pub fn reflect_at(p: DVec4, d: DVec4, n: DVec4) -> Option<DVec4> {
    let k = 2.0 * lorentz::tangent_dot(p, d, n) / lorentz::tangent_dot(p, n, n);
    lorentz::unit_tangent_at(p, d - k * n)
}

/// Snell refraction of the unit tangent `d` through a surface with unit normal
/// `n` (either orientation), going from index `n1` to index `n2`.
///
/// Returns `None` on total internal reflection.
///
/// # Accuracy
///
/// The textbook vector form of Snell's law, exact in the tangent space (the
/// Lorentz form is positive definite there): for unit inputs the result is
/// unit and obeys `sin t = (n1/n2) sin i` to a few ulps
/// (`refraction_obeys_snell_and_total_internal_reflection` in this module,
/// 1e-15). Total internal reflection is decided on `sin^2 t > 1` with
/// rounding of a few ulps, so rays within ~1e-16 of the critical angle may
/// go either way.
pub fn refract(d: DVec4, n: DVec4, n1: f64, n2: f64) -> Option<DVec4> {
    let mut cos_i = -lorentz::dot(d, n);
    let mut normal = n;
    if cos_i < 0.0 {
        cos_i = -cos_i;
        normal = -n;
    }
    let eta = n1 / n2;
    // Not a clamp of user input: for unit d and n, cos_i <= 1 exactly, so
    // 1 - cos_i^2 >= 0; the guard only stops rounding (cos_i = 1 + 1 ulp
    // at normal incidence) from producing sin^2 i = -2e-16.
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
///
/// # Accuracy
///
/// Each component within a few ulps of the exact push-forward of `w` at the
/// stored point: no cancellation (the relative error of `V` is below 1e-12
/// out to depth 12, `ray_direction_is_a_unit_tangent` in
/// `tests/properties.rs`). Precondition: `w` non-zero (else NaN).
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
///
/// # Accuracy
///
/// `v (1 + x0) - x v0` cancels when `V` is nearly radial far out: the
/// absolute error of the unnormalised vector is about `eps |X| |V|`, so the
/// direction is accurate to about `eps |X|^2` (1e-14 for points within ~2
/// of the origin: `tangent_round_trip` in this module; angles are
/// preserved to `1e-12 + 100 eps |X|^2` in `isometries_preserve_angles`).
/// Precondition: `V` tangent at `X` and non-zero (else NaN).
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
        let p = Point::from_coords(DVec3::new(0.3, -0.2, 0.5)).unwrap();
        let w = DVec3::new(0.2, 0.9, -0.1).normalize();
        let v = hyperboloid_direction(&p, w);
        let x = p.to_hyperboloid();
        assert!(lorentz::dot(x, v).abs() < 1e-14);
        assert!((lorentz::dot(v, v) - 1.0).abs() < 1e-14);
        assert!((ball_direction(x, v) - w).length() < 1e-14);
    }

    #[test]
    fn ray_stays_on_hyperboloid_at_unit_speed() {
        let p = Point::from_coords(DVec3::new(0.3, -0.2, 0.5)).unwrap();
        let r = Ray::from_ball_unchecked(&p, DVec3::new(1.0, 1.0, 0.0));
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

    /// Long segments out to the f64 limit: a ray from the origin along `u`
    /// out to 36. Its tangent at `t` is `cosh t (u, 0) + sinh t (0, 1)`;
    /// at any length the one given points along `u` to 1e-13 and has
    /// `w / |x| = tanh t` to 1e-13, relative (its Lorentz length cannot be
    /// evaluated in f64 that far out: its terms are `e^{2t}`).
    #[test]
    fn long_segments_keep_unit_tangents() {
        let u = DVec3::new(0.3, -0.2, 0.9).normalize();
        let ray = Ray::from_origin_unchecked(u);
        for t in [0.25, 0.5, 0.75, 1.0, 6.0, 12.0, 18.0, 24.0, 30.0, 36.0] {
            let d = ray.tangent_at(t);
            let x = d.truncate();
            assert!((x.normalize() - u).length() < 1e-13, "t {t}: {x}");
            let ratio = d.w / x.length() / t.tanh();
            assert!((ratio - 1.0).abs() < 1e-13, "t {t}: {ratio}");
        }
    }
}
