//! The denoiser (Intel Open Image Denoise, loaded at run time) on a small
//! Cornell box: its guides are sane, and denoising a noisy picture brings
//! it nearer a many-sample reference. Without the library the picture
//! checks say they were skipped, unless `HSCENE_REQUIRE_OIDN` is set (as
//! `HSCENE_REQUIRE_FFMPEG` is for ffmpeg), which makes them fail.

use hrender::{IntegratorKind, RenderOptions, render, render_guides};
use hscene_ir::{Resolution, Scene};

/// `scenes/path/cornell-h3.hsc`: the box the measurement in
/// docs/performance.md uses.
fn cornell() -> Scene {
    let src = include_str!("../../../scenes/path/cornell-h3.hsc");
    let compiled = hscene_lang::compile(src);
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    compiled.scene.expect("a scene")
}

fn options(samples: u32, seed: u64) -> RenderOptions {
    RenderOptions {
        integrator: Some(IntegratorKind::Path),
        samples: Some(samples),
        seed,
        resolution: Resolution::new(40, 40),
        ..RenderOptions::default()
    }
}

/// The library, or `None` (a skip) where it is not installed and not
/// required.
fn denoiser() -> Option<&'static hrender::Denoiser> {
    match hrender::denoiser() {
        Ok(d) => Some(d),
        Err(e) => {
            assert!(
                std::env::var_os("HSCENE_REQUIRE_OIDN").is_none(),
                "HSCENE_REQUIRE_OIDN is set but the denoiser cannot be loaded: {e}"
            );
            eprintln!("skipped: {e}");
            None
        }
    }
}

/// Relative RMSE of `a` against `reference`: the root of the mean squared
/// difference over the mean squared reference.
fn relative_rmse(a: &hrender::Image, reference: &hrender::Image) -> f64 {
    let (mut err, mut norm) = (0.0, 0.0);
    for (p, q) in a.pixels().iter().zip(reference.pixels()) {
        for c in 0..3 {
            let (x, y) = (f64::from(p[c]), f64::from(q[c]));
            err += (x - y) * (x - y);
            norm += y * y;
        }
    }
    (err / norm).sqrt()
}

/// The guides: albedos within [0, 1] with the walls' colours, normals of
/// unit length where a wall is met.
#[test]
fn guides_are_albedo_and_unit_normals() {
    let scene = cornell();
    let guides = render_guides(&scene, &options(1, 0), None).unwrap();
    assert_eq!(guides.albedo.len(), 1600);
    assert!(
        guides
            .albedo
            .iter()
            .flatten()
            .all(|v| (0.0..=1.0).contains(v))
    );
    // The red wall is on the left, the green on the right (row 20).
    let left = guides.albedo[20 * 40 + 3];
    let right = guides.albedo[20 * 40 + 36];
    assert!(left[0] > 0.6 && left[1] < 0.2, "{left:?}");
    assert!(right[1] > 0.5 && right[0] < 0.2, "{right:?}");
    let n = guides.normal[20 * 40 + 20];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    assert!((len - 1.0).abs() < 0.05, "{n:?}");
}

/// Denoising 4 samples a pixel lowers its error against 256 by much.
#[test]
fn denoising_lowers_the_error_against_a_reference() {
    let Some(denoiser) = denoiser() else {
        return;
    };
    let scene = cornell();
    let reference = render(&scene, &options(256, 7), &|_| {}).unwrap().image;
    let noisy = render(&scene, &options(4, 1), &|_| {}).unwrap().image;
    let guides = render_guides(&scene, &options(4, 1), None).unwrap();
    let denoised = denoiser.denoise(&noisy, &guides, None).unwrap();
    assert!(denoised.pixels().iter().flatten().all(|v| v.is_finite()));
    let (before, after) = (
        relative_rmse(&noisy, &reference),
        relative_rmse(&denoised, &reference),
    );
    assert!(
        after < 0.7 * before,
        "relative RMSE {before:.4} noisy, {after:.4} denoised"
    );
}

/// Guides of the wrong size are refused, not read past their end.
#[test]
fn mismatched_guides_are_refused() {
    let Some(denoiser) = denoiser() else {
        return;
    };
    let image = hrender::Image::from_pixels(2, 2, vec![[0.5; 3]; 4]);
    let guides = hrender::Guides {
        albedo: vec![[0.5; 3]; 3],
        normal: vec![[0.0, 0.0, 1.0]; 4],
    };
    assert!(matches!(
        denoiser.denoise(&image, &guides, None),
        Err(hrender::DenoiseError::GuideSize { .. })
    ));
}
