//! The lint for objects outside every view ray of net 0 (`HSC1005`, which
//! also covers objects behind the eye).
//!
//! In the camera's canonical frame (eye at the origin, view +z, up +y) net
//! 0 looks along the diameters through the window `[-w/2, w/2] x [-h/2,
//! h/2]` at height `f` (the ball coordinate of the target); the rays fill
//! the cone bounded by four h-planes through the eye, which in the ball
//! are flat planes through the origin, with inward Euclidean normals
//! `(-f, 0, w/2)`, `(f, 0, w/2)`, `(0, -f, h/2)` and `(0, f, h/2)`. An
//! object entirely on the outer side of one of them meets no view ray. The
//! other nets look through the view h-plane, whose visible part is not
//! bounded by four planes through the eye; they keep the behind-the-eye
//! lint only. Lights are not linted: lights are meant to shine from
//! outside the picture.

use hgeom::glam::DVec3;

use super::Lowerer;
use super::seen_from::SeenFrom;
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::{Camera, Net};
use crate::view::{canonical_frame, fov_window};

impl Lowerer<'_> {
    /// Report each object statement whose objects all lie outside the view
    /// of net 0 (and not behind the eye, which the scene lint reports).
    pub(super) fn lint_outside_view(&mut self, camera: &Camera) {
        // In a quotient space rays come back through the gluing: what is
        // outside the window is seen in it again.
        if self.settings.net != Net::Euclidean || self.settings.space.is_some() {
            return;
        }
        let Some(crate::view::CanonicalFrame {
            stages: [_, rotation],
            view_distance: f,
            ..
        }) = canonical_frame(camera)
        else {
            return;
        };
        // Decided in the eye's own frame (see `seen_from`): the canonical
        // frame is that frame turned by `rotation`, so a direction `m` there
        // is `R^T m` here.
        let eye = SeenFrom::new(camera.eye);
        let unturn = rotation.linear_part().transpose();
        let window = match self.settings.fov {
            Some(fov) => match fov_window(fov, Net::Euclidean, self.settings.resolution, f) {
                Ok(w) => w,
                Err(_) => return,
            },
            None => self.settings.window,
        };
        let (hw, hh) = (window.width / 2.0, window.height / 2.0);
        // The inward normals of the four h-planes through the eye and the
        // window's edges: an object entirely behind one of them is unseen.
        let sides: Vec<DVec3> = [
            DVec3::new(-f, 0.0, hw),
            DVec3::new(f, 0.0, hw),
            DVec3::new(0.0, -f, hh),
            DVec3::new(0.0, f, hh),
        ]
        .into_iter()
        .map(|m| (unturn * m).normalize())
        .filter(|m| m.is_finite())
        .collect();
        let behind = eye.direction_to(&camera.target);
        let mut found = Vec::new();
        for group in self.objects.chunk_by(|a, b| a.1 == b.1) {
            let span = group[0].1;
            let all_behind = |v: &DVec3| group.iter().all(|(o, _)| eye.is_behind(&o.shape, *v));
            if behind.as_ref().is_some_and(all_behind) {
                continue;
            }
            if sides.iter().any(all_behind) {
                found.push(
                    Diagnostic::new(
                        Code::ObjectBehindEye,
                        span,
                        "this object is outside the window: no view ray reaches it",
                    )
                    .with_help("widen `fov` or `window_size`, aim `to` at it, or remove it"),
                );
            }
        }
        self.diags.extend(found);
    }
}

/// The share of the angles a great-disk picture shows that may fall in
/// the central tenth of its window before the picture counts as squeezed.
const SQUEEZE: f64 = 0.75;

/// The angle from the view axis of the net-2 ray through the disk point at
/// distance `r` from the disk's centre, the disk moved to the view plane at
/// ball height `f`: the Möbius translation of `(r, 0, 0)` by `(0, 0, f)` is
/// `((1 - f²) r, 0, (1 + r²) f) / (1 + f² r²)`.
fn disk_ray_angle(r: f64, f: f64) -> f64 {
    ((1.0 - f * f) * r).atan2((1.0 + r * r) * f)
}

