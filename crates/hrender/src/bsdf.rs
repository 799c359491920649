//! The path integrator's reading of a material: physically based lobes
//! made from the thesis's Phong fields (docs/rendering.md, "The path
//! integrator"):
//!
//! - `diffuse` is the albedo `ρ_d` of a Lambertian lobe, `ρ_d / π`;
//! - `specular` and `shininess` are a normalised Phong lobe,
//!   `k_s (n + 2) / (2π) cos^n α`, `α` from the mirror direction, which
//!   reflects at most `k_s` of what arrives and conserves energy;
//! - `alpha` is a perfect mirror reflecting `k_r`;
//! - `trans` is the share `k_t` that meets a dielectric interface of index
//!   `refraction`: Fresnel decides between reflection and refraction
//!   (total internal reflection included); index 1 lets it through
//!   unbent, as clear glass without an interface;
//! - `ambient` has no meaning (light between surfaces is computed).
//!
//! When the lobes add up to more than all the light (the largest channel of
//! `ρ_d + k_s`, plus `k_r + k_t`, above 1), every lobe is scaled down by
//! that sum, so that no surface creates light.

use std::f64::consts::{FRAC_1_PI, TAU};

use hgeom::glam::DVec4;
use hgeom::lorentz;
use hgeom::ray::{reflect, refract};
use hscene_ir::{Material, Rgb};

use crate::light_sampling::tangent_basis;
use crate::tangent::{mirrored, reflected, renormalize};

/// The lobes of a material at a shading point.
#[derive(Clone, Copy, Debug)]
pub struct Bsdf {
    diffuse: Rgb,
    glossy: Rgb,
    exponent: f64,
    mirror: f64,
    transmission: f64,
    index: f64,
    /// The probabilities of choosing each lobe when sampling: diffuse,
    /// glossy, mirror, transmission (summing to 1, or all 0 for a black
    /// surface).
    choose: [f64; 4],
}

/// A direction drawn from a [`Bsdf`].
#[derive(Clone, Copy, Debug)]
pub struct Scatter {
    /// The new direction, a unit tangent at the shading point.
    pub dir: DVec4,
    /// What the path's throughput is multiplied by: `f cos / pdf`, or a
    /// delta lobe's weight over its probability.
    pub weight: Rgb,
    /// The solid-angle density the direction was drawn with, over every
    /// smooth lobe (for multiple importance sampling); `None` for a delta
    /// lobe (mirror or dielectric).
    pub pdf: Option<f64>,
    /// The direction went through an index-1 interface unbent: the path is
    /// where it was as far as light sampling is concerned.
    pub passed_through: bool,
}

/// The mean of the channels: a lobe's share in the choice of lobes.
fn mean(c: Rgb) -> f64 {
    (c.r + c.g + c.b) / 3.0
}

/// The factor every lobe of `m` is scaled by so that the material reflects
/// and transmits at most all of the light: `1 / max(1, total)`.
pub(crate) fn energy_scale(m: &Material, diffuse: Rgb) -> f64 {
    let smooth = (diffuse + m.specular)
        .channels()
        .into_iter()
        .fold(0.0, f64::max);
    let total = smooth + m.reflection + m.transmission;
    if total > 1.0 { 1.0 / total } else { 1.0 }
}

/// The fraction of light a shadow ray carries through a surface of `m`:
/// only index-1 transmission lets light through unbent (a refracting
/// surface bends the shadow ray away from the light), by the same share
/// the [`Bsdf`] gives it.
pub fn clear_transmission(m: &Material) -> f64 {
    if m.refraction == 1.0 && m.transmission > 0.0 {
        m.transmission * energy_scale(m, m.diffuse)
    } else {
        0.0
    }
}

impl Bsdf {
    /// The lobes of `m` with diffuse albedo `diffuse` (the material's or
    /// its texture's there).
    pub fn new(m: &Material, diffuse: Rgb) -> Bsdf {
        let k = energy_scale(m, diffuse);
        let diffuse = diffuse * k;
        let glossy = m.specular * k;
        let (mirror, transmission) = (m.reflection * k, m.transmission * k);
        let weights = [mean(diffuse), mean(glossy), mirror, transmission];
        let sum: f64 = weights.iter().sum();
        let choose = if sum > 0.0 && sum.is_finite() {
            weights.map(|w| w / sum)
        } else {
            [0.0; 4]
        };
        Bsdf {
            diffuse,
            glossy,
            exponent: m.shininess,
            mirror,
            transmission,
            index: m.refraction,
            choose,
        }
    }

    /// True if the material scatters light smoothly (a diffuse or glossy
    /// lobe), so light sampling can find it.
    pub fn is_smooth(&self) -> bool {
        self.choose[0] + self.choose[1] > 0.0
    }

