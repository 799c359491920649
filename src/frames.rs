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

/// Builds frames 1.. of `scene` (frame 0 is `scene`, which the compiler
/// checked) as the render loop will, and asks of each what the renderer asks before tracing (is every
/// object and light representable from the eye). The first failure is
/// reported with its location: the frame is compiled on its own (`compile`),
/// as `check --frame K` does, and its diagnostics shown.
pub fn check_every_frame(
    scene: &hscene_ir::Scene,
    frames: u32,
    compile: &dyn Fn(u32) -> hscene_lang::Compiled,
    show: &dyn Fn(&[hscene_lang::Diagnostic]),
) -> Result<(), ExitCode> {
    for k in 1..frames {
        let failure = if scene.animation.moves_points {
            let compiled = compile(k);
            match compiled.scene {
                Some(s) => hscene_ir::first_too_far(&s)
                    .map(|what| format!("{what} is too far from the eye")),
                None => {
                    diagln!("error: frame {k} of the animation has errors (nothing was written):");
                    show(&compiled.diagnostics);
                    return Err(ExitCode::from(EXIT_SCENE_ERRORS));
                }
            }
        } else {
            match scene.frame(k) {
                Ok(s) => hscene_ir::first_too_far(&s)
                    .map(|what| format!("{what} is too far from the eye")),
                Err(e) => Some(e.to_string()),
            }
        };
        let Some(failure) = failure else {
            continue;
        };
        diagln!("error: frame {k} of the animation cannot be rendered (nothing was written):");
        let compiled = compile(k);
        let errors: Vec<_> = compiled
            .diagnostics
            .into_iter()
            .filter(hscene_lang::Diagnostic::is_error)
            .collect();
        if errors.is_empty() {
            diagln!("error: {failure}");
        } else {
            show(&errors);
        }
        return Err(ExitCode::from(EXIT_SCENE_ERRORS));
    }
    Ok(())
}
