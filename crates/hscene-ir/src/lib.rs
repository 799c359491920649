//! # hscene-ir — the compiled scene
//!
//! What a scene is once its text is gone: hyperbolic data in Poincaré-ball
//! coordinates, every reference resolved, every transformation applied,
//! every default filled in. The scene language (`hscene-lang`) compiles
//! text to it; the renderer (`hrender`) traces it; neither needs the other.
//!
//! Also here, because both sides need them: the view geometry ([`view`]:
//! the camera's canonical frame, the window a field of view gives each
//! pixel net, a picture's pixel footprint), the limits every front end and
//! renderer agree on ([`limits`]), and the one colour type ([`Rgb`]).
//!
//! Invariants: the IR carries no source text and no spans; its types carry
//! their invariants (a [`Resolution`] is never zero, a [`MaterialId`] names
//! a material of its scene).

mod animation;
pub mod bounded_read;
mod camera;
mod chart;
mod color;
mod frame;
mod honeycomb;
mod integrator;
mod lens;
pub mod limits;
mod material;
mod object;
mod placement;
mod scene;
mod shape;
mod sky;
mod space;
mod texture_image;
pub mod view;

pub use animation::{Animation, FrameError, Motion, Track, TrackBase, compose, frame_time};
pub use camera::{Camera, Net, Resolution, Window, move_camera};
pub use chart::{TextureChart, disc_frame};
pub use color::Rgb;
pub use honeycomb::{Honeycomb, PartMaterials, palette_period};
pub use integrator::IntegratorKind;
pub use lens::{Lens, MAX_APERTURE, MAX_FOCUS, confusion_angle};
pub use material::{ImageTexture, Material, MaterialId, Pattern, Texture};
pub use object::{Object, move_object};
pub use placement::{first_too_far, light_in_frame, surely_traceable_near, traceable_in_frame};
pub use scene::{Fog, Light, PointRecord, Scene, Settings};
pub use shape::{BoxedSurface, MESH_TRIANGLES_PER_PRIMITIVE, Shape, Surfaces, mesh_budget_cost};
pub use sky::{Sky, equirectangular};
pub use space::{
    DEFAULT_LIGHT_REACH, DomainEdges, MAX_LIGHT_IMAGES, MAX_LIGHT_REACH, MAX_SPACE_CROSSINGS,
    MAX_SPACE_LIGHTS, Space,
};
pub use texture_image::{MAX_TEXTURE_PIXELS, TextureImage, TextureImageError, srgb_to_linear};
