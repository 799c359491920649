//! The window: winit for events, softbuffer for pixels (pure Rust on X11,
//! Wayland, macOS and Windows). Each turn of the event loop applies the
//! moves that arrived and hands the next stage (a coarse frame after a
//! move, else the next full-resolution pass) to the pass worker
//! (`worker`), which wakes the loop when it is done; the loop shows it.
//! A change of view cancels the stage in flight. Rendering never runs on
//! the loop's thread, so keys are answered at once: `Esc` closes the
//! window within milliseconds whatever renders, and `P`'s full render
//! shows its progress in the title. When the view has converged the loop
//! sleeps, waking every quarter second to look for changes to the scene
//! file.

use std::num::NonZeroU32;
use std::path::PathBuf;
use std::rc::Rc;
use std::sync::Arc;
use std::time::{Duration, Instant};

use hscene_ir::Scene;
use thiserror::Error;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, MouseButton, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{ModifiersState, PhysicalKey};
use winit::window::{Window, WindowId};

use crate::SceneSource;
use crate::keys::{Action, action_for_key};
use crate::pose::{Axis, Move, Pose, camera_lines};
use crate::progressive::{Frame, Progressive, ViewOptions};
use crate::worker::{FullRender, PassDone, PassPoll, PassWorker, Wake};

/// How often a still view looks for a changed scene file.
const WATCH_INTERVAL: Duration = Duration::from_millis(250);

/// Radians of turn per pixel of mouse drag.
const DRAG_TURN: f64 = 0.004;

/// Frames per second an animation plays at.
const ANIMATION_FPS: f64 = 10.0;

/// How often the title shows a full render's progress.
const PROGRESS_INTERVAL: Duration = Duration::from_millis(100);

/// How long the title says where a full render was saved.
const NOTICE_TIME: Duration = Duration::from_secs(5);

/// How long closing waits for a cancelled full render's thread (after the
/// window is gone): a cancelled render stops within a pixel's time, and a
/// file being written is let finish rather than left half written.
const SAVE_GRACE: Duration = Duration::from_secs(2);

/// Why the window could not run.
#[derive(Debug, Error)]
pub enum ViewError {
    /// No display, or the windowing system refused.
    #[error("cannot open a window: {0} (is there a display? `--headless` needs none)")]
    Display(String),
    /// The scene could not be loaded at the start.
    #[error("{0}")]
    Scene(String),
    /// The thread that renders the view could not start or stopped.
    #[error("the viewer's render worker {0}")]
    Worker(String),
}

impl ViewError {
    /// A windowing error in words, without the source file and line
    /// winit puts in front of an OS error's message ("os error at
    /// /root/.cargo/registry/.../winit-0.30/src/...rs:42: neither
    /// WAYLAND_DISPLAY nor ... is set"): that path says nothing to the user.
    fn display(message: &str) -> ViewError {
        let words = message
            .strip_prefix("os error at ")
            .and_then(|rest| rest.split_once(": ").map(|(_, words)| words))
            .unwrap_or(message);
        ViewError::Display(words.to_string())
    }
}

struct Live {
    window: Rc<Window>,
    surface: softbuffer::Surface<Rc<Window>, Rc<Window>>,
}

struct App<'s> {
    source: &'s mut dyn SceneSource,
    /// The scene as compiled (all frames); `scene` is the one shown.
    base: Scene,
    /// Shared with the stage in flight (changed copy-on-write).
    scene: Arc<Scene>,
    pose: Pose,
    flown: bool,
    /// The view's refinement; `None` while its next stage is on the worker.
    view: Option<Box<Progressive>>,
    options: ViewOptions,
    /// Bumped by every change of view: a stage rendered for an older
    /// one is thrown away.
    generation: u64,
    /// Samples per pixel of the picture shown (0 after a change).
    samples: u32,
    passes: PassWorker,
    /// The `P` render in progress.
    saving: Option<FullRender>,
    /// Wakes the event loop from a worker.
    wake: Wake,
    /// Words the title shows for a while ("saved x.png").
    notice: Option<(String, Instant)>,
    /// The title last set: set again only when it changes.
    shown_title: String,
    step: f64,
    save_dir: PathBuf,
    live: Option<Live>,
    pending: Vec<Move>,
    modifiers: ModifiersState,
    dragging: Option<(f64, f64)>,
    cursor: (f64, f64),
    last_frame: Option<Frame>,
    presented: Vec<Instant>,
    last_watch: Instant,
    error: Option<String>,
    frame_index: u32,
    playing: bool,
    last_tick: Instant,
    failure: Option<ViewError>,
    /// A render failed: nothing more is tried until something changes.
    stalled: bool,
    /// `Esc` or the window's close: nothing more is started.
    closing: bool,
}

