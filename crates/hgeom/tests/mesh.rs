//! Triangle meshes: agreement with `ConvexPolygon`, hits on their triangles,
//! watertightness, isometry invariance, and the hard cases.
//!
//! Run with `cargo test -p hgeom --test integration mesh::`; `PROPTEST_CASES=n` raises the
//! case count of the properties, and `--nocapture` prints the measured
//! errors.

use std::f64::consts::{PI, TAU};

use glam::{DVec3, DVec4};
use hgeom::{
    ConvexPolygon, HPlane, Hit, Isometry, Point, Ray, Segment, TriangleMesh, Vertex, lorentz,
};
use hscene_test_support::{SplitMix64, icosphere};
use proptest::prelude::*;

// ---------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------

fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(64);
    ProptestConfig {
        failure_persistence: None,
        ..ProptestConfig::with_cases(cases)
    }
}

/// Random geometry for the deterministic tests, drawn from the shared
/// stream.
trait RandomGeometry {
    /// A point at hyperbolic distance in `[0, max)` from the origin, in a
    /// uniformly random direction (drawn first).
    fn point(&mut self, max: f64) -> Point;

    /// A random isometry moving the origin up to `reach` away, with a random
    /// rotation, and a reflection half of the time.
    fn placement(&mut self, reach: f64) -> Isometry;
}

impl RandomGeometry for SplitMix64 {
    fn point(&mut self, max: f64) -> Point {
        let d = self.direction();
        Point::at_distance_from_origin(d, self.range(0.0, max)).unwrap()
    }

    fn placement(&mut self, reach: f64) -> Isometry {
        let end = Point::at_distance_from_origin(self.direction(), 0.5).unwrap();
        let axis = Segment::new(Point::ORIGIN, end).unwrap();
        let spin = Isometry::rotation_about_segment_unchecked(&axis, self.range(-PI, PI));
        let shift = Isometry::transvection_from_origin(self.point(reach));
        let f = shift.compose(&spin);
        if self.next_u64() & 1 == 0 {
            let mirror = HPlane::through(
                &self.point(0.5).into(),
                &self.point(0.5).into(),
                &self.point(0.5).into(),
            );
            match mirror {
                Ok(m) => f.compose(&Isometry::reflection(&m)),
                Err(_) => f,
            }
        } else {
            f
        }
    }
}

/// The ray from `from` towards `to` (ball points).
fn ray_towards(from: &Point, to: &Point) -> Ray {
    let dir = Segment::new(*from, *to).unwrap().direction_at_start();
    Ray::from_ball_unchecked(from, dir)
}

/// The ray `ray` moved by the isometry `f`.
fn moved_ray(f: &Isometry, ray: &Ray) -> Ray {
    let p = Point::from_hyperboloid(ray.origin).unwrap();
    let dir = hgeom::ray::ball_direction(ray.origin, ray.dir);
    Ray::from_ball_unchecked(&f.apply(&p), f.apply_direction(&p, dir))
}

/// Scale a future timelike vector onto the hyperboloid and read it as a point.
fn from_timelike(x: DVec4) -> Point {
    let q = -lorentz::dot(x, x);
    Point::from_hyperboloid(x / q.sqrt()).unwrap()
}

/// `|<a,b>|` relative to the Euclidean sizes of the two vectors: the scale of
/// rounding in a Lorentz product.
fn ldot_rel(a: DVec4, b: DVec4) -> f64 {
    lorentz::dot(a, b).abs() / (a.length() * b.length())
}

/// Rounding scale of a plane hit at arc length `t` from a ray origin `x`
/// (as in `tests/properties.rs`): `ray.at(t)` and `tanh t = tau` both lose
/// `~cosh^2 t` ulps, and the products `~eps |X|^2`.
fn plane_hit_tol(x: DVec4, t: f64) -> f64 {
    1e-13 + 100.0 * (f64::EPSILON + f64::EPSILON * x.length_squared()) * t.cosh().powi(2)
}

/// Barycentric coordinates of a point of a triangle's plane, in Klein
/// coordinates (where the h-triangle is the Euclidean one).
fn barycentric(x: DVec4, [a, b, c]: [DVec4; 3]) -> [f64; 3] {
    let k = |v: DVec4| v.truncate() / v.w;
    let (ka, kb, kc, kx) = (k(a), k(b), k(c), k(x));
    let n = (kb - ka).cross(kc - ka);
    let w = |u: DVec3, v: DVec3| (u - kx).cross(v - kx).dot(n) / n.length_squared();
    [w(kb, kc), w(kc, ka), w(ka, kb)]
}

