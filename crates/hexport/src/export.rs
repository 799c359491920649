//! A scene as printed parts: every object's shape through the cut rule,
//! meshed in parallel, in scene order.

use std::sync::atomic::{AtomicUsize, Ordering};

use hgeom::glam::DVec4;
use hscene_ir::{Object, Scene, Shape};
use rayon::prelude::*;

use crate::error::ExportError;
use crate::grid::{PoleSurface, mesh_surface};
use crate::honeycomb::{self, segment_axis};
use crate::model::{ExportMaterial, Model, Owner, Shell};
use crate::options::ExportOptions;
use crate::rules::{PartSurface, euclidean_ball, plane_plate, polygon_plate, tube};
use crate::tube::Axis;

/// One part to mesh: its surface, its object's label and its scene
/// material.
enum Job {
    Surface(PartSurface),
    /// A triangle mesh's vertices (hyperboloid) and triangles.
    Mesh(Vec<DVec4>, Vec<[u32; 3]>),
}

struct Piece {
    job: Job,
    object: usize,
    material: usize,
}

/// How an object is named in messages: `object 3` or `object 3 ("name")`.
pub fn object_label(index: usize, object: &Object) -> String {
    match &object.name {
        Some(name) => format!("object {} (\"{name}\")", index + 1),
        None => format!("object {}", index + 1),
    }
}

/// How a slicer names an object: its name, else its kind and number
/// (`Sphere 3`), so that the parts list reads like the scene.
pub fn object_name(index: usize, object: &Object) -> String {
    match &object.name {
        Some(name) => name.clone(),
        None => {
            let kind = object.shape.kind_name();
            let mut letters = kind.chars();
            let first = letters.next().map(|c| c.to_ascii_uppercase());
            format!(
                "{}{} {}",
                first.into_iter().collect::<String>(),
                letters.as_str(),
                index + 1
            )
        }
    }
}

/// The printed parts of one object, and how many were cut.
fn object_parts(
    index: usize,
    object: &Object,
    options: &ExportOptions,
    out: &mut Vec<Piece>,
) -> Result<usize, ExportError> {
    let own = object.material.index();
    let mut cut = 0;
    let mut keep = |surface: Option<PartSurface>, material: usize| match surface {
        Some(s) => out.push(Piece {
            job: Job::Surface(s),
            object: index,
            material,
        }),
        None => cut += 1,
    };
    match &object.shape {
        Shape::Sphere(s) => {
            let (centre, radius) = s.euclidean();
            keep(euclidean_ball(centre, radius, options), own);
        }
        Shape::Horosphere(h) => {
            let (centre, radius) = h.euclidean();
            keep(euclidean_ball(centre, radius, options), own);
        }
        Shape::Polygon(_) | Shape::Polyhedron(_) => {
            for face in object.shape.faces() {
                let corners: Vec<DVec4> =
                    face.vertices().iter().map(|v| v.to_hyperboloid()).collect();
                keep(polygon_plate(&corners, face.plane().normal(), options), own);
            }
        }
        Shape::Plane(p) => keep(plane_plate(p.normal(), options), own),
        Shape::Rod(r) => {
            let axis = segment_axis(&r.start(), &r.end());
            keep(axis.and_then(|a| tube(a, r.radius(), options)), own);
        }
        Shape::Wireframe(rods) => {
            for r in rods.iter() {
                let axis = segment_axis(&r.start(), &r.end());
                keep(axis.and_then(|a| tube(a, r.radius(), options)), own);
            }
        }
        Shape::Cylinder(c) => {
            let axis = Axis::of_line(&c.line(), f64::NEG_INFINITY, f64::INFINITY);
            keep(tube(axis, c.radius(), options), own);
        }
        Shape::Mesh(m) => {
            let vertices = m.vertices().iter().map(|p| p.to_hyperboloid()).collect();
            out.push(Piece {
                job: Job::Mesh(vertices, m.triangles().into_owned()),
                object: index,
                material: own,
            });
        }
        Shape::Honeycomb(h) => {
            let (parts, thin) = honeycomb::parts(&h.surface, options).map_err(|e| match e {
                ExportError::Geometry { source, .. } => ExportError::Geometry {
                    object: object_label(index, object),
                    source,
                },
                other => other,
            })?;
            cut += thin;
            for p in parts {
                out.push(Piece {
                    job: Job::Surface(p.surface),
                    object: index,
                    material: h.materials.material(p.part, own),
                });
            }
        }
    }
    Ok(cut)
}

