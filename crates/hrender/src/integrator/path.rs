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
//! heuristic), next-event estimation to every point light, every
//! spherical emitter (area lights and emissive h-spheres, by the cone they
//! subtend) and every triangle of an emissive polygon or polyhedron (by
//! the spherical triangle it subtends), then one
//! direction from the material's lobes ([`Bsdf`]); Russian roulette after
//! three bounces (a path survives with the probability of its largest
//! throughput channel, when below 1), at most [`MAX_PATH_LENGTH`] bounces.

use hgeom::glam::DVec4;
use hgeom::lorentz::{self, Separation};
use hgeom::{HSphere, Ray};
use hscene_ir::Rgb;

use super::Integrator;
use crate::absorption::{absorbed, sheet_filter};
use crate::bsdf::{Bsdf, clear_transmission};
use crate::light_sampling::SphereCone;
use crate::material::reflectances;
use crate::sampling::SampleStream;
use crate::scene::{Nearest, PreparedScene, T_MIN};
use crate::spherical_triangle::SphericalTriangle;
use crate::tangent::is_unit;
use crate::trace_stats::TraceStats;
use hgeom::on_hyperboloid;

/// The most surfaces a path scatters from: far beyond where Russian
/// roulette ends paths in any scene that absorbs light at all.
pub const MAX_PATH_LENGTH: u32 = 64;

/// Bounces before Russian roulette may end a path.
const ROULETTE_AFTER: u32 = 3;

/// A spherical emitter: an area light, or an emissive h-sphere object.
struct SphereEmitter {
    centre: DVec4,
    radius: f64,
    /// The radiance it emits, from both sides.
    radiance: Rgb,
    /// The area light's own surface (an object's is in the scene).
    surface: Option<HSphere>,
    /// The object it is, for an emissive h-sphere object.
    object: Option<usize>,
}

/// An emissive object with flat faces (a polygon, a polyhedron).
struct FaceEmitter {
    object: usize,
    /// The radiance it emits, from both sides.
    radiance: Rgb,
    /// Its faces as geodesic triangles.
    triangles: Vec<[DVec4; 3]>,
}

/// The path integrator over a prepared scene.
pub struct PathTracer<'s> {
    scene: &'s PreparedScene,
    emitters: Vec<SphereEmitter>,
    faces: Vec<FaceEmitter>,
    /// Paths end at this many diffuse or glossy vertices (after light
    /// sampling there).
    smooth_vertices: u32,
}

/// What the last scattering vertex tells the next emitter hit: where it
/// was, the object it was on, and the density its smooth lobes drew the
/// direction with; `None` at the eye or after a mirror or a refraction,
/// which light sampling cannot reproduce.
type LastScatter = Option<(DVec4, usize, f64)>;