/// The world hyperboloid corners of triangle `i`.
fn corners(mesh: &TriangleMesh, i: usize) -> [DVec4; 3] {
    let vs = mesh.vertices();
    mesh.triangles()[i].map(|k| vs[k as usize].to_hyperboloid())
}

/// Each triangle as a `ConvexPolygon` (None where it is too thin to pass
/// the polygon's checks).
fn polygons(mesh: &TriangleMesh) -> Vec<Option<ConvexPolygon>> {
    let vs = mesh.vertices();
    mesh.triangles()
        .iter()
        .map(|t| ConvexPolygon::new(t.map(|k| Vertex::from(vs[k as usize])).to_vec()).ok())
        .collect()
}

/// Triangles scattered through a ball of radius `reach`, sides up to `size`.
fn soup(rng: &mut SplitMix64, count: usize, reach: f64, size: f64) -> TriangleMesh {
    let mut vertices = Vec::with_capacity(3 * count);
    let mut triangles = Vec::with_capacity(count);
    for i in 0..count as u32 {
        let c = Isometry::transvection_from_origin(rng.point(reach));
        for _ in 0..3 {
            let d = rng.direction();
            let r = rng.range(0.1, 1.0) * size;
            vertices.push(c.apply(&Point::at_distance_from_origin(d, r).unwrap()));
        }
        triangles.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    TriangleMesh::new(vertices, triangles).unwrap()
}

/// A closed, outward-wound icosphere about the origin: the icosahedron
/// subdivided `levels` times, each vertex at distance `radius * (1 + bump)`
/// with `bump` uniform in `[-bumps, bumps]` (star-shaped about the origin).
fn bumpy_icosphere(
    rng: &mut SplitMix64,
    levels: usize,
    radius: f64,
    bumps: f64,
) -> (Vec<Point>, Vec<[u32; 3]>) {
    let (dirs, faces) = icosphere(levels as u32);
    for f in &faces {
        let [a, b, c] = f.map(|k| dirs[k as usize]);
        assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "inward face");
    }
    let points = dirs
        .iter()
        .map(|d| {
            let r = radius * (1.0 + rng.range(-bumps, bumps));
            Point::at_distance_from_origin(*d, r).unwrap()
        })
        .collect();
    (points, faces)
}

/// Every hit along the ray, nearest first, merging crossings closer than
/// `1e-9` (the two triangles at an edge).
fn all_hits(mesh: &TriangleMesh, ray: &Ray) -> Vec<Hit> {
    let mut hits: Vec<Hit> = Vec::new();
    let mut t_min = 0.0;
    while let Some(h) = mesh.intersect(ray, t_min, f64::INFINITY) {
        if hits.last().is_none_or(|last| h.t - last.t > 1e-9) {
            hits.push(h);
        }
        t_min = h.t;
        assert!(hits.len() < 1000, "runaway");
    }
    hits
}

fn assert_hit_finite(hit: &Hit) {
    assert!(
        hit.t.is_finite() && hit.point.is_finite() && hit.normal.is_finite(),
        "{hit:?}"
    );
}

// ---------------------------------------------------------------------------
// Agreement with ConvexPolygon, and hits on their triangles
// ---------------------------------------------------------------------------

