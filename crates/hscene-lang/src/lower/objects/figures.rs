//! Predefined figures centred at the origin (thesis §7.2), built by hgeom:
//! regular and ideal regular polygons, Lambert and Saccheri quadrilaterals,
//! ideal Platonic solids, the cuboctahedron, the small stellated
//! dodecahedron, the icosahedron's golden rectangles, and the {4,3,5} cube
//! with its tessellation. (The five Platonic solids of the thesis's format
//! are built with the other core objects in `build.rs`.)

use hgeom::{
    GeomError, Platonic, Polyhedron, cube_435, ideal_regular_polygon, lambert_quadrilateral,
    regular_polygon, saccheri_quadrilateral, tessellation_placements,
};

use super::args::Arg;
use super::built::Built;
use crate::ir::Shape;

/// A predefined figure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Figure {
    /// A regular polygon with this many vertices (3 to 6), by circumradius.
    Regular(usize),
    /// `RegularPolygon n, size`.
    RegularN,
    /// An ideal regular polygon with this many vertices.
    IdealRegular(usize),
    /// `IdealRegularPolygon n`.
    IdealRegularN,
    Lambert,
    Saccheri,
    IdealPlatonic(Platonic),
    Cuboctahedron,
    SmallStellatedDodecahedron,
    GoldenRectangles,
    Cube435,
    Tessellation435,
}

/// The deepest `Tessellation435` accepted: 41511 cells (depth 8 would
/// exceed hgeom's cell budget).
pub(super) const MAX_TESSELLATION_DEPTH: u64 = 7;

/// Why a figure was not built.
#[derive(Debug)]
pub(super) enum FigureError {
    /// hgeom refused the values.
    Geom(GeomError),
    /// The arguments do not fit the figure's parameters in the keyword
    /// table (they are checked against the same table, so this does not
    /// happen).
    Arguments,
}

impl From<GeomError> for FigureError {
    fn from(e: GeomError) -> FigureError {
        FigureError::Geom(e)
    }
}

/// Builds a figure from checked arguments (in the order of its parameters
/// in the keyword table).
pub(super) fn build(f: Figure, args: &[Arg]) -> Result<Built, FigureError> {
    let numbers: Vec<f64> = args
        .iter()
        .map(Arg::number)
        .collect::<Option<_>>()
        .ok_or(FigureError::Arguments)?;
    let polygon = |p| Ok(Built::Shapes(vec![Shape::Polygon(Box::new(p))]));
    let solid = |p| Ok(Built::Shapes(vec![Shape::Polyhedron(p)]));
    // Counts were checked against their range, so they convert exactly.
    match (f, numbers.as_slice()) {
        (Figure::Regular(n), [size]) => polygon(regular_polygon(n, *size)?),
        (Figure::RegularN, [n, size]) => polygon(regular_polygon(*n as usize, *size)?),
        (Figure::IdealRegular(n), []) => polygon(ideal_regular_polygon(n)?),
        (Figure::IdealRegularN, [n]) => polygon(ideal_regular_polygon(*n as usize)?),
        (Figure::Lambert, [a, b]) => polygon(lambert_quadrilateral(*a, *b)?),
        (Figure::Saccheri, [base, leg]) => polygon(saccheri_quadrilateral(*base, *leg)?),
        (Figure::IdealPlatonic(k), []) => solid(Polyhedron::ideal_platonic(k)?),
        (Figure::Cuboctahedron, [size]) => solid(Polyhedron::cuboctahedron(*size)?),
        (Figure::SmallStellatedDodecahedron, [size]) => {
            solid(Polyhedron::small_stellated_dodecahedron(*size)?)
        }
        (Figure::GoldenRectangles, [size]) => solid(Polyhedron::golden_rectangles(*size)?),
        (Figure::Cube435, []) => solid(cube_435()?),
        (Figure::Tessellation435, [depth]) => {
            let cell = cube_435()?;
            let placements = tessellation_placements(&cell, *depth as usize)?;
            Ok(Built::Copies {
                cell,
                placements: placements.into_iter().map(|(p, _)| p).collect(),
            })
        }
        _ => Err(FigureError::Arguments),
    }
}

/// What values a figure admits, for the help of `ImpossibleFigure`.
pub(super) fn limits(f: Figure) -> &'static str {
    match f {
        Figure::Lambert => {
            "a Lambert quadrilateral with sides a and b at its right-angled vertex exists only when sinh a · sinh b < 1 (for a = b: a < 0.8813); make a side shorter"
        }
        Figure::RegularN | Figure::IdealRegularN => "regular polygons have 3 to 6 vertices",
        _ => "see the figure's entry in docs/language.md for the values it admits",
    }
}

/// Cells of `Tessellation435 d` for `d = 0..=7`.
const TESSELLATION_CELLS: [u64; 8] = [1, 7, 37, 163, 661, 2643, 10497, 41511];

/// Primitives a figure will have at most, where that is large enough to
/// matter and known before building it: its faces if they are drawn and
/// its edges as rods if they are drawn (each edge counted for every cell,
/// an upper bound); 0 otherwise (it is counted once built).
pub(super) fn figure_estimate(f: Figure, depth: Option<f64>, faces: bool, edges: bool) -> u64 {
    match (f, depth) {
        // Six faces and twelve edges per cube; the depth was checked
        // against 0..=7.
        (Figure::Tessellation435, Some(d)) => {
            TESSELLATION_CELLS.get(d as usize).map_or(u64::MAX, |c| {
                c * (6 * u64::from(faces) + 12 * u64::from(edges))
            })
        }
        _ => 0,
    }
}
