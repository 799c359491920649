//! The four-wide layout of the hierarchy: each node holds the boxes of up
//! to four children side by side, so one pass of four-lane `f32`
//! arithmetic tests them all ([`Chord32`]), and a ray visits about half as
//! many nodes as in the binary tree. It is collapsed from the binary build:
//! a node takes its two children, then replaces the inner child of largest
//! surface area by that child's two until it has four (the standard
//! collapse of a binary SAH tree, as in Embree's BVH4).

use hgeom::glam::Vec4;

use super::build::Node;
use super::chord32::{CORNER, Chord32};

/// Children per node.
pub(super) const WIDTH: usize = 4;

/// The most leaf boxes a tree is built over (`2^31`, about 96 GiB of
/// leaves; far past any scene this memory holds).
pub(super) const MAX_LEAVES: usize = 1 << 31;

/// The top bit of `child`: set for a leaf. Item indices stay below it:
/// [`super::Accel::new`] builds no tree over `MAX_LEAVES` or more boxes.
const LEAF: u32 = 1 << 31;

/// A node: the boxes of its children in four lanes; each child is another
/// node, a leaf (`child` has its top bit set; the items are
/// `items[first .. first + count]`, `first` the rest of `child`), or absent
/// (an empty box, which no chord enters).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(super) struct WideNode {
    /// `corner[0][axis]`: the children's least corners, rounded down to
    /// `f32`; `corner[1][axis]`: their greatest, rounded up. Indexed, not
    /// named, so a chord picks its near and far side by index.
    corner: [[Vec4; 3]; 2],
    pub child: [u32; WIDTH],
    count: [u32; WIDTH],
}

impl WideNode {
    /// Which children's boxes the chord enters within `[lo, hi]`, the
    /// leaves and the inner nodes apart (bit `k` for child `k`), and lower
    /// bounds of where it enters each. `OCTANT` is the chord's
    /// [`Chord32::octant`]: which corner of a box it meets first is then
    /// known when this is compiled, and each corner is read at a fixed
    /// offset (instead of offsets recomputed at every node).
    #[inline(always)]
    pub fn entries<const OCTANT: usize>(
        &self,
        c: &Chord32,
        lo: f32,
        hi: f32,
    ) -> (u32, u32, [f32; WIDTH]) {
        let near = [OCTANT & 1, (OCTANT >> 1) & 1, (OCTANT >> 2) & 1];
        let mut enter = Vec4::splat(lo);
        let mut leave = Vec4::splat(hi);
        for (axis, near) in near.into_iter().enumerate() {
            enter = enter.max(c.enter(axis, self.corner[near][axis]));
            leave = leave.min(c.leave(axis, self.corner[1 - near][axis]));
        }
        let entered = enter.cmple(leave).bitmask();
        // The leaf bits are the sign bits of `child` read as `f32` lanes:
        // one instruction, no arithmetic on the values.
        let leaves = Vec4::from_array(self.child.map(f32::from_bits)).is_negative_bitmask();
        (entered & leaves, entered & !leaves, enter.to_array())
    }

    /// The items of child `k`, a leaf.
    #[inline(always)]
    pub fn items<'a>(&self, k: usize, items: &'a [u32]) -> &'a [u32] {
        let first = (self.child[k] & !LEAF) as usize;
        &items[first..first + self.count[k] as usize]
    }
}

/// The four-wide layout of a binary hierarchy (root first, each node's
/// left child next to it and its right one at `index`). A root that is a
/// leaf gets a node of its own, with one child.
pub(super) fn collapse(binary: &[Node]) -> Vec<WideNode> {
    let mut out = Vec::new();
    if !binary.is_empty() {
        if binary[0].count > 0 {
            out.push(node_of(binary, &[0], &[0]));
        } else {
            place(binary, 0, &mut out);
        }
    }
    out
}

