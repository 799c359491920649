//! Animation compiled once: every frame computed from the compiled scene
//! (`Scene::frame`) is the scene that compiling that frame alone gives,
//! exactly (the same IR, bit for bit).

use hscene_lang::ir::{FrameError, Scene};
use hscene_lang::{Options, compile_with};

/// Named objects (a sphere, a polyhedron with edges), a light and the
/// camera, each moved by fixed and animated transformations interleaved.
const ORBIT: &str = "
Globals { frames = 7; from = %eye; to = %centre; }
Points  { eye = (0, 0, 0); centre = (0, 0, 0.3); above = (0, 0.1, 0.3);
          side = (0.1, 0, 0.3); c = (0.05, 0, 0.3); }
BRDFs   { diffuse = (1, 1, 1); }
Lights  { sun: (0, 0.3, 0.1), (1, 1, 1), (1, 1, 1); }
Objects {
    ball: Sphere %c, 0.03, #1;
    cube: Cube 0.05, #1, at = %centre, edges = 0.004;
}
Transformations {
    vertical: hline (%centre, %above);
    across: hline (%centre, %side);
    @camera->Rotate(%vertical, 6.283185307179586), animate;
    @ball->Translate(%across);
    @ball->Rotate(%vertical, 3.0), animate;
    @ball->Translate(%across), animate;
    @cube->Rotate(%across, 1.0), animate;
    @cube->Rotate(%vertical, 0.5);
    @sun->Translate(%across), animate;
}
";

fn compiled(source: &str, frame: u32) -> Scene {
    let out = compile_with(
        source,
        &Options {
            base_dir: None,
            frame,
            ..Options::default()
        },
    );
    assert!(!out.has_errors(), "{:?}", out.diagnostics);
    out.scene.expect("a scene")
}

#[test]
fn every_frame_from_the_compiled_scene_is_the_frame_compiled_alone() {
    let first = compiled(ORBIT, 0);
    assert_eq!(first.settings.frames, 7);
    // The camera, the ball, the cube's faces and edges, the light.
    assert_eq!(first.animation.tracks.len(), 4);
    assert!(!first.animation.moves_points);
    for k in 0..7 {
        let alone = compiled(ORBIT, k);
        assert_eq!(first.frame(k).unwrap(), alone, "frame {k}");
        // And from any compiled frame, not just the first.
        assert_eq!(alone.frame(0).unwrap(), first, "frame 0 from frame {k}");
    }
}

#[test]
fn frames_move() {
    let first = compiled(ORBIT, 0);
    let last = first.frame(6).unwrap();
    assert_ne!(first.camera, last.camera.clone());
    assert_ne!(first.objects[0], last.objects[0]);
    assert_ne!(first.lights[0].position, last.lights[0].position);
    // A still target stays.
    assert_eq!(first.materials, last.materials);
}

#[test]
fn a_frame_past_the_end_is_refused() {
    let scene = compiled(ORBIT, 0);
    assert_eq!(
        scene.frame(7),
        Err(FrameError::PastEnd { frame: 7, last: 6 })
    );
}

#[test]
fn a_still_scene_has_one_frame_and_no_tracks() {
    let src = "Points { (0,0,0.2); } BRDFs { diffuse = (1,0,0); } Objects { Sphere %1, 0.1, #1; }";
    let scene = compiled(src, 0);
    assert!(scene.animation.tracks.is_empty());
    assert_eq!(scene.frame(0).unwrap(), scene);
    assert!(scene.frame(1).is_err());
}

/// Animated points change what is built from them, so such a scene's other
/// frames come from the source; the compiled scene says so instead of
/// giving a wrong frame.
#[test]
fn animated_points_need_the_source() {
    let src = "
Globals { frames = 3; }
Points  { o = (0, 0, 0); x = (0.1, 0, 0); p = (0, 0, 0.3); q = (0.1, 0, 0.3); r = (0, 0.1, 0.3); }
BRDFs   { diffuse = (1, 1, 1); }
Objects { Polygon (%p, %q, %r), #1; }
Transformations { line: hline (%o, %x); %q->Translate(%line), animate; }
";
    let first = compiled(src, 0);
    assert!(first.animation.moves_points);
    assert_eq!(first.frame(0).unwrap(), first);
    assert_eq!(first.frame(2), Err(FrameError::NeedsSource { frame: 2 }));
    // Compiled alone, the frame is there.
    assert_ne!(compiled(src, 2).objects, first.objects);
}