impl App<'_> {
    fn title(&self) -> String {
        let now = Instant::now();
        let fps = self
            .presented
            .iter()
            .filter(|t| now.duration_since(**t) < Duration::from_secs(1))
            .count();
        let mut t = format!(
            "hscene view — {} — {fps} fps — {}/{} spp",
            self.source.name(),
            self.samples,
            self.options.samples
        );
        if self.base.settings.frames > 1 {
            t += &format!(" — frame {}", self.frame_index);
        }
        if self.error.is_some() {
            t += " — error: see the terminal";
        }
        if let Some(r) = &self.saving {
            t += &format!(" — rendering full picture… {} %", r.percent());
        } else if let Some((words, at)) = &self.notice
            && now.duration_since(*at) < NOTICE_TIME
        {
            t += &format!(" — {words}");
        }
        t
    }

    /// Sets the title if it changed (the loop wakes often; the window
    /// system need not hear the same title each time).
    fn refresh_title(&mut self) {
        let title = self.title();
        if title != self.shown_title
            && let Some(live) = &self.live
        {
            live.window.set_title(&title);
            self.shown_title = title;
        }
    }

    /// The view changed: the stage in flight is cancelled (it comes back
    /// from an older generation and is thrown away) and refinement
    /// starts over.
    fn restart_view(&mut self) {
        self.generation += 1;
        self.passes.cancel();
        if let Some(view) = &mut self.view {
            view.restart();
        }
        self.samples = 0;
        self.stalled = false;
    }

    /// Back to the scene's own camera for the frame shown. Not the shown
    /// scene's camera: the loop keeps that one at the pose, so `Home` did
    /// nothing.
    fn reset(&mut self) {
        let own = self.base.frame(self.frame_index).ok().map(|s| s.camera);
        if let Some(p) = own.as_ref().and_then(Pose::of) {
            self.pose = p;
        }
        self.flown = false;
        self.restart_view();
    }

    fn apply_moves(&mut self) {
        if self.pending.is_empty() {
            return;
        }
        // In a quotient space the eye is folded back into the domain after
        // each move (`Pose::folded`), so flying never leaves f64's range.
        let space = self
            .scene
            .settings
            .space
            .as_ref()
            .and_then(|s| s.build().ok());
        for m in std::mem::take(&mut self.pending) {
            match self.pose.moved(m) {
                Some(p) => self.pose = space.as_ref().map_or(p, |q| p.folded(q)),
                None => diagln!("hscene view: that move would take the eye past what f64 holds"),
            }
        }
        self.flown = true;
        self.restart_view();
    }

    /// The scene with the camera where the eye is now.
    fn sync_camera(&mut self) {
        if let Some(camera) = self.pose.camera()
            && self.scene.camera != camera
        {
            Arc::make_mut(&mut self.scene).camera = camera;
        }
    }

    fn show_frame(&mut self, k: u32) {
        match self.base.frame(k) {
            Ok(mut s) => {
                if self.flown {
                    s.camera = self.scene.camera;
                } else if let Some(p) = Pose::of(&s.camera) {
                    self.pose = p;
                }
                self.scene = Arc::new(s);
                self.frame_index = k;
                self.restart_view();
            }
            Err(e) => diagln!("hscene view: frame {k}: {e}"),
        }
    }

    fn reload(&mut self) {
        match self.source.load() {
            Ok(scene) => {
                self.error = None;
                self.base = scene;
                let k = self
                    .frame_index
                    .min(self.base.settings.frames.saturating_sub(1));
                self.show_frame(k);
                if !self.flown {
                    self.reset();
                }
                diagln!("hscene view: reloaded {}", self.source.name());
            }
            Err(message) => {
                diag!("{message}");
                self.error = Some(message);
            }
        }
        // The picture may not change (an error keeps the last good scene):
        // the title says what happened now.
        self.refresh_title();
    }

    /// Starts the full render `P` asks for, on its own thread; the title
    /// shows its progress from now on.
    fn save(&mut self) {
        if self.saving.is_some() {
            diagln!("hscene view: a full render is already running");
            return;
        }
        let name = self.source.name();
        let stem = std::path::Path::new(&name)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "view".into());
        let path = (1..10_000)
            .map(|k| self.save_dir.join(format!("{stem}-view-{k:03}.png")))
            .find(|p| !p.exists());
        let Some(path) = path else {
            diagln!("hscene view: no free file name to save to");
            return;
        };
        let o = self.options;
        let options = hrender::RenderOptions {
            net: o.net,
            resolution: Some(o.resolution),
            threads: o.threads,
            samples: Some(o.samples),
            exposure: hrender::Exposure::Stops(o.exposure),
            integrator: o.integrator,
            ..hrender::RenderOptions::default()
        };
        // Moves made just before `P` are part of the view it means.
        self.sync_camera();
        let scene = Scene::clone(&self.scene);
        match FullRender::start(scene, options, path, self.wake.clone()) {
            Ok(render) => {
                diagln!("hscene view: rendering {}", render.path.display());
                self.saving = Some(render);
            }
            Err(e) => diagln!("hscene view: cannot start the full render: {e}"),
        }
        self.refresh_title();
    }

    /// Collects a full render that has ended.
    fn finish_save(&mut self) {
        if !self.saving.as_ref().is_some_and(FullRender::is_finished) {
            return;
        }
        let Some(render) = self.saving.take() else {
            return;
        };
        let words = match render.finish() {
            Ok(path) => {
                diagln!("hscene view: saved {}", path.display());
                let file = path.file_name().unwrap_or(path.as_os_str());
                format!("saved {}", file.to_string_lossy())
            }
            Err(e) => {
                diagln!("hscene view: cannot save: {e}");
                "not saved: see the terminal".to_string()
            }
        };
        self.notice = Some((words, Instant::now()));
    }

    /// Closes at once: the window goes first, then whatever renders is
    /// cancelled (a full render is given [`SAVE_GRACE`] to stop, so no
    /// file is left half written; the pass worker is left to stop alone,
    /// as it writes nothing).
    fn quit(&mut self, event_loop: &ActiveEventLoop) {
        self.closing = true;
        self.passes.cancel();
        self.live = None;
        event_loop.exit();
        if let Some(render) = self.saving.take() {
            let path = render.path.clone();
            match render.cancel_and_wait(SAVE_GRACE) {
                Some(Ok(_)) => diagln!("hscene view: saved {}", path.display()),
                Some(Err(_)) => diagln!("hscene view: full render cancelled"),
                None => diagln!("hscene view: the full render did not stop in time"),
            }
        }
    }

    fn present(&mut self) {
        let (Some(live), Some(frame)) = (&mut self.live, &self.last_frame) else {
            return;
        };
        let size = live.window.inner_size();
        let (Some(w), Some(h)) = (NonZeroU32::new(size.width), NonZeroU32::new(size.height)) else {
            return;
        };
        if live.surface.resize(w, h).is_err() {
            return;
        }
        let Ok(mut buffer) = live.surface.buffer_mut() else {
            return;
        };
        let (w, h) = (w.get(), h.get());
        // The picture at the top left, 1:1; any margin black.
        for y in 0..h {
            for x in 0..w {
                buffer[(y * w + x) as usize] = if x < frame.width && y < frame.height {
                    frame.pixels[(y * frame.width + x) as usize]
                } else {
                    0
                };
            }
        }
        let _ = buffer.present();
        self.presented.push(Instant::now());
        let cutoff = Instant::now() - Duration::from_secs(2);
        self.presented.retain(|t| *t > cutoff);
        self.refresh_title();
    }

    /// Takes back a stage the worker finished and shows it.
    fn collect_pass(&mut self, event_loop: &ActiveEventLoop) {
        match self.passes.poll() {
            PassPoll::Idle | PassPoll::Busy => {}
            PassPoll::Done(done) => {
                let PassDone {
                    mut view,
                    result,
                    generation,
                } = *done;
                if generation != self.generation {
                    // Rendered (or cancelled) for a view since left.
                    view.restart();
                    self.view = Some(view);
                    return;
                }
                self.view = Some(view);
                match result {
                    Ok(frame) => {
                        self.samples = frame.samples;
                        self.last_frame = Some(frame);
                        self.present();
                    }
                    // Only a close cancels a current stage; nothing to show.
                    Err(hrender::RenderError::Cancelled) => {}
                    Err(e) => {
                        diagln!("hscene view: {e}");
                        self.error = Some(e.to_string());
                        self.stalled = true;
                    }
                }
            }
            PassPoll::Gone => {
                self.failure = Some(ViewError::Worker("stopped".into()));
                self.quit(event_loop);
            }
        }
    }

    /// Hands the next stage to the worker if the view wants one.
    fn start_pass(&mut self, animated: bool) {
        let Some(view) = &self.view else {
            return;
        };
        // While an animation plays, one full pass a frame is enough.
        let wanted = !(self.stalled || view.is_converged() || animated && view.samples() >= 1);
        // A full render has the cores: after a move the coarse frame still
        // shows at once, and the passes wait for it to end.
        let deferred = self.saving.is_some() && !view.next_is_coarse();
        if !wanted || deferred || self.passes.is_busy() {
            return;
        }
        if let Some(view) = self.view.take()
            && let Err(view) = self
                .passes
                .submit(view, self.scene.clone(), self.generation)
        {
            self.view = Some(view);
            diagln!("hscene view: the render worker stopped");
            self.stalled = true;
        }
    }

    fn act(&mut self, action: Action, event_loop: &ActiveEventLoop) {
        // Moves that arrived before this key are part of the view it means.
        if !matches!(action, Action::Fly(_)) {
            self.apply_moves();
        }
        match action {
            Action::Fly(m) => self.pending.push(m),
            Action::Reset => self.reset(),
            Action::PrintCamera => match self.pose.camera() {
                Some(c) => {
                    use std::io::Write as _;
                    // A closed or full stdout loses the print, not the view.
                    let _ = writeln!(std::io::stdout().lock(), "{}", camera_lines(&c));
                }
                None => diagln!("hscene view: the camera is past what f64 holds"),
            },
            Action::Save => self.save(),
            Action::TogglePlay => self.playing = !self.playing,
            Action::Quit => self.quit(event_loop),
        }
    }
}

