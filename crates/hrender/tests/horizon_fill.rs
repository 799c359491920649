//! Beyond a honeycomb's horizon: the pixels there take the honeycomb's
//! average appearance, not the background, so the disc where the walk
//! stops (the cusp of a horosphere-inscribed cell of `{4,4,3}`, whose
//! size follows the resolution) is not a hole that moves with it.

use hrender::RenderOptions;
use hscene_ir::{Resolution, Scene};

/// Looking from inside a `{4,4,3}` cell straight up its cusp: the cell's
/// ideal centre is in the middle of the picture.
fn cusp_scene(objects: &str, materials: &str) -> Scene {
    let source = format!(
        "Globals {{ resolution = (64, 64); from = (-0.3, 0, 0); to = (-0.6, 0, 0); \
         fov = 90; background = (0, 0, 0); ambient = (0.4, 0.4, 0.4); \
         recursion_depth = 8; }}\n\
         BRDFs {{ gold: ambient = (0.5, 0.4, 0.2), diffuse = (0.8, 0.6, 0.3); {materials} }}\n\
         Lights {{ (-0.25, 0.1, 0.05), (2, 2, 2), (0, 0, 0); }}\n\
         Objects {{ {objects} }}"
    );
    let out = hscene_lang::compile(&source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

/// The picture at `size` squared, averaged over `blocks` squared blocks
/// (linear radiance, box filter).
fn downsampled(scene: &Scene, size: u32, blocks: u32) -> Vec<[f64; 3]> {
    let options = RenderOptions {
        resolution: Resolution::new(size, size),
        samples: Some(1),
        ..RenderOptions::default()
    };
    let image = hrender::render(scene, &options, &|_| {})
        .expect("the scene renders")
        .image;
    let per = size / blocks;
    let mut out = vec![[0.0; 3]; (blocks * blocks) as usize];
    for y in 0..size {
        for x in 0..size {
            let p = image.get(x, y);
            let cell = &mut out[((y / per) * blocks + x / per) as usize];
            for c in 0..3 {
                cell[c] += f64::from(p[c]) / f64::from(per * per);
            }
        }
    }
    out
}

/// Over the middle `k` by `k` blocks: the largest difference of a channel,
/// and the mean of each picture (all channels).
fn middle(a: &[[f64; 3]], b: &[[f64; 3]], blocks: u32, k: u32) -> (f64, f64, f64) {
    let lo = (blocks - k) / 2;
    let (mut worst, mut sum_a, mut sum_b): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for y in lo..lo + k {
        for x in lo..lo + k {
            let i = (y * blocks + x) as usize;
            for c in 0..3 {
                worst = worst.max((a[i][c] - b[i][c]).abs());
                sum_a += a[i][c];
                sum_b += b[i][c];
            }
        }
    }
    let n = f64::from(3 * k * k);
    (worst, sum_a / n, sum_b / n)
}

/// Opaque edges, and coloured glass faces over edges and vertices: at 200
/// and 800 pixels, box-filtered to 25 by 25, the middle fifth of the
/// picture (where the 200-pixel walk stops on 14 % of the width) agrees:
/// its mean within 10 %, each block within 0.025 (of 1, linear). Drawing
/// the background there, the means were 0.003 and 0.018 (edges).
#[test]
fn the_cusp_looks_the_same_at_200_and_800_pixels() {
    let cases = [
        (
            "edges",
            cusp_scene("Honeycomb {4,4,3}, #gold, edges = 0.03;", ""),
        ),
        (
            "glass faces",
            cusp_scene(
                "Honeycomb {4,4,3}, #gold, edges = 0.03, vertices = 0.05, faces = #glass, \
                 colors = (#gold, #cyan);",
                "glass: ambient = (0.02, 0.04, 0.08), diffuse = (0.05, 0.1, 0.2), trans = 0.8; \
                 cyan: ambient = (0.1, 0.35, 0.4), diffuse = (0.2, 0.7, 0.8);",
            ),
        ),
    ];
    for (what, scene) in cases {
        let coarse = downsampled(&scene, 200, 25);
        let fine = downsampled(&scene, 800, 25);
        let (worst, mean_coarse, mean_fine) = middle(&coarse, &fine, 25, 5);
        assert!(
            (mean_coarse - mean_fine).abs() < 0.1 * mean_fine,
            "{what}: middle means {mean_coarse} at 200 pixels, {mean_fine} at 800"
        );
        assert!(worst < 0.025, "{what}: a middle block differs by {worst}");
        // Not the background: something is drawn there.
        assert!(mean_coarse > 0.02, "{what}: {mean_coarse}");
    }
}
