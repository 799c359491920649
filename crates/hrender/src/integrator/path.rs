//! The path integrator: an unbiased Monte Carlo estimate of the light
//! arriving along each primary ray, with H³'s own radiometry
//! (docs/geometry.md, "Radiometry of H³"; docs/rendering.md, "The path
//! integrator").
//!
//! Radiance is constant along a geodesic in vacuum, so a path carries it
//! from vertex to vertex unchanged; the only place the geometry of H³
//! enters is where light is sampled by area or by point: the solid angle
//! of an area element `dA` at distance `r` is `cos θ' dA / sinh² r` (the
//! sphere of radius `r` has area `4π sinh² r`), so a point light's
//! irradiance falls as `1 / sinh² r`; an h-sphere is sampled exactly by
//! solid angle ([`SphereCone`]).
//!
//! At each vertex: emission (weighted against light sampling by the power
//! heuristic), next-event estimation to one light unit drawn by
//! [`LightSelector`]: a point light, a spherical emitter (an area light or
//! an emissive h-sphere, by the cone it subtends) or a triangle of an
//! emissive polygon, polyhedron or mesh (by the spherical triangle it
//! subtends), then one
//! direction from the material's lobes ([`Bsdf`]); Russian roulette after
//! three bounces (a path survives with the probability of its largest
//! throughput channel, when below 1), at most [`MAX_PATH_LENGTH`] bounces.

use hgeom::glam::DVec4;
use hgeom::lorentz;
use hgeom::{HSphere, Ray};
use hscene_ir::Rgb;

use super::Integrator;
use crate::absorption::{absorbed, sheet_filter};
use crate::bsdf::Bsdf;
use crate::light_select::{LightSelector, LightUnit};
use crate::material::reflectances;
use crate::sampling::SampleStream;
use crate::scene::{Nearest, PreparedScene, T_MIN};
use crate::tangent::is_unit;
use crate::trace_stats::TraceStats;
use hgeom::on_hyperboloid;

/// The most surfaces a path scatters from: far beyond where Russian
/// roulette ends paths in any scene that absorbs light at all.
pub const MAX_PATH_LENGTH: u32 = 64;

/// Bounces before Russian roulette may end a path.
const ROULETTE_AFTER: u32 = 3;

/// A spherical emitter: an area light, or an emissive h-sphere object.
pub(super) struct SphereEmitter {
    pub(super) centre: DVec4,
    pub(super) radius: f64,
    /// The radiance it emits, from both sides.
    pub(super) radiance: Rgb,
    /// The area light's own surface (an object's is in the scene).
    pub(super) surface: Option<HSphere>,
    /// The object it is, for an emissive h-sphere object.
    pub(super) object: Option<usize>,
    /// Its light unit in the selector.
    pub(super) unit: usize,
}

/// An emissive object with flat faces (a polygon, a polyhedron).
pub(super) struct FaceEmitter {
    pub(super) object: usize,
    /// The radiance it emits, from both sides.
    pub(super) radiance: Rgb,
    /// Its faces as geodesic triangles, each with the unit normal of its
    /// h-plane (`<x, m> = 0` on it).
    pub(super) triangles: Vec<([DVec4; 3], DVec4)>,
    /// The light unit of its first triangle; the others follow in order.
    pub(super) first_unit: usize,
    /// A hit's `part` is the index of its triangle (a mesh).
    pub(super) by_part: bool,
}

/// What a light unit of the selector is, in the integrator's own lists.
#[derive(Clone, Copy)]
pub(super) enum Source {
    /// `scene.lights[k]`, a point light.
    Point(usize),
    /// `emitters[k]`.
    Sphere(usize),
    /// Triangle `t` of `faces[f]`.
    Triangle(usize, usize),
}

/// The path integrator over a prepared scene.
pub struct PathTracer<'s> {
    pub(super) scene: &'s PreparedScene,
    pub(super) emitters: Vec<SphereEmitter>,
    pub(super) faces: Vec<FaceEmitter>,
    /// Every light next-event estimation may draw, one per vertex.
    pub(super) selector: LightSelector,
    /// What each of the selector's units is.
    pub(super) sources: Vec<Source>,
    /// Paths end at this many diffuse or glossy vertices (after light
    /// sampling there).
    smooth_vertices: u32,
}

