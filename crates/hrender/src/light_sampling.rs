//! Sampling points on lights: a point light is its own sample; a spherical
//! area light is sampled uniformly in area over the cap a shading point
//! can see (docs/rendering.md has the derivation).

use std::f64::consts::TAU;

use hgeom::glam::{DVec3, DVec4};
use hgeom::lorentz;

use crate::sampling::SampleStream;
use crate::scene::PreparedLight;

/// The golden ratio's fractional part: successive area-light samples turn
/// by this share of a full turn about the axis towards the shading point.
const GOLDEN_TURN: f64 = 0.618_033_988_749_894_8;

/// The part of a spherical area light (an h-sphere of radius `r` about the
/// light's position, each surface element of which emits its share of the
/// light's power uniformly into its outer half-space) that a point can
/// see: the cap of angle `phi` at the centre with `cos phi >= tanh r /
/// tanh D`, `D` the distance of the centre. Its [`points`] are uniform in
/// area on the cap, stratified in `cos phi` and turned by the golden angle;
/// each lit like a point light and averaged, and weighted by the cap's
/// share of the light's power, `1 - tanh r / tanh D` ([`weight`]), they
/// give an unbiased estimate that lights a surface facing the light with
/// exactly the point light's `1/(4 pi sinh^2 D)`, and tends to the point
/// light as `r -> 0`.
///
/// [`points`]: VisibleCap::point
/// [`weight`]: VisibleCap::weight
pub struct VisibleCap {
    centre: DVec4,
    /// The unit tangent at the centre towards the shading point.
    towards: DVec4,
    /// With `towards`, an orthonormal basis of the tangent space there.
    basis: (DVec4, DVec4),
    sinh_r: f64,
    cosh_r: f64,
    /// `1 - tanh r / tanh D`.
    cap: f64,
    count: f64,
    /// The turn of the first sample about `towards`, in turns.
    turn: f64,
}

impl VisibleCap {
    /// The cap of `light` (radius above 0) that `p` sees, drawing the
    /// turn of its samples from `stream`; `None` when `p` is on or inside
    /// the sphere (the emission faces outward) or at its centre.
    pub fn of(light: &PreparedLight, p: DVec4, stream: &mut SampleStream) -> Option<VisibleCap> {
        let centre = light.position;
        let r = light.radius;
        // At the centre itself there is no direction: the point is inside.
        let (towards, dist) = lorentz::direction_towards(centre, p)?;
        if !(dist > r) {
            return None;
        }
        // 1 - tanh r / tanh D, written without cancellation.
        let cap = (dist - r).sinh() / (dist.sinh() * r.cosh());
        let basis = tangent_basis(centre, towards);
        Some(VisibleCap {
            centre,
            towards,
            basis,
            sinh_r: r.sinh(),
            cosh_r: r.cosh(),
            cap,
            count: f64::from(light.samples),
            turn: stream.next_unit(),
        })
    }

    /// The `k`-th of the light's samples (from 0), its jitter within its
    /// stratum drawn from `stream`: a point on the hyperboloid.
    #[inline]
    pub fn point(&self, k: u32, stream: &mut SampleStream) -> DVec4 {
        let k = f64::from(k);
        // 1 - cos(phi), uniform over the cap (area on the sphere is
        // proportional to 1 - cos(phi)), one sample per stratum.
        let h = (k + stream.next_unit()) / self.count * self.cap;
        let (cos_phi, sin_phi) = (1.0 - h, (h * (2.0 - h)).sqrt());
        let psi = TAU * (self.turn + k * GOLDEN_TURN).fract();
        let (b1, b2) = self.basis;
        let u = self.towards * cos_phi + (b1 * psi.cos() + b2 * psi.sin()) * sin_phi;
        self.cosh_r * self.centre + self.sinh_r * u
    }

    /// The weight of the sum of what the samples give: the cap's share of
    /// the light's power over the number of samples.
    #[inline]
    pub fn weight(&self) -> f64 {
        self.cap / self.count
    }
}

