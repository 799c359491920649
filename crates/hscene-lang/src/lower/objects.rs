//! The `Objects` section: the table of object keywords, argument and option
//! checking, and the construction of every shape.
//!
//! An object statement is
//!
//! ```text
//! (name:)? Keyword arg, arg, ..., #material (, option = value)* ;
//! ```
//!
//! Positional arguments come first and are checked against the keyword's
//! parameter list ([`Param`]); options (`wireframe`, `edges`,
//! `edge_material`, `at`, `smooth`) follow. Every argument is checked even after one
//! fails, so one statement reports all of its problems.

use std::collections::HashMap;

use hgeom::{
    ConvexPolygon, GeomError, HCylinder, HLine, HSphere, Horosphere, IdealPoint, Isometry,
    Platonic, Point, Polyhedron, Rod, Vertex,
};

use super::figures::{self, Figure};
use super::{Lowerer, TargetSlot};
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{MaterialId, Object, Shape};
use crate::syntax::{Clause, Ident, Statement, Value};

/// What an object keyword builds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Kind {
    Sphere,
    Polygon,
    Rod,
    Cylinder,
    Plane,
    Horosphere,
    Platonic(Platonic),
    /// A triangle mesh read from an OBJ or PLY file.
    Mesh,
    /// A predefined figure centred at the origin (see `figures.rs`).
    Figure(Figure),
}

/// Every object keyword, in the order the help lists them.
pub(crate) fn object_names() -> Vec<&'static str> {
    let mut names = vec![
        "Sphere",
        "Polygon",
        "Rod",
        "Cylinder",
        "Plane",
        "Horosphere",
        "Mesh",
        "Tetrahedron",
        "Cube",
        "Hexahedron",
        "Octahedron",
        "Dodecahedron",
        "Icosahedron",
    ];
    names.extend(figures::ALL.iter().map(|(name, _)| *name));
    names
}

fn kind_by_name(name: &str) -> Option<Kind> {
    Some(match name {
        "Sphere" => Kind::Sphere,
        "Polygon" => Kind::Polygon,
        "Rod" => Kind::Rod,
        "Cylinder" => Kind::Cylinder,
        "Plane" => Kind::Plane,
        "Horosphere" => Kind::Horosphere,
        "Mesh" => Kind::Mesh,
        "Tetrahedron" => Kind::Platonic(Platonic::Tetrahedron),
        "Cube" | "Hexahedron" => Kind::Platonic(Platonic::Cube),
        "Octahedron" => Kind::Platonic(Platonic::Octahedron),
        "Dodecahedron" => Kind::Platonic(Platonic::Dodecahedron),
        "Icosahedron" => Kind::Platonic(Platonic::Icosahedron),
        other => Kind::Figure(figures::by_name(other)?),
    })
}

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
}

/// A checked positional argument.
#[derive(Clone, Debug)]
pub(super) enum Arg {
    Point(Point),
    Vertex(Vertex),
    Ideal(IdealPoint),
    Number(f64),
    Vertices(Vec<Vertex>),
    File(String),
}

impl Arg {
    pub(super) fn number(&self) -> f64 {
        match self {
            Arg::Number(x) => *x,
            _ => f64::NAN,
        }
    }
}

/// The signature of an object keyword.
struct Spec {
    params: &'static [Param],
    /// "a centre, a radius and a material", for arity messages.
    takes: &'static str,
    /// The help for arity errors; `{name}` is replaced by the keyword.
    usage: &'static str,
    /// Polygons and polyhedra: `wireframe`, `edges`, `edge_material` apply.
    faceted: bool,
    /// Predefined figures centred at the origin: `at` applies.
    centred: bool,
}

