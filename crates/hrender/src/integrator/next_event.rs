//! Next-event estimation for the path integrator: at each vertex one light
//! unit drawn by [`LightSelector`] (in proportion to what it can bring
//! there), one point or direction on it, one shadow ray; and the
//! multiple-importance weights of emission that the paths' own bounces
//! find, which must use the same selection probability.

use hgeom::glam::DVec4;
use hgeom::lorentz::{self, Separation};
use hgeom::{Hit, Ray};
use hscene_ir::Rgb;

use super::path::{FaceEmitter, LastScatter, PathTracer, ShadingPoint, Source, power_heuristic};
use crate::bsdf::clear_transmission;
use crate::light_sampling::SphereCone;
use crate::sampling::SampleStream;
use crate::scene::T_MIN;
use crate::spherical_triangle::SphericalTriangle;
use crate::trace_stats::TraceStats;

/// The arc length at which the geodesic from `p` with unit tangent `wi`
/// meets the h-plane of unit normal `m`: on `cosh t p + sinh t wi`,
/// `<x, m> = 0` gives `tanh t = -<p, m> / <wi, m>` exactly. With it, a
/// sampled triangle is not intersected again (and the shadow ray stops at
/// the sampled triangle itself, not at whatever face of the same object is
/// nearer: each triangle lights only with its own visible points).
fn plane_distance(p: DVec4, wi: DVec4, m: DVec4) -> Option<f64> {
    let tanh = -lorentz::dot(p, m) / lorentz::dot(wi, m);
    (tanh > 0.0 && tanh < 1.0).then(|| tanh.atanh())
}

