//! The regular honeycombs traced by walking the Coxeter simplex, checked
//! against explicit cells, their own symmetries and a 320-bit walk.

use glam::{DMat3, DMat4, DVec3, DVec4};
use hgeom::{
    ConvexPolygon, CoxeterSimplex, HSphere, Hit, HoneycombPart, HoneycombStyle, Isometry, Point,
    Ray, RegularHoneycomb, Rod, Schlafli, Shape, cube_435, decode_honeycomb_part, lorentz,
    tessellate, unique_edges,
};
use hscene_test_support::SplitMix64;
use hscene_test_support::reference::{R, V4, distance_h, ldot};

fn honeycomb(p: u32, q: u32, r: u32, style: HoneycombStyle) -> RegularHoneycomb {
    RegularHoneycomb::new(Schlafli::new(p, q, r).unwrap(), style).unwrap()
}

fn faces_only() -> HoneycombStyle {
    HoneycombStyle {
        edges: None,
        faces: true,
        vertices: None,
        depth: None,
        cell_classes: 1,
    }
}

#[test]
fn a_ray_along_an_axis_meets_the_cube_face_at_the_inradius() {
    let h = honeycomb(4, 3, 5, faces_only());
    let ray = Ray::from_origin(DVec3::X).unwrap();
    let hit = h.intersect(&ray, 1e-9, f64::INFINITY).unwrap();
    let inradius = (5f64.sqrt() - 2.0).sqrt().atanh();
    assert!((hit.t - inradius).abs() < 1e-14, "{} vs {inradius}", hit.t);
    assert_eq!(decode_honeycomb_part(hit.part).0, HoneycombPart::Face);
    // The normal faces the ray.
    assert!(lorentz::dot(hit.normal, ray.tangent_at(hit.t)) < -0.999);
    let _ = DVec4::W;
}

/// The explicit {4,3,5} cells within `depth`: faces, rods about the unique
/// edges, balls at the unique vertices, as the `Tessellation435` figure
/// draws them.
fn explicit_435(depth: usize, style: &HoneycombStyle) -> Vec<Box<dyn Shape>> {
    let cells = tessellate(&cube_435().unwrap(), depth).unwrap();
    let faces: Vec<ConvexPolygon> = cells
        .iter()
        .flat_map(|c| c.polyhedron.faces().to_vec())
        .collect();
    let mut shapes: Vec<Box<dyn Shape>> = Vec::new();
    let edges = unique_edges(&faces);
    if let Some(w) = style.edges {
        for (a, b) in &edges {
            shapes.push(Box::new(Rod::new(*a, *b, w).unwrap()));
        }
    }
    if let Some(r) = style.vertices {
        let mut seen: Vec<DVec3> = Vec::new();
        for v in edges.iter().flat_map(|(a, b)| [*a, *b]) {
            if seen.iter().all(|s| (*s - v.coords()).length() > 1e-9) {
                seen.push(v.coords());
                let p = Point::from_coords(v.coords()).unwrap();
                shapes.push(Box::new(HSphere::new(p, r).unwrap()));
            }
        }
    }
    if style.faces {
        for f in faces {
            shapes.push(Box::new(f));
        }
    }
    shapes
}

fn nearest(shapes: &[Box<dyn Shape>], ray: &Ray) -> Option<Hit> {
    shapes
        .iter()
        .filter_map(|s| s.intersect(ray, 1e-9, f64::INFINITY))
        .min_by(|a, b| a.t.total_cmp(&b.t))
}

/// A ray from a random point within `reach` of the origin in a random
/// direction.
fn random_ray(rng: &mut SplitMix64, reach: f64) -> Ray {
    let p = Point::at_distance_from_origin(rng.direction(), rng.range(0.0, reach)).unwrap();
    Ray::from_ball(&p, rng.direction()).unwrap()
}

