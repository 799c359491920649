//! The scene prepared for tracing: everything moved into the canonical frame
//! once, in f64, so near the eye every quantity is small and well conditioned;
//! and bounding h-spheres around everything finite, in a hierarchy, so a ray
//! pays the exact intersection only for what it may actually meet.

use hgeom::glam::{DVec3, DVec4};
use hgeom::{Hit, Isometry, Point, Ray};
use hscene_lang::ir::{self, BoxedSurface, Fog, Material, PartMaterials, Rgb, Scene, Surfaces};

use crate::bvh::{Bound, Bvh, Step};
use crate::camera::CanonicalCamera;
use crate::error::RenderError;

/// A traceable shape in the canonical frame: one surface, or the parts of a
/// composite (a polyhedron's faces, a wireframe's rods) under a hierarchy of
/// their own. Which kinds of surface there are is the IR's business
/// ([`ir::Shape`]); here every surface is an `hgeom::Shape`.
pub enum Primitive {
    /// One surface.
    Single(BoxedSurface),
    /// Parts with a hierarchy over them.
    Composite(Composite),
}

impl std::fmt::Debug for Primitive {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Primitive::Single(_) => f.write_str("Primitive::Single"),
            Primitive::Composite(c) => write!(f, "Primitive::Composite({} parts)", c.parts.len()),
        }
    }
}

/// Parts with a hierarchy of bounds over them.
pub struct Composite {
    parts: Vec<BoxedSurface>,
    accel: Accel,
}

impl Composite {
    fn new(parts: Vec<BoxedSurface>) -> Composite {
        let mut leaves = Vec::new();
        for (i, part) in parts.iter().enumerate() {
            let pieces = part.bound_pieces();
            if pieces.is_empty() {
                leaves.push((i as u32, None));
            }
            leaves.extend(
                pieces
                    .iter()
                    .map(|b| (i as u32, Bound::new(b.center(), b.radius()))),
            );
        }
        Composite {
            parts,
            accel: Accel::new(&leaves),
        }
    }

    /// The parts.
    pub fn parts(&self) -> &[BoxedSurface] {
        &self.parts
    }

    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        self.accel
            .nearest(ray, t_min, t_max, |i, lo, hi| {
                self.parts[i as usize].intersect(ray, lo, hi)
            })
            .map(|(hit, _)| hit)
    }

    #[inline]
    fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let mut found = false;
        self.accel.any(ray, t_min, t_max, |i| {
            found = self.parts[i as usize].blocks(ray, t_min, t_max);
            if found { Step::Stop } else { Step::Continue }
        });
        found
    }
}

/// A bounding hierarchy over items `0..n`, plus the items without a bound
/// (h-planes, h-cylinders, horospheres, anything with an ideal point), which
/// every ray tests.
#[derive(Clone, Debug, Default)]
struct Accel {
    bvh: Bvh,
    unbounded: Vec<u32>,
}

impl Accel {
    /// From `(item, bound)` leaves; an item may have several leaves (its
    /// exact test then runs at most once per leaf the ray enters, which is
    /// harmless: a repeated test finds nothing nearer).
    fn new(leaves: &[(u32, Option<Bound>)]) -> Accel {
        let mut bounded = Vec::new();
        let mut unbounded = Vec::new();
        for (i, b) in leaves {
            match b {
                Some(b) => bounded.push((*i, *b)),
                None => unbounded.push(*i),
            }
        }
        Accel {
            bvh: Bvh::build(&bounded),
            unbounded,
        }
    }

    /// A ball around every item, if all are bounded.
    fn bound(&self) -> Option<Bound> {
        if self.unbounded.is_empty() {
            self.bvh.bound()
        } else {
            None
        }
    }

