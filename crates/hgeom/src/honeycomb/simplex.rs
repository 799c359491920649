//! The characteristic simplex (orthoscheme) of a regular honeycomb `{p,q,r}`:
//! the fundamental domain of its Coxeter group `[p,q,r]`.
//!
//! **Vertices and mirrors.** The simplex has vertices `v0` (a vertex of the
//! honeycomb), `v1` (the midpoint of an edge at `v0`), `v2` (the centre of a
//! face at that edge) and `v3` (the centre of a cell at that face); the
//! mirror `m_i` is the face of the simplex opposite `v_i`. So `m0` (through
//! `v1 v2 v3`) is the perpendicular bisector of the edge, `m1` and `m2` are
//! symmetry planes of the cell through its centre, and `m3` (through
//! `v0 v1 v2`) is the plane of the face. Their inward unit normals `n_i`
//! (the simplex is `{X : <X,n_i> >= 0}`) have the Gram matrix
//! `<n_i,n_j> = -cos(π/m_ij)` with `m01 = p`, `m12 = q`, `m23 = r` and all
//! other pairs `2` ([`super::schlafli`]); `v_k` is the future vector
//! Lorentz-orthogonal to the three `n_j`, `j != k`: a hyperboloid point,
//! or a null vector (scaled to time 1) when the vertex is ideal.
//!
//! **Placement.** Three mirrors through a finite vertex have spacelike
//! normals with no time part when that vertex is the origin, so:
//!
//! - *Finite cells* (`v3` finite; the compact honeycombs and those with
//!   ideal vertices): `v3` is the origin, with `u0 = (0,0,1)`,
//!   `u2 = (1,-1,0)/√2` and `u1 = (x, y, -cos π/p)` solving
//!   `u1.u2 = -cos π/q`, `|u1| = 1`:
//!   `x = (-c_q + S)/√2`, `y = (c_q + S)/√2` with
//!   `S = sqrt(sin²(π/p) - cos²(π/q))` (real because the cell is
//!   spherical). The face centre lies on `m0 ∩ m1` along the unit `f`
//!   orthogonal to `u0`, `u1` with `f.u2 > 0`, and the face plane is
//!   `x.f = h w` (Klein model) with inward normal `k(-f, -h)`; unit length
//!   gives `k² (1 - h²) = 1` and `<n2,n3> = -k (u2.f) = -cos π/r` gives
//!   `k = cos(π/r)/(u2.f)`. For `{4,3}` this is `f = (1,0,0)`,
//!   `v1 ∝ (1,1,0)`, `v0 ∝ (1,1,1)` and `h² = √5 - 2` for `r = 5`: exactly
//!   the cell of [`cube_435`](super::cube_435), axis-aligned with its
//!   vertices on the rays `(±1,±1,±1)`.
//! - *Horosphere-inscribed cells* (`v3` ideal: `{6,3,r}`, `{4,4,r}`,
//!   `{3,6,3}`): the face centre `v2` is the origin, with
//!   `u0 = (0,0,1)`, `u1 = (0, sin π/p, -cos π/p)`, `u3 = (-1,0,0)` (the face
//!   is the plane `x = 0`, the cell on its `x < 0` side) and
//!   `n2 = (s, c)` with `s.u0 = 0`, `s.u1 = -cos π/q`, `s.u3 = -cos π/r`:
//!   `s = (cos π/r, -cos(π/q)/sin(π/p), 0)` and `c = -sqrt(|s|² - 1)`
//!   (`|s|² > 1` is `det G < 0`; `c < 0` puts the origin inside).
//!
//! The base point ([`CoxeterSimplex::base`]) is that origin: the cell
//! centre when it is finite, else the face centre.

use glam::{DMat4, DVec3, DVec4};
use std::f64::consts::{FRAC_1_SQRT_2, PI};

use crate::lorentz;

use super::schlafli::Schlafli;

