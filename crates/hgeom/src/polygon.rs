//! Convex planar h-polygons, possibly with ideal vertices.

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::plane::HPlane;
use crate::point::{Point, Vertex};
use crate::ray::{Hit, Ray};

/// How far from a polygon's first vertex its other vertices may be for that
/// vertex to anchor the checks (`ConvexPolygon::new`): within it they keep
/// about 1e-8 of their Klein coordinates' separation.
const VERTEX_ANCHOR_REACH: f64 = 18.0;

/// Relative tolerance for planarity and convexity checks of user input
/// (scene files give coordinates to about 14 digits).
const SHAPE_TOLERANCE: f64 = 1e-9;

/// A convex planar h-polygon.
///
/// Invariants: at least three vertices, all on one h-plane, in cyclic order,
/// forming a convex polygon. The plane's normal follows the right-hand rule
/// with the vertex order. `edges[i]` is the unit normal of the h-plane through
/// edge `i -> i+1` perpendicular to the polygon, pointing inside, so a point
/// of the polygon's plane is inside iff `<X, edges[i]> >= 0` for all `i`.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexPolygon {
    vertices: Vec<Vertex>,
    plane: HPlane,
    edges: Vec<DVec4>,
}

impl ConvexPolygon {
    /// Build and validate a polygon from vertices in cyclic order.
    ///
    /// The plane and edge normals are computed with the polygon moved so its
    /// Klein centroid (a point inside it) is at the origin, then carried back
    /// by the Lorentz matrix: far from the origin the hyperboloid vectors are
    /// ~e^d long and cross products of their differences would lose ~e^{2d}
    /// ulps; this way each normal is correct to a few ulps per component.
    ///
    /// Errors: [`GeomError::TooFewVertices`], [`GeomError::Collinear`] (no
    /// three vertices span a plane), [`GeomError::NonPlanar`] (a vertex off
    /// the plane by more than 1e-9 relative, naming it),
    /// [`GeomError::NonConvex`] (a reflex corner, or a boundary that winds
    /// more than once), [`GeomError::Coincident`] (a zero-length edge).
    ///
    /// # Accuracy
    ///
    /// The plane and edge normals are accurate to a few ulps per component
    /// (see above): against a 320-bit reference, ray hits on quadrilaterals
    /// up to 8 away are within 5e-9 (measured 7e-10; the `ray-polygon`
    /// family of `tests/reference.rs`). The checks use a relative tolerance
    /// of 1e-9, so vertices given to ~14 digits are accepted.
    pub fn new(vertices: Vec<Vertex>) -> Result<ConvexPolygon, GeomError> {
        ConvexPolygon::new_with_fuzz(vertices, 0.0)
    }

