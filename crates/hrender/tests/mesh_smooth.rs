//! Smooth shading changes the light on a mesh, never which pixels it
//! covers: the hits are those of the flat mesh (docs/geometry.md, "Smooth
//! meshes").

use hscene_test_support::scenes::draw;

fn bunny(options: &str) -> hrender::Image {
    let meshes = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes/meshes");
    // A red bunny on blue: a pixel is covered exactly when it has no blue.
    let src = format!(
        "Globals {{ resolution = (64, 64); window_size = (0.5, 0.5); to = (0, 0, 0.635149);
                    background = (0, 0, 1); ambient = (0.2, 0.2, 0.2); recursion_depth = 0; }}
         BRDFs {{ ambient = (1, 0, 0), diffuse = (0.8, 0, 0), specular = (0.3, 0, 0), shininess = 20; }}
         Lights {{ (-0.25, 0.3, 0.45), (30, 30, 30), (12, 12, 12); }}
         Objects {{ Mesh \"bunny.ply\", 0.8, #1, at = (0, 0, 0.635149){options}; }}"
    );
    let compiled = hscene_lang::compile_with(
        &src,
        &hscene_lang::Options {
            base_dir: Some(meshes.into()),
            frame: 0,
        },
    );
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    draw(&compiled.scene.unwrap())
}

#[test]
fn smoothing_keeps_the_silhouette_and_changes_the_shading() {
    let flat = bunny("");
    let smooth = bunny(", smooth = 60");
    let mask =
        |img: &hrender::Image| -> Vec<bool> { img.pixels().iter().map(|p| p[2] == 0.0).collect() };
    let (a, b) = (mask(&flat), mask(&smooth));
    let covered = a.iter().filter(|&&c| c).count();
    assert!(covered > 500, "{covered}");
    assert_eq!(a, b, "the silhouettes differ");
    let changed = flat
        .pixels()
        .iter()
        .zip(smooth.pixels())
        .filter(|(p, q)| (p[0] - q[0]).abs() > 1e-3)
        .count();
    assert!(changed > covered / 4, "{changed} of {covered}");
}
