//! `irradiance_at = D` on a light: a surface facing the light at distance
//! `D` receives exactly the colour given, whatever `D` (the intensity is
//! scaled by `4 pi sinh^2 D`, the fall-off takes it back).

use hscene_test_support::scenes::draw;

/// A white Lambertian sphere whose near pole is 1.5 from the eye; the light
/// sits at the eye, so the pole faces it (cos = 1) and its radiance is the
/// irradiance the light delivers there.
#[test]
fn a_surface_at_the_chosen_distance_receives_the_given_colour() {
    for (d, pole) in [(1.5f64, 1.5f64), (0.75, 1.5), (3.0, 1.5)] {
        let c = 1f64.tanh(); // ball coordinate of distance 2
        let src = format!(
            "Globals {{ resolution = (3, 3); window_size = (0.2, 0.2); to = (0, 0, 0.1); ambient = (0, 0, 0); }}
             Points {{ (0, 0, {c:.17}); (0, 0, 0); }}
             BRDFs {{ ambient = (0, 0, 0), diffuse = (1, 1, 1), specular = (0, 0, 0); }}
             Lights {{ %2, (0.5, 0.25, 0.125), (0, 0, 0), irradiance_at = {d}; }}
             Objects {{ Sphere %1, 0.5, #1; }}"
        );
        let compiled = hscene_lang::compile(&src);
        assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
        let img = draw(&compiled.scene.unwrap());
        // At the pole the irradiance is E sinh^2(d) / sinh^2(pole).
        let k = d.sinh().powi(2) / f64::sinh(pole).powi(2);
        for (got, e) in img.get(1, 1).into_iter().zip([0.5, 0.25, 0.125]) {
            assert!(
                (f64::from(got) - e * k).abs() < 1e-6 * e * k.max(1.0),
                "{d}: {got}"
            );
        }
    }
}

/// The white sphere of the test above with its near pole `pole` from the
/// eye, lit by `light` (a light statement's point and options around the
/// colours `(0.5, 0.25, 0.125), (0, 0, 0)`); the middle pixel.
fn pole_pixel(camera: &str, light_point: &str, options: &str, pole: f64) -> [f32; 3] {
    let c = 1f64.tanh();
    let src = format!(
        "Globals {{ resolution = (3, 3); window_size = (0.2, 0.2); {camera} ambient = (0, 0, 0); }}
         Points {{ (0, 0, {c:.17}); (0, 0, 0); }}
         BRDFs {{ ambient = (0, 0, 0), diffuse = (1, 1, 1), specular = (0, 0, 0); }}
         Lights {{ {light_point}, (0.5, 0.25, 0.125), (0, 0, 0), irradiance_at = 1{options}; }}
         Objects {{ Sphere %1, {}, #1; }}",
        2.0 - pole
    );
    let compiled = hscene_lang::compile(&src);
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    draw(&compiled.scene.unwrap()).get(1, 1)
}

/// `near = D`: a surface nearer the light than `D` receives what it would
/// at `D`; one farther, what it always did.
#[test]
fn near_bounds_the_fall_off() {
    let camera = "to = (0, 0, 0.1);";
    for (pole, near) in [(0.3f64, 0.6f64), (0.05, 0.6), (1.5, 0.6), (0.3, 0.2)] {
        let got = pole_pixel(camera, "%2", &format!(", near = {near}"), pole);
        let k = 1f64.sinh().powi(2) / pole.max(near).sinh().powi(2);
        for (g, e) in got.into_iter().zip([0.5, 0.25, 0.125]) {
            assert!(
                (f64::from(g) - e * k).abs() < 1e-6 * e * k.max(1.0),
                "pole {pole}, near {near}: {g} against {}",
                e * k
            );
        }
    }
}

/// `camera` as a light's point puts it at the eye, wherever the eye is:
/// the picture is the one with a light written at the eye's point.
#[test]
fn a_camera_light_is_at_the_eye() {
    for camera in [
        "to = (0, 0, 0.1);",
        "from = (0, 0, -0.2); to = (0, 0, 0.1);",
    ] {
        let eye = if camera.starts_with("from") {
            "(0, 0, -0.2)"
        } else {
            "%2"
        };
        let written = pole_pixel(camera, eye, ", near = 0.4", 0.3);
        let carried = pole_pixel(camera, "camera", ", near = 0.4", 0.3);
        assert_eq!(written, carried, "{camera}");
    }
}
