//! Moving a mesh: the placement composed in O(1) over the shared local
//! data, and what reads the mesh through it (its vertices, its winding, its
//! bounding ball).

use std::borrow::Cow;
use std::sync::Arc;

use glam::DVec4;

use super::{Shared, TriangleMesh};
use crate::isometry::Isometry;
use crate::point::Point;

/// Points with a larger gap (within ~8 of the origin) are settled: their
/// gap is recomputed from their coordinates (see [`settled`]).
const SETTLE_GAP: f64 = 1e-3;

impl TriangleMesh {
    /// The mesh over `shared` moved by `moved`: the placement settled once
    /// here, so the Möbius form and the two cached Lorentz matrices every
    /// query uses are the same map.
    pub(super) fn placed(shared: Arc<Shared>, moved: Isometry) -> TriangleMesh {
        let placement = settled_isometry(moved.compose(&shared.base));
        TriangleMesh {
            to_world: placement.to_lorentz(),
            to_local: placement.inverse().to_lorentz(),
            shared,
            moved,
            placement,
            smooth: None,
        }
    }

    /// The vertices in the current world frame, in the order given.
    ///
    /// Borrowed (the very points given to [`TriangleMesh::new`]) until the
    /// mesh is moved; afterwards each is the image, under the placement, of
    /// the local vertex the intersection uses, computed here (O(n)). So a
    /// moved mesh's vertices are exactly as consistent with its hits as an
    /// unmoved mesh's are.
    ///
    /// # Accuracy
    ///
    /// Exact before any move. After, one [`Isometry::apply`] (a few `fuzz`
    /// of the image and of the placement's translation part) of a local
    /// vertex, which is itself within a few `fuzz` of the given point moved
    /// into the local frame: a mesh moved next to the origin reports its
    /// vertices to about 1e-15 (`long_chains_of_moves_stay_accurate` in
    /// `tests/mesh.rs`: 1e-9 after 1000 moves and back). A mesh given far
    /// out carries the `fuzz` of its given coordinates (about 1e-3 at
    /// `1 - |x| = 1e-12`) into the local frame once, and its moved images
    /// are consistent with its hits, not with a re-moved copy of the given
    /// points (`mesh_next_to_the_absolute`).
    pub fn vertices(&self) -> Cow<'_, [Point]> {
        if self.moved == Isometry::IDENTITY {
            Cow::Borrowed(&self.shared.input)
        } else {
            let sh = &*self.shared;
            let back = sh.base.inverse();
            Cow::Owned(
                (0..sh.input.len())
                    .map(|k| self.placement.apply(&sh.local_point(&back, k)))
                    .collect(),
            )
        }
    }

    /// The kept triangles as index triples into [`TriangleMesh::vertices`],
    /// in the order given, wound so that the normal side follows the
    /// right-hand rule (reversed, `[a, c, b]`, after an orientation-reversing
    /// move). Computed (O(n)): the mesh keeps them in its BVH's order only.
    ///
    /// # Accuracy
    ///
    /// Exact.
    pub fn triangles(&self) -> Cow<'_, [[u32; 3]]> {
        let mut triangles = self.shared.given_order();
        if !self.moved.preserves_orientation() {
            for t in &mut triangles {
                t.swap(1, 2);
            }
        }
        Cow::Owned(triangles)
    }

    /// The isometry from the mesh's local frame (where it is centred on the
    /// origin) to the world frame.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored placement (a composition of the moves with the
    /// local frame, each to [`Isometry::compose`]'s accuracy).
    pub fn placement(&self) -> Isometry {
        self.placement
    }

    /// The image under an isometry, in O(1): the local data is shared and
    /// only the placement is composed.
    ///
    /// # Accuracy
    ///
    /// [`Isometry::compose`] of the move with the stored placement: drift
    /// over long chains is that of the gyrovector composition (1000 random
    /// moves and their inverses return hits to 1e-9,
    /// `long_chains_of_moves_stay_accurate` in `tests/mesh.rs`); a moved
    /// mesh intersects like the original intersected with the inversely
    /// moved ray (`moving_the_mesh_equals_moving_the_ray`).
    pub fn transformed(&self, iso: &Isometry) -> TriangleMesh {
        // The first move is stored as given (composing with the identity
        // would round it).
        let moved = if self.moved == Isometry::IDENTITY {
            *iso
        } else {
            iso.compose(&self.moved)
        };
        let mut mesh = TriangleMesh::placed(Arc::clone(&self.shared), moved);
        mesh.smooth.clone_from(&self.smooth);
        mesh
    }

    /// A ball containing the whole mesh: its centre on the hyperboloid (in
    /// the world frame) and its hyperbolic radius, the shape of a renderer's
    /// bounding h-sphere.
    ///
    /// # Accuracy
    ///
    /// The centre is the placement's image of the local origin; the radius
    /// is the largest local distance of a vertex of a kept triangle (1e-14
    /// relative), so the ball contains every triangle (h-balls are convex).
    /// It is padded by `1e-9 (1 + r) + 64 eps |C| e^r`, which covers the
    /// rounding of the placement and of the moved vertices, so it contains
    /// [`TriangleMesh::vertices`]; hit points lie in it up to their own
    /// error (see [`TriangleMesh::intersect`];
    /// `bounding_ball_contains_vertices_and_hits` in `tests/mesh.rs`).
    pub fn bounding_ball(&self) -> (DVec4, f64) {
        let center = self.placement.translation_part().to_hyperboloid();
        let r = self.shared.radius;
        // The rounding of the placement and of the moved vertices: a few
        // `fuzz` (eps / gap, about eps |X| / 2) of points up to r from the
        // centre.
        let pad = 1e-9 * (1.0 + r) + 64.0 * f64::EPSILON * center.length() * r.exp();
        (center, r + pad)
    }
}

