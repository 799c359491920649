//! A thin lens at the eye: depth of field (`aperture = A; focus = D;`).
//!
//! **The lens.** In the canonical frame (eye at the origin, view along
//! `+z`) the lens is the disc of hyperbolic radius `A` in the eye's tangent
//! plane orthogonal to the view axis, carried onto the space by the
//! exponential map: the lens point at polar coordinates `(ρ, φ)` of the disc
//! is `L = (sinh ρ e, cosh ρ)` on the hyperboloid, `e = (cos φ, sin φ, 0)`,
//! at distance `ρ` from the eye along the geodesic orthogonal to the axis.
//! A pixel whose central (pinhole) ray runs along the unit direction `u`
//! reaches the point of focus `F = (sinh D u, cosh D)` at distance `D`;
//! each of its samples starts at a lens point, `ρ = A √ξ₁`, `φ = 2π ξ₂`
//! (uniform over the disc's area in the tangent plane), and travels the
//! geodesic from `L` through `F`. So every point at distance `D` from the
//! eye is seen sharp, whatever the lens point.
//!
//! **The circle of confusion.** Take a point `P` on the view axis at
//! distance `d` and a lens point at distance `a` from the eye. In the
//! plane through the axis and `L` (coordinates `(x, z; w)` on the
//! hyperboloid) `L = (sinh a, 0; cosh a)`, `P = (0, sinh d; cosh d)`, and the
//! point of focus of the pixel at angle `θ` from the axis, towards `L`, is
//! `F_θ = (sinh D sin θ, sinh D cos θ; cosh D)`. Three points lie on one
//! geodesic exactly when they are linearly dependent (a geodesic is a plane
//! through the origin of Minkowski space), so the pixel that sees `P`
//! through that lens point has
//!
//! ```text
//! sinh a (sinh d cosh D - cosh d sinh D cos θ) = cosh a sinh d sinh D sin θ
//! ```
//!
//! that is `α cos θ + β sin θ = γ` with `α = sinh a cosh d`,
//! `β = cosh a sinh d`, `γ = sinh a sinh d coth D`, whose root near 0 is
//! `θ(a) = atan2(β, α) - acos(γ / √(α² + β²))` ([`confusion_angle`]). At
//! `d = D`, `γ = α` and `θ = 0`: the point is sharp. To first order in `θ`,
//! `θ ≈ tanh a · sinh(d - D) / (sinh d sinh D)`, the Euclidean
//! `a (d - D) / (d D)` for small distances. The image of `P` is the disc of
//! angular radius `|θ(A)|` (the lens rim), filled as the lens is: its
//! intensity-weighted mean of `θ²` is the mean of `θ(a)²` over the lens,
//! which the test `the_circle_of_confusion_has_the_derived_size` compares
//! with rendered pictures.

use hgeom::glam::DVec3;
use hgeom::{Ray, lorentz};

/// The most a lens radius may be: a lens of hyperbolic radius 2 is already
/// larger than anything a view of a few units could focus.
pub const MAX_APERTURE: f64 = 2.0;

/// The farthest focus: as `irradiance_at`'s and `near`'s bound.
pub const MAX_FOCUS: f64 = 30.0;

/// A thin lens at the eye.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lens {
    /// The lens radius `A`, hyperbolic. Invariant: in `(0, MAX_APERTURE]`.
    pub aperture: f64,
    /// The distance `D` from the eye to the points seen sharp. Invariant:
    /// in `(0, MAX_FOCUS]`.
    pub focus: f64,
}

impl Lens {
    /// The ray of one sample of the pixel whose pinhole ray from the eye
    /// (the canonical origin) runs along the unit `dir`, through the lens
    /// point of the unit-square sample `(xi1, xi2)` (module docs).
    pub fn ray(&self, dir: DVec3, xi1: f64, xi2: f64) -> Ray {
        let rho = self.aperture * xi1.sqrt();
        let phi = std::f64::consts::TAU * xi2;
        let e = DVec3::new(phi.cos(), phi.sin(), 0.0);
        let origin = (rho.sinh() * e).extend(rho.cosh());
        let focus = (self.focus.sinh() * dir).extend(self.focus.cosh());
        match lorentz::unit_tangent_towards(origin, focus) {
            Some(towards) => Ray {
                origin,
                dir: towards,
            },
            // The lens centre itself (ρ = 0) or a focus at the lens point:
            // the pinhole ray.
            None => Ray::from_origin_unchecked(dir),
        }
    }
}

/// The angle from the view axis of the pixel that sees a point on the axis
/// at distance `d` through the lens point at distance `a` from the eye,
/// focus `focus` (module docs, "The circle of confusion"); positive
/// towards the lens point's side.
pub fn confusion_angle(a: f64, d: f64, focus: f64) -> f64 {
    let alpha = a.sinh() * d.cosh();
    let beta = a.cosh() * d.sinh();
    let gamma = a.sinh() * d.sinh() / focus.tanh();
    let r = alpha.hypot(beta);
    beta.atan2(alpha) - (gamma / r).clamp(-1.0, 1.0).acos()
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec4;

    /// Every lens ray passes through the pixel's point of focus, and starts
    /// on the lens: orthogonal to the axis, within the aperture.
    #[test]
    fn lens_rays_meet_at_the_point_of_focus() {
        let lens = Lens {
            aperture: 0.3,
            focus: 2.5,
        };
        let dir = DVec3::new(0.2, -0.1, 1.0).normalize();
        let f = (lens.focus.sinh() * dir).extend(lens.focus.cosh());
        for k in 0..50 {
            let (xi1, xi2) = (f64::from(k) / 50.0 + 0.01, (f64::from(k) * 0.618).fract());
            let ray = lens.ray(dir, xi1, xi2);
            assert!(ray.origin.z.abs() < 1e-15);
            let rho = ray.origin.w.acosh();
            assert!(rho <= lens.aperture + 1e-12);
            // The point of the ray at the distance of F from the origin is F.
            let t = lorentz::distance(ray.origin, f);
            let at: DVec4 = ray.at(t);
            assert!((at - f).length() < 1e-12 * f.w, "{at} against {f}");
        }
    }

    /// The circle of confusion is 0 in focus, and its first-order form
    /// agrees for a small lens; nearer points blur to the other side.
    #[test]
    fn confusion_angle_is_zero_in_focus_and_matches_first_order() {
        assert!(confusion_angle(0.2, 1.5, 1.5).abs() < 1e-14);
        let (a, d, focus): (f64, f64, f64) = (1e-3, 2.0, 1.2);
        let first = a.tanh() * (d - focus).sinh() / (d.sinh() * focus.sinh());
        let exact = confusion_angle(a, d, focus);
        assert!(
            (exact - first).abs() < 1e-6 * first.abs(),
            "{exact} {first}"
        );
        assert!(confusion_angle(0.1, 0.8, 1.2) < 0.0);
        assert!(confusion_angle(0.1, 3.0, 1.2) > 0.0);
    }
}
