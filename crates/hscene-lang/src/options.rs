//! What a compilation needs besides the source text.

/// What [`compile_with`] needs besides the source text.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// The directory that relative mesh file names are resolved from
    /// (normally the scene file's own); `None`: the current directory.
    pub base_dir: Option<std::path::PathBuf>,
    /// The animation frame to lower, 0-based (`frames = N` in `Globals`);
    /// past the last frame means the last. Every frame reports the same
    /// diagnostics except those about where things end up (lints on the
    /// final positions, numeric failures of the moves).
    pub frame: u32,
    /// The meshes and images read, shared with earlier compiles of the same
    /// scene (see [`FileCache`]); the default is a fresh one.
    pub files: crate::file_cache::FileCache,
    /// The scene's space given by the caller instead of by `space = ...`
    /// in the text (the Python binding's `Scene.from_str(text,
    /// space=...)`): the face pairings of a Dirichlet domain, Lorentz
    /// matrices with the time coordinate last, already checked as a gluing
    /// by [`hgeom::QuotientSpace::from_pairings`]. A text that names a
    /// space as well is refused (HSC0403 at its `space`).
    pub space: Option<std::sync::Arc<[hgeom::glam::DMat4]>>,
}