#[test]
fn walk_matches_explicit_cells() {
    let styles = [
        faces_only(),
        HoneycombStyle {
            edges: Some(0.08),
            faces: false,
            vertices: Some(0.3),
            depth: None,
            cell_classes: 1,
        },
        HoneycombStyle {
            edges: Some(0.05),
            faces: true,
            vertices: Some(0.1),
            depth: None,
            cell_classes: 1,
        },
    ];
    let mut rng = SplitMix64::new(435);
    let mut worst: f64 = 0.0;
    let mut kinds = [0usize; 3];
    let mut misses = 0;
    for depth in [1u32, 2] {
        for style in styles {
            let style = HoneycombStyle {
                depth: Some(depth),
                ..style
            };
            let walk = honeycomb(4, 3, 5, style);
            let explicit = explicit_435(depth as usize, &style);
            for _ in 0..150 {
                let ray = random_ray(&mut rng, 1.0);
                let a = walk.intersect(&ray, 1e-9, f64::INFINITY);
                let b = nearest(&explicit, &ray);
                match (a, b) {
                    (Some(a), Some(b)) => {
                        kinds[decode_honeycomb_part(a.part).0 as usize] += 1;
                        worst = worst.max((a.t - b.t).abs());
                        assert!((a.t - b.t).abs() < 1e-9, "{} vs {} ({style:?})", a.t, b.t);
                        assert!(
                            (a.normal - b.normal).length() < 1e-6
                                || (a.normal + b.normal).length() < 1e-6,
                            "{:?} vs {:?}",
                            a.normal,
                            b.normal
                        );
                    }
                    (None, None) => misses += 1,
                    (a, b) => panic!("walk {a:?} vs explicit {b:?} ({style:?}, {ray:?})"),
                }
            }
        }
    }
    println!("walk vs explicit: worst |dt| = {worst:e}, hits {kinds:?}, misses {misses}");
    // Every kind of part is met, and rays also leave the listed cells.
    assert!(
        kinds.iter().all(|&k| k > 20) && misses > 20,
        "{kinds:?} {misses}"
    );
}

fn everything(classes: u32) -> HoneycombStyle {
    HoneycombStyle {
        edges: Some(0.05),
        faces: true,
        vertices: Some(0.12),
        depth: None,
        cell_classes: classes,
    }
}

fn moved(ray: &Ray, l: DMat4) -> Ray {
    Ray {
        origin: l * ray.origin,
        dir: l * ray.dir,
    }
}

#[test]
fn unlimited_walk_matches_explicit_cells_near_the_base() {
    // Edges only: rays pass through several cells before meeting a rod.
    let style = HoneycombStyle {
        edges: Some(0.06),
        faces: false,
        vertices: Some(0.1),
        depth: None,
        cell_classes: 1,
    };
    let walk = honeycomb(4, 3, 5, style);
    let explicit = explicit_435(3, &style);
    let mut rng = SplitMix64::new(7);
    let mut compared = 0;
    for _ in 0..400 {
        let ray = random_ray(&mut rng, 0.3);
        let a = walk.intersect(&ray, 1e-9, f64::INFINITY);
        let b = nearest(&explicit, &ray);
        // Depth 3 holds every point within 1.6 of the origin.
        if let Some(a) = a.filter(|h| h.t < 1.3) {
            let b = b.unwrap();
            assert!((a.t - b.t).abs() < 1e-9, "{} vs {}", a.t, b.t);
            compared += 1;
        } else if let Some(b) = b {
            assert!(b.t >= 1.3 - 1e-9, "explicit {} missed by the walk", b.t);
        }
    }
    assert!(compared > 50, "{compared}");
}

