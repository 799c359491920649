//! Criterion micro-benchmarks of the intersection kernels and a small render.
//!
//! Speed only; the accuracy of the same kernels is measured against a 320-bit
//! reference by `cargo run --release -p hgeom --example accuracy`, which
//! prints each kernel's error next to its ns per call.
//!
//! Every input is a fixed literal (points well inside the ball, valid
//! radii, the repository's own Appendix A scene). Building the fixtures
//! returns errors all the same: a fixture that could not be built is
//! reported and its benchmarks skipped.

use std::hint::black_box;

use criterion::{Criterion, criterion_main};
use hgeom::glam::DVec3;
use hgeom::{
    ConvexPolygon, GeomError, HCylinder, HLine, HPlane, HSphere, Horosphere, IdealPoint, Isometry,
    Platonic, Point, Polyhedron, Ray, Rod, TriangleMesh,
};

fn rays(n: usize) -> Vec<Ray> {
    (0..n)
        .map(|i| {
            let a = i as f64 * 0.618_033_988_749_895;
            Ray::from_origin_unchecked(DVec3::new(0.3 * a.sin(), 0.3 * a.cos(), 1.0))
        })
        .collect()
}

/// How many rays of `rs` hit, through `hit`: the measured loop of every
/// kernel benchmark below.
fn count_hits(rs: &[Ray], hit: impl Fn(&Ray) -> bool) -> usize {
    rs.iter().filter(|r| hit(black_box(r))).count()
}

fn bench_kernel(c: &mut Criterion, name: &str, rs: &[Ray], hit: impl Fn(&Ray) -> bool) {
    c.bench_function(name, |b| b.iter(|| count_hits(rs, &hit)));
}

/// Reports a fixture that could not be built (its benchmarks are skipped).
fn skipped(what: &str, err: &dyn std::fmt::Display) {
    eprintln!("{what}: fixture not built ({err}); skipped");
}

fn kernels(c: &mut Criterion) {
    if let Err(e) = kernel_benches(c) {
        skipped("kernels", &e);
    }
}

fn kernel_benches(c: &mut Criterion) -> Result<(), GeomError> {
    let rs = rays(1024);
    let p = |x: f64, y: f64, z: f64| Point::from_coords(DVec3::new(x, y, z));
    let sphere = HSphere::new(p(0.02, -0.01, 0.2)?, 0.1)?;
    bench_kernel(c, "sphere_intersect_x1024", &rs, |r| {
        sphere.intersect(r, 1e-9, f64::INFINITY).is_some()
    });
    let dodeca = Polyhedron::platonic(Platonic::Dodecahedron, 0.5)?;
    bench_kernel(c, "dodecahedron_intersect_x1024", &rs, |r| {
        dodeca.intersect(r, 1e-9, f64::INFINITY).is_some()
    });
    let (a, b, q) = (p(-0.2, 0.05, 0.3)?, p(0.2, -0.05, 0.3)?, p(0.0, 0.2, 0.3)?);
    let plane = HPlane::through(&a.into(), &b.into(), &q.into())?;
    bench_kernel(c, "plane_intersect_x1024", &rs, |r| {
        plane.intersect(r, 1e-9, f64::INFINITY).is_some()
    });
    let polygon = ConvexPolygon::new(vec![a.into(), b.into(), q.into()])?;
    bench_kernel(c, "triangle_intersect_x1024", &rs, |r| {
        polygon.intersect(r, 1e-9, f64::INFINITY).is_some()
    });
    let cylinder = HCylinder::new(HLine::through(&a.into(), &b.into())?, 0.05)?;
    bench_kernel(c, "cylinder_intersect_x1024", &rs, |r| {
        cylinder.intersect(r, 1e-9, f64::INFINITY).is_some()
    });
    let rod = Rod::new(a.into(), b.into(), 0.05)?;
    bench_kernel(c, "rod_intersect_x1024", &rs, |r| {
        rod.intersect(r, 1e-9, f64::INFINITY).is_some()
    });
    let horosphere = Horosphere::new(IdealPoint::from_direction(DVec3::Z)?, &p(0.0, 0.0, 0.3)?)?;
    bench_kernel(c, "horosphere_intersect_x1024", &rs, |r| {
        horosphere.intersect(r, 1e-9, f64::INFINITY).is_some()
    });
    Ok(())
}

