//! Reproducible random meshes for the unit tests of the mesh modules.

use std::f64::consts::TAU;

use glam::DVec3;

use super::TriangleMesh;
use crate::isometry::Isometry;
use crate::point::Point;

/// SplitMix64, for reproducible random meshes.
pub(super) struct Rng(pub(super) u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    pub(super) fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
    }

    pub(super) fn dir(&mut self) -> DVec3 {
        let z = self.uniform(-1.0, 1.0);
        let phi = self.uniform(0.0, TAU);
        let s = (1.0 - z * z).max(0.0).sqrt();
        DVec3::new(s * phi.cos(), s * phi.sin(), z)
    }

    pub(super) fn point(&mut self, max: f64) -> Point {
        let d = self.dir();
        Point::at_distance_from_origin(d, self.uniform(0.0, max)).unwrap()
    }
}

pub(super) fn p(x: f64, y: f64, z: f64) -> Point {
    Point::from_coords(DVec3::new(x, y, z)).unwrap()
}

/// Triangles scattered through a ball of radius `reach`, each with
/// sides up to about `size`.
pub(super) fn soup(rng: &mut Rng, count: usize, reach: f64, size: f64) -> TriangleMesh {
    let mut vertices = Vec::with_capacity(3 * count);
    let mut triangles = Vec::with_capacity(count);
    for i in 0..count as u32 {
        let c = rng.point(reach);
        for _ in 0..3 {
            let dir = rng.dir();
            vertices.push(Isometry::transvection_from_origin(c).apply(
                &Point::at_distance_from_origin(dir, rng.uniform(0.1, 1.0) * size).unwrap(),
            ));
        }
        triangles.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    TriangleMesh::new(vertices, triangles).unwrap()
}
