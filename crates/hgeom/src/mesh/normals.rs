//! Smooth shading normals for triangle meshes (`docs/geometry.md`, "Smooth
//! meshes").
//!
//! Each corner of a triangle gets a unit normal at its vertex: one given by
//! the mesh file, or the angle-weighted average of the plane normals of the
//! triangles around the vertex whose normals are within the crease angle of
//! the corner's own (so creases sharper than the angle stay sharp and a
//! vertex on a crease gets one normal per side).
//!
//! **Storage.** A tangent vector `T` at a local hyperboloid vertex `A` is
//! stored as the unit Euclidean 3-vector `t` with `T = B_A (t, 0)`, where
//! `B_A` is the translation from the local origin to `A`: the direction at
//! the origin that the translation carries to `T`. Such a vector is well
//! scaled wherever `A` is, so `f32` holds it to 6e-8; corners whose normal
//! is their triangle's plane normal store no vector at all ([`FLAT`]).
//!
//! **Interpolation.** The hit point `X` and the vertices are points of the
//! Klein model of the local frame, where the h-triangle is a Euclidean
//! triangle, so `X` has exact, well-defined barycentric coordinates `λ`
//! there. The shading normal is `B_X (m / |m|, 0)` with `m = Σ λ_i t_i`:
//! interpolated at the origin, carried to the hit point, a unit tangent
//! there by construction.

use std::collections::HashMap;

use glam::{DVec3, DVec4};

use super::TriangleMesh;
use super::build::kept_plane;
use crate::error::GeomError;
use crate::lorentz;

/// A corner index meaning "the triangle's own plane normal".
const FLAT: u32 = u32::MAX;
/// Two plane normals closer than this (`1 - cos`) count as the same plane.
const SAME_PLANE: f64 = 1e-12;

/// Vertex normals given with the mesh (from a file).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GivenNormals {
    /// Tangent vectors of the hyperboloid, in the frame of the vertices given
    /// to [`TriangleMesh::new`]; each is used at the vertex of the corners
    /// that refer to it and need not be unit or exactly tangent there (it is
    /// projected onto the vertex's tangent space and normalised).
    pub normals: Vec<DVec4>,
    /// The triangles given to [`TriangleMesh::new`], dropped ones included.
    pub triangles: Vec<[u32; 3]>,
    /// One entry per entry of `triangles`: for each corner, an index into
    /// `normals`, or `u32::MAX` where the file gives none (that corner's
    /// normal is then computed).
    pub corners: Vec<[u32; 3]>,
}

/// The stored vertex normals of a smoothed mesh.
#[derive(Debug, PartialEq)]
pub(super) struct Smooth {
    /// The crease angle asked for, in degrees.
    crease: f64,
    /// Unit directions at the local origin (see the module docs).
    normals: Vec<[f32; 3]>,
    /// For each kept triangle, its corners' indices into `normals`, or
    /// [`FLAT`].
    corners: Vec<[u32; 3]>,
}

impl TriangleMesh {
    /// The bytes of vertex-normal data a smoothed mesh holds (0 unless
    /// [`TriangleMesh::smoothed`]): 12 per triangle (three `u32` corner
    /// indices) and 12 per distinct stored normal (three `f32`).
    ///
    /// # Accuracy
    ///
    /// Exact.
    pub fn smooth_bytes(&self) -> usize {
        self.smooth
            .as_ref()
            .map_or(0, |s| s.normals.len() * 12 + s.corners.len() * 12)
    }

    /// The crease angle in degrees of a smoothed mesh
    /// ([`TriangleMesh::smoothed`]); `None` for a flat-shaded one.
    ///
    /// # Accuracy
    ///
    /// Exact.
    pub fn smooth_angle(&self) -> Option<f64> {
        self.smooth.as_ref().map(|s| s.crease)
    }

