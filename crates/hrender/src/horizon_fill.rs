//! What a honeycomb looks like beyond the walk's horizon.
//!
//! A honeycomb is walked no farther than where its cells shrink below a
//! pixel, and never past distance 12 from the eye
//! ([`hgeom::DEFAULT_HORIZON`]). The pixel horizon is a saving, not a
//! statement about the space: drawing the background beyond it made a
//! hole whose size followed the output resolution (the cusp of a
//! horosphere-inscribed cell of `{4,4,3}` took 14.5 % of the width at 200
//! pixels, 8.4 % at 600). So the walk reports a *horizon hit* where it
//! gives up ([`hgeom::RegularHoneycomb::with_horizon_hits`]), and the
//! renderer draws there what the rest of the way to distance 12 holds on
//! average: the picture is the one a walk to 12 at any resolution would
//! give, with the part below a pixel averaged.
//!
//! **The average.** What a geodesic segment of length `Δ` meets in a
//! honeycomb is, on average over where it starts and where it points, the
//! same everywhere (the honeycomb's symmetries move any cell to any
//! other). It is measured once per prepared scene: [`SAMPLES`] lines
//! start at distance [`SAMPLE_START`] from the eye in an even spread of
//! directions (past the cells around the eye, so that one cell's faces do
//! not decide; at that distance the starts fall all over the cells) and
//! are walked to distance 12. Each takes the ambient reflectance and
//! emission of the parts it meets within `Δ`, through a transparent part
//! `trans` times what it meets next (filtered by a tinted face,
//! `absorption.rs`), up to the recursion depth. The mean,
//! for `Δ` in steps of [`STEP`], is a material with those ambient and
//! emission terms and nothing else (no diffuse, specular, mirror or glass
//! term); a horizon hit at distance `h` from the eye takes the one for
//! `Δ = 12 - h`. The integrators shade it as any hit: Whitted gives
//! `ambient × scene ambient + emission`, the path tracer (no ambient term)
//! the emission; fog acts along the ray to the horizon as it does on the
//! cells around it. Lights do not reach it: a light `r` away gives a cell
//! `1/sinh² r` of its intensity, under `1e-5` of a nearby cell's once `r`
//! passes 6, and the pixel horizon lies beyond 6 in any picture of a few
//! hundred pixels.

use hgeom::glam::DVec3;
use hgeom::{DEFAULT_HORIZON, HoneycombPart, Isometry, Ray, decode_honeycomb_part};
use hscene_ir::{Material, Rgb, Scene};

use crate::absorption::sheet_filter;
use crate::horizon_bucket::STEP;
use crate::material::reflectances;
use crate::scene::{PreparedObject, PreparedScene, T_MIN};

/// How many sample lines make a honeycomb's average appearance.
const SAMPLES: usize = 1024;

/// Where along its direction from the eye a sample line starts.
pub const SAMPLE_START: f64 = 3.0;

/// Gives each honeycomb of `prepared` (made from `scene` moved by
/// `stages`) its horizon materials: its average appearance for every
/// remaining length (module docs), appended to the materials.
pub fn fill_horizons(prepared: &mut PreparedScene, scene: &Scene, stages: &[Isometry]) {
    let depth = scene.settings.recursion_depth;
    for (o, source) in prepared.objects.iter_mut().zip(&scene.objects) {
        if o.parts.is_none() {
            continue;
        }
        // The same honeycomb walked to distance 12 whatever the picture's
        // pixels, for the average.
        let sampler = PreparedObject {
            surfaces: PreparedObject::moved(&source.shape, stages, None, false).0,
            material: o.material,
            parts: o.parts.clone(),
            opaque: o.opaque,
            to_local: o.to_local,
            ball: None,
            faces: Vec::new(),
            horizon: Vec::new(),
            mapping: None,
        };
        let beyond = average_appearance(&sampler, &prepared.materials, depth);
        let first = prepared.materials.len();
        o.horizon = (first..first + beyond.len()).collect();
        prepared.materials.extend(beyond);
    }
}

