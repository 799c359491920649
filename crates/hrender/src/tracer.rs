//! Whitted ray tracing with the Phong model and hyperbolic attenuation
//! (docs/rendering.md "Light"; thesis Eq. 4, 7 and 9), solid checker textures and spherical
//! area lights (soft shadows).

use std::f64::consts::{PI, TAU};

use hgeom::glam::DVec4;
use hgeom::lorentz::{self, Separation};
use hgeom::ray::{reflect, refract};
use hgeom::{Hit, Point, Ray, fermi_coordinates};
use hscene_lang::ir::{Material, Pattern, Rgb, Texture};

use crate::color::Color;
use crate::fog::through_fog;
use crate::ray_budget::RayBudget;
use crate::sampling::SampleStream;
use crate::scene::{Nearest, PreparedLight, PreparedObject, PreparedScene};

/// Secondary rays ignore hits closer than this (hyperbolic length), so a ray
/// leaving a surface does not hit the same surface at its own origin.
pub const T_MIN: f64 = 1e-9;

/// How far `<v,v>` may stray from 1 before a tangent vector counts as lost.
const UNIT_TOLERANCE: f64 = 1e-2;

/// Rays whose weight in the final pixel falls below this are not traced.
const MIN_WEIGHT: f64 = 1e-3;

/// The golden ratio's fractional part: successive area-light samples turn
/// by this share of a full turn about the axis towards the shading point.
const GOLDEN_TURN: f64 = 0.618_033_988_749_894_8;

/// Per-ray outcome counters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Rays traced (primary, secondary, shadow).
    pub rays: u64,
    /// Numeric failures: rays or hits that were not finite, and shading
    /// results that were not finite. Each is replaced by the background and
    /// counted, never silently.
    pub failures: u64,
    /// Primary rays whose ray tree the [`RayBudget`] cut short.
    pub cut_trees: u64,
}

impl TraceStats {
    /// Sum two counters.
    pub fn merge(self, o: TraceStats) -> TraceStats {
        TraceStats {
            rays: self.rays + o.rays,
            failures: self.failures + o.failures,
            cut_trees: self.cut_trees + o.cut_trees,
        }
    }
}

/// Traces rays through a prepared scene.
pub struct Tracer<'s> {
    scene: &'s PreparedScene,
}

