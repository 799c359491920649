//! What an object statement built, before it is placed.

use hgeom::{Isometry, Polyhedron};

use crate::ir::Shape;

/// What a statement built, for `Lowerer::place` (`options.rs`).
pub(super) enum Built {
    /// The shapes themselves.
    Shapes(Vec<Shape>),
    /// Copies of one cell, one per placement, not built yet: a tessellation
    /// drawn as edges alone needs only the copies' vertices, and building
    /// ten thousand cells' faces for that was most of its set-up.
    Copies {
        cell: Polyhedron,
        placements: Vec<Isometry>,
    },
}

impl Built {
    /// The shapes, the copies built as polyhedra.
    pub(super) fn into_shapes(self) -> Vec<Shape> {
        match self {
            Built::Shapes(shapes) => shapes,
            Built::Copies { cell, placements } => placements
                .iter()
                .map(|p| Shape::Polyhedron(cell.transformed(p)))
                .collect(),
        }
    }
}
