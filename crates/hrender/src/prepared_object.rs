//! An object ready for tracing: its surfaces in the canonical frame, its
//! materials, and what light sampling and textures need of its moved shape
//! (`scene.rs` holds the whole scene and its hierarchy).

use hgeom::glam::DVec4;
use hgeom::{Hit, Isometry, Ray};
use hscene_ir::view::PixelFootprint;
use hscene_ir::{self as ir, PartMaterials, Rgb, Surfaces};

use crate::horizon_bucket::{HorizonFill, bucket_of, is_horizon};
use crate::image_texture::TextureMapping;

/// An object ready for tracing.
pub struct PreparedObject {
    /// Its surfaces in the canonical frame: one, or the parts of a
    /// composite (a polyhedron's faces, a wireframe's rods). Which kinds of
    /// surface there are is the IR's business ([`ir::Shape`]); here every
    /// surface is an `hgeom::Shape`.
    pub surfaces: Surfaces,
    /// Index into the materials.
    pub material: usize,
    /// The materials of its parts, for an object drawn in several (a
    /// honeycomb's faces, edges and cell colours): each hit's `part` picks
    /// one ([`PreparedObject::material_of`]).
    pub parts: Option<PartMaterials>,
    /// Every material it can be drawn in (its own and its parts') lets no
    /// light through: a shadow ray needs only to know whether it meets
    /// the object, not which parts it crosses.
    pub opaque: bool,
    /// From the canonical frame to the object's local space, where its
    /// texture is fixed: `(to_canonical ∘ placement)^-1`.
    pub to_local: Isometry,
    /// The centre and radius of an object that is an h-sphere, in the
    /// canonical frame: an emissive one is a light that can be sampled by
    /// solid angle.
    pub ball: Option<(DVec4, f64)>,
    /// For an emissive object with flat faces (a polygon, a polyhedron, a
    /// triangle mesh), its faces as triangles in the canonical frame: the
    /// path integrator samples them by solid angle. Empty for every other
    /// object.
    pub faces: Vec<[DVec4; 3]>,
    /// A hit's `part` is the index of its triangle in `faces` (a mesh's,
    /// in the mesh's order); otherwise (fans of a polygon's or a
    /// polyhedron's faces) the triangle holding a hit is found by its plane.
    pub faces_by_part: bool,
    /// For a honeycomb, what its horizon hits draw: its average
    /// appearance along the rest of the way to distance 12 and how open
    /// that rest is, by its length (`horizon_fill.rs`). Empty for every
    /// other object.
    pub horizon: Vec<HorizonFill>,
    /// Where its own material's image texture lands on it
    /// (`image_texture.rs`), boxed (152 of each object's 464 bytes, and
    /// few have one); `None` without one, or for a shape with no mapping.
    pub mapping: Option<Box<TextureMapping>>,
}

impl std::fmt::Debug for PreparedObject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PreparedObject")
            .field("surfaces", &self.surfaces.len())
            .field("material", &self.material)
            .finish()
    }
}

impl PreparedObject {
    /// The index of the material of the part a hit met (`hit.part`; for
    /// a honeycomb's horizon hit, by where it is).
    pub fn material_of(&self, hit: &Hit) -> usize {
        match &self.parts {
            None => self.material,
            Some(_) if is_horizon(hit.part) && !self.horizon.is_empty() => {
                self.horizon[bucket_of(hit, self.horizon.len())].material
            }
            Some(p) => p.material(hit.part, self.material),
        }
    }

    /// For a honeycomb's horizon hit, the share of what lies beyond the
    /// honeycomb that arrives through the rest of the way (per channel);
    /// `None` for every other hit.
    pub fn open_beyond(&self, hit: &Hit) -> Option<Rgb> {
        match &self.parts {
            Some(_) if is_horizon(hit.part) && !self.horizon.is_empty() => {
                Some(self.horizon[bucket_of(hit, self.horizon.len())].open)
            }
            _ => None,
        }
    }

    /// The shape moved by each of `stages` in turn, as surfaces; drawn for
    /// pixels of `footprint` if given.
    #[cfg(test)]
    pub(crate) fn surfaces_of(
        shape: &ir::Shape,
        stages: &[Isometry],
        footprint: Option<&PixelFootprint>,
    ) -> Surfaces {
        Self::moved(shape, stages, footprint, false).0
    }

    /// [`PreparedObject::surfaces_of`], what an emitter needs of the moved
    /// shape: its centre and radius if it is an h-sphere, and with
    /// `faces`, its flat faces cut into triangles (fans; a face with an
    /// ideal vertex has no finite area and is left out), or a mesh's
    /// triangles.
    pub(crate) fn moved(
        shape: &ir::Shape,
        stages: &[Isometry],
        footprint: Option<&PixelFootprint>,
        faces: bool,
    ) -> (Surfaces, Option<(DVec4, f64)>, Vec<[DVec4; 3]>) {
        // A camera at the origin has identity stages, and moving by the
        // identity only copies (every cached quantity is recomputed from
        // the same inputs by the same formulas): tens of thousands of rods
        // of a wireframe honeycomb are not copied for nothing.
        let mut moved: Option<ir::Shape> = None;
        for iso in stages.iter().filter(|iso| **iso != Isometry::IDENTITY) {
            moved = Some(moved.as_ref().unwrap_or(shape).transformed(iso));
        }
        if let Some(nearer) =
            footprint.and_then(|f| moved.as_ref().unwrap_or(shape).for_footprint(f))
        {
            moved = Some(nearer);
        }
        // A honeycomb's walk reports where its horizon stops a ray, which
        // is drawn in the honeycomb's average appearance (`horizon_fill.rs`).
        if let Some(hits) = moved
            .as_ref()
            .unwrap_or(shape)
            .with_walk(|w| w.with_horizon_hits(true))
        {
            moved = Some(hits);
        }
        let ball = |s: &ir::Shape| {
            s.sphere()
                .map(|b| (b.center().to_hyperboloid(), b.radius()))
        };
        let triangles = |s: &ir::Shape| -> Vec<[DVec4; 3]> {
            if !faces {
                return Vec::new();
            }
            // A mesh's triangles in its own order, which its hits' `part`
            // counts in.
            if let Some(mesh) = s.mesh() {
                let points: Vec<DVec4> =
                    mesh.vertices().iter().map(|p| p.to_hyperboloid()).collect();
                return mesh
                    .triangles()
                    .iter()
                    .map(|t| t.map(|k| points[k as usize]))
                    .collect();
            }
            s.faces()
                .iter()
                .filter_map(|f| {
                    f.vertices()
                        .iter()
                        .map(|v| match v {
                            hgeom::Vertex::Interior(p) => Some(p.to_hyperboloid()),
                            hgeom::Vertex::Ideal(_) => None,
                        })
                        .collect::<Option<Vec<DVec4>>>()
                })
                .flat_map(|v| (1..v.len().saturating_sub(1)).map(move |k| [v[0], v[k], v[k + 1]]))
                .collect()
        };
        match moved {
            Some(shape) => {
                let (b, t) = (ball(&shape), triangles(&shape));
                (shape.into_surfaces(), b, t)
            }
            None => (shape.to_surfaces(), ball(shape), triangles(shape)),
        }
    }

    /// The nearest hit on any of its surfaces in `(t_min, t_max)`, by
    /// testing each: the reference the hierarchy is checked against.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut limit = t_max;
        let mut best = None;
        for s in self.surfaces.iter() {
            if let Some(hit) = s.intersect(ray, t_min, limit) {
                limit = hit.t;
                best = Some(hit);
            }
        }
        best
    }
}
