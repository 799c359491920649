//! The thesis's benchmark scenes (thesis §8.5, Tables 2 and 3): the
//! "h-spheres" and "h-cylinders" cases as scene text for hscene and as
//! Euclidean twins for POV-Ray. The `thesis` bench renders them all; the
//! `honeycomb` bench compares against the 16-sphere twin.

use std::fmt::Write as _;

use hgeom::glam::DVec3;
use hgeom::{HSphere, Point};

use super::v;

/// One benchmark scene.
pub struct Case {
    pub kind: Kind,
    pub count: usize,
    pub lights: usize,
    pub depth: u32,
    /// The thesis's time in seconds (Core2 Duo 2.2 GHz).
    pub thesis_s: f64,
}

#[derive(Clone, Copy, PartialEq)]
pub enum Kind {
    Spheres,
    Cylinders,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Spheres => "h-spheres",
            Kind::Cylinders => "h-cylinders",
        }
    }
}

pub fn cases() -> Vec<Case> {
    let mut out = Vec::new();
    let sphere_rows: [(usize, u32, [f64; 5]); 3] = [
        (1, 0, [2.3, 3.4, 5.8, 10.8, 22.0]),
        (5, 0, [3.3, 5.5, 10.3, 20.6, 45.6]),
        (5, 1, [4.4, 7.7, 15.4, 32.0, 75.7]),
    ];
    for (lights, depth, times) in sphere_rows {
        for (count, thesis_s) in [1, 2, 4, 8, 16].into_iter().zip(times) {
            out.push(Case {
                kind: Kind::Spheres,
                count,
                lights,
                depth,
                thesis_s,
            });
        }
    }
    let cylinder_rows: [(usize, [f64; 4]); 2] = [
        (1, [29.1, 67.2, 146.3, 333.1]),
        (5, [37.7, 101.6, 266.9, 736.5]),
    ];
    for (lights, times) in cylinder_rows {
        for (count, thesis_s) in [1, 2, 4, 8].into_iter().zip(times) {
            out.push(Case {
                kind: Kind::Cylinders,
                count,
                lights,
                depth: 0,
                thesis_s,
            });
        }
    }
    out
}

/// Grid layout (columns, rows) for `n` objects.
fn grid(n: usize) -> (usize, usize) {
    match n {
        1 => (1, 1),
        2 => (2, 1),
        4 => (2, 2),
        8 => (4, 2),
        _ => (4, n.div_ceil(4)),
    }
}

const SPHERE_RADIUS: f64 = 0.15;
const CYLINDER_RADIUS: f64 = 0.04;
const WINDOW: f64 = 0.12;
const VIEW: f64 = 0.1;

fn sphere_centres(n: usize) -> Vec<DVec3> {
    let (cols, rows) = grid(n);
    let s = 0.14;
    let mut out = Vec::new();
    for j in 0..rows {
        for i in 0..cols {
            if out.len() < n {
                let x = (i as f64 - (cols as f64 - 1.0) / 2.0) * s;
                let y = (j as f64 - (rows as f64 - 1.0) / 2.0) * s;
                out.push(DVec3::new(x, y, 0.55));
            }
        }
    }
    out
}

fn cylinder_axes(n: usize) -> Vec<(DVec3, DVec3)> {
    (0..n)
        .map(|i| {
            let x = (i as f64 - (n as f64 - 1.0) / 2.0) * 0.09;
            (DVec3::new(x, -0.2, 0.6), DVec3::new(x, 0.2, 0.6))
        })
        .collect()
}

fn light_positions(n: usize) -> Vec<DVec3> {
    let all = [
        DVec3::new(0.0, 0.3, 0.2),
        DVec3::new(-0.3, 0.0, 0.2),
        DVec3::new(0.3, 0.0, 0.2),
        DVec3::new(0.0, -0.3, 0.2),
        DVec3::new(0.0, 0.0, 0.05),
    ];
    all[..n].to_vec()
}