impl<'s> PathTracer<'s> {
    /// The integrator over `scene`: its spherical emitters gathered once.
    pub fn new(scene: &'s PreparedScene) -> PathTracer<'s> {
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
                faces.push(FaceEmitter {
                    object: index,
                    radiance: m.emission,
                    triangles: object.faces.clone(),
                });
            }
            if let (Some((centre, radius)), false) = (object.ball, m.emission.is_black()) {
                emitters.push(SphereEmitter {
                    centre,
                    radius,
                    radiance: m.emission,
                    surface: None,
                    object: Some(index),
                });
            }
        }
        PathTracer {
            scene,
            emitters,
            faces,
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

    /// The power-heuristic weight of emission from emitter `k` reached by
    /// a direction the last vertex's lobes drew.
    fn emission_weight(&self, k: usize, last: LastScatter) -> f64 {
        let Some((from, on, pdf_bsdf)) = last else {
            return 1.0;
        };
        let e = &self.emitters[k];
        // Light sampling skips the emitter a point lies on (`direct`).
        if e.object == Some(on) {
            return 1.0;
        }
        match SphereCone::new(from, e.centre, e.radius) {
            Some(cone) => power_heuristic(pdf_bsdf, cone.pdf()),
            None => 1.0,
        }
    }

    /// Light arriving at the shading point straight from the point lights,
    /// the spherical emitters and the emissive faces, reflected towards the
    /// viewer: next-event estimation.
    fn direct(
        &self,
        at: &ShadingPoint<'_>,
        own: usize,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> Rgb {
        let ShadingPoint { p, n, wo, bsdf } = *at;
        let mut sum = Rgb::BLACK;
        for light in self.scene.lights.iter().filter(|l| l.radius == 0.0) {
            if light.out_of_reach(p) {
                continue;
            }
            let Some(wi) = lorentz::unit_tangent_towards(p, light.position) else {
                continue;
            };
            let cos = lorentz::dot(n, wi);
            if !(cos > 0.0) {
                continue;
            }
            let apart = Separation::between(p, light.position);
            // An image beyond its reach (quotient spaces) lights nothing.
            let weight = light.fade(apart.distance());
            if weight == 0.0 {
                continue;
            }
            stats.rays += 1;
            let shadow = self.scene.transmittance(
                &Ray { origin: p, dir: wi },
                T_MIN,
                apart.distance(),
                apart.tanh(),
                clear_transmission,
            );
            if shadow == 0.0 {
                continue;
            }
            // A point light of colour Φ has radiant intensity Φ/4 (power
            // πΦ): a Lambertian surface of albedo ρ facing it reflects
            // exactly Whitted's `ρ Φ / (4π sinh² r)`; clear tinted glass on
            // the way filters it.
            let intensity = light.diffuse.tint(self.filtered(p, wi, apart.distance())) * 0.25;
            sum += bsdf.eval(n, wo, wi).tint(intensity)
                * (cos * shadow * weight / light.falloff_sinh2(apart.sinh_squared()));
        }
        for e in &self.emitters {
            let (u1, u2) = (stream.next_unit(), stream.next_unit());
            if e.object == Some(own) {
                continue;
            }
            let Some(cone) = SphereCone::new(p, e.centre, e.radius) else {
                continue;
            };
            let wi = cone.sample(u1, u2);
            sum += self.light_along(at, wi, cone.pdf(), e.radiance, stats, |ray| {
                self.emitter_distance(e, ray)
            });
        }
        // Emissive faces: one direction per triangle, drawn uniformly
        // from the spherical triangle of directions it fills.
        for e in self.faces.iter().filter(|e| e.object != own) {
            for tri in &e.triangles {
                let (u1, u2) = (stream.next_unit(), stream.next_unit());
                let Some(solid) = SphericalTriangle::new(p, *tri) else {
                    continue;
                };
                let wi = solid.sample(u1, u2);
                let pdf = 1.0 / solid.solid_angle();
                sum += self.light_along(at, wi, pdf, e.radiance, stats, |ray| {
                    self.scene.objects[e.object]
                        .intersect(ray, 0.0, f64::INFINITY)
                        .map(|h| h.t)
                });
            }
        }
        sum
    }

    /// What an emitter of `radiance` sends to `at` along the unit tangent
    /// `wi`, drawn by light sampling with density `pdf`, reflected towards
    /// the viewer: nothing below the surface; `surface` finds where the ray
    /// meets the emitter, and the shadow ray stops short of it; weighted
    /// against the lobes by the power heuristic.
    fn light_along(
        &self,
        at: &ShadingPoint<'_>,
        wi: DVec4,
        pdf: f64,
        radiance: Rgb,
        stats: &mut TraceStats,
        surface: impl FnOnce(&Ray) -> Option<f64>,
    ) -> Rgb {
        let cos = lorentz::dot(at.n, wi);
        if !(cos > 0.0) {
            return Rgb::BLACK;
        }
        let ray = Ray {
            origin: at.p,
            dir: wi,
        };
        let Some(t) = surface(&ray) else {
            return Rgb::BLACK;
        };
        let t_max = t - T_MIN;
        stats.rays += 1;
        let shadow = if t_max > T_MIN {
            self.scene
                .transmittance(&ray, T_MIN, t_max, t_max.tanh(), clear_transmission)
        } else {
            1.0
        };
        if shadow == 0.0 {
            return Rgb::BLACK;
        }
        let radiance = radiance.tint(self.filtered(at.p, wi, t_max));
        let w = power_heuristic(pdf, at.bsdf.pdf(at.n, at.wo, wi));
        at.bsdf.eval(at.n, at.wo, wi).tint(radiance) * (cos * shadow * w / pdf)
    }

    /// The power-heuristic weight of emission from the faces of object
    /// `index` at `point`, reached by a direction the last vertex's lobes
    /// drew: light sampling would have drawn it from the one triangle whose
    /// solid angle holds it.
    fn face_weight(&self, index: usize, point: DVec4, last: LastScatter) -> f64 {
        let Some((from, on, pdf_bsdf)) = last else {
            return 1.0;
        };
        let Some(e) = self.faces.iter().find(|e| e.object == index) else {
            return 1.0;
        };
        if on == index {
            return 1.0;
        }
        let Some(d) = lorentz::unit_tangent_towards(from, point) else {
            return 1.0;
        };
        e.triangles
            .iter()
            .filter_map(|tri| SphericalTriangle::new(from, *tri))
            .find(|solid| solid.contains(d))
            .map_or(1.0, |solid| {
                power_heuristic(pdf_bsdf, 1.0 / solid.solid_angle())
            })
    }

    /// Where `ray` meets emitter `e`'s sphere.
    fn emitter_distance(&self, e: &SphereEmitter, ray: &Ray) -> Option<f64> {
        match (&e.surface, e.object) {
            (Some(s), _) => s.intersect(ray, 0.0, f64::INFINITY).map(|h| h.t),
            (None, Some(o)) => self.scene.objects[o]
                .intersect(ray, 0.0, f64::INFINITY)
                .map(|h| h.t),
            (None, None) => None,
        }
    }

    /// Radiance brought by a ray that leaves the scene: the fog colour in
    /// fog, else the sky where the ray ends, else the background.
    fn leaving(&self, ray: &Ray) -> Rgb {
        match &self.scene.fog {
            Some(fog) => fog.color,
            None => self
                .scene
                .sky_radiance(ray)
                .unwrap_or(self.scene.background),
        }
    }

    /// The emitter that is object `index`, if it is one.
    fn emitter_of(&self, index: usize) -> Option<usize> {
        self.emitters.iter().position(|e| e.object == Some(index))
    }
}

/// A shading point as light sampling sees it.
#[derive(Clone, Copy)]
struct ShadingPoint<'b> {
    p: DVec4,
    /// The shading normal on the viewer's side.
    n: DVec4,
    /// Towards the viewer.
    wo: DVec4,
    bsdf: &'b Bsdf,
}

/// Veach's power heuristic with one sample of each strategy.
fn power_heuristic(f: f64, g: f64) -> f64 {
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
            let Some((hit, index)) = found else {
                radiance += beta.tint(self.leaving(&ray));
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
                    None => self.face_weight(index, hit.point, last),
                };
                radiance += beta.tint(m.emission) * w;
            }
            // Beyond a honeycomb's horizon the path ends: what lies behind
            // arrives through the share of the way left open
            // (`horizon_fill.rs`).
            if let Some(open) = object.open_beyond(&hit) {
                radiance += beta.tint(open.tint(self.leaving(&ray)));
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
            if bsdf.is_smooth() {
                let at = ShadingPoint {
                    p,
                    n,
                    wo,
                    bsdf: &bsdf,
                };
                radiance += beta.tint(self.direct(&at, index, stream, stats));
                smooth += 1;
                if smooth >= self.smooth_vertices {
                    break;
                }
            }
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
                last = scatter.pdf.map(|pdf| (p, index, pdf));
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
    fn filtered(&self, p: DVec4, dir: DVec4, t_max: f64) -> Rgb {
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
