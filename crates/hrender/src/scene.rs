//! The scene prepared for tracing: everything moved into the canonical frame
//! once, in f64, so near the eye every quantity is small and well conditioned;
//! and one hierarchy of Klein-model boxes over every bounded surface of every
//! object ([`crate::accel`]), so a ray pays the exact intersection only for
//! what it may actually meet.
//!
//! Its queries are geometric only: the nearest hit along a ray, and what a
//! geodesic segment passes through. How light is carried (which materials a
//! shadow ray passes, and how much) is each integrator's policy, passed in.

use hgeom::Shape as Surface;
use hgeom::glam::DVec4;
use hgeom::{Hit, IdealPoint, Isometry, KleinBox, Point, Ray};
use hscene_ir::view::PixelFootprint;
use hscene_ir::{self as ir, Fog, Material, PartMaterials, Rgb, Scene, Sky};

use rayon::prelude::*;
use smallvec::SmallVec;

use crate::accel::{Accel, Leaf, Step};
use crate::error::RenderError;
use crate::horizon_bucket::is_horizon;
use crate::image_texture::TextureMapping;
pub use crate::prepared_object::PreparedObject;

/// Rays that leave a surface ignore hits closer than this (hyperbolic
/// length), so that they do not meet the same surface at their own origin.
pub const T_MIN: f64 = 1e-9;

/// A segment through an object drawn in several materials stops counting
/// its crossings here: the light left is below 1/1000 (counted as none) or
/// the segment has crossed this many of its parts.
const MIN_TRANSMITTANCE: f64 = 1e-3;
const MAX_PART_CROSSINGS: u32 = 64;

/// How far past a part's crossing the next one is looked for: the hit was
/// on a wall the walk crosses there, and finding it again would count one
/// face twice. The offset of rays leaving a surface.
const PART_GAP: f64 = T_MIN;

/// One surface of one object: what a leaf of the hierarchy names.
#[derive(Clone, Copy, Debug)]
struct SurfaceRef {
    object: u32,
    surface: u32,
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
    /// `sinh²` of the light's `near` distance: a point light's fall-off
    /// `1/(4π sinh² r)` uses `max(sinh² r, near_sinh2)`.
    pub near_sinh2: f64,
    /// In a quotient space, the light reach: this image lights a point
    /// only within that distance of it, faded out over the last unit
    /// ([`PreparedLight::fade`]); infinite in H³.
    pub reach: f64,
    /// `cosh` of `reach`, which [`PreparedLight::out_of_reach`] compares
    /// with at every shading point.
    pub cosh_reach: f64,
}

impl PreparedLight {
    /// The `sinh² r` a point light's fall-off divides by, at `r` from it
    /// (given as `sinh² r`): never less than at its `near` distance.
    pub fn falloff_sinh2(&self, sinh2: f64) -> f64 {
        sinh2.max(self.near_sinh2)
    }

    /// True if `p` (a hyperboloid point) is beyond the light's reach:
    /// one Lorentz product, before any direction or shadow ray is formed.
    #[inline]
    pub fn out_of_reach(&self, p: DVec4) -> bool {
        -hgeom::lorentz::dot(p, self.position) > self.cosh_reach
    }

    /// The weight of this light at distance `d` from a point: 1 within
    /// `reach - 1` (or half the reach, if that is less than 1 away), 0
    /// beyond `reach`, and a smoothstep between. Lighting by the images of
    /// a light in a quotient space is then a continuous function of the
    /// point, the same on both sides of a face (`docs/manifolds.md`).
    #[inline]
    pub fn fade(&self, d: f64) -> f64 {
        if !self.reach.is_finite() {
            return 1.0;
        }
        let width = (0.5 * self.reach).min(1.0);
        let x = ((self.reach - d) / width).clamp(0.0, 1.0);
        x * x * (3.0 - 2.0 * x)
    }

