//! The cell of a honeycomb inscribed in a horosphere (`{6,3,r}`,
//! `{4,4,r}`, `{3,6,3}`) as a domain with mirror walls. Its faces are
//! infinitely many: the images of the face mirror `m3` of the
//! characteristic simplex under the cell's own group `G = <R0, R1, R2>`,
//! which fixes the cell's ideal centre `v3` and acts on the horospheres
//! about it as a Euclidean wallpaper group.
//!
//! **The exit.** A ray in the cell leaves it through the first face it
//! reaches. Fold the ray into the *chamber* `{<X,n_k> >= 0, k = 0,1,2}` (a
//! cone from `v3`, one of `G`'s fundamental domains) by reflecting it in
//! the mirrors it is on the wrong side of; then walk it from chamber to
//! chamber, reflecting it in each of `m0..m2` it crosses (which keeps it
//! in the same cell), until it crosses `m3`: the face it leaves by is `m3`
//! carried back by the reflections made, `A⁻¹ n3`. A ray that runs into
//! `v3` crosses the chambers' walls ever more often and never a face; after
//! [`MAX_CHAMBER_STEPS`] it is taken to stay in the cell.
//!
//! **Faces near the base point.** The searches over tiles (`tiles.rs`)
//! need a finite list: the faces within [`NEAR_FACES`] of the base point
//! (the centre of face `m3`, at the origin), from a breadth-first search
//! over the chambers.

use glam::{DMat4, DVec4};

use crate::honeycomb::CoxeterSimplex;
use crate::lorentz;
use crate::ray::Ray;

use super::Crossing;
use super::gluing::EdgeCycle;

/// The most chambers a ray is walked through before it is taken to run
/// into the cell's ideal centre.
pub const MAX_CHAMBER_STEPS: usize = 10_000;

/// The distance from the base point within which faces are listed for the
/// searches over tiles: objects and lights must lie within it, less their
/// size (`docs/manifolds.md`).
pub const NEAR_FACES: f64 = 5.0;

/// The cell's chamber: the simplex's mirrors in the current placement.
#[derive(Clone, Debug)]
pub(super) struct HoroCell {
    normals: [DVec4; 4],
    mirrors: [DMat4; 4],
}

pub(super) use crate::lorentz::reflection_matrix as reflection;

impl HoroCell {
    /// The cell of `simplex` (whose cells are horosphere-inscribed) and its
    /// faces within [`NEAR_FACES`] of the base point.
    pub(super) fn new(simplex: &CoxeterSimplex) -> (HoroCell, Vec<DVec4>) {
        let normals = simplex.normals();
        let cell = HoroCell {
            normals,
            mirrors: normals.map(reflection),
        };
        let reach = NEAR_FACES.sinh();
        let mut faces = vec![normals[3]];
        // Chambers by their face: breadth first over G, keeping those whose
        // face is near.
        let key = |x: DVec4| {
            let q = x.truncate() / x.w;
            (
                (q.x * 1e7).round() as i64,
                (q.y * 1e7).round() as i64,
                (q.z * 1e7).round() as i64,
            )
        };
        let nudge = 0.01 * (normals[0] + normals[1] + normals[2]);
        let mut queue = std::collections::VecDeque::from([DMat4::IDENTITY]);
        let mut seen = std::collections::HashSet::from([key(DVec4::W + nudge)]);
        while let Some(g) = queue.pop_front() {
            if seen.len() > 50_000 {
                break;
            }
            for k in 0..3 {
                let h = g * cell.mirrors[k];
                let face = h * normals[3];
                // The key: where the chamber's own point (the base point
                // nudged into it) goes, so chambers sharing a face differ.
                if !seen.insert(key(h * (DVec4::W + nudge))) {
                    continue;
                }
                // <origin, n> = -n.w: sinh of the distance to the plane.
                if face.w.abs() > reach {
                    continue;
                }
                if !faces.iter().any(|f| (*f - face).abs().max_element() < 1e-9) {
                    faces.push(face);
                }
                queue.push_back(h);
            }
        }
        (cell, faces)
    }

    /// The base point (the centre of face `m3`, the simplex's vertex `v2`)
    /// in the current placement: the point on `m0`, `m1` and `m3`.
    fn base_point(&self) -> DVec4 {
        let [n0, n1, _, n3] = self.normals;
        // v2 is orthogonal to m0, m1 and m3.
        let mut x = lorentz::orthogonal_complement(n0, n1, n3);
        if x.w < 0.0 {
            x = -x;
        }
        x / (-lorentz::dot(x, x)).sqrt()
    }

