//! Face pairings: built from vertex correspondences, and checked.
//!
//! **A pairing from three vertices.** The pairing of face `i` onto face
//! `j` maps three vertices `a, b, c` of face `i` to `a', b', c'` of face
//! `j` and the outside of the domain at `i` to the inside at `j`, so its
//! Lorentz matrix `M` has `M n_i = -n_j` and `M a = λ_a a'` (etc.), with
//! `λ = 1` for finite vertices. For ideal vertices (null vectors, defined
//! up to scale) the scales follow from `<Ma, Mb> = <a, b>`:
//! `λ_a λ_b = <a,b>/<a',b'>` and its two companions give
//! `λ_a = sqrt(P_ab P_ac / P_bc)` with `P_xy = <x,y>/<x',y'>`. Then
//! `M = [λ_a a', λ_b b', λ_c c', -n_j] [a, b, c, n_i]⁻¹`.
//!
//! **Edge cycles** (Poincaré's polyhedron theorem). Leave the domain
//! through face `f` at edge `e`: the pairing `g_f` carries `e` to an edge
//! `e'` on the partner face and one other face `f'`, through which one
//! goes on, until the walk is back at `e` leaving by `f`. The dihedral
//! angles met sum to `S`, and the product `H` of the pairings fixes `e`. A
//! manifold needs `S = 2π` and `H = I` (the tiles close round the edge
//! once); the cell with mirror walls has cycles of two faces, `S = 2α`
//! for its dihedral angle `α = 2π/r`, and the Coxeter relation
//! `(g_b g_a)^r = I`.

