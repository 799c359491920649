//! Light from the sphere at infinity (`sky = (zenith, horizon)`): a ray
//! that meets nothing brings the radiance of the ideal point it runs to.
//! The ideal point, not the ray's first direction, selects the colour, so
//! a mirror reflects the sky where its reflected rays end, and moving the
//! eye moves the sky as it does in H³ (a parallel ray from another place
//! ends at another ideal point).

use hgeom::glam::DVec3;

use crate::color::Rgb;

/// A sky.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sky {
    /// A gradient by elevation: `zenith` at the ideal point `+y` of the
    /// ball, `horizon` on the great circle `y = 0` and below it.
    Gradient {
        /// The colour straight up.
        zenith: Rgb,
        /// The colour at the horizon and beneath.
        horizon: Rgb,
    },
}

impl Sky {
    /// The radiance from the ideal point with unit direction `u` (ball
    /// coordinates of the scene, not the camera's): for the gradient,
    /// `horizon + (zenith - horizon) max(u_y, 0)`, linear in the sine of
    /// the elevation.
    pub fn radiance(&self, u: DVec3) -> Rgb {
        match *self {
            Sky::Gradient { zenith, horizon } => {
                let t = u.y.clamp(0.0, 1.0);
                Rgb::new(
                    horizon.r + (zenith.r - horizon.r) * t,
                    horizon.g + (zenith.g - horizon.g) * t,
                    horizon.b + (zenith.b - horizon.b) * t,
                )
            }
        }
    }
}