fn spec(kind: Kind) -> Spec {
    match kind {
        Kind::Sphere => Spec {
            params: &[
                Param::Point("a sphere centre"),
                Param::Length("the sphere radius"),
            ],
            takes: "a centre, a radius and a material",
            usage: "write `Sphere %P, radius, #M;` (radius is hyperbolic)",
            faceted: false,
            centred: false,
        },
        Kind::Polygon => Spec {
            params: &[Param::Vertices],
            takes: "a vertex list and a material",
            usage: "write `Polygon (%1, %2, %3), #M;`",
            faceted: true,
            centred: false,
        },
        Kind::Rod => Spec {
            params: &[
                Param::Vertex("a rod end"),
                Param::Vertex("a rod end"),
                Param::Length("the rod radius"),
            ],
            takes: "two end points, a radius and a material",
            usage: "write `Rod %A, %B, radius, #M;` (the points within `radius` of the h-segment AB)",
            faceted: false,
            centred: false,
        },
        Kind::Cylinder => Spec {
            params: &[
                Param::Vertex("a point of the cylinder's axis"),
                Param::Vertex("a point of the cylinder's axis"),
                Param::Length("the cylinder radius"),
            ],
            takes: "two points of its axis, a radius and a material",
            usage: "write `Cylinder %A, %B, radius, #M;` (the points at `radius` from the h-line AB)",
            faceted: false,
            centred: false,
        },
        Kind::Plane => Spec {
            params: &[
                Param::Vertex("a point of the plane"),
                Param::Vertex("a point of the plane"),
                Param::Vertex("a point of the plane"),
            ],
            takes: "three points and a material",
            usage: "write `Plane %A, %B, %C, #M;` (its outside is where the right-hand rule on A, B, C points)",
            faceted: false,
            centred: false,
        },
        Kind::Horosphere => Spec {
            params: &[
                Param::Ideal("the horosphere centre"),
                Param::Point("the point the horosphere passes through"),
            ],
            takes: "an ideal centre, a point on it and a material",
            usage: "write `Horosphere %ideal, %through, #M;` (the centre is a point on the absolute)",
            faceted: false,
            centred: false,
        },
        Kind::Mesh => Spec {
            params: &[Param::File("the mesh file"), Param::Length("the mesh size")],
            takes: "a file name, a size and a material",
            usage: "write `Mesh \"bunny.ply\", size, #M;` (an OBJ or PLY file, relative to the scene file; size: the hyperbolic distance from the mesh's centre to its farthest vertex)",
            faceted: false,
            centred: true,
        },
        Kind::Platonic(_) => Spec {
            params: &[Param::Length("the size")],
            takes: "a size and a material",
            usage: "write `{name} size, #M;` (size: hyperbolic circumradius)",
            faceted: true,
            centred: true,
        },
        Kind::Figure(f) => {
            let s = figures::spec(f);
            Spec {
                params: s.params,
                takes: s.takes,
                usage: s.usage,
                faceted: true,
                centred: true,
            }
        }
    }
}

/// The options of faceted objects, after checking.
#[derive(Default)]
struct Options {
    /// `wireframe = t`: edges only, as rods of radius `t`.
    wireframe: Option<(f64, Span)>,
    /// `edges = t`: faces plus rods of radius `t`.
    edges: Option<(f64, Span)>,
    /// `edge_material = #M`: the rods' material.
    edge_material: Option<MaterialId>,
    /// `at = %P`: the figure's centre, moved from the origin.
    at: Option<(Point, Span)>,
    /// `smooth = ANGLE`: a mesh's crease angle in degrees.
    pub(super) smooth: Option<f64>,
}

pub(crate) const OPTION_NAMES: [&str; 5] = ["wireframe", "edges", "edge_material", "at", "smooth"];

/// Whether the keyword takes `smooth` (only `Mesh`: a file as its first
/// parameter).
fn smoothable(spec: &Spec) -> bool {
    matches!(spec.params.first(), Some(Param::File(_)))
}

