//! h-spheres, horospheres and honeycomb vertices: Euclidean spheres in the
//! ball (an h-sphere of radius `r` about a point at Euclidean distance `ρ`
//! is the sphere of radius `(1 - ρ²) t / (1 - ρ² t²)`, `t = tanh(r/2)`,
//! which `hgeom::HSphere::euclidean` computes; a horosphere is the sphere
//! tangent to the boundary at its ideal centre), gridded by latitude and
//! longitude with every vertex exactly on the sphere.

use std::f64::consts::{PI, TAU};

use hgeom::glam::DVec3;

use crate::grid::PoleSurface;

/// A Euclidean sphere in ball units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    /// The centre.
    pub centre: DVec3,
    /// The radius.
    pub radius: f64,
}

impl PoleSurface for Ball {
    fn point(&self, u: f64, v: f64) -> DVec3 {
        let (polar, azimuth) = (PI * u, TAU * v);
        let dir = DVec3::new(
            polar.sin() * azimuth.cos(),
            polar.sin() * azimuth.sin(),
            polar.cos(),
        );
        self.centre + self.radius * dir
    }

    fn u_creases(&self) -> Vec<f64> {
        vec![0.0, 1.0]
    }

    fn v_creases(&self) -> Vec<f64> {
        vec![0.0]
    }
}