/// What the last scattering vertex tells the next emitter hit: where it
/// was, its shading normal, the object it was on, the density its smooth
/// lobes drew the direction with, and the sum of the lights' importances
/// there (light selection's normaliser); `None` at the eye or after a
/// mirror or a refraction, which light sampling cannot reproduce.
#[derive(Clone, Copy)]
pub(super) struct Scattered {
    pub(super) from: DVec4,
    pub(super) n: DVec4,
    pub(super) on: usize,
    pub(super) pdf_bsdf: f64,
    pub(super) total: f64,
}

pub(super) type LastScatter = Option<Scattered>;

impl<'s> PathTracer<'s> {
    /// The integrator over `scene`: its spherical emitters gathered once.
    pub fn new(scene: &'s PreparedScene) -> PathTracer<'s> {
        let mut units = Vec::new();
        let mut sources = Vec::new();
        for (k, light) in scene.lights.iter().enumerate() {
            if light.radius == 0.0 {
                units.push(LightUnit::point(
                    light.position,
                    light.diffuse,
                    light.near_sinh2,
                    light.cosh_reach,
                ));
                sources.push(Source::Point(k));
            }
        }
        let mut emitters = Vec::new();
        for light in scene.lights.iter().filter(|l| l.radius > 0.0) {
            let surface = light.sphere();
            if surface.is_some() {
                emitters.push(SphereEmitter {
                    centre: light.position,
                    radius: light.radius,
                    radiance: light.radiance(),
                    surface,
                    object: None,
                    unit: 0,
                });
            }
        }
        let mut faces = Vec::new();
        // In a quotient space a path that meets a glowing object may have
        // crossed faces, and light sampling cannot tell which image it
        // met: such objects are found by the paths' own bounces alone
        // (unbiased, noisier; `docs/manifolds.md`).
        let sampled = if scene.in_space() {
            &[][..]
        } else {
            &scene.objects[..]
        };
        for (index, object) in sampled.iter().enumerate() {
            let m = &scene.materials[object.material];
            if !object.faces.is_empty() && !m.emission.is_black() {
                // Every triangle keeps its place (a mesh's hits count
                // them); a degenerate one gets no normal and, below, a unit
                // that is never drawn.
                let triangles = object
                    .faces
                    .iter()
                    .map(|t| (*t, plane_normal(*t).unwrap_or(DVec4::ZERO)))
                    .collect();
                faces.push(FaceEmitter {
                    object: index,
                    radiance: m.emission,
                    triangles,
                    first_unit: 0,
                    by_part: object.faces_by_part,
                });
            }
            if let (Some((centre, radius)), false) = (object.ball, m.emission.is_black()) {
                emitters.push(SphereEmitter {
                    centre,
                    radius,
                    radiance: m.emission,
                    surface: None,
                    object: Some(index),
                    unit: 0,
                });
            }
        }
        for (k, e) in emitters.iter_mut().enumerate() {
            e.unit = units.len();
            units.push(LightUnit::sphere(e.centre, e.radius, e.radiance, e.object));
            sources.push(Source::Sphere(k));
        }
        for (f, e) in faces.iter_mut().enumerate() {
            e.first_unit = units.len();
            // A triangle too degenerate for a unit could not be sampled
            // anyway (its solid angle is nothing): it keeps a unit that is
            // never drawn, so the indices stay in step.
            for (t, (tri, _)) in e.triangles.iter().enumerate() {
                let unit = LightUnit::triangle(*tri, e.radiance, e.object)
                    .unwrap_or_else(|| LightUnit::sphere(tri[0], 0.0, Rgb::BLACK, Some(e.object)));
                units.push(unit);
                sources.push(Source::Triangle(f, t));
            }
        }
        // A mesh's many triangles go under a tree of their own.
        let trees: Vec<(usize, usize)> = faces
            .iter()
            .map(|e| (e.first_unit, e.triangles.len()))
            .collect();
        PathTracer {
            scene,
            emitters,
            faces,
            selector: LightSelector::new(units, &trees),
            sources,
            smooth_vertices: MAX_PATH_LENGTH,
        }
    }

    /// The same integrator, its paths ended at their first diffuse or
    /// glossy vertex after the light sampled there: the light that reaches
    /// the eye straight from the lights, through mirrors and clear glass,
    /// with no light bouncing between surfaces. That is what Whitted's
    /// integrator computes too, with the same conventions, so the two can
    /// be compared image for image (`path_tracer.rs`,
    /// `direct_light_agrees_with_whitted`).
    pub fn direct_only(self) -> Self {
        PathTracer {
            smooth_vertices: 1,
            ..self
        }
    }

    /// The nearest area light along `ray` before `t_max`: its index and
    /// distance.
    fn light_hit(&self, ray: &Ray, t_max: f64) -> Option<(usize, f64)> {
        let mut best: Option<(usize, f64)> = None;
        for (k, e) in self.emitters.iter().enumerate() {
            let Some(surface) = &e.surface else {
                continue;
            };
            let limit = best.map_or(t_max, |b| b.1);
            if let Some(hit) = surface.intersect(ray, T_MIN, limit) {
                best = Some((k, hit.t));
            }
        }
        best
    }

    /// The emitter that is object `index`, if it is one.
    fn emitter_of(&self, index: usize) -> Option<usize> {
        self.emitters.iter().position(|e| e.object == Some(index))
    }
}

/// A shading point as light sampling sees it.
#[derive(Clone, Copy)]
pub(super) struct ShadingPoint<'b> {
    pub(super) p: DVec4,
    /// The shading normal on the viewer's side.
    pub(super) n: DVec4,
    /// Towards the viewer.
    pub(super) wo: DVec4,
    pub(super) bsdf: &'b Bsdf,
}