#[test]
fn symmetries_of_the_honeycomb_leave_hits_unchanged() {
    let mut rng = SplitMix64::new(15);
    for (p, q, r) in Schlafli::ALL {
        let symbol = Schlafli::new(p, q, r).unwrap();
        let h = RegularHoneycomb::new(symbol, everything(3)).unwrap();
        let simplex = CoxeterSimplex::new(symbol);
        let mut hits = 0;
        for _ in 0..40 {
            let ray = random_ray(&mut rng, 0.3);
            let a = h.intersect(&ray, 1e-9, f64::INFINITY);
            for k in 0..4 {
                let b = h.intersect(&moved(&ray, simplex.reflection(k)), 1e-9, f64::INFINITY);
                match (a, b) {
                    (Some(a), Some(b)) => {
                        assert!(
                            (a.t - b.t).abs() < 1e-9,
                            "{symbol} m{k}: {} vs {}",
                            a.t,
                            b.t
                        );
                        let (ka, ca) = decode_honeycomb_part(a.part);
                        let (kb, cb) = decode_honeycomb_part(b.part);
                        assert_eq!(ka, kb);
                        // The mirrors through the base point and the base
                        // cell's centre (or, for an ideal centre, the line
                        // to it) fix the base cell's ranking.
                        if k < 2 || (k == 2 && !symbol.has_ideal_cells()) {
                            assert_eq!(ca, cb, "{symbol} m{k}");
                        }
                        let n = simplex.reflection(k) * a.normal;
                        // Far out the components are ~e^t and mostly
                        // null: compare by the Lorentz angle.
                        let cos = lorentz::dot(n, b.normal);
                        let tol = 1e-12 * (1.0 + n.length_squared());
                        assert!((1.0 - cos).abs() < tol, "{symbol} m{k}: {cos}");
                    }
                    (None, None) => {}
                    _ => panic!("{symbol} m{k}: {a:?} vs {b:?}"),
                }
            }
            hits += usize::from(a.is_some());
        }
        assert!(hits > 30, "{symbol}: {hits}");
    }
}

#[test]
fn placement_moves_the_honeycomb_with_the_ray() {
    let h = honeycomb(5, 3, 4, everything(2));
    let g = Isometry::transvection_from_origin(Point::new(0.3, -0.2, 0.4).unwrap())
        .compose(&Isometry::orthogonal(DMat3::from_rotation_y(0.7)).unwrap());
    let placed = h.transformed(&g);
    assert!((placed.base_cell_center().coords() - DVec3::new(0.3, -0.2, 0.4)).length() < 1e-15);
    let l = g.to_lorentz();
    let mut rng = SplitMix64::new(3);
    for _ in 0..100 {
        let ray = random_ray(&mut rng, 0.5);
        let a = h.intersect(&ray, 1e-9, f64::INFINITY);
        let b = placed.intersect(&moved(&ray, l), 1e-9, f64::INFINITY);
        assert_eq!(a.is_some(), b.is_some());
        if let (Some(a), Some(b)) = (a, b) {
            assert!((a.t - b.t).abs() < 1e-9);
            assert_eq!(a.part, b.part);
            assert!((l * a.normal - b.normal).length() < 1e-8);
        }
    }
}

#[test]
fn shadow_rays_agree_with_nearest_hits() {
    let mut rng = SplitMix64::new(99);
    for (p, q, r) in Schlafli::ALL {
        for depth in [None, Some(0)] {
            let style = HoneycombStyle {
                depth,
                ..everything(1)
            };
            let h = honeycomb(p, q, r, style);
            for _ in 0..30 {
                let ray = random_ray(&mut rng, 0.5);
                let t_max = rng.range(0.0, 3.0);
                assert_eq!(
                    h.blocks(&ray, 1e-9, t_max),
                    h.intersect(&ray, 1e-9, t_max).is_some(),
                );
            }
        }
    }
}

