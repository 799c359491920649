//! Building the hierarchy: top-down, binned surface-area heuristic
//! (Wald 2007) over the leaves' box centres, binned along the axis where
//! the centres spread most (as pbrt-v4 does: a third of the binning work of
//! all three axes, for trees about as good). Each leaf's box is rounded
//! outwards to `f32` once, when it is made: the union of rounded boxes is
//! the rounded union (rounding outwards is monotone), so every node's box
//! is what rounding its `f64` box would give, and the build moves and
//! compares boxes of half the size, four lanes at a time.

use hgeom::glam::Vec3A;
use hgeom::{KleinBox, round_outward_f32};

use super::MAX_DEPTH;

/// A node of the binary hierarchy as built: its box, and either its
/// children (`count == 0`: the left child is the next node, the right one
/// at `index`) or its items (`items[index .. index + count]`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Node {
    pub lo: [f32; 3],
    pub hi: [f32; 3],
    pub index: u32,
    pub count: u32,
}

/// Bins along the split axis.
const BINS: usize = 16;
/// Cost of visiting a node, relative to one exact test.
const TRAVERSAL_COST: f64 = 0.5;
/// The most items a leaf holds when splitting would cost more.
const MAX_LEAF: usize = 4;

/// One leaf box (rounded outwards to `f32`) and the item it bounds.
#[derive(Clone, Copy, Debug)]
pub struct Leaf {
    lo: Vec3A,
    hi: Vec3A,
    item: u32,
}

impl Leaf {
    /// A box around (part of) `item`.
    pub fn new(bounds: KleinBox, item: u32) -> Leaf {
        let (lo, hi) = round_outward_f32(bounds.lo(), bounds.hi());
        Leaf {
            lo: Vec3A::from_array(lo),
            hi: Vec3A::from_array(hi),
            item,
        }
    }

    /// Twice the centre of its box (the build compares centres only).
    #[inline(always)]
    fn centre2(&self) -> Vec3A {
        self.lo + self.hi
    }

    /// The item it bounds.
    pub fn item(&self) -> u32 {
        self.item
    }
}

/// Subtrees with more leaves than this are built on two threads.
const PARALLEL_LEAVES: usize = 4096;

/// The nodes (root first, depth-first order) and the leaf item list.
pub(super) fn build(mut leaves: Vec<Leaf>) -> (Vec<Node>, Vec<u32>) {
    if leaves.is_empty() {
        return (Vec::new(), Vec::new());
    }
    build_parallel(&mut leaves, 0)
}

/// A subtree whose indices count from its own first node and item.
fn build_parallel(leaves: &mut [Leaf], depth: usize) -> (Vec<Node>, Vec<u32>) {
    if leaves.len() <= PARALLEL_LEAVES {
        let mut nodes = Vec::with_capacity(2 * leaves.len() / MAX_LEAF + 1);
        let mut items = Vec::with_capacity(leaves.len());
        split(&mut nodes, &mut items, leaves, depth);
        return (nodes, items);
    }
    let (bounds, mid) = choose(leaves, depth);
    let Some(mid) = mid else {
        let mut nodes = Vec::new();
        let mut items = Vec::new();
        split(&mut nodes, &mut items, leaves, depth);
        return (nodes, items);
    };
    let (left, right) = leaves.split_at_mut(mid);
    let ((mut nodes, mut items), (right_nodes, right_items)) = rayon::join(
        || build_parallel(left, depth + 1),
        || build_parallel(right, depth + 1),
    );
    let (lo, hi) = (bounds.0.to_array(), bounds.1.to_array());
    let node_offset = 1 + nodes.len() as u32;
    let item_offset = items.len() as u32;
    // The root goes first; every index below it moves by one.
    for n in nodes.iter_mut().filter(|n| n.count == 0) {
        n.index += 1;
    }
    let mut all = Vec::with_capacity(1 + nodes.len() + right_nodes.len());
    all.push(Node {
        lo,
        hi,
        index: node_offset,
        count: 0,
    });
    all.append(&mut nodes);
    all.extend(right_nodes.into_iter().map(|mut n| {
        if n.count == 0 {
            n.index += node_offset;
        } else {
            n.index += item_offset;
        }
        n
    }));
    items.extend(right_items);
    (all, items)
}