/// Veach's power heuristic with one sample of each strategy.
pub(super) fn power_heuristic(f: f64, g: f64) -> f64 {
    let (f2, g2) = (f * f, g * g);
    if f2 + g2 > 0.0 { f2 / (f2 + g2) } else { 0.0 }
}

impl Integrator for PathTracer<'_> {
    fn radiance(&self, primary: &Ray, stream: &mut SampleStream, stats: &mut TraceStats) -> Rgb {
        let mut radiance = Rgb::BLACK;
        let mut beta = Rgb::new(1.0, 1.0, 1.0);
        let mut ray = *primary;
        let mut last: LastScatter = None;
        let mut smooth = 0;
        for bounce in 0..MAX_PATH_LENGTH {
            // Each bounce draws from its own Sobol dimensions (sampling.rs).
            stream.begin_bounce(bounce);
            stats.rays += 1;
            // In a quotient space the ray comes back carried into the
            // domain, `travelled` along it.
            let traced = self.scene.trace(&ray, T_MIN);
            ray = traced.ray;
            let travelled = traced.travelled;
            let found = match traced.nearest {
                Nearest::Failure => {
                    stats.failures += 1;
                    return self.scene.background;
                }
                Nearest::Miss => None,
                Nearest::Hit(hit, index) => Some((hit, index)),
            };
            let scene_t = found.as_ref().map_or(f64::INFINITY, |(h, _)| h.t);
            if let Some((k, t)) = self.light_hit(&ray, scene_t) {
                let beta_fogged = self.fogged(&mut radiance, beta, t);
                radiance +=
                    beta_fogged.tint(self.emitters[k].radiance) * self.emission_weight(k, last);
                break;
            }
            // Where a walk in a space gave up, the space's average for the
            // rest of the way: its parts' glow under the surround, and what
            // lies beyond through its openness (`space_fill.rs`).
            if let Some((m, open, at)) = self.scene.beyond_space(&traced) {
                let beta_fogged = self.fogged(&mut radiance, beta, at);
                radiance += beta_fogged.tint(m.emission + open.tint(self.scene.leaving(&ray)));
                break;
            }
            let Some((hit, index)) = found else {
                radiance += beta.tint(self.scene.leaving(&ray));
                break;
            };
            beta = self.fogged(&mut radiance, beta, travelled + hit.t);
            let p = on_hyperboloid(hit.point);
            let d = ray.tangent_arriving_at(hit.t, p);
            if !(is_unit(d) && is_unit(hit.normal) && is_unit(hit.shading)) {
                stats.failures += 1;
                return self.scene.background;
            }
            let object = &self.scene.objects[index];
            let m = &self.scene.materials[object.material_of(&hit)];
            if !m.emission.is_black() {
                let w = match self.emitter_of(index) {
                    Some(k) => self.emission_weight(k, last),
                    None => self.face_weight(index, &hit, last),
                };
                radiance += beta.tint(m.emission) * w;
            }
            // Beyond a honeycomb's horizon the path ends: what lies behind
            // arrives through the share of the way left open
            // (`horizon_fill.rs`).
            if let Some(open) = object.open_beyond(&hit) {
                radiance += beta.tint(open.tint(self.scene.leaving(&ray)));
                break;
            }
            let entering = lorentz::dot(d, hit.normal) < 0.0;
            // The path segment just traced ran inside this object when it
            // leaves by this hit: absorbing glass filters it.
            let sheet = object.parts.is_some();
            if !sheet && !entering && !m.absorption.is_black() {
                beta = beta.tint(absorbed(m, travelled + hit.t));
            }
            let n = if entering { hit.shading } else { -hit.shading };
            let wo = -d;
            let (_, diffuse) = reflectances(object, m, &hit);
            let bsdf = Bsdf::new(m, diffuse);
            let mut total = 0.0;
            if bsdf.is_smooth() {
                let at = ShadingPoint {
                    p,
                    n,
                    wo,
                    bsdf: &bsdf,
                };
                let (light, sum) = self.direct(&at, index, stream, stats);
                radiance += beta.tint(light);
                total = sum;
                smooth += 1;
                if smooth >= self.smooth_vertices {
                    break;
                }
            }
            stream.seek(3);
            let u = [stream.next_unit(), stream.next_unit(), stream.next_unit()];
            let Some(scatter) = bsdf.sample(p, n, hit.normal, entering, wo, u) else {
                break;
            };
            beta = beta.tint(scatter.weight);
            // A tinted sheet (a honeycomb's face) filters what crosses it.
            if sheet && scatter.passed_through {
                beta = beta.tint(sheet_filter(m, lorentz::dot(d, hit.normal)));
            }
            if !scatter.passed_through {
                last = scatter.pdf.map(|pdf_bsdf| Scattered {
                    from: p,
                    n,
                    on: index,
                    pdf_bsdf,
                    total,
                });
            }
            ray = Ray {
                origin: p,
                dir: scatter.dir,
            };
            // Survival in proportion to the throughput left: a path that
            // carries all its light on (a perfect mirror) is never cut,
            // and MAX_PATH_LENGTH bounds it.
            let q = beta.channels().into_iter().fold(0.0, f64::max);
            if bounce + 1 >= ROULETTE_AFTER && q < 1.0 {
                stream.seek(6);
                if !(stream.next_unit() < q) {
                    break;
                }
                beta = beta * (1.0 / q);
            }
        }
        if radiance.is_finite() {
            radiance
        } else {
            stats.failures += 1;
            self.scene.background
        }
    }
}