#[test]
fn rays_into_ideal_vertices_end_on_the_rods_without_nan() {
    for (p, q, r) in Schlafli::ALL {
        let symbol = Schlafli::new(p, q, r).unwrap();
        let simplex = CoxeterSimplex::new(symbol);
        let ideal: Vec<(usize, DVec4)> = (0..4)
            .filter(|&k| simplex.ideal()[k])
            .map(|k| (k, simplex.vertices()[k]))
            .collect();
        for (k, v) in ideal {
            for style in [everything(2), faces_only()] {
                let h = RegularHoneycomb::new(symbol, style).unwrap();
                for wobble in [0.0, 1e-12, 1e-6, 1e-3] {
                    let dir = v.truncate() + DVec3::new(wobble, -0.5 * wobble, 0.0);
                    let ray = Ray::from_origin(dir).unwrap();
                    let (hit, stats) = h.intersect_with_stats(&ray, 1e-9, f64::INFINITY);
                    assert!(stats.steps > 0);
                    if let Some(hit) = hit {
                        assert!(hit.t.is_finite() && hit.point.is_finite());
                        assert!(hit.normal.is_finite());
                        assert!((lorentz::dot(hit.normal, hit.normal) - 1.0).abs() < 1e-6);
                    } else {
                        // Up the cusp of an ideal vertex the rods widen
                        // until they fill it; the cusp of an ideal cell
                        // centre is the cell's inside, which the ray may
                        // cross to the horizon without meeting a part.
                        assert!(style.edges.is_none() || k == 3, "{symbol} {wobble}");
                    }
                }
            }
        }
    }
}

#[test]
fn hit_normals_are_unit_tangents_facing_the_ray() {
    let mut rng = SplitMix64::new(5);
    for (p, q, r) in Schlafli::ALL {
        let h = honeycomb(p, q, r, everything(4));
        for _ in 0..30 {
            let ray = random_ray(&mut rng, 0.5);
            let Some(hit) = h.intersect(&ray, 1e-9, f64::INFINITY) else {
                continue;
            };
            assert!((lorentz::dot(hit.normal, hit.normal) - 1.0).abs() < 1e-9);
            assert!(lorentz::dot(hit.normal, hit.point).abs() < 1e-9);
            assert!((hit.point - ray.at(hit.t)).length() < 1e-12 * hit.point.length());
            let (kind, class) = decode_honeycomb_part(hit.part);
            assert!(class < 4);
            if kind != HoneycombPart::Face {
                // Rods and balls: the ray enters from outside.
                assert!(lorentz::dot(hit.normal, ray.tangent_at(hit.t)) < 0.0);
            }
        }
    }
}

/// The walk of `walls` replayed at 320 bits from the same f64 ray and
/// normals: the arc length and the point after each step, and whether
/// the reference itself would have left through that wall.
fn reference_walk(normals: &[DVec4], ray: &Ray, walls: &[usize]) -> Vec<(R, V4, bool)> {
    let n: Vec<V4> = normals.iter().map(|v| V4::from_f64(*v)).collect();
    let mut o = V4::from_f64(ray.origin);
    let mut d = V4::from_f64(ray.dir);
    let mut t = R::f(0.0);
    let one = R::f(1.0);
    let two = R::f(2.0);
    let mut last = usize::MAX;
    let mut out = Vec::new();
    for &w in walls {
        // The exit the reference would choose: least -a/b over b < 0.
        let mut best: Option<(usize, R)> = None;
        for (i, ni) in n.iter().enumerate() {
            let b = ldot(&d, ni);
            if i == last || !b.is_negative() {
                continue;
            }
            let s = -(ldot(&o, ni) / b);
            if best.as_ref().is_none_or(|(_, bs)| s.lt(bs)) {
                best = Some((i, s));
            }
        }
        let agrees = best.as_ref().is_some_and(|(i, _)| *i == w);
        let s = -(ldot(&o, &n[w]) / ldot(&d, &n[w]));
        let c = one.clone() / (one.clone() - s.clone() * &s).sqrt();
        let o2 = o.add(&d.scale(&s)).scale(&c);
        let d2 = o.scale(&s).add(&d).scale(&c);
        let reflect = |x: &V4| x.sub(&n[w].scale(&(two.clone() * ldot(x, &n[w]))));
        o = reflect(&o2);
        d = reflect(&d2);
        t = t + ((one.clone() + &s) / (one.clone() - &s)).ln() * R::f(0.5);
        last = w;
        out.push((t.clone(), o.clone(), agrees));
    }
    out
}

