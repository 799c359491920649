//! Euclidean measures of hyperbolic things in the unit ball: where a
//! hyperboloid point lands, how thick a part prints, how far a chamber
//! reaches.
//!
//! **The thickness bound.** The image of the hyperbolic sphere of radius
//! `w` about a point at Euclidean distance `ρ` from the centre is a
//! Euclidean sphere of radius `R = (1 - ρ²) t / (1 - ρ² t²)`, `t =
//! tanh(w/2)`. Since `ρ t < t`, `R <= (1 - ρ²) t / (1 - t²) = (1 - ρ²)
//! sinh(w) / 2 <= (1 - ρ) sinh w`. Every cross-section of a tube of radius
//! `w`, and every chord across a plate of half-thickness `w`, lies in such
//! a sphere, so nothing of radius `w` is thicker than `2 (1 - ρ) sinh w`
//! where it is: a part thicker than `m` has `ρ <= 1 - m / (2 sinh w)`.

use hgeom::glam::{DVec3, DVec4};

/// The Poincaré-ball point of a hyperboloid point.
pub fn to_ball(x: DVec4) -> DVec3 {
    x.truncate() / (1.0 + x.w)
}

/// The diameter of the circle through three points (`0` if collinear).
pub fn circle_diameter(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (ab, ac) = (b - a, c - a);
    let cross = ab.cross(ac).length();
    if cross == 0.0 {
        return 0.0;
    }
    // The circumradius is |ab| |ac| |bc| / (2 |ab x ac|).
    ab.length() * ac.length() * (c - b).length() / cross
}

/// The largest Euclidean radius `ρ` at which anything of hyperbolic
/// radius `w` can still be `m` thick (module docs); negative when nothing
/// can.
pub fn thick_enough_radius(w: f64, m: f64) -> f64 {
    1.0 - m / (2.0 * w.sinh())
}

/// The Klein-model radius of the ball about the centre whose Poincaré
/// radius is `rho`.
pub fn klein_radius(rho: f64) -> f64 {
    2.0 * rho / (1.0 + rho * rho)
}

/// The Euclidean distance from the origin to the tetrahedron with these
/// corners (0 when the origin is inside).
pub fn distance_to_tetrahedron(k: [DVec3; 4]) -> f64 {
    let faces = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
    let inside = faces.iter().enumerate().all(|(opposite, f)| {
        let [a, b, c] = f.map(|i| k[i]);
        let n = (b - a).cross(c - a);
        let other = k[3 - opposite];
        // The origin is on the same side of each face as the fourth corner.
        n.dot(-a) * n.dot(other - a) >= 0.0
    });
    if inside {
        return 0.0;
    }
    faces
        .iter()
        .map(|f| distance_to_triangle(DVec3::ZERO, f.map(|i| k[i])))
        .fold(f64::INFINITY, f64::min)
}

/// The Euclidean distance from `p` to a triangle (the closest point by
/// the triangle's Voronoi regions).
pub fn distance_to_triangle(p: DVec3, [a, b, c]: [DVec3; 3]) -> f64 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return ap.length();
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return bp.length();
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return (p - (a + v * ab)).length();
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return cp.length();
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return (p - (a + w * ac)).length();
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return (p - (b + w * (c - b))).length();
    }
    let denom = 1.0 / (va + vb + vc);
    let (v, w) = (vb * denom, vc * denom);
    (p - (a + ab * v + ac * w)).length()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circles_and_tetrahedra_measure_as_euclid_says() {
        let d = circle_diameter(DVec3::X, DVec3::Y, -DVec3::X);
        assert!((d - 2.0).abs() < 1e-15);
        let unit = [DVec3::X, DVec3::Y, DVec3::Z, DVec3::ZERO].map(|v| v + DVec3::ONE);
        assert!((distance_to_tetrahedron(unit) - 3f64.sqrt()).abs() < 1e-15);
        let around = [
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(1.0, -1.0, -1.0),
            DVec3::new(-1.0, 1.0, -1.0),
            DVec3::new(-1.0, -1.0, 1.0),
        ];
        assert_eq!(distance_to_tetrahedron(around), 0.0);
        let t = [
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 1.0),
        ];
        assert!((distance_to_triangle(DVec3::ZERO, t) - 1.0).abs() < 1e-15);
    }

    /// The bound of the module docs holds for the exact sphere radius.
    #[test]
    fn the_thickness_bound_holds() {
        for &w in &[0.01, 0.1, 1.0, 3.0] {
            for &rho in &[0.0, 0.3, 0.9, 0.999] {
                let t = (w / 2.0f64).tanh();
                let exact = (1.0 - rho * rho) * t / (1.0 - rho * rho * t * t);
                assert!(exact <= (1.0 - rho) * w.sinh() * (1.0 + 1e-12), "{w} {rho}");
            }
        }
    }
}
