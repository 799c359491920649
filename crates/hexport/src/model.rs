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

/// The scene object a shell belongs to.
#[derive(Clone, Debug, PartialEq)]
pub struct Owner {
    /// Its index in the scene's objects.
    pub index: usize,
    /// How messages name it, as `check` does: `object 3 ("name")`.
    pub label: String,
    /// What a slicer shows: the object's name, else its kind and number
    /// (`Sphere 3`).
    pub name: String,
}

/// One shell: the surface of one solid part.
#[derive(Clone, Debug, PartialEq)]
pub struct Shell {
    /// The object it belongs to, as `check` names objects.
    pub object: String,
    /// Its object's index in the scene.
    pub object_index: usize,
    /// Its object's name for a slicer ([`Owner::name`]).
    pub object_name: String,
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
    pub fn from_grid(owner: &Owner, material: usize, mesh: TriangleShell, scale: f64) -> Shell {
        let mut shell = Shell {
            closed: true,
            ..Shell::open(owner, material, mesh, scale)
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
    pub fn open(owner: &Owner, material: usize, mesh: TriangleShell, scale: f64) -> Shell {
        Shell {
            object: owner.label.clone(),
            object_index: owner.index,
            object_name: owner.name.clone(),
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

    /// The corners of the box that holds it, in millimetres.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let far = DVec3::splat(f64::INFINITY);
        self.vertices
            .iter()
            .fold((far, -far), |(lo, hi), v| (lo.min(*v), hi.max(*v)))
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

    /// The shells grouped by the object they belong to, in scene order:
    /// one printed body each.
    pub fn bodies(&self) -> Vec<Vec<&Shell>> {
        let mut bodies: Vec<Vec<&Shell>> = Vec::new();
        for shell in &self.shells {
            match bodies
                .iter_mut()
                .find(|b| b[0].object_index == shell.object_index)
            {
                Some(body) => body.push(shell),
                None => bodies.push(vec![shell]),
            }
        }
        bodies
    }

    /// The labels of the bodies that would float in a print of several:
    /// those whose box meets no other body's box (within `gap`
    /// millimetres), so they touch nothing for certain. Bodies whose boxes
    /// meet may still not touch; this names only the sure ones. A print
    /// of one body has none.
    pub fn floating_bodies(&self, gap: f64) -> Vec<String> {
        let bodies = self.bodies();
        let boxes: Vec<(DVec3, DVec3)> = bodies
            .iter()
            .map(|b| {
                let far = DVec3::splat(f64::INFINITY);
                b.iter()
                    .map(|s| s.bounds())
                    .fold((far, -far), |(lo, hi), (l, h)| (lo.min(l), hi.max(h)))
            })
            .collect();
        let meet = |(a0, a1): (DVec3, DVec3), (b0, b1): (DVec3, DVec3)| {
            (a0 - b1).max_element() <= gap && (b0 - a1).max_element() <= gap
        };
        if bodies.len() < 2 {
            return Vec::new();
        }
        (0..bodies.len())
            .filter(|&i| (0..bodies.len()).all(|j| j == i || !meet(boxes[i], boxes[j])))
            .map(|i| bodies[i][0].object.clone())
            .collect()
    }
}
