//! Horospheres: limits of h-spheres whose centre runs off to an ideal point.

use glam::{DVec3, DVec4};

use crate::accurate::one_minus_norm_sq;
use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::point::{IdealPoint, Point};
use crate::ray::{Hit, Ray};
use crate::roots::{exp_roots, hit_at_first_root};

/// A horosphere centred at an ideal point.
///
/// With `L = (xi, 1)` the null vector of the centre `xi`, the horosphere is
/// `{X : -<X,L> = k}` and its horoball (the inside, towards `xi`) is
/// `-<X,L> < k`. In the ball it is a Euclidean sphere tangent to the
/// absolute at `xi`.
///
/// Invariants: `center` is a unit vector; `null = (center, 1)`; `k > 0`
/// and finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Horosphere {
    center: IdealPoint,
    null: DVec4,
    k: f64,
}

impl Horosphere {
    /// The horosphere centred at `center` passing through `through`.
    ///
    /// Errors: [`GeomError::NotInBall`] for a point that fails
    /// [`Point::is_representable`], [`GeomError::Coincident`] if the level
    /// `k` is not positive and finite.
    ///
    /// # Accuracy
    ///
    /// `k = |p - xi|^2 / gap`, a sum of squares over the accurate gap: within
    /// a few ulps, so `through` lies on the horosphere to a few ulps of `k`
    /// (`through_point_is_on_it_and_euclidean_form_is_tangent` in this
    /// module; `horosphere_level_is_the_euclidean_sphere` in
    /// `tests/derivations.rs`).
    pub fn new(center: IdealPoint, through: &Point) -> Result<Horosphere, GeomError> {
        if !through.is_representable() {
            return Err(GeomError::NotInBall {
                norm: through.coords().length(),
            });
        }
        let null = center.to_hyperboloid();
        // -<X,L> for X = ((1+|p|^2), 2p)/g and L = (xi, 1) is
        // ((1+|p|^2) - 2 p.xi)/g = (|p - xi|^2)/g: a sum of squares, no cancellation.
        let k = (through.coords() - center.coords()).length_squared() / through.gap();
        if !(k > 0.0 && k.is_finite()) {
            return Err(GeomError::Coincident);
        }
        Ok(Horosphere { center, null, k })
    }

    /// The ideal centre.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored point.
    pub fn center(&self) -> IdealPoint {
        self.center
    }

    /// The horosphere as a Euclidean sphere in the ball: tangent to the
    /// absolute at the centre `xi`, with centre `xi/(1+k)` and radius `k/(1+k)`.
    ///
    /// (It meets the diameter towards `xi` at `s xi` with `k = (1-s)/(1+s)`,
    /// so its Euclidean diameter is `1 - s = 2k/(1+k)`.)
    ///
    /// # Accuracy
    ///
    /// Centre and radius within 2 ulps of the formula for the stored `k`
    /// (no cancellation); the sphere passes through the defining point and
    /// touches the absolute at `xi` to 1e-15 near the origin.
    pub fn euclidean(&self) -> (DVec3, f64) {
        let inv = 1.0 / (1.0 + self.k);
        (self.center.coords() * inv, self.k * inv)
    }

    /// The image under an isometry.
    ///
    /// With `M` the Lorentz matrix, `M L` is a multiple `lambda L'` of the
    /// image centre's null vector `L' = (xi', 1)`, and the image is
    /// `-<Y,L'> = k / lambda`. `lambda = -<M L, E> = -<L, M^-1 E>` is the
    /// level of the point `c = f^-1(0)` (the translation part of the
    /// inverse): `|c - xi|^2 / gap_c`, a sum of squares over an exact gap.
    /// Carrying `L` by `M` instead rounds at `eps |M|`, which far out (a
    /// horosphere moved 25 away and back) is all of `k`.
    ///
    /// # Accuracy
    ///
    /// The centre as [`Isometry::apply_ideal`] (a few ulps plus
    /// `eps / gap_a` radians); `k` within a few ulps plus the rounding of
    /// `c`'s coordinates relative to `|c - xi|` (4e-11 relative for a
    /// horosphere through a point 25 away, moved back to the origin:
    /// `horosphere_moved_far_and_back` in `tests/far.rs`). Image points
    /// stay on the image to 1e-14 relative near the origin
    /// (`transformed_horosphere_contains_the_image_point`).
    pub fn transformed(&self, iso: &Isometry) -> Horosphere {
        let center = iso.apply_ideal(&self.center);
        let c = iso.inverse().translation_part();
        let lambda = (c.coords() - self.center.coords()).length_squared() / c.gap();
        Horosphere {
            center,
            null: center.to_hyperboloid(),
            k: self.k / lambda,
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

    /// True if the hyperboloid point is strictly inside the horoball.
    ///
    /// # Accuracy
    ///
    /// Decides `-<X,L> < k` with `<X,L>` rounded at about `eps |X|`: exact
    /// away from the surface.
    pub fn contains_hyperboloid(&self, x: DVec4) -> bool {
        -lorentz::dot(x, self.null) < self.k
    }

    /// The first intersection with `t` in `(t_min, t_max)`; the normal points
    /// out of the horoball.
    ///
    /// Along the ray `-<X(t),L> = a cosh t + b sinh t` with `a = -<X,L>`,
    /// `b = -<V,L>`; in `u = e^t`, `(a+b) u^2 - 2k u + (a-b) = 0`, where
    /// `a +- b = -<X +- V, L> >= 0` (two future null/causal vectors).
    ///
    /// # Accuracy
    ///
    /// Against a 320-bit reference, rays from the origin to horospheres
    /// through points up to 10 away: `t` within 2e-11 (measured 1.4e-12; the
    /// `ray-horosphere` family of `tests/reference.rs`). Hits lie on the
    /// horosphere so that the horosphere through the hit point agrees with it
    /// to 1e-9 (`horosphere_hits_lie_on_the_surface` in `tests/surfaces.rs`).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (plus, minus) = if ray.origin == DVec4::W {
            // A ray from the origin along the unit direction `û = u/|u|`:
            // `a = 1`, `b = -û.xi`, so `a -+ b = |û -+ xi|^2 / 2`, sums of
            // squares; `1 - u.xi` itself cancels for a ray aimed near the
            // centre (all of a far horosphere's hits: one 20 ahead is met
            // only within 2e-9 rad). The unit defects `δ` of `u` and `xi`
            // enter as `|û -+ xî|^2 = |u -+ xi|^2 + δ (1 -+ u.xi)`, with
            // `1 -+ u.xi = (δ + |u -+ xi|^2) / 2` (as for spheres).
            let (u, xi) = (ray.dir.truncate(), self.center.coords());
            let delta = one_minus_norm_sq(u) + one_minus_norm_sq(xi);
            let unit = |sq: f64| 0.5 * (sq + delta * 0.5 * (delta + sq));
            (
                unit((u - xi).length_squared()),
                unit((u + xi).length_squared()),
            )
        } else {
            let a = -lorentz::dot(ray.origin, self.null);
            let b = -lorentz::dot(ray.dir, self.null);
            (a + b, a - b)
        };
        let roots = exp_roots(plus, self.k, minus)?;
        hit_at_first_root(ray, roots, t_min, t_max, |x| self.normal_at(x))
    }

