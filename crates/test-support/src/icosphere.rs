//! The geodesic icosphere: a sphere mesh of `20 * 4^k` triangles, for the
//! mesh tests and the scale bench.

use hgeom::glam::DVec3;

/// The geodesic icosphere subdivided `k` times: unit vertices and
/// triangles wound counter-clockwise seen from outside.
pub fn icosphere(k: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let g = 0.5 * (1.0 + 5f64.sqrt());
    let mut verts: Vec<DVec3> = [
        (-1.0, g, 0.0),
        (1.0, g, 0.0),
        (-1.0, -g, 0.0),
        (1.0, -g, 0.0),
        (0.0, -1.0, g),
        (0.0, 1.0, g),
        (0.0, -1.0, -g),
        (0.0, 1.0, -g),
        (g, 0.0, -1.0),
        (g, 0.0, 1.0),
        (-g, 0.0, -1.0),
        (-g, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
    .collect();
    let mut faces: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..k {
        let mut middle = std::collections::HashMap::with_capacity(faces.len() * 3 / 2);
        let mut next = Vec::with_capacity(4 * faces.len());
        for [a, b, c] in faces {
            let mut mid = |u: u32, w: u32| {
                *middle.entry((u.min(w), u.max(w))).or_insert_with(|| {
                    verts.push((verts[u as usize] + verts[w as usize]).normalize());
                    verts.len() as u32 - 1
                })
            };
            let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
            next.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        faces = next;
    }
    (verts, faces)
}
