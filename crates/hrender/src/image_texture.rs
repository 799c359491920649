//! Image textures: where a hit lands in its material's image, by a mapping
//! that means something in H³ and is fixed in the object's own space (so a
//! texture follows its object under every isometry).
//!
//! - **h-sphere**: latitude and longitude about its centre, in the axes of
//!   the object's space (`+y` the north pole, the image's middle column
//!   looking along `+z`), the equirectangular map of the sky
//!   ([`hscene_ir::equirectangular`]).
//! - **h-plane and polygon**: the Poincaré-disc coordinates of the plane in
//!   its own frame: the plane is moved, by the transvection along the
//!   perpendicular, so that its centre is at the origin, and turned so
//!   that its normal is `+z`; its points are then the disc `z = 0`, whose
//!   ball coordinates `(x, y)` are the Poincaré-disc model of the plane.
//!   The image's inscribed circle is that disc (`u = (1 + x)/2`,
//!   `v = (1 - y)/2`), so a tiling drawn in the disc lands on the plane as
//!   that exact tiling, its straight edges on the plane's geodesics. The
//!   centre is the foot of the perpendicular from the object's origin for
//!   a plane, the Klein-model centroid of the vertices for a polygon; the
//!   disc's `x` axis is the object's `+x` seen in the plane (or `+y` when
//!   `+x` is the plane's normal).
//! - **mesh**: each triangle by the barycentric coordinates of the hit in
//!   the Klein model (where the h-triangle is flat, so they are the
//!   geodesic ones): its first vertex at the image's lower left, the second
//!   at its lower right, the third at the top middle.
//! - **horosphere**: its flat (Euclidean) coordinates, the image repeated
//!   once per unit of flat length. The frame moves the horosphere's point
//!   nearest the object's origin to the origin (along the diameter to its
//!   centre `ξ`, which stays put) and turns `ξ` to `+y`; the horosphere is
//!   then `w - y = 1`, whose points `(s, y, t; w)` have `w + y = 1 + s² + t²`
//!   and the induced metric `ds² + dt²`: `(s, t)` are its flat coordinates.
//! - **honeycomb faces**: each face by the Poincaré-disc coordinates of its
//!   own plane about its centre (as a plane's, `x` axis the object's `+x`
//!   seen there), scaled so that the face's circumcircle fills the image's
//!   inscribed circle ([`hgeom::RegularHoneycomb::face_frame`]); edges and
//!   vertices show the material's own colours.
//! - Other surfaces (rods, cylinders) show the material's own colours.
//!
//! The texel's colour multiplies the material's ambient and diffuse
//! reflectances (white keeps the image's colours). The mipmap level
//! follows the pixel's footprint at the hit: a pixel `α` wide at the eye
//! spreads to `α sinh d` at distance `d`, over `W / (2π sinh r)` texels per
//! unit length round a sphere of radius `r`, `W (1 - |x|²) / 4` at the disc
//! point `x` (the Poincaré metric `2|dx| / (1 - |x|²)`).

use hgeom::glam::{DMat3, DMat4, DVec3, DVec4};
use hgeom::{Hit, Isometry, Point, Vertex, lorentz};
use hscene_ir::{ImageTexture, Rgb, Shape, equirectangular};

/// How an object's image texture is laid on it.
#[derive(Clone, Debug)]
pub struct TextureMapping {
    /// From the canonical frame to the mapping's frame (Lorentz matrix).
    to_frame: DMat4,
    kind: MapKind,
    /// The angle between neighbouring pixels at the eye.
    pixel_angle: f64,
}

#[derive(Clone, Debug)]
enum MapKind {
    /// Latitude and longitude about the origin of the frame; `sinh r`.
    Sphere(f64),
    /// The Poincaré disc `z = 0` of the frame.
    Disc,
    /// The horosphere `w - y = 1` of the frame, by its flat coordinates.
    Flat,
    /// A mesh's triangles, each by barycentric coordinates: the Klein
    /// coordinates of its vertices in the frame (the object's space).
    Triangles(std::sync::Arc<Vec<[DVec3; 3]>>),
    /// A regular honeycomb's faces, each in its own disc; the honeycomb in
    /// the frame (the object's space).
    Faces(Box<hgeom::RegularHoneycomb>),
}

