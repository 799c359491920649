//! Texture charts: the coordinates an image is laid on a surface by, one
//! kind per shape, fixed in the shape's own space (derived in
//! docs/rendering.md, "Image textures"). The renderer looks images up
//! through a chart and names no kind of shape.

use std::sync::Arc;

use hgeom::glam::{DMat3, DVec3, DVec4};
use hgeom::{Isometry, Point, RegularHoneycomb, Vertex, lorentz};

use crate::shape::Shape;

/// How an image is laid on a shape (in the shape's own coordinates).
#[derive(Clone, Debug)]
pub enum TextureChart {
    /// Latitude and longitude about the origin of `frame`'s image (the
    /// sphere's centre moved to the origin); `sinh_radius` of the sphere.
    Sphere {
        /// To the sphere's frame.
        frame: Isometry,
        /// `sinh` of its radius.
        sinh_radius: f64,
    },
    /// The Poincaré disc `z = 0` of `frame`'s image (the plane moved onto
    /// it, its centre at the origin).
    Disc {
        /// To the plane's frame.
        frame: Isometry,
    },
    /// The flat coordinates `(x, z)` of the horosphere `w - y = 1` that
    /// `frame` moves it onto.
    Flat {
        /// To the horosphere's frame.
        frame: Isometry,
    },
    /// A mesh's triangles, each by barycentric coordinates: the Klein
    /// coordinates of their vertices.
    Triangles(Arc<Vec<[DVec3; 3]>>),
    /// A regular honeycomb's faces, each in its own disc
    /// ([`RegularHoneycomb::face_frame`], [`disc_frame`]).
    Faces(Box<RegularHoneycomb>),
}

impl Shape {
    /// The chart an image texture is laid on this shape by; `None` for
    /// rods, cylinders and wireframes (they keep their material's colours).
    pub fn texture_chart(&self) -> Option<TextureChart> {
        match self {
            Shape::Sphere(s) => Some(TextureChart::Sphere {
                frame: Isometry::transvection_from_origin(s.center()).inverse(),
                sinh_radius: s.radius().sinh(),
            }),
            Shape::Plane(p) => {
                let n = p.normal();
                let foot = DVec4::W - lorentz::dot(DVec4::W, n) * n;
                Some(TextureChart::Disc {
                    frame: disc_frame(foot, n)?,
                })
            }
            Shape::Polygon(p) => {
                let klein: Vec<DVec3> = p.vertices().iter().map(klein_of).collect();
                let mean = klein.iter().sum::<DVec3>() / klein.len().max(1) as f64;
                Some(TextureChart::Disc {
                    frame: disc_frame(mean.extend(1.0), p.plane().normal())?,
                })
            }
            Shape::Horosphere(h) => {
                let xi = h.center().coords();
                let (_, r) = h.euclidean();
                let near = Point::from_coords(xi * (1.0 - 2.0 * r)).ok()?;
                let to_origin = Isometry::transvection_from_origin(near).inverse();
                let x = across(xi, [DVec3::X, DVec3::Z])?;
                Some(TextureChart::Flat {
                    frame: rotation(x, xi, x.cross(xi)).compose(&to_origin),
                })
            }
            Shape::Mesh(m) => {
                let vertices = m.vertices();
                let klein = |i: u32| klein_of(&Vertex::Interior(vertices[i as usize]));
                let triangles = m.triangles().iter().map(|t| t.map(klein)).collect();
                Some(TextureChart::Triangles(Arc::new(triangles)))
            }
            Shape::Honeycomb(h) => Some(TextureChart::Faces(Box::new(h.surface.clone()))),
            Shape::Polyhedron(_) | Shape::Rod(_) | Shape::Cylinder(_) | Shape::Wireframe(_) => None,
        }
    }
}

/// The Klein coordinates of a vertex (an ideal one is its direction).
fn klein_of(v: &Vertex) -> DVec3 {
    match v {
        Vertex::Interior(q) => {
            let x = q.to_hyperboloid();
            x.truncate() / x.w
        }
        Vertex::Ideal(i) => i.coords(),
    }
}

/// The isometry that takes the plane of Lorentz normal `n` to the plane
/// `z = 0` through the origin, its point `centre` (any positive multiple of
/// a point of the plane, or of the Klein model's `(k, 1)`) to the origin;
/// the disc's `x` axis is `+x` seen in the plane (`+y` when `+x` is its
/// normal). `None` for a degenerate plane.
pub fn disc_frame(centre: DVec4, n: DVec4) -> Option<Isometry> {
    let norm2 = -lorentz::dot(centre, centre);
    if !(norm2 > 0.0 && norm2.is_finite()) {
        return None;
    }
    let c = centre / norm2.sqrt();
    let to_origin = Isometry::transvection_from_origin(Point::from_hyperboloid(c)?).inverse();
    let v = (to_origin.to_lorentz() * n).truncate();
    let z = v.try_normalize()?;
    let x = across(z, [DVec3::X, DVec3::Y])?;
    Some(rotation(x, z.cross(x), z).compose(&to_origin))
}

/// The first of `candidates` with its part along the unit `axis` taken
/// out, normalised: the frame's `x` axis, orthogonal to `axis`.
fn across(axis: DVec3, candidates: [DVec3; 2]) -> Option<DVec3> {
    candidates
        .into_iter()
        .map(|a| a - a.dot(axis) * axis)
        .find(|a| a.length() > 1e-6)
        .map(DVec3::normalize)
}

/// The rotation taking the orthonormal `x`, `y`, `z` to the coordinate
/// axes.
fn rotation(x: DVec3, y: DVec3, z: DVec3) -> Isometry {
    Isometry::orthogonal_unchecked(DMat3::from_cols(x, y, z).transpose())
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::HPlane;

    /// A plane's frame puts its foot at the origin and its points on
    /// `z = 0`.
    #[test]
    fn disc_frames_flatten_their_plane() {
        let a = Vertex::Interior(Point::new(0.1, 0.5, 0.2).unwrap());
        let b = Vertex::Interior(Point::new(-0.3, 0.4, 0.1).unwrap());
        let c = Vertex::Interior(Point::new(0.2, 0.45, -0.4).unwrap());
        let plane = HPlane::through(&a, &b, &c).unwrap();
        let n = plane.normal();
        let foot = DVec4::W - lorentz::dot(DVec4::W, n) * n;
        let frame = disc_frame(foot, n).unwrap().to_lorentz();
        for v in [a, b, c] {
            let Vertex::Interior(p) = v else {
                unreachable!()
            };
            let q = frame * p.to_hyperboloid();
            assert!(q.z.abs() < 1e-12, "{q}");
        }
        let f = frame * (foot / (-lorentz::dot(foot, foot)).sqrt());
        assert!((f - DVec4::W).length() < 1e-12, "{f}");
    }
}
