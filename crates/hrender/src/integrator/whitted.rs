//! Whitted ray tracing with the thesis's Phong model and hyperbolic
//! attenuation (docs/rendering.md "Light"; thesis Eq. 4, 7 and 9):
//! `I = k_a I_a + sum_i S_i f_att(r_i) (k_d L_d cos(theta) + k_s L_s cos^n(alpha)) + k_r I_r + k_t I_t`,
//! with point lights, spherical area lights (soft shadows), fog, and shadow
//! rays that pass through glass by its transmission.

use std::f64::consts::PI;

use hgeom::HSphere;
use hgeom::Ray;
use hgeom::glam::DVec4;
use hgeom::lorentz::{self, Separation};
use hgeom::ray::refract;

use crate::absorption::{absorbed, sheet_filter};
use hscene_ir::{Material, Rgb};

use super::Integrator;
use crate::fog::through_fog;
use crate::light_sampling::VisibleCap;
use crate::material::{Shading, reflectances};
use crate::ray_budget::RayBudget;
use crate::sampling::SampleStream;
use crate::scene::{Nearest, PreparedLight, PreparedScene, T_MIN};
use crate::space_walk::Traced;
use crate::tangent::{is_unit, mirrored, renormalize};
use crate::trace_stats::TraceStats;
use hgeom::on_hyperboloid;

/// Rays whose weight in the final pixel falls below this are not traced.
const MIN_WEIGHT: f64 = 1e-3;

/// Whitted's integrator over a prepared scene.
pub struct Whitted<'s> {
    scene: &'s PreparedScene,
    /// The area lights' spheres and their radiance: seen directly and in
    /// mirrors (a point light has no surface to see).
    visible: Vec<(HSphere, Rgb)>,
}

impl Integrator for Whitted<'_> {
    /// The recursion from the primary ray, its ray tree bounded by a
    /// [`RayBudget`]. Area lights draw their sample points from `stream`;
    /// point lights draw nothing.
    fn radiance(&self, ray: &Ray, stream: &mut SampleStream, stats: &mut TraceStats) -> Rgb {
        let mut budget = RayBudget::default();
        let c = self.trace(ray, 0, 1.0, &mut budget, stream, stats);
        stats.cut_trees += u64::from(budget.was_cut());
        if c.is_finite() {
            c
        } else {
            stats.failures += 1;
            self.scene.background
        }
    }
}

/// Whitted's shadow rays pass through glass, dimmed by its transmission
/// coefficient and not bent.
fn passes(m: &Material) -> f64 {
    m.transmission
}

