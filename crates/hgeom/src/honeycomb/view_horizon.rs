//! A horizon that depends on the direction of a ray from the eye: where a
//! picture's pixels are wider, its cells fall below a pixel sooner.
//!
//! On a flat image plane at distance `f` from the eye, perpendicular to the
//! view axis, with pixels `p` apart, the ray through the plane point
//! `x = (x, y, f)` has the unit direction `u = x/|x|`, and moving the point
//! by `p` along the plane's x axis turns `u` by
//! `|∂u/∂x| p = p sqrt(1 - u_x²)/|x|`. With `θ` the angle between `u` and
//! the axis, `|x| = f / cos θ` and `u_x² <= sin² θ`, so the angle between
//! the rays of neighbouring pixels is at least `(p/f) cos² θ` (the same
//! along y). A cell feature of size `s` at distance `t` subtends
//! `s / sinh t`, so it falls below that pixel beyond
//! `t = asinh(s / (a cos² θ))`, `a` the pixel angle at the middle: the
//! horizon of each ray is where its own pixel no longer resolves the cells
//! ([`crate::RegularHoneycomb::horizon_for_pixel`] for the smallest pixel
//! of the picture is the farthest of them).

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::ray::Ray;

/// The horizon of rays from the frame's origin as a function of their
/// direction: `asinh(size_over_angle / cos² θ)`, `θ` from `axis`.
///
/// Invariants: `axis` is a unit vector; `size_over_angle > 0` and finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct ViewHorizon {
    axis: DVec3,
    size_over_angle: f64,
}

impl ViewHorizon {
    /// For cell features of size `size` and pixels `pixel_angle` apart at
    /// the middle of the picture, whose view axis is `axis`.
    ///
    /// Errors: [`GeomError::BadDirection`] for an axis that is zero or not
    /// finite; [`GeomError::BadAngle`] unless `size / pixel_angle` is
    /// positive and finite.
    pub(super) fn new(axis: DVec3, size: f64, pixel_angle: f64) -> Result<ViewHorizon, GeomError> {
        let len = axis.length();
        if !(len > 0.0 && len.is_finite()) {
            return Err(GeomError::BadDirection);
        }
        let size_over_angle = size / pixel_angle;
        if !(size_over_angle > 0.0 && size_over_angle.is_finite()) {
            return Err(GeomError::BadAngle(pixel_angle));
        }
        Ok(ViewHorizon {
            axis: axis / len,
            size_over_angle,
        })
    }

    /// `cosh` of the horizon of `ray`, at most `cosh_farthest`: its own for
    /// a ray from the frame's origin (the eye; its direction is then the
    /// spatial part of `ray.dir`), `cosh_farthest` for every other ray.
    /// No transcendental function: `cosh(asinh x) = sqrt(1 + x²)`.
    #[inline]
    pub(super) fn cosh_for(&self, ray: &Ray, cosh_farthest: f64) -> f64 {
        if ray.origin != DVec4::W {
            return cosh_farthest;
        }
        let u = ray.dir.truncate();
        let along = u.dot(self.axis);
        // size / (a cos² θ), with cos² θ = along² / |u|².
        let x = self.size_over_angle * u.length_squared() / (along * along);
        let cosh = (1.0 + x * x).sqrt();
        // A ray across the axis (along = 0) gives inf, a degenerate one
        // NaN: both fail the comparison and keep the farthest.
        if cosh < cosh_farthest {
            cosh
        } else {
            cosh_farthest
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Along the axis the horizon is `asinh(size / angle)`; at `θ` from it,
    /// `asinh(size / (angle cos² θ))`; never beyond the farthest; rays not
    /// from the origin and rays across the axis keep the farthest.
    #[test]
    fn the_horizon_follows_the_pixel_of_the_direction() {
        let view = ViewHorizon::new(DVec3::new(0.0, 0.0, 2.0), 1.25, 1e-3).unwrap();
        let farthest = 9.0f64.cosh();
        let along = Ray::from_origin_unchecked(DVec3::Z);
        let want = (1.25f64 / 1e-3).asinh().cosh();
        assert!((view.cosh_for(&along, farthest) / want - 1.0).abs() < 1e-12);
        for deg in [10.0f64, 30.0, 50.0] {
            let th = deg.to_radians();
            let ray = Ray::from_origin_unchecked(DVec3::new(th.sin(), 0.0, th.cos()));
            let want = (1.25 / (1e-3 * th.cos() * th.cos())).asinh().cosh();
            let got = view.cosh_for(&ray, farthest);
            assert!((got / want.min(farthest) - 1.0).abs() < 1e-12, "{deg}°");
        }
        let across = Ray::from_origin_unchecked(DVec3::X);
        assert_eq!(view.cosh_for(&across, farthest), farthest);
        let start = crate::Point::from_coords(DVec3::new(0.0, 0.0, 0.1)).unwrap();
        let elsewhere = Ray::from_ball_unchecked(&start, DVec3::Z);
        assert_eq!(view.cosh_for(&elsewhere, farthest), farthest);
        assert!(ViewHorizon::new(DVec3::ZERO, 1.0, 1e-3).is_err());
        assert!(ViewHorizon::new(DVec3::Z, 1.0, 0.0).is_err());
        assert!(ViewHorizon::new(DVec3::Z, 1.0, f64::NAN).is_err());
    }
}
