//! The table of object keywords: one row per keyword (aliases included)
//! with what it builds, its parameters, the texts of its messages and the
//! options it takes. The help, the "did you mean" candidates and the
//! editor vocabulary all come from this table; adding a keyword is a row
//! here plus its case in `build.rs`.

use hgeom::Platonic;

use super::args::Param;
use super::figures::{Figure, MAX_TESSELLATION_DEPTH};
use super::options::ObjectOption;
use crate::lower::table::{self, Row, words};

/// What an object keyword builds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum ObjectKeyword {
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
    /// A regular honeycomb `{p,q,r}`, walked (see `honeycomb.rs`).
    Honeycomb,
}

/// How an object keyword is written: its positional parameters (the
/// material, always last, is not listed) and its options.
#[derive(Clone, Copy, Debug)]
pub(super) struct Signature {
    pub(super) params: &'static [Param],
    /// "a centre, a radius and a material", for arity messages.
    pub(super) takes: &'static str,
    /// The help for arity errors; `{name}` stands for the keyword.
    pub(super) usage: &'static str,
    /// The options it accepts, in the order of the options table.
    pub(super) options: &'static [ObjectOption],
}

/// One object keyword.
#[derive(Clone, Copy, Debug)]
pub(super) struct KeywordRow {
    pub(super) name: &'static str,
    pub(super) builds: ObjectKeyword,
    pub(super) signature: Signature,
}

impl Row for KeywordRow {
    fn word(&self) -> &'static str {
        self.name
    }
}

const fn row(name: &'static str, builds: ObjectKeyword, signature: Signature) -> KeywordRow {
    KeywordRow {
        name,
        builds,
        signature,
    }
}

/// The options of polygons: their edges can be drawn.
const FACETED: &[ObjectOption] = &[
    ObjectOption::Wireframe,
    ObjectOption::Edges,
    ObjectOption::EdgeMaterial,
];

/// The options of figures built at the origin: their edges can be drawn,
/// and `at` moves them.
const FIGURE: &[ObjectOption] = &[
    ObjectOption::Wireframe,
    ObjectOption::Edges,
    ObjectOption::EdgeMaterial,
    ObjectOption::At,
];

/// The options of a honeycomb: what it draws, how deep, in which colours,
/// which uniform honeycomb of its group, and where its base cell is.
const HONEYCOMB: &[ObjectOption] = &[
    ObjectOption::Wireframe,
    ObjectOption::Edges,
    ObjectOption::At,
    ObjectOption::Faces,
    ObjectOption::Vertices,
    ObjectOption::Depth,
    ObjectOption::Colors,
    ObjectOption::FaceColors,
    ObjectOption::ColorBy,
    ObjectOption::Rings,
];

const SIZE: &[Param] = &[Param::Length("the size")];

/// Platonic solids and figures given by one size.
const SIZED: Signature = Signature {
    params: SIZE,
    takes: "a size and a material",
    usage: "write `{name} size, #M;` (size: hyperbolic circumradius)",
    options: FIGURE,
};

/// Figures whose every vertex is on the absolute.
const IDEAL: Signature = Signature {
    params: &[],
    takes: "only a material",
    usage: "write `{name} #M;` (every vertex is on the absolute, so there is no size)",
    options: FIGURE,
};

const LAMBERT: Signature = Signature {
    params: &[Param::Length("side a"), Param::Length("side b")],
    takes: "two sides and a material",
    usage: "write `{name} a, b, #M;` (a, b: the sides at the right-angled vertex, with sinh a · sinh b < 1)",
    options: FIGURE,
};

const SACCHERI: Signature = Signature {
    params: &[Param::Length("the base"), Param::Length("the leg")],
    takes: "a base, a leg and a material",
    usage: "write `{name} base, leg, #M;` (hyperbolic lengths)",
    options: FIGURE,
};