impl TextureMapping {
    /// The mapping of `shape` (in the scene's frame) for an object whose
    /// own space is `to_local` away from the canonical frame, where
    /// `placement` put it; `None` for a shape that has none.
    pub fn of(
        shape: &Shape,
        placement: &Isometry,
        to_local: &Isometry,
        pixel_angle: f64,
    ) -> Option<TextureMapping> {
        let local = shape.transformed(&placement.inverse());
        let (frame, kind) = match &local {
            Shape::Sphere(s) => (
                Isometry::transvection_from_origin(s.center()).inverse(),
                MapKind::Sphere(s.radius().sinh()),
            ),
            Shape::Plane(p) => {
                let n = p.normal();
                let o = DVec4::W;
                let foot = o - lorentz::dot(o, n) * n;
                (disc_frame(foot, n)?, MapKind::Disc)
            }
            Shape::Polygon(p) => {
                let klein: Vec<DVec3> = p
                    .vertices()
                    .iter()
                    .map(|v| match v {
                        Vertex::Interior(q) => {
                            let x = q.to_hyperboloid();
                            x.truncate() / x.w
                        }
                        Vertex::Ideal(i) => i.coords(),
                    })
                    .collect();
                let mean = klein.iter().sum::<DVec3>() / klein.len().max(1) as f64;
                (
                    disc_frame(mean.extend(1.0), p.plane().normal())?,
                    MapKind::Disc,
                )
            }
            Shape::Horosphere(h) => {
                let xi = h.center().coords();
                let (_, r) = h.euclidean();
                let near = Point::from_coords(xi * (1.0 - 2.0 * r)).ok()?;
                let to_origin = Isometry::transvection_from_origin(near).inverse();
                let y = xi;
                let x = across(y, [DVec3::X, DVec3::Z])?;
                (
                    rotation(x, y, x.cross(y)).compose(&to_origin),
                    MapKind::Flat,
                )
            }
            Shape::Honeycomb(h) => (
                Isometry::IDENTITY,
                MapKind::Faces(Box::new(h.surface.clone())),
            ),
            Shape::Mesh(m) => {
                let vertices = m.vertices();
                let klein = |i: u32| {
                    let x = vertices[i as usize].to_hyperboloid();
                    x.truncate() / x.w
                };
                let triangles = m
                    .triangles()
                    .iter()
                    .map(|t| t.map(klein))
                    .collect::<Vec<_>>();
                (
                    Isometry::IDENTITY,
                    MapKind::Triangles(std::sync::Arc::new(triangles)),
                )
            }
            _ => return None,
        };
        Some(TextureMapping {
            to_frame: frame.compose(to_local).to_lorentz(),
            kind,
            pixel_angle,
        })
    }