    /// [`ConvexPolygon::new`] for vertices that carry, besides their own
    /// rounding, an error of `extra` (hyperbolic distance, summed over the
    /// vertices): images under an isometry.
    ///
    /// The planarity and convexity checks accept what rounding can explain:
    /// a vertex at gap `g` is only placed to about `eps / g` (rounding its
    /// coordinates moves it that far, 2.8e-17 e^d at distance `d`), so the
    /// tolerance is `max(1e-9, 16 (eps sum 1/g_i + extra))`, with ideal
    /// vertices counted at the gap of the anchor the polygon is built
    /// around (their direction's rounding, seen from there). A fixed 1e-9
    /// rejected a square 18.7 from the origin, whose vertices rounding alone
    /// puts 4.4e-9 off its plane.
    fn new_with_fuzz(vertices: Vec<Vertex>, extra: f64) -> Result<ConvexPolygon, GeomError> {
        let n = vertices.len();
        if n < 3 {
            return Err(GeomError::TooFewVertices(n));
        }
        // An interior vertex lands exactly on the origin (x (+) -x = 0), which
        // measured better than the centroid; ideal polygons use the centroid.
        // A vertex anchor sees the other vertices from one end of the
        // polygon: a large one (a cube of circumradius 18 has edges 34 long)
        // puts them beyond what f64 resolves from there, so the centroid,
        // nearer all of them, anchors it instead.
        let sees_all = |a: &Point| {
            vertices.iter().all(|v| match v {
                Vertex::Interior(p) => a.distance(*p) <= VERTEX_ANCHOR_REACH,
                Vertex::Ideal(_) => true,
            })
        };
        let anchor = vertices
            .iter()
            .find_map(|v| match v {
                Vertex::Interior(p) => Some(*p),
                Vertex::Ideal(_) => None,
            })
            .filter(sees_all)
            .or_else(|| {
                // The Klein centroid, then walked to the middle. Not a clamp
                // of user input: the anchor is any point near the polygon
                // (it only sets the conditioning), and a centroid rounding
                // onto the absolute falls back to building in place.
                let first = klein_centroid(&vertices)?;
                Some(centred_anchor(&vertices, first))
            })
            .filter(|p| p.coords() != DVec3::ZERO);
        let anchor_gap = anchor.map_or(1.0, |a| a.gap());
        let fuzz: f64 = vertices
            .iter()
            .map(|v| match v {
                Vertex::Interior(p) => f64::EPSILON / p.gap(),
                Vertex::Ideal(_) => f64::EPSILON / anchor_gap,
            })
            .sum();
        let tolerance = SHAPE_TOLERANCE.max(16.0 * (fuzz + extra));
        let Some(anchor) = anchor else {
            return ConvexPolygon::build(vertices, tolerance);
        };
        let to_anchor = Isometry::transvection_from_origin(anchor);
        let back = to_anchor.inverse();
        let local = ConvexPolygon::build(
            vertices.iter().map(|v| back.apply_vertex(v)).collect(),
            tolerance,
        )?;
        let l = to_anchor.to_lorentz();
        Ok(ConvexPolygon {
            vertices,
            plane: local.plane.transformed(&to_anchor),
            edges: local.edges.iter().map(|e| l * *e).collect(),
        })
    }

    fn build(vertices: Vec<Vertex>, tolerance: f64) -> Result<ConvexPolygon, GeomError> {
        let n = vertices.len();
        let xs: Vec<DVec4> = vertices
            .iter()
            .map(|v| unit_time(v.to_hyperboloid()))
            .collect();
        let centroid = xs.iter().copied().sum::<DVec4>() / n as f64;
        let scale: f64 = xs
            .iter()
            .map(|x| (*x - centroid).length())
            .fold(0.0, f64::max);
        // The plane of the first three vertices that are not collinear; for a
        // convex polygon its orientation is the polygon's (right-hand rule),
        // and fitting it to a prefix lets errors name the vertex that is off.
        let normal = (2..n)
            .map(|k| lorentz::orthogonal_complement(xs[0], xs[1] - xs[0], xs[k] - xs[0]))
            .find(|c| lorentz::norm(*c) > 1e-12 * scale * scale)
            .ok_or(GeomError::Collinear)?;
        // Orient it by the polygon's total turning (a Newell sum over the fan
        // from the centroid), so a reflex first corner does not flip it.
        let newell: DVec4 = (0..n)
            .map(|i| {
                lorentz::orthogonal_complement(
                    centroid,
                    xs[i] - centroid,
                    xs[(i + 1) % n] - centroid,
                )
            })
            .sum();
        let normal = if lorentz::dot(newell, normal) < 0.0 {
            -normal
        } else {
            normal
        };
        let plane = HPlane::from_normal(normal)?;
        let nrm = plane.normal();
        for (index, x) in xs.iter().enumerate() {
            let offset = lorentz::dot(*x, nrm);
            if offset.abs() > tolerance * x.length().max(scale) {
                return Err(GeomError::NonPlanar { index, offset });
            }
        }
        // Convexity, vertex by vertex: each corner must turn the same way as
        // the polygon (a reflex corner turns against the normal).
        for i in 0..n {
            let (prev, here, next) = (xs[(i + n - 1) % n], xs[i], xs[(i + 1) % n]);
            let corner = lorentz::orthogonal_complement(prev, here - prev, next - prev);
            if lorentz::dot(corner, nrm) < -tolerance * scale * scale {
                return Err(GeomError::NonConvex { index: i });
            }
        }
        let mut edges = Vec::with_capacity(n);
        for i in 0..n {
            let (a, b) = (xs[i], xs[(i + 1) % n]);
            let mut e = lorentz::orthogonal_complement(a, b - a, nrm);
            let len = lorentz::norm(e);
            if !(len > 0.0) {
                return Err(GeomError::Coincident);
            }
            e /= len;
            if lorentz::dot(e, centroid) < 0.0 {
                e = -e;
            }
            // Every corner may turn the right way while the boundary still
            // winds twice (a pentagram): some vertex is then outside an edge.
            for (j, x) in xs.iter().enumerate() {
                if j != i && j != (i + 1) % n && lorentz::dot(e, *x) < -tolerance * x.length() {
                    return Err(GeomError::NonConvex { index: j });
                }
            }
            edges.push(e);
        }
        Ok(ConvexPolygon {
            vertices,
            plane,
            edges,
        })
    }

