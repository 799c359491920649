//! `hscene check --emit ir`: the lowered scene as JSON.
//!
//! The schema is documented (and declared stable) in `docs/ir-schema.md`;
//! bump [`SCHEMA`] on any change that is not a pure addition. JSON lives in
//! the binary only: the libraries know nothing of serde.

use std::path::Path;

use hgeom::{BallShape, ConvexPolygon, Point, Rod, Vertex};
use hscene_ir::{Camera, Light, Material, Object, Rgb, Scene, Shape};
use serde_json::{Value, json};

/// The version of the IR schema.
pub const SCHEMA: u32 = 1;

/// Writes the whole scene as one JSON object and a newline, streamed: the
/// lists (points, materials, lights, objects) go out one element at a
/// time, so memory stays at one element's JSON however large the scene.
/// The keys come in sorted order, as in [`scene_to_json`], and the bytes
/// are the same as its serialisation.
pub fn write_scene_json(
    out: &mut impl std::io::Write,
    path: &Path,
    scene: &Scene,
) -> std::io::Result<()> {
    let mut out = std::io::BufWriter::new(out);
    let head = header(path, scene);
    let field = |out: &mut std::io::BufWriter<_>, key: &str, first: bool| -> std::io::Result<()> {
        out.write_all(if first { b"{" } else { b"," })?;
        serde_json::to_writer(&mut *out, key)?;
        out.write_all(b":")
    };
    use std::io::Write;
    field(&mut out, "camera", true)?;
    serde_json::to_writer(&mut out, &head["camera"])?;
    field(&mut out, "file", false)?;
    serde_json::to_writer(&mut out, &head["file"])?;
    field(&mut out, "frame", false)?;
    serde_json::to_writer(&mut out, &head["frame"])?;
    field(&mut out, "lights", false)?;
    list(
        &mut out,
        scene.lights.iter().enumerate().map(|(i, l)| light(i, l)),
    )?;
    field(&mut out, "materials", false)?;
    list(
        &mut out,
        scene
            .materials
            .iter()
            .enumerate()
            .map(|(i, m)| material(i, m)),
    )?;
    field(&mut out, "objects", false)?;
    list(
        &mut out,
        scene.objects.iter().enumerate().map(|(i, o)| object(i, o)),
    )?;
    field(&mut out, "points", false)?;
    list(&mut out, scene.points.iter().map(point_entry))?;
    field(&mut out, "schema", false)?;
    serde_json::to_writer(&mut out, &head["schema"])?;
    field(&mut out, "settings", false)?;
    serde_json::to_writer(&mut out, &head["settings"])?;
    out.write_all(b"}\n")?;
    out.flush()
}

/// A JSON array written element by element.
fn list(out: &mut impl std::io::Write, items: impl Iterator<Item = Value>) -> std::io::Result<()> {
    out.write_all(b"[")?;
    for (i, item) in items.enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        serde_json::to_writer(&mut *out, &item)?;
    }
    out.write_all(b"]")
}

/// The small, fixed-size part of the scene object.
fn header(path: &Path, scene: &Scene) -> Value {
    let s = &scene.settings;
    json!({
        "schema": SCHEMA,
        "file": path.display().to_string(),
        "settings": {
            "recursion_depth": s.recursion_depth,
            "resolution": [s.resolution.width(), s.resolution.height()],
            "window_size": [s.window.width, s.window.height],
            "net_type": s.net.index(),
            "background": rgb(s.background),
            "ambient": rgb(s.ambient),
            "samples": s.samples,
            "frames": s.frames,
            "fov": s.fov,
            "integrator": s.integrator.name(),
            "denoise": s.denoise,
            "sky": s.sky.as_ref().map(|sky| match sky {
                hscene_ir::Sky::Gradient { zenith, horizon } => json!({
                    "zenith": rgb(*zenith),
                    "horizon": rgb(*horizon),
                }),
                hscene_ir::Sky::Image(image) => json!({
                    "image": [image.width(), image.height()],
                }),
            }),
            "fog": s.fog.map(|f| json!({
                "color": rgb(f.color),
                "distance": f.distance,
            })),
            "aperture": s.lens.map_or(0.0, |l| l.aperture),
            "focus": s.lens.map(|l| l.focus),
            "space": s.space.as_ref().map(space),
        },
        "frame": scene.frame,
        "camera": camera(&scene.camera),
    })
}

/// The space: its name, its domain's face count and volume (hgeom's,
/// from the domain), the light reach and the domain's rods.
fn space(s: &hscene_ir::Space) -> Value {
    let built = s.build().ok();
    json!({
        "name": s.kind.to_string(),
        "pairings": s.pairings.as_ref().map(|p| p.len()),
        "faces": built.as_ref().map(|q| q.faces().len()),
        "volume": built.as_ref().and_then(|q| q.volume()),
        "light_reach": s.light_reach,
        "domain": s.domain.map(|d| json!({
            "width": d.width,
            "material": d.material.index() + 1,
        })),
    })
}

