//! Families of accuracy cases shared by hgeom's reference tests and its
//! `accuracy` example: each family draws inputs from a [`SplitMix64`]
//! stream, runs hgeom in f64, and measures the error against the 320-bit
//! [`reference`](crate::reference).
//!
//! The points the families build cannot fail: each comes from a direction
//! and a distance the family itself chose well inside the ball (or a corner
//! at 0.3 of the radius); there is no user input here, and
//! [`fixture`](crate::fixture) says so where it is built.

use hgeom::glam::{self, DVec3};
use hgeom::{
    ConvexPolygon, HCylinder, HLine, HPlane, HSphere, Horosphere, IdealPoint, Isometry, Point, Ray,
    Rod, Segment, Vertex,
};

use crate::SplitMix64;
use crate::reference::{self as r, R, V4};

/// A uniformly distributed unit vector by rejection from the cube (three
/// draws per try): the accuracy cases' own distribution, which their
/// recorded bounds were measured with.
fn cube_direction(rng: &mut SplitMix64) -> DVec3 {
    loop {
        let v = DVec3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        );
        let l = v.length();
        if l > 0.1 && l <= 1.0 {
            return v / l;
        }
    }
}

/// A point at a random hyperbolic distance in `[lo, hi)` from the origin,
/// in a random direction.
fn point_in(rng: &mut SplitMix64, lo: f64, hi: f64) -> Point {
    let d = rng.range(lo, hi);
    // Cannot fail: the cases draw distances of at most ~20, well inside f64's range for a ball point.
    crate::fixture(
        Point::at_distance_from_origin(cube_direction(rng), d),
        "finite distance",
    )
}

/// A random isometry with translation part at distance up to `max_d`.
fn random_isometry(rng: &mut SplitMix64, max_d: f64) -> Isometry {
    let a = point_in(rng, 0.0, max_d);
    let axis = cube_direction(rng);
    let angle = rng.range(-3.0, 3.0);
    let q = glam::DMat3::from_axis_angle(axis, angle);
    Isometry::transvection_from_origin(a).compose(&Isometry::orthogonal_unchecked(q))
}

/// One operation's measured errors, and its speed.
pub struct Family {
    /// What was measured, with the range of its inputs; stable, since the
    /// reference tests look their bounds up by its prefix.
    pub operation: &'static str,
    /// The unit of every error: "relative" or "hyperbolic distance".
    pub unit: &'static str,
    /// One error per case that produced a result.
    pub errors: Vec<f64>,
    /// Mean wall time of one f64 call, in nanoseconds (noisy; reported,
    /// never asserted).
    pub ns_per_op: f64,
}

/// Run `f` a few times and return its result with the mean time per call.
/// Single calls are too short for the clock; 32 repetitions are enough.
pub fn timed<T>(f: impl Fn() -> T) -> (T, f64) {
    const REPS: u32 = 32;
    let start = std::time::Instant::now();
    for _ in 1..REPS {
        // Calling through an opaque reference stops the optimiser from
        // hoisting the loop-invariant call out of the loop.
        std::hint::black_box(std::hint::black_box(&f)());
    }
    let out = f();
    (out, start.elapsed().as_nanos() as f64 / f64::from(REPS))
}

/// Accumulates per-call times.
#[derive(Default)]
struct Clock {
    total: f64,
    calls: usize,
}

impl Clock {
    fn run<T>(&mut self, f: impl Fn() -> T) -> T {
        let (out, ns) = timed(f);
        self.total += ns;
        self.calls += 1;
        out
    }
    fn mean(&self) -> f64 {
        if self.calls == 0 {
            0.0
        } else {
            self.total / self.calls as f64
        }
    }
}

impl Family {
    /// The largest error; 0 with no cases.
    pub fn max(&self) -> f64 {
        self.errors.iter().copied().fold(0.0, f64::max)
    }
    /// The median error (the upper one of an even count); 0 with no cases.
    pub fn median(&self) -> f64 {
        let mut e = self.errors.clone();
        e.sort_by(f64::total_cmp);
        e.get(e.len() / 2).copied().unwrap_or(0.0)
    }
}

fn rel(got: f64, want: &R) -> f64 {
    let w = want.to_f64();
    ((got - w) / w).abs()
}