/// The cone of directions in which a point sees an h-sphere: a sphere of
/// radius `a` whose centre is at distance `d > a` subtends the half-angle
/// `α` with `sin α = sinh a / sinh d` (the right triangle of the centre,
/// the point and a point of tangency: `sin α = sinh(opposite) /
/// sinh(hypotenuse)`), so its directions are sampled exactly, uniformly by
/// solid angle, with density `1 / (2π (1 - cos α))`.
pub struct SphereCone {
    p: DVec4,
    axis: DVec4,
    basis: (DVec4, DVec4),
    /// `1 - cos α`, without cancellation.
    one_minus_cos: f64,
    /// `cosh` and `sinh` of the centre's distance, `cosh` of the radius.
    cosh_d: f64,
    sinh_d: f64,
    cosh_a: f64,
    /// `sinh²` of the radius.
    sinh2_a: f64,
}

impl SphereCone {
    /// The cone from `p` to the sphere of `radius` about `centre`; `None`
    /// when `p` is not outside it.
    pub fn new(p: DVec4, centre: DVec4, radius: f64) -> Option<SphereCone> {
        let (axis, d) = lorentz::direction_towards(p, centre)?;
        if !(d > radius) {
            return None;
        }
        let (sinh_a, sinh_d) = (radius.sinh(), d.sinh());
        let sin = sinh_a / sinh_d;
        let cos = (1.0 - sin * sin).max(0.0).sqrt();
        let one_minus_cos = sin * sin / (1.0 + cos);
        if !(one_minus_cos > 0.0) {
            return None;
        }
        Some(SphereCone {
            p,
            axis,
            basis: tangent_basis(p, axis),
            one_minus_cos,
            cosh_d: d.cosh(),
            sinh_d,
            cosh_a: radius.cosh(),
            sinh2_a: sinh_a * sinh_a,
        })
    }

    /// A direction drawn uniformly from the cone with the uniforms `u1`,
    /// `u2` (a unit tangent at the point), with the distance at which the direction
    /// meets the sphere, from the triangle of the point, the centre and
    /// the hit: the hyperbolic law of cosines `cosh a = cosh d cosh t -
    /// sinh d sinh t cos θ` has the nearer root `e^t = (A + B) / (C +
    /// sqrt(sinh² a - sinh² d sin² θ))` with `A = cosh d`, `B = sinh d cos
    /// θ`, `C = cosh a` (written without cancellation). No intersection is
    /// computed again.
    pub fn sample_with_distance(&self, u1: f64, u2: f64) -> (DVec4, f64) {
        let h = u1 * self.one_minus_cos;
        let sin2 = (h * (2.0 - h)).max(0.0);
        let (cos, sin) = (1.0 - h, sin2.sqrt());
        let phi = TAU * u2;
        let (b1, b2) = self.basis;
        let v = self.axis * cos + (b1 * phi.cos() + b2 * phi.sin()) * sin;
        let disc = (self.sinh2_a - self.sinh_d * self.sinh_d * sin2).max(0.0);
        let t = ((self.cosh_d + self.sinh_d * cos) / (self.cosh_a + disc.sqrt())).ln();
        (crate::tangent::renormalize(self.p, v), t)
    }

    /// The density of [`SphereCone::sample`] per unit solid angle.
    pub fn pdf(&self) -> f64 {
        1.0 / (TAU * self.one_minus_cos)
    }
}

