//! A material at a shading point: its reflectances there (a texture's or
//! its own) and the thesis's Phong BRDF (docs/rendering.md "Light"; thesis
//! Eq. 4 and 7).

use hgeom::Hit;
use hgeom::glam::DVec4;
use hgeom::lorentz;
use hgeom::ray::reflect;
use hscene_ir::{Material, Rgb};

use crate::scene::PreparedObject;
use crate::texture::texture_colours;

/// The ambient and diffuse reflectances of `m` at `hit` on `object`: a
/// texture replaces them in part of the surface; only textured materials
/// pay for finding out where.
#[inline]
pub fn reflectances(object: &PreparedObject, m: &Material, hit: &Hit) -> (Rgb, Rgb) {
    let own = match &m.texture {
        None => (m.ambient, m.diffuse),
        Some(t) => texture_colours(object, m, t, hit),
    };
    match (&m.image, &object.mapping) {
        (Some(image), Some(mapping)) => mapping.colours(image, own, hit),
        _ => own,
    }
}

/// What the lights see of a shading point.
pub struct Shading<'m> {
    /// The hit point.
    pub p: DVec4,
    /// The normal on the side the ray came from.
    pub n: DVec4,
    /// Towards the eye (the reversed ray).
    pub view: DVec4,
    /// The diffuse reflectance there (the texture's or the material's).
    pub diffuse: Rgb,
    /// The material (specular reflectance and exponent).
    pub m: &'m Material,
}

impl Shading<'_> {
    /// Diffuse plus specular Phong terms for light of diffuse and specular
    /// intensities `light_diffuse`, `light_specular` arriving from the unit
    /// tangent `to_light` with `cos_theta = <n, to_light> > 0`, before
    /// attenuation and shadowing.
    #[inline]
    pub fn phong(
        &self,
        light_diffuse: Rgb,
        light_specular: Rgb,
        to_light: DVec4,
        cos_theta: f64,
    ) -> Rgb {
        let mirrored = reflect(-to_light, self.n);
        // A cosine of unit vectors: at most 1 up to the rounding that
        // `is_unit` bounds; keep rounding from being raised to a high
        // Phong exponent.
        let cos_alpha = lorentz::dot(mirrored, self.view).clamp(0.0, 1.0);
        let diffuse = self.diffuse.tint(light_diffuse) * cos_theta;
        let specular = self.m.specular.tint(light_specular) * cos_alpha.powf(self.m.shininess);
        diffuse + specular
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Light along the normal, seen along the normal: the whole diffuse
    /// term times the cosine and the whole specular term; seen from the
    /// mirror direction of a slanted light, the specular peak.
    #[test]
    fn phong_terms_at_their_peaks() {
        let m = Material {
            specular: Rgb::new(0.5, 0.5, 0.5),
            shininess: 20.0,
            ..Material::default()
        };
        let n = DVec4::new(0.0, 0.0, 1.0, 0.0);
        let at = Shading {
            p: DVec4::new(0.0, 0.0, 0.0, 1.0),
            n,
            view: n,
            diffuse: Rgb::new(0.2, 0.4, 0.8),
            m: &m,
        };
        let white = Rgb::new(1.0, 1.0, 1.0);
        let c = at.phong(white, white, n, 1.0);
        assert!((c.r - 0.7).abs() < 1e-15 && (c.b - 1.3).abs() < 1e-15);
        // Light 60 degrees off the normal; the view 60 degrees the other
        // way sees the specular peak, the normal only cos^20 of 60 degrees.
        let (s, k) = (3f64.sqrt() / 2.0, 0.5);
        let light = DVec4::new(s, 0.0, k, 0.0);
        let mirror = Shading {
            view: DVec4::new(-s, 0.0, k, 0.0),
            ..at
        };
        let peak = mirror.phong(Rgb::BLACK, white, light, k);
        assert!((peak.g - 0.5).abs() < 1e-12);
        let off = at.phong(Rgb::BLACK, white, light, k);
        assert!((off.g - 0.5 * 0.5f64.powi(20)).abs() < 1e-12);
    }
}
