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
//! the emission plus the parts' glow under the surround (below); fog acts along the ray to the horizon as it does on the
//! cells around it. Lights do not reach it: a light `r` away gives a cell
//! `1/sinh² r` of its intensity, under `1e-5` of a nearby cell's once `r`
//! passes 6, and the pixel horizon lies beyond 6 in any picture of a few
//! hundred pixels.
//!
//! **What lies behind.** Each line also carries the light from beyond its
//! end, weight 1, multiplied at each part by its `trans` and tint and
//! stopped by an opaque part or the last recursion depth (the path
//! tracer's: its 64 bounces). The mean weight
//! left at length `Δ` is the *openness* `O(Δ)`; a horizon hit adds `O(Δ)`
//! times what a ray leaving the scene along it brings (sky, background,
//! fog colour). The lines are 9 long; a longer rest is two independent
//! stretches (`O(9 + x) = O(9) O(x)`).
//!
//! **The parts under the path tracer** glow as the surround lights them:
//! a Lambertian part of reflectance `ρ` sees the surround's mean radiance
//! `L̄` through the open share `O` of its directions and parts as bright
//! as itself through the rest, `R = ρ (O L̄ + (1 - O) R)`, so
//! `R = ρ O L̄ / (1 - ρ (1 - O))`, with `O` a whole line's openness
//! (docs/rendering.md, "Beyond a honeycomb's horizon").
//!
//! The averaging ([`average_appearance`], [`seen_along`]) takes the sample
//! lines' walk as a function: a quotient space's fill (`space_fill.rs`)
//! walks the same lines across the domain's faces.

use hgeom::glam::DVec3;
use hgeom::{DEFAULT_HORIZON, HoneycombPart, Isometry, Ray, decode_honeycomb_part};
use hscene_ir::{IntegratorKind, Material, Rgb, Scene};

use crate::absorption::sheet_filter;
use crate::horizon_bucket::{HorizonFill, STEP};
use crate::integrator::MAX_PATH_LENGTH;
use crate::material::reflectances;
use crate::scene::{PreparedObject, PreparedScene, T_MIN};
use rayon::prelude::*;

/// How many sample lines make a honeycomb's average appearance.
const SAMPLES: usize = 1024;

/// Where along its direction from the eye a sample line starts.
pub const SAMPLE_START: f64 = 3.0;

/// Gives each honeycomb of `prepared` (made from `scene` moved by
/// `stages`) its horizon fills: its average appearance and openness for
/// every remaining length (module docs), the materials appended to the
/// scene's.
pub fn fill_horizons(prepared: &mut PreparedScene, scene: &Scene, stages: &[Isometry]) {
    let (depth, surround) = depth_and_surround(scene);
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
            faces_by_part: false,
            horizon: Vec::new(),
            mapping: None,
        };
        let materials = &prepared.materials;
        let walk = |from_eye: &Ray| honeycomb_line(&sampler, materials, from_eye, depth);
        let beyond = average_appearance(
            walk,
            &materials[sampler.material],
            "the honeycomb beyond its horizon",
            surround,
        );
        o.horizon = append_fills(&mut prepared.materials, beyond);
    }
}

/// How deep the sample lines look through transparent parts, and the
/// mean radiance from beyond that lights the parts (the path tracer's
/// only): the path tracer lights surfaces by the sky, and its paths pass
/// as many faces as they have bounces; Whitted lights by the ambient term
/// and stops at the recursion depth.
pub(crate) fn depth_and_surround(scene: &Scene) -> (u32, Option<Rgb>) {
    match scene.settings.integrator {
        IntegratorKind::Path => (MAX_PATH_LENGTH, Some(mean_surround(scene))),
        IntegratorKind::Whitted => (scene.settings.recursion_depth, None),
    }
}

/// The fills of `beyond` (one per remaining length), their materials
/// appended to `materials`.
pub(crate) fn append_fills(
    materials: &mut Vec<Material>,
    beyond: Vec<(Material, Rgb)>,
) -> Vec<HorizonFill> {
    let first = materials.len();
    let fills = (beyond.iter().enumerate())
        .map(|(k, (_, open))| HorizonFill {
            material: first + k,
            open: *open,
        })
        .collect();
    materials.extend(beyond.into_iter().map(|(m, _)| m));
    fills
}