#[test]
fn walk_drift_against_a_320_bit_walk() {
    let mut rng = SplitMix64::new(320);
    for (p, q, r) in [
        (4, 3, 5),
        (5, 3, 4),
        (3, 5, 3),
        (6, 3, 3),
        (3, 3, 6),
        (4, 4, 4),
    ] {
        let symbol = Schlafli::new(p, q, r).unwrap();
        let h = RegularHoneycomb::new(symbol, faces_only())
            .unwrap()
            .with_horizon(30.0)
            .unwrap();
        let normals = h.walls();
        // Drift grows like eps e^t (nearby geodesics diverge like e^t, and
        // each step adds a rounding): checkpoints by arc length.
        let checkpoints = [5.0, 10.0, 12.0, 15.0];
        let mut worst_t = [0.0f64; 4];
        let mut worst_x = [0.0f64; 4];
        for _ in 0..6 {
            // From the base point, which lies in the simplex.
            let ray = Ray::from_origin(rng.direction()).unwrap();
            let steps = h.walk_steps(&ray, 400);
            let walls: Vec<usize> = steps.iter().map(|s| s.wall).collect();
            let reference = reference_walk(&normals, &ray, &walls);
            for (k, &at) in checkpoints.iter().enumerate() {
                let Some(n) = steps.iter().position(|s| s.t >= at) else {
                    continue;
                };
                if !reference[..=n].iter().all(|r| r.2) {
                    continue;
                }
                let (t, x, _) = &reference[n];
                let dt = (t.clone() - R::f(steps[n].t)).abs().to_f64();
                let dx = distance_h(x, &V4::from_f64(steps[n].origin)).to_f64();
                worst_t[k] = worst_t[k].max(dt);
                worst_x[k] = worst_x[k].max(dx);
            }
        }
        println!("{symbol}: drift at t = {checkpoints:?}: t {worst_t:?}, point {worst_x:?}");
        // Nearby geodesics of the folded walk part like e^{2t} (measured:
        // a 1e-13 change of the start grows the same way), and the walk's
        // own rounding with them: 3e-15 e^{2t}, 3e-5 at the default
        // horizon of 12.
        for (k, at) in checkpoints.iter().enumerate() {
            let bound = 3e-15 * (2.0 * at).exp();
            assert!(
                worst_t[k] < bound && worst_x[k] < bound,
                "{symbol} t = {at}"
            );
        }
    }
}

/// A ray back from a hit towards where it came from crosses nothing: the
/// walk from the hit does not find the part it starts on again, even far
/// out where the two walks drift apart.
#[test]
fn rays_back_from_far_hits_are_clear() {
    let mut rng = SplitMix64::new(11);
    for (p, q, r) in [(4, 3, 5), (6, 3, 3), (4, 4, 4)] {
        // Thin rods: rays go far before meeting one.
        let style = HoneycombStyle {
            edges: Some(0.001),
            faces: false,
            vertices: None,
            depth: None,
            cell_classes: 1,
        };
        let h = honeycomb(p, q, r, style).with_horizon(15.0).unwrap();
        let mut bad = Vec::new();
        let mut ts = Vec::new();
        for _ in 0..400 {
            let ray = random_ray(&mut rng, 0.3);
            let Some(hit) = h.intersect(&ray, 1e-9, f64::INFINITY) else {
                continue;
            };
            ts.push(hit.t);
            let back = Ray {
                origin: hit.point,
                dir: -ray.tangent_at(hit.t),
            };
            if let Some(b) = h.intersect(&back, 1e-9, hit.t * (1.0 - 1e-9)) {
                bad.push((hit.t, b.t));
            }
        }
        ts.sort_by(f64::total_cmp);
        assert!(bad.is_empty(), "{p}{q}{r}: {bad:?}");
        assert!(
            ts.iter().filter(|&&t| t > 10.0).count() >= 3,
            "{p}{q}{r}: {ts:?}"
        );
    }
}

