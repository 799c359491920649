//! h-spheres: the points at hyperbolic distance `r` from a centre.

use glam::{DVec3, DVec4};

use crate::accurate::one_minus_norm_sq;
use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::point::Point;
use crate::ray::{Hit, Ray};
use crate::roots::{ExpRoots, exp_roots_lazy};

/// An h-sphere with hyperbolic centre and radius.
///
/// Invariants: `radius` is positive with `cosh r` finite; the centre is
/// representable ([`Point::is_representable`]); the cached hyperboloid
/// centre and `cosh r` are computed from them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HSphere {
    center: Point,
    radius: f64,
    center_h: DVec4,
    cosh_r: f64,
    sinh_r: f64,
}

impl HSphere {
    /// The sphere of hyperbolic `radius` about `center`.
    ///
    /// Errors: [`GeomError::BadRadius`] unless `radius > 0` with `cosh r`
    /// finite (radius below ~710), [`GeomError::NotInBall`] for a centre
    /// that fails [`Point::is_representable`].
    ///
    /// # Accuracy
    ///
    /// The centre and radius are stored exactly; the cached hyperboloid
    /// centre is [`Point::to_hyperboloid`] (2 ulps per component) and
    /// `cosh r` is correctly rounded to an ulp or two.
    pub fn new(center: Point, radius: f64) -> Result<HSphere, GeomError> {
        // cosh r must be finite too: radii past ~710 overflow it.
        if !(radius > 0.0 && radius.cosh().is_finite()) {
            return Err(GeomError::BadRadius(radius));
        }
        if !center.is_representable() {
            return Err(GeomError::NotInBall {
                norm: center.coords().length(),
            });
        }
        Ok(HSphere::new_unchecked(center, radius))
    }

    /// The sphere of hyperbolic `radius` about `center`, with nothing
    /// checked: the `_unchecked` form of [`HSphere::new`], for hot paths
    /// (rebuilding spheres per frame or per ray) whose inputs are valid by
    /// construction.
    ///
    /// # Preconditions
    ///
    /// `radius > 0` with `cosh r` finite, and `center` representable
    /// ([`Point::is_representable`]). A violated precondition gives
    /// meaningless hits (possibly NaN), never undefined behaviour.
    ///
    /// # Accuracy
    ///
    /// As [`HSphere::new`], and bit-identical to it on valid input
    /// (`tests/constructors.rs`).
    #[inline]
    pub fn new_unchecked(center: Point, radius: f64) -> HSphere {
        HSphere {
            center,
            radius,
            center_h: center.to_hyperboloid(),
            cosh_r: radius.cosh(),
            sinh_r: radius.sinh(),
        }
    }

    /// Hyperbolic centre.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored centre.
    pub fn center(&self) -> Point {
        self.center
    }

    /// Hyperbolic radius.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The Euclidean sphere in the ball: centre `c (1-T^2)/(1-a^2 T^2)` and
    /// radius `T (1-a^2)/(1-a^2 T^2)`, with `T = tanh(r/2)` and `a = |c|`.
    ///
    /// Evaluated as `1 - a^2 T^2 = (1 - T^2) + T^2 (1 - a^2)`, a sum of
    /// non-negative terms, with the accurate gap for `1 - a^2`.
    ///
    /// # Accuracy
    ///
    /// No cancellation anywhere, so the centre's components and the radius
    /// are within a few ulps (relative) of the formula for the stored centre
    /// and radius, for every radius with finite `cosh r` and every
    /// representable centre (`euclidean_sphere_matches_the_reference` in
    /// `tests/derivations.rs` bounds the relative error by 1e-14, measured
    /// 7e-16 for centres up to 30 away and radii up to 20;
    /// `euclidean_sphere_is_the_h_sphere` and `sphere_of_radius_20` in
    /// `tests/properties.rs` check the points of the Euclidean sphere lie at
    /// hyperbolic distance `r` from the centre).
    pub fn euclidean(&self) -> (DVec3, f64) {
        let t = (0.5 * self.radius).tanh();
        let one_minus_t2 = 1.0 / (0.5 * self.radius).cosh().powi(2);
        let gap = self.center.gap();
        let denom = one_minus_t2 + t * t * gap;
        (
            self.center.coords() * (one_minus_t2 / denom),
            t * gap / denom,
        )
    }

