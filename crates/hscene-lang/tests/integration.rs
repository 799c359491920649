//! The scene language's tests through its public interface.
//!
//! One test program for the package (one link, and every test scheduled
//! across the cores together): each module is one area, its own file.
//! Programs of their own: `golden`, `memory_fuzz`. `.ci/test-targets`
//! checks that every file here is one or the other.

mod animation;
mod corpus;
mod doc_examples;
mod format_scenes;
mod honeycomb;
mod lowering;
mod mesh_smooth;
mod objects;
mod scaling;
mod space_files;
mod spaces;
