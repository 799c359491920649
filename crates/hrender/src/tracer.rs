//! Whitted ray tracing with the Phong model and hyperbolic attenuation
//! (SPEC 3.3, thesis Eq. 4, 7 and 9).

use std::f64::consts::PI;

use hgeom::Ray;
use hgeom::glam::DVec4;
use hgeom::lorentz;
use hgeom::ray::{reflect, refract};

use crate::color::Color;
use crate::scene::{Nearest, PreparedScene};

/// Secondary rays ignore hits closer than this (hyperbolic length), so a ray
/// leaving a surface does not hit the same surface at its own origin.
pub const T_MIN: f64 = 1e-9;

/// How far `<v,v>` may stray from 1 before a tangent vector counts as lost.
const UNIT_TOLERANCE: f64 = 1e-2;

/// Rays whose weight in the final pixel falls below this are not traced.
const MIN_WEIGHT: f64 = 1e-3;

/// Per-ray outcome counters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Rays traced (primary, secondary, shadow).
    pub rays: u64,
    /// Numeric failures: rays or hits that were not finite, and shading
    /// results that were not finite. Each is replaced by the background and
    /// counted, never silently.
    pub failures: u64,
}

impl TraceStats {
    /// Sum two counters.
    pub fn merge(self, o: TraceStats) -> TraceStats {
        TraceStats {
            rays: self.rays + o.rays,
            failures: self.failures + o.failures,
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

    /// Radiance along a primary ray.
    pub fn primary(&self, ray: &Ray, stats: &mut TraceStats) -> Color {
        let c = self.trace(ray, 0, 1.0, stats);
        if c.is_finite() {
            c
        } else {
            stats.failures += 1;
            self.scene.background.into()
        }
    }

    /// Whitted recursion:
    /// `I = k_a I_a + sum_i S_i f_att(r_i) (k_d L_d cos(theta) + k_s L_s cos^n(alpha)) + k_r I_r + k_t I_t`.
    fn trace(&self, ray: &Ray, depth: u32, weight: f64, stats: &mut TraceStats) -> Color {
        stats.rays += 1;
        let (hit, index) = match self.scene.nearest(ray, T_MIN) {
            Nearest::Miss => return self.scene.background.into(),
            Nearest::Failure => {
                stats.failures += 1;
                return self.scene.background.into();
            }
            Nearest::Hit(hit, index) => (hit, index),
        };
        let object = &self.scene.objects[index];
        // PreparedScene::new checked every material index.
        let m = &self.scene.materials[object.material];
        let d = ray.tangent_at(hit.t);
        // The hyperboloid loses unit tangent vectors far from the eye (SPEC
        // 2.3: its f64 range ends near distance 19). Along a ray the error of
        // the invariants grows like `1e-16 cosh^2(s) cosh^2(t)` for an origin
        // at distance `s` from the eye and arc length `t`, so long secondary
        // rays from far points lose them sooner (s + t near 17 costs 1 %).
        // Shading with such vectors would be silent garbage (cosines far
        // above 1): count it as a numeric failure instead.
        if !(is_unit(d) && is_unit(hit.normal)) {
            stats.failures += 1;
            return self.scene.background.into();
        }
        let entering = lorentz::dot(d, hit.normal) < 0.0;
        // The normal on the side the ray came from, for shading.
        let n = if entering { hit.normal } else { -hit.normal };
        let p = hit.point;

        let mut color = Color::from(m.ambient).tint(self.scene.ambient.into());
        let view = -d;
        // A material without diffuse and specular terms ignores the lights:
        // skip their shadow rays.
        let lit = [m.diffuse, m.specular]
            .iter()
            .any(|c| c.r != 0.0 || c.g != 0.0 || c.b != 0.0);
        for light in self.scene.lights.iter().filter(|_| lit) {
            // A light exactly at the hit point has no direction: it lights
            // nothing there (its attenuation would be infinite).
            let Some((to_light, dist)) = lorentz::direction_towards(p, light.position) else {
                continue;
            };
            let cos_theta = lorentz::dot(n, to_light);
            if !(cos_theta > 0.0) {
                continue;
            }
            let cos_theta = cos_theta.min(1.0);
            stats.rays += 1;
            let shadow = self.scene.transmittance(
                &Ray {
                    origin: p,
                    dir: to_light,
                },
                T_MIN,
                dist,
            );
            if shadow == 0.0 {
                continue;
            }
            // The area of the hyperbolic sphere of radius r is 4 pi sinh^2 r.
            let sinh = dist.sinh();
            let f_att = 1.0 / (4.0 * PI * sinh * sinh);
            let mirrored = reflect(-to_light, n);
            // A cosine of unit vectors: at most 1 up to the rounding that
            // `is_unit` bounds; keep rounding from being raised to a high
            // Phong exponent.
            let cos_alpha = lorentz::dot(mirrored, view).clamp(0.0, 1.0);
            let diffuse = Color::from(m.diffuse).tint(light.diffuse.into()) * cos_theta;
            let specular =
                Color::from(m.specular).tint(light.specular.into()) * cos_alpha.powf(m.shininess);
            color += (diffuse + specular) * (shadow * f_att);
        }

        if depth < self.scene.max_depth {
            let reflected = Ray {
                origin: p,
                dir: renormalize(p, reflect(d, n)),
            };
            if m.reflection > 0.0 && weight * m.reflection > MIN_WEIGHT {
                color +=
                    self.trace(&reflected, depth + 1, weight * m.reflection, stats) * m.reflection;
            }
            if m.transmission > 0.0 && weight * m.transmission > MIN_WEIGHT {
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
                color +=
                    self.trace(&next, depth + 1, weight * m.transmission, stats) * m.transmission;
            }
        }
        color
    }
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