fn point_entry(p: &hscene_ir::PointRecord) -> Value {
    let (position, ideal) = match p.position {
        Vertex::Interior(q) => (q.coords(), false),
        Vertex::Ideal(q) => (q.coords(), true),
    };
    json!({
        "number": p.number,
        "name": p.name,
        "position": vec3(position),
        "ideal": ideal,
    })
}

/// The whole scene as one JSON value (tests compare the stream with it).
#[cfg(test)]
pub fn scene_to_json(path: &Path, scene: &Scene) -> Value {
    let mut v = header(path, scene);
    v["points"] = scene.points.iter().map(point_entry).collect();
    v["materials"] = scene
        .materials
        .iter()
        .enumerate()
        .map(|(i, m)| material(i, m))
        .collect();
    v["lights"] = scene
        .lights
        .iter()
        .enumerate()
        .map(|(i, l)| light(i, l))
        .collect();
    v["objects"] = scene
        .objects
        .iter()
        .enumerate()
        .map(|(i, o)| object(i, o))
        .collect();
    v
}

fn vec3(v: hgeom::glam::DVec3) -> Value {
    json!([v.x, v.y, v.z])
}

fn rgb(c: Rgb) -> Value {
    json!([c.r, c.g, c.b])
}

fn point(p: &Point) -> Value {
    vec3(p.coords())
}

fn vertex(v: &Vertex) -> Value {
    json!({ "position": vec3(v.coords()), "ideal": v.is_ideal() })
}

fn camera(c: &Camera) -> Value {
    json!({
        "from": point(&c.eye),
        "to": point(&c.target),
        "up": c.up.as_ref().map(point),
    })
}

fn material(i: usize, m: &Material) -> Value {
    json!({
        "number": i + 1,
        "name": m.name,
        "ambient": rgb(m.ambient),
        "diffuse": rgb(m.diffuse),
        "specular": rgb(m.specular),
        "alpha": m.reflection,
        "trans": m.transmission,
        "shininess": m.shininess,
        "refraction": m.refraction,
        "emission": rgb(m.emission),
        "absorption": rgb(m.absorption),
        "checker": m.texture.as_ref().map(|t| json!({
            "size": t.scale,
            "diffuse": rgb(t.diffuse),
            "ambient": rgb(t.ambient),
        })),
        "texture": m.image.as_ref().map(|t| json!({
            "file": t.path,
            "size": [t.image.width(), t.image.height()],
            "rotate": t.rotate,
        })),
    })
}

fn light(i: usize, l: &Light) -> Value {
    json!({
        "number": i + 1,
        "name": l.name,
        "position": point(&l.position),
        "diffuse": rgb(l.diffuse),
        "specular": rgb(l.specular),
        "radius": l.radius,
        "samples": l.samples,
    })
}

/// An isometry `x -> a (+) Q x`: the Möbius translation part `a` (where
/// the origin goes) and the rotation `Q`, row by row.
fn isometry(iso: &hgeom::Isometry) -> Value {
    let q = iso.linear_part().transpose();
    json!({
        "translation": point(&iso.translation_part()),
        "rotation": [vec3(q.x_axis), vec3(q.y_axis), vec3(q.z_axis)],
    })
}

fn polygon(p: &ConvexPolygon) -> Value {
    json!({ "vertices": p.vertices().iter().map(vertex).collect::<Vec<_>>() })
}

fn rod(r: &Rod) -> Value {
    json!({ "start": vertex(&r.start()), "end": vertex(&r.end()), "radius": r.radius() })
}

