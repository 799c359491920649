//! A fully resolved scene: its settings, lights and the lists of camera,
//! materials and objects.

use hgeom::{Point, Vertex};

use crate::animation::Animation;
use crate::camera::{Camera, Net, Resolution, Window};
use crate::color::Rgb;
use crate::integrator::IntegratorKind;
use crate::lens::Lens;
use crate::material::Material;
use crate::object::Object;
use crate::sky::Sky;

/// Global render settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Maximum number of reflection/refraction bounces.
    pub recursion_depth: u32,
    /// Output size.
    pub resolution: Resolution,
    /// Window on the view plane.
    pub window: Window,
    /// Pixel net.
    pub net: Net,
    /// Colour of rays that leave the scene.
    pub background: Rgb,
    /// Ambient light intensity `I_a`.
    pub ambient: Rgb,
    /// Anti-aliasing: samples per pixel (`samples = N`), 1 for the pixel
    /// centre only. Invariant: `1..=`[`MAX_SAMPLES`](crate::limits::MAX_SAMPLES).
    pub samples: u32,
    /// Number of animation frames (`frames = N`); 1 for a still scene.
    /// Invariant: at least 1.
    pub frames: u32,
    /// Horizontal field of view in degrees (`fov = DEGREES`); when set it
    /// replaces `window`, which the renderer then derives for the net and
    /// resolution it uses ([`crate::view::fov_window`]). Invariant: in
    /// `(0, 180)`.
    pub fov: Option<f64>,
    /// Fog (`fog_distance = D`, `fog_color`), if any.
    pub fog: Option<Fog>,
    /// How light is computed (`integrator = NAME;`).
    pub integrator: IntegratorKind,
    /// Light from the sphere at infinity for rays that meet nothing
    /// (`sky = (zenith, horizon)`); `None`: the background colour.
    pub sky: Option<Sky>,
    /// Depth of field (`aperture = A; focus = D;`): a thin lens at the eye;
    /// `None`: a pinhole.
    pub lens: Option<Lens>,
    /// The space the scene is in (`space = NAME;`); `None`: H³.
    pub space: Option<crate::space::Space>,
    /// Denoise the finished picture (`denoise = true;`, `render
    /// --denoise`): Intel Open Image Denoise guided by the first hit's
    /// albedo and normal, where the library is installed.
    pub denoise: bool,
}

/// Fog: the radiance carried along a ray segment of hyperbolic length `s`
/// is mixed towards `color` with weight `1 - exp(-s / distance)`; a ray that
/// leaves the scene takes `color`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    /// The colour far things fade to.
    pub color: Rgb,
    /// The hyperbolic length over which radiance keeps `1/e` of itself.
    /// Invariant: positive and finite.
    pub distance: f64,
}

/// A point light.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Position.
    pub position: Point,
    /// Diffuse intensity per channel.
    pub diffuse: Rgb,
    /// Specular intensity per channel.
    pub specular: Rgb,
    /// The light's name (`sun: %1, ...;`), if it has one.
    pub name: Option<String>,
    /// Hyperbolic radius of a spherical area light (`radius = r`); 0 for a
    /// point light. Invariant: finite and non-negative.
    pub radius: f64,
    /// Shadow rays per shading point for an area light (`samples = n`);
    /// 1 for a point light. Invariant: at least 1.
    pub samples: u32,
    /// `near = D`: nearer than this hyperbolic distance the light's
    /// fall-off stops growing (a surface there receives what it would at
    /// `D`); 0 for none. Invariant: finite and non-negative.
    pub near: f64,
    /// The light is at the eye wherever the camera goes (`camera` as its
    /// position); `position` is then the camera's eye.
    pub on_camera: bool,
}

/// The final position of a declared point, for inspection (`--emit ir`).
#[derive(Clone, Debug, PartialEq)]
pub struct PointRecord {
    /// 1-based number in declaration order.
    pub number: usize,
    /// Name, if declared with one.
    pub name: Option<String>,
    /// Final position after all transformations: an h-point, or an ideal
    /// point on the absolute.
    pub position: Vertex,
}

/// A fully resolved scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Global settings.
    pub settings: Settings,
    /// The observer.
    pub camera: Camera,
    /// Materials, indexed by [`MaterialId`](crate::MaterialId).
    pub materials: Vec<Material>,
    /// Point lights.
    pub lights: Vec<Light>,
    /// Objects.
    pub objects: Vec<Object>,
    /// Every declared point with its final position.
    pub points: Vec<PointRecord>,
    /// Which animation frame this is (0-based, below `settings.frames`).
    pub frame: u32,
    /// What moves from frame to frame: [`Scene::frame`] gives any frame
    /// of the animation from this one.
    pub animation: Animation,
}

impl Scene {
    /// True when the ambient term lights something: a non-black global
    /// `ambient` and a material (or its texture) that reflects it. The path
    /// integrator has no ambient term, so such a scene looks different
    /// there.
    pub fn reflects_ambient(&self) -> bool {
        !self.settings.ambient.is_black() && self.materials.iter().any(Material::reflects_ambient)
    }
}
