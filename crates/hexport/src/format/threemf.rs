//! 3MF: a zip package holding the content types, the relationship to the
//! model part, and the model (millimetres): one base-material group with a
//! display colour per material, one object per scene object (its shells
//! one mesh, named as the scene names it), each in the build.
//! Entries carry the zip format's earliest time stamp, not the clock's, so
//! two exports of one scene are the same bytes.

use std::fmt::Write as _;
use std::io::{Cursor, Write};

use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, DateTime, ZipWriter};

use crate::error::ExportError;
use crate::model::Model;

const CONTENT_TYPES: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>
"#;

const RELS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>
"#;

/// XML text with the five special characters escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&apos;")
}

/// A linear channel as an 8-bit sRGB value.
fn srgb8(linear: f64) -> u8 {
    let c = linear.clamp(0.0, 1.0);
    let s = if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    // In [0, 255] after the clamp.
    (s * 255.0).round() as u8
}

fn model_xml(model: &Model) -> String {
    let mut x = String::new();
    x.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    x.push_str("<model unit=\"millimeter\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n");
    x.push_str(" <metadata name=\"Application\">hscene</metadata>\n <resources>\n");
    x.push_str("  <basematerials id=\"1\">\n");
    for m in &model.materials {
        let [r, g, b] = m.color.map(srgb8);
        let _ = writeln!(
            x,
            "   <base name=\"{}\" displaycolor=\"#{r:02X}{g:02X}{b:02X}\"/>",
            escape(&m.name)
        );
    }
    x.push_str("  </basematerials>\n");
    // One object a scene object, its shells one mesh: a slicer places
    // and moves it whole, under the scene's name for it. Triangles of a
    // shell in another material than the first say so (`p1`).
    let bodies = model.bodies();
    for (k, body) in bodies.iter().enumerate() {
        let material = body[0].material;
        let _ = writeln!(
            x,
            "  <object id=\"{}\" type=\"model\" pid=\"1\" pindex=\"{material}\" name=\"{}\">\n   <mesh>\n    <vertices>",
            k + 2,
            escape(&body[0].object_name)
        );
        for v in body.iter().flat_map(|s| &s.vertices) {
            let _ = writeln!(
                x,
                "     <vertex x=\"{}\" y=\"{}\" z=\"{}\"/>",
                v.x as f32, v.y as f32, v.z as f32
            );
        }
        x.push_str("    </vertices>\n    <triangles>\n");
        let mut first = 0u32;
        for shell in body {
            let own = if shell.material == material {
                String::new()
            } else {
                format!(" pid=\"1\" p1=\"{}\"", shell.material)
            };
            for t in &shell.triangles {
                let [a, b, c] = t.map(|v| v + first);
                let _ = writeln!(x, "     <triangle v1=\"{a}\" v2=\"{b}\" v3=\"{c}\"{own}/>");
            }
            // A body's vertices are counted in u32 by the triangle budget.
            first += shell.vertices.len() as u32;
        }
        x.push_str("    </triangles>\n   </mesh>\n  </object>\n");
    }
    x.push_str(" </resources>\n <build>\n");
    for k in 0..bodies.len() {
        let _ = writeln!(x, "  <item objectid=\"{}\"/>", k + 2);
    }
    x.push_str(" </build>\n</model>\n");
    x
}

pub(super) fn encode(model: &Model) -> Result<Vec<u8>, ExportError> {
    let options = SimpleFileOptions::default()
        .compression_method(CompressionMethod::Deflated)
        .last_modified_time(DateTime::default())
        .large_file(false);
    let err = |e: &dyn std::fmt::Display| ExportError::Package(e.to_string());
    let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
    for (name, text) in [
        ("[Content_Types].xml", CONTENT_TYPES.to_string()),
        ("_rels/.rels", RELS.to_string()),
        ("3D/3dmodel.model", model_xml(model)),
    ] {
        zip.start_file(name, options).map_err(|e| err(&e))?;
        zip.write_all(text.as_bytes()).map_err(|e| err(&e))?;
    }
    Ok(zip.finish().map_err(|e| err(&e))?.into_inner())
}
