//! What a walk reports besides its hit: its counts ([`WalkStats`]) and,
//! for measuring its drift, each step ([`WalkStep`]).

use glam::{DMat4, DVec4};

/// Counts from one walk.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WalkStats {
    /// Domains entered, the first included: cells when the cells are
    /// finite, chambers (copies of the characteristic simplex) when they
    /// are horosphere-inscribed.
    pub steps: u32,
    /// Cells entered (crossings of face planes, plus the first cell); 1
    /// for a uniform honeycomb other than the regular one, whose faces do
    /// not lie in the walls the walk crosses.
    pub cells: u32,
    /// Reflections that folded the start into the simplex.
    pub folds: u32,
}

/// One step of a walk
/// ([`RegularHoneycomb::walk_steps`](super::RegularHoneycomb::walk_steps)):
/// the ray after it has crossed a wall, in the base simplex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WalkStep {
    /// The wall crossed: an index into
    /// [`RegularHoneycomb::walls`](super::RegularHoneycomb::walls).
    pub wall: usize,
    /// True if that wall is a face plane (the step enters another cell of
    /// a regular honeycomb).
    pub face: bool,
    /// The arc length along the original ray at the crossing.
    pub t: f64,
    /// The crossing point, reflected into the base simplex (on the wall).
    pub origin: DVec4,
    /// The reflected direction there.
    pub dir: DVec4,
    /// The Lorentz matrix from the base domain to the domain entered (in
    /// the honeycomb's frame, before placement); its last column is the
    /// centre of the cell entered when the cells are finite and the walk
    /// goes from cell to cell.
    pub chamber: DMat4,
}