    /// The radiance an area light's sphere emits, from both sides: a light
    /// of colour Φ has the power πΦ (as a point light of that colour
    /// would, `1/(4π sinh² r)` from it), spread over the sphere's area
    /// `4π sinh² a` as Lambertian emission of radiance `L`: power
    /// `π L 4π sinh² a`, so `L = Φ / (4π sinh² a)`. Black for a point
    /// light, which has no surface to see.
    pub fn radiance(&self) -> Rgb {
        if self.radius > 0.0 {
            self.diffuse * (1.0 / (4.0 * std::f64::consts::PI * self.radius.sinh().powi(2)))
        } else {
            Rgb::BLACK
        }
    }

    /// An area light's sphere (`None` for a point light).
    pub fn sphere(&self) -> Option<hgeom::HSphere> {
        if !(self.radius > 0.0) {
            return None;
        }
        Point::from_hyperboloid(self.position)
            .and_then(|c| hgeom::HSphere::new(c, self.radius).ok())
    }
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
    /// Every surface of every object, as the hierarchy's items name them.
    surfaces: Vec<SurfaceRef>,
    /// Hierarchy over the surfaces.
    accel: Accel,
    /// The objects whose material absorbs (`absorption.rs`), in order.
    absorbing: Vec<usize>,
    /// The sky, and the map from the canonical frame back to the scene's
    /// (the sky is fixed in the scene, not in the camera).
    sky: Option<(Sky, Isometry)>,
    /// The quotient space the scene is in, in the canonical frame
    /// (`space_walk.rs`); `None` in H³.
    pub(crate) space: Option<crate::space_domain::PreparedSpace>,
}

impl PreparedScene {
    /// The objects whose own material absorbs light inside them.
    pub fn absorbing(&self) -> &[usize] {
        &self.absorbing
    }

