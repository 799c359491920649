//! The field of view and fog, against closed forms: `fov = 60` at a view
//! distance of 0.1 draws what `window_size = (0.11547, 0.11547)` draws;
//! fog mixes a surface at hyperbolic distance `s` by exactly `exp(-s/D)`,
//! a far surface and a ray leaving the scene take the fog colour.

use hrender::Image;
use hscene_ir::Scene;
use hscene_test_support::scenes::{agreement, draw};

fn compile(src: &str) -> Scene {
    let compiled = hscene_lang::compile(src);
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    compiled.scene.expect("a scene")
}

/// Spheres off the axis and a polygon, lit, so that every window change
/// would move an edge.
fn view_scene(view: &str, net: u32) -> Scene {
    compile(&format!(
        "Globals {{ resolution = (40, 30); net_type = {net}; to = (0, 0, 0.1); {view} ambient = (0.3, 0.3, 0.3); }}
         Points {{ (0.02, 0.01, 0.3); (-0.05, 0.0, 0.25); (0.0, 0.3, 0.2); (0.3, -0.1, 0.5); (-0.3, -0.1, 0.5); (0.0, 0.2, 0.5); }}
         BRDFs {{ ambient = (1, 0.5, 0.2), diffuse = (0.6, 0.6, 0.6), specular = (0.3, 0.3, 0.3), shininess = 20; }}
         Lights {{ %3, (3, 3, 3), (3, 3, 3); }}
         Objects {{ Sphere %1, 0.05, #1; Sphere %2, 0.03, #1; Polygon (%4, %5, %6), #1; }}"
    ))
}

/// `fov = 60` with `to = (0, 0, 0.1)` is the window `2 * 0.1 * tan(30 deg)
/// = 0.1154700538...` of net 0: every pixel equals that of the window
/// written out in full, and that of the five digits `0.11547` (the pixels
/// move by less than 1e-4 of a pixel, so no sample changes side), up to
/// the rounding of the view distance in the camera's frame (the windows
/// differ in the last bit, the colours by 1e-6 at most).
#[test]
fn fov_60_is_the_window_0_11547() {
    let by_fov = draw(&view_scene("fov = 60;", 0));
    let full = 2.0 * 0.1 * 30f64.to_radians().tan();
    let exact = draw(&view_scene(
        &format!("window_size = ({full:.17}, {:.17});", full * 0.75),
        0,
    ));
    assert_eq!(agreement(&by_fov, &exact, 1e-6), 1.0);
    // Height follows the aspect ratio: 0.11547 * 30/40 = 0.0866025.
    let five = draw(&view_scene("window_size = (0.11547, 0.0866025);", 0));
    assert_eq!(agreement(&by_fov, &five, 1e-4), 1.0);
    assert!(
        by_fov.pixels().iter().any(|p| p[0] > 0.5),
        "something is drawn"
    );
    // A window 1 % wider is visibly different: the comparison can tell.
    let wider = draw(&view_scene("window_size = (0.1166, 0.08745);", 0));
    assert!(agreement(&by_fov, &wider, 1e-4) < 0.99);
}

/// For the other nets `fov` opens the same angle at the eye: the object
/// straddling the axis comes out the same width (within a pixel) in every
/// net, since near the axis they all agree.
#[test]
fn fov_means_the_same_angle_in_every_net() {
    let width = |img: &Image| {
        (0..img.width())
            .filter(|&x| img.get(x, 15)[0] > 0.1)
            .count() as i64
    };
    let w0 = width(&draw(&view_scene("fov = 60;", 0)));
    assert!(w0 > 3);
    for net in 1..=4 {
        let w = width(&draw(&view_scene("fov = 60;", net)));
        assert!((w - w0).abs() <= 1, "net {net}: {w} against {w0}");
    }
}

fn fog_scene(extra: &str) -> Scene {
    // A sphere of radius 0.5 whose centre is at hyperbolic distance 2 on
    // the view axis: the middle pixel sees its near pole at s = 1.5 (ball
    // coordinate tanh(2/2)); ambient-only, so its radiance is exactly its
    // ambient colour; another sphere far away at distance 14, radius 1.
    let c = 1f64.tanh();
    let far = 7f64.tanh();
    compile(&format!(
        "Globals {{ resolution = (3, 3); window_size = (0.2, 0.2); to = (0, 0, 0.1); ambient = (1, 1, 1); background = (0, 0, 1); {extra} }}
         Points {{ (0, 0, {c:.17}); ({far:.17}, 0, 0); }}
         BRDFs {{ ambient = (0.9, 0.3, 0.1), diffuse = (0, 0, 0), specular = (0, 0, 0); }}
         Objects {{ Sphere %1, 0.5, #1; Sphere %2, 1, #1; }}"
    ))
}

#[test]
fn fog_mixes_by_the_hyperbolic_length() {
    let fog = [0.2, 0.4, 0.6];
    let img = draw(&fog_scene("fog_color = (0.2, 0.4, 0.6); fog_distance = 2;"));
    let keep = (-1.5f64 / 2.0).exp();
    let centre = img.get(1, 1);
    for (k, own) in [0.9, 0.3, 0.1].into_iter().enumerate() {
        let expect = own * keep + fog[k] * (1.0 - keep);
        assert!((f64::from(centre[k]) - expect).abs() < 1e-6, "{centre:?}");
    }
    // The corner pixel's ray leaves the scene: the fog colour, not the
    // background.
    assert_eq!(img.get(0, 0), [0.2, 0.4, 0.6]);
    // Without fog the same pixels are the sphere's colour and the
    // background.
    let clear = draw(&fog_scene(""));
    assert_eq!(clear.get(1, 1), [0.9, 0.3, 0.1]);
    assert_eq!(clear.get(0, 0), [0.0, 0.0, 1.0]);
}

/// A surface 13 units away in a fog of distance 0.25 (`exp(-52)`, below
/// f32's resolution next to the fog colour) takes the fog colour exactly.
#[test]
fn a_far_surface_takes_the_fog_colour() {
    let src = "Globals { resolution = (3, 3); window_size = (0.2, 0.2); to = (0.1, 0, 0); ambient = (1, 1, 1); fog_color = (0.2, 0.4, 0.6); fog_distance = 0.25; }";
    let far = 7f64.tanh();
    let scene = compile(&format!(
        "{src} Points {{ ({far:.17}, 0, 0); }} BRDFs {{ ambient = (0.9, 0.3, 0.1), diffuse = (0, 0, 0), specular = (0, 0, 0); }} Objects {{ Sphere %1, 1, #1; }}"
    ));
    let img = draw(&scene);
    assert_eq!(img.get(1, 1), [0.2, 0.4, 0.6]);
    // Without fog the middle pixel sees the far sphere's own colour: it is
    // really there.
    let plain = src.replace("fog_color = (0.2, 0.4, 0.6); fog_distance = 0.25;", "");
    let scene = compile(&format!(
        "{plain} Points {{ ({far:.17}, 0, 0); }} BRDFs {{ ambient = (0.9, 0.3, 0.1), diffuse = (0, 0, 0), specular = (0, 0, 0); }} Objects {{ Sphere %1, 1, #1; }}"
    ));
    assert_eq!(draw(&scene).get(1, 1), [0.9, 0.3, 0.1]);
}

/// The ball coordinates of the point at distance `rho` from the foot of
/// the view axis at distance 1, in the h-plane orthogonal to the axis
/// there, in direction `(cos phi, sin phi)`: on the hyperboloid `cosh(rho)
/// (cosh 1, 0, 0, sinh 1) + sinh(rho) (0, cos phi, sin phi, 0)`.
fn on_mirror(rho: f64, phi: f64) -> String {
    let x0 = rho.cosh() * 1f64.cosh();
    let (x, y, z) = (
        rho.sinh() * phi.cos(),
        rho.sinh() * phi.sin(),
        rho.cosh() * 1f64.sinh(),
    );
    format!(
        "({:.17}, {:.17}, {:.17})",
        x / (1.0 + x0),
        y / (1.0 + x0),
        z / (1.0 + x0)
    )
}

/// A mirror fogs its reflection by the whole path: a mirror at distance 1
/// showing a surface 1.75 behind it (along the reflected ray) gives
/// `e^{-1/D} (e^{-1.75/D} L + (1 - e^{-1.75/D}) C) + (1 - e^{-1/D}) C`.
#[test]
fn reflected_segments_are_fogged_too() {
    // An ideal mirror (reflection 1, nothing else) orthogonal to the view
    // axis at distance 1; the middle pixel's ray comes straight back
    // through the eye to a sphere of radius 0.25 about the point at
    // distance 1 behind the eye: its near pole is 2 - 0.25 = 1.75 from
    // the mirror. The eye is no obstacle.
    let base = |fog: &str| {
        compile(&format!(
            "Globals {{ resolution = (3, 3); window_size = (0.2, 0.2); to = (0, 0, 0.1); ambient = (1, 1, 1); recursion_depth = 1; {fog} }}
             Points {{ {}; {}; {}; (0, 0, {back:.17}); }}
             BRDFs {{ ambient = (0, 0, 0), diffuse = (0, 0, 0), specular = (0, 0, 0), alpha = 1; ambient = (0.9, 0.3, 0.1), diffuse = (0, 0, 0), specular = (0, 0, 0); }}
             Objects {{ Plane %1, %2, %3, #1; Sphere %4, 0.25, #2; }}",
            on_mirror(0.5, 0.0),
            on_mirror(0.5, 2.0),
            on_mirror(0.5, 4.0),
            back = -(0.5f64.tanh()),
        ))
    };
    let clear = draw(&base(""));
    let own = [0.9, 0.3, 0.1];
    for (got, own) in clear.get(1, 1).into_iter().zip(own) {
        let got = f64::from(got);
        assert!(
            (got - own).abs() < 1e-6,
            "the mirror shows the sphere: {got}"
        );
    }
    let img = draw(&base("fog_color = (0.2, 0.4, 0.6); fog_distance = 3;"));
    let (k1, k2) = ((-1.0f64 / 3.0).exp(), (-1.75f64 / 3.0).exp());
    for (k, fog) in [0.2, 0.4, 0.6].into_iter().enumerate() {
        let expect = k1 * (k2 * own[k] + (1.0 - k2) * fog) + (1.0 - k1) * fog;
        let got = f64::from(img.get(1, 1)[k]);
        assert!((got - expect).abs() < 1e-6, "{got} against {expect}");
    }
}
