//! Reproducible random meshes for the unit tests of the mesh modules
//! (compiled for tests only). Their points and meshes come from the tests'
//! own constants and seeded streams, never from input: a fixture that
//! cannot be built stops the test through `hscene_test_support::fixture`.

use glam::DVec3;
use hscene_test_support::{SplitMix64, fixture};

use super::TriangleMesh;
use crate::isometry::Isometry;
use crate::point::Point;

/// A random point at most `max` from the origin: a uniform direction, then
/// a uniform distance.
pub(super) fn random_point(rng: &mut SplitMix64, max: f64) -> Point {
    let d = rng.direction();
    fixture(
        Point::at_distance_from_origin(d, rng.range(0.0, max)),
        "a random point",
    )
}

pub(super) fn p(x: f64, y: f64, z: f64) -> Point {
    fixture(Point::from_coords(DVec3::new(x, y, z)), "a ball point")
}

/// Triangles scattered through a ball of radius `reach`, each with
/// sides up to about `size`.
pub(super) fn soup(rng: &mut SplitMix64, count: usize, reach: f64, size: f64) -> TriangleMesh {
    let mut vertices = Vec::with_capacity(3 * count);
    let mut triangles = Vec::with_capacity(count);
    for i in 0..count as u32 {
        let c = random_point(rng, reach);
        for _ in 0..3 {
            let dir = rng.direction();
            vertices.push(Isometry::transvection_from_origin(c).apply(&fixture(
                Point::at_distance_from_origin(dir, rng.range(0.1, 1.0) * size),
                "a triangle vertex",
            )));
        }
        triangles.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    fixture(TriangleMesh::new(vertices, triangles), "a triangle soup")
}
