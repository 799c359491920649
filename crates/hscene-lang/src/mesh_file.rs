//! Reading triangle meshes from OBJ and PLY files, and laying them out in
//! the ball.
//!
//! A mesh file holds Euclidean coordinates in units of its own. `Mesh
//! "file", size, #M;` centres the mesh on the centre of its bounding box,
//! scales it so that its farthest vertex lies at distance 1, and maps each
//! vertex `u` to the h-point at hyperbolic distance `size * |u|` from the
//! origin in the direction of `u` (geodesic polar coordinates about the
//! origin). Distances from the centre and angles at the centre are kept, up
//! to the factor `size`; the faces become h-triangles (the convex hulls of
//! their vertices). Polygonal faces are split into fans of triangles first.
//!
//! The loader knows about files, the layout about hyperbolic space; neither
//! knows about spans or diagnostics.

use std::path::Path;

mod data;
mod normals;
mod obj;
mod ply;

pub use data::{MAX_MESH_FILE_BYTES, MAX_MESH_TRIANGLES, MeshData, MeshFileError};

/// The formats a mesh is read from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    /// Wavefront OBJ.
    Obj,
    /// PLY, ASCII or binary.
    Ply,
}

impl MeshFormat {
    /// The format a file name's extension names (case-insensitively).
    pub fn from_path(path: &Path) -> Option<MeshFormat> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("obj") => Some(MeshFormat::Obj),
            Some("ply") => Some(MeshFormat::Ply),
            _ => None,
        }
    }
}

/// Reads an OBJ or PLY file (chosen by extension, case-insensitively).
///
/// Only a regular file of at most [`MAX_MESH_FILE_BYTES`] is read: a device,
/// a FIFO or a huge file is refused before any of it is read, and the read
/// itself stops at the limit (a file growing meanwhile cannot get past it).
/// Every object of an OBJ file is merged into one mesh; materials, normals
/// and texture coordinates are ignored. A PLY file needs a `vertex` element
/// with `x`, `y`, `z` and a `face` element with a `vertex_indices` (or
/// `vertex_index`) list.
///
/// A PLY file is read as a stream (never held whole, see `mesh_file/ply.rs`),
/// through a reader that stops at the limit: a file that grows past it
/// while being read ends early for the parser. An OBJ file is read whole.
pub fn load(path: &Path) -> Result<MeshData, MeshFileError> {
    use std::io::Read;
    let format = MeshFormat::from_path(path).ok_or(MeshFileError::UnknownFormat)?;
    let file = open_bounded(path)?;
    let data = match format {
        MeshFormat::Obj => obj::parse(&read_bounded(file)?)?,
        MeshFormat::Ply => {
            let len = file.metadata().map_err(MeshFileError::Io)?.len();
            let source = std::io::BufReader::new(file.take(MAX_MESH_FILE_BYTES));
            ply::parse(source, len)?
        }
    };
    data.check()?;
    Ok(data)
}

/// Parses the bytes of a mesh file and checks the [`MeshData`] invariants.
pub fn parse(format: MeshFormat, bytes: &[u8]) -> Result<MeshData, MeshFileError> {
    let data = match format {
        MeshFormat::Obj => obj::parse(bytes)?,
        MeshFormat::Ply => ply::parse(bytes, bytes.len() as u64)?,
    };
    data.check()?;
    Ok(data)
}

/// The regular file at `path`, if it is one of at most
/// [`MAX_MESH_FILE_BYTES`].
fn open_bounded(path: &Path) -> Result<std::fs::File, MeshFileError> {
    // Opening a FIFO for reading blocks until a writer comes; look first.
    let meta = std::fs::metadata(path).map_err(MeshFileError::Io)?;
    if !meta.is_file() {
        return Err(MeshFileError::NotAFile);
    }
    if meta.len() > MAX_MESH_FILE_BYTES {
        return Err(MeshFileError::TooLarge { size: meta.len() });
    }
    let file = std::fs::File::open(path).map_err(MeshFileError::Io)?;
    // The path may have been swapped for something else since the check.
    let meta = file.metadata().map_err(MeshFileError::Io)?;
    if !meta.is_file() {
        return Err(MeshFileError::NotAFile);
    }
    Ok(file)
}