impl ApplicationHandler for App<'_> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        // A closing viewer has dropped its window on purpose.
        if self.live.is_some() || self.closing {
            return;
        }
        let o = self.options;
        let attributes = Window::default_attributes()
            .with_title(self.title())
            .with_inner_size(PhysicalSize::new(
                o.resolution.width(),
                o.resolution.height(),
            ))
            .with_resizable(false);
        let opened = event_loop
            .create_window(attributes)
            .map_err(|e| e.to_string())
            .and_then(|window| {
                let window = Rc::new(window);
                let context =
                    softbuffer::Context::new(window.clone()).map_err(|e| e.to_string())?;
                let surface = softbuffer::Surface::new(&context, window.clone())
                    .map_err(|e| e.to_string())?;
                Ok(Live { window, surface })
            });
        match opened {
            Ok(live) => self.live = Some(live),
            Err(e) => {
                self.failure = Some(ViewError::display(&e));
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested => self.quit(event_loop),
            WindowEvent::ModifiersChanged(m) => self.modifiers = m.state(),
            WindowEvent::KeyboardInput { event, .. } if event.state == ElementState::Pressed => {
                if let PhysicalKey::Code(code) = event.physical_key
                    && let Some(action) =
                        action_for_key(code, self.step, self.modifiers.shift_key())
                {
                    self.act(action, event_loop);
                }
            }
            WindowEvent::MouseInput {
                state,
                button: MouseButton::Left,
                ..
            } => {
                self.dragging = (state == ElementState::Pressed).then_some(self.cursor);
            }
            WindowEvent::CursorMoved { position, .. } => {
                self.cursor = (position.x, position.y);
                if let Some((x0, y0)) = self.dragging {
                    let (dx, dy) = (position.x - x0, position.y - y0);
                    if dx != 0.0 {
                        self.pending.push(Move::Turn(Axis::Up, -dx * DRAG_TURN));
                    }
                    if dy != 0.0 {
                        self.pending.push(Move::Turn(Axis::Right, -dy * DRAG_TURN));
                    }
                    self.dragging = Some(self.cursor);
                }
            }
            WindowEvent::RedrawRequested => self.present(),
            _ => {}
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.closing {
            return;
        }
        let now = Instant::now();
        if now.duration_since(self.last_watch) >= WATCH_INTERVAL {
            self.last_watch = now;
            if self.source.changed() {
                self.reload();
            }
        }
        let animated = self.base.settings.frames > 1 && self.playing;
        // The next frame waits for the stage in flight: advancing would
        // cancel it, and a slow scene would then never show a frame.
        let due = now.duration_since(self.last_tick).as_secs_f64() >= 1.0 / ANIMATION_FPS;
        if animated && due && !self.passes.is_busy() {
            self.last_tick = now;
            let next = (self.frame_index + 1) % self.base.settings.frames;
            self.show_frame(next);
        }
        self.apply_moves();
        self.sync_camera();
        self.collect_pass(event_loop);
        self.finish_save();
        if self.closing {
            return;
        }
        self.start_pass(animated);
        self.refresh_title();
        // A finished stage wakes the loop itself (the worker's user
        // event); the timer is for the title's progress, the animation
        // and the scene file.
        let wake = if self.saving.is_some() {
            PROGRESS_INTERVAL
        } else if animated {
            Duration::from_secs_f64(1.0 / ANIMATION_FPS)
        } else {
            WATCH_INTERVAL
        };
        event_loop.set_control_flow(ControlFlow::WaitUntil(now + wake));
    }
}

