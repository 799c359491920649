//! Beyond a quotient space's horizon: where the walk across the domain's
//! faces gives up (the pixel horizon, or the crossing cap down a cusp),
//! the pixels take the space's average appearance, not the background
//! (`space_fill.rs`), under both integrators.

use hrender::{PreparedScene, RenderOptions};
use hscene_ir::{Resolution, Scene};

/// Ambient-only gold (drawn in its ambient colour exactly under
/// Whitted), and a pure blue background no mixture of gold and the fill
/// can equal.
fn compile(camera: &str, globals: &str, objects: &str) -> Scene {
    compile_on("(0, 0, 1)", camera, globals, objects)
}

/// [`compile`] on `background`.
fn compile_on(background: &str, camera: &str, globals: &str, objects: &str) -> Scene {
    let source = format!(
        "Globals {{ resolution = (64, 64); {camera} fov = 90; \
         background = {background}; ambient = (1, 1, 1); {globals} }}\n\
         BRDFs {{ gold: ambient = (0.8, 0.6, 0.2), diffuse = (0, 0, 0); }}\n\
         Objects {{ {objects} }}"
    );
    let out = hscene_lang::compile(&source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

const CAMERA: &str = "from = (0.03, 0.02, 0.01); to = (0.2, 0.1, 0.3);";

/// The picture at `size` squared, one sample a pixel: linear RGB by rows.
fn render(scene: &Scene, size: u32) -> Vec<[f32; 3]> {
    let options = RenderOptions {
        resolution: Resolution::new(size, size),
        samples: Some(1),
        ..RenderOptions::default()
    };
    let r = hrender::render(scene, &options, &|_| {}).expect("the scene renders");
    assert_eq!(r.stats.numeric_failures, 0);
    let image = &r.image;
    (0..image.height())
        .flat_map(|y| (0..image.width()).map(move |x| image.get(x, y)))
        .collect()
}

fn background(p: &[f32; 3]) -> bool {
    *p == [0.0, 0.0, 1.0]
}

/// Seifert-Weber space from inside, 64 pixels wide: its pixel horizon
/// stops the walk well inside distance 12. No pixel is the background
/// (before, 3,268 of 4,096 were, under either integrator); a ray's walk that gave
/// up reports where; and the fill mixes the gold met on average with the
/// blue let through, under both integrators.
#[test]
fn a_space_beyond_its_horizon_shows_its_average_not_the_background() {
    let globals = "space = seifert_weber; domain = 0.03, #gold;";
    let scene = compile(CAMERA, globals, "");
    let camera = hrender::canonical_frame(&scene.camera).expect("a camera");
    let prepared = PreparedScene::for_camera(&scene, &camera).expect("it prepares");
    // Rays in many directions: those that meet nothing gave up, at the
    // horizon (12 without a picture's pixels) or where their crossings ran
    // out, and say where.
    let mut misses = 0;
    for k in 0..400 {
        let (z, phi) = (1.0 - (2 * k + 1) as f64 / 400.0, 2.399963 * k as f64);
        let r = (1.0 - z * z).sqrt();
        let dir = hgeom::glam::DVec3::new(r * phi.cos(), r * phi.sin(), z);
        let traced = prepared.trace(
            &hgeom::Ray::from_origin(dir).expect("a unit direction"),
            1e-9,
        );
        if let hrender::Nearest::Miss = traced.nearest {
            misses += 1;
            let at = traced.gave_up.expect("a miss in a closed space gave up");
            assert!(at > 0.0 && at <= 12.0 + 1e-9, "{at}");
        }
    }
    assert!(misses > 0, "no ray reached the horizon");
    for integrator in ["whitted", "path"] {
        let scene = compile(CAMERA, &format!("{globals} integrator = {integrator};"), "");
        let pixels = render(&scene, 64);
        let shown = pixels.iter().filter(|p| background(p)).count();
        println!(
            "{integrator}: {shown} background pixels of {}",
            pixels.len()
        );
        assert_eq!(shown, 0, "{integrator}");
    }
    let pixels = render(&compile(CAMERA, globals, ""), 64);
    let edge = [0.8f32, 0.6, 0.2];
    let filled = pixels
        .iter()
        .filter(|p| **p != edge && p[0] > 0.0 && p[2] > 0.0)
        .count();
    assert!(filled > 1000, "{filled}");
}

/// The number of pixels of a `size` squared picture (not on its border)
/// brighter than each of their 8 neighbours by more than 0.1 (linear,
/// mean of the channels): the far field's speckle.
fn isolated_bright(pixels: &[[f32; 3]], size: usize) -> usize {
    let lum = |x: usize, y: usize| pixels[y * size + x].iter().sum::<f32>() / 3.0;
    let mut count = 0;
    for y in 1..size - 1 {
        for x in 1..size - 1 {
            let around = (0..9)
                .filter(|k| *k != 4)
                .map(|k| lum(x + k % 3 - 1, y + k / 3 - 1))
                .fold(f32::MIN, f32::max);
            if lum(x, y) > around + 0.1 {
                count += 1;
            }
        }
    }
    count
}

/// Seifert-Weber space's domain is a cell of `{5,3,5}`, and its edges
/// drawn as rods are that honeycomb's: at one sample a pixel, 96 wide,
/// the space has no more isolated bright pixels than the honeycomb (which
/// fills beyond its horizon with its own average). The two walks meet the
/// same edges, and the two averages are taken along the same lines, so
/// no slack is needed (231 against 236). Those pixels are edges met
/// inside the horizon, where the tiles are near a pixel, so the count was
/// the same before the space had its fill; what the fill changed is what
/// lies between them: the picture's mean brightness is the honeycomb's
/// within 3 % (before, 0.142 against 0.237: 40 % darker, the far field
/// edges on the background).
#[test]
fn a_space_at_one_sample_has_no_more_isolated_bright_pixels_than_its_honeycomb() {
    // The manifold scenes' dark background: bright speckle on it is what
    // the eye catches.
    let dark = "(0.02, 0.02, 0.05)";
    let globals = "space = seifert_weber; domain = 0.03, #gold;";
    let space = compile_on(dark, CAMERA, globals, "");
    let honeycomb = compile_on(dark, CAMERA, "", "Honeycomb {5,3,5}, #gold, edges = 0.03;");
    let (space, honeycomb) = (render(&space, 96), render(&honeycomb, 96));
    let (s, h) = (isolated_bright(&space, 96), isolated_bright(&honeycomb, 96));
    println!("isolated bright pixels: space {s}, honeycomb {h}");
    assert!(s <= h, "space {s}, honeycomb {h}");
    let mean = |p: &[[f32; 3]]| {
        p.iter().flatten().map(|c| f64::from(*c)).sum::<f64>() / (3 * p.len()) as f64
    };
    let (ms, mh) = (mean(&space), mean(&honeycomb));
    println!("mean: space {ms:.4}, honeycomb {mh:.4}");
    assert!((ms - mh).abs() < 0.03 * mh, "space {ms}, honeycomb {mh}");
}

/// The figure-eight knot complement looked at down its cusp (the camera
/// of scenes/manifolds/figure-eight.hsc): rays there cross ever smaller
/// tiles until their 1,024 crossings run out, and the others stop at the
/// pixel horizon. None of them shows the background now (before: 4,485
/// of 9,216 pixels at 96 wide, under either integrator).
#[test]
fn a_cusp_shows_the_spaces_average_not_the_background() {
    let camera = "from = (-0.05, -0.05, -0.02); to = (0.12, 0.12, 0.24);";
    for integrator in ["whitted", "path"] {
        let globals =
            format!("space = figure_eight; domain = 0.03, #gold; integrator = {integrator};");
        let pixels = render(&compile(camera, &globals, ""), 96);
        let shown = pixels.iter().filter(|p| background(p)).count();
        println!(
            "{integrator}: {shown} background pixels of {}",
            pixels.len()
        );
        assert_eq!(shown, 0, "{integrator}");
    }
}
