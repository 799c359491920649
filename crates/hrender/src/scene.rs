//! The scene prepared for tracing: everything moved into the canonical frame
//! once, in f64, so near the eye every quantity is small and well conditioned.

use hgeom::glam::DVec4;
use hgeom::{
    ConvexPolygon, HCylinder, HPlane, HSphere, Hit, Horosphere, Isometry, Polyhedron, Ray, Rod,
    Vertex,
};
use hscene_lang::ir::{self, Material, Rgb, Scene};

use crate::error::RenderError;

/// A traceable shape in the canonical frame.
#[derive(Clone, Debug)]
pub enum Primitive {
    /// An h-sphere.
    Sphere(HSphere),
    /// A convex polygon.
    Polygon(ConvexPolygon),
    /// A polyhedral surface.
    Polyhedron(Polyhedron),
    /// A whole h-plane.
    Plane(HPlane),
    /// A rod about a segment.
    Rod(Rod),
    /// An h-cylinder about a whole line.
    Cylinder(HCylinder),
    /// A horosphere.
    Horosphere(Horosphere),
    /// A set of rods.
    Wireframe(Vec<Rod>),
}

impl Primitive {
    fn from_shape(shape: &ir::Shape, iso: &Isometry) -> Primitive {
        match shape {
            ir::Shape::Sphere(s) => Primitive::Sphere(s.transformed(iso)),
            ir::Shape::Polygon(p) => Primitive::Polygon(p.transformed(iso)),
            ir::Shape::Polyhedron(p) => Primitive::Polyhedron(p.transformed(iso)),
            ir::Shape::Plane(p) => Primitive::Plane(p.transformed(iso)),
            ir::Shape::Rod(r) => Primitive::Rod(r.transformed(iso)),
            ir::Shape::Cylinder(c) => Primitive::Cylinder(c.transformed(iso)),
            ir::Shape::Horosphere(h) => Primitive::Horosphere(h.transformed(iso)),
            ir::Shape::Wireframe(rods) => {
                Primitive::Wireframe(rods.iter().map(|r| r.transformed(iso)).collect())
            }
        }
    }

    /// True if every defining point is representable in f64 in this frame.
    fn is_representable(&self) -> bool {
        let vertex_ok = |v: &Vertex| match v {
            Vertex::Interior(p) => p.is_representable(),
            Vertex::Ideal(_) => true,
        };
        match self {
            Primitive::Sphere(s) => s.center().is_representable(),
            Primitive::Polygon(p) => p.vertices().iter().all(vertex_ok),
            Primitive::Polyhedron(p) => {
                p.faces().iter().all(|f| f.vertices().iter().all(vertex_ok))
            }
            Primitive::Plane(p) => p.normal().is_finite(),
            Primitive::Rod(r) => vertex_ok(&r.start()) && vertex_ok(&r.end()),
            Primitive::Cylinder(c) => c.line().base().is_representable(),
            Primitive::Horosphere(h) => h.euclidean().1.is_finite(),
            Primitive::Wireframe(rods) => rods
                .iter()
                .all(|r| vertex_ok(&r.start()) && vertex_ok(&r.end())),
        }
    }

    /// Nearest hit in `(t_min, t_max)`.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        match self {
            Primitive::Sphere(s) => s.intersect(ray, t_min, t_max),
            Primitive::Polygon(p) => p.intersect(ray, t_min, t_max),
            Primitive::Polyhedron(p) => p.intersect(ray, t_min, t_max),
            Primitive::Plane(p) => p.intersect(ray, t_min, t_max),
            Primitive::Rod(r) => r.intersect(ray, t_min, t_max),
            Primitive::Cylinder(c) => c.intersect(ray, t_min, t_max),
            Primitive::Horosphere(h) => h.intersect(ray, t_min, t_max),
            Primitive::Wireframe(rods) => {
                let mut best: Option<Hit> = None;
                let mut limit = t_max;
                for r in rods {
                    if let Some(hit) = r.intersect(ray, t_min, limit) {
                        limit = hit.t;
                        best = Some(hit);
                    }
                }
                best
            }
        }
    }
}

/// An object ready for tracing.
#[derive(Clone, Debug)]
pub struct PreparedObject {
    /// Geometry in the canonical frame.
    pub primitive: Primitive,
    /// Index into the materials.
    pub material: usize,
}

/// A point light on the hyperboloid.
#[derive(Clone, Copy, Debug)]
pub struct PreparedLight {
    /// Position.
    pub position: DVec4,
    /// Diffuse intensity.
    pub diffuse: Rgb,
    /// Specular intensity.
    pub specular: Rgb,
}

/// The whole scene in the canonical frame.
#[derive(Clone, Debug)]
pub struct PreparedScene {
    /// Objects.
    pub objects: Vec<PreparedObject>,
    /// Lights.
    pub lights: Vec<PreparedLight>,
    /// Materials.
    pub materials: Vec<Material>,
    /// Background colour.
    pub background: Rgb,
    /// Ambient light.
    pub ambient: Rgb,
    /// Maximum bounce depth.
    pub max_depth: u32,
}

impl PreparedScene {
    /// Move every object and light by `to_canonical`.
    ///
    /// Fails if something lies so far from the eye (beyond distance ~37)
    /// that f64 cannot represent it in the eye's frame: that is reported,
    /// not silently dropped.
    pub fn new(scene: &Scene, to_canonical: &Isometry) -> Result<PreparedScene, RenderError> {
        let mut objects = Vec::with_capacity(scene.objects.len());
        for (index, o) in scene.objects.iter().enumerate() {
            let primitive = Primitive::from_shape(&o.shape, to_canonical);
            if !primitive.is_representable() {
                return Err(RenderError::OutOfRange {
                    what: format!("object {}", index + 1),
                });
            }
            objects.push(PreparedObject {
                primitive,
                material: o.material.0,
            });
        }
        let mut lights = Vec::with_capacity(scene.lights.len());
        for (index, l) in scene.lights.iter().enumerate() {
            let p = to_canonical
                .try_apply(&l.position)
                .map_err(|_| RenderError::OutOfRange {
                    what: format!("light {}", index + 1),
                })?;
            lights.push(PreparedLight {
                position: p.to_hyperboloid(),
                diffuse: l.diffuse,
                specular: l.specular,
            });
        }
        Ok(PreparedScene {
            objects,
            lights,
            materials: scene.materials.clone(),
            background: scene.settings.background,
            ambient: scene.settings.ambient,
            max_depth: scene.settings.recursion_depth,
        })
    }

    /// The nearest hit and the index of the object hit.
    pub fn nearest(&self, ray: &Ray, t_min: f64) -> Option<(Hit, usize)> {
        let mut best = None;
        let mut limit = f64::INFINITY;
        for (i, o) in self.objects.iter().enumerate() {
            if let Some(hit) = o.primitive.intersect(ray, t_min, limit) {
                limit = hit.t;
                best = Some((hit, i));
            }
        }
        best
    }
}
