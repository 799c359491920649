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
            ..Default::default()
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

/// A glass icosphere, smoothed, refracts like the h-sphere it approximates:
/// its mirror and refracted rays follow the interpolated normal (with flat
/// normals, glass looks like cut crystal). Behind the glass, a checker
/// plane; the smooth mesh's picture is much nearer the exact sphere's than
/// the flat mesh's, for both integrators' conventions (Whitted here).
#[test]
fn smooth_glass_refracts_like_the_sphere_it_approximates() {
    use std::fmt::Write as _;
    let dir = tempfile::tempdir().expect("a temporary directory");
    let (vertices, faces) = hscene_test_support::icosphere(3);
    let mut ply = format!(
        "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\nelement face {}\nproperty list uchar int vertex_indices\nend_header\n",
        vertices.len(),
        faces.len()
    );
    for v in &vertices {
        let _ = writeln!(ply, "{} {} {}", v.x, v.y, v.z);
    }
    for f in &faces {
        let _ = writeln!(ply, "3 {} {} {}", f[0], f[1], f[2]);
    }
    std::fs::write(dir.path().join("ico.ply"), ply).expect("writes");
    let draw_with = |object: &str| {
        let src = format!(
            "Globals {{ resolution = (64, 64); fov = 40; to = (0, 0, 0.3); background = (0, 0, 0);
                        ambient = (1, 1, 1); recursion_depth = 6; }}
             BRDFs {{ glass: trans = 1, refraction = 1.5;
                      floor: ambient = (0.9, 0.9, 0.9), checker = 0.08,
                             checker_ambient = (0.1, 0.1, 0.5); }}
             Objects {{ {object};
                        Plane (0.3, 0.3, 0.8), (-0.3, 0.3, 0.8), (0, -0.3, 0.8), #floor; }}"
        );
        let compiled = hscene_lang::compile_with(
            &src,
            &hscene_lang::Options {
                base_dir: Some(dir.path().into()),
                frame: 0,
                ..Default::default()
            },
        );
        assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
        draw(&compiled.scene.expect("compiles"))
    };
    let exact = draw_with("Sphere (0, 0, 0.3), 0.25, #glass");
    let flat = draw_with("Mesh \"ico.ply\", 0.25, #glass, at = (0, 0, 0.3)");
    let smooth = draw_with("Mesh \"ico.ply\", 0.25, #glass, at = (0, 0, 0.3), smooth = 60");
    let distance = |a: &hrender::Image, b: &hrender::Image| -> f64 {
        a.pixels()
            .iter()
            .zip(b.pixels())
            .map(|(p, q)| f64::from((p[0] - q[0]).abs() + (p[2] - q[2]).abs()))
            .sum()
    };
    let (d_flat, d_smooth) = (distance(&flat, &exact), distance(&smooth, &exact));
    assert!(d_flat > 0.0);
    assert!(d_smooth < 0.6 * d_flat, "smooth {d_smooth}, flat {d_flat}");
}
