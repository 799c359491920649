//! Why an export fails.

use thiserror::Error;

/// An export that cannot be made.
#[derive(Debug, Error)]
pub enum ExportError {
    /// An OBJ's MTL name goes into its `mtllib` line, which has no
    /// escapes: a line break there would start lines of its own.
    #[error(
        "an OBJ's name is written into its `mtllib` line: `{0}` has a line break or control character; rename the output"
    )]
    UnwritableName(String),
    /// A length that is not `100mm`, `10cm`, `0.1m`, `4in` or a number.
    #[error("`{0}` is not a length: write e.g. 100mm, 10cm, 0.1m or 4in (positive)")]
    BadLength(String),
    /// Options that contradict one another or a limit.
    #[error("bad export options: {0}")]
    BadOptions(String),
    /// An output name whose extension is not a format we write.
    #[error("cannot tell the format of `{0}`: the name must end in .stl, .3mf, .obj or .glb")]
    UnknownFormat(String),
    /// The scene is in a quotient space: its objects are seen again and
    /// again through the gluing, which no one solid in the ball shows.
    #[error(
        "the scene is in the space {space}, which has no one shape in the ball to print: remove \
         `space` to print what the domain holds, or print the domain's cell with \
         `Honeycomb {{p,q,r}}, depth = 0`"
    )]
    InSpace {
        /// The space's name.
        space: String,
    },
    /// The triangles would exceed the budget.
    #[error(
        "{object} needs more than the {budget} triangles left of --max-triangles \
         (raise it, or coarsen --tolerance, or raise --min-feature)"
    )]
    TooManyTriangles {
        /// The object (as `check` names it) that went over.
        object: String,
        /// What was left of the budget when it did.
        budget: usize,
    },
    /// A mesh with a boundary, for a format that must be closed.
    #[error(
        "{object} is an open surface (an edge has {uses} triangle(s) where a closed one has 2): \
         a printer needs closed shells; export it to .obj or .glb instead"
    )]
    OpenMesh {
        /// The object.
        object: String,
        /// How many triangles share the offending edge.
        uses: usize,
    },
    /// Nothing is thick enough to print.
    #[error(
        "nothing is left to print: every part is thinner than --min-feature \
         ({min_feature} mm) at a size of {size} mm; raise --size or lower --min-feature"
    )]
    NothingToPrint {
        /// The minimum feature, in millimetres.
        min_feature: f64,
        /// The size, in millimetres.
        size: f64,
    },
    /// A honeycomb's search ran past its budget of chambers.
    #[error("{object}: {source}")]
    Geometry {
        /// The object.
        object: String,
        /// What hgeom said.
        source: hgeom::GeomError,
    },
    /// The 3MF package could not be assembled.
    #[error("cannot write the 3MF package: {0}")]
    Package(String),
}