/// The characteristic simplex of a honeycomb, in its base placement.
///
/// Invariants: `normals[i]` are unit spacelike with the Gram matrix of the
/// symbol; `vertices[k]` is future, on the hyperboloid when finite, null
/// with time 1 when ideal (`ideal[k]`); `<vertices[k], normals[j]> = 0`
/// for `j != k` and `> 0` for `j = k`; all to rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoxeterSimplex {
    normals: [DVec4; 4],
    vertices: [DVec4; 4],
    ideal: [bool; 4],
}

fn cos_pi(m: u32) -> f64 {
    (PI / f64::from(m)).cos()
}

fn sin_pi(m: u32) -> f64 {
    (PI / f64::from(m)).sin()
}

impl CoxeterSimplex {
    /// The simplex of `{p,q,r}` in the placement of the module docs.
    ///
    /// # Accuracy
    ///
    /// The Gram matrix holds to 1e-15 and the vertices are orthogonal to
    /// their three mirrors to 1e-15 (`gram_matrix_and_vertices_of_all_fifteen`).
    pub fn new(symbol: Schlafli) -> CoxeterSimplex {
        let (p, q, r) = (symbol.p(), symbol.q(), symbol.r());
        let (cp, sp, cq, cr) = (cos_pi(p), sin_pi(p), cos_pi(q), cos_pi(r));
        let u0 = DVec3::Z;
        let normals = if symbol.has_ideal_cells() {
            let u1 = DVec3::new(0.0, sp, -cp);
            let s = DVec3::new(cr, -cq / sp, 0.0);
            // |s|^2 - 1 > 0 is det G < 0 (module docs); the guard only keeps
            // rounding of an exact identity from a NaN.
            let c = -(s.length_squared() - 1.0).max(0.0).sqrt();
            [u0.extend(0.0), u1.extend(0.0), s.extend(c), DVec4::NEG_X]
        } else {
            let root = (sp * sp - cq * cq).max(0.0).sqrt();
            let u1 = DVec3::new(
                (root - cq) * FRAC_1_SQRT_2,
                (root + cq) * FRAC_1_SQRT_2,
                -cp,
            );
            let u2 = DVec3::new(FRAC_1_SQRT_2, -FRAC_1_SQRT_2, 0.0);
            let mut f = u0.cross(u1).normalize();
            if f.dot(u2) < 0.0 {
                f = -f;
            }
            let k = cr / f.dot(u2);
            let h = (1.0 - 1.0 / (k * k)).max(0.0).sqrt();
            [
                u0.extend(0.0),
                u1.extend(0.0),
                u2.extend(0.0),
                k * (-f).extend(-h),
            ]
        };
        let ideal = [
            symbol.has_ideal_vertices(),
            false,
            false,
            symbol.has_ideal_cells(),
        ];
        let mut vertices = [DVec4::W; 4];
        for (k, v) in vertices.iter_mut().enumerate() {
            let [a, b, c] = match k {
                0 => [1, 2, 3],
                1 => [0, 2, 3],
                2 => [0, 1, 3],
                _ => [0, 1, 2],
            }
            .map(|j| normals[j]);
            let mut x = lorentz::orthogonal_complement(a, b, c);
            if x.w < 0.0 {
                x = -x;
            }
            *v = if ideal[k] {
                // Null: the spatial part has length w; scaling it to 1 keeps
                // the vector exactly null.
                let s = x.truncate().normalize();
                s.extend(1.0)
            } else {
                x / (-lorentz::dot(x, x)).sqrt()
            };
        }
        // The base point is exactly the origin.
        let base = if symbol.has_ideal_cells() { 2 } else { 3 };
        vertices[base] = DVec4::W;
        CoxeterSimplex {
            normals,
            vertices,
            ideal,
        }
    }

    /// The inward unit normals of the mirrors `m0..m3`.
    pub fn normals(&self) -> [DVec4; 4] {
        self.normals
    }

