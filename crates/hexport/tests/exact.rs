//! Every exported shell is closed and lies on its exact surface: the named
//! tests of `docs/export.md`.

use hexport::{ExportOptions, Format, Millimetres, Model, ThinParts, export_scene};
use hgeom::glam::{DVec3, DVec4};
use hgeom::{HLine, Point, lorentz};

fn compile(source: &str) -> hscene_lang::ir::Scene {
    let out = hscene_lang::compile(source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

fn scene(objects: &str) -> hscene_lang::ir::Scene {
    compile(&format!(
        "Points {{ (0.1, 0.1, 0.2); (-0.3, 0.2, 0.2); (-0.2, -0.3, 0.2); }}\n\
         BRDFs {{ red: diffuse = (0.8, 0.1, 0.1); blue: diffuse = (0.1, 0.2, 0.9); }}\n\
         Objects {{\n{objects}\n}}\n"
    ))
}

fn export(objects: &str, options: &ExportOptions) -> Model {
    export_scene(&scene(objects), options, &|_, _| {}).unwrap_or_else(|e| panic!("{e}"))
}

/// The hyperboloid point of a vertex in millimetres.
fn hyperboloid(v: DVec3, options: &ExportOptions) -> DVec4 {
    Point::from_coords(v / options.scale())
        .unwrap()
        .to_hyperboloid()
}

fn assert_closed(model: &Model) {
    for shell in &model.shells {
        assert_eq!(shell.boundary_defect(), None, "{}", shell.object);
        assert!(shell.smallest_area() > 0.0, "{}", shell.object);
        assert!(shell.signed_volume() > 0.0, "{}", shell.object);
    }
}

#[test]
fn sphere_vertices_lie_on_the_exact_sphere() {
    let options = ExportOptions::default();
    let model = export("Sphere (0.3, -0.2, 0.1), 0.7, #red;", &options);
    assert_closed(&model);
    let centre = Point::new(0.3, -0.2, 0.1).unwrap().to_hyperboloid();
    let shell = &model.shells[0];
    for v in &shell.vertices {
        let d = lorentz::distance(hyperboloid(*v, &options), centre);
        assert!((d - 0.7).abs() < 1e-9, "{d}");
    }
    // Between vertices the flat triangles stay within the tolerance: their
    // centroids are no farther than it from the Euclidean sphere.
    let sphere = hgeom::HSphere::new(Point::new(0.3, -0.2, 0.1).unwrap(), 0.7).unwrap();
    let (c, r) = sphere.euclidean();
    let (c, r) = (c * options.scale(), r * options.scale());
    for t in &shell.triangles {
        let [a, b, d] = shell.corners(t);
        let g = (a + b + d) / 3.0;
        assert!(r - (g - c).length() <= options.tolerance.get() + 1e-9);
    }
}

#[test]
fn rod_vertices_are_at_the_rods_radius_from_its_segment() {
    let options = ExportOptions::default();
    let model = export(
        "Rod (-0.4, 0.1, 0.0), (0.5, 0.2, -0.1), 0.08, #red;",
        &options,
    );
    assert_closed(&model);
    let (a, b) = (
        Point::new(-0.4, 0.1, 0.0).unwrap(),
        Point::new(0.5, 0.2, -0.1).unwrap(),
    );
    let line = HLine::through(&a.into(), &b.into()).unwrap();
    let length = a.distance(b);
    for v in &model.shells[0].vertices {
        let p = Point::from_coords(*v / options.scale()).unwrap();
        let s = line.foot_parameter(&p);
        let d = if s < 0.0 {
            p.distance(a)
        } else if s > length {
            p.distance(b)
        } else {
            line.distance_to(&p)
        };
        assert!((d - 0.08).abs() < 1e-9, "{d} at {s}");
    }
}

#[test]
fn cylinders_are_cut_where_they_get_too_thin() {
    let options = ExportOptions::default();
    let model = export("Cylinder (0, 0, 0), (0.3, 0.1, 0), 0.1, #blue;", &options);
    assert_closed(&model);
    let line = HLine::through(
        &Point::ORIGIN.into(),
        &Point::new(0.3, 0.1, 0.0).unwrap().into(),
    )
    .unwrap();
    let mut farthest: f64 = 0.0;
    for v in &model.shells[0].vertices {
        let p = Point::from_coords(*v / options.scale()).unwrap();
        let d = line.distance_to(&p);
        // Tube vertices at the radius, cap vertices within it.
        assert!(d <= 0.1 + 1e-9, "{d}");
        farthest = farthest.max(v.length());
    }
    // The cut ends where the tube is 0.8 mm thick: inside the ball.
    assert!(farthest < 50.0 && farthest > 40.0, "{farthest}");
}

#[test]
fn plates_are_the_polygon_thickened_by_half_the_face_thickness() {
    let options = ExportOptions::default();
    let model = export("Polygon (%1, %2, %3), #red;", &options);
    assert_closed(&model);
    let corners = [(0.1, 0.1, 0.2), (-0.3, 0.2, 0.2), (-0.2, -0.3, 0.2)]
        .map(|(x, y, z)| hgeom::Vertex::from(Point::new(x, y, z).unwrap()));
    let plane = hgeom::HPlane::through(&corners[0], &corners[1], &corners[2]).unwrap();
    let (mut faces, mut rim) = (0, 0);
    for v in &model.shells[0].vertices {
        let p = Point::from_coords(*v / options.scale()).unwrap();
        let d = plane.signed_distance(&p).abs();
        assert!(d <= options.face_half_thickness + 1e-9, "{d}");
        if (d - options.face_half_thickness).abs() < 1e-9 {
            faces += 1;
        } else {
            rim += 1;
        }
    }
    assert!(faces > rim, "{faces} on the faces, {rim} on the rim");
}

/// The cut honeycomb keeps no part thinner than the minimum feature: each
/// tube's end cross-sections, each ball and each plate's rim.
#[test]
fn the_cut_honeycomb_has_nothing_thinner_than_the_minimum() {
    let options = ExportOptions::default();
    for symbol in ["{5,3,4}", "{4,3,5}", "{3,5,3}", "{4,4,3}", "{3,3,6}"] {
        let model = export(
            &format!("Honeycomb {symbol}, #red, edges = 0.06, vertices = 0.08, faces = #blue;"),
            &options,
        );
        assert_closed(&model);
        for shell in &model.shells {
            // Every vertex of a shell is within the ball, and each shell
            // is at least the minimum across: its extent on every axis.
            let lo = shell
                .vertices
                .iter()
                .fold(DVec3::splat(f64::MAX), |a, v| a.min(*v));
            let hi = shell
                .vertices
                .iter()
                .fold(DVec3::splat(f64::MIN), |a, v| a.max(*v));
            let extent = hi - lo;
            let least = options.min_feature.get() - 2.0 * options.tolerance.get();
            assert!(
                extent.min_element() >= least,
                "{symbol}: a shell {extent:?} across"
            );
            assert!(shell.vertices.iter().all(|v| v.length() < options.scale()));
        }
    }
}

#[test]
fn thickened_tubes_are_never_thinner_than_the_minimum() {
    let options = ExportOptions {
        thin: ThinParts::Thicken,
        min_feature: Millimetres::new(1.5).unwrap(),
        ..ExportOptions::default()
    };
    let model = export("Honeycomb {5,3,4}, #red, edges = 0.05;", &options);
    assert_closed(&model);
    for shell in &model.shells {
        let lo = shell
            .vertices
            .iter()
            .fold(DVec3::splat(f64::MAX), |a, v| a.min(*v));
        let hi = shell
            .vertices
            .iter()
            .fold(DVec3::splat(f64::MIN), |a, v| a.max(*v));
        // Vertices are exact; chords between them cut in by at most the
        // tolerance on either side.
        let least = 1.5 - 2.0 * options.tolerance.get();
        assert!((hi - lo).min_element() >= least, "{:?}", hi - lo);
    }
    let cut = export(
        "Honeycomb {5,3,4}, #red, edges = 0.05;",
        &ExportOptions {
            thin: ThinParts::Cut,
            ..options
        },
    );
    // Thickening keeps edges the cut rule drops.
    assert!(model.shells.len() > cut.shells.len());
}

#[test]
fn exporting_twice_gives_the_same_bytes() {
    let options = ExportOptions::default();
    let objects = "Honeycomb {4,3,5}, #red, edges = 0.06, vertices = 0.08, colors = (#red, #blue);\n\
                   Sphere (0.2, 0.1, 0.0), 0.3, #blue;";
    for name in ["a.stl", "a.3mf", "a.obj", "a.glb"] {
        let path = std::path::Path::new(name);
        let format = Format::from_path(path).unwrap();
        let once = format.encode(&export(objects, &options), path).unwrap();
        let twice = format.encode(&export(objects, &options), path).unwrap();
        assert_eq!(once, twice, "{name}");
        assert!(once.iter().all(|f| !f.bytes.is_empty()));
    }
}

#[test]
fn the_triangle_budget_names_the_object_that_exceeds_it() {
    let options = ExportOptions {
        max_triangles: 500,
        ..ExportOptions::default()
    };
    let scene = scene("Sphere (0, 0, 0), 0.2, #red;\nSphere (0.3, 0, 0), 0.9, #red;");
    let err = export_scene(&scene, &options, &|_, _| {}).unwrap_err();
    let message = err.to_string();
    assert!(message.contains("object"), "{message}");
    assert!(message.contains("--max-triangles"), "{message}");
}

#[test]
fn nothing_thick_enough_is_a_clear_error() {
    let options = ExportOptions {
        size: Millimetres::new(10.0).unwrap(),
        ..ExportOptions::default()
    };
    let scene = scene("Sphere (0, 0, 0), 0.05, #red;");
    let err = export_scene(&scene, &options, &|_, _| {}).unwrap_err();
    assert!(
        err.to_string().contains("nothing is left to print"),
        "{err}"
    );
}

#[test]
fn materials_follow_the_honeycombs_colours() {
    let model = export(
        "Honeycomb {4,3,5}, #red, edges = 0.06, faces = #blue, colors = (#red, #blue);",
        &ExportOptions::default(),
    );
    assert_eq!(model.materials.len(), 2);
    let names: Vec<&str> = model.materials.iter().map(|m| m.name.as_str()).collect();
    assert!(
        names.contains(&"red") && names.contains(&"blue"),
        "{names:?}"
    );
}

/// No two shells share a grid edge, even where their parts meet along a
/// side (a cube's faces, a honeycomb's coplanar faces across an edge): an
/// STL reader welds equal points, and a shared edge would join two shells
/// into a non-manifold one.
#[test]
fn no_two_shells_share_an_edge() {
    use std::collections::HashMap;
    let options = ExportOptions::default();
    for objects in [
        "Cube 0.6, #red;",
        "Honeycomb {6,3,4}, #red, edges = 0.04, faces = #blue;",
    ] {
        let model = export(objects, &options);
        let key = |v: DVec3| [v.x as f32, v.y as f32, v.z as f32].map(f32::to_bits);
        let mut owner: HashMap<([u32; 3], [u32; 3]), usize> = HashMap::new();
        for (k, shell) in model.shells.iter().enumerate() {
            for t in &shell.triangles {
                for c in 0..3 {
                    let (a, b) = (
                        key(shell.vertices[t[c] as usize]),
                        key(shell.vertices[t[(c + 1) % 3] as usize]),
                    );
                    let edge = if a < b { (a, b) } else { (b, a) };
                    if let Some(other) = owner.insert(edge, k) {
                        assert_eq!(other, k, "{objects}: shells {other} and {k} share an edge");
                    }
                }
            }
        }
    }
}
