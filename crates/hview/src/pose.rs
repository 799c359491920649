//! The flying camera as an element of the Lorentz group: the matrix whose
//! columns are the camera's right, up and forward unit tangents and its
//! eye, all in the scene's hyperboloid coordinates (the inverse of the
//! render's canonical frame). A move is a Lorentz matrix in the camera's
//! own frame composed on the right: a boost along an axis (a step along
//! the geodesic leaving the eye that way) or a rotation about the eye.
//! Both are exact isometries; only rounding drifts, and
//! [`Pose::renormalise`] takes it out after every move (Gram-Schmidt in the
//! Lorentz metric, eye first), so the columns stay orthonormal to about
//! one rounding and an hour of flying stays an isometry.

use hgeom::glam::{DMat4, DVec4};
use hgeom::{Point, lorentz};
use hscene_ir::Camera;
use hscene_ir::view::CanonicalFrame;

/// The distance of the up point the camera is written back with.
const UP_POINT_DISTANCE: f64 = 0.5;

/// An axis of the camera's own frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// To the right of the picture (`x`).
    Right,
    /// Up in the picture (`y`).
    Up,
    /// Along the line of sight (`z`).
    Forward,
}

impl Axis {
    fn index(self) -> usize {
        match self {
            Axis::Right => 0,
            Axis::Up => 1,
            Axis::Forward => 2,
        }
    }
}

/// A move in the camera's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Move {
    /// Along the geodesic leaving the eye along an axis, this far.
    Step(Axis, f64),
    /// About an axis through the eye, this many radians (right-handed).
    Turn(Axis, f64),
}

impl Move {
    /// The move's Lorentz matrix in the camera's frame.
    pub fn matrix(self) -> DMat4 {
        let mut m = DMat4::IDENTITY;
        match self {
            Move::Step(axis, d) => {
                let a = axis.index();
                let (c, s) = (d.cosh(), d.sinh());
                m.col_mut(a)[a] = c;
                m.col_mut(a)[3] = s;
                m.col_mut(3)[a] = s;
                m.col_mut(3)[3] = c;
            }
            Move::Turn(axis, angle) => {
                // The plane of the other two axes, turned right-handedly.
                let (i, j) = match axis {
                    Axis::Right => (1, 2),
                    Axis::Up => (2, 0),
                    Axis::Forward => (0, 1),
                };
                let (c, s) = (angle.cos(), angle.sin());
                m.col_mut(i)[i] = c;
                m.col_mut(i)[j] = s;
                m.col_mut(j)[i] = -s;
                m.col_mut(j)[j] = c;
            }
        }
        m
    }

    /// The move that undoes this one.
    pub fn inverse(self) -> Move {
        match self {
            Move::Step(a, d) => Move::Step(a, -d),
            Move::Turn(a, t) => Move::Turn(a, -t),
        }
    }
}

/// The camera's pose (module docs), with the eye-target distance it keeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// Columns right, up, forward, eye.
    frame: DMat4,
    /// The hyperbolic distance from the eye to the view target.
    target_distance: f64,
}

impl Pose {
    /// The pose of a scene's camera; `None` for a degenerate camera.
    pub fn of(camera: &Camera) -> Option<Pose> {
        let frame = CanonicalFrame::of(camera)?;
        let target_distance = 2.0 * frame.view_distance.atanh();
        let mut pose = Pose {
            frame: frame.to_canonical.inverse().to_lorentz(),
            target_distance,
        };
        pose.renormalise();
        Some(pose)
    }

    /// The Lorentz matrix (columns right, up, forward, eye).
    pub fn matrix(&self) -> DMat4 {
        self.frame
    }

    /// The eye on the hyperboloid.
    pub fn eye(&self) -> DVec4 {
        self.frame.w_axis
    }

    /// The pose after `m`, renormalised; `None` (and no change) if the eye
    /// would leave what f64 can represent as a ball point.
    pub fn moved(&self, m: Move) -> Option<Pose> {
        let mut next = Pose {
            frame: self.frame * m.matrix(),
            target_distance: self.target_distance,
        };
        next.renormalise();
        next.camera().map(|_| next)
    }

    /// The same view with the eye folded into the fundamental domain of a
    /// quotient space (`space = NAME`): the scene is the same from every
    /// copy of the domain, so the picture does not change, but the eye
    /// stays near the origin however far one flies, instead of leaving
    /// f64's range after a few dozen units. Left as it is when the fold
    /// would reflect the view (a mirrored cell) or cannot be found.
    pub fn folded(&self, space: &hgeom::QuotientSpace) -> Pose {
        let Some(eye) = Point::from_hyperboloid(self.frame.w_axis) else {
            return *self;
        };
        match space.fold(&eye) {
            Ok(g) if g.preserves_orientation() => {
                let mut next = Pose {
                    frame: g.to_lorentz() * self.frame,
                    target_distance: self.target_distance,
                };
                next.renormalise();
                next
            }
            _ => *self,
        }
    }

    /// Gram-Schmidt in the Lorentz metric: the eye normalised to the
    /// hyperboloid, then right, up and forward made orthogonal to it and to
    /// one another, and unit.
    pub fn renormalise(&mut self) {
        let mut cols = [
            self.frame.x_axis,
            self.frame.y_axis,
            self.frame.z_axis,
            self.frame.w_axis,
        ];
        let eye = cols[3];
        cols[3] = eye / (-lorentz::dot(eye, eye)).sqrt();
        for i in 0..3 {
            let mut c = cols[i];
            // <e, e> = -1: the component along e is -<c, e> e.
            c += lorentz::dot(c, cols[3]) * cols[3];
            for prev in cols.iter().take(i) {
                c -= lorentz::dot(c, *prev) * *prev;
            }
            cols[i] = c / lorentz::dot(c, c).sqrt();
        }
        self.frame = DMat4::from_cols(cols[0], cols[1], cols[2], cols[3]);
    }