/// The point with its gap recomputed from its coordinates, if it is within
/// ~8 of the origin.
///
/// A Möbius sum of two far points that lands near the origin (a far mesh
/// moved into its own frame, or into the frame of an eye next to it) has
/// coordinates and a gap that are each within the far operands' `fuzz` of
/// the exact result, but not consistent with each other: `1 - |x|^2` and the
/// gap differ by about that fuzz (1e-5 relative at `1 - |x| ~ 1e-12`). Then
/// the point's Möbius and hyperboloid readings differ by as much, and so
/// would the mesh's vertices and its hits. Near the origin the coordinates
/// determine the gap to a few ulps, so recomputing it loses nothing and makes
/// both readings the same point. Farther out the gap is the more precise
/// quantity and is kept.
pub(super) fn settled(p: Point) -> Point {
    if p.gap() >= SETTLE_GAP {
        Point::from_coords(p.coords()).unwrap_or(p)
    } else {
        p
    }
}

/// The isometry with its translation part [`settled`], so that its Möbius
/// form and its Lorentz matrix are the same map.
fn settled_isometry(iso: Isometry) -> Isometry {
    let a = iso.translation_part();
    let b = settled(a);
    if (b.gap() - a.gap()).abs() <= 8.0 * f64::EPSILON * a.gap() {
        iso
    } else {
        Isometry::transvection_from_origin(b)
            .compose(&Isometry::orthogonal_unchecked(iso.linear_part()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lorentz;
    use crate::mesh::test_support::{p, random_point, soup};
    use crate::plane::HPlane;
    use crate::ray::Ray;
    use hscene_test_support::SplitMix64;

    #[test]
    fn moves_share_the_data_and_reverse_the_winding_of_reflections() {
        let mut rng = SplitMix64::new(1);
        let mesh = soup(&mut rng, 50, 1.0, 0.3);
        let plane = HPlane::through(
            &p(0.1, 0.0, 0.0).into(),
            &p(0.0, 0.2, 0.0).into(),
            &p(0.0, 0.0, 0.3).into(),
        )
        .unwrap();
        let mirror = Isometry::reflection(&plane);
        let moved = mesh.transformed(&mirror);
        assert!(Arc::ptr_eq(&mesh.shared, &moved.shared));
        assert_ne!(moved, mesh);
        assert_eq!(moved, mesh.transformed(&mirror));
        assert_eq!(mesh.clone(), mesh);
        assert_eq!(mesh.transformed(&Isometry::IDENTITY), mesh);
        let tris = moved.triangles();
        for (t, u) in tris.iter().zip(mesh.triangles().iter()) {
            assert_eq!(*t, [u[0], u[2], u[1]]);
        }
        // The moved normals follow the right-hand rule with the reported
        // winding.
        let vs = moved.vertices();
        for _ in 0..300 {
            let ray = Ray::from_ball_unchecked(&random_point(&mut rng, 2.0), rng.direction());
            if let Some((hit, i)) = moved.intersect_indexed(&ray, 0.0, f64::INFINITY) {
                let [a, b, c] = tris[i].map(|k| crate::point::Vertex::from(vs[k as usize]));
                let n = HPlane::through(&a, &b, &c).unwrap().normal();
                assert!(lorentz::dot(n, hit.normal) > 0.99, "{n} vs {}", hit.normal);
            }
        }
    }
}