    /// The smooth lobes' value `f(wo, wi)` for `wo` towards the viewer and
    /// `wi` towards the light, both unit tangents on the side of the normal
    /// `n`; black below the surface.
    pub fn eval(&self, n: DVec4, wo: DVec4, wi: DVec4) -> Rgb {
        if !(lorentz::dot(n, wi) > 0.0) {
            return Rgb::BLACK;
        }
        let mut f = self.diffuse * FRAC_1_PI;
        if self.choose[1] > 0.0 {
            let cos_alpha = lorentz::dot(reflect(-wo, n), wi).clamp(0.0, 1.0);
            f += self.glossy * ((self.exponent + 2.0) / TAU * cos_alpha.powf(self.exponent));
        }
        f
    }

    /// The density of [`Bsdf::sample`] drawing `wi` through its smooth
    /// lobes, per unit solid angle.
    pub fn pdf(&self, n: DVec4, wo: DVec4, wi: DVec4) -> f64 {
        let cos = lorentz::dot(n, wi);
        if !(cos > 0.0) {
            return 0.0;
        }
        let mut pdf = self.choose[0] * cos * FRAC_1_PI;
        if self.choose[1] > 0.0 {
            let cos_alpha = lorentz::dot(reflect(-wo, n), wi).clamp(0.0, 1.0);
            pdf += self.choose[1] * (self.exponent + 1.0) / TAU * cos_alpha.powf(self.exponent);
        }
        pdf
    }

    /// Draw a direction at `p` for light arriving from `wo` (towards the
    /// viewer), `n` the shading normal on the viewer's side and `geometric`
    /// the true normal there (sides and refraction), with `entering` true
    /// when the path arrives from the side the geometric normal points to.
    /// `u` are three uniforms. `None`: the path ends (a black surface, or a
    /// direction below the surface).
    #[allow(clippy::too_many_arguments)]
    pub fn sample(
        &self,
        p: DVec4,
        n: DVec4,
        geometric: DVec4,
        entering: bool,
        wo: DVec4,
        u: [f64; 3],
    ) -> Option<Scatter> {
        let [p_diffuse, p_glossy, p_mirror, _] = self.choose;
        let pick = u[0];
        if pick < p_diffuse + p_glossy {
            let wi = if pick < p_diffuse {
                cosine_direction(p, n, u[1], u[2])
            } else {
                let r = reflected(p, -wo, n);
                phong_direction(p, r, self.exponent, u[1], u[2])
            };
            let cos = lorentz::dot(n, wi);
            if !(cos > 0.0) {
                return None;
            }
            let pdf = self.pdf(n, wo, wi);
            if !(pdf > 0.0) {
                return None;
            }
            let weight = self.eval(n, wo, wi) * (cos / pdf);
            return Some(Scatter {
                dir: wi,
                weight,
                pdf: Some(pdf),
                passed_through: false,
            });
        }
        let d = -wo;
        // The geometric normal on the side the path came from.
        let g = if entering { geometric } else { -geometric };
        // Mirror and refraction follow the shading normal (a smoothed mesh
        // is smooth glass, not cut crystal), unless it sends the ray to the
        // wrong side of the true surface; on every other surface the two
        // normals are the same.
        let mirrored = mirrored(p, d, n, g);
        if pick < p_diffuse + p_glossy + p_mirror {
            let w = self.mirror / p_mirror;
            return Some(Scatter {
                dir: mirrored,
                weight: Rgb::new(w, w, w),
                pdf: None,
                passed_through: false,
            });
        }
        let p_transmission = self.choose[3];
        if !(p_transmission > 0.0) {
            return None;
        }
        let w = self.transmission / p_transmission;
        let weight = Rgb::new(w, w, w);
        if self.index == 1.0 {
            return Some(Scatter {
                dir: d,
                weight,
                pdf: None,
                passed_through: true,
            });
        }
        let (n1, n2) = if entering {
            (1.0, self.index)
        } else {
            (self.index, 1.0)
        };
        // Reflected with the Fresnel probability (1 on total internal
        // reflection), refracted otherwise: the weight is the lobe's own.
        let refracted = match refract(d, n, n1, n2) {
            Some(t) if lorentz::dot(t, g) < 0.0 => Some(t),
            _ => refract(d, g, n1, n2),
        };
        let f = match refracted {
            Some(_) => fresnel(-lorentz::dot(d, n), n1, n2),
            None => 1.0,
        };
        let dir = match refracted {
            Some(t) if u[1] >= f => renormalize(p, t),
            _ => mirrored,
        };
        Some(Scatter {
            dir,
            weight,
            pdf: None,
            passed_through: false,
        })
    }
}

/// Unpolarised Fresnel reflectance of a dielectric interface for light
/// arriving at `cos_i` from the side of index `n1`.
pub fn fresnel(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin_t = n1 / n2 * (1.0 - cos_i * cos_i).sqrt();
    if sin_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    let rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
    0.5 * (rs * rs + rp * rp)
}

/// A cosine-distributed direction about `n` at `p` (Malley's method: a
/// uniform point of the unit disc lifted to the hemisphere).
fn cosine_direction(p: DVec4, n: DVec4, u1: f64, u2: f64) -> DVec4 {
    let (b1, b2) = tangent_basis(p, n);
    let r = u1.sqrt();
    let phi = TAU * u2;
    let z = (1.0 - u1).max(0.0).sqrt();
    renormalize(p, b1 * (r * phi.cos()) + b2 * (r * phi.sin()) + n * z)
}

