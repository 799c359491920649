//! A scene in a quotient space made ready for the domain walk: the eye,
//! every object and every light folded into the domain, each object
//! joined by its images that reach into the domain (so one that crosses a
//! face is whole on both sides), each light by its images within the
//! light reach, and the domain's edges added as a honeycomb of the
//! domain's cells. What is kept and why is in `docs/manifolds.md`.

use hgeom::glam::DVec3;
use hgeom::{
    DEFAULT_HORIZON, GeomError, HCylinder, HLine, HoneycombStyle, IdealPoint, Isometry, Point,
    QuotientSpace, RegularHoneycomb, Rod, Vertex,
};
use hscene_ir::view::PixelFootprint;
use hscene_ir::{
    self as ir, DomainEdges, Light, MAX_LIGHT_IMAGES, MAX_SPACE_LIGHTS, Object, PartMaterials,
    Scene, Space,
};

use crate::error::RenderError;
use crate::space_domain::PreparedSpace;

/// The scene unfolded about the domain, the stages that take it to the
/// canonical frame (the eye folded into the domain first), and the space
/// in that frame.
pub(crate) struct Unfolded {
    pub scene: Scene,
    pub stages: Vec<Isometry>,
    pub space: PreparedSpace,
}

/// `scene` (in `space`) unfolded for a camera moved by `stages`, drawn for
/// `footprint` if given.
pub(crate) fn unfold(
    scene: &Scene,
    space: &Space,
    stages: &[Isometry],
    footprint: Option<&PixelFootprint>,
) -> Result<Unfolded, RenderError> {
    let invalid = |what: String| RenderError::InvalidScene(what);
    let q = space
        .build()
        .map_err(|e| invalid(format!("the space {}: {e}", space.kind)))?;
    let to_canonical = stages
        .iter()
        .fold(Isometry::IDENTITY, |acc, stage| stage.compose(&acc));
    let eye = to_canonical.inverse().apply(&Point::ORIGIN);
    let eye_home = q
        .fold(&eye)
        .map_err(|e| invalid(format!("the eye cannot be folded into the domain: {e}")))?;
    let staged = match folded_stages(stages, &eye_home) {
        Some(folded) => folded,
        None => {
            let mut staged = vec![eye_home.inverse()];
            staged.extend_from_slice(stages);
            staged
        }
    };

    let mut unfolded = scene.clone();
    unfolded.settings.sky = None;
    unfolded.objects.clear();
    let mut numbers = Vec::new();
    for (index, o) in scene.objects.iter().enumerate() {
        let what = || format!("object {}", index + 1);
        for copy in object_images(&q, o).map_err(|e| match e {
            Failure::Unbounded => invalid(format!(
                "{} is unbounded: in a space only bounded objects can be placed",
                what()
            )),
            Failure::Geometry(e) => invalid(format!("{}: {e}", what())),
            Failure::OutOfRange => RenderError::OutOfRange { what: what() },
        })? {
            unfolded.objects.push(copy);
            numbers.push(index + 1);
        }
    }
    if let Some(d) = space.domain {
        let rods = domain_edges(&q, d)?;
        numbers.extend(std::iter::repeat_n(scene.objects.len() + 1, rods.len()));
        unfolded.objects.extend(rods);
    }
    if scene.lights.len() > MAX_SPACE_LIGHTS {
        return Err(invalid(format!(
            "{} lights in a space: at most {MAX_SPACE_LIGHTS} (each shines through its images)",
            scene.lights.len()
        )));
    }
    unfolded.lights.clear();
    for (index, l) in scene.lights.iter().enumerate() {
        if l.radius > 0.0 {
            return Err(invalid(format!(
                "light {} has a radius: area lights are not drawn in a space (a glowing \
                 sphere is)",
                index + 1
            )));
        }
        let at = if l.on_camera { eye } else { l.position };
        let home = q
            .fold(&at)
            .map_err(|e| invalid(format!("light {}: {e}", index + 1)))?;
        let p = home.apply(&at).to_hyperboloid();
        // Every image that can light a point of the domain: within the
        // reach of the domain's farthest finite point from its centre.
        let within = space.light_reach + q.radius();
        for image in q.images_within(p, within, MAX_LIGHT_IMAGES) {
            let Some(position) = Point::from_hyperboloid(image) else {
                continue;
            };
            unfolded.lights.push(Light {
                position,
                on_camera: false,
                ..l.clone()
            });
        }
    }
    let to_canonical = staged
        .iter()
        .fold(Isometry::IDENTITY, |acc, stage| stage.compose(&acc));
    // A domain from its pairings has no honeycomb: it is walked to the
    // default horizon (or its crossings run out first).
    let horizon = match (footprint, q.symbol()) {
        (Some(f), Some(symbol)) => RegularHoneycomb::new(symbol, HoneycombStyle::default())
            .map_or(DEFAULT_HORIZON, |h| h.horizon_for_pixel(f.smallest))
            .min(DEFAULT_HORIZON),
        _ => DEFAULT_HORIZON,
    };
    Ok(Unfolded {
        scene: unfolded,
        stages: staged,
        space: PreparedSpace {
            space: q.transformed(&to_canonical),
            horizon,
            numbers,
            fill: Vec::new(),
        },
    })
}

