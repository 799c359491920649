//! The `Points` section, and points written as literals anywhere:
//! `(x, y, z)` is an h-point inside the ball or an ideal point on the
//! absolute. In `Points`, `(x, y, z), distance = d` is the point at
//! hyperbolic distance `d` from the origin in the direction `(x, y, z)`.

use hgeom::glam::DVec3;
use hgeom::{IdealPoint, Point, Vertex};

use super::Lowerer;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::{BrokenStatement, Clause, Section, Value};

/// How close to the absolute a typed point may come before its decimal
/// rounding alone moves it by more than about 1e-6 in hyperbolic distance.
const NEAR_ABSOLUTE_GAP: f64 = 1e-10;

/// How far from the unit sphere a typed point may be and still count as ideal.
const IDEAL_TOLERANCE: f64 = 1e-12;

/// The largest `distance = d` of a point by direction and distance: as for
/// `Translate(L, d)`, beyond 36 f64 holds no ball point.
const MAX_POINT_DISTANCE: f64 = 36.0;

/// A declared point: its name as written (also when another point took the
/// name first) and its position, `None` if it was refused.
pub(super) struct DeclaredPoint {
    pub(super) name: Option<String>,
    pub(super) position: Option<Vertex>,
}

impl Lowerer<'_> {
    pub(super) fn points_section(&mut self, section: &Section) {
        let mut broken = section.broken.iter().peekable();
        for st in &section.statements {
            while let Some(b) = broken.next_if(|b| b.span.start() < st.span.start()) {
                self.broken_point(b);
            }
            // `..., distance = d` after the coordinates: by direction and
            // distance.
            let (clauses, distance) = match &st.clauses[..] {
                [first, Clause::Assign { key, value, .. }] if key.text == "distance" => {
                    (std::slice::from_ref(first), Some(value))
                }
                all => (all, None),
            };
            let (name, value) = match (st.label.as_ref(), clauses) {
                (label, [Clause::Value(v)]) => (label.cloned(), v),
                (None, [Clause::Assign { key, value, .. }]) => (Some(key.clone()), value),
                _ => {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            st.span,
                            "a point is written `(x, y, z);` or `name = (x, y, z);`, or by direction and distance `(x, y, z), distance = d;`",
                        )
                        .with_label("not a point declaration"),
                    );
                    // Keep numbering aligned with what the user counted.
                    let point = DeclaredPoint {
                        name: None,
                        position: None,
                    };
                    self.points.push(point, st.span, true);
                    continue;
                }
            };
            let position = match distance {
                None => self
                    .point_literal(value)
                    .and_then(|(v, span)| self.classify_point(v, span)),
                Some(d) => self.point_by_distance(value, d),
            };
            let point = DeclaredPoint {
                name: name.as_ref().map(|n| n.text.to_string()),
                position,
            };
            let declared = self.points.push_declared(point, st.span, name.as_ref());
            self.report_refused(declared);
        }
        for b in broken {
            self.broken_point(b);
        }
    }

    /// A point statement that did not parse (already reported) still takes
    /// its number and name, so later references do not cascade into errors.
    fn broken_point(&mut self, b: &BrokenStatement) {
        let name = b.name.as_ref().map(|n| n.text.to_string());
        let point = DeclaredPoint {
            name: name.clone(),
            position: None,
        };
        let index = self.points.push(point, b.span, true);
        if let Some(n) = &name {
            self.points.bind(n, index);
        }
    }

    /// `(x, y, z), distance = d`: the point at hyperbolic distance `d` from
    /// the origin in the direction `(x, y, z)` (any length but zero).
    fn point_by_distance(&mut self, direction: &Value, distance: &Value) -> Option<Vertex> {
        let (dir, span) = self.point_literal(direction)?;
        let d = self.number(distance)?;
        if !(dir.length() > 0.0 && dir.is_finite()) {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    span,
                    "a point by direction and distance needs a direction: these coordinates are all 0",
                )
                .with_help("`(0, 1, 0), distance = 2` is the point 2 from the origin along +y"),
            );
            return None;
        }
        if !(0.0..=MAX_POINT_DISTANCE).contains(&d) {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    distance.span(),
                    format!(
                        "a point's distance from the origin must be from 0 to {MAX_POINT_DISTANCE}, got {}",
                        hgeom::Compact(d)
                    ),
                )
                .with_help("the distance is hyperbolic; beyond 36 no ball point can be told from the absolute in f64"),
            );
            return None;
        }
        match Point::at_distance_from_origin(dir, d) {
            Ok(p) => Some(Vertex::Interior(p)),
            Err(e) => {
                self.report(Diagnostic::new(
                    Code::InvalidValue,
                    span,
                    format!(
                        "no point at distance {} in this direction: {e}",
                        hgeom::Compact(d)
                    ),
                ));
                None
            }
        }
    }

    /// The coordinates of a point literal `(x, y, z)`, and where it is.
    pub(super) fn point_literal(&mut self, value: &Value) -> Option<(DVec3, Span)> {
        let v = self.tuple_of_numbers(value, 3, "a point `(x, y, z)`")?;
        Some((DVec3::new(v[0], v[1], v[2]), value.span()))
    }

    /// Typed coordinates as an ideal point (on the unit sphere) or an
    /// h-point (inside it); outside the ball is an error.
    pub(super) fn classify_point(&mut self, v: DVec3, span: Span) -> Option<Vertex> {
        let norm = v.length();
        // Ideal first: a point typed on the unit sphere whose f64 norm happens
        // to round just below 1 must not become a far interior point.
        if let Ok(ideal) = IdealPoint::new(v, IDEAL_TOLERANCE) {
            return Some(Vertex::Ideal(ideal));
        }
        if let Ok(p) = Point::from_coords(v) {
            if p.gap() < NEAR_ABSOLUTE_GAP {
                // gap = 1 - |x|^2 = (1 - |x|)(1 + |x|), about twice 1 - |x| here.
                self.report(
                    Diagnostic::new(Code::PointNearAbsolute, span, format!("this point is within {:.1e} of the absolute; decimal rounding alone moves it noticeably", 0.5 * p.gap()))
                        .with_help("positions this close to the absolute are not reproducible in f64; move it inward or place it with transformations"),
                );
            }
            return Some(Vertex::Interior(p));
        }
        self.report(
            Diagnostic::new(Code::PointOutsideAbsolute, span, format!("point lies outside the absolute: |x| = {}", norm_text(norm)))
                .with_label("outside the unit ball")
                .with_help("h-points need |x| < 1 (ideal points |x| = 1); scale the coordinates into the unit ball"),
        );
        None
    }
}

/// A norm above 1 in few digits that still show it is above 1: `1.0392`,
/// or `1 + 2.5e-9` when four decimals would read as 1 (a message once
/// printed all sixteen digits of `1.0392304845413265`).
fn norm_text(norm: f64) -> String {
    if norm.is_finite() && norm > 1.0 && norm - 1.0 < 1e-4 {
        format!("1 + {:.1e}", norm - 1.0)
    } else if norm.is_finite() && norm < 1e9 {
        format!("{norm:.4}")
    } else {
        format!("{}", hgeom::Compact(norm))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn norms_are_short_and_above_one() {
        assert_eq!(norm_text(1.039_230_484_541_326_5), "1.0392");
        assert_eq!(norm_text(1.0 + 2.5e-9), "1 + 2.5e-9");
        assert_eq!(norm_text(1.5e12), "1.5e12");
        assert_eq!(norm_text(3.0), "3.0000");
    }
}
