//! Rods (the thesis's "h-valjak"): the points within distance `r` of an
//! h-segment. Wireframe polygons and polyhedra draw their edges with them.

use glam::DVec4;

use crate::cylinder::HCylinder;
use crate::distance::distance;
use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::line::HLine;
use crate::lorentz;
use crate::point::{Point, Vertex};
use crate::ray::{Hit, Ray};
use crate::sphere::HSphere;

/// The solid of points within hyperbolic distance `radius` of the geodesic
/// segment from `start` to `end`.
///
/// Its boundary is the part of the h-cylinder about the segment's line that
/// lies between the two h-planes orthogonal to the line at the end points,
/// closed by two hemispherical caps (halves of the h-spheres of radius `r`
/// about the end points). An ideal end point makes the rod run out to the
/// absolute on that side, with no cap: a rod between two ideal points is a
/// whole h-cylinder.
///
/// Invariants: `start != end`; `radius > 0`; each cap exists exactly when its
/// end point is an h-point, and the end planes' normals `U_start`, `U_end`
/// are the unit tangents of the line at those points, pointing from `start`
/// towards `end`.
///
/// There is no `_unchecked` constructor: building a rod (a line's Lorentz
/// basis, two spheres) costs far more than its checks, so skipping them
/// would gain nothing on any hot path.
#[derive(Clone, Debug, PartialEq)]
pub struct Rod {
    start: Vertex,
    end: Vertex,
    tube: HCylinder,
    start_cap: Option<Cap>,
    end_cap: Option<Cap>,
}

/// A hemispherical end of a rod: the sphere about the end point, and the
/// unit tangent of the axis there (the normal of the end plane).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Cap {
    sphere: HSphere,
    axis: DVec4,
}

impl Rod {
    /// The rod of hyperbolic `radius` about the segment `start -> end`.
    ///
    /// Errors: [`HLine::through`]'s (coincident ends, a point f64 cannot
    /// hold), [`HCylinder::new`]'s and [`HSphere::new`]'s
    /// ([`GeomError::BadRadius`]).
    ///
    /// # Accuracy
    ///
    /// The tube, caps and end-plane normals are each as accurate as their
    /// constructors ([`HLine::through`], [`HSphere::new`]); the end
    /// tangent `sinh(len) P + cosh(len) U` is within a few ulps of
    /// `cosh(len) |M|`.
    pub fn new(start: Vertex, end: Vertex, radius: f64) -> Result<Rod, GeomError> {
        let line = HLine::through(&start, &end)?;
        let tube = HCylinder::new(line, radius)?;
        let basis = line.lorentz_basis();
        let (p, u) = (basis.w_axis, basis.z_axis);
        // HLine::through puts the base point at `start` when it is an h-point,
        // else at `end` when that one is: the tangent there is U itself.
        let (start_cap, end_cap) = match (start, end) {
            (Vertex::Interior(a), Vertex::Interior(b)) => {
                let len = distance(&a, &b);
                let at_end = len.sinh() * p + len.cosh() * u;
                (
                    Some(Cap {
                        sphere: HSphere::new(a, radius)?,
                        axis: u,
                    }),
                    Some(Cap {
                        sphere: HSphere::new(b, radius)?,
                        axis: at_end,
                    }),
                )
            }
            (Vertex::Interior(a), Vertex::Ideal(_)) => (
                Some(Cap {
                    sphere: HSphere::new(a, radius)?,
                    axis: u,
                }),
                None,
            ),
            (Vertex::Ideal(_), Vertex::Interior(b)) => (
                None,
                Some(Cap {
                    sphere: HSphere::new(b, radius)?,
                    axis: u,
                }),
            ),
            (Vertex::Ideal(_), Vertex::Ideal(_)) => (None, None),
        };
        Ok(Rod {
            start,
            end,
            tube,
            start_cap,
            end_cap,
        })
    }

    /// First end point.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored vertex.
    pub fn start(&self) -> Vertex {
        self.start
    }

    /// Second end point.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored vertex.
    pub fn end(&self) -> Vertex {
        self.end
    }

    /// Hyperbolic radius.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored radius.
    pub fn radius(&self) -> f64 {
        self.tube.radius()
    }

    /// The h-cylinder the rod's side lies on.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored cylinder.
    pub fn tube(&self) -> HCylinder {
        self.tube
    }

