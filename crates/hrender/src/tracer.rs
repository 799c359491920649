//! Whitted ray tracing with the Phong model and hyperbolic attenuation
//! (SPEC 3.3, thesis Eq. 4, 7 and 9).

use std::f64::consts::PI;

use hgeom::Ray;
use hgeom::glam::DVec4;
use hgeom::lorentz;
use hgeom::ray::{reflect, refract};

use crate::color::Color;
use crate::scene::PreparedScene;

/// Secondary rays ignore hits closer than this (hyperbolic length), so a ray
/// leaving a surface does not hit the same surface at its own origin.
pub const T_MIN: f64 = 1e-9;

/// Rays whose weight in the final pixel falls below this are not traced.
const MIN_WEIGHT: f64 = 1e-3;

/// Per-ray outcome counters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Rays traced (primary, secondary, shadow).
    pub rays: u64,
    /// Shading results that were not finite; such pixels are counted and
    /// shown as the background, never silently.
    pub numeric_failures: u64,
}

impl TraceStats {
    /// Sum two counters.
    pub fn merge(self, o: TraceStats) -> TraceStats {
        TraceStats {
            rays: self.rays + o.rays,
            numeric_failures: self.numeric_failures + o.numeric_failures,
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
            stats.numeric_failures += 1;
            self.scene.background.into()
        }
    }

    /// Whitted recursion:
    /// `I = k_a I_a + sum_i S_i f_att(r_i) (k_d L_d cos(theta) + k_s L_s cos^n(alpha)) + k_r I_r + k_t I_t`.
    fn trace(&self, ray: &Ray, depth: u32, weight: f64, stats: &mut TraceStats) -> Color {
        stats.rays += 1;
        let Some((hit, index)) = self.scene.nearest(ray, T_MIN) else {
            return self.scene.background.into();
        };
        let object = &self.scene.objects[index];
        let m = &self.scene.materials[object.material];
        let d = ray.tangent_at(hit.t);
        let entering = lorentz::dot(d, hit.normal) < 0.0;
        // The normal on the side the ray came from, for shading.
        let n = if entering { hit.normal } else { -hit.normal };
        let p = hit.point;

        let mut color = Color::from(m.ambient).tint(self.scene.ambient.into());
        let view = -d;
        for light in &self.scene.lights {
            let Some((to_light, dist)) = lorentz::direction_towards(p, light.position) else {
                continue;
            };
            let cos_theta = lorentz::dot(n, to_light);
            if cos_theta <= 0.0 {
                continue;
            }
            let shadow = self.transmittance(
                &Ray {
                    origin: p,
                    dir: to_light,
                },
                dist,
                stats,
            );
            if shadow == 0.0 {
                continue;
            }
            let sinh = dist.sinh();
            let f_att = 1.0 / (4.0 * PI * sinh * sinh);
            let mirrored = reflect(-to_light, n);
            let cos_alpha = lorentz::dot(mirrored, view).max(0.0);
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
                // Total internal reflection sends the transmitted share along the mirror ray.
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

    /// The fraction of a light's intensity reaching along the shadow ray up to
    /// `dist`: each object in the way multiplies it by its transmission
    /// coefficient (opaque objects block it).
    fn transmittance(&self, ray: &Ray, dist: f64, stats: &mut TraceStats) -> f64 {
        stats.rays += 1;
        let mut s = 1.0;
        for o in &self.scene.objects {
            if o.primitive.intersect(ray, T_MIN, dist).is_some() {
                s *= self.scene.materials[o.material].transmission;
                if s == 0.0 {
                    break;
                }
            }
        }
        s
    }
}

/// Restore `<v,v> = 1`, `<p,v> = 0` after floating-point arithmetic on a
/// tangent vector, so rounding never accumulates along a path.
fn renormalize(p: DVec4, v: DVec4) -> DVec4 {
    let t = v + lorentz::dot(p, v) * p;
    t / lorentz::norm(t)
}