    /// The vertices `v0..v3`: hyperboloid points, or null vectors with time
    /// 1 for ideal vertices.
    pub fn vertices(&self) -> [DVec4; 4] {
        self.vertices
    }

    /// Which vertices are ideal.
    pub fn ideal(&self) -> [bool; 4] {
        self.ideal
    }

    /// The index of the vertex at the origin: 3 (the cell centre) when it is
    /// finite, else 2 (the face centre).
    pub fn base(&self) -> usize {
        if self.ideal[3] { 2 } else { 3 }
    }

    /// The Lorentz matrix of the reflection in mirror `i`:
    /// `X -> X - 2 <X,n> n`.
    pub fn reflection(&self, i: usize) -> DMat4 {
        reflection_matrix(self.normals[i])
    }
}

pub(crate) use crate::lorentz::reflection_matrix;

#[cfg(test)]
mod tests {
    use super::*;

    fn gram(m: (u32, u32, u32), i: usize, j: usize) -> f64 {
        if i == j {
            return 1.0;
        }
        let (a, b) = (i.min(j), i.max(j));
        match (a, b) {
            (0, 1) => -cos_pi(m.0),
            (1, 2) => -cos_pi(m.1),
            (2, 3) => -cos_pi(m.2),
            _ => 0.0,
        }
    }

    #[test]
    fn gram_matrix_and_vertices_of_all_fifteen() {
        for (p, q, r) in Schlafli::ALL {
            let s = CoxeterSimplex::new(Schlafli::new(p, q, r).unwrap());
            let n = s.normals();
            for i in 0..4 {
                for j in 0..4 {
                    let g = lorentz::dot(n[i], n[j]);
                    assert!(
                        (g - gram((p, q, r), i, j)).abs() < 1e-15,
                        "{p}{q}{r} {i}{j}"
                    );
                }
            }
            for (k, v) in s.vertices().iter().enumerate() {
                let norm = lorentz::dot(*v, *v);
                if s.ideal()[k] {
                    assert!(norm.abs() < 1e-15 && v.w == 1.0);
                } else {
                    assert!((norm + 1.0).abs() < 1e-14 && v.w >= 1.0);
                }
                for (j, nj) in n.iter().enumerate() {
                    let d = lorentz::dot(*v, *nj);
                    if j == k {
                        assert!(d > 0.01, "{p}{q}{r} v{k} inside m{j}: {d}");
                    } else {
                        assert!(d.abs() < 1e-15, "{p}{q}{r} v{k} on m{j}: {d}");
                    }
                }
            }
            assert_eq!(s.vertices()[s.base()], DVec4::W);
        }
    }

    #[test]
    fn the_435_simplex_is_the_cube_of_cube_435() {
        let s = CoxeterSimplex::new(Schlafli::new(4, 3, 5).unwrap());
        let v = s.vertices();
        let dir = |x: DVec4| x.truncate().normalize();
        assert!((dir(v[0]) - DVec3::ONE.normalize()).length() < 1e-15);
        assert!((dir(v[1]) - DVec3::new(1.0, 1.0, 0.0).normalize()).length() < 1e-15);
        assert!((dir(v[2]) - DVec3::X).length() < 1e-15);
        // cosh of the circumradius is phi^2/sqrt 2; the edge has cosh e = phi^2
        // (twice the distance v0 v1).
        let phi2 = (3.0 + 5f64.sqrt()) / 2.0;
        assert!((v[0].w - phi2 / 2f64.sqrt()).abs() < 1e-14);
        let half = lorentz::distance(v[0], v[1]);
        assert!(((2.0 * half).cosh() - phi2).abs() < 1e-14);
        // The face plane x = h w with h^2 = sqrt 5 - 2.
        let n3 = s.normals()[3];
        assert!(((n3.w / n3.x).powi(2) - (5f64.sqrt() - 2.0)).abs() < 1e-15);
    }