/// The canonical frame of the camera carried home by `home` (the fold of
/// its eye into the domain), when `home` keeps orientation: the camera's
/// eye, a point ahead and a point above, carried back from the canonical
/// frame and home, make a camera near the domain whose frame is built
/// afresh. Composing `stages` with `home`'s inverse instead multiplies two
/// isometries that each move by the eye's distance (20 after flying 20
/// through a closed space): their product is near the identity, but every
/// image of an object or light passes through points as far again on the
/// way, past what f64 holds. `None` (compose them as they are) for the
/// identity, a fold that reflects (a mirror cell: a camera rebuilt from
/// points would see the picture mirrored) or a point that cannot be made.
fn folded_stages(stages: &[Isometry], home: &Isometry) -> Option<Vec<Isometry>> {
    if *home == Isometry::IDENTITY || !home.preserves_orientation() {
        return None;
    }
    let back = stages
        .iter()
        .fold(Isometry::IDENTITY, |acc, stage| stage.compose(&acc))
        .inverse();
    let carry = |p: Point| home.checked_apply(&back.checked_apply(&p).ok()?).ok();
    let camera = ir::Camera {
        eye: carry(Point::ORIGIN)?,
        target: carry(Point::at_distance_from_origin(DVec3::Z, 1.0).ok()?)?,
        up: Some(carry(Point::at_distance_from_origin(DVec3::Y, 1.0).ok()?)?),
    };
    Some(ir::view::canonical_frame(&camera)?.stages.to_vec())
}

/// Why an object has no images.
enum Failure {
    Unbounded,
    OutOfRange,
    Geometry(GeomError),
}

/// The object folded into the domain, and its images that may meet the
/// domain (the folded object first).
fn object_images(q: &QuotientSpace, o: &Object) -> Result<Vec<Object>, Failure> {
    let surfaces = o.shape.to_surfaces();
    let balls: Vec<_> = surfaces.iter().map(|s| s.bound()).collect();
    let balls: Vec<_> = balls
        .into_iter()
        .collect::<Option<_>>()
        .ok_or(Failure::Unbounded)?;
    let Some(first) = balls.first() else {
        return Err(Failure::Unbounded);
    };
    let centre = first.center();
    let radius = balls.iter().fold(0.0f64, |r, b| {
        r.max(hgeom::lorentz::distance(centre, b.center()) + b.radius())
    });
    let centre_point = Point::from_hyperboloid(centre).ok_or(Failure::OutOfRange)?;
    let home = q.fold(&centre_point).map_err(Failure::Geometry)?;
    let folded = ir::move_object(o, &home).ok_or(Failure::OutOfRange)?;
    let centre = home.apply(&centre_point).to_hyperboloid();
    let images = q
        .copies_meeting(centre, radius)
        .map_err(Failure::Geometry)?;
    images
        .iter()
        .map(|b| {
            if *b == Isometry::IDENTITY {
                Ok(folded.clone())
            } else {
                ir::move_object(&folded, b).ok_or(Failure::OutOfRange)
            }
        })
        .collect()
}

/// The domain's edges as rods of `d`'s radius: the honeycomb of the
/// domain's cells (exactly what `Honeycomb {p,q,r}, edges = w` draws), or
/// for a domain from its pairings, a rod on each finite edge and the tube
/// about the line of each edge that runs into a cusp (the walk tests it
/// only inside the domain, where it is that edge's rod); the other tiles'
/// edges through a vertex that are not the domain's own are not drawn, a
/// difference within the rods' radius of the vertex.
fn domain_edges(q: &QuotientSpace, d: DomainEdges) -> Result<Vec<Object>, RenderError> {
    let invalid = |e: GeomError| RenderError::InvalidScene(format!("the domain's edges: {e}"));
    let object = |shape: ir::Shape| Object {
        shape,
        material: d.material,
        name: None,
        placement: Isometry::IDENTITY,
    };
    if let Some(symbol) = q.symbol() {
        let style = HoneycombStyle {
            edges: Some(d.width),
            faces: false,
            vertices: None,
            depth: None,
            cell_classes: 1,
        };
        let surface = RegularHoneycomb::new(symbol, style).map_err(invalid)?;
        return Ok(vec![object(ir::Shape::Honeycomb(Box::new(
            ir::Honeycomb {
                surface,
                materials: PartMaterials {
                    faces: None,
                    palette: Vec::new(),
                    face_palette: Vec::new(),
                },
            },
        )))]);
    }
    let Some(domain) = q.domain() else {
        return Ok(Vec::new());
    };
    let vertex = |k: usize| -> Result<Vertex, GeomError> {
        let v = domain.vertices()[k];
        if domain.ideal()[k] {
            Ok(Vertex::Ideal(IdealPoint::from_direction(v.truncate())?))
        } else {
            Point::from_hyperboloid(v)
                .map(Vertex::Interior)
                .ok_or(GeomError::NotFinite)
        }
    };
    domain
        .edges()
        .iter()
        .map(|e| {
            let (a, b) = (vertex(e.vertices[0])?, vertex(e.vertices[1])?);
            // A finite edge is a rod (bounded, so the hierarchy culls it);
            // one that runs into a cusp the tube about its whole line.
            if matches!((a, b), (Vertex::Interior(_), Vertex::Interior(_))) {
                return Ok(object(ir::Shape::Rod(Box::new(Rod::new(a, b, d.width)?))));
            }
            let line = HLine::through(&a, &b)?;
            Ok(object(ir::Shape::Cylinder(Box::new(HCylinder::new(
                line, d.width,
            )?))))
        })
        .collect::<Result<Vec<_>, GeomError>>()
        .map_err(invalid)
}