impl Lowerer<'_> {
    /// Nets 2 and 4 show the great disk moved onto the view plane: with the
    /// target very near the eye, the disk's every point but the middle is
    /// seen almost sideways, and all the directions in front of the eye
    /// crowd into the central pixels (`HSC1011`).
    pub(super) fn lint_squeezed_disk(&mut self, camera: &Camera) {
        if !matches!(
            self.settings.net,
            Net::GreatDisk | Net::EquidistantInterpolated
        ) {
            return;
        }
        let Some(span) = self.target_span() else {
            return;
        };
        let Some(frame) = canonical_frame(camera) else {
            return;
        };
        let f = frame.view_distance;
        let window = match self.settings.fov {
            Some(fov) => match fov_window(fov, self.settings.net, self.settings.resolution, f) {
                Ok(w) => w,
                Err(_) => return,
            },
            None => self.settings.window,
        };
        let r = (window.width.max(window.height) / 2.0).min(1.0);
        let share = disk_ray_angle(0.1 * r, f) / disk_ray_angle(r, f);
        if share > SQUEEZE {
            self.report(
                Diagnostic::new(
                    Code::SqueezedDisk,
                    span,
                    format!(
                        "with `to` this close to the eye, net {} crowds {:.0} % of the directions it shows into the central tenth of the picture",
                        self.settings.net.index(),
                        100.0 * share
                    ),
                )
                .with_help("move `to` farther from the eye (a ball distance of 0.1 or more suits most pictures), or use net 0 with `fov`"),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::diagnostic::Code;

    /// Net 2 with `to` a hair from the eye crowds nearly every direction
    /// into the middle and is linted; the usual distance is not, nor net 0.
    #[test]
    fn a_great_disk_squeezed_by_a_near_target_is_linted() {
        let squeezed = |to: f64, net: u32| {
            let src = format!(
                "Globals {{ net_type = {net}; to = (0, 0, {to}); window_size = (1.6, 1.6); }}
                 BRDFs {{ diffuse = (1, 1, 1); }} Objects {{ Sphere (0, 0, 0.3), 0.05, #1; }}"
            );
            crate::compile(&src)
                .diagnostics
                .iter()
                .any(|d| d.code == Code::SqueezedDisk)
        };
        assert!(squeezed(0.005, 2));
        assert!(squeezed(0.005, 4));
        assert!(!squeezed(0.1, 2));
        assert!(!squeezed(0.45, 2));
        assert!(!squeezed(0.005, 0));
        // The angle formula: the disk's centre looks straight ahead, its
        // rim (r = 1, translated) at `atan2(1 - f², 2 f)` from the axis.
        assert_eq!(super::disk_ray_angle(0.0, 0.3), 0.0);
        let f = 0.3;
        let rim = super::disk_ray_angle(1.0, f);
        assert!((rim - (1.0 - f * f).atan2(2.0 * f)).abs() < 1e-15);
    }

    /// Lints of a scene with one sphere of radius 0.05 at ball point
    /// `(x, 0, 0.3)`, seen through `fov = 30` (half-angle 15 degrees).
    fn outside(x: f64, net: u32) -> bool {
        let src = format!(
            "Globals {{ net_type = {net}; fov = 30; }} BRDFs {{ diffuse = (1, 1, 1); }}
             Objects {{ Sphere ({x}, 0, 0.3), 0.05, #1; }}"
        );
        crate::compile(&src)
            .diagnostics
            .iter()
            .any(|d| d.code == Code::ObjectBehindEye)
    }

    /// The sphere's centre direction makes `atan(x / 0.3)` with the axis;
    /// its angular radius there is about 8 degrees. Inside the window, or
    /// straddling its edge, it is not linted; wholly beyond, it is. Nets
    /// 1-4 are not linted for the window.
    #[test]
    fn only_objects_wholly_outside_the_window_are_linted() {
        assert!(!outside(0.0, 0));
        assert!(!outside(0.1, 0)); // 18 degrees: straddles the edge
        assert!(outside(0.3, 0)); // 45 degrees
        assert!(outside(-0.3, 0));
        assert!(!outside(0.3, 2));
    }
}
