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

use hgeom::glam::DVec3;

mod data;
mod normals;
mod obj;

use data::fan;
pub use data::{MAX_MESH_FILE_BYTES, MeshData, MeshFileError};

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
pub fn load(path: &Path) -> Result<MeshData, MeshFileError> {
    let format = MeshFormat::from_path(path).ok_or(MeshFileError::UnknownFormat)?;
    parse(format, &read_bounded(path)?)
}

/// Parses the bytes of a mesh file and checks the [`MeshData`] invariants.
pub fn parse(format: MeshFormat, bytes: &[u8]) -> Result<MeshData, MeshFileError> {
    let data = match format {
        MeshFormat::Obj => obj::parse(bytes)?,
        MeshFormat::Ply => parse_ply(bytes)?,
    };
    data.check()?;
    Ok(data)
}

fn read_bounded(path: &Path) -> Result<Vec<u8>, MeshFileError> {
    use std::io::Read;
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

fn parse_ply(bytes: &[u8]) -> Result<MeshData, MeshFileError> {
    use ply_rs_bw::parser::Parser;
    use ply_rs_bw::ply::{DefaultElement, Property};

    // The parser's messages quote the offending line; only its position
    // and the kind of problem are passed on.
    let ply = Parser::<DefaultElement>::new()
        .read_ply(&mut std::io::Cursor::new(bytes))
        .map_err(|e| {
            let problem = match e.kind() {
                std::io::ErrorKind::UnexpectedEof => "not a valid PLY file: it ends early",
                _ => "not a valid PLY file: malformed header or data",
            };
            match e.line() {
                Some(line) => MeshFileError::invalid_at(line, problem),
                None => MeshFileError::Invalid(problem.to_string()),
            }
        })?;
    let scalar = |p: &Property| -> Option<f64> {
        Some(match *p {
            Property::Char(x) => f64::from(x),
            Property::UChar(x) => f64::from(x),
            Property::Short(x) => f64::from(x),
            Property::UShort(x) => f64::from(x),
            Property::Int(x) => f64::from(x),
            Property::UInt(x) => f64::from(x),
            Property::Float(x) => f64::from(x),
            Property::Double(x) => x,
            _ => return None,
        })
    };
    let list = |p: &Property| -> Option<Vec<u32>> {
        let ints: Vec<i64> = match p {
            Property::ListChar(v) => v.iter().map(|&x| i64::from(x)).collect(),
            Property::ListUChar(v) => v.iter().map(|&x| i64::from(x)).collect(),
            Property::ListShort(v) => v.iter().map(|&x| i64::from(x)).collect(),
            Property::ListUShort(v) => v.iter().map(|&x| i64::from(x)).collect(),
            Property::ListInt(v) => v.iter().map(|&x| i64::from(x)).collect(),
            Property::ListUInt(v) => v.iter().map(|&x| i64::from(x)).collect(),
            _ => return None,
        };
        // A negative index becomes u32::MAX, which the range check rejects.
        Some(
            ints.into_iter()
                .map(|i| u32::try_from(i).unwrap_or(u32::MAX))
                .collect(),
        )
    };
    let vertices = ply
        .payload
        .get("vertex")
        .ok_or_else(|| MeshFileError::Invalid("the PLY file has no `vertex` element".into()))?;
    let mut positions = Vec::with_capacity(vertices.len());
    let mut normals = Vec::new();
    for (i, v) in vertices.iter().enumerate() {
        let coord = |name: &str| v.get(name).and_then(scalar);
        match (coord("x"), coord("y"), coord("z")) {
            (Some(x), Some(y), Some(z)) => positions.push(DVec3::new(x, y, z)),
            _ => {
                return Err(MeshFileError::Invalid(format!(
                    "PLY vertex {} lacks a numeric x, y or z",
                    i + 1
                )));
            }
        }
        if let (Some(x), Some(y), Some(z)) = (coord("nx"), coord("ny"), coord("nz")) {
            let n = DVec3::new(x, y, z);
            if !n.is_finite() {
                return Err(MeshFileError::Invalid(format!(
                    "PLY vertex {} has a normal that is not a finite number",
                    i + 1
                )));
            }
            normals.push(n);
        }
    }
    // A PLY element's properties are the same for every vertex: either all
    // have a normal or none has.
    let has_normals = !positions.is_empty() && normals.len() == positions.len();
    if !has_normals {
        normals.clear();
    }
    let faces = ply
        .payload
        .get("face")
        .ok_or_else(|| MeshFileError::Invalid("the PLY file has no `face` element".into()))?;
    let mut triangles = Vec::with_capacity(faces.len());
    for (i, f) in faces.iter().enumerate() {
        let face = f
            .get("vertex_indices")
            .or_else(|| f.get("vertex_index"))
            .and_then(list)
            .ok_or_else(|| {
                MeshFileError::Invalid(format!(
                    "PLY face {} has no `vertex_indices` list of integers",
                    i + 1
                ))
            })?;
        fan(&face, &mut triangles);
    }
    let corner_normals = if has_normals {
        triangles.clone()
    } else {
        Vec::new()
    };
    Ok(MeshData {
        positions,
        triangles,
        normals,
        corner_normals,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