impl<'s> Tracer<'s> {
    /// A tracer over the scene.
    pub fn new(scene: &'s PreparedScene) -> Tracer<'s> {
        Tracer { scene }
    }

    /// Radiance along a primary ray, with area lights sampled from a fixed
    /// stream ([`Tracer::primary_sampled`] takes the pixel sample's own).
    pub fn primary(&self, ray: &Ray, stats: &mut TraceStats) -> Color {
        self.primary_sampled(ray, &mut SampleStream::new(0), stats)
    }

    /// Radiance along a primary ray; the points sampled on area lights are
    /// drawn from `stream` (the renderer passes
    /// [`Sampler::stream`](crate::Sampler::stream) of the pixel sample, so
    /// the image does not depend on the thread count). Point lights draw
    /// nothing.
    pub fn primary_sampled(
        &self,
        ray: &Ray,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> Color {
        let mut budget = RayBudget::default();
        let c = self.trace(ray, 0, 1.0, &mut budget, stream, stats);
        stats.cut_trees += u64::from(budget.was_cut());
        if c.is_finite() {
            c
        } else {
            stats.failures += 1;
            self.scene.background.into()
        }
    }

    /// Whitted recursion:
    /// `I = k_a I_a + sum_i S_i f_att(r_i) (k_d L_d cos(theta) + k_s L_s cos^n(alpha)) + k_r I_r + k_t I_t`.
    fn trace(
        &self,
        ray: &Ray,
        depth: u32,
        weight: f64,
        budget: &mut RayBudget,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> Color {
        stats.rays += 1;
        let (hit, index) = match self.scene.nearest(ray, T_MIN) {
            Nearest::Miss => return self.leaving(),
            Nearest::Failure => {
                stats.failures += 1;
                return self.scene.background.into();
            }
            Nearest::Hit(hit, index) => (hit, index),
        };
        let object = &self.scene.objects[index];
        // PreparedScene::new checked every material index.
        let m = &self.scene.materials[object.material_of(hit.part)];
        let d = ray.tangent_at(hit.t);
        // The hyperboloid loses unit tangent vectors far from the eye (its
        // f64 range ends near distance 19, docs/geometry.md section 16). Along a ray the error of
        // the invariants grows like `1e-16 cosh^2(s) cosh^2(t)` for an origin
        // at distance `s` from the eye and arc length `t`, so long secondary
        // rays from far points lose them sooner (s + t near 17 costs 1 %).
        // Shading with such vectors would be silent garbage (cosines far
        // above 1): count it as a numeric failure instead.
        if !(is_unit(d) && is_unit(hit.normal) && is_unit(hit.shading)) {
            stats.failures += 1;
            return self.scene.background.into();
        }
        let entering = lorentz::dot(d, hit.normal) < 0.0;
        // The normal on the side the ray came from, for shading.
        let n = if entering { hit.normal } else { -hit.normal };
        // A smoothed mesh's interpolated normal lights the surface; it is
        // turned to the ray's side with the geometric normal, which alone
        // decides sides, reflections and refractions (docs/rendering.md).
        let lit_normal = if entering { hit.shading } else { -hit.shading };
        let p = hit.point;
        // A texture replaces the ambient and diffuse reflectances in part of
        // the surface; only textured materials pay for finding out where.
        let (ambient, diffuse) = match &m.texture {
            None => (m.ambient, m.diffuse),
            Some(t) => texture_colours(object, m, t, &hit),
        };

        let mut color = Color::from(ambient).tint(self.scene.ambient.into());
        let view = -d;
        // A material without diffuse and specular terms ignores the lights:
        // skip their shadow rays.
        let lit = [diffuse, m.specular]
            .iter()
            .any(|c| c.r != 0.0 || c.g != 0.0 || c.b != 0.0);
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
            let reflected = Ray {
                origin: p,
                dir: renormalize(p, reflect(d, n)),
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
                let dir = refract(d, n, n1, n2).unwrap_or(reflected.dir);
                let next = Ray {
                    origin: p,
                    dir: renormalize(p, dir),
                };
                let w = weight * m.transmission;
                color += self.trace(&next, depth + 1, w, budget, stream, stats) * m.transmission;
            }
        }
        match &self.scene.fog {
            Some(fog) => through_fog(fog, color, hit.t),
            None => color,
        }
    }

    /// What a ray that leaves the scene brings: the fog colour in fog,
    /// else the background.
    fn leaving(&self) -> Color {
        match &self.scene.fog {
            Some(fog) => fog.color.into(),
            None => self.scene.background.into(),
        }
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
    ) -> Color {
        let Some(to_light) = lorentz::unit_tangent_towards(at.p, from) else {
            return Color::default();
        };
        let cos_theta = lorentz::dot(at.n, to_light);
        if !(cos_theta > 0.0) {
            return Color::default();
        }
        // The distance, its tangent (the shadow ray's arc) and its sinh
        // (the attenuation) by algebra from one Lorentz separation.
        let apart = Separation::between(at.p, from);
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
                )
            }
        };
        if shadow == 0.0 {
            return Color::default();
        }
        let f_att = 1.0 / (4.0 * PI * apart.sinh_squared());
        at.phong(light, to_light, cos_theta.min(1.0)) * (shadow * f_att)
    }

    /// Direct light from a spherical area light: the light is the h-sphere
    /// of radius `r` about its position, each surface element of which
    /// emits its share of the light's power uniformly into its outer
    /// half-space. Only the cap visible from the shading point (angle `phi`
    /// at the centre with `cos phi >= tanh r / tanh D`, `D` the distance of
    /// the centre) can light it; `samples` points uniform in area on that
    /// cap, stratified in `cos phi` and turned by the golden angle, each
    /// lit like a point light (own direction, attenuation, shadow ray),
    /// averaged and weighted by the cap's share of the light's power,
    /// `1 - tanh r / tanh D`. The estimate is unbiased, gives a surface
    /// facing the light exactly the point light's `1/(4 pi sinh^2 D)`, and
    /// tends to the point light as `r -> 0`. A shading point inside the
    /// sphere receives nothing (the emission faces outward).
    /// `docs/rendering.md` has the derivation.
    fn area_light(
        &self,
        light: &PreparedLight,
        at: &Shading<'_>,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> Color {
        let centre = light.position;
        let r = light.radius;
        // At the centre itself there is no direction: the point is inside.
        let Some((towards, dist)) = lorentz::direction_towards(centre, at.p) else {
            return Color::default();
        };
        if !(dist > r) {
            return Color::default();
        }
        // 1 - tanh r / tanh D, written without cancellation.
        let cap = (dist - r).sinh() / (dist.sinh() * r.cosh());
        let (b1, b2) = tangent_basis(centre, towards);
        let (sinh_r, cosh_r) = (r.sinh(), r.cosh());
        let count = f64::from(light.samples);
        let turn = stream.next_unit();
        let mut sum = Color::default();
        for k in 0..light.samples {
            let k = f64::from(k);
            // 1 - cos(phi), uniform over the cap (area on the sphere is
            // proportional to 1 - cos(phi)), one sample per stratum.
            let h = (k + stream.next_unit()) / count * cap;
            let (cos_phi, sin_phi) = (1.0 - h, (h * (2.0 - h)).sqrt());
            let psi = TAU * (turn + k * GOLDEN_TURN).fract();
            let u = towards * cos_phi + (b1 * psi.cos() + b2 * psi.sin()) * sin_phi;
            let q = cosh_r * centre + sinh_r * u;
            // A sample that coincides with the shading point (a point on
            // the light's surface, to rounding) lights nothing there, like a
            // point light at the hit.
            sum += self.point_light(light, q, Visibility::Trace, at, stats);
        }
        sum * (cap / count)
    }
}

