//! The geometry of a scene object, and the one place that knows each kind
//! of shape: every pass (moves, budgets, lints, the renderer, the IR's
//! JSON form) asks a [`Shape`] through these methods instead of matching on
//! its variants.
//!
//! Adding a kind of shape: its hgeom surface (implementing `hgeom::Shape`),
//! a variant here with a row in each `match` below, its object keyword in
//! the lowering's keyword table, and its JSON fields in the binary's IR
//! writer (`docs/ARCHITECTURE.md`, "Adding a primitive").

use std::sync::Arc;

use hgeom::glam::{DVec3, DVec4};

use crate::honeycomb::{Honeycomb, PartMaterials};
use crate::view::PixelFootprint;
use hgeom::{
    ConvexPolygon, HCylinder, HPlane, HSphere, Horosphere, Isometry, Point, Polyhedron, Rod,
    Shape as Surface, TriangleMesh, Vertex, lorentz, nearest_to_origin,
};

/// A surface the renderer can trace, of any kind.
pub type BoxedSurface = Box<dyn Surface + Send + Sync>;

/// What a shape is made of, for a renderer: one surface, or several parts
/// (a polyhedron's faces, a wireframe's rods), which a renderer may put
/// under a bounding hierarchy; the object is met where its nearest part
/// is. Parts are kept as they are, not boxed one by one: a wireframe of
/// tens of thousands of rods is shared with the IR, not copied.
// A tag byte of its own: without it the variant is read from a niche of
// the faces' `Vec` (several comparisons), once per exact test.
#[repr(u8)]
pub enum Surfaces {
    /// One surface.
    Single(BoxedSurface),
    /// A polyhedron's faces.
    Faces(Vec<ConvexPolygon>),
    /// A wireframe's rods.
    Rods(Arc<Vec<Rod>>),
}

impl Surfaces {
    /// The number of surfaces.
    pub fn len(&self) -> usize {
        match self {
            Surfaces::Single(_) => 1,
            Surfaces::Faces(f) => f.len(),
            Surfaces::Rods(r) => r.len(),
        }
    }

    /// True if there are none (a polyhedron without faces).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The `k`-th surface; panics unless `k < len()` for parts, like a
    /// slice (a single surface is surface 0, and any `k` gives it).
    #[inline]
    pub fn get(&self, k: usize) -> &(dyn Surface + Send + Sync) {
        match self {
            Surfaces::Single(s) => {
                debug_assert_eq!(k, 0, "a single surface is surface 0");
                s.as_ref()
            }
            Surfaces::Faces(f) => &f[k],
            Surfaces::Rods(r) => &r[k],
        }
    }

    /// The surfaces in order.
    pub fn iter(&self) -> impl Iterator<Item = &(dyn Surface + Send + Sync)> {
        (0..self.len()).map(|k| self.get(k))
    }
}

/// Mesh triangles per primitive of the scene-wide budget: a mesh of up to
/// 2,000,000 triangles fits in it.
pub const MESH_TRIANGLES_PER_PRIMITIVE: u64 = 4;

/// What `triangles` mesh triangles cost of the budget.
pub fn mesh_budget_cost(triangles: u64) -> u64 {
    triangles.div_ceil(MESH_TRIANGLES_PER_PRIMITIVE)
}

/// The geometry of a scene object.
///
/// The kinds larger than a sphere are boxed, so an object entry is about
/// 220 bytes instead of 700 (a rod's tube frame and caps are 568): a scene
/// of many objects is mostly spheres, and the IR is built once and read by
/// the renderer's own prepared surfaces, not traced (docs/performance.md,
/// "Memory of scenes of many objects").
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// An h-sphere.
    Sphere(HSphere),
    /// A convex planar h-polygon.
    Polygon(Box<ConvexPolygon>),
    /// A polyhedral surface (faces oriented outward).
    Polyhedron(Polyhedron),
    /// A whole h-plane (its normal side is the outside).
    Plane(Box<HPlane>),
    /// The points within a distance of an h-segment.
    Rod(Box<Rod>),
    /// The points at a distance from a whole h-line.
    Cylinder(Box<HCylinder>),
    /// A horosphere (the outside is away from its ideal centre).
    Horosphere(Horosphere),
    /// A wireframe: the edges of a polygon or polyhedron as rods (shared:
    /// a tessellation's are tens of megabytes, which the renderer traces in
    /// place when the camera needs no move).
    Wireframe(Arc<Vec<Rod>>),
    /// A triangle mesh (from an OBJ or PLY file).
    Mesh(Box<TriangleMesh>),
    /// A regular honeycomb, walked ray by ray (boxed: its walk tables are
    /// large, and a scene has few of them).
    Honeycomb(Box<Honeycomb>),
}

