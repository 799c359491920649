//! What a step of a honeycomb walk shares with the parts it tests: the ray
//! in one domain, the parts a domain can report, and the most walls a
//! domain has (`domain.rs` describes the domains).

use glam::DVec4;

use super::style::HoneycombPart;

/// The most walls a domain has: the 20 faces of an icosahedral cell.
pub(super) const MAX_WALLS: usize = 20;

/// A part found in a domain: which kind, and which of the domain's edges,
/// vertices or walls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum DomainPart {
    Edge(usize),
    Vertex(usize),
    Face(usize),
    /// A uniform honeycomb's half-edge (`uniform.rs`).
    HalfEdge(usize),
    /// The ball of the edges' radius about a uniform honeycomb's seed.
    Cap,
    /// A uniform honeycomb's face piece.
    Piece(usize),
}

impl DomainPart {
    pub(super) fn kind(self) -> HoneycombPart {
        match self {
            DomainPart::Edge(_) | DomainPart::HalfEdge(_) | DomainPart::Cap => HoneycombPart::Edge,
            DomainPart::Vertex(_) => HoneycombPart::Vertex,
            DomainPart::Face(_) | DomainPart::Piece(_) => HoneycombPart::Face,
        }
    }

    /// True for a uniform honeycomb's own parts (`uniform.rs`).
    pub(super) fn is_seeded(self) -> bool {
        matches!(
            self,
            DomainPart::HalfEdge(_) | DomainPart::Cap | DomainPart::Piece(_)
        )
    }
}

/// The ray in one domain: its start and direction in the base frame
/// (scaled by a common `λ`, `kernels.rs`), their products with the walls,
/// where it leaves, and `e^{2τ}` there.
pub(super) struct DomainRay<'a> {
    pub(super) o: DVec4,
    pub(super) d: DVec4,
    pub(super) a: &'a [f64],
    pub(super) b: &'a [f64],
    pub(super) exit: Option<usize>,
    /// `tanh τ` at the exit (1 with no exit).
    pub(super) s_exit: f64,
    pub(super) v_exit: f64,
}
