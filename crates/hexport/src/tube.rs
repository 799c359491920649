//! Rods, honeycomb edges and cylinders: the points within hyperbolic
//! distance `w` of a piece of a geodesic, as the closed surface the
//! mesher grids.
//!
//! **Exact points.** The geodesic is `P(s) = cosh s A + sinh s T` (`A` a
//! point of it, `T` the unit tangent there), with unit tangent
//! `τ(s) = sinh s A + cosh s T`; `N1`, `N2` complete `A`, `T` to an orthonormal basis, and
//! being orthogonal to the geodesic's plane they are parallel along it. A
//! point at distance `w` from `P(s)` in the direction `d` (a unit vector
//! orthogonal to `P(s)`) is `cosh w P(s) + sinh w d`. The surface is: a
//! hemisphere about `P(s0)` (`d = -cos ψ τ + sin ψ N(θ)`, `ψ` from 0 to
//! `π/2`), the tube (`d = N(θ) = cos θ N1 + sin θ N2`, `s` from `s0` to
//! `s1`), and a hemisphere about `P(s1)` (`ψ` from `π/2` to `π`): exactly
//! what a rod is.
//!
//! **Where a tube is cut.** The Euclidean image of the cross-section at
//! `s` is a circle; its diameter, from three of its exact points, is the
//! tube's printed thickness there. It is largest near the point of the
//! geodesic nearest the ball's centre and falls off monotonically towards
//! both ends, so the part thick enough is one interval of `s`, found by
//! bisection. Thickened tubes keep the whole length and take, at each
//! `s`, the radius whose cross-section is exactly the minimum where `w`
//! alone is thinner (again by bisection).

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use hgeom::HLine;
use hgeom::glam::{DVec3, DVec4};

use crate::grid::PoleSurface;
use crate::measure::{circle_diameter, to_ball};

/// The most `|s|` a tube reaches from its line's base point: beyond,
/// `cosh s` leaves the range where the ball map keeps its digits, and no
/// part of a print is that thin anyway (its thickness is about
/// `2 e^{-|s|}`).
const FAR: f64 = 30.0;

/// A geodesic with its frame, and a range of it.
#[derive(Clone, Copy, Debug)]
pub struct Axis {
    a: DVec4,
    t: DVec4,
    n1: DVec4,
    n2: DVec4,
    /// The range of `s`, finite or infinite at ideal ends.
    pub from: f64,
    /// The end of the range.
    pub to: f64,
}

impl Axis {
    /// The axis of a line, over `[from, to]` of its parameter.
    pub fn of_line(line: &HLine, from: f64, to: f64) -> Axis {
        let m = line.lorentz_basis();
        Axis {
            a: m.w_axis,
            t: m.z_axis,
            n1: m.x_axis,
            n2: m.y_axis,
            from,
            to,
        }
    }

    /// The point at `s`.
    pub fn point(&self, s: f64) -> DVec4 {
        self.at(s)
    }

    fn at(&self, s: f64) -> DVec4 {
        s.cosh() * self.a + s.sinh() * self.t
    }

    /// The tangent at `s`.
    fn tangent(&self, s: f64) -> DVec4 {
        s.sinh() * self.a + s.cosh() * self.t
    }

    /// The normal direction at angle `theta`.
    fn normal(&self, theta: f64) -> DVec4 {
        theta.cos() * self.n1 + theta.sin() * self.n2
    }

    /// The point at distance `w` from `P(s)` in direction `d`.
    fn off(&self, s: f64, w: f64, d: DVec4) -> DVec3 {
        to_ball(w.cosh() * self.at(s) + w.sinh() * d)
    }

    /// The Euclidean diameter of the cross-section of radius `w` at `s`.
    pub fn thickness(&self, s: f64, w: f64) -> f64 {
        let p = |theta: f64| self.off(s, w, self.normal(theta));
        circle_diameter(p(0.0), p(2.0 * PI / 3.0), p(4.0 * PI / 3.0))
    }

