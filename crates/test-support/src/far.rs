//! The far-isometry measurement: one scene holding every kind of object
//! (sphere, plane, horosphere, rods, a cylinder, polygons with edges and an
//! ideal vertex, a polyhedron with a wireframe), written in the scene
//! language, rendered unmoved and moved — eye, target, up point, every
//! object and every light — by one hyperbolic translation of length `d`.
//! The pictures must agree, and so must the warnings of `check`.
//!
//! Shared by hrender's `tests/far_isometries.rs` (pass/fail at 10..25) and
//! `examples/far_isometry.rs` (the table at 10..30).

use hgeom::glam::DVec3;
use hrender::{Image, RenderOptions, render};
use hscene_lang::ir::Net;

/// Windows per net that frame the objects (Euclidean for nets 0, 2 and 4,
/// hyperbolic lengths for 1 and 3).
const WINDOWS: [f64; 5] = [0.12, 0.4, 0.5, 0.4, 0.5];

/// The scene's source: net `net`, `size` x `size` pixels, moved by the
/// translation along the h-line from the origin to the point at distance
/// `d` in direction `dir` (unmoved for `d = 0`). The Transformations come
/// last, so the other statements keep their lines and the warnings can be
/// compared line by line.
pub fn far_scene_source(net: usize, size: u32, d: f64, dir: DVec3) -> String {
    let w = WINDOWS[net];
    let mut s = format!(
        "Globals {{
    resolution = ({size}, {size});
    window_size = ({w}, {w});
    net_type = {net};
    to = (0, 0, 0.1);
    up = (0, 0.1, 0);
    background = (0.05, 0.05, 0.1);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 2;
}}
BRDFs {{
    red:    ambient = (0.8, 0.3, 0.2), diffuse = (0.8, 0.3, 0.2), specular = (0.5, 0.5, 0.5), shininess = 20;
    green:  ambient = (0.2, 0.7, 0.3), diffuse = (0.2, 0.7, 0.3);
    blue:   ambient = (0.3, 0.4, 0.9), diffuse = (0.3, 0.4, 0.9), specular = (0.5, 0.5, 0.5), shininess = 20;
    mirror: ambient = (0.6, 0.6, 0.2), diffuse = (0.6, 0.6, 0.2), alpha = 0.5;
    white:  ambient = (0.9, 0.9, 0.9), diffuse = (0.9, 0.9, 0.9);
    wall:   ambient = (0.3, 0.3, 0.35), diffuse = (0.5, 0.5, 0.55);
    sky:    ambient = (0.5, 0.5, 0.9), diffuse = (0.25, 0.25, 0.45);
    glass:  ambient = (0.1, 0.1, 0.1), diffuse = (0.2, 0.2, 0.2), trans = 0.6, refraction = 1.3;
}}
Lights {{
    key:  (0, 0.3, 0.1), (8, 8, 8), (8, 8, 8);
    fill: (-0.3, -0.1, 0.2), (4, 4, 4), (4, 4, 4);
    shut: (0.3, 0.3, -0.3), (4, 4, 4), (4, 4, 4);
}}
Objects {{
    ball:   Sphere (0.1, 0.05, 0.4), 0.12, #red;
    drop:   Sphere (-0.12, -0.1, 0.3), 0.06, #mirror;
    quad:   Polygon ((-0.25, -0.12, 0.5), (0.05, -0.12, 0.45), (0.05, 0.05, 0.45), (-0.25, 0.05, 0.5)), #green, edges = 0.008, edge_material = #white;
    tri:    Polygon ((-0.2, -0.2, 0.55), (0.2, -0.2, 0.55), (0, 0.6, 0.8)), #glass, edges = 0.006, edge_material = #white;
    stick:  Rod (-0.2, 0.15, 0.35), (0.15, 0.2, 0.5), 0.02, #blue;
    spoke:  Rod (0.15, -0.05, 0.35), (0, 0.6, 0.8), 0.01, #white;
    tube:   Cylinder (-0.1, -0.2, 0.6), (0.2, 0, 0.55), 0.03, #blue;
    box:    Cube 0.12, #mirror, edges = 0.006, edge_material = #white, at = (0.2, -0.15, 0.5);
    floor:  Horosphere (0, -0.9578262852211514, 0.28734788556634544), (0, -0.25, 0.35), #sky;
    back:   Plane (-0.4, -0.4, 0.75), (0.4, -0.4, 0.75), (0, 0.4, 0.75), #wall;
    hidden: Sphere (0, 0, -0.5), 0.05, #red;
    shade:  Sphere (0.3, 0.3, -0.3), 0.05, #red;
    fan:    Polygon ((0.28, 0.96, 0), (-0.6, 0.8, 0), (-0.1, 0.36, 0.9275774900244185)), #sky, edges = 0.004, edge_material = #white;
    gem:    IdealPentagon #blue, at = (0.2, 0.25, 0.7);
    cage:   IdealOctahedron #white, wireframe = 0.003, at = (-0.25, 0.1, 0.6);
}}
"
    );
    if d > 0.0 {
        // A point typed within 1e-12 of the unit sphere is read as ideal
        // (docs/language.md), which a point beyond distance ~28.3 is: longer
        // translations are written as several equal steps along one line.
        let steps = (d / 25.0).ceil();
        let away = dir.normalize() * (0.5 * d / steps).tanh();
        s.push_str(&format!(
            "Points {{ o = (0, 0, 0); away = ({:?}, {:?}, {:?}); }}
Transformations {{
    move: hline (%o, %away);
",
            away.x, away.y, away.z
        ));
        for _ in 0..steps as usize {
            s.push_str("    @camera->Translate(%move);\n");
        }
        for name in [
            "key", "fill", "shut", "ball", "drop", "quad", "tri", "stick", "spoke", "tube", "box",
            "floor", "back", "hidden", "shade", "fan", "gem", "cage",
        ] {
            for _ in 0..steps as usize {
                s.push_str(&format!("    @{name}->Translate(%move);\n"));
            }
        }
        s.push_str("}\n");
    }
    s
}

/// Warnings of a compiled scene as `(line, code: message)` pairs, in
/// order, on the lines of the unmoved scene: the moved scene's appended
/// `Points` and `Transformations` hold only the translation itself, whose
/// end point 25 away rightly draws "near the absolute" and is not part of
/// what is compared.
pub fn warnings(source: &str) -> Vec<(usize, String)> {
    let scene_lines = far_scene_source(0, 1, 0.0, DVec3::Z).lines().count();
    let compiled = hscene_lang::compile(source);
    compiled
        .diagnostics
        .iter()
        .map(|d| {
            let line = source[..d.span.start()].matches('\n').count() + 1;
            (line, format!("{:?}: {}", d.code, d.message))
        })
        .filter(|(line, _)| *line <= scene_lines)
        .collect()
}

/// Renders a scene source: the image and the numeric failures counted, or
/// the error messages joined when it does not compile or render.
pub fn render_source(source: &str) -> Result<(Image, u64), String> {
    let compiled = hscene_lang::compile(source);
    let Some(scene) = compiled.scene else {
        let errors: Vec<&str> = compiled
            .diagnostics
            .iter()
            .filter(|d| d.is_error())
            .map(|d| d.message.as_str())
            .collect();
        return Err(errors.join("; "));
    };
    let out = render(&scene, &RenderOptions::default(), &|_| {}).map_err(|e| e.to_string())?;
    Ok((out.image, out.stats.numeric_failures))
}

/// Every pixel net, in order.
pub const NETS: [Net; 5] = Net::ALL;

/// One measurement: the fraction of pixels within 1/255 of the unmoved
/// image (0 when the moved scene does not compile or render), whether the
/// warnings agree, and the numeric failures of the moved render.
#[derive(Clone, Debug)]
pub struct FarCase {
    /// Fraction of pixels whose channels agree within 1/255.
    pub share: f64,
    /// The warnings of `check` are the same, line for line.
    pub same_warnings: bool,
    /// The moved scene's warnings where they differ (empty otherwise).
    pub moved_warnings: Vec<(usize, String)>,
    /// Numeric failures counted by the moved render.
    pub failures: u64,
    /// Why the moved scene gave no image, if it did not.
    pub error: Option<String>,
}

/// Measure net `net` at `size` pixels, moved by `d` along `dir`; `base` is
/// the unmoved render (see [`render_source`]).
pub fn far_case(net: usize, size: u32, d: f64, dir: DVec3, base: &Image) -> FarCase {
    let base_src = far_scene_source(net, size, 0.0, dir);
    let src = far_scene_source(net, size, d, dir);
    let moved = warnings(&src);
    let same_warnings = warnings(&base_src) == moved;
    let moved_warnings = if same_warnings { Vec::new() } else { moved };
    match render_source(&src) {
        Ok((img, failures)) => FarCase {
            share: crate::scenes::agreement(base, &img, 1.0 / 255.0),
            same_warnings,
            moved_warnings,
            failures,
            error: None,
        },
        Err(e) => FarCase {
            share: 0.0,
            same_warnings,
            moved_warnings,
            failures: 0,
            error: Some(e),
        },
    }
}
