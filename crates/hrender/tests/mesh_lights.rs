//! Emissive triangle meshes as lights: their triangles are light units
//! under a tree of their own (`light_tree.rs`), drawn at every vertex and
//! weighted against the paths' own hits by the triangle a hit names.

use hrender::{IntegratorKind, RenderOptions};
use hscene_ir::Scene;

/// The icosphere of 320 triangles (the test support's, subdivided twice),
/// wound counter-clockwise seen from outside, as an OBJ file.
fn icosphere_obj() -> String {
    let (vertices, triangles) = hscene_test_support::icosphere(2);
    let mut obj = String::new();
    for p in &vertices {
        obj += &format!("v {} {} {}\n", p.x, p.y, p.z);
    }
    for t in &triangles {
        obj += &format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    obj
}

fn compile(src: &str) -> Scene {
    let compiled = hscene_lang::compile(src);
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    compiled.scene.expect("a scene")
}

/// A closed icosphere mesh (320 triangles, so under a light tree) that
/// emits `E` and reflects `ρ`, round a ball of the same material in front
/// of the eye, filling the view: every surface in sight sees only surfaces of radiance `L =
/// E + ρ L`, so every pixel is `E / (1 - ρ)`. The ball's vertices draw the
/// mesh's triangles down the tree (the mesh's own vertices draw the ball),
/// and the paths that meet a triangle weigh it by the triangle their hit
/// names: a wrong probability anywhere shows as a bias.
#[test]
fn a_furnace_of_an_emissive_mesh_round_an_emissive_ball() {
    let dir = tempfile::tempdir().expect("a folder");
    let mesh = dir.path().join("icosphere.obj");
    std::fs::write(&mesh, icosphere_obj()).expect("writes");
    let scene = compile(&format!(
        "Globals {{ resolution = (16, 16); from = (0, 0, -0.25); to = (0, 0, 0.2); fov = 40;
                    ambient = (0, 0, 0); background = (0, 0, 0); }}
         BRDFs {{ wall: diffuse = (0.6, 0.6, 0.6), emission = (0.5, 0.5, 0.5); }}
         Objects {{ Mesh {:?}, 1.4, #wall; Sphere (0, 0, 0.2), 0.35, #wall; }}",
        mesh.display().to_string()
    ));
    let options = RenderOptions {
        integrator: Some(IntegratorKind::Path),
        samples: Some(256),
        seed: 3,
        ..RenderOptions::default()
    };
    let image = hrender::render(&scene, &options, &|_| {}).expect("renders");
    let expected = 0.5 / (1.0 - 0.6);
    let values: Vec<f64> = image
        .image
        .pixels()
        .iter()
        .map(|p| (f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2])) / 3.0)
        .collect();
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let error = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt();
    assert!(
        (mean - expected).abs() < 5.0 * error + 1e-6,
        "{mean} vs {expected} (standard error {error})"
    );
    // A unit drawn with a probability 20 % off gives 2.5 % here.
    assert!(error < 0.003 * expected, "the test can tell: {error}");
    assert_eq!(image.stats.numeric_failures, 0);
}
