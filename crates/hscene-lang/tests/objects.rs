//! Integration tests of the objects and transformations the language adds to
//! the thesis's format: rods, cylinders, planes, horospheres, wireframes and
//! their options, named objects and lights, and transformations of objects,
//! lights and the camera. Positions are checked against formulas derived
//! independently here (Möbius addition, rotations, reflections, Euclidean
//! forms), not against hgeom's own code paths. Each new diagnostic has a test
//! of its exact code, severity and span.

use hgeom::glam::DVec3;
use hgeom::{BallShape, Point, Vertex};
use hscene_lang::ir::{Light, Object, Scene, Shape};
use hscene_lang::{Compiled, Diagnostic, Severity, Span, compile};
use proptest::prelude::*;

// ----- helpers ---------------------------------------------------------------

/// Möbius addition `u (+) v`, from its definition.
fn mobius_add(u: DVec3, v: DVec3) -> DVec3 {
    let uv = u.dot(v);
    let u2 = u.length_squared();
    let v2 = v.length_squared();
    ((1.0 + 2.0 * uv + v2) * u + (1.0 - u2) * v) / (1.0 + 2.0 * uv + u2 * v2)
}

/// Rotation by `t` radians about `+y`, right-hand rule.
fn rot_y(p: DVec3, t: f64) -> DVec3 {
    let (s, c) = t.sin_cos();
    DVec3::new(p.x * c + p.z * s, p.y, -p.x * s + p.z * c)
}

/// The ball point at hyperbolic distance `d` from the origin along `dir`.
fn at(dir: DVec3, d: f64) -> DVec3 {
    dir.normalize() * (0.5 * d).tanh()
}

fn pt(v: DVec3) -> Point {
    Point::from_coords(v).unwrap()
}

#[track_caller]
fn close(actual: DVec3, expected: DVec3, tol: f64) {
    let err = (actual - expected).abs().max_element();
    assert!(
        err <= tol,
        "got {actual:?}, expected {expected:?} (error {err:e})"
    );
}

/// Compiles `src`, asserting there is no error, and returns the scene.
#[track_caller]
fn scene(src: &str) -> Scene {
    let c = compile(src);
    assert!(
        !c.has_errors(),
        "unexpected errors for {src}: {:#?}",
        c.diagnostics
    );
    c.scene.unwrap()
}

/// Exactly one diagnostic with `code`, of `severity`, covering exactly
/// `snippet` (its `nth` occurrence), and no error with another code.
#[track_caller]
fn expect(src: &str, code: &str, severity: Severity, snippet: &str, nth: usize) -> Diagnostic {
    let c: Compiled = compile(src);
    let matching: Vec<&Diagnostic> = c
        .diagnostics
        .iter()
        .filter(|d| d.code.as_str() == code)
        .collect();
    assert_eq!(
        matching.len(),
        1,
        "expected exactly one {code} for {src}, got {:#?}",
        c.diagnostics
    );
    let d = matching[0].clone();
    assert_eq!(d.severity, severity);
    let start = src
        .match_indices(snippet)
        .nth(nth)
        .unwrap_or_else(|| panic!("{snippet:?} not in source"))
        .0;
    assert_eq!(
        d.span,
        Span::new(start, start + snippet.len()),
        "{code} covers {:?}, expected {snippet:?}",
        &src[d.span.start()..d.span.end()]
    );
    let others: Vec<&Diagnostic> = c
        .diagnostics
        .iter()
        .filter(|x| x.is_error() && x.code.as_str() != code)
        .collect();
    assert!(others.is_empty(), "other errors: {others:#?}");
    assert_eq!(c.scene.is_some(), severity == Severity::Warning);
    assert!(d.help.is_some(), "{code} has no help: {d:?}");
    d
}

const MATTE: &str = "BRDFs { diffuse = (1,1,1); edge: diffuse = (1,0,0); }";

fn only_object(s: &Scene) -> &Object {
    assert_eq!(s.objects.len(), 1, "{:#?}", s.objects);
    &s.objects[0]
}

fn interior(v: Vertex) -> DVec3 {
    match v {
        Vertex::Interior(p) => p.coords(),
        Vertex::Ideal(p) => panic!("ideal: {p:?}"),
    }
}

// ----- rods and cylinders ----------------------------------------------------

#[test]
fn rod_is_the_points_within_its_radius_of_the_segment() {
    let s = scene(&format!(
        "Points {{ (0,0,0.2); (0.3,0,0.2); }} {MATTE} Objects {{ Rod %1, %2, 0.01, #1; }}"
    ));
    let Shape::Rod(rod) = &only_object(&s).shape else {
        panic!("not a rod")
    };
    close(interior(rod.start()), DVec3::new(0.0, 0.0, 0.2), 0.0);
    close(interior(rod.end()), DVec3::new(0.3, 0.0, 0.2), 0.0);
    assert_eq!(rod.radius(), 0.01);
    // Around the first end (an h-point), the rod is the ball of radius 0.01
    // on the side away from the segment: move out from the end along -x.
    let a = pt(DVec3::new(0.0, 0.0, 0.2));
    let beyond_in = pt(mobius_add(a.coords(), at(DVec3::NEG_X, 0.0099)));
    let beyond_out = pt(mobius_add(a.coords(), at(DVec3::NEG_X, 0.0101)));
    // The transvection by `a` moves the origin to `a` and preserves distances.
    assert!((a.distance(beyond_in) - 0.0099).abs() < 1e-12);
    assert!(rod.contains(&beyond_in));
    assert!(!rod.contains(&beyond_out));
}

#[test]
fn rods_take_ideal_ends() {
    let s = scene(&format!(
        "Points {{ (0,0,0.2); (1,0,0); (-1,0,0); }} {MATTE} Objects {{ Rod %1, %2, 0.01, #1; Rod %3, %2, 0.02, #1; }}"
    ));
    let Shape::Rod(half) = &s.objects[0].shape else {
        panic!()
    };
    assert!(half.end().is_ideal() && !half.start().is_ideal());
    let Shape::Rod(whole) = &s.objects[1].shape else {
        panic!()
    };
    assert!(whole.start().is_ideal() && whole.end().is_ideal());
    // A rod between two ideal points is the whole h-cylinder: the origin's
    // neighbour at distance 0.019 from the x axis, far along it, is inside.
    let far = pt(mobius_add(at(DVec3::X, 5.0), at(DVec3::Y, 0.019)));
    assert!(whole.contains(&far));
}