    /// The image under an isometry (spheres map to spheres of the same radius).
    ///
    /// # Accuracy
    ///
    /// The new centre is [`Isometry::apply`] of the old one (error about
    /// one coordinate ulp there, `~2 eps / gap` in hyperbolic distance);
    /// the radius is unchanged. The image of a centre pushed past distance
    /// ~37 is not representable and the sphere is then meaningless; callers
    /// that move spheres that far check the centre with
    /// [`Isometry::checked_apply`].
    pub fn transformed(&self, iso: &Isometry) -> HSphere {
        let center = iso.apply(&self.center);
        HSphere {
            center,
            radius: self.radius,
            center_h: center.to_hyperboloid(),
            cosh_r: self.cosh_r,
            sinh_r: self.sinh_r,
        }
    }

    /// True if the h-point `p` lies strictly inside: [`Self::contains_hyperboloid`]
    /// of its hyperboloid image.
    ///
    /// # Accuracy
    ///
    /// As [`Self::contains_hyperboloid`], with `X` within 2 ulps of the exact image
    /// ([`Point::to_hyperboloid`]).
    pub fn contains(&self, p: &Point) -> bool {
        self.contains_hyperboloid(p.to_hyperboloid())
    }

    /// True if the hyperboloid point `x` is strictly inside.
    ///
    /// # Accuracy
    ///
    /// Decides `-<X,C> < cosh r` with `<X,C>` rounded at about
    /// `eps |X| |C|`: exact away from the surface, and a point within that
    /// band of the sphere may go either way.
    pub fn contains_hyperboloid(&self, x: DVec4) -> bool {
        -lorentz::dot(x, self.center_h) < self.cosh_r
    }