    /// Move everything by each of `stages` in turn (at least one), without
    /// the honeycombs' horizon materials (`prepare.rs` adds them).
    pub(crate) fn staged(
        scene: &Scene,
        stages: &[Isometry],
        footprint: Option<&PixelFootprint>,
    ) -> Result<PreparedScene, RenderError> {
        // Objects are moved on every thread; the first failing one, in
        // scene order, is the one reported.
        let prepared: Vec<Result<PreparedObject, RenderError>> = scene
            .objects
            .par_iter()
            .enumerate()
            .map(|(index, o)| {
                if o.material.index() >= scene.materials.len() {
                    return Err(RenderError::InvalidScene(format!(
                        "object {} uses material {}, but there are only {}",
                        index + 1,
                        o.material.index() + 1,
                        scene.materials.len()
                    )));
                }
                let parts = o.shape.part_materials().cloned();
                if let Some(bad) = parts
                    .iter()
                    .flat_map(PartMaterials::ids)
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
                let emits = !scene.materials[o.material.index()].emission.is_black();
                let (surfaces, ball, faces) =
                    PreparedObject::moved(&o.shape, stages, footprint, emits);
                if !surfaces.iter().all(|s| s.is_traceable()) {
                    return Err(RenderError::OutOfRange {
                        what: format!("object {}", index + 1),
                    });
                }
                let opaque = std::iter::once(o.material)
                    .chain(parts.iter().flat_map(PartMaterials::ids))
                    .all(|m| scene.materials[m.index()].transmission == 0.0);
                Ok(PreparedObject {
                    surfaces,
                    material: o.material.index(),
                    parts,
                    opaque,
                    to_local: stages
                        .iter()
                        .fold(o.placement, |f, iso| iso.compose(&f))
                        .inverse(),
                    ball,
                    faces_by_part: o.shape.mesh().is_some(),
                    faces,
                    horizon: Vec::new(),
                    mapping: if textured(scene, o) {
                        let to_local = stages
                            .iter()
                            .fold(o.placement, |f, iso| iso.compose(&f))
                            .inverse();
                        // Without a footprint (a picture of no two
                        // neighbouring rays) the finest level is used.
                        let angle = footprint.map_or(0.0, |f| f.smallest);
                        TextureMapping::of(&o.shape, &o.placement, &to_local, angle).map(Box::new)
                    } else {
                        None
                    },
                })
            })
            .collect();
        let objects = prepared.into_iter().collect::<Result<Vec<_>, _>>()?;
        for (index, m) in scene.materials.iter().enumerate() {
            let bad_scale = m
                .texture
                .as_ref()
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
            // A camera light is at the eye, the canonical frame's origin,
            // in every frame of an animation; the compiler asked the same.
            let p = ir::light_in_frame(l, stages).ok_or_else(out_of_range)?;
            let reach = scene
                .settings
                .space
                .as_ref()
                .map_or(f64::INFINITY, |s| s.light_reach);
            lights.push(PreparedLight {
                position: p.to_hyperboloid(),
                diffuse: l.diffuse,
                specular: l.specular,
                radius: l.radius,
                samples: l.samples,
                near_sinh2: l.near.sinh().powi(2),
                reach,
                cosh_reach: reach.cosh(),
            });
        }
        let (surfaces, accel) = hierarchy(&objects);
        // Solids absorb along their inside; an object drawn in several
        // materials (a honeycomb) is made of sheets with no inside, which
        // absorb per crossing (`absorption.rs`).
        let absorbing = objects
            .iter()
            .enumerate()
            .filter(|(_, o)| match &o.parts {
                None => !scene.materials[o.material].absorption.is_black(),
                Some(parts) => std::iter::once(o.material)
                    .chain(parts.ids().map(|m| m.index()))
                    .any(|m| !scene.materials[m].absorption.is_black()),
            })
            .map(|(k, _)| k)
            .collect();
        Ok(PreparedScene {
            objects,
            lights,
            materials: scene.materials.clone(),
            background: scene.settings.background,
            fog: scene.settings.fog,
            ambient: scene.settings.ambient,
            max_depth: scene.settings.recursion_depth,
            surfaces,
            accel,
            absorbing,
            sky: scene.settings.sky.clone().map(|sky| {
                let to_canonical = stages
                    .iter()
                    .fold(Isometry::IDENTITY, |acc, stage| stage.compose(&acc));
                (sky, to_canonical.inverse())
            }),
            space: None,
        })
    }

    /// What a ray that meets nothing brings from the sky: the radiance of
    /// the ideal point it runs to, in the scene's frame (`None` without a
    /// sky, or if the endpoint cannot be formed).
    pub fn sky_radiance(&self, ray: &Ray) -> Option<Rgb> {
        let (sky, to_world) = self.sky.as_ref()?;
        // X(t) = cosh t O + sinh t D runs to the null vector O + D.
        let end = IdealPoint::from_direction((ray.origin + ray.dir).truncate()).ok()?;
        Some(sky.radiance(to_world.apply_ideal(&end).coords()))
    }

    /// What a ray that leaves the scene brings, under either integrator:
    /// the fog colour in fog, else the sky's radiance where the ray ends,
    /// else the background.
    pub(crate) fn leaving(&self, ray: &Ray) -> Rgb {
        match &self.fog {
            Some(fog) => fog.color,
            None => self.sky_radiance(ray).unwrap_or(self.background),
        }
    }

    /// The nearest hit beyond `t_min` along the geodesic of `ray` in H³
    /// (in a quotient space, the nearest within the domain's tiles near
    /// the domain: [`PreparedScene::trace`] follows rays across faces).
    pub fn nearest(&self, ray: &Ray, t_min: f64) -> Nearest {
        self.nearest_within(ray, t_min, f64::INFINITY)
    }

