//! The cut rule: which parts are printed, and how much of each
//! (`docs/export.md`, "The cut rule").
//!
//! - A tube (rod, cylinder, honeycomb edge) is kept over the interval of
//!   its axis where its printed thickness is at least the minimum feature,
//!   and capped there; with [`ThinParts::Thicken`] it keeps its whole
//!   length, thickened where it is thinner, and only an end at infinity is
//!   cut, where the axis comes within twice the minimum of the ball's
//!   boundary; a thickened tube shorter than four times the minimum is
//!   left out (it would print as a blob).
//! - A ball (h-sphere, honeycomb vertex, horosphere) is kept whole when
//!   its diameter is at least the minimum, else left out; a honeycomb's
//!   vertex ball with cut edges also needs a ball of the edge radius there
//!   to be thick enough, so that the edges reach it and it never floats.
//! - A plate (polygon, honeycomb face) is kept whole when it is at least
//!   the minimum thick at its thinnest place, else left out (so a face
//!   with an ideal corner never is); a whole plane is printed as the disc
//!   about its point nearest the centre out to where it gets that thin.

use hgeom::glam::DVec4;

use crate::ball::Ball;
use crate::options::{ExportOptions, ThinParts};
use crate::slab::{Outline, Plate, plane_disc};
use crate::tube::{Axis, Capsule, TubeRadius};

/// A thickened tube is kept when its axis is at least this many minimum
/// features long: shorter, it would print as a blob, not a rod.
pub const THICKENED_MIN_LENGTH: f64 = 4.0;

/// The largest hyperbolic radius searched for a plane's disc.
const MAX_DISC_RADIUS: f64 = 30.0;

/// The surface of one printed part.
pub enum PartSurface {
    /// A sphere.
    Ball(Ball),
    /// A capsule.
    Capsule(Capsule),
    /// A plate.
    Plate(Plate),
}

/// The tube of radius `w` about `axis` as the rule keeps it, if at all.
pub fn tube(axis: Axis, w: f64, options: &ExportOptions) -> Option<PartSurface> {
    let m = options.min_feature_ball();
    let capsule = match options.thin {
        ThinParts::Cut => Capsule::new(
            axis.trimmed(|s| axis.thickness(s, w) >= m)?,
            TubeRadius::Exact(w),
        ),
        ThinParts::Thicken => {
            let axis = if axis.is_finite() {
                axis
            } else {
                axis.trimmed(|s| 1.0 - axis.ball_radius(s) >= 2.0 * m)?
            };
            if axis.chord() < THICKENED_MIN_LENGTH * m {
                return None;
            }
            Capsule::new(axis, TubeRadius::Thickened { base: w, min: m })
        }
    };
    // A tube cut down to less than the tolerance is the ball about its
    // middle: its two cap rows would be closer than any reader's welding
    // distance.
    if capsule.axis.chord() < options.tolerance_ball() {
        let s = 0.5 * (capsule.axis.from + capsule.axis.to);
        return ball_about(capsule.axis.point(s), capsule.radius_at(s), options);
    }
    Some(PartSurface::Capsule(capsule))
}

/// The ball of hyperbolic radius `r` about the hyperboloid point `x`, if
/// thick enough.
pub fn ball_about(x: DVec4, r: f64, options: &ExportOptions) -> Option<PartSurface> {
    let p = hgeom::Point::from_hyperboloid(x)?;
    let sphere = hgeom::HSphere::new(p, r).ok()?;
    let (centre, radius) = sphere.euclidean();
    euclidean_ball(centre, radius, options)
}

/// A Euclidean ball (ball units), if its diameter is at least the minimum.
pub fn euclidean_ball(
    centre: hgeom::glam::DVec3,
    radius: f64,
    options: &ExportOptions,
) -> Option<PartSurface> {
    (2.0 * radius >= options.min_feature_ball() && radius.is_finite())
        .then_some(PartSurface::Ball(Ball { centre, radius }))
}

/// The plate on a polygon with these corners (hyperboloid points, or null
/// for ideal ones), if thick enough everywhere.
pub fn polygon_plate(
    corners: &[DVec4],
    normal: DVec4,
    options: &ExportOptions,
) -> Option<PartSurface> {
    if corners.iter().any(|x| hgeom::lorentz::dot(*x, *x) > -0.5) {
        return None;
    }
    let plate = Plate {
        outline: Outline::polygon(corners),
        normal,
        half: options.face_half_thickness,
    };
    (plate.thinnest() >= options.min_feature_ball()).then_some(PartSurface::Plate(plate))
}

/// The disc of the plane with unit normal `normal` out to where it gets
/// thinner than the minimum, if it is thick enough at all.
pub fn plane_plate(normal: DVec4, options: &ExportOptions) -> Option<PartSurface> {
    let m = options.min_feature_ball();
    let plate = |radius: f64| Plate {
        outline: plane_disc(normal, radius),
        normal,
        half: options.face_half_thickness,
    };
    if plate(0.0).thinnest() < m {
        return None;
    }
    let (mut a, mut b) = (0.0, MAX_DISC_RADIUS);
    for _ in 0..60 {
        let mid = 0.5 * (a + b);
        if plate(mid).thinnest() >= m {
            a = mid;
        } else {
            b = mid;
        }
    }
    // A disc of radius 0 is no plate.
    (a > 1e-9).then(|| PartSurface::Plate(plate(a)))
}
