//! Whether an object or a light can be carried into the camera's canonical
//! frame (the eye at the origin), where the renderer traces everything.
//!
//! Points are stored up to distance 36 from the ball's origin; the eye may
//! be as far on the other side, so a thing can be up to 72 from the eye,
//! and f64 holds points only to about 37 from the origin. The compiler
//! asks these questions to refuse such a scene with a location, the
//! renderer asks the same ones before it traces: a scene `check` passes
//! never fails to render for this.

use hgeom::glam::{DVec3, DVec4};
use hgeom::{Isometry, Point, lorentz};

use crate::scene::Light;
use crate::shape::Shape;
#[cfg(doc)]
use crate::view::CanonicalFrame;

/// The light's position moved by each of `stages` in turn (those of a
/// [`CanonicalFrame`]), if it and (for an area light) its whole ball are
/// representable there. A light on the camera is at the origin.
pub fn light_in_frame(light: &Light, stages: &[Isometry]) -> Option<Point> {
    let p = if light.on_camera {
        Point::ORIGIN
    } else {
        stages
            .iter()
            .try_fold(light.position, |p, iso| iso.checked_apply(&p).ok())?
    };
    if light.radius > 0.0 {
        Point::at_distance_from_origin(DVec3::Z, p.distance_from_origin() + light.radius).ok()?;
    }
    Some(p)
}

/// A sphere wholly within this distance of the eye is traceable in the
/// eye's frame: its centre is representable there (to about 37), and that
/// is all a sphere's traceability asks.
const SPHERE_SURELY_NEAR: f64 = 12.0;

/// True if `shape` is a sphere wholly within [`SPHERE_SURELY_NEAR`] of the
/// eye (`eye` its point on the hyperboloid), so that
/// [`traceable_in_frame`] holds without moving it: one Lorentz product
/// (`cosh d = -<E,C>`), where moving the sphere into the frame was the
/// compiler's share of the work done twice (the renderer then moves every
/// object itself). 10,000 spheres: `traceable_in_frame` 6.95 M of 582 M
/// instructions of `check` before, about 1.1 M after.
///
/// Only for an eye within about 14.5 of the origin (`E_w < 1e6`): the
/// product's rounding is at most `16 eps E_w^2` of its value there (a few
/// thousandths), so a far sphere is never taken for a near one; a far eye
/// (the far-invariance tests' 25 and 30) takes the whole test.
pub fn surely_traceable_near(shape: &Shape, eye: DVec4) -> bool {
    let Shape::Sphere(s) = shape else {
        return false;
    };
    if !(eye.w < 1e6) {
        return false;
    }
    let rest = SPHERE_SURELY_NEAR - s.radius();
    rest > 0.0 && -lorentz::dot(eye, s.center().to_hyperboloid()) < rest.cosh()
}

/// Whether every surface of `shape`, moved by each of `stages` in turn,
/// is traceable there (`hgeom::Surface::is_traceable`).
pub fn traceable_in_frame(shape: &Shape, stages: &[Isometry]) -> bool {
    let mut moved: Option<Shape> = None;
    for iso in stages.iter().filter(|iso| **iso != Isometry::IDENTITY) {
        moved = Some(moved.as_ref().unwrap_or(shape).transformed(iso));
    }
    moved
        .as_ref()
        .unwrap_or(shape)
        .to_surfaces()
        .iter()
        .all(|s| s.is_traceable())
}

/// The first object or light of `scene` that cannot be carried into its
/// camera's canonical frame, named as the renderer names it ("object 3",
/// "light 1"); `None` when everything can (or the scene is in a space,
/// which folds everything near the eye). A degenerate camera is not this
/// function's concern.
pub fn first_too_far(scene: &crate::scene::Scene) -> Option<String> {
    if scene.settings.space.is_some() {
        return None;
    }
    let frame = crate::view::canonical_frame(&scene.camera)?;
    if let Some(i) = scene
        .objects
        .iter()
        .position(|o| !traceable_in_frame(&o.shape, &frame.stages))
    {
        return Some(format!("object {}", i + 1));
    }
    scene
        .lights
        .iter()
        .position(|l| light_in_frame(l, &frame.stages).is_none())
        .map(|i| format!("light {}", i + 1))
}

#[cfg(test)]
mod tests {
    use hgeom::HSphere;

    use super::*;
    use crate::camera::Camera;

    fn at(dir: DVec3, d: f64) -> Point {
        Point::at_distance_from_origin(dir.normalize(), d).unwrap()
    }

    /// The shortcut says "traceable" only where the whole test does, for
    /// eyes near and far and spheres near, at the cut and beyond it.
    #[test]
    fn a_sphere_surely_near_the_eye_is_traceable_in_its_frame() {
        let dirs = [
            DVec3::X,
            DVec3::new(0.3, -0.5, 0.8),
            DVec3::new(-1.0, 0.2, 0.1),
        ];
        let mut near = 0;
        for eye_d in [0.0, 3.0, 14.0, 25.0, 30.0] {
            for (k, dir) in dirs.iter().enumerate() {
                let eye = at(*dir, eye_d);
                let camera = Camera {
                    eye,
                    target: at(dirs[(k + 1) % 3], 0.5),
                    up: None,
                };
                let Some(frame) = crate::view::canonical_frame(&camera) else {
                    continue;
                };
                for centre_d in [0.5, 6.0, 11.5, 12.5, 20.0, 35.0] {
                    for r in [0.01, 0.4] {
                        let sphere = Shape::Sphere(
                            HSphere::new(at(dirs[(k + 2) % 3], centre_d), r).unwrap(),
                        );
                        if surely_traceable_near(&sphere, eye.to_hyperboloid()) {
                            near += 1;
                            assert!(eye_d < 14.5, "a far eye takes the whole test");
                            assert!(traceable_in_frame(&sphere, &frame.stages));
                        }
                    }
                }
            }
        }
        assert!(near > 0, "some spheres take the shortcut");
        let far = Shape::Sphere(HSphere::new(at(DVec3::Z, 11.9), 0.2).unwrap());
        assert!(!surely_traceable_near(&far, Point::ORIGIN.to_hyperboloid()));
    }
}