/// What the sample line along `from_eye` meets in the honeycomb
/// `sampler` from [`SAMPLE_START`] on.
fn honeycomb_line(
    sampler: &PreparedObject,
    materials: &[Material],
    from_eye: &Ray,
    max_depth: u32,
) -> Vec<Met> {
    let line = Ray {
        origin: from_eye.at(SAMPLE_START),
        dir: from_eye.tangent_at(SAMPLE_START),
    };
    let mut t_min = T_MIN;
    let next = || {
        let hit = sampler
            .intersect(&line, t_min, f64::INFINITY)
            .filter(|h| decode_honeycomb_part(h.part).0 != HoneycombPart::Horizon)?;
        t_min = hit.t + T_MIN;
        let m = &materials[sampler.material_of(&hit)];
        let (ambient, diffuse) = reflectances(sampler, m, &hit);
        let cos = hgeom::lorentz::dot(line.tangent_at(hit.t), hit.normal);
        Some(Seen {
            s: hit.t,
            material: m,
            ambient,
            diffuse,
            filter: sheet_filter(m, cos),
        })
    };
    seen_along(next, max_depth)
}

/// The radiance arriving from beyond every honeycomb, averaged over all
/// directions: the fog colour in fog, else the sky's mean over the sphere,
/// else the background.
pub(crate) fn mean_surround(scene: &Scene) -> Rgb {
    let settings = &scene.settings;
    if let Some(fog) = &settings.fog {
        return fog.color;
    }
    let Some(sky) = &settings.sky else {
        return settings.background;
    };
    let mut sum = Rgb::BLACK;
    for k in 0..SAMPLES {
        sum += sky.radiance(fibonacci_direction(k, SAMPLES));
    }
    sum * (1.0 / SAMPLES as f64)
}

/// What the sample lines of a honeycomb met, summed per remaining length.
struct Tally {
    ambient: Vec<Rgb>,
    emission: Vec<Rgb>,
    /// Sums of the light from beyond each line lets through.
    open: Vec<Rgb>,
    /// The diffuse parts met: from which bucket on they count, their
    /// diffuse reflectance and the weight of the line's light there.
    diffuse: Vec<(usize, Rgb, Rgb)>,
}

/// The average appearance, along the rest of the way to distance 12, of
/// what the sample lines meet, and how open that rest is: one material
/// (`base` with only ambient and emission terms, called `name`) and one
/// openness for each `Δ = k STEP`, `k = 0..=12/STEP` (module docs).
/// `walk` gives what the line along a direction from the eye meets from
/// [`SAMPLE_START`] on (a honeycomb's parts, or a space's objects and
/// rods across its faces: `space_fill.rs`). With `surround` (the path
/// tracer's mean radiance from beyond), the parts glow as lit by it.
pub(crate) fn average_appearance(
    walk: impl Fn(&Ray) -> Vec<Met> + Sync,
    base: &Material,
    name: &str,
    surround: Option<Rgb>,
) -> Vec<(Material, Rgb)> {
    let buckets = (DEFAULT_HORIZON / STEP).round() as usize + 1;
    let mut t = Tally {
        ambient: vec![Rgb::BLACK; buckets],
        emission: vec![Rgb::BLACK; buckets],
        // Every line is open over every length until it meets something.
        open: vec![Rgb::new(1.0, 1.0, 1.0) * SAMPLES as f64; buckets],
        diffuse: Vec::new(),
    };
    // The lines are walked in parallel and summed in order: the sums do
    // not depend on the threads.
    let lines: Vec<Vec<Met>> = (0..SAMPLES)
        .into_par_iter()
        .map(|k| walk(&Ray::from_origin_unchecked(fibonacci_direction(k, SAMPLES))))
        .collect();
    for met in lines.into_iter().flatten() {
        // A part met at arc length s counts for every Δ > s.
        let first = ((met.s / STEP).floor() as usize + 1).min(buckets);
        for b in first..buckets {
            t.ambient[b] += met.ambient;
            t.emission[b] += met.emission;
            t.open[b] += met.stopped * -1.0;
        }
        t.diffuse.push((first, met.diffuse, met.weight));
    }
    let share = 1.0 / SAMPLES as f64;
    // The lines are 12 - SAMPLE_START long: what lies beyond that length
    // is a second, independent stretch behind the first.
    let walked = (((DEFAULT_HORIZON - SAMPLE_START) / STEP).floor() as usize).min(buckets - 1);
    if let Some(l) = surround {
        let whole = clamp_unit(t.open[walked] * share);
        for &(first, rho, weight) in &t.diffuse {
            let glow = lit_by_surround(rho, whole, l).tint(weight);
            for b in first..buckets {
                t.emission[b] += glow;
            }
        }
    }
    for b in walked + 1..buckets {
        let (rest, through) = (b - walked, t.open[walked] * share);
        t.ambient[b] = t.ambient[walked] + t.ambient[rest].tint(through);
        t.emission[b] = t.emission[walked] + t.emission[rest].tint(through);
        t.open[b] = t.open[rest].tint(through);
    }
    (0..buckets)
        .map(|b| {
            let material = Material {
                name: Some(name.to_owned()),
                ambient: t.ambient[b] * share,
                diffuse: Rgb::BLACK,
                specular: Rgb::BLACK,
                reflection: 0.0,
                transmission: 0.0,
                emission: t.emission[b] * share,
                absorption: Rgb::BLACK,
                texture: None,
                ..base.clone()
            };
            (material, clamp_unit(t.open[b] * share))
        })
        .collect()
}

