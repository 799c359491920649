//! The nearest hit along a ray followed across the domain's faces: what
//! every integrator asks first, in H³ and in a quotient space alike.

use hgeom::Ray;
use hscene_ir::MAX_SPACE_CROSSINGS;

use crate::horizon_bucket::is_horizon;
use crate::scene::{Nearest, PreparedScene};

/// What a ray met, and the ray as it was when it met it.
#[derive(Clone, Copy, Debug)]
pub struct Traced {
    /// The nearest hit (its `t` on [`Traced::ray`]), a miss or a failure.
    pub nearest: Nearest,
    /// The ray carried into the domain by the faces it crossed (the ray
    /// itself in H³); the hit's point, normal and `t` are on it.
    pub ray: Ray,
    /// The arc length travelled before [`Traced::ray`]'s origin: the hit
    /// lies `travelled + hit.t` along the whole path (fog, absorption).
    pub travelled: f64,
    /// How many faces the ray crossed (0 in H³).
    pub crossings: u32,
    /// For a miss in a quotient space, the arc length along the whole
    /// path where the walk gave up (at the horizon or the crossing cap):
    /// the rest of the way to distance 12 is drawn in the space's average
    /// appearance (`space_fill.rs`). `None` in H³ and for a hit.
    pub gave_up: Option<f64>,
}

impl PreparedScene {
    /// True when the scene is in a quotient space.
    pub fn in_space(&self) -> bool {
        self.space.is_some()
    }

    /// The nearest hit beyond `t_min` along `ray`; in a quotient space the
    /// ray is carried across the faces it leaves the domain by until it
    /// meets something, reaches the horizon or has crossed
    /// [`MAX_SPACE_CROSSINGS`] faces (both a miss that reports where the
    /// walk gave up, [`Traced::gave_up`]: `docs/manifolds.md`).
    pub fn trace(&self, ray: &Ray, t_min: f64) -> Traced {
        self.trace_recording(ray, t_min, |_| {})
    }

    /// [`PreparedScene::trace`], calling `crossed(face)` for each face the
    /// ray leaves the domain by, in order (the word of the group element
    /// that takes the tile it meets onto the domain: `docs/manifolds.md`).
    pub fn trace_recording(&self, ray: &Ray, t_min: f64, crossed: impl FnMut(usize)) -> Traced {
        let horizon = self.space.as_ref().map_or(0.0, |s| s.horizon);
        self.walk(ray, t_min, horizon, crossed)
    }

    /// [`PreparedScene::trace_recording`] with the walk stopped at arc
    /// length `horizon` (the space's own, or distance 12 for the sample
    /// lines of its average appearance, `space_fill.rs`).
    pub(crate) fn walk(
        &self,
        ray: &Ray,
        t_min: f64,
        horizon: f64,
        mut crossed: impl FnMut(usize),
    ) -> Traced {
        let Some(space) = &self.space else {
            return Traced {
                nearest: self.nearest(ray, t_min),
                ray: *ray,
                travelled: 0.0,
                crossings: 0,
                gave_up: None,
            };
        };
        let miss = |ray: Ray, travelled: f64, crossings: u32, at: f64| Traced {
            nearest: Nearest::Miss,
            ray,
            travelled,
            crossings,
            gave_up: Some(at),
        };
        if !(ray.origin.is_finite() && ray.dir.is_finite()) {
            return Traced {
                nearest: Nearest::Failure,
                ray: *ray,
                travelled: 0.0,
                crossings: 0,
                gave_up: None,
            };
        }
        let (mut ray, mut travelled, mut lo) = (*ray, 0.0, t_min);
        let mut crossings = 0;
        for _ in 0..=MAX_SPACE_CROSSINGS {
            let left = horizon - travelled;
            if !(left > lo) {
                return miss(ray, travelled, crossings, horizon);
            }
            let exit = space.space.exit(&ray).filter(|c| c.t < left);
            let hi = exit.map_or(left, |c| c.t);
            match self.nearest_within(&ray, lo, hi) {
                // A honeycomb's own horizon (12 from this piece's start)
                // lies beyond every piece: not a hit here.
                Nearest::Hit(hit, _) if is_horizon(hit.part) => {}
                Nearest::Miss => {}
                found => {
                    return Traced {
                        nearest: found,
                        ray,
                        travelled,
                        crossings,
                        gave_up: None,
                    };
                }
            }
            // No face before the horizon: the walk ends there.
            let Some(c) = exit else {
                return miss(ray, travelled, crossings, horizon);
            };
            crossed(c.face);
            crossings += 1;
            ray = space.space.carry(&ray, c);
            travelled += c.t;
            lo = (lo - c.t).max(0.0);
        }
        // The crossings ran out (a ray down a cusp crosses ever smaller
        // tiles): the walk gives up where it is.
        miss(ray, travelled, crossings, travelled)
    }
}