    /// The nearest hit in `(t_min, t_max)`.
    pub(crate) fn nearest_within(&self, ray: &Ray, t_min: f64, t_max: f64) -> Nearest {
        // A NaN ray would miss every exact test and every bound: catch it
        // here, where it is still a failure and not yet a "miss".
        if !(ray.origin.is_finite() && ray.dir.is_finite()) {
            return Nearest::Failure;
        }
        let found = self.accel.nearest(ray, t_min, t_max, |i, lo, hi| {
            let r = self.surfaces[i as usize];
            self.objects[r.object as usize]
                .surfaces
                .get(r.surface as usize)
                .intersect(ray, lo, hi)
        });
        match found {
            None => Nearest::Miss,
            Some((hit, i)) if hit.point.is_finite() && hit.normal.is_finite() => {
                Nearest::Hit(hit, self.surfaces[i as usize].object as usize)
            }
            Some(_) => Nearest::Failure,
        }
    }

    /// The product of `pass(material)` over what the ray's arc
    /// `(t_min, t_max)` passes through: each object it meets once, by its
    /// material; an object drawn in several materials (a honeycomb) once per
    /// part crossed, since its parts are many separate sheets, unless every
    /// material it can be drawn in is opaque (`transmission == 0`), when one
    /// any-hit test settles it. The search ends once the product is 0 (a
    /// blocker: most segments). `tanh_t_max` is `tanh(t_max)`, which the
    /// hierarchy culls with. `pass` is the integrator's policy: Whitted's
    /// lets a shadow ray through glass by its transmission; `|_| 0.0` asks
    /// only whether the segment is clear.
    /// In a quotient space the segment is followed across the domain's
    /// faces (`space_domain.rs`).
    #[inline]
    pub fn transmittance<P: Fn(&Material) -> f64>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        tanh_t_max: f64,
        pass: P,
    ) -> f64 {
        if let Some(space) = &self.space {
            let mut s = 1.0;
            space.segments(ray, t_min, t_max, |piece, lo, hi| {
                s *= self.transmittance_in_domain(piece, lo, hi, hi.tanh(), &pass);
                s > 0.0
            });
            return s;
        }
        self.transmittance_in_domain(ray, t_min, t_max, tanh_t_max, pass)
    }

    /// [`PreparedScene::transmittance`] along one geodesic segment.
    #[inline]
    fn transmittance_in_domain<P: Fn(&Material) -> f64>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        tanh_t_max: f64,
        pass: P,
    ) -> f64 {
        let mut s = 1.0;
        // The objects already counted: only translucent ones get here, and
        // a segment meets few of them.
        let mut counted: SmallVec<[u32; 8]> = SmallVec::new();
        self.accel.any(ray, t_min, tanh_t_max, |i| {
            let r = self.surfaces[i as usize];
            // Most segments meet only opaque objects: nothing to look up.
            if !counted.is_empty() && counted.contains(&r.object) {
                return Step::Continue;
            }
            let o = &self.objects[r.object as usize];
            let surface = o.surfaces.get(r.surface as usize);
            if o.parts.is_some() && !o.opaque {
                // Each part crossed counts: translucent faces are many
                // separate sheets.
                s *= self.parts_transmittance(o, surface, ray, t_min, t_max, &pass);
            } else if surface.blocks(ray, t_min, t_max) {
                // PreparedScene::new checked every material index.
                s *= pass(&self.materials[o.material]);
            } else {
                return Step::Continue;
            }
            // Nothing changes the light left once it is none (an opaque
            // blocker: most shadow rays, which then never allocate) or once
            // every object is counted (a lone wireframe of thousands of
            // rods: its first rod crossed settles the ray).
            if s == 0.0 {
                return Step::Stop;
            }
            counted.push(r.object);
            if counted.len() == self.objects.len() {
                Step::Stop
            } else {
                Step::Continue
            }
        });
        s
    }

    /// The light an object drawn in several materials lets through along
    /// `(t_min, t_max)` of one of its surfaces: the product of the
    /// transmissions of the parts the ray crosses, found one after the
    /// other.
    fn parts_transmittance(
        &self,
        o: &PreparedObject,
        surface: &dyn Surface,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        pass: &impl Fn(&Material) -> f64,
    ) -> f64 {
        let mut s = 1.0;
        let mut from = t_min;
        for _ in 0..MAX_PART_CROSSINGS {
            // Past the horizon nothing is known: the light goes on.
            let Some(hit) = surface
                .intersect(ray, from, t_max)
                .filter(|h| !is_horizon(h.part))
            else {
                return s;
            };
            // PreparedScene::new checked every material index of the parts.
            s *= pass(&self.materials[o.material_of(&hit)]);
            if s < MIN_TRANSMITTANCE {
                return 0.0;
            }
            from = hit.t + PART_GAP;
        }
        s
    }
}

