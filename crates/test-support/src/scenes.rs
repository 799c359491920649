//! Scene builders shared by the renderer's integration tests and examples.
//!
//! Scenes are built directly from the IR types, so the tests do not depend on
//! the concrete syntax of the scene language. Every builder panics on
//! invalid geometry, through [`fixture`](crate::fixture): its inputs are
//! the tests' own constants.

use hgeom::glam::{DMat3, DVec3};
use hgeom::{
    ConvexPolygon, HCylinder, HLine, HPlane, HSphere, Horosphere, IdealPoint, Isometry, Platonic,
    Point, Polyhedron, Rod, Vertex,
};
use hscene_lang::ir::{
    Camera, Light, Material, MaterialId, Net, Object, Pattern, Resolution, Rgb, Scene, Settings,
    Shape, Texture, Window,
};

use crate::SplitMix64;

/// Renders with `options`, checking that no pixel failed or is non-finite.
pub fn draw_with(scene: &Scene, options: &hrender::RenderOptions) -> hrender::Image {
    // A fixture that does not render stops the test with the renderer's error.
    let out = crate::fixture(hrender::render(scene, options, &|_| {}), "render");
    assert_eq!(out.stats.numeric_failures, 0);
    assert!(out.image.pixels().iter().flatten().all(|c| c.is_finite()));
    out.image
}

/// Renders with the default options (see [`draw_with`]).
pub fn draw(scene: &Scene) -> hrender::Image {
    draw_with(scene, &hrender::RenderOptions::default())
}

/// Fraction of pixels whose channels all agree within `tol`.
pub fn agreement(a: &hrender::Image, b: &hrender::Image, tol: f32) -> f64 {
    let good = a
        .pixels()
        .iter()
        .zip(b.pixels())
        .filter(|(p, q)| (0..3).all(|c| (p[c] - q[c]).abs() <= tol))
        .count();
    good as f64 / a.pixels().len() as f64
}

/// An h-point from ball coordinates.
pub fn p(x: f64, y: f64, z: f64) -> Point {
    // Cannot fail: callers pass literal coordinates inside the ball; a wrong literal is a bug in the test.
    crate::fixture(
        Point::from_coords(DVec3::new(x, y, z)),
        "test point inside the ball",
    )
}

/// An h-point at hyperbolic distance `d` from the origin in direction `dir`.
pub fn at(dir: DVec3, d: f64) -> Point {
    // Cannot fail: callers pass literal, moderate distances and non-zero directions.
    crate::fixture(Point::at_distance_from_origin(dir, d), "test point")
}

/// An ideal point in direction `dir`.
pub fn ideal(dir: DVec3) -> IdealPoint {
    // Cannot fail: callers pass literal non-zero directions.
    crate::fixture(IdealPoint::from_direction(dir), "test ideal point")
}

/// A Phong material with the same colour for ambient and diffuse.
pub fn matte(r: f64, g: f64, b: f64) -> Material {
    Material {
        name: None,
        ambient: Rgb::new(r, g, b),
        diffuse: Rgb::new(r, g, b),
        specular: Rgb::new(0.5, 0.5, 0.5),
        reflection: 0.0,
        transmission: 0.0,
        shininess: 20.0,
        refraction: 1.0,
        texture: None,
        image: None,
        emission: Rgb::BLACK,
        absorption: Rgb::BLACK,
    }
}

/// A material that only glows with its ambient colour (no lights needed).
pub fn flat(r: f64, g: f64, b: f64) -> Material {
    Material {
        ambient: Rgb::new(r, g, b),
        ..Material::default()
    }
}

/// Settings with the given net, resolution and (square) window.
pub fn settings(net: Net, size: u32, window: f64) -> Settings {
    Settings {
        recursion_depth: 1,
        // Cannot fail: test images are at least 1x1.
        resolution: crate::fixture(
            Resolution::new(size, size).ok_or("zero size"),
            "test resolution",
        ),
        window: Window {
            width: window,
            height: window,
        },
        net,
        background: Rgb::new(0.05, 0.05, 0.1),
        ambient: Rgb::new(0.2, 0.2, 0.2),
        samples: 1,
        frames: 1,
        fov: None,
        fog: None,
        integrator: Default::default(),
        sky: None,
        lens: None,
        space: None,
        denoise: false,
    }
}

/// The default camera: eye at the origin, looking along +z, up +y.
pub fn default_camera(view_distance: f64) -> Camera {
    Camera {
        eye: Point::ORIGIN,
        target: p(0.0, 0.0, view_distance),
        up: Some(p(0.0, 0.1, 0.0)),
    }
}