    /// The vertices in order.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored vertices.
    pub fn vertices(&self) -> &[Vertex] {
        &self.vertices
    }

    /// The polygon's oriented plane.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored plane.
    pub fn plane(&self) -> HPlane {
        self.plane
    }

    /// The image under an isometry. Orientation-reversing maps reverse the
    /// vertex order so the normal stays the image of the old normal.
    ///
    /// # Accuracy
    ///
    /// The moved polygon is rebuilt from the moved vertices, so it is as
    /// accurate as [`ConvexPolygon::new`] on them (hits agree with the
    /// original's to 1e-10 relative, `platonic_hits_lie_on_faces` in
    /// `tests/properties.rs`). Beyond distance ~17 from the origin the
    /// rebuilt polygon fails the 1e-9 planarity check and the plane and edge
    /// normals are carried by the Lorentz matrix instead
    /// (`far_polygon_gets_its_new_plane` in `tests/derivations.rs`).
    pub fn transformed(&self, iso: &Isometry) -> ConvexPolygon {
        let mut vs: Vec<Vertex> = self.vertices.iter().map(|v| iso.apply_vertex(v)).collect();
        if !iso.preserves_orientation() {
            vs.reverse();
        }
        // An isometric image of a valid polygon is valid; rebuilding keeps the
        // cached planes accurate for the new position. Far out (distance ~17
        // and beyond) rounding of the image vertices can trip the planarity
        // tolerance; the plane and edge planes are then carried over by the
        // isometry's Lorentz matrix, which is exact up to rounding (edge
        // planes are only used as a set, so the vertex reversal above does
        // not disturb them).
        // The images carry the rounding of the sources and of the
        // translation part besides their own.
        let moved_by = 1.0 / iso.translation_part().gap();
        let extra = f64::EPSILON
            * self
                .vertices
                .iter()
                .map(|v| match v {
                    Vertex::Interior(p) => 1.0 / p.gap() + moved_by,
                    Vertex::Ideal(_) => moved_by,
                })
                .sum::<f64>();
        ConvexPolygon::new_with_fuzz(vs.clone(), extra).unwrap_or_else(|_| {
            let l = iso.to_lorentz();
            ConvexPolygon {
                vertices: vs,
                plane: self.plane.transformed(iso),
                edges: self.edges.iter().map(|e| l * *e).collect(),
            }
        })
    }

    /// The first intersection with `t` in `(t_min, t_max)`.
    ///
    /// Along the ray `<X(t),N> = cosh t <X,N> + sinh t <V,N>`, so the plane is
    /// met at `tanh t = -<X,N>/<V,N>`; a ray parallel to the plane (or meeting
    /// it only beyond the absolute) misses. The hit's normal is the plane's.
    ///
    /// # Accuracy
    ///
    /// `t` as [`HPlane::crossing`]. The inside test accepts points with
    /// `<P, e_i> >= -1e-10 |P| |e_i|`, a slack of the size of the rounding
    /// in those products, so shared edges are watertight
    /// (`rays_through_shared_edges_hit_the_solid` in `tests/properties.rs`)
    /// and a ray may count as hitting a polygon up to about `1e-10 |P|` (in
    /// `sinh` of distance) outside an edge.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let hit = self.plane.intersect(ray, t_min, t_max)?;
        let point = hit.point;
        // Rounding in <P,E> scales with |P||E| (both grow like cosh of the
        // distance from the origin); a slack of that size keeps shared edges
        // watertight, so rays through an edge of a solid hit one of its faces.
        let slack = -1e-10 * point.length();
        self.edges
            .iter()
            .all(|e| lorentz::dot(point, *e) >= slack * e.length())
            .then_some(hit)
    }
}

