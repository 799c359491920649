//! Smooth mesh shading: closed-form expectations for
//! `TriangleMesh::smoothed` (see `docs/geometry.md`, "Smooth meshes").

use glam::{DVec3, DVec4};
use hgeom::{GivenNormals, HSphere, Isometry, Point, Ray, TriangleMesh, lorentz};

/// The angle between two unit tangent vectors at one point.
fn angle(a: DVec4, b: DVec4) -> f64 {
    lorentz::dot(a, b).clamp(-1.0, 1.0).acos()
}

/// An octahedron subdivided `levels` times with its vertices pushed onto
/// the unit sphere of directions (counter-clockwise from outside).
fn octasphere(levels: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut dirs = vec![
        DVec3::X,
        DVec3::NEG_X,
        DVec3::Y,
        DVec3::NEG_Y,
        DVec3::Z,
        DVec3::NEG_Z,
    ];
    let mut tris: Vec<[u32; 3]> = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    for _ in 0..levels {
        let mut mid = std::collections::HashMap::new();
        let mut next = Vec::with_capacity(tris.len() * 4);
        let mut midpoint = |a: u32, b: u32, dirs: &mut Vec<DVec3>| -> u32 {
            *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
                dirs.push((dirs[a as usize] + dirs[b as usize]).normalize());
                (dirs.len() - 1) as u32
            })
        };
        for [a, b, c] in tris {
            let ab = midpoint(a, b, &mut dirs);
            let bc = midpoint(b, c, &mut dirs);
            let ca = midpoint(c, a, &mut dirs);
            next.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        tris = next;
    }
    (dirs, tris)
}

/// Pseudo-random directions (a fixed LCG, so the numbers are reproducible).
fn directions(count: usize, around: DVec3, spread: f64) -> Vec<DVec3> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..count)
        .map(|_| (around + spread * DVec3::new(next(), next(), next())).normalize())
        .collect()
}

#[test]
fn smoothed_sphere_shades_with_the_true_sphere_normal() {
    let (radius, centre) = (0.5, Point::new(0.2, -0.1, 0.15).unwrap());
    let to_centre = Isometry::transvection_from_origin(centre);
    let (dirs, tris) = octasphere(5);
    let vertices: Vec<Point> = dirs
        .iter()
        .map(|&d| to_centre * Point::at_distance_from_origin(d, radius).unwrap())
        .collect();
    let sphere = HSphere::new(centre, radius).unwrap();
    let exact = GivenNormals {
        normals: vertices
            .iter()
            .map(|p: &Point| sphere.normal_at(p.to_hyperboloid()))
            .collect(),
        corners: tris.clone(),
        triangles: tris.clone(),
    };
    let flat = TriangleMesh::new(vertices, tris).unwrap();
    let smooth = flat.smoothed(60.0, None).unwrap();
    let given = flat.smoothed(60.0, Some(&exact)).unwrap();
    let mut worst_given = 0.0f64;
    let (mut worst_flat, mut worst_smooth, mut hits) = (0.0f64, 0.0f64, 0);
    for d in directions(2000, centre.coords().normalize(), 0.6) {
        let ray = Ray::from_origin(d).unwrap();
        let (Some(a), Some(b)) = (
            flat.intersect(&ray, 0.0, f64::INFINITY),
            smooth.intersect(&ray, 0.0, f64::INFINITY),
        ) else {
            assert!(smooth.intersect(&ray, 0.0, f64::INFINITY).is_none());
            continue;
        };
        // Smoothing changes the shading normal only.
        assert_eq!((a.t, a.point, a.normal), (b.t, b.point, b.normal));
        assert_eq!(a.shading, a.normal);
        let truth = sphere.normal_at(b.point);
        worst_flat = worst_flat.max(angle(a.normal, truth));
        worst_smooth = worst_smooth.max(angle(b.shading, truth));
        let g = given.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        worst_given = worst_given.max(angle(g.shading, truth));
        assert!(lorentz::dot(b.shading, b.point).abs() < 1e-12);
        assert!((lorentz::dot(b.shading, b.shading) - 1.0).abs() < 1e-12);
        hits += 1;
    }
    println!(
        "{hits} hits; worst normal error flat {worst_flat:.3e}, smooth {worst_smooth:.3e}, \
         smooth with the exact vertex normals {worst_given:.3e}"
    );
    assert!(hits > 500);
    assert!(worst_flat > 0.04);
    // Computed vertex normals (angle-weighted face averages) are themselves
    // off by O(h^2) on this uneven tessellation; interpolating exact vertex
    // normals is exact for a sphere about the mesh's centre, to the f32
    // storage.
    assert!(worst_smooth < 6e-3, "smooth error {worst_smooth}");
    assert!(worst_smooth < worst_flat / 7.0);
    assert!(worst_given < 1e-6, "exact-normal error {worst_given}");
    // 8192 triangles, 4098 vertices: 12 bytes per triangle and 12 per vertex.
    assert_eq!(smooth.smooth_bytes(), 8192 * 12 + 4098 * 12);
}

