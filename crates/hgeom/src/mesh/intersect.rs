//! Ray queries: the nearest hit through the BVH (front to back, pruned by
//! the best hit so far), the any-hit form for shadow rays, and the
//! exhaustive reference both are checked against.

use glam::DVec4;

use super::TriangleMesh;
use super::build::kept_plane;
use super::bvh::{KleinSegment, MAX_DEPTH};
use super::exact::Projection;
use crate::plane::HPlane;
use crate::ray::{Hit, Ray};

/// The traversal stack: at most one entry per level, plus the root.
const STACK: usize = MAX_DEPTH + 2;

impl TriangleMesh {
    /// The first intersection with `t` in `(t_min, t_max)`, with the same
    /// contract as [`ConvexPolygon::intersect`](crate::ConvexPolygon::intersect):
    /// `None` for a miss, a ray parallel to a triangle's plane, or a
    /// non-finite ray. Triangles are two-sided; the hit normal is the unit
    /// normal of the triangle's plane on its counter-clockwise side (see the
    /// type docs), which is tangent at every point of the plane.
    ///
    /// The ray is carried into the local frame by the inverse placement's
    /// Lorentz matrix; the BVH and the inside test run there (see the module
    /// docs), and the crossing is solved with the triangle's plane carried
    /// out to the world frame ([`HPlane::crossing`], cancellation-free for
    /// rays from the origin), so `t`, the point ([`Ray::at`]) and the
    /// normal need no transformation back. Ties in `t` go to the triangle
    /// listed first.
    ///
    /// # Accuracy
    ///
    /// `t` as [`HPlane::crossing`] of the triangle's plane, whose normal is
    /// accurate to a few ulps per component: within 5e-12 (relative for
    /// `t > 1`; measured 2e-12) of the same triangle as a
    /// [`ConvexPolygon`](crate::ConvexPolygon) for rays from the origin to
    /// meshes up to 5 away, and within the polygon's own rounding scale
    /// (`plane_hit_tol`, measured 8e-12) for rays starting within 2 of the
    /// mesh (`mesh_hits_agree_with_convex_polygons` in `tests/mesh.rs`).
    /// Hit points lie on their plane to the rounding of [`Ray::at`]
    /// (`|<P,N>| / (|P| |N|)` measured 5e-15). The inside test is
    /// exact for the rounded projections, whose error is about
    /// `eps |X|^2 |A|` with `X` the ray origin in the local frame and `A` a
    /// vertex (so about `eps e^{2d}` for a ray starting `d` from the mesh's
    /// centre): a ray can count as hitting within that of an edge, but rays
    /// through shared edges and vertices of a closed mesh never miss
    /// (`rays_through_edges_and_vertices_never_miss`).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        self.intersect_indexed(ray, t_min, t_max)
            .map(|(hit, _)| hit)
    }

    /// [`TriangleMesh::intersect`], with the index of the triangle hit (into
    /// [`TriangleMesh::triangles`]).
    ///
    /// # Accuracy
    ///
    /// As [`TriangleMesh::intersect`].
    pub fn intersect_indexed(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(Hit, usize)> {
        let sh = &*self.shared;
        let local = self.local_ray(ray);
        let exact = Projection::new(&local)?;
        let segment = KleinSegment::new(&local, sh.scale);
        let s_lo = segment.lower(t_min);
        let mut s_hi = segment.upper(t_max);
        let mut best: Option<Candidate> = None;
        let mut best_t = t_max;
        let mut stack = [(0u32, 0.0f64); STACK];
        let mut sp = 0;
        if let Some(e) = segment.enter(&sh.nodes[0], s_lo, s_hi) {
            stack[0] = (0, e);
            sp = 1;
        }
        while sp > 0 {
            sp -= 1;
            let (index, entry) = stack[sp];
            if entry > s_hi {
                continue;
            }
            let node = &sh.nodes[index as usize];
            if node.count > 0 {
                let first = node.first as usize;
                for pos in first..first + node.count as usize {
                    let Some((t, normal)) = self.crossing(&exact, pos, ray, &local) else {
                        continue;
                    };
                    let triangle = sh.order[pos] as usize;
                    let closer =
                        t < best_t || (t == best_t && best.is_some_and(|b| triangle < b.triangle));
                    if t > t_min && closer {
                        best = Some(Candidate {
                            t,
                            normal,
                            triangle,
                            pos,
                        });
                        best_t = t;
                        s_hi = s_hi.min(segment.prune(t));
                    }
                }
            } else {
                let (a, b) = (index + 1, node.first);
                let ea = segment.enter(&sh.nodes[a as usize], s_lo, s_hi);
                let eb = segment.enter(&sh.nodes[b as usize], s_lo, s_hi);
                // Push the farther child first, so the nearer is visited first.
                let (near, far) = match (ea, eb) {
                    (Some(x), Some(y)) if y < x => (Some((b, y)), Some((a, x))),
                    _ => (ea.map(|x| (a, x)), eb.map(|y| (b, y))),
                };
                for item in [far, near].into_iter().flatten() {
                    stack[sp] = item;
                    sp += 1;
                }
            }
        }
        best.map(|c| (self.hit(ray, c), c.triangle))
    }

    /// Whether any triangle is met with `t` in `(t_min, t_max)`: the shadow
    /// ray form of [`TriangleMesh::intersect`], stopping at the first hit
    /// found (in no particular order).
    ///
    /// # Accuracy
    ///
    /// As [`TriangleMesh::intersect`]: true exactly when `intersect` would
    /// return a hit (`blocks_agrees_with_intersect` in this module).
    pub fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let sh = &*self.shared;
        let local = self.local_ray(ray);
        let Some(exact) = Projection::new(&local) else {
            return false;
        };
        let segment = KleinSegment::new(&local, sh.scale);
        let s_lo = segment.lower(t_min);
        let s_hi = segment.upper(t_max);
        let mut stack = [0u32; STACK];
        let mut sp = 0;
        if segment.enter(&sh.nodes[0], s_lo, s_hi).is_some() {
            sp = 1;
        }
        while sp > 0 {
            sp -= 1;
            let node = &sh.nodes[stack[sp] as usize];
            if node.count > 0 {
                let first = node.first as usize;
                for pos in first..first + node.count as usize {
                    let t = self.crossing(&exact, pos, ray, &local).map(|(t, _)| t);
                    if t.is_some_and(|t| t > t_min && t < t_max) {
                        return true;
                    }
                }
            } else {
                let index = stack[sp];
                for child in [index + 1, node.first] {
                    if segment
                        .enter(&sh.nodes[child as usize], s_lo, s_hi)
                        .is_some()
                    {
                        stack[sp] = child;
                        sp += 1;
                    }
                }
            }
        }
        false
    }

    /// [`TriangleMesh::intersect_indexed`] without the BVH: every triangle is
    /// tested. The reference the BVH is checked against, and the baseline
    /// of its benchmark; O(n) per ray.
    ///
    /// # Accuracy
    ///
    /// As [`TriangleMesh::intersect`], and identical to it: the same
    /// triangle, `t`, point and normal (`bvh_equals_brute_force` in this
    /// module, random meshes of 2000 triangles).
    pub fn intersect_exhaustive(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(Hit, usize)> {
        let sh = &*self.shared;
        let local = self.local_ray(ray);
        let exact = Projection::new(&local)?;
        let mut best: Option<Candidate> = None;
        for pos in 0..sh.tris.len() {
            let Some((t, normal)) = self.crossing(&exact, pos, ray, &local) else {
                continue;
            };
            let triangle = sh.order[pos] as usize;
            let closer = best.map_or(t < t_max, |b| {
                t < b.t || (t == b.t && triangle < b.triangle)
            });
            if t > t_min && closer {
                best = Some(Candidate {
                    t,
                    normal,
                    triangle,
                    pos,
                });
            }
        }
        best.map(|c| (self.hit(ray, c), c.triangle))
    }

    /// The ray carried into the local frame.
    #[inline]
    fn local_ray(&self, ray: &Ray) -> Ray {
        Ray {
            origin: self.to_local * ray.origin,
            dir: self.to_local * ray.dir,
        }
    }

    /// The exact test of the triangle at leaf position `pos`: if the ray's
    /// geodesic meets it, the arc length of the crossing (of either sign) and
    /// the world normal of its plane.
    #[inline]
    fn crossing(
        &self,
        exact: &Projection,
        pos: usize,
        ray: &Ray,
        local: &Ray,
    ) -> Option<(f64, DVec4)> {
        let corners = self.shared.corners(pos);
        if !exact.crosses(corners) {
            return None;
        }
        // The plane the build computed for this triangle, recomputed from
        // the same vertices (see `kept_plane`): only for the few triangles
        // the geodesic meets, so no triangle stores one.
        let plane = kept_plane(corners)?;
        // The world plane: its normal carried out by the Lorentz matrix and
        // renormalised, as `ConvexPolygon` does. Far out (beyond ~18) the
        // renormalisation cancels; the crossing is then solved in the local
        // frame, where it is as good as the local ray.
        let normal = self.to_world * plane.normal();
        match HPlane::from_normal(normal) {
            Ok(world) => world.crossing(ray).map(|t| (t, world.normal())),
            Err(_) => plane.crossing(local).map(|t| (t, normal)),
        }
    }

    #[inline]
    fn hit(&self, ray: &Ray, c: Candidate) -> Hit {
        let point = ray.at(c.t);
        let shading = match &self.smooth {
            Some(smooth) => self.shading_normal(smooth, (c.triangle, c.pos), point, c.normal),
            None => c.normal,
        };
        Hit {
            t: c.t,
            point,
            normal: c.normal,
            shading,
            // Which triangle: a renderer maps textures by it.
            part: u32::try_from(c.triangle).unwrap_or(u32::MAX),
        }
    }
}