impl Shape {
    /// The kind's name in lower case, as messages, hovers and the IR's JSON
    /// form (`"kind"`) write it.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Shape::Sphere(_) => "sphere",
            Shape::Polygon(_) => "polygon",
            Shape::Polyhedron(_) => "polyhedron",
            Shape::Plane(_) => "plane",
            Shape::Rod(_) => "rod",
            Shape::Cylinder(_) => "cylinder",
            Shape::Horosphere(_) => "horosphere",
            Shape::Wireframe(_) => "wireframe",
            Shape::Mesh(_) => "mesh",
            Shape::Honeycomb(_) => "honeycomb",
        }
    }

    /// The materials of the parts of a shape drawn in several (a
    /// honeycomb's faces, edges and cells), if it is one; every other
    /// shape is drawn in its object's material.
    pub fn part_materials(&self) -> Option<&PartMaterials> {
        match self {
            Shape::Honeycomb(h) => Some(&h.materials),
            _ => None,
        }
    }

    /// The h-sphere, if the shape is one.
    pub fn sphere(&self) -> Option<&HSphere> {
        match self {
            Shape::Sphere(s) => Some(s),
            _ => None,
        }
    }

    /// The flat faces of a faceted shape (a polygon is its own face, a
    /// polyhedron has its faces); empty for every other shape.
    pub fn faces(&self) -> &[ConvexPolygon] {
        match self {
            Shape::Polygon(p) => std::slice::from_ref(p),
            Shape::Polyhedron(p) => p.faces(),
            _ => &[],
        }
    }

    /// The local frame the shape defines by itself, if any: a sphere's is
    /// the translation from the origin to its centre, so that a texture is
    /// centred on the sphere.
    pub fn natural_placement(&self) -> Option<Isometry> {
        self.sphere()
            .map(|s| Isometry::transvection_from_origin(s.center()))
    }

    /// The image of the shape under an isometry (unchecked: ask
    /// [`Shape::is_representable`] of the result).
    pub fn transformed(&self, iso: &Isometry) -> Shape {
        match self {
            Shape::Sphere(s) => Shape::Sphere(s.transformed(iso)),
            Shape::Polygon(p) => Shape::Polygon(Box::new(p.transformed(iso))),
            Shape::Polyhedron(p) => Shape::Polyhedron(p.transformed(iso)),
            Shape::Plane(p) => Shape::Plane(Box::new(p.transformed(iso))),
            Shape::Rod(r) => Shape::Rod(Box::new(r.transformed(iso))),
            Shape::Cylinder(c) => Shape::Cylinder(Box::new(c.transformed(iso))),
            Shape::Horosphere(h) => Shape::Horosphere(h.transformed(iso)),
            Shape::Mesh(m) => Shape::Mesh(Box::new(m.transformed(iso))),
            Shape::Wireframe(rods) => {
                Shape::Wireframe(Arc::new(rods.iter().map(|r| r.transformed(iso)).collect()))
            }
            Shape::Honeycomb(h) => Shape::Honeycomb(Box::new(Honeycomb {
                surface: h.surface.transformed(iso),
                materials: h.materials.clone(),
            })),
        }
    }

    /// The image of the shape under an isometry, or `None` if some part of
    /// it leaves what f64 can represent.
    pub fn moved(&self, iso: &Isometry) -> Option<Shape> {
        let moved = self.transformed(iso);
        moved.is_representable().then_some(moved)
    }

    /// True if every surface of the shape is representable in f64
    /// (`hgeom::Shape::is_representable`).
    pub fn is_representable(&self) -> bool {
        self.all(&|s| s.is_representable())
    }

    /// True if `test` holds for every surface of the shape.
    fn all(&self, test: &dyn Fn(&dyn Surface) -> bool) -> bool {
        match self {
            Shape::Sphere(s) => test(s),
            Shape::Polygon(p) => test(&**p),
            Shape::Polyhedron(p) => test(p),
            Shape::Plane(p) => test(&**p),
            Shape::Rod(r) => test(&**r),
            Shape::Cylinder(c) => test(&**c),
            Shape::Horosphere(h) => test(h),
            Shape::Wireframe(rods) => rods.iter().all(|r| test(r)),
            Shape::Mesh(m) => test(&**m),
            Shape::Honeycomb(h) => test(&h.surface),
        }
    }

    /// The number of primitives the renderer traces for it: faces, rods or
    /// triangles of a composite, 1 otherwise.
    pub fn primitive_count(&self) -> u64 {
        match self {
            Shape::Mesh(m) => m.triangle_count() as u64,
            other => other.budget_cost(),
        }
    }

    /// The shape as drawn in a picture whose pixels sample the directions
    /// at the eye, the origin of the frame it is in, as `footprint` says:
    /// a honeycomb is walked no farther than where its cells shrink below
    /// the smallest pixel (`RegularHoneycomb::horizon_for_pixel`), and on a
    /// flat image plane each ray from the eye no farther than where they
    /// shrink below its own pixel (`RegularHoneycomb::with_view_horizon`);
    /// beyond, the renderer draws the honeycomb's average appearance
    /// (docs/honeycombs.md). Every other
    /// shape is unchanged, and `None` says so (without a copy).
    pub fn for_footprint(&self, footprint: &PixelFootprint) -> Option<Shape> {
        let Shape::Honeycomb(h) = self else {
            return None;
        };
        let unchanged = footprint.plane.is_none()
            && h.surface.horizon_for_pixel(footprint.smallest) >= h.surface.horizon();
        if unchanged {
            return None;
        }
        let surface = h
            .surface
            .clone()
            .for_pixels(footprint.smallest, footprint.plane)
            .ok()?;
        let mut h = h.clone();
        h.surface = surface;
        Some(Shape::Honeycomb(h))
    }

    /// What it costs of the scene-wide primitive budget: its primitives,
    /// except that [`MESH_TRIANGLES_PER_PRIMITIVE`] mesh triangles make one
    /// (a mesh triangle takes about 100 bytes at the peak, a figure's rod
    /// or face several hundred).
    pub fn budget_cost(&self) -> u64 {
        let n = match self {
            Shape::Polyhedron(p) => p.faces().len(),
            Shape::Wireframe(rods) => rods.len(),
            Shape::Mesh(m) => mesh_budget_cost(m.triangle_count() as u64) as usize,
            Shape::Sphere(_)
            | Shape::Polygon(_)
            | Shape::Plane(_)
            | Shape::Rod(_)
            | Shape::Cylinder(_)
            | Shape::Horosphere(_)
            // One walk, whatever the number of cells: its cost per ray is
            // the cells the ray crosses, and its memory a few tables.
            | Shape::Honeycomb(_) => 1,
        };
        n as u64
    }

    /// The surfaces to trace: composites give their parts.
    pub fn into_surfaces(self) -> Surfaces {
        match self {
            Shape::Sphere(s) => Surfaces::Single(boxed(s)),
            Shape::Polygon(p) => Surfaces::Single(p),
            Shape::Polyhedron(p) => Surfaces::Faces(p.into_faces()),
            Shape::Plane(p) => Surfaces::Single(p),
            Shape::Rod(r) => Surfaces::Single(r),
            Shape::Cylinder(c) => Surfaces::Single(c),
            Shape::Horosphere(h) => Surfaces::Single(boxed(h)),
            Shape::Wireframe(rods) => Surfaces::Rods(rods),
            Shape::Mesh(m) => Surfaces::Single(m),
            Shape::Honeycomb(h) => Surfaces::Single(boxed(h.surface)),
        }
    }

    /// [`Shape::into_surfaces`] of a copy, without copying the whole shape
    /// first: a polyhedron gives a copy of its faces alone, a wireframe
    /// its shared rods.
    pub fn to_surfaces(&self) -> Surfaces {
        match self {
            Shape::Polyhedron(p) => Surfaces::Faces(p.faces().to_vec()),
            _ => self.clone().into_surfaces(),
        }
    }

    /// True if the point is strictly inside the shape, decided in the
    /// point's own frame: `to_origin` takes the point to the origin (where
    /// every product is small, so far scenes get exact answers; the sphere
    /// needs no move, its ball distance being good anywhere). Only closed
    /// shapes have an inside: polygons, planes and meshes (whose closedness
    /// is not checked) never contain a point.
    pub fn encloses(&self, point: &Point, to_origin: &Isometry) -> bool {
        let here = DVec4::W;
        match self {
            Shape::Sphere(s) => point.distance(s.center()) < s.radius(),
            // A honeycomb fills space: the eye is always in some cell, which
            // is where it is meant to be; its rods and balls are too thin
            // to matter for the lint.
            Shape::Polygon(_) | Shape::Plane(_) | Shape::Mesh(_) | Shape::Honeycomb(_) => false,
            Shape::Polyhedron(p) => {
                // Behind every face plane means inside only for a closed
                // surface (the golden rectangles are not one): there every
                // edge belongs to exactly two faces. For star polyhedra this
                // finds the core.
                let sides: usize = p.faces().iter().map(|f| f.vertices().len()).sum();
                let closed = !p.faces().is_empty() && sides == 2 * p.edges().len();
                closed
                    && p.faces().iter().all(|f| {
                        lorentz::dot(here, f.plane().transformed(to_origin).normal()) < 0.0
                    })
            }
            Shape::Rod(r) => rod_encloses_origin(r, r.radius().tanh(), to_origin),
            Shape::Cylinder(c) => c.transformed(to_origin).contains_hyperboloid(here),
            Shape::Horosphere(h) => h.transformed(to_origin).contains_hyperboloid(here),
            Shape::Wireframe(rods) => {
                // A wireframe's rods share one radius: one `tanh` for all
                // of them, not one per rod and frame.
                let mut reach = (f64::NAN, f64::NAN);
                rods.iter().any(|r| {
                    if r.radius() != reach.0 {
                        reach = (r.radius(), r.radius().tanh());
                    }
                    rod_encloses_origin(r, reach.1, to_origin)
                })
            }
        }
    }

    /// True if the shape lies entirely on the far side of the plane through
    /// a point orthogonal to `view` (a unit ball direction there), decided
    /// in that point's frame (`to_origin` takes it to the origin): there the
    /// plane is the flat one `x . view = 0`, and a point's side is the sign
    /// of `x . view`, its signed distance `asinh(2 x.view / g)`.
    pub fn lies_behind(&self, to_origin: &Isometry, view: DVec3) -> bool {
        let sinh_ahead = |p: &Point| {
            let q = to_origin.apply(p);
            2.0 * q.coords().dot(view) / q.gap()
        };
        let vertex_behind = |v: &Vertex| to_origin.apply_vertex(v).coords().dot(view) < 0.0;
        // A rod is behind the plane when both ends are, by more than its
        // radius (the rod lies within its radius of the segment, which is
        // behind if its ends are: half-spaces are convex). An ideal end: the
        // rod's tube reaches the absolute there.
        let rod_behind = |rod: &Rod| {
            let end_behind = |v: Vertex| match v {
                Vertex::Interior(p) => sinh_ahead(&p) < -rod.radius().sinh(),
                Vertex::Ideal(_) => false,
            };
            end_behind(rod.start()) && end_behind(rod.end())
        };
        match self {
            Shape::Sphere(s) => sinh_ahead(&s.center()) < -s.radius().sinh(),
            Shape::Polygon(p) => p.vertices().iter().all(vertex_behind),
            Shape::Polyhedron(p) => p
                .faces()
                .iter()
                .all(|f| f.vertices().iter().all(vertex_behind)),
            // Unbounded surfaces always reach in front of the plane.
            Shape::Plane(_) | Shape::Cylinder(_) | Shape::Horosphere(_) | Shape::Honeycomb(_) => {
                false
            }
            Shape::Rod(r) => rod_behind(r),
            Shape::Wireframe(rods) => rods.iter().all(rod_behind),
            Shape::Mesh(m) => m.vertices().iter().all(|p| sinh_ahead(p) < 0.0),
        }
    }
}