/// Compare one ray against the mesh and against every triangle as a
/// polygon; returns the `|t|` disagreement, relative to `max(1, t)` (failing
/// if it exceeds `tol(t)`), and the hit's plane residual `|<P,N>|/(|P||N|)`
/// against the polygon's plane.
fn compare_with_polygons(
    mesh: &TriangleMesh,
    polys: &[Option<ConvexPolygon>],
    ray: &Ray,
    tol: impl Fn(f64) -> f64,
) -> (f64, f64) {
    let near_edge = |i: usize, h: &Hit| {
        let w = barycentric(h.point, corners(mesh, i));
        w.iter().map(|x| x.abs()).fold(f64::INFINITY, f64::min) < 1e-8
    };
    let (mut worst, mut residual): (f64, f64) = (0.0, 0.0);
    let mesh_hit = mesh.intersect_indexed(ray, 0.0, f64::INFINITY);
    if let Some((h, i)) = &mesh_hit {
        assert_hit_finite(h);
        match polys[*i]
            .as_ref()
            .and_then(|p| p.intersect(ray, 0.0, f64::INFINITY))
        {
            Some(q) => {
                let err = (h.t - q.t).abs() / h.t.max(1.0);
                assert!(err < tol(h.t), "t {} vs polygon {}: {err:e}", h.t, q.t);
                assert!((h.normal - q.normal).length() < tol(h.t) * q.normal.length());
                worst = worst.max(err);
                residual = ldot_rel(h.point, q.normal);
            }
            None => assert!(
                polys[*i].is_none() || near_edge(*i, h),
                "polygon {i} misses a mesh hit away from its edges"
            ),
        }
    }
    let poly_hit = polys
        .iter()
        .enumerate()
        .filter_map(|(i, p)| Some((p.as_ref()?.intersect(ray, 0.0, f64::INFINITY)?, i)))
        .min_by(|a, b| a.0.t.total_cmp(&b.0.t));
    if let Some((q, j)) = poly_hit {
        match &mesh_hit {
            Some((h, _)) => assert!(
                h.t <= q.t + tol(q.t) * q.t.max(1.0),
                "mesh hit {} beyond polygon {j} at {}",
                h.t,
                q.t
            ),
            None => assert!(
                near_edge(j, &q),
                "the mesh misses polygon {j} away from its edges"
            ),
        }
    }
    (worst, residual)
}

#[test]
fn mesh_hits_agree_with_convex_polygons() {
    let mut rng = SplitMix64::new(2024);
    let (mut from_origin, mut from_elsewhere): (f64, f64) = (0.0, 0.0);
    let (mut residual_origin, mut residual_elsewhere): (f64, f64) = (0.0, 0.0);
    for case in 0..24 {
        let local = soup(&mut rng, 60, 1.0, 0.5);
        let reach = [0.0, 2.0, 5.0][case % 3];
        let mesh = local.transformed(&rng.placement(reach));
        let polys = polygons(&mesh);
        let toward = mesh.placement().translation_part();
        for k in 0..300 {
            // Rays from the origin (the renderer's primary rays): aimed
            // near the mesh, so most of them hit.
            let aim = Isometry::transvection_from_origin(toward).apply(&rng.point(1.5));
            let ray = if toward.coords() == DVec3::ZERO || k % 4 == 0 {
                Ray::from_origin_unchecked(rng.direction())
            } else {
                Ray::from_origin_unchecked(aim.coords())
            };
            let (err, res) = compare_with_polygons(&mesh, &polys, &ray, |_| 5e-12);
            from_origin = from_origin.max(err);
            residual_origin = residual_origin.max(res);
            // Rays from points within 2 of the mesh.
            let start = Isometry::transvection_from_origin(toward).apply(&rng.point(2.0));
            if start.distance(aim) > 1e-6 {
                let ray = ray_towards(&start, &aim);
                let x = ray.origin;
                let (err, res) =
                    compare_with_polygons(&mesh, &polys, &ray, |t| plane_hit_tol(x, t));
                from_elsewhere = from_elsewhere.max(err);
                residual_elsewhere = residual_elsewhere.max(res);
            }
        }
    }
    eprintln!(
        "mesh vs ConvexPolygon, max |dt|/max(1,t): rays from the origin {from_origin:.2e}, \
         from near the mesh {from_elsewhere:.2e}; plane residual |<P,N>|/(|P||N|): \
         {residual_origin:.2e}, {residual_elsewhere:.2e}"
    );
}