    /// Unit normal out of the horoball at a point of the horosphere: the
    /// tangent projection `-(L + cX)` of the gradient of `-<X,L>`, with
    /// `c = <X,L>` (its Lorentz length is `|c|` in exact arithmetic).
    ///
    /// # Accuracy
    ///
    /// Normalised by its computed length, so unit to about `eps |N|^2` and
    /// tangent to about `eps |X| |N|` (`assert_hit_on_ray` in
    /// `tests/surfaces.rs`: 1e-12 relative).
    pub fn normal_at(&self, x: DVec4) -> DVec4 {
        let c = lorentz::dot(x, self.null);
        let n = self.null + c * x;
        // Normalise by the computed length: far out, X is off the hyperboloid
        // by rounding of relative size ~|X|^2 eps, and the exact-identity
        // length |c| would then leave the normal visibly non-unit.
        let len = lorentz::norm(n);
        if c < 0.0 && len > 0.0 && len.is_finite() {
            -n / len
        } else {
            // <X,L> < 0 for every point of the hyperboloid; unreachable in exact
            // arithmetic, but keep a unit tangent rather than NaN.
            DVec4::X
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::point::Point;

    #[test]
    fn through_point_is_on_it_and_euclidean_form_is_tangent() {
        let xi = IdealPoint::from_direction(DVec3::new(0.0, 0.0, 1.0)).unwrap();
        let q = Point::from_coords(DVec3::new(0.0, 0.0, 0.2)).unwrap();
        let h = Horosphere::new(xi, &q).unwrap();
        let (c, r) = h.euclidean();
        assert!(((q.coords() - c).length() - r).abs() < 1e-15);
        assert!(((xi.coords() - c).length() - r).abs() < 1e-15);
    }

    #[test]
    fn ray_towards_the_centre_hits_at_the_through_point() {
        let xi = IdealPoint::from_direction(DVec3::new(1.0, 1.0, 0.0)).unwrap();
        let q = Point::at_distance_from_origin(DVec3::new(1.0, 1.0, 0.0), 1.5).unwrap();
        let h = Horosphere::new(xi, &q).unwrap();
        let hit = h
            .intersect(
                &Ray::from_origin_unchecked(DVec3::new(1.0, 1.0, 0.0)),
                0.0,
                f64::INFINITY,
            )
            .unwrap();
        assert!((hit.t - 1.5).abs() < 1e-14);
        // Outward normal points back towards the origin: against the ray.
        assert!(
            lorentz::dot(
                hit.normal,
                Ray::from_origin_unchecked(DVec3::new(1.0, 1.0, 0.0)).tangent_at(hit.t)
            ) < -0.999
        );
        // A ray away from the centre misses.
        assert!(
            h.intersect(
                &Ray::from_origin_unchecked(DVec3::new(-1.0, -1.0, 0.0)),
                0.0,
                f64::INFINITY
            )
            .is_none()
        );
    }

    #[test]
    fn transformed_horosphere_contains_the_image_point() {
        let xi = IdealPoint::from_direction(DVec3::new(0.0, 1.0, 0.0)).unwrap();
        let q = Point::from_coords(DVec3::new(0.1, 0.3, -0.2)).unwrap();
        let h = Horosphere::new(xi, &q).unwrap();
        let iso = Isometry::transvection_from_origin(
            Point::from_coords(DVec3::new(0.4, -0.2, 0.1)).unwrap(),
        );
        let h2 = h.transformed(&iso);
        let q2 = iso.apply(&q).to_hyperboloid();
        assert!((-lorentz::dot(q2, h2.null) - h2.k).abs() < 1e-14 * h2.k.max(1.0));
    }
}
