//! The sky behind a honeycomb: beyond the walk's pixel horizon what lies
//! behind the honeycomb (the sky, the background) arrives through the
//! share of the rest of the way that is open, under both integrators and
//! at every resolution (`horizon_fill.rs`). The scene is the README's
//! `scenes/path/honeycomb-353-sky.hsc`, the `{3,5,3}` under a blue sky.

use hrender::RenderOptions;
use hscene_ir::{Resolution, Scene};

/// The sky scene under `integrator`.
fn sky_scene(integrator: &str) -> Scene {
    let source = format!(
        "Globals {{ from = (0.01, 0.02, 0.0); to = (0.05, 0.08, 0.4); fov = 100; \
         integrator = {integrator}; background = (0.55, 0.65, 0.9); }}\n\
         BRDFs {{ clay: diffuse = (0.85, 0.6, 0.4); }}\n\
         Objects {{ Honeycomb {{3,5,3}}, #clay, edges = 0.03, vertices = 0.06; }}"
    );
    let out = hscene_lang::compile(&source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

/// The mean linear colour of the whole picture at `size` squared and of
/// its middle ninth (the `size/3` square about the centre).
fn means(scene: &Scene, size: u32, samples: u32) -> ([f64; 3], [f64; 3]) {
    let options = RenderOptions {
        resolution: Resolution::new(size, size),
        samples: Some(samples),
        ..RenderOptions::default()
    };
    let image = hrender::render(scene, &options, &|_| {})
        .expect("the scene renders")
        .image;
    let (mut all, mut middle) = ([0.0; 3], [0.0; 3]);
    let (lo, hi) = (size / 3, 2 * size / 3);
    for y in 0..size {
        for x in 0..size {
            let p = image.get(x, y);
            let inside = (lo..hi).contains(&x) && (lo..hi).contains(&y);
            for c in 0..3 {
                all[c] += f64::from(p[c]) / f64::from(size * size);
                if inside {
                    middle[c] += f64::from(p[c]) / f64::from((hi - lo) * (hi - lo));
                }
            }
        }
    }
    (all, middle)
}

/// Path-traced, at 60, 120 and 240 pixels: the sky arrives (the blue
/// channel's mean about 0.25 of 1, linear; 0.0 when the fill was
/// emission only and every path that reached it ended black), the means
/// agree across resolutions to 10 %, and the middle is no darker than the
/// whole (no black disc at the centre).
#[test]
fn the_sky_shows_between_the_edges_at_every_resolution_path_traced() {
    let scene = sky_scene("path");
    let pictures: Vec<_> = [60, 120, 240].map(|n| (n, means(&scene, n, 4))).into();
    let (_, (reference, _)) = pictures[2];
    for (n, (all, middle)) in pictures {
        assert!(all[2] > 0.15, "{n} pixels: mean {all:?}");
        for c in 0..3 {
            let apart = (all[c] - reference[c]).abs() / reference[c];
            assert!(
                apart < 0.1,
                "{n} pixels: mean {all:?}, at 240: {reference:?}"
            );
            assert!(
                middle[c] > 0.9 * all[c],
                "{n} pixels: middle {middle:?}, all {all:?}"
            );
        }
    }
}

/// Whitted's integrator, with no lights: the clay is black, so all that
/// is seen is the sky through the gaps, blue where the fill was black
/// (blue over red in the sky's own ratio, 0.9 to 0.55), the same at 60 and
/// 240 pixels to 10 %, with no dark disc in the middle.
#[test]
fn the_sky_shows_between_the_edges_at_every_resolution_whitted() {
    let scene = sky_scene("whitted");
    let (coarse, middle_coarse) = means(&scene, 60, 1);
    let (fine, middle_fine) = means(&scene, 240, 1);
    for (all, middle) in [(coarse, middle_coarse), (fine, middle_fine)] {
        assert!(all[2] > 0.1, "mean {all:?}");
        assert!((all[2] / all[0] - 0.9 / 0.55).abs() < 0.01, "mean {all:?}");
        assert!(middle[2] > 0.9 * all[2], "middle {middle:?}, all {all:?}");
    }
    assert!(
        (coarse[2] - fine[2]).abs() < 0.1 * fine[2],
        "{coarse:?} {fine:?}"
    );
}
