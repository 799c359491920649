//! The named spaces, each built from cells of a regular honeycomb placed
//! as [`RegularHoneycomb`](crate::RegularHoneycomb) places them, so that
//! the domain's edges are the honeycomb's.
//!
//! - **Seifert-Weber dodecahedral space** (closed): the base cell of
//!   `{5,3,5}` (a dodecahedron with dihedral angles of 72°), each face
//!   glued to the opposite face with a 3/10 turn. The pairing of face `i`
//!   (outward direction `u`, inradius `ρ`) is the translation by `2ρ`
//!   along `-u` followed by the rotation about the axis `u` by `3π/5`:
//!   the translation alone lands the face on its opposite turned by a
//!   tenth (opposite faces of a dodecahedron are turned by 36°), and a
//!   further 108° makes 144°, a symmetry of the pentagon. Its thirty edges
//!   fall into six cycles of five: `5 × 72° = 360°`.
//! - **The figure-eight knot complement** (one cusp): the base cell of
//!   `{3,3,6}` (a regular ideal tetrahedron) and its mirror image in the
//!   face `n3` of the characteristic simplex, a bipyramid of six ideal
//!   triangles glued in three pairs; its nine edges (60° each) fall into
//!   two cycles of six.
//! - **The Whitehead link complement** (two cusps): the base cell of
//!   `{3,4,4}` (a regular ideal octahedron, 90° dihedral angles), its eight
//!   faces glued in four pairs; twelve edges in three cycles of four.
//! - **A honeycomb's cell with mirror walls**, for each of the fifteen
//!   `{p,q,r}`: each face glued to itself by the reflection in it (the
//!   cells inscribed in horospheres, with infinitely many faces, in
//!   `horocell.rs`).
//!
//! The pairings of the two link complements are given by vertex
//! correspondences, derived and checked (edge cycles, homology, cusps) as
//! recorded in `docs/manifolds.md`; every space is checked again when it
//! is built (`gluing.rs`).

use glam::{DMat3, DMat4, DVec3, DVec4};

use crate::accurate::{two_prod, two_sum};
use crate::error::GeomError;
use crate::honeycomb::{CoxeterSimplex, Schlafli};
use crate::isometry::Isometry;
use crate::plane::HPlane;
use crate::point::Point;

use super::QuotientSpace;
use super::gluing::{check_cycles, check_pairings, edge_cycles, isometries, pairing_matrix};
use super::horocell::{HoroCell, reflection};
use super::polyhedron::DomainPolyhedron;

/// The names `space = NAME` accepts besides a symbol `{p,q,r}`.
pub const SPACE_NAMES: [&str; 3] = ["seifert_weber", "figure_eight", "whitehead"];

/// Which space.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpaceKind {
    /// The Seifert-Weber dodecahedral space, from `{5,3,5}`.
    SeifertWeber,
    /// The figure-eight knot complement, from `{3,3,6}`.
    FigureEight,
    /// The Whitehead link complement, from `{3,4,4}`.
    Whitehead,
    /// The cell of a regular honeycomb, with mirror walls.
    Mirrors(Schlafli),
    /// A manifold given by the face pairings of a Dirichlet domain
    /// ([`QuotientSpace::from_pairings`]), read from a file.
    Pairings,
}

impl SpaceKind {
    /// The space called `name` (one of [`SPACE_NAMES`]).
    pub fn from_name(name: &str) -> Option<SpaceKind> {
        match name {
            "seifert_weber" => Some(SpaceKind::SeifertWeber),
            "figure_eight" => Some(SpaceKind::FigureEight),
            "whitehead" => Some(SpaceKind::Whitehead),
            _ => None,
        }
    }

    /// The regular honeycomb whose cells make the domain; `None` for a
    /// domain given by its pairings.
    pub fn symbol(&self) -> Option<Schlafli> {
        let (p, q, r) = match self {
            SpaceKind::SeifertWeber => (5, 3, 5),
            SpaceKind::FigureEight => (3, 3, 6),
            SpaceKind::Whitehead => (3, 4, 4),
            SpaceKind::Mirrors(s) => return Some(*s),
            SpaceKind::Pairings => return None,
        };
        // The three symbols are hyperbolic (schlafli.rs lists the fifteen).
        Schlafli::new(p, q, r).ok()
    }

    /// True for the cell with mirror walls.
    pub fn is_mirrored(&self) -> bool {
        matches!(self, SpaceKind::Mirrors(_))
    }
}