/// A white point light.
pub fn light(at: Point, intensity: f64) -> Light {
    Light {
        position: at,
        diffuse: Rgb::new(intensity, intensity, intensity),
        specular: Rgb::new(intensity, intensity, intensity),
        name: None,
        radius: 0.0,
        samples: 1,
        near: 0.0,
        on_camera: false,
    }
}

/// A white spherical area light of hyperbolic radius `radius` sampled by
/// `samples` shadow rays per shading point.
pub fn area_light(at: Point, intensity: f64, radius: f64, samples: u32) -> Light {
    Light {
        radius,
        samples,
        ..light(at, intensity)
    }
}

/// `material` with a checker texture of cell size `scale` whose odd cells
/// take `colour` as their ambient and diffuse reflectance.
pub fn checkered(material: Material, scale: f64, colour: Rgb) -> Material {
    Material {
        texture: Some(Box::new(Texture {
            pattern: Pattern::Checker,
            scale,
            diffuse: colour,
            ambient: colour,
        })),
        ..material
    }
}

/// An object of a test scene, its material given by its index in the
/// materials passed to [`scene`] (which makes the [`Object`]).
pub struct TestObject {
    shape: Shape,
    material: usize,
    placement: Isometry,
}

/// An object with material index `m` and placement `placement`.
pub fn obj_in(shape: Shape, m: usize, placement: Isometry) -> TestObject {
    TestObject {
        placement,
        ..obj(shape, m)
    }
}

/// An object with material index `m`.
pub fn obj(shape: Shape, m: usize) -> TestObject {
    TestObject {
        shape,
        material: m,
        placement: hgeom::Isometry::IDENTITY,
    }
}

/// A scene from parts.
pub fn scene(
    settings: Settings,
    camera: Camera,
    materials: Vec<Material>,
    lights: Vec<Light>,
    objects: Vec<TestObject>,
) -> Scene {
    let objects = objects
        .into_iter()
        .map(|o| Object {
            shape: o.shape,
            // Cannot fail: the fixture lists index their own material list.
            material: crate::fixture(
                MaterialId::of(&materials, o.material).ok_or("no such material"),
                "test material index",
            ),
            name: None,
            placement: o.placement,
        })
        .collect();
    Scene {
        settings,
        camera,
        materials,
        lights,
        objects,
        points: Vec::new(),
        frame: 0,
        animation: Default::default(),
    }
}

/// An h-sphere of centre `c` and hyperbolic radius `r`.
pub fn sphere(c: Point, r: f64) -> Shape {
    // Cannot fail: callers pass positive literal radii.
    Shape::Sphere(crate::fixture(HSphere::new(c, r), "test sphere"))
}

/// A rod of hyperbolic radius `r` from `a` to `b`.
pub fn rod(a: Point, b: Point, r: f64) -> Shape {
    // Cannot fail: callers pass distinct literal end points and a positive radius.
    Shape::Rod(Box::new(crate::fixture(
        Rod::new(a.into(), b.into(), r),
        "test rod",
    )))
}

/// The h-cylinder of hyperbolic radius `r` about the h-line through `a` and
/// `b`.
pub fn cylinder(a: Point, b: Point, r: f64) -> Shape {
    // Cannot fail: callers pass two distinct literal points.
    let line = crate::fixture(HLine::through(&a.into(), &b.into()), "test line");
    // Cannot fail: callers pass a positive literal radius.
    Shape::Cylinder(Box::new(crate::fixture(
        HCylinder::new(line, r),
        "test cylinder",
    )))
}

/// The convex polygon with vertices `vs`, in order.
pub fn polygon(vs: Vec<Vertex>) -> Shape {
    // Cannot fail: callers pass literal convex polygons.
    Shape::Polygon(Box::new(crate::fixture(
        ConvexPolygon::new(vs),
        "test polygon",
    )))
}

