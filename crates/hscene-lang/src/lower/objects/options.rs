//! The `key = value` options that end an object statement: `wireframe`,
//! `edges` and `edge_material` (the edges of faceted objects as rods),
//! `at` (where a figure built at the origin goes), `smooth` (a mesh's
//! crease angle) and a honeycomb's `faces`, `vertices`, `depth`, `colors`
//! and `rings`; and placing the built shapes by them.

use hgeom::{CellColouring, GeomError, Isometry, Point, Polyhedron, Rings, Rod, Vertex};

use super::built::Built;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{MaterialId, Object, Shape};
use crate::lower::Lowerer;
use crate::lower::suggest::closest;
use crate::lower::table::{self, SeenKeys, words};
use crate::syntax::{Ident, Statement, Value};

/// An object option.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ObjectOption {
    /// `wireframe = t`: edges only, as rods of radius `t`.
    Wireframe,
    /// `edges = t`: faces plus rods of radius `t`.
    Edges,
    /// `edge_material = #M`: the rods' material.
    EdgeMaterial,
    /// `at = %P`: the figure's centre, moved from the origin.
    At,
    /// `smooth = ANGLE`: a mesh's crease angle in degrees.
    Smooth,
    /// `faces = #F`: a honeycomb's faces, in material `#F`.
    Faces,
    /// `vertices = r`: a honeycomb's vertices as balls of radius `r`.
    Vertices,
    /// `depth = N`: a honeycomb's cells within `N` face reflections.
    Depth,
    /// `colors = (#A, #B, ...)`: a honeycomb's cells coloured by class.
    Colors,
    /// `face_colors = (#A, #B, ...)`: its faces coloured by class apart.
    FaceColors,
    /// `color_by = rank | parity`: the rule that classes the cells.
    ColorBy,
    /// `rings = (0, 1)`: the ringed nodes of a honeycomb's Coxeter diagram
    /// (a uniform honeycomb by Wythoff's construction).
    Rings,
}

/// The word of an option, as scenes spell it.
#[cfg(test)]
pub(super) fn option_word(option: ObjectOption) -> &'static str {
    OPTIONS
        .iter()
        .find(|(_, o)| *o == option)
        .map_or("", |(w, _)| w)
}

/// Every object option, in the order the help lists them.
const OPTIONS: &[(&str, ObjectOption)] = &[
    ("wireframe", ObjectOption::Wireframe),
    ("edges", ObjectOption::Edges),
    ("edge_material", ObjectOption::EdgeMaterial),
    ("at", ObjectOption::At),
    ("smooth", ObjectOption::Smooth),
    ("faces", ObjectOption::Faces),
    ("vertices", ObjectOption::Vertices),
    ("depth", ObjectOption::Depth),
    ("colors", ObjectOption::Colors),
    ("face_colors", ObjectOption::FaceColors),
    ("color_by", ObjectOption::ColorBy),
    ("rings", ObjectOption::Rings),
];

/// The deepest `depth` of a honeycomb, as for `Tessellation435` (whose
/// cells at that depth it draws).
pub(super) const MAX_HONEYCOMB_DEPTH: u64 = super::figures::MAX_TESSELLATION_DEPTH;

/// The most colours a honeycomb's `colors` may list.
pub(super) const MAX_CELL_COLORS: usize = 16;

/// The names of the object options, in the order of [`OPTIONS`].
pub(crate) const OPTION_NAMES: [&str; OPTIONS.len()] = words!(OPTIONS, 0);

fn option(name: &str) -> Option<ObjectOption> {
    table::find(OPTIONS, name).map(|(_, o)| *o)
}

/// The options of one statement, after checking.
#[derive(Default)]
pub(super) struct ObjectOptions {
    wireframe: Option<(f64, Span)>,
    edges: Option<(f64, Span)>,
    edge_material: Option<MaterialId>,
    at: Option<(Point, Span)>,
    pub(super) smooth: Option<f64>,
    faces_material: Option<MaterialId>,
    vertices: Option<(f64, Span)>,
    depth: Option<(u32, Span)>,
    colors: Option<Vec<MaterialId>>,
    face_colors: Option<Vec<MaterialId>>,
    color_by: Option<(CellColouring, Span)>,
    rings: Option<(Rings, Span)>,
}

