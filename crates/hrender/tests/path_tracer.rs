//! The path integrator against closed forms of H³'s radiometry and against
//! the Whitted integrator: the white furnace, the irradiance of an
//! emitting h-sphere (`sinh² a / sinh² d`, not `a² / d²`), direct light
//! equal to Whitted's, invariance under a far isometry, and noise falling
//! as `1 / sqrt(samples)`.

use hgeom::Ray;
use hrender::{
    Integrator, IntegratorKind, PathTracer, PixelNet, PreparedScene, RenderOptions, Sample,
    SampleStream, TraceStats, Whitted,
};
use hscene_ir::{Scene, move_camera, move_object};

fn compile(src: &str) -> Scene {
    let compiled = hscene_lang::compile(src);
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    compiled.scene.expect("a scene")
}

fn path(samples: u32, seed: u64) -> RenderOptions {
    RenderOptions {
        integrator: Some(IntegratorKind::Path),
        samples: Some(samples),
        seed,
        ..RenderOptions::default()
    }
}

fn luminance(p: [f32; 3]) -> f64 {
    (f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2])) / 3.0
}

/// Mean and standard error of the mean of values.
fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

/// The eye inside a closed h-sphere that emits `E` and reflects `ρ`
/// diffusely sees `L = E + ρ L`, so `E / (1 - ρ)`, in every pixel: every
/// bounce of a cosine-sampled Lambertian path carries exactly `ρ`, and
/// Russian roulette keeps the sum unbiased. The test measures the noise
/// across pixels and asks for agreement within five standard errors, and
/// every pixel within reach.
#[test]
fn white_furnace() {
    let scene = compile(
        "Globals { resolution = (16, 16); fov = 120; ambient = (0, 0, 0); }
         BRDFs { wall: diffuse = (0.6, 0.6, 0.6), emission = (0.5, 0.5, 0.5); }
         Objects { Sphere (0, 0, 0), 1.5, #wall; }",
    );
    let image = hrender::render(&scene, &path(64, 1), &|_| {}).expect("renders");
    let expected = 0.5 / (1.0 - 0.6);
    let values: Vec<f64> = image.image.pixels().iter().map(|p| luminance(*p)).collect();
    let (mean, error) = mean_and_error(&values);
    assert!(
        (mean - expected).abs() < 5.0 * error + 1e-6,
        "{mean} vs {expected} (standard error {error})"
    );
    assert!(error < 0.01 * expected, "the test can tell: {error}");
    // Each pixel's 64 paths: Russian roulette gives them a long tail, so
    // a pixel may stray by a third; none by half.
    for v in &values {
        assert!((v - expected).abs() < 0.5 * expected, "{v}");
    }
    // A different albedo, a different answer: the test is not blind.
    let grey = compile(
        "Globals { resolution = (4, 4); fov = 120; ambient = (0, 0, 0); }
         BRDFs { wall: diffuse = (0.3, 0.3, 0.3), emission = (0.5, 0.5, 0.5); }
         Objects { Sphere (0, 0, 0), 1.5, #wall; }",
    );
    let grey = hrender::render(&grey, &path(64, 1), &|_| {}).expect("renders");
    let v = luminance(grey.image.pixels()[5]);
    assert!((v - 0.5 / 0.7).abs() < 0.05, "{v}");
}

/// The irradiance scene: a Lambertian floor (the h-plane `y = 0` through
/// the origin) of albedo `ρ` under an h-sphere of radius `a` emitting `L`,
/// its centre at distance `d` straight above the origin; the one pixel
/// looks at the origin from the side.
fn irradiance_scene(a: f64, d: f64) -> Scene {
    let y = (d / 2.0).tanh();
    compile(&format!(
        "Globals {{ resolution = (1, 1); from = (0.3, 0.25, -0.3); to = (0, 0, 0); fov = 0.5;
                    ambient = (0, 0, 0); background = (0, 0, 0); }}
         BRDFs {{ floor: diffuse = (0.8, 0.8, 0.8); lamp: emission = (1, 1, 1); }}
         Objects {{ Plane (0.5, 0, 0), (0, 0, 0.5), (-0.5, 0, 0.1), #floor;
                    Sphere (0, {y:.17}, 0), {a}, #lamp; }}"
    ))
}

/// A Lambertian floor under an emitting h-sphere reflects
/// `ρ L sinh² a / sinh² d` at the foot of the sphere's centre: the sphere
/// fills the cone `sin α = sinh a / sinh d` about the normal, whose
/// cosine-weighted solid angle is `π sin² α`. Euclidean space would give
/// `ρ L a² / d²`, 87 % more here: the test tells them apart by far.
#[test]
fn hyperbolic_irradiance() {
    let (a, d, rho) = (0.5f64, 1.5f64, 0.8);
    let hyperbolic = rho * a.sinh().powi(2) / d.sinh().powi(2);
    let euclidean = rho * a * a / (d * d);
    let mut estimates = Vec::new();
    for seed in 0..8 {
        let r =
            hrender::render(&irradiance_scene(a, d), &path(1024, seed), &|_| {}).expect("renders");
        estimates.push(luminance(r.image.pixels()[0]));
    }
    let (mean, error) = mean_and_error(&estimates);
    assert!(
        (mean - hyperbolic).abs() < 5.0 * error + 1e-4 * hyperbolic,
        "{mean} vs {hyperbolic} (standard error {error})"
    );
    assert!((mean - euclidean).abs() > 100.0 * error.max(1e-4));
}

/// Radiance along each pixel-centre ray of `scene` through `integrator`,
/// drawn `draws` times with different streams.
fn trace_pixels(
    scene: &Scene,
    integrator: &dyn Integrator,
    draws: u64,
    size: u32,
) -> Vec<Vec<[f64; 3]>> {
    let frame = hrender::canonical_frame(&scene.camera).expect("a camera");
    let net = PixelNet::new(
        scene.settings.net,
        scene.settings.window,
        frame.view_distance,
    );
    let mut out = Vec::new();
    for j in 0..size {
        for i in 0..size {
            let sx = (f64::from(i) + 0.5) / f64::from(size) - 0.5;
            let sy = 0.5 - (f64::from(j) + 0.5) / f64::from(size);
            let Sample::Ray(dir) = net.sample(sx, sy) else {
                panic!("net 0 covers the image");
            };
            let ray = Ray::from_origin_unchecked(dir);
            let pixel = (0..draws)
                .map(|k| {
                    let mut stream = SampleStream::new(1000 * u64::from(j * size + i) + k);
                    let mut stats = TraceStats::default();
                    let c = integrator.radiance(&ray, &mut stream, &mut stats);
                    assert_eq!(stats.failures, 0);
                    [c.r, c.g, c.b]
                })
                .collect();
            out.push(pixel);
        }
    }
    out
}

/// With point lights, Lambertian surfaces, mirrors and clear glass, and
/// paths ended at their first diffuse vertex, the path integrator computes
/// what Whitted's does: the same direct light (a point light of colour `Φ`
/// has intensity `Φ/4`, so `ρ/π · Φ/4 · cos / sinh² r` is Whitted's
/// `ρ Φ cos / (4π sinh² r)`), the same mirror and glass weights, the same
/// shadows through glass. Pixels whose paths are deterministic agree to
/// 1e-9; the others (where Russian roulette cut a long mirror chain) agree
/// within five standard errors of their own draws.
#[test]
fn direct_light_agrees_with_whitted() {
    let scene = compile(
        "Globals { resolution = (24, 24); fov = 100; ambient = (0, 0, 0); background = (0, 0, 0);
                   recursion_depth = 12; }
         BRDFs { matte: diffuse = (0.8, 0.6, 0.4);
                 floor: diffuse = (0.5, 0.7, 0.5);
                 mirror: alpha = 0.9;
                 glass: trans = 0.7, refraction = 1; }
         Lights { (0.2, 0.45, 0.1), (3, 3, 3), (0, 0, 0); (-0.3, 0.2, 0.5), (1, 0.5, 0.2), (0, 0, 0); }
         Objects { Sphere (0, 0, 0.45), 0.25, #matte;
                   Sphere (0.2, -0.05, 0.3), 0.12, #mirror;
                   Sphere (-0.12, 0.06, 0.2), 0.1, #glass;
                   Plane (0, -0.3, 0), (0.2, -0.3, 0.3), (-0.2, -0.32, 0.3), #floor; }",
    );
    let frame = hrender::canonical_frame(&scene.camera).expect("a camera");
    let prepared = PreparedScene::for_camera(&scene, &frame).expect("prepares");
    let whitted = trace_pixels(&scene, &Whitted::new(&prepared), 1, 24);
    let direct = PathTracer::new(&prepared).direct_only();
    let paths = trace_pixels(&scene, &direct, 64, 24);
    let (mut exact, mut lit) = (0, 0);
    for (w, draws) in whitted.iter().zip(&paths) {
        let w = w[0];
        lit += usize::from(w.iter().any(|c| *c > 0.0));
        let deterministic = draws.iter().all(|d| d == &draws[0]);
        for c in 0..3 {
            if deterministic {
                let p = draws[0][c];
                assert!(
                    (p - w[c]).abs() <= 1e-9 * w[c].abs().max(1e-6),
                    "{p} vs {}",
                    w[c]
                );
            } else {
                let values: Vec<f64> = draws.iter().map(|d| d[c]).collect();
                let (mean, error) = mean_and_error(&values);
                assert!(
                    (mean - w[c]).abs() <= 5.0 * error + 1e-9,
                    "{mean} vs {}",
                    w[c]
                );
            }
        }
        exact += usize::from(deterministic);
    }
    eprintln!("{lit} lit pixels, {exact} deterministic");
    assert!(lit > 60, "only {lit} lit pixels");
    assert!(exact > 300, "only {exact} deterministic pixels");
}

/// The image's statistics do not change when the whole scene (objects,
/// lights, camera) moves by an isometry of translation 20: the path tracer
/// works in the camera's frame, where the moved scene is the same.
#[test]
fn invariant_under_a_translation_of_20() {
    let scene = compile(
        "Globals { resolution = (12, 12); fov = 90; ambient = (0, 0, 0); background = (0.05, 0.05, 0.1); }
         BRDFs { matte: diffuse = (0.8, 0.6, 0.4); lamp: emission = (4, 4, 3); shiny: diffuse = (0.2, 0.2, 0.2), specular = (0.6, 0.6, 0.6), shininess = 30; }
         Lights { (0.1, 0.3, 0.2), (2, 2, 2), (0, 0, 0), radius = 0.05; }
         Objects { Sphere (0, 0, 0.4), 0.2, #matte; Sphere (0.25, 0.25, 0.45), 0.08, #lamp;
                   Sphere (-0.2, -0.1, 0.3), 0.1, #shiny;
                   Plane (0, -0.3, 0), (0.2, -0.3, 0.3), (-0.2, -0.32, 0.3), #matte; }",
    );
    let far = hgeom::Isometry::transvection_from_origin(
        hgeom::Point::at_distance_from_origin(hgeom::glam::DVec3::new(0.3, -0.5, 0.8), 20.0)
            .expect("representable"),
    );
    let mut moved = scene.clone();
    moved.objects = scene
        .objects
        .iter()
        .map(|o| move_object(o, &far).expect("representable"))
        .collect();
    for light in &mut moved.lights {
        light.position = far.checked_apply(&light.position).expect("representable");
    }
    move_camera(&mut moved.camera, &far).expect("representable");
    let mean = |s: &Scene, seed: u64| {
        let r = hrender::render(s, &path(64, seed), &|_| {}).expect("renders");
        let v: Vec<f64> = r.image.pixels().iter().map(|p| luminance(*p)).collect();
        v.iter().sum::<f64>() / v.len() as f64
    };
    let near: Vec<f64> = (0..4).map(|s| mean(&scene, s)).collect();
    let far_means: Vec<f64> = (0..4).map(|s| mean(&moved, s + 10)).collect();
    let (a, ea) = mean_and_error(&near);
    let (b, eb) = mean_and_error(&far_means);
    assert!(a > 0.01, "the scene is lit: {a}");
    assert!(
        (a - b).abs() < 5.0 * (ea * ea + eb * eb).sqrt() + 1e-3 * a,
        "{a} ± {ea} vs {b} ± {eb}"
    );
}

/// The noise the render reports falls as `1 / sqrt(samples)`: sixteen
/// times the samples, a quarter of the noise (measured on two renders,
/// not assumed), and adaptive sampling reaches the noise it is asked for.
#[test]
fn noise_falls_as_one_over_root_samples() {
    let scene = irradiance_scene(0.5, 1.5);
    let noise = |samples: u32| {
        hrender::render(&scene, &path(samples, 3), &|_| {})
            .expect("renders")
            .stats
            .noise
            .expect("measurable")
    };
    let ratio = noise(64) / noise(1024);
    assert!((ratio - 4.0).abs() < 0.6, "{ratio}");
    let adaptive = RenderOptions {
        adaptive: Some(hrender::Adaptive {
            noise: 0.02,
            max_samples: 4096,
        }),
        ..path(1, 3)
    };
    let r = hrender::render(&scene, &adaptive, &|_| {}).expect("renders");
    let reached = r.stats.noise.expect("measurable");
    assert!(reached <= 0.02, "{reached}");
    assert!(r.stats.samples < 4096 && r.stats.samples >= 16);
}

/// The same seed gives the same path-traced image on any number of
/// threads.
#[test]
fn same_seed_same_image_on_any_thread_count() {
    let scene = irradiance_scene(0.5, 1.5);
    let mut big = scene.clone();
    big.settings.resolution = hscene_ir::Resolution::new(16, 8).expect("not empty");
    let one = hrender::render(
        &big,
        &RenderOptions {
            threads: Some(1),
            ..path(8, 9)
        },
        &|_| {},
    )
    .expect("renders");
    let two = hrender::render(
        &big,
        &RenderOptions {
            threads: Some(2),
            ..path(8, 9)
        },
        &|_| {},
    )
    .expect("renders");
    assert_eq!(one.image.pixels(), two.image.pixels());
}

/// A Lambertian floor under an emitting geodesic triangle reflects
/// `ρ/π E` at the origin, with `E = L/2 |Σ γ_i (m_i · n)|` (Lambert's
/// formula for a polygon, in the tangent space at the point: the edges'
/// directions `a_i`, the angles `γ_i` between consecutive ones and the unit
/// normals `m_i` of the planes they span; at the ball's centre the unit
/// tangent towards a point is its ball direction). The triangle is sampled
/// exactly by solid angle, so the estimate is also far less noisy than the
/// lobes' directions alone would make it.
#[test]
fn irradiance_under_an_emitting_triangle() {
    let v = [[0.1, 0.3, 0.05], [-0.15, 0.35, 0.1], [0.0, 0.32, -0.2]];
    let scene = compile(&format!(
        "Globals {{ resolution = (1, 1); from = (0.3, 0.25, -0.3); to = (0, 0, 0); fov = 0.5;
                    ambient = (0, 0, 0); background = (0, 0, 0); }}
         BRDFs {{ floor: diffuse = (0.8, 0.8, 0.8); lamp: emission = (1, 1, 1); }}
         Objects {{ Plane (0.5, 0, 0), (0, 0, 0.5), (-0.5, 0, 0.1), #floor;
                    Polygon (({}, {}, {}), ({}, {}, {}), ({}, {}, {})), #lamp; }}",
        v[0][0], v[0][1], v[0][2], v[1][0], v[1][1], v[1][2], v[2][0], v[2][1], v[2][2]
    ));
    let dirs: Vec<hgeom::glam::DVec3> = v
        .iter()
        .map(|p| hgeom::glam::DVec3::new(p[0], p[1], p[2]).normalize())
        .collect();
    let n = hgeom::glam::DVec3::Y;
    let mut sum = 0.0;
    for k in 0..3 {
        let (a, b) = (dirs[k], dirs[(k + 1) % 3]);
        sum += a.angle_between(b) * a.cross(b).normalize().dot(n);
    }
    let expected = 0.8 / std::f64::consts::PI * (0.5 * sum.abs());
    let mut estimates = Vec::new();
    for seed in 0..8 {
        let r = hrender::render(&scene, &path(256, seed), &|_| {}).expect("renders");
        estimates.push(luminance(r.image.pixels()[0]));
    }
    let (mean, error) = mean_and_error(&estimates);
    assert!(
        (mean - expected).abs() < 5.0 * error + 1e-4 * expected,
        "{mean} vs {expected} (standard error {error})"
    );
    assert!(error < 0.02 * expected, "the test can tell: {error}");
}