    /// The Euclidean distance from the ball's centre of the point at `s`.
    pub fn ball_radius(&self, s: f64) -> f64 {
        to_ball(self.at(s)).length()
    }

    /// The parameter of the point nearest the ball's centre, in the range.
    pub fn nearest_centre(&self) -> f64 {
        // -<O, P(s)> = cosh s a_w + sinh s t_w is least where
        // tanh s = -t_w / a_w (|t_w| < a_w for a timelike a).
        let s = (-self.t.w / self.a.w).atanh();
        s.clamp(self.from.max(-FAR), self.to.min(FAR))
    }

    /// The range's ends, clamped to what f64 holds.
    fn finite_ends(&self) -> (f64, f64) {
        (self.from.max(-FAR), self.to.min(FAR))
    }

    /// The sub-range where `keep(s)` holds, assuming it holds on an
    /// interval about [`Axis::nearest_centre`]; `None` if it fails there.
    pub fn trimmed(&self, keep: impl Fn(f64) -> bool) -> Option<Axis> {
        let mid = self.nearest_centre();
        if !keep(mid) {
            return None;
        }
        let (lo, hi) = self.finite_ends();
        let edge = |inside: f64, outside: f64| {
            if keep(outside) {
                return outside;
            }
            let (mut a, mut b) = (inside, outside);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if keep(m) {
                    a = m;
                } else {
                    b = m;
                }
            }
            a
        };
        Some(Axis {
            from: edge(mid, lo),
            to: edge(mid, hi),
            ..*self
        })
    }

    /// True if both ends are points (not ideal, not beyond f64).
    pub fn is_finite(&self) -> bool {
        self.from > -FAR && self.to < FAR
    }

    /// The Euclidean distance between the ends.
    pub fn chord(&self) -> f64 {
        let (lo, hi) = self.finite_ends();
        (to_ball(self.at(hi)) - to_ball(self.at(lo))).length()
    }
}

/// The radius of a tube along its axis.
#[derive(Clone, Copy, Debug)]
pub enum TubeRadius {
    /// One hyperbolic radius throughout.
    Exact(f64),
    /// At least `base`, and wherever that is thinner than `min` (ball
    /// units), the radius that makes it `min` thick.
    Thickened {
        /// The object's radius.
        base: f64,
        /// The least printed thickness.
        min: f64,
    },
}

/// Samples of a thickened tube's radius along its axis.
const PROFILE_SAMPLES: usize = 256;

/// A capsule: the surface at a radius from a geodesic segment.
pub struct Capsule {
    /// The segment.
    pub axis: Axis,
    /// The radius.
    pub radius: TubeRadius,
    /// A thickened tube's radius at `PROFILE_SAMPLES + 1` evenly spaced
    /// parameters, interpolated between (the thickening is a choice of
    /// shape, not a surface to follow exactly; an exact tube has none).
    profile: Vec<f64>,
    /// Where the grid's columns start round the axis: a different angle
    /// for each tube (from its frame), so that tubes meeting at a vertex
    /// share no grid point. STL keeps no topology; readers weld equal
    /// points, and two shells welded at a point are no longer manifold.
    phase: f64,
}

impl Capsule {
    /// The capsule about `axis` (finite ends) of this radius.
    pub fn new(axis: Axis, radius: TubeRadius) -> Capsule {
        let seed = axis.a.dot(DVec4::new(12.9898, 78.233, 37.719, 0.0))
            + axis.t.dot(DVec4::new(4.898, 7.23, 23.1407, 1.0));
        let phase = TAU * (seed * 43_758.545_3).rem_euclid(1.0);
        let mut capsule = Capsule {
            axis,
            radius,
            profile: Vec::new(),
            phase,
        };
        if let TubeRadius::Thickened { base, min } = radius {
            capsule.profile = (0..=PROFILE_SAMPLES)
                .map(|k| {
                    let f = k as f64 / PROFILE_SAMPLES as f64;
                    capsule.thickened(axis.from + f * (axis.to - axis.from), base, min)
                })
                .collect();
        }
        capsule
    }

