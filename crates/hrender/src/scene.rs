//! The scene prepared for tracing: everything moved into the canonical frame
//! once, in f64, so near the eye every quantity is small and well conditioned;
//! and bounding h-spheres around everything finite, in a hierarchy, so a ray
//! pays the exact intersection only for what it may actually meet.

use hgeom::glam::{DVec3, DVec4};
use hgeom::lorentz;
use hgeom::{
    ConvexPolygon, HCylinder, HPlane, HSphere, Hit, Horosphere, Isometry, Point, Ray, Rod,
    TriangleMesh, Vertex,
};
use hscene_lang::ir::{self, Fog, Material, Rgb, Scene};

use crate::bvh::{Bound, Bvh, Step};
use crate::camera::CanonicalCamera;
use crate::error::RenderError;

/// Padding of bounds around polygons. A polygon accepts hits slightly
/// outside its edges (`<P,E> >= -1e-10 |P| |E|`, to keep shared edges
/// watertight); that slack grows like `cosh^2` of the distance from the
/// origin, so the pad is this factor times `1 + max w^2` over the vertices.
const FLAT_PAD: f64 = 1e-9;

/// A traceable shape in the canonical frame.
#[derive(Clone, Debug)]
pub enum Primitive {
    /// An h-sphere.
    Sphere(HSphere),
    /// A convex polygon.
    Polygon(ConvexPolygon),
    /// A polyhedral surface: its faces, with a hierarchy over them.
    Polyhedron(Composite<ConvexPolygon>),
    /// A whole h-plane.
    Plane(HPlane),
    /// A rod about a segment (boxed: a rod is several times larger than
    /// the other variants).
    Rod(Box<Rod>),
    /// An h-cylinder about a whole line (boxed, likewise).
    Cylinder(Box<HCylinder>),
    /// A horosphere.
    Horosphere(Horosphere),
    /// A set of rods, with a hierarchy over them.
    Wireframe(Composite<Rod>),
    /// A triangle mesh, with its own hierarchy (in Klein coordinates of the
    /// mesh's local frame; boxed: the mesh's header is large).
    Mesh(Box<TriangleMesh>),
}

/// What a composite primitive is made of.
pub trait Part {
    /// Nearest hit in `(t_min, t_max)`.
    fn hit(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit>;
    /// A ball containing the part, if it is bounded.
    fn bound(&self) -> Option<Bound>;
    /// Balls whose union contains the part, for the hierarchy's leaves;
    /// empty if the part is unbounded. Long thin parts give several small
    /// balls, which hug them far better than one ball can.
    fn pieces(&self) -> Vec<Bound> {
        self.bound().into_iter().collect()
    }
}

impl Part for ConvexPolygon {
    #[inline]
    fn hit(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        self.intersect(ray, t_min, t_max)
    }
    fn bound(&self) -> Option<Bound> {
        polygon_bound(self)
    }
}

impl Part for Rod {
    #[inline]
    fn hit(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        self.intersect(ray, t_min, t_max)
    }
    fn bound(&self) -> Option<Bound> {
        rod_bound(self)
    }
    fn pieces(&self) -> Vec<Bound> {
        rod_pieces(self)
    }
}

/// Parts with a hierarchy of bounds over them.
#[derive(Clone, Debug)]
pub struct Composite<T> {
    parts: Vec<T>,
    accel: Accel,
}

impl<T: Part> Composite<T> {
    fn new(parts: Vec<T>) -> Composite<T> {
        let mut leaves = Vec::new();
        for (i, part) in parts.iter().enumerate() {
            let pieces = part.pieces();
            if pieces.is_empty() {
                leaves.push((i as u32, None));
            }
            leaves.extend(pieces.into_iter().map(|b| (i as u32, Some(b))));
        }
        Composite {
            parts,
            accel: Accel::new(&leaves),
        }
    }

    /// The parts.
    pub fn parts(&self) -> &[T] {
        &self.parts
    }

    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        self.accel
            .nearest(ray, t_min, t_max, |i, lo, hi| {
                self.parts[i as usize].hit(ray, lo, hi)
            })
            .map(|(hit, _)| hit)
    }

