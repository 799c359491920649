//! The `Transformations` section: h-lines and h-planes declared for later
//! statements, and the moves of points (`%P->Rotate(L, angle);`,
//! `Translate`, `Reflect`), applied in statement order. Moves of named
//! objects, lights and the camera are built here and applied later
//! (`moves.rs`).

use hgeom::{HPlane, Isometry, Point, Segment, Vertex};

use super::ranges::MAX_LENGTH;

use super::Lowerer;
use super::moves::PendingMove;
use super::table::{self, unknown_word, words};
use super::text::{and_list, reference_text};
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::Motion;
use crate::syntax::{Clause, Ident, RefSigil, Reference, Section, Value};

/// What a transformation keyword does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Transformation {
    /// `hline (%A, %B);` declares an h-line.
    Line,
    /// `hplane (%A, %B, %C);` declares an h-plane.
    Plane,
    Rotate,
    Translate,
    Reflect,
}

/// Every transformation keyword, in the order the help lists them.
const KEYWORDS: &[(&str, Transformation)] = &[
    ("hline", Transformation::Line),
    ("hplane", Transformation::Plane),
    ("Rotate", Transformation::Rotate),
    ("Translate", Transformation::Translate),
    ("Reflect", Transformation::Reflect),
];

/// The transformation keywords, in the order of [`KEYWORDS`].
pub(crate) const TRANSFORMATIONS: [&str; KEYWORDS.len()] = words!(KEYWORDS, 0);

fn keyword(name: &str) -> Option<Transformation> {
    table::find(KEYWORDS, name).map(|(_, t)| *t)
}