fn boxed<S: Surface + Send + Sync + 'static>(s: S) -> BoxedSurface {
    Box::new(s)
}

/// True if `rod`, moved by `to_origin`, contains the origin; `tanh_r` is
/// the hyperbolic tangent of its radius.
///
/// A rod is the set of points within its radius `r` of its segment, and
/// the distance from the origin to a point of Klein radius `k` is
/// `artanh k`, which grows with `k`: the rod contains the origin exactly
/// when the segment's Klein point nearest the origin (in the Euclidean
/// sense, the segment being straight there) has `k < tanh r`. Only the two
/// ends are moved for that, which is far cheaper than moving the rod (a
/// wireframe honeycomb has tens of thousands, asked once per light); where
/// the nearest point is within `CLEAR` of the threshold the moved rod's
/// own exact test decides, so rounding of the ends cannot change the
/// answer.
fn rod_encloses_origin(rod: &Rod, tanh_r: f64, to_origin: &Isometry) -> bool {
    /// Klein-radius margin past which the segment is certainly out of
    /// reach: far above the rounding of ends moved by a transvection.
    const CLEAR: f64 = 1e-6;
    let klein = |v: Vertex| {
        let h = to_origin.apply_vertex(&v).to_hyperboloid();
        h.truncate() / h.w
    };
    let nearest = nearest_to_origin(klein(rod.start()), klein(rod.end()));
    // A NaN from an end f64 cannot move falls through to the exact test.
    if nearest > tanh_r + CLEAR {
        return false;
    }
    rod.transformed(to_origin).contains_hyperboloid(DVec4::W)
}