/// Point pairs near the absolute: gaps `1 - |x|` log-uniform in
/// `[1e-15, 1]`, distances up to ~70.
pub fn boundary_pairs(rng: &mut SplitMix64, n: usize) -> Vec<(Point, Point)> {
    (0..n)
        .map(|_| {
            let mut p = || {
                let g = 10f64.powf(rng.range(-15.0, 0.0));
                let dir = cube_direction(rng);
                Point::from_coords(dir * (1.0 - g)).unwrap_or(Point::ORIGIN)
            };
            (p(), p())
        })
        .collect()
}

/// Relative error of `distance` over point pairs, timed.
fn distance_family(operation: &'static str, pairs: &[(Point, Point)]) -> Family {
    let mut clock = Clock::default();
    let errors = pairs
        .iter()
        .map(|(a, b)| {
            rel(
                clock.run(|| (*a).distance(*b)),
                &r::distance(a.coords(), b.coords()),
            )
        })
        .collect();
    Family {
        operation,
        unit: "relative",
        errors,
        ns_per_op: clock.mean(),
    }
}

/// Relative error of `distance` on pairs near the absolute.
pub fn distance_boundary(rng: &mut SplitMix64, n: usize) -> Family {
    distance_family("distance (1-|x| down to 1e-15)", &boundary_pairs(rng, n))
}

/// Pairs `1e-12` apart (Euclidean) anywhere in the ball.
pub fn near_pairs(rng: &mut SplitMix64, n: usize) -> Vec<(Point, Point)> {
    (0..n)
        .map(|_| {
            let a = point_in(rng, 0.0, 6.0);
            let step = cube_direction(rng) * 1e-12;
            let b = Point::from_coords(a.coords() + step).unwrap_or(a);
            (a, b)
        })
        .collect()
}

/// Relative error of `distance` on nearly coincident points.
pub fn distance_near(rng: &mut SplitMix64, n: usize) -> Family {
    distance_family("distance (points 1e-12 apart)", &near_pairs(rng, n))
}

/// Segments with ends up to distance `reach` from the origin.
pub fn segments(rng: &mut SplitMix64, n: usize, reach: f64) -> Vec<Segment> {
    (0..n)
        .filter_map(|_| {
            let a = point_in(rng, 0.0, reach);
            let b = point_in(rng, 0.0, reach);
            Segment::new(a, b).ok()
        })
        .collect()
}

/// Hyperbolic distance from `T(start)` to `end` for the translation along a segment.
pub fn translation(rng: &mut SplitMix64, n: usize) -> Family {
    let mut clock = Clock::default();
    let errors = segments(rng, n, 8.0)
        .iter()
        .filter_map(|s| {
            let moved = clock.run(|| Some(Isometry::translation(s).ok()?.apply(&s.start())))?;
            Some(r::distance(moved.coords(), s.end().coords()).to_f64())
        })
        .collect();
    Family {
        operation: "translation along a segment: build + apply (ends within 8)",
        unit: "hyperbolic distance",
        errors,
        ns_per_op: clock.mean(),
    }
}

/// Hyperbolic distance from `R(R(x))` to `x` for reflections in random planes.
pub fn reflection_involution(rng: &mut SplitMix64, n: usize) -> Family {
    let mut clock = Clock::default();
    let errors = (0..n)
        .filter_map(|_| {
            let pts: Vec<Vertex> = (0..3).map(|_| point_in(rng, 0.0, 4.0).into()).collect();
            let plane = HPlane::through(&pts[0], &pts[1], &pts[2]).ok()?;
            let refl = Isometry::reflection(&plane);
            let x = point_in(rng, 0.0, 6.0);
            let twice = clock.run(|| refl.apply(&refl.apply(&x)));
            Some(r::distance(twice.coords(), x.coords()).to_f64())
        })
        .collect();
    Family {
        operation: "reflection applied twice (involution)",
        unit: "hyperbolic distance",
        errors,
        ns_per_op: clock.mean() / 2.0,
    }
}