#[test]
fn cylinder_is_the_equidistant_surface_of_the_whole_line() {
    let s = scene(&format!(
        "Points {{ (0,0,0); (0.1,0,0); }} {MATTE} Objects {{ Cylinder %1, %2, 0.02, #1; }}"
    ));
    let Shape::Cylinder(c) = &only_object(&s).shape else {
        panic!()
    };
    assert_eq!(c.radius(), 0.02);
    // Distance from the x axis of q = (x, y, 0):
    // sinh d = 2|y| / (1 - |q|^2) (the hyperboloid's |X_y| coordinate).
    let dist = |q: DVec3| (2.0 * q.y.abs() / (1.0 - q.length_squared())).asinh();
    for x in [-0.9, -0.3, 0.0, 0.5, 0.95] {
        // Far beyond both points, the tube keeps its radius.
        // sinh d = 2|y| / (1 - x^2 - y^2) is about 0.019 and 0.021.
        let inside = 0.5 * (1.0 - x * x) * 0.019;
        let outside = 0.5 * (1.0 - x * x) * 0.021;
        for (y, inside) in [(inside, true), (outside, false)] {
            let q = DVec3::new(x, y, 0.0);
            assert_eq!(c.contains(&pt(q)), inside, "x = {x}, distance {}", dist(q));
        }
    }
    let (back, front) = c.line().ends();
    close(back.coords(), DVec3::NEG_X, 1e-15);
    close(front.coords(), DVec3::X, 1e-15);
}

// ----- planes and horospheres ------------------------------------------------

#[test]
fn plane_through_three_points_is_oriented_by_the_right_hand_rule() {
    let s = scene(&format!(
        "Points {{ (0,0,0); (0.1,0,0); (0,0.1,0); }} {MATTE} Objects {{ Plane %1, %2, %3, #1; Plane %1, %3, %2, #1; }}"
    ));
    let Shape::Plane(p) = &s.objects[0].shape else {
        panic!()
    };
    match p.ball_shape() {
        BallShape::Flat { normal } => close(normal, DVec3::Z, 1e-15),
        other => panic!("{other:?}"),
    }
    let Shape::Plane(q) = &s.objects[1].shape else {
        panic!()
    };
    match q.ball_shape() {
        BallShape::Flat { normal } => close(normal, DVec3::NEG_Z, 1e-15),
        other => panic!("{other:?}"),
    }
}

#[test]
fn plane_off_the_origin_with_an_ideal_point() {
    let s = scene(&format!(
        "Points {{ a = (0.3,0,0.1); b = (0.3,0.2,0.1); c = (0,0,1); }} {MATTE} Objects {{ Plane %a, %b, %c, #1; }}"
    ));
    let Shape::Plane(p) = &only_object(&s).shape else {
        panic!()
    };
    for v in [DVec3::new(0.3, 0.0, 0.1), DVec3::new(0.3, 0.2, 0.1)] {
        assert!(p.signed_distance(&pt(v)).abs() < 1e-14);
    }
    // The sphere of the plane meets the absolute orthogonally and passes
    // through the ideal point.
    let BallShape::Sphere { center, radius } = p.ball_shape() else {
        panic!()
    };
    assert!((center.length_squared() - 1.0 - radius * radius).abs() < 1e-12);
    assert!(((DVec3::Z - center).length() - radius).abs() < 1e-12);
}

#[test]
fn horosphere_through_a_point() {
    let s = scene(&format!(
        "Points {{ i = (0,0,1); p = (0,0,0.5); }} {MATTE} Objects {{ Horosphere %i, %p, #1; }}"
    ));
    let Shape::Horosphere(h) = &only_object(&s).shape else {
        panic!()
    };
    // Tangent to the absolute at (0,0,1) and through (0,0,0.5): Euclidean
    // centre (0,0,0.75), radius 0.25.
    let (c, r) = h.euclidean();
    close(c, DVec3::new(0.0, 0.0, 0.75), 1e-15);
    assert!((r - 0.25).abs() < 1e-15);
    close(h.center().coords(), DVec3::Z, 0.0);
}

// ----- wireframes and options --------------------------------------------------

