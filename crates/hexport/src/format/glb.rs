//! Binary glTF 2.0: a JSON chunk and one binary buffer; per shell a node,
//! a mesh of one primitive (f32 positions in metres, glTF's unit; u32
//! indices) and its material (`baseColorFactor`, linear as glTF wants).
//! Normals are left to the reader, which shades flat without them.

use serde_json::json;

use crate::model::Model;

pub(super) fn encode(model: &Model) -> Vec<u8> {
    let mut bin: Vec<u8> = Vec::new();
    let (mut views, mut accessors, mut meshes, mut nodes) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (k, shell) in model.shells.iter().enumerate() {
        let positions: Vec<[f32; 3]> = shell
            .vertices
            .iter()
            .map(|v| {
                let v = *v * super::METRES_PER_MM;
                [v.x as f32, v.y as f32, v.z as f32]
            })
            .collect();
        let mut lo = [f32::INFINITY; 3];
        let mut hi = [f32::NEG_INFINITY; 3];
        let start = bin.len();
        for p in &positions {
            for c in 0..3 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
                bin.extend_from_slice(&p[c].to_le_bytes());
            }
        }
        views.push(json!({"buffer": 0, "byteOffset": start, "byteLength": bin.len() - start, "target": 34962}));
        accessors.push(json!({
            "bufferView": views.len() - 1, "componentType": 5126, "count": positions.len(),
            "type": "VEC3", "min": lo, "max": hi
        }));
        let start = bin.len();
        for t in &shell.triangles {
            for i in t {
                bin.extend_from_slice(&i.to_le_bytes());
            }
        }
        views.push(json!({"buffer": 0, "byteOffset": start, "byteLength": bin.len() - start, "target": 34963}));
        accessors.push(json!({
            "bufferView": views.len() - 1, "componentType": 5125,
            "count": shell.triangles.len() * 3, "type": "SCALAR"
        }));
        meshes.push(json!({"primitives": [{
            "attributes": {"POSITION": accessors.len() - 2},
            "indices": accessors.len() - 1,
            "material": shell.material
        }]}));
        nodes.push(json!({"mesh": k, "name": shell.object}));
    }
    let materials: Vec<_> = model
        .materials
        .iter()
        .map(|m| {
            let [r, g, b] = m.color;
            json!({
                "name": m.name,
                "pbrMetallicRoughness": {
                    "baseColorFactor": [r, g, b, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.6
                }
            })
        })
        .collect();
    let document = json!({
        "asset": {"version": "2.0", "generator": "hscene export"},
        "scene": 0,
        "scenes": [{"nodes": (0..nodes.len()).collect::<Vec<_>>()}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": bin.len()}],
    });
    let mut text = document.to_string().into_bytes();
    while !text.len().is_multiple_of(4) {
        text.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + text.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    // Lengths are bounded by the triangle budget, below u32::MAX.
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(text.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&text);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}