/// The average appearance of the honeycomb `sampler` (the scene's
/// honeycomb walked to distance 12 from the eye, with its part
/// materials) along the rest of the way to 12: one material for each
/// `Δ = k STEP`, `k = 0..=12/STEP` (module docs).
pub fn average_appearance(
    sampler: &PreparedObject,
    materials: &[Material],
    max_depth: u32,
) -> Vec<Material> {
    let buckets = (DEFAULT_HORIZON / STEP).round() as usize + 1;
    let mut ambient = vec![Rgb::BLACK; buckets];
    let mut emission = vec![Rgb::BLACK; buckets];
    for k in 0..SAMPLES {
        let from_eye = Ray::from_origin_unchecked(fibonacci_direction(k, SAMPLES));
        let line = Ray {
            origin: from_eye.at(SAMPLE_START),
            dir: from_eye.tangent_at(SAMPLE_START),
        };
        for met in seen_along(sampler, materials, &line, max_depth) {
            // A part met at arc length s counts for every Δ > s.
            let first = (met.s / STEP).floor() as usize + 1;
            for b in first.min(buckets)..buckets {
                ambient[b] += met.ambient;
                emission[b] += met.emission;
            }
        }
    }
    let share = 1.0 / SAMPLES as f64;
    (0..buckets)
        .map(|b| Material {
            name: Some("the honeycomb beyond its horizon".to_owned()),
            ambient: ambient[b] * share,
            diffuse: Rgb::BLACK,
            specular: Rgb::BLACK,
            reflection: 0.0,
            transmission: 0.0,
            emission: emission[b] * share,
            absorption: Rgb::BLACK,
            texture: None,
            ..materials[sampler.material].clone()
        })
        .collect()
}

/// A part a sample line met: where, and what it adds (already weighted by
/// the transparent parts before it).
struct Met {
    s: f64,
    ambient: Rgb,
    emission: Rgb,
}

/// The parts a line meets in the honeycomb, through transparent ones, up
/// to the recursion depth, until an opaque one or the walk's end.
fn seen_along(
    object: &PreparedObject,
    materials: &[Material],
    line: &Ray,
    max_depth: u32,
) -> Vec<Met> {
    let mut met = Vec::new();
    let mut weight = Rgb::new(1.0, 1.0, 1.0);
    let mut t_min = T_MIN;
    for _ in 0..=max_depth {
        let Some(hit) = object
            .intersect(line, t_min, f64::INFINITY)
            .filter(|h| decode_honeycomb_part(h.part).0 != HoneycombPart::Horizon)
        else {
            break;
        };
        let m = &materials[object.material_of(&hit)];
        let (a, _) = reflectances(object, m, &hit);
        met.push(Met {
            s: hit.t,
            ambient: a.tint(weight),
            emission: m.emission.tint(weight),
        });
        let cos = hgeom::lorentz::dot(line.tangent_at(hit.t), hit.normal);
        weight = weight.tint(sheet_filter(m, cos)) * m.transmission;
        if weight.is_black() {
            break;
        }
        t_min = hit.t + T_MIN;
    }
    met
}

/// The `k`-th of `n` directions spread evenly over the sphere (a Fibonacci
/// lattice: equal areas in height, the golden angle apart in azimuth).
fn fibonacci_direction(k: usize, n: usize) -> DVec3 {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let z = 1.0 - (2.0 * k as f64 + 1.0) / n as f64;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = golden * k as f64;
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fibonacci_directions_are_unit_and_balanced() {
        let n = 1024;
        let sum: DVec3 = (0..n).map(|k| fibonacci_direction(k, n)).sum();
        for k in 0..n {
            assert!((fibonacci_direction(k, n).length() - 1.0).abs() < 1e-12);
        }
        assert!(sum.length() / (n as f64) < 1e-3, "{sum}");
    }
}