/// Opens the window on `source`'s scene and runs until it is closed.
/// `step` is the distance one key press flies; saved renders go to
/// `save_dir`.
pub fn run_window(
    source: &mut dyn SceneSource,
    options: ViewOptions,
    step: f64,
    save_dir: PathBuf,
) -> Result<(), ViewError> {
    let base = source.load().map_err(ViewError::Scene)?;
    let scene = base.clone();
    let pose = Pose::of(&scene.camera)
        .ok_or_else(|| ViewError::Scene("the scene's camera is degenerate".into()))?;
    let event_loop = EventLoop::new().map_err(|e| ViewError::display(&e.to_string()))?;
    // Workers wake the loop through its proxy; once the loop is gone the
    // wake is lost, which is what a closed window wants.
    let proxy = event_loop.create_proxy();
    let wake: Wake = Arc::new(move || {
        let _ = proxy.send_event(());
    });
    let passes = PassWorker::start(wake.clone())
        .map_err(|e| ViewError::Worker(format!("cannot start: {e}")))?;
    let now = Instant::now();
    let mut app = App {
        source,
        base,
        scene: Arc::new(scene),
        pose,
        flown: false,
        view: Some(Box::new(Progressive::new(options))),
        options,
        generation: 0,
        samples: 0,
        passes,
        saving: None,
        wake,
        notice: None,
        shown_title: String::new(),
        step,
        save_dir,
        live: None,
        pending: Vec::new(),
        modifiers: ModifiersState::empty(),
        dragging: None,
        cursor: (0.0, 0.0),
        last_frame: None,
        presented: Vec::new(),
        last_watch: now,
        error: None,
        frame_index: 0,
        playing: true,
        last_tick: now,
        failure: None,
        stalled: false,
        closing: false,
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| ViewError::display(&e.to_string()))?;
    match app.failure {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// winit's source path is dropped, the reason kept; other messages
    /// are left as they are.
    #[test]
    fn display_errors_drop_the_source_path() {
        let e = ViewError::display(
            "os error at /root/.cargo/registry/src/winit-0.30.12/src/platform_impl/linux/mod.rs:771: neither WAYLAND_DISPLAY nor WAYLAND_SOCKET nor DISPLAY is set.",
        );
        let text = e.to_string();
        assert!(!text.contains(".rs"), "{text}");
        assert!(text.contains("neither WAYLAND_DISPLAY"), "{text}");
        assert_eq!(
            ViewError::display("the display refused").to_string(),
            ViewError::Display("the display refused".into()).to_string()
        );
    }
}