/// Scale a future vector to time component 1 (the Klein-model representative);
/// keeps interior and ideal vertices on a common footing.
fn unit_time(x: DVec4) -> DVec4 {
    x / x.w
}

/// The ball point at the Klein centroid of `vertices`, with its gap
/// computed without cancellation, or `None` when the centroid is on the
/// absolute (all vertices one ideal point).
///
/// With `k_i` the Klein points and `g_i = 1 - |k_i|^2` their Klein gaps,
/// the centroid `k = mean k_i` has
/// `1 - |k|^2 = mean g_i + (1 / 2n^2) sum_ij |k_i - k_j|^2`
/// (expand `|k|^2 = (1/n^2) sum_ij k_i.k_j` with
/// `2 k_i.k_j = |k_i|^2 + |k_j|^2 - |k_i - k_j|^2`): two sums of
/// non-negative terms. Formed as `1 - |k|^2` it cancels to nothing once the
/// vertices are closer than `sqrt(eps)`: the ideal vertices of a polygon
/// moved 25 from the origin are 1e-11 apart, their centroid rounded onto
/// the absolute and the polygon was refused as collinear. A Klein point
/// with gap `g` is the ball point `k / (1 + s)` with gap `2 s / (1 + s)`,
/// `s = sqrt(g)`; for an interior vertex `k_i = 2 p / (2 - gap)` and
/// `g_i = (gap / (2 - gap))^2`, both exact in the ball's gap.
fn klein_centroid(vertices: &[Vertex]) -> Option<Point> {
    let klein: Vec<(DVec3, f64)> = vertices
        .iter()
        .map(|v| match v {
            Vertex::Interior(p) => {
                let d = 2.0 - p.gap();
                (2.0 * p.coords() / d, (p.gap() / d).powi(2))
            }
            Vertex::Ideal(i) => (i.coords().normalize_or_zero(), 0.0),
        })
        .collect();
    let n = klein.len() as f64;
    let centroid = klein.iter().map(|(k, _)| *k).sum::<DVec3>() / n;
    let spread: f64 = klein
        .iter()
        .enumerate()
        .flat_map(|(i, (a, _))| {
            klein[i + 1..]
                .iter()
                .map(move |(b, _)| (*a - *b).length_squared())
        })
        .sum();
    let gap = klein.iter().map(|(_, g)| g).sum::<f64>() / n + spread / (n * n);
    let s = gap.sqrt();
    let ball_gap = 2.0 * s / (1.0 + s);
    let point = Point::new_unchecked(centroid / (1.0 + s), ball_gap);
    (ball_gap > 0.0 && centroid.is_finite() && point.is_representable()).then_some(point)
}

/// Steps (at most this many) by which [`centred_anchor`] walks towards the
/// middle of a polygon.
const ANCHOR_STEPS: usize = 64;

