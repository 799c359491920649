//! hexport's tests through its public interface.
//!
//! One test program for the package (one link, and every test scheduled
//! across the cores together): each module is one area, its own file.
//! Programs of their own: none. `.ci/test-targets`
//! checks that every file here is one or the other.

mod exact;
mod threemf;