    /// The ambient and diffuse reflectances of material colours `own` with
    /// the texture `t` at `hit`.
    pub fn colours(&self, t: &ImageTexture, own: (Rgb, Rgb), hit: &Hit) -> (Rgb, Rgb) {
        let q = self.to_frame * hit.point;
        let width = t.image.width() as f64;
        let spread = self.pixel_angle * hit.point.w.max(1.0).acosh().sinh();
        let (u, v, texels_per_length) = match &self.kind {
            MapKind::Faces(h) => {
                if hgeom::decode_honeycomb_part(hit.part).0 != hgeom::HoneycombPart::Face {
                    return own;
                }
                let Some(face) = h.face_frame(q) else {
                    return own;
                };
                let Some(frame) = disc_frame(face.centre, face.normal) else {
                    return own;
                };
                let p = frame.to_lorentz() * q;
                let b = p.truncate() / (1.0 + p.w);
                // The circumcircle's disc radius; 1 for ideal vertices.
                let fit = (face.circumradius / 2.0).tanh().max(1e-9);
                let (s, c) = t.rotate.sin_cos();
                let (x, y) = ((c * b.x + s * b.y) / fit, (-s * b.x + c * b.y) / fit);
                let gap = (1.0 - b.x * b.x - b.y * b.y).max(0.0);
                (0.5 + 0.5 * x, 0.5 - 0.5 * y, width * gap / (4.0 * fit))
            }
            MapKind::Triangles(triangles) => {
                let Some(&[a, b, c]) = triangles.get(hit.part as usize) else {
                    return own;
                };
                let k = q.truncate() / q.w;
                let n = (b - a).cross(c - a);
                let n2 = n.length_squared();
                if !(n2 > 0.0) {
                    return own;
                }
                let wb = (k - a).cross(c - a).dot(n) / n2;
                let wc = (b - a).cross(k - a).dot(n) / n2;
                // Klein lengths near the triangle are its size's scale.
                let size = (b - a).length().max((c - a).length()).max(1e-12);
                (wb + 0.5 * wc, 1.0 - wc, width / size)
            }
            MapKind::Flat => {
                let (fs, ft) = (q.x, q.z);
                let (sn, cs) = t.rotate.sin_cos();
                let (a, b) = (cs * fs + sn * ft, -sn * fs + cs * ft);
                (a.rem_euclid(1.0), b.rem_euclid(1.0), width)
            }
            &MapKind::Sphere(sinh_r) => {
                let d = q.truncate();
                let len = d.length();
                if !(len > 0.0 && len.is_finite()) {
                    return own;
                }
                let (u, v) = equirectangular(d / len);
                let u = u + t.rotate / std::f64::consts::TAU;
                (u, v, width / (std::f64::consts::TAU * sinh_r))
            }
            MapKind::Disc => {
                let b = q.truncate() / (1.0 + q.w);
                let (s, c) = t.rotate.sin_cos();
                let (x, y) = (c * b.x + s * b.y, -s * b.x + c * b.y);
                let gap = (1.0 - b.x * b.x - b.y * b.y).max(0.0);
                (0.5 + 0.5 * x, 0.5 - 0.5 * y, width * gap / 4.0)
            }
        };
        let [r, g, b] = t.image.sample(u, v, spread * texels_per_length);
        let texel = Rgb::new(r, g, b);
        (own.0.tint(texel), own.1.tint(texel))
    }
}

/// The isometry that takes the plane of Lorentz normal `n` to the plane
/// `z = 0` through the origin, its point `centre` (any positive multiple of
/// a point of the plane, or of the Klein model's `(k, 1)`) to the origin;
/// `None` for a degenerate plane.
fn disc_frame(centre: DVec4, n: DVec4) -> Option<Isometry> {
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

    /// A horosphere's frame takes it to `w - y = 1`, and its flat
    /// coordinates `(s, t)` measure it: points of the horosphere met by
    /// rays from the origin are `d` apart with `cosh d = 1 + |Δ(s, t)|² / 2`
    /// (the chord of a horosphere).
    #[test]
    fn horosphere_frames_give_flat_coordinates() {
        use hgeom::{Horosphere, IdealPoint, Ray};
        let xi = IdealPoint::from_direction(DVec3::new(0.3, -1.0, 0.4)).unwrap();
        let h = Horosphere::new(xi, &Point::new(0.1, -0.3, 0.2).unwrap()).unwrap();
        let mapping = TextureMapping::of(
            &Shape::Horosphere(h),
            &Isometry::IDENTITY,
            &Isometry::IDENTITY,
            0.0,
        )
        .unwrap();
        let points: Vec<DVec4> = [
            DVec3::new(0.2, -1.0, 0.3),
            DVec3::new(0.5, -1.0, 0.1),
            DVec3::new(0.1, -1.0, 0.7),
            DVec3::new(0.4, -0.8, 0.5),
        ]
        .iter()
        .map(|d| {
            let ray = Ray::from_origin_unchecked(d.normalize());
            h.intersect(&ray, 0.0, f64::INFINITY).unwrap().point
        })
        .collect();
        let flat: Vec<DVec4> = points.iter().map(|x| mapping.to_frame * *x).collect();
        for q in &flat {
            assert!((q.w - q.y - 1.0).abs() < 1e-9, "{q}");
        }
        for i in 0..points.len() {
            for j in 0..i {
                let cosh_d = -lorentz::dot(points[i], points[j]);
                let (ds, dt) = (flat[i].x - flat[j].x, flat[i].z - flat[j].z);
                let chord = 1.0 + (ds * ds + dt * dt) / 2.0;
                assert!((cosh_d - chord).abs() < 1e-9 * cosh_d, "{cosh_d} {chord}");
            }
        }
    }
}