/// True if one of the materials object `o` is drawn in has an image.
fn textured(scene: &Scene, o: &ir::Object) -> bool {
    std::iter::once(o.material)
        .chain(o.shape.part_materials().into_iter().flat_map(|p| p.ids()))
        .any(|m| {
            scene
                .materials
                .get(m.index())
                .is_some_and(|m| m.image.is_some())
        })
}

/// The hierarchy over every surface of every object: one leaf per Klein
/// box of a surface; surfaces without one go to the unbounded list.
fn hierarchy(objects: &[PreparedObject]) -> (Vec<SurfaceRef>, Accel) {
    let surfaces: Vec<SurfaceRef> = objects
        .iter()
        .enumerate()
        .flat_map(|(o, object)| {
            (0..object.surfaces.len()).map(move |k| SurfaceRef {
                object: o as u32,
                surface: k as u32,
            })
        })
        .collect();
    let boxes: Vec<Vec<KleinBox>> = surfaces
        .par_iter()
        .map(|r| {
            fewest_boxes(
                objects[r.object as usize]
                    .surfaces
                    .get(r.surface as usize)
                    .klein_boxes(),
            )
        })
        .collect();
    let mut leaves = Vec::with_capacity(boxes.iter().map(Vec::len).sum());
    let mut unbounded = Vec::new();
    for (item, boxes) in boxes.into_iter().enumerate() {
        let item = item as u32;
        if boxes.is_empty() {
            unbounded.push(item);
        }
        leaves.extend(boxes.into_iter().map(|b| Leaf::new(b, item)));
    }
    (surfaces, Accel::new(leaves, unbounded))
}

