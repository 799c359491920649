//! Tinted glass: Beer-Lambert absorption along the geodesic length inside
//! an object. Light that travels a hyperbolic distance `d` inside a
//! material of absorption `σ` (per channel, per unit distance) keeps
//! `exp(-σ d)`: the law of a homogeneous absorbing medium, which holds in
//! H³ as it does in Euclidean space because it is a statement about
//! length along the ray, and a ray's parameter is its hyperbolic arc
//! length.
//!
//! Rays the integrators follow through glass start on its surface, so the
//! length inside is the distance to the hit where they leave (the hit the
//! ray meets from inside: the direction against the outward normal is
//! positive). Shadow rays cross whole objects: their length inside each
//! absorbing object is summed from its entries and exits along the
//! segment ([`PreparedScene::absorption_along`]).

use hgeom::Ray;
use hgeom::lorentz;
use hscene_ir::{Material, Rgb};

use crate::scene::PreparedScene;

/// The most surface crossings counted along one shadow segment of one
/// object (beyond, the rest of the segment counts as inside).
const MAX_CROSSINGS: usize = 64;

/// What is left of light after `d` inside `m`.
pub fn absorbed(m: &Material, d: f64) -> Rgb {
    let a = m.absorption;
    let d = d.max(0.0);
    Rgb::new((-a.r * d).exp(), (-a.g * d).exp(), (-a.b * d).exp())
}

impl PreparedScene {
    /// The product over the absorbing objects of what they let through of
    /// the segment `(t_min, t_max)` of `ray` (white without any):
    /// [`absorbed`] over the length of the segment inside each.
    pub fn absorption_along(&self, ray: &Ray, t_min: f64, t_max: f64) -> Rgb {
        let mut left = Rgb::new(1.0, 1.0, 1.0);
        for &k in self.absorbing() {
            let o = &self.objects[k];
            let m = &self.materials[o.material];
            let mut crossings: Vec<(f64, bool)> = Vec::new();
            for surface in o.surfaces.iter() {
                let mut from = t_min;
                while crossings.len() < MAX_CROSSINGS {
                    let Some(hit) = surface.intersect(ray, from, t_max) else {
                        break;
                    };
                    let entering = lorentz::dot(ray.tangent_at(hit.t), hit.normal) < 0.0;
                    crossings.push((hit.t, entering));
                    from = hit.t + 1e-9;
                }
            }
            if crossings.is_empty() {
                continue;
            }
            crossings.sort_by(|a, b| a.0.total_cmp(&b.0));
            // Inside at the start when the first crossing is a way out.
            let mut inside_from = (!crossings[0].1).then_some(t_min);
            let mut length = 0.0;
            for &(t, entering) in &crossings {
                match (entering, inside_from) {
                    (true, None) => inside_from = Some(t),
                    (false, Some(start)) => {
                        length += t - start;
                        inside_from = None;
                    }
                    _ => {}
                }
            }
            if let Some(start) = inside_from {
                length += t_max - start;
            }
            left = left.tint(absorbed(m, length));
        }
        left
    }
}