/// One step of a random walk of isometries that wanders out to about `cap`
/// from the origin and stays there: a random isometry while the composite's
/// translation part is within `cap`, else a transvection of length 1..2
/// pulling it back towards the origin.
pub fn walk_step(rng: &mut SplitMix64, current: &Point, cap: f64) -> Isometry {
    if current.distance_from_origin() > cap {
        let home = -current.coords().normalize();
        let len = rng.range(1.0, 2.0);
        // Cannot fail: a step of 1 to 2 from the origin is a ball point.
        let p = crate::fixture(Point::at_distance_from_origin(home, len), "short step");
        Isometry::transvection_from_origin(p)
    } else {
        random_isometry(rng, 2.0)
    }
}

/// Leftover translation after composing `steps` random isometries and then
/// their inverses in reverse order, for a walk capped at `cap`; also returns
/// the peak distance the composite reached.
pub fn drift(rng: &mut SplitMix64, chains: usize, steps: usize, cap: f64) -> (Family, f64) {
    let mut peak: f64 = 0.0;
    let mut errors = Vec::new();
    let mut ns = 0.0;
    for _ in 0..chains {
        let mut acc = Isometry::IDENTITY;
        let mut isos = Vec::with_capacity(steps);
        for _ in 0..steps {
            let g = walk_step(rng, &acc.translation_part(), cap);
            acc = g.compose(&acc);
            peak = peak.max(acc.translation_part().distance_from_origin());
            isos.push(g);
        }
        ns += timed(|| {
            isos.iter()
                .fold(Isometry::IDENTITY, |acc, i| i.compose(&acc))
        })
        .1 / steps as f64;
        for g in isos.iter().rev() {
            acc = g.inverse().compose(&acc);
        }
        errors.push(acc.translation_part().distance_from_origin());
    }
    (
        Family {
            operation: "compose 1000 isometries then inverses (drift, peak ~12)",
            unit: "hyperbolic distance",
            errors,
            ns_per_op: ns / chains.max(1) as f64,
        },
        peak,
    )
}

/// Rays from the origin towards random targets, and the error of each hit's
/// arc length against the reference root of the surface's equation along
/// the exact ray. Along one geodesic, the hyperbolic distance between the
/// computed and the true hit points is `|t - t_ref|`.
type HitCase = Option<(DVec3, f64, Box<dyn Fn(&V4) -> R>)>;

fn hit_family(
    operation: &'static str,
    rng: &mut SplitMix64,
    n: usize,
    mut case: impl FnMut(&mut SplitMix64, &mut Clock) -> HitCase,
) -> Family {
    let mut clock = Clock::default();
    let mut errors = Vec::new();
    let mut attempts = 0;
    while errors.len() < n && attempts < 50 * n {
        attempts += 1;
        let Some((dir, t, f)) = case(rng, &mut clock) else {
            continue;
        };
        if let Some(t_ref) = r::root_near(t, |s| f(&r::from_origin(dir, s))) {
            errors.push((R::f(t) - t_ref).abs().to_f64());
        }
    }
    Family {
        operation,
        unit: "hyperbolic distance",
        errors,
        ns_per_op: clock.mean(),
    }
}

/// A direction from the origin that passes near `target`.
fn aim(rng: &mut SplitMix64, target: &Point, spread: f64) -> DVec3 {
    (target.coords().normalize() + cube_direction(rng) * spread).normalize()
}

/// Arc length error of ray-h-sphere hits, centres 0.5 to 12 away.
pub fn sphere_hits(rng: &mut SplitMix64, n: usize) -> Family {
    hit_family(
        "ray-sphere hit (centres up to 12 away)",
        rng,
        n,
        |rng, clock| {
            let c = point_in(rng, 0.5, 12.0);
            let radius = c.distance_from_origin() * rng.range(0.01, 0.4);
            let s = HSphere::new(c, radius).ok()?;
            let dir = aim(rng, &c, 0.05);
            let ray = Ray::from_origin_unchecked(dir);
            let hit = clock.run(|| s.intersect(&ray, 0.0, f64::INFINITY))?;
            let ch = r::hyperboloid(c.coords());
            let cosh_r = R::f(radius).cosh();
            Some((
                dir,
                hit.t,
                Box::new(move |x: &V4| -r::ldot(x, &ch) - &cosh_r),
            ))
        },
    )
}

