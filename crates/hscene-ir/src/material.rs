//! Materials: the thesis's Phong coefficients, textures, and the ids that
//! name a scene's materials.

use crate::color::Rgb;

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
    /// of the surface; `None` for a uniform material. Boxed, as is `image`:
    /// few materials have one, and inline the two made every material of a
    /// scene of many 280 bytes instead of 192 (docs/performance.md).
    pub texture: Option<Box<Texture>>,
    /// An image texture (`texture = "file.png"`): its texels replace the
    /// ambient and diffuse reflectances where it is mapped.
    pub image: Option<Box<ImageTexture>>,
    /// Radiance the surface emits, the same from both of its sides and in
    /// every direction (a Lambertian emitter): it makes the surface a light.
    pub emission: Rgb,
    /// Beer-Lambert absorption per unit of hyperbolic distance, per
    /// channel: light that travels `d` inside the object keeps
    /// `exp(-absorption d)` (tinted glass). Black: none.
    pub absorption: Rgb,
}

impl Material {
    /// True when the material (or its texture) reflects ambient light,
    /// which only Whitted's integrator has.
    pub fn reflects_ambient(&self) -> bool {
        !self.ambient.is_black() || self.texture.as_ref().is_some_and(|t| !t.ambient.is_black())
    }
}

impl Default for Material {
    /// Every field at the language's default: black, no mirror, opaque,
    /// shininess 1, refraction index 1, no texture, no emission.
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
            image: None,
            emission: Rgb::BLACK,
            absorption: Rgb::BLACK,
        }
    }
}

/// An image on a material (`texture = "file.png"`), mapped per surface
/// (docs/rendering.md, "Image textures"): an h-sphere by latitude and
/// longitude about its centre, an h-plane or polygon by the Poincaré-disc
/// coordinates of its plane.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageTexture {
    /// The file as written in the scene.
    pub path: String,
    /// Its texels, shared by every material that names the file.
    pub image: std::sync::Arc<crate::texture_image::TextureImage>,
    /// `texture_rotate`: a turn of the image about the mapping's centre
    /// (a longitude offset on a sphere), in radians.
    pub rotate: f64,
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
/// by [`Object::placement`](crate::Object::placement)), so it moves with the object.
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

/// Index into [`Scene::materials`](crate::Scene::materials). Made by a front end for the materials
/// it declares, or by [`MaterialId::of`] for an index a material list has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MaterialId(usize);

impl MaterialId {
    /// The id of `materials[index]`; `None` if the list is shorter.
    pub fn of(materials: &[Material], index: usize) -> Option<MaterialId> {
        (index < materials.len()).then_some(MaterialId(index))
    }

    /// The id of the material declared `index`-th (from 0), for a front
    /// end that makes the list as it goes (the scene language's lowering):
    /// it must push that material before the scene is used.
    pub fn declared(index: usize) -> MaterialId {
        MaterialId(index)
    }

    /// The position in [`Scene::materials`](crate::Scene::materials).
    pub fn index(self) -> usize {
        self.0
    }
}