/// Two unit tangents at `c` that complete the unit tangent `e` to a Lorentz
/// orthonormal basis of the tangent space, without a square root or a
/// branch on the data's size.
///
/// The boost that takes the origin to `c = (x, w)` maps the origin's
/// tangent space (Euclidean `R³`) isometrically onto `c`'s:
/// `v ↦ (v + (x·v)/(1+w) x, x·v)`, with inverse `(e_s, e_t) ↦ e_s -
/// e_t/(1+w) x` on tangents. So `e` is pulled back to a Euclidean unit
/// vector, completed there by the branchless orthonormal basis of Duff et
/// al. (2017, "Building an orthonormal basis, revisited"; Frisvad's with
/// the singularity at `z = -1` removed), and the two are pushed forward.
pub fn tangent_basis(c: DVec4, e: DVec4) -> (DVec4, DVec4) {
    let x = c.truncate();
    let k = 1.0 / (1.0 + c.w);
    let n = e.truncate() - (e.w * k) * x;
    let sign = 1.0f64.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    let u = DVec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    let v = DVec3::new(b, sign + n.y * n.y * a, -n.y);
    let push = |t: DVec3| {
        let xt = x.dot(t);
        (t + (xt * k) * x).extend(xt)
    };
    (push(u), push(v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::Point;

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

    /// Every direction of the cone meets the sphere, and the cone's solid
    /// angle is `2π (1 - cos α)` with `sin α = sinh a / sinh d`: measured
    /// against the fraction of uniform directions that meet the sphere.
    #[test]
    fn the_cone_is_the_sphere_seen_from_the_point() {
        use hgeom::HSphere;
        let (a, d) = (0.4, 1.7);
        let centre = Point::at_distance_from_origin(DVec3::new(0.3, -0.2, 0.9), d).unwrap();
        let sphere = HSphere::new(centre, a).unwrap();
        let p = Point::ORIGIN.to_hyperboloid();
        let cone = SphereCone::new(p, centre.to_hyperboloid(), a).unwrap();
        let mut stream = SampleStream::new(11);
        for _ in 0..1000 {
            let (dir, t) = cone.sample_with_distance(stream.next_unit(), stream.next_unit());
            let ray = hgeom::Ray { origin: p, dir };
            let hit = sphere.intersect(&ray, 0.0, f64::INFINITY).expect("a hit");
            // The law of cosines gives the intersection's own distance.
            assert!((hit.t - t).abs() < 1e-12, "{} vs {t}", hit.t);
        }
        // Uniform directions on the sphere of directions at the origin.
        let n = 400_000;
        let mut hits = 0;
        for _ in 0..n {
            let z = 2.0 * stream.next_unit() - 1.0;
            let phi = TAU * stream.next_unit();
            let r = (1.0 - z * z).sqrt();
            let ray =
                hgeom::Ray::from_origin_unchecked(DVec3::new(r * phi.cos(), r * phi.sin(), z));
            hits += usize::from(sphere.intersect(&ray, 0.0, f64::INFINITY).is_some());
        }
        let sin = a.sinh() / d.sinh();
        let share = (1.0 - (1.0 - sin * sin).sqrt()) / 2.0;
        let measured = hits as f64 / f64::from(n);
        let sigma = (share * (1.0 - share) / f64::from(n)).sqrt();
        assert!(
            (measured - share).abs() < 5.0 * sigma,
            "{measured} vs {share}"
        );
        // The Euclidean cone, sin α = a / d, is far off.
        let euclid = (1.0 - (1.0 - (a / d) * (a / d)).sqrt()) / 2.0;
        assert!((measured - euclid).abs() > 50.0 * sigma);
        assert!(
            (cone.pdf() - 1.0 / (4.0 * std::f64::consts::PI * share)).abs() < 1e-9 * cone.pdf()
        );
    }

    /// Every sample lies on the light's sphere, on the cap the shading
    /// point sees; a point inside the sphere sees none.
    #[test]
    fn samples_lie_on_the_visible_cap() {
        let centre = Point::at_distance_from_origin(DVec3::new(0.2, 0.5, -0.1), 1.5).unwrap();
        let light = PreparedLight {
            position: centre.to_hyperboloid(),
            diffuse: hscene_ir::Rgb::BLACK,
            specular: hscene_ir::Rgb::BLACK,
            radius: 0.3,
            samples: 16,
            near_sinh2: 0.0,
            reach: f64::INFINITY,
            cosh_reach: f64::INFINITY,
        };
        let p = Point::ORIGIN.to_hyperboloid();
        let mut stream = SampleStream::new(7);
        let cap = VisibleCap::of(&light, p, &mut stream).expect("the origin is outside");
        let d = centre.distance_from_origin();
        for k in 0..16 {
            let q = cap.point(k, &mut stream);
            let r = (-lorentz::dot(q, light.position)).acosh();
            assert!((r - 0.3).abs() < 1e-12);
            // On the cap: cos phi >= tanh r / tanh D, phi the angle at the
            // centre between the sample and the shading point.
            let (towards_p, _) = lorentz::direction_towards(light.position, p).unwrap();
            let (towards_q, _) = lorentz::direction_towards(light.position, q).unwrap();
            let cos_phi = lorentz::dot(towards_p, towards_q);
            assert!(cos_phi >= 0.3f64.tanh() / d.tanh() - 1e-12);
        }
        let inside = Point::at_distance_from_origin(DVec3::new(0.2, 0.5, -0.1), 1.4)
            .unwrap()
            .to_hyperboloid();
        assert!(VisibleCap::of(&light, inside, &mut stream).is_none());
    }
}
