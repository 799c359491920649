//! Scenes of one pixel, compiled from source and rendered at one sample:
//! the radiance along the central ray, for the tests that compare it with
//! a closed form.

use hrender::RenderOptions;
use hscene_ir::Scene;

/// The scene of `source`; panics with the diagnostics if it has errors.
pub fn compile(source: &str) -> Scene {
    let out = hscene_lang::compile(source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

/// The first pixel of `scene` rendered at one sample.
pub fn pixel(scene: &Scene) -> [f32; 3] {
    let options = RenderOptions {
        samples: Some(1),
        ..RenderOptions::default()
    };
    hrender::render(scene, &options, &|_| {})
        .unwrap()
        .image
        .get(0, 0)
}