/// Lay out the wide node for inner binary node `b` and, after it, those of
/// its inner descendants; returns its index.
fn place(binary: &[Node], b: usize, out: &mut Vec<WideNode>) -> u32 {
    let inner = |i: usize| binary[i].count == 0;
    let mut children = vec![b + 1, binary[b].index as usize];
    while children.len() < WIDTH {
        // Open the inner child with the largest box: the one most rays
        // would otherwise visit as a node of its own.
        let Some(k) = (0..children.len())
            .filter(|&k| inner(children[k]))
            .max_by(|&x, &y| area(&binary[children[x]]).total_cmp(&area(&binary[children[y]])))
        else {
            break;
        };
        let c = children.swap_remove(k);
        children.extend([c + 1, binary[c].index as usize]);
    }
    let index = out.len();
    // A placeholder until the children's indices are known.
    out.push(node_of(binary, &children, &[]));
    let placed: Vec<u32> = children
        .iter()
        .map(|&c| if inner(c) { place(binary, c, out) } else { 0 })
        .collect();
    out[index] = node_of(binary, &children, &placed);
    index as u32
}

/// The wide node over binary nodes `children`, the inner ones at wide
/// indices `placed` (in the same order; ignored for leaves).
fn node_of(binary: &[Node], children: &[usize], placed: &[u32]) -> WideNode {
    let mut lo = [[f32::INFINITY; WIDTH]; 3];
    let mut hi = [[f32::NEG_INFINITY; WIDTH]; 3];
    let mut child = [0; WIDTH];
    let mut count = [0; WIDTH];
    for (k, &c) in children.iter().enumerate() {
        let n = &binary[c];
        for axis in 0..3 {
            // The arc never leaves [-CORNER, CORNER]^3, so clamping there
            // keeps every box the chord can meet; it bounds the slab
            // products of `Chord32`.
            lo[axis][k] = n.lo[axis].clamp(-CORNER, CORNER);
            hi[axis][k] = n.hi[axis].clamp(-CORNER, CORNER);
        }
        if n.count > 0 {
            (child[k], count[k]) = (LEAF | n.index, n.count);
        } else {
            child[k] = placed.get(k).copied().unwrap_or(0);
        }
    }
    WideNode {
        corner: [lo.map(Vec4::from_array), hi.map(Vec4::from_array)],
        child,
        count,
    }
}

/// Half the surface area of a node's box.
fn area(n: &Node) -> f64 {
    let e = [0, 1, 2].map(|a| f64::from(n.hi[a]) - f64::from(n.lo[a]));
    e[0] * e[1] + e[1] * e[2] + e[2] * e[0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;
    use hgeom::{KleinRay, Ray};

    /// [`WideNode::entries`] for the chord's own octant, over the whole
    /// chord.
    fn entries_any(node: &WideNode, c: &Chord32) -> (u32, u32, [f32; WIDTH]) {
        let (lo, hi) = (f32::NEG_INFINITY, f32::INFINITY);
        by_octant!(c.octant(), O => node.entries::<O>(c, lo, hi))
    }

    /// A leaf root: one child and three absent lanes. Chords through the
    /// box along every axis, in both directions, enter the child's lane and
    /// never an absent one (their empty boxes give no NaN for either sign
    /// of the chord), and chords beside the box enter none.
    #[test]
    fn absent_lanes_are_never_entered() {
        let leaf = Node {
            lo: [-0.1, -0.1, -0.1],
            hi: [0.1, 0.1, 0.1],
            index: 0,
            count: 1,
        };
        let nodes = collapse(&[leaf]);
        assert_eq!(nodes.len(), 1);
        for axis in 0..3 {
            for sign in [1.0, -1.0] {
                let mut dir = DVec3::ZERO;
                dir[axis] = sign;
                let ray = Ray::from_origin_unchecked(dir);
                let c = Chord32::new(&KleinRay::new(&ray));
                let (leaves, inner, entries) = entries_any(&nodes[0], &c);
                assert_eq!((leaves, inner), (1, 0), "axis {axis}, sign {sign}");
                assert!(entries[0] <= 0.0, "{}", entries[0]);
                // From a start beside the box, parallel to it: no lane.
                let mut beside = DVec3::splat(0.0);
                beside[(axis + 1) % 3] = 0.5;
                let start = hgeom::Point::from_coords(beside).unwrap();
                let ray = Ray::from_ball_unchecked(&start, dir);
                let c = Chord32::new(&KleinRay::new(&ray));
                let (leaves, inner, _) = entries_any(&nodes[0], &c);
                assert_eq!((leaves, inner), (0, 0), "axis {axis}, sign {sign}, beside");
            }
        }
    }
}