/// A honeycomb's own options, taken out of [`ObjectOptions`] (its edges are
/// part of its walk, not rods added beside it).
pub(super) struct HoneycombOptions {
    /// The rod radius (`edges` or `wireframe`) and where it was given.
    pub(super) edges: Option<(f64, Span)>,
    pub(super) faces: Option<MaterialId>,
    pub(super) vertices: Option<(f64, Span)>,
    pub(super) depth: Option<(u32, Span)>,
    pub(super) colors: Option<Vec<MaterialId>>,
    pub(super) face_colors: Option<Vec<MaterialId>>,
    /// The colouring rule and where it was given.
    pub(super) color_by: Option<(CellColouring, Span)>,
    /// The ringed nodes and where they were given.
    pub(super) rings: Option<(Rings, Span)>,
}

impl ObjectOptions {
    /// Whether the faces are drawn (not only the edges).
    pub(super) fn faces(&self) -> bool {
        self.wireframe.is_none()
    }

    /// Whether the edges are drawn.
    pub(super) fn edges(&self) -> bool {
        self.wireframe.or(self.edges).is_some()
    }

    /// Takes the options a honeycomb draws itself, leaving `at`.
    pub(super) fn take_honeycomb(&mut self) -> HoneycombOptions {
        HoneycombOptions {
            edges: self.wireframe.take().or(self.edges.take()),
            faces: self.faces_material.take(),
            vertices: self.vertices.take(),
            depth: self.depth.take(),
            colors: self.colors.take(),
            face_colors: self.face_colors.take(),
            color_by: self.color_by.take(),
            rings: self.rings.take(),
        }
    }
}