/// A surface's boxes, or their union alone where that is no bigger in
/// total area: a ray meets a box about in proportion to its area, so pieces
/// only pay (in exact tests saved against leaves built and visited) when
/// they hug the surface better than one box does, as for a long rod
/// diagonal to the axes; one lying along an axis is as tight in one box.
fn fewest_boxes(boxes: Vec<KleinBox>) -> Vec<KleinBox> {
    let Some((first, rest)) = boxes.split_first() else {
        return boxes;
    };
    if rest.is_empty() {
        return boxes;
    }
    let union = rest.iter().fold(*first, |u, b| u.union(b));
    let pieces: f64 = boxes.iter().map(KleinBox::half_area).sum();
    if union.half_area() <= pieces {
        vec![union]
    } else {
        boxes
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;
    use hgeom::{ConvexPolygon, HPlane, Rod};

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    /// Whitted's policy for shadow rays: glass passes its transmission.
    fn by_transmission(m: &Material) -> f64 {
        m.transmission
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
        let traceable = |plane: &HPlane| {
            PreparedObject::surfaces_of(&ir::Shape::Plane(Box::new(*plane)), &[back], None)
                .iter()
                .all(|s| s.is_traceable())
        };
        assert!(traceable(&placed));
        assert!(!traceable(&bare));
    }

    /// A shadow ray through an opaque honeycomb only asks whether it meets
    /// it (the walk stops at the first part, with no hit to build), and the
    /// answer is the one counting its parts one by one gives: for rays
    /// from inside the base cell and from a cell away, that meet edges
    /// and that miss, to near and far ends. A honeycomb with glass faces
    /// still counts its crossings.
    #[test]
    fn opaque_honeycomb_shadows_agree_with_counting_parts() {
        let source = |faces: &str| {
            format!(
                "Globals {{ resolution = (8, 8); }}\n\
                 BRDFs {{ edge: ambient = (0.4, 0.3, 0.2), diffuse = (0.9, 0.75, 0.45); \
                 glass: ambient = (0.1, 0.2, 0.3), diffuse = (0.2, 0.4, 0.6), trans = 0.5; }}\n\
                 Lights {{ (0.1, 0, 0), (1, 1, 1), (1, 1, 1); }}\n\
                 Objects {{ Honeycomb {{4,3,5}}, #edge, edges = 0.05{faces}; }}"
            )
        };
        let prepare = |faces: &str| {
            let compiled = hscene_lang::compile(&source(faces));
            let scene = compiled.scene.expect("the test scene compiles");
            PreparedScene::new(&scene, &Isometry::IDENTITY).unwrap()
        };
        assert!(!prepare(", faces = #glass").objects[0].opaque);
        let prepared = prepare("");
        let o = &prepared.objects[0];
        assert!(o.opaque);
        let surface = o.surfaces.get(0);
        let (mut blocked, mut clear) = (0, 0);
        for k in 0..300 {
            // Directions on a golden spiral, starts near the centre and
            // a cell away.
            let z = 1.0 - 2.0 * (f64::from(k) + 0.5) / 300.0;
            let a = f64::from(k) * 2.399_963_229_728_653;
            let r = (1.0 - z * z).sqrt();
            let dir = DVec3::new(r * a.cos(), r * a.sin(), z);
            let start = if k % 2 == 0 {
                p(0.03, -0.02, 0.05)
            } else {
                p(0.55, 0.1, -0.05)
            };
            let ray = Ray::from_ball_unchecked(&start, dir);
            for t_max in [0.2, 1.0, 4.0] {
                let got = prepared.transmittance(&ray, 1e-9, t_max, t_max.tanh(), by_transmission);
                let want =
                    prepared.parts_transmittance(o, surface, &ray, 1e-9, t_max, &by_transmission);
                assert_eq!(got, want, "ray {k}, t_max {t_max}");
                if got == 0.0 {
                    blocked += 1;
                } else {
                    clear += 1;
                }
            }
        }
        assert!(
            blocked > 100 && clear > 100,
            "{blocked} blocked, {clear} clear"
        );
    }

    /// A shadow ray through translucent objects keeps each object's
    /// transmission once, however many of its parts it crosses, and the
    /// search that stops once every object is counted gives the product a
    /// search of every part gives: here a wireframe of rods strung along
    /// the ray, with and without a glass sphere beyond them.
    #[test]
    fn shadow_rays_count_each_translucent_object_once() {
        use hscene_test_support::scenes::{
            default_camera, flat, light, obj, scene, settings, sphere,
        };
        let along = |z: f64| p(0.0, 0.0, z);
        let rods: Vec<Rod> = (0..40)
            .map(|k| {
                let z = 0.05 + 0.015 * f64::from(k);
                Rod::new(p(-0.1, 0.0, z).into(), p(0.1, 0.0, z).into(), 0.004).unwrap()
            })
            .collect();
        let glass = |t: f64| ir::Material {
            transmission: t,
            ..flat(0.5, 0.5, 0.5)
        };
        let lamp = light(along(0.9), 1.0);
        let ray = Ray::from_ball_unchecked(&Point::ORIGIN, DVec3::Z);
        let t_max = Point::ORIGIN.distance(along(0.9));
        for with_sphere in [false, true] {
            let mut objects = vec![obj(ir::Shape::Wireframe(rods.clone().into()), 0)];
            if with_sphere {
                objects.push(obj(sphere(along(0.75), 0.05), 1));
            }
            let s = scene(
                settings(ir::Net::Euclidean, 4, 0.1),
                default_camera(0.1),
                vec![glass(0.5), glass(0.25)],
                vec![lamp.clone()],
                objects,
            );
            let prepared = PreparedScene::new(&s, &Isometry::IDENTITY).unwrap();
            // Every part of every object, each object once if any part
            // blocks: what the hierarchy's search must give.
            let want: f64 = prepared
                .objects
                .iter()
                .filter(|o| o.surfaces.iter().any(|x| x.blocks(&ray, 1e-9, t_max)))
                .map(|o| prepared.materials[o.material].transmission)
                .product();
            let got = prepared.transmittance(&ray, 1e-9, t_max, t_max.tanh(), by_transmission);
            assert_eq!(got, want);
            assert_eq!(got, if with_sphere { 0.125 } else { 0.5 });
        }
    }

    /// Every surface's boxes contain the hits of many rays (each hit lies
    /// in a box of the surface hit), and the chord of every ray that hits
    /// enters that box: the hierarchy never culls what the exact test finds.
    #[test]
    fn boxes_contain_every_hit() {
        let rod = Rod::new(p(-0.3, 0.1, 0.4).into(), p(0.2, -0.1, 0.6).into(), 0.05).unwrap();
        let poly = ConvexPolygon::new(vec![
            p(-0.2, -0.2, 0.5).into(),
            p(0.2, -0.2, 0.5).into(),
            p(0.0, 0.25, 0.55).into(),
        ])
        .unwrap();
        let ideal = ConvexPolygon::new(vec![
            p(-0.2, -0.2, 0.5).into(),
            p(0.2, -0.2, 0.5).into(),
            hgeom::IdealPoint::from_direction(DVec3::new(0.1, 0.3, 1.0))
                .unwrap()
                .into(),
        ])
        .unwrap();
        let dodeca = hgeom::Polyhedron::platonic(hgeom::Platonic::Dodecahedron, 0.4)
            .unwrap()
            .transformed(&Isometry::transvection_from_origin(p(0.0, 0.0, 0.5)));
        let shapes = [
            ir::Shape::Rod(Box::new(rod.clone())),
            ir::Shape::Polygon(Box::new(poly)),
            ir::Shape::Polygon(Box::new(ideal)),
            ir::Shape::Polyhedron(dodeca),
            ir::Shape::Wireframe(vec![rod].into()),
            ir::Shape::Sphere(hgeom::HSphere::new(p(0.1, 0.0, 0.6), 0.3).unwrap()),
        ];
        for shape in &shapes {
            let surfaces = PreparedObject::surfaces_of(shape, &[Isometry::IDENTITY], None);
            let mut hits = 0;
            for i in 0..2000 {
                let a = f64::from(i) * 0.618_033_988_749_895;
                let r = 0.9 * (f64::from(i) / 2000.0).sqrt();
                let ray = Ray::from_origin_unchecked(DVec3::new(r * a.sin(), r * a.cos(), 1.0));
                let chord = hgeom::KleinRay::new(&ray);
                let (lo, hi) = chord.arc(0.0, f64::INFINITY);
                for s in surfaces.iter() {
                    let boxes = s.klein_boxes();
                    assert!(!boxes.is_empty(), "{}", shape.kind_name());
                    if let Some(hit) = s.intersect(&ray, 0.0, f64::INFINITY) {
                        hits += 1;
                        assert!(
                            boxes
                                .iter()
                                .any(|b| b.contains(hit.point) && chord.entry(b, lo, hi).is_some()),
                            "{}",
                            shape.kind_name()
                        );
                    }
                }
            }
            assert!(hits > 50, "{}: {hits}", shape.kind_name());
        }
    }
}