    /// The cell moved by the Lorentz matrix `m`.
    pub(super) fn transformed(&self, m: &DMat4) -> HoroCell {
        let normals = self.normals.map(|n| *m * n);
        HoroCell {
            normals,
            mirrors: normals.map(reflection),
        }
    }

    /// `x` reflected into the chamber, and the reflections made (as one
    /// matrix `A`: chamber frame = `A` cell frame).
    fn fold(&self, mut x: DVec4, mut d: DVec4) -> (DVec4, DVec4, DMat4) {
        let mut a = DMat4::IDENTITY;
        for _ in 0..MAX_CHAMBER_STEPS {
            let Some(k) = (0..3).find(|&k| lorentz::dot(x, self.normals[k]) < 0.0) else {
                break;
            };
            x = self.mirrors[k] * x;
            d = self.mirrors[k] * d;
            a = self.mirrors[k] * a;
        }
        (x, d, a)
    }

    /// True if `x` lies in the cell, to `tolerance` in `sinh` of the
    /// distance outside a face.
    pub(super) fn contains(&self, x: DVec4, tolerance: f64) -> bool {
        let (x, _, _) = self.fold(x, DVec4::ZERO);
        lorentz::dot(x, self.normals[3]) >= -tolerance
    }

    /// The first face the ray leaves the cell by (module docs).
    pub(super) fn exit(&self, ray: &Ray) -> Option<Crossing> {
        let (mut o, mut d, mut a) = self.fold(ray.origin, ray.dir);
        let mut t = 0.0;
        for _ in 0..MAX_CHAMBER_STEPS {
            let mut best: Option<(usize, f64)> = None;
            for (k, n) in self.normals.iter().enumerate() {
                let b = lorentz::dot(d, *n);
                if !(b < 0.0) {
                    continue;
                }
                let s = lorentz::dot(o, *n).max(0.0) / -b;
                if best.is_none_or(|(_, bs)| s < bs) {
                    best = Some((k, s));
                }
            }
            let (k, s) = best?;
            if !(s < 1.0) {
                return None;
            }
            t += s.atanh();
            if k == 3 {
                let normal = lorentz::inverse(a) * self.normals[3];
                return Some(Crossing {
                    face: usize::MAX,
                    t,
                    tanh_t: t.tanh(),
                    normal,
                });
            }
            // Step to the wall and fold the ray back into the chamber.
            let mut x = o + s * d;
            let mut v = s * o + d;
            lorentz::renormalise(&mut x, &mut v);
            o = self.mirrors[k] * x;
            d = self.mirrors[k] * v;
            a = self.mirrors[k] * a;
        }
        None
    }

    /// The Coxeter relations of the mirror walls: for each pair of the
    /// listed faces within distance 1.5 of the base point (as a matrix
    /// far out is good only to `eps cosh²` of its distance, the relations
    /// are checked where they are sharp; the group is the same
    /// everywhere) that meet at the cell's dihedral angle `2π/r`, the
    /// two-face cycle and its holonomy `R_b R_a`.
    pub(super) fn relations(&self, faces: &[DVec4], r: u32) -> Vec<EdgeCycle> {
        let angle = 2.0 * std::f64::consts::PI / f64::from(r);
        let origin = self.base_point();
        let near: Vec<usize> = (0..faces.len())
            .filter(|&k| lorentz::dot(origin, faces[k]).abs() <= 1.5f64.sinh())
            .collect();
        let mut cycles = Vec::new();
        for (i, &a) in near.iter().enumerate() {
            for &b in &near[i + 1..] {
                let c = -lorentz::dot(faces[a], faces[b]);
                if (c - angle.cos()).abs() > 1e-9 {
                    continue;
                }
                let holonomy = reflection(faces[b]) * reflection(faces[a]);
                cycles.push(EdgeCycle {
                    faces: vec![a, b],
                    angle_sum: 2.0 * c.clamp(-1.0, 1.0).acos(),
                    size: super::dirichlet::size(&reflection(faces[a]))
                        * super::dirichlet::size(&reflection(faces[b])),
                    holonomy,
                });
            }
        }
        cycles
    }
}