    /// The nearest hit among the items: `test(item, t_min, t_max)` is the
    /// item's exact test, called with the nearest hit so far as `t_max`.
    #[inline]
    fn nearest(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        mut test: impl FnMut(u32, f64, f64) -> Option<Hit>,
    ) -> Option<(Hit, u32)> {
        let mut best = None;
        let mut limit = t_max;
        for &i in &self.unbounded {
            if let Some(hit) = test(i, t_min, limit) {
                limit = hit.t;
                best = Some((hit, i));
            }
        }
        if !self.bvh.is_empty() {
            // The bounds work in u = e^t (no logarithms in their test).
            let mut u_max = limit.exp();
            self.bvh.traverse(ray, t_min.exp(), &mut u_max, |i, u_max| {
                if let Some(hit) = test(i, t_min, limit) {
                    limit = hit.t;
                    *u_max = hit.t.exp();
                    best = Some((hit, i));
                }
                Step::Continue
            });
        }
        best
    }

    /// Visit every item that may meet the ray's arc `(t_min, t_max)`, until
    /// `visit` says stop.
    #[inline]
    fn any(&self, ray: &Ray, t_min: f64, t_max: f64, mut visit: impl FnMut(u32) -> Step) {
        for &i in &self.unbounded {
            if visit(i) == Step::Stop {
                return;
            }
        }
        let mut u_max = t_max.exp();
        self.bvh
            .traverse(ray, t_min.exp(), &mut u_max, |i, _| visit(i));
    }
}

impl Primitive {
    /// The shape moved by each of `stages` in turn.
    fn from_shape(shape: &ir::Shape, stages: &[Isometry]) -> Primitive {
        let mut moved = shape.transformed(&stages[0]);
        for iso in &stages[1..] {
            moved = moved.transformed(iso);
        }
        match moved.into_surfaces() {
            Surfaces::Single(s) => Primitive::Single(s),
            Surfaces::Parts(parts) => Primitive::Composite(Composite::new(parts)),
        }
    }

    /// True if every part can be traced exactly in the canonical frame.
    fn is_traceable(&self) -> bool {
        match self {
            Primitive::Single(s) => s.is_traceable(),
            Primitive::Composite(c) => c.parts.iter().all(|p| p.is_traceable()),
        }
    }

    /// A ball containing the primitive, if it is bounded.
    fn bound(&self) -> Option<Bound> {
        match self {
            Primitive::Single(s) => s.bound().and_then(|b| Bound::new(b.center(), b.radius())),
            Primitive::Composite(c) => c.accel.bound(),
        }
    }

    /// Nearest hit in `(t_min, t_max)`.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        match self {
            Primitive::Single(s) => s.intersect(ray, t_min, t_max),
            Primitive::Composite(c) => c.intersect(ray, t_min, t_max),
        }
    }

    /// True if the primitive meets the ray anywhere in `(t_min, t_max)`; for
    /// composites, stops at the first part met.
    #[inline]
    pub fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match self {
            Primitive::Single(s) => s.blocks(ray, t_min, t_max),
            Primitive::Composite(c) => c.blocks(ray, t_min, t_max),
        }
    }
}

/// An object ready for tracing.
#[derive(Debug)]
pub struct PreparedObject {
    /// Geometry in the canonical frame.
    pub primitive: Primitive,
    /// Index into the materials.
    pub material: usize,
    /// The materials of its parts, for an object drawn in several (a
    /// honeycomb's faces, edges and cell colours): each hit's `part` picks
    /// one ([`PreparedObject::material_of`]).
    pub parts: Option<PartMaterials>,
    /// From the canonical frame to the object's local space, where its
    /// texture is fixed: `(to_canonical ∘ placement)^-1`.
    pub to_local: Isometry,
}

impl PreparedObject {
    /// The index of the material of the part a hit met (`hit.part`).
    pub fn material_of(&self, part: u32) -> usize {
        match &self.parts {
            None => self.material,
            Some(p) => p.material(part, self.material),
        }
    }
}

/// Shadow rays through an object drawn in several materials stop counting
/// its crossings here: the light left is below 1/1000 (counted as none) or
/// the ray has crossed this many of its parts.
const MIN_TRANSMITTANCE: f64 = 1e-3;
const MAX_PART_CROSSINGS: u32 = 64;

