//! Wavefront OBJ in metres (Blender's unit), one `o` group a shell, with
//! `usemtl` naming the MTL's materials (diffuse colour `Kd`).

use std::fmt::Write;

use crate::model::Model;

pub(super) fn encode(model: &Model, mtl: &str) -> Vec<u8> {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# hscene export: the Poincare ball, metres, centre at the origin"
    );
    let _ = writeln!(out, "mtllib {mtl}");
    let mut base = 1usize;
    for (k, shell) in model.shells.iter().enumerate() {
        let _ = writeln!(out, "o part-{} {}", k + 1, shell.object.replace(' ', "_"));
        let _ = writeln!(out, "usemtl {}", material_name(model, shell.material));
        for v in &shell.vertices {
            let v = *v * super::METRES_PER_MM;
            let _ = writeln!(out, "v {:.9} {:.9} {:.9}", v.x, v.y, v.z);
        }
        for t in &shell.triangles {
            let [a, b, c] = t.map(|i| i as usize + base);
            let _ = writeln!(out, "f {a} {b} {c}");
        }
        base += shell.vertices.len();
    }
    out.into_bytes()
}

/// A material's name as OBJ and MTL write it: no spaces.
fn material_name(model: &Model, k: usize) -> String {
    model.materials[k].name.replace(char::is_whitespace, "_")
}

pub(super) fn encode_mtl(model: &Model) -> Vec<u8> {
    let mut out = String::from("# hscene export: diffuse colours (linear)\n");
    for (k, m) in model.materials.iter().enumerate() {
        let [r, g, b] = m.color;
        let _ = writeln!(out, "newmtl {}", material_name(model, k));
        let _ = writeln!(out, "Kd {r:.6} {g:.6} {b:.6}");
        let _ = writeln!(out, "Ka 0 0 0\nKs 0 0 0\nd 1\nillum 1");
    }
    out.into_bytes()
}
