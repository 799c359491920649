//! The file's vertex normals, carried through the layout into the ball.
//!
//! The layout (see `mesh_file.rs`) sends a file point `u` (centred and
//! scaled) to the h-point at distance `r = size |u|` in the direction of
//! `u`. Its differential stretches the radial direction by `size` and the
//! directions across it by `k = sinh(r) / |u|` (in an orthonormal frame at
//! the image). A normal is orthogonal to the surface's tangent plane, so it
//! maps by the inverse transpose: its radial part is divided by `size`, its
//! transverse part by `k` (`docs/geometry.md`, "Smooth meshes").

use hgeom::GivenNormals;
use hgeom::glam::{DVec3, DVec4};
use std::collections::HashMap;

use super::data::MeshData;

impl MeshData {
    /// The file's normals at the laid-out vertices, as hyperboloid tangent
    /// vectors (see the module docs), with the corners that use them;
    /// `None` when the file gives no normals or the mesh has no extent.
    pub fn layout_normals(&self, size: f64) -> Option<GivenNormals> {
        if self.corner_normals.is_empty() {
            return None;
        }
        let ball = self.bounding_ball()?;
        // One tangent per (vertex, file normal) pair in use: a file may
        // share one normal between vertices, whose tangent spaces differ.
        let mut index: HashMap<(u32, u32), u32> = HashMap::new();
        let mut normals = Vec::new();
        let mut corners = Vec::with_capacity(self.triangles.len());
        for (t, c) in self.triangles.iter().zip(&self.corner_normals) {
            let mut row = [u32::MAX; 3];
            for j in 0..3 {
                let Some(&n) = self.normals.get(c[j] as usize) else {
                    continue;
                };
                let u = ball.unit(self.positions[t[j] as usize]);
                let next = u32::try_from(normals.len()).ok()?;
                row[j] = *index.entry((t[j], c[j])).or_insert_with(|| {
                    normals.push(laid_out(u, n, size));
                    next
                });
            }
            corners.push(row);
        }
        Some(GivenNormals {
            normals,
            triangles: self.triangles.clone(),
            corners,
        })
    }
}

/// The image of normal `n` at the scaled file point `u` (see the module
/// docs), a tangent vector (not unit) at the laid-out vertex.
fn laid_out(u: DVec3, n: DVec3, size: f64) -> DVec4 {
    let len = u.length();
    if len == 0.0 {
        // At the centre the layout is `size` times the identity.
        return n.extend(0.0);
    }
    let radial = u / len;
    let r = size * len;
    let along = n.dot(radial);
    let across = n - along * radial;
    let k = r.sinh() / len;
    // The unit radial tangent at the image, and the transverse part.
    let e_r = (radial * r.cosh()).extend(r.sinh());
    e_r * (along / size) + (across / k).extend(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::{Point, lorentz};

    #[test]
    fn laid_out_normals_are_tangent_and_keep_radial_and_transverse_normals() {
        let (u, size) = (DVec3::new(0.6, 0.0, 0.0), 2.0);
        let p = Point::at_distance_from_origin(u, size * u.length())
            .unwrap()
            .to_hyperboloid();
        for n in [DVec3::X, DVec3::Y, DVec3::new(0.3, -0.4, 0.5)] {
            let t = laid_out(u, n, size);
            assert!(lorentz::dot(t, p).abs() < 1e-12, "{n}");
        }
        // A radial normal stays radial, a transverse one transverse.
        let radial = laid_out(u, DVec3::X, size);
        assert!(radial.y == 0.0 && radial.z == 0.0 && radial.x > 0.0);
        let across = laid_out(u, DVec3::Y, size);
        let expected = DVec4::new(0.0, 0.6 / (1.2f64).sinh(), 0.0, 0.0);
        assert!((across - expected).length() < 1e-15, "{across}");
    }
}