/// How far past a part's crossing the next one is looked for: the hit was
/// on a wall the walk crosses there, and finding it again would count one
/// face twice. The tracer's own offset for secondary rays.
const PART_GAP: f64 = crate::tracer::T_MIN;

/// A light on the hyperboloid: a point, or an h-sphere about it.
#[derive(Clone, Copy, Debug)]
pub struct PreparedLight {
    /// Position (the centre of an area light).
    pub position: DVec4,
    /// Diffuse intensity.
    pub diffuse: Rgb,
    /// Specular intensity.
    pub specular: Rgb,
    /// Hyperbolic radius of an area light; 0 for a point light.
    pub radius: f64,
    /// Shadow rays per shading point for an area light (at least 1).
    pub samples: u32,
}

/// The outcome of looking for the nearest hit.
#[derive(Clone, Copy, Debug)]
pub enum Nearest {
    /// The ray leaves the scene.
    Miss,
    /// The nearest hit and the index of the object hit.
    Hit(Hit, usize),
    /// The ray or its hit is not finite: a numeric failure, to be counted,
    /// never shown as a silent miss.
    Failure,
}

/// The whole scene in the canonical frame.
#[derive(Debug)]
pub struct PreparedScene {
    /// Objects.
    pub objects: Vec<PreparedObject>,
    /// Lights.
    pub lights: Vec<PreparedLight>,
    /// Materials.
    pub materials: Vec<Material>,
    /// Background colour.
    pub background: Rgb,
    /// Fog along every ray segment (`docs/rendering.md#fog`).
    pub fog: Option<Fog>,
    /// Ambient light.
    pub ambient: Rgb,
    /// Maximum bounce depth.
    pub max_depth: u32,
    /// Hierarchy over the objects.
    accel: Accel,
}

impl PreparedScene {
    /// Move every object and light by `to_canonical`, and build the
    /// bounding hierarchy.
    ///
    /// Fails if something lies so far from the eye (beyond distance ~37)
    /// that f64 cannot represent it in the canonical frame: that is reported,
    /// not silently dropped.
    pub fn new(scene: &Scene, to_canonical: &Isometry) -> Result<PreparedScene, RenderError> {
        PreparedScene::staged(scene, std::slice::from_ref(to_canonical))
    }

    /// [`PreparedScene::new`] for a camera: everything is moved by the
    /// camera's [`stages`](CanonicalCamera::stages) in turn, which keeps far
    /// scenes exact to the rounding of their input.
    pub fn for_camera(
        scene: &Scene,
        camera: &CanonicalCamera,
    ) -> Result<PreparedScene, RenderError> {
        PreparedScene::staged(scene, &camera.stages)
    }

