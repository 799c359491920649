//! Area lights are seen: directly, and in a mirror, with the radiance
//! their sphere emits (`PreparedLight::radiance`: Φ / (4π sinh² a)), under
//! both integrators; point lights have no surface to see.

use crate::one_pixel::{compile, pixel};

fn radiance(phi: f64, a: f64) -> f64 {
    phi / (4.0 * std::f64::consts::PI * a.sinh().powi(2))
}

#[test]
fn an_area_light_is_seen_with_the_radiance_it_emits() {
    for integrator in ["whitted", "path"] {
        let scene = compile(&format!(
            "Globals {{ resolution = (1, 1); from = (0, 0, 0); to = (0, 0, 0.3); \
             integrator = {integrator}; }}\n\
             Lights {{ (0, 0, 0.5), (2, 1, 0.5), (0, 0, 0), radius = 0.1, samples = 4; }}\n"
        ));
        let got = pixel(&scene);
        for (c, phi) in [2.0, 1.0, 0.5].into_iter().enumerate() {
            let want = radiance(phi, 0.1);
            assert!(
                (f64::from(got[c]) - want).abs() < 1e-4 * want,
                "{integrator}: {got:?}, want {want} in channel {c}"
            );
        }
    }
}

#[test]
fn a_point_light_has_no_surface_to_see() {
    let scene = compile(
        "Globals { resolution = (1, 1); from = (0, 0, 0); to = (0, 0, 0.3); background = (0.1, 0.2, 0.3); }\n\
         Lights { (0, 0, 0.5), (2, 1, 0.5), (0, 0, 0); }\n",
    );
    let got = pixel(&scene);
    assert!((got[2] - 0.3).abs() < 1e-6, "{got:?}");
}

/// Looking down at a level mirror under a light straight above the eye:
/// the central ray comes back up through the light.
#[test]
fn a_mirror_shows_the_light() {
    let scene = compile(
        "Globals { resolution = (1, 1); from = (0, 0, 0); to = (0, -0.1, 0); up = (0, 0, 0.3); recursion_depth = 2; }\n\
         Points { a = (0.3, -0.2, 0); b = (-0.15, -0.2, -0.25980762113533157); c = (-0.15, -0.2, 0.25980762113533157); }\n\
         BRDFs { mirror: alpha = 1; }\n\
         Lights { (0, 0.4, 0), (1, 1, 1), (0, 0, 0), radius = 0.05, samples = 1; }\n\
         Objects { Plane %a, %b, %c, #mirror; }\n",
    );
    let got = pixel(&scene);
    let want = radiance(1.0, 0.05);
    assert!(
        (f64::from(got[0]) - want).abs() < 1e-4 * want,
        "{got:?} against {want}"
    );
}
