//! The nearest hit along a ray followed across the domain's faces: what
//! every integrator asks first, in H³ and in a quotient space alike.

use hgeom::Ray;
use hscene_ir::MAX_SPACE_CROSSINGS;

use crate::scene::{Nearest, PreparedScene, is_horizon};

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
}

impl PreparedScene {
    /// True when the scene is in a quotient space.
    pub fn in_space(&self) -> bool {
        self.space.is_some()
    }

    /// The nearest hit beyond `t_min` along `ray`; in a quotient space the
    /// ray is carried across the faces it leaves the domain by until it
    /// meets something, reaches the horizon or has crossed
    /// [`MAX_SPACE_CROSSINGS`] faces (both a miss: `docs/manifolds.md`).
    pub fn trace(&self, ray: &Ray, t_min: f64) -> Traced {
        self.trace_recording(ray, t_min, |_| {})
    }

    /// [`PreparedScene::trace`], calling `crossed(face)` for each face the
    /// ray leaves the domain by, in order (the word of the group element
    /// that takes the tile it meets onto the domain: `docs/manifolds.md`).
    pub fn trace_recording(&self, ray: &Ray, t_min: f64, mut crossed: impl FnMut(usize)) -> Traced {
        let Some(space) = &self.space else {
            return Traced {
                nearest: self.nearest(ray, t_min),
                ray: *ray,
                travelled: 0.0,
                crossings: 0,
            };
        };
        let miss = |ray: Ray, travelled: f64, crossings: u32| Traced {
            nearest: Nearest::Miss,
            ray,
            travelled,
            crossings,
        };
        if !(ray.origin.is_finite() && ray.dir.is_finite()) {
            return Traced {
                nearest: Nearest::Failure,
                ray: *ray,
                travelled: 0.0,
                crossings: 0,
            };
        }
        let (mut ray, mut travelled, mut lo) = (*ray, 0.0, t_min);
        let mut crossings = 0;
        for _ in 0..=MAX_SPACE_CROSSINGS {
            let left = space.horizon - travelled;
            if !(left > lo) {
                break;
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
                    };
                }
            }
            let Some(c) = exit else {
                break;
            };
            crossed(c.face);
            crossings += 1;
            ray = space.space.carry(&ray, c);
            travelled += c.t;
            lo = (lo - c.t).max(0.0);
        }
        miss(ray, travelled, crossings)
    }
}
