//! A quotient space in the canonical frame, and the pieces a geodesic
//! segment is cut into as it crosses the domain's faces.
//!
//! Every query of the prepared scene (nearest hit, what a shadow segment
//! passes, absorption) runs on one piece at a time: the ray in the domain
//! up to the face it leaves by, then the ray carried by that face's
//! pairing into the domain again ([`hgeom::QuotientSpace::carry`]). The
//! objects near the domain are there with their images (`space_prepare.rs`),
//! so a piece meets what the unfolded ray meets in the universal cover.

use hgeom::{QuotientSpace, Ray};

use hscene_ir::MAX_SPACE_CROSSINGS;

use crate::horizon_bucket::HorizonFill;

/// The space a prepared scene is in.
#[derive(Clone, Debug)]
pub struct PreparedSpace {
    /// The domain and pairings, in the canonical frame.
    pub space: QuotientSpace,
    /// Where rays stop, as arc length from their origin: the horizon a
    /// honeycomb of the domain's cells would have in this picture
    /// (`docs/manifolds.md`).
    pub horizon: f64,
    /// The number each prepared object has in the scene's object list
    /// (as `check --emit ir` lists them, from 1): an object and all its
    /// images share it; the domain's rods (`domain = w, #M`) are one more
    /// than the last object.
    pub numbers: Vec<usize>,
    /// What a walk that gives up draws, by the rest of the way to
    /// distance 12 (`space_fill.rs`; empty until it is measured).
    pub fill: Vec<HorizonFill>,
}

impl PreparedSpace {
    /// Calls `piece(ray, lo, hi)` for each piece of the segment
    /// `(t_min, t_max)` of `ray` in turn, each ray in the domain with its
    /// own arc length, until `piece` returns false, the segment ends, or
    /// it has crossed [`MAX_SPACE_CROSSINGS`] faces (the rest counts as
    /// clear: it is beyond the horizon of any picture).
    pub fn segments(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        mut piece: impl FnMut(&Ray, f64, f64) -> bool,
    ) {
        let mut ray = *ray;
        let (mut lo, mut left) = (t_min, t_max);
        for _ in 0..=MAX_SPACE_CROSSINGS {
            let exit = self.space.exit(&ray).filter(|c| c.t < left);
            let hi = exit.map_or(left, |c| c.t);
            if hi > lo && !piece(&ray, lo, hi) {
                return;
            }
            let Some(c) = exit else {
                return;
            };
            ray = self.space.carry(&ray, c);
            left -= c.t;
            lo = (lo - c.t).max(0.0);
        }
    }
}
