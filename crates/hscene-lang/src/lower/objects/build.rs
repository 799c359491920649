//! Building the shapes of a checked object statement, and the messages
//! for shapes hgeom refuses to build.

use hgeom::{
    ConvexPolygon, GeomError, HCylinder, HLine, HSphere, Horosphere, Polyhedron, Rod, Vertex,
};

use super::args::Arg;
use super::built::Built;
use super::figures::{self, Figure, FigureError};
use super::keywords::ObjectKeyword;
use super::options::ObjectOptions;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::Shape;
use crate::lower::Lowerer;
use crate::syntax::{Ident, Value};

impl Lowerer<'_> {
    /// Builds the shape(s) of a checked statement: one shape, or for
    /// polygons, polyhedra and figures the faceted shapes (each
    /// `Shape::Polygon` or `Shape::Polyhedron`) whose edges the wireframe
    /// options draw; a tessellation as the copies of its cell
    /// ([`Built::Copies`]).
    pub(super) fn build(
        &mut self,
        kind: ObjectKeyword,
        name: &Ident,
        args: &[Arg],
        values: &[&Value],
        opts: &mut ObjectOptions,
        statement: Span,
    ) -> Option<Built> {
        // Exhaustive over the keywords, so a new keyword without a case here
        // does not compile; the arguments were checked against the keyword's
        // row, so a mismatch (`None`) follows an error already reported.
        let shapes = match kind {
            ObjectKeyword::Sphere => {
                let [Arg::Point(c), Arg::Number(r)] = args else {
                    return None;
                };
                HSphere::new(*c, *r)
                    .map_err(|e| self.geom_failure(values[1].span(), "this sphere", &e))
                    .ok()
                    .map(|s| vec![Shape::Sphere(s)])
            }
            ObjectKeyword::Polygon => {
                let [Arg::Vertices(vs)] = args else {
                    return None;
                };
                let Value::Tuple { items, span } = values[0] else {
                    return None;
                };
                self.convex_polygon(vs.clone(), items, *span)
                    .map(|p| vec![Shape::Polygon(Box::new(p))])
            }
            ObjectKeyword::Rod => {
                let [Arg::Vertex(a), Arg::Vertex(b), Arg::Number(r)] = args else {
                    return None;
                };
                match Rod::new(*a, *b, *r) {
                    Ok(rod) => Some(vec![Shape::Rod(Box::new(rod))]),
                    Err(e) => {
                        self.line_failure(values[0].span(), values[1].span(), "rod", &e);
                        None
                    }
                }
            }
            ObjectKeyword::Cylinder => {
                let [Arg::Vertex(a), Arg::Vertex(b), Arg::Number(r)] = args else {
                    return None;
                };
                match HLine::through(a, b).and_then(|l| HCylinder::new(l, *r)) {
                    Ok(c) => Some(vec![Shape::Cylinder(Box::new(c))]),
                    Err(e) => {
                        self.line_failure(values[0].span(), values[1].span(), "cylinder", &e);
                        None
                    }
                }
            }
            ObjectKeyword::Plane => {
                let [Arg::Vertex(a), Arg::Vertex(b), Arg::Vertex(c)] = args else {
                    return None;
                };
                // A triangle's plane is oriented by the right-hand rule on its
                // vertex order, the rule polygons follow too.
                match ConvexPolygon::new(vec![*a, *b, *c]) {
                    Ok(t) => Some(vec![Shape::Plane(Box::new(t.plane()))]),
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
            ObjectKeyword::Horosphere => {
                let [Arg::Ideal(c), Arg::Point(p)] = args else {
                    return None;
                };
                match Horosphere::new(*c, p) {
                    Ok(h) => Some(vec![Shape::Horosphere(h)]),
                    Err(e) => {
                        self.geom_failure(values[1].span(), "this horosphere", &e);
                        None
                    }
                }
            }
            ObjectKeyword::Mesh => {
                let [Arg::File(file), Arg::Number(size)] = args else {
                    return None;
                };
                self.mesh(file, *size, values, opts.smooth)
                    .map(|m| vec![Shape::Mesh(Box::new(m))])
            }
            ObjectKeyword::Platonic(k) => {
                let [Arg::Number(size)] = args else {
                    return None;
                };
                match Polyhedron::platonic(k, *size) {
                    Ok(p) => Some(vec![Shape::Polyhedron(p)]),
                    Err(e) => {
                        self.error(
                            Code::NumericFailure,
                            values[0].span(),
                            format!("cannot build this polyhedron: {e}"),
                        );
                        None
                    }
                }
            }
            ObjectKeyword::Figure(f) => {
                return match figures::build(f, args) {
                    Ok(built) => Some(built),
                    Err(FigureError::Geom(e)) => {
                        self.figure_failure(f, name, values, &e);
                        None
                    }
                    // The arguments were checked against the same table.
                    Err(FigureError::Arguments) => None,
                };
            }
            ObjectKeyword::Honeycomb => {
                let [Arg::Symbol(symbol)] = args else {
                    return None;
                };
                self.honeycomb(*symbol, opts, statement)
            }
        };
        shapes.map(Built::Shapes)
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
    fn convex_polygon(
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
}
