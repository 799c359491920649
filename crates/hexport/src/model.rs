//! The exported model: closed triangle shells in millimetres, each with
//! the object it came from and its material.

use hgeom::glam::DVec3;

use crate::grid::TriangleShell;

/// A colour for a format's material table: linear RGB in `[0, 1]`.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportMaterial {
    /// The name: the scene's, or `material-K`.
    pub name: String,
    /// The diffuse colour (linear).
    pub color: [f64; 3],
}

/// One shell: the surface of one solid part.
#[derive(Clone, Debug, PartialEq)]
pub struct Shell {
    /// The object it belongs to, as `check` names objects.
    pub object: String,
    /// Index into [`Model::materials`].
    pub material: usize,
    /// Vertices in millimetres, the ball's centre at the origin.
    pub vertices: Vec<DVec3>,
    /// Triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// True for a closed 2-manifold (every part but an open mesh).
    pub closed: bool,
}

impl Shell {
    /// A shell from a grid mesh in ball units, scaled to millimetres and
    /// wound so that its normals point out.
    pub fn from_grid(object: &str, material: usize, mesh: TriangleShell, scale: f64) -> Shell {
        let mut shell = Shell {
            object: object.to_string(),
            material,
            vertices: mesh.vertices.iter().map(|v| *v * scale).collect(),
            triangles: mesh.triangles,
            closed: true,
        };
        if shell.signed_volume() < 0.0 {
            for t in &mut shell.triangles {
                t.swap(1, 2);
            }
        }
        shell
    }

    /// An open surface (a mesh file's with a boundary), scaled to
    /// millimetres, wound as given.
    pub fn open(object: &str, material: usize, mesh: TriangleShell, scale: f64) -> Shell {
        Shell {
            object: object.to_string(),
            material,
            vertices: mesh.vertices.iter().map(|v| *v * scale).collect(),
            triangles: mesh.triangles,
            closed: false,
        }
    }

    /// The corners of triangle `t`.
    pub fn corners(&self, t: &[u32; 3]) -> [DVec3; 3] {
        t.map(|k| self.vertices[k as usize])
    }

    /// The enclosed volume in cubic millimetres (the divergence theorem
    /// over the triangles: positive when they wind outward).
    pub fn signed_volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = self.corners(t);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    /// How many triangles use the most- or least-used edge, if any edge is
    /// used other than twice in opposite directions: `None` for a closed,
    /// consistently wound 2-manifold.
    pub fn boundary_defect(&self) -> Option<usize> {
        crate::triangles::open_edge(&self.triangles)
    }

    /// The smallest triangle area, in square millimetres.
    pub fn smallest_area(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = self.corners(t);
                0.5 * (b - a).cross(c - a).length()
            })
            .fold(f64::INFINITY, f64::min)
    }
}

/// Everything exported from one scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Model {
    /// The materials the shells use.
    pub materials: Vec<ExportMaterial>,
    /// The shells, in scene order.
    pub shells: Vec<Shell>,
    /// Parts left out by the cut rule.
    pub parts_cut: usize,
}

impl Model {
    /// The number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.shells.iter().map(|s| s.triangles.len()).sum()
    }

    /// The sum of the shells' volumes in cubic millimetres (shells that
    /// overlap count their overlap twice).
    pub fn volume(&self) -> f64 {
        self.shells.iter().map(Shell::signed_volume).sum()
    }
}