impl Lowerer<'_> {
    /// Checks the options of an object `name` that accepts `accepted`.
    pub(super) fn object_options(
        &mut self,
        name: &Ident,
        accepted: &[ObjectOption],
        options: &[(&Ident, &Value)],
    ) -> Option<ObjectOptions> {
        let mut out = ObjectOptions::default();
        let mut ok = true;
        let mut seen = SeenKeys::default();
        for (key, value) in options {
            let Some(kind) = option(&key.text).filter(|o| accepted.contains(o)) else {
                ok = false;
                self.refused_option(name, accepted, key);
                continue;
            };
            if let Some(twice) = seen.again(key) {
                self.report(twice.with_help("remove one of the two"));
            }
            match kind {
                ObjectOption::Wireframe | ObjectOption::Edges => {
                    let what = format!("the `{}` thickness", key.text);
                    match self.length(value, &what) {
                        Some(t) if kind == ObjectOption::Wireframe => {
                            out.wireframe = Some((t, key.span.to(value.span())))
                        }
                        Some(t) => out.edges = Some((t, key.span.to(value.span()))),
                        None => ok = false,
                    }
                }
                ObjectOption::EdgeMaterial => match self.material_arg(value) {
                    Some(m) => out.edge_material = Some(m),
                    None => ok = false,
                },
                ObjectOption::Smooth => match self.crease_angle(value) {
                    Some(a) => out.smooth = Some(a),
                    None => ok = false,
                },
                ObjectOption::At => match self.point_arg(value, "the centre (`at`)") {
                    Some(p) => out.at = Some((p, value.span())),
                    None => ok = false,
                },
                ObjectOption::Faces => match self.material_arg(value) {
                    Some(m) => out.faces_material = Some(m),
                    None => ok = false,
                },
                ObjectOption::Vertices => match self.length(value, "the `vertices` radius") {
                    Some(r) => out.vertices = Some((r, value.span())),
                    None => ok = false,
                },
                ObjectOption::Depth => {
                    match self.integer(value, 0, MAX_HONEYCOMB_DEPTH, "the `depth`") {
                        // At most MAX_HONEYCOMB_DEPTH, so it fits.
                        Some(d) => out.depth = Some((d as u32, value.span())),
                        None => ok = false,
                    }
                }
                ObjectOption::Colors => match self.cell_colors(value, "colors") {
                    Some(c) => out.colors = Some(c),
                    None => ok = false,
                },
                ObjectOption::FaceColors => match self.cell_colors(value, "face_colors") {
                    Some(c) => out.face_colors = Some(c),
                    None => ok = false,
                },
                ObjectOption::ColorBy => match self.colouring_rule(value) {
                    Some(c) => out.color_by = Some((c, key.span.to(value.span()))),
                    None => ok = false,
                },
                ObjectOption::Rings => match self.ring_nodes(value) {
                    Some(r) => out.rings = Some((r, key.span.to(value.span()))),
                    None => ok = false,
                },
            }
        }
        if let (Some((_, w)), Some((_, e))) = (out.wireframe, out.edges) {
            let second = if w.start() < e.start() { e } else { w };
            let help = if accepted.contains(&ObjectOption::Faces) {
                "for a honeycomb they are the same option (the edges' radius; its faces are drawn by `faces` or `face_colors`): keep one"
            } else {
                "`wireframe = t` draws only the edges; `edges = t` draws the faces and the edges: keep one"
            };
            self.report(
                Diagnostic::new(
                    Code::ConflictingOptions,
                    second,
                    "`wireframe` and `edges` cannot both be given",
                )
                .with_help(help),
            );
            ok = false;
        }
        let drawn = out.wireframe.is_some() || out.edges.is_some();
        // An `edge_material` the object does not take was refused above.
        let useless = options.iter().find(|(k, _)| {
            option(&k.text) == Some(ObjectOption::EdgeMaterial)
                && accepted.contains(&ObjectOption::EdgeMaterial)
                && !drawn
        });
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

    /// `color_by = rank | parity`.
    fn colouring_rule(&mut self, value: &Value) -> Option<CellColouring> {
        const HELP: &str = "write `color_by = rank` (layers about the base cell, the default) or `color_by = parity` (a two-colouring: neighbours across a face differ)";
        match value {
            Value::Ident(word) if word.text == "rank" => Some(CellColouring::Rank),
            Value::Ident(word) if word.text == "parity" => Some(CellColouring::Parity),
            other => {
                self.report(
                    Diagnostic::new(
                        Code::InvalidValue,
                        other.span(),
                        format!("expected `rank` or `parity`, found {}", other.describe()),
                    )
                    .with_help(HELP),
                );
                None
            }
        }
    }

    /// `colors = (#A, #B, ...)` (or `face_colors`, named by `key`): one to
    /// [`MAX_CELL_COLORS`] materials.
    fn cell_colors(&mut self, value: &Value, key: &str) -> Option<Vec<MaterialId>> {
        let Value::Tuple { items, span } = value else {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    value.span(),
                    format!(
                        "expected a list of materials like `(#1, #2)`, found {}",
                        value.describe()
                    ),
                )
                .with_help(format!("write `{key} = (#red, #green, #blue)`: cell class k is drawn in the k-th material, counting round")),
            );
            return None;
        };
        if items.len() > MAX_CELL_COLORS {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    *span,
                    format!(
                        "`{key}` lists {} materials; at most {MAX_CELL_COLORS} are used",
                        items.len()
                    ),
                )
                .with_help("a few colours are enough to read the structure: list fewer"),
            );
            return None;
        }
        let mut out = Vec::with_capacity(items.len());
        let mut ok = true;
        for item in items {
            match self.material_arg(item) {
                Some(m) => out.push(m),
                None => ok = false,
            }
        }
        ok.then_some(out)
    }

    /// An option that `name` does not take, or that does not exist.
    fn refused_option(&mut self, name: &Ident, accepted: &[ObjectOption], key: &Ident) {
        let mut d = if option(&key.text).is_some() {
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
        let accepted: Vec<&str> = OPTIONS
            .iter()
            .filter(|(_, o)| accepted.contains(o))
            .map(|(n, _)| *n)
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
    }

    /// Applies `at`, draws the edges, pushes the IR objects and returns
    /// their indices.
    pub(super) fn place(
        &mut self,
        built: Built,
        material: MaterialId,
        opts: ObjectOptions,
        st: &Statement,
    ) -> Vec<usize> {
        let name = st.label.as_ref().map(|l| l.text.to_string());
        let mut shapes = match (built, opts.wireframe) {
            // Edges alone, where the copies stay: their vertices are all
            // that is needed, so no face of any copy is built.
            (Built::Copies { cell, placements }, Some((t, span))) if opts.at.is_none() => {
                return match copies_wireframe(&cell, &placements, t) {
                    Ok(rods) => vec![self.push_wireframe(
                        rods,
                        material,
                        &opts,
                        name,
                        Isometry::IDENTITY,
                        st,
                    )],
                    Err(e) => {
                        self.geom_failure(span, "the edges", &e);
                        Vec::new()
                    }
                };
            }
            (built, _) => built.into_shapes(),
        };
        let mut placement = Isometry::IDENTITY;
        if let Some((centre, span)) = opts.at {
            let iso = Isometry::transvection_from_origin(centre);
            placement = iso;
            let mut moved = Vec::with_capacity(shapes.len());
            for s in &shapes {
                match s.moved(&iso) {
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
                let placement = match shape.natural_placement() {
                    Some(own) if opts.at.is_none() => own,
                    _ => placement,
                };
                self.objects.push((
                    Object {
                        shape,
                        material,
                        name: name.clone(),
                        placement,
                    },
                    st.span,
                ));
            }
        }
        if let Some(rods) = rods {
            out.push(self.push_wireframe(rods, material, &opts, name, placement, st));
        }
        out
    }

    /// Pushes the rods of the edges as one object and returns its index.
    fn push_wireframe(
        &mut self,
        rods: Vec<Rod>,
        material: MaterialId,
        opts: &ObjectOptions,
        name: Option<String>,
        placement: Isometry,
        st: &Statement,
    ) -> usize {
        self.objects.push((
            Object {
                shape: Shape::Wireframe(std::sync::Arc::new(rods)),
                material: opts.edge_material.unwrap_or(material),
                name,
                placement,
            },
            st.span,
        ));
        self.objects.len() - 1
    }
}

/// The rods along every edge of the faces, each edge once.
fn wireframe(shapes: &[Shape], radius: f64) -> Result<Vec<Rod>, GeomError> {
    let mut edges = EdgeSet::new(radius);
    for face in shapes.iter().flat_map(Shape::faces) {
        edges.add_face(face.vertices())?;
    }
    Ok(edges.rods)
}

/// [`wireframe`] of the copies of `cell`, without building them: each copy's
/// face has the vertices `p(v)` of the cell's face, in reverse order when
/// `p` reverses orientation, exactly as [`Polyhedron::transformed`] gives
/// them, so the rods are the same, in the same order.
///
/// The edges are walked as [`wireframe`] walks the copies' faces, but each
/// copy moves the cell's vertices once (not once per face that has them)
/// and offers each of its edges once (not once per face): an edge a copy
/// offers twice is refused the second time anyway, so the rods and their
/// order are unchanged.
fn copies_wireframe(
    cell: &Polyhedron,
    placements: &[Isometry],
    radius: f64,
) -> Result<Vec<Rod>, GeomError> {
    let walk = CellEdges::of(cell);
    let mut edges = EdgeSet::new(radius);
    // Every copy's edges, an upper bound (neighbours share them): reserved
    // untouched, so growing never copies tens of megabytes of rods.
    edges.reserve(placements.len() * walk.forward.len());
    let mut moved = Vec::with_capacity(walk.vertices.len());
    let mut keys = Vec::with_capacity(walk.vertices.len());
    for p in placements {
        moved.clear();
        moved.extend(walk.vertices.iter().map(|v| p.apply_vertex(v)));
        keys.clear();
        keys.extend(moved.iter().map(grid_key));
        let order = if p.preserves_orientation() {
            &walk.forward
        } else {
            &walk.reversed
        };
        for &(a, b) in order {
            edges.add_edge((keys[a], keys[b]), &moved[a], &moved[b])?;
        }
    }
    Ok(edges.rods)
}

/// A cell's distinct vertices, and its edges as pairs of their indices in
/// the order a walk round its faces first meets them, for the cell as it
/// is (`forward`) and with every face reversed (`reversed`).
struct CellEdges {
    vertices: Vec<Vertex>,
    forward: Vec<(usize, usize)>,
    reversed: Vec<(usize, usize)>,
}

impl CellEdges {
    fn of(cell: &Polyhedron) -> CellEdges {
        // Vertices are the same when their bits are: moving equal bits
        // gives equal bits, which is all the walk relies on.
        let bits = |v: &Vertex| (v.is_ideal(), v.coords().to_array().map(f64::to_bits));
        let mut vertices: Vec<Vertex> = Vec::new();
        let faces: Vec<Vec<usize>> = cell
            .faces()
            .iter()
            .map(|f| {
                f.vertices()
                    .iter()
                    .map(|v| match vertices.iter().position(|u| bits(u) == bits(v)) {
                        Some(k) => k,
                        None => {
                            vertices.push(*v);
                            vertices.len() - 1
                        }
                    })
                    .collect()
            })
            .collect();
        let walk = |reverse: bool| {
            let mut order: Vec<(usize, usize)> = Vec::new();
            for face in &faces {
                let mut face = face.clone();
                if reverse {
                    face.reverse();
                }
                for (i, &a) in face.iter().enumerate() {
                    let b = face[(i + 1) % face.len()];
                    if !order.iter().any(|&e| e == (a, b) || e == (b, a)) {
                        order.push((a, b));
                    }
                }
            }
            order
        };
        CellEdges {
            forward: walk(false),
            reversed: walk(true),
            vertices,
        }
    }
}

/// Where a vertex falls on the grid edge ends are matched on ([`EdgeSet`]).
fn grid_key(v: &Vertex) -> [i64; 3] {
    let c = v.coords() * 1e9;
    [c.x.round() as i64, c.y.round() as i64, c.z.round() as i64]
}

/// Rods along edges, each edge once however many faces bring it.
///
/// Faces of one polyhedron (and neighbouring cells of a tessellation) share
/// edges whose end points agree only to rounding, so ends are matched on a
/// grid of 1e-9 in ball coordinates: much finer than any two distinct
/// vertices of a scene, much coarser than rounding.
struct EdgeSet {
    radius: f64,
    seen: foldhash::HashSet<([i64; 3], [i64; 3])>,
    rods: Vec<Rod>,
}

impl EdgeSet {
    fn new(radius: f64) -> EdgeSet {
        EdgeSet {
            radius,
            seen: foldhash::HashSetExt::new(),
            rods: Vec::new(),
        }
    }

    fn reserve(&mut self, edges: usize) {
        self.seen.reserve(edges);
        self.rods.reserve(edges);
    }

    /// Adds the edges of the closed polygon `vs` not already present.
    fn add_face(&mut self, vs: &[Vertex]) -> Result<(), GeomError> {
        for (i, a) in vs.iter().enumerate() {
            let b = &vs[(i + 1) % vs.len()];
            self.add_edge((grid_key(a), grid_key(b)), a, b)?;
        }
        Ok(())
    }

    /// Adds the edge `a -> b` unless an edge with the same ends (`keys`,
    /// their [`grid_key`]s) is present.
    fn add_edge(
        &mut self,
        (ka, kb): ([i64; 3], [i64; 3]),
        a: &Vertex,
        b: &Vertex,
    ) -> Result<(), GeomError> {
        let k = if ka <= kb { (ka, kb) } else { (kb, ka) };
        if self.seen.insert(k) {
            self.rods.push(Rod::new(*a, *b, self.radius)?);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The edges of unbuilt copies are the edges of the built cells: the
    /// same rods, bit for bit, in the same order (so images do not change).
    #[test]
    fn copies_give_the_rods_of_their_built_cells() {
        let cell = hgeom::cube_435().unwrap();
        let placements: Vec<Isometry> = hgeom::tessellation_placements(&cell, 3)
            .unwrap()
            .into_iter()
            .map(|(p, _)| p)
            .collect();
        let direct = copies_wireframe(&cell, &placements, 0.02).unwrap();
        let built = Built::Copies {
            cell: cell.clone(),
            placements,
        }
        .into_shapes();
        assert_eq!(built.len(), 163);
        let through_faces = wireframe(&built, 0.02).unwrap();
        assert_eq!(direct.len(), through_faces.len());
        assert!(direct == through_faces);
    }
}
