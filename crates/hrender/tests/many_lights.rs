//! Light selection with many lights: one light unit drawn per vertex
//! (`light_select.rs`) converges to what sampling every light gives, and
//! the rays a path traces do not grow with the number of lights.

use hgeom::Ray;
use hrender::{
    Integrator, PathTracer, PixelNet, PreparedScene, Sample, SampleStream, TraceStats, Whitted,
};
use hscene_ir::Scene;

fn compile(src: &str) -> Scene {
    let compiled = hscene_lang::compile(src);
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    compiled.scene.expect("a scene")
}

/// A ball filling the view, a small one casting shadows on it, a floor,
/// and `count` point lights of different colours on a ring between the
/// eye and the ball (deterministic positions).
fn ring_of_lights(count: u32) -> Scene {
    let mut lights = String::new();
    for k in 0..count {
        let a = std::f64::consts::TAU * f64::from(k) / f64::from(count);
        let h = 0.05 + 0.1 * f64::from(k % 5) / 5.0;
        let c = [1.0 + f64::from(k % 3), 1.0 + f64::from(k % 2), 1.0];
        let s = 8.0 / f64::from(count);
        lights += &format!(
            "({:.4}, {:.4}, {h:.4}), ({:.4}, {:.4}, {:.4}), (0, 0, 0);\n",
            0.3 * a.cos(),
            0.3 * a.sin(),
            c[0] * s,
            c[1] * s,
            c[2] * s
        );
    }
    compile(&format!(
        "Globals {{ resolution = (16, 16); fov = 100; ambient = (0, 0, 0); background = (0, 0, 0); }}
         BRDFs {{ matte: diffuse = (0.8, 0.6, 0.4); floor: diffuse = (0.5, 0.7, 0.5); }}
         Lights {{ {lights} }}
         Objects {{ Sphere (0, 0, 0.45), 0.25, #matte;
                   Sphere (0.08, 0.05, 0.17), 0.04, #matte;
                   Plane (0, -0.3, 0), (0.2, -0.3, 0.3), (-0.2, -0.32, 0.3), #floor; }}"
    ))
}

/// Radiance along each pixel-centre ray, drawn `draws` times, with the
/// rays traced in all.
fn trace_pixels(
    scene: &Scene,
    integrator: &dyn Integrator,
    draws: u64,
    size: u32,
) -> (Vec<Vec<[f64; 3]>>, u64) {
    let frame = hrender::canonical_frame(&scene.camera).expect("a camera");
    let net = PixelNet::new(
        scene.settings.net,
        scene.settings.window,
        frame.view_distance,
    );
    let mut out = Vec::new();
    let mut stats = TraceStats::default();
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
                    let mut stream = SampleStream::new(7919 * u64::from(j * size + i) + k);
                    let c = integrator.radiance(&ray, &mut stream, &mut stats);
                    [c.r, c.g, c.b]
                })
                .collect();
            out.push(pixel);
        }
    }
    assert_eq!(stats.failures, 0);
    (out, stats.rays)
}

/// With 64 point lights and paths ended at their first diffuse vertex,
/// the mean of the one-light estimates is Whitted's sum over all 64
/// lights, pixel by pixel, within five standard errors of the draws (the
/// tolerance follows the estimator's own variance; the seed is fixed).
#[test]
fn one_of_sixty_four_lights_converges_to_all_of_them() {
    let scene = ring_of_lights(64);
    let frame = hrender::canonical_frame(&scene.camera).expect("a camera");
    let prepared = PreparedScene::for_camera(&scene, &frame).expect("prepares");
    let (whitted, _) = trace_pixels(&scene, &Whitted::new(&prepared), 1, 16);
    let direct = PathTracer::new(&prepared).direct_only();
    let (paths, rays) = trace_pixels(&scene, &direct, 400, 16);
    let mut lit = 0;
    for (w, draws) in whitted.iter().zip(&paths) {
        let w = w[0];
        lit += usize::from(w.iter().any(|c| *c > 0.0));
        for c in 0..3 {
            let values: Vec<f64> = draws.iter().map(|d| d[c]).collect();
            let n = values.len() as f64;
            let mean = values.iter().sum::<f64>() / n;
            let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
            let error = (var / n).sqrt();
            assert!(
                (mean - w[c]).abs() <= 5.0 * error + 1e-9 * w[c].abs().max(1e-6),
                "{mean} vs {} (error {error})",
                w[c]
            );
        }
    }
    assert!(lit > 40, "only {lit} lit pixels");
    // One primary ray and at most one shadow ray per path.
    assert!(rays <= 2 * 256 * 400, "{rays} rays");
}

/// The rays a full path traces hardly change from one light to 64: one
/// shadow ray per vertex, whatever the number of lights (counted, not
/// timed). Sampling every light traced 64 per vertex.
#[test]
fn rays_per_path_are_flat_in_the_number_of_lights() {
    let per_path = |count: u32| {
        let scene = ring_of_lights(count);
        let frame = hrender::canonical_frame(&scene.camera).expect("a camera");
        let prepared = PreparedScene::for_camera(&scene, &frame).expect("prepares");
        let (_, rays) = trace_pixels(&scene, &PathTracer::new(&prepared), 64, 16);
        rays as f64 / f64::from(256 * 64)
    };
    let (one, many) = (per_path(1), per_path(64));
    eprintln!("rays per path: {one:.2} with 1 light, {many:.2} with 64");
    assert!(many < 1.25 * one, "{one} vs {many}");
    assert!(many < 12.0, "{many}");
}
