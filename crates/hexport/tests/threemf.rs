//! The 3MF package read back: one object per scene object, named as the
//! scene names it, so that a slicer places each whole.

use std::io::Read;

use hexport::{ExportOptions, Format, Model, export_scene};

fn model(source: &str) -> Model {
    let out = hscene_lang::compile(source);
    let scene = out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics));
    export_scene(&scene, &ExportOptions::default(), &|_, _| {}).unwrap_or_else(|e| panic!("{e}"))
}

/// The model part of the 3MF package written for `model`.
fn model_xml(model: &Model) -> String {
    let path = std::path::Path::new("m.3mf");
    let files = Format::from_path(path)
        .unwrap()
        .encode(model, path)
        .unwrap();
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(files[0].bytes.clone())).unwrap();
    let mut text = String::new();
    zip.by_name("3D/3dmodel.model")
        .unwrap()
        .read_to_string(&mut text)
        .unwrap();
    text
}

/// The value of `attribute` in each `<tag ...>` element, in order.
fn attributes(xml: &str, tag: &str, attribute: &str) -> Vec<String> {
    let open = format!("<{tag} ");
    let key = format!(" {attribute}=\"");
    xml.match_indices(&open)
        .filter_map(|(at, _)| {
            let element = &xml[at..at + xml[at..].find('>').unwrap_or(0)];
            let start = element.find(&key)? + key.len();
            let len = element[start..].find('"')?;
            Some(element[start..start + len].to_string())
        })
        .collect()
}

const SCENE: &str = "BRDFs { red: diffuse = (0.8, 0.1, 0.1); blue: diffuse = (0.1, 0.2, 0.9); }\n\
     Objects {\n\
       Cube 0.5, #red;\n\
       ball: Sphere (0.2, 0.1, 0), 0.2, #blue;\n\
       Sphere (-0.2, 0, 0), 0.2, #red;\n\
       Honeycomb {4,3,5}, #red, edges = 0.06, vertices = 0.08, colors = (#red, #blue);\n\
     }\n";

#[test]
fn each_scene_object_is_one_3mf_object_named_as_the_scene_names_it() {
    let m = model(SCENE);
    // The cube is several shells (its faces' plates).
    let cube_shells = m.shells.iter().filter(|s| s.object_index == 0).count();
    assert!(cube_shells > 1, "{cube_shells} shells");
    let xml = model_xml(&m);
    assert_eq!(
        attributes(&xml, "object", "name"),
        ["Polyhedron 1", "ball", "Sphere 3", "Honeycomb 4"]
    );
    assert_eq!(attributes(&xml, "item", "objectid"), ["2", "3", "4", "5"]);
    // Every shell's triangles are in its object's mesh, renumbered into
    // the one vertex list: as many triangles as the shells hold, and no
    // index past the object's vertices.
    let triangles = attributes(&xml, "triangle", "v1").len();
    assert_eq!(triangles, m.triangle_count());
    for object in xml.split("<object ").skip(1) {
        let vertices = object.matches("<vertex ").count();
        for corner in ["v1", "v2", "v3"] {
            for v in attributes(object, "triangle", corner) {
                assert!(v.parse::<usize>().unwrap() < vertices, "{v} of {vertices}");
            }
        }
    }
    // The honeycomb's edges in the other colour say so per triangle.
    let last = xml.split("<object ").nth(4).unwrap();
    assert!(last.contains(" p1=\""), "the edges keep their colours");
    assert!(!xml.split("<object ").nth(1).unwrap().contains(" p1=\""));
}

#[test]
fn bodies_that_touch_nothing_are_named_as_floating() {
    // Two balls apart and a rod joining nothing: all three float.
    let apart = model(
        "BRDFs { diffuse = (1, 1, 1); }\n\
         Objects { Sphere (0.4, 0, 0), 0.1, #1; Sphere (-0.4, 0, 0), 0.1, #1; }\n",
    );
    assert_eq!(apart.floating_bodies(0.01), ["object 1", "object 2"]);
    // A ball resting on a rod, and a ball far from both.
    let resting = model(
        "BRDFs { diffuse = (1, 1, 1); }\n\
         Objects { Rod (-0.5, 0, 0), (0.5, 0, 0), 0.05, #1; lone: Sphere (0, 0.5, 0.5), 0.1, #1; \
         Sphere (0, 0, 0), 0.1, #1; }\n",
    );
    assert_eq!(resting.floating_bodies(0.01), ["object 2 (\"lone\")"]);
    // One body alone is a print, not a loose part.
    let one = model("BRDFs { diffuse = (1, 1, 1); }\nObjects { Sphere (0.4, 0, 0), 0.1, #1; }\n");
    assert!(one.floating_bodies(0.01).is_empty());
}
