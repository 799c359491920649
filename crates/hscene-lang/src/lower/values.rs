//! Checking argument values: numbers (positive, in a range, whole), tuples,
//! colours, points that must be inside the ball, points that may be ideal,
//! and material references. Each reports what is wrong and returns `None`.

use hgeom::{IdealPoint, Point, Vertex};

use super::Lowerer;
use super::text::count;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{MaterialId, Rgb};
use crate::syntax::{RefSigil, Value};

/// Where ideal points may stand, for the help of `IdealPointNotAllowed`.
const IDEAL_ALLOWED_HELP: &str = "ideal points are allowed only as polygon vertices, rod and cylinder ends, `Plane` and `hplane` points and horosphere centres";

impl Lowerer<'_> {
    pub(super) fn number(&mut self, value: &Value) -> Option<f64> {
        match value {
            // An overflowing literal was already reported by the parser.
            Value::Number { value, .. } if !value.is_finite() => None,
            Value::Number { value, .. } => Some(*value),
            Value::Ident(name) if crate::numbers::is_non_finite_word(&name.text) => {
                self.report(crate::numbers::non_finite(name.span, &name.text));
                None
            }
            other => {
                self.report(Diagnostic::new(
                    Code::WrongType,
                    other.span(),
                    format!("expected a number, found {}", other.describe()),
                ));
                None
            }
        }
    }

    pub(super) fn positive(&mut self, value: &Value, what: &str) -> Option<f64> {
        let x = self.number(value)?;
        if x > 0.0 {
            Some(x)
        } else {
            self.report(
                Diagnostic::new(
                    Code::NonPositiveRadius,
                    value.span(),
                    format!("{what} must be positive, got {}", hgeom::Compact(x)),
                )
                .with_help("lengths are hyperbolic and must be greater than 0"),
            );
            None
        }
    }

    pub(super) fn unit_interval(&mut self, value: &Value, what: &str) -> Option<f64> {
        let x = self.number(value)?;
        if (0.0..=1.0).contains(&x) {
            Some(x)
        } else {
            self.report(Diagnostic::new(
                Code::InvalidValue,
                value.span(),
                format!(
                    "`{what}` must be between 0 and 1, got {}",
                    hgeom::Compact(x)
                ),
            ));
            None
        }
    }

    pub(super) fn integer(&mut self, value: &Value, min: u64, max: u64, what: &str) -> Option<u64> {
        let x = self.number(value)?;
        self.integer_value(x, min, max, value.span(), what)
    }

    pub(super) fn integer_value(
        &mut self,
        x: f64,
        min: u64,
        max: u64,
        span: Span,
        what: &str,
    ) -> Option<u64> {
        if x.fract() == 0.0 && x >= min as f64 && x <= max as f64 {
            Some(x as u64)
        } else {
            self.report(Diagnostic::new(
                Code::InvalidValue,
                span,
                format!(
                    "{what} must be a whole number from {min} to {max}, got {}",
                    hgeom::Compact(x)
                ),
            ));
            None
        }
    }

    pub(super) fn tuple_of_numbers(
        &mut self,
        value: &Value,
        n: usize,
        what: &str,
    ) -> Option<Vec<f64>> {
        let Value::Tuple { items, span } = value else {
            self.report(Diagnostic::new(
                Code::WrongType,
                value.span(),
                format!("expected {what}, found {}", value.describe()),
            ));
            return None;
        };
        if items.len() != n {
            self.report(Diagnostic::new(
                Code::WrongArity,
                *span,
                format!(
                    "expected {what} with {}, found {}",
                    count(n, "value"),
                    items.len()
                ),
            ));
            return None;
        }
        let mut out = Vec::with_capacity(n);
        for item in items {
            out.push(self.number(item)?);
        }
        Some(out)
    }

    pub(super) fn rgb(&mut self, value: &Value) -> Option<Rgb> {
        let v = self.tuple_of_numbers(value, 3, "a colour `(r, g, b)`")?;
        self.colour_in_range(value, [v[0], v[1], v[2]])
    }

    /// A point given as a reference or a literal, with where it is
    /// written; the "wrong type" message names its role if it has one.
    fn located_vertex(&mut self, value: &Value, role: Option<&str>) -> Option<(Vertex, Span)> {
        match value {
            Value::Reference(r) => {
                let i = self.resolve_point(r)?;
                Some((self.points[i].position?, r.span))
            }
            Value::Tuple { .. } => {
                let (v, span) = self.point_literal(value)?;
                Some((self.classify_point(v, span)?, span))
            }
            other => {
                let found = other.describe();
                let message = match role {
                    Some(role) => format!("expected a point for {role}, found {found}"),
                    None => format!("expected a point, found {found}"),
                };
                self.report(Diagnostic::new(Code::WrongType, other.span(), message));
                self.point_ref_failed = true;
                None
            }
        }
    }

    /// An interior point given as a reference or a literal.
    pub(super) fn point_arg(&mut self, value: &Value, role: &str) -> Option<Point> {
        let (pos, span) = self.located_vertex(value, Some(role))?;
        match pos {
            Vertex::Interior(p) => Some(p),
            Vertex::Ideal(_) => {
                self.report(
                    Diagnostic::new(
                        Code::IdealPointNotAllowed,
                        span,
                        format!(
                            "{role} must be inside the ball, but this point is on the absolute"
                        ),
                    )
                    .with_help(IDEAL_ALLOWED_HELP),
                );
                None
            }
        }
    }

    /// A point that may be ideal.
    pub(super) fn vertex_arg(&mut self, value: &Value) -> Option<Vertex> {
        self.located_vertex(value, None).map(|(v, _)| v)
    }

    /// A point that may be ideal, with a role for the "wrong type" message.
    pub(super) fn vertex_arg_for(&mut self, value: &Value, role: &str) -> Option<Vertex> {
        if matches!(value, Value::Number { .. } | Value::Ident(_)) {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    value.span(),
                    format!("expected a point for {role}, found {}", value.describe()),
                )
                .with_help("write a point as `(x, y, z)` or refer to one as `%N` or `%name`"),
            );
            return None;
        }
        self.vertex_arg(value)
    }

    /// A point that must be ideal (on the absolute).
    pub(super) fn ideal_arg(&mut self, value: &Value, role: &str) -> Option<IdealPoint> {
        match self.vertex_arg_for(value, role)? {
            Vertex::Ideal(p) => Some(p),
            Vertex::Interior(p) => {
                self.report(
                    Diagnostic::new(
                        Code::IdealPointRequired,
                        value.span(),
                        format!("{role} must be an ideal point (on the absolute), but this point is inside the ball"),
                    )
                    .with_label(format!("|x| = {:.6}, not 1", p.coords().length()))
                    .with_help("use a point with x² + y² + z² = 1, e.g. `(0, 0, 1)`"),
                );
                None
            }
        }
    }

    /// A material reference `#N` or `#name`.
    pub(super) fn material_arg(&mut self, value: &Value) -> Option<MaterialId> {
        match value {
            Value::Reference(r) if r.sigil == RefSigil::Hash => self.resolve_material(r),
            other => {
                self.material_ref_failed = true;
                self.report(
                    Diagnostic::new(
                        Code::WrongType,
                        other.span(),
                        format!(
                            "expected a material reference like `#1`, found {}",
                            other.describe()
                        ),
                    )
                    .with_label("expected `#N` or `#name`"),
                );
                None
            }
        }
    }
}
