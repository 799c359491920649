//! hrender's tests through its public interface.
//!
//! One test program for the package (one link, and every test scheduled
//! across the cores together): each module is one area, its own file.
//! Programs of their own: none. `.ci/test-targets`
//! checks that every file here is one or the other.

mod absorption;
mod aov;
mod area_lights;
mod closed_mirrors;
mod denoise;
mod depth_of_field;
mod far_isometries;
mod geometry;
mod horizon_fill;
mod horizon_sky;
mod image_textures;
mod light_strength;
mod many_lights;
mod mesh_lights;
mod mesh_smooth;
mod one_pixel;
mod optics;
mod path_tracer;
mod robustness;
mod sky;
mod space_fill;
mod spaces;
mod textures;
mod view_and_fog;
mod visible_lights;