/// The nearest crossing found so far.
#[derive(Clone, Copy)]
struct Candidate {
    t: f64,
    normal: DVec4,
    triangle: usize,
    /// Its leaf position.
    pos: usize,
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::isometry::Isometry;
    use crate::lorentz;
    use crate::mesh::test_support::{p, random_point, soup};
    use crate::point::Point;
    use crate::polygon::ConvexPolygon;
    use hscene_test_support::SplitMix64;

    #[test]
    fn bvh_equals_brute_force() {
        let mut rng = SplitMix64::new(7);
        for (reach, size) in [(1.5, 0.15), (3.0, 0.4), (0.5, 0.05)] {
            let mesh = soup(&mut rng, 2000, reach, size);
            let mut hits = 0;
            for k in 0..600 {
                let ray = if k % 2 == 0 {
                    Ray::from_origin_unchecked(rng.direction())
                } else {
                    Ray::from_ball_unchecked(&random_point(&mut rng, reach + 1.0), rng.direction())
                };
                let t_min = if k % 3 == 0 { 0.0 } else { 1e-9 };
                let t_max = if k % 5 == 0 { 1.0 } else { f64::INFINITY };
                let fast = mesh.intersect_indexed(&ray, t_min, t_max);
                let slow = mesh.intersect_exhaustive(&ray, t_min, t_max);
                assert_eq!(fast, slow, "ray {k}: {ray:?}");
                assert_eq!(mesh.blocks(&ray, t_min, t_max), slow.is_some());
                hits += usize::from(slow.is_some());
            }
            assert!(hits > 100, "only {hits} hits");
        }
    }

