//! Building the hierarchy: top-down, binned surface-area heuristic
//! (Wald 2007) over the leaves' box centres, with the boxes themselves
//! rounded outwards to `f32` for storage.

use hgeom::KleinBox;
use hgeom::glam::DVec3;

use super::{MAX_DEPTH, Node};

/// Bins per axis.
const BINS: usize = 16;
/// Cost of visiting a node, relative to one exact test.
const TRAVERSAL_COST: f64 = 0.5;
/// The most items a leaf holds when splitting would cost more.
const MAX_LEAF: usize = 4;

/// One leaf box and the item it bounds.
#[derive(Clone, Copy, Debug)]
pub struct Leaf {
    bounds: KleinBox,
    centre: DVec3,
    item: u32,
}

impl Leaf {
    /// A box around (part of) `item`.
    pub fn new(bounds: KleinBox, item: u32) -> Leaf {
        Leaf {
            bounds,
            centre: bounds.centre(),
            item,
        }
    }
}

/// The nodes (root first, depth-first order) and the leaf item list.
pub(super) fn build(mut leaves: Vec<Leaf>) -> (Vec<Node>, Vec<u32>) {
    let mut nodes = Vec::with_capacity(2 * leaves.len() / MAX_LEAF + 1);
    let mut items = Vec::with_capacity(leaves.len());
    if !leaves.is_empty() {
        split(&mut nodes, &mut items, &mut leaves, 0);
    }
    (nodes, items)
}

fn bounds_of(leaves: &[Leaf]) -> KleinBox {
    leaves[1..]
        .iter()
        .fold(leaves[0].bounds, |b, l| b.union(&l.bounds))
}

/// Round outwards to `f32`.
fn outward(b: &KleinBox) -> ([f32; 3], [f32; 3]) {
    let down = |x: f64| {
        let f = x as f32;
        if f64::from(f) > x { f.next_down() } else { f }
    };
    let up = |x: f64| {
        let f = x as f32;
        if f64::from(f) < x { f.next_up() } else { f }
    };
    let (lo, hi) = (b.lo(), b.hi());
    (
        [down(lo.x), down(lo.y), down(lo.z)],
        [up(hi.x), up(hi.y), up(hi.z)],
    )
}

fn split(nodes: &mut Vec<Node>, items: &mut Vec<u32>, leaves: &mut [Leaf], depth: usize) {
    let bounds = bounds_of(leaves);
    let (lo, hi) = outward(&bounds);
    let index = nodes.len();
    nodes.push(Node {
        lo,
        hi,
        index: 0,
        count: 0,
    });
    let n = leaves.len();
    let cut = if n <= 1 || depth >= MAX_DEPTH - 1 {
        None
    } else {
        best_cut(leaves, &bounds)
    };
    let Some(mid) = cut.or_else(|| (n > MAX_LEAF && depth < MAX_DEPTH - 1).then_some(n / 2))
    else {
        nodes[index].index = items.len() as u32;
        nodes[index].count = n as u32;
        items.extend(leaves.iter().map(|l| l.item));
        return;
    };
    let (left, right) = leaves.split_at_mut(mid);
    split(nodes, items, left, depth + 1);
    nodes[index].index = nodes.len() as u32;
    split(nodes, items, right, depth + 1);
}

/// Reorder `leaves` and return the split point with the least estimated
/// cost, or `None` if a leaf of them all is cheaper (and small enough).
fn best_cut(leaves: &mut [Leaf], bounds: &KleinBox) -> Option<usize> {
    let n = leaves.len();
    let (clo, chi) = leaves.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), l| (lo.min(l.centre), hi.max(l.centre)),
    );
    let extent = chi - clo;
    let mut best: Option<(f64, usize, usize)> = None;
    for axis in 0..3 {
        if !(extent[axis] > 0.0) {
            continue;
        }
        let scale = BINS as f64 / extent[axis];
        let bin_of = |l: &Leaf| (((l.centre[axis] - clo[axis]) * scale) as usize).min(BINS - 1);
        let mut count = [0usize; BINS];
        let mut boxes: [Option<KleinBox>; BINS] = [None; BINS];
        for l in leaves.iter() {
            let b = bin_of(l);
            count[b] += 1;
            boxes[b] = Some(boxes[b].map_or(l.bounds, |x| x.union(&l.bounds)));
        }
        // Areas and counts of every prefix and suffix of the bins.
        let mut right_area = [0.0; BINS];
        let mut acc: Option<KleinBox> = None;
        let mut right_count = [0usize; BINS];
        let mut c = 0;
        for b in (1..BINS).rev() {
            if let Some(x) = boxes[b] {
                acc = Some(acc.map_or(x, |a| a.union(&x)));
            }
            c += count[b];
            right_count[b] = c;
            right_area[b] = acc.map_or(0.0, |a| a.half_area());
        }
        let mut acc: Option<KleinBox> = None;
        let mut c = 0;
        for b in 0..BINS - 1 {
            if let Some(x) = boxes[b] {
                acc = Some(acc.map_or(x, |a| a.union(&x)));
            }
            c += count[b];
            let (nl, nr) = (c, right_count[b + 1]);
            if nl == 0 || nr == 0 {
                continue;
            }
            let cost = acc.map_or(0.0, |a| a.half_area()) * nl as f64
                + right_area[b + 1] * nr as f64;
            if best.is_none_or(|(k, _, _)| cost < k) {
                best = Some((cost, axis, b + 1));
            }
        }
    }
    let (cost, axis, first_right) = best?;
    let area = bounds.half_area();
    let split_cost = TRAVERSAL_COST + if area > 0.0 { cost / area } else { n as f64 };
    if n <= MAX_LEAF && split_cost >= n as f64 {
        return None;
    }
    // Partition by the same bin rule the costs were computed with.
    let scale = BINS as f64 / extent[axis];
    let mut mid = 0;
    for i in 0..n {
        let b = (((leaves[i].centre[axis] - clo[axis]) * scale) as usize).min(BINS - 1);
        if b < first_right {
            leaves.swap(i, mid);
            mid += 1;
        }
    }
    (mid > 0 && mid < n).then_some(mid)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f32_boxes_contain_the_f64_box() {
        let b = KleinBox::new(
            DVec3::new(0.1, -0.3333333333333333, 0.7),
            DVec3::new(0.2, 0.123456789012345, 0.9999999999),
        )
        .unwrap();
        let (lo, hi) = outward(&b);
        for k in 0..3 {
            assert!(f64::from(lo[k]) <= b.lo()[k]);
            assert!(f64::from(hi[k]) >= b.hi()[k]);
        }
    }

    /// Every leaf's box lies in each of its ancestors' boxes, and every item
    /// appears once per leaf box.
    #[test]
    fn nodes_nest() {
        let leaves: Vec<Leaf> = (0..1000)
            .map(|i| {
                let x = f64::from(i) / 1000.0;
                let c = DVec3::new((x * 7.0).sin(), (x * 13.0).cos(), x) * 0.5;
                Leaf::new(KleinBox::new(c, c + DVec3::splat(0.01)).unwrap(), i)
            })
            .collect();
        let (nodes, items) = build(leaves);
        let mut sorted = items.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..1000).collect::<Vec<u32>>());
        fn check(nodes: &[Node], n: usize) {
            let node = nodes[n];
            if node.count > 0 {
                return;
            }
            for child in [n + 1, node.index as usize] {
                let c = nodes[child];
                for k in 0..3 {
                    assert!(c.lo[k] >= node.lo[k] && c.hi[k] <= node.hi[k]);
                }
                check(nodes, child);
            }
        }
        check(&nodes, 0);
    }
}
