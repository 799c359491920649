//! Tracing rays against a few shapes through the `Shape` trait: the core of
//! a minimal renderer, printed as a 48x24 character picture.
//!
//! ```text
//! cargo run -p hgeom --example trace
//! ```
//!
//! The eye sits at the centre of the ball looking along +z. Each character
//! is one primary ray: the nearest surface it meets, shaded by the angle
//! between the surface normal and the ray (in the hyperboloid's tangent
//! space, which is exactly the hyperbolic angle).

use hgeom::glam::DVec3;
use hgeom::{GeomError, HCylinder, HLine, HPlane, HSphere, Hit, Point, Ray, Shape, lorentz};

fn main() -> Result<(), GeomError> {
    let sphere = HSphere::new(Point::new(0.25, 0.1, 0.6)?, 0.5)?;
    let axis = HLine::through(
        &Point::new(-0.5, -0.5, 0.5)?.into(),
        &Point::new(-0.3, 0.5, 0.6)?.into(),
    )?;
    let tube = HCylinder::new(axis, 0.15)?;
    let floor = HPlane::from_normal(hgeom::glam::DVec4::new(0.0, 1.0, 0.0, 0.3))?;
    // Different shape types, one interface.
    let shapes: [&dyn Shape; 3] = [&sphere, &tube, &floor];

    let (w, h) = (48, 24);
    let ramp = b" .:-=+*#%@";
    let mut hits = 0;
    for row in 0..h {
        let mut line = String::with_capacity(w);
        for col in 0..w {
            // A pinhole camera: directions through a window at z = 1.
            let x = (col as f64 + 0.5) / w as f64 * 2.0 - 1.0;
            let y = 1.0 - (row as f64 + 0.5) / h as f64 * 2.0;
            let ray = Ray::from_origin(DVec3::new(x, y * 0.5, 1.0))?;
            let nearest = shapes
                .iter()
                .filter_map(|s| s.intersect(&ray, 0.0, f64::INFINITY))
                .min_by(|a, b| a.t.total_cmp(&b.t));
            line.push(match nearest {
                Some(hit) => {
                    hits += 1;
                    let k = (facing(&ray, &hit) * (ramp.len() - 1) as f64).round() as usize;
                    ramp[k.min(ramp.len() - 1)] as char
                }
                None => ' ',
            });
        }
        println!("{line}");
    }
    println!("{hits} of {} rays hit", w * h);
    Ok(())
}

/// `|cos|` of the angle between the ray's direction at the hit and the normal.
fn facing(ray: &Ray, hit: &Hit) -> f64 {
    lorentz::dot(ray.tangent_at(hit.t), hit.normal)
        .abs()
        .min(1.0)
}