/// The mixed scene of the invariance tests: spheres, a polygon, a rod and a
/// cylinder, two lights, seen through a window of the given size.
pub fn mixed_scene(net: Net, size: u32, window: f64) -> Scene {
    let materials = vec![
        matte(0.8, 0.3, 0.2),
        matte(0.2, 0.7, 0.3),
        matte(0.3, 0.4, 0.9),
        Material {
            reflection: 0.5,
            ..matte(0.6, 0.6, 0.2)
        },
    ];
    let quad = polygon(vec![
        p(-0.25, -0.12, 0.5).into(),
        p(0.05, -0.12, 0.45).into(),
        p(0.05, 0.05, 0.45).into(),
        p(-0.25, 0.05, 0.5).into(),
    ]);
    let objects = vec![
        obj(sphere(p(0.1, 0.05, 0.4), 0.12), 0),
        obj(sphere(p(-0.12, -0.1, 0.3), 0.06), 3),
        obj(quad, 1),
        obj(rod(p(-0.2, 0.15, 0.35), p(0.15, 0.2, 0.5), 0.02), 2),
        obj(cylinder(p(-0.1, -0.2, 0.6), p(0.2, 0.0, 0.55), 0.03), 2),
    ];
    let lights = vec![light(p(0.0, 0.3, 0.1), 8.0), light(p(-0.3, -0.1, 0.2), 4.0)];
    let mut s = scene(
        settings(net, size, window),
        default_camera(0.1),
        materials,
        lights,
        objects,
    );
    s.settings.recursion_depth = 2;
    s
}

/// Apply one isometry to everything in a scene: camera (eye, target, up),
/// every object (its shape and its placement, so textures move with it)
/// and every light.
pub fn moved(scene: &Scene, iso: &Isometry) -> Scene {
    let mut s = scene.clone();
    // Cannot fail: every fixture scene sets an explicit up point.
    let up = crate::fixture(s.camera.up.ok_or("no up point"), "the camera's up point");
    s.camera.eye = iso.apply(&s.camera.eye);
    s.camera.target = iso.apply(&s.camera.target);
    s.camera.up = Some(iso.apply(&up));
    for l in &mut s.lights {
        l.position = iso.apply(&l.position);
    }
    for o in &mut s.objects {
        o.placement = iso.compose(&o.placement);
        o.shape = o.shape.transformed(iso);
    }
    s
}

/// A random isometry: a rotation (orientation-reversing when `mirror`)
/// followed by a transvection of hyperbolic length between `max_shift / 2`
/// and `max_shift`.
pub fn random_isometry(rng: &mut SplitMix64, max_shift: f64, mirror: bool) -> Isometry {
    let axis = rng.direction();
    let angle = rng.range(0.0, std::f64::consts::TAU);
    let mut q = DMat3::from_axis_angle(axis, angle);
    if mirror {
        q *= DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0));
    }
    let shift = at(rng.direction(), rng.range(0.5 * max_shift, max_shift));
    Isometry::transvection_from_origin(shift).compose(&Isometry::orthogonal_unchecked(q))
}

/// Many rods: `n` rods with random ends in a shell in front of the eye, as
/// separate objects, plus the same number again as one wireframe.
pub fn many_rods_scene(n: usize, size: u32) -> Scene {
    let mut rng = SplitMix64::new(7);
    let materials = vec![
        matte(0.9, 0.6, 0.2),
        matte(0.3, 0.6, 0.9),
        matte(0.7, 0.7, 0.7),
    ];
    let mut objects = Vec::new();
    let mut wire = Vec::new();
    for i in 0..2 * n {
        let centre = at(
            DVec3::new(rng.range(-0.6, 0.6), rng.range(-0.6, 0.6), 1.0),
            rng.range(0.6, 2.0),
        );
        let to_origin = Isometry::transvection_from_origin(centre);
        let a = to_origin.apply(&at(rng.direction(), rng.range(0.05, 0.25)));
        let b = to_origin.apply(&at(rng.direction(), rng.range(0.05, 0.25)));
        // Cannot fail: the two ends are drawn 0.05 to 0.25 from a point, in random directions: distinct to rounding far above f64's.
        let r = crate::fixture(Rod::new(a.into(), b.into(), 0.008), "random rod");
        if i < n {
            objects.push(obj(Shape::Rod(Box::new(r)), 0));
        } else {
            wire.push(r);
        }
    }
    objects.push(obj(Shape::Wireframe(wire.into()), 1));
    // A wall behind everything, to catch the shadows: the h-plane
    // orthogonal to the z axis at distance 2.3.
    // Cannot fail: two distinct points on the z axis.
    let wall = crate::fixture(
        HPlane::orthogonal_at(&at(DVec3::Z, 2.3), &at(DVec3::Z, 2.4)),
        "wall",
    );
    objects.push(obj(Shape::Plane(Box::new(wall)), 2));
    let lights = vec![
        light(at(DVec3::new(0.3, 1.0, 0.2), 0.8), 40.0),
        light(at(DVec3::new(-0.5, 0.2, 0.3), 0.5), 10.0),
    ];
    scene(
        settings(Net::Euclidean, size, 0.2),
        default_camera(0.1),
        materials,
        lights,
        objects,
    )
}