/// The scene's objects as closed shells in millimetres, the ball's centre
/// at the origin (`docs/export.md`). `progress(done, total)` is called as
/// parts are meshed.
///
/// Errors: [`ExportError::BadOptions`]; [`ExportError::TooManyTriangles`]
/// naming the object that went over the budget;
/// [`ExportError::NothingToPrint`] when every part was cut;
/// [`ExportError::InSpace`] for a scene in a quotient space;
/// [`ExportError::Geometry`] when a honeycomb's search runs past its
/// budget.
pub fn export_scene(
    scene: &Scene,
    options: &ExportOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Model, ExportError> {
    options.validate()?;
    if let Some(space) = &scene.settings.space {
        return Err(ExportError::InSpace {
            space: space.kind.to_string(),
        });
    }
    let mut pieces = Vec::new();
    let mut parts_cut = 0;
    for (index, object) in scene.objects.iter().enumerate() {
        parts_cut += object_parts(index, object, options, &mut pieces)?;
    }
    if pieces.is_empty() {
        return Err(ExportError::NothingToPrint {
            min_feature: options.min_feature.get(),
            size: options.size.get(),
        });
    }
    let owners: Vec<Owner> = scene
        .objects
        .iter()
        .enumerate()
        .map(|(index, o)| Owner {
            index,
            label: object_label(index, o),
            name: object_name(index, o),
        })
        .collect();
    let (tolerance, scale) = (options.tolerance_ball(), options.scale());
    let used = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let total = pieces.len();
    let over = |object: usize| ExportError::TooManyTriangles {
        object: owners[object].label.clone(),
        budget: options
            .max_triangles
            .saturating_sub(used.load(Ordering::Relaxed)),
    };
    let meshed: Vec<Result<(Shell, bool), ExportError>> = pieces
        .par_iter()
        .map(|piece| {
            let left = options
                .max_triangles
                .saturating_sub(used.load(Ordering::Relaxed));
            let (mesh, closed) = match &piece.job {
                Job::Surface(s) => (mesh_surface(surface(s), tolerance, left), true),
                Job::Mesh(v, t) => (
                    crate::triangles::subdivide(v, t, tolerance, left),
                    crate::triangles::open_edge(t).is_none(),
                ),
            };
            let mesh = mesh.ok_or_else(|| over(piece.object))?;
            if used.fetch_add(mesh.triangles.len(), Ordering::Relaxed) + mesh.triangles.len()
                > options.max_triangles
            {
                return Err(over(piece.object));
            }
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            let owner = &owners[piece.object];
            let shell = if closed {
                Shell::from_grid(owner, piece.material, mesh, scale)
            } else {
                Shell::open(owner, piece.material, mesh, scale)
            };
            Ok((shell, closed))
        })
        .collect();
    let mut model = Model {
        parts_cut,
        ..Model::default()
    };
    // Materials in order of first use, so the tables hold only what the
    // shells use, the same every time.
    let mut index_of = vec![None; scene.materials.len()];
    for result in meshed {
        let (mut shell, closed) = result?;
        let k = *index_of[shell.material].get_or_insert_with(|| {
            let m = &scene.materials[shell.material];
            model.materials.push(ExportMaterial {
                name: m
                    .name
                    .clone()
                    .unwrap_or_else(|| format!("material-{}", shell.material + 1)),
                color: [m.diffuse.r, m.diffuse.g, m.diffuse.b].map(|c| c.clamp(0.0, 1.0)),
            });
            model.materials.len() - 1
        });
        shell.material = k;
        shell.closed = closed;
        model.shells.push(shell);
    }
    Ok(model)
}

fn surface(s: &PartSurface) -> &dyn PoleSurface {
    match s {
        PartSurface::Ball(b) => b,
        PartSurface::Capsule(c) => c,
        PartSurface::Plate(p) => p,
    }
}