    /// The octahedron subdivided `levels` times (8 * 4^levels triangles),
    /// vertices at distance `radius`, wound outward.
    fn octasphere(levels: usize, radius: f64) -> (Vec<Point>, Vec<[u32; 3]>) {
        let mut dirs = vec![
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            -DVec3::X,
            -DVec3::Y,
            -DVec3::Z,
        ];
        let mut faces: Vec<[u32; 3]> = vec![
            [0, 1, 2],
            [1, 3, 2],
            [3, 4, 2],
            [4, 0, 2],
            [1, 0, 5],
            [3, 1, 5],
            [4, 3, 5],
            [0, 4, 5],
        ];
        for _ in 0..levels {
            let mut mid = std::collections::HashMap::new();
            let mut next = Vec::with_capacity(4 * faces.len());
            for [a, b, c] in faces {
                let mut m = |u: u32, v: u32| {
                    *mid.entry((u.min(v), u.max(v))).or_insert_with(|| {
                        dirs.push((dirs[u as usize] + dirs[v as usize]).normalize());
                        dirs.len() as u32 - 1
                    })
                };
                let (ab, bc, ca) = (m(a, b), m(b, c), m(c, a));
                next.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
            }
            faces = next;
        }
        for f in &faces {
            let [a, b, c] = f.map(|k| dirs[k as usize]);
            assert!((b - a).cross(c - a).dot(a + b + c) > 0.0);
        }
        let points = dirs
            .iter()
            .map(|d| Point::at_distance_from_origin(*d, radius).unwrap())
            .collect();
        (points, faces)
    }

    /// On a closed mesh, with rays aimed at its vertices and edges (where a
    /// box test that is not conservative would cull the triangle the exact
    /// test accepts), the BVH finds exactly what testing every triangle
    /// finds, and no ray escapes.
    #[test]
    fn bvh_equals_brute_force_at_edges_and_vertices() {
        let (points, faces) = octasphere(4, 1.2);
        let mut rng = SplitMix64::new(13);
        let f = Isometry::transvection_from_origin(random_point(&mut rng, 2.0)).compose(
            &Isometry::rotation_about_segment_unchecked(
                &crate::segment::Segment::new(Point::ORIGIN, random_point(&mut rng, 1.0)).unwrap(),
                1.0,
            ),
        );
        let mesh = TriangleMesh::new(points.clone(), faces.clone())
            .unwrap()
            .transformed(&f);
        assert_eq!(mesh.triangle_count(), 2048);
        let centre = f.apply(&Point::ORIGIN);
        let l = f.to_lorentz();
        let mut targets: Vec<DVec4> = points.iter().map(|p| l * p.to_hyperboloid()).collect();
        for [a, b, _] in &faces {
            let (x, y) = (
                points[*a as usize].to_hyperboloid(),
                points[*b as usize].to_hyperboloid(),
            );
            targets.push(l * (0.5 * (x + y)));
            targets.push(l * (0.9 * x + 0.1 * y));
        }
        for x in &targets {
            let target = Point::from_hyperboloid(*x / (-lorentz::dot(*x, *x)).sqrt()).unwrap();
            let outside = f.apply(&random_point(&mut rng, 0.4)).coords();
            let starts = [centre, Point::from_coords(outside).unwrap()];
            for start in starts {
                let dir = crate::segment::Segment::new(start, target)
                    .unwrap()
                    .direction_at_start();
                let ray = Ray::from_ball_unchecked(&start, dir);
                let fast = mesh.intersect_indexed(&ray, 0.0, f64::INFINITY);
                assert_eq!(fast, mesh.intersect_exhaustive(&ray, 0.0, f64::INFINITY));
                assert!(fast.is_some(), "escaped through {x:?}");
            }
        }
    }