impl PathTracer<'_> {
    /// What absorbing objects let through of the shadow segment from `p`
    /// along `dir` to distance `t_max` (white in a scene without any).
    pub(super) fn filtered(&self, p: DVec4, dir: DVec4, t_max: f64) -> Rgb {
        if self.scene.absorbing().is_empty() {
            return Rgb::new(1.0, 1.0, 1.0);
        }
        self.scene
            .absorption_along(&Ray { origin: p, dir }, T_MIN, t_max)
    }

    /// Fog over a segment of length `s`: the fog colour it adds to
    /// `radiance` and the throughput left for what lies beyond (the same
    /// depth cue as Whitted's, `docs/rendering.md#fog`).
    fn fogged(&self, radiance: &mut Rgb, beta: Rgb, s: f64) -> Rgb {
        match &self.scene.fog {
            Some(fog) => {
                let keep = (-s / fog.distance).exp();
                *radiance += beta.tint(fog.color) * (-(-s / fog.distance).exp_m1());
                beta * keep
            }
            None => beta,
        }
    }
}

/// The unit normal `m` of the h-plane through a geodesic triangle (`<x, m>
/// = 0` on it), or `None` for a degenerate one. Formed from the edge
/// differences, which keeps the cross product well conditioned.
pub(super) fn plane_normal(v: [DVec4; 3]) -> Option<DVec4> {
    let m = lorentz::orthogonal_complement(v[0], v[1] - v[0], v[2] - v[0]);
    let len = lorentz::norm(m);
    (len > 0.0 && len.is_finite()).then(|| m / len)
}
