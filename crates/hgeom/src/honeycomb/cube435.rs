//! The order-5 cubic honeycomb {4,3,5}: regular h-cubes with dihedral angle
//! 72°, five around every edge, filling hyperbolic space (thesis Fig. 36).
//!
//! **The cell.** In the Klein model h-planes are flat, so the cube centred at
//! the origin has faces `x = ±h w`, `y = ±h w`, `z = ±h w` (time in `w`) with
//! outward normals `N = (e, h)`. Two adjacent faces meet at the interior
//! dihedral angle `θ` with `cos θ = -<N_1,N_2>/<N,N> = h²/(1 - h²)`. For
//! `θ = 2π/5`, `cos θ = (√5 - 1)/4` gives `h² = √5 - 2 = 1/(√5 + 2)`. The
//! vertices `(±h, ±h, ±h)` sit at Klein radius `√3 h`, so the circumradius `R`
//! has `tanh² R = 3√5 - 6`, i.e. `cosh² R = 1/(7 - 3√5) = (7 + 3√5)/4 = φ⁴/2`:
//!
//! `cosh R = φ²/√2`, `R ≈ 1.22646`.
//!
//! Cross-check through the characteristic orthoscheme (Schläfli): the vertex
//! figure is a spherical equilateral triangle with angles `θ` and sides equal
//! to the face angle `α`, so `cos θ = cos α/(1 + cos α)` and `cos α = 1/√5`;
//! a regular h-square with angle `α` has edge `e` with
//! `cosh(e/2) = cos(π/4)/sin(α/2)`, so `cosh e = φ²`; and in the cube
//! `cosh e = (1 - h²)/(1 - 3h²) = φ²` too. Both are pinned by tests.
//!
//! **The tessellation.** The reflection in a face plane of the cell is a
//! symmetry of the honeycomb (that plane is a mirror of the characteristic
//! orthoscheme), and it maps the cell onto its neighbour across that face, so
//! breadth-first reflection in faces reaches every cell, layer by layer.

use foldhash::{HashMap, HashMapExt};
use std::f64::consts::{PI, SQRT_2};

use crate::distance::distance;
use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::point::Point;
use crate::polyhedron::{Platonic, Polyhedron};

/// The dihedral angle of the {4,3,5} cube: `2π/5` (72°).
pub const CUBE_435_DIHEDRAL: f64 = 2.0 * PI / 5.0;

/// The most cells a tessellation may produce; deeper requests fail with
/// [`GeomError::TooManyCells`] before any cell geometry is built.
pub const MAX_TESSELLATION_CELLS: usize = 100_000;

/// Two cells whose centres are closer than this (hyperbolic distance) are
/// the same cell. Distinct cells of a honeycomb are at least twice the
/// inradius apart (1.06 for {4,3,5}); the same cell reached by two paths
/// differs only by rounding (about 1e-13 at depth 8).
pub const SAME_CELL_DISTANCE: f64 = 1e-6;

/// Bucket size for centre look-ups, in hyperboloid spatial coordinates:
/// coarse enough that two copies of one cell (rounding apart) fall in the
/// same or adjacent buckets out to distance ~30, fine enough that a bucket
/// holds only a few honeycomb cells (their spatial coordinates differ by at
/// least `2 sinh(inradius)`).
const BUCKET: f64 = 0.25;

/// The circumradius of the {4,3,5} cube: `R = arcosh(φ²/√2) ≈ 1.2264568`
/// (derivation in the module docs).
///
/// # Accuracy
///
/// An ulp or two: `cosh R = φ²/√2` to 1e-14 and `R = 1.2264568` to 1e-7
/// (`cube_435_has_dihedral_angles_of_72_degrees` in `tests/figures.rs`).
pub fn cube_435_circumradius() -> f64 {
    let phi_sq = (3.0 + 5f64.sqrt()) / 2.0;
    (phi_sq / SQRT_2).acosh()
}

/// The {4,3,5} cell: the regular h-cube centred at the origin with all
/// dihedral angles exactly `2π/5` (to rounding), vertices on the rays
/// `(±1, ±1, ±1)` at distance [`cube_435_circumradius`], faces pointing
/// outwards.
///
/// Errors: none in practice (the `Result` is [`Polyhedron::platonic`]'s).
///
/// # Accuracy
///
/// The 12 dihedral angles are 72° to 1e-12, the edges satisfy
/// `cosh e = φ²` to 1e-13 and the face angles `cos α = 1/√5` to 1e-13
/// (`cube_435_has_dihedral_angles_of_72_degrees`).
pub fn cube_435() -> Result<Polyhedron, GeomError> {
    Polyhedron::platonic(Platonic::Cube, cube_435_circumradius())
}

/// One cell of a tessellation.
///
/// Invariant: `polyhedron` is the generating cell transformed by
/// `placement`, which is a product of `depth` face reflections.
#[derive(Clone, Debug, PartialEq)]
pub struct HoneycombCell {
    /// The cell, with its own centre (the image of the generating cell's).
    pub polyhedron: Polyhedron,
    /// The isometry that maps the generating cell onto this one (a product
    /// of `depth` face reflections; orientation-reversing for odd depth).
    pub placement: Isometry,
    /// The breadth-first layer: the fewest face crossings from the
    /// generating cell.
    pub depth: usize,
}