impl std::fmt::Display for SpaceKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SpaceKind::SeifertWeber => f.write_str("seifert_weber"),
            SpaceKind::FigureEight => f.write_str("figure_eight"),
            SpaceKind::Whitehead => f.write_str("whitehead"),
            SpaceKind::Mirrors(s) => write!(f, "{s}"),
            SpaceKind::Pairings => f.write_str("a domain from its pairings"),
        }
    }
}

impl QuotientSpace {
    /// The space `kind` in its base placement (the domain's base cell
    /// centred at the origin), its gluing checked.
    ///
    /// Errors: the gluing checks' errors, which the built-in spaces pass
    /// (`tests/spaces.rs`).
    pub fn new(kind: SpaceKind) -> Result<QuotientSpace, GeomError> {
        let Some(symbol) = kind.symbol() else {
            return Err(GeomError::BadDomain(
                "a domain given by its pairings is built by QuotientSpace::from_pairings".into(),
            ));
        };
        let simplex = CoxeterSimplex::new(symbol);
        if symbol.has_ideal_cells() {
            // Only a mirrored cell has such a domain (the named spaces'
            // cells are finite): its faces are walked, not listed.
            let (cell, faces) = HoroCell::new(&simplex);
            let pairings = faces
                .iter()
                .map(|n| Ok(Isometry::reflection(&HPlane::from_normal(*n)?)))
                .collect::<Result<Vec<_>, GeomError>>()?;
            let matrices: Vec<DMat4> = pairings.iter().map(Isometry::to_lorentz).collect();
            check_cycles(&cell.relations(&faces, symbol.r()), &[], true)?;
            return Ok(QuotientSpace {
                kind,
                domain: None,
                partner: (0..faces.len()).collect(),
                faces,
                pairings,
                matrices,
                horo: Some(cell),
                placement: Isometry::IDENTITY,
            });
        }
        let cell = cell_faces(&simplex);
        let (faces, partner, matrices) = match kind {
            SpaceKind::SeifertWeber => seifert_weber(cell)?,
            SpaceKind::Mirrors(_) => {
                let matrices = cell.iter().map(|n| reflection(*n)).collect();
                (cell.clone(), (0..cell.len()).collect(), matrices)
            }
            SpaceKind::FigureEight => {
                let n3 = simplex.normals()[3];
                let mirror = reflection(n3);
                // The base tetrahedron's other faces and their mirror images.
                let mut faces: Vec<DVec4> = cell
                    .iter()
                    .copied()
                    .filter(|n| (*n - n3).abs().max_element() > 1e-9)
                    .collect();
                let images: Vec<DVec4> = faces.iter().map(|n| mirror * *n).collect();
                faces.extend(images);
                by_correspondence(faces, &FIGURE_EIGHT)?
            }
            SpaceKind::Whitehead => by_correspondence(cell, &WHITEHEAD)?,
            // Handled above: it has no symbol.
            SpaceKind::Pairings => return Err(GeomError::BadDomain("no cells".into())),
        };
        QuotientSpace::glued(kind, faces, partner, &matrices)
    }

    /// The space of a finite domain with faces `faces` (inward unit
    /// normals) glued to `partner` by `matrices`, checked.
    pub(super) fn glued(
        kind: SpaceKind,
        faces: Vec<DVec4>,
        partner: Vec<usize>,
        matrices: &[DMat4],
    ) -> Result<QuotientSpace, GeomError> {
        let domain = DomainPolyhedron::from_faces(faces)?;
        // The walk uses the matrices of the exact isometries (the stable
        // form, which conjugation by a placement keeps exact): check those.
        let pairings = isometries(matrices)?;
        let matrices: Vec<DMat4> = pairings.iter().map(Isometry::to_lorentz).collect();
        check_pairings(&domain, &partner, &matrices)?;
        let cycles = edge_cycles(&domain, &partner, &matrices)?;
        check_cycles(&cycles, &matrices, kind.is_mirrored())?;
        Ok(QuotientSpace {
            kind,
            pairings,
            matrices,
            partner,
            faces: domain.faces().to_vec(),
            domain: Some(domain),
            horo: None,
            placement: Isometry::IDENTITY,
        })
    }

    /// The Seifert-Weber dodecahedral space.
    ///
    /// Errors: as [`QuotientSpace::new`] (none: `tests/spaces.rs`).
    pub fn seifert_weber() -> Result<QuotientSpace, GeomError> {
        QuotientSpace::new(SpaceKind::SeifertWeber)
    }