/// The cells a walk enters are cells of `Tessellation435`: the centre of
/// each (the chamber matrix applied to the base centre) is one of
/// `tessellate`'s, and rays in all directions enter every cell of depth 1.
#[test]
fn cells_entered_by_walks_are_those_of_tessellate() {
    let h = honeycomb(4, 3, 5, faces_only());
    let explicit: Vec<DVec4> = tessellate(&cube_435().unwrap(), 3)
        .unwrap()
        .iter()
        .map(|c| c.polyhedron.center().to_hyperboloid())
        .collect();
    let near: Vec<DVec4> = explicit[..7].to_vec();
    let mut entered = vec![false; near.len()];
    let mut rng = SplitMix64::new(8);
    let mut checked = 0;
    for _ in 0..300 {
        let ray = Ray::from_origin(rng.direction()).unwrap();
        for step in h.walk_steps(&ray, 40).iter().filter(|s| s.face) {
            // The chamber entered across a face plane: its cell's centre.
            let c = step.chamber.col(3);
            if c.w > 4.0 {
                break;
            }
            assert!(
                explicit.iter().any(|e| lorentz::distance(*e, c) < 1e-9),
                "{c:?} is no cell of depth 3"
            );
            checked += 1;
            for (k, e) in near.iter().enumerate() {
                entered[k] |= lorentz::distance(*e, c) < 1e-9;
            }
        }
    }
    assert!(checked > 300);
    assert!(entered[1..].iter().all(|&e| e), "{entered:?}");
}

#[test]
fn honeycombs_can_be_shared_between_threads() {
    fn shareable<T: Send + Sync + Clone + std::fmt::Debug>() {}
    shareable::<RegularHoneycomb>();
    let h: Box<dyn Shape + Send + Sync> = Box::new(honeycomb(3, 5, 3, everything(1)));
    assert!(h.bound().is_none() && h.is_representable());
}

/// With a view horizon a ray from the origin stops where the cells fall
/// below its own pixel: along the axis at `horizon_for_pixel(a)`, at 50°
/// from it farther (the pixel there is `cos² 50°` as wide), and never past
/// the honeycomb's horizon: its walk is the walk to that horizon cut at its
/// own. A ray from elsewhere keeps the honeycomb's horizon.
#[test]
fn a_view_horizon_stops_rays_from_the_eye_by_their_pixel() {
    let far = honeycomb(4, 3, 5, HoneycombStyle::default())
        .with_horizon(8.0)
        .unwrap();
    let a = 4e-3;
    let near = far.clone().with_view_horizon(DVec3::Z, a).unwrap();
    let walls_and_t = |h: &RegularHoneycomb, ray: &Ray| -> Vec<(usize, f64)> {
        h.walk_steps(ray, 400)
            .iter()
            .map(|s| (s.wall, s.t))
            .collect()
    };
    let th = 50f64.to_radians();
    for (dir, want) in [
        (DVec3::Z, far.horizon_for_pixel(a)),
        (
            DVec3::new(th.sin(), 0.0, th.cos()),
            far.horizon_for_pixel(a * th.cos() * th.cos()),
        ),
    ] {
        assert!(want < 8.0, "{want}");
        let ray = Ray::from_origin_unchecked(dir);
        let cut: Vec<(usize, f64)> = walls_and_t(&far, &ray)
            .into_iter()
            .filter(|&(_, t)| t <= want)
            .collect();
        let walked = walls_and_t(&near, &ray);
        assert!(walked.len() >= 4, "{dir}: {walked:?}");
        assert_eq!(walked, cut, "{dir}");
        if dir == DVec3::Z {
            // Along the axis the view horizon is well inside the
            // honeycomb's: the far walk goes on.
            assert!(walls_and_t(&far, &ray).len() > walked.len() + 1);
        }
    }
    let start = Point::from_coords(DVec3::new(0.05, 0.0, 0.0)).unwrap();
    let aside = Ray::from_ball_unchecked(&start, DVec3::Z);
    assert_eq!(walls_and_t(&near, &aside), walls_and_t(&far, &aside));
    // `for_pixels` is both: the smallest pixel's horizon where it is
    // nearer (a pixel of `a` here), the view horizon on a plane.
    let axis_ray = Ray::from_origin_unchecked(DVec3::Z);
    let drawn = far
        .clone()
        .for_pixels(a / 100.0, Some((DVec3::Z, a)))
        .unwrap();
    assert_eq!(drawn.horizon(), far.horizon());
    assert_eq!(
        walls_and_t(&drawn, &axis_ray),
        walls_and_t(&near, &axis_ray)
    );
    let flat = far.clone().for_pixels(a, None).unwrap();
    assert_eq!(flat.horizon(), far.horizon_for_pixel(a));
    // Along the axis the view horizon is that same distance.
    assert_eq!(walls_and_t(&flat, &axis_ray), walls_and_t(&near, &axis_ray));
    assert!(far.clone().with_view_horizon(DVec3::ZERO, a).is_err());
    assert!(far.with_view_horizon(DVec3::Z, -1.0).is_err());
}