/// The hscene source of a case.
pub fn scene_source(c: &Case, resolution: u32) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "// {} {}: {} lights, recursion {}",
        c.count,
        c.kind.name(),
        c.lights,
        c.depth
    );
    let _ = writeln!(
        s,
        "Globals {{ recursion_depth = {}; resolution = ({resolution}, {resolution}); window_size = ({WINDOW}, {WINDOW}); net_type = 0; to = (0, 0, {VIEW}); background = (0.05, 0.05, 0.1); ambient = (0.1, 0.1, 0.1); }}",
        c.depth
    );
    let _ = writeln!(
        s,
        "BRDFs {{ m: ambient = (0.3, 0.1, 0.1), diffuse = (0.8, 0.3, 0.3), specular = (0.6, 0.6, 0.6), alpha = 0.3, trans = 0, shininess = 40, refraction = 1; }}"
    );
    s.push_str("Points {\n");
    match c.kind {
        Kind::Spheres => {
            for p in sphere_centres(c.count) {
                let _ = writeln!(s, "  {};", v(p));
            }
        }
        Kind::Cylinders => {
            for (a, b) in cylinder_axes(c.count) {
                let _ = writeln!(s, "  {}; {};", v(a), v(b));
            }
        }
    }
    let first_light = match c.kind {
        Kind::Spheres => c.count,
        Kind::Cylinders => 2 * c.count,
    };
    for p in light_positions(c.lights) {
        let _ = writeln!(s, "  {};", v(p));
    }
    s.push_str("}\nLights {\n");
    for k in 0..c.lights {
        let _ = writeln!(s, "  %{}, (1.5, 1.5, 1.5), (1, 1, 1);", first_light + k + 1);
    }
    s.push_str("}\nObjects {\n");
    for k in 0..c.count {
        match c.kind {
            Kind::Spheres => {
                let _ = writeln!(s, "  Sphere %{}, {SPHERE_RADIUS}, #m;", k + 1);
            }
            Kind::Cylinders => {
                let _ = writeln!(
                    s,
                    "  Cylinder %{}, %{}, {CYLINDER_RADIUS}, #m;",
                    2 * k + 1,
                    2 * k + 2
                );
            }
        }
    }
    s.push_str("}\n");
    s
}

/// The Euclidean twin for POV-Ray: the same camera, lights and material, a
/// Euclidean sphere where the h-sphere appears in the ball, and a straight
/// cylinder of the same apparent thickness along each h-line's chord.
pub fn pov_source(c: &Case, resolution: u32) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "global_settings {{ max_trace_level {} assumed_gamma 1 }}",
        c.depth + 1
    );
    let _ = writeln!(
        s,
        "camera {{ perspective location <0,0,0> direction <0,0,{VIEW}> right <{WINDOW},0,0> up <0,{WINDOW},0> }}"
    );
    let _ = writeln!(s, "background {{ color rgb <0.05,0.05,0.1> }}");
    for p in light_positions(c.lights) {
        let _ = writeln!(
            s,
            "light_source {{ <{},{},{}> color rgb <1,1,1> }}",
            p.x, p.y, p.z
        );
    }
    let tex = "texture { pigment { color rgb <0.8,0.3,0.3> } finish { ambient 0.03 diffuse 0.8 specular 0.6 roughness 0.02 reflection 0.3 } }";
    match c.kind {
        Kind::Spheres => {
            for p in sphere_centres(c.count) {
                let Some((ec, er)) = Point::from_coords(p)
                    .ok()
                    .and_then(|p| HSphere::new(p, SPHERE_RADIUS).ok())
                    .map(|s| s.euclidean())
                else {
                    continue;
                };
                let _ = writeln!(s, "sphere {{ <{},{},{}>, {er} {tex} }}", ec.x, ec.y, ec.z);
            }
        }
        Kind::Cylinders => {
            for (a, _) in cylinder_axes(c.count) {
                let mid = DVec3::new(a.x, 0.0, a.z);
                let gap = 1.0 - mid.length_squared();
                let er = (0.5 * CYLINDER_RADIUS).tanh() * gap;
                let _ = writeln!(
                    s,
                    "cylinder {{ <{},-1,{}>, <{},1,{}>, {er} {tex} }}",
                    a.x, a.z, a.x, a.z
                );
            }
        }
    }
    let _ = resolution;
    s
}
