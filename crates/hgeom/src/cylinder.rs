//! h-cylinders: the equidistant surface at distance `r` from an h-line.

use glam::DVec4;

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::line::HLine;
use crate::lorentz;
use crate::point::Point;
use crate::ray::{Hit, Ray};
use crate::roots::{exp_roots, hit_at_first_root};

/// The points at hyperbolic distance `radius` from an h-line (an
/// equidistant surface; in the ball, a "banana" through the line's two
/// ideal ends).
///
/// With the line's adapted Lorentz basis (see [`HLine`]) the surface is the quadric
/// `<X,N1>^2 + <X,N2>^2 = sinh^2 r` of `R^{3,1}`, so a ray meets it where a
/// quadratic vanishes: a closed form, where the thesis bisected.
///
/// Invariants: `radius` is positive and `sinh^2 r` finite; the cached
/// `sinh^2 r` is computed from it; the line obeys [`HLine`]'s invariants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HCylinder {
    line: HLine,
    radius: f64,
    sinh2_r: f64,
}

/// [`HCylinder::quadratic`]: its coefficients, and `|o|²`, `|d|²` and
/// `p.q = |o|² - |d|²` of the axis coordinates it came from.
#[derive(Clone, Copy, Debug)]
struct TubeQuadratic {
    a: f64,
    c: f64,
    k: f64,
    oo: f64,
    dd: f64,
    pq: f64,
}

impl TubeQuadratic {
    /// The two arc lengths, as [`HCylinder::roots`].
    #[inline]
    fn roots(&self) -> Option<(f64, f64)> {
        if !(self.k > 0.0) {
            return None;
        }
        let (near, far) = exp_roots(self.a, self.k, self.c)?;
        Some((0.5 * near, 0.5 * far))
    }
}

/// The coefficients of the equidistant quadric along a ray, shared with rods.
#[derive(Clone, Copy, Debug)]
pub(crate) struct AxisCoords {
    /// `<X,N_i>` at the ray's origin.
    o: [f64; 2],
    /// `<V,N_i>` for the ray's direction.
    d: [f64; 2],
}

impl HCylinder {
    /// The equidistant surface at hyperbolic distance `radius` from `line`.
    ///
    /// Errors: [`GeomError::BadRadius`] unless `radius > 0` with `sinh^2 r`
    /// finite (radius below ~355).
    ///
    /// # Accuracy
    ///
    /// The line and radius are stored exactly; `sinh^2 r` is within a few
    /// ulps.
    pub fn new(line: HLine, radius: f64) -> Result<HCylinder, GeomError> {
        let s = radius.sinh();
        if !(radius > 0.0 && (s * s).is_finite()) {
            return Err(GeomError::BadRadius(radius));
        }
        Ok(HCylinder::new_unchecked(line, radius))
    }

    /// The equidistant surface at distance `radius` from `line`, with
    /// nothing checked: the `_unchecked` form of [`HCylinder::new`].
    ///
    /// # Preconditions
    ///
    /// `radius > 0` with `sinh^2 r` finite. A violated precondition gives
    /// meaningless hits, never undefined behaviour.
    ///
    /// # Accuracy
    ///
    /// As [`HCylinder::new`], and bit-identical to it on valid input
    /// (`tests/constructors.rs`).
    #[inline]
    pub fn new_unchecked(line: HLine, radius: f64) -> HCylinder {
        let s = radius.sinh();
        HCylinder {
            line,
            radius,
            sinh2_r: s * s,
        }
    }

    /// The axis.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored line.
    pub fn line(&self) -> HLine {
        self.line
    }

