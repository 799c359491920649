//! The canonical frame: the isometry that puts the eye at the
//! origin, the view direction along +z and up along +y.

use hgeom::{Isometry, Point};
use hscene_lang::ir::Camera;

use crate::error::RenderError;

/// The camera in canonical form.
#[derive(Clone, Copy, Debug)]
pub struct CanonicalCamera {
    /// Maps the scene into the canonical frame: `stages[1] ∘ stages[0]`.
    pub to_canonical: Isometry,
    /// The same map in two stages, to be applied in turn: the transvection
    /// taking the eye to the origin, then the rotation. A far point moved by
    /// the composite `R(-eye) (+) R P` is rotated first, and the rotation's
    /// rounding of the two far vectors survives their cancellation; in
    /// stages, `(-eye) (+) P` cancels the exactly stored coordinates and
    /// only the near result is rotated (`docs/geometry.md`, section 16.5).
    pub stages: [Isometry; 2],
    /// Euclidean distance from the origin to the view plane in the canonical
    /// frame, `tanh(d/2)` for the hyperbolic eye-target distance `d`.
    pub view_distance: f64,
}

impl CanonicalCamera {
    /// Build the canonical frame.
    ///
    /// First the transvection taking the eye to the origin; there the view
    /// direction is the diameter towards the moved target, and up is the
    /// direction towards the moved up point, made orthogonal to it (default:
    /// the image of the ball's `+y` at the eye). Then the rotation taking
    /// (right, up, view) to (x, y, z), with right = up x view. Screen x grows
    /// to the right, y upwards, z away from the eye (the convention of the
    /// thesis and of POV-Ray).
    pub fn new(camera: &Camera) -> Result<CanonicalCamera, RenderError> {
        let canonical =
            hscene_lang::view::canonical_frame(camera).ok_or(RenderError::DegenerateCamera)?;
        Ok(CanonicalCamera {
            to_canonical: canonical.to_canonical,
            stages: canonical.stages,
            view_distance: canonical.view_distance,
        })
    }

    /// The view target's image in the canonical frame, on the +z axis.
    pub fn canonical_target(&self, camera: &Camera) -> Point {
        self.apply(&camera.target)
    }

    /// A point's image in the canonical frame, stage by stage (see
    /// [`CanonicalCamera::stages`]).
    pub fn apply(&self, p: &Point) -> Point {
        self.stages.iter().fold(*p, |p, iso| iso.apply(&p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    #[test]
    fn default_camera_is_the_identity() {
        let cam = Camera {
            eye: Point::ORIGIN,
            target: p(0.0, 0.0, 0.1),
            up: None,
        };
        let c = CanonicalCamera::new(&cam).unwrap();
        let q = p(0.3, -0.2, 0.4);
        assert!((c.to_canonical.apply(&q).coords() - q.coords()).length() < 1e-15);
        assert!((c.view_distance - 0.1).abs() < 1e-15);
    }

    #[test]
    fn moved_camera_sees_target_on_axis_and_up_upwards() {
        let cam = Camera {
            eye: p(0.2, 0.1, -0.3),
            target: p(-0.1, 0.4, 0.2),
            up: Some(p(0.2, 0.6, -0.3)),
        };
        let c = CanonicalCamera::new(&cam).unwrap();
        assert!(c.to_canonical.apply(&cam.eye).coords().length() < 1e-15);
        let t = c.canonical_target(&cam).coords();
        assert!(t.x.abs() < 1e-14 && t.y.abs() < 1e-14 && t.z > 0.0);
        let u = c.to_canonical.apply(&cam.up.unwrap()).coords();
        assert!(u.y > 0.0 && u.x.abs() < 1e-14);
    }
}