/// Every object keyword, in the order the help lists them.
pub(super) const KEYWORDS: &[KeywordRow] = &[
    row(
        "Sphere",
        ObjectKeyword::Sphere,
        Signature {
            params: &[
                Param::Point("a sphere centre"),
                Param::Length("the sphere radius"),
            ],
            takes: "a centre, a radius and a material",
            usage: "write `Sphere %P, radius, #M;` (radius is hyperbolic)",
            options: &[],
        },
    ),
    row(
        "Polygon",
        ObjectKeyword::Polygon,
        Signature {
            params: &[Param::Vertices],
            takes: "a vertex list and a material",
            usage: "write `Polygon (%1, %2, %3), #M;`",
            options: FACETED,
        },
    ),
    row(
        "Rod",
        ObjectKeyword::Rod,
        Signature {
            params: &[
                Param::Vertex("a rod end"),
                Param::Vertex("a rod end"),
                Param::Length("the rod radius"),
            ],
            takes: "two end points, a radius and a material",
            usage: "write `Rod %A, %B, radius, #M;` (the points within `radius` of the h-segment AB)",
            options: &[],
        },
    ),
    row(
        "Cylinder",
        ObjectKeyword::Cylinder,
        Signature {
            params: &[
                Param::Vertex("a point of the cylinder's axis"),
                Param::Vertex("a point of the cylinder's axis"),
                Param::Length("the cylinder radius"),
            ],
            takes: "two points of its axis, a radius and a material",
            usage: "write `Cylinder %A, %B, radius, #M;` (the points at `radius` from the h-line AB)",
            options: &[],
        },
    ),
    row(
        "Plane",
        ObjectKeyword::Plane,
        Signature {
            params: &[
                Param::Vertex("a point of the plane"),
                Param::Vertex("a point of the plane"),
                Param::Vertex("a point of the plane"),
            ],
            takes: "three points and a material",
            usage: "write `Plane %A, %B, %C, #M;` (its outside is where the right-hand rule on A, B, C points)",
            options: &[],
        },
    ),
    row(
        "Horosphere",
        ObjectKeyword::Horosphere,
        Signature {
            params: &[
                Param::Ideal("the horosphere centre"),
                Param::Point("the point the horosphere passes through"),
            ],
            takes: "an ideal centre, a point on it and a material",
            usage: "write `Horosphere %ideal, %through, #M;` (the centre is a point on the absolute)",
            options: &[],
        },
    ),
    row(
        "Mesh",
        ObjectKeyword::Mesh,
        Signature {
            params: &[Param::File("the mesh file"), Param::Length("the mesh size")],
            takes: "a file name, a size and a material",
            usage: "write `Mesh \"bunny.ply\", size, #M;` (an OBJ or PLY file, relative to the scene file; size: the hyperbolic distance from the mesh's centre to its farthest vertex)",
            options: &[ObjectOption::At, ObjectOption::Smooth],
        },
    ),
    row(
        "Tetrahedron",
        ObjectKeyword::Platonic(Platonic::Tetrahedron),
        SIZED,
    ),
    row("Cube", ObjectKeyword::Platonic(Platonic::Cube), SIZED),
    row("Hexahedron", ObjectKeyword::Platonic(Platonic::Cube), SIZED),
    row(
        "Octahedron",
        ObjectKeyword::Platonic(Platonic::Octahedron),
        SIZED,
    ),
    row(
        "Dodecahedron",
        ObjectKeyword::Platonic(Platonic::Dodecahedron),
        SIZED,
    ),
    row(
        "Icosahedron",
        ObjectKeyword::Platonic(Platonic::Icosahedron),
        SIZED,
    ),
    row("Triangle", ObjectKeyword::Figure(Figure::Regular(3)), SIZED),
    row("Square", ObjectKeyword::Figure(Figure::Regular(4)), SIZED),
    row("Pentagon", ObjectKeyword::Figure(Figure::Regular(5)), SIZED),
    row("Hexagon", ObjectKeyword::Figure(Figure::Regular(6)), SIZED),
    row(
        "RegularPolygon",
        ObjectKeyword::Figure(Figure::RegularN),
        Signature {
            params: &[
                Param::Count("the vertex count", 3, 6),
                Param::Length("the size"),
            ],
            takes: "a vertex count, a size and a material",
            usage: "write `RegularPolygon n, size, #M;` (n from 3 to 6; size: hyperbolic circumradius)",
            options: FIGURE,
        },
    ),
    row(
        "IdealTriangle",
        ObjectKeyword::Figure(Figure::IdealRegular(3)),
        IDEAL,
    ),
    row(
        "IdealSquare",
        ObjectKeyword::Figure(Figure::IdealRegular(4)),
        IDEAL,
    ),
    row(
        "IdealPentagon",
        ObjectKeyword::Figure(Figure::IdealRegular(5)),
        IDEAL,
    ),
    row(
        "IdealHexagon",
        ObjectKeyword::Figure(Figure::IdealRegular(6)),
        IDEAL,
    ),
    row(
        "IdealRegularPolygon",
        ObjectKeyword::Figure(Figure::IdealRegularN),
        Signature {
            params: &[Param::Count("the vertex count", 3, 6)],
            takes: "a vertex count and a material",
            usage: "write `IdealRegularPolygon n, #M;` (n from 3 to 6)",
            options: FIGURE,
        },
    ),
    row("Lambert", ObjectKeyword::Figure(Figure::Lambert), LAMBERT),
    row(
        "LambertQuadrilateral",
        ObjectKeyword::Figure(Figure::Lambert),
        LAMBERT,
    ),
    row(
        "Saccheri",
        ObjectKeyword::Figure(Figure::Saccheri),
        SACCHERI,
    ),
    row(
        "SaccheriQuadrilateral",
        ObjectKeyword::Figure(Figure::Saccheri),
        SACCHERI,
    ),
    row(
        "IdealTetrahedron",
        ObjectKeyword::Figure(Figure::IdealPlatonic(Platonic::Tetrahedron)),
        IDEAL,
    ),
    row(
        "IdealCube",
        ObjectKeyword::Figure(Figure::IdealPlatonic(Platonic::Cube)),
        IDEAL,
    ),
    row(
        "IdealOctahedron",
        ObjectKeyword::Figure(Figure::IdealPlatonic(Platonic::Octahedron)),
        IDEAL,
    ),
    row(
        "IdealDodecahedron",
        ObjectKeyword::Figure(Figure::IdealPlatonic(Platonic::Dodecahedron)),
        IDEAL,
    ),
    row(
        "IdealIcosahedron",
        ObjectKeyword::Figure(Figure::IdealPlatonic(Platonic::Icosahedron)),
        IDEAL,
    ),
    row(
        "Cuboctahedron",
        ObjectKeyword::Figure(Figure::Cuboctahedron),
        SIZED,
    ),
    row(
        "SmallStellatedDodecahedron",
        ObjectKeyword::Figure(Figure::SmallStellatedDodecahedron),
        SIZED,
    ),
    row(
        "StarDodecahedron",
        ObjectKeyword::Figure(Figure::SmallStellatedDodecahedron),
        SIZED,
    ),
    row(
        "GoldenRectangles",
        ObjectKeyword::Figure(Figure::GoldenRectangles),
        SIZED,
    ),
    row(
        "Cube435",
        ObjectKeyword::Figure(Figure::Cube435),
        Signature {
            params: &[],
            takes: "only a material",
            usage: "write `Cube435 #M;` (the {4,3,5} cell has a fixed size: its dihedral angles are 72°)",
            options: FIGURE,
        },
    ),
    row(
        "Tessellation435",
        ObjectKeyword::Figure(Figure::Tessellation435),
        Signature {
            params: &[Param::Count("the depth", 0, MAX_TESSELLATION_DEPTH)],
            takes: "a depth and a material",
            usage: "write `Tessellation435 depth, #M;` (depth 0 to 7: 1, 7, 37, 163, 661, 2643, 10497 or 41511 cells)",
            options: FIGURE,
        },
    ),
    row(
        "Honeycomb",
        ObjectKeyword::Honeycomb,
        Signature {
            params: &[Param::Symbol],
            takes: "a Schläfli symbol and a material",
            usage: "write `Honeycomb {4,3,5}, #M;` (one of the 15 regular honeycombs of hyperbolic space; options edges = w, faces = #F, vertices = r, depth = N, colors = (#A, #B), face_colors = (#C, #D), color_by = parity, rings = (0, 1) for a uniform honeycomb, at = %P)",
            options: HONEYCOMB,
        },
    ),
];

/// The keyword spelt exactly `name`.
pub(super) fn keyword(name: &str) -> Option<&'static KeywordRow> {
    table::find(KEYWORDS, name)
}

/// Every object keyword, in the order of [`KEYWORDS`].
pub(crate) const OBJECT_KEYWORDS: [&str; KEYWORDS.len()] = words!(KEYWORDS, name);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_keyword_has_one_row() {
        let mut names = OBJECT_KEYWORDS.to_vec();
        names.sort_unstable();
        let before = names.len();
        names.dedup();
        assert_eq!(names.len(), before);
    }

    /// The help of `Honeycomb` names every option it takes (it once left
    /// out `rings`): every option of its row but the alias `wireframe`.
    #[test]
    fn the_honeycomb_help_names_every_option() {
        let row = keyword("Honeycomb").expect("a row");
        for option in row.signature.options {
            let word = super::super::options::option_word(*option);
            if word == "wireframe" {
                continue;
            }
            assert!(
                row.signature.usage.contains(&format!("{word} = ")),
                "{word} missing from {}",
                row.signature.usage
            );
        }
    }
}
