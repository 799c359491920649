//! Preparing a scene for tracing: everything moved into the canonical
//! frame and the hierarchy built (`scene.rs`), then each honeycomb's
//! average appearance beyond its horizon (`horizon_fill.rs`), and a
//! quotient space's beyond its walk's (`space_fill.rs`).

use hgeom::Isometry;
use hscene_ir::Scene;
use hscene_ir::view::{CanonicalFrame, PixelFootprint};

use crate::error::RenderError;
use crate::horizon_fill::fill_horizons;
use crate::scene::PreparedScene;
use crate::space_fill::fill_space;
use crate::space_prepare::unfold;

impl PreparedScene {
    /// Move every object and light by `to_canonical`, and build the
    /// bounding hierarchy.
    ///
    /// Fails if something lies so far from the eye (beyond distance ~37)
    /// that f64 cannot represent it in the canonical frame: that is reported,
    /// not silently dropped.
    pub fn new(scene: &Scene, to_canonical: &Isometry) -> Result<PreparedScene, RenderError> {
        prepared(scene, std::slice::from_ref(to_canonical), None)
    }

    /// [`PreparedScene::new`] for a camera: everything is moved by the
    /// camera's [`stages`](CanonicalFrame::stages) in turn, which keeps far
    /// scenes exact to the rounding of their input.
    pub fn for_camera(
        scene: &Scene,
        camera: &CanonicalFrame,
    ) -> Result<PreparedScene, RenderError> {
        prepared(scene, &camera.stages, None)
    }

    /// [`PreparedScene::for_camera`] for a picture whose pixels sample the
    /// directions at the eye as `footprint` says: detail that no pixel can
    /// resolve is not traced ([`hscene_ir::Shape::for_footprint`]).
    pub fn for_picture(
        scene: &Scene,
        camera: &CanonicalFrame,
        footprint: &PixelFootprint,
    ) -> Result<PreparedScene, RenderError> {
        prepared(scene, &camera.stages, Some(footprint))
    }
}

/// The scene moved by `stages`, drawn for `footprint` if given, with its
/// honeycombs' horizon materials.
fn prepared(
    scene: &Scene,
    stages: &[Isometry],
    footprint: Option<&PixelFootprint>,
) -> Result<PreparedScene, RenderError> {
    if let Some(space) = &scene.settings.space {
        // In a quotient space the picture-wide horizon is the walk's own
        // (`space_prepare.rs`); honeycombs there are the domain's edges,
        // walked piece by piece. Beyond the walk's horizon the space's
        // average fills in (`space_fill.rs`).
        let unfolded = unfold(scene, space, stages, footprint)?;
        let mut prepared = PreparedScene::staged(&unfolded.scene, &unfolded.stages, None)?;
        prepared.space = Some(unfolded.space);
        fill_space(&mut prepared, &unfolded.scene);
        return Ok(prepared);
    }
    let mut prepared = PreparedScene::staged(scene, stages, footprint)?;
    fill_horizons(&mut prepared, scene, stages);
    Ok(prepared)
}