    /// The same mesh shaded smoothly: hits get a shading normal
    /// ([`Hit::shading`](crate::Hit::shading)) interpolated from vertex
    /// normals, while `normal`, the geometry and the hits themselves stay
    /// those of the flat mesh.
    ///
    /// Corners with a normal in `given` use it; the others get the
    /// angle-weighted average of the plane normals of the triangles at
    /// their vertex whose normals are within `crease_degrees` of their own
    /// triangle's. A corner whose average is its own plane normal (a flat
    /// or creased region) shades exactly flat.
    ///
    /// Errors: [`GeomError::BadCreaseAngle`] for an angle outside
    /// `0..=180` (or not a number); [`GeomError::MeshIndexOutOfRange`] when
    /// `given` has the wrong number of triangles or a corner refers past
    /// its normals (`index` is the offending index, `vertices` the number
    /// of normals).
    ///
    /// # Accuracy
    ///
    /// The stored directions are `f32` (6e-8); carrying a normal from a
    /// vertex `d` from the mesh's centre to the origin and back loses about
    /// `eps cosh^2 d`. The shading normal is a unit tangent at the hit point
    /// to the rounding of the placement (1e-12 measured). An h-sphere of
    /// radius 0.5 tessellated into 8192 triangles shades within 5e-3 rad of
    /// its true normal with computed vertex normals (flat: 4.5e-2), and
    /// within 4e-8 with exact ones
    /// (`smoothed_sphere_shades_with_the_true_sphere_normal` in
    /// `tests/mesh_smooth.rs`).
    pub fn smoothed(
        &self,
        crease_degrees: f64,
        given: Option<&GivenNormals>,
    ) -> Result<TriangleMesh, GeomError> {
        if !(0.0..=180.0).contains(&crease_degrees) {
            return Err(GeomError::BadCreaseAngle(crease_degrees));
        }
        let sh = &*self.shared;
        let triangles = sh.given_order();
        let kept = triangles.len();
        // Plane normals per kept triangle, as the intersection computes them.
        let mut planes = vec![DVec4::ZERO; kept];
        for (pos, &k) in sh.order.iter().enumerate() {
            if let Some(plane) = kept_plane(sh.corners(pos)) {
                planes[k as usize] = plane.normal();
            }
        }
        let verts = |k: usize| triangles[k].map(|i| sh.local[i as usize]);
        let given_local = match given {
            Some(g) => Some(self.kept_given(g, &triangles)?),
            None => None,
        };
        // The corners at each vertex.
        let mut at_vertex: HashMap<u32, Vec<(usize, usize)>> = HashMap::new();
        for (k, t) in triangles.iter().enumerate() {
            for (c, &v) in t.iter().enumerate() {
                at_vertex.entry(v).or_default().push((k, c));
            }
        }
        let cos_crease = crease_degrees.to_radians().cos();
        let mut normals: Vec<[f32; 3]> = Vec::new();
        let mut index: HashMap<(u32, [u32; 3]), u32> = HashMap::new();
        let mut corners = vec![[FLAT; 3]; kept];
        for (k, t) in triangles.iter().enumerate() {
            for c in 0..3 {
                let a = verts(k)[c];
                let tangent = match given_local.as_ref().and_then(|g| g[k][c]) {
                    Some(n) => Some(n),
                    None => computed(&at_vertex[&t[c]], &planes, &verts, k, cos_crease),
                };
                // Plane normals are tangent at the vertex only to rounding.
                let Some(tangent) = tangent.and_then(|n| unit_tangent(a, n)) else {
                    continue;
                };
                let Some(dir) = to_origin(a, tangent) else {
                    continue;
                };
                let stored = [dir.x as f32, dir.y as f32, dir.z as f32];
                let key = (t[c], stored.map(f32::to_bits));
                // At most three normals per triangle, and triangles are
                // counted in u32 indices.
                let next = u32::try_from(normals.len()).unwrap_or(FLAT);
                corners[k][c] = *index.entry(key).or_insert_with(|| {
                    normals.push(stored);
                    next
                });
            }
        }
        let mut mesh = self.clone();
        mesh.smooth = Some(std::sync::Arc::new(Smooth {
            crease: crease_degrees,
            normals,
            corners,
        }));
        Ok(mesh)
    }

    /// The given normals of the kept triangles, carried into the local frame
    /// and made unit tangents at their vertices (`None`: compute).
    fn kept_given(
        &self,
        g: &GivenNormals,
        triangles: &[[u32; 3]],
    ) -> Result<Vec<[Option<DVec4>; 3]>, GeomError> {
        let sh = &*self.shared;
        let to_local = sh.base.inverse().to_lorentz();
        if g.corners.len() != g.triangles.len() {
            return Err(GeomError::MeshIndexOutOfRange {
                triangle: g.corners.len().min(g.triangles.len()),
                index: 0,
                vertices: g.normals.len(),
            });
        }
        // The kept triangles are the given ones in order, less the dropped
        // (degenerate) ones; a dropped triangle never equals a kept one.
        let mut aligned = Vec::with_capacity(triangles.len());
        for (t, c) in g.triangles.iter().zip(&g.corners) {
            if triangles.get(aligned.len()) == Some(t) {
                aligned.push(*c);
            }
        }
        if aligned.len() != triangles.len() {
            return Err(GeomError::MeshIndexOutOfRange {
                triangle: g.triangles.len(),
                index: 0,
                vertices: g.normals.len(),
            });
        }
        let mut result = Vec::with_capacity(aligned.len());
        for (k, c) in aligned.iter().enumerate() {
            let mut row = [None; 3];
            for j in 0..3 {
                if c[j] == FLAT {
                    continue;
                }
                let Some(n) = g.normals.get(c[j] as usize) else {
                    return Err(GeomError::MeshIndexOutOfRange {
                        triangle: k,
                        index: c[j],
                        vertices: g.normals.len(),
                    });
                };
                let a = sh.local[triangles[k][j] as usize];
                row[j] = unit_tangent(a, to_local * *n);
            }
            result.push(row);
        }
        Ok(result)
    }

