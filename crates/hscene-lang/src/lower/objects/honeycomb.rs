//! `Honeycomb {p,q,r}, #M [, edges = w] [, faces = #F] [, vertices = r]
//! [, depth = N] [, colors = (#A, ...)] [, rings = (i, ...)] [, at = %P];`:
//! the Schläfli symbol checked (which geometry a symbol that is not one of
//! the 15 belongs to), the ringed nodes of a uniform honeycomb, the style
//! and the materials of the parts, and hgeom's walking surface.

use hgeom::{
    CellColouring, CoxeterSimplex, GeomError, HoneycombStyle, RegularHoneycomb, Rings, Schlafli,
};

use super::options::{HoneycombOptions, ObjectOptions};
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{Honeycomb, PartMaterials, Shape};
use crate::lower::Lowerer;
use crate::syntax::Value;

/// The edges' radius when none of `edges`, `wireframe`, `faces`,
/// `vertices` and `face_colors` is given: thin enough that the far cells stay
/// apart in the picture, thick enough to see from inside the base cell.
pub(super) const DEFAULT_EDGE_RADIUS: f64 = 0.02;

/// The largest entry of a symbol worth checking: hgeom classifies any
/// `{p,q,r}`, and past this every symbol is hyperideal anyway.
const MAX_ENTRY: u64 = 1_000_000;

/// The 15 symbols, for the help of a refused one.
const THE_FIFTEEN: &str = "the 15 regular honeycombs of hyperbolic space are {4,3,5}, {5,3,4}, {5,3,5}, {3,5,3} (compact) and {6,3,3}, {3,3,6}, {4,3,6}, {6,3,4}, {5,3,6}, {6,3,5}, {6,3,6}, {3,6,3}, {4,4,3}, {3,4,4}, {4,4,4} (paracompact)";