/// The cells reached from `cell` by at most `depth` reflections in faces:
/// depth 0 is `cell` alone, and layer `k` holds every image of a layer
/// `k - 1` cell under the reflection in one of its own faces that is not
/// already present (same centre within [`SAME_CELL_DISTANCE`]). Cells come in
/// layer order, the generating cell first.
///
/// For the cell of a regular honeycomb `{p,q,r}` (a regular polyhedron with
/// dihedral angle `2π/r`, e.g. [`cube_435`]) the layers are the honeycomb's
/// cells by face distance, fitting face to face; for any other polyhedron
/// the result is the set of reflected copies, which may overlap.
///
/// The reflection of the cell with placement `P` in its face `P(F)` is
/// `P R_F P⁻¹`, so the neighbour's placement is `P R_F`: only the generating
/// cell's face reflections are ever built, and the search runs on
/// placements and centres alone; the cells' faces are built once at the end.
///
/// Errors: [`GeomError::TooManyCells`] as soon as the count passes
/// [`MAX_TESSELLATION_CELLS`] (for {4,3,5}: depth 8 and beyond),
/// [`GeomError::NotInBall`] if a cell lands too far out for f64.
///
/// # Accuracy
///
/// Placements are products of up to `depth` reflections (see
/// [`Isometry::compose`]); neighbouring {4,3,5} cells share faces to 1e-14
/// and distinct centres stay at least twice the inradius apart
/// (`honeycomb_435_cell_counts_and_face_to_face_fit` in
/// `tests/figures.rs`). Two centres within [`SAME_CELL_DISTANCE`] are one
/// cell: rounding is ~1e-13 at depth 8, distinct cells are 1.06 apart.
pub fn tessellate(cell: &Polyhedron, depth: usize) -> Result<Vec<HoneycombCell>, GeomError> {
    Ok(tessellation_placements(cell, depth)?
        .into_iter()
        .map(|(placement, depth)| HoneycombCell {
            polyhedron: cell.transformed(&placement),
            placement,
            depth,
        })
        .collect())
}

/// The placements of [`tessellate`]'s cells, in the same order, with each
/// cell's layer: the search without building any cell. A caller that needs
/// only some of a cell's geometry (its vertices, for the edges) maps the
/// generating cell's by the placement itself; [`tessellate`] is
/// `cell.transformed(placement)` over this list.
///
/// Errors and accuracy: as [`tessellate`].
pub fn tessellation_placements(
    cell: &Polyhedron,
    depth: usize,
) -> Result<Vec<(Isometry, usize)>, GeomError> {
    let mirrors: Vec<Isometry> = cell
        .faces()
        .iter()
        .map(|f| Isometry::reflection(&f.plane()))
        .collect();
    let centre = cell.center();
    let mut placements = vec![(Isometry::IDENTITY, 0usize)];
    let mut centres = vec![centre];
    let mut index: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    index.entry(bucket(&centre)).or_default().push(0);
    let mut layer = 0..1;
    for d in 1..=depth {
        let start = placements.len();
        for i in layer.clone() {
            let parent = placements[i].0;
            for mirror in &mirrors {
                let placement = parent.compose(mirror);
                let c = placement.checked_apply(&centre)?;
                if find(&index, &centres, &c).is_some() {
                    continue;
                }
                if placements.len() >= MAX_TESSELLATION_CELLS {
                    return Err(GeomError::TooManyCells {
                        limit: MAX_TESSELLATION_CELLS,
                    });
                }
                index.entry(bucket(&c)).or_default().push(centres.len());
                centres.push(c);
                placements.push((placement, d));
            }
        }
        layer = start..placements.len();
    }
    Ok(placements)
}

/// The {4,3,5} honeycomb to the given depth: [`tessellate`] applied to
/// [`cube_435`], as polyhedra (each with its own centre). Cell counts for
/// depths 0 to 7 are 1, 7, 37, 163, 661, 2643, 10497, 41511; depth 8 and
/// beyond exceed [`MAX_TESSELLATION_CELLS`].
///
/// Errors: as [`tessellate`].
///
/// # Accuracy
///
/// As [`tessellate`].
pub fn honeycomb_435(depth: usize) -> Result<Vec<Polyhedron>, GeomError> {
    Ok(tessellate(&cube_435()?, depth)?
        .into_iter()
        .map(|c| c.polyhedron)
        .collect())
}

fn bucket(p: &Point) -> [i64; 3] {
    let x = p.to_hyperboloid().truncate() / BUCKET;
    // `as` saturates; centres are finite (checked by checked_apply).
    [x.x.floor() as i64, x.y.floor() as i64, x.z.floor() as i64]
}

fn find(index: &HashMap<[i64; 3], Vec<usize>>, centres: &[Point], c: &Point) -> Option<usize> {
    let [bx, by, bz] = bucket(c);
    for dx in -1..=1 {
        for dy in -1..=1 {
            for dz in -1..=1 {
                let key = [bx + dx, by + dy, bz + dz];
                if let Some(found) = index.get(&key).and_then(|ids| {
                    ids.iter()
                        .find(|&&j| distance(&centres[j], c) < SAME_CELL_DISTANCE)
                }) {
                    return Some(*found);
                }
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_form_matches_the_general_dihedral_formula() {
        let general = Platonic::Cube
            .circumradius_for_dihedral(CUBE_435_DIHEDRAL)
            .unwrap();
        assert!((general - cube_435_circumradius()).abs() < 1e-14);
    }
}
