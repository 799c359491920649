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

use hgeom::{Hit, KleinRay, Ray, plain_max, plain_min};

pub use build::Leaf;

/// What a visit asks the traversal to do next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Keep going.
    Continue,
    /// Stop the traversal (a shadow ray found an opaque blocker).
    Stop,
}

/// A node of the hierarchy: the boxes of its two children side by side,
/// so one pass of two-lane arithmetic tests both; each child is another
/// node (`count == 0`), a leaf (`items[child .. child + count]`), or absent
/// (`child == ABSENT`, only under a root that is a leaf).
#[derive(Clone, Copy, Debug)]
struct PairNode {
    /// `lo[axis][k]`: child `k`'s least corner, rounded down to `f32`.
    lo: [[f32; 2]; 3],
    /// `hi[axis][k]`: its greatest corner, rounded up.
    hi: [[f32; 2]; 3],
    child: [u32; 2],
    count: [u32; 2],
}

const ABSENT: u32 = u32::MAX;

/// A chord set up for slab tests: per axis, its start, `1/V`, and which
/// corner of a box it meets first (the least when `V >= 0`).
#[derive(Clone, Copy, Debug)]
struct Slabs {
    origin: [f64; 3],
    inv_dir: [f64; 3],
    negative: [bool; 3],
}

impl Slabs {
    fn new(chord: &KleinRay) -> Slabs {
        let (o, inv) = (chord.origin(), chord.inv_dir());
        Slabs {
            origin: o.to_array(),
            inv_dir: inv.to_array(),
            negative: [inv.x < 0.0, inv.y < 0.0, inv.z < 0.0],
        }
    }
}

impl PairNode {
    /// Where the chord enters each child's box within `[lo, hi]`, if it
    /// does: [`KleinRay::slab_entry`] for both children in two lanes, with
    /// the near and far corner of each axis chosen once per ray by the
    /// sign of `1/V` instead of a `min` and a `max` per axis (the same
    /// products and comparisons, so the same answer). The boxes in `f64`
    /// are exact (every `f32` is an `f64`).
    #[inline(always)]
    fn entries(&self, s: &Slabs, lo: f64, hi: f64) -> [Option<f64>; 2] {
        let (min, max) = (plain_min, plain_max);
        let mut enter = [lo; 2];
        let mut leave = [hi; 2];
        for axis in 0..3 {
            let (near, far) = if s.negative[axis] {
                (&self.hi[axis], &self.lo[axis])
            } else {
                (&self.lo[axis], &self.hi[axis])
            };
            let (o, inv) = (s.origin[axis], s.inv_dir[axis]);
            for k in 0..2 {
                enter[k] = max(enter[k], (f64::from(near[k]) - o) * inv);
                leave[k] = min(leave[k], (f64::from(far[k]) - o) * inv);
            }
        }
        [0, 1].map(|k| (self.child[k] != ABSENT && enter[k] <= leave[k]).then_some(enter[k]))
    }

    /// The items of child `k`, if it is a leaf.
    #[inline(always)]
    fn leaf<'a>(&self, k: usize, items: &'a [u32]) -> Option<&'a [u32]> {
        let first = self.child[k] as usize;
        (self.count[k] > 0).then(|| &items[first..first + self.count[k] as usize])
    }
}

/// The hierarchy over items `0..n` and the items without a box.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    nodes: Vec<PairNode>,
    /// Leaf contents, in node order.
    items: Vec<u32>,
    /// Items every ray tests: those without a box, and all of them when
    /// there are too few for a hierarchy to pay.
    direct: Vec<u32>,
}

/// At most this many leaves are tested directly, without a hierarchy.
const DIRECT_LEAVES: usize = 2;

/// The deepest a hierarchy may be: the build stops splitting there (the
/// binned build halves the item count at least every few levels, so real
/// scenes stay far below), so a fixed traversal stack always suffices.
const MAX_DEPTH: usize = 60;

