//! The scene's one acceleration structure: a bounding-volume hierarchy of
//! axis-aligned boxes in the Klein model over every bounded surface (each
//! part of a composite is a surface of its own), plus the short list of
//! unbounded surfaces every ray tests.
//!
//! In the Klein model every ray is a straight chord and every bounded
//! surface has an exact box ([`hgeom::KleinBox`]), so this is the standard
//! machinery of Euclidean tracers: a binned surface-area-heuristic build
//! ([`build`]), boxes stored in `f32` rounded outwards (half the memory
//! traffic of `f64`, never smaller than the `f64` box), the slab test in
//! `f64`, nearest-first traversal ordered by the chord parameter `λ` (which
//! increases with hyperbolic distance along the ray), and any-hit traversal
//! for shadow rays. Exactness stays with the leaves: every box test is
//! conservative, and the exact `f64` intersection decides.

mod build;

use hgeom::glam::DVec3;
use hgeom::{Hit, KleinRay, Ray};

pub use build::Leaf;

/// What a visit asks the traversal to do next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Keep going.
    Continue,
    /// Stop the traversal (a shadow ray found an opaque blocker).
    Stop,
}

/// A node of the hierarchy: its box, and either its children (`count ==
/// 0`: the left child is the next node, the right one at `index`) or its
/// items (`items[index .. index + count]`).
#[derive(Clone, Copy, Debug)]
struct Node {
    lo: [f32; 3],
    hi: [f32; 3],
    index: u32,
    count: u32,
}

impl Node {
    /// Where the chord enters the node's box within `[lo, hi]`. The box in
    /// `f64` is exact (every `f32` is an `f64`) and valid by construction.
    #[inline(always)]
    fn entry(&self, chord: &KleinRay, lo: f64, hi: f64) -> Option<f64> {
        let f = |a: [f32; 3]| DVec3::new(a[0].into(), a[1].into(), a[2].into());
        chord.slab_entry(f(self.lo), f(self.hi), lo, hi)
    }
}

/// The hierarchy over items `0..n` and the items without a box.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    nodes: Vec<Node>,
    /// Leaf contents, in node order.
    items: Vec<u32>,
    unbounded: Vec<u32>,
}

/// The deepest a hierarchy may be: the build stops splitting there (the
/// binned build halves the item count at least every few levels, so real
/// scenes stay far below), so a fixed traversal stack always suffices.
const MAX_DEPTH: usize = 60;

impl Accel {
    /// From leaves: each a box and the item it bounds (an item may have
    /// several boxes; its exact test then runs at most once per box the ray
    /// enters, which is harmless: a repeated test finds nothing nearer), and
    /// the items with no box at all.
    pub fn new(leaves: Vec<Leaf>, unbounded: Vec<u32>) -> Accel {
        let (nodes, items) = build::build(leaves);
        Accel {
            nodes,
            items,
            unbounded,
        }
    }

    /// The nearest hit among the items on the ray's arc `(t_min, t_max)`:
    /// `test(item, t_min, t_max)` is the item's exact test, called with the
    /// nearest hit so far as `t_max`.
    #[inline]
    pub fn nearest(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        mut test: impl FnMut(u32, f64, f64) -> Option<Hit>,
    ) -> Option<(Hit, u32)> {
        let mut best = None;
        let mut limit = t_max;
        for &i in &self.unbounded {
            if let Some(hit) = test(i, t_min, limit) {
                limit = hit.t;
                best = Some((hit, i));
            }
        }
        if self.nodes.is_empty() {
            return best;
        }
        let chord = KleinRay::new(ray);
        if !chord.is_finite() {
            // No chord to cull with: every item gets its exact test.
            for i in self.items.iter().copied() {
                if let Some(hit) = test(i, t_min, limit) {
                    limit = hit.t;
                    best = Some((hit, i));
                }
            }
            return best;
        }
        let (lo, mut hi) = chord.arc(t_min, limit);
        let mut stack = [(0u32, 0f64); MAX_DEPTH + 1];
        let mut top = 0usize;
        let Some(root) = self.entry(&chord, 0, lo, hi) else {
            return best;
        };
        stack[0] = (0, root);
        top += 1;
        let mut last = u32::MAX;
        while top > 0 {
            top -= 1;
            let (n, enter) = stack[top];
            if enter > hi {
                continue;
            }
            let node = self.nodes[n as usize];
            if node.count > 0 {
                let first = node.index as usize;
                for &i in &self.items[first..first + node.count as usize] {
                    // Consecutive boxes of one item (a rod's pieces) need
                    // one exact test.
                    if i == last {
                        continue;
                    }
                    last = i;
                    if let Some(hit) = test(i, t_min, limit) {
                        limit = hit.t;
                        hi = chord.arc_end_at(hit.point);
                        best = Some((hit, i));
                    }
                }
                continue;
            }
            let (left, right) = (n + 1, node.index);
            let l = self.entry(&chord, left, lo, hi);
            let r = self.entry(&chord, right, lo, hi);
            match (l, r) {
                (Some(el), Some(er)) => {
                    // The farther child goes below, so the nearer is taken
                    // first and can shrink the arc for the other.
                    let (near, far) = if el <= er {
                        ((left, el), (right, er))
                    } else {
                        ((right, er), (left, el))
                    };
                    stack[top] = far;
                    stack[top + 1] = near;
                    top += 2;
                }
                (Some(el), None) => {
                    stack[top] = (left, el);
                    top += 1;
                }
                (None, Some(er)) => {
                    stack[top] = (right, er);
                    top += 1;
                }
                (None, None) => {}
            }
        }
        best
    }

