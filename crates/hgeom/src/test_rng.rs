//! A small xorshift generator for hgeom's unit tests (its integration
//! tests use `hscene_test_support`, which unit tests cannot: they would see
//! two copies of hgeom's types).

use glam::DVec3;

/// Xorshift64: enough to spread rays and points, reproducibly.
pub(crate) struct Rng(pub(crate) u64);

impl Rng {
    /// Uniform in `[0, 1)`.
    pub(crate) fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A unit vector, uniform on the sphere (rejection from the cube).
    pub(crate) fn direction(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(self.unit(), self.unit(), self.unit()) * 2.0 - DVec3::ONE;
            if (0.01..1.0).contains(&v.length_squared()) {
                return v.normalize();
            }
        }
    }
}