/// The anchor of a polygon seen from `first` (its Klein centroid), moved
/// on while the vertices' Klein centroid, seen from the anchor, is far
/// from it: a polygon with ideal vertices moved 20 from the origin has
/// three of four vertices within 1e-9 of each other seen from there, and
/// its centroid (about 1 out) sees them no better; each step goes to the
/// centroid seen from the last, until the vertices surround the anchor.
/// The anchor only sets the conditioning of the checks, never the result.
fn centred_anchor(vertices: &[Vertex], first: Point) -> Point {
    let mut anchor = first;
    for _ in 0..ANCHOR_STEPS {
        let to_anchor = Isometry::transvection_from_origin(anchor);
        let back = to_anchor.inverse();
        let seen: Vec<Vertex> = vertices.iter().map(|v| back.apply_vertex(v)).collect();
        let Some(step) = klein_centroid(&seen) else {
            break;
        };
        // Within 0.5 of the anchor (ball radius tanh 0.25): centred enough.
        if !(step.coords().length() > 0.245) {
            break;
        }
        match to_anchor.apply(&step) {
            p if p.gap() > 0.0 && p.is_representable() => anchor = p,
            _ => break,
        }
    }
    anchor
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::point::{IdealPoint, Point};
    use glam::DVec3;

    fn v(x: f64, y: f64, z: f64) -> Vertex {
        Point::from_coords(DVec3::new(x, y, z)).unwrap().into()
    }

    fn square() -> ConvexPolygon {
        // In the plane z = 0.2 shifted... use a plane through the origin: z = 0.
        ConvexPolygon::new(vec![
            v(0.3, 0.3, 0.0),
            v(-0.3, 0.3, 0.0),
            v(-0.3, -0.3, 0.0),
            v(0.3, -0.3, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn normal_follows_right_hand_rule() {
        let sq = square();
        let n = sq.plane().normal();
        assert!((n - DVec4::new(0.0, 0.0, 1.0, 0.0)).length() < 1e-14);
    }

    #[test]
    fn ray_hits_inside_and_misses_outside() {
        let sq = square();
        let p = Point::from_coords(DVec3::new(0.1, 0.1, 0.5)).unwrap();
        let hit = sq.intersect(&Ray::from_ball_unchecked(&p, -DVec3::Z), 0.0, f64::INFINITY);
        assert!(hit.is_some());
        let q = Point::from_coords(DVec3::new(0.5, 0.1, 0.5)).unwrap();
        assert!(
            sq.intersect(&Ray::from_ball_unchecked(&q, -DVec3::Z), 0.0, f64::INFINITY)
                .is_none()
        );
        // Parallel ray misses.
        assert!(
            sq.intersect(&Ray::from_ball_unchecked(&p, DVec3::X), 0.0, f64::INFINITY)
                .is_none()
        );
    }

    #[test]
    fn ideal_vertices_are_accepted() {
        let ideal =
            |x: f64, y: f64| Vertex::Ideal(IdealPoint::new(DVec3::new(x, y, 0.0), 1e-12).unwrap());
        let tri = ConvexPolygon::new(vec![
            ideal(1.0, 0.0),
            ideal(-0.5, 0.75f64.sqrt()),
            ideal(-0.5, -(0.75f64.sqrt())),
        ])
        .unwrap();
        // The ideal triangle contains the origin.
        let p = Point::from_coords(DVec3::new(0.0, 0.0, 0.5)).unwrap();
        assert!(
            tri.intersect(&Ray::from_ball_unchecked(&p, -DVec3::Z), 0.0, f64::INFINITY)
                .is_some()
        );
    }

    #[test]
    fn non_convex_and_non_planar_are_rejected() {
        let bad = ConvexPolygon::new(vec![
            v(0.3, 0.3, 0.0),
            v(0.0, 0.0, 0.0),
            v(-0.3, 0.3, 0.0),
            v(0.0, -0.3, 0.0),
        ]);
        assert_eq!(bad, Err(GeomError::NonConvex { index: 1 }));
        // Crossed order of a square: a reflex corner is named.
        let bowtie = ConvexPolygon::new(vec![
            v(0.3, 0.3, 0.0),
            v(-0.3, -0.3, 0.0),
            v(-0.3, 0.3, 0.0),
            v(0.3, -0.3, 0.0),
        ]);
        assert!(matches!(bowtie, Err(GeomError::NonConvex { .. })));
        let star: Vec<Vertex> = (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
                v(0.3 * a.cos(), 0.3 * a.sin(), 0.0)
            })
            .collect();
        assert!(matches!(
            ConvexPolygon::new(star),
            Err(GeomError::NonConvex { .. })
        ));
        let tilted = ConvexPolygon::new(vec![
            v(0.3, 0.3, 0.0),
            v(-0.3, 0.3, 0.0),
            v(-0.3, -0.3, 0.0),
            v(0.3, -0.3, 0.1),
        ]);
        assert!(matches!(tilted, Err(GeomError::NonPlanar { index: 3, .. })));
        assert!(matches!(
            ConvexPolygon::new(vec![v(0.0, 0.0, 0.0), v(0.1, 0.0, 0.0)]),
            Err(GeomError::TooFewVertices(2))
        ));
    }
}
