//! Transformations of named objects, lights and the camera:
//! `@name->Rotate(L, angle);`, `@name->Translate(L);`, `@name->Reflect(S);`,
//! `@camera->...`.
//!
//! The isometry of each statement is built where the statement stands (so
//! it sees the h-lines and h-planes declared before it, as point
//! transformations do). The target is resolved once every object and light
//! exists, and the isometries are applied to it in statement order: an
//! object is built from the final positions of its points, then moved by
//! its own transformations, first to last (composed, then applied once).

use std::collections::HashMap;

use hgeom::glam::DVec3;
use hgeom::{HLine, Isometry, Point};

use super::Lowerer;
use super::names::{CAMERA, TargetSlot};
use super::suggest::{MAX_CANDIDATES, closest};
use super::text::{quote, reference_text, shorten};
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::{Camera, Shape};
use crate::syntax::{RefTarget, Reference};

/// A transformation of an `@` target, waiting for its target to exist.
pub(super) struct PendingMove {
    pub(super) target: Reference,
    /// `None` when the isometry could not be built (already reported); the
    /// target is still resolved so that a misspelt name is reported too.
    pub(super) iso: Option<Isometry>,
}

impl Lowerer<'_> {
    /// Applies the pending `@` transformations in statement order.
    ///
    /// The isometries of each target are composed first (in statement
    /// order) and the composition is applied once, so that a target with
    /// many vertices (a tessellation) moved by many statements costs one
    /// pass, and every vertex is rounded once. If the result leaves what f64
    /// can represent, the target's last transformation is blamed.
    pub(super) fn apply_moves(&mut self, camera: &mut Option<Camera>) {
        let moves = std::mem::take(&mut self.moves);
        // Per target, in order of first use: the composed isometry (`None`
        // if one of them failed to build, which was reported) and the last
        // statement's target reference.
        let mut order: Vec<String> = Vec::new();
        let mut composed: HashMap<String, (Option<Isometry>, Reference)> = HashMap::new();
        for mv in &moves {
            let name = match &mv.target.target {
                RefTarget::Name(n) => n.clone(),
                RefTarget::Index(_) => {
                    self.report(
                        Diagnostic::new(
                            Code::UndefinedTarget,
                            mv.target.span,
                            format!(
                                "`{}`: objects and lights are transformed by name, not by number",
                                reference_text(&mv.target)
                            ),
                        )
                        .with_help("name the object (`ball: Sphere %1, 0.1, #1;`) or light (`sun: %2, (1,1,1), (1,1,1);`) and write `@ball->...`; points are moved with `%N->...`"),
                    );
                    continue;
                }
            };
            if name != CAMERA && self.targets.by_name(&name).is_none() {
                self.undefined_target(&mv.target, &name);
                continue;
            }
            match composed.get_mut(&name) {
                Some((acc, last)) => {
                    *acc = match (acc.as_ref(), &mv.iso) {
                        // `a.compose(b)` applies `b` first.
                        (Some(a), Some(b)) => Some(b.compose(a)),
                        _ => None,
                    };
                    *last = mv.target.clone();
                }
                None => {
                    order.push(name.clone());
                    composed.insert(name, (mv.iso, mv.target.clone()));
                }
            }
        }
        for name in order {
            let Some((Some(iso), target)) = composed.remove(&name) else {
                continue;
            };
            if name == CAMERA {
                if let Some(cam) = camera.as_mut()
                    && move_camera(cam, &iso).is_none()
                {
                    self.out_of_range(&target, "the camera");
                }
                continue;
            }
            let Some(slot) = self.targets.by_name(&name).map(|i| self.targets[i].clone()) else {
                continue;
            };
            match slot {
                TargetSlot::Objects(indices) => {
                    for i in indices {
                        match transform_shape(&self.objects[i].0.shape, &iso) {
                            Some(s) => {
                                let object = &mut self.objects[i].0;
                                object.shape = s;
                                object.placement = iso.compose(&object.placement);
                            }
                            None => {
                                self.out_of_range(&target, "this object");
                                break;
                            }
                        }
                    }
                }
                TargetSlot::Light(Some(i)) => match iso.checked_apply(&self.lights[i].0.position) {
                    Ok(p) => self.lights[i].0.position = p,
                    Err(_) => self.out_of_range(&target, "this light"),
                },
                // The light had errors of its own.
                TargetSlot::Light(None) => {}
            }
        }
    }

    fn undefined_target(&mut self, target: &Reference, name: &str) {
        let mut d = Diagnostic::new(
            Code::UndefinedTarget,
            target.span,
            format!("no object or light is named {}", quote(name)),
        );
        // The camera and the declared targets; none when there are too many
        // to compare (see `suggest.rs`), so this stays linear per error.
        let mut declared: Vec<&str> = Vec::new();
        if self.targets.name_count() < MAX_CANDIDATES {
            declared = self.targets.names().collect();
            declared.push(CAMERA);
        }
        d = if self.points.by_name(name).is_some() {
            let name = shorten(name);
            d.with_help(format!(
                "`{name}` is a point: write `%{name}->...` to move it"
            ))
        } else if let Some(s) = closest(name, &declared) {
            d.with_help(format!("did you mean `@{s}`?"))
        } else {
            d.with_help("name the object in `Objects` (`ball: Sphere %1, 0.1, #1;`) or the light in `Lights` (`sun: %2, (1,1,1), (1,1,1);`); `@camera` is the camera")
        };
        self.report(d);
    }

    fn out_of_range(&mut self, target: &Reference, what: &str) {
        self.report(
            Diagnostic::new(
                Code::NumericFailure,
                target.span,
                format!("this moves {what} so close to the absolute that f64 cannot represent it"),
            )
            .with_help(
                "f64 holds ball points out to about distance 37 from the origin; move it less far",
            ),
        );
    }
}

/// Moves the eye, the target and the up point. A camera with the default
/// up direction (`+y` at the eye) first gets an explicit up point on the
/// geodesic leaving the eye in that direction, so that the direction turns
/// with the camera. `None` if a point leaves what f64 can represent.
fn move_camera(cam: &mut Camera, iso: &Isometry) -> Option<()> {
    if cam.up.is_none() {
        cam.up = default_up_point(&cam.eye);
    }
    let eye = iso.checked_apply(&cam.eye).ok()?;
    let target = iso.checked_apply(&cam.target).ok()?;
    let up = match &cam.up {
        Some(u) => Some(iso.checked_apply(u).ok()?),
        None => None,
    };
    *cam = Camera { eye, target, up };
    Some(())
}

/// A point towards which the default up direction (`+y` at the eye) points.
fn default_up_point(eye: &Point) -> Option<Point> {
    let line = HLine::from_point_direction(eye, DVec3::Y).ok()?;
    // Any point on the geodesic gives the same direction; a short step stays
    // representable even for an eye far out.
    [1.0, 0.1, 1e-3]
        .into_iter()
        .find_map(|s| line.point_at(s).ok())
}

/// The image of a shape under an isometry, or `None` if some part of it
/// leaves what f64 can represent.
pub(super) fn transform_shape(shape: &Shape, iso: &Isometry) -> Option<Shape> {
    let moved = shape.transformed(iso);
    moved.is_representable().then_some(moved)
}