    /// The edge cycles of its gluing (`gluing.rs`).
    ///
    /// Errors: none for a space that was built; kept for a gluing read
    /// from elsewhere.
    pub fn edge_cycles(&self) -> Result<Vec<super::EdgeCycle>, GeomError> {
        match (&self.domain, &self.horo) {
            (Some(domain), _) => edge_cycles(domain, &self.partner, &self.matrices),
            (None, Some(cell)) => {
                Ok(cell.relations(&self.faces, self.kind.symbol().map_or(2, |s| s.r())))
            }
            (None, None) => Ok(Vec::new()),
        }
    }
}

/// The faces (inward unit normals) of the base cell: the orbit of the face
/// mirror `n3` under the cell's group `<R0, R1, R2>`. The cell's mirrors
/// fix the origin (no time part), so the orbit is that of `n3`'s spatial
/// part under three reflections of R³, carried out in double-double
/// arithmetic: each face is rounded once, and a dodecahedron's dihedral
/// angles then sum round an edge cycle to 2π within 1e-14 (in plain f64
/// the deepest faces gather 1e-14 each).
fn cell_faces(simplex: &CoxeterSimplex) -> Vec<DVec4> {
    let normals = simplex.normals();
    let mirrors: Vec<DVec3> = normals[..3].iter().map(|n| n.truncate()).collect();
    let start = normals[3].truncate();
    let mut orbit: Vec<[DVec3; 2]> = vec![[start, DVec3::ZERO]];
    let mut k = 0;
    while k < orbit.len() && orbit.len() <= 64 {
        let x = orbit[k];
        for m in &mirrors {
            let image = reflect_dd(x, *m);
            if !orbit
                .iter()
                .any(|f| (f[0] - image[0]).abs().max_element() < 1e-9)
            {
                orbit.push(image);
            }
        }
        k += 1;
    }
    orbit
        .iter()
        .map(|[hi, lo]| (*hi + *lo).extend(normals[3].w))
        .collect()
}

/// `x - 2 (x.m) m` for `x = hi + lo` in double-double arithmetic (`m`
/// taken as exact).
fn reflect_dd([hi, lo]: [DVec3; 2], m: DVec3) -> [DVec3; 2] {
    // d = x.m to double-double.
    let mut d = (0.0, 0.0);
    for i in 0..3 {
        let (p, e) = two_prod(hi[i], m[i]);
        let (s, f) = two_sum(d.0, p);
        d = (s, d.1 + f + e + lo[i] * m[i]);
    }
    let (d_hi, d_lo) = two_sum(d.0, d.1);
    let mut out = [DVec3::ZERO; 2];
    for i in 0..3 {
        let (p, e) = two_prod(2.0 * d_hi, m[i]);
        let (s, f) = two_sum(hi[i], -p);
        let low = lo[i] + f - e - 2.0 * d_lo * m[i];
        let (h, l) = two_sum(s, low);
        out[0][i] = h;
        out[1][i] = l;
    }
    out
}

/// Faces, partners and matrices of Seifert-Weber (module docs).
fn seifert_weber(faces: Vec<DVec4>) -> Result<Gluing, GeomError> {
    let mut partner = Vec::with_capacity(faces.len());
    let mut matrices = Vec::with_capacity(faces.len());
    for n in &faces {
        let u = -n.truncate().normalize();
        let inradius = (-n.w).asinh();
        let opposite = faces
            .iter()
            .position(|m| (m.truncate().normalize() - u).length() < 1e-9)
            .ok_or_else(|| GeomError::BadDomain("a dodecahedron face has no opposite".into()))?;
        let shift =
            Isometry::transvection_from_origin(Point::at_distance_from_origin(-u, 2.0 * inradius)?);
        let turn = Isometry::orthogonal(DMat3::from_axis_angle(u, 0.6 * std::f64::consts::PI))?;
        partner.push(opposite);
        matrices.push(turn.compose(&shift).to_lorentz());
    }
    Ok((faces, partner, matrices))
}

/// Faces, partners and pairing matrices.
type Gluing = (Vec<DVec4>, Vec<usize>, Vec<DMat4>);

/// A pairing by vertex correspondence: three vertices of a face (ideal
/// points, by direction) and their images on the partner face.
struct FacePairing {
    from: [DVec3; 3],
    to: [DVec3; 3],
}