/// The whole of an opened file, stopping past the limit.
fn read_bounded(file: std::fs::File) -> Result<Vec<u8>, MeshFileError> {
    use std::io::Read;
    let mut bytes = Vec::new();
    file.take(MAX_MESH_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(MeshFileError::Io)?;
    if bytes.len() as u64 > MAX_MESH_FILE_BYTES {
        return Err(MeshFileError::TooLarge {
            size: bytes.len() as u64,
        });
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;

    fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
        let path = dir.join(name);
        std::fs::write(&path, text).expect("write test file");
        path
    }

    #[test]
    fn obj_and_ply_give_the_same_mesh() {
        let dir = tempfile::tempdir().expect("tempdir");
        let obj = write(
            dir.path(),
            "quad.obj",
            "# a square and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\nf 1 2 5\n",
        );
        let ply = write(
            dir.path(),
            "quad.PLY",
            "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n\
             element face 2\nproperty list uchar int vertex_indices\nend_header\n\
             0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 1 4\n",
        );
        let a = load(&obj).expect("obj loads");
        let b = load(&ply).expect("ply loads");
        assert_eq!(a, b);
        assert_eq!(a.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 1, 4]]);
        assert_eq!(a.positions.len(), 5);
    }

    #[test]
    fn bad_files_are_errors_not_panics() {
        let dir = tempfile::tempdir().expect("tempdir");
        let missing = load(&dir.path().join("none.obj"));
        assert!(matches!(missing, Err(MeshFileError::Io(_))), "{missing:?}");
        let txt = write(dir.path(), "mesh.txt", "v 0 0 0\n");
        assert!(matches!(load(&txt), Err(MeshFileError::UnknownFormat)));
        let no_faces = write(dir.path(), "empty.obj", "v 0 0 0\nv 1 0 0\n");
        assert!(matches!(load(&no_faces), Err(MeshFileError::Invalid(_))));
        let out_of_range = write(
            dir.path(),
            "range.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
        );
        assert!(load(&out_of_range).is_err());
        let garbage = write(
            dir.path(),
            "garbage.ply",
            "ply\nformat ascii 1.0\nelement vertex x\n",
        );
        assert!(matches!(load(&garbage), Err(MeshFileError::Invalid(_))));
        let no_xyz = write(
            dir.path(),
            "noxyz.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float u\nelement face 0\n\
             property list uchar int vertex_indices\nend_header\n0\n",
        );
        assert!(matches!(load(&no_xyz), Err(MeshFileError::Invalid(_))));
    }

    #[test]
    fn layout_puts_the_farthest_vertex_at_the_size() {
        let data = MeshData {
            positions: vec![
                DVec3::new(-2.0, 0.0, 0.0),
                DVec3::new(2.0, 0.0, 0.0),
                DVec3::new(0.0, 1.0, 0.0),
            ],
            triangles: vec![[0, 1, 2]],
            normals: Vec::new(),
            corner_normals: Vec::new(),
        };
        let pts = data.layout(3.0).expect("layout");
        // Box centre (0, 0.5, 0); farthest vertices at sqrt(4.25).
        let far = pts[0].distance_from_origin();
        assert!((far - 3.0).abs() < 1e-12, "{far}");
        let near = pts[2].distance_from_origin();
        assert!((near - 3.0 * 0.5 / 4.25f64.sqrt()).abs() < 1e-12, "{near}");
        // Directions are kept.
        assert!(pts[2].coords().normalize().abs_diff_eq(DVec3::Y, 1e-15));
        let flat = MeshData {
            positions: vec![DVec3::ONE; 3],
            triangles: vec![[0, 1, 2]],
            normals: Vec::new(),
            corner_normals: Vec::new(),
        };
        assert!(flat.layout(1.0).is_none());
    }
}
