//! Spherical area lights: they tend to the point light as their radius
//! shrinks, give a surface facing them the point light's irradiance, cast
//! soft shadows whose penumbra grows with the radius, and render the same
//! image on any number of threads.

use hgeom::HPlane;
use hgeom::glam::DVec3;
use hrender::RenderOptions;
use hscene_ir::{Light, Material, Net, Rgb, Scene, Shape};
use hscene_test_support::SplitMix64;
use hscene_test_support::scenes::*;

/// A grey Lambertian material (no highlights), with a little ambient.
fn grey() -> Material {
    Material {
        ambient: Rgb::new(0.1, 0.1, 0.1),
        diffuse: Rgb::new(1.0, 1.0, 1.0),
        specular: Rgb::BLACK,
        ..flat(0.0, 0.0, 0.0)
    }
}

/// The soft-shadow scene: a grey h-plane facing the eye at distance 1.5,
/// and (with `blocker`) an opaque sphere in front of it that glows red
/// (ambient only, so plane pixels are the grey ones); `light` above the
/// eye casts the sphere's shadow on the plane.
fn shadow_scene(light: Light, blocker: bool) -> Scene {
    let plane = HPlane::orthogonal_at(&at(DVec3::Z, 1.5), &at(DVec3::Z, 1.6)).expect("plane");
    let mut objects = vec![obj(Shape::Plane(Box::new(plane)), 0)];
    if blocker {
        objects.push(obj(sphere(at(DVec3::new(0.0, 0.25, 1.0), 1.0), 0.12), 1));
    }
    let mut s = scene(
        settings(Net::Euclidean, 96, 0.1),
        default_camera(0.1),
        vec![grey(), flat(1.0, 0.0, 0.0)],
        vec![light],
        objects,
    );
    s.settings.ambient = Rgb::new(1.0, 1.0, 1.0);
    s
}

/// The light of the soft-shadow scene, above the eye.
fn shadow_light(radius: f64, samples: u32) -> Light {
    area_light(at(DVec3::new(0.0, 1.0, 0.25), 0.7), 30.0, radius, samples)
}

/// Plane pixels (grey) strictly between umbra and full light, as the share
/// of the light that reaches them: `(I - A) / (L - A)` with `A` the
/// ambient term and `L` the unshadowed radiance. Counts those with a
/// visibility in `(0.05, 0.95)`, and returns with it the number of plane
/// pixels that are in the umbra (visibility below 0.05) or penumbra.
fn penumbra(radius: f64, samples: u32) -> (usize, usize) {
    let lit = draw(&shadow_scene(shadow_light(radius, samples), false));
    let shadowed = draw(&shadow_scene(shadow_light(radius, samples), true));
    let ambient = 0.1f32;
    let (mut between, mut dark) = (0, 0);
    for (s, l) in shadowed.pixels().iter().zip(lit.pixels()) {
        // The red blocker and the background are not the plane.
        if (s[0] - s[1]).abs() > 1e-6 || (s[1] - s[2]).abs() > 1e-6 {
            continue;
        }
        let v = (s[0] - ambient) / (l[0] - ambient);
        if v < 0.95 {
            dark += 1;
            if v > 0.05 {
                between += 1;
            }
        }
    }
    (between, dark)
}

/// As its radius shrinks to 1e-4, an area light renders as the point light
/// at its centre: every pixel of the mixed scene (spheres, a polygon, a rod,
/// a cylinder, a mirror, two lights) within 1/255 on all but 0.1 % of
/// pixels (a shadow-edge pixel may flip on a shift of 1e-4).
#[test]
fn a_tiny_area_light_is_the_point_light() {
    let point = mixed_scene(Net::Euclidean, 96, 0.12);
    let point_img = draw(&point);
    for samples in [1, 4] {
        let mut tiny = point.clone();
        for l in &mut tiny.lights {
            l.radius = 1e-4;
            l.samples = samples;
        }
        let share = agreement(&draw(&tiny), &point_img, 1.0 / 255.0);
        assert!(share >= 0.999, "{samples} samples: {share}");
    }
}

