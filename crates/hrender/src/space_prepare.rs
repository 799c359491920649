//! A scene in a quotient space made ready for the domain walk: the eye,
//! every object and every light folded into the domain, each object
//! joined by its images that reach into the domain (so one that crosses a
//! face is whole on both sides), each light by its images within the
//! light reach, and the domain's edges added as a honeycomb of the
//! domain's cells. What is kept and why is in `docs/manifolds.md`.

use hgeom::{
    DEFAULT_HORIZON, GeomError, HoneycombStyle, Isometry, Point, QuotientSpace, RegularHoneycomb,
};
use hscene_ir::view::PixelFootprint;
use hscene_ir::{self as ir, Light, MAX_LIGHT_IMAGES, Object, PartMaterials, Scene, Space};

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
    let q = QuotientSpace::new(space.kind)
        .map_err(|e| invalid(format!("the space {}: {e}", space.kind)))?;
    let to_canonical = stages
        .iter()
        .fold(Isometry::IDENTITY, |acc, stage| stage.compose(&acc));
    let eye = to_canonical.inverse().apply(&Point::ORIGIN);
    let eye_home = q
        .fold(&eye)
        .map_err(|e| invalid(format!("the eye cannot be folded into the domain: {e}")))?;
    let mut staged = vec![eye_home.inverse()];
    staged.extend_from_slice(stages);

    let mut unfolded = scene.clone();
    unfolded.settings.sky = None;
    unfolded.objects.clear();
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
        }
    }
    if let Some(d) = space.domain {
        let style = HoneycombStyle {
            edges: Some(d.width),
            faces: false,
            vertices: None,
            depth: None,
            cell_classes: 1,
        };
        let surface = RegularHoneycomb::new(q.symbol(), style)
            .map_err(|e| invalid(format!("the domain's edges: {e}")))?;
        unfolded.objects.push(Object {
            shape: ir::Shape::Honeycomb(Box::new(ir::Honeycomb {
                surface,
                materials: PartMaterials {
                    faces: None,
                    palette: Vec::new(),
                    face_palette: Vec::new(),
                },
            })),
            material: d.material,
            name: None,
            placement: Isometry::IDENTITY,
        });
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
        for image in q.images_within(p, space.light_reach, MAX_LIGHT_IMAGES) {
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
    let horizon = footprint.map_or(DEFAULT_HORIZON, |f| {
        RegularHoneycomb::new(q.symbol(), HoneycombStyle::default())
            .map_or(DEFAULT_HORIZON, |h| h.horizon_for_pixel(f.smallest))
            .min(DEFAULT_HORIZON)
    });
    Ok(Unfolded {
        scene: unfolded,
        stages: staged,
        space: PreparedSpace {
            space: q.transformed(&to_canonical),
            horizon,
        },
    })
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