/// The leaves' box, and the box of their (doubled) centres, in one pass.
/// `Vec3A::min`/`max` are single SSE instructions; the boxes are finite.
fn bounds_of(leaves: &[Leaf]) -> ((Vec3A, Vec3A), (Vec3A, Vec3A)) {
    let inf = Vec3A::splat(f32::INFINITY);
    let (mut lo, mut hi, mut clo, mut chi) = (inf, -inf, inf, -inf);
    for l in leaves {
        lo = lo.min(l.lo);
        hi = hi.max(l.hi);
        let c = l.centre2();
        clo = clo.min(c);
        chi = chi.max(c);
    }
    ((lo, hi), (clo, chi))
}

/// The leaves' box, and where to split them (after reordering), or `None`
/// for a leaf.
fn choose(leaves: &mut [Leaf], depth: usize) -> ((Vec3A, Vec3A), Option<usize>) {
    let (bounds, centres) = bounds_of(leaves);
    let n = leaves.len();
    if n <= 1 || depth >= MAX_DEPTH - 1 {
        return (bounds, None);
    }
    let cut = best_cut(leaves, bounds, centres).or_else(|| (n > MAX_LEAF).then_some(n / 2));
    (bounds, cut)
}

fn split(nodes: &mut Vec<Node>, items: &mut Vec<u32>, leaves: &mut [Leaf], depth: usize) {
    let (bounds, cut) = choose(leaves, depth);
    let (lo, hi) = (bounds.0.to_array(), bounds.1.to_array());
    let index = nodes.len();
    nodes.push(Node {
        lo,
        hi,
        index: 0,
        count: 0,
    });
    let Some(mid) = cut else {
        nodes[index].index = items.len() as u32;
        nodes[index].count = leaves.len() as u32;
        items.extend(leaves.iter().map(|l| l.item));
        return;
    };
    let (left, right) = leaves.split_at_mut(mid);
    split(nodes, items, left, depth + 1);
    nodes[index].index = nodes.len() as u32;
    split(nodes, items, right, depth + 1);
}

/// Half the area of the box `lo..hi`; 0 for an empty one (in `f64`: the
/// costs of a large node sum many areas).
fn half_area(lo: Vec3A, hi: Vec3A) -> f64 {
    let e = (hi - lo).max(Vec3A::ZERO).as_dvec3();
    e.x * e.y + e.y * e.z + e.z * e.x
}

/// The axis where the centres spread most.
#[inline]
fn axis_of(extent: Vec3A) -> usize {
    if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    }
}

