//! Animation compiled once: the transformations of named objects, lights
//! and the camera, kept as motions that any frame can be asked of
//! ([`Scene::frame`](crate::Scene::frame)) without compiling the scene again.
//!
//! A target's transformations are applied in statement order, composed into
//! one isometry and applied once; an animated one (`, animate`) contributes
//! the fraction `k / (N - 1)` of its angle or distance in frame `k` of `N`.
//! A target with at least one animated transformation is a [`Track`]: its
//! state before its transformations is kept, and each frame composes the
//! motions at that frame's time and applies them to it, exactly as the
//! lowering of that frame alone would.

use hgeom::{GeomError, Isometry, Point, Segment};

use crate::camera::Camera;
use crate::object::Object;

/// One transformation of a target, as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Motion {
    /// Applied in full in every frame (not animated, or a reflection).
    Fixed(Isometry),
    /// A rotation about the h-line through the segment's points, by the
    /// frame's time times `angle` (radians).
    Rotate {
        /// Two points of the axis.
        axis: Segment,
        /// The whole angle, reached in the last frame.
        angle: f64,
    },
    /// The translation along the segment's h-line by the frame's time times
    /// its length: the identity at time 0, the whole translation (first
    /// point to second) at 1.
    Translate {
        /// From where to where the whole translation goes.
        along: Segment,
    },
}

impl Motion {
    /// The isometry at `time` in `0..=1`.
    pub fn at(&self, time: f64) -> Result<Isometry, GeomError> {
        match self {
            Motion::Fixed(iso) => Ok(*iso),
            Motion::Rotate { axis, angle } => Ok(Isometry::rotation_about_segment_unchecked(
                axis,
                time * angle,
            )),
            Motion::Translate { along } => partial_translation(along, time),
        }
    }

    /// True unless the motion is the same in every frame.
    pub fn is_animated(&self) -> bool {
        !matches!(self, Motion::Fixed(_))
    }
}

/// The translation along `line` by `fraction` of its length: the whole
/// translation (first point to second) at 1, the identity at 0.
///
/// Built as [`Isometry::translation`] builds the whole one: the start moved
/// to the origin, the end to a point `w` at distance `d` from it, the
/// transvection to the point at `fraction * d` along `w`'s diameter, and
/// back. Every point involved lies between the origin and the whole
/// translation's end, so whatever the whole one can build, every fraction
/// of it can (points along the line's own parametrisation lay far outside
/// for a line far from the origin: a translation of 24 was refused halfway).
fn partial_translation(line: &Segment, fraction: f64) -> Result<Isometry, GeomError> {
    if fraction == 1.0 {
        return Isometry::translation(line);
    }
    if fraction == 0.0 {
        return Ok(Isometry::IDENTITY);
    }
    let to_origin = Isometry::transvection_from_origin(line.start()).inverse();
    let w = to_origin.apply(&line.end());
    if w.coords() == hgeom::glam::DVec3::ZERO {
        return Err(GeomError::Coincident);
    }
    let part = Point::at_distance_from_origin(w.coords(), fraction * w.distance_from_origin())?;
    Ok(to_origin
        .inverse()
        .compose(&Isometry::transvection_from_origin(part))
        .compose(&to_origin))
}

/// The composition of `motions` at `time`: the first applied first.
pub fn compose(motions: &[Motion], time: f64) -> Result<Isometry, GeomError> {
    let mut isos = motions.iter().map(|m| m.at(time));
    let first = isos.next().unwrap_or(Ok(Isometry::IDENTITY))?;
    // `a.compose(b)` applies `b` first.
    isos.try_fold(first, |acc, iso| Ok(iso?.compose(&acc)))
}

/// What a track moves, as it was before its transformations.
#[derive(Clone, Debug, PartialEq)]
pub enum TrackBase {
    /// The objects one statement declared.
    Objects {
        /// Their indices in [`Scene::objects`](crate::Scene::objects).
        indices: Vec<usize>,
        /// The objects before their transformations, in the same order.
        objects: Vec<Object>,
    },
    /// A light's position (`Scene::lights[index]`).
    Light {
        /// Index in [`Scene::lights`](crate::Scene::lights).
        index: usize,
        /// The position before its transformations.
        position: Point,
    },
    /// The camera before its transformations.
    Camera(Camera),
}

/// A target with at least one animated transformation.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// The target before its transformations.
    pub base: TrackBase,
    /// Its transformations in statement order; at least one is animated.
    pub motions: Vec<Motion>,
}

/// The animation of a scene: how many frames, and what moves.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Animation {
    /// The targets that move from frame to frame.
    pub tracks: Vec<Track>,
    /// True when animated transformations act on points (`%P->...,
    /// animate`): what is built from those points changes shape between
    /// frames, so each frame must be compiled from the source
    /// (the scene language compiles such a frame on its own); [`Scene::frame`](crate::Scene::frame) refuses.
    pub moves_points: bool,
}

/// Why [`Scene::frame`](crate::Scene::frame) cannot give a frame.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FrameError {
    /// Past the last frame.
    #[error("frame {frame} is past the last frame ({last})")]
    PastEnd {
        /// The frame asked for.
        frame: u32,
        /// The last frame.
        last: u32,
    },
    /// The scene animates points; compile the frame from the source.
    #[error("the scene animates points, so frame {frame} must be compiled from the source")]
    NeedsSource {
        /// The frame asked for.
        frame: u32,
    },
    /// A transformation takes its target beyond what f64 represents, or
    /// cannot be built, in this frame.
    #[error("in frame {frame}, {what} leaves what f64 can represent")]
    OutOfRange {
        /// The frame.
        frame: u32,
        /// What moved: `object 3`, `light 1`, `the camera`.
        what: String,
    },
}

/// The time of frame `k` of `frames`: `k / (frames - 1)`, 0 for a still.
pub fn frame_time(frame: u32, frames: u32) -> f64 {
    if frames > 1 {
        f64::from(frame) / f64::from(frames - 1)
    } else {
        0.0
    }
}

#[cfg(test)]
mod partial_translation_tests {
    use super::*;
    use hgeom::glam::DVec3;

    /// A translation of 24 along a line through the origin, and one along a
    /// line 3 from the origin: every fraction is built, moves the start the
    /// fraction of the way, and two fractions summing to one make the whole.
    #[test]
    fn long_translations_are_built_at_every_fraction() {
        for (start, dir) in [
            (Point::ORIGIN, DVec3::X),
            (
                Point::at_distance_from_origin(DVec3::Y, 3.0).unwrap(),
                DVec3::new(1.0, 0.2, 0.0),
            ),
        ] {
            let away = Isometry::transvection_from_origin(start);
            let end = away.apply(&Point::at_distance_from_origin(dir, 24.0).unwrap());
            let line = Segment::new(start, end).unwrap();
            let whole = partial_translation(&line, 1.0).unwrap();
            for t in [1.0 / 3.0, 0.5, 0.75] {
                let part = partial_translation(&line, t).unwrap();
                let moved = part.apply(&start);
                assert!((start.distance(moved) - 24.0 * t).abs() < 1e-6, "{t}");
                let rest = partial_translation(&line, 1.0 - t).unwrap();
                let probe = Point::new(0.1, -0.2, 0.3).unwrap();
                let (a, b) = (rest.compose(&part).apply(&probe), whole.apply(&probe));
                // The probe ends up to 27 from the origin, where a
                // coordinate's ulp is about 1e-5 of hyperbolic distance.
                assert!(a.distance(b) < 1e-3, "{t}: {}", a.distance(b));
            }
        }
    }
}