#[test]
fn wireframe_polygon_is_its_edges_as_rods() {
    let s = scene(&format!(
        "Points {{ (0,0,0.3); (0.2,0,0.3); (0.2,0.2,0.3); (0,0.2,0.3); }} {MATTE}
         Objects {{ sq: Polygon (%1, %2, %3, %4), #1, wireframe = 0.005; }}"
    ));
    let o = only_object(&s);
    assert_eq!(o.name.as_deref(), Some("sq"));
    let Shape::Wireframe(rods) = &o.shape else {
        panic!()
    };
    assert_eq!(rods.len(), 4);
    let corners = [
        DVec3::new(0.0, 0.0, 0.3),
        DVec3::new(0.2, 0.0, 0.3),
        DVec3::new(0.2, 0.2, 0.3),
        DVec3::new(0.0, 0.2, 0.3),
    ];
    for (i, r) in rods.iter().enumerate() {
        close(interior(r.start()), corners[i], 0.0);
        close(interior(r.end()), corners[(i + 1) % 4], 0.0);
        assert_eq!(r.radius(), 0.005);
    }
}

#[test]
fn platonic_wireframe_has_one_rod_per_edge() {
    // (name, edges) for the five solids.
    for (name, edges) in [
        ("Tetrahedron", 6),
        ("Cube", 12),
        ("Octahedron", 12),
        ("Dodecahedron", 30),
        ("Icosahedron", 30),
    ] {
        let s = scene(&format!(
            "{MATTE} Objects {{ {name} 0.4, #1, wireframe = 0.01; }}"
        ));
        let Shape::Wireframe(rods) = &only_object(&s).shape else {
            panic!()
        };
        assert_eq!(rods.len(), edges, "{name}");
        for r in rods.iter() {
            // Every end is a vertex: at the circumradius from the origin.
            for v in [r.start(), r.end()] {
                let p = pt(interior(v));
                assert!((p.distance_from_origin() - 0.4).abs() < 1e-12, "{name}");
            }
        }
    }
}

#[test]
fn edges_option_gives_faces_and_rods_with_the_edge_material() {
    let s = scene(&format!(
        "{MATTE} Objects {{ c: Cube 0.3, #1, edges = 0.01, edge_material = #edge; }}"
    ));
    assert_eq!(s.objects.len(), 2);
    assert!(matches!(s.objects[0].shape, Shape::Polyhedron(_)));
    assert_eq!(s.objects[0].material.index(), 0);
    let Shape::Wireframe(rods) = &s.objects[1].shape else {
        panic!()
    };
    assert_eq!(rods.len(), 12);
    assert_eq!(s.objects[1].material.index(), 1);
    assert_eq!(s.objects[0].name.as_deref(), Some("c"));
    assert_eq!(s.objects[1].name.as_deref(), Some("c"));
}

#[test]
fn at_moves_a_predefined_figure_by_the_translation_from_the_origin() {
    let c = DVec3::new(0.2, 0.1, 0.4);
    let s = scene(&format!(
        "Points {{ c = (0.2,0.1,0.4); }} {MATTE} Objects {{ Dodecahedron 0.3, #1, at = %c; }}"
    ));
    let Shape::Polyhedron(p) = &only_object(&s).shape else {
        panic!()
    };
    close(p.center().coords(), c, 1e-15);
    let (dirs, _) = hgeom::Platonic::Dodecahedron.combinatorics();
    let expected: Vec<DVec3> = dirs.iter().map(|d| mobius_add(c, at(*d, 0.3))).collect();
    for f in p.faces() {
        for v in f.vertices() {
            let v = interior(*v);
            assert!(
                expected.iter().any(|e| (v - *e).length() < 1e-14),
                "vertex {v:?} is not a translated vertex"
            );
            assert!((pt(v).distance(pt(c)) - 0.3).abs() < 1e-12);
        }
    }
}

// ----- transformations of objects, lights and the camera ---------------------------

const AXES: &str =
    "Points { o = (0,0,0); z = (0,0,0.2); y = (0,0.1,0); x = (0.1,0,0); c = (0.1,0,0.3); }";
const LINES: &str = "along_z: hline (%o, %z); about_y: hline (%o, %y); floor: hplane (%o, %x, %y);";

fn sphere_centre(o: &Object) -> DVec3 {
    match &o.shape {
        Shape::Sphere(s) => s.center().coords(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn named_object_is_translated_rotated_and_reflected() {
    let src = |moves: &str| {
        format!(
            "{AXES} {MATTE} Objects {{ ball: Sphere %c, 0.05, #1; }} Transformations {{ {LINES} {moves} }}"
        )
    };
    let c = DVec3::new(0.1, 0.0, 0.3);
    let z = DVec3::new(0.0, 0.0, 0.2);
    let s = scene(&src("@ball->Translate(%along_z);"));
    close(sphere_centre(&s.objects[0]), mobius_add(z, c), 1e-15);
    let s = scene(&src("@ball->Rotate(%about_y, 0.7);"));
    close(sphere_centre(&s.objects[0]), rot_y(c, 0.7), 1e-15);
    let s = scene(&src("@ball->Reflect(%floor);"));
    close(
        sphere_centre(&s.objects[0]),
        DVec3::new(0.1, 0.0, -0.3),
        1e-15,
    );
    // Statement order: first translate, then rotate.
    let s = scene(&src(
        "@ball->Translate(%along_z); @ball->Rotate(%about_y, 0.7);",
    ));
    close(
        sphere_centre(&s.objects[0]),
        rot_y(mobius_add(z, c), 0.7),
        1e-15,
    );
    let s = scene(&src(
        "@ball->Rotate(%about_y, 0.7); @ball->Translate(%along_z);",
    ));
    close(
        sphere_centre(&s.objects[0]),
        mobius_add(z, rot_y(c, 0.7)),
        1e-15,
    );
    // The radius is unchanged.
    let Shape::Sphere(sp) = &s.objects[0].shape else {
        panic!()
    };
    assert_eq!(sp.radius(), 0.05);
}

#[test]
fn object_transformations_do_not_move_its_points() {
    // `%c` keeps its position; a second sphere on it stays put.
    let s = scene(&format!(
        "{AXES} {MATTE} Objects {{ ball: Sphere %c, 0.05, #1; Sphere %c, 0.02, #1; }}
         Transformations {{ {LINES} @ball->Translate(%along_z); }}"
    ));
    close(sphere_centre(&s.objects[1]), DVec3::new(0.1, 0.0, 0.3), 0.0);
    assert!((sphere_centre(&s.objects[0]) - DVec3::new(0.1, 0.0, 0.3)).length() > 0.1);
}

#[test]
fn every_shape_kind_can_be_moved() {
    let s = scene(&format!(
        "{AXES} {MATTE} Points {{ i = (0,0,1); }}
         Objects {{
           a: Rod %x, %c, 0.01, #1;  b: Cylinder %x, %c, 0.01, #1;  p: Plane %o, %x, %c, #1;
           h: Horosphere %i, %c, #1; w: Cube 0.2, #1, edges = 0.01;
           poly: Polygon (%o, %x, %c), #1;
         }}
         Transformations {{ {LINES}
           @a->Translate(%along_z); @b->Translate(%along_z); @p->Translate(%along_z);
           @h->Translate(%along_z); @w->Translate(%along_z); @poly->Translate(%along_z);
         }}"
    ));
    let z = DVec3::new(0.0, 0.0, 0.2);
    let moved = |v: DVec3| mobius_add(z, v);
    let Shape::Rod(r) = &s.objects[0].shape else {
        panic!()
    };
    close(interior(r.start()), moved(DVec3::new(0.1, 0.0, 0.0)), 1e-15);
    close(interior(r.end()), moved(DVec3::new(0.1, 0.0, 0.3)), 1e-15);
    let Shape::Cylinder(cy) = &s.objects[1].shape else {
        panic!()
    };
    assert!(cy.line().distance_to(&pt(moved(DVec3::new(0.1, 0.0, 0.3)))) < 1e-12);
    let Shape::Plane(pl) = &s.objects[2].shape else {
        panic!()
    };
    assert!(pl.signed_distance(&pt(moved(DVec3::ZERO))).abs() < 1e-14);
    let Shape::Horosphere(h) = &s.objects[3].shape else {
        panic!()
    };
    // The translation along the z axis fixes the ideal point (0,0,1).
    close(h.center().coords(), DVec3::Z, 1e-15);
    let (hc, hr) = h.euclidean();
    assert!(((moved(DVec3::new(0.1, 0.0, 0.3)) - hc).length() - hr).abs() < 1e-14);
    let Shape::Polyhedron(cube) = &s.objects[4].shape else {
        panic!()
    };
    close(cube.center().coords(), z, 1e-15);
    let Shape::Wireframe(rods) = &s.objects[5].shape else {
        panic!()
    };
    for r in rods.iter() {
        let d = pt(interior(r.start())).distance(pt(z));
        assert!((d - 0.2).abs() < 1e-12);
    }
    let Shape::Polygon(poly) = &s.objects[6].shape else {
        panic!()
    };
    close(interior(poly.vertices()[0]), z, 1e-15);
}

#[test]
fn named_light_is_moved() {
    let s = scene(&format!(
        "{AXES} Lights {{ sun: %c, (1,1,1), (1,1,1); %o, (1,1,1), (1,1,1); }}
         Transformations {{ {LINES} @sun->Rotate(%about_y, -0.4); }}"
    ));
    let Light { position, name, .. } = &s.lights[0];
    assert_eq!(name.as_deref(), Some("sun"));
    close(
        position.coords(),
        rot_y(DVec3::new(0.1, 0.0, 0.3), -0.4),
        1e-15,
    );
    assert_eq!(s.lights[1].name, None);
}

#[test]
fn camera_rotation_about_the_eye_turns_the_view() {
    let s = scene(&format!(
        "{AXES} Transformations {{ {LINES} @camera->Rotate(%about_y, 1.5707963267948966); }}"
    ));
    // The default camera: eye at the origin, target (0,0,0.1), up +y.
    close(s.camera.eye.coords(), DVec3::ZERO, 0.0);
    close(s.camera.target.coords(), DVec3::new(0.1, 0.0, 0.0), 1e-15);
    // Up is turned with the camera; about y it stays +y.
    let up = s.camera.up.unwrap().coords();
    close(up.normalize(), DVec3::Y, 1e-15);
}

#[test]
fn camera_translation_moves_eye_target_and_up() {
    let s = scene(&format!(
        "{AXES} Globals {{ from = (0,0,0); to = (0,0,0.1); up = (0,0.1,0); }}
         Transformations {{ {LINES} @camera->Translate(%along_z); }}"
    ));
    let z = DVec3::new(0.0, 0.0, 0.2);
    close(s.camera.eye.coords(), z, 1e-15);
    close(
        s.camera.target.coords(),
        mobius_add(z, DVec3::new(0.0, 0.0, 0.1)),
        1e-15,
    );
    close(
        s.camera.up.unwrap().coords(),
        mobius_add(z, DVec3::new(0.0, 0.1, 0.0)),
        1e-15,
    );
}

#[test]
fn default_up_turns_with_the_camera() {
    // Rolling the camera about its line of sight by 90 degrees turns +y to -x.
    let s = scene(
        "Points { o = (0,0,0); t = (0,0,0.3); }
         Globals { from = %o; to = %t; }
         Transformations { sight: hline (%o, %t); @camera->Rotate(%sight, 1.5707963267948966); }",
    );
    let up = s.camera.up.unwrap().coords();
    close(up.normalize(), DVec3::NEG_X, 1e-15);
}

#[test]
fn thesis_figure_33_one_translation_of_scene_and_observer() {
    // Moving the scene's objects, lights and the camera by one isometry
    // keeps every distance between them (the image is unchanged, docs/rendering.md).
    let s = scene(&format!(
        "{AXES} {MATTE} Lights {{ l: %x, (1,1,1), (1,1,1); }}
         Objects {{ b: Sphere %c, 0.05, #1; }}
         Transformations {{ {LINES}
           @b->Translate(%along_z); @l->Translate(%along_z); @camera->Translate(%along_z); }}"
    ));
    let eye = s.camera.eye;
    let ball = pt(sphere_centre(&s.objects[0]));
    let light = s.lights[0].position;
    assert!(
        (eye.distance(ball) - Point::ORIGIN.distance(pt(DVec3::new(0.1, 0.0, 0.3)))).abs() < 1e-13
    );
    assert!(
        (eye.distance(light) - Point::ORIGIN.distance(pt(DVec3::new(0.1, 0.0, 0.0)))).abs() < 1e-13
    );
}

// ----- diagnostics ---------------------------------------------------------------

const P: &str = "Points { a = (0,0,0.2); b = (0.1,0,0.2); c = (0,0.1,0.2); i = (0,0,1); }";

#[test]
fn unknown_object_suggests_the_nearest_name() {
    let src = format!("{P} {MATTE} Objects {{ Rodd %a, %b, 0.01, #1; }}");
    let d = expect(&src, "HSC0105", Severity::Error, "Rodd", 0);
    assert!(d.help.unwrap().contains("did you mean `Rod`?"));
}

#[test]
fn rod_arity_and_types() {
    let src = format!("{P} {MATTE} Objects {{ Rod %a, %b, #1; }}");
    let d = expect(&src, "HSC0107", Severity::Error, "Rod %a, %b, #1;", 0);
    assert!(
        d.message
            .contains("two end points, a radius and a material")
    );
    let src = format!("{P} {MATTE} Objects {{ Rod %a, %b, 0.01, #1, 5; }}");
    expect(&src, "HSC0107", Severity::Error, "5", 0);
    let src = format!("{P} {MATTE} Objects {{ Rod %a, 0.3, 0.01, #1; }}");
    let d = expect(&src, "HSC0108", Severity::Error, "0.3", 0);
    assert!(d.message.contains("a rod end"));
}

#[test]
fn non_positive_radius_and_thickness() {
    let src = format!("{P} {MATTE} Objects {{ Cylinder %a, %b, -0.5, #1; }}");
    expect(&src, "HSC0303", Severity::Error, "-0.5", 0);
    let src = format!("{MATTE} Objects {{ Cube 0.3, #1, wireframe = -0.01; }}");
    let d = expect(&src, "HSC0303", Severity::Error, "-0.01", 0);
    assert!(d.message.contains("`wireframe` thickness"));
}

#[test]
fn coincident_rod_and_cylinder_points() {
    let src = format!("{P} {MATTE} Objects {{ Rod %a, %a, 0.01, #1; }}");
    expect(&src, "HSC0304", Severity::Error, "%a", 1);
    let src = format!("{P} {MATTE} Objects {{ Cylinder %i, (0,0,1), 0.01, #1; }}");
    expect(&src, "HSC0304", Severity::Error, "(0,0,1)", 1);
}

#[test]
fn collinear_plane_points() {
    let src = format!("{MATTE} Objects {{ Plane (0,0,0), (0.1,0,0), (0.2,0,0), #1; }}");
    expect(
        &src,
        "HSC0310",
        Severity::Error,
        "(0,0,0), (0.1,0,0), (0.2,0,0)",
        0,
    );
    let src = format!("{P} Transformations {{ hplane (%a, %b, %a); %c->Reflect(%1); }}");
    expect(&src, "HSC0310", Severity::Error, "%a, %b, %a", 0);
}

#[test]
fn horosphere_centre_must_be_ideal_and_its_point_interior() {
    let src = format!("{P} {MATTE} Objects {{ Horosphere %a, %b, #1; }}");
    let d = expect(&src, "HSC0309", Severity::Error, "%a", 0);
    assert!(d.message.contains("horosphere centre"));
    let src = format!("{P} {MATTE} Objects {{ Horosphere %i, %i, #1; }}");
    expect(&src, "HSC0302", Severity::Error, "%i", 1);
}

#[test]
fn ideal_point_as_figure_centre_is_rejected() {
    let src = format!("{P} {MATTE} Objects {{ Cube 0.2, #1, at = %i; }}");
    expect(&src, "HSC0302", Severity::Error, "%i", 0);
}

#[test]
fn options_an_object_does_not_take() {
    let src = format!("{P} {MATTE} Objects {{ Sphere %a, 0.1, #1, wireframe = 0.01; }}");
    let d = expect(&src, "HSC0103", Severity::Error, "wireframe", 0);
    assert!(d.help.unwrap().contains("`Sphere` takes no options"));
    let src = format!("{MATTE} Objects {{ Cube 0.2, #1, wirefrme = 0.01; }}");
    let d = expect(&src, "HSC0103", Severity::Error, "wirefrme", 0);
    assert!(d.help.unwrap().contains("did you mean `wireframe`?"));
    let src = format!("{P} {MATTE} Objects {{ Polygon (%a, %b, %c), #1, at = %a; }}");
    expect(&src, "HSC0103", Severity::Error, "at", 0);
}

#[test]
fn duplicate_option_is_a_warning() {
    let src = format!("{MATTE} Objects {{ Cube 0.2, #1, edges = 0.01, edges = 0.02; }}");
    expect(&src, "HSC0104", Severity::Warning, "edges", 1);
}

#[test]
fn wireframe_and_edges_conflict() {
    let src = format!("{MATTE} Objects {{ Cube 0.2, #1, wireframe = 0.01, edges = 0.01; }}");
    expect(&src, "HSC0112", Severity::Error, "edges = 0.01", 0);
}

#[test]
fn edge_material_without_edges_has_no_effect() {
    let src = format!("{MATTE} Objects {{ Cube 0.2, #1, edge_material = #2; }}");
    expect(&src, "HSC1007", Severity::Warning, "edge_material", 0);
}

#[test]
fn positional_argument_after_an_option() {
    let src = format!("{MATTE} Objects {{ Cube 0.2, edges = 0.01, #1; }}");
    expect(&src, "HSC0108", Severity::Error, "#1", 0);
}

#[test]
fn undefined_transformation_targets() {
    let base = format!("{P} {MATTE} Objects {{ ball: Sphere %a, 0.05, #1; }}");
    let src = format!("{base} Transformations {{ l: hline (%a, %b); @bal->Translate(%l); }}");
    let d = expect(&src, "HSC0204", Severity::Error, "@bal", 0);
    assert!(d.help.unwrap().contains("did you mean `@ball`?"));
    let src = format!("{base} Transformations {{ l: hline (%a, %b); @1->Translate(%l); }}");
    expect(&src, "HSC0204", Severity::Error, "@1", 0);
    let src = format!("{base} Transformations {{ l: hline (%a, %b); @c->Translate(%l); }}");
    let d = expect(&src, "HSC0204", Severity::Error, "@c", 0);
    assert!(d.help.unwrap().contains("`%c->"));
    // An object written as a point: the help says to use `@`.
    let src = format!("{base} Transformations {{ l: hline (%a, %b); %ball->Translate(%l); }}");
    let d = expect(&src, "HSC0201", Severity::Error, "%ball", 0);
    assert!(d.help.unwrap().contains("@ball"));
}

#[test]
fn a_failed_object_does_not_cascade_into_its_transformations() {
    let src = format!(
        "{P} {MATTE} Objects {{ ball: Sphere %a, -1, #1; }} Transformations {{ l: hline (%a, %b); @ball->Translate(%l); }}"
    );
    let c = compile(&src);
    let codes: Vec<&str> = c
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code.as_str())
        .collect();
    assert_eq!(codes, ["HSC0303"]);
}

#[test]
fn reserved_and_duplicate_target_names() {
    let src = format!("{P} {MATTE} Objects {{ camera: Sphere %a, 0.05, #1; }}");
    expect(&src, "HSC0111", Severity::Error, "camera", 0);
    let src = format!(
        "{P} {MATTE} Objects {{ dup: Sphere %a, 0.05, #1; }} Lights {{ dup: %b, (1,1,1), (1,1,1); }}"
    );
    // The later declaration in the file is the duplicate, whatever the
    // order in which sections are processed.
    expect(&src, "HSC0110", Severity::Error, "dup", 1);
}

#[test]
fn a_material_cannot_be_transformed() {
    let src = format!("{P} {MATTE} Transformations {{ l: hline (%a, %b); #1->Translate(%l); }}");
    expect(&src, "HSC0108", Severity::Error, "#1", 0);
}

#[test]
fn moving_an_object_beyond_what_f64_holds() {
    // Three translations by distance ~14.5 each: beyond distance 37.
    let src = format!(
        "Points {{ o = (0,0,0); far = (0,0,0.999999); }} {MATTE}
         Objects {{ ball: Sphere %o, 0.1, #1; }}
         Transformations {{ l: hline (%o, %far);
           @ball->Translate(%l); @ball->Translate(%l); @ball->Translate(%l); }}"
    );
    expect(&src, "HSC0308", Severity::Error, "@ball", 2);
}

#[test]
fn one_run_reports_every_problem_in_objects_and_transformations() {
    let src = format!(
        "{P} {MATTE}
         Objects {{
           Rodd %a, %b, 0.01, #1;
           Rod %a, %a, 0.01, #1;
           Horosphere %a, %b, #1;
           Cube 0.2, #1, wireframe = 0.01, edges = 0.01;
           Sphere %a, 0.1, #1, edges = 0.1;
         }}
         Transformations {{ @nothing->Rotate(%1, 0.1); }}"
    );
    let c = compile(&src);
    let codes: Vec<&str> = c
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code.as_str())
        .collect();
    assert_eq!(
        codes,
        [
            "HSC0105", "HSC0304", "HSC0309", "HSC0112", "HSC0103", "HSC0204", "HSC0203"
        ]
    );
}

// ----- predefined figures ----------------------------------------------------

/// The ball point with Klein coordinates `k`: `k / (1 + sqrt(1 - |k|^2))`.
fn from_klein(k: DVec3) -> DVec3 {
    k / (1.0 + (1.0 - k.length_squared()).sqrt())
}

/// The ball point of a hyperboloid vector `(x, t)`: `x / (1 + t)`.
fn from_hyperboloid(x: DVec3, t: f64) -> DVec3 {
    x / (1.0 + t)
}

fn polygon_vertices(o: &Object) -> Vec<Vertex> {
    match &o.shape {
        Shape::Polygon(p) => p.vertices().to_vec(),
        other => panic!("not a polygon: {other:?}"),
    }
}

fn polyhedron(o: &Object) -> &hgeom::Polyhedron {
    match &o.shape {
        Shape::Polyhedron(p) => p,
        other => panic!("not a polyhedron: {other:?}"),
    }
}

#[test]
fn regular_polygons_by_circumradius() {
    for (name, n) in [
        ("Triangle", 3),
        ("Square", 4),
        ("Pentagon", 5),
        ("Hexagon", 6),
    ] {
        let s = scene(&format!(
            "{MATTE} Objects {{ {name} 0.6, #1, at = (0,0,0.5); }}"
        ));
        let vs = polygon_vertices(&s.objects[0]);
        assert_eq!(vs.len(), n, "{name}");
        let centre = pt(DVec3::new(0.0, 0.0, 0.5));
        for v in &vs {
            assert!((pt(interior(*v)).distance(centre) - 0.6).abs() < 1e-12);
        }
        // Equal sides: sinh(s/2) = sinh(R) sin(pi/n) (right triangle centre,
        // vertex, side midpoint).
        let side = 2.0 * (0.6f64.sinh() * (std::f64::consts::PI / n as f64).sin()).asinh();
        for i in 0..n {
            let d = pt(interior(vs[i])).distance(pt(interior(vs[(i + 1) % n])));
            assert!((d - side).abs() < 1e-12, "{name}: side {d} vs {side}");
        }
    }
    // The general form gives the same pentagon.
    let a = scene(&format!(
        "{MATTE} Objects {{ Pentagon 0.3, #1, at = (0,0,0.5); }}"
    ));
    let b = scene(&format!(
        "{MATTE} Objects {{ RegularPolygon 5, 0.3, #1, at = (0,0,0.5); }}"
    ));
    assert_eq!(a.objects[0].shape, b.objects[0].shape);
}

#[test]
fn ideal_regular_polygons() {
    let s = scene(&format!(
        "{MATTE} Objects {{ IdealPentagon #1; IdealRegularPolygon 3, #1, wireframe = 0.01; }}"
    ));
    let vs = polygon_vertices(&s.objects[0]);
    assert_eq!(vs.len(), 5);
    for v in &vs {
        assert!(v.is_ideal());
        let c = v.coords();
        assert!((c.length() - 1.0).abs() < 1e-15 && c.z == 0.0);
    }
    let Shape::Wireframe(rods) = &s.objects[1].shape else {
        panic!()
    };
    assert_eq!(rods.len(), 3);
    assert!(
        rods.iter()
            .all(|r| r.start().is_ideal() && r.end().is_ideal())
    );
}

#[test]
fn lambert_quadrilateral_matches_the_klein_construction() {
    let (a, b) = (0.5f64, 0.7f64);
    let s = scene(&format!(
        "{MATTE} Objects {{ Lambert 0.5, 0.7, #1, at = (0,0,0.5); }}"
    ));
    let t = s.objects.len();
    assert_eq!(t, 1);
    let s0 = scene(&format!("{MATTE} Objects {{ q: Lambert 0.5, 0.7, #1; }}"));
    let vs: Vec<DVec3> = polygon_vertices(&s0.objects[0])
        .into_iter()
        .map(interior)
        .collect();
    // O at the origin, A on +x at distance a, B on +y at distance b, and C
    // with Klein coordinates (tanh a, tanh b); order O, B, C, A.
    close(vs[0], DVec3::ZERO, 0.0);
    close(vs[1], at(DVec3::Y, b), 1e-15);
    close(
        vs[2],
        from_klein(DVec3::new(a.tanh(), b.tanh(), 0.0)),
        1e-15,
    );
    close(vs[3], at(DVec3::X, a), 1e-15);
}

#[test]
fn saccheri_quadrilateral_matches_the_hyperboloid_construction() {
    let (base, leg) = (0.6f64, 0.4f64);
    let s = scene(&format!("{MATTE} Objects {{ q: Saccheri 0.6, 0.4, #1; }}"));
    let vs: Vec<DVec3> = polygon_vertices(&s.objects[0])
        .into_iter()
        .map(interior)
        .collect();
    let h = 0.5 * base;
    // Q± = cosh(leg) P± + sinh(leg) (0,1,0,0) on the hyperboloid.
    let q = |sign: f64| {
        from_hyperboloid(
            DVec3::new(sign * leg.cosh() * h.sinh(), leg.sinh(), 0.0),
            leg.cosh() * h.cosh(),
        )
    };
    close(vs[0], at(DVec3::NEG_X, h), 1e-15);
    close(vs[1], q(-1.0), 1e-15);
    close(vs[2], q(1.0), 1e-15);
    close(vs[3], at(DVec3::X, h), 1e-15);
    // The legs have length `leg`.
    assert!((pt(vs[0]).distance(pt(vs[1])) - leg).abs() < 1e-13);
}

#[test]
fn polyhedral_figures_have_the_right_counts_and_circumradius() {
    // (keyword, faces, vertices, edges)
    for (name, faces, verts, edges) in [
        ("Cuboctahedron", 14, 12, 24),
        ("SmallStellatedDodecahedron", 60, 32, 90),
        ("StarDodecahedron", 60, 32, 90),
        ("GoldenRectangles", 3, 12, 12),
    ] {
        let s = scene(&format!(
            "{MATTE} Objects {{ {name} 0.5, #1, edges = 0.01; }}"
        ));
        let p = polyhedron(&s.objects[0]);
        assert_eq!(p.faces().len(), faces, "{name}");
        let mut seen: Vec<DVec3> = Vec::new();
        for f in p.faces() {
            for v in f.vertices() {
                let c = interior(*v);
                if !seen.iter().any(|q| (*q - c).length() < 1e-12) {
                    seen.push(c);
                }
            }
        }
        assert_eq!(seen.len(), verts, "{name}");
        let Shape::Wireframe(rods) = &s.objects[1].shape else {
            panic!()
        };
        assert_eq!(rods.len(), edges, "{name}");
        // Every vertex is within the circumradius (the tips and the
        // cuboctahedron's and rectangles' vertices are at it).
        let far = seen
            .iter()
            .map(|c| pt(*c).distance_from_origin())
            .fold(0.0, f64::max);
        assert!((far - 0.5).abs() < 1e-12, "{name}: {far}");
    }
}

#[test]
fn ideal_platonic_solids() {
    let s = scene(&format!(
        "{MATTE} Objects {{ IdealCube #1, at = (0,0,0.3); }}"
    ));
    let p = polyhedron(&s.objects[0]);
    assert_eq!(p.faces().len(), 6);
    assert!(
        p.faces()
            .iter()
            .flat_map(|f| f.vertices())
            .all(Vertex::is_ideal)
    );
}

#[test]
fn cube_435_has_72_degree_dihedral_angles() {
    let s = scene(&format!(
        "{MATTE} Objects {{ Cube435 #1, at = (0,0,0.9); }}"
    ));
    let p = polyhedron(&s.objects[0]);
    // cosh R = phi^2 / sqrt 2, R the circumradius.
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let r = (phi * phi / 2f64.sqrt()).acosh();
    let c = p.center();
    for f in p.faces() {
        for v in f.vertices() {
            assert!((pt(interior(*v)).distance(c) - r).abs() < 1e-12);
        }
    }
    // Adjacent faces (sharing an edge): -<N1,N2> = cos of the interior angle.
    let faces = p.faces();
    let mut checked = 0;
    for i in 0..faces.len() {
        for j in i + 1..faces.len() {
            let shared = faces[i]
                .vertices()
                .iter()
                .filter(|a| {
                    faces[j]
                        .vertices()
                        .iter()
                        .any(|b| (a.coords() - b.coords()).length() < 1e-12)
                })
                .count();
            if shared == 2 {
                let cos =
                    -hgeom::lorentz::dot(faces[i].plane().normal(), faces[j].plane().normal());
                assert!(
                    (cos - (0.4 * std::f64::consts::PI).cos()).abs() < 1e-12,
                    "{cos}"
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 12);
}

#[test]
fn tessellation_435_cells_fit_face_to_face() {
    let s = scene(&format!(
        "{MATTE} Objects {{ t: Tessellation435 1, #1, edges = 0.005, at = (0,0,0.8); }}"
    ));
    // 7 cells and one wireframe, all named `t`.
    assert_eq!(s.objects.len(), 8);
    assert!(s.objects.iter().all(|o| o.name.as_deref() == Some("t")));
    let centre = polyhedron(&s.objects[0]).center();
    // Neighbouring centres are twice the inradius apart; the inradius has
    // Klein distance h with h^2 = sqrt 5 - 2.
    let inradius = (5f64.sqrt() - 2.0).sqrt().atanh();
    for o in &s.objects[1..7] {
        let d = polyhedron(o).center().distance(centre);
        assert!((d - 2.0 * inradius).abs() < 1e-12, "{d}");
    }
    // 12 edges of the centre cell, 8 more for each neighbour: shared edges
    // are drawn once although the cells compute them separately.
    let Shape::Wireframe(rods) = &s.objects[7].shape else {
        panic!()
    };
    assert_eq!(rods.len(), 12 + 6 * 8);
    assert_eq!(
        scene(&format!(
            "{MATTE} Objects {{ Tessellation435 2, #1, at = (0,0,0.8); }}"
        ))
        .objects
        .len(),
        37
    );
}

#[test]
fn figure_diagnostics() {
    let src = format!("{MATTE} Objects {{ Lambert 1, 1.5, #1; }}");
    let d = expect(&src, "HSC0311", Severity::Error, "1, 1.5", 0);
    assert!(d.help.unwrap().contains("sinh a · sinh b < 1"));
    let src = format!("{MATTE} Objects {{ Tessellation435 8, #1; }}");
    expect(&src, "HSC0403", Severity::Error, "8", 0);
    let src = format!("{MATTE} Objects {{ RegularPolygon 7, 0.3, #1; }}");
    expect(&src, "HSC0403", Severity::Error, "7", 0);
    // Every object length has one range, 0 to 36, checked before building.
    let src = format!("{MATTE} Objects {{ Pentagon 80, #1; }}");
    expect(&src, "HSC0403", Severity::Error, "80", 0);
    let src = format!("{MATTE} Objects {{ Saccheri 0.5, #1; }}");
    let d = expect(&src, "HSC0107", Severity::Error, "Saccheri 0.5, #1;", 0);
    assert!(d.help.unwrap().contains("Saccheri base, leg, #M;"));
    let src = format!("{MATTE} Objects {{ Cube435 0.5, #1; }}");
    expect(&src, "HSC0107", Severity::Error, "#1", 0);
}

#[test]
fn lints_count_statements_not_the_objects_they_give() {
    // The eye at the origin is inside the middle cell of the honeycomb: one
    // warning for the statement, not one per cell.
    let src = format!("{MATTE} Objects {{ Tessellation435 2, #1, edges = 0.01; }}");
    let d = expect(
        &src,
        "HSC1006",
        Severity::Warning,
        "Tessellation435 2, #1, edges = 0.01;",
        0,
    );
    assert!(d.message.contains("eye is inside"));
    // A cube with edges behind the eye: faces and edges are one warning.
    let src = format!("{MATTE} Objects {{ Cube 0.1, #1, edges = 0.01, at = (0,0,-0.5); }}");
    let c = compile(&src);
    let behind = c
        .diagnostics
        .iter()
        .filter(|d| d.code.as_str() == "HSC1005")
        .count();
    assert_eq!(behind, 1, "{:#?}", c.diagnostics);
}

// ----- robustness ------------------------------------------------------------

/// Scenes made of the new objects, options and transformations with
/// arguments drawn from a pool of good and bad values.
fn object_scene() -> impl Strategy<Value = String> {
    let keyword = prop::sample::select(vec![
        "Sphere",
        "Polygon",
        "Rod",
        "Cylinder",
        "Plane",
        "Horosphere",
        "Cube",
        "Pentagon",
        "RegularPolygon",
        "IdealSquare",
        "Lambert",
        "Saccheri",
        "IdealCube",
        "Cuboctahedron",
        "StarDodecahedron",
        "GoldenRectangles",
        "Cube435",
        "Tessellation435",
        "Nope",
    ]);
    let value = prop::sample::select(vec![
        "%1",
        "%2",
        "%3",
        "%4",
        "%9",
        "%i",
        "#1",
        "#2",
        "#7",
        "@x",
        "0",
        "-1",
        "0.2",
        "1.5",
        "40",
        "1e300",
        "3",
        "(0,0,0.3)",
        "(0,0,1)",
        "(2,0,0)",
        "(%1,%2,%3)",
        "(%i,%1)",
        "x",
    ]);
    let option = prop::sample::select(vec![
        "wireframe = 0.01",
        "edges = 0.02",
        "edges = -1",
        "edge_material = #1",
        "edge_material = %1",
        "at = %1",
        "at = %i",
        "at = (0,0,0.999999)",
        "bogus = 1",
    ]);
    let object = (
        prop::option::of(prop::sample::select(vec!["x", "y", "camera"])),
        keyword,
        prop::collection::vec(value, 0..5),
        prop::collection::vec(option, 0..3),
    )
        .prop_map(|(label, k, args, opts)| {
            let mut parts = vec![format!("{k} {}", args.first().copied().unwrap_or(""))];
            parts.extend(args.iter().skip(1).map(|a| a.to_string()));
            parts.extend(opts.iter().map(|o| o.to_string()));
            let label = label.map(|l| format!("{l}: ")).unwrap_or_default();
            format!("{label}{};", parts.join(", "))
        });
    let mv = (
        prop::sample::select(vec!["@x", "@y", "@camera", "@3", "%1", "#1"]),
        prop::sample::select(vec![
            "Rotate(%1, 0.5)",
            "Translate(%1)",
            "Reflect(%1)",
            "Translate(%far)",
        ]),
    )
        .prop_map(|(t, op)| format!("{t}->{op};"));
    (
        prop::collection::vec(object, 0..5),
        prop::collection::vec(mv, 0..5),
    )
        .prop_map(|(objects, moves)| {
            format!(
                "Points {{ (0,0,0); (0,0,0.2); (0.1,0,0.2); i = (0,1,0); far = (0,0,0.9999999); }}
                 BRDFs {{ diffuse = (1,1,1); edge: diffuse = (1,0,0); }}
                 Lights {{ y: (0,0.1,0), (1,1,1), (1,1,1); }}
                 Objects {{ {} }}
                 Transformations {{ hline (%1, %2); far: hline (%1, %far); hplane (%1, %2, %3); {} }}",
                objects.join(" "),
                moves.join(" ")
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn objects_and_moves_never_panic(src in object_scene()) {
        let c = compile(&src);
        for d in &c.diagnostics {
            prop_assert!(d.span.start() <= d.span.end() && d.span.end() <= src.len());
            prop_assert_eq!(d.severity, d.code.severity());
        }
        prop_assert_eq!(c.scene.is_some(), !c.has_errors());
        if let Some(scene) = &c.scene {
            for o in &scene.objects {
                prop_assert!(o.material.index() < scene.materials.len());
            }
        }
    }
}