impl PathTracer<'_> {
    /// Light arriving at the shading point straight from one light unit
    /// drawn in proportion to its importance, reflected towards the
    /// viewer; with the sum of the importances at the point (for the
    /// weight of emission the next bounce finds).
    pub(super) fn direct(
        &self,
        at: &ShadingPoint<'_>,
        own: usize,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> (Rgb, f64) {
        let (u0, u1, u2) = (stream.next_unit(), stream.next_unit(), stream.next_unit());
        let total = self.selector.total(at.p, at.n, own);
        let Some(choice) = self.selector.select(at.p, at.n, own, total, u0) else {
            return (Rgb::BLACK, total);
        };
        let light = match self.sources[choice.unit] {
            Source::Point(k) => self.point_light(at, k, stats),
            Source::Sphere(k) => {
                let e = &self.emitters[k];
                match SphereCone::new(at.p, e.centre, e.radius) {
                    Some(cone) => {
                        // The distance to the sphere comes with the
                        // direction: the emitter is not intersected again.
                        let (wi, t) = cone.sample_with_distance(u1, u2);
                        let pdf = cone.pdf() * choice.pmf;
                        self.light_along(at, wi, pdf, e.radiance, stats, |_| {
                            (t > 0.0 && t.is_finite()).then_some(t)
                        })
                    }
                    None => Rgb::BLACK,
                }
            }
            Source::Triangle(f, t) => {
                let e = &self.faces[f];
                let (tri, m) = e.triangles[t];
                match SphericalTriangle::new(at.p, tri) {
                    Some(solid) => {
                        let wi = solid.sample(u1, u2);
                        let pdf = choice.pmf / solid.solid_angle();
                        self.light_along(at, wi, pdf, e.radiance, stats, |ray| {
                            plane_distance(ray.origin, ray.dir, m)
                        })
                    }
                    None => Rgb::BLACK,
                }
            }
        };
        // A point light is a delta: the probability divides it here; the
        // area units' is in their densities.
        let light = match self.sources[choice.unit] {
            Source::Point(_) => light * (1.0 / choice.pmf),
            _ => light,
        };
        (light, total)
    }

    /// What point light `k` sends to `at`, reflected towards the viewer.
    fn point_light(&self, at: &ShadingPoint<'_>, k: usize, stats: &mut TraceStats) -> Rgb {
        let ShadingPoint { p, n, wo, bsdf } = *at;
        let light = &self.scene.lights[k];
        if light.out_of_reach(p) {
            return Rgb::BLACK;
        }
        let Some(wi) = lorentz::unit_tangent_towards(p, light.position) else {
            return Rgb::BLACK;
        };
        let cos = lorentz::dot(n, wi);
        if !(cos > 0.0) {
            return Rgb::BLACK;
        }
        let apart = Separation::between(p, light.position);
        // An image beyond its reach (quotient spaces) lights nothing.
        let distance = apart.distance();
        let weight = light.fade(distance);
        if weight == 0.0 {
            return Rgb::BLACK;
        }
        stats.rays += 1;
        let shadow = self.scene.transmittance(
            &Ray { origin: p, dir: wi },
            T_MIN,
            distance,
            apart.tanh(),
            clear_transmission,
        );
        if shadow == 0.0 {
            return Rgb::BLACK;
        }
        // A point light of colour Φ has radiant intensity Φ/4 (power
        // πΦ): a Lambertian surface of albedo ρ facing it reflects
        // exactly Whitted's `ρ Φ / (4π sinh² r)`; clear tinted glass on
        // the way filters it.
        let intensity = light.diffuse.tint(self.filtered(p, wi, distance)) * 0.25;
        bsdf.eval(n, wo, wi).tint(intensity)
            * (cos * shadow * weight / light.falloff_sinh2(apart.sinh_squared()))
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
        if !(cos > 0.0 && pdf > 0.0) {
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

    /// The power-heuristic weight of emission from emitter `k` reached by
    /// a direction the last vertex's lobes drew: light sampling would have
    /// drawn it with the emitter's selection probability there times the
    /// cone's density.
    pub(super) fn emission_weight(&self, k: usize, last: LastScatter) -> f64 {
        let Some(last) = last else {
            return 1.0;
        };
        let e = &self.emitters[k];
        let pmf = self
            .selector
            .pmf(e.unit, last.from, last.n, last.on, last.total);
        if pmf == 0.0 {
            return 1.0;
        }
        match SphereCone::new(last.from, e.centre, e.radius) {
            Some(cone) => power_heuristic(last.pdf_bsdf, pmf * cone.pdf()),
            None => 1.0,
        }
    }

    /// The power-heuristic weight of emission from the faces of object
    /// `index` met by `hit`, reached by a direction the last vertex's lobes
    /// drew: light sampling would have drawn it from the one triangle that
    /// holds the point, with that triangle's selection probability.
    pub(super) fn face_weight(&self, index: usize, hit: &Hit, last: LastScatter) -> f64 {
        let Some(last) = last else {
            return 1.0;
        };
        let Some(e) = self.faces.iter().find(|e| e.object == index) else {
            return 1.0;
        };
        if last.on == index {
            return 1.0;
        }
        let holding = if e.by_part {
            // A mesh says which triangle it met.
            let t = hit.part as usize;
            e.triangles
                .get(t)
                .and_then(|(tri, _)| SphericalTriangle::new(last.from, *tri))
                .map(|solid| (t, solid.solid_angle()))
        } else {
            // Otherwise the triangle is found by the hit's direction.
            let Some(d) = lorentz::unit_tangent_towards(last.from, hit.point) else {
                return 1.0;
            };
            holding_triangle(e, last.from, hit.point, d)
        };
        match holding {
            Some((t, solid_angle)) => {
                let pmf =
                    self.selector
                        .pmf(e.first_unit + t, last.from, last.n, last.on, last.total);
                if pmf == 0.0 {
                    1.0
                } else {
                    power_heuristic(last.pdf_bsdf, pmf / solid_angle)
                }
            }
            None => 1.0,
        }
    }
}

/// The triangle of `e` that holds `point` (seen from `from` in direction
/// `d`), and its solid angle from `from`: of the triangles whose planes
/// pass nearest the point, the one whose directions hold `d`.
fn holding_triangle(e: &FaceEmitter, from: DVec4, point: DVec4, d: DVec4) -> Option<(usize, f64)> {
    // `<x, m>` is the sinh of the distance from the plane: rounding makes
    // it of the order of eps times the point's coordinates on its own.
    let tolerance = 1e-9 * point.w.abs().max(1.0);
    let mut best: Option<(usize, f64, f64)> = None;
    for (t, (tri, m)) in e.triangles.iter().enumerate() {
        let off = lorentz::dot(point, *m).abs();
        if off > tolerance || best.is_some_and(|b| b.2 <= off) {
            continue;
        }
        if let Some(solid) = SphericalTriangle::new(from, *tri)
            && solid.contains(d)
        {
            best = Some((t, solid.solid_angle(), off));
        }
    }
    best.map(|(t, omega, _)| (t, omega))
}
