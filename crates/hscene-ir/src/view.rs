//! The field of view (`fov = DEGREES`): the window on the view plane that
//! each pixel net needs for a given horizontal opening angle at the eye.
//!
//! In the camera's canonical frame the eye is the origin and the view
//! plane passes through the target at Euclidean (ball) distance `f =
//! tanh(d/2)` on the +z axis, `d` the hyperbolic distance from eye to
//! target. `fov` fixes the angle at the eye between the primary rays
//! through the left and right ends of the middle row; the window's height
//! follows from the resolution's aspect ratio (`h = w H / W`), so pixels are
//! square at the centre. `docs/rendering.md#field-of-view` derives the
//! formulas below.

use hgeom::glam::{DMat3, DVec3};
use hgeom::{Isometry, Point};

use crate::camera::{Camera, Net, Resolution, Window};

/// How finely a picture samples the directions at the eye (the origin of
/// the canonical frame): what decides how far a honeycomb is walked
/// ([`crate::Shape::for_footprint`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelFootprint {
    /// The smallest angle between the primary rays of two neighbouring
    /// pixels anywhere in the picture, in radians.
    pub smallest: f64,
    /// For a flat image plane (net 0): its axis (+z in the canonical
    /// frame) and a lower bound of the angle between neighbouring pixels'
    /// rays at its middle, `a`; a ray at `θ` from the axis has neighbours
    /// at least `a cos² θ` away.
    pub plane: Option<(DVec3, f64)>,
}

/// The camera's canonical frame: the isometry that takes the eye to the
/// origin, the view direction to +z and up to +y, and the view-plane
/// distance there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CanonicalFrame {
    /// Maps the scene into the canonical frame: `stages[1] ∘ stages[0]`.
    pub to_canonical: Isometry,
    /// The same map in two stages, to be applied in turn: the transvection
    /// taking the eye to the origin, then the rotation. A far point moved by
    /// the composite `R(-eye) (+) R P` is rotated first, and the rotation's
    /// rounding of the two far vectors survives their cancellation; in
    /// stages, `(-eye) (+) P` cancels the exactly stored coordinates and
    /// only the near result is rotated (`docs/geometry.md`, section 16.5).
    pub stages: [Isometry; 2],
    /// Euclidean distance `f = tanh(d/2)` from the origin to the view plane
    /// in the canonical frame, `d` the hyperbolic eye-target distance.
    pub view_distance: f64,
}

impl CanonicalFrame {
    /// The frame of `camera` ([`canonical_frame`]); `None` when its view
    /// and up directions are degenerate.
    pub fn of(camera: &Camera) -> Option<CanonicalFrame> {
        canonical_frame(camera)
    }

    /// A point's image in the canonical frame, stage by stage (see
    /// [`CanonicalFrame::stages`]).
    pub fn apply(&self, p: &Point) -> Point {
        self.stages.iter().fold(*p, |p, iso| iso.apply(&p))
    }

    /// The view target's image in the canonical frame, on the +z axis.
    pub fn target(&self, camera: &Camera) -> Point {
        self.apply(&camera.target)
    }
}

/// The camera's [`CanonicalFrame`]. First the transvection taking the eye
/// to the origin; there the view direction is the diameter towards the
/// moved target, and up is the direction towards the moved up point, made
/// orthogonal to it (default: the image of the ball's `+y` at the eye).
/// Then the rotation taking (right, up, view) to (x, y, z), with right = up
/// x view: screen x grows to the right, y upwards, z away from the eye.
/// `None` when view and up are degenerate.
pub fn canonical_frame(camera: &Camera) -> Option<CanonicalFrame> {
    let to_origin = Isometry::transvection_from_origin(camera.eye).inverse();
    let target = to_origin.apply(&camera.target);
    let view = target.coords().normalize();
    let up_hint = match &camera.up {
        Some(u) => to_origin.apply(u).coords(),
        None => to_origin.apply_direction(&camera.eye, DVec3::Y),
    };
    let up = (up_hint - view * up_hint.dot(view)).normalize();
    let right = up.cross(view);
    if !(view.is_finite() && up.is_finite() && right.is_finite()) {
        return None;
    }
    // Rows right, up, view: maps those vectors to x, y, z.
    let rotation = Isometry::orthogonal_unchecked(DMat3::from_cols(right, up, view).transpose());
    Some(CanonicalFrame {
        to_canonical: rotation.compose(&to_origin),
        stages: [to_origin, rotation],
        view_distance: target.coords().length(),
    })
}

