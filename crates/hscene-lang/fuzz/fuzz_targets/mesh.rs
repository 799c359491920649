//! Fuzz target: arbitrary bytes through the mesh reader. The first byte
//! picks the format (even: OBJ, odd: PLY) and the next the layout size; the
//! rest is the file. Nothing may panic; an error is one line; a mesh that
//! loads keeps the `MeshData` invariants and lays out inside the ball.

#![no_main]

use hscene_lang::mesh_file::{MeshFormat, parse};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let [kind, size, file @ ..] = data else {
        return;
    };
    let format = if kind % 2 == 0 {
        MeshFormat::Obj
    } else {
        MeshFormat::Ply
    };
    match parse(format, file) {
        Err(e) => {
            let message = e.to_string();
            assert!(!message.is_empty() && !message.contains('\n'), "{message:?}");
        }
        Ok(mesh) => {
            assert!(!mesh.triangles.is_empty());
            assert!(mesh.positions.iter().all(|p| p.is_finite()));
            let n = mesh.positions.len();
            assert!(mesh.triangles.iter().flatten().all(|&i| (i as usize) < n));
            // Sizes 0.07 to 18, the documented range.
            let size = 0.07 * f64::from(*size).max(1.0);
            if let Some(points) = mesh.layout(size) {
                assert!(points.iter().all(|p| p.coords().length() < 1.0));
            }
        }
    }
});
