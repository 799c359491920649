//! Building a mesh: the input checked, the local frame chosen, every vertex
//! moved into it and every triangle given its oriented plane there (or
//! dropped as degenerate), then the BVH built over the kept triangles.

use std::sync::Arc;

use glam::DVec4;

use super::bvh::build_bvh;
use super::placement::settled;
use super::{Shared, TriangleMesh};
use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::plane::HPlane;
use crate::point::Point;

/// A triangle is dropped as degenerate when its Lorentz normal is below this
/// fraction of the size of the vectors it is formed from (the criterion of
/// [`HPlane::through`]): its three vertices lie on one h-line to rounding.
const DEGENERATE_TOLERANCE: f64 = 1e-14;

impl TriangleMesh {
    /// Build a mesh from interior vertices and index triples.
    ///
    /// Triangles with a repeated index, or whose three vertices lie on one
    /// h-line (zero area, to a relative 1e-14), are dropped and counted
    /// ([`TriangleMesh::dropped_triangles`]).
    ///
    /// Errors: [`GeomError::EmptyMesh`] when there are no vertices, no
    /// triangles, or no triangle survives; [`GeomError::MeshIndexOutOfRange`]
    /// for an index past the vertex list; [`GeomError::NotFinite`] or
    /// [`GeomError::NotInBall`] for a vertex that is not a representable
    /// interior point, or one more than ~37 from the mesh's centre (which f64
    /// cannot place in the local frame).
    ///
    /// # Accuracy
    ///
    /// Each vertex is moved into the local frame by one isometry (a Möbius
    /// addition, a few `fuzz` of the vertex and of the centre), and each
    /// triangle's plane is computed there from vectors of moderate size, so
    /// its normal is accurate to a few ulps per component; hits then agree
    /// with [`ConvexPolygon`](crate::ConvexPolygon) triangles to 5e-12 in
    /// `t` (relative for `t > 1`; measured 2e-12) for rays from the origin
    /// to meshes up to 5 away (`mesh_hits_agree_with_convex_polygons` in
    /// `tests/mesh.rs`). Building is O(n log n) in the triangle count
    /// (0.45 ms for 2016 triangles, `benches/kernels.rs`).
    pub fn new(
        vertices: Vec<Point>,
        mut triangles: Vec<[u32; 3]>,
    ) -> Result<TriangleMesh, GeomError> {
        if vertices.is_empty() || triangles.is_empty() {
            return Err(GeomError::EmptyMesh { dropped: 0 });
        }
        for p in &vertices {
            if !p.coords().is_finite() {
                return Err(GeomError::NotFinite);
            }
            if !p.is_representable() {
                return Err(GeomError::NotInBall {
                    norm: p.coords().length(),
                });
            }
        }
        let n = vertices.len();
        for (triangle, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&k| k as usize >= n) {
                return Err(GeomError::MeshIndexOutOfRange {
                    triangle,
                    index,
                    vertices: n,
                });
            }
        }
        let base = local_frame(&vertices);
        let back = base.inverse();
        let mut local = Vec::with_capacity(n);
        let mut distance = Vec::with_capacity(n);
        for p in &vertices {
            let q = settled(back.apply(p));
            if !q.is_representable() {
                return Err(GeomError::NotInBall {
                    norm: p.coords().length(),
                });
            }
            local.push(q.to_hyperboloid());
            distance.push(q.distance_from_origin());
        }
        // The kept triangles stay in the given list, compacted in place.
        let given = triangles.len();
        triangles.retain(|&t| local_plane(t, t.map(|k| local[k as usize])).is_some());
        let dropped = given - triangles.len();
        if triangles.is_empty() {
            return Err(GeomError::EmptyMesh { dropped });
        }
        let (mut radius, mut scale) = (0.0f64, 0.0f64);
        for t in &triangles {
            for &k in t {
                radius = radius.max(distance[k as usize]);
                scale = scale.max(local[k as usize].abs().element_sum());
            }
        }
        drop(distance);
        let (nodes, order) = build_bvh(&local, &triangles);
        let tris = order.iter().map(|&i| triangles[i as usize]).collect();
        drop(triangles);
        let shared = Shared {
            input: vertices,
            local,
            tris,
            order,
            dropped,
            base,
            nodes,
            radius,
            scale,
        };
        Ok(TriangleMesh::placed(Arc::new(shared), Isometry::IDENTITY))
    }
}

/// The local frame: the hyperboloid barycentre of the vertices, found with
/// the first vertex moved to the origin (so far-out meshes sum moderate
/// vectors), moved to the origin. Any frame is correct; this one only sets
/// the conditioning, so a failure falls back to the first vertex.
fn local_frame(points: &[Point]) -> Isometry {
    let Some(first) = points.first() else {
        return Isometry::IDENTITY;
    };
    let anchor = Isometry::transvection_from_origin(*first);
    let back = anchor.inverse();
    let sum: DVec4 = points.iter().map(|p| back.apply(p).to_hyperboloid()).sum();
    let mean = sum / points.len() as f64;
    // -<m,m> >= 1 for a mean of hyperboloid points; a rounded value below
    // that (a mesh spanning ~18 or more) only loses the better centre.
    let q = -lorentz::dot(mean, mean);
    let centre = (q.is_finite() && q >= 0.5)
        .then(|| Point::from_hyperboloid(mean / q.sqrt()))
        .flatten()
        .filter(Point::is_representable);
    match centre {
        Some(c) => anchor.compose(&Isometry::transvection_from_origin(c)),
        None => anchor,
    }
}