impl Lowerer<'_> {
    pub(super) fn transformations_section(&mut self, section: &Section) {
        for st in &section.statements {
            let (first, animate) = match &st.clauses[..] {
                [first] => (Some(first), None),
                [
                    first,
                    Clause::Apply {
                        target: None,
                        name,
                        arg: None,
                        ..
                    },
                ] if name.text == "animate" => (Some(first), Some(name.span)),
                _ => (None, None),
            };
            let Some(Clause::Apply {
                target,
                name,
                arg,
                span,
            }) = first
            else {
                self.report(
                    Diagnostic::new(Code::WrongType, st.span, "expected a transformation statement")
                        .with_help("write `hline (%A, %B);`, `hplane (%A, %B, %C);`, `%P->Rotate(L, angle);`, `%P->Translate(L);`, `%P->Translate(L, d);` or `%P->Reflect(S);`; a rotation or translation may end in `, animate`"),
                );
                continue;
            };
            let kind = keyword(&name.text);
            let is_move = matches!(
                kind,
                Some(Transformation::Rotate | Transformation::Translate | Transformation::Reflect)
            );
            if let Some(at) = animate
                && !is_move
            {
                self.report(
                    Diagnostic::new(
                        Code::NotAnimatable,
                        at,
                        format!("`{}` cannot be animated", name.text),
                    )
                    .with_help(
                        "only the transformations `Rotate` and `Translate` can end in `, animate`",
                    ),
                );
            }
            match (target, kind) {
                (None, Some(Transformation::Line)) => {
                    self.declare_line(st.label.as_ref(), name, arg.as_ref(), *span)
                }
                (None, Some(Transformation::Plane)) => {
                    self.declare_plane(st.label.as_ref(), name, arg.as_ref(), *span)
                }
                (Some(target), Some(kind)) if is_move => match target.sigil {
                    RefSigil::At => {
                        let motion = self.transformation(kind, name, arg.as_ref(), *span, animate);
                        self.moves.push(PendingMove {
                            target: (**target).clone(),
                            motion,
                        });
                    }
                    RefSigil::Hash => {
                        self.report(
                            Diagnostic::new(
                                Code::WrongType,
                                target.span,
                                format!("a material (`{}`) cannot be transformed", reference_text(target)),
                            )
                            .with_help("transformations act on points (`%P`), named objects and lights (`@name`) and the camera (`@camera`)"),
                        );
                        let _ = self.transformation(kind, name, arg.as_ref(), *span, animate);
                    }
                    RefSigil::Percent => {
                        let motion = self.transformation(kind, name, arg.as_ref(), *span, animate);
                        if let Some(motion) = motion {
                            // What is built from a moving point changes shape
                            // between frames: each frame is compiled alone.
                            self.animation.moves_points |= motion.is_animated();
                            match motion.at(self.time) {
                                Ok(iso) => self.move_point(target, &iso),
                                // Checked when the motion was built.
                                Err(_) => {
                                    let _ = self.resolve_point(target);
                                }
                            }
                        } else {
                            // Still mark the target as used so errors don't cascade into lints.
                            let _ = self.resolve_point(target);
                        }
                    }
                },
                (None, Some(_)) => self.report(
                    Diagnostic::new(
                        Code::WrongType,
                        name.span,
                        format!("`{}` needs a point to act on", name.text),
                    )
                    .with_help(format!("write `%P->{}(...)`", name.text)),
                ),
                (Some(_), _) | (None, None) => self.report(unknown_word(
                    Code::UnknownTransformation,
                    name,
                    "transformation",
                    &TRANSFORMATIONS,
                    &format!("transformations are {}", and_list(&TRANSFORMATIONS)),
                )),
            }
        }
    }

    fn declare_line(
        &mut self,
        label: Option<&Ident>,
        name: &Ident,
        arg: Option<&Value>,
        span: Span,
    ) {
        let segment = match arg {
            Some(Value::Tuple { items, .. }) if items.len() == 2 => {
                let a = self.point_arg(&items[0], "an h-line end");
                let b = self.point_arg(&items[1], "an h-line end");
                match (a, b) {
                    (Some(a), Some(b)) => match Segment::new(a, b) {
                        Ok(s) => Some(s),
                        Err(_) => {
                            self.report(
                                Diagnostic::new(
                                    Code::DegenerateLine,
                                    span,
                                    "the two points of this h-line coincide",
                                )
                                .with_help("an h-line needs two distinct points"),
                            );
                            None
                        }
                    },
                    _ => None,
                }
            }
            _ => {
                self.wrong_arity(
                    span,
                    format!("`{}` takes two points", name.text),
                    "write `hline (%A, %B);`",
                );
                None
            }
        };
        let declared = self.lines.push_declared(segment, span, label);
        self.report_refused(declared);
    }

    fn declare_plane(
        &mut self,
        label: Option<&Ident>,
        name: &Ident,
        arg: Option<&Value>,
        span: Span,
    ) {
        let plane = match arg {
            Some(Value::Tuple { items, .. }) if items.len() == 3 => {
                let vs: Vec<Option<Vertex>> = items.iter().map(|v| self.vertex_arg(v)).collect();
                match (vs[0], vs[1], vs[2]) {
                    (Some(a), Some(b), Some(c)) => match HPlane::through(&a, &b, &c) {
                        Ok(p) => Some(p),
                        Err(_) => {
                            self.report(
                                Diagnostic::new(
                                    Code::DegeneratePlane,
                                    items[0].span().to(items[2].span()),
                                    "these three points lie on one h-line, so they do not fix an h-plane",
                                )
                                .with_help("choose three points that are not on one h-line (and all distinct)"),
                            );
                            None
                        }
                    },
                    _ => None,
                }
            }
            _ => {
                self.wrong_arity(
                    span,
                    format!("`{}` takes three points", name.text),
                    "write `hplane (%A, %B, %C);`",
                );
                None
            }
        };
        let declared = self.planes.push_declared(plane, span, label);
        self.report_refused(declared);
    }

    /// The motion of a `Rotate`, `Translate` or `Reflect` statement: fixed,
    /// or with `animate` (the span of the `animate` clause) a rotation or
    /// translation of which frame `k` takes the fraction `k / (N - 1)`. An
    /// animated translation is built at this frame's time here, so that one
    /// that cannot be built is reported.
    fn transformation(
        &mut self,
        kind: Transformation,
        name: &Ident,
        arg: Option<&Value>,
        span: Span,
        animate: Option<Span>,
    ) -> Option<Motion> {
        let items: Vec<&Value> = match arg {
            Some(Value::Tuple { items, .. }) => items.iter().collect(),
            Some(v) => vec![v],
            None => Vec::new(),
        };
        let animated = match animate {
            Some(at) => {
                self.animations.push(at);
                true
            }
            None => false,
        };
        match (kind, items.as_slice()) {
            (Transformation::Rotate, [line, angle]) => {
                let line = self.resolve_line(line);
                let angle = self.number(angle);
                let (axis, angle) = (line?, angle?);
                Some(if animated {
                    Motion::Rotate { axis, angle }
                } else {
                    Motion::Fixed(Isometry::rotation_about_segment_unchecked(&axis, angle))
                })
            }
            (Transformation::Translate, [line, ..]) if items.len() <= 2 => {
                let along = match items.get(1) {
                    None => self.resolve_line(line)?,
                    Some(distance) => {
                        let line = self.resolve_line(line);
                        let d = self.number(distance);
                        self.by_distance(line?, d?, distance.span())?
                    }
                };
                let motion = Motion::Translate { along };
                match motion.at(if animated { self.time } else { 1.0 }) {
                    Ok(_) if animated => Some(motion),
                    Ok(whole) => Some(Motion::Fixed(whole)),
                    Err(e) => {
                        self.error(
                            Code::NumericFailure,
                            span,
                            format!("cannot build this translation: {e}"),
                        );
                        None
                    }
                }
            }
            (Transformation::Reflect, [plane]) => {
                if let Some(at) = animate {
                    self.report(
                        Diagnostic::new(Code::NotAnimatable, at, "a reflection cannot be animated")
                            .with_help("a reflection has no halfway state; animate a rotation or translation instead, or remove `, animate`"),
                    );
                }
                Some(Motion::Fixed(Isometry::reflection(
                    &self.resolve_plane(plane)?,
                )))
            }
            (kind, _) => {
                let usage = match kind {
                    Transformation::Rotate => {
                        "`%P->Rotate(L, angle);` (L: an h-line number, angle in radians)"
                    }
                    Transformation::Translate => {
                        "`%P->Translate(L);` (along h-line L, from its first point to its second) or `%P->Translate(L, d);` (by hyperbolic distance d along L's direction)"
                    }
                    _ => "`%P->Reflect(S);` (S: an h-plane number)",
                };
                self.wrong_arity(
                    span,
                    format!("wrong number of arguments to `{}`", name.text),
                    format!("write {usage}"),
                );
                None
            }
        }
    }

    /// The segment from `line`'s first point to the point at hyperbolic
    /// distance `d` from it along the line (towards its second point;
    /// backwards for a negative `d`): translating along it moves by `d`.
    fn by_distance(&mut self, line: Segment, d: f64, span: Span) -> Option<Segment> {
        if !(d != 0.0 && d.abs() <= MAX_LENGTH) {
            self.error(
                Code::InvalidValue,
                span,
                format!(
                    "a translation distance must be non-zero and at most {MAX_LENGTH} in size, not {}",
                    hgeom::Compact(d)
                ),
            );
            return None;
        }
        let start = line.start();
        let end = hgeom::HLine::through(&start.into(), &line.end().into())
            .and_then(|l| l.point_at(d))
            .ok()
            .filter(Point::is_representable);
        match end.and_then(|e| Segment::new(start, e).ok()) {
            Some(segment) => Some(segment),
            None => {
                self.error(
                    Code::NumericFailure,
                    span,
                    format!(
                        "the point {} along this line leaves what f64 can represent",
                        hgeom::Compact(d)
                    ),
                );
                None
            }
        }
    }

    fn move_point(&mut self, target: &Reference, iso: &Isometry) {
        let Some(i) = self.resolve_point(target) else {
            return;
        };
        let moved = match self.points[i].position {
            Some(Vertex::Interior(q)) => match iso.checked_apply(&q) {
                Ok(p) => Some(Vertex::Interior(p)),
                Err(_) => {
                    self.report(
                        Diagnostic::new(
                            Code::NumericFailure,
                            target.span,
                            format!(
                                "this moves `{}` so close to the absolute that f64 cannot represent it",
                                reference_text(target)
                            ),
                        )
                        .with_help("f64 holds ball points out to about distance 37 from the origin; move it less far"),
                    );
                    None
                }
            },
            Some(Vertex::Ideal(q)) => Some(Vertex::Ideal(iso.apply_ideal(&q))),
            None => None,
        };
        self.points[i].position = moved;
    }
}