    /// The image under an isometry. Exact and infallible: the tube and the
    /// caps are carried over, and the end-plane normals are derived afresh
    /// from the moved tube's Lorentz basis, as [`Rod::new`] derives them.
    ///
    /// Multiplying the old end-plane normals by the isometry's Lorentz
    /// matrix, both of size `e^d` far out, lost `eps e^{2d}`: a cap axis
    /// 0.12 off at distance 17.6 and 12 off at 19.9. The tube's Lorentz basis is the
    /// Lorentz matrix of a composed isometry, whose entries are of the size
    /// of the rod's own distance from the origin.
    ///
    /// # Accuracy
    ///
    /// As [`HCylinder::transformed`] and [`HSphere::transformed`]; the
    /// end-plane normals are within a few ulps of the basis vectors.
    /// Hits on the moved rod agree with the original's to 1e-8 relative
    /// (`isometries_preserve_hits` in `tests/surfaces.rs`), also after a
    /// move 25 away and back (`rod_moved_far_and_back` in `tests/far.rs`).
    pub fn transformed(&self, iso: &Isometry) -> Rod {
        let tube = self.tube.transformed(iso);
        let basis = tube.line().lorentz_basis();
        let (p, u) = (basis.w_axis, basis.z_axis);
        // The line's base point is the start when it is an h-point, else the
        // end (see `try_new`); isometries keep it so.
        let end_axis = match (self.start, self.end) {
            (Vertex::Interior(a), Vertex::Interior(b)) => {
                let len = distance(&a, &b);
                len.sinh() * p + len.cosh() * u
            }
            _ => u,
        };
        let cap = |c: &Cap, axis: DVec4| Cap {
            sphere: c.sphere.transformed(iso),
            axis,
        };
        Rod {
            start: iso.apply_vertex(&self.start),
            end: iso.apply_vertex(&self.end),
            tube,
            start_cap: self.start_cap.as_ref().map(|c| cap(c, u)),
            end_cap: self.end_cap.as_ref().map(|c| cap(c, end_axis)),
        }
    }

    /// Which side of the end planes a point is on: `<X,U> < -slack` is
    /// beyond the start, `<X,U_end> > slack` beyond the end.
    #[inline]
    fn beyond_start(&self, x: DVec4, slack: f64) -> bool {
        self.start_cap
            .as_ref()
            .is_some_and(|c| lorentz::dot(x, c.axis) < -slack)
    }

    #[inline]
    fn beyond_end(&self, x: DVec4, slack: f64) -> bool {
        self.end_cap
            .as_ref()
            .is_some_and(|c| lorentz::dot(x, c.axis) > slack)
    }

    /// True if the h-point `p` lies strictly inside: [`Self::contains_hyperboloid`]
    /// of its hyperboloid image.
    ///
    /// # Accuracy
    ///
    /// As [`Self::contains_hyperboloid`], with `X` within 2 ulps of the exact image
    /// ([`Point::to_hyperboloid`]).
    pub fn contains(&self, p: &Point) -> bool {
        self.contains_hyperboloid(p.to_hyperboloid())
    }

    /// True if the hyperboloid point is strictly within `radius` of the segment.
    ///
    /// # Accuracy
    ///
    /// Decided by the end planes and then the tube or a cap, each with
    /// Lorentz products rounded at about `eps |X| |M|`: exact away from the
    /// boundary.
    pub fn contains_hyperboloid(&self, x: DVec4) -> bool {
        if self.beyond_start(x, 0.0) {
            self.start_cap
                .as_ref()
                .is_some_and(|c| c.sphere.contains_hyperboloid(x))
        } else if self.beyond_end(x, 0.0) {
            self.end_cap
                .as_ref()
                .is_some_and(|c| c.sphere.contains_hyperboloid(x))
        } else {
            self.tube.contains_hyperboloid(x)
        }
    }

