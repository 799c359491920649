//! The lint for an `up` point written as if it were a direction
//! (`HSC1012`). `up` is a point: the camera's up is the direction from the
//! eye towards it, made orthogonal to the line of sight. With the eye at
//! the origin a point and the direction to it agree, so `up = (0, 0.3, 0)`
//! means "+y"; with the eye elsewhere the direction from the eye to that
//! point can be far from `(0, 1, 0)` carried to the eye, and the picture
//! rolls (about 60° in a fly-through a user reported). The lint compares,
//! in the view plane, the up the point gives with the up its coordinates
//! give read as a direction at the eye; it warns when they differ by more
//! than [`ROLL_WARNING_DEGREES`] while the coordinates read as a direction
//! name (within that angle) the default up, `+y` carried to the eye, and
//! the point lies nearer the origin's side than the eye's (at least half as
//! far from the eye as the origin is): the mark of a direction written
//! where a point belongs. An up point placed deliberately (near the eye in
//! the wanted direction, or off to roll the picture on purpose, or a whole
//! scene moved far from the origin) is not linted.

use hgeom::glam::DVec3;
use hgeom::{HLine, Isometry};

use super::Lowerer;
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::Camera;

/// Rolls larger than this are linted.
pub(super) const ROLL_WARNING_DEGREES: f64 = 30.0;

impl Lowerer<'_> {
    /// Lint an explicit `up` point that rolls the camera away from its
    /// coordinates read as a direction (module docs).
    pub(super) fn lint_up_roll(&mut self, camera: &Camera) {
        let (Some(up), Some(span)) = (camera.up, self.up_span()) else {
            return;
        };
        let written = up.coords();
        if !(written.length() > 0.0) {
            return;
        }
        // A point placed near the eye was placed as a point.
        if up.distance(camera.eye) < 0.5 * camera.eye.distance_from_origin() {
            return;
        }
        let to_origin = Isometry::transvection_from_origin(camera.eye).inverse();
        let view = to_origin.apply(&camera.target).coords().normalize();
        let in_view_plane = |v: DVec3| (v - view * v.dot(view)).normalize();
        let actual = in_view_plane(to_origin.apply(&up).coords());
        let meant = in_view_plane(to_origin.apply_direction(&camera.eye, written.normalize()));
        let default = in_view_plane(to_origin.apply_direction(&camera.eye, DVec3::Y));
        if !(actual.is_finite() && meant.is_finite() && default.is_finite()) {
            return;
        }
        let angle = |a: DVec3, b: DVec3| a.dot(b).clamp(-1.0, 1.0).acos().to_degrees();
        let roll = angle(actual, meant);
        if roll <= ROLL_WARNING_DEGREES || angle(meant, default) > ROLL_WARNING_DEGREES {
            return;
        }
        let suggestion = HLine::from_point_direction(&camera.eye, written)
            .and_then(|l| l.point_at(0.1))
            .map(|p| {
                let c = p.coords();
                format!(
                    "; for `({}, {}, {})` as the up direction, put the point near the eye that way: `up = ({:.4}, {:.4}, {:.4});`",
                    hgeom::Compact(written.x),
                    hgeom::Compact(written.y),
                    hgeom::Compact(written.z),
                    c.x,
                    c.y,
                    c.z
                )
            })
            .unwrap_or_default();
        self.report(
            Diagnostic::new(
                Code::UpRoll,
                span,
                format!(
                    "`up` is a point, not a direction: from this eye it rolls the picture {roll:.0}° from the direction its coordinates name"
                ),
            )
            .with_help(format!(
                "the camera's up points from the eye towards the up point{suggestion}"
            )),
        );
    }
}

#[cfg(test)]
mod tests {
    use crate::diagnostic::Code;

    fn rolls(src: &str) -> bool {
        crate::compile(src)
            .diagnostics
            .iter()
            .any(|d| d.code == Code::UpRoll)
    }

    /// The reported case: an eye off the origin and `up` written like a
    /// direction rolls the picture and is linted; the same `up` from the
    /// origin, an up point placed near the eye, or one placed to roll the
    /// picture on purpose, is not.
    #[test]
    fn an_up_point_written_as_a_direction_is_linted_off_the_origin() {
        let objects = "BRDFs { diffuse = (1, 1, 1); } Objects { Sphere (0, 0, 0.6), 0.1, #1; }";
        assert!(rolls(&format!(
            "Globals {{ from = (0.5, 0.5, 0); to = (0, 0, 0.6); up = (0, 0.3, 0); }} {objects}"
        )));
        assert!(!rolls(&format!(
            "Globals {{ from = (0, 0, 0); to = (0, 0, 0.6); up = (0, 0.3, 0); }} {objects}"
        )));
        assert!(!rolls(&format!(
            "Globals {{ from = (0.5, 0.5, 0); to = (0, 0, 0.6); up = (0.5, 0.6, 0); }} {objects}"
        )));
        assert!(!rolls(&format!(
            "Globals {{ from = (0.5, 0.5, 0); to = (0, 0, 0.6); up = (0.6, 0.45, 0); }} {objects}"
        )));
    }
}