/// The oriented plane of a triangle in the local frame, or `None` if it is
/// degenerate (a repeated index, or collinear vertices to a relative 1e-14).
fn local_plane(t: [u32; 3], [a, b, c]: [DVec4; 3]) -> Option<HPlane> {
    if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
        return None;
    }
    let n = plane_vector(a, b, c);
    let scale = (b - a).length() * (c - a).length() * a.length();
    if !(lorentz::norm(n) > DEGENERATE_TOLERANCE * scale) {
        return None;
    }
    HPlane::from_normal(n).ok()
}

/// The plane of a kept triangle, from its local vertices: the very
/// computation [`local_plane`] made when the triangle was kept, so the same
/// plane bit for bit (a deterministic function of the same floats), which
/// no triangle needs to store. `None` cannot happen for a kept triangle (its
/// normal was finite and nonzero then, and is the same now).
#[inline]
pub(super) fn kept_plane([a, b, c]: [DVec4; 3]) -> Option<HPlane> {
    HPlane::from_normal(plane_vector(a, b, c)).ok()
}

/// The unnormalised Lorentz normal of the triangle `abc` (right-hand rule).
#[inline]
fn plane_vector(a: DVec4, b: DVec4, c: DVec4) -> DVec4 {
    // As `HPlane::through`: differences are better conditioned than the raw
    // vectors, and the right-hand rule orients the normal.
    lorentz::orthogonal_complement(a, b - a, c - a)
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::mesh::test_support::p;
    use crate::ray::Ray;
    use hscene_test_support::SplitMix64;

    #[test]
    fn degenerate_triangles_are_dropped_and_counted() {
        let vs = vec![
            p(0.0, 0.0, 0.0),
            p(0.3, 0.0, 0.0),
            p(0.0, 0.3, 0.0),
            p(-0.3, 0.0, 0.0),
        ];
        let mesh = TriangleMesh::new(vs.clone(), vec![[0, 1, 2], [0, 0, 1], [1, 0, 3], [1, 2, 2]])
            .unwrap();
        assert_eq!(mesh.triangle_count(), 1);
        assert_eq!(mesh.dropped_triangles(), 3);
        assert_eq!(mesh.vertex_count(), 4);
        assert_eq!(&*mesh.triangles(), &[[0, 1, 2]]);
        assert_eq!(&*mesh.vertices(), vs.as_slice());
        assert_eq!(
            TriangleMesh::new(vs.clone(), vec![[0, 1, 3]]),
            Err(GeomError::EmptyMesh { dropped: 1 })
        );
        assert_eq!(
            TriangleMesh::new(vs.clone(), vec![[0, 1, 4]]),
            Err(GeomError::MeshIndexOutOfRange {
                triangle: 0,
                index: 4,
                vertices: 4
            })
        );
        assert_eq!(
            TriangleMesh::new(vs, vec![]),
            Err(GeomError::EmptyMesh { dropped: 0 })
        );
        assert_eq!(
            TriangleMesh::new(vec![], vec![[0, 1, 2]]),
            Err(GeomError::EmptyMesh { dropped: 0 })
        );
        let far = Point::new_unchecked(DVec3::new(1.0, 0.0, 0.0), 1e-300);
        assert!(matches!(
            TriangleMesh::new(
                vec![far, p(0.1, 0.0, 0.0), p(0.0, 0.1, 0.0)],
                vec![[0, 1, 2]]
            ),
            Err(GeomError::NotInBall { .. })
        ));
        let nan = Point::new_unchecked(DVec3::new(f64::NAN, 0.0, 0.0), 1.0);
        assert_eq!(
            TriangleMesh::new(
                vec![nan, p(0.1, 0.0, 0.0), p(0.0, 0.1, 0.0)],
                vec![[0, 1, 2]]
            ),
            Err(GeomError::NotFinite)
        );
    }

    #[test]
    fn translated_mesh_builds_its_frame_far_out() {
        // A small mesh 20 from the origin: the local frame keeps its planes
        // accurate even though the world vectors are ~1e9 long.
        let centre = Point::at_distance_from_origin(DVec3::new(0.3, 0.4, 1.0), 20.0).unwrap();
        let there = Isometry::transvection_from_origin(centre);
        let corners = [p(0.2, 0.0, 0.0), p(0.0, 0.2, 0.0), p(0.0, 0.0, 0.2)];
        let mesh = TriangleMesh::new(
            corners.iter().map(|c| there.apply(c)).collect(),
            vec![[0, 1, 2]],
        )
        .unwrap();
        let (c, r) = mesh.bounding_ball();
        let c = Point::from_hyperboloid(c).unwrap();
        // The barycentre of the corners is 0.226 from the origin (before the
        // move), and the corners 0.34 from it.
        let offset = crate::distance::distance(&c, &centre);
        assert!((offset - 0.226).abs() < 1e-3, "{offset}");
        assert!((r - 0.34).abs() < 0.01, "{r}");
        // Carried back next to the origin, it is the triangle it was.
        let back = mesh.transformed(&there.inverse());
        let direct = TriangleMesh::new(corners.to_vec(), vec![[0, 1, 2]]).unwrap();
        let mut rng = SplitMix64::new(2);
        for _ in 0..200 {
            let ray = Ray::from_origin_unchecked(rng.direction() + DVec3::splat(0.8));
            let (a, b) = (
                back.intersect(&ray, 0.0, f64::INFINITY),
                direct.intersect(&ray, 0.0, f64::INFINITY),
            );
            assert_eq!(a.is_some(), b.is_some());
            if let (Some(a), Some(b)) = (a, b) {
                assert!((a.t - b.t).abs() < 1e-6, "{} vs {}", a.t, b.t);
            }
        }
    }
}
