//! The frames of an animation: their file names, and the check that every
//! frame can be rendered, made before the first is written, so that a run
//! never leaves frames 0-2 and then fails at frame 3.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::exit::EXIT_SCENE_ERRORS;

/// `out.png` -> `out-0007.png` for frame 7 (at least four digits).
pub fn frame_path(output: &Path, frame: u32) -> PathBuf {
    let stem = output
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = match output.extension() {
        Some(ext) => format!("{stem}-{frame:04}.{}", ext.to_string_lossy()),
        None => format!("{stem}-{frame:04}"),
    };
    output.with_file_name(name)
}

/// The message for a frame number past the animation's end.
pub fn frame_past_end(k: u32, frames: u32) -> String {
    format!(
        "--frame {k} is past the scene's last frame ({} of `frames = {frames}`, counted from 0)",
        frames.saturating_sub(1)
    )
}

/// The most objects (summed over frames) that the check keeps built for
/// the render loop: about 1 KiB an object, so the frames kept hold at most
/// some 200 MiB; past it a frame is built again when its turn comes
/// (docs/limits.md).
pub const KEPT_OBJECT_FRAMES: usize = 200_000;

/// Frames 1.. of an animation: built by the check before the first frame is
/// written, and kept for the render loop so that no frame is built twice,
/// as far as [`KEPT_OBJECT_FRAMES`] allows; a frame not kept is built again
/// when its turn comes.
pub struct LaterFrames<'a> {
    kept: Vec<Option<hscene_ir::Scene>>,
    objects: usize,
    /// Compiles frame `k` on its own from the source, as `check --frame K`
    /// does.
    compile: &'a dyn Fn(u32) -> hscene_lang::Compiled,
    /// Shows diagnostics.
    show: &'a dyn Fn(&[hscene_lang::Diagnostic]),
}

impl<'a> LaterFrames<'a> {
    /// None built yet.
    pub fn new(
        compile: &'a dyn Fn(u32) -> hscene_lang::Compiled,
        show: &'a dyn Fn(&[hscene_lang::Diagnostic]),
    ) -> LaterFrames<'a> {
        LaterFrames {
            kept: Vec::new(),
            objects: 0,
            compile,
            show,
        }
    }

    fn keep(&mut self, k: u32, scene: hscene_ir::Scene) {
        let k = k as usize;
        if self.kept.len() <= k {
            self.kept.resize_with(k + 1, || None);
        }
        let objects = scene.objects.len() + scene.lights.len() + 1;
        if self.objects + objects <= KEPT_OBJECT_FRAMES {
            self.objects += objects;
            self.kept[k] = Some(scene);
        }
    }

    /// Frame `k` (1..) of `scene`, built as the render loop builds it: from
    /// the compiled animation, or compiled from the source when the
    /// animation moves points. A compile's errors are shown here (and the
    /// error is empty); a frame the animation cannot build says why.
    /// `checking`: before the first frame is written (the error says
    /// nothing was).
    fn build(
        &self,
        scene: &hscene_ir::Scene,
        k: u32,
        checking: bool,
    ) -> Result<hscene_ir::Scene, String> {
        if !scene.animation.moves_points {
            return scene.frame(k).map_err(|e| e.to_string());
        }
        let compiled = (self.compile)(k);
        match compiled.scene {
            Some(s) => Ok(s),
            None => {
                let nothing = if checking {
                    " (nothing was written)"
                } else {
                    ""
                };
                diagln!("error: frame {k} of the animation has errors{nothing}:");
                (self.show)(&compiled.diagnostics);
                Err(String::new())
            }
        }
    }

    /// Frame `k` (1..) for the render loop: the one the check kept, else
    /// built again.
    pub fn take(&mut self, scene: &hscene_ir::Scene, k: u32) -> Result<hscene_ir::Scene, ExitCode> {
        if let Some(s) = self.kept.get_mut(k as usize).and_then(Option::take) {
            return Ok(s);
        }
        self.build(scene, k, false).map_err(|e| {
            if !e.is_empty() {
                diagln!("error: {e}");
            }
            ExitCode::from(EXIT_SCENE_ERRORS)
        })
    }

    /// Builds frames 1.. of `scene` (frame 0 is `scene`, which the
    /// compiler checked) and asks of each what the renderer asks before
    /// tracing (is every object and light representable from the eye). The
    /// first failure is reported with its location: the frame is compiled
    /// on its own, as `check --frame K` does, and its diagnostics shown.
    /// The frames built are kept for [`LaterFrames::take`].
    pub fn check_every_frame(
        &mut self,
        scene: &hscene_ir::Scene,
        frames: u32,
    ) -> Result<(), ExitCode> {
        for k in 1..frames {
            let failure = match self.build(scene, k, true) {
                Ok(s) => match hscene_ir::first_too_far(&s) {
                    Some(what) => format!("{what} is too far from the eye"),
                    None => {
                        self.keep(k, s);
                        continue;
                    }
                },
                // Already shown.
                Err(e) if e.is_empty() => return Err(ExitCode::from(EXIT_SCENE_ERRORS)),
                Err(e) => e,
            };
            diagln!("error: frame {k} of the animation cannot be rendered (nothing was written):");
            let compiled = (self.compile)(k);
            let errors: Vec<_> = compiled
                .diagnostics
                .into_iter()
                .filter(hscene_lang::Diagnostic::is_error)
                .collect();
            if errors.is_empty() {
                diagln!("error: {failure}");
            } else {
                (self.show)(&errors);
            }
            return Err(ExitCode::from(EXIT_SCENE_ERRORS));
        }
        Ok(())
    }
}
