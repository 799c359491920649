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

use hgeom::glam::{DMat4, DVec3};
use hgeom::{Hit, Isometry};
use hscene_ir::{ImageTexture, Rgb, Shape, TextureChart, disc_frame, equirectangular};

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
        let chart = shape.transformed(&placement.inverse()).texture_chart()?;
        let (frame, kind) = match chart {
            TextureChart::Sphere { frame, sinh_radius } => (frame, MapKind::Sphere(sinh_radius)),
            TextureChart::Disc { frame } => (frame, MapKind::Disc),
            TextureChart::Flat { frame } => (frame, MapKind::Flat),
            TextureChart::Triangles(t) => (Isometry::IDENTITY, MapKind::Triangles(t)),
            TextureChart::Faces(h) => (Isometry::IDENTITY, MapKind::Faces(h)),
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

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec4;
    use hgeom::{Point, lorentz};

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
