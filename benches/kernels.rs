//! Criterion micro-benchmarks of the intersection kernels and a small render.
//!
//! Speed only; the accuracy of the same kernels is measured by hgeom's tests
//! and (issue 3/6) by the accuracy report, printed next to these timings.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use hgeom::glam::DVec3;
use hgeom::{HSphere, Platonic, Point, Polyhedron, Ray};

fn rays(n: usize) -> Vec<Ray> {
    (0..n)
        .map(|i| {
            let a = i as f64 * 0.618_033_988_749_895;
            Ray::from_origin(DVec3::new(0.3 * a.sin(), 0.3 * a.cos(), 1.0))
        })
        .collect()
}

fn kernels(c: &mut Criterion) {
    let rs = rays(1024);
    let sphere =
        HSphere::try_new(Point::try_new(DVec3::new(0.02, -0.01, 0.2)).unwrap(), 0.1).unwrap();
    c.bench_function("sphere_intersect_x1024", |b| {
        b.iter(|| {
            rs.iter()
                .filter(|r| {
                    sphere
                        .intersect(black_box(r), 1e-9, f64::INFINITY)
                        .is_some()
                })
                .count()
        })
    });
    let dodeca = Polyhedron::platonic(Platonic::Dodecahedron, 0.5).unwrap();
    c.bench_function("dodecahedron_intersect_x1024", |b| {
        b.iter(|| {
            rs.iter()
                .filter(|r| {
                    dodeca
                        .intersect(black_box(r), 1e-9, f64::INFINITY)
                        .is_some()
                })
                .count()
        })
    });
}

fn appendix_render(c: &mut Criterion) {
    let source = include_str!("../scenes/thesis-appendix-a.hsc");
    let scene = hscene_lang::compile(source)
        .scene
        .expect("appendix compiles");
    let options = hrender::RenderOptions {
        resolution: Some(hscene_lang::ir::Resolution {
            width: 64,
            height: 64,
        }),
        ..Default::default()
    };
    let mut group = c.benchmark_group("render");
    group.sample_size(10);
    group.bench_function("appendix_a_64x64", |b| {
        b.iter(|| hrender::render(&scene, &options, &|_| {}).map(|r| r.stats.rays))
    });
    group.finish();
}

criterion_group!(benches, kernels, appendix_render);
criterion_main!(benches);
