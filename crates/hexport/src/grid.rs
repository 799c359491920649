//! Every exported solid is a sphere topologically: a surface `F(u, v)`
//! with `u` in `[0, 1]` running from one pole to the other and `v` in
//! `[0, 1)` round the axis. A grid of rows (constant `u`) and columns
//! (constant `v`) with a fan at each pole is then a closed, consistently
//! wound 2-manifold by construction, whatever `F` is: each interior grid
//! edge is shared by exactly two triangles, each row closes on itself, and
//! the two poles are single vertices.
//!
//! **Creases.** A surface made of pieces (a capsule's caps and body, a
//! plate's top, side and bottom, a polygon's corners) lists the parameters
//! where the pieces meet; they are grid lines, so the triangles follow
//! every crease exactly and never cut a corner.
//!
//! **Refinement.** Each span between creases starts with one or a few
//! subdivisions and is doubled while the exact surface at the middle of a
//! grid edge, or at the middle of a grid cell, lies farther than the
//! tolerance from the chord midpoint (for a cell: the midpoint of the
//! diagonal its triangles share). That is the sagitta test of a mesher;
//! every grid vertex itself is an exact surface point.

use hgeom::glam::DVec3;

/// A surface with the topology of a sphere (module docs).
pub trait PoleSurface: Sync {
    /// The surface point at `(u, v)`; at `u = 0` and `u = 1` it must not
    /// depend on `v` (the poles).
    fn point(&self, u: f64, v: f64) -> DVec3;

    /// The creases along `u`: increasing, from `0` to `1`.
    fn u_creases(&self) -> Vec<f64>;

    /// The creases round the axis: increasing, from `0`, below `1`.
    fn v_creases(&self) -> Vec<f64>;
}

/// A closed triangle mesh: vertices and counter-clockwise triangles
/// (before the caller orients it).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleShell {
    /// The vertices.
    pub vertices: Vec<DVec3>,
    /// Triangles as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
}

/// The grid's parameters: each crease span subdivided `counts[k]` times.
fn parameters(creases: &[f64], end: f64, counts: &[usize]) -> Vec<(f64, usize)> {
    let mut out = Vec::new();
    for (k, &n) in counts.iter().enumerate() {
        let a = creases[k];
        let b = creases.get(k + 1).copied().unwrap_or(end);
        for i in 0..n {
            out.push((a + (b - a) * i as f64 / n as f64, k));
        }
    }
    out
}

/// Triangles of a grid with `rows` rows of `columns` points and `columns`
/// >= 3, plus two poles.
fn triangle_count(rows: usize, columns: usize) -> usize {
    2 * columns * rows.saturating_sub(1) + 2 * columns
}

/// The grid mesh of `surface` within `tolerance`, with at most `budget`
/// triangles; `None` if it needs more.
pub fn mesh_surface(
    surface: &dyn PoleSurface,
    tolerance: f64,
    budget: usize,
) -> Option<TriangleShell> {
    let uc = surface.u_creases();
    let vc = surface.v_creases();
    // At least two rows per span (a pole span needs a row to fan to) and
    // three columns in all.
    let mut nu = vec![2usize; uc.len() - 1];
    let mut nv = vec![(3usize).div_ceil(vc.len()).max(1); vc.len()];
    loop {
        let us = parameters(&uc, 1.0, &nu);
        let vs = parameters(&vc, 1.0, &nv);
        // Rows are the u parameters but the first (the pole at 0).
        let rows = &us[1..];
        if triangle_count(rows.len(), vs.len()) > budget {
            return None;
        }
        let grid: Vec<Vec<DVec3>> = rows
            .iter()
            .map(|&(u, _)| vs.iter().map(|&(v, _)| surface.point(u, v)).collect())
            .collect();
        let (south, north) = (surface.point(0.0, 0.0), surface.point(1.0, 0.0));
        let mut grow_u = vec![false; nu.len()];
        let mut grow_v = vec![false; nv.len()];
        let far = |exact: DVec3, chord: DVec3| (exact - chord).length() > tolerance;
        // The rows with the poles as degenerate rows at either end.
        let row_at = |i: usize, j: usize| -> DVec3 {
            match i {
                0 => south,
                i if i > rows.len() => north,
                i => grid[i - 1][j],
            }
        };
        let u_at = |i: usize| {
            if i > rows.len() {
                (1.0, nu.len() - 1)
            } else {
                us[i]
            }
        };
        for i in 0..=rows.len() {
            let (u0, span) = u_at(i);
            let (u1, _) = u_at(i + 1);
            let um = 0.5 * (u0 + u1);
            for j in 0..vs.len() {
                let (v0, vspan) = vs[j];
                let v1 = vs.get(j + 1).map_or(1.0, |x| x.0);
                let vm = 0.5 * (v0 + v1);
                let jn = (j + 1) % vs.len();
                let (a, b) = (row_at(i, j), row_at(i + 1, j));
                if far(surface.point(um, v0), 0.5 * (a + b)) {
                    grow_u[span] = true;
                }
                if i > 0 && far(surface.point(u0, vm), 0.5 * (a + row_at(i, jn))) {
                    grow_v[vspan] = true;
                }
                if far(surface.point(um, vm), 0.5 * (a + row_at(i + 1, jn))) {
                    grow_u[span] = true;
                    grow_v[vspan] = true;
                }
            }
        }
        if !grow_u.contains(&true) && !grow_v.contains(&true) {
            return Some(assemble(grid, south, north));
        }
        for (n, grow) in nu.iter_mut().zip(&grow_u) {
            if *grow {
                *n *= 2;
            }
        }
        for (n, grow) in nv.iter_mut().zip(&grow_v) {
            if *grow {
                *n *= 2;
            }
        }
    }
}

/// The triangles of the grid: fans at the poles, two triangles a cell.
fn assemble(grid: Vec<Vec<DVec3>>, south: DVec3, north: DVec3) -> TriangleShell {
    let columns = grid[0].len();
    let rows = grid.len();
    let mut vertices = Vec::with_capacity(rows * columns + 2);
    vertices.push(south);
    for row in grid {
        vertices.extend(row);
    }
    vertices.push(north);
    // Vertex counts are bounded by the triangle budget, far below u32::MAX.
    let at = |i: usize, j: usize| (1 + i * columns + j % columns) as u32;
    let north_index = (vertices.len() - 1) as u32;
    let mut triangles = Vec::with_capacity(triangle_count(rows, columns));
    for j in 0..columns {
        triangles.push([0, at(0, j + 1), at(0, j)]);
    }
    for i in 0..rows - 1 {
        for j in 0..columns {
            triangles.push([at(i, j), at(i, j + 1), at(i + 1, j + 1)]);
            triangles.push([at(i, j), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    for j in 0..columns {
        triangles.push([at(rows - 1, j), at(rows - 1, j + 1), north_index]);
    }
    TriangleShell {
        vertices,
        triangles,
    }
}
