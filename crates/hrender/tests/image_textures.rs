//! Image textures: a `{7,3}` tiling drawn in the Poincaré disc lands on an
//! h-plane as that tiling, edges on the plane's geodesics; textured
//! objects look the same after the whole scene is moved far away.

use std::path::Path;

use hrender::RenderOptions;
use hscene_ir::Scene;

/// Half the width of the tiling's drawn edges, hyperbolic.
const HALF_WIDTH: f64 = 0.04;

/// The seven edge lines of the `{7,3}` tiling's central heptagon, as unit
/// spacelike normals `(cosh h e, sinh h)` in the 2D hyperboloid `(x, y; w)`
/// (the line at distance `h`, the inradius, along `e`): `cosh h =
/// cos(π/3) / sin(π/7)`. One edge faces `+y`, so the tiling is symmetric
/// under `x -> -x`.
fn heptagon_edges() -> Vec<[f64; 3]> {
    let pi = std::f64::consts::PI;
    let h = ((pi / 3.0).cos() / (pi / 7.0).sin()).acosh();
    (0..7)
        .map(|k| {
            let t = pi / 2.0 + 2.0 * pi * f64::from(k) / 7.0;
            [h.cosh() * t.cos(), h.cosh() * t.sin(), h.sinh()]
        })
        .collect()
}

/// The hyperbolic distance from the disc point `(x, y)` to the nearest edge
/// of the tiling: the point is folded into the central heptagon by
/// reflections in its edges (symmetries of the tiling).
fn distance_to_tiling(x: f64, y: f64) -> f64 {
    let edges = heptagon_edges();
    let r2 = x * x + y * y;
    let mut p = [
        2.0 * x / (1.0 - r2),
        2.0 * y / (1.0 - r2),
        (1.0 + r2) / (1.0 - r2),
    ];
    let dot = |a: &[f64; 3], n: &[f64; 3]| a[0] * n[0] + a[1] * n[1] - a[2] * n[2];
    for _ in 0..200 {
        // The centre has <O, n> = -sinh h < 0: inside is <X, n> < 0.
        let Some(n) = edges.iter().find(|n| dot(&p, n) > 1e-12) else {
            break;
        };
        let k = 2.0 * dot(&p, n);
        p = [p[0] - k * n[0], p[1] - k * n[1], p[2] - k * n[2]];
    }
    edges
        .iter()
        .map(|n| dot(&p, n).abs().asinh())
        .fold(f64::INFINITY, f64::min)
}

/// The tiling drawn in the disc inscribed in a square PNG: black within
/// [`HALF_WIDTH`] of an edge, white elsewhere.
fn write_tiling(path: &Path, size: u32) {
    let img = image::RgbImage::from_fn(size, size, |i, j| {
        let x = (f64::from(i) + 0.5) / f64::from(size) * 2.0 - 1.0;
        let y = 1.0 - (f64::from(j) + 0.5) / f64::from(size) * 2.0;
        let dark = x * x + y * y < 1.0 && distance_to_tiling(x, y) < HALF_WIDTH;
        image::Rgb(if dark { [0, 0, 0] } else { [255, 255, 255] })
    });
    img.save(path).unwrap();
}

