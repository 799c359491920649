//! Pixel layers: what each pixel's central ray meets, against closed forms.

use hrender::{Aov, RenderOptions, render_aovs, write_exr_with_layers};
use hscene_ir::Scene;

fn compile(source: &str) -> Scene {
    let out = hscene_lang::compile(source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

/// The middle pixel of a 5 by 5 picture looks along the view axis.
const MIDDLE: usize = 12;

/// A sphere of radius `r` centred `c` from the eye on the axis: the middle
/// pixel's depth is `c - r` to 1e-9, its normal faces the eye (`-z` in the
/// scene's ball coordinates, and the same after moving the eye and sphere
/// together, since normals are in the scene's frame), its id is the
/// sphere's number.
#[test]
fn depth_normal_and_id_of_the_middle_pixel() {
    let (c, r) = (1.3f64, 0.4f64);
    let z = (c / 2.0).tanh();
    let source = format!(
        "Globals {{ resolution = (5, 5); from = (0, 0, 0); to = (0, 0, 0.3); }}\n\
         BRDFs {{ diffuse = (1, 1, 1); }}\n\
         Objects {{ Sphere (0, 0.9, 0), 0.05, #1; Sphere (0, 0, {z}), {r}, #1; }}\n"
    );
    let layers = render_aovs(
        &compile(&source),
        &RenderOptions::default(),
        None,
        &[Aov::Depth, Aov::Normal, Aov::Id, Aov::Cell],
    )
    .unwrap();
    let at = |name: &str| f64::from(layers.channel(name).unwrap()[MIDDLE]);
    // f32 channels: 1e-9 of the distance is below their resolution, so
    // the f64 value the channel was made from is checked through its
    // rounding, and the f64 depth against 1e-9 below.
    assert!((at("Z") - (c - r)).abs() <= f64::from(f32::EPSILON) * c);
    assert!((at("N.Z") + 1.0).abs() < 1e-6 && at("N.X").abs() < 1e-6);
    assert_eq!(at("id"), 2.0);
    assert!(at("cell.rank").is_nan() && at("cell.class").is_nan());
    // A corner pixel misses: infinite depth, id 0.
    assert_eq!(layers.channel("Z").unwrap()[0], f32::INFINITY);
    assert_eq!(layers.channel("id").unwrap()[0], 0.0);
}

/// The depth before rounding to f32: the hit's own `t`, against the
/// closed form `c - r` to 1e-9 (the scene prepared as the layers are).
#[test]
fn the_middle_depth_is_the_closed_form_to_1e_9() {
    let (c, r) = (2.7f64, 0.9f64);
    let z = (c / 2.0).tanh();
    let source = format!(
        "Globals {{ resolution = (5, 5); to = (0, 0, 0.3); }}\n\
         BRDFs {{ diffuse = (1, 1, 1); }}\n\
         Objects {{ Sphere (0, 0, {z}), {r}, #1; }}\n"
    );
    let scene = compile(&source);
    let frame = hrender::canonical_frame(&scene.camera).unwrap();
    let prepared = hrender::PreparedScene::for_camera(&scene, &frame).unwrap();
    let ray = hgeom::Ray::from_origin_unchecked(hgeom::glam::DVec3::Z);
    let hrender::Nearest::Hit(hit, _) = prepared.nearest(&ray, hrender::T_MIN) else {
        panic!("the axis meets the sphere");
    };
    assert!((hit.t - (c - r)).abs() < 1e-9, "{}", hit.t - (c - r));
}

/// A `{4,3,5}` coloured by three classes, seen from the cell across the
/// base cell's +z face looking on along +z: the face ahead is shared with
/// the cell two out, so its rank (the least of its cells') is 1; the
/// class is 1 of 3. From the base cell's centre the face ahead is the base
/// cell's own: rank 0.
#[test]
fn cell_rank_and_class_of_the_middle_pixel() {
    for (eye, rank) in [("(0, 0, 0)", 0.0), ("(0, 0, 0.5)", 1.0)] {
        let source = format!(
            "Globals {{ resolution = (5, 5); from = {eye}; to = (0, 0, 0.9); fov = 20; }}\n\
             BRDFs {{ a: diffuse = (1, 0, 0); b: diffuse = (0, 1, 0); c: diffuse = (0, 0, 1); }}\n\
             Lights {{ (0, 0, 0), (1, 1, 1), (1, 1, 1); }}\n\
             Objects {{ Honeycomb {{4,3,5}}, #a, face_colors = (#a, #b, #c); }}\n"
        );
        let layers = render_aovs(
            &compile(&source),
            &RenderOptions::default(),
            None,
            &[Aov::Cell],
        )
        .unwrap();
        let at = |name: &str| f64::from(layers.channel(name).unwrap()[MIDDLE]);
        assert_eq!(at("cell.rank"), rank, "from {eye}");
        assert_eq!(at("cell.class"), rank % 3.0, "from {eye}");
    }
}

/// Written beside the colour in one OpenEXR part, the layers read back (by
/// the exr crate) with their values.
#[test]
fn layers_read_back_from_the_exr() {
    use exr::prelude::{ReadChannels, ReadLayers};
    let source = "Globals { resolution = (5, 5); to = (0, 0, 0.3); }\n\
                  BRDFs { diffuse = (1, 1, 1); }\n\
                  Lights { (0, 0, 0), (1, 1, 1), (1, 1, 1); }\n\
                  Objects { Sphere (0, 0, 0.5), 0.3, #1; }\n";
    let scene = compile(source);
    let options = RenderOptions::default();
    let image = hrender::render(&scene, &options, &|_| {}).unwrap().image;
    let layers = render_aovs(&scene, &options, None, &[Aov::Depth, Aov::Id]).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("layers.exr");
    write_exr_with_layers(&image, &layers, &path).unwrap();
    let read = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .all_layers()
        .all_attributes()
        .from_file(&path)
        .unwrap();
    let layer = &read.layer_data[0];
    let names: Vec<String> = layer
        .channel_data
        .list
        .iter()
        .map(|c| c.name.to_string())
        .collect();
    assert_eq!(names, ["B", "G", "R", "Z", "id"]);
    let z = &layer.channel_data.list[3].sample_data;
    assert_eq!(
        z.value_by_flat_index(MIDDLE).to_f32(),
        layers.channel("Z").unwrap()[MIDDLE]
    );
}

/// Layers stop at the first surface that is not fully transparent: a
/// sphere of `trans = 1` (nothing reflected, index 1) in front of an opaque
/// one is passed through, and every layer is the opaque sphere's.
#[test]
fn a_fully_transparent_surface_does_not_stop_the_layers() {
    let source = "Globals { resolution = (5, 5); from = (0, 0, 0); to = (0, 0, 0.3); }\n\
         BRDFs { clear: diffuse = (0, 0, 0), specular = (0, 0, 0), trans = 1; solid: diffuse = (1, 1, 1); }\n\
         Objects { Sphere (0, 0, 0.2), 0.1, #clear; Sphere (0, 0, 0.6), 0.1, #solid; }\n";
    let layers = render_aovs(
        &compile(source),
        &RenderOptions::default(),
        None,
        &[Aov::Depth, Aov::Id],
    )
    .unwrap();
    let at = |name: &str| f64::from(layers.channel(name).unwrap()[MIDDLE]);
    assert_eq!(at("id"), 2.0);
    // The opaque sphere's near side: 2 atanh(0.6) - 0.1.
    let expected = 2.0 * 0.6f64.atanh() - 0.1;
    assert!(
        (at("Z") - expected).abs() < 1e-5,
        "{} vs {expected}",
        at("Z")
    );
    // A sphere that reflects a little is not fully transparent.
    let tinted = source.replace(
        "diffuse = (0, 0, 0), specular",
        "diffuse = (0.1, 0, 0), specular",
    );
    let layers = render_aovs(
        &compile(&tinted),
        &RenderOptions::default(),
        None,
        &[Aov::Id],
    )
    .unwrap();
    assert_eq!(layers.channel("id").unwrap()[MIDDLE], 1.0);
}

/// In a space, `id` follows the object list of `check --emit ir` (each
/// object's images share its number) and the domain's rods are numbered
/// one after the last object.
#[test]
fn in_a_space_ids_follow_the_object_list_and_rods_come_after() {
    let source = "Globals { resolution = (24, 24); space = seifert_weber; domain = 0.04, #a; \
                  from = (0, 0, 0); to = (0, 0, 0.3); fov = 100; }\n\
         BRDFs { a: diffuse = (1, 1, 1); }\n\
         Objects { Sphere (0.3, 0.3, -0.2), 0.05, #a; Sphere (0, 0, 0.25), 0.08, #a; }\n";
    let layers = render_aovs(
        &compile(source),
        &RenderOptions::default(),
        None,
        &[Aov::Id],
    )
    .unwrap();
    let ids = layers.channel("id").unwrap();
    // The middle of an even picture: the pixel just off the axis.
    assert_eq!(ids[12 * 24 + 12], 2.0);
    assert!(
        ids.iter().all(|&id| [0.0, 1.0, 2.0, 3.0].contains(&id)),
        "{ids:?}"
    );
    assert!(ids.contains(&3.0), "no rod seen");
}

/// The `word` layer lists the faces the ray left the domain by, as hgeom's
/// own walk of the same ray does, and its length; 0 in H³.
#[test]
fn the_word_layer_is_the_faces_crossed() {
    let source = "Globals { resolution = (5, 5); space = seifert_weber; domain = 0.04, #a; \
                  from = (0, 0, 0); to = (0.1, 0.2, 0.7); fov = 10; }\n\
         BRDFs { a: diffuse = (1, 1, 1); }\n\
         Objects { Sphere (0.05, -0.05, -0.1), 0.02, #a; }\n";
    let layers = render_aovs(
        &compile(source),
        &RenderOptions::default(),
        None,
        &[Aov::Word, Aov::Depth],
    )
    .unwrap();
    let at = |name: &str| f64::from(layers.channel(name).unwrap()[MIDDLE]);
    let length = at("word.length") as usize;
    assert!(length >= 1, "the middle ray crosses a face before a rod");
    let space = hgeom::QuotientSpace::seifert_weber().unwrap();
    let mut ray =
        hgeom::Ray::from_origin(hgeom::glam::DVec3::new(0.1, 0.2, 0.7).normalize()).unwrap();
    for letter in 1..=length.min(8) {
        let c = space.exit(&ray).unwrap();
        assert_eq!(
            at(&format!("word.{letter}")),
            (c.face + 1) as f64,
            "letter {letter}"
        );
        ray = space.carry(&ray, c);
    }
    if length < 8 {
        assert_eq!(at(&format!("word.{}", length + 1)), 0.0);
    }
    // In H³ every word is empty.
    let h3 = "Globals { resolution = (5, 5); }\nBRDFs { diffuse = (1, 1, 1); }\nObjects { Sphere (0, 0, 0.5), 0.1, #1; }\n";
    let layers = render_aovs(&compile(h3), &RenderOptions::default(), None, &[Aov::Word]).unwrap();
    assert!(
        layers
            .channel("word.length")
            .unwrap()
            .iter()
            .all(|&x| x == 0.0)
    );
}