impl Lowerer<'_> {
    /// A Schläfli symbol of one of the 15 hyperbolic regular honeycombs;
    /// any other is an error on its span saying which geometry it is.
    pub(in crate::lower) fn schlafli(&mut self, value: &Value, usage: &str) -> Option<Schlafli> {
        let Value::Symbol { entries, span } = value else {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    value.span(),
                    format!(
                        "expected a Schläfli symbol like `{{4,3,5}}`, found {}",
                        value.describe()
                    ),
                )
                .with_help(usage.to_string()),
            );
            return None;
        };
        let [p, q, r] = &entries[..] else {
            let what = match entries.len() {
                2 => "a regular polyhedron or a regular tiling of a plane",
                _ => "a regular polytope or honeycomb of another dimension",
            };
            self.report(
                Diagnostic::new(
                    Code::NotHyperbolic,
                    *span,
                    format!(
                        "a symbol of {} entries describes {what}, not a honeycomb of 3-space",
                        entries.len()
                    ),
                )
                .with_label("three entries {p,q,r} expected")
                .with_help(THE_FIFTEEN),
            );
            return None;
        };
        let mut whole = [0u32; 3];
        for (slot, entry) in whole.iter_mut().zip([p, q, r]) {
            let x = self.number(entry)?;
            // At most MAX_ENTRY, so it fits in u32.
            *slot = self.integer_value(
                x,
                0,
                MAX_ENTRY,
                entry.span(),
                "an entry of a Schläfli symbol",
            )? as u32;
        }
        match Schlafli::new(whole[0], whole[1], whole[2]) {
            Ok(s) => Some(s),
            Err(e) => {
                self.report(
                    Diagnostic::new(Code::NotHyperbolic, *span, e.to_string())
                        .with_label("not a honeycomb of hyperbolic space")
                        .with_help(THE_FIFTEEN),
                );
                None
            }
        }
    }

    /// `rings = (i, ...)` (or `rings = i`): distinct nodes 0 to 3 of the
    /// Coxeter diagram.
    pub(super) fn ring_nodes(&mut self, value: &Value) -> Option<Rings> {
        const HELP: &str = "write the ringed nodes of the diagram [p,q,r], each 0 to 3: `rings = (0)` is {p,q,r} itself, `(0, 1)` its truncation, `(1)` its rectification, `(0, 3)` its runcination, `(3)` the dual {r,q,p}";
        let items = match value {
            Value::Tuple { items, .. } => &items[..],
            Value::Number { .. } => std::slice::from_ref(value),
            other => {
                self.report(
                    Diagnostic::new(
                        Code::WrongType,
                        other.span(),
                        format!(
                            "expected ringed nodes like `(0, 1)`, found {}",
                            other.describe()
                        ),
                    )
                    .with_help(HELP),
                );
                return None;
            }
        };
        let mut nodes = Vec::with_capacity(items.len());
        for item in items {
            let x = self.number(item)?;
            // At most 3, so it fits.
            let node = self.integer_value(x, 0, 3, item.span(), "a ringed node")? as u32;
            if nodes.contains(&node) {
                self.report(
                    Diagnostic::new(
                        Code::InvalidValue,
                        item.span(),
                        format!("node {node} is ringed twice"),
                    )
                    .with_help(HELP),
                );
                return None;
            }
            nodes.push(node);
        }
        // Distinct nodes 0 to 3, at least one (a tuple is never empty).
        Rings::new(&nodes).ok()
    }

    /// The honeycomb's shape: its style from the options (edges of radius
    /// [`DEFAULT_EDGE_RADIUS`] when nothing is asked for), the materials of
    /// its parts, and hgeom's walk. `at` stays in `opts` for the placement.
    pub(super) fn honeycomb(
        &mut self,
        symbol: Schlafli,
        opts: &mut ObjectOptions,
        statement: Span,
    ) -> Option<Vec<Shape>> {
        let HoneycombOptions {
            edges,
            faces,
            vertices,
            depth,
            colors,
            face_colors,
            color_by,
            rings,
        } = opts.take_honeycomb();
        let (rings, rings_span) = match rings {
            Some((r, span)) => (r, Some(span)),
            None => (Rings::REGULAR, None),
        };
        let name = if rings.is_regular() {
            symbol.to_string()
        } else {
            format!("{rings}{symbol}")
        };
        if let Some(span) = rings_span.filter(|_| !rings.is_regular())
            && (depth.is_some()
                || (rings == Rings::DUAL && (colors.is_some() || face_colors.is_some())))
        {
            // Node 3 alone is the dual, a regular honeycomb of its own.
            let (p, q, r) = (symbol.p(), symbol.q(), symbol.r());
            let (message, help) = if rings == Rings::DUAL {
                (
                    format!(
                        "`depth` and `colors` count cells of regular honeycombs; {name} is the regular {{{r},{q},{p}}}, with a vertex where a cell of {symbol} is centred"
                    ),
                    format!("write `Honeycomb {{{r},{q},{p}}}` to count and colour its cells"),
                )
            } else {
                (
                    format!(
                        "`depth` is for regular honeycombs; {name} has cells of several kinds, so it has no layers to count"
                    ),
                    "remove `depth` (`colors` colours its parts by kind), or ring node 0 alone (`rings = (0)`, the regular honeycomb)".to_string(),
                )
            };
            self.report(Diagnostic::new(Code::ConflictingOptions, span, message).with_help(help));
            return None;
        }
        if let Some((d, span)) = depth.filter(|(d, _)| *d > 0 && symbol.has_ideal_cells()) {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    span,
                    format!(
                        "the cells of {symbol} are inscribed in horospheres, each with infinitely many faces and neighbours, so `depth = {d}` would draw infinitely many cells"
                    ),
                )
                .with_help("use `depth = 0` (the base cell alone) or no `depth` (the whole honeycomb, walked)"),
            );
            return None;
        }
        let palette = colors.unwrap_or_default();
        let face_palette = face_colors.unwrap_or_default();
        // `colors` alone colours the edges and vertices (the default
        // edges, unless `edges` or `vertices` says otherwise): it must not
        // close every cell with walls the user never asked for.
        let nothing_asked =
            edges.is_none() && faces.is_none() && vertices.is_none() && face_palette.is_empty();
        let ideal_vertices = rings.seed_is_ideal(&CoxeterSimplex::new(symbol));
        if let Some((_, span)) = vertices.filter(|_| ideal_vertices) {
            self.report(
                Diagnostic::new(
                    Code::IneffectiveOption,
                    span,
                    format!(
                        "every vertex of {name} is ideal (on the absolute), so `vertices` draws nothing"
                    ),
                )
                .with_help("its edges run out to the absolute; remove `vertices`, or draw the edges with `edges = w`"),
            );
        }
        let style = HoneycombStyle {
            edges: if nothing_asked {
                Some(DEFAULT_EDGE_RADIUS)
            } else {
                edges.map(|(w, _)| w)
            },
            faces: faces.is_some() || !face_palette.is_empty(),
            vertices: vertices.map(|(r, _)| r),
            depth: depth.map(|(d, _)| d),
            // Both palettes count round the same classes: as many as the
            // least common multiple of their lengths (at most 16 · 15). A
            // uniform honeycomb's classes are its parts' kinds (0 to 3).
            cell_classes: if rings.is_regular() {
                hscene_ir::palette_period(palette.len(), face_palette.len()) as u32
            } else {
                1
            },
        };
        let colouring = color_by.map_or(CellColouring::Rank, |(c, _)| c);
        let built = RegularHoneycomb::uniform(symbol, rings, style)
            .and_then(|h| h.with_colouring(colouring));
        match built {
            Ok(surface) => Some(vec![Shape::Honeycomb(Box::new(Honeycomb {
                surface,
                materials: PartMaterials {
                    faces,
                    palette,
                    face_palette,
                },
            }))]),
            Err(e) => {
                let span = match &e {
                    GeomError::TooManyCells { .. } => depth.map(|(_, s)| s),
                    GeomError::OddEdgeCycle { .. } | GeomError::UniformWithCells => {
                        color_by.map(|(_, s)| s)
                    }
                    _ => edges.or(vertices).map(|(_, s)| s),
                };
                let span = span.unwrap_or(statement);
                let d = match e {
                    GeomError::TooManyCells { limit } => Diagnostic::new(
                        Code::InvalidValue,
                        span,
                        format!("{name} at this depth has more than {limit} cells"),
                    )
                    .with_help("use a smaller depth, or none: without `depth` the whole honeycomb is drawn by walking, at no cost per cell"),
                    GeomError::OddEdgeCycle { r } => Diagnostic::new(
                        Code::ConflictingOptions,
                        span,
                        format!("{name} has {r} cells round each edge, an odd cycle of neighbours, so its cells cannot be coloured by parity"),
                    )
                    .with_help("`color_by = parity` needs an even r (e.g. {5,3,4}, {4,3,6}, {3,4,4}); use `color_by = rank` here"),
                    GeomError::UniformWithCells => Diagnostic::new(
                        Code::ConflictingOptions,
                        span,
                        format!("{name} has cells of several kinds: `color_by = parity` is for regular honeycombs"),
                    )
                    .with_help("remove `color_by`: `colors` colours a uniform honeycomb's parts by kind"),
                    other => Diagnostic::new(
                        Code::ImpossibleFigure,
                        span,
                        format!("cannot build {name}: {other}"),
                    )
                    .with_help("edges and vertices must be thinner than the cells (see docs/honeycombs.md)"),
                };
                self.report(d);
                None
            }
        }
    }
}
