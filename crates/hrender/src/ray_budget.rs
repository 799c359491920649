//! The second bound on a ray tree (the first is its contribution, see
//! `MIN_WEIGHT` in the tracer): a fixed number of reflected and transmitted
//! rays per primary ray.
//!
//! Whitted recursion branches at every surface that both reflects and
//! transmits, so a tree is up to `2^depth` rays. Where the contribution does
//! not fall (`reflection = 1, transmission = 1`, which creates light) the
//! weight bound never cuts, and `recursion_depth = 64` would never finish.
//! The budget caps every tree, depth-first in the order the tracer follows
//! (reflection before transmission), and the render reports how many primary
//! rays it cut, so no image is silently different.

/// Reflected and transmitted rays one primary ray may spawn in all: a
/// mirror path of the deepest allowed recursion (64) fits four times over,
/// and a full binary tree of depth 7 (254 rays) fits; past it the cost per
/// pixel stays that of a few hundred rays (POV-Ray's default
/// `max_trace_level = 5` allows trees of 62).
pub const MAX_SECONDARY_RAYS: u32 = 256;

/// What is left of one primary ray's budget.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RayBudget {
    left: u32,
    cut: bool,
}

impl Default for RayBudget {
    fn default() -> Self {
        RayBudget {
            left: MAX_SECONDARY_RAYS,
            cut: false,
        }
    }
}

impl RayBudget {
    /// Takes one ray from the budget; `false` (and the tree counts as cut)
    /// when none is left.
    pub fn take(&mut self) -> bool {
        if self.left == 0 {
            self.cut = true;
            return false;
        }
        self.left -= 1;
        true
    }

    /// Whether a ray was refused.
    pub fn was_cut(self) -> bool {
        self.cut
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gives_exactly_the_budget_then_reports_the_cut() {
        let mut b = RayBudget::default();
        assert!((0..MAX_SECONDARY_RAYS).all(|_| b.take()));
        assert!(!b.was_cut());
        assert!(!b.take());
        assert!(b.was_cut());
    }
}