    #[test]
    fn reflections_fix_their_mirror_and_preserve_the_form() {
        let s = CoxeterSimplex::new(Schlafli::new(5, 3, 6).unwrap());
        for i in 0..4 {
            let m = s.reflection(i);
            let n = s.normals()[i];
            assert!((m * n + n).length() < 1e-14);
            for (k, v) in s.vertices().iter().enumerate() {
                if k != i {
                    assert!((m * *v - *v).length() < 1e-14);
                }
            }
            let (a, b) = (
                DVec4::new(0.3, -0.2, 0.1, 1.2),
                DVec4::new(1.0, 0.5, -0.7, 0.4),
            );
            assert!((lorentz::dot(m * a, m * b) - lorentz::dot(a, b)).abs() < 1e-14);
        }
    }
}

#[cfg(test)]
mod measures {
    use super::*;
    use crate::honeycomb::Schlafli;

    /// The table of docs/honeycombs.md ("Measures"): edge length, inradius,
    /// circumradius, midradius and face width of the fifteen, to 1e-6
    /// (infinite where a vertex or a cell centre is ideal).
    #[test]
    fn the_measures_table_of_the_docs() {
        let inf = f64::INFINITY;
        let table = [
            (
                (4, 3, 5),
                [1.616922, 0.530638, 1.226457, 0.842482, 1.253739],
            ),
            (
                (5, 3, 4),
                [1.061275, 0.808461, 1.226457, 1.061275, 1.253739],
            ),
            (
                (5, 3, 5),
                [1.992769, 0.996384, 1.902847, 1.439106, 1.827264],
            ),
            (
                (3, 5, 3),
                [1.736596, 0.868298, 1.382571, 0.972659, 0.788307],
            ),
            // The edge of {6,3,3} is exactly ln 2.
            ((6, 3, 3), [std::f64::consts::LN_2, inf, inf, inf, 1.098612]),
            ((3, 3, 6), [inf, 0.346574, inf, 0.658479, 1.098612]),
            ((4, 3, 6), [inf, 0.658479, inf, 1.146216, 1.762747]),
            ((6, 3, 4), [1.316958, inf, inf, inf, 1.762747]),
            ((5, 3, 6), [inf, 1.083937, inf, 1.690197, 2.248354]),
            ((6, 3, 5), [2.167874, inf, inf, inf, 2.248354]),
            ((6, 3, 6), [inf, inf, inf, inf, 2.633916]),
            ((3, 6, 3), [inf, inf, inf, inf, 1.098612]),
            ((4, 4, 3), [1.316958, inf, inf, inf, 1.098612]),
            ((3, 4, 4), [inf, 0.658479, inf, 0.881374, 1.098612]),
            ((4, 4, 4), [inf, inf, inf, inf, 1.762747]),
        ];
        for ((p, q, r), want) in table {
            let s = CoxeterSimplex::new(Schlafli::new(p, q, r).unwrap());
            let (n, v, ideal) = (s.normals(), s.vertices(), s.ideal());
            let d = |a: usize, b: usize| {
                if ideal[a] || ideal[b] {
                    inf
                } else {
                    lorentz::distance(v[a], v[b])
                }
            };
            // Half an edge is the vertex's distance from mirror 0; the
            // inradius the cell centre's from its face's mirror 3.
            let edge = if ideal[0] {
                inf
            } else {
                2.0 * lorentz::dot(v[0], n[0]).asinh()
            };
            let inradius = if ideal[3] {
                inf
            } else {
                lorentz::dot(v[3], n[3]).asinh()
            };
            let got = [edge, inradius, d(3, 0), d(3, 1), 2.0 * d(1, 2)];
            for (g, w) in got.iter().zip(want) {
                let ok = if w.is_infinite() {
                    g.is_infinite()
                } else {
                    (g - w).abs() < 1e-6
                };
                assert!(ok, "{{{p},{q},{r}}}: {got:?} against {want:?}");
            }
        }
    }
}
