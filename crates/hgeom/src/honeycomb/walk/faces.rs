//! The face a point of a regular honeycomb's face lies on: its centre, its
//! plane and its size, for laying an image on each face.
//!
//! The point is folded into the walk's domain by reflections in its walls
//! (symmetries of the honeycomb), as a ray's start is, keeping their
//! product `m`; there it lies on a face wall `n`, whose face is centred at
//! the foot of the perpendicular from the base cell's centre `v3` (the
//! face centre `v2` when the domain is the characteristic simplex). `m`
//! carries the centre and the normal back to the face the point is on.
//! The face's circumradius is `d(v2, v0)`, infinite when its vertices are
//! ideal.

use glam::{DMat4, DVec4};

use crate::lorentz;

use super::super::kernels::reflect;
use super::super::simplex::reflection_matrix;
use super::RegularHoneycomb;

/// The most reflections a point is folded by: a point within the horizon
/// is a few hundred walls from the base domain.
const MAX_FOLDS: usize = 10_000;

/// A face of a regular honeycomb, in the frame the honeycomb is placed in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceFrame {
    /// The face's centre, on the hyperboloid.
    pub centre: DVec4,
    /// The unit normal of its plane (either side).
    pub normal: DVec4,
    /// The distance from its centre to its vertices (infinite when they
    /// are ideal).
    pub circumradius: f64,
}

impl RegularHoneycomb {
    /// The face that the hyperboloid point `x` (a face hit's point) lies
    /// on (module docs); `None` for a uniform honeycomb or a point that
    /// cannot be folded.
    pub fn face_frame(&self, x: DVec4) -> Option<FaceFrame> {
        if !self.rings.is_regular() || !x.is_finite() {
            return None;
        }
        let walls = self.domain.walls();
        let mut o = self.to_local * x;
        let mut m = DMat4::IDENTITY;
        for _ in 0..MAX_FOLDS {
            // Points on a wall (the face itself) stay where they are.
            let tol = 1e-12 * o.w.abs().max(1.0);
            let outside = walls
                .iter()
                .map(|n| lorentz::dot(o, *n))
                .enumerate()
                .filter(|(_, a)| *a < -tol)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            let Some((i, _)) = outside else {
                break;
            };
            o = reflect(o, walls[i]);
            m *= reflection_matrix(walls[i]);
        }
        let (i, _) = walls
            .iter()
            .enumerate()
            .filter(|(i, _)| self.domain.is_face(*i))
            .map(|(i, n)| (i, lorentz::dot(o, *n).abs()))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        let v = self.simplex_vertices;
        let n = walls[i];
        let foot = v[3] - lorentz::dot(v[3], n) * n;
        let norm2 = -lorentz::dot(foot, foot);
        if !(norm2 > 0.0 && norm2.is_finite()) {
            return None;
        }
        let to = self.to_world * m;
        let circumradius = if v[0].w.is_finite() && lorentz::dot(v[0], v[0]) < -0.5 {
            lorentz::distance(v[2], v[0])
        } else {
            f64::INFINITY
        };
        Some(FaceFrame {
            centre: to * (foot / norm2.sqrt()),
            normal: to * n,
            circumradius,
        })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::honeycomb::{HoneycombStyle, Schlafli, decode_honeycomb_part};
    use crate::ray::Ray;

    /// Rays from inside the base cube of `{4,3,5}` meet its faces: the
    /// first hit's face is centred `0.530638` (the inradius) from the
    /// origin; every hit lies on its face's plane, with the centre, and the
    /// circumradius is the square's.
    #[test]
    fn faces_are_found_where_rays_meet_them() {
        let style = HoneycombStyle {
            edges: None,
            faces: true,
            vertices: None,
            ..HoneycombStyle::default()
        };
        let h = RegularHoneycomb::new(Schlafli::new(4, 3, 5).unwrap(), style).unwrap();
        for d in [
            DVec3::new(0.1, 0.2, 1.0),
            DVec3::new(-0.7, 0.3, 0.2),
            DVec3::new(0.3, -0.9, -0.4),
        ] {
            let ray = Ray::from_origin_unchecked(d.normalize());
            let mut from = 0.0;
            for k in 0..3 {
                let hit = h.intersect(&ray, from, f64::INFINITY).unwrap();
                assert_eq!(
                    decode_honeycomb_part(hit.part).0,
                    crate::HoneycombPart::Face
                );
                let f = h.face_frame(hit.point).unwrap();
                assert!(
                    lorentz::dot(hit.point, f.normal).abs() < 1e-9,
                    "on its plane"
                );
                assert!(
                    lorentz::dot(f.centre, f.normal).abs() < 1e-9,
                    "centre on it"
                );
                if k == 0 {
                    let r = f.centre.w.acosh();
                    assert!((r - 0.530_638).abs() < 1e-6, "{r}");
                }
                // The right triangle centre, edge midpoint, vertex: half
                // the edge (1.616922) and half the face width (1.253739).
                let want = ((1.616_922f64 / 2.0).cosh() * (1.253_739f64 / 2.0).cosh()).acosh();
                assert!((f.circumradius - want).abs() < 1e-5, "{}", f.circumradius);
                from = hit.t + 1e-9;
            }
        }
    }
}