    /// The first intersection with `t` in `(t_min, t_max)`.
    ///
    /// Along the ray `-<X(t),C> = A cosh t + B sinh t` with `A = -<X,C>`,
    /// `B = -<V,C>`; setting it to `cosh r` and `u = e^t` gives
    /// `(A+B) u^2 - 2 cosh(r) u + (A-B) = 0`, solved in the cancellation-free
    /// form. `A ± B > 0` always (`X ± V` are future null vectors), so the
    /// roots are positive and `t = ln u` is defined. A tangent ray (zero
    /// discriminant) touches at one point; no input gives NaN.
    ///
    /// # Accuracy
    ///
    /// Against a 320-bit reference, rays from the origin to spheres with
    /// centres up to 12 away: `t` within 2e-10 (measured 1.6e-11; the
    /// `ray-sphere` family of `tests/reference.rs`). In general the root
    /// moves by the rounding of `<X,C>`, `<V,C>` (about
    /// `eps |X| |C|`) over the slope `sinh r` of `-<X(t),C>` at the surface
    /// (`sphere_hits_lie_on_the_sphere` in `tests/properties.rs`). A tangent
    /// ray is a double root: there an error `e` in the coefficients moves `t`
    /// by about `sqrt(e)` (`tangent_rays_to_a_sphere`). A ray heading at
    /// (or away from) the centre from far off has `A -+ B` as small as
    /// `e^-d` (`d` its distance from the centre), which the rounding of
    /// `A` and `B` would swamp; that one is computed as
    /// `(A^2 - B^2) / (A +- B)` from the Gram determinant of `X`, `V`, `C`
    /// (`lazy_roots`): chords of a sphere of radius 14 from a point on it,
    /// at every angle to the inward normal, are the law of cosines' chord
    /// to 1e-9 (measured 3.2e-10 at 1e-3 from the normal; through the
    /// centre exactly 28, where it was 28.0001), and along an axis out to
    /// radius 30 and segments of 66 (`tests/stable_rays.rs`). For a generic direction the ray's own
    /// rounding leaves its direction known to `eps cosh d`, so an angle
    /// `θ ~ e^-r` to the centre, where the chord's slope `dL/dθ` is
    /// `~e^r / 2`, is known only to `eps e^{2r}` (5e-6 at radius 14), and
    /// a chord through the centre of a sphere past radius ~17 not at all.
    /// The hit point is `cosh t X + sinh t V`, or where that cancels (a
    /// long chord back towards the origin) the point of the sphere on the
    /// geodesic from the centre through it (`onto_surface`): on the sphere
    /// to rounding (1,000 bounces inside a mirror sphere of radius 14 stay
    /// on it, `tests/stable_rays.rs`). The normal is a unit
    /// tangent to rounding (`|<N,N> - 1| < 1e-13 + 100 eps |N|^2` in
    /// `sphere_hits_lie_on_the_sphere`).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let t = self.lazy_roots(ray)?.first_in_range(t_min, t_max)?;
        let point = self.onto_surface(ray, t);
        Some(Hit::on_surface(t, point, self.normal_at(point)))
    }

    /// The ray's point at `t`, a root, put on the sphere where that is the
    /// more accurate: `cosh t X + sinh t V` rounds at `eps e^t |X|` per
    /// component, which a chord back towards the origin cancels down to the
    /// point's own size (a chord of 28 through the centre of a sphere of
    /// radius 14 about the origin, from a point on it, ended 7e-5 off the
    /// sphere). The point at distance `r` from the centre along the
    /// geodesic through that one, `cosh r C + sinh r T` with `T` the unit
    /// tangent at `C` towards it, rounds at about `eps |C|^2` relative
    /// instead ([`lorentz::unit_tangent_towards`]); it is taken when
    /// `e^t X_w > C_w^2 x_w`. It moves the point only across the sphere, by
    /// that point's rounding; along the sphere the point stays where the
    /// ray's rounding leaves it. Where `e^t X_w` is below 16 the ray's
    /// point is already within 16 ulps and is kept: most hits of most
    /// scenes, which then pay for no projection (instruction-count guard).
    #[inline]
    fn onto_surface(&self, ray: &Ray, t: f64) -> DVec4 {
        let x = ray.at(t);
        let c = self.center_h;
        let grown = t.exp() * ray.origin.w;
        if grown > 16.0
            && grown > c.w * c.w * x.w
            && let Some(towards) = lorentz::unit_tangent_towards(c, x)
        {
            return self.cosh_r * c + self.sinh_r * towards;
        }
        x
    }

    /// True if the ray meets the sphere in `(t_min, t_max)`: exactly
    /// `intersect(..).is_some()`, without the hit point and normal (the
    /// shadow-ray test).
    #[inline]
    pub fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.lazy_roots(ray)
            .and_then(|r| r.first_in_range(t_min, t_max))
            .is_some()
    }

    /// Both arc lengths (possibly negative or infinite, never NaN) at which
    /// the ray's geodesic meets the sphere, nearest first; `None` if it misses.
    ///
    /// # Accuracy
    ///
    /// As [`HSphere::intersect`], for both roots.
    pub fn roots(&self, ray: &Ray) -> Option<(f64, f64)> {
        self.lazy_roots(ray).map(|r| (r.near(), r.far()))
    }

    /// [`HSphere::roots`] before the logarithms.
    #[inline]
    fn lazy_roots(&self, ray: &Ray) -> Option<ExpRoots> {
        if ray.origin == DVec4::W {
            // A ray from the origin along the unit direction `û = u/|u|`
            // (`V = (û, 0)`), `C = (2c, 2 - g)/g`: `a -+ b = c0 -+ û.c
            // = |û -+ c|^2 / g`, sums of squares over the exact gap.
            // `c0 - u.c` itself cancels for a far sphere straight ahead
            // (error `eps cosh D`: a radius-2 sphere 16 away came out 3e-4
            // too small, 18 % at 18). With `δ = 1 - |u|^2` (compensated, a
            // few ulps), `|û -+ c|^2 = |u -+ c|^2 + δ (1 -+ u.c)` and
            // `1 -+ u.c = (δ + |u -+ c|^2 + g) / 2`: the rounding of `|u| = 1`
            // would otherwise cost `eps e^D` relative (docs/geometry.md 16.5).
            let (u, c, g) = (ray.dir.truncate(), self.center.coords(), self.center.gap());
            let delta = one_minus_norm_sq(u);
            let unit = |sq: f64| sq + delta * 0.5 * (delta + sq + g);
            return exp_roots_lazy(
                unit((u - c).length_squared()) / g,
                self.cosh_r,
                unit((u + c).length_squared()) / g,
            );
        }
        let a = -lorentz::dot(ray.origin, self.center_h);
        let b = -lorentz::dot(ray.dir, self.center_h);
        // `a - |b|` carries an absolute error of about `eps a`; past
        // `1 / a` that is the smaller error (the one below is
        // `eps a sinh d sin θ`, and `a - |b| ~ sinh d sin^2 θ / 2`).
        // And as `a - |b| >= e^-d` for `a = cosh d`, the difference is good
        // to `eps e^{2d}` relative: 14 ulps within `a <= 2`, where the rays
        // of most scenes start, which then pay for no complement
        // (instruction-count guard, `render-mirrors`).
        if a <= 2.0 || !((a - b.abs()) * a < 1.0) {
            return exp_roots_lazy(a + b, self.cosh_r, a - b);
        }
        let (small, big) = self.cancelling_pair(ray, a, b);
        if b < 0.0 {
            exp_roots_lazy(small, self.cosh_r, big)
        } else {
            exp_roots_lazy(big, self.cosh_r, small)
        }
    }

    /// `(a - |b|, a + |b|)` for `a = -<X,C>`, `b = -<V,C>`, where
    /// `a - |b| < 1 / a`.
    ///
    /// With `d` the distance from `X` to the centre and `θ` the angle
    /// between `V` and the geodesic to it, `a = cosh d` and
    /// `b = -sinh d cos θ`: `a - |b|` is `e^-d` for a ray straight at (or
    /// away from) the centre, and the plain difference loses it to the
    /// rounding of `a` and `b` (about `eps |X| |V|`, and the rounding of
    /// `X` and `V` themselves is as large): a ray starting on a sphere of
    /// radius 14 about the origin, through the centre, had `a + b` out by
    /// 1e-4 relative and the chord 28 out by 1e-4; at radius 20 it found
    /// no far root at all. Instead `a - |b| = (a^2 - b^2) / (a + |b|)` with
    /// `a^2 - b^2 = 1 + sinh^2 d sin^2 θ` and
    /// `sinh^2 d sin^2 θ = <N,N>`, `N` the Lorentz-orthogonal complement of
    /// `C`, `X`, `V` (`-<N,N>` is their Gram determinant
    /// `1 + b^2 - a^2` for `<X,X> = <C,C> = -1`, `<X,V> = 0`,
    /// `<V,V> = 1`): a sum of squares of 3x3 minors, which for a centre at
    /// the origin are the components of `x × v` (`|x| |v| sin θ`, no
    /// cancellation beyond the direction's own rounding), and `a + |b|`
    /// has no cancellation.
    #[inline]
    fn cancelling_pair(&self, ray: &Ray, a: f64, b: f64) -> (f64, f64) {
        let n = lorentz::orthogonal_complement(self.center_h, ray.origin, ray.dir);
        // Not a clamp of input: `N` is spacelike (or zero) in exact
        // arithmetic; the guard only stops rounding of a zero `N` (a ray
        // straight at the centre) from going negative.
        let across = lorentz::dot(n, n).max(0.0);
        let big = a + b.abs();
        ((1.0 + across) / big, big)
    }

    /// Outward unit normal at a point of the sphere (a tangent vector there).
    ///
    /// # Accuracy
    ///
    /// [`lorentz::unit_tangent_towards`] from the point to the centre, negated:
    /// a unit tangent to about `eps |X|^2`, pointing along the geodesic from
    /// the centre to within the rounding of `X` (`sphere_hits_lie_on_the_sphere`
    /// checks `<N,C> = -sinh r`).
    pub fn normal_at(&self, x: DVec4) -> DVec4 {
        match lorentz::unit_tangent_towards(x, self.center_h) {
            Some(towards_center) => -towards_center,
            // Only reachable for a degenerate sphere; any unit tangent will do.
            None => DVec4::X,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distance::distance;

    #[test]
    fn euclidean_form_matches_spec_formula() {
        let c = Point::from_coords(DVec3::new(0.3, 0.0, 0.0)).unwrap();
        let s = HSphere::new(c, 0.5).unwrap();
        let (ec, er) = s.euclidean();
        // The two Euclidean extreme points on the diameter are at hyperbolic
        // distance r from the centre.
        for sign in [-1.0, 1.0] {
            let q = Point::from_coords(ec + DVec3::X * er * sign).unwrap();
            assert!((distance(&q, &c) - 0.5).abs() < 1e-14);
        }
    }

    #[test]
    fn blocks_agrees_with_intersect() {
        let s = HSphere::new(Point::new(0.1, -0.2, 0.5).unwrap(), 0.3).unwrap();
        let start = Point::new(0.0, 0.3, -0.2).unwrap();
        for i in 0..500 {
            let a = f64::from(i) * 2.399_963_229_728_653;
            let dir = DVec3::new(0.4 * a.cos(), 0.4 * a.sin() - 0.3, 1.0);
            for ray in [
                Ray::from_origin_unchecked(dir),
                Ray::from_ball_unchecked(&start, dir),
            ] {
                for (lo, hi) in [(0.0, f64::INFINITY), (1e-9, 0.8), (0.9, 1.2)] {
                    assert_eq!(s.blocks(&ray, lo, hi), s.intersect(&ray, lo, hi).is_some());
                }
            }
        }
    }

    #[test]
    fn ray_from_centre_hits_at_radius() {
        let c = Point::from_coords(DVec3::new(0.1, 0.2, -0.1)).unwrap();
        let s = HSphere::new(c, 0.7).unwrap();
        let ray = Ray::from_ball_unchecked(&c, DVec3::new(0.3, -1.0, 0.2));
        let hit = s.intersect(&ray, 1e-9, f64::INFINITY).unwrap();
        assert!((hit.t - 0.7).abs() < 1e-13);
        // The normal is the ray's own tangent there.
        assert!((hit.normal - ray.tangent_at(hit.t)).length() < 1e-12);
    }

    #[test]
    fn miss_and_tangent() {
        let c = Point::from_coords(DVec3::new(0.0, 0.0, 0.5)).unwrap();
        let s = HSphere::new(c, 0.2).unwrap();
        assert!(
            s.intersect(&Ray::from_origin_unchecked(DVec3::X), 0.0, f64::INFINITY)
                .is_none()
        );
        let hit = s
            .intersect(&Ray::from_origin_unchecked(DVec3::Z), 0.0, f64::INFINITY)
            .unwrap();
        let expect = c.distance_from_origin() - 0.2;
        assert!((hit.t - expect).abs() < 1e-14);
        assert!(
            s.intersect(&Ray::from_origin_unchecked(-DVec3::Z), 0.0, f64::INFINITY)
                .is_none()
        );
    }

    #[test]
    fn bad_radius_is_rejected() {
        assert!(HSphere::new(Point::ORIGIN, -1.0).is_err());
        assert!(HSphere::new(Point::ORIGIN, 0.0).is_err());
        assert!(HSphere::new(Point::ORIGIN, f64::NAN).is_err());
    }
}
