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
