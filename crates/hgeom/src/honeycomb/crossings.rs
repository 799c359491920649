//! The walls a walk crosses, kept until the domain matrix is needed (when
//! it is needed: `walk_in` in `walk.rs`).

use glam::{DMat4, DVec4};

use super::kernels::times_reflection;

/// What a walk does with the walls it crosses.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Crossings {
    /// Folds each into the domain matrix at once (the drawn cells are asked
    /// for at every step).
    Eager,
    /// Keeps them, to fold in batches or at a hit.
    Deferred,
    /// Drops them: the matrix is never read (an any-hit walk).
    Unused,
}

/// Walls crossed but not yet folded into the domain matrix.
pub(super) struct Pending {
    walls: [u8; Pending::CAPACITY],
    len: usize,
    crossings: Crossings,
}

impl Pending {
    const CAPACITY: usize = 16;

    pub(super) fn new(crossings: Crossings) -> Pending {
        Pending {
            walls: [0; Pending::CAPACITY],
            len: 0,
            crossings,
        }
    }

    /// The walk crossed `wall`: `m` becomes (or will become) `m R_wall`.
    #[inline(always)]
    pub(super) fn cross(&mut self, wall: usize, m: &mut DMat4, walls: &[DVec4]) {
        match self.crossings {
            Crossings::Eager => *m = times_reflection(m, walls[wall]),
            Crossings::Deferred => self.push(wall, m, walls),
            Crossings::Unused => {}
        }
    }

    fn push(&mut self, wall: usize, m: &mut DMat4, walls: &[DVec4]) {
        if self.len == Self::CAPACITY {
            self.fold_into(m, walls);
        }
        // Walls number at most MAX_WALLS (20): a u8 holds the index.
        self.walls[self.len] = wall as u8;
        self.len += 1;
    }

    /// `m` times the pending reflections, in the order crossed.
    pub(super) fn fold_into(&mut self, m: &mut DMat4, walls: &[DVec4]) {
        for &w in &self.walls[..self.len] {
            *m = times_reflection(m, walls[usize::from(w)]);
        }
        self.len = 0;
    }
}