    #[inline]
    fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let mut found = false;
        self.accel.any(ray, t_min, t_max, |i| {
            found = self.parts[i as usize].hit(ray, t_min, t_max).is_some();
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

/// A ball around a polygon: around its vertices (a convex polygon is their
/// convex hull, and balls are convex); none if a vertex is ideal.
fn polygon_bound(p: &ConvexPolygon) -> Option<Bound> {
    let pts = p
        .vertices()
        .iter()
        .map(|v| match v {
            Vertex::Interior(q) => Some(q.to_hyperboloid()),
            Vertex::Ideal(_) => None,
        })
        .collect::<Option<Vec<DVec4>>>()?;
    let far = pts.iter().map(|x| x.w * x.w).fold(1.0, f64::max);
    Bound::around(&pts, FLAT_PAD * (1.0 + far))
}

/// A ball around a finite rod: centred at the segment's midpoint, of radius
/// half its length plus the rod's radius (the rod is the `r`-neighbourhood
/// of the segment, and the segment lies in the ball about its midpoint).
fn rod_bound(r: &Rod) -> Option<Bound> {
    match (r.start(), r.end()) {
        (Vertex::Interior(a), Vertex::Interior(b)) => Bound::around(
            &[a.to_hyperboloid(), b.to_hyperboloid()],
            r.radius() * (1.0 + 1e-9) + 1e-12,
        ),
        _ => None,
    }
}

/// Balls along a finite rod: the segment cut into `k` equal pieces, each
/// in the ball about its midpoint of radius half its length plus the rod's
/// radius (the end pieces' balls contain the caps, as the caps are balls of
/// the rod's radius about the end points). `k` makes the pieces about 16
/// rod radii long, at most 8 of them: measured on a {4,3,5} wireframe that
/// saves a quarter of the work (long rods around the eye), while on 600
/// short random rods it costs 2 %; finer pieces only add leaves.
fn rod_pieces(r: &Rod) -> Vec<Bound> {
    let single = || rod_bound(r).into_iter().collect();
    let (Vertex::Interior(a), Vertex::Interior(b)) = (r.start(), r.end()) else {
        return Vec::new();
    };
    let (xa, xb) = (a.to_hyperboloid(), b.to_hyperboloid());
    let Some((towards, len)) = lorentz::direction_towards(xa, xb) else {
        return single();
    };
    let k = (len / (16.0 * r.radius())).ceil().clamp(1.0, 8.0);
    if !(k > 1.0) {
        return single();
    }
    let half = 0.5 * len / k;
    let radius = (half + r.radius()) * (1.0 + 1e-9) + 1e-12;
    let pieces: Option<Vec<Bound>> = (0..k as u32)
        .map(|i| {
            let s = (2.0 * f64::from(i) + 1.0) * half;
            Bound::new(lorentz::geodesic_point(xa, towards, s), radius)
        })
        .collect();
    pieces.unwrap_or_else(single)
}

impl Primitive {
    /// The shape moved by each of `stages` in turn.
    fn from_shape(shape: &ir::Shape, stages: &[Isometry]) -> Primitive {
        let mut prim = Primitive::moved(shape, &stages[0]);
        for iso in &stages[1..] {
            prim = prim.transformed(iso);
        }
        prim
    }

    fn transformed(&self, iso: &Isometry) -> Primitive {
        match self {
            Primitive::Sphere(s) => Primitive::Sphere(s.transformed(iso)),
            Primitive::Polygon(p) => Primitive::Polygon(p.transformed(iso)),
            Primitive::Polyhedron(p) => Primitive::Polyhedron(Composite::new(
                p.parts.iter().map(|f| f.transformed(iso)).collect(),
            )),
            Primitive::Plane(p) => Primitive::Plane(p.transformed(iso)),
            Primitive::Rod(r) => Primitive::Rod(Box::new(r.transformed(iso))),
            Primitive::Cylinder(c) => Primitive::Cylinder(Box::new(c.transformed(iso))),
            Primitive::Horosphere(h) => Primitive::Horosphere(h.transformed(iso)),
            Primitive::Wireframe(w) => Primitive::Wireframe(Composite::new(
                w.parts.iter().map(|r| r.transformed(iso)).collect(),
            )),
            Primitive::Mesh(m) => Primitive::Mesh(Box::new(m.transformed(iso))),
        }
    }

    fn moved(shape: &ir::Shape, iso: &Isometry) -> Primitive {
        match shape {
            ir::Shape::Sphere(s) => Primitive::Sphere(s.transformed(iso)),
            ir::Shape::Polygon(p) => Primitive::Polygon(p.transformed(iso)),
            ir::Shape::Polyhedron(p) => {
                Primitive::Polyhedron(Composite::new(p.transformed(iso).faces().to_vec()))
            }
            ir::Shape::Plane(p) => Primitive::Plane(p.transformed(iso)),
            ir::Shape::Rod(r) => Primitive::Rod(Box::new(r.transformed(iso))),
            ir::Shape::Cylinder(c) => Primitive::Cylinder(Box::new(c.transformed(iso))),
            ir::Shape::Horosphere(h) => Primitive::Horosphere(h.transformed(iso)),
            ir::Shape::Wireframe(rods) => Primitive::Wireframe(Composite::new(
                rods.iter().map(|r| r.transformed(iso)).collect(),
            )),
            ir::Shape::Mesh(m) => Primitive::Mesh(Box::new(m.transformed(iso))),
        }
    }

    /// True if every defining point is representable in f64 in this frame.
    fn is_representable(&self) -> bool {
        let vertex_ok = |v: &Vertex| match v {
            Vertex::Interior(p) => p.is_representable(),
            Vertex::Ideal(i) => i.coords().is_finite(),
        };
        let rod_ok = |r: &Rod| {
            vertex_ok(&r.start()) && vertex_ok(&r.end()) && r.tube().line().frame().is_finite()
        };
        // A plane whose normal is no longer unit in this frame (it came from
        // a bare normal far out, carried by a Lorentz matrix that lost
        // `eps e^{2d}`) would meet rays at the wrong place or not at all: a
        // silent loss. Planes placed by an isometry are unit here to rounding.
        let plane_ok = |n: DVec4| n.is_finite() && (lorentz::dot(n, n) - 1.0).abs() <= 1e-6;
        let polygon_ok =
            |p: &ConvexPolygon| p.vertices().iter().all(vertex_ok) && plane_ok(p.plane().normal());
        match self {
            Primitive::Sphere(s) => s.center().is_representable(),
            Primitive::Polygon(p) => polygon_ok(p),
            Primitive::Polyhedron(p) => p.parts().iter().all(polygon_ok),
            Primitive::Plane(p) => plane_ok(p.normal()),
            Primitive::Rod(r) => rod_ok(r),
            Primitive::Cylinder(c) => {
                c.line().base().is_representable() && c.line().frame().is_finite()
            }
            Primitive::Horosphere(h) => {
                let (c, r) = h.euclidean();
                c.is_finite() && r.is_finite()
            }
            Primitive::Wireframe(w) => w.parts().iter().all(rod_ok),
            // The placement's translation part is the mesh's centre; the
            // vertices are within the bounding radius of it.
            Primitive::Mesh(m) => {
                let (centre, radius) = m.bounding_ball();
                m.placement().translation_part().is_representable()
                    && centre.is_finite()
                    && radius.is_finite()
            }
        }
    }

    /// A ball containing the primitive, if it is bounded.
    fn bound(&self) -> Option<Bound> {
        match self {
            Primitive::Sphere(s) => Bound::new(s.center().to_hyperboloid(), s.radius()),
            Primitive::Polygon(p) => polygon_bound(p),
            Primitive::Polyhedron(p) => p.accel.bound(),
            Primitive::Rod(r) => rod_bound(r),
            Primitive::Wireframe(w) => w.accel.bound(),
            Primitive::Mesh(m) => {
                let (centre, radius) = m.bounding_ball();
                Bound::new(centre, radius)
            }
            Primitive::Plane(_) | Primitive::Cylinder(_) | Primitive::Horosphere(_) => None,
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
            Primitive::Wireframe(w) => w.intersect(ray, t_min, t_max),
            Primitive::Mesh(m) => m.intersect(ray, t_min, t_max),
        }
    }

    /// True if the primitive meets the ray anywhere in `(t_min, t_max)`; for
    /// composites, stops at the first part met.
    #[inline]
    pub fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match self {
            Primitive::Polyhedron(p) => p.blocks(ray, t_min, t_max),
            Primitive::Wireframe(w) => w.blocks(ray, t_min, t_max),
            Primitive::Mesh(m) => m.blocks(ray, t_min, t_max),
            _ => self.intersect(ray, t_min, t_max).is_some(),
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
    /// From the canonical frame to the object's local space, where its
    /// texture is fixed: `(to_canonical ∘ frame)^-1`.
    pub to_local: Isometry,
}

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
    /// that f64 cannot represent it in the eye's frame: that is reported,
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
            let primitive = Primitive::from_shape(&o.shape, stages);
            if !primitive.is_representable() {
                return Err(RenderError::OutOfRange {
                    what: format!("object {}", index + 1),
                });
            }
            objects.push(PreparedObject {
                primitive,
                material: o.material.index(),
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
    /// per object. The search ends at the first opaque blocker.
    pub fn transmittance(&self, ray: &Ray, t_min: f64, t_max: f64) -> f64 {
        let mut s = 1.0;
        self.accel.any(ray, t_min, t_max, |i| {
            let o = &self.objects[i as usize];
            if o.primitive.blocks(ray, t_min, t_max) {
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
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let prim = |plane: &HPlane| Primitive::Plane(*plane).transformed(&back);
        assert!(prim(&placed).is_representable());
        assert!(!prim(&bare).is_representable());
    }

    /// A long rod's pieces cover it: every hit lies in one of them.
    #[test]
    fn rod_pieces_cover_the_rod() {
        let rod = Rod::new(p(-0.6, 0.1, 0.4).into(), p(0.5, -0.1, 0.6).into(), 0.02).unwrap();
        let pieces = rod_pieces(&rod);
        assert_eq!(pieces.len(), 8);
        let mut hits = 0;
        for i in 0..4000 {
            let a = f64::from(i) * 0.618_033_988_749_895;
            let r = 0.95 * (f64::from(i) / 4000.0).sqrt();
            let ray = Ray::from_origin_unchecked(DVec3::new(r * a.sin(), r * a.cos(), 1.0));
            if let Some(hit) = rod.intersect(&ray, 0.0, f64::INFINITY) {
                hits += 1;
                assert!(
                    pieces
                        .iter()
                        .any(|b| -hgeom::lorentz::dot(hit.point, b.center())
                            <= b.radius().cosh() * (1.0 + 1e-12)),
                    "hit {i} outside every piece"
                );
            }
        }
        assert!(hits > 50, "{hits}");
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
        let prims = [
            Primitive::Rod(Box::new(rod.clone())),
            Primitive::Polygon(poly),
            Primitive::Polyhedron(Composite::new(dodeca.faces().to_vec())),
            Primitive::Wireframe(Composite::new(vec![rod])),
        ];
        for prim in &prims {
            let b = prim.bound().expect("bounded");
            for i in 0..2000 {
                let a = f64::from(i) * 0.618_033_988_749_895;
                let r = 0.9 * (f64::from(i) / 2000.0).sqrt();
                let ray = Ray::from_origin_unchecked(DVec3::new(r * a.sin(), r * a.cos(), 1.0));
                if let Some(hit) = prim.intersect(&ray, 0.0, f64::INFINITY) {
                    assert!(
                        -hgeom::lorentz::dot(hit.point, b.center()) <= b.radius().cosh() + 1e-12,
                        "{prim:?}"
                    );
                    assert!(b.entry(&ray, 1.0, f64::INFINITY).is_some());
                }
            }
        }
    }
}