    /// The shading normal at world hit `point` on kept triangle `k` (at
    /// leaf position `pos`), whose world plane normal is `normal` (see the
    /// module docs).
    pub(super) fn shading_normal(
        &self,
        smooth: &Smooth,
        (k, pos): (usize, usize),
        point: DVec4,
        normal: DVec4,
    ) -> DVec4 {
        let corners = smooth.corners[k];
        if corners == [FLAT; 3] {
            return normal;
        }
        let v = self.shared.corners(pos);
        let x = self.to_local * point;
        let klein = |p: DVec4| p.truncate() / p.w;
        let (k0, k1, k2, kx) = (klein(v[0]), klein(v[1]), klein(v[2]), klein(x));
        let e = (k1 - k0).cross(k2 - k0);
        let area = e.length_squared();
        if !(area > 0.0) {
            return normal;
        }
        let raw = [
            (k1 - kx).cross(k2 - kx).dot(e) / area,
            (k2 - kx).cross(k0 - kx).dot(e) / area,
            (k0 - kx).cross(k1 - kx).dot(e) / area,
        ];
        // The hit lies in the triangle up to rounding: clamp it back in.
        let lambda = raw.map(|l| l.max(0.0));
        let sum: f64 = lambda.iter().sum();
        if !(sum > 0.0) {
            return normal;
        }
        let local_plane = self.to_local * normal;
        let mut m = DVec3::ZERO;
        for c in 0..3 {
            let dir = match corners[c] {
                FLAT => to_origin(v[c], local_plane).unwrap_or(DVec3::ZERO),
                i => DVec3::from(smooth.normals[i as usize].map(f64::from)),
            };
            m += dir * (lambda[c] / sum);
        }
        let len = m.length();
        if !(len > 1e-6) {
            return normal;
        }
        let world = self.to_world * from_origin(x, m / len);
        unit_tangent(point, world).unwrap_or(normal)
    }
}

/// The computed normal of corner `k` at a vertex whose corners are `around`:
/// the angle-weighted sum of the plane normals within the crease of `k`'s,
/// or `None` when they are all `k`'s own plane (flat).
fn computed(
    around: &[(usize, usize)],
    planes: &[DVec4],
    verts: &dyn Fn(usize) -> [DVec4; 3],
    k: usize,
    cos_crease: f64,
) -> Option<DVec4> {
    let own = planes[k];
    let mut sum = DVec4::ZERO;
    let mut flat = true;
    for &(j, c) in around {
        let cos = lorentz::dot(own, planes[j]);
        if cos < cos_crease && j != k {
            continue;
        }
        flat &= cos >= 1.0 - SAME_PLANE;
        sum += planes[j] * corner_angle(verts(j), c);
    }
    if flat { None } else { Some(sum) }
}

/// The h-angle of triangle `v` at corner `c`.
fn corner_angle(v: [DVec4; 3], c: usize) -> f64 {
    let a = v[c];
    let along = |b: DVec4| b + a * lorentz::dot(a, b);
    let (u, w) = (along(v[(c + 1) % 3]), along(v[(c + 2) % 3]));
    let cos = lorentz::dot(u, w) / (lorentz::norm(u) * lorentz::norm(w));
    if cos.is_finite() {
        cos.clamp(-1.0, 1.0).acos()
    } else {
        0.0
    }
}

/// `n` made a unit tangent at `a`, if it has a tangential part.
fn unit_tangent(a: DVec4, n: DVec4) -> Option<DVec4> {
    let t = n + a * lorentz::dot(a, n);
    let len = lorentz::norm(t);
    (len > 0.0 && len.is_finite()).then(|| t / len)
}

/// The unit direction `t` at the origin that the translation to `a` carries
/// to the direction of tangent `n` (`n = B_a (s t, 0)`, `s > 0`).
fn to_origin(a: DVec4, n: DVec4) -> Option<DVec3> {
    let t = n.truncate() - a.truncate() * (n.w / (1.0 + a.w));
    let len = t.length();
    (len > 0.0 && len.is_finite()).then(|| t / len)
}

/// `B_a (t, 0)`: direction `t` at the origin carried to `a` by the
/// translation (a unit tangent at `a` when `t` is a unit vector).
fn from_origin(a: DVec4, t: DVec3) -> DVec4 {
    let s = a.truncate().dot(t);
    (t + a.truncate() * (s / (1.0 + a.w))).extend(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::point::Point;

    #[test]
    fn translation_of_directions_round_trips_and_is_tangent() {
        let a = Point::new(0.3, -0.5, 0.2).unwrap().to_hyperboloid();
        let t = DVec3::new(0.48, 0.6, -0.64);
        let n = from_origin(a, t);
        assert!(lorentz::dot(n, a).abs() < 1e-14);
        assert!((lorentz::dot(n, n) - 1.0).abs() < 1e-14);
        let back = to_origin(a, n).unwrap();
        assert!((back - t).length() < 1e-14);
    }
}