/// What the lights see of a shading point.
struct Shading<'m> {
    /// The hit point.
    p: DVec4,
    /// The normal on the side the ray came from.
    n: DVec4,
    /// Towards the eye (the reversed ray).
    view: DVec4,
    /// The diffuse reflectance there (the texture's or the material's).
    diffuse: Rgb,
    /// The material (specular reflectance and exponent).
    m: &'m Material,
}

impl Shading<'_> {
    /// Diffuse plus specular Phong terms for light arriving from the unit
    /// tangent `to_light` with `cos_theta = <n, to_light> > 0`, before
    /// attenuation and shadowing.
    #[inline]
    fn phong(&self, light: &PreparedLight, to_light: DVec4, cos_theta: f64) -> Color {
        let mirrored = reflect(-to_light, self.n);
        // A cosine of unit vectors: at most 1 up to the rounding that
        // `is_unit` bounds; keep rounding from being raised to a high
        // Phong exponent.
        let cos_alpha = lorentz::dot(mirrored, self.view).clamp(0.0, 1.0);
        let diffuse = Color::from(self.diffuse).tint(light.diffuse.into()) * cos_theta;
        let specular = Color::from(self.m.specular).tint(light.specular.into())
            * cos_alpha.powf(self.m.shininess);
        diffuse + specular
    }
}

/// The ambient and diffuse reflectances of a textured material at a hit:
/// the hit taken to the object's local space, its Fermi coordinates `c`
/// ([`fermi_coordinates`]), the cell `floor(c / scale)`; cells with an odd
/// sum of indices take the texture's colours, the others the material's.
/// A hit whose local point f64 cannot represent keeps the material's own
/// colours (it is drawn, only not patterned).
fn texture_colours(object: &PreparedObject, m: &Material, t: &Texture, hit: &Hit) -> (Rgb, Rgb) {
    let own = (m.ambient, m.diffuse);
    let Some(local) = Point::from_hyperboloid(hit.point).map(|w| object.to_local.apply(&w)) else {
        return own;
    };
    if !local.is_representable() {
        return own;
    }
    match t.pattern {
        Pattern::Checker => {
            if checker_is_odd(fermi_coordinates(&local), t.scale) {
                (t.ambient, t.diffuse)
            } else {
                own
            }
        }
    }
}

/// True when the checker cell `floor(c / scale)` of local Fermi coordinates
/// `c` has an odd sum of indices. Indices are exact integers in f64 below
/// 2^53 (beyond, every f64 is even); a non-finite cell counts as even.
#[inline]
fn checker_is_odd(c: hgeom::glam::DVec3, scale: f64) -> bool {
    let cell = (c / scale).floor();
    (cell.x + cell.y + cell.z).rem_euclid(2.0) == 1.0
}