impl Lowerer<'_> {
    pub(super) fn objects_section(&mut self, section: &crate::syntax::Section) {
        for st in &section.statements {
            let indices = self.object_statement(st);
            if let Some(label) = &st.label {
                self.declare_target(label, TargetSlot::Objects(indices));
            }
        }
    }

    /// Lowers one object statement; returns the indices of the IR objects it
    /// produced (none on error, two for `edges = t`, one per cell for
    /// tessellations).
    fn object_statement(&mut self, st: &Statement) -> Vec<usize> {
        let Some((
            Clause::Apply {
                target: None,
                name,
                arg,
                ..
            },
            rest,
        )) = st.clauses.split_first()
        else {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    st.span,
                    "expected an object, e.g. `Sphere %1, 0.05, #1;`",
                )
                .with_help(format!("objects are {}", object_names().join(", "))),
            );
            return Vec::new();
        };
        let Some(kind) = kind_by_name(&name.text) else {
            self.unknown_object(name);
            return Vec::new();
        };
        // Positional values first, then `key = value` options.
        let mut positional: Vec<&Value> = arg.iter().collect();
        let mut options: Vec<(&Ident, &Value)> = Vec::new();
        for clause in rest {
            match clause {
                Clause::Value(v) if options.is_empty() => positional.push(v),
                Clause::Value(v) => {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            v.span(),
                            "positional arguments must come before the options",
                        )
                        .with_help("move the options (`key = value`) to the end of the statement"),
                    );
                    return Vec::new();
                }
                Clause::Assign { key, value, .. } => options.push((key, value)),
                Clause::Apply { .. } => {
                    self.error(
                        Code::WrongType,
                        clause.span(),
                        "object arguments must be values separated by `,`",
                    );
                    return Vec::new();
                }
            }
        }
        let spec = spec(kind);
        let usage = spec.usage.replace("{name}", &name.text);
        let wanted = spec.params.len() + 1;
        if positional.len() != wanted {
            let span = if positional.len() > wanted {
                positional[wanted]
                    .span()
                    .to(positional[positional.len() - 1].span())
            } else {
                st.span
            };
            self.wrong_arity(span, format!("`{}` takes {}", name.text, spec.takes), usage);
            return Vec::new();
        }
        let mut ok = true;
        let mut args = Vec::with_capacity(spec.params.len());
        for (param, value) in spec.params.iter().zip(&positional) {
            match self.object_arg(*param, value, &usage) {
                Some(a) => args.push(a),
                None => ok = false,
            }
        }
        let material = self.material_arg(positional[wanted - 1]);
        let opts = self.object_options(name, &spec, &options);
        let (Some(material), Some(opts), true) = (material, opts, ok) else {
            return Vec::new();
        };
        if let Kind::Figure(f) = kind {
            let depth = args.first().map(Arg::number);
            let (faces, edges) = (
                opts.wireframe.is_none(),
                opts.wireframe.or(opts.edges).is_some(),
            );
            let estimate = super::budget::figure_estimate(f, depth, faces, edges);
            if !self.fits(estimate, st.span) {
                return Vec::new();
            }
        }
        let Some(built) = self.build(kind, name, &args, &positional, opts.smooth) else {
            return Vec::new();
        };
        let placed = self.place(built, material, opts, st);
        let cost = placed
            .iter()
            .map(|&i| self.objects[i].0.shape.primitive_count())
            .sum();
        if !self.charge(cost, st.span) {
            return Vec::new();
        }
        placed
    }

    fn unknown_object(&mut self, name: &Ident) {
        let other = name.text.as_str();
        let names = object_names();
        let mut d = Diagnostic::new(
            Code::UnknownObject,
            name.span,
            format!("unknown object {}", super::quote(other)),
        );
        d = if let Some(s) = names.iter().find(|s| s.eq_ignore_ascii_case(other)) {
            d.with_help(format!(
                "object names are case-sensitive: did you mean `{s}`?"
            ))
        } else if let Some(s) = closest(other, &names) {
            d.with_help(format!("did you mean `{s}`?"))
        } else {
            d.with_help(format!("objects are {}", names.join(", ")))
        };
        self.report(d);
    }

    /// Checks one positional argument against its parameter.
    fn object_arg(&mut self, param: Param, value: &Value, usage: &str) -> Option<Arg> {
        match param {
            Param::Point(role) => self.point_arg(value, role).map(Arg::Point),
            Param::Vertex(role) => self.vertex_arg_for(value, role).map(Arg::Vertex),
            Param::Ideal(role) => self.ideal_arg(value, role).map(Arg::Ideal),
            Param::Length(what) => self.length(value, what).map(Arg::Number),
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

    /// A point that may be ideal, with a role for the "wrong type" message.
    fn vertex_arg_for(&mut self, value: &Value, role: &str) -> Option<Vertex> {
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
    fn ideal_arg(&mut self, value: &Value, role: &str) -> Option<IdealPoint> {
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

    fn object_options(
        &mut self,
        name: &Ident,
        spec: &Spec,
        options: &[(&Ident, &Value)],
    ) -> Option<Options> {
        let mut out = Options::default();
        let mut ok = true;
        let mut seen: HashMap<&str, Span> = HashMap::new();
        for (key, value) in options {
            let allowed = match key.text.as_str() {
                "wireframe" | "edges" | "edge_material" => spec.faceted,
                "at" => spec.centred,
                "smooth" => smoothable(spec),
                _ => false,
            };
            if !allowed {
                ok = false;
                let mut d = if OPTION_NAMES.contains(&key.text.as_str()) {
                    Diagnostic::new(
                        Code::UnknownKey,
                        key.span,
                        format!("`{}` has no option `{}`", name.text, key.text),
                    )
                } else {
                    Diagnostic::new(
                        Code::UnknownKey,
                        key.span,
                        format!("unknown object option `{}`", key.text),
                    )
                };
                let accepted: Vec<&str> = OPTION_NAMES
                    .iter()
                    .copied()
                    .filter(|o| match *o {
                        "at" => spec.centred,
                        "smooth" => smoothable(spec),
                        _ => spec.faceted,
                    })
                    .collect();
                d = match (accepted.is_empty(), closest(&key.text, &accepted)) {
                    (true, _) => d.with_help(format!("`{}` takes no options", name.text)),
                    (false, Some(s)) if s != key.text => d.with_help(format!(
                        "did you mean `{s}`? The options of `{}` are {}",
                        name.text,
                        accepted.join(", ")
                    )),
                    (false, _) => d.with_help(format!(
                        "the options of `{}` are {}",
                        name.text,
                        accepted.join(", ")
                    )),
                };
                self.report(d);
                continue;
            }
            if seen.insert(key.text.as_str(), key.span).is_some() {
                self.report(
                    Diagnostic::new(
                        Code::DuplicateKey,
                        key.span,
                        format!("`{}` is set twice; the last value wins", key.text),
                    )
                    .with_help("remove one of the two"),
                );
            }
            match key.text.as_str() {
                "wireframe" | "edges" => {
                    let what = format!("the `{}` thickness", key.text);
                    match self.positive(value, &what) {
                        Some(t) if key.text == "wireframe" => {
                            out.wireframe = Some((t, key.span.to(value.span())))
                        }
                        Some(t) => out.edges = Some((t, key.span.to(value.span()))),
                        None => ok = false,
                    }
                }
                "edge_material" => match self.material_arg(value) {
                    Some(m) => out.edge_material = Some(m),
                    None => ok = false,
                },
                "smooth" => match self.crease_angle(value) {
                    Some(a) => out.smooth = Some(a),
                    None => ok = false,
                },
                _ => match self.point_arg(value, "the centre (`at`)") {
                    Some(p) => out.at = Some((p, value.span())),
                    None => ok = false,
                },
            }
        }
        if let (Some((_, w)), Some((_, e))) = (out.wireframe, out.edges) {
            let second = if w.start < e.start { e } else { w };
            self.report(
                Diagnostic::new(
                    Code::ConflictingOptions,
                    second,
                    "`wireframe` and `edges` cannot both be given",
                )
                .with_help("`wireframe = t` draws only the edges; `edges = t` draws the faces and the edges: keep one"),
            );
            ok = false;
        }
        let drawn = out.wireframe.is_some() || out.edges.is_some();
        let useless = options
            .iter()
            .find(|(k, _)| k.text == "edge_material" && !drawn);
        if let Some((key, _)) = useless {
            self.report(
                Diagnostic::new(
                    Code::IneffectiveOption,
                    key.span,
                    "`edge_material` has no effect without `wireframe` or `edges`",
                )
                .with_help("add `edges = 0.01` (faces and edges) or `wireframe = 0.01` (edges only), or remove `edge_material`"),
            );
        }
        ok.then_some(out)
    }

    /// Builds the shape(s) of a checked statement: one shape, or for
    /// polygons, polyhedra and figures the faceted shapes (each
    /// `Shape::Polygon` or `Shape::Polyhedron`) whose edges the wireframe
    /// options draw.
    fn build(
        &mut self,
        kind: Kind,
        name: &Ident,
        args: &[Arg],
        values: &[&Value],
        smooth: Option<f64>,
    ) -> Option<Vec<Shape>> {
        match (kind, args) {
            (Kind::Sphere, [Arg::Point(c), Arg::Number(r)]) => HSphere::new(*c, *r)
                .map_err(|e| self.geom_failure(values[1].span(), "this sphere", &e))
                .ok()
                .map(|s| vec![Shape::Sphere(s)]),
            (Kind::Polygon, [Arg::Vertices(vs)]) => {
                let Value::Tuple { items, span } = values[0] else {
                    return None;
                };
                self.convex_polygon(vs.clone(), items, *span)
                    .map(|p| vec![Shape::Polygon(p)])
            }
            (Kind::Rod, [Arg::Vertex(a), Arg::Vertex(b), Arg::Number(r)]) => {
                match Rod::new(*a, *b, *r) {
                    Ok(rod) => Some(vec![Shape::Rod(rod)]),
                    Err(e) => {
                        self.line_failure(values[0].span(), values[1].span(), "rod", &e);
                        None
                    }
                }
            }
            (Kind::Cylinder, [Arg::Vertex(a), Arg::Vertex(b), Arg::Number(r)]) => {
                match HLine::through(a, b).and_then(|l| HCylinder::new(l, *r)) {
                    Ok(c) => Some(vec![Shape::Cylinder(c)]),
                    Err(e) => {
                        self.line_failure(values[0].span(), values[1].span(), "cylinder", &e);
                        None
                    }
                }
            }
            (Kind::Plane, [Arg::Vertex(a), Arg::Vertex(b), Arg::Vertex(c)]) => {
                // A triangle's plane is oriented by the right-hand rule on its
                // vertex order, the rule polygons follow too.
                match ConvexPolygon::new(vec![*a, *b, *c]) {
                    Ok(t) => Some(vec![Shape::Plane(t.plane())]),
                    Err(_) => {
                        self.report(
                            Diagnostic::new(
                                Code::DegeneratePlane,
                                values[0].span().to(values[2].span()),
                                "these three points lie on one h-line, so they do not fix an h-plane",
                            )
                            .with_help("choose three points that are not on one h-line (and all distinct)"),
                        );
                        None
                    }
                }
            }
            (Kind::Horosphere, [Arg::Ideal(c), Arg::Point(p)]) => match Horosphere::new(*c, p) {
                Ok(h) => Some(vec![Shape::Horosphere(h)]),
                Err(e) => {
                    self.geom_failure(values[1].span(), "this horosphere", &e);
                    None
                }
            },
            (Kind::Mesh, [Arg::File(file), Arg::Number(size)]) => self
                .mesh(file, *size, values, smooth)
                .map(|m| vec![Shape::Mesh(m)]),
            (Kind::Platonic(k), [Arg::Number(size)]) => match Polyhedron::platonic(k, *size) {
                Ok(p) => Some(vec![Shape::Polyhedron(p)]),
                Err(e) => {
                    self.error(
                        Code::NumericFailure,
                        values[0].span(),
                        format!("cannot build this polyhedron: {e}"),
                    );
                    None
                }
            },
            (Kind::Figure(f), args) => match figures::build(f, args) {
                Ok(shapes) => Some(shapes),
                Err(e) => {
                    self.figure_failure(f, name, values, &e);
                    None
                }
            },
            // The arguments were checked against the same table.
            _ => None,
        }
    }

    /// A failed rod or cylinder: coincident points, or a numeric problem.
    fn line_failure(&mut self, first: Span, second: Span, what: &str, e: &GeomError) {
        match e {
            GeomError::Coincident => self.report(
                Diagnostic::new(
                    Code::DegenerateLine,
                    second,
                    format!("the two points of this {what} coincide, so they do not fix an h-line"),
                )
                .with_label("same point as the first")
                .with_help("use two different points"),
            ),
            other => self.geom_failure(first.to(second), &format!("this {what}"), other),
        }
    }

    /// A predefined figure that hgeom refused to build.
    fn figure_failure(&mut self, f: Figure, name: &Ident, values: &[&Value], e: &GeomError) {
        // The parameters (everything before the material) are at fault.
        let params = &values[..values.len().saturating_sub(1)];
        let span = match (params.first(), params.last()) {
            (Some(a), Some(b)) => a.span().to(b.span()),
            _ => name.span,
        };
        match e {
            GeomError::LambertOpen { .. }
            | GeomError::BadAngle(_)
            | GeomError::VertexCountOutOfRange { .. } => self.report(
                Diagnostic::new(
                    Code::ImpossibleFigure,
                    span,
                    format!("there is no `{}` with these values: {e}", name.text),
                )
                .with_help(figures::limits(f)),
            ),
            GeomError::TooManyCells { limit } => self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    span,
                    format!("this would build more than {limit} cells"),
                )
                .with_help("use a smaller depth"),
            ),
            other => self.geom_failure(span, &format!("this `{}`", name.text), other),
        }
    }

    pub(super) fn geom_failure(&mut self, span: Span, what: &str, e: &GeomError) {
        self.report(
            Diagnostic::new(
                Code::NumericFailure,
                span,
                format!("cannot build {what}: {e}"),
            )
            .with_help("f64 holds ball points out to about distance 37 from the origin; use smaller sizes or points farther from the absolute"),
        );
    }

    /// A convex polygon from checked vertices; errors name the vertex.
    pub(super) fn convex_polygon(
        &mut self,
        vertices: Vec<Vertex>,
        items: &[Value],
        list_span: Span,
    ) -> Option<ConvexPolygon> {
        match ConvexPolygon::new(vertices) {
            Ok(p) => Some(p),
            Err(e) => {
                let at = |i: usize| items.get(i).map_or(list_span, Value::span);
                let (code, msg, item_span) = match e {
                    GeomError::TooFewVertices(n) => (
                        Code::WrongArity,
                        format!("a polygon needs at least 3 vertices, got {n}"),
                        list_span,
                    ),
                    GeomError::NonPlanar { index, .. } => (
                        Code::NonPlanarPolygon,
                        format!("vertex {} is not on the h-plane of the others", index + 1),
                        at(index),
                    ),
                    GeomError::NonConvex { index } => (
                        Code::NonConvexPolygon,
                        format!(
                            "the polygon is not convex at vertex {} (or its vertices are not in cyclic order)",
                            index + 1
                        ),
                        at(index),
                    ),
                    other => (
                        Code::NonConvexPolygon,
                        format!("degenerate polygon: {other}"),
                        list_span,
                    ),
                };
                self.report(Diagnostic::new(code, item_span, msg).with_help("list the vertices of a convex planar polygon in order around it; split other polygons into convex pieces"));
                None
            }
        }
    }

    /// Applies `at`, draws the edges, pushes the IR objects and returns
    /// their indices.
    fn place(
        &mut self,
        mut shapes: Vec<Shape>,
        material: MaterialId,
        opts: Options,
        st: &Statement,
    ) -> Vec<usize> {
        let name = st.label.as_ref().map(|l| l.text.clone());
        let mut frame = Isometry::IDENTITY;
        if let Some((centre, span)) = opts.at {
            let iso = Isometry::transvection_from_origin(centre);
            frame = iso;
            let mut moved = Vec::with_capacity(shapes.len());
            for s in &shapes {
                match super::moves::transform_shape(s, &iso) {
                    Some(m) => moved.push(m),
                    None => {
                        self.report(
                            Diagnostic::new(
                                Code::NumericFailure,
                                span,
                                "moving the figure here puts part of it so close to the absolute that f64 cannot represent it",
                            )
                            .with_help("f64 holds ball points out to about distance 37 from the origin; choose a centre nearer the origin or a smaller figure"),
                        );
                        return Vec::new();
                    }
                }
            }
            shapes = moved;
        }
        let thickness = opts.wireframe.or(opts.edges);
        let rods = match thickness {
            Some((t, span)) => match wireframe(&shapes, t) {
                Ok(rods) => Some(rods),
                Err(e) => {
                    self.geom_failure(span, "the edges", &e);
                    return Vec::new();
                }
            },
            None => None,
        };
        let mut out = Vec::new();
        if opts.wireframe.is_none() {
            for shape in shapes {
                out.push(self.objects.len());
                let frame = match &shape {
                    Shape::Sphere(s) if opts.at.is_none() => {
                        Isometry::transvection_from_origin(s.center())
                    }
                    _ => frame,
                };
                self.objects.push((
                    Object {
                        shape,
                        material,
                        name: name.clone(),
                        frame,
                    },
                    st.span,
                ));
            }
        }
        if let Some(rods) = rods {
            out.push(self.objects.len());
            self.objects.push((
                Object {
                    shape: Shape::Wireframe(rods),
                    material: opts.edge_material.unwrap_or(material),
                    name,
                    frame,
                },
                st.span,
            ));
        }
        out
    }
}

/// The rods along every edge of the faces, each edge once.
///
/// Faces of one polyhedron (and neighbouring cells of a tessellation) share
/// edges whose end points agree only to rounding, so ends are matched on a
/// grid of 1e-9 in ball coordinates: much finer than any two distinct
/// vertices of a scene, much coarser than rounding.
pub(super) fn wireframe(shapes: &[Shape], radius: f64) -> Result<Vec<Rod>, GeomError> {
    type Key = [i64; 3];
    let key = |v: &Vertex| -> Key {
        let c = v.coords() * 1e9;
        [c.x.round() as i64, c.y.round() as i64, c.z.round() as i64]
    };
    let mut seen: std::collections::HashSet<(Key, Key)> = std::collections::HashSet::new();
    let mut rods = Vec::new();
    let mut add_polygon = |p: &ConvexPolygon, rods: &mut Vec<Rod>| -> Result<(), GeomError> {
        let vs = p.vertices();
        for (i, a) in vs.iter().enumerate() {
            let b = &vs[(i + 1) % vs.len()];
            let (ka, kb) = (key(a), key(b));
            let k = if ka <= kb { (ka, kb) } else { (kb, ka) };
            if seen.insert(k) {
                rods.push(Rod::new(*a, *b, radius)?);
            }
        }
        Ok(())
    };
    for shape in shapes {
        match shape {
            Shape::Polygon(p) => add_polygon(p, &mut rods)?,
            Shape::Polyhedron(p) => {
                for f in p.faces() {
                    add_polygon(f, &mut rods)?;
                }
            }
            // Only faceted shapes reach here.
            _ => {}
        }
    }
    Ok(rods)
}

/// Most candidates a "did you mean" compares.
pub(super) const MAX_CANDIDATES: usize = 1000;

/// The candidate nearest to `word` by edit distance (ignoring case), if it
/// is close enough to be a plausible typo.
///
/// Ties go to the alphabetically first candidate, so the answer does not
/// depend on the candidates' order. Long words and very long candidate lists
/// get no suggestion, which keeps the cost bounded.
pub(super) fn closest<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    const MAX_WORD: usize = 64;
    if word.len() > MAX_WORD || candidates.len() > MAX_CANDIDATES {
        return None;
    }
    let w = word.to_ascii_lowercase();
    let limit = |c: &str| 2.max(c.len() / 4);
    candidates
        .iter()
        .filter(|c| c.len().abs_diff(w.len()) <= limit(c))
        .map(|c| (edit_distance(&w, &c.to_ascii_lowercase()), *c))
        .filter(|(d, c)| *d <= limit(c) && *d < c.len())
        .min_by_key(|&(d, c)| (d, c))
        .map(|(_, c)| c)
}

/// Levenshtein distance over bytes (names are ASCII identifiers).
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            cur[j + 1] = (prev[j] + usize::from(ca != cb))
                .min(prev[j + 1] + 1)
                .min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edit_distance_and_closest() {
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(closest("Spere", &["Sphere", "Polygon"]), Some("Sphere"));
        assert_eq!(
            closest("wirefrme", &["wireframe", "edges"]),
            Some("wireframe")
        );
        assert_eq!(closest("Xyz", &["Sphere", "Polygon"]), None);
    }
}