    /// The first intersection with `t` in `(t_min, t_max)`, with the outward
    /// normal.
    ///
    /// Every boundary point is either on the tube between the end planes or
    /// on a cap sphere beyond its end plane; the nearest such candidate among
    /// the (at most six) roots is the hit.
    ///
    /// At the seam circle tube and cap meet tangentially, so a ray through
    /// the seam has two nearly equal roots whose rounded points can straddle
    /// the end plane the wrong way for both pieces. Each piece therefore
    /// accepts points up to `SEAM_SLACK` (relative to `|X|`) past the plane;
    /// there the two surfaces differ only to second order, so the accepted
    /// point is on the boundary to rounding and the seam is watertight.
    ///
    /// # Accuracy
    ///
    /// Against a 320-bit reference, rays from the origin to rods with ends
    /// up to 6 away: `t` within 1e-11 (measured 1.4e-12; the `ray-rod`
    /// family of `tests/reference.rs`). Hits lie at distance `r` from the
    /// segment to 1e-9 (`rod_hits_are_at_distance_r_from_the_segment` in
    /// `tests/surfaces.rs`); rays aimed at the seam circle hit
    /// (`rod_seam_is_watertight`). The seam slack accepts a tube or cap point
    /// with `<X,U>` up to `1e-9 x0` past its end plane (a distance `delta`
    /// of about `1e-9 x0`), where tube and cap differ by about
    /// `delta^2 / tanh r`: below the hit point's own rounding `eps x0^2`
    /// for radii above ~0.005.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (t, piece) = self.first_piece(ray, t_min, t_max, false)?;
        let point = ray.at(t);
        let normal = match piece {
            Piece::Tube => self.tube.normal_at(point),
            Piece::StartCap => self.start_cap.as_ref()?.sphere.normal_at(point),
            Piece::EndCap => self.end_cap.as_ref()?.sphere.normal_at(point),
        };
        Some(Hit::on_surface(t, point, normal))
    }

    /// True if the ray meets the rod in `(t_min, t_max)`: exactly
    /// `intersect(..).is_some()`, stopping at the first candidate accepted.
    #[inline]
    pub fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.first_piece(ray, t_min, t_max, true).is_some()
    }

    /// The nearest accepted candidate among the (at most six) roots, or with
    /// `any` the first one accepted. A root is only looked at (its point
    /// built, its seam side checked) if it could still win: inside
    /// `(t_min, t_max)` and before the best so far. The winner is the one
    /// [`Rod::intersect`] has always chosen: the least accepted root, with
    /// every root compared (rounding can put a tangent ray's "far" root an
    /// ulp before its "near" one).
    fn first_piece(&self, ray: &Ray, t_min: f64, t_max: f64, any: bool) -> Option<(f64, Piece)> {
        let mut best: Option<(f64, Piece)> = None;
        let wanted = |t: f64, best: &Option<(f64, Piece)>| {
            t.is_finite() && t > t_min && t < t_max && best.is_none_or(|(bt, _)| t < bt)
        };
        // Looks at one root, and makes it the best if it is accepted.
        let look = |t: f64, piece: Piece, best: &mut Option<(f64, Piece)>| {
            if !wanted(t, best) {
                return;
            }
            let x = ray.at(t);
            let slack = SEAM_SLACK * x.w;
            let inside = match piece {
                Piece::Tube => !self.beyond_start(x, slack) && !self.beyond_end(x, slack),
                Piece::StartCap => self
                    .start_cap
                    .as_ref()
                    .is_some_and(|c| lorentz::dot(x, c.axis) <= slack),
                Piece::EndCap => self
                    .end_cap
                    .as_ref()
                    .is_some_and(|c| lorentz::dot(x, c.axis) >= -slack),
            };
            if inside {
                *best = Some((t, piece));
            }
        };
        let (tube, clear) = self.tube.roots_or_clear(ray);
        if let Some((near, far)) = tube {
            for t in [near, far] {
                look(t, Piece::Tube, &mut best);
                if any && best.is_some() {
                    return best;
                }
            }
        }
        // A line clear of the tube cannot meet the caps, which lie within
        // the radius of the axis.
        if clear {
            return best;
        }
        for (cap, piece) in [
            (self.start_cap.as_ref(), Piece::StartCap),
            (self.end_cap.as_ref(), Piece::EndCap),
        ] {
            let Some(cap) = cap else { continue };
            if let Some((near, far)) = cap.sphere.roots(ray) {
                for t in [near, far] {
                    look(t, piece, &mut best);
                    if any && best.is_some() {
                        return best;
                    }
                }
            }
        }
        best
    }
}

