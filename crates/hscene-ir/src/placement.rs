//! Whether an object or a light can be carried into the camera's canonical
//! frame (the eye at the origin), where the renderer traces everything.
//!
//! Points are stored up to distance 36 from the ball's origin; the eye may
//! be as far on the other side, so a thing can be up to 72 from the eye,
//! and f64 holds points only to about 37 from the origin. The compiler
//! asks these questions to refuse such a scene with a location, the
//! renderer asks the same ones before it traces: a scene `check` passes
//! never fails to render for this.

use hgeom::glam::DVec3;
use hgeom::{Isometry, Point};

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
