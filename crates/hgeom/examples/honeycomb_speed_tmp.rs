use glam::DVec3;
use hgeom::{HoneycombStyle, Ray, RegularHoneycomb, Schlafli};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(500);
    let horizon: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(15.0);
    for (p, q, r) in [(4, 3, 5), (5, 3, 4), (3, 5, 3), (6, 3, 3), (4, 4, 4)] {
        let style = HoneycombStyle {
            edges: Some(0.05),
            faces: false,
            vertices: None,
            depth: None,
            cell_classes: 1,
        };
        let h = RegularHoneycomb::new(Schlafli::new(p, q, r).unwrap(), style)
            .unwrap()
            .with_horizon(horizon)
            .unwrap();
        let start = Instant::now();
        let (mut ch, mut cells, mut hits) = (0u64, 0u64, 0u64);
        for j in 0..n {
            for i in 0..n {
                let x = (i as f64 + 0.5) / n as f64 * 2.0 - 1.0;
                let y = (j as f64 + 0.5) / n as f64 * 2.0 - 1.0;
                let ray = Ray::from_origin_unchecked(
                    DVec3::new(x, y, 1.0) + DVec3::new(0.01, 0.02, 0.03),
                );
                let (hit, s) = h.intersect_with_stats(&ray, 1e-9, f64::INFINITY);
                ch += s.chambers as u64;
                cells += s.cells as u64;
                hits += hit.is_some() as u64;
            }
        }
        let dt = start.elapsed().as_secs_f64();
        let rays = (n * n) as f64;
        println!(
            "{{{p},{q},{r}}} {n}x{n} horizon {horizon}: {:.3} s, {:.0} rays/s, chambers/ray {:.1}, cells/ray {:.2}, hit {:.3}",
            dt,
            rays / dt,
            ch as f64 / rays,
            cells as f64 / rays,
            hits as f64 / rays
        );
    }
}