impl<'s> Whitted<'s> {
    /// The integrator over `scene`.
    pub fn new(scene: &'s PreparedScene) -> Whitted<'s> {
        let visible = scene
            .lights
            .iter()
            .filter_map(|l| Some((l.sphere()?, l.radiance())))
            .collect();
        Whitted { scene, visible }
    }

    /// The radiance of the nearest area light the ray sees before `t_max`,
    /// and where: from outside only, since a light's emission faces
    /// outward (a point inside the sphere is not lit by it either).
    fn light_seen(&self, ray: &Ray, t_max: f64) -> Option<(Rgb, f64)> {
        let mut best: Option<(Rgb, f64)> = None;
        for (sphere, radiance) in &self.visible {
            let limit = best.map_or(t_max, |b| b.1);
            if let Some(hit) = sphere.intersect(ray, T_MIN, limit)
                && lorentz::dot(ray.tangent_at(hit.t), hit.normal) < 0.0
            {
                best = Some((*radiance, hit.t));
            }
        }
        best
    }

    /// One ray of the tree, `depth` bounces from the eye and weighing
    /// `weight` in the pixel.
    fn trace(
        &self,
        ray: &Ray,
        depth: u32,
        weight: f64,
        budget: &mut RayBudget,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> Rgb {
        stats.rays += 1;
        // In a quotient space the ray comes back carried into the domain,
        // `travelled` along: everything after is on the carried ray.
        let traced = self.scene.trace(ray, T_MIN);
        let (found, ray, travelled) = (traced.nearest, &traced.ray, traced.travelled);
        // An area light nearer than what the ray meets is what it sees.
        if !self.visible.is_empty() {
            let t_max = match &found {
                Nearest::Hit(hit, _) => hit.t,
                _ => f64::INFINITY,
            };
            if let Some((radiance, t)) = self.light_seen(ray, t_max) {
                return match &self.scene.fog {
                    Some(fog) => through_fog(fog, radiance, t),
                    None => radiance,
                };
            }
        }
        let (hit, index) = match found {
            // Where a walk in a space gave up, the space's average
            // appearance for the rest of the way (`space_fill.rs`).
            Nearest::Miss => {
                return self
                    .beyond_space(&traced)
                    .unwrap_or_else(|| self.scene.leaving(ray));
            }
            Nearest::Failure => {
                stats.failures += 1;
                return self.scene.background;
            }
            Nearest::Hit(hit, index) => (hit, index),
        };
        let object = &self.scene.objects[index];
        // PreparedScene::new checked every material index.
        let m = &self.scene.materials[object.material_of(&hit)];
        // Each bounce starts on the hyperboloid, so the rounding of one
        // segment is not carried into the next (`tangent.rs`).
        let p = on_hyperboloid(hit.point);
        let d = ray.tangent_arriving_at(hit.t, p);
        // The hyperboloid loses unit tangent vectors far from the eye (its
        // f64 range ends near distance 19, docs/geometry.md section 16). Along a ray the error of
        // the invariants grows like `1e-16 cosh^2(s) cosh^2(t)` for an origin
        // at distance `s` from the eye and arc length `t`, so long secondary
        // rays from far points lose them sooner (s + t near 17 costs 1 %).
        // Shading with such vectors would be silent garbage (cosines far
        // above 1): count it as a numeric failure instead.
        if !(is_unit(d) && is_unit(hit.normal) && is_unit(hit.shading)) {
            stats.failures += 1;
            return self.scene.background;
        }
        let entering = lorentz::dot(d, hit.normal) < 0.0;
        // An object drawn in several materials (a honeycomb) is sheets,
        // with no inside: its absorption acts per crossing.
        let sheet = object.parts.is_some();
        // The normal on the side the ray came from, for shading.
        let n = if entering { hit.normal } else { -hit.normal };
        // A smoothed mesh's interpolated normal lights the surface; it is
        // turned to the ray's side with the geometric normal, which alone
        // decides sides, reflections and refractions (docs/rendering.md).
        let lit_normal = if entering { hit.shading } else { -hit.shading };
        let (ambient, diffuse) = reflectances(object, m, &hit);

        let mut color = ambient.tint(self.scene.ambient);
        // An emissive surface glows with its own radiance (nothing is added
        // for the usual black: the sums stay bit for bit what they were).
        if !m.emission.is_black() {
            color += m.emission;
        }
        // Beyond a honeycomb's horizon what lies behind it arrives through
        // the share of the way left open (`horizon_fill.rs`).
        if let Some(open) = object.open_beyond(&hit) {
            color += open.tint(self.scene.leaving(ray));
        }
        let view = -d;
        // A material without diffuse and specular terms ignores the lights:
        // skip their shadow rays.
        let lit = !(diffuse.is_black() && m.specular.is_black());
        let shading = Shading {
            p,
            n: lit_normal,
            view,
            diffuse,
            m,
        };
        for light in self.scene.lights.iter().filter(|_| lit) {
            if light.radius > 0.0 {
                color += self.area_light(light, &shading, stream, stats);
                continue;
            }
            // A light where this ray started (a headlight at the eye) sees
            // the hit along the ray itself, which met nothing before it:
            // its shadow ray would retrace that segment and find it clear.
            let seen = if at_ray_origin(light.position, ray) {
                Visibility::Clear
            } else {
                Visibility::Trace
            };
            color += self.point_light(light, light.position, seen, &shading, stats);
        }

        if depth < self.scene.max_depth {
            // A smoothed mesh bends its mirror and refracted rays by the
            // interpolated normal too, or glass looks like cut crystal
            // under smooth shading; where that normal would send a ray to
            // the wrong side of the true surface, the true normal decides.
            let bend = if hit.shading == hit.normal {
                n
            } else {
                lit_normal
            };
            let mirrored = mirrored(p, d, bend, n);
            let reflected = Ray {
                origin: p,
                dir: mirrored,
            };
            if m.reflection > 0.0 && weight * m.reflection > MIN_WEIGHT && budget.take() {
                let w = weight * m.reflection;
                color += self.trace(&reflected, depth + 1, w, budget, stream, stats) * m.reflection;
            }
            if m.transmission > 0.0 && weight * m.transmission > MIN_WEIGHT && budget.take() {
                let (n1, n2) = if entering {
                    (1.0, m.refraction)
                } else {
                    (m.refraction, 1.0)
                };
                // Total internal reflection sends the transmitted share along
                // the mirror ray (thesis Fig. 31).
                let dir = match refract(d, bend, n1, n2) {
                    Some(t) if lorentz::dot(t, n) < 0.0 => t,
                    Some(_) => refract(d, n, n1, n2).unwrap_or(reflected.dir),
                    None => reflected.dir,
                };
                let next = Ray {
                    origin: p,
                    dir: renormalize(p, dir),
                };
                let w = weight * m.transmission;
                let mut through = self.trace(&next, depth + 1, w, budget, stream, stats);
                // A tinted sheet (a honeycomb's face) filters what passes.
                if sheet {
                    through = through.tint(sheet_filter(m, lorentz::dot(d, hit.normal)));
                }
                color += through * m.transmission;
            }
        }
        // A ray leaving an absorbing object travelled `hit.t` inside it:
        // what it brings back is what is left after that much glass.
        if !sheet && !entering && !m.absorption.is_black() {
            color = color.tint(absorbed(m, travelled + hit.t));
        }
        match &self.scene.fog {
            Some(fog) => through_fog(fog, color, travelled + hit.t),
            None => color,
        }
    }

    /// What a ray whose walk in a quotient space gave up sees: the space's
    /// average ambient and emission over the rest of the way to distance
    /// 12, and through its openness what lies beyond, fogged to where the
    /// walk stopped (`space_fill.rs`). `None` for every other miss.
    fn beyond_space(&self, traced: &Traced) -> Option<Rgb> {
        let (m, open, at) = self.scene.beyond_space(traced)?;
        let color = m.ambient.tint(self.scene.ambient)
            + m.emission
            + open.tint(self.scene.leaving(&traced.ray));
        Some(match &self.scene.fog {
            Some(fog) => through_fog(fog, color, at),
            None => color,
        })
    }

    /// What `light`, emitting from `from` as a point source, gives the
    /// shading point: Phong times the shadow ray's transmittance times the
    /// attenuation `1/(4 pi sinh^2 r)` (the area of the hyperbolic sphere of
    /// radius r). Nothing when `from` is the shading point itself (no
    /// direction; the attenuation would be infinite) or lies behind the
    /// surface.
    fn point_light(
        &self,
        light: &PreparedLight,
        from: DVec4,
        seen: Visibility,
        at: &Shading<'_>,
        stats: &mut TraceStats,
    ) -> Rgb {
        if light.out_of_reach(at.p) {
            return Rgb::default();
        }
        let Some(to_light) = lorentz::unit_tangent_towards(at.p, from) else {
            return Rgb::default();
        };
        let cos_theta = lorentz::dot(at.n, to_light);
        if !(cos_theta > 0.0) {
            return Rgb::default();
        }
        // The distance, its tangent (the shadow ray's arc) and its sinh
        // (the attenuation) by algebra from one Lorentz separation.
        let apart = Separation::between(at.p, from);
        // An image of a light in a quotient space beyond its reach lights
        // nothing here: no shadow ray.
        let weight = light.fade(apart.distance());
        if weight == 0.0 {
            return Rgb::default();
        }
        let shadow = match seen {
            Visibility::Clear => 1.0,
            Visibility::Trace => {
                stats.rays += 1;
                self.scene.transmittance(
                    &Ray {
                        origin: at.p,
                        dir: to_light,
                    },
                    T_MIN,
                    apart.distance(),
                    apart.tanh(),
                    passes,
                )
            }
        };
        if shadow == 0.0 {
            return Rgb::default();
        }
        let f_att = weight / (4.0 * PI * light.falloff_sinh2(apart.sinh_squared()));
        let lit = at.phong(light.diffuse, light.specular, to_light, cos_theta.min(1.0))
            * (shadow * f_att);
        // Tinted glass between the point and the light filters it.
        if self.scene.absorbing().is_empty() {
            lit
        } else {
            let ray = Ray {
                origin: at.p,
                dir: to_light,
            };
            lit.tint(self.scene.absorption_along(&ray, T_MIN, apart.distance()))
        }
    }

    /// Direct light from a spherical area light: `samples` points on the
    /// cap the shading point sees ([`VisibleCap`]), each lit like a point
    /// light (own direction, attenuation, shadow ray), summed and weighted.
    /// A shading point inside the sphere receives nothing (the emission
    /// faces outward).
    fn area_light(
        &self,
        light: &PreparedLight,
        at: &Shading<'_>,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> Rgb {
        let Some(cap) = VisibleCap::of(light, at.p, stream) else {
            return Rgb::default();
        };
        let mut sum = Rgb::default();
        for k in 0..light.samples {
            let q = cap.point(k, stream);
            // A sample that coincides with the shading point (a point on
            // the light's surface, to rounding) lights nothing there, like a
            // point light at the hit.
            sum += self.point_light(light, q, Visibility::Trace, at, stats);
        }
        sum * cap.weight()
    }
}

/// Whether a point light's shadow ray must be traced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Visibility {
    /// The light is at the start of the ray that found the shading point.
    Clear,
    Trace,
}

/// True if `light` lies within [`T_MIN`] of the ray's start. For two points
/// of the hyperboloid `<L - O, L - O> = 4 sinh²(d/2)`, accurate for near
/// points where `-<L,O> = cosh d` loses `d` to cancellation.
fn at_ray_origin(light: DVec4, ray: &Ray) -> bool {
    let delta = light - ray.origin;
    lorentz::dot(delta, delta) < T_MIN * T_MIN
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::Point;
    use hgeom::glam::DVec3;

    /// A light within `T_MIN` of a ray's start is at it; one farther off
    /// is not (`<L-O,L-O>` keeps the distance where `cosh d` rounds to 1).
    #[test]
    fn lights_at_the_ray_origin_are_found_to_t_min() {
        let eye = Point::from_coords(DVec3::ZERO).unwrap().to_hyperboloid();
        let ray = Ray {
            origin: eye,
            dir: DVec4::new(0.0, 0.0, 1.0, 0.0),
        };
        let light = |x: f64| {
            Point::from_coords(DVec3::new(x, 0.0, 0.0))
                .unwrap()
                .to_hyperboloid()
        };
        assert!(at_ray_origin(eye, &ray));
        // Ball x is distance 2x near the origin.
        assert!(at_ray_origin(light(0.4e-9), &ray));
        assert!(!at_ray_origin(light(0.6e-9), &ray));
        assert!(!at_ray_origin(light(0.1), &ray));
    }

    /// A headlight (the light at the eye) lights every primary hit it faces:
    /// its shadow ray would retrace the primary ray, which met nothing
    /// before the hit, so it is not traced. The image is the one traced
    /// shadow rays give with the light a hair (1e-7) off the eye, through
    /// a honeycomb, a glass ball and a mirror bounce.
    #[test]
    fn headlight_shadows_are_known_clear() {
        let source = |light: &str| {
            format!(
                "Globals {{ resolution = (48, 48); to = (0.1, 0.13, 0.4); fov = 90; \
                 recursion_depth = 1; ambient = (0.2, 0.2, 0.2); }}\n\
                 BRDFs {{ edge: ambient = (0.4, 0.3, 0.2), diffuse = (0.9, 0.75, 0.45), \
                 specular = (1, 1, 1), shininess = 40, alpha = 0.3; \
                 glass: ambient = (0.1, 0.2, 0.3), diffuse = (0.2, 0.4, 0.6), \
                 specular = (1, 1, 1), shininess = 60, trans = 0.5, refraction = 1.3; }}\n\
                 Lights {{ {light}, (6, 6, 6), (4, 4, 4); }}\n\
                 Objects {{ Honeycomb {{4,3,5}}, #edge, edges = 0.05; \
                 Sphere (0.05, 0.08, 0.3), 0.08, #glass; }}"
            )
        };
        let draw = |light: &str| {
            let compiled = hscene_lang::compile(&source(light));
            let scene = compiled.scene.expect("the test scene compiles");
            crate::render(&scene, &crate::RenderOptions::default(), &|_| {})
                .expect("the test scene renders")
        };
        let headlight = draw("(0, 0, 0)");
        let traced = draw("(1e-7, 0, 0)");
        assert!(headlight.stats.rays < traced.stats.rays);
        let mut lit = 0;
        for (h, t) in headlight.image.pixels().iter().zip(traced.image.pixels()) {
            for (a, b) in h.iter().zip(t) {
                assert!((a - b).abs() <= 1e-5 * b.abs().max(1.0), "{h:?} {t:?}");
            }
            lit += usize::from(h[0] > 0.3);
        }
        assert!(lit > 100, "only {lit} lit pixels");
    }
}