/// The weighting keeps the light's power: a white Lambertian plane facing an
/// unoccluded area light of radius `r` at distance `D` from its centre gets
/// the point light's `1/(4 pi sinh^2 D)` on the axis (the flux through the
/// concentric sphere of radius `D`), for small and large radii; with 1024
/// stratified samples to 1e-4 (measured 3e-6). A shading point inside the
/// light gets nothing from it. The eye looks at the plane's point on the
/// axis from beside it, so that its ray does not pass the light (lights
/// are seen: `visible_lights.rs`).
#[test]
fn an_area_light_gives_a_facing_surface_the_point_lights_irradiance() {
    for (plane_at, light_at, radius) in [(1.5, 0.2, 0.05), (1.5, 0.2, 0.8), (3.0, 1.0, 1.5)] {
        let plane = HPlane::orthogonal_at(&at(DVec3::Z, plane_at), &at(DVec3::Z, plane_at + 0.1))
            .expect("plane");
        let white = Material {
            ambient: Rgb::BLACK,
            diffuse: Rgb::new(1.0, 1.0, 1.0),
            ..flat(0.0, 0.0, 0.0)
        };
        let target = at(DVec3::Z, plane_at);
        let beside = |s: f64| {
            hgeom::HLine::from_point_direction(&target, DVec3::new(1.0, 0.0, -0.4))
                .and_then(|l| l.point_at(s))
                .expect("a point beside the target")
        };
        let camera = hscene_ir::Camera {
            eye: beside(0.2),
            target,
            up: Some(at(DVec3::Y, 0.5)),
        };
        let s = scene(
            settings(Net::Euclidean, 3, 0.01),
            camera,
            vec![white],
            vec![area_light(at(DVec3::Z, light_at), 1.0, radius, 1024)],
            vec![obj(Shape::Plane(Box::new(plane)), 0)],
        );
        let img = draw(&s);
        let r = plane_at - light_at;
        let want = 1.0 / (4.0 * std::f64::consts::PI * r.sinh().powi(2));
        let got = f64::from(img.get(1, 1)[0]);
        assert!(
            (got - want).abs() < 1e-4 * want,
            "radius {radius}: {got} vs {want}"
        );
        // The same plane inside a light that reaches past it: dark.
        let mut inside = s.clone();
        inside.lights[0].radius = r + 0.1;
        assert_eq!(draw(&inside).get(1, 1)[0], 0.0);
    }
}

/// Soft shadows: a sphere's shadow on a plane from an area light has a
/// penumbra, pixels strictly between umbra and full light, and it widens
/// with the light's radius; the point light's shadow has (almost) none
/// (only pixels cut by the shadow's edge could be, and one sample per pixel
/// never is).
#[test]
fn area_lights_cast_soft_shadows() {
    let (hard, hard_dark) = penumbra(0.0, 1);
    assert!(hard_dark > 200, "the shadow is in view: {hard_dark}");
    assert!(
        hard <= hard_dark / 100,
        "point light: {hard} of {hard_dark}"
    );
    let mut last = hard;
    for radius in [0.05, 0.1, 0.2] {
        let (soft, dark) = penumbra(radius, 64);
        assert!(soft > last + 20, "radius {radius}: {soft} after {last}");
        assert!(dark >= hard_dark / 2, "radius {radius}: shadow {dark}");
        last = soft;
    }
}

/// Area lights draw their sample points from the pixel sample's own
/// stream: the same seed gives the same image on 1 or 3 threads, with and
/// without anti-aliasing and in net 4 (whose nodes are shared by pixels);
/// another seed moves the samples.
#[test]
fn area_lights_are_deterministic_across_threads() {
    let s = shadow_scene(shadow_light(0.15, 3), true);
    let opts = |samples, seed, threads| RenderOptions {
        samples: Some(samples),
        seed,
        threads: Some(threads),
        ..Default::default()
    };
    for (net, samples) in [
        (Net::Euclidean, 1),
        (Net::Euclidean, 4),
        (Net::EquidistantInterpolated, 1),
        (Net::EquidistantInterpolated, 2),
    ] {
        let o = |seed, threads| RenderOptions {
            net: Some(net),
            ..opts(samples, seed, threads)
        };
        let a = draw_with(&s, &o(5, 1));
        let b = draw_with(&s, &o(5, 3));
        assert_eq!(a, b, "{net:?}, {samples} samples: threads do not matter");
        let c = draw_with(&s, &o(6, 3));
        assert_ne!(a, c, "{net:?}, {samples} samples: the seed matters");
    }
}

/// The samples on an area light are placed by the geometry, not by the
/// coordinates: moving the eye, the target, the up point, the objects and
/// the light by one isometry leaves the soft-shadow image unchanged (three
/// random isometries with translation parts of length 2.5 to 5; at most
/// 0.1 % of pixels off by more than 1/255).
#[test]
fn area_lights_move_with_the_scene() {
    let base = shadow_scene(shadow_light(0.15, 16), true);
    let before = draw(&base);
    let mut rng = SplitMix64::new(99);
    for case in 0..3 {
        let iso = random_isometry(&mut rng, 5.0, false);
        let share = agreement(&draw(&moved(&base, &iso)), &before, 1.0 / 255.0);
        assert!(share >= 0.999, "isometry {case}: {share}");
    }
}