/// A latitude-longitude sphere of hyperbolic radius `radius` about the
/// origin: `rings` circles of `segments` vertices between the poles,
/// `2 segments rings` triangles, wound outward.
fn sphere_mesh(rings: u32, segments: u32, radius: f64) -> Result<TriangleMesh, GeomError> {
    let at = |d: DVec3| Point::at_distance_from_origin(d, radius);
    let mut vertices = vec![at(DVec3::Z)?, at(-DVec3::Z)?];
    for i in 1..=rings {
        let theta = std::f64::consts::PI * f64::from(i) / f64::from(rings + 1);
        for j in 0..segments {
            let phi = std::f64::consts::TAU * f64::from(j) / f64::from(segments);
            let d = DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            vertices.push(at(d)?);
        }
    }
    let ring = |i: u32, j: u32| 2 + (i - 1) * segments + j % segments;
    let mut triangles = Vec::new();
    for j in 0..segments {
        triangles.push([0, ring(1, j), ring(1, j + 1)]);
        triangles.push([1, ring(rings, j + 1), ring(rings, j)]);
        for i in 1..rings {
            let (a, b) = (ring(i, j), ring(i, j + 1));
            let (c, d) = (ring(i + 1, j), ring(i + 1, j + 1));
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    TriangleMesh::new(vertices, triangles)
}

/// A 2016-triangle sphere-like mesh: the BVH against testing every
/// triangle, for rays from the origin inside it (every ray hits) and for the
/// mesh moved 2 away (most rays hit; the others are culled by the boxes).
fn mesh(c: &mut Criterion) {
    if let Err(e) = mesh_benches(c) {
        skipped("mesh", &e);
    }
}

fn mesh_benches(c: &mut Criterion) -> Result<(), GeomError> {
    let rs = rays(1024);
    let sphere = sphere_mesh(24, 42, 1.0)?;
    assert_eq!(sphere.triangle_count(), 2016);
    let away = Isometry::transvection_from_origin(Point::at_distance_from_origin(DVec3::Z, 2.0)?);
    let far = sphere.transformed(&away);
    let mut group = c.benchmark_group("mesh");
    group.bench_function("bvh_x1024", |b| {
        b.iter(|| count_hits(&rs, |r| sphere.intersect(r, 1e-9, f64::INFINITY).is_some()))
    });
    group.bench_function("brute_force_x1024", |b| {
        b.iter(|| {
            count_hits(&rs, |r| {
                sphere
                    .intersect_exhaustive(r, 1e-9, f64::INFINITY)
                    .is_some()
            })
        })
    });
    group.bench_function("blocks_x1024", |b| {
        b.iter(|| count_hits(&rs, |r| sphere.blocks(r, 1e-9, f64::INFINITY)))
    });
    group.bench_function("moved_bvh_x1024", |b| {
        b.iter(|| count_hits(&rs, |r| far.intersect(r, 1e-9, f64::INFINITY).is_some()))
    });
    group.bench_function("moved_brute_force_x1024", |b| {
        b.iter(|| {
            count_hits(&rs, |r| {
                far.intersect_exhaustive(r, 1e-9, f64::INFINITY).is_some()
            })
        })
    });
    group.bench_function("build_2016", |b| {
        b.iter(|| sphere_mesh(24, 42, black_box(1.0)).map(|m| m.triangle_count()))
    });
    group.bench_function("transformed", |b| {
        b.iter(|| sphere.transformed(black_box(&away)).triangle_count())
    });
    group.finish();
    Ok(())
}

fn appendix_render(c: &mut Criterion) {
    let source = include_str!("../scenes/thesis-appendix-a.hsc");
    let Some(scene) = hscene_lang::compile(source).scene else {
        skipped("render", &"the appendix scene does not compile");
        return;
    };
    let options = hrender::RenderOptions {
        resolution: hscene_lang::ir::Resolution::new(64, 64),
        ..Default::default()
    };
    let mut group = c.benchmark_group("render");
    group.sample_size(10);
    group.bench_function("appendix_a_64x64", |b| {
        b.iter(|| hrender::render(&scene, &options, &|_| {}).map(|r| r.stats.rays))
    });
    group.finish();
}

// `criterion_group!` declares an undocumented `pub fn`; in a private module
// it is no public item for `missing_docs` to flag.
mod group {
    criterion::criterion_group!(benches, super::kernels, super::mesh, super::appendix_render);
}
criterion_main!(group::benches);
