//! Light from the sphere at infinity (`sky = (zenith, horizon)`): a ray
//! that meets nothing brings the radiance of the ideal point it runs to.
//! The ideal point, not the ray's first direction, selects the colour, so
//! a mirror reflects the sky where its reflected rays end, and moving the
//! eye moves the sky as it does in H³ (a parallel ray from another place
//! ends at another ideal point).

use std::sync::Arc;

use hgeom::glam::DVec3;

use crate::color::Rgb;
use crate::texture_image::TextureImage;

/// A sky.
#[derive(Clone, Debug, PartialEq)]
pub enum Sky {
    /// A gradient by elevation: `zenith` at the ideal point `+y` of the
    /// ball, `horizon` on the great circle `y = 0` and below it.
    Gradient {
        /// The colour straight up.
        zenith: Rgb,
        /// The colour at the horizon and beneath.
        horizon: Rgb,
    },
    /// An equirectangular image (`sky = "file.exr"`): the ideal point of
    /// unit direction `u` takes the texel at longitude
    /// `atan2(u_x, u_z)` (the image's middle column looks along `+z`,
    /// growing to the right towards `+x`) and latitude `asin(u_y)` (the top
    /// row is `+y`).
    Image(Arc<TextureImage>),
}

impl Sky {
    /// The radiance from the ideal point with unit direction `u` (ball
    /// coordinates of the scene, not the camera's): for the gradient,
    /// `horizon + (zenith - horizon) max(u_y, 0)`, linear in the sine of
    /// the elevation.
    pub fn radiance(&self, u: DVec3) -> Rgb {
        match self {
            Sky::Image(image) => {
                let (uu, vv) = equirectangular(u);
                let [r, g, b] = image.sample(uu, vv, 1.0);
                Rgb::new(r, g, b)
            }
            &Sky::Gradient { zenith, horizon } => {
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
/// The `(u, v)` of the unit direction `d` in an equirectangular image:
/// `u = 1/2 + atan2(d_x, d_z) / 2π`, `v = acos(d_y) / π` (module docs of
/// [`Sky::Image`]; the same map textures a sphere).
pub fn equirectangular(d: DVec3) -> (f64, f64) {
    let u = 0.5 + d.x.atan2(d.z) / std::f64::consts::TAU;
    let v = d.y.clamp(-1.0, 1.0).acos() / std::f64::consts::PI;
    (u, v)
}
