//! Any frame of an animation, from the compiled scene.

use crate::animation::{FrameError, TrackBase, compose, frame_time};
use crate::camera::move_camera;
use crate::object::move_object;
use crate::scene::Scene;

impl Scene {
    /// The scene in animation frame `k` (0-based, below `settings.frames`),
    /// from this compiled scene, whichever frame it was compiled for: the
    /// tracks' motions at frame `k`'s time applied to their targets.
    pub fn frame(&self, k: u32) -> Result<Scene, FrameError> {
        let frames = self.settings.frames;
        if k >= frames {
            return Err(FrameError::PastEnd {
                frame: k,
                last: frames.saturating_sub(1),
            });
        }
        if self.animation.moves_points && k != self.frame {
            return Err(FrameError::NeedsSource { frame: k });
        }
        let time = frame_time(k, frames);
        let mut scene = self.clone();
        scene.frame = k;
        for track in &self.animation.tracks {
            let out_of_range = |what: String| FrameError::OutOfRange { frame: k, what };
            let base_name = match &track.base {
                TrackBase::Objects { indices, .. } => {
                    format!("object {}", indices.first().map_or(0, |i| i + 1))
                }
                TrackBase::Light { index, .. } => format!("light {}", index + 1),
                TrackBase::Camera(_) => "the camera".to_string(),
            };
            let iso = compose(&track.motions, time).map_err(|_| out_of_range(base_name.clone()))?;
            match &track.base {
                TrackBase::Objects { indices, objects } => {
                    for (&i, base) in indices.iter().zip(objects) {
                        let moved = move_object(base, &iso)
                            .ok_or_else(|| out_of_range(format!("object {}", i + 1)))?;
                        scene.objects[i] = moved;
                    }
                }
                TrackBase::Light { index, position } => {
                    scene.lights[*index].position = iso
                        .checked_apply(position)
                        .map_err(|_| out_of_range(base_name))?;
                }
                TrackBase::Camera(base) => {
                    let mut camera = *base;
                    move_camera(&mut camera, &iso).ok_or_else(|| out_of_range(base_name))?;
                    scene.camera = camera;
                }
            }
        }
        Ok(scene)
    }
}
