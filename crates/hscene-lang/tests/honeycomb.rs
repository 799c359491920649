//! The `Honeycomb {p,q,r}` object: every one of the 15 symbols lowers to
//! one walking object, its options become the style and the materials of
//! its parts, `at` moves its base cell, and the symbols of other geometries
//! are refused on the symbol (their messages are in the golden snapshots
//! `tests/broken/9x-honeycomb-*.hsc`).

use hgeom::Schlafli;
use hgeom::glam::DVec3;
use hscene_lang::ir::{Honeycomb, MaterialId, Scene, Shape};
use hscene_lang::{Severity, compile};

const MATERIALS: &str = "BRDFs { edge: diffuse = (1, 1, 1); glass: diffuse = (0.2, 0.4, 0.9), trans = 0.6; \
                         a: diffuse = (1, 0, 0); b: diffuse = (0, 1, 0); }\n";

#[track_caller]
fn scene(objects: &str) -> Scene {
    let src = format!("{MATERIALS}Objects {{ {objects} }}");
    let c = compile(&src);
    assert!(!c.has_errors(), "errors for {src}: {:#?}", c.diagnostics);
    c.scene.expect("no errors, so a scene")
}

#[track_caller]
fn only_honeycomb(s: &Scene) -> &Honeycomb {
    assert_eq!(s.objects.len(), 1, "one object, however many cells");
    match &s.objects[0].shape {
        Shape::Honeycomb(h) => h,
        other => panic!("expected a honeycomb, got a {}", other.kind_name()),
    }
}

fn material(s: &Scene, name: &str) -> MaterialId {
    let index = ["edge", "glass", "a", "b"]
        .iter()
        .position(|n| *n == name)
        .expect("a material of MATERIALS");
    MaterialId::of(&s.materials, index).expect("declared")
}

#[test]
fn every_hyperbolic_symbol_is_one_object_with_edges_by_default() {
    for (p, q, r) in Schlafli::ALL {
        let s = scene(&format!("Honeycomb {{{p},{q},{r}}}, #edge;"));
        let h = only_honeycomb(&s);
        let symbol = h.surface.symbol();
        assert_eq!((symbol.p(), symbol.q(), symbol.r()), (p, q, r));
        assert_eq!(h.surface.style().edges, Some(0.02), "{{{p},{q},{r}}}");
        assert!(
            !h.surface.style().faces
                && h.surface.style().vertices.is_none()
                && h.surface.style().depth.is_none()
        );
        assert_eq!(h.surface.style().cell_classes, 1);
        assert_eq!(s.objects[0].shape.primitive_count(), 1);
        assert_eq!(s.objects[0].shape.kind_name(), "honeycomb");
        assert_eq!(s.objects[0].material, material(&s, "edge"));
        // The base point is the origin until `at` moves it.
        let c = h.surface.base_cell_center().coords();
        assert!(c.length() < 1e-15, "{c:?}");
    }
}

#[test]
fn options_become_the_style_and_the_materials_of_the_parts() {
    let s = scene(
        "Honeycomb {5,3,4}, #edge, edges = 0.03, faces = #glass, vertices = 0.05, depth = 2;",
    );
    let h = only_honeycomb(&s);
    assert_eq!(h.surface.style().edges, Some(0.03));
    assert!(h.surface.style().faces);
    assert_eq!(h.surface.style().vertices, Some(0.05));
    assert_eq!(h.surface.style().depth, Some(2));
    assert_eq!(h.materials.faces, Some(material(&s, "glass")));
    assert!(h.materials.palette.is_empty());

    // `wireframe` is `edges`; faces alone draw no edges.
    let s = scene("Honeycomb {4,3,5}, #edge, wireframe = 0.01;");
    assert_eq!(only_honeycomb(&s).surface.style().edges, Some(0.01));
    let s = scene("Honeycomb {4,3,5}, #edge, faces = #glass;");
    let h = only_honeycomb(&s);
    assert_eq!(h.surface.style().edges, None);
    assert!(h.surface.style().faces);

    // `colors` colours the default edges, one class per colour, and
    // closes no cell.
    let s = scene("Honeycomb {3,5,3}, #edge, colors = (#a, #b, #glass);");
    let h = only_honeycomb(&s);
    assert!(!h.surface.style().faces);
    assert_eq!(h.surface.style().edges, Some(0.02));
    assert_eq!(h.surface.style().cell_classes, 3);
    assert_eq!(
        h.materials.palette,
        [material(&s, "a"), material(&s, "b"), material(&s, "glass")]
    );
}

#[test]
fn at_moves_the_base_cell_by_the_translation_from_the_origin() {
    let s = scene("Honeycomb {4,3,5}, #edge, at = (0.1, -0.2, 0.3);");
    let c = only_honeycomb(&s).surface.base_cell_center().coords();
    assert!((c - DVec3::new(0.1, -0.2, 0.3)).length() < 1e-14, "{c:?}");
}