/// The gluing of `faces` by `pairings`, each given once (the partner's is
/// its inverse).
fn by_correspondence(faces: Vec<DVec4>, pairings: &[FacePairing]) -> Result<Gluing, GeomError> {
    let domain = DomainPolyhedron::from_faces(faces.clone())?;
    let mut partner = vec![usize::MAX; faces.len()];
    let mut matrices = vec![DMat4::IDENTITY; faces.len()];
    let find = |dirs: &[DVec3; 3]| -> Result<(usize, [usize; 3]), GeomError> {
        let mut k = [0usize; 3];
        for (slot, d) in k.iter_mut().zip(dirs) {
            *slot = domain
                .vertex_at(d.normalize().extend(1.0))
                .ok_or_else(|| GeomError::BadDomain(format!("no vertex at {d}")))?;
        }
        let face = (0..faces.len())
            .find(|&f| k.iter().all(|v| domain.face_vertices(f).contains(v)))
            .ok_or_else(|| GeomError::BadDomain(format!("no face through {dirs:?}")))?;
        Ok((face, k))
    };
    for p in pairings {
        let (i, from) = find(&p.from)?;
        let (j, to) = find(&p.to)?;
        let m = pairing_matrix(&domain, (i, from), (j, to))?;
        partner[i] = j;
        partner[j] = i;
        matrices[i] = m;
        matrices[j] = crate::lorentz::inverse(m);
    }
    if let Some(face) = partner.iter().position(|&p| p == usize::MAX) {
        return Err(GeomError::BadPairing {
            face: face + 1,
            problem: "is missing".to_string(),
        });
    }
    Ok((faces, partner, matrices))
}

/// The directions of a vertex of a gluing table: the ideal point with
/// that unit spatial part.
const fn dir(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// `1/√6` and `2/√6`.
const A6: f64 = 0.408_248_290_463_863;
const B6: f64 = 0.816_496_580_927_726_1;
/// The bipyramid's equatorial vertices off the shared face: the base
/// tetrahedron's apex and its mirror image in `n3`.
const E1: f64 = 0.169_101_978_725_763_7;
const E2: f64 = 0.985_598_559_653_491_3;

/// The figure-eight knot complement's gluing (`docs/manifolds.md`): the
/// bipyramid's vertices `v0 = (a, a, 2a)`, `v1 = (a, a, -2a)` with
/// `a = 1/√6` (the shared face's two vertices off the equator),
/// `v2 = (e1, -e2, 0)` (its third), the base apex `v3 = (-e2, e1, 0)`
/// and its mirror image `v4 = (e2, -e1, 0)`; each face of the base
/// tetrahedron glued to one of its mirror image.
const FIGURE_EIGHT: [FacePairing; 3] = {
    let v0 = dir(A6, A6, B6);
    let v1 = dir(A6, A6, -B6);
    let v2 = dir(E1, -E2, 0.0);
    let v3 = dir(-E2, E1, 0.0);
    let v4 = dir(E2, -E1, 0.0);
    [
        FacePairing {
            from: [v0, v1, v3],
            to: [v0, v4, v2],
        },
        FacePairing {
            from: [v0, v3, v2],
            to: [v1, v2, v4],
        },
        FacePairing {
            from: [v1, v2, v3],
            to: [v1, v4, v0],
        },
    ]
};

/// The Whitehead link complement's gluing (`docs/manifolds.md`): the
/// octahedron's vertices `w0 = (½, ½, h)`, `w1 = (½, ½, -h)`,
/// `w2 = (h, -h, 0)`, `w3 = (-h, h, 0)`, `w4 = (-½, -½, h)`,
/// `w5 = (-½, -½, -h)` with `h = 1/√2`; the cusps are `{w0, w5}` and
/// `{w1, w2, w3, w4}`.
const WHITEHEAD: [FacePairing; 4] = {
    use std::f64::consts::FRAC_1_SQRT_2 as H;
    let w0 = dir(0.5, 0.5, H);
    let w1 = dir(0.5, 0.5, -H);
    let w2 = dir(H, -H, 0.0);
    let w3 = dir(-H, H, 0.0);
    let w4 = dir(-0.5, -0.5, H);
    let w5 = dir(-0.5, -0.5, -H);
    [
        FacePairing {
            from: [w0, w2, w1],
            to: [w0, w4, w3],
        },
        FacePairing {
            from: [w0, w1, w3],
            to: [w5, w2, w1],
        },
        FacePairing {
            from: [w0, w4, w2],
            to: [w5, w3, w4],
        },
        FacePairing {
            from: [w1, w5, w3],
            to: [w2, w5, w4],
        },
    ]
};