fn object(i: usize, o: &Object) -> Value {
    let mut v = json!({
        "number": i + 1,
        "name": o.name,
        "material": o.material.index() + 1,
        "frame": isometry(&o.placement),
    });
    let params = match &o.shape {
        Shape::Sphere(s) => {
            let (c, r) = s.euclidean();
            json!({
                "center": point(&s.center()),
                "radius": s.radius(),
                "euclidean": { "center": vec3(c), "radius": r },
            })
        }
        Shape::Polygon(p) => polygon(p),
        Shape::Polyhedron(p) => json!({
            "center": point(&p.center()),
            "faces": p.faces().iter().map(polygon).collect::<Vec<_>>(),
        }),
        Shape::Plane(p) => {
            let n = p.normal();
            let ball = match p.ball_shape() {
                BallShape::Flat { normal } => json!({ "shape": "flat", "normal": vec3(normal) }),
                BallShape::Sphere { center, radius } => {
                    json!({ "shape": "sphere", "center": vec3(center), "radius": radius })
                }
            };
            json!({ "normal": [n.x, n.y, n.z, n.w], "ball": ball })
        }
        Shape::Rod(r) => rod(r),
        Shape::Cylinder(c) => {
            let line = c.line();
            let (back, front) = line.ends();
            json!({
                "line": {
                    "base": point(&line.base()),
                    "ends": [vec3(back.coords()), vec3(front.coords())],
                },
                "radius": c.radius(),
            })
        }
        Shape::Horosphere(h) => {
            let (c, r) = h.euclidean();
            json!({
                "center": vec3(h.center().coords()),
                "euclidean": { "center": vec3(c), "radius": r },
            })
        }
        Shape::Wireframe(rods) => json!({ "rods": rods.iter().map(rod).collect::<Vec<_>>() }),
        Shape::Mesh(m) => json!({
            "vertices": m.vertices().iter().map(point).collect::<Vec<_>>(),
            "triangles": m.triangles().iter().map(|t| json!(t)).collect::<Vec<_>>(),
            "dropped_triangles": m.dropped_triangles(),
            "smooth": m.smooth_angle(),
        }),
        Shape::Honeycomb(h) => {
            let symbol = h.surface.symbol();
            let style = h.surface.style();
            json!({
                "symbol": [symbol.p(), symbol.q(), symbol.r()],
                "rings": h.surface.rings().nodes().collect::<Vec<_>>(),
                "base_center": point(&h.surface.base_cell_center()),
                "edges": style.edges,
                "vertices": style.vertices,
                "depth": style.depth,
                "face_material": h.materials.faces.map(|m| m.index() + 1),
                "colors": h.materials.palette.iter().map(|m| m.index() + 1).collect::<Vec<_>>(),
            })
        }
    };
    if let (Value::Object(out), Value::Object(params)) = (&mut v, params) {
        out.insert("kind".into(), Value::from(o.shape.kind_name()));
        out.extend(params);
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shape_kind_is_emitted() {
        let src = "\
Points { c = (0,0,0.3); a = (0.1,0,0.3); b = (0,0.1,0.3); i = (0,0,1); }
BRDFs { m: diffuse = (1,1,1); }
Lights { sun: %c, (1,1,1), (1,1,1); }
Objects {
  ball: Sphere %c, 0.05, #m;
  Polygon (%c, %a, %b), #1;
  Cube 0.2, #1, edges = 0.01;
  Plane %c, %a, %b, #1;
  Rod %a, %b, 0.01, #1;
  Cylinder %a, %i, 0.01, #1;
  Horosphere %i, %c, #1;
  Honeycomb {5,3,4}, #1, edges = 0.03, faces = #m, depth = 1, colors = (#1, #m), at = %c;
}";
        let compiled = hscene_lang::compile(src);
        assert!(!compiled.has_errors(), "{:#?}", compiled.diagnostics);
        let scene = compiled.scene.unwrap();
        let v = scene_to_json(Path::new("x.hsc"), &scene);
        let mut streamed = Vec::new();
        write_scene_json(&mut streamed, Path::new("x.hsc"), &scene).unwrap();
        assert_eq!(String::from_utf8(streamed).unwrap(), format!("{v}\n"));
        assert_eq!(v["schema"], 1);
        assert_eq!(v["points"][3]["ideal"], true);
        assert_eq!(v["points"][0]["name"], "c");
        assert_eq!(v["lights"][0]["name"], "sun");
        let kinds: Vec<&str> = v["objects"]
            .as_array()
            .unwrap()
            .iter()
            .map(|o| o["kind"].as_str().unwrap())
            .collect();
        assert_eq!(
            kinds,
            [
                "sphere",
                "polygon",
                "polyhedron",
                "wireframe",
                "plane",
                "rod",
                "cylinder",
                "horosphere",
                "honeycomb"
            ]
        );
        let h = &v["objects"][8];
        assert_eq!(h["symbol"], json!([5, 3, 4]));
        assert_eq!(h["rings"], json!([0]));
        assert_eq!(h["edges"], 0.03);
        assert_eq!(h["vertices"], Value::Null);
        assert_eq!(h["depth"], 1);
        assert_eq!(h["face_material"], 1);
        assert_eq!(h["colors"], json!([1, 1]));
        let z = h["base_center"][2].as_f64().unwrap();
        assert!((z - 0.3).abs() < 1e-15, "{}", h["base_center"]);
        assert_eq!(v["objects"][0]["name"], "ball");
        assert_eq!(v["objects"][0]["radius"], 0.05);
        assert_eq!(v["objects"][2]["faces"].as_array().unwrap().len(), 6);
        assert_eq!(v["objects"][3]["rods"].as_array().unwrap().len(), 12);
        assert_eq!(v["objects"][5]["end"]["ideal"], false);
        assert_eq!(v["camera"]["up"], Value::Null);
        assert_eq!(v["settings"]["resolution"], json!([512, 512]));
    }
}
