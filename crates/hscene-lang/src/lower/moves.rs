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
//! A target with an animated transformation becomes a track of the IR's
//! animation, which keeps its state before the moves so that any frame can
//! be computed from the compiled scene (`ir::Scene::frame`).

use std::collections::HashMap;

use super::Lowerer;
use super::names::{CAMERA, TargetSlot};
use super::suggest::{MAX_CANDIDATES, closest};
use super::text::{quote, reference_text, shorten};
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::{Camera, Motion, Track, TrackBase, compose};
use crate::ir::{move_camera, move_object};
use crate::syntax::{RefTarget, Reference};

/// A transformation of an `@` target, waiting for its target to exist.
pub(super) struct PendingMove {
    pub(super) target: Reference,
    /// `None` when the motion could not be built (already reported); the
    /// target is still resolved so that a misspelt name is reported too.
    pub(super) motion: Option<Motion>,
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
        // Per target, in order of first use: its motions (`None` if one of
        // them failed to build, which was reported) and the last
        // statement's target reference.
        let mut order: Vec<String> = Vec::new();
        let mut collected: HashMap<String, (Option<Vec<Motion>>, Reference)> = HashMap::new();
        for mv in moves {
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
            match collected.get_mut(&name) {
                Some((motions, last)) => {
                    *motions = match (motions.take(), mv.motion) {
                        (Some(mut all), Some(m)) => {
                            all.push(m);
                            Some(all)
                        }
                        _ => None,
                    };
                    *last = mv.target;
                }
                None => {
                    order.push(name.clone());
                    collected.insert(name, (mv.motion.map(|m| vec![m]), mv.target));
                }
            }
        }
        for name in order {
            let Some((Some(motions), target)) = collected.remove(&name) else {
                continue;
            };
            // Every motion was built at this frame's time, so this succeeds.
            let Ok(iso) = compose(&motions, self.time) else {
                self.out_of_range(&target, "this target");
                continue;
            };
            let animated = motions.iter().any(Motion::is_animated);
            let mut track = |base: TrackBase| {
                if animated {
                    self.animation.tracks.push(Track {
                        base,
                        motions: motions.clone(),
                    });
                }
            };
            if name == CAMERA {
                if let Some(cam) = camera.as_mut() {
                    track(TrackBase::Camera(*cam));
                    if move_camera(cam, &iso).is_none() {
                        self.out_of_range(&target, "the camera");
                    }
                }
                continue;
            }
            let Some(slot) = self.targets.by_name(&name).map(|i| self.targets[i].clone()) else {
                continue;
            };
            match slot {
                TargetSlot::Objects(indices) => {
                    track(TrackBase::Objects {
                        objects: indices.iter().map(|&i| self.objects[i].0.clone()).collect(),
                        indices: indices.clone(),
                    });
                    for i in indices {
                        match move_object(&self.objects[i].0, &iso) {
                            Some(moved) => self.objects[i].0 = moved,
                            None => {
                                self.out_of_range(&target, "this object");
                                break;
                            }
                        }
                    }
                }
                TargetSlot::Light(Some(i)) => {
                    let position = self.lights[i].0.position;
                    track(TrackBase::Light { index: i, position });
                    match iso.checked_apply(&position) {
                        Ok(p) => self.lights[i].0.position = p,
                        Err(_) => self.out_of_range(&target, "this light"),
                    }
                }
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