impl Shape {
    /// The triangle mesh, if the shape is one.
    pub fn mesh(&self) -> Option<&TriangleMesh> {
        match self {
            Shape::Mesh(m) => Some(m),
            _ => None,
        }
    }

    /// The honeycomb, if the shape is one.
    pub fn honeycomb(&self) -> Option<&Honeycomb> {
        match self {
            Shape::Honeycomb(h) => Some(h),
            _ => None,
        }
    }

    /// For a honeycomb, the same honeycomb with `change` made to its walk
    /// (horizon hits, rank classes); `None` for any other shape.
    pub fn with_walk(
        &self,
        change: impl FnOnce(hgeom::RegularHoneycomb) -> hgeom::RegularHoneycomb,
    ) -> Option<Shape> {
        let h = self.honeycomb()?;
        Some(Shape::Honeycomb(Box::new(Honeycomb {
            surface: change(h.surface.clone()),
            materials: h.materials.clone(),
        })))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::IdealPoint;
    use proptest::prelude::*;

    fn unit(v: [f64; 3]) -> DVec3 {
        let d = DVec3::from_array(v);
        if d.length() < 1e-3 {
            DVec3::Z
        } else {
            d.normalize()
        }
    }

    /// A wireframe's surfaces are its rods, shared and not copied, in
    /// order; a polyhedron's are its faces; every other shape is one.
    #[test]
    fn surfaces_are_the_parts_in_order_and_a_wireframe_shares_its_rods() {
        let p = |x: f64, y: f64| Vertex::from(Point::from_coords(DVec3::new(x, y, 0.1)).unwrap());
        let rods = Arc::new(vec![
            Rod::new(p(0.0, 0.0), p(0.3, 0.0), 0.02).unwrap(),
            Rod::new(p(0.3, 0.0), p(0.3, 0.4), 0.05).unwrap(),
        ]);
        let wire = Shape::Wireframe(rods.clone());
        let surfaces = wire.to_surfaces();
        let Surfaces::Rods(shared) = &surfaces else {
            panic!("a wireframe gives its rods");
        };
        assert!(Arc::ptr_eq(shared, &rods));
        assert_eq!(surfaces.len(), 2);
        let ray = hgeom::Ray::from_ball_unchecked(&Point::ORIGIN, DVec3::new(0.3, 0.2, 0.1));
        for (k, s) in surfaces.iter().enumerate() {
            assert_eq!(
                s.intersect(&ray, 0.0, 9.0),
                rods[k].intersect(&ray, 0.0, 9.0)
            );
            assert_eq!(s.klein_boxes(), rods[k].klein_boxes());
        }
        let cube = hgeom::cube_435().unwrap();
        let faces = Shape::Polyhedron(cube.clone()).to_surfaces();
        assert!(matches!(faces, Surfaces::Faces(_)));
        assert_eq!(faces.len(), cube.faces().len());
        assert_eq!(faces.get(3).klein_boxes(), cube.faces()[3].klein_boxes());
        let ball = Shape::Sphere(HSphere::new(Point::ORIGIN, 0.5).unwrap()).into_surfaces();
        assert_eq!((ball.len(), ball.is_empty()), (1, false));
    }

    proptest! {
        /// The end-point shortcut of the inside lint answers as the moved
        /// rod's exact test does: for rods near and far from the origin,
        /// with ideal ends, and for points on either side of the surface.
        #[test]
        fn rod_shortcut_agrees_with_the_moved_rod(
            a in prop::array::uniform3(-1.0..1.0f64),
            b in prop::array::uniform3(-1.0..1.0f64),
            da in 0.0..2.5f64,
            db in 0.0..2.5f64,
            ideal_end in 0..4u8,
            radius in 0.01..1.0f64,
            along in -0.2..1.2f64,
            off in prop::array::uniform3(-1.0..1.0f64),
            reach in 0.5..1.5f64,
            far in prop::array::uniform3(-1.0..1.0f64),
            far_d in 0.0..15.0f64,
        ) {
            let start: Vertex = Point::at_distance_from_origin(unit(a), da).unwrap().into();
            let end: Vertex = if ideal_end == 0 {
                IdealPoint::from_direction(unit(b)).unwrap().into()
            } else {
                Point::at_distance_from_origin(unit(b), db + 0.05).unwrap().into()
            };
            prop_assume!(start != end);
            let Ok(rod) = Rod::new(start, end, radius) else { return Ok(()) };
            // A point about `reach` radii from the segment's Klein point at
            // `along`: inside, on and outside the rod (kept off an ideal end,
            // where no f64 point is).
            let (ka, kb) = (start.to_hyperboloid(), end.to_hyperboloid());
            let on = (ka.truncate() / ka.w).lerp(kb.truncate() / kb.w, along.clamp(0.0, 0.98));
            let centre = Point::from_coords(on / (1.0 + (1.0 - on.length_squared()).max(0.0).sqrt()))
                .unwrap_or(Point::ORIGIN);
            let to_centre = Isometry::transvection_from_origin(centre);
            let point = to_centre.apply(&Point::at_distance_from_origin(unit(off), reach * radius).unwrap());
            // The whole scene moved away from the origin.
            let away = Isometry::transvection_from_origin(
                Point::at_distance_from_origin(unit(far), far_d).unwrap(),
            );
            let (rod, point) = (rod.transformed(&away), away.apply(&point));
            let to_origin = Isometry::transvection_from_origin(point).inverse();
            prop_assert_eq!(
                rod_encloses_origin(&rod, rod.radius().tanh(), &to_origin),
                rod.transformed(&to_origin).contains_hyperboloid(DVec4::W)
            );
        }
    }
}
