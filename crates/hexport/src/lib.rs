//! Meshes of hyperbolic scenes as they sit in the Poincaré ball: the
//! surfaces of a scene's objects, computed exactly and triangulated within
//! a tolerance, scaled so the ball has a given diameter, for 3D printing
//! (STL, 3MF, in millimetres) and for Euclidean renderers (OBJ, glTF, in
//! metres). The user's guide is `docs/export.md`.
//!
//! - `options`: sizes, the minimum feature, the tolerance, cut or thicken.
//! - `grid`: every part is gridded as a surface between two poles, closed
//!   by construction; `model`: the shells and materials.
//! - `ball`, `tube`, `slab`, `triangles`: the exact surfaces of balls,
//!   tubes about geodesics, thickened plane pieces, mesh files.
//! - `rules`: the cut rule; `measure`: the Euclidean measures it uses;
//!   `honeycomb`: a honeycomb's explicit parts; `export`: a whole scene.
//! - `format`: STL, 3MF, OBJ and glTF encoders.

mod ball;
mod error;
mod export;
mod format;
mod grid;
mod honeycomb;
mod measure;
mod model;
mod options;
mod rules;
mod slab;
mod triangles;
mod tube;

pub use error::ExportError;
pub use export::{export_scene, object_label, object_name};
pub use format::{Format, OutputFile};
pub use honeycomb::MAX_CHAMBERS;
pub use model::{ExportMaterial, Model, Owner, Shell};
pub use options::{DEFAULT_MAX_TRIANGLES, ExportOptions, MAX_TRIANGLES, Millimetres, ThinParts};
pub use rules::THICKENED_MIN_LENGTH;