#[test]
fn creases_sharper_than_the_angle_stay_flat() {
    let a = 0.4;
    let corner = |i: u32| {
        let s = |bit: u32| if i & bit != 0 { a } else { -a };
        Point::new(s(1), s(2), s(4)).unwrap()
    };
    let vertices = (0..8).map(corner).collect();
    // Faces counter-clockwise from outside, two triangles each.
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let tris = quads
        .iter()
        .flat_map(|&[p, q, r, s]| [[p, q, r], [p, r, s]])
        .collect();
    let cube = TriangleMesh::new(vertices, tris).unwrap();
    let creased = cube.smoothed(30.0, None).unwrap();
    let rounded = cube.smoothed(180.0, None).unwrap();
    let (mut flat_hits, mut rounded_differ) = (0, 0);
    for d in directions(500, DVec3::new(0.3, 0.2, 0.1), 1.0) {
        let ray = Ray::from_origin(d).unwrap();
        let hit = creased.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert_eq!(hit.shading, hit.normal);
        flat_hits += 1;
        let round = rounded.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        if angle(round.shading, round.normal) > 1e-3 {
            rounded_differ += 1;
        }
    }
    assert_eq!(flat_hits, 500);
    // Without creases the cube's corners are rounded off in shading.
    assert!(rounded_differ > 400, "{rounded_differ}");
    // Every corner is flat: no normal is stored, only the corner indices.
    assert_eq!(creased.smooth_bytes(), 12 * 12);
}

#[test]
fn given_normals_are_used() {
    // A square in the plane z = 0 about the origin, with every vertex normal
    // tilted 20 degrees from the plane's normal towards +x.
    let s = 0.3;
    let vertices: Vec<Point> = [(-s, -s), (s, -s), (s, s), (-s, s)]
        .iter()
        .map(|&(x, y)| Point::new(x, y, 0.0).unwrap())
        .collect();
    let tris = vec![[0, 1, 2], [0, 2, 3]];
    let tilt = 20f64.to_radians();
    let dir = DVec3::new(tilt.sin(), 0.0, tilt.cos());
    // The ball direction `dir` at each vertex, as a hyperboloid tangent: the
    // differential of the ball-to-hyperboloid map.
    let normals = vertices
        .iter()
        .map(|p| {
            let x = p.coords();
            let q = 1.0 - x.length_squared();
            let dx = 2.0 * dir / q + 4.0 * x * x.dot(dir) / (q * q);
            dx.extend(4.0 * x.dot(dir) / (q * q))
        })
        .collect();
    let given = GivenNormals {
        normals,
        triangles: tris.clone(),
        corners: vec![[0, 1, 2], [0, 2, 3]],
    };
    let mesh = TriangleMesh::new(vertices, tris).unwrap();
    let tilted = mesh.smoothed(0.0, Some(&given)).unwrap();
    // From 1 above the square's centre, straight down at it.
    let up = Ray::from_origin(DVec3::Z).unwrap();
    let start = lorentz::geodesic_point(up.origin, up.dir, 1.0);
    let ray = Ray {
        origin: start,
        dir: lorentz::unit_tangent_towards(start, up.origin).unwrap(),
    };
    let hit = tilted
        .intersect(&ray, 0.0, f64::INFINITY)
        .expect("the ray towards the origin meets the square");
    // At the origin the tangent space is the ball's: the shading normal is
    // `dir` itself, 20 degrees from the plane's normal.
    assert!((angle(hit.shading, hit.normal) - tilt).abs() < 1e-6);
    assert!((hit.shading.truncate() - dir).length() < 1e-6);
}