    /// Hyperbolic distance of the surface from its axis.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The image under an isometry (equidistant surfaces map to equidistant
    /// surfaces of the same radius about the image line).
    ///
    /// # Accuracy
    ///
    /// As [`HLine::transformed`]: the axis moves by the composition's
    /// rounding (about one coordinate ulp of its base point); the radius is
    /// unchanged. Hits on the moved surface agree with hits on the original
    /// to 1e-8 relative (`isometries_preserve_hits` in `tests/surfaces.rs`).
    pub fn transformed(&self, iso: &Isometry) -> HCylinder {
        HCylinder {
            line: self.line.transformed(iso),
            ..*self
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

    /// True if the hyperboloid point is strictly closer to the axis than `radius`.
    ///
    /// # Accuracy
    ///
    /// Decides `<X,N1>^2 + <X,N2>^2 < sinh^2 r` with the products rounded at
    /// about `eps |X| |M|` (`M` the line's Lorentz basis): exact away from the surface.
    pub fn contains_hyperboloid(&self, x: DVec4) -> bool {
        let m = self.line.lorentz_basis();
        let (c1, c2) = (lorentz::dot(x, m.x_axis), lorentz::dot(x, m.y_axis));
        c1 * c1 + c2 * c2 < self.sinh2_r
    }

    /// The first intersection with `t` in `(t_min, t_max)`; the normal points
    /// away from the axis.
    ///
    /// # Accuracy
    ///
    /// Against a 320-bit reference, rays from the origin to cylinders about
    /// axes through points up to 8 away: `t` within 1e-11 (measured
    /// 2.6e-13; the `ray-cylinder` family of `tests/reference.rs`). Hit
    /// points lie at distance `r` from the axis to 1e-9 for eyes and axes
    /// within 3 of the origin (`cylinder_hits_lie_on_the_surface` in
    /// `tests/surfaces.rs`), and rays from the axis obey
    /// `sinh r = sinh t sin theta` to 1e-9 relative. Near tangency the
    /// root is a double one (error about the square root of the
    /// coefficients' rounding); no input gives NaN
    /// (`tangent_and_grazing_rays_to_a_cylinder`).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        hit_at_first_root(ray, self.roots(ray)?, t_min, t_max, |x| self.normal_at(x))
    }

    /// Both arc lengths at which the ray's geodesic meets the surface,
    /// nearest first (possibly negative or infinite, never NaN).
    ///
    /// With `c_i(t) = <X(t),N_i> = o_i cosh t + d_i sinh t` and `u = e^t`,
    /// `2 c_i = u p_i + q_i / u` where `p_i = o_i + d_i`, `q_i = o_i - d_i`.
    /// Then `c_1^2 + c_2^2 = sinh^2 r` becomes, in `v = e^{2t}`,
    /// `A v^2 - 2 k v + C = 0` with `A = |p|^2`, `C = |q|^2` and
    /// `k = 2 sinh^2 r - p.q`. `A, C >= 0`, so real positive roots need
    /// `k > 0`, and they are found by the same cancellation-free pair as the
    /// sphere's.
    ///
    /// # Accuracy
    ///
    /// As [`HCylinder::intersect`], for both roots.
    pub fn roots(&self, ray: &Ray) -> Option<(f64, f64)> {
        self.quadratic(ray).roots()
    }

    /// [`HCylinder::roots`], or with none whether the ray's whole line
    /// passes clear of the tube: farther from the axis everywhere than a
    /// radius whose `sinh²` is `1 + CLEAR` times this one's, so that no
    /// ball of this radius about a point of the axis (a rod's cap) can
    /// meet it.
    ///
    /// The line comes within `ρ` of the axis where
    /// `a u² - 2 k_ρ u + c <= 0` for some `u = e^{2t} > 0`, that is iff
    /// `k_ρ > 0` and `k_ρ² >= a c` (`a, c >= 0`), with
    /// `k_ρ = 2 sinh² ρ - p.q`. In `g = k_ρ - sqrt(a c)` widening the tube
    /// adds the margin `M = 2 sinh² r CLEAR`. Rounding moves `g` by a few
    /// ulps of `|o|² + |d|²` in the last steps, and by `|o| + |d|` times
    /// the error of the axis coordinates `o`, `d` themselves: Lorentz
    /// products of the ray's start and direction with the axis basis, a
    /// few ulps of `(X_0 + V_0 + 1) |N|` (Euclidean norms; large for a
    /// ray starting far out beside a far rod, where the products cancel).
    /// The answer is "clear" only where a thousand times both is below half
    /// the margin, and "not clear" (test the caps) otherwise.
    pub(crate) fn roots_or_clear(&self, ray: &Ray) -> (Option<(f64, f64)>, bool) {
        const CLEAR: f64 = 1e-2;
        const SLACK: f64 = 1e-12;
        let q = self.quadratic(ray);
        if let Some(roots) = q.roots() {
            return (Some(roots), false);
        }
        let wide = 2.0 * self.sinh2_r * (1.0 + CLEAR) - q.pq;
        // `x + y < M` with `x = SLACK (|o|² + |d|²)` and
        // `y = SLACK sqrt(|o|² + |d|²) (X_0 + V_0 + 1) |N|`, squared where
        // both sides are positive: no square root.
        let m = self.line.lorentz_basis();
        let nn = m.x_axis.length_squared().max(m.y_axis.length_squared());
        let input = ray.origin.w.abs() + ray.dir.w.abs() + 1.0;
        let margin = self.sinh2_r * CLEAR;
        let size = q.oo + q.dd;
        let x = SLACK * size;
        let y2 = SLACK * SLACK * size * input * input * nn;
        let resolved = x < margin && y2 < (margin - x) * (margin - x);
        (None, resolved && (wide <= 0.0 || wide * wide < q.a * q.c))
    }

    /// The tube's quadratic `a u² - 2 k u + c` in `u = e^{2t}` along `ray`.
    #[inline]
    fn quadratic(&self, ray: &Ray) -> TubeQuadratic {
        let ax = self.axis_coords(ray);
        let p = [ax.o[0] + ax.d[0], ax.o[1] + ax.d[1]];
        let q = [ax.o[0] - ax.d[0], ax.o[1] - ax.d[1]];
        // p.q = |o|^2 - |d|^2, computed from o and d directly: fewer roundings.
        let (oo, dd) = (
            ax.o[0] * ax.o[0] + ax.o[1] * ax.o[1],
            ax.d[0] * ax.d[0] + ax.d[1] * ax.d[1],
        );
        let pq = oo - dd;
        TubeQuadratic {
            a: p[0] * p[0] + p[1] * p[1],
            c: q[0] * q[0] + q[1] * q[1],
            k: 2.0 * self.sinh2_r - pq,
            oo,
            dd,
            pq,
        }
    }

    pub(crate) fn axis_coords(&self, ray: &Ray) -> AxisCoords {
        let m = self.line.lorentz_basis();
        AxisCoords {
            o: [
                lorentz::dot(ray.origin, m.x_axis),
                lorentz::dot(ray.origin, m.y_axis),
            ],
            d: [
                lorentz::dot(ray.dir, m.x_axis),
                lorentz::dot(ray.dir, m.y_axis),
            ],
        }
    }

    /// Unit normal pointing away from the axis at a point of the surface.
    ///
    /// The gradient of `F = <X,N1>^2 + <X,N2>^2` is `2 G` with
    /// `G = c_1 N1 + c_2 N2`; projected onto the tangent space at `X` it is
    /// `G + <G,X> X`, of Lorentz length `c sqrt(1 + c^2)` where
    /// `c^2 = c_1^2 + c_2^2` (exactly, by `<X,X> = -1`), which normalises it
    /// without a cancelling norm computation.
    ///
    /// # Accuracy
    ///
    /// A unit tangent to rounding (`|<N,N> - 1| < 1e-12 |N|^2` and
    /// `|<N,X>| < 1e-12 |X| |N|` in `tests/surfaces.rs`); stepping `1e-4`
    /// along it increases the distance to the axis by `1e-4` to 1e-8.
    pub fn normal_at(&self, x: DVec4) -> DVec4 {
        let m = self.line.lorentz_basis();
        let (c1, c2) = (lorentz::dot(x, m.x_axis), lorentz::dot(x, m.y_axis));
        let c2sum = c1 * c1 + c2 * c2;
        let g = c1 * m.x_axis + c2 * m.y_axis;
        let n = g + lorentz::dot(g, x) * x;
        let len = (c2sum * (1.0 + c2sum)).sqrt();
        if len > 0.0 && len.is_finite() {
            n / len
        } else {
            // Only on the axis itself, which is not on a surface of positive radius.
            m.x_axis
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::point::Point;
    use glam::DVec3;

    fn z_axis_cylinder(r: f64) -> HCylinder {
        let line = HLine::from_point_direction(&Point::ORIGIN, DVec3::Z).unwrap();
        HCylinder::new(line, r).unwrap()
    }

    #[test]
    fn ray_from_the_axis_hits_at_the_radius() {
        let cyl = z_axis_cylinder(0.4);
        let ray = Ray::from_origin_unchecked(DVec3::new(1.0, 0.5, 0.0));
        let hit = cyl.intersect(&ray, 1e-9, f64::INFINITY).unwrap();
        assert!((hit.t - 0.4).abs() < 1e-14, "{}", hit.t);
        assert!((hit.normal - ray.tangent_at(hit.t)).length() < 1e-13);
    }

    #[test]
    fn oblique_ray_from_the_axis_hits_where_trigonometry_says() {
        // A ray from a point of the axis at angle theta to it reaches distance
        // r from the axis after arc length t with sinh r = sinh t sin theta
        // (right-angled triangle: hypotenuse t, angle theta opposite side r).
        let cyl = z_axis_cylinder(0.3);
        let theta = 0.6f64;
        let ray = Ray::from_origin_unchecked(DVec3::new(theta.sin(), 0.0, theta.cos()));
        let hit = cyl.intersect(&ray, 1e-9, f64::INFINITY).unwrap();
        let want = (0.3f64.sinh() / theta.sin()).asinh();
        assert!((hit.t - want).abs() < 1e-14, "{} vs {want}", hit.t);
    }

    #[test]
    fn rays_along_and_tangent() {
        let cyl = z_axis_cylinder(0.3);
        // Along the axis: never meets the surface.
        assert!(
            cyl.intersect(&Ray::from_origin_unchecked(DVec3::Z), 0.0, f64::INFINITY)
                .is_none()
        );
        // From outside, parallel to the axis direction, misses; no NaN anywhere.
        let out = Point::from_coords(DVec3::new(0.5, 0.0, 0.0)).unwrap();
        let ray = Ray::from_ball_unchecked(&out, DVec3::Z);
        let r = cyl.roots(&ray);
        assert!(r.is_none() || r.is_some_and(|(a, b)| !a.is_nan() && !b.is_nan()));
    }
}