/// A dodecahedron, a wireframe cube and a horosphere: the kinds the other
/// builders do not cover.
pub fn solids_scene(net: Net, size: u32, window: f64) -> Scene {
    // Cannot fail: a Platonic solid of a positive literal circumradius.
    let dodeca = crate::fixture(
        Polyhedron::platonic(Platonic::Dodecahedron, 0.3),
        "dodecahedron",
    )
    .transformed(&Isometry::transvection_from_origin(p(-0.15, 0.0, 0.3)));
    // Cannot fail: a Platonic solid of a positive literal circumradius.
    let cube = crate::fixture(Polyhedron::platonic(Platonic::Cube, 0.25), "cube")
        .transformed(&Isometry::transvection_from_origin(p(0.15, 0.05, 0.3)));
    let mut edges = Vec::new();
    for f in cube.faces() {
        let vs = f.vertices();
        for i in 0..vs.len() {
            // Cannot fail: consecutive vertices of a valid face are distinct.
            edges.push(crate::fixture(
                Rod::new(vs[i], vs[(i + 1) % vs.len()], 0.01),
                "edge",
            ));
        }
    }
    // Cannot fail: a literal ideal point and a literal point inside the ball.
    let horo = crate::fixture(
        Horosphere::new(ideal(DVec3::new(0.0, -1.0, 0.3)), &p(0.0, -0.25, 0.35)),
        "horosphere",
    );
    let objects = vec![
        obj(Shape::Polyhedron(dodeca), 0),
        obj(Shape::Wireframe(edges.into()), 1),
        obj(Shape::Horosphere(horo), 2),
    ];
    scene(
        settings(net, size, window),
        default_camera(0.1),
        vec![
            matte(0.8, 0.4, 0.2),
            matte(0.9, 0.9, 0.3),
            matte(0.3, 0.5, 0.8),
        ],
        vec![light(p(0.0, 0.4, 0.1), 8.0)],
        objects,
    )
}

/// Many polyhedra, as the {4,3,5} tessellation will arrive: an
/// `n x n x n` block of small cubes, each its own object, in front of the eye.
pub fn many_cells_scene(n: usize, size: u32) -> Scene {
    let mut objects = Vec::new();
    // Cannot fail: a Platonic solid of a positive literal circumradius.
    let cube = crate::fixture(Polyhedron::platonic(Platonic::Cube, 0.08), "cube");
    let step = 0.16;
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                let off = |v: usize| (v as f64 - (n as f64 - 1.0) / 2.0) * step;
                let c = p(0.0, 0.0, 0.0);
                // Move along x, then y, then z by hyperbolic lengths: a
                // lattice of cells like a (non-tiling) honeycomb block.
                let t = Isometry::transvection_from_origin(at(
                    DVec3::Z,
                    0.9 + off(k) + step * n as f64 / 2.0,
                ))
                .compose(&Isometry::transvection_from_origin(
                    at(DVec3::Y, off(j).abs()).then_sign(off(j)),
                ))
                .compose(&Isometry::transvection_from_origin(
                    at(DVec3::X, off(i).abs()).then_sign(off(i)),
                ));
                let _ = c;
                objects.push(obj(
                    Shape::Polyhedron(cube.transformed(&t)),
                    (i + j + k) % 3,
                ));
            }
        }
    }
    scene(
        settings(Net::Euclidean, size, 0.2),
        default_camera(0.1),
        vec![
            matte(0.9, 0.5, 0.3),
            matte(0.4, 0.8, 0.5),
            matte(0.5, 0.6, 0.9),
        ],
        vec![
            light(p(0.1, 0.3, 0.05), 6.0),
            light(at(DVec3::new(-1.0, 0.5, 1.0), 1.2), 20.0),
        ],
        objects,
    )
}

/// Sign helper for lattice offsets.
trait ThenSign {
    fn then_sign(self, s: f64) -> Point;
}

impl ThenSign for Point {
    fn then_sign(self, s: f64) -> Point {
        if s < 0.0 {
            // Cannot fail: the mirror image of a ball point is a ball point.
            crate::fixture(Point::from_coords(-self.coords()), "mirror image")
        } else {
            self
        }
    }
}