/// Why a field of view gives no window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FovError {
    /// Not strictly between 0 and 180 degrees.
    OutOfRange,
    /// Nets 1-4 sample the view h-plane, which the eye sees under less
    /// than 180 degrees: twice the angle of parallelism of the distance to
    /// the target, `2 atan(1 / sinh d)`. Holds that limit in degrees.
    BeyondViewPlane(f64),
}

/// The widest field of view, in degrees (exclusive), that `net` can show
/// with the view plane at Euclidean distance `f` from the eye: 180 for net
/// 0, `2 atan((1 - f^2) / (2 f)) = 2 atan(1 / sinh d)` for the others.
pub fn max_fov_degrees(net: Net, view_distance: f64) -> f64 {
    match net {
        Net::Euclidean => 180.0,
        _ => {
            let f = view_distance;
            2.0 * ((1.0 - f) * (1.0 + f)).atan2(2.0 * f).to_degrees()
        }
    }
}

/// The window of `net` whose middle row spans `fov_degrees` at the eye.
///
/// - Net 0 (points `(w sx, h sy, f)`): `w = 2 f tan(fov/2)`.
/// - Nets 2 and 4 (disk points `u` moved by `T_f`): the ray through the
///   moved point `(u, 0, 0)` makes `tan(theta) = (1 - f^2) u / (f (1 + u^2))`
///   with the axis, so `u` is the smaller root of `f t u^2 - (1 - f^2) u + f t
///   = 0` with `t = tan(fov/2)`, written `u = 2 f t / ((1 - f^2) + sqrt((1 -
///   f^2)^2 - 4 f^2 t^2))` to avoid cancellation; `w = 2 u`.
/// - Nets 1 and 3 (hyperbolic distances `a` along the disk): the middle
///   row's end lies at disk point `u = tanh(a/2)`, so `w = 2 a = 4 atanh u`.
pub fn fov_window(
    fov_degrees: f64,
    net: Net,
    resolution: Resolution,
    view_distance: f64,
) -> Result<Window, FovError> {
    if !(fov_degrees > 0.0 && fov_degrees < 180.0) {
        return Err(FovError::OutOfRange);
    }
    let t = (fov_degrees.to_radians() / 2.0).tan();
    let f = view_distance;
    let width = match net {
        Net::Euclidean => 2.0 * f * t,
        _ => {
            let max = max_fov_degrees(net, f);
            let one_minus = (1.0 - f) * (1.0 + f);
            let disc = one_minus * one_minus - 4.0 * f * f * t * t;
            if !(fov_degrees < max && disc > 0.0) {
                return Err(FovError::BeyondViewPlane(max));
            }
            let u = 2.0 * f * t / (one_minus + disc.sqrt());
            match net {
                Net::GreatDisk | Net::EquidistantInterpolated => 2.0 * u,
                _ => 4.0 * u.atanh(),
            }
        }
    };
    let aspect = f64::from(resolution.height()) / f64::from(resolution.width());
    Ok(Window {
        width,
        height: width * aspect,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let c = CanonicalFrame::of(&cam).unwrap();
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
        let c = CanonicalFrame::of(&cam).unwrap();
        assert!(c.to_canonical.apply(&cam.eye).coords().length() < 1e-15);
        let t = c.target(&cam).coords();
        assert!(t.x.abs() < 1e-14 && t.y.abs() < 1e-14 && t.z > 0.0);
        let u = c.to_canonical.apply(&cam.up.unwrap()).coords();
        assert!(u.y > 0.0 && u.x.abs() < 1e-14);
    }

    #[test]
    fn a_degenerate_camera_has_no_frame() {
        // Up lies on the line of sight.
        let cam = Camera {
            eye: Point::ORIGIN,
            target: p(0.0, 0.0, 0.3),
            up: Some(p(0.0, 0.0, 0.5)),
        };
        assert!(CanonicalFrame::of(&cam).is_none());
    }

    const SQUARE: Resolution = Resolution::new(100, 100).unwrap();

    /// `fov = 60` at `f = 0.1` is the window 0.11547 of net 0; a wide
    /// resolution keeps the pixels square.
    #[test]
    fn net0_window_is_2f_tan() {
        let w = fov_window(60.0, Net::Euclidean, SQUARE, 0.1).unwrap();
        assert!((w.width - 0.115_470_053_837_925_15).abs() < 1e-15);
        assert_eq!(w.width, w.height);
        let wide = Resolution::new(200, 100).unwrap();
        let w = fov_window(90.0, Net::Euclidean, wide, 0.25).unwrap();
        assert!((w.width - 0.5).abs() < 1e-15 && (w.height - 0.25).abs() < 1e-15);
        assert_eq!(
            fov_window(180.0, Net::Euclidean, SQUARE, 0.1),
            Err(FovError::OutOfRange)
        );
        assert_eq!(
            fov_window(0.0, Net::Euclidean, SQUARE, 0.1),
            Err(FovError::OutOfRange)
        );
    }

    /// The edge ray of the middle row, as the net maps it, makes exactly
    /// fov/2 with the axis: checked against the Möbius translation written
    /// out for nets 2 and 4, and through `u = tanh(a/2)` for nets 1 and 3.
    #[test]
    fn disk_nets_open_the_asked_angle() {
        for f in [0.05, 0.1, 0.3, 0.6] {
            for fov in [10.0, 45.0, 60.0, 90.0] {
                for net in [
                    Net::GreatDisk,
                    Net::EquidistantInterpolated,
                    Net::HyperparallelLines,
                    Net::Equidistant,
                ] {
                    let Ok(w) = fov_window(fov, net, SQUARE, f) else {
                        assert!(fov >= max_fov_degrees(net, f), "{net:?} {f} {fov}");
                        continue;
                    };
                    let u = match net {
                        Net::GreatDisk | Net::EquidistantInterpolated => w.width / 2.0,
                        _ => (w.width / 4.0).tanh(),
                    };
                    // T_f(u, 0, 0) = ((1 - f^2) u, 0, (1 + u^2) f) / (1 + f^2 u^2).
                    let angle = ((1.0 - f * f) * u).atan2((1.0 + u * u) * f);
                    assert!(
                        (angle.to_degrees() - fov / 2.0).abs() < 1e-10,
                        "{net:?} {f} {fov}"
                    );
                }
            }
        }
    }

    /// The limit is twice the angle of parallelism of the target distance:
    /// `d = 2 atanh f`, `Pi(d) = atan(1 / sinh d)`.
    #[test]
    fn disk_nets_stop_at_the_angle_of_parallelism() {
        let f: f64 = 0.3;
        let d = 2.0 * f.atanh();
        let limit = 2.0 * (1.0 / d.sinh()).atan().to_degrees();
        assert!((max_fov_degrees(Net::GreatDisk, f) - limit).abs() < 1e-10);
        assert_eq!(
            fov_window(limit + 1.0, Net::GreatDisk, SQUARE, f),
            Err(FovError::BeyondViewPlane(max_fov_degrees(
                Net::GreatDisk,
                f
            )))
        );
        assert!(fov_window(limit - 1.0, Net::Equidistant, SQUARE, f).is_ok());
    }
}
