//! References to declarations (`%3`, `%apex`, `#glass`): resolved against
//! the tables, marked used, and when undefined reported with what is
//! declared or the nearest name.

use hgeom::{HPlane, Segment};

use super::Lowerer;
use super::suggest::closest_declared;
use super::text::{count, reference_text, shorten};
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::MaterialId;
use crate::syntax::{RefSigil, RefTarget, Reference, Value};

/// The totally geodesic subspaces a transformation's `%` references name:
/// h-lines (rotation axes, translations) and h-planes (reflections).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Subspace {
    Line,
    Plane,
}

impl Lowerer<'_> {
    /// Whether `r` is an index the parser already reported as too large
    /// (it stands for `u64::MAX`); reporting it as undefined would repeat it.
    pub(super) fn index_overflowed(&self, r: &Reference) -> bool {
        r.target == RefTarget::Index(u64::MAX)
            && self
                .diags
                .iter()
                .any(|d| d.code == Code::InvalidNumber && d.span == r.span)
    }

    /// The point `r` names, marked used; reported if there is none.
    pub(super) fn resolve_point(&mut self, r: &Reference) -> Option<usize> {
        if r.sigil != RefSigil::Percent {
            let what = match r.sigil {
                RefSigil::At => "the object reference",
                _ => "the material reference",
            };
            self.report(Diagnostic::new(
                Code::WrongType,
                r.span,
                format!(
                    "expected a point reference like `%1`, found {what} `{}`",
                    reference_text(r)
                ),
            ));
            self.point_ref_failed = true;
            return None;
        }
        let found = self.points.find(&r.target);
        match found {
            Some(i) => {
                self.points.mark_used(i);
                Some(i)
            }
            None if self.index_overflowed(r) => {
                self.point_ref_failed = true;
                None
            }
            None => {
                self.point_ref_failed = true;
                let help = match (&r.target, self.points.len()) {
                    (RefTarget::Index(0), _) => "points are numbered from %1".to_string(),
                    (_, 0) => {
                        "no points are declared: add them to the `Points` section".to_string()
                    }
                    (RefTarget::Index(_), n) => {
                        format!("{} declared (%1 to %{n})", count(n, "point"))
                    }
                    (RefTarget::Name(n), _) if self.target_labels.contains(n) => {
                        let n = shorten(n);
                        format!(
                            "`{n}` is an object or light, not a point: write `@{n}` to transform it"
                        )
                    }
                    (RefTarget::Name(n), _) => match closest_declared(n, self.points.names()) {
                        Some(s) => format!("did you mean `%{s}`?"),
                        None => "declare it in `Points` as `name = (x, y, z);`".to_string(),
                    },
                };
                self.report(
                    Diagnostic::new(
                        Code::UndefinedPoint,
                        r.span,
                        format!("undefined point `{}`", reference_text(r)),
                    )
                    .with_help(help),
                );
                None
            }
        }
    }

    /// The material `r` names, marked used; reported if there is none.
    pub(super) fn resolve_material(&mut self, r: &Reference) -> Option<MaterialId> {
        let found = self.materials.find(&r.target);
        match found {
            Some(i) => {
                self.materials.mark_used(i);
                Some(MaterialId::declared(i))
            }
            None if self.index_overflowed(r) => {
                self.material_ref_failed = true;
                None
            }
            None => {
                self.material_ref_failed = true;
                let suggestion = match &r.target {
                    RefTarget::Name(n) => closest_declared(n, self.materials.names()),
                    RefTarget::Index(_) => None,
                };
                let help = match (suggestion, self.materials.len()) {
                    (Some(s), _) => format!("did you mean `#{s}`?"),
                    (None, 0) => {
                        "no materials are declared: add one to the `BRDFs` section".to_string()
                    }
                    (None, n) => format!("{} declared (#1 to #{n})", count(n, "material")),
                };
                self.report(
                    Diagnostic::new(
                        Code::UndefinedMaterial,
                        r.span,
                        format!("undefined material `{}`", reference_text(r)),
                    )
                    .with_help(help),
                );
                None
            }
        }
    }

    pub(super) fn resolve_line(&mut self, value: &Value) -> Option<Segment> {
        let index = self.resolve_subspace(value, Subspace::Line)?;
        self.lines[index]
    }

    pub(super) fn resolve_plane(&mut self, value: &Value) -> Option<HPlane> {
        let index = self.resolve_subspace(value, Subspace::Plane)?;
        self.planes[index]
    }

    /// Resolve `%N` / `%name` against the line or plane table.
    fn resolve_subspace(&mut self, value: &Value, kind: Subspace) -> Option<usize> {
        let Value::Reference(
            r @ Reference {
                sigil: RefSigil::Percent,
                ..
            },
        ) = value
        else {
            let what = match kind {
                Subspace::Line => "h-line",
                Subspace::Plane => "h-plane",
            };
            self.report(Diagnostic::new(
                Code::WrongType,
                value.span(),
                format!(
                    "expected an {what} reference like `%1`, found {}",
                    value.describe()
                ),
            ));
            return None;
        };
        let (found, len, what, declare) = match kind {
            Subspace::Line => (
                self.lines.find(&r.target),
                self.lines.len(),
                "h-line",
                "hline (%A, %B);",
            ),
            Subspace::Plane => (
                self.planes.find(&r.target),
                self.planes.len(),
                "h-plane",
                "hplane (%A, %B, %C);",
            ),
        };
        if found.is_none() && !self.index_overflowed(r) {
            let declared = if len == 0 {
                format!("no {what}s are declared yet")
            } else {
                format!("{} declared so far", count(len, what))
            };
            self.report(
                Diagnostic::new(
                    Code::UndefinedLine,
                    r.span,
                    format!("undefined {what} `{}`", reference_text(r)),
                )
                .with_help(format!(
                    "{declared}; declare one with `{declare}` before using it"
                )),
            );
        }
        found
    }
}
