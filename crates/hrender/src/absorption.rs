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
//!
//! **Sheets.** A honeycomb's faces are sheets with no inside: light crosses
//! each and goes on. On a sheet `absorption` is per crossing, as for a thin
//! slab whose thickness is the unit: at normal incidence a crossing keeps
//! `exp(-σ)`, at an angle `θ` to the normal `exp(-σ / |cos θ|)` (the path
//! through a thin slab grows as `1/|cos θ|`). Layers of tinted faces then
//! multiply, as stacked coloured glass does, instead of adding their own
//! colours ([`sheet_filter`]).

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

/// What is left of light that crosses a sheet of `m` at `cos θ` to its
/// normal (module docs, "Sheets"); white for a material that does not
/// absorb.
pub fn sheet_filter(m: &Material, cos: f64) -> Rgb {
    if m.absorption.is_black() {
        return Rgb::new(1.0, 1.0, 1.0);
    }
    // Grazing crossings keep nothing; the floor keeps 1/|cos θ| finite.
    absorbed(m, 1.0 / cos.abs().max(1e-9))
}

impl PreparedScene {
    /// The product over the absorbing objects of what they let through of
    /// the segment `(t_min, t_max)` of `ray` (white without any):
    /// [`absorbed`] over the length of the segment inside each.
    /// In a quotient space the segment is followed across the domain's
    /// faces.
    pub fn absorption_along(&self, ray: &Ray, t_min: f64, t_max: f64) -> Rgb {
        let Some(space) = &self.space else {
            return self.absorption_in_domain(ray, t_min, t_max);
        };
        let mut left = Rgb::new(1.0, 1.0, 1.0);
        space.segments(ray, t_min, t_max, |piece, lo, hi| {
            left = left.tint(self.absorption_in_domain(piece, lo, hi));
            true
        });
        left
    }

    /// [`PreparedScene::absorption_along`] along one geodesic segment.
    fn absorption_in_domain(&self, ray: &Ray, t_min: f64, t_max: f64) -> Rgb {
        let mut left = Rgb::new(1.0, 1.0, 1.0);
        for &k in self.absorbing() {
            let o = &self.objects[k];
            if o.parts.is_some() {
                left = left.tint(self.sheets_along(k, ray, t_min, t_max));
                continue;
            }
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

    /// What the sheets (faces) of object `k`, drawn in several materials,
    /// let through of the segment: [`sheet_filter`] for each part it
    /// crosses.
    fn sheets_along(&self, k: usize, ray: &Ray, t_min: f64, t_max: f64) -> Rgb {
        let o = &self.objects[k];
        let mut left = Rgb::new(1.0, 1.0, 1.0);
        for surface in o.surfaces.iter() {
            let mut from = t_min;
            for _ in 0..MAX_CROSSINGS {
                let Some(hit) = surface.intersect(ray, from, t_max) else {
                    break;
                };
                let m = &self.materials[o.material_of(&hit)];
                let cos = lorentz::dot(ray.tangent_at(hit.t), hit.normal);
                left = left.tint(sheet_filter(m, cos));
                from = hit.t + 1e-9;
            }
        }
        left
    }
}
