//! Predefined figures centred at the origin (thesis §7.2), built by hgeom:
//! regular and ideal regular polygons, Lambert and Saccheri quadrilaterals,
//! ideal Platonic solids, the cuboctahedron, the small stellated
//! dodecahedron, the icosahedron's golden rectangles, and the {4,3,5} cube
//! with its tessellation. (The five Platonic solids of the thesis's format
//! are handled with the other core objects in `objects.rs`.)

use hgeom::{
    GeomError, Platonic, Polyhedron, cube_435, honeycomb_435, ideal_regular_polygon,
    lambert_quadrilateral, regular_polygon, saccheri_quadrilateral,
};

use super::objects::{Arg, Param};
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

/// Every figure keyword (aliases included), in the order the help lists them.
pub(super) const ALL: &[(&str, Figure)] = &[
    ("Triangle", Figure::Regular(3)),
    ("Square", Figure::Regular(4)),
    ("Pentagon", Figure::Regular(5)),
    ("Hexagon", Figure::Regular(6)),
    ("RegularPolygon", Figure::RegularN),
    ("IdealTriangle", Figure::IdealRegular(3)),
    ("IdealSquare", Figure::IdealRegular(4)),
    ("IdealPentagon", Figure::IdealRegular(5)),
    ("IdealHexagon", Figure::IdealRegular(6)),
    ("IdealRegularPolygon", Figure::IdealRegularN),
    ("Lambert", Figure::Lambert),
    ("LambertQuadrilateral", Figure::Lambert),
    ("Saccheri", Figure::Saccheri),
    ("SaccheriQuadrilateral", Figure::Saccheri),
    (
        "IdealTetrahedron",
        Figure::IdealPlatonic(Platonic::Tetrahedron),
    ),
    ("IdealCube", Figure::IdealPlatonic(Platonic::Cube)),
    (
        "IdealOctahedron",
        Figure::IdealPlatonic(Platonic::Octahedron),
    ),
    (
        "IdealDodecahedron",
        Figure::IdealPlatonic(Platonic::Dodecahedron),
    ),
    (
        "IdealIcosahedron",
        Figure::IdealPlatonic(Platonic::Icosahedron),
    ),
    ("Cuboctahedron", Figure::Cuboctahedron),
    (
        "SmallStellatedDodecahedron",
        Figure::SmallStellatedDodecahedron,
    ),
    ("StarDodecahedron", Figure::SmallStellatedDodecahedron),
    ("GoldenRectangles", Figure::GoldenRectangles),
    ("Cube435", Figure::Cube435),
    ("Tessellation435", Figure::Tessellation435),
];

/// The deepest `Tessellation435` accepted: 41511 cells (depth 8 would
/// exceed hgeom's cell budget).
pub(super) const MAX_TESSELLATION_DEPTH: u64 = 7;

pub(super) fn by_name(name: &str) -> Option<Figure> {
    ALL.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
}

/// A figure's signature (the material, always last, is not listed).
pub(super) struct FigureSpec {
    pub(super) params: &'static [Param],
    pub(super) takes: &'static str,
    pub(super) usage: &'static str,
}

const SIZE: &[Param] = &[Param::Length("the size")];
const NOTHING: &[Param] = &[];

pub(super) fn spec(f: Figure) -> FigureSpec {
    match f {
        Figure::Regular(_)
        | Figure::Cuboctahedron
        | Figure::SmallStellatedDodecahedron
        | Figure::GoldenRectangles => FigureSpec {
            params: SIZE,
            takes: "a size and a material",
            usage: "write `{name} size, #M;` (size: hyperbolic circumradius)",
        },
        Figure::RegularN => FigureSpec {
            params: &[
                Param::Count("the vertex count", 3, 6),
                Param::Length("the size"),
            ],
            takes: "a vertex count, a size and a material",
            usage: "write `RegularPolygon n, size, #M;` (n from 3 to 6; size: hyperbolic circumradius)",
        },
        Figure::IdealRegular(_) | Figure::IdealPlatonic(_) => FigureSpec {
            params: NOTHING,
            takes: "only a material",
            usage: "write `{name} #M;` (every vertex is on the absolute, so there is no size)",
        },
        Figure::IdealRegularN => FigureSpec {
            params: &[Param::Count("the vertex count", 3, 6)],
            takes: "a vertex count and a material",
            usage: "write `IdealRegularPolygon n, #M;` (n from 3 to 6)",
        },
        Figure::Lambert => FigureSpec {
            params: &[Param::Length("side a"), Param::Length("side b")],
            takes: "two sides and a material",
            usage: "write `{name} a, b, #M;` (a, b: the sides at the right-angled vertex, with sinh a · sinh b < 1)",
        },
        Figure::Saccheri => FigureSpec {
            params: &[Param::Length("the base"), Param::Length("the leg")],
            takes: "a base, a leg and a material",
            usage: "write `{name} base, leg, #M;` (hyperbolic lengths)",
        },
        Figure::Cube435 => FigureSpec {
            params: NOTHING,
            takes: "only a material",
            usage: "write `Cube435 #M;` (the {4,3,5} cell has a fixed size: its dihedral angles are 72°)",
        },
        Figure::Tessellation435 => FigureSpec {
            params: &[Param::Count("the depth", 0, MAX_TESSELLATION_DEPTH)],
            takes: "a depth and a material",
            usage: "write `Tessellation435 depth, #M;` (depth 0 to 7: 1, 7, 37, 163, 661, 2643, 10497 or 41511 cells)",
        },
    }
}

/// Builds a figure from checked arguments (in the order of its `params`).
pub(super) fn build(f: Figure, args: &[Arg]) -> Result<Vec<Shape>, GeomError> {
    let num = |i: usize| args.get(i).map_or(f64::NAN, Arg::number);
    // Counts were checked against their range, so they convert exactly.
    let count = |i: usize| num(i) as usize;
    let polygon = |p| Ok(vec![Shape::Polygon(p)]);
    let solid = |p| Ok(vec![Shape::Polyhedron(p)]);
    match f {
        Figure::Regular(n) => polygon(regular_polygon(n, num(0))?),
        Figure::RegularN => polygon(regular_polygon(count(0), num(1))?),
        Figure::IdealRegular(n) => polygon(ideal_regular_polygon(n)?),
        Figure::IdealRegularN => polygon(ideal_regular_polygon(count(0))?),
        Figure::Lambert => polygon(lambert_quadrilateral(num(0), num(1))?),
        Figure::Saccheri => polygon(saccheri_quadrilateral(num(0), num(1))?),
        Figure::IdealPlatonic(k) => solid(Polyhedron::ideal_platonic(k)?),
        Figure::Cuboctahedron => solid(Polyhedron::cuboctahedron(num(0))?),
        Figure::SmallStellatedDodecahedron => {
            solid(Polyhedron::small_stellated_dodecahedron(num(0))?)
        }
        Figure::GoldenRectangles => solid(Polyhedron::golden_rectangles(num(0))?),
        Figure::Cube435 => solid(cube_435()?),
        Figure::Tessellation435 => Ok(honeycomb_435(count(0))?
            .into_iter()
            .map(Shape::Polyhedron)
            .collect()),
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