/// How far (as `<X,U>/x0`, about the sinh of the distance) a tube or cap
/// point may lie past its end plane and still count; see [`Rod::intersect`].
const SEAM_SLACK: f64 = 1e-9;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Piece {
    Tube,
    StartCap,
    EndCap,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::point::{IdealPoint, Point};
    use glam::DVec3;

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    /// The shadow test answers exactly what the nearest-hit test finds, for
    /// rays that meet the tube, the caps, the seam or nothing, from outside
    /// and from inside.
    #[test]
    fn blocks_agrees_with_intersect() {
        let rod = Rod::new(p(-0.3, 0.1, 0.4).into(), p(0.25, -0.1, 0.5).into(), 0.07).unwrap();
        let inside = p(0.0, 0.0, 0.45);
        for i in 0..2000 {
            let a = f64::from(i) * 2.399_963_229_728_653;
            let r = 0.8 * (f64::from(i) / 2000.0).sqrt();
            let dir = DVec3::new(r * a.cos(), r * a.sin(), 1.0);
            for ray in [
                Ray::from_origin_unchecked(dir),
                Ray::from_ball_unchecked(&inside, dir),
            ] {
                for (lo, hi) in [(0.0, f64::INFINITY), (1e-9, 0.45), (0.5, 2.0)] {
                    assert_eq!(
                        rod.blocks(&ray, lo, hi),
                        rod.intersect(&ray, lo, hi).is_some(),
                        "ray {i} on ({lo}, {hi})"
                    );
                }
            }
        }
    }

    /// Where the tube test says the ray's line passes clear of the tube,
    /// the caps are missed too (so `first_piece` may skip them), and the
    /// roots are the tube's own. Rays graze the ends at the radius and a
    /// little outside it, on rods near the eye and far from it.
    #[test]
    fn a_line_clear_of_the_tube_misses_the_caps() {
        let mut rng = hscene_test_support::SplitMix64::new(5);
        let (mut clear, mut tested) = (0, 0);
        for case in 0..3000 {
            let far = [0.2, 3.0, 8.0, 12.0][case % 4];
            let towards = rng.direction();
            let mut end_point = || {
                let dir = (towards + 0.2 * rng.direction()).normalize();
                Point::at_distance_from_origin(dir, far + rng.range(0.0, 0.5))
            };
            let (Ok(a), Ok(b)) = (end_point(), end_point()) else {
                continue;
            };
            let radius = [0.005, 0.015, 0.1, 0.6][case / 4 % 4];
            let Ok(rod) = Rod::new(a.into(), b.into(), radius) else {
                continue;
            };
            let end = if case % 2 == 0 { a } else { b };
            // Shadow and reflected rays start out there, beside the rod.
            let shrink = 1.0 - end.coords().length_squared();
            let beside = Point::from_coords(
                0.5 * (a.coords() + b.coords()) + 0.01 * shrink * rng.direction(),
            );
            for k in 0..8 {
                // Aim past the end, off by about the radius in the ball.
                let off = radius * (0.2 + 0.3 * f64::from(k)) * shrink;
                let aim = end.coords() + off * rng.direction();
                let ray = match (&beside, k % 2) {
                    (Ok(start), 1) => Ray::from_ball_unchecked(start, aim - start.coords()),
                    _ => Ray::from_origin_unchecked(aim),
                };
                let (roots, is_clear) = rod.tube.roots_or_clear(&ray);
                assert_eq!(roots, rod.tube.roots(&ray), "case {case}");
                tested += 1;
                if is_clear {
                    clear += 1;
                    assert!(roots.is_none(), "case {case}");
                    for cap in [&rod.start_cap, &rod.end_cap].into_iter().flatten() {
                        assert!(cap.sphere.roots(&ray).is_none(), "case {case}, ray {k}");
                    }
                }
            }
        }
        // The shortcut is taken for many of these rays, and not for all.
        assert!(clear > tested / 10 && clear < tested, "{clear} of {tested}");
    }

    #[test]
    fn side_and_cap_hits() {
        // Rod along the x axis from -0.3 to 0.3, radius 0.05; eye on the z axis.
        let rod = Rod::new(p(-0.3, 0.0, 0.0).into(), p(0.3, 0.0, 0.0).into(), 0.05).unwrap();
        let eye = p(0.0, 0.0, -0.5);
        let side = rod
            .intersect(
                &Ray::from_ball_unchecked(&eye, DVec3::Z),
                0.0,
                f64::INFINITY,
            )
            .unwrap();
        // Along the z axis the rod's side is at distance 0.05 from the origin.
        assert!((side.t - (eye.distance_from_origin() - 0.05)).abs() < 1e-13);
        // Looking along the axis from beyond the end meets the cap first.
        let beyond = p(0.8, 0.0, 0.0);
        let cap = rod
            .intersect(
                &Ray::from_ball_unchecked(&beyond, -DVec3::X),
                0.0,
                f64::INFINITY,
            )
            .unwrap();
        let want = distance(&beyond, &p(0.3, 0.0, 0.0)) - 0.05;
        assert!((cap.t - want).abs() < 1e-13);
        // A ray passing beyond the end, outside the cap, misses.
        let miss = Ray::from_ball_unchecked(&p(0.45, 0.0, -0.5), DVec3::Z);
        assert!(rod.intersect(&miss, 0.0, f64::INFINITY).is_none());
    }

    #[test]
    fn from_inside_the_hit_is_the_exit() {
        let rod = Rod::new(p(-0.3, 0.0, 0.0).into(), p(0.3, 0.0, 0.0).into(), 0.05).unwrap();
        let inside = p(0.1, 0.0, 0.0);
        assert!(rod.contains(&inside));
        let hit = rod
            .intersect(
                &Ray::from_ball_unchecked(&inside, DVec3::Y),
                1e-9,
                f64::INFINITY,
            )
            .unwrap();
        assert!((hit.t - 0.05).abs() < 1e-13);
    }

    #[test]
    fn ideal_end_has_no_cap() {
        let e = IdealPoint::from_direction(DVec3::X).unwrap();
        let rod = Rod::new(p(-0.3, 0.0, 0.0).into(), e.into(), 0.05).unwrap();
        // Far out towards the ideal end the tube is still there.
        let eye = p(0.9, 0.0, -0.09);
        assert!(
            rod.intersect(
                &Ray::from_ball_unchecked(&eye, DVec3::Z),
                0.0,
                f64::INFINITY
            )
            .is_some()
        );
    }
}