fn compile_in(dir: &Path, source: &str) -> Scene {
    let options = hscene_lang::Options {
        base_dir: Some(dir.to_path_buf()),
        ..hscene_lang::Options::default()
    };
    let out = hscene_lang::compile_with(source, &options);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

/// Looking straight down at the plane `z = 0` from `s` above its centre:
/// the pixel at angle `φ` from the axis meets the plane at hyperbolic
/// distance `ρ` from its centre with `tanh ρ = sinh s tan φ` (a right
/// triangle), in the pixel's own azimuth. Where that point is well inside
/// a drawn edge the pixel is dark, well outside it is bright: the tiling
/// lies on the plane with its edges on the plane's geodesics.
#[test]
fn a_heptagonal_tiling_lands_on_a_plane_as_that_tiling() {
    let dir = tempfile::tempdir().unwrap();
    write_tiling(&dir.path().join("tiling.png"), 1024);
    let (s, size, fov) = (1.0f64, 161u32, 60.0f64);
    let z = -(s / 2.0).tanh();
    let source = format!(
        "Globals {{ resolution = ({size}, {size}); from = (0, 0, {z}); to = (0, 0, 0); \
         fov = {fov}; ambient = (1, 1, 1); background = (0, 0, 0); }}\n\
         BRDFs {{ ambient = (1, 1, 1), diffuse = (0, 0, 0), specular = (0, 0, 0), \
         texture = \"tiling.png\"; }}\n\
         Objects {{ Plane (0, 0, 0), (0.5, 0, 0), (0, 0.5, 0), #1; }}\n"
    );
    let scene = compile_in(dir.path(), &source);
    let image = hrender::render(&scene, &RenderOptions::default(), &|_| {})
        .unwrap()
        .image;
    let half = (fov.to_radians() / 2.0).tan();
    let (mut dark_ok, mut dark_n, mut bright_ok, mut bright_n) = (0, 0, 0, 0);
    for j in 0..size {
        for i in 0..size {
            let sx = (f64::from(i) + 0.5) / f64::from(size) - 0.5;
            let sy = 0.5 - (f64::from(j) + 0.5) / f64::from(size);
            let phi = (2.0 * half * sx.hypot(sy)).atan();
            let rho = (s.sinh() * phi.tan()).atanh();
            // Far out the disc's edges shrink below a texel: skip them.
            if !(rho < 1.6) {
                continue;
            }
            let r = (rho / 2.0).tanh() / sx.hypot(sy).max(1e-300);
            let (x, y) = (sx * r, sy * r);
            let d = distance_to_tiling(x, y);
            let v = image.get(i, j)[0];
            if d < 0.4 * HALF_WIDTH {
                dark_n += 1;
                dark_ok += usize::from(v < 0.3);
            } else if d > 3.0 * HALF_WIDTH {
                bright_n += 1;
                bright_ok += usize::from(v > 0.7);
            }
        }
    }
    assert!(dark_n > 200 && bright_n > 5000, "{dark_n} {bright_n}");
    assert!(
        dark_ok as f64 >= 0.97 * dark_n as f64,
        "{dark_ok} of {dark_n} edge pixels dark"
    );
    assert!(
        bright_ok as f64 >= 0.99 * bright_n as f64,
        "{bright_ok} of {bright_n} bright"
    );
}

/// A textured sphere, plane and mesh, the eye and the light, all moved by
/// a translation of hyperbolic length 20: the picture is the same.
#[test]
fn textured_objects_look_the_same_after_a_translation_of_20() {
    let dir = tempfile::tempdir().unwrap();
    write_tiling(&dir.path().join("tiling.png"), 256);
    std::fs::write(
        dir.path().join("tet.obj"),
        "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n",
    )
    .unwrap();
    let picture = |moved: bool| {
        let moves = if moved {
            "Transformations { far: hline ((0, 0, 0), (0.3, 0.1, 0.2)); \
             @camera->Translate(%far, 20); @ball->Translate(%far, 20); \
             @floor->Translate(%far, 20); @lamp->Translate(%far, 20); \
             @tet->Translate(%far, 20); }"
        } else {
            ""
        };
        let source = format!(
            "Globals {{ resolution = (64, 48); from = (0, 0.2, -0.5); to = (0, 0, 0); \
             fov = 80; ambient = (0.3, 0.3, 0.3); }}\n{moves}\n\
             BRDFs {{ tex: ambient = (1, 1, 1), diffuse = (0.8, 0.8, 0.8), \
             texture = \"tiling.png\", texture_rotate = 20; }}\n\
             Lights {{ lamp: (0, 0.4, -0.3), (2, 2, 2), (0, 0, 0); }}\n\
             Objects {{ ball: Sphere (-0.15, 0.05, 0), 0.3, #tex; \
             floor: Plane (0, -0.3, 0), (0.3, -0.3, 0), (0, -0.3, 0.3), #tex; \
             tet: Mesh \"tet.obj\", 0.15, #tex, at = (0.2, -0.1, 0.05); }}\n"
        );
        hrender::render(
            &compile_in(dir.path(), &source),
            &RenderOptions::default(),
            &|_| {},
        )
        .unwrap()
        .image
    };
    let (near, far) = (picture(false), picture(true));
    let close = near
        .pixels()
        .iter()
        .zip(far.pixels())
        .filter(|(a, b)| (0..3).all(|c| (a[c] - b[c]).abs() < 2.0 / 255.0))
        .count();
    assert!(
        close as f64 >= 0.99 * near.pixels().len() as f64,
        "{close} of {} pixels agree",
        near.pixels().len()
    );
}

/// Honeycomb faces each carry the image in their own disc, centred on the
/// face: from the centre of `{4,3,5}`'s base cube the face ahead shows the
/// image's middle (red) at its centre, and so does the face two cubes on,
/// seen through it along the axis; towards a corner of the face ahead the
/// image's rim (white) shows.
#[test]
fn honeycomb_faces_carry_the_image_on_each_face() {
    let dir = tempfile::tempdir().unwrap();
    let img = image::RgbImage::from_fn(64, 64, |i, j| {
        let (x, y) = (f64::from(i) - 31.5, f64::from(j) - 31.5);
        image::Rgb(if x.hypot(y) < 8.0 {
            [255, 0, 0]
        } else {
            [255, 255, 255]
        })
    });
    img.save(dir.path().join("dot.png")).unwrap();
    let pixel = |to: &str, trans: f64| {
        let source = format!(
            "Globals {{ resolution = (5, 5); to = {to}; fov = 1; ambient = (1, 1, 1); \
             background = (0, 0, 0); recursion_depth = 4; }}\n\
             BRDFs {{ ambient = (1, 1, 1), diffuse = (0, 0, 0), specular = (0, 0, 0), \
             trans = {trans}, texture = \"dot.png\"; }}\n\
             Objects {{ Honeycomb {{4,3,5}}, #1, faces = #1; }}\n"
        );
        let image = hrender::render(
            &compile_in(dir.path(), &source),
            &RenderOptions::default(),
            &|_| {},
        )
        .unwrap()
        .image;
        image.get(2, 2)
    };
    let ahead = pixel("(0, 0, 0.3)", 0.0);
    assert!(ahead[0] > 0.99 && ahead[1] < 0.01, "{ahead:?}");
    // Through a clear first face (trans 1 would pass all; 0.5 mixes the
    // two faces' centres, both red).
    let through = pixel("(0, 0, 0.3)", 0.5);
    assert!(through[1] < 0.01 && through[0] > 0.5, "{through:?}");
    let corner = pixel("(0.25, 0.25, 0.3)", 0.0);
    assert!(corner[1] > 0.99, "{corner:?}");
}