proptest! {
    #![proptest_config(config())]

    /// Hits lie on their triangle's plane and inside the triangle, at the
    /// stated distance along the ray, with a unit normal tangent there.
    #[test]
    fn hits_lie_on_their_triangle(seed in any::<u64>(), reach in 0.0f64..5.0, from in 0.0f64..3.0) {
        let mut rng = SplitMix64::new(seed);
        let mesh = soup(&mut rng, 40, 1.0, 0.6).transformed(&rng.placement(reach));
        let centre = mesh.placement().translation_part();
        let there = Isometry::transvection_from_origin(centre);
        let mut hits = 0;
        for _ in 0..40 {
            let start = there.apply(&rng.point(from + 1.0));
            let aim = there.apply(&rng.point(1.0));
            if start.distance(aim) < 1e-6 {
                continue;
            }
            let ray = ray_towards(&start, &aim);
            let Some((hit, i)) = mesh.intersect_indexed(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            hits += 1;
            assert_hit_finite(&hit);
            let tol = plane_hit_tol(ray.origin, hit.t);
            let abc = corners(&mesh, i);
            let [a, b, c] = abc.map(|x| Vertex::from(Point::from_hyperboloid(x).unwrap()));
            let n = HPlane::through(&a, &b, &c).unwrap().normal();
            prop_assert!(ldot_rel(hit.point, n) < tol, "off the plane: {}", ldot_rel(hit.point, n));
            prop_assert!(ldot_rel(hit.point, hit.normal) < tol);
            // Unit to the rounding of a Lorentz square, `eps |N|^2`.
            let unit = (lorentz::dot(hit.normal, hit.normal) - 1.0).abs();
            prop_assert!(unit < 1e-13 + 100.0 * f64::EPSILON * hit.normal.length_squared());
            // Same orientation as the plane through the corners (right-hand rule).
            prop_assert!(lorentz::dot(hit.normal, n) > 0.999);
            let w = barycentric(hit.point, abc);
            prop_assert!(w.iter().all(|x| *x > -1e-9), "outside its triangle: {w:?}");
            let travelled = lorentz::distance(ray.origin, hit.point);
            prop_assert!((travelled - hit.t).abs() < tol * hit.t.max(1.0));
        }
        prop_assert!(hits > 0 || reach > 4.0);
    }

    /// Moving the mesh by `f` and intersecting equals intersecting with the
    /// ray moved by `f^-1`.
    #[test]
    fn moving_the_mesh_equals_moving_the_ray(seed in any::<u64>(), reach in 0.0f64..3.0) {
        let mut rng = SplitMix64::new(seed);
        let mesh = soup(&mut rng, 60, 1.0, 0.5);
        let f = rng.placement(reach);
        let moved = mesh.transformed(&f);
        let back = f.inverse();
        for _ in 0..40 {
            let ray = Ray::from_ball_unchecked(&rng.point(3.0), rng.direction());
            let a = moved.intersect_indexed(&ray, 0.0, f64::INFINITY);
            let b = mesh.intersect_indexed(&moved_ray(&back, &ray), 0.0, f64::INFINITY);
            match (a, b) {
                (Some((a, i)), Some((b, j))) => {
                    let tol = 1e-10 * a.t.max(1.0);
                    // A different triangle only at a tie (a shared crossing).
                    prop_assert!(i == j || (a.t - b.t).abs() < tol);
                    prop_assert!((a.t - b.t).abs() < tol, "{} vs {}", a.t, b.t);
                }
                (None, None) => {}
                (a, b) => {
                    // Only grazing an edge may flip the outcome.
                    let (h, i) = a.or(b).unwrap();
                    let m = if a.is_some() { &moved } else { &mesh };
                    let w = barycentric(h.point, corners(m, i));
                    prop_assert!(w.iter().map(|x| x.abs()).fold(1.0, f64::min) < 1e-9, "{w:?}");
                }
            }
        }
    }
}

#[test]
fn bounding_ball_contains_vertices_and_hits() {
    let mut rng = SplitMix64::new(77);
    for reach in [0.0, 1.0, 3.0, 6.0] {
        let mesh = soup(&mut rng, 100, 1.0, 0.5).transformed(&rng.placement(reach));
        let (c, r) = mesh.bounding_ball();
        let centre = Point::from_hyperboloid(c).unwrap();
        assert!(r < 2.0, "{r}");
        for v in mesh.vertices().iter() {
            assert!(centre.distance(*v) <= r);
        }
        for _ in 0..300 {
            let ray = Ray::from_origin_unchecked(rng.direction());
            if let Some(hit) = mesh.intersect(&ray, 0.0, f64::INFINITY) {
                let p = Point::from_hyperboloid(hit.point).unwrap();
                assert!(centre.distance(p) <= r);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Watertightness
// ---------------------------------------------------------------------------

/// Rays from inside a closed mesh always hit it, and rays from the centre of
/// a star-shaped one cross it exactly once.
#[test]
fn rays_from_inside_a_closed_mesh_always_hit() {
    let mut rng = SplitMix64::new(11);
    let mut rays = 0;
    for case in 0..12 {
        let radius = [0.3, 1.0, 2.5][case % 3];
        let (points, faces) = bumpy_icosphere(&mut rng, 3, radius, 0.05);
        let f = rng.placement([0.0, 2.0, 4.0][case % 3]);
        let mesh = TriangleMesh::new(points, faces).unwrap().transformed(&f);
        assert_eq!(mesh.triangle_count(), 1280);
        let centre = f.apply(&Point::ORIGIN);
        for k in 0..400 {
            let start = if k % 2 == 0 {
                centre
            } else {
                f.apply(&rng.point(0.5 * radius))
            };
            let ray = Ray::from_ball_unchecked(&start, rng.direction());
            let hits = all_hits(&mesh, &ray);
            rays += 1;
            assert_eq!(hits.len(), 1, "case {case}, ray {k}: {hits:?}");
            let hit = hits[0];
            assert_hit_finite(&hit);
            if k % 2 == 0 {
                assert!(hit.t > 0.9 * radius && hit.t < 1.06 * radius, "{}", hit.t);
            }
            // Leaving through the outside.
            assert!(lorentz::dot(ray.tangent_at(hit.t), hit.normal) > 0.0);
            assert!(mesh.blocks(&ray, 0.0, f64::INFINITY));
        }
    }
    assert_eq!(rays, 4800);
}

/// Rays aimed exactly at shared vertices and edges (from the centre, where
/// a radial ray passes through the vertex to the last bit) never miss, and
/// neither do the same rays after moving mesh and ray by an isometry, which
/// leaves them within rounding of the edge: the hardest case for a
/// triangle test.
#[test]
fn rays_through_edges_and_vertices_never_miss() {
    let mut rng = SplitMix64::new(5);
    let (points, faces) = bumpy_icosphere(&mut rng, 2, 1.0, 0.1);
    let mesh = TriangleMesh::new(points.clone(), faces.clone()).unwrap();
    let mut targets: Vec<DVec4> = points.iter().map(Point::to_hyperboloid).collect();
    for [a, b, c] in &faces {
        for (u, v) in [(a, b), (b, c), (c, a)] {
            let (x, y) = (
                points[*u as usize].to_hyperboloid(),
                points[*v as usize].to_hyperboloid(),
            );
            for lambda in [0.5, 0.25, 1e-3, 1e-9] {
                targets.push((1.0 - lambda) * x + lambda * y);
            }
        }
    }
    let moves = [
        Isometry::IDENTITY,
        rng.placement(1.0),
        rng.placement(3.0),
        rng.placement(5.0),
    ];
    let mut rays = 0;
    for f in &moves {
        let moved = mesh.transformed(f);
        for x in &targets {
            // From the centre, exactly radial in the unmoved frame.
            let ray = moved_ray(f, &Ray::from_origin_unchecked(x.truncate()));
            let hit = moved.intersect(&ray, 0.0, f64::INFINITY);
            assert!(hit.is_some(), "missed {x:?} from the centre after {f:?}");
            let target = f.apply(&from_timelike(*x));
            let expect = f.apply(&Point::ORIGIN).distance(target);
            assert!((hit.unwrap().t - expect).abs() < 1e-9 * expect.max(1.0));
            // From outside on the same radial line, aimed at the centre
            // (the mesh is star-shaped about it, so the point is not on the
            // silhouette, where a ray may rightly graze past).
            let out = Point::at_distance_from_origin(x.truncate(), 3.0).unwrap();
            let ray = moved_ray(f, &Ray::from_ball_unchecked(&out, -x.truncate()));
            assert!(
                moved.intersect(&ray, 0.0, f64::INFINITY).is_some(),
                "missed {x:?} from outside after {f:?}"
            );
            rays += 2;
        }
    }
    assert!(rays > 3000, "{rays}");
}

// ---------------------------------------------------------------------------
// Chains of moves
// ---------------------------------------------------------------------------

#[test]
fn long_chains_of_moves_stay_accurate() {
    let mut rng = SplitMix64::new(99);
    let (points, faces) = bumpy_icosphere(&mut rng, 2, 0.8, 0.1);
    let mesh = TriangleMesh::new(points, faces).unwrap();
    // 1000 random moves (rotations, reflections, translations up to 0.5;
    // a mesh that wandered more than 2 away is brought back 0.3 towards
    // the origin, as a random walk in H^3 would otherwise drift off), then
    // their inverses in reverse order.
    let mut steps: Vec<Isometry> = Vec::with_capacity(1000);
    let mut moved = mesh.clone();
    let mut total = Isometry::IDENTITY;
    for _ in 0..1000 {
        let at = moved.placement().translation_part();
        let step = if at.distance_from_origin() > 2.0 {
            let towards = Isometry::transvection_from_origin(at)
                .apply(&Point::at_distance_from_origin(-at.coords(), 0.3).unwrap());
            Isometry::translation(&Segment::new(at, towards).unwrap()).unwrap()
        } else {
            rng.placement(0.5)
        };
        moved = moved.transformed(&step);
        total = step.compose(&total);
        steps.push(step);
    }
    // The chain equals the composed isometry applied once.
    let once = mesh.transformed(&total);
    for _ in 0..200 {
        let ray = Ray::from_ball_unchecked(&rng.point(2.0), rng.direction());
        let (a, b) = (
            moved.intersect(&ray, 0.0, f64::INFINITY),
            once.intersect(&ray, 0.0, f64::INFINITY),
        );
        assert_eq!(a.is_some(), b.is_some());
        if let (Some(a), Some(b)) = (a, b) {
            assert!(
                (a.t - b.t).abs() < 1e-12 * a.t.max(1.0),
                "{} vs {}",
                a.t,
                b.t
            );
        }
    }
    for s in steps.iter().rev() {
        moved = moved.transformed(&s.inverse());
    }
    let mut worst: f64 = 0.0;
    for _ in 0..400 {
        let ray = Ray::from_ball_unchecked(&rng.point(0.3), rng.direction());
        let a = moved.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        let b = mesh.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        worst = worst.max((a.t - b.t).abs());
    }
    eprintln!("1000 moves and back: hits move by {worst:.2e}");
    assert!(worst < 1e-9, "{worst}");
    let drift = moved
        .vertices()
        .iter()
        .zip(mesh.vertices().iter())
        .map(|(a, b)| (*a).distance(*b))
        .fold(0.0, f64::max);
    assert!(drift < 1e-9, "{drift}");
}

// ---------------------------------------------------------------------------
// Hard cases
// ---------------------------------------------------------------------------

/// A mesh whose vertices lie at `1 - |x| ~ 1e-12` (distance ~28): it builds,
/// keeps its vertices, and intersects correctly in a frame near it (the
/// camera frame a renderer moves it to: `transformed` is exact enough for
/// that), watertight there too.
#[test]
fn mesh_next_to_the_absolute() {
    let mut rng = SplitMix64::new(12);
    let (points, faces) = bumpy_icosphere(&mut rng, 2, 0.5, 0.1);
    let d = 28.3;
    let centre = Point::at_distance_from_origin(DVec3::new(0.3, -0.5, 0.8), d).unwrap();
    let there = Isometry::transvection_from_origin(centre);
    let far: Vec<Point> = points.iter().map(|p| there.apply(p)).collect();
    let gaps = far.iter().map(|p| 1.0 - p.coords().length());
    let (lo, hi) = gaps.fold((1.0f64, 0.0f64), |(lo, hi), g| (lo.min(g), hi.max(g)));
    assert!(lo > 1e-13 && hi < 1e-11, "1 - |x| in [{lo:e}, {hi:e}]");
    let mesh = TriangleMesh::new(far.clone(), faces.clone()).unwrap();
    assert_eq!(mesh.dropped_triangles(), 0);
    assert_eq!(&*mesh.vertices(), far.as_slice());
    let (c, r) = mesh.bounding_ball();
    let c = Point::from_hyperboloid(c).unwrap();
    assert!(c.distance(centre) < 0.1, "{}", c.distance(centre));
    assert!(r < 0.7, "{r}");
    // An eye 1.5 from the mesh's centre, moved to the origin.
    let eye = there.apply(&Point::at_distance_from_origin(DVec3::X, 1.5).unwrap());
    let to_eye = Isometry::transvection_from_origin(eye).inverse();
    let seen = mesh.transformed(&to_eye);
    let polys = polygons(&seen);
    let seen_from_eye = to_eye.compose(&there);
    let mut hits = 0;
    let mut worst: f64 = 0.0;
    for _ in 0..400 {
        let aim = seen_from_eye.apply(&rng.point(0.7));
        let ray = Ray::from_origin_unchecked(aim.coords());
        let (err, _) = compare_with_polygons(&seen, &polys, &ray, |_| 5e-12);
        worst = worst.max(err);
        hits += usize::from(seen.intersect(&ray, 0.0, f64::INFINITY).is_some());
    }
    eprintln!("next to the absolute, in the eye's frame: max |dt| {worst:.2e}");
    assert!(hits > 200, "{hits}");
    // Watertight there: rays from the moved centre always leave once.
    let inside = seen_from_eye.apply(&Point::ORIGIN);
    for _ in 0..400 {
        let ray = Ray::from_ball_unchecked(&inside, rng.direction());
        assert_eq!(all_hits(&seen, &ray).len(), 1);
    }
}

/// Rays in, and almost in, the plane of a triangle.
#[test]
fn grazing_rays_along_a_triangle_plane() {
    let corner = |x: f64, y: f64| Point::from_coords(DVec3::new(x, y, 0.0)).unwrap();
    let flat = TriangleMesh::new(
        vec![corner(0.8, 0.0), corner(-0.4, 0.6), corner(-0.4, -0.6)],
        vec![[0, 1, 2]],
    )
    .unwrap();
    let mut rng = SplitMix64::new(17);
    let shift = rng.placement(2.0);
    let (mut hits, mut misses) = (0, 0);
    for (mesh, f) in [
        (flat.clone(), Isometry::IDENTITY),
        (flat.transformed(&shift), shift),
    ] {
        let poly =
            ConvexPolygon::new(mesh.vertices().iter().map(|p| Vertex::from(*p)).collect()).unwrap();
        let n = poly.plane().normal();
        for _ in 0..200 {
            let base = corner(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5));
            let phi = rng.range(0.0, TAU);
            for h in [0.0, 1e-15, 1e-10] {
                for eps in [0.0, 1e-16, -1e-16, 1e-12, -1e-12, -1e-8] {
                    let start =
                        Point::from_hyperboloid(Ray::from_ball_unchecked(&base, DVec3::Z).at(h))
                            .unwrap();
                    let dir = DVec3::new(phi.cos(), phi.sin(), eps).normalize();
                    let ray =
                        Ray::from_ball_unchecked(&f.apply(&start), f.apply_direction(&start, dir));
                    match mesh.intersect(&ray, 0.0, f64::INFINITY) {
                        Some(hit) => {
                            hits += 1;
                            assert_hit_finite(&hit);
                            assert!(hit.t > 0.0);
                            let tol = plane_hit_tol(ray.origin, hit.t);
                            assert!(ldot_rel(hit.point, n) < tol, "{hit:?}");
                            let travelled = lorentz::distance(ray.origin, hit.point);
                            assert!((travelled - hit.t).abs() < tol * hit.t.max(1.0));
                        }
                        None => misses += 1,
                    }
                }
            }
        }
    }
    assert!(hits > 0 && misses > 0, "{hits} hits, {misses} misses");
    // Exactly in the plane through the origin: parallel, a miss.
    let along = Ray::from_origin_unchecked(DVec3::new(0.6, 0.8, 0.0));
    assert!(flat.intersect(&along, 0.0, f64::INFINITY).is_none());
    assert!(!flat.blocks(&along, 0.0, f64::INFINITY));
    // Height h above the plane, heading down at angle beta:
    // tanh t = tanh h / sin beta.
    let h = 1e-10;
    let above = Point::from_hyperboloid(Ray::from_origin_unchecked(DVec3::Z).at(h)).unwrap();
    for beta in [1e-3f64, 1e-6, 2e-10] {
        let ray = Ray::from_ball_unchecked(&above, DVec3::new(beta.cos(), 0.0, -beta.sin()));
        let expect = (h.tanh() / beta.sin()).atanh();
        let hit = flat.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!(
            (hit.t - expect).abs() < 1e-9 * expect,
            "beta {beta:e}: {} vs {expect}",
            hit.t
        );
    }
    // Shallower than tanh h: the geodesic never reaches the plane.
    let ray = Ray::from_ball_unchecked(&above, DVec3::new(1.0, 0.0, -0.5e-10));
    assert!(flat.intersect(&ray, 0.0, f64::INFINITY).is_none());
}

/// Rays through the hub of a fan of 5 to 12 triangles (a vertex shared by
/// all of them, moved anywhere by an isometry, so the ray passes it only to
/// rounding) never miss: the vertex case of watertightness, where a test
/// that decides each edge on its own can let a ray through. A lone
/// triangle is hit 1e-9 inside a vertex and missed 1e-9 outside it.
#[test]
fn rays_through_a_vertex() {
    let mut rng = SplitMix64::new(23);
    let mut rays = 0;
    for case in 0..60 {
        let m = 5 + case % 8;
        let mut angles: Vec<f64> = (0..m)
            .map(|k| (k as f64 + rng.range(0.1, 0.9)) * TAU / m as f64)
            .collect();
        angles.sort_by(f64::total_cmp);
        let mut points = vec![Point::ORIGIN];
        for a in &angles {
            let r = rng.range(0.2, 1.5);
            points.push(
                Point::at_distance_from_origin(DVec3::new(a.cos(), a.sin(), 0.0), r).unwrap(),
            );
        }
        let faces: Vec<[u32; 3]> = (0..m as u32)
            .map(|k| [0, 1 + k, 1 + (k + 1) % m as u32])
            .collect();
        let f = rng.placement(3.0);
        let fan = TriangleMesh::new(points, faces).unwrap().transformed(&f);
        let hub = f.apply(&Point::ORIGIN);
        for _ in 0..100 {
            // From either side of the fan's plane, at a random slant.
            let mut d = rng.direction();
            if d.z.abs() < 0.05 {
                d.z = 0.05f64.copysign(d.z);
            }
            let start = f.apply(&Point::at_distance_from_origin(d, rng.range(0.05, 3.0)).unwrap());
            let ray = ray_towards(&start, &hub);
            let hit = fan.intersect(&ray, 0.0, f64::INFINITY);
            let hit = hit.unwrap_or_else(|| panic!("slipped through the hub, case {case}"));
            let expect = start.distance(hub);
            assert!(
                (hit.t - expect).abs() < 1e-9 * expect.max(1.0),
                "{} vs {expect}",
                hit.t
            );
            rays += 1;
        }
    }
    assert_eq!(rays, 6000);
    // A lone triangle, just inside and just outside each vertex.
    for _ in 0..200 {
        let vs = [rng.point(2.0), rng.point(2.0), rng.point(2.0)];
        let Ok(mesh) = TriangleMesh::new(vs.to_vec(), vec![[0, 1, 2]]) else {
            continue;
        };
        let start = rng.point(1.0);
        let xs = vs.map(|p| p.to_hyperboloid());
        for k in 0..3 {
            let (v, others) = (xs[k], 0.5 * (xs[(k + 1) % 3] + xs[(k + 2) % 3]));
            for (lambda, inside) in [(1e-9, true), (-1e-9, false)] {
                let aim = from_timelike((1.0 - lambda) * v + lambda * others);
                if start.distance(aim) < 1e-3 {
                    continue;
                }
                let ray = ray_towards(&start, &aim);
                let hit = mesh.intersect(&ray, 0.0, f64::INFINITY);
                // A ray nearly in the triangle's plane decides nothing.
                let [a, b, c] = vs.map(Vertex::from);
                let n = HPlane::through(&a, &b, &c).unwrap().normal();
                if lorentz::dot(ray.tangent_at(start.distance(aim)), n).abs() < 1e-3 {
                    continue;
                }
                assert_eq!(hit.is_some(), inside, "lambda {lambda}");
            }
        }
    }
}

/// The renderer's use: a big mesh moved into a camera frame is shared, and
/// intersects like the original with the ray moved back.
#[test]
fn transformed_shares_a_large_mesh() {
    let mut rng = SplitMix64::new(31);
    let (points, faces) = bumpy_icosphere(&mut rng, 4, 1.0, 0.02);
    let mesh = TriangleMesh::new(points, faces).unwrap();
    assert_eq!(mesh.triangle_count(), 5120);
    let f = rng.placement(2.0);
    let moved = mesh.transformed(&f);
    assert_eq!(moved.triangle_count(), 5120);
    let back = f.inverse();
    for _ in 0..200 {
        let ray = Ray::from_ball_unchecked(&rng.point(3.0), rng.direction());
        let a = moved.intersect(&ray, 0.0, f64::INFINITY);
        let b = mesh.intersect(&moved_ray(&back, &ray), 0.0, f64::INFINITY);
        assert_eq!(a.is_some(), b.is_some());
        if let (Some(a), Some(b)) = (a, b) {
            assert!((a.t - b.t).abs() < 1e-10 * a.t.max(1.0));
        }
    }
}
