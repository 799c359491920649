//! A renderable object: its shape, material and placement.

use hgeom::Isometry;

use crate::material::MaterialId;
use crate::shape::Shape;

/// A renderable object.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Geometry.
    pub shape: Shape,
    /// Surface material.
    pub material: MaterialId,
    /// The name of the statement that declared it (`ball: Sphere ...;`), if
    /// any. One statement can give several objects: a polyhedron with
    /// `edges = t` gives its faces and its edges (a wireframe), a
    /// tessellation one polyhedron per cell; they share the name.
    pub name: Option<String>,
    /// The object's placement: the isometry from its local space to the
    /// world. Textures are fixed in the local space. It is the identity for
    /// objects given by world points (polygons, planes, rods, cylinders,
    /// horospheres), the translation from the origin to the centre for a
    /// sphere, the `at` translation for figures and meshes (built about the
    /// origin), each followed by the object's own `@name` transformations.
    pub placement: Isometry,
}

/// The object moved by `iso`: its shape moved, its placement composed;
/// `None` if the shape leaves what f64 can represent.
pub fn move_object(object: &Object, iso: &Isometry) -> Option<Object> {
    Some(Object {
        shape: object.shape.moved(iso)?,
        material: object.material,
        name: object.name.clone(),
        placement: iso.compose(&object.placement),
    })
}
