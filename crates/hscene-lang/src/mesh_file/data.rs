//! What a mesh file gives: its data in file coordinates, the errors of
//! reading it, and the layout in the ball. A leaf: the readers (`obj.rs`,
//! the PLY reader in `mesh_file.rs`, `normals.rs`) import it, it imports
//! none of them.

use std::fmt;

use hgeom::Point;
use hgeom::glam::DVec3;

/// The vertices and triangles read from a mesh file, in file coordinates.
///
/// Invariants: every coordinate is finite, every index is below
/// `positions.len()`, and there is at least one triangle.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshData {
    /// Vertex positions as written in the file.
    pub positions: Vec<DVec3>,
    /// Triangles as vertex indices, in the file's winding order.
    pub triangles: Vec<[u32; 3]>,
    /// Vertex normals as written in the file (OBJ `vn`, PLY `nx ny nz`),
    /// finite, of any length.
    pub normals: Vec<DVec3>,
    /// For each triangle, each corner's index into `normals`, or
    /// `u32::MAX` where the file gives none; empty when it gives none at
    /// all.
    pub corner_normals: Vec<[u32; 3]>,
}

/// Largest mesh file read, in bytes (64 MiB): several million triangles,
/// far more than a scene can hold (see `docs/limits.md`).
pub const MAX_MESH_FILE_BYTES: u64 = 64 << 20;

/// Most triangles a mesh file may make (after polygons are split into
/// fans): 2,000,000, what the primitives budget of one scene holds (500,000
/// primitives, 4 mesh triangles each). Counted while reading, so a file of
/// one face of millions of vertices is refused before its fan is built.
pub const MAX_MESH_TRIANGLES: usize = 2_000_000;

/// Why a mesh file could not be used.
#[derive(Debug)]
pub enum MeshFileError {
    /// The file could not be opened or read.
    Io(std::io::Error),
    /// The path names something other than a regular file (a directory, a
    /// device such as `/dev/zero`, a FIFO, a socket).
    NotAFile,
    /// The file is larger than [`MAX_MESH_FILE_BYTES`].
    TooLarge {
        /// Its size in bytes.
        size: u64,
    },
    /// The file makes more than [`MAX_MESH_TRIANGLES`] triangles.
    TooManyTriangles,
    /// The extension is neither `.obj` nor `.ply`.
    UnknownFormat,
    /// The file is not valid OBJ/PLY, or lacks what a mesh needs. The text
    /// names a position and a kind of problem, never the file's content.
    Invalid(String),
}

impl MeshFileError {
    pub(super) fn invalid_at(line: usize, problem: &str) -> MeshFileError {
        MeshFileError::Invalid(format!("line {line}: {problem}"))
    }
}

impl fmt::Display for MeshFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshFileError::Io(e) => write!(f, "{e}"),
            MeshFileError::NotAFile => f.write_str("it is not a regular file"),
            MeshFileError::TooManyTriangles => write!(
                f,
                "it makes more than {MAX_MESH_TRIANGLES} triangles, the most one scene holds"
            ),
            MeshFileError::TooLarge { size } => write!(
                f,
                "it has {size} bytes, more than the limit of {MAX_MESH_FILE_BYTES}"
            ),
            MeshFileError::UnknownFormat => {
                f.write_str("the file name does not end in .obj or .ply")
            }
            MeshFileError::Invalid(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for MeshFileError {}

impl MeshData {
    /// Checks the invariants of [`MeshData`].
    pub(super) fn check(&self) -> Result<(), MeshFileError> {
        if let Some(i) = self.positions.iter().position(|p| !p.is_finite()) {
            return Err(MeshFileError::Invalid(format!(
                "vertex {} has a coordinate that is not a finite number",
                i + 1
            )));
        }
        let n = self.positions.len();
        if let Some((i, t)) = self
            .triangles
            .iter()
            .enumerate()
            .find(|(_, t)| t.iter().any(|&v| v as usize >= n))
        {
            return Err(MeshFileError::Invalid(format!(
                "face {} refers to vertex {} but the file has {n} vertices",
                i + 1,
                t.iter().map(|&v| v as usize).max().unwrap_or(0) + 1
            )));
        }
        if self.triangles.is_empty() {
            return Err(MeshFileError::Invalid("the file has no faces".into()));
        }
        Ok(())
    }

    /// The centre of the bounding box and the largest distance of a vertex
    /// from it (`None` if every vertex is the same point). Any finite
    /// coordinates are fine: a mesh 1e-200 across or 2e308 across (whose
    /// squared lengths would underflow or overflow) is measured in units of
    /// its own largest coordinate offset.
    pub fn bounding_ball(&self) -> Option<BoundingBall> {
        let (lo, hi) = self.positions.iter().fold(
            (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        // Halved first: `lo + hi` overflows for a mesh 2e308 across.
        let centre = 0.5 * lo + 0.5 * hi;
        let scale = self
            .positions
            .iter()
            .map(|p| (*p - centre).abs().max_element())
            .fold(0.0, f64::max);
        if !(scale > 0.0 && scale.is_finite()) {
            return None;
        }
        let radius = self
            .positions
            .iter()
            .map(|p| ((*p - centre) / scale).length())
            .fold(0.0, f64::max);
        Some(BoundingBall {
            centre,
            scale,
            radius,
        })
    }

    /// The vertices laid out in the ball: centred, scaled to unit size, and
    /// mapped by geodesic polar coordinates so that the farthest vertex is
    /// at hyperbolic distance `size` from the origin (see the module docs).
    /// `None` if the mesh has no extent.
    pub fn layout(&self, size: f64) -> Option<Vec<Point>> {
        let ball = self.bounding_ball()?;
        // Sized up front: collecting `Option`s would grow the vector by
        // doubling, up to twice the memory of the points.
        let mut points = Vec::with_capacity(self.positions.len());
        for p in &self.positions {
            let u = ball.unit(*p);
            let len = u.length();
            points.push(if len == 0.0 {
                Point::ORIGIN
            } else {
                Point::at_distance_from_origin(u, size * len).ok()?
            });
        }
        Some(points)
    }
}

/// A mesh's bounding ball, from the centre of its bounding box.
#[derive(Clone, Copy, Debug)]
pub struct BoundingBall {
    centre: DVec3,
    /// The largest coordinate offset from the centre: the unit of `radius`.
    scale: f64,
    /// The largest distance from the centre, in units of `scale` (1 to √3).
    radius: f64,
}

impl BoundingBall {
    /// `p` relative to the ball: its farthest vertex at length 1.
    pub fn unit(&self, p: DVec3) -> DVec3 {
        ((p - self.centre) / self.scale) / self.radius
    }
}

/// Splits a polygon `face` (vertex indices in order) into a fan.
pub(super) fn fan(face: &[u32], out: &mut Vec<[u32; 3]>) -> Result<(), MeshFileError> {
    if out.len() + face.len().saturating_sub(2) > MAX_MESH_TRIANGLES {
        return Err(MeshFileError::TooManyTriangles);
    }
    if let Some((&first, rest)) = face.split_first() {
        for pair in rest.windows(2) {
            out.push([first, pair[0], pair[1]]);
        }
    }
    Ok(())
}