use glam::{DMat4, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;

use super::dirichlet::{PAIRING_TOLERANCE, size};
use super::polyhedron::DomainPolyhedron;

/// One edge cycle: the faces left by in turn, the sum of the dihedral
/// angles and the product of the pairings.
#[derive(Clone, Debug)]
pub struct EdgeCycle {
    /// The faces left by, in order.
    pub faces: Vec<usize>,
    /// The sum of the dihedral angles at the edges of the cycle.
    pub angle_sum: f64,
    /// `g_{f_k} ∘ ... ∘ g_{f_1}`, which fixes the starting edge.
    pub holonomy: DMat4,
    /// The product of the pairings' sizes (largest entries), which bounds
    /// the size of the holonomy and of its rounding.
    pub size: f64,
}

/// The most a cycle's tolerance grows with its size: a gluing that does
/// not close is off by a finite angle or a translation along the edge,
/// never by this little.
const MAX_CYCLE_TOLERANCE: f64 = 1e-4;

/// The Lorentz matrix of the pairing that maps vertices `from` of face
/// `i` to `to` of face `j` (module docs).
pub(super) fn pairing_matrix(
    domain: &DomainPolyhedron,
    (i, from): (usize, [usize; 3]),
    (j, to): (usize, [usize; 3]),
) -> Result<DMat4, GeomError> {
    let v = domain.vertices();
    let [a, b, c] = from.map(|k| v[k]);
    let [a2, b2, c2] = to.map(|k| v[k]);
    let p = |x: DVec4, y: DVec4, x2: DVec4, y2: DVec4| lorentz::dot(x, y) / lorentz::dot(x2, y2);
    let (pab, pac, pbc) = (p(a, b, a2, b2), p(a, c, a2, c2), p(b, c, b2, c2));
    let la = (pab * pac / pbc).sqrt();
    let lb = pab / la;
    let lc = pac / la;
    let source = DMat4::from_cols(a, b, c, domain.faces()[i]);
    let image = DMat4::from_cols(la * a2, lb * b2, lc * c2, -domain.faces()[j]);
    let m = image * source.inverse();
    if !m.is_finite() {
        return Err(GeomError::BadPairing {
            face: i + 1,
            problem: "is not an isometry (its vertices are not congruent to the partner's)"
                .to_string(),
        });
    }
    Ok(m)
}

/// Checks that each pairing maps its face's vertices onto its partner's
/// and the outside at its face to the inside at its partner, and that
/// the partner's pairing is its inverse.
pub(super) fn check_pairings(
    domain: &DomainPolyhedron,
    partner: &[usize],
    matrices: &[DMat4],
) -> Result<(), GeomError> {
    for (i, m) in matrices.iter().enumerate() {
        let j = partner[i];
        let bad = |problem: &str| GeomError::BadPairing {
            face: i + 1,
            problem: problem.to_string(),
        };
        if partner.get(j) != Some(&i) {
            return Err(bad("names a partner that is not paired back with it"));
        }
        let (ni, nj) = (domain.faces()[i], domain.faces()[j]);
        let error = (*m * ni + nj).abs().max_element();
        let tolerance = PAIRING_TOLERANCE * size(m) * ni.abs().max_element().max(1.0);
        if !(error <= tolerance) {
            return Err(GeomError::InexactPairing {
                face: i + 1,
                problem: "does not send the outside of its face to the inside of its partner",
                error,
                tolerance,
            });
        }
        let mut images: Vec<usize> = Vec::new();
        for &k in domain.face_vertices(i) {
            match domain.vertex_at(*m * domain.vertices()[k]) {
                Some(image) if domain.face_vertices(j).contains(&image) => images.push(image),
                _ => return Err(bad("does not map its face's vertices onto its partner's")),
            }
        }
        images.sort_unstable();
        images.dedup();
        if images.len() != domain.face_vertices(j).len() {
            return Err(bad("does not map its face onto its partner's whole face"));
        }
        let error = size(&(matrices[j] * *m - DMat4::IDENTITY));
        let tolerance = PAIRING_TOLERANCE * size(&matrices[j]) * size(m);
        if !(error <= tolerance) {
            return Err(GeomError::InexactPairing {
                face: i + 1,
                problem: "is not undone by its partner's pairing",
                error,
                tolerance,
            });
        }
    }
    Ok(())
}

/// Every edge cycle of the gluing, each listed once (from its first edge
/// in the domain's order, leaving by that edge's first face).
pub(super) fn edge_cycles(
    domain: &DomainPolyhedron,
    partner: &[usize],
    matrices: &[DMat4],
) -> Result<Vec<EdgeCycle>, GeomError> {
    let edges = domain.edges();
    // (edge, face left by) pairs already in a cycle.
    let mut seen = vec![[false; 2]; edges.len()];
    let mut cycles = Vec::new();
    for start in 0..edges.len() {
        if seen[start][0] {
            continue;
        }
        let (mut e, mut side) = (start, 0usize);
        let mut faces = Vec::new();
        let mut angle_sum = 0.0;
        let mut holonomy = DMat4::IDENTITY;
        let mut cycle_size = 1.0f64;
        for _ in 0..=4 * edges.len() {
            seen[e][side] = true;
            let f = edges[e].faces[side];
            faces.push(f);
            angle_sum += domain.dihedral(&edges[e]);
            let m = matrices[f];
            holonomy = m * holonomy;
            cycle_size = (cycle_size * size(&m)).min(1e300);
            let ends = edges[e]
                .vertices
                .map(|k| domain.vertex_at(m * domain.vertices()[k]));
            let next = edges.iter().position(|x| {
                let [Some(u), Some(v)] = ends else {
                    return false;
                };
                x.vertices == [u, v] || x.vertices == [v, u]
            });
            let Some(next) = next else {
                return Err(GeomError::BadPairing {
                    face: f + 1,
                    problem: "does not map an edge of its face onto an edge".to_string(),
                });
            };
            // Arrived through the partner face; leave by the other one.
            let arrived = partner[f];
            let other = if edges[next].faces[0] == arrived {
                1
            } else if edges[next].faces[1] == arrived {
                0
            } else {
                return Err(GeomError::BadPairing {
                    face: f + 1,
                    problem: "maps an edge to one off its partner face".to_string(),
                });
            };
            e = next;
            side = other;
            if e == start && side == 0 {
                break;
            }
        }
        // The walk from the other side of the same cycle is the same cycle.
        mark_reverse(domain, partner, matrices, &mut seen, start);
        cycles.push(EdgeCycle {
            faces,
            angle_sum,
            holonomy,
            size: cycle_size,
        });
    }
    Ok(cycles)
}

/// Marks the cycle of `(start, leaving by its second face)`: the same
/// cycle walked the other way round.
fn mark_reverse(
    domain: &DomainPolyhedron,
    partner: &[usize],
    matrices: &[DMat4],
    seen: &mut [[bool; 2]],
    start: usize,
) {
    let edges = domain.edges();
    let (mut e, mut side) = (start, 1usize);
    for _ in 0..=4 * edges.len() {
        if seen[e][side] {
            return;
        }
        seen[e][side] = true;
        let f = edges[e].faces[side];
        let m = matrices[f];
        let ends = edges[e]
            .vertices
            .map(|k| domain.vertex_at(m * domain.vertices()[k]));
        let Some(next) = edges.iter().position(|x| {
            let [Some(u), Some(v)] = ends else {
                return false;
            };
            x.vertices == [u, v] || x.vertices == [v, u]
        }) else {
            return;
        };
        let arrived = partner[f];
        side = usize::from(edges[next].faces[0] == arrived);
        e = next;
    }
}

/// Checks each cycle: a manifold's sums to 2π with the identity, to
/// `τ k max|M|²` in the angle and `τ k Π|M|` in the holonomy's entries
/// for a cycle of `k` faces (both at most [`MAX_CYCLE_TOLERANCE`]); a
/// mirror's (two faces, each its own partner, exact built-in cells)
/// keeps the Coxeter relation to 1e-10.
pub(super) fn check_cycles(
    cycles: &[EdgeCycle],
    matrices: &[DMat4],
    mirrors: bool,
) -> Result<(), GeomError> {
    use std::f64::consts::PI;
    for c in cycles {
        let (error, tolerance) = if mirrors {
            // (g_b g_a)^r = I, with r = 2π / α = 4π / S.
            let r = (4.0 * PI / c.angle_sum).round();
            let off = (4.0 * PI / c.angle_sum - r).abs();
            let power_error = if (2.0..1e3).contains(&r) {
                size(&(power(c.holonomy, r as u32) - DMat4::IDENTITY))
            } else {
                f64::INFINITY
            };
            // Both measured against 1e-10: report the larger ratio.
            (off.max(power_error), 1e-10)
        } else {
            let k = c.faces.len() as f64;
            let largest = c
                .faces
                .iter()
                .map(|&f| size(&matrices[f]))
                .fold(1.0, f64::max);
            let angle_tolerance =
                (PAIRING_TOLERANCE * k * largest * largest).clamp(1e-12, MAX_CYCLE_TOLERANCE);
            let holonomy_tolerance =
                (PAIRING_TOLERANCE * k * c.size).clamp(1e-12, MAX_CYCLE_TOLERANCE);
            let angle_error = (c.angle_sum - 2.0 * PI).abs();
            let holonomy_error = size(&(c.holonomy - DMat4::IDENTITY));
            if angle_error / angle_tolerance >= holonomy_error / holonomy_tolerance {
                (angle_error, angle_tolerance)
            } else {
                (holonomy_error, holonomy_tolerance)
            }
        };
        if !(error <= tolerance) {
            return Err(GeomError::EdgeCycle {
                faces: c.faces.iter().map(|f| f + 1).collect(),
                degrees: c.angle_sum.to_degrees(),
                error,
                tolerance,
            });
        }
    }
    Ok(())
}

/// `m^k`.
pub(super) fn power(m: DMat4, k: u32) -> DMat4 {
    (0..k).fold(DMat4::IDENTITY, |acc, _| m * acc)
}

/// The pairings as isometries (their exact, stable form), from their
/// matrices; the orthogonal part is rounded to `τ |M|²` like the rest.
pub(super) fn isometries(matrices: &[DMat4]) -> Result<Vec<Isometry>, GeomError> {
    matrices
        .iter()
        .map(|m| {
            let s = size(m);
            Isometry::from_lorentz_within(*m, (PAIRING_TOLERANCE * s * s).max(1e-9))
        })
        .collect()
}
