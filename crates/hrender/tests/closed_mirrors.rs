//! Rays bouncing inside a closed mirror: the eye inside a mirror h-sphere,
//! every ray reflected to the deepest recursion allowed. Each bounce starts
//! from its hit point put back on the hyperboloid (`tangent.rs`
//! `on_hyperboloid`), so the rounding of one bounce is not carried, grown
//! by `e^{2·chord}`, into the next: the error stays that of one bounce,
//! about `1e-16 e^{3r}` for a sphere of radius `r` (docs/rendering.md,
//! "Rays that bounce many times").

use hrender::RenderOptions;

fn mirror_scene(radius: f64, depth: u32, integrator: &str) -> hscene_ir::Scene {
    let source = format!(
        "Points {{ eye = (0.02, 0.01, 0); c = (0, 0, 0.03); }}\n\
         Globals {{ from = %eye; to = (0.1, 0.02, 0.05); fov = 90; resolution = (24, 24); \
         recursion_depth = {depth}; integrator = {integrator}; }}\n\
         BRDFs {{ m: diffuse = (0.2, 0.2, 0.2), alpha = 1; b: diffuse = (1, 0.3, 0.2); }}\n\
         Objects {{ Sphere %c, {radius}, #m; Sphere (0.2, 0.1, 0), 0.05, #b; }}\n\
         Lights {{ (0, 0.1, 0), (1, 1, 1), (0, 0, 0); }}\n"
    );
    let out = hscene_lang::compile(&source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

fn failures(scene: &hscene_ir::Scene) -> u64 {
    let options = RenderOptions {
        samples: Some(2),
        ..RenderOptions::default()
    };
    hrender::render(scene, &options, &|_| {})
        .unwrap()
        .stats
        .numeric_failures
}

/// Radii 1 to 8 at recursion depth 64 (the most allowed), a perfect mirror
/// (no weight lost, so every level is traced): no pixel fails. Before,
/// radius 2 failed every pixel from depth 5, radius 3 from depth 3.
#[test]
fn the_deepest_recursion_in_a_closed_mirror_holds() {
    for radius in [0.5, 1.0, 2.0, 3.0, 5.0, 8.0] {
        let scene = mirror_scene(radius, 64, "whitted");
        assert_eq!(failures(&scene), 0, "radius {radius}");
    }
}

/// The path tracer's mirror bounces start from projected points too.
#[test]
fn path_traced_bounces_in_a_closed_mirror_hold() {
    for radius in [1.0, 3.0] {
        let scene = mirror_scene(radius, 64, "path");
        assert_eq!(failures(&scene), 0, "radius {radius}");
    }
}

/// A light whose intensity and fall-off are both in range but whose
/// product leaves f32 (colour 1e18 delivered at distance 30: 3.6e44)
/// saturates the pixels it lights instead of failing them.
#[test]
fn a_light_brighter_than_f32_saturates_instead_of_failing() {
    let source = "Points { eye = (0, 0, 0); c = (0.5, 0, 0); }\n\
        Globals { from = %eye; to = %c; fov = 60; resolution = (16, 16); }\n\
        BRDFs { m: diffuse = (0.5, 0.5, 0.5); }\n\
        Objects { Sphere %c, 0.3, #m; }\n\
        Lights { (0, 0.3, 0), (1e18, 1e18, 1e18), (0, 0, 0), irradiance_at = 30; }\n";
    let scene = hscene_lang::compile(source).scene.unwrap();
    let rendered = hrender::render(&scene, &RenderOptions::default(), &|_| {}).unwrap();
    assert_eq!(rendered.stats.numeric_failures, 0);
    let lit = rendered
        .image
        .pixels()
        .iter()
        .filter(|p| p.iter().all(|v| *v == f32::MAX))
        .count();
    assert!(lit > 0, "the ball is drawn, saturated");
}