/// Two unit tangents at `c` that complete the unit tangent `e` to a Lorentz
/// orthonormal basis of the tangent space. The first is a coordinate axis
/// projected into the tangent space and away from `e` (the axis that keeps
/// most of its length, so the projection never degenerates); the second is
/// orthogonal to `c`, `e` and the first.
fn tangent_basis(c: DVec4, e: DVec4) -> (DVec4, DVec4) {
    let project = |a: DVec4| {
        let v = a + lorentz::dot(c, a) * c;
        v - lorentz::dot(e, v) * e
    };
    let mut b1 = project(DVec4::X);
    for a in [DVec4::Y, DVec4::Z] {
        let v = project(a);
        if lorentz::dot(v, v) > lorentz::dot(b1, b1) {
            b1 = v;
        }
    }
    let b1 = b1 / lorentz::norm(b1);
    let b2 = lorentz::orthogonal_complement(c, e, b1);
    (b1, b2 / lorentz::norm(b2))
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

/// True if the tangent vector's Lorentz norm is 1 up to a tolerance far
/// above the rounding of any resolvable vector (which grows like
/// `1e-16 cosh^2` of the distance from the eye: 3e-4 at distance 15).
#[inline]
fn is_unit(v: DVec4) -> bool {
    (lorentz::dot(v, v) - 1.0).abs() <= UNIT_TOLERANCE
}

/// Restore `<v,v> = 1`, `<p,v> = 0` after floating-point arithmetic on a
/// tangent vector, so rounding never accumulates along a path. A degenerate
/// input gives a non-finite ray, which the next trace counts as a failure.
fn renormalize(p: DVec4, v: DVec4) -> DVec4 {
    let t = v + lorentz::dot(p, v) * p;
    t / lorentz::norm(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;

    /// The checker uses the parity of the cell of the local Fermi
    /// coordinates: the middle of the cell at the origin is even (material
    /// colours), its neighbours along each axis odd, diagonal neighbours
    /// even again.
    #[test]
    fn checker_parity_is_that_of_the_fermi_cell() {
        let s = 0.3;
        let middle = |i: f64, j: f64, k: f64| {
            let c = fermi_coordinates(&hgeom::from_fermi_coordinates(
                (DVec3::new(i, j, k) + 0.5) * s,
            ));
            checker_is_odd(c, s)
        };
        assert!(!middle(0.0, 0.0, 0.0));
        assert!(middle(1.0, 0.0, 0.0) && middle(0.0, -1.0, 0.0) && middle(0.0, 0.0, 1.0));
        assert!(!middle(1.0, 1.0, 0.0) && !middle(-1.0, 0.0, 1.0));
        assert!(middle(1.0, 1.0, 1.0) && middle(-3.0, 2.0, 4.0));
        assert!(!checker_is_odd(DVec3::new(f64::NAN, 0.0, 0.0), s));
        assert!(!checker_is_odd(DVec3::splat(1e300), 1e-300));
    }

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

    /// The tangent basis is Lorentz orthonormal and tangent, also for a
    /// centre away from the origin and every direction.
    #[test]
    fn tangent_basis_is_orthonormal() {
        let centre = Point::at_distance_from_origin(DVec3::new(0.3, -1.0, 0.4), 2.5)
            .unwrap()
            .to_hyperboloid();
        for e3 in [DVec3::X, DVec3::Y, DVec3::Z, DVec3::new(1.0, 2.0, -0.5)] {
            let e =
                hgeom::ray::hyperboloid_direction(&Point::from_hyperboloid(centre).unwrap(), e3);
            let (b1, b2) = tangent_basis(centre, e);
            for (a, b, expect) in [
                (b1, b1, 1.0),
                (b2, b2, 1.0),
                (b1, b2, 0.0),
                (b1, e, 0.0),
                (b2, e, 0.0),
                (b1, centre, 0.0),
                (b2, centre, 0.0),
            ] {
                assert!((lorentz::dot(a, b) - expect).abs() < 1e-12, "{e3}");
            }
        }
    }
}
