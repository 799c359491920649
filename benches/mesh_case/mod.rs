//! The `mesh-N` case of the `scale` bench: the icosphere it renders, the
//! binary PLY file it is read from, and its POV-Ray twin.

use std::fmt::Write as _;

use hgeom::glam::DVec3;
pub use hscene_test_support::icosphere;

/// The number of subdivisions `k` of an icosphere of `n = 20 * 4^k`
/// triangles (at most 9: the PLY file must stay under the loader's 64 MiB).
pub fn subdivisions(n: usize) -> Result<u32, String> {
    (0..=9).find(|&k| 20 << (2 * k) == n).ok_or(format!(
        "--mesh: {n} is not 20 * 4^k triangles (20480, 81920, 327680, 1310720, ...)"
    ))
}

/// A binary little-endian PLY file of a mesh (`float` coordinates, `int`
/// indices, as scanned meshes usually come).
pub fn ply_bytes(verts: &[DVec3], faces: &[[u32; 3]]) -> Vec<u8> {
    let header = format!(
        "ply\nformat binary_little_endian 1.0\ncomment geodesic icosphere (benches/scale.rs)\n\
         element vertex {}\nproperty float x\nproperty float y\nproperty float z\n\
         element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        verts.len(),
        faces.len()
    );
    let mut out = Vec::with_capacity(header.len() + 12 * verts.len() + 13 * faces.len());
    out.extend_from_slice(header.as_bytes());
    for p in verts {
        for c in [p.x, p.y, p.z] {
            out.extend_from_slice(&(c as f32).to_le_bytes());
        }
    }
    for f in faces {
        out.push(3);
        for &i in f {
            out.extend_from_slice(&i.to_le_bytes());
        }
    }
    out
}

/// A mesh as a POV-Ray `mesh2` with its world vertices at their Klein
/// coordinates (`f32` precision, ample for the picture).
pub fn pov_mesh(s: &mut String, m: &hgeom::TriangleMesh, tex: usize) {
    let vertices = m.vertices();
    let _ = writeln!(s, "mesh2 {{ vertex_vectors {{ {}", vertices.len());
    for p in vertices.iter() {
        let h = p.to_hyperboloid();
        let k = (h.truncate() / h.w).as_vec3();
        let _ = writeln!(s, ",<{},{},{}>", k.x, k.y, k.z);
    }
    let triangles = m.triangles();
    let _ = writeln!(s, "}} face_indices {{ {}", triangles.len());
    for [a, b, c] in triangles.iter() {
        let _ = writeln!(s, ",<{a},{b},{c}>");
    }
    let _ = writeln!(s, "}} texture {{ T{tex} }} }}");
}