/// `CellColouring::Parity` two-colours the cells of `{5,3,4}` and
/// `{4,3,6}` (four and six round each edge): along any ray the faces it
/// crosses alternate 0, 1, 0, ... from the base cell, and a ray started
/// in a far cell sees the class that cell has from the base cell's count,
/// whatever way it takes. `{4,3,5}` (five round each edge) is refused.
#[test]
fn parity_two_colours_the_cells_where_r_is_even() {
    use hgeom::CellColouring;
    let mut rng = SplitMix64::new(42);
    for (p, q, r) in [(5, 3, 4), (4, 3, 6)] {
        let h = honeycomb(p, q, r, faces_only())
            .with_colouring(CellColouring::Parity)
            .unwrap();
        for _ in 0..40 {
            let ray = Ray::from_origin_unchecked(rng.direction());
            let mut from = 0.0;
            let mut classes = Vec::new();
            for _ in 0..4 {
                let Some(hit) = h.intersect(&ray, from, 6.0) else {
                    break;
                };
                classes.push(decode_honeycomb_part(hit.part).1);
                from = hit.t + 1e-9;
            }
            assert!(classes.len() >= 2, "{{{p},{q},{r}}}: {classes:?}");
            for (k, c) in classes.iter().enumerate() {
                assert_eq!(*c, (k % 2) as u32, "{{{p},{q},{r}}}: {classes:?}");
            }
            // From a point just past the second face (in a cell two
            // crossings out: class 0), any direction sees class 0 first.
            let second = {
                let first = h.intersect(&ray, 0.0, 6.0).unwrap();
                h.intersect(&ray, first.t + 1e-9, 6.0).unwrap()
            };
            let inside = ray.at(second.t + 1e-6);
            for _ in 0..5 {
                let w = rng.direction().extend(0.0);
                let d = w + lorentz::dot(w, inside) * inside;
                let d = d / lorentz::norm(d);
                let from_far = Ray {
                    origin: inside,
                    dir: d,
                };
                let hit = h.intersect(&from_far, 1e-7, 6.0).unwrap();
                assert_eq!(
                    decode_honeycomb_part(hit.part).1,
                    0,
                    "{{{p},{q},{r}}}: a cell two crossings out"
                );
            }
        }
    }
    assert!(
        honeycomb(4, 3, 5, faces_only())
            .with_colouring(CellColouring::Parity)
            .is_err()
    );
}