    /// Move everything by each of `stages` in turn (at least one).
    fn staged(scene: &Scene, stages: &[Isometry]) -> Result<PreparedScene, RenderError> {
        let mut objects = Vec::with_capacity(scene.objects.len());
        for (index, o) in scene.objects.iter().enumerate() {
            if o.material.index() >= scene.materials.len() {
                return Err(RenderError::InvalidScene(format!(
                    "object {} uses material {}, but there are only {}",
                    index + 1,
                    o.material.index() + 1,
                    scene.materials.len()
                )));
            }
            let parts = o.shape.part_materials().cloned();
            let part_ids = parts.iter().flat_map(|p| p.faces.iter().chain(&p.palette));
            if let Some(bad) = part_ids
                .map(|m| m.index())
                .find(|&m| m >= scene.materials.len())
            {
                return Err(RenderError::InvalidScene(format!(
                    "object {} uses material {} for some of its parts, but there are only {}",
                    index + 1,
                    bad + 1,
                    scene.materials.len()
                )));
            }
            let primitive = Primitive::from_shape(&o.shape, stages);
            if !primitive.is_traceable() {
                return Err(RenderError::OutOfRange {
                    what: format!("object {}", index + 1),
                });
            }
            objects.push(PreparedObject {
                primitive,
                material: o.material.index(),
                parts,
                to_local: stages
                    .iter()
                    .fold(o.placement, |f, iso| iso.compose(&f))
                    .inverse(),
            });
        }
        for (index, m) in scene.materials.iter().enumerate() {
            let bad_scale = m
                .texture
                .map(|t| t.scale)
                .filter(|s| !(*s > 0.0 && s.is_finite()));
            if let Some(scale) = bad_scale {
                return Err(RenderError::InvalidScene(format!(
                    "material {} has a texture scale of {scale}; it must be positive and finite",
                    index + 1,
                )));
            }
        }
        let mut lights = Vec::with_capacity(scene.lights.len());
        for (index, l) in scene.lights.iter().enumerate() {
            if !(l.radius >= 0.0 && l.radius.is_finite()) || l.samples == 0 {
                return Err(RenderError::InvalidScene(format!(
                    "light {} has radius {} and {} samples; the radius must be finite and \
                     non-negative, the samples at least 1",
                    index + 1,
                    l.radius,
                    l.samples
                )));
            }
            let out_of_range = || RenderError::OutOfRange {
                what: format!("light {}", index + 1),
            };
            let p = stages
                .iter()
                .try_fold(l.position, |p, iso| iso.checked_apply(&p))
                .map_err(|_| out_of_range())?;
            // Every point of an area light must be placeable too.
            if l.radius > 0.0 {
                Point::at_distance_from_origin(DVec3::Z, p.distance_from_origin() + l.radius)
                    .map_err(|_| out_of_range())?;
            }
            lights.push(PreparedLight {
                position: p.to_hyperboloid(),
                diffuse: l.diffuse,
                specular: l.specular,
                radius: l.radius,
                samples: l.samples,
            });
        }
        // One leaf per object, so a shadow ray meets each object once.
        let bounds: Vec<(u32, Option<Bound>)> = objects
            .iter()
            .enumerate()
            .map(|(i, o)| (i as u32, o.primitive.bound()))
            .collect();
        Ok(PreparedScene {
            objects,
            lights,
            materials: scene.materials.clone(),
            background: scene.settings.background,
            fog: scene.settings.fog,
            ambient: scene.settings.ambient,
            max_depth: scene.settings.recursion_depth,
            accel: Accel::new(&bounds),
        })
    }

    /// The nearest hit beyond `t_min`.
    pub fn nearest(&self, ray: &Ray, t_min: f64) -> Nearest {
        // A NaN ray would miss every exact test and every bound: catch it
        // here, where it is still a failure and not yet a "miss".
        if !(ray.origin.is_finite() && ray.dir.is_finite()) {
            return Nearest::Failure;
        }
        let found = self.accel.nearest(ray, t_min, f64::INFINITY, |i, lo, hi| {
            self.objects[i as usize].primitive.intersect(ray, lo, hi)
        });
        match found {
            None => Nearest::Miss,
            Some((hit, i)) if hit.point.is_finite() && hit.normal.is_finite() => {
                Nearest::Hit(hit, i as usize)
            }
            Some(_) => Nearest::Failure,
        }
    }

    /// The fraction of light passing along the ray's arc `(t_min, t_max)`:
    /// each object met multiplies it by its transmission coefficient, once
    /// per object; an object drawn in several materials (a honeycomb) by
    /// that of each part crossed, since its transparent faces are many
    /// separate sheets. The search ends at the first opaque blocker.
    pub fn transmittance(&self, ray: &Ray, t_min: f64, t_max: f64) -> f64 {
        let mut s = 1.0;
        self.accel.any(ray, t_min, t_max, |i| {
            let o = &self.objects[i as usize];
            if o.parts.is_some() {
                s *= self.parts_transmittance(o, ray, t_min, t_max);
                if s == 0.0 {
                    return Step::Stop;
                }
            } else if o.primitive.blocks(ray, t_min, t_max) {
                // PreparedScene::new checked every material index.
                s *= self.materials[o.material].transmission;
                if s == 0.0 {
                    return Step::Stop;
                }
            }
            Step::Continue
        });
        s
    }

