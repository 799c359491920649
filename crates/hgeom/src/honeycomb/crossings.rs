//! The walls a walk crosses, kept until the domain matrix is needed (when
//! it is needed: `walk_in` in `walk.rs`).

use glam::{DMat4, DVec4};

use super::kernels::{reflect, times_reflection};

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

    /// The pending reflections applied to `v`, the last crossed first: `m`
    /// times this is `m` with the reflections folded in, times `v`, for a
    /// tenth of the work when only one vector is wanted (a hit's normal).
    pub(super) fn unfold(&self, mut v: DVec4, walls: &[DVec4]) -> DVec4 {
        for &w in self.walls[..self.len].iter().rev() {
            v = reflect(v, walls[usize::from(w)]);
        }
        v
    }

    /// `m` times the pending reflections, in the order crossed.
    pub(super) fn fold_into(&mut self, m: &mut DMat4, walls: &[DVec4]) {
        for &w in &self.walls[..self.len] {
            *m = times_reflection(m, walls[usize::from(w)]);
        }
        self.len = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::honeycomb::schlafli::Schlafli;
    use crate::honeycomb::simplex::CoxeterSimplex;

    /// A vector moved by the pending reflections (`unfold`) is the one the
    /// folded matrix moves, for walks shorter and longer than the capacity
    /// (which fold part of the walls into the matrix early), to a few ulps.
    #[test]
    fn unfold_moves_a_vector_as_the_folded_matrix_does() {
        let walls = CoxeterSimplex::new(Schlafli::new(4, 3, 5).unwrap()).normals();
        let v = DVec4::new(0.3, -0.2, 0.5, 1.2);
        for len in [0, 1, 5, Pending::CAPACITY, Pending::CAPACITY + 7, 40] {
            let mut pending = Pending::new(Crossings::Deferred);
            let mut m = DMat4::IDENTITY;
            let mut wall = 0;
            for k in 0..len {
                // Never the same wall twice in a row, as a walk crosses.
                wall = (wall + 1 + k % 3) % 4;
                pending.cross(wall, &mut m, &walls);
            }
            let unfolded = m * pending.unfold(v, &walls);
            pending.fold_into(&mut m, &walls);
            let folded = m * v;
            let scale = folded.abs().max_element().max(1.0);
            assert!(
                (unfolded - folded).abs().max_element() < 1e-12 * scale,
                "{len} walls: {unfolded} against {folded}"
            );
        }
    }
}