/// Arc length error of ray-h-plane hits, planes 0.5 to 10 away.
pub fn plane_hits(rng: &mut SplitMix64, n: usize) -> Family {
    hit_family(
        "ray-plane hit (planes up to 10 away)",
        rng,
        n,
        |rng, clock| {
            let centre = point_in(rng, 0.5, 10.0);
            let pts: Vec<Point> = (0..3)
                .map(|_| {
                    let off = Isometry::transvection_from_origin(centre);
                    off.apply(&point_in(rng, 0.2, 1.0))
                })
                .collect();
            let verts: Vec<Vertex> = pts.iter().map(|&p| p.into()).collect();
            let plane = HPlane::through(&verts[0], &verts[1], &verts[2]).ok()?;
            let dir = aim(rng, &centre, 0.02);
            let ray = Ray::from_origin_unchecked(dir);
            let hit = clock.run(|| plane.intersect(&ray, 0.0, f64::INFINITY))?;
            let h: Vec<V4> = pts.iter().map(|p| r::hyperboloid(p.coords())).collect();
            Some((
                dir,
                hit.t,
                Box::new(move |x: &V4| det4(x, &h[0], &h[1], &h[2])),
            ))
        },
    )
}

/// Arc length error of ray-polygon hits, polygons 0.5 to 8 away.
pub fn polygon_hits(rng: &mut SplitMix64, n: usize) -> Family {
    hit_family(
        "ray-polygon hit (polygons up to 8 away)",
        rng,
        n,
        |rng, clock| {
            let centre = point_in(rng, 0.5, 8.0);
            let off = Isometry::transvection_from_origin(centre);
            let verts: Vec<Vertex> = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
                .iter()
                .map(|&(x, y)| {
                    // Cannot fail: corners of the unit square times 0.3 lie inside the ball.
                    let corner =
                        crate::fixture(Point::from_coords(DVec3::new(x, y, 0.0) * 0.3), "inside");
                    off.apply(&corner).into()
                })
                .collect();
            let poly = ConvexPolygon::new(verts.clone()).ok()?;
            let dir = aim(rng, &centre, 0.0);
            let ray = Ray::from_origin_unchecked(dir);
            let hit = clock.run(|| poly.intersect(&ray, 0.0, f64::INFINITY))?;
            let h: Vec<V4> = verts
                .iter()
                .take(3)
                .map(|v| r::hyperboloid(v.coords()))
                .collect();
            Some((
                dir,
                hit.t,
                Box::new(move |x: &V4| det4(x, &h[0], &h[1], &h[2])),
            ))
        },
    )
}

/// A tube about the points `a` and `b`, each 0.5 to `reach` from the
/// origin, of radius 0.01 to `max_radius`, drawn in that order.
fn tube(rng: &mut SplitMix64, reach: f64, max_radius: f64) -> (Point, Point, f64) {
    let a = point_in(rng, 0.5, reach);
    let b = point_in(rng, 0.5, reach);
    (a, b, rng.range(0.01, max_radius))
}

/// A tube as the reference sees it: `a` and `b` on the hyperboloid and
/// `sinh^2` of the radius.
fn tube_reference(a: &Point, b: &Point, radius: f64) -> (V4, V4, R) {
    let (ah, bh) = (r::hyperboloid(a.coords()), r::hyperboloid(b.coords()));
    let s = R::f(radius).sinh();
    (ah, bh, &s * &s)
}

/// Arc length error of ray-h-cylinder hits, axes through points 0.5 to 8
/// away.
pub fn cylinder_hits(rng: &mut SplitMix64, n: usize) -> Family {
    hit_family(
        "ray-cylinder hit (closed form; axes up to 8 away)",
        rng,
        n,
        |rng, clock| {
            let (a, b, radius) = tube(rng, 8.0, 0.5);
            let cyl = HCylinder::new(HLine::through(&a.into(), &b.into()).ok()?, radius).ok()?;
            let mid = Point::from_coords((a.coords() + b.coords()) * 0.5).ok()?;
            let dir = aim(rng, &mid, 0.1);
            let ray = Ray::from_origin_unchecked(dir);
            let hit = clock.run(|| cyl.intersect(&ray, 1e-9, f64::INFINITY))?;
            let (ah, bh, s2) = tube_reference(&a, &b, radius);
            Some((
                dir,
                hit.t,
                Box::new(move |x: &V4| r::sinh2_to_line(x, &ah, &bh) - &s2),
            ))
        },
    )
}