#[test]
fn named_honeycombs_move_with_their_transformations() {
    let src = format!(
        "{MATERIALS}Points {{ o = (0, 0, 0); x = (0.2, 0, 0); }}\n\
         Objects {{ cells: Honeycomb {{5,3,5}}, #edge; }}\n\
         Transformations {{ l: hline (%o, %x); @cells->Translate(%l); }}"
    );
    let c = compile(&src);
    assert!(!c.has_errors(), "{:#?}", c.diagnostics);
    let s = c.scene.expect("no errors");
    let centre = only_honeycomb(&s).surface.base_cell_center().coords();
    assert!(
        (centre - DVec3::new(0.2, 0.0, 0.0)).length() < 1e-14,
        "{centre:?}"
    );
}

#[test]
fn symbols_of_other_geometries_are_errors_on_the_symbol() {
    for (symbol, word) in [
        ("{4,3,4}", "Euclidean"),
        ("{3,3,5}", "spherical"),
        ("{5,3,3}", "spherical"),
        ("{7,3,3}", "hyperideal"),
        ("{3,3,7}", "hyperideal"),
        ("{2,3,5}", "degenerate"),
        ("{4,3,5,3}", "entries"),
    ] {
        let src = format!("{MATERIALS}Objects {{ Honeycomb {symbol}, #edge; }}");
        let c = compile(&src);
        let errors: Vec<_> = c.diagnostics.iter().filter(|d| d.is_error()).collect();
        assert_eq!(errors.len(), 1, "{symbol}: {errors:#?}");
        let d = errors[0];
        assert_eq!(d.code.as_str(), "HSC0313", "{symbol}");
        assert_eq!(d.severity, Severity::Error);
        assert_eq!(&src[d.span.start()..d.span.end()], symbol);
        assert!(d.message.contains(word), "{symbol}: {}", d.message);
    }
}

#[test]
fn the_keyword_and_its_options_are_in_the_vocabulary() {
    let words = hscene_lang::vocabulary::object_keywords();
    assert!(words.contains(&"Honeycomb"));
    let options = hscene_lang::vocabulary::object_options();
    for o in ["faces", "vertices", "depth", "colors", "rings"] {
        assert!(options.contains(&o), "{o}");
    }
}

#[test]
fn the_formatter_keeps_the_symbol_as_mathematicians_write_it() {
    let src = "Objects{Honeycomb { 6 ,3, 3 },#1,depth=1;}";
    let out = hscene_lang::format(src).expect("no syntax errors");
    assert_eq!(out, "Objects {\n    Honeycomb {6,3,3}, #1, depth = 1;\n}\n");
}

/// Every hit says what it met; faces take `face_colors` or `faces = #F`,
/// edges and vertices the palette by class, or `#M` without one (classes
/// count round both palettes).
#[test]
fn each_part_is_drawn_in_its_material() {
    use hgeom::{HoneycombPart, Ray, decode_honeycomb_part};
    let directions = (0..3000).map(|i| {
        let a = f64::from(i) * 0.618_033_988_749_895 * std::f64::consts::TAU;
        let z = 1.0 - 2.0 * (f64::from(i) + 0.5) / 3000.0;
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * a.cos(), r * a.sin(), z)
    });
    let directions: Vec<DVec3> = directions.collect();
    let cases = [
        "Honeycomb {5,3,4}, #edge, edges = 0.05, vertices = 0.15, colors = (#a, #b);",
        "Honeycomb {5,3,4}, #edge, edges = 0.05, vertices = 0.15, faces = #glass, colors = (#a, #b);",
        "Honeycomb {5,3,4}, #edge, edges = 0.05, vertices = 0.15, faces = #glass;",
        "Honeycomb {5,3,4}, #edge, edges = 0.05, vertices = 0.15, colors = (#a, #b), \
         face_colors = (#glass, #edge, #a);",
    ];
    for (case, objects) in cases.iter().enumerate() {
        let s = scene(objects);
        let h = only_honeycomb(&s);
        let own = s.objects[0].material.index();
        let [edge, glass, a, b] = ["edge", "glass", "a", "b"].map(|n| material(&s, n).index());
        let mut seen = [false; 3];
        for dir in &directions {
            let ray = Ray::from_origin_unchecked(*dir);
            let Some(hit) = h.surface.intersect(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            let (kind, class) = decode_honeycomb_part(hit.part);
            let coloured = if class % 2 == 0 { a } else { b };
            let face_coloured = [glass, edge, a][class as usize % 3];
            let got = h.materials.material(hit.part, own);
            let want = match (case, kind) {
                (0, HoneycombPart::Face) => panic!("`colors` alone drew a face"),
                (0, _) => coloured,
                (1, HoneycombPart::Face) => glass,
                (1, _) => coloured,
                (2, HoneycombPart::Face) => glass,
                (2, _) => edge,
                (_, HoneycombPart::Face) => face_coloured,
                (_, _) => coloured,
            };
            assert_eq!(got, want, "case {case}: {kind:?} of class {class}");
            seen[kind as usize] = true;
        }
        if case == 0 {
            assert!(seen[0] && seen[2], "case 0: parts met {seen:?}");
        } else {
            assert!(seen.iter().all(|s| *s), "case {case}: parts met {seen:?}");
        }
        if case == 3 {
            // Classes count round six: 2 and 3 colours together.
            assert_eq!(h.surface.style().cell_classes, 6);
        }
    }
}