/// A direction about `axis` at `p` with density `(e + 1)/(2π) cos^e α`.
fn phong_direction(p: DVec4, axis: DVec4, e: f64, u1: f64, u2: f64) -> DVec4 {
    let (b1, b2) = tangent_basis(p, axis);
    let cos = u1.powf(1.0 / (e + 1.0));
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let phi = TAU * u2;
    renormalize(p, axis * cos + (b1 * phi.cos() + b2 * phi.sin()) * sin)
}

/// `1/π`, for the tests' expected values.
#[cfg(test)]
const INV_PI: f64 = 1.0 / std::f64::consts::PI;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::SampleStream;

    const P: DVec4 = DVec4::new(0.0, 0.0, 0.0, 1.0);
    const N: DVec4 = DVec4::new(0.0, 0.0, 1.0, 0.0);

    fn material(diffuse: f64, specular: f64, shininess: f64) -> Material {
        Material {
            diffuse: Rgb::new(diffuse, diffuse, diffuse),
            specular: Rgb::new(specular, specular, specular),
            shininess,
            ..Material::default()
        }
    }

    /// For every smooth material the estimator `f cos / pdf` of the
    /// directional albedo averages to the albedo: `ρ_d` for Lambert, at most
    /// `k_s` for the normalised Phong lobe (less at grazing views, where
    /// part of the lobe falls below the surface), and its draws agree with
    /// `eval` and `pdf`.
    #[test]
    fn sampling_is_consistent_with_eval_and_pdf() {
        let mut stream = SampleStream::new(3);
        for (m, albedo) in [
            (material(0.6, 0.0, 1.0), Some(0.6)),
            (material(0.3, 0.5, 40.0), None),
            (material(0.0, 0.9, 200.0), None),
        ] {
            let bsdf = Bsdf::new(&m, m.diffuse);
            let wo = renormalize(P, DVec4::new(0.3, 0.1, 0.9, 0.0));
            let n_samples = 200_000;
            let mut sum = 0.0;
            for _ in 0..n_samples {
                let u = [stream.next_unit(), stream.next_unit(), stream.next_unit()];
                if let Some(s) = bsdf.sample(P, N, N, true, wo, u) {
                    let pdf = s.pdf.expect("a smooth lobe");
                    assert!((pdf - bsdf.pdf(N, wo, s.dir)).abs() <= 1e-9 * pdf);
                    let cos = lorentz::dot(N, s.dir);
                    let expect = bsdf.eval(N, wo, s.dir) * (cos / pdf);
                    assert!((expect.g - s.weight.g).abs() <= 1e-12);
                    sum += s.weight.g;
                }
            }
            let average = sum / f64::from(n_samples);
            let bound = mean(m.diffuse) + mean(m.specular);
            assert!(average <= bound + 0.01, "{average} > {bound}");
            if let Some(a) = albedo {
                assert!((average - a).abs() < 0.005, "{average} vs {a}");
            }
        }
    }

    /// The Lambertian lobe is `ρ/π` whatever the directions.
    #[test]
    fn lambert_is_albedo_over_pi() {
        let bsdf = Bsdf::new(&material(0.5, 0.0, 1.0), Rgb::new(0.5, 0.5, 0.5));
        let wo = renormalize(P, DVec4::new(0.5, 0.0, 0.5, 0.0));
        let wi = renormalize(P, DVec4::new(-0.2, 0.7, 0.3, 0.0));
        assert!((bsdf.eval(N, wo, wi).r - 0.5 * INV_PI).abs() < 1e-15);
        assert_eq!(bsdf.eval(N, wo, -N).r, 0.0);
    }

    /// Fresnel at normal incidence is `((n1 - n2)/(n1 + n2))²`, 1 beyond
    /// the critical angle, 0 for matched indices.
    #[test]
    fn fresnel_closed_forms() {
        assert!((fresnel(1.0, 1.0, 1.5) - 0.04).abs() < 1e-15);
        assert_eq!(fresnel(0.1, 1.5, 1.0), 1.0);
        assert_eq!(fresnel(0.7, 1.3, 1.3), 0.0);
    }

    /// Lobes that add up to more than 1 are scaled down to 1; a clear
    /// (index-1) transmission passes shadow rays by its scaled share, a
    /// refracting one not at all.
    #[test]
    fn energy_is_conserved() {
        let m = Material {
            diffuse: Rgb::new(0.8, 0.8, 0.8),
            reflection: 0.5,
            transmission: 0.7,
            ..Material::default()
        };
        let b = Bsdf::new(&m, m.diffuse);
        assert!((mean(b.diffuse) + b.mirror + b.transmission - 1.0).abs() < 1e-15);
        assert!((clear_transmission(&m) - 0.7 / 2.0).abs() < 1e-15);
        let bent = Material {
            refraction: 1.5,
            ..m
        };
        assert_eq!(clear_transmission(&bent), 0.0);
    }
}
