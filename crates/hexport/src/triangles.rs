//! Triangle meshes from OBJ and PLY files. Each of their triangles is a
//! geodesic triangle, flat in the Klein model and curved in the ball: it
//! is subdivided `k` times along each side in Klein coordinates (every
//! point exactly on it) and mapped to the ball. One `k` serves the whole
//! mesh, and a point on a shared side is computed from that side's two
//! vertices in index order, so neighbouring triangles share it bit for
//! bit and the mesh stays as closed as it was given.

use std::collections::HashMap;

use hgeom::glam::{DVec3, DVec4};

use crate::grid::TriangleShell;
use crate::measure::to_ball;

/// The most subdivisions of a side.
const MAX_SUBDIVISIONS: usize = 64;

/// Where a subdivision point sits: a corner, on a side (its vertices in
/// index order and the step from the first), or inside one triangle.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Site {
    Corner(u32),
    Side(u32, u32, usize),
    Inside(usize, usize, usize),
}

fn klein(x: DVec4) -> DVec3 {
    x.truncate() / x.w
}

fn from_klein(k: DVec3) -> DVec3 {
    to_ball(k.extend(1.0) / (1.0 - k.length_squared()).sqrt())
}

/// The ball point at barycentric steps `(i, j)` of `k` (the third is
/// `k - i - j`) in triangle `t`, computed from its site.
fn point(ks: &[DVec3], t: [u32; 3], i: usize, j: usize, k: usize) -> (Site, DVec3) {
    let l = k - i - j;
    let steps = [i, j, l];
    let nonzero: Vec<usize> = (0..3).filter(|&c| steps[c] > 0).collect();
    match nonzero[..] {
        [c] => (Site::Corner(t[c]), from_klein(ks[t[c] as usize])),
        [c, d] => {
            let (lo, hi, step) = if t[c] < t[d] {
                (t[c], t[d], steps[d])
            } else {
                (t[d], t[c], steps[c])
            };
            let (a, b) = (ks[lo as usize], ks[hi as usize]);
            let p = a + (b - a) * (step as f64 / k as f64);
            (Site::Side(lo, hi, step), from_klein(p))
        }
        _ => {
            let [a, b, c] = t.map(|v| ks[v as usize]);
            let p = (a * i as f64 + b * j as f64 + c * l as f64) / k as f64;
            (Site::Inside(i, j, usize::MAX), from_klein(p))
        }
    }
}

/// The deviation of triangle `t` subdivided `k` times: how far the exact
/// surface at the middle of each small side lies from the chord.
fn deviation(ks: &[DVec3], t: [u32; 3], k: usize) -> f64 {
    let [a, b, c] = t.map(|v| ks[v as usize]);
    let at = |i: f64, j: f64| {
        let l = k as f64 - i - j;
        (a * i + b * j + c * l) / k as f64
    };
    let mut worst: f64 = 0.0;
    for i in 0..k {
        for j in 0..k - i {
            let (i, j) = (i as f64, j as f64);
            for (p, q) in [
                ((i, j), (i + 1.0, j)),
                ((i, j), (i, j + 1.0)),
                ((i + 1.0, j), (i, j + 1.0)),
            ] {
                let chord = 0.5 * (from_klein(at(p.0, p.1)) + from_klein(at(q.0, q.1)));
                let exact = from_klein(at(0.5 * (p.0 + q.0), 0.5 * (p.1 + q.1)));
                worst = worst.max((exact - chord).length());
            }
        }
    }
    worst
}

/// The mesh's triangles subdivided until within `tolerance` (ball units),
/// with at most `budget` triangles; `None` if it needs more.
pub fn subdivide(
    vertices: &[DVec4],
    triangles: &[[u32; 3]],
    tolerance: f64,
    budget: usize,
) -> Option<TriangleShell> {
    let ks: Vec<DVec3> = vertices.iter().map(|x| klein(*x)).collect();
    let mut k = 1;
    while k < MAX_SUBDIVISIONS && triangles.iter().any(|t| deviation(&ks, *t, k) > tolerance) {
        k *= 2;
    }
    if triangles.len().saturating_mul(k * k) > budget {
        return None;
    }
    let mut index: HashMap<Site, u32> = HashMap::new();
    let mut out = TriangleShell::default();
    for (n, t) in triangles.iter().enumerate() {
        let mut id = |i: usize, j: usize| -> u32 {
            let (site, p) = point(&ks, *t, i, j, k);
            let site = match site {
                Site::Inside(i, j, _) => Site::Inside(i, j, n),
                other => other,
            };
            *index.entry(site).or_insert_with(|| {
                out.vertices.push(p);
                // Bounded by the budget, far below u32::MAX.
                (out.vertices.len() - 1) as u32
            })
        };
        // Steps (i, j) weight corners 0 and 1; corner 2 takes the rest.
        // Small triangles keep the big one's winding.
        let mut small = Vec::new();
        for i in 0..k {
            for j in 0..k - i {
                small.push([id(i + 1, j), id(i, j + 1), id(i, j)]);
                if i + j + 2 <= k {
                    small.push([id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
                }
            }
        }
        out.triangles.extend(small);
    }
    Some(out)
}

/// How many triangles use the worst edge, if some edge of the mesh is not
/// used exactly twice in opposite directions (an open or non-manifold
/// mesh); `None` when it is closed.
pub fn open_edge(triangles: &[[u32; 3]]) -> Option<usize> {
    let mut uses: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
    for t in triangles {
        for c in 0..3 {
            let (a, b) = (t[c], t[(c + 1) % 3]);
            let e = uses.entry((a.min(b), a.max(b))).or_default();
            if a < b {
                e.0 += 1;
            } else {
                e.1 += 1;
            }
        }
    }
    let mut bad: Vec<usize> = uses
        .values()
        .filter(|&&(f, b)| !(f == 1 && b == 1))
        .map(|&(f, b)| f + b)
        .collect();
    bad.sort_unstable();
    bad.first().copied()
}
