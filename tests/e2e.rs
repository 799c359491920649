//! The `hscene` binary's end-to-end tests.
//!
//! One test program for the package (one link, and every test scheduled
//! across the cores together): each module is one area, its own file.
//! Programs of their own: `docs`. `.ci/test-targets`
//! checks that every file here is one or the other.

mod cli;
mod cli_corpus;
mod colour_cli;
mod denoise_cli;
mod editor_cli;
mod editor_grammar;
mod emit_ir;
mod export_cli;
mod extensions_cli;
mod honeycomb;
mod hostile;
mod hostile_files;
mod hostile_round4;
mod limited_run;
mod lsp;
mod render_cli;
mod tiles;
mod video_cli;
mod view_headless;
mod view_x11;