    /// Visit every item that may meet the ray's arc `(t_min, t_max)`, in no
    /// particular order, until `visit` says stop.
    #[inline]
    pub fn any(&self, ray: &Ray, t_min: f64, t_max: f64, mut visit: impl FnMut(u32) -> Step) {
        for &i in &self.unbounded {
            if visit(i) == Step::Stop {
                return;
            }
        }
        if self.nodes.is_empty() {
            return;
        }
        let chord = KleinRay::new(ray);
        if !chord.is_finite() {
            for i in self.items.iter().copied() {
                if visit(i) == Step::Stop {
                    return;
                }
            }
            return;
        }
        let (lo, hi) = chord.arc(t_min, t_max);
        let mut stack = [0u32; MAX_DEPTH + 1];
        let mut top = 0usize;
        if self.entry(&chord, 0, lo, hi).is_some() {
            top = 1;
        }
        let mut last = u32::MAX;
        while top > 0 {
            top -= 1;
            let n = stack[top];
            let node = self.nodes[n as usize];
            if node.count > 0 {
                let first = node.index as usize;
                for &i in &self.items[first..first + node.count as usize] {
                    if i == last {
                        continue;
                    }
                    last = i;
                    if visit(i) == Step::Stop {
                        return;
                    }
                }
                continue;
            }
            for child in [node.index, n + 1] {
                if self.entry(&chord, child, lo, hi).is_some() {
                    stack[top] = child;
                    top += 1;
                }
            }
        }
    }

    #[inline(always)]
    fn entry(&self, chord: &KleinRay, node: u32, lo: f64, hi: f64) -> Option<f64> {
        self.nodes[node as usize].entry(chord, lo, hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::{HSphere, Point, Shape};

    /// Random small spheres: the hierarchy's nearest hit equals the
    /// exhaustive search's, and its any-hit visits every sphere the ray
    /// meets.
    #[test]
    fn hierarchy_agrees_with_exhaustive_search() {
        let mut state = 7u64;
        let mut rnd = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64) / ((1u64 << 53) as f64) * 2.0 - 1.0
        };
        let mut spheres = Vec::new();
        while spheres.len() < 500 {
            let c = DVec3::new(rnd(), rnd(), rnd()) * 0.9;
            if c.length() < 0.9 {
                spheres.push(
                    HSphere::new(Point::from_coords(c).unwrap(), 0.02 + 0.1 * rnd().abs()).unwrap(),
                );
            }
        }
        let leaves: Vec<Leaf> = spheres
            .iter()
            .enumerate()
            .flat_map(|(i, s)| {
                s.klein_boxes()
                    .into_iter()
                    .map(move |b| Leaf::new(b, i as u32))
            })
            .collect();
        let accel = Accel::new(leaves, Vec::new());
        let mut hits = 0;
        for k in 0..3000 {
            let dir = DVec3::new(rnd(), rnd(), rnd());
            let start = Point::from_coords(DVec3::new(rnd(), rnd(), rnd()) * 0.3).unwrap();
            let ray = Ray::from_ball_unchecked(&start, dir);
            let exhaustive = spheres
                .iter()
                .enumerate()
                .filter_map(|(i, s)| s.intersect(&ray, 1e-9, f64::INFINITY).map(|h| (h.t, i)))
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let found = accel
                .nearest(&ray, 1e-9, f64::INFINITY, |i, lo, hi| {
                    spheres[i as usize].intersect(&ray, lo, hi)
                })
                .map(|(h, i)| (h.t, i as usize));
            assert_eq!(found, exhaustive, "ray {k}");
            if let Some((t, _)) = exhaustive {
                hits += 1;
                let mut seen = vec![false; spheres.len()];
                accel.any(&ray, 1e-9, t * 2.0, |i| {
                    seen[i as usize] = true;
                    Step::Continue
                });
                for (i, s) in spheres.iter().enumerate() {
                    if s.blocks(&ray, 1e-9, t * 2.0) {
                        assert!(seen[i], "ray {k}: any-hit skipped sphere {i}");
                    }
                }
            }
        }
        assert!(hits > 500, "{hits}");
    }
}