    /// The hyperbolic radius at `s`.
    pub fn radius_at(&self, s: f64) -> f64 {
        match self.radius {
            TubeRadius::Exact(w) => w,
            TubeRadius::Thickened { .. } => {
                let span = self.axis.to - self.axis.from;
                let x = if span > 0.0 {
                    ((s - self.axis.from) / span).clamp(0.0, 1.0) * PROFILE_SAMPLES as f64
                } else {
                    0.0
                };
                // x is in [0, PROFILE_SAMPLES].
                let k = (x.floor() as usize).min(PROFILE_SAMPLES - 1);
                let f = x - k as f64;
                self.profile[k] * (1.0 - f) + self.profile[k + 1] * f
            }
        }
    }

    /// The radius of a thickened tube at `s`: `base`, or where that is
    /// thinner than `min`, the radius that is `min` thick (bisection).
    fn thickened(&self, s: f64, base: f64, min: f64) -> f64 {
        if self.axis.thickness(s, base) >= min {
            return base;
        }
        let (mut a, mut b) = (base, base);
        while self.axis.thickness(s, b) < min && b < 20.0 {
            a = b;
            b *= 2.0;
        }
        for _ in 0..50 {
            let m = 0.5 * (a + b);
            if self.axis.thickness(s, m) < min {
                a = m;
            } else {
                b = m;
            }
        }
        b
    }
}

impl PoleSurface for Capsule {
    fn point(&self, u: f64, v: f64) -> DVec3 {
        let (s0, s1) = (self.axis.from, self.axis.to);
        let theta = TAU * v + self.phase;
        let (s, psi) = if u <= 1.0 / 3.0 {
            (s0, 3.0 * u * FRAC_PI_2)
        } else if u <= 2.0 / 3.0 {
            (s0 + (3.0 * u - 1.0) * (s1 - s0), FRAC_PI_2)
        } else {
            (s1, FRAC_PI_2 + (3.0 * u - 2.0) * FRAC_PI_2)
        };
        let d = -psi.cos() * self.axis.tangent(s) + psi.sin() * self.axis.normal(theta);
        self.axis.off(s, self.radius_at(s), d)
    }

    fn u_creases(&self) -> Vec<f64> {
        vec![0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    }

    fn v_creases(&self) -> Vec<f64> {
        vec![0.0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::{Point, lorentz};

    /// The line's basis is the frame the tube's points are built from:
    /// `A` on the hyperboloid, `T`, `N1`, `N2` unit and orthogonal to it.
    #[test]
    fn the_axis_frame_is_orthonormal_and_thickest_nearest_the_centre() {
        let a = Point::new(0.3, -0.1, 0.2).unwrap();
        let b = Point::new(-0.4, 0.5, 0.1).unwrap();
        let line = HLine::through(&a.into(), &b.into()).unwrap();
        let axis = Axis::of_line(&line, -5.0, 5.0);
        let close = |x: f64, y: f64| (x - y).abs() < 1e-12;
        assert!(close(lorentz::dot(axis.a, axis.a), -1.0));
        assert!(close(lorentz::dot(axis.t, axis.t), 1.0));
        for n in [axis.n1, axis.n2] {
            assert!(close(lorentz::dot(n, n), 1.0));
            assert!(close(lorentz::dot(n, axis.a), 0.0));
            assert!(close(lorentz::dot(n, axis.t), 0.0));
        }
        let mid = axis.nearest_centre();
        let thick = axis.thickness(mid, 0.1);
        for ds in [-0.5, -0.1, 0.1, 0.5] {
            assert!(axis.thickness(mid + ds, 0.1) < thick);
        }
    }
}
