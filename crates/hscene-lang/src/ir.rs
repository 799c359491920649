//! The typed intermediate representation: a fully resolved scene.
//!
//! Everything here is hyperbolic data in ball coordinates: every reference is
//! resolved, every transformation applied, every default filled in. The IR
//! carries no source text and no spans; the renderer needs nothing else.

use std::num::NonZeroU32;

use hgeom::{Isometry, Point, Vertex};

pub(crate) mod animation;
mod honeycomb;
mod shape;

pub use animation::{Animation, FrameError, Motion, Track, TrackBase, compose, frame_time};
pub use honeycomb::{Honeycomb, PartMaterials};
pub use shape::{BoxedSurface, MESH_TRIANGLES_PER_PRIMITIVE, Shape, Surfaces, mesh_budget_cost};

/// A linear RGB triple.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rgb {
    /// Red.
    pub r: f64,
    /// Green.
    pub g: f64,
    /// Blue.
    pub b: f64,
}

impl Rgb {
    /// Black.
    pub const BLACK: Rgb = Rgb::new(0.0, 0.0, 0.0);

    /// A colour from its components.
    pub const fn new(r: f64, g: f64, b: f64) -> Rgb {
        Rgb { r, g, b }
    }
}

/// The pixel net (docs/rendering.md, "The five pixel nets"), numbered as
/// in the thesis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Net {
    /// Net 0: the Euclidean grid on the plane `z = f` (a pinhole camera).
    Euclidean,
    /// Net 1: intersections of two pencils of hyperparallel h-lines.
    HyperparallelLines,
    /// Net 2: a Euclidean grid on the great disk, moved onto the view plane.
    GreatDisk,
    /// Net 3: nodes of two families of h-equidistant curves, one per pixel.
    Equidistant,
    /// Net 4: net 3 nodes, shown on the great disk by interpolation.
    EquidistantInterpolated,
}

impl Net {
    /// All nets, by index.
    pub const ALL: [Net; 5] = [
        Net::Euclidean,
        Net::HyperparallelLines,
        Net::GreatDisk,
        Net::Equidistant,
        Net::EquidistantInterpolated,
    ];

    /// The thesis's index `0..=4`.
    pub fn index(self) -> u8 {
        match self {
            Net::Euclidean => 0,
            Net::HyperparallelLines => 1,
            Net::GreatDisk => 2,
            Net::Equidistant => 3,
            Net::EquidistantInterpolated => 4,
        }
    }

    /// The net with the thesis's index.
    pub fn from_index(i: u64) -> Option<Net> {
        Net::ALL.get(usize::try_from(i).ok()?).copied()
    }
}

/// Image size in pixels, both sides at least 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resolution {
    width: NonZeroU32,
    height: NonZeroU32,
}

impl Resolution {
    /// `width` columns by `height` rows; `None` if either is 0.
    pub const fn new(width: u32, height: u32) -> Option<Resolution> {
        match (NonZeroU32::new(width), NonZeroU32::new(height)) {
            (Some(width), Some(height)) => Some(Resolution { width, height }),
            _ => None,
        }
    }

    /// Columns.
    pub const fn width(self) -> u32 {
        self.width.get()
    }

    /// Rows.
    pub const fn height(self) -> u32 {
        self.height.get()
    }
}

/// Size of the sampled window on the view plane (Euclidean units for nets 0,
/// 2 and 4, hyperbolic lengths for nets 1 and 3). Invariant: both positive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Horizontal extent.
    pub width: f64,
    /// Vertical extent.
    pub height: f64,
}

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
    /// centre only. Invariant: `1..=MAX_SAMPLES` of hscene-lang.
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

/// The observer.
///
/// Invariants: `target != eye`, and `up` (when given) does not lie on the
/// h-line through `eye` and `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The eye point.
    pub eye: Point,
    /// The view target: the view h-plane passes through it, orthogonal to the
    /// view direction.
    pub target: Point,
    /// A point towards which "up" points; `None` means the ball's `+y`
    /// direction at the eye.
    pub up: Option<Point>,
}

/// A Phong material (thesis Eq. 4/7 coefficients).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Optional name (`#glass`).
    pub name: Option<String>,
    /// Ambient reflectance per channel.
    pub ambient: Rgb,
    /// Diffuse reflectance per channel.
    pub diffuse: Rgb,
    /// Specular reflectance per channel.
    pub specular: Rgb,
    /// Mirror reflection coefficient `k_r` (the thesis's `alpha`).
    pub reflection: f64,
    /// Transmission coefficient `k_t` (the thesis's `trans`).
    pub transmission: f64,
    /// Phong exponent `n`.
    pub shininess: f64,
    /// Index of refraction.
    pub refraction: f64,
    /// A pattern that replaces the diffuse and ambient reflectances in part
    /// of the surface; `None` for a uniform material.
    pub texture: Option<Texture>,
}

impl Default for Material {
    /// Every field at the language's default: black, no mirror, opaque,
    /// shininess 1, refraction index 1, no texture.
    fn default() -> Material {
        Material {
            name: None,
            ambient: Rgb::BLACK,
            diffuse: Rgb::BLACK,
            specular: Rgb::BLACK,
            reflection: 0.0,
            transmission: 0.0,
            shininess: 1.0,
            refraction: 1.0,
            texture: None,
        }
    }
}

/// The pattern of a [`Texture`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pattern {
    /// A solid checker: the object's local space is cut into cells of side
    /// `scale` in Fermi coordinates (`hgeom::fermi_coordinates`), and the
    /// cells whose integer coordinates have an odd sum take the texture's
    /// colours.
    Checker,
}

/// A solid texture, fixed in its object's local space (placed in the world
/// by [`Object::placement`]), so it moves with the object.
///
/// Invariant: `scale` positive and finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texture {
    /// Which pattern.
    pub pattern: Pattern,
    /// The cell size: a hyperbolic length.
    pub scale: f64,
    /// Diffuse reflectance in the pattern's second colour.
    pub diffuse: Rgb,
    /// Ambient reflectance in the pattern's second colour.
    pub ambient: Rgb,
}

/// Index into [`Scene::materials`]. Made by the lowering for the materials
/// it declares, or by [`MaterialId::of`] for an index a material list has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MaterialId(usize);

impl MaterialId {
    /// The id of `materials[index]`; `None` if the list is shorter.
    pub fn of(materials: &[Material], index: usize) -> Option<MaterialId> {
        (index < materials.len()).then_some(MaterialId(index))
    }

    /// The id of the material declared `index`-th (from 0), for the
    /// lowering, which makes the list as it goes.
    pub(crate) fn declared(index: usize) -> MaterialId {
        MaterialId(index)
    }

    /// The position in [`Scene::materials`].
    pub fn index(self) -> usize {
        self.0
    }
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
}

/// A renderable object.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Geometry.
    pub shape: Shape,
    /// Surface material.
    pub material: MaterialId,
    /// The name of the statement that declared it (`ball: Sphere ...;`), if
    /// any. One statement can give several objects: a polyhedron with
    /// `edges = t` gives its faces and its edges (a wireframe), a
    /// tessellation one polyhedron per cell; they share the name.
    pub name: Option<String>,
    /// The object's placement: the isometry from its local space to the
    /// world. Textures are fixed in the local space. It is the identity for
    /// objects given by world points (polygons, planes, rods, cylinders,
    /// horospheres), the translation from the origin to the centre for a
    /// sphere, the `at` translation for figures and meshes (built about the
    /// origin), each followed by the object's own `@name` transformations.
    pub placement: Isometry,
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
    /// Materials, indexed by [`MaterialId`].
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