impl Accel {
    /// From leaves: each a box and the item it bounds (an item may have
    /// several boxes; its exact test then runs at most once per box the ray
    /// enters, which is harmless: a repeated test finds nothing nearer), and
    /// the items with no box at all.
    pub fn new(leaves: Vec<Leaf>, mut unbounded: Vec<u32>) -> Accel {
        if leaves.len() <= DIRECT_LEAVES {
            // Culling a ray against so few boxes costs more than it saves
            // (the chord's set-up alone is four divisions): test directly.
            let mut items: Vec<u32> = leaves.iter().map(Leaf::item).collect();
            items.dedup();
            unbounded.extend(items);
            return Accel {
                nodes: Vec::new(),
                items: Vec::new(),
                direct: unbounded,
            };
        }
        let (binary, items) = build::build(leaves);
        Accel {
            nodes: pair_up(&binary),
            items,
            direct: unbounded,
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
        for &i in &self.direct {
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
        let slabs = Slabs::new(&chord);
        let mut stack = [(0u32, 0f64); MAX_DEPTH + 1];
        stack[0] = (0, lo);
        let mut top = 1usize;
        let mut last = u32::MAX;
        while top > 0 {
            top -= 1;
            let (n, enter) = stack[top];
            if enter > hi {
                continue;
            }
            let node = &self.nodes[n as usize];
            let [e0, e1] = node.entries(&slabs, lo, hi);
            // Children in the order the chord enters them.
            let order = match (e0, e1) {
                (Some(a), Some(b)) if b < a => [(1, b), (0, a)],
                (Some(a), Some(b)) => [(0, a), (1, b)],
                (Some(a), None) => [(0, a), (2, 0.0)],
                (None, Some(b)) => [(1, b), (2, 0.0)],
                (None, None) => continue,
            };
            // Leaves now, nearest first; inner children onto the stack,
            // the farther below.
            let mut push = [(0u32, 0f64); 2];
            let mut pushed = 0;
            for (k, e) in order {
                if k == 2 || e > hi {
                    continue;
                }
                let Some(leaf) = node.leaf(k, &self.items) else {
                    push[pushed] = (node.child[k], e);
                    pushed += 1;
                    continue;
                };
                for &i in leaf {
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
            }
            for p in push[..pushed].iter().rev() {
                stack[top] = *p;
                top += 1;
            }
        }
        best
    }

    /// Visit every item that may meet the ray's arc `(t_min, t_max)`, in no
    /// particular order, until `visit` says stop.
    #[inline]
    pub fn any(&self, ray: &Ray, t_min: f64, t_max: f64, mut visit: impl FnMut(u32) -> Step) {
        for &i in &self.direct {
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
        let slabs = Slabs::new(&chord);
        let mut stack = [0u32; MAX_DEPTH + 1];
        let mut top = 1usize;
        let mut last = u32::MAX;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            let entries = node.entries(&slabs, lo, hi);
            for (k, entry) in entries.iter().enumerate() {
                if entry.is_none() {
                    continue;
                }
                let Some(leaf) = node.leaf(k, &self.items) else {
                    stack[top] = node.child[k];
                    top += 1;
                    continue;
                };
                for &i in leaf {
                    if i == last {
                        continue;
                    }
                    last = i;
                    if visit(i) == Step::Stop {
                        return;
                    }
                }
            }
        }
    }
}

/// The paired layout of a binary hierarchy: one pair node per inner node,
/// in the same order (a root that is a leaf gets a pair node of its own,
/// with the second child absent).
fn pair_up(binary: &[build::Node]) -> Vec<PairNode> {
    let Some(root) = binary.first() else {
        return Vec::new();
    };
    // Pair-node index of each inner binary node.
    let mut index = vec![u32::MAX; binary.len()];
    let mut count = 0u32;
    for (i, n) in binary.iter().enumerate() {
        if n.count == 0 {
            index[i] = count;
            count += 1;
        }
    }
    let child = |b: usize| -> (u32, u32) {
        let n = &binary[b];
        if n.count == 0 {
            (index[b], 0)
        } else {
            (n.index, n.count)
        }
    };
    let mut out = Vec::with_capacity(count as usize + 1);
    if root.count > 0 {
        out.push(PairNode {
            lo: [[root.lo[0], 0.0], [root.lo[1], 0.0], [root.lo[2], 0.0]],
            hi: [[root.hi[0], 0.0], [root.hi[1], 0.0], [root.hi[2], 0.0]],
            child: [root.index, ABSENT],
            count: [root.count, 0],
        });
        return out;
    }
    for (i, n) in binary.iter().enumerate() {
        if n.count > 0 {
            continue;
        }
        let (l, r) = (i + 1, n.index as usize);
        let (bl, br) = (&binary[l], &binary[r]);
        let ((cl, nl), (cr, nr)) = (child(l), child(r));
        out.push(PairNode {
            lo: [0, 1, 2].map(|a| [bl.lo[a], br.lo[a]]),
            hi: [0, 1, 2].map(|a| [bl.hi[a], br.hi[a]]),
            child: [cl, cr],
            count: [nl, nr],
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;
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
