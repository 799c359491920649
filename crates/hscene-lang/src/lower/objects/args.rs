//! The positional arguments of an object statement, checked against the
//! parameters of its keyword.

use hgeom::{IdealPoint, Point, Schlafli, Vertex};

use crate::diagnostic::{Code, Diagnostic};
use crate::lower::Lowerer;
use crate::syntax::Value;

/// One positional parameter of an object (the material, always last, is
/// not listed). The strings name the argument in messages.
#[derive(Clone, Copy, Debug)]
pub(super) enum Param {
    /// An h-point (not ideal), e.g. a sphere centre.
    Point(&'static str),
    /// An h-point or an ideal point, e.g. a rod end.
    Vertex(&'static str),
    /// An ideal point, e.g. a horosphere centre.
    Ideal(&'static str),
    /// A positive hyperbolic length.
    Length(&'static str),
    /// A whole number in `min..=max`.
    Count(&'static str, u64, u64),
    /// A parenthesised vertex list `(%1, %2, ...)`.
    Vertices,
    /// A file name in quotes.
    File(&'static str),
    /// A Schläfli symbol `{p,q,r}` of a hyperbolic regular honeycomb.
    Symbol,
}

/// A checked positional argument.
#[derive(Clone, Debug)]
pub(super) enum Arg {
    Point(Point),
    Vertex(Vertex),
    Ideal(IdealPoint),
    /// A length, or a count (a whole number in its range).
    Number(f64),
    Vertices(Vec<Vertex>),
    File(String),
    Symbol(Schlafli),
}

impl Arg {
    /// The value of a length or a count; `None` for other arguments.
    pub(super) fn number(&self) -> Option<f64> {
        match self {
            Arg::Number(x) => Some(*x),
            _ => None,
        }
    }
}

impl Lowerer<'_> {
    /// Checks one positional argument against its parameter.
    pub(super) fn object_arg(&mut self, param: Param, value: &Value, usage: &str) -> Option<Arg> {
        match param {
            Param::Point(role) => self.point_arg(value, role).map(Arg::Point),
            Param::Vertex(role) => self.vertex_arg_for(value, role).map(Arg::Vertex),
            Param::Ideal(role) => self.ideal_arg(value, role).map(Arg::Ideal),
            Param::Length(what) => self.length(value, what).map(Arg::Number),
            Param::Symbol => self.schlafli(value, usage).map(Arg::Symbol),
            Param::Count(what, min, max) => {
                let x = self.number(value)?;
                if x.fract() == 0.0 && x >= min as f64 && x <= max as f64 {
                    Some(Arg::Number(x))
                } else {
                    self.report(
                        Diagnostic::new(
                            Code::InvalidValue,
                            value.span(),
                            format!(
                                "{what} must be a whole number from {min} to {max}, got {}",
                                hgeom::Compact(x)
                            ),
                        )
                        .with_help(usage.to_string()),
                    );
                    None
                }
            }
            Param::File(role) => match value {
                Value::Str { text, .. } => Some(Arg::File(text.clone())),
                _ => {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            value.span(),
                            format!(
                                "expected {role} as a name in quotes, found {}",
                                value.describe()
                            ),
                        )
                        .with_help(usage.to_string()),
                    );
                    None
                }
            },
            Param::Vertices => {
                let Value::Tuple { items, .. } = value else {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            value.span(),
                            format!(
                                "expected a vertex list `(%1, %2, %3)`, found {}",
                                value.describe()
                            ),
                        )
                        .with_help("write `Polygon (%1, %2, %3), #M;`"),
                    );
                    return None;
                };
                let mut vertices = Vec::with_capacity(items.len());
                let mut ok = true;
                for item in items {
                    match self.vertex_arg(item) {
                        Some(v) => vertices.push(v),
                        None => ok = false,
                    }
                }
                ok.then_some(Arg::Vertices(vertices))
            }
        }
    }
}