    #[test]
    fn blocks_agrees_with_intersect() {
        let mut rng = SplitMix64::new(3);
        let mesh = soup(&mut rng, 300, 1.0, 0.3);
        for _ in 0..500 {
            let ray = Ray::from_ball_unchecked(&random_point(&mut rng, 2.0), rng.direction());
            let hit = mesh.intersect(&ray, 0.0, f64::INFINITY);
            assert_eq!(mesh.blocks(&ray, 0.0, f64::INFINITY), hit.is_some());
            if let Some(h) = hit {
                assert!(!mesh.blocks(&ray, 0.0, h.t));
                assert!(mesh.blocks(&ray, 0.0, h.t * (1.0 + 1e-12) + 1e-300));
            }
        }
    }

    /// Barycentric coordinates of a point of a triangle's plane, in Klein
    /// coordinates (where the triangle is Euclidean).
    fn barycentric(x: DVec4, [a, b, c]: [DVec4; 3]) -> [f64; 3] {
        let k = |v: DVec4| v.truncate() / v.w;
        let (ka, kb, kc, kx) = (k(a), k(b), k(c), k(x));
        let n = (kb - ka).cross(kc - ka);
        let w = |u: DVec3, v: DVec3| (u - kx).cross(v - kx).dot(n) / n.length_squared();
        [w(kb, kc), w(kc, ka), w(ka, kb)]
    }

    #[test]
    fn single_triangle_matches_the_polygon_and_its_orientation() {
        let (a, b, c) = (p(0.3, -0.1, 0.2), p(-0.2, 0.4, 0.1), p(-0.1, -0.3, 0.25));
        let mesh = TriangleMesh::new(vec![a, b, c], vec![[0, 1, 2]]).unwrap();
        let poly = ConvexPolygon::new(vec![a.into(), b.into(), c.into()]).unwrap();
        let corners = [a, b, c].map(|v| v.to_hyperboloid());
        let mut rng = SplitMix64::new(9);
        let (mut hits, mut disagree) = (0, 0);
        for k in 0..4000 {
            // Aim at the triangle and around it, so edges are crossed often.
            let w = [0, 1, 2].map(|_| rng.range(-0.2, 1.0));
            let aim = w[0] * corners[0] + w[1] * corners[1] + w[2] * corners[2];
            let ray = if k % 2 == 0 || !(aim.w > 0.0 && lorentz::dot(aim, aim) < 0.0) {
                Ray::from_origin_unchecked(rng.direction())
            } else {
                Ray::from_origin_unchecked(aim.truncate())
            };
            let m = mesh.intersect(&ray, 0.0, f64::INFINITY);
            let q = poly.intersect(&ray, 0.0, f64::INFINITY);
            match (m, q) {
                (Some(m), Some(q)) => {
                    hits += 1;
                    assert!((m.t - q.t).abs() < 1e-14, "{} vs {}", m.t, q.t);
                    assert!((m.normal - q.normal).length() < 1e-14);
                }
                (None, None) => {}
                (m, q) => {
                    // Only within rounding of an edge may the two disagree.
                    disagree += 1;
                    let h = m.or(q).unwrap();
                    let w = barycentric(h.point, corners);
                    let edge = w.iter().map(|x| x.abs()).fold(f64::INFINITY, f64::min);
                    assert!(edge < 1e-9, "disagree away from an edge: {w:?}");
                }
            }
        }
        assert!(hits > 1000, "{hits} hits, {disagree} disagreements");
        assert!(disagree < 10, "{disagree} disagreements");
        // Orientation: the normal follows the right-hand rule, like the plane's.
        let n = HPlane::through(&a.into(), &b.into(), &c.into())
            .unwrap()
            .normal();
        let hit = mesh
            .intersect(
                &Ray::from_origin_unchecked(corners.iter().sum::<DVec4>().truncate()),
                0.0,
                f64::INFINITY,
            )
            .unwrap();
        assert!((hit.normal - n).length() < 1e-14);
    }
}