/// `rings` picks the uniform honeycomb of the symbol's group: node 0 alone
/// (or no `rings`) is the regular honeycomb, a single number is one node,
/// and the order of the nodes does not matter.
#[test]
fn rings_pick_a_uniform_honeycomb_of_the_group() {
    use hgeom::Rings;
    let rings_of = |objects: &str| only_honeycomb(&scene(objects)).surface.rings();
    assert_eq!(rings_of("Honeycomb {4,3,5}, #edge;"), Rings::REGULAR);
    assert_eq!(
        rings_of("Honeycomb {4,3,5}, #edge, rings = (0);"),
        Rings::REGULAR
    );
    assert_eq!(
        rings_of("Honeycomb {4,3,5}, #edge, rings = 1;"),
        Rings::new(&[1]).unwrap()
    );
    assert_eq!(
        rings_of("Honeycomb {6,3,3}, #edge, faces = #glass, vertices = 0.04, rings = (3, 0);"),
        Rings::new(&[0, 3]).unwrap()
    );
    // Every ring set of every symbol lowers (the seed is always a point or
    // an ideal point).
    for (p, q, r) in Schlafli::ALL {
        for nodes in ["(0, 1)", "(1, 2)", "(0, 1, 2, 3)", "(2)", "(3)"] {
            let s = scene(&format!(
                "Honeycomb {{{p},{q},{r}}}, #edge, faces = #glass, rings = {nodes};"
            ));
            assert!(!only_honeycomb(&s).surface.rings().is_regular());
        }
    }
}

/// Balls on the vertices of a uniform honeycomb whose seed is an ideal
/// vertex of the simplex (ringing `v3` of `{6,3,3}`, whose cells are
/// horosphere-inscribed, gives the ideal vertices of `{3,3,6}`) are a
/// warning, as for the regular honeycombs with ideal vertices.
#[test]
fn balls_on_ideal_seeds_are_a_warning() {
    let src = format!(
        "{MATERIALS}Objects {{ Honeycomb {{6,3,3}}, #edge, vertices = 0.1, rings = (3); }}"
    );
    let c = compile(&src);
    assert!(!c.has_errors());
    assert!(
        c.diagnostics
            .iter()
            .any(|d| d.severity == Severity::Warning && d.message.contains("t3{6,3,3}")),
        "{:#?}",
        c.diagnostics
    );
}

/// `colors` without `faces` used to close every cell with opaque walls in
/// the palette: from inside the base cell every ray stopped at its own
/// walls. Now it colours the edges and vertices, and rays from the centre
/// between them go out through the open cells.
#[test]
fn colors_without_faces_colours_the_edges_and_leaves_the_cells_open() {
    use hgeom::{HoneycombPart, Ray, decode_honeycomb_part};
    let s = scene("Honeycomb {4,3,5}, #edge, colors = (#a, #b);");
    let h = only_honeycomb(&s);
    assert!(!h.surface.style().faces, "no walls were asked for");
    let own = s.objects[0].material.index();
    let [a, b] = ["a", "b"].map(|n| material(&s, n).index());
    // Rays that leave the base cell: no hit, or a part of a farther cell.
    let (mut beyond, mut edges) = (0, 0);
    for i in 0..2000 {
        let t = f64::from(i) * 0.618_033_988_749_895 * std::f64::consts::TAU;
        let z = 1.0 - 2.0 * (f64::from(i) + 0.5) / 2000.0;
        let r = (1.0 - z * z).sqrt();
        let ray = Ray::from_origin_unchecked(DVec3::new(r * t.cos(), r * t.sin(), z));
        match h.surface.intersect(&ray, 0.0, f64::INFINITY) {
            None => beyond += 1,
            Some(hit) => {
                let (kind, class) = decode_honeycomb_part(hit.part);
                assert_ne!(kind, HoneycombPart::Face);
                beyond += usize::from(class != 0);
                if kind == HoneycombPart::Edge {
                    edges += 1;
                    let want = if class % 2 == 0 { a } else { b };
                    assert_eq!(h.materials.material(hit.part, own), want, "class {class}");
                }
            }
        }
    }
    assert!(edges > 0, "no edge met");
    assert!(
        beyond > 200,
        "only {beyond} of 2000 rays left the base cell"
    );
}
