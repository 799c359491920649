//! hgeom's tests through its public interface.
//!
//! One test program for the package (one link, and every test scheduled
//! across the cores together): each module is one area, its own file.
//! Programs of their own: none. `.ci/test-targets`
//! checks that every file here is one or the other.

mod constructors;
mod derivations;
mod far;
mod figures;
mod honeycomb_walk;
mod mesh;
mod mesh_smooth;
mod properties;
mod reference;
mod serde;
mod snappy_census;
mod spaces;
mod stable_rays;
mod surfaces;
