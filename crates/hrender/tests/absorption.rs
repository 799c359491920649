//! Tinted glass: Beer-Lambert absorption over a known geodesic length, in
//! both integrators and along shadow rays.

use hrender::RenderOptions;
use hscene_ir::{IntegratorKind, Scene};

/// A clear absorbing ball of radius `r` whose centre is `c` from the eye
/// on the line of sight, in front of a white background; `extra` objects
/// and lights as given.
fn scene(r: f64, c: f64, absorption: &str, integrator: &str) -> Scene {
    let z = (c / 2.0).tanh();
    let source = format!(
        "Globals {{ resolution = (1, 1); from = (0, 0, 0); to = (0, 0, {z}); \
         background = (1, 1, 1); integrator = {integrator}; recursion_depth = 8; }}\n\
         BRDFs {{ glass: trans = 1, absorption = {absorption}; }}\n\
         Objects {{ Sphere (0, 0, {z}), {r}, #glass; }}\n"
    );
    let out = hscene_lang::compile(&source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

fn centre_pixel(scene: &Scene, samples: u32) -> [f32; 3] {
    let options = RenderOptions {
        samples: Some(samples),
        ..RenderOptions::default()
    };
    hrender::render(scene, &options, &|_| {})
        .unwrap()
        .image
        .get(0, 0)
}

/// The central ray crosses a diameter, `2r` of glass: each channel keeps
/// `exp(-2 r σ)`, in the Whitted tracer and in the path tracer (index 1,
/// no scattering: the path is deterministic).
#[test]
fn light_through_a_diameter_keeps_exp_minus_two_r_sigma() {
    let (r, sigma) = (0.7, [0.2, 1.0, 3.0]);
    for integrator in ["whitted", "path"] {
        let s = scene(
            r,
            2.0,
            &format!("({}, {}, {})", sigma[0], sigma[1], sigma[2]),
            integrator,
        );
        assert!(matches!(
            s.settings.integrator,
            IntegratorKind::Whitted | IntegratorKind::Path
        ));
        let got = centre_pixel(&s, 1);
        for c in 0..3 {
            let want = (-2.0 * r * sigma[c]).exp();
            assert!(
                (f64::from(got[c]) - want).abs() < 1e-5,
                "{integrator}: channel {c}: {} against {want}",
                got[c]
            );
        }
    }
}

/// No absorption: the glass is clear (the light passes whole).
#[test]
fn zero_absorption_is_clear_glass() {
    let got = centre_pixel(&scene(0.7, 2.0, "(0, 0, 0)", "whitted"), 1);
    assert!(got.iter().all(|c| (c - 1.0).abs() < 1e-6), "{got:?}");
}

/// A lamp behind a slab of tinted glass (a ball): the lit point's
/// shadow ray crosses the ball through its centre, and the light it gets
/// is filtered by `exp(-2 r σ)` per channel.
#[test]
fn shadow_rays_through_tinted_glass_are_filtered() {
    let source = |absorption: &str| {
        format!(
            "Globals {{ resolution = (1, 1); from = (0, 0, 0); to = (0, 0, 0.3); \
             background = (0, 0, 0); recursion_depth = 8; }}\n\
             Points {{ a = (-0.1, -0.1, 0.6); b = (0.1, -0.1, 0.6); c = (0, 0.1, 0.6); }}\n\
             BRDFs {{ wall: diffuse = (1, 1, 1); glass: trans = 1, absorption = {absorption}; }}\n\
             Lights {{ (0, 0, 0.1), (1, 1, 1), (0, 0, 0); }}\n\
             Objects {{ Plane %a, %c, %b, #wall; Sphere (0, 0, 0.35), 0.2, #glass; }}\n"
        )
    };
    let compile = |a: &str| {
        let out = hscene_lang::compile(&source(a));
        out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
    };
    // The camera ray crosses the glass too: both the lamp's light on the
    // wall and the view of the wall pass the same diameter, 2r each.
    let clear = centre_pixel(&compile("(0, 0, 0)"), 1);
    let tinted = centre_pixel(&compile("(0.5, 1, 2)"), 1);
    for (c, sigma) in [0.5f64, 1.0, 2.0].into_iter().enumerate() {
        let want = (-2.0 * 2.0 * 0.2 * sigma).exp();
        let ratio = f64::from(tinted[c]) / f64::from(clear[c]);
        assert!(
            (ratio - want).abs() < 1e-4,
            "channel {c}: {ratio} against {want}"
        );
    }
}

/// Tinted honeycomb faces are sheets: each crossing at normal incidence
/// keeps `exp(-σ)`, and layers multiply. Along the axis of `{4,3,5}`
/// through face centres (perpendicular to every face it crosses), a
/// `depth = 1` honeycomb puts two faces in the way: `exp(-2σ)` of the
/// white background comes through, in both integrators.
#[test]
fn tinted_faces_filter_per_crossing() {
    let sigma: [f64; 3] = [0.1, 0.5, 1.5];
    for integrator in ["whitted", "path"] {
        let source = format!(
            "Globals {{ resolution = (33, 33); from = (0, 0, 0); to = (0, 0, 0.3); \
             background = (1, 1, 1); integrator = {integrator}; recursion_depth = 8; \
             ambient = (0, 0, 0); }}\n\
             BRDFs {{ tint: ambient = (0, 0, 0), diffuse = (0, 0, 0), specular = (0, 0, 0), \
             trans = 1, absorption = ({}, {}, {}); }}\n\
             Objects {{ Honeycomb {{4,3,5}}, #tint, faces = #tint, depth = 1; }}\n",
            sigma[0], sigma[1], sigma[2]
        );
        let out = hscene_lang::compile(&source);
        let scene = out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics));
        // Not one pixel: a pixel of 60° would stop the walk (its pixel
        // horizon) before the second face.
        let options = RenderOptions {
            samples: Some(1),
            ..RenderOptions::default()
        };
        let got = hrender::render(&scene, &options, &|_| {})
            .unwrap()
            .image
            .get(16, 16);
        for (g, s) in got.iter().zip(sigma) {
            let want = (-2.0 * s).exp();
            assert!(
                (f64::from(*g) - want).abs() < 1e-5,
                "{integrator}: {got:?}, want exp(-2 {s}) = {want}"
            );
        }
    }
}
