//! What a [`RegularHoneycomb`](super::RegularHoneycomb) draws, and how a
//! hit says which part it met.

use crate::error::{GeomError, positive_length};

/// The parts of a honeycomb to draw, its extent and its colouring.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HoneycombStyle {
    /// Edges as rods of this hyperbolic radius (the tube about each edge);
    /// `None`: no edges.
    pub edges: Option<f64>,
    /// Faces as planar polygons (infinitely thin, two-sided).
    pub faces: bool,
    /// Finite vertices as balls of this hyperbolic radius; ideal vertices
    /// are never drawn (their ball would be a horoball). `None`: none.
    pub vertices: Option<f64>,
    /// Only the cells within this many face reflections of the base cell
    /// (and their faces, edges and vertices); `None`: the whole honeycomb.
    pub depth: Option<u32>,
    /// How many colour classes the cells fall into (1: no colouring); see
    /// [`decode_honeycomb_part`].
    pub cell_classes: u32,
}

impl Default for HoneycombStyle {
    /// Edges of radius 0.05, nothing else, unlimited, one class.
    fn default() -> HoneycombStyle {
        HoneycombStyle {
            edges: Some(0.05),
            faces: false,
            vertices: None,
            depth: None,
            cell_classes: 1,
        }
    }
}

impl HoneycombStyle {
    /// Checks the radii (finite, positive) and that there is at least one
    /// class. A style that draws nothing is valid (and invisible).
    ///
    /// Errors: [`GeomError::BadRadius`] for a radius that is not positive
    /// and finite; [`GeomError::NoCellClasses`] for `cell_classes = 0`.
    pub fn validate(&self) -> Result<(), GeomError> {
        if let Some(w) = self.edges {
            positive_length(w)?;
        }
        if let Some(r) = self.vertices {
            positive_length(r)?;
        }
        if self.cell_classes == 0 {
            return Err(GeomError::NoCellClasses);
        }
        Ok(())
    }
}

/// How a regular honeycomb's parts get their class
/// ([`RegularHoneycomb::with_colouring`](super::RegularHoneycomb::with_colouring)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CellColouring {
    /// By rank: the layer (with a depth) or shell of the part's cell
    /// nearest the base cell, modulo the number of classes.
    #[default]
    Rank,
    /// By parity: the two cosets of the index-2 subgroup of the symmetry
    /// group that counts face crossings modulo 2, a proper two-colouring
    /// of the cells (neighbours across a face differ). It exists exactly
    /// when `r` is even (an odd number of cells round an edge is an odd
    /// cycle). A part is drawn in the class of the cell the ray sees it
    /// from, 0 or 1.
    Parity,
}

/// The kind of honeycomb part a ray met.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HoneycombPart {
    /// The rod about an edge.
    Edge,
    /// A face.
    Face,
    /// The ball about a vertex.
    Vertex,
    /// No part: the walk reached its horizon before meeting one (reported
    /// only by a honeycomb that asks for it,
    /// [`RegularHoneycomb::with_horizon_hits`](super::RegularHoneycomb::with_horizon_hits)).
    Horizon,
}

/// The `part` of a horizon hit: a code no part of a cell class has.
const HORIZON_PART: u32 = u32::MAX;

impl HoneycombPart {
    fn code(self) -> u32 {
        match self {
            HoneycombPart::Edge => 0,
            HoneycombPart::Face => 1,
            HoneycombPart::Vertex => 2,
            HoneycombPart::Horizon => HORIZON_PART,
        }
    }
}

/// The [`Hit::part`](crate::Hit::part) of a honeycomb hit: the kind of part
/// and the class of its cell.
pub(crate) fn encode_part(kind: HoneycombPart, class: u32) -> u32 {
    if kind == HoneycombPart::Horizon {
        return HORIZON_PART;
    }
    // Classes are below `cell_classes`, a small number: a part of a cell
    // class never reaches the horizon's code.
    class.saturating_mul(3).saturating_add(kind.code())
}

/// What a [`Hit::part`](crate::Hit::part) from a
/// [`RegularHoneycomb`](super::RegularHoneycomb) says: the kind of part,
/// and its class in `0..cell_classes` (the rule is in the honeycomb's
/// docs: the rank of the nearest of the part's cells to the base cell,
/// modulo the number of classes). For hits of other shapes (`part = 0`) it
/// reads `(Edge, 0)`, which means nothing there.
pub fn decode_honeycomb_part(part: u32) -> (HoneycombPart, u32) {
    if part == HORIZON_PART {
        return (HoneycombPart::Horizon, 0);
    }
    let kind = match part % 3 {
        0 => HoneycombPart::Edge,
        1 => HoneycombPart::Face,
        _ => HoneycombPart::Vertex,
    };
    (kind, part / 3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parts_round_trip() {
        for kind in [
            HoneycombPart::Edge,
            HoneycombPart::Face,
            HoneycombPart::Vertex,
        ] {
            for class in [0, 1, 7, 1000] {
                assert_eq!(
                    decode_honeycomb_part(encode_part(kind, class)),
                    (kind, class)
                );
            }
        }
        assert_eq!(
            decode_honeycomb_part(encode_part(HoneycombPart::Horizon, 5)),
            (HoneycombPart::Horizon, 0)
        );
    }

    #[test]
    fn styles_are_validated() {
        assert!(HoneycombStyle::default().validate().is_ok());
        let bad = |s: HoneycombStyle| s.validate().is_err();
        let d = HoneycombStyle::default();
        assert!(bad(HoneycombStyle {
            edges: Some(-1.0),
            ..d
        }));
        assert!(bad(HoneycombStyle {
            edges: Some(f64::NAN),
            ..d
        }));
        assert!(bad(HoneycombStyle {
            vertices: Some(f64::INFINITY),
            ..d
        }));
        assert!(bad(HoneycombStyle {
            cell_classes: 0,
            ..d
        }));
    }
}
