//! Warnings about a scene that lowers but probably does not show what was
//! meant: the eye or a light inside an object, objects behind the eye,
//! unused points and materials, animations with one frame. (Objects
//! outside the window are in `view_lint.rs`.)

use super::Lowerer;
use super::seen_from::SeenFrom;
use super::text::numbered;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{Camera, IntegratorKind};
use crate::syntax::{Clause, RefSigil, Reference, Section, Value};

/// Calls `f` on every reference in `value`.
fn each_reference<'a>(value: &'a Value, f: &mut impl FnMut(&'a Reference)) {
    match value {
        Value::Reference(r) => f(r),
        Value::Tuple { items, .. } => items.iter().for_each(|v| each_reference(v, f)),
        Value::Number { .. } | Value::Ident(_) | Value::Str { .. } | Value::Symbol { .. } => {}
    }
}

impl Lowerer<'_> {
    pub(super) fn lint_scene(&mut self, camera: &Camera) {
        // Decided in the eye's own frame (see `seen_from`): the plane through
        // the eye orthogonal to the view direction; objects entirely on its
        // far side can't be seen.
        let eye = SeenFrom::new(camera.eye);
        let view = eye.direction_to(&camera.target);
        let mut found = Vec::new();
        // One statement can give many objects (edges, tessellation cells),
        // all with the statement's span: lint each statement once.
        for group in self.objects.chunk_by(|a, b| a.1 == b.1) {
            let span = group[0].1;
            if group.iter().any(|(o, _)| eye.is_inside(&o.shape)) {
                found.push(
                    Diagnostic::new(
                        Code::EyeInsideObject,
                        span,
                        "the eye is inside this object, so every view ray starts inside it",
                    )
                    .with_help("move the eye (`from`) or the object if this is not intended"),
                );
            } else if self.settings.space.is_none()
                && view.is_some_and(|v| group.iter().all(|(o, _)| eye.is_behind(&o.shape, v)))
            {
                // In a quotient space every object is seen again through
                // the gluing, in front of the eye as well.
                found.push(Diagnostic::new(
                    Code::ObjectBehindEye,
                    span,
                    "this object is entirely behind the eye and cannot be seen",
                ));
            }
        }
        for (light, span) in &self.lights {
            let from = SeenFrom::new(light.position);
            for (object, _) in &self.objects {
                let opaque = self
                    .materials
                    .get(object.material.index())
                    .is_some_and(|m| m.transmission == 0.0);
                if opaque && from.is_inside(&object.shape) {
                    found.push(Diagnostic::new(
                        Code::LightInsideOpaqueObject,
                        *span,
                        "this light is inside an opaque object, so it lights nothing outside it",
                    ));
                    break;
                }
            }
        }
        self.diags.extend(found);
    }

    /// Statements that did not parse or failed to lower stop early, before
    /// they resolve all their references: mark what they refer to as used,
    /// so that one error does not also make its points and materials look
    /// unused.
    ///
    /// Called for each section right after it is lowered, so that its
    /// syntax can be dropped then: an error found later (the checks against
    /// the camera) is at a statement that had resolved its references.
    pub(super) fn mark_failed_references(&mut self, section: &Section) {
        let mut error_starts: Vec<usize> = self
            .diags
            .iter()
            .filter(|d| d.is_error())
            .map(|d| d.span.start())
            .collect();
        if error_starts.is_empty() {
            return;
        }
        error_starts.sort_unstable();
        let has_error = |span: Span| {
            let i = error_starts.partition_point(|&s| s < span.start());
            error_starts.get(i).is_some_and(|&s| s < span.end())
        };
        let mut refs: Vec<&Reference> = Vec::new();
        refs.extend(section.broken.iter().flat_map(|b| &b.references));
        for st in section.statements.iter().filter(|st| has_error(st.span)) {
            for clause in &st.clauses {
                match clause {
                    Clause::Assign { value, .. } => each_reference(value, &mut |r| refs.push(r)),
                    Clause::Apply { target, arg, .. } => {
                        refs.extend(target.as_deref());
                        if let Some(v) = arg {
                            each_reference(v, &mut |r| refs.push(r));
                        }
                    }
                    Clause::Value(v) => each_reference(v, &mut |r| refs.push(r)),
                }
            }
        }
        for r in refs {
            match r.sigil {
                RefSigil::Percent => {
                    if let Some(i) = self.points.find(&r.target) {
                        self.points.mark_used(i);
                    }
                }
                RefSigil::Hash => {
                    if let Some(i) = self.materials.find(&r.target) {
                        self.materials.mark_used(i);
                    }
                }
                RefSigil::At => {}
            }
        }
    }

    /// Reports unused points and materials, unless a failed reference means
    /// that one of them was probably meant (the warnings would only add
    /// noise to the error).
    pub(super) fn lint_unused(&mut self) {
        let mut found = Vec::new();
        for (i, p) in self.points.entries().iter().enumerate() {
            if !self.point_ref_failed && !p.used && p.value.position.is_some() {
                let name = numbered('%', i + 1, p.value.name.as_deref());
                found.push(Diagnostic::new(
                    Code::UnusedPoint,
                    p.span,
                    format!("point {name} is never used"),
                ));
            }
        }
        for (i, m) in self.materials.entries().iter().enumerate() {
            if !self.material_ref_failed && !m.used {
                let name = numbered('#', i + 1, m.value.name.as_deref());
                found.push(Diagnostic::new(
                    Code::UnusedMaterial,
                    m.span,
                    format!("material {name} is never used"),
                ));
            }
        }
        self.diags.extend(found);
    }

    /// Animated transformations in a scene of one frame stay at their start.
    /// `integrator = path` with ambient light that some material reflects:
    /// the path tracer ignores it (`HSC1010`).
    pub(super) fn lint_ambient_under_path(&mut self) {
        let Some(span) = self.integrator_span else {
            return;
        };
        if self.settings.integrator != IntegratorKind::Path || !relies_on_ambient(self) {
            return;
        }
        self.report(
            Diagnostic::new(
                Code::AmbientUnderPath,
                span,
                "`ambient` has no meaning under the path integrator, which computes the light bouncing between surfaces instead",
            )
            .with_help("light the scene with lights, `emission` or `background` and remove `ambient`, or use `integrator = whitted`"),
        );
    }

    pub(super) fn lint_still_animation(&mut self) {
        if self.settings.frames == 1
            && !self.frames_refused
            && let Some(&at) = self.animations.first()
        {
            self.report(
                Diagnostic::new(
                    Code::StillAnimation,
                    at,
                    "this scene has one frame, so the animated transformations stay at their start",
                )
                .with_help("set `frames = 48;` (say) in `Globals` to render the animation, or remove `, animate` to apply the transformation in full"),
            );
        }
    }
}

/// True when the ambient term would light something: a non-black global
/// `ambient` and a material that reflects it.
fn relies_on_ambient(lw: &Lowerer<'_>) -> bool {
    !lw.settings.ambient.is_black()
        && lw
            .materials
            .entries()
            .iter()
            .any(|e| e.value.reflects_ambient())
}