/// The radiance a Lambertian part of reflectance `rho` sends out in a
/// honeycomb of openness `open` over the whole way, lit by the mean
/// radiance `l` from beyond (docs/rendering.md, "Beyond a honeycomb's
/// horizon"): its directions see `l` through the open share and other
/// parts, as bright as itself, through the rest, so
/// `R = rho (open l + (1 - open) R)`, `R = rho open l / (1 - rho (1 - open))`.
fn lit_by_surround(rho: Rgb, open: Rgb, l: Rgb) -> Rgb {
    let one = |rho: f64, open: f64, l: f64| {
        let bounce = rho * (1.0 - open);
        if bounce < 1.0 {
            rho * open * l / (1.0 - bounce)
        } else {
            0.0
        }
    };
    Rgb::new(
        one(rho.r, open.r, l.r),
        one(rho.g, open.g, l.g),
        one(rho.b, open.b, l.b),
    )
}

/// Each channel of `c` within `[0, 1]` (the sums of shares round).
fn clamp_unit(c: Rgb) -> Rgb {
    let [r, g, b] = c.channels().map(|x| x.clamp(0.0, 1.0));
    Rgb::new(r, g, b)
}

/// A part a sample line met: where, what it adds (already weighted by
/// the transparent parts before it) and how much of the line's light
/// from beyond it stops (the weight before it less the weight after).
pub(crate) struct Met {
    s: f64,
    ambient: Rgb,
    emission: Rgb,
    stopped: Rgb,
    /// The part's diffuse reflectance, and the weight of the line's light
    /// that reaches it.
    diffuse: Rgb,
    weight: Rgb,
}

/// A part a sample line reaches, as its walk finds it.
pub(crate) struct Seen<'m> {
    /// The arc length from the line's start.
    pub s: f64,
    /// The part's material.
    pub material: &'m Material,
    /// Its ambient and diffuse reflectances there (textures applied).
    pub ambient: Rgb,
    pub diffuse: Rgb,
    /// What is left of light that passes this crossing, besides the
    /// material's transmission: a tinted sheet's filter, or a solid's
    /// absorption over the way inside when the line leaves it.
    pub filter: Rgb,
}

/// The parts a line meets, `next` giving each in turn, through
/// transparent ones, up to the recursion depth, until an opaque one or
/// the walk's end. The line's light from beyond is stopped by opaque
/// parts, filtered by transparent ones, and stopped where the recursion
/// ends (Whitted traces no ray on from a hit at the last depth).
pub(crate) fn seen_along<'m>(
    mut next: impl FnMut() -> Option<Seen<'m>>,
    max_depth: u32,
) -> Vec<Met> {
    let mut met = Vec::new();
    let mut weight = Rgb::new(1.0, 1.0, 1.0);
    for depth in 0..=max_depth {
        let Some(hit) = next() else {
            break;
        };
        let m = hit.material;
        let after = if depth == max_depth {
            Rgb::BLACK
        } else {
            weight.tint(hit.filter) * m.transmission
        };
        met.push(Met {
            s: hit.s,
            ambient: hit.ambient.tint(weight),
            emission: m.emission.tint(weight),
            stopped: weight + after * -1.0,
            diffuse: hit.diffuse,
            weight,
        });
        weight = after;
        if weight.is_black() {
            break;
        }
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

    /// `R = rho open l / (1 - rho (1 - open))`: a part in the open takes
    /// `rho l`; a part that sees only other parts (a closed honeycomb)
    /// takes nothing; in between, the bounces add up to the closed form.
    #[test]
    fn parts_glow_as_the_surround_lights_them() {
        let l = Rgb::new(1.0, 0.5, 2.0);
        let rho = Rgb::new(0.5, 0.5, 0.5);
        let open = |x| Rgb::new(x, x, x);
        assert_eq!(lit_by_surround(rho, open(1.0), l), Rgb::new(0.5, 0.25, 1.0));
        assert_eq!(lit_by_surround(rho, open(0.0), l), Rgb::BLACK);
        // Half open: the series rho o l (1 + rho (1-o) + ...) summed.
        let series: f64 = (0..200).map(|k| 0.25 * 0.25f64.powi(k)).sum();
        let r = lit_by_surround(rho, open(0.5), l);
        assert!((r.r - series).abs() < 1e-12, "{r:?} {series}");
    }
}