/// Arc length error of ray-rod hits on tubes and caps, ends 0.5 to 6 away.
pub fn rod_hits(rng: &mut SplitMix64, n: usize) -> Family {
    hit_family(
        "ray-rod hit (tube and caps, ends up to 6 away)",
        rng,
        n,
        |rng, clock| {
            let (a, b, radius) = tube(rng, 6.0, 0.3);
            let rod = Rod::new(a.into(), b.into(), radius).ok()?;
            let dir = if rng.unit() < 0.5 {
                aim(rng, &a, 0.02)
            } else {
                aim(
                    rng,
                    &Point::from_coords((a.coords() + b.coords()) * 0.5).ok()?,
                    0.05,
                )
            };
            let ray = Ray::from_origin_unchecked(dir);
            let hit = clock.run(|| rod.intersect(&ray, 1e-9, f64::INFINITY))?;
            let (ah, bh, s2) = tube_reference(&a, &b, radius);
            Some((
                dir,
                hit.t,
                Box::new(move |x: &V4| r::sinh2_to_segment(x, &ah, &bh) - &s2),
            ))
        },
    )
}

/// Arc length error of ray-horosphere hits, horospheres through points up
/// to 10 away.
pub fn horosphere_hits(rng: &mut SplitMix64, n: usize) -> Family {
    hit_family(
        "ray-horosphere hit (through points up to 10 away)",
        rng,
        n,
        |rng, clock| {
            let xi_dir = cube_direction(rng);
            let xi = IdealPoint::from_direction(xi_dir).ok()?;
            let q = point_in(rng, 0.0, 10.0);
            let h = Horosphere::new(xi, &q).ok()?;
            let dir = (xi_dir + cube_direction(rng) * 0.5).normalize();
            let ray = Ray::from_origin_unchecked(dir);
            let hit = clock.run(|| h.intersect(&ray, 0.0, f64::INFINITY))?;
            let l = r::ideal(xi.coords());
            let k = -r::ldot(&r::hyperboloid(q.coords()), &l);
            Some((dir, hit.t, Box::new(move |x: &V4| -r::ldot(x, &l) - &k)))
        },
    )
}

/// The 4x4 determinant `det[x; a; b; c]`, zero iff `x` lies in the span of
/// `a, b, c` (on their h-plane).
fn det4(x: &V4, a: &V4, b: &V4, c: &V4) -> R {
    let m = [&x.0, &a.0, &b.0, &c.0];
    let det3 = |r0: usize, r1: usize, r2: usize, cols: [usize; 3]| -> R {
        let e = |r: usize, c: usize| &m[r][cols[c]];
        e(r0, 0) * &(e(r1, 1) * e(r2, 2) - e(r1, 2) * e(r2, 1))
            - e(r0, 1) * &(e(r1, 0) * e(r2, 2) - e(r1, 2) * e(r2, 0))
            + e(r0, 2) * &(e(r1, 0) * e(r2, 1) - e(r1, 1) * e(r2, 0))
    };
    let minors = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];
    let mut acc = R::f(0.0);
    for (col, cols) in minors.iter().enumerate() {
        let term = &m[0][col] * &det3(1, 2, 3, *cols);
        acc = if col % 2 == 0 { acc + term } else { acc - term };
    }
    acc
}

/// Every family, in report order.
pub fn all(seed: u64, n: usize) -> Vec<Family> {
    let mut rng = SplitMix64::new(seed);
    vec![
        distance_boundary(&mut rng, n),
        distance_near(&mut rng, n),
        translation(&mut rng, n),
        reflection_involution(&mut rng, n),
        drift(&mut rng, 8, 1000, 12.0).0,
        sphere_hits(&mut rng, n),
        plane_hits(&mut rng, n),
        polygon_hits(&mut rng, n),
        cylinder_hits(&mut rng, n),
        rod_hits(&mut rng, n),
        horosphere_hits(&mut rng, n),
    ]
}