    /// The light an object drawn in several materials lets through along
    /// `(t_min, t_max)`: the product of the transmissions of the parts the
    /// ray crosses, found one after the other.
    fn parts_transmittance(&self, o: &PreparedObject, ray: &Ray, t_min: f64, t_max: f64) -> f64 {
        let mut s = 1.0;
        let mut from = t_min;
        for _ in 0..MAX_PART_CROSSINGS {
            let Some(hit) = o.primitive.intersect(ray, from, t_max) else {
                return s;
            };
            // PreparedScene::new checked every material index of the parts.
            s *= self.materials[o.material_of(hit.part)].transmission;
            if s < MIN_TRANSMITTANCE {
                return 0.0;
            }
            from = hit.t + PART_GAP;
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::{ConvexPolygon, HPlane, Rod};

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    /// A plane given by a bare normal 17 from the eye cannot be resolved in
    /// f64 (its `<N,N>` rounds at `eps e^34 / 4 ~ 3e-2`; at 25 the bare
    /// normal is not even spacelike): the scene is refused, not drawn
    /// without it. The same plane placed by an isometry is exact.
    #[test]
    fn unresolvable_plane_is_reported() {
        let far = Isometry::transvection_from_origin(
            Point::at_distance_from_origin(DVec3::new(0.2, 0.1, 1.0), 17.0).unwrap(),
        );
        let placed = HPlane::orthogonal_at(&p(0.0, 0.0, 0.3), &p(0.0, 0.0, 0.4))
            .unwrap()
            .transformed(&far);
        let bare = HPlane::from_normal(placed.normal()).unwrap();
        let back = far.inverse();
        let prim = |plane: &HPlane| Primitive::from_shape(&ir::Shape::Plane(*plane), &[back]);
        assert!(prim(&placed).is_traceable());
        assert!(!prim(&bare).is_traceable());
    }

    /// Every primitive's bound contains the hits of many rays: the bound
    /// never culls what the exact test finds.
    #[test]
    fn bounds_contain_every_hit() {
        let rod = Rod::new(p(-0.3, 0.1, 0.4).into(), p(0.2, -0.1, 0.6).into(), 0.05).unwrap();
        let poly = ConvexPolygon::new(vec![
            p(-0.2, -0.2, 0.5).into(),
            p(0.2, -0.2, 0.5).into(),
            p(0.0, 0.25, 0.55).into(),
        ])
        .unwrap();
        let dodeca = hgeom::Polyhedron::platonic(hgeom::Platonic::Dodecahedron, 0.4)
            .unwrap()
            .transformed(&Isometry::transvection_from_origin(p(0.0, 0.0, 0.5)));
        let shapes = [
            ir::Shape::Rod(rod.clone()),
            ir::Shape::Polygon(poly),
            ir::Shape::Polyhedron(dodeca),
            ir::Shape::Wireframe(vec![rod]),
        ];
        for shape in &shapes {
            let prim = Primitive::from_shape(shape, &[Isometry::IDENTITY]);
            let b = prim.bound().expect("bounded");
            let mut hits = 0;
            for i in 0..2000 {
                let a = f64::from(i) * 0.618_033_988_749_895;
                let r = 0.9 * (f64::from(i) / 2000.0).sqrt();
                let ray = Ray::from_origin_unchecked(DVec3::new(r * a.sin(), r * a.cos(), 1.0));
                if let Some(hit) = prim.intersect(&ray, 0.0, f64::INFINITY) {
                    hits += 1;
                    assert!(b.contains(hit.point, 1e-12), "{prim:?}");
                    assert!(b.entry(&ray, 1.0, f64::INFINITY).is_some());
                }
            }
            assert!(hits > 50, "{prim:?}: {hits}");
        }
    }
}
