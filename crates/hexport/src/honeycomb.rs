//! A honeycomb's parts as printed parts: its explicit vertices, edges and
//! faces (`hgeom`'s chamber search), searched out to the chambers that can
//! still hold something thick enough, each kept by the cut rule.
//!
//! The search goes on from a chamber while the chamber (a tetrahedron,
//! flat in the Klein model) meets the ball about the centre inside which a
//! part of the largest radius can still be thick enough
//! (`measure::thick_enough_radius`; the Klein radius of that ball is
//! `2ρ / (1 + ρ²)`); with thickened tubes, out to where tubes are cut
//! (twice the minimum from the boundary).

use hgeom::glam::DVec4;
use hgeom::{HLine, IdealPoint, Point, RegularHoneycomb, Vertex, lorentz};

use crate::error::ExportError;
use crate::measure::{distance_to_tetrahedron, klein_radius, thick_enough_radius};
use crate::options::{ExportOptions, ThinParts};
use crate::rules::{PartSurface, ball_about, polygon_plate, tube};
use crate::tube::Axis;

/// The most chambers a honeycomb's search visits.
pub const MAX_CHAMBERS: usize = 4_000_000;

/// A part of a honeycomb: its surface and the part code its material
/// follows ([`hgeom::Hit::part`]).
pub struct HoneycombPart {
    /// The printed surface.
    pub surface: PartSurface,
    /// The part code.
    pub part: u32,
}

/// A hyperboloid point or ideal point as a vertex.
pub fn vertex(x: DVec4) -> Option<Vertex> {
    if lorentz::dot(x, x) < -0.5 {
        Point::from_hyperboloid(x).map(Vertex::from)
    } else {
        IdealPoint::from_direction(x.truncate())
            .ok()
            .map(Vertex::from)
    }
}

/// The axis of the segment between two vertices (finite or ideal).
pub fn segment_axis(a: &Vertex, b: &Vertex) -> Option<Axis> {
    let line = HLine::through(a, b).ok()?;
    // The line's base point is `a` when finite, else `b` when finite,
    // else the point nearest the centre; it runs from a towards b.
    let (from, to) = match (a, b) {
        (Vertex::Interior(p), Vertex::Interior(q)) => (0.0, p.distance(*q)),
        (Vertex::Interior(_), _) => (0.0, f64::INFINITY),
        (_, Vertex::Interior(_)) => (f64::NEG_INFINITY, 0.0),
        _ => (f64::NEG_INFINITY, f64::INFINITY),
    };
    Some(Axis::of_line(&line, from, to))
}

/// The printed parts of a honeycomb.
pub fn parts(
    h: &RegularHoneycomb,
    options: &ExportOptions,
) -> Result<(Vec<HoneycombPart>, usize), ExportError> {
    let style = h.style();
    let m = options.min_feature_ball();
    let widest = [
        style.edges,
        style.vertices,
        style.faces.then_some(options.face_half_thickness),
    ]
    .into_iter()
    .flatten()
    .fold(0.0, f64::max);
    let mut rho = thick_enough_radius(widest, m);
    if options.thin == ThinParts::Thicken
        && let Some(w) = style.edges
    {
        // A kept thickened edge is at least THICKENED_MIN_LENGTH minimum
        // features long; an edge of hyperbolic length l is at most
        // 2 (1 - ρ) sinh(l) long at ρ (the bound of `measure`, for a ball
        // of radius l about its end), so none lies wholly beyond this.
        let edge = h.edge_length().unwrap_or(f64::INFINITY).min(20.0);
        let long_enough = 1.0 - crate::rules::THICKENED_MIN_LENGTH * m / (2.0 * edge.sinh());
        rho = rho
            .max(long_enough.min(1.0 - 2.0 * m))
            .max(thick_enough_radius(w, m));
    }
    if rho <= 0.0 {
        return Ok((Vec::new(), 0));
    }
    let reach = klein_radius(rho);
    let go_on = |corners: &[DVec4; 4]| {
        distance_to_tetrahedron(corners.map(|x| x.truncate() / x.w)) <= reach
    };
    let pieces = h
        .explicit_parts(go_on, MAX_CHAMBERS)
        .map_err(|source| ExportError::Geometry {
            object: String::new(),
            source,
        })?;
    let mut out = Vec::new();
    let mut cut = 0;
    let mut keep = |surface: Option<PartSurface>, part: u32| match surface {
        Some(surface) => out.push(HoneycombPart { surface, part }),
        None => cut += 1,
    };
    if let Some(r) = style.vertices {
        // A vertex ball printed where its edges are cut would float free:
        // with cut edges, a ball is kept only where an edge's tube at its
        // centre is thick enough too (so the edges reach it).
        let attached = match (style.edges, options.thin) {
            (Some(w), ThinParts::Cut) => Some(w.min(r)),
            _ => None,
        };
        for v in &pieces.vertices {
            let ball = ball_about(v.geometry, r, options)
                .filter(|_| attached.is_none_or(|w| ball_about(v.geometry, w, options).is_some()));
            keep(ball, v.part);
        }
    }
    if let Some(w) = style.edges {
        for e in &pieces.edges {
            let axis = match e.geometry.map(vertex) {
                [Some(a), Some(b)] => segment_axis(&a, &b),
                _ => None,
            };
            keep(axis.and_then(|a| tube(a, w, options)), e.part);
        }
    }
    for f in &pieces.faces {
        let normal = match f.geometry[..] {
            [a, b, c, ..] => lorentz::orthogonal_complement(a, b, c),
            _ => continue,
        };
        let n = lorentz::dot(normal, normal);
        let surface = (n > 0.0)
            .then(|| polygon_plate(&f.geometry, normal / n.sqrt(), options))
            .flatten();
        keep(surface, f.part);
    }
    Ok((out, cut))
}