    /// The camera of this pose: the eye, the target at the kept distance
    /// along the line of sight, an up point along `up`. `None` if a point
    /// leaves what f64 can represent.
    pub fn camera(&self) -> Option<Camera> {
        let along = |axis: DVec4, d: f64| {
            Point::from_hyperboloid(d.cosh() * self.frame.w_axis + d.sinh() * axis)
                .filter(|p| p.is_representable())
        };
        let eye = along(self.frame.z_axis, 0.0)?;
        let target = along(self.frame.z_axis, self.target_distance)?;
        let up = along(self.frame.y_axis, UP_POINT_DISTANCE)?;
        if eye == target {
            return None;
        }
        Some(Camera {
            eye,
            target,
            up: Some(up),
        })
    }

    /// How far this pose is from `other`: the larger of the eyes'
    /// hyperbolic distance and the largest angle between their axes (in
    /// radians, measured at the first pose's eye after moving the other's
    /// frame there, to first order the entries' difference).
    pub fn distance(&self, other: &Pose) -> f64 {
        let eyes = lorentz::distance(self.eye(), other.eye());
        let d = self.frame - other.frame;
        let axes = [d.x_axis, d.y_axis, d.z_axis]
            .iter()
            .map(|v| v.abs().max_element())
            .fold(0.0, f64::max);
        eyes.max(axes)
    }
}

/// The lines that put this camera in a scene's `Globals`.
pub fn camera_lines(camera: &Camera) -> String {
    let p = |p: &Point| {
        let c = p.coords();
        format!("({:.17}, {:.17}, {:.17})", c.x, c.y, c.z)
    };
    let mut out = format!("from = {};\nto = {};\n", p(&camera.eye), p(&camera.target));
    if let Some(up) = &camera.up {
        out += &format!("up = {};\n", p(up));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera {
            eye: Point::new(0.1, 0.2, -0.3).unwrap(),
            target: Point::new(0.2, 0.1, 0.3).unwrap(),
            up: Some(Point::new(0.1, 0.6, -0.2).unwrap()),
        }
    }

    /// Random moves and then their inverses in reverse order bring the
    /// camera back to within 1e-12, however many: renormalisation keeps
    /// the pose an isometry, so rounding does not compound. (Steps of up to
    /// 0.01: a random walk in H³ escapes at a steady speed, and longer
    /// random steps would carry the eye past f64's range in 100,000 moves;
    /// these wander a few units away and back.)
    #[test]
    fn a_hundred_thousand_steps_and_back_return_the_camera() {
        let start = Pose::of(&camera()).unwrap();
        let mut pose = start;
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let axes = [Axis::Right, Axis::Up, Axis::Forward];
        let moves: Vec<Move> = (0..100_000)
            .map(|_| {
                let axis = axes[(next() * 3.0) as usize % 3];
                if next() < 0.5 {
                    Move::Step(axis, (next() - 0.5) * 0.02)
                } else {
                    Move::Turn(axis, (next() - 0.5) * 0.2)
                }
            })
            .collect();
        let mut far: f64 = 0.0;
        for m in &moves {
            pose = pose.moved(*m).unwrap();
            far = far.max(lorentz::distance(pose.eye(), DVec4::W));
        }
        for m in moves.iter().rev() {
            pose = pose.moved(m.inverse()).unwrap();
        }
        let drift = pose.distance(&start);
        assert!(
            drift < 1e-12,
            "drift {drift:e} after wandering {far:.2} away"
        );
    }

    /// The pose of a camera gives back that camera's view: the same eye,
    /// the target on the same line of sight at the same distance, and the
    /// same canonical frame.
    #[test]
    fn the_pose_of_a_camera_gives_the_camera_back() {
        let cam = camera();
        let pose = Pose::of(&cam).unwrap();
        let back = pose.camera().unwrap();
        assert!(back.eye.distance(cam.eye) < 1e-13);
        assert!(back.target.distance(cam.target) < 1e-12);
        let (a, b) = (
            CanonicalFrame::of(&cam).unwrap(),
            CanonicalFrame::of(&back).unwrap(),
        );
        let d = a.to_canonical.to_lorentz() - b.to_canonical.to_lorentz();
        let worst = [d.x_axis, d.y_axis, d.z_axis, d.w_axis]
            .iter()
            .map(|v| v.abs().max_element())
            .fold(0.0, f64::max);
        assert!(worst < 1e-12, "{worst:e}");
    }

    /// A forward step moves the eye along the line of sight by exactly the
    /// step.
    #[test]
    fn a_step_is_a_step_along_the_line_of_sight() {
        let pose = Pose::of(&camera()).unwrap();
        let moved = pose.moved(Move::Step(Axis::Forward, 0.25)).unwrap();
        assert!((lorentz::distance(pose.eye(), moved.eye()) - 0.25).abs() < 1e-14);
        let cam = pose.camera().unwrap();
        let towards =
            cam.eye.distance(cam.target) - moved.camera().unwrap().eye.distance(cam.target);
        assert!((towards - 0.25).abs() < 1e-12);
    }
}