/// Reorder `leaves` and return the split point with the least estimated
/// cost, or `None` if a leaf of them all is cheaper (and small enough).
fn best_cut(
    leaves: &mut [Leaf],
    (lo, hi): (Vec3A, Vec3A),
    (clo, chi): (Vec3A, Vec3A),
) -> Option<usize> {
    let n = leaves.len();
    let extent = chi - clo;
    // A small node gets as many bins as leaves: most of the sweep over
    // sixteen would run over empty bins, and small nodes are most nodes.
    let bins_n = BINS.min(n);
    let scale = Vec3A::splat(bins_n as f32) / extent;
    // Centres lie in clo..=chi, so the product is in 0..=bins_n: a
    // conversion to i64 (one instruction and a fix-up, where usize's
    // saturating conversion needs several) and a clamp.
    let (c_lo, c_scale) = (clo[axis_of(extent)], scale[axis_of(extent)]);
    let bin = |l: &Leaf, axis: usize| {
        let x = ((l.centre2()[axis] - c_lo) * c_scale) as i64;
        x.clamp(0, bins_n as i64 - 1) as usize
    };
    let empty = (
        Vec3A::splat(f32::INFINITY),
        Vec3A::splat(f32::NEG_INFINITY),
        0usize,
    );
    let axis = axis_of(extent);
    if !(extent[axis] > 0.0) {
        return None;
    }
    let mut bins = [empty; BINS];
    for l in leaves.iter() {
        let b = &mut bins[bin(l, axis)];
        b.0 = b.0.min(l.lo);
        b.1 = b.1.max(l.hi);
        b.2 += 1;
    }
    let mut best: Option<(f64, usize)> = None;
    // Area and count of every suffix of the bins.
    let mut right = [(0.0, 0usize); BINS];
    let (mut rlo, mut rhi, mut c) = empty;
    for b in (1..bins_n).rev() {
        rlo = rlo.min(bins[b].0);
        rhi = rhi.max(bins[b].1);
        c += bins[b].2;
        right[b] = (half_area(rlo, rhi), c);
    }
    let (mut llo, mut lhi, mut c) = empty;
    for b in 0..bins_n - 1 {
        llo = llo.min(bins[b].0);
        lhi = lhi.max(bins[b].1);
        c += bins[b].2;
        let (right_area, nr) = right[b + 1];
        if c == 0 || nr == 0 {
            continue;
        }
        let cost = half_area(llo, lhi) * c as f64 + right_area * nr as f64;
        if best.is_none_or(|(k, _)| cost < k) {
            best = Some((cost, b + 1));
        }
    }
    let (cost, first_right) = best?;
    let area = half_area(lo, hi);
    let split_cost = TRAVERSAL_COST + if area > 0.0 { cost / area } else { n as f64 };
    if n <= MAX_LEAF && split_cost >= n as f64 {
        return None;
    }
    // Partition by the same bin rule the costs were computed with.
    let mut mid = 0;
    for i in 0..n {
        if bin(&leaves[i], axis) < first_right {
            leaves.swap(i, mid);
            mid += 1;
        }
    }
    (mid > 0 && mid < n).then_some(mid)
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;

    #[test]
    fn f32_boxes_contain_the_f64_box() {
        let b = KleinBox::new(
            DVec3::new(0.1, -0.3333333333333333, 0.7),
            DVec3::new(0.2, 0.123456789012345, 0.9999999999),
        )
        .unwrap();
        let (lo, hi) = round_outward_f32(b.lo(), b.hi());
        for k in 0..3 {
            assert!(f64::from(lo[k]) <= b.lo()[k]);
            assert!(f64::from(hi[k]) >= b.hi()[k]);
        }
    }

    /// Every leaf's box lies in each of its ancestors' boxes, and every item
    /// appears once per leaf box, also where subtrees were built on two
    /// threads and joined.
    #[test]
    fn nodes_nest() {
        const N: u32 = 5 * PARALLEL_LEAVES as u32;
        let leaves: Vec<Leaf> = (0..N)
            .map(|i| {
                let x = f64::from(i) / f64::from(N);
                let c = DVec3::new((x * 7.0).sin(), (x * 13.0).cos(), x) * 0.5;
                Leaf::new(KleinBox::new(c, c + DVec3::splat(0.01)).unwrap(), i)
            })
            .collect();
        let (nodes, items) = build(leaves);
        let mut sorted = items.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..N).collect::<Vec<u32>>());
        let mut listed = 0;
        fn check(nodes: &[Node], n: usize, listed: &mut usize) {
            let node = nodes[n];
            if node.count > 0 {
                assert_eq!(node.index as usize, *listed, "leaves list items in order");
                *listed += node.count as usize;
                return;
            }
            for child in [n + 1, node.index as usize] {
                let c = nodes[child];
                for k in 0..3 {
                    assert!(c.lo[k] >= node.lo[k] && c.hi[k] <= node.hi[k]);
                }
                check(nodes, child, listed);
            }
        }
        check(&nodes, 0, &mut listed);
        assert_eq!(listed, N as usize);
    }
}
