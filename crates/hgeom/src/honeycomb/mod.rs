//! Regular honeycombs of hyperbolic 3-space.
//!
//! - `cube435`: the {4,3,5} cube and the tessellation by face reflections
//!   (a list of explicit cells, `Tessellation435`).
//! - `schlafli`: the symbols `{p,q,r}` and their classification by the Gram
//!   matrix of the Coxeter group `[p,q,r]`.
//! - `simplex`: the characteristic simplex, the fundamental domain of
//!   `[p,q,r]`, in the base placement.
//! - `cells`: the cells within a depth, the cells around a part, the
//!   colouring rule.
//! - `style`: what is drawn; the parts a hit reports.
//! - `uniform`: [`Rings`] and the parts of the uniform honeycombs of
//!   Wythoff's construction inside the simplex.
//! - `walk`: [`RegularHoneycomb`], the honeycomb as one surface traced by
//!   walking each ray from cell to cell (or through the simplex);
//!   `domain`: the cell or simplex it walks and the parts inside it;
//!   `domain_ray`: the ray in one domain and the parts a domain reports;
//!   `kernels`: the arithmetic of one step; `crossings`: the walls crossed,
//!   folded into the domain matrix only when it is needed; `walk_record`:
//!   what a walk reports besides its hit; `view_horizon`: where a ray
//!   from the eye stops, by the width of its pixel; `picture_horizons`:
//!   both horizons of a picture set at once; `parts`: the parts listed
//!   one by one ([`RegularHoneycomb::explicit_parts`]).

mod cells;
mod crossings;
mod cube435;
mod domain;
mod domain_ray;
mod kernels;
mod parts;
mod picture_horizons;
mod schlafli;
mod simplex;
mod style;
mod uniform;
mod view_horizon;
mod walk;
mod walk_record;

pub use cube435::{
    CUBE_435_DIHEDRAL, HoneycombCell, MAX_TESSELLATION_CELLS, SAME_CELL_DISTANCE, cube_435,
    cube_435_circumradius, honeycomb_435, tessellate, tessellation_placements,
};
pub use parts::{HoneycombPiece, HoneycombPieces};
pub use schlafli::{Schlafli, SchlafliError};
pub use simplex::CoxeterSimplex;
pub use style::{CellColouring, HoneycombPart, HoneycombStyle, decode_honeycomb_part};
pub use uniform::Rings;
pub use walk::{DEFAULT_HORIZON, FaceFrame, MAX_WALK_STEPS, RANK_CLASSES, RegularHoneycomb};
pub use walk_record::{WalkStats, WalkStep};
