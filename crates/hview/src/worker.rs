//! Rendering off the event loop: the window's passes on one worker thread,
//! a full render (`P`) on a thread of its own. The event loop only hands
//! out jobs, shows what comes back and sets cancel flags, so it answers a
//! key (`Esc` above all) within a few milliseconds whatever is rendering:
//! the renderer looks at a job's flag before every pixel.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use hrender::{RenderError, RenderOptions};
use hscene_ir::Scene;

use crate::progressive::{Frame, Progressive};

/// Called by a worker when it has something for the event loop (the
/// window wakes it through winit's proxy; a test may count).
pub(crate) type Wake = Arc<dyn Fn() + Send + Sync>;

/// One stage of a view to render: the view travels to the worker and
/// back, so its sums are never shared between threads.
struct PassJob {
    view: Box<Progressive>,
    scene: Arc<Scene>,
    cancel: Arc<AtomicBool>,
    generation: u64,
}

/// A stage rendered (or cancelled, or failed), with the view it belongs to.
pub(crate) struct PassDone {
    pub view: Box<Progressive>,
    pub result: Result<Frame, RenderError>,
    /// The [`PassWorker::submit`] generation it was asked for: an older
    /// one than the window's is a view that has since moved.
    pub generation: u64,
}

/// What the pass worker has for the event loop.
pub(crate) enum PassPoll {
    /// Nothing handed out.
    Idle,
    /// A stage is rendering.
    Busy,
    /// A stage came back.
    Done(Box<PassDone>),
    /// The worker is gone (it panicked): the view went with it.
    Gone,
}

/// The thread that renders the window's passes, one at a time.
pub(crate) struct PassWorker {
    jobs: Sender<PassJob>,
    done: Receiver<PassDone>,
    /// The flag of the stage in flight, if one is.
    in_flight: Option<Arc<AtomicBool>>,
}

impl PassWorker {
    /// Starts the worker; `wake` is called after each stage.
    pub fn start(wake: Wake) -> std::io::Result<PassWorker> {
        let (jobs, inbox) = mpsc::channel::<PassJob>();
        let (outbox, done) = mpsc::channel();
        // Detached: it ends when the window drops `jobs`, and a stage in
        // flight then is cancelled first, so it never holds the process
        // up (and it writes no files an exit could leave half done).
        std::thread::Builder::new()
            .name("hview-pass".into())
            .spawn(move || {
                for job in inbox {
                    let mut view = job.view;
                    let result = view.step_cancellable(&job.scene, &job.cancel);
                    let back = PassDone {
                        view,
                        result,
                        generation: job.generation,
                    };
                    if outbox.send(back).is_err() {
                        break;
                    }
                    wake();
                }
            })?;
        Ok(PassWorker {
            jobs,
            done,
            in_flight: None,
        })
    }

    /// True while a stage is rendering.
    pub fn is_busy(&self) -> bool {
        self.in_flight.is_some()
    }

    /// Hands `view`'s next stage of `scene` to the worker; if the worker is
    /// gone, the view comes back.
    pub fn submit(
        &mut self,
        view: Box<Progressive>,
        scene: Arc<Scene>,
        generation: u64,
    ) -> Result<(), Box<Progressive>> {
        let cancel = Arc::new(AtomicBool::new(false));
        let job = PassJob {
            view,
            scene,
            cancel: cancel.clone(),
            generation,
        };
        match self.jobs.send(job) {
            Ok(()) => {
                self.in_flight = Some(cancel);
                Ok(())
            }
            Err(mpsc::SendError(job)) => Err(job.view),
        }
    }

    /// Stops the stage in flight, if any (it comes back `Cancelled`).
    pub fn cancel(&self) {
        if let Some(flag) = &self.in_flight {
            flag.store(true, Ordering::Relaxed);
        }
    }

    /// What the worker has, without waiting.
    pub fn poll(&mut self) -> PassPoll {
        if self.in_flight.is_none() {
            return PassPoll::Idle;
        }
        match self.done.try_recv() {
            Ok(done) => {
                self.in_flight = None;
                PassPoll::Done(Box::new(done))
            }
            Err(TryRecvError::Empty) => PassPoll::Busy,
            Err(TryRecvError::Disconnected) => {
                self.in_flight = None;
                PassPoll::Gone
            }
        }
    }
}

/// A full-quality render of one view to a file, on its own thread.
pub(crate) struct FullRender {
    /// Where it goes.
    pub path: PathBuf,
    rows: Arc<AtomicUsize>,
    total: usize,
    cancel: Arc<AtomicBool>,
    handle: JoinHandle<Result<(), RenderError>>,
}

impl FullRender {
    /// Starts rendering `scene` as `options` ask to `path`; `wake` is
    /// called when it ends.
    pub fn start(
        scene: Scene,
        options: RenderOptions,
        path: PathBuf,
        wake: Wake,
    ) -> std::io::Result<FullRender> {
        let rows = Arc::new(AtomicUsize::new(0));
        let cancel = Arc::new(AtomicBool::new(false));
        let total = options
            .resolution
            .unwrap_or(scene.settings.resolution)
            .height() as usize;
        let handle = {
            let (rows, cancel, path) = (rows.clone(), cancel.clone(), path.clone());
            std::thread::Builder::new()
                .name("hview-save".into())
                .spawn(move || {
                    let saved = render_to_file(&scene, &options, &path, &rows, &cancel);
                    wake();
                    saved
                })?
        };
        Ok(FullRender {
            path,
            rows,
            total,
            cancel,
            handle,
        })
    }

    /// Rows finished, and the picture's rows.
    pub fn progress(&self) -> (usize, usize) {
        (
            self.rows.load(Ordering::Relaxed).min(self.total),
            self.total,
        )
    }

    /// Whole percent done.
    pub fn percent(&self) -> usize {
        let (done, total) = self.progress();
        (done * 100).checked_div(total).unwrap_or(100)
    }

    /// True once the thread has ended (saved, failed or cancelled).
    pub fn is_finished(&self) -> bool {
        self.handle.is_finished()
    }

    /// The outcome, waiting for the thread if it has not ended.
    pub fn finish(self) -> Result<PathBuf, String> {
        match self.handle.join() {
            Ok(Ok(())) => Ok(self.path),
            Ok(Err(e)) => Err(e.to_string()),
            Err(_) => Err("the render stopped unexpectedly".into()),
        }
    }

    /// Cancels it and waits up to `bound` for the thread to end, so a file
    /// being written is finished (saves are atomic: a cancelled render
    /// writes nothing). The outcome if it ended in time (a render that was
    /// already writing its file saves it); `None` if it is left to end
    /// alone.
    pub fn cancel_and_wait(self, bound: Duration) -> Option<Result<PathBuf, String>> {
        self.cancel.store(true, Ordering::Relaxed);
        let deadline = Instant::now() + bound;
        while !self.handle.is_finished() {
            if Instant::now() >= deadline {
                return None;
            }
            std::thread::sleep(Duration::from_millis(1));
        }
        Some(self.finish())
    }
}

/// Renders `scene` and writes it to `path` (atomically), counting rows in
/// `rows`; nothing is written once `cancel` is set.
fn render_to_file(
    scene: &Scene,
    options: &RenderOptions,
    path: &std::path::Path,
    rows: &AtomicUsize,
    cancel: &AtomicBool,
) -> Result<(), RenderError> {
    // Rows finish in any order across threads, each reporting the count
    // so far: the largest seen is the count.
    let progress = |n: u32| {
        rows.fetch_max(n as usize, Ordering::Relaxed);
    };
    let rendered = hrender::render_region_cancellable(scene, options, None, &progress, cancel)?;
    if cancel.load(Ordering::Relaxed) {
        return Err(RenderError::Cancelled);
    }
    hrender::write_image(&rendered.image, path, hrender::SampleDepth::Eight)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::progressive::ViewOptions;
    use hscene_ir::Resolution;

    fn scene(width: u32, height: u32) -> Scene {
        let text = format!(
            "Globals {{ resolution = ({width}, {height}); fov = 70; from = (0, 0, 0); to = (0, 0, 0.3); }}\n\
             BRDFs {{ paint: ambient = (0.2, 0.2, 0.2), diffuse = (0.9, 0.3, 0.1), specular = (0.5, 0.5, 0.5), shininess = 20; }}\n\
             Lights {{ (0.2, 0.4, 0.1), (1, 1, 1), (0.5, 0.5, 0.5); }}\n\
             Objects {{ Sphere (0, 0, 0.45), 0.3, #paint; Sphere (0.25, -0.1, 0.3), 0.12, #paint; }}\n"
        );
        let compiled = hscene_lang::compile(&text);
        compiled.scene.expect("the test scene compiles")
    }

    fn full_options(width: u32, height: u32, samples: u32) -> RenderOptions {
        RenderOptions {
            resolution: Resolution::new(width, height),
            samples: Some(samples),
            threads: Some(2),
            ..RenderOptions::default()
        }
    }

    fn no_wake() -> Wake {
        Arc::new(|| {})
    }

    /// The files in `dir`, by name.
    fn files(dir: &std::path::Path) -> Vec<String> {
        std::fs::read_dir(dir)
            .expect("the directory reads")
            .map(|e| {
                e.expect("an entry")
                    .file_name()
                    .to_string_lossy()
                    .into_owned()
            })
            .collect()
    }

    /// A pass far longer than the test, cancelled, comes back `Cancelled`
    /// within 100 ms of the flag (the renderer looks at it before every
    /// pixel), with the view as it was: the pass still to do.
    #[test]
    fn a_cancelled_pass_comes_back_cancelled_within_100_ms() {
        let options = ViewOptions {
            resolution: Resolution::new(3000, 2000).expect("a size"),
            net: None,
            integrator: None,
            samples: 4,
            coarse: 1,
            exposure: 0.0,
            threads: Some(2),
            denoise: false,
        };
        let woken = Arc::new(AtomicUsize::new(0));
        let counter = woken.clone();
        let mut worker = PassWorker::start(Arc::new(move || {
            counter.fetch_add(1, Ordering::Relaxed);
        }))
        .expect("the worker starts");
        let scene = Arc::new(scene(3000, 2000));
        assert!(
            worker
                .submit(Box::new(Progressive::new(options)), scene, 7)
                .is_ok()
        );
        // Long enough for the picture's set-up (not cancellable, and slow
        // on a loaded machine) to be over: the pass itself is rendering.
        std::thread::sleep(Duration::from_millis(500));
        assert!(
            matches!(worker.poll(), PassPoll::Busy),
            "the pass ended early"
        );
        let asked = Instant::now();
        worker.cancel();
        let done = loop {
            match worker.poll() {
                PassPoll::Done(done) => break done,
                PassPoll::Busy => std::thread::sleep(Duration::from_millis(1)),
                PassPoll::Idle | PassPoll::Gone => panic!("the pass was lost"),
            }
        };
        let latency = asked.elapsed();
        eprintln!("cancelled after {latency:?}");
        assert!(
            latency < Duration::from_millis(100),
            "cancelled after {latency:?}"
        );
        assert!(matches!(done.result, Err(RenderError::Cancelled)));
        assert_eq!(done.generation, 7);
        assert_eq!(done.view.samples(), 0);
        assert_eq!(woken.load(Ordering::Relaxed), 1);
        assert!(matches!(worker.poll(), PassPoll::Idle));
    }

    /// The passes a worker renders are those `step` renders: the view
    /// comes back with its samples counted and the picture to show.
    #[test]
    fn passes_on_the_worker_refine_the_view() {
        let options = ViewOptions {
            resolution: Resolution::new(32, 24).expect("a size"),
            net: None,
            integrator: None,
            samples: 2,
            coarse: 4,
            exposure: 0.0,
            threads: Some(2),
            denoise: false,
        };
        let mut worker = PassWorker::start(no_wake()).expect("the worker starts");
        let scene = Arc::new(scene(32, 24));
        let mut view = Box::new(Progressive::new(options));
        let mut direct = Progressive::new(options);
        for _ in 0..3 {
            assert!(worker.submit(view, scene.clone(), 0).is_ok());
            let done = loop {
                match worker.poll() {
                    PassPoll::Done(done) => break done,
                    PassPoll::Busy => std::thread::sleep(Duration::from_millis(1)),
                    PassPoll::Idle | PassPoll::Gone => panic!("the pass was lost"),
                }
            };
            view = done.view;
            let frame = done.result.expect("the pass renders");
            assert_eq!(frame, direct.step(&scene).expect("the view renders"));
        }
        assert!(view.is_converged());
    }

    /// A full render counts its rows up to the picture's and saves the
    /// picture, with no other file left in the directory.
    #[test]
    fn full_render_progress_reaches_the_total() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let path = dir.path().join("out.png");
        let woken = Arc::new(AtomicUsize::new(0));
        let counter = woken.clone();
        let render = FullRender::start(
            scene(48, 36),
            full_options(48, 36, 4),
            path.clone(),
            Arc::new(move || {
                counter.fetch_add(1, Ordering::Relaxed);
            }),
        )
        .expect("the render starts");
        let deadline = Instant::now() + Duration::from_secs(60);
        while !render.is_finished() {
            assert!(Instant::now() < deadline, "the render never ended");
            std::thread::sleep(Duration::from_millis(5));
        }
        assert_eq!(render.progress(), (36, 36));
        assert_eq!(render.percent(), 100);
        assert_eq!(render.finish(), Ok(path.clone()));
        assert_eq!(woken.load(Ordering::Relaxed), 1);
        assert_eq!(files(dir.path()), vec!["out.png".to_string()]);
    }

    /// A full render cancelled part way stops within 100 ms of the flag,
    /// says `Cancelled` and leaves no file, temporary or not.
    #[test]
    fn a_cancelled_full_render_stops_within_100_ms_and_writes_nothing() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let path = dir.path().join("out.png");
        let render = FullRender::start(
            scene(1600, 1200),
            full_options(1600, 1200, 64),
            path,
            no_wake(),
        )
        .expect("the render starts");
        let deadline = Instant::now() + Duration::from_secs(60);
        while render.progress().0 == 0 {
            assert!(Instant::now() < deadline, "no row was ever finished");
            std::thread::sleep(Duration::from_millis(5));
        }
        assert!(render.percent() < 100, "the render ended early");
        let asked = Instant::now();
        let outcome = render.cancel_and_wait(Duration::from_secs(10));
        let latency = asked.elapsed();
        eprintln!("cancelled after {latency:?}");
        assert!(
            latency < Duration::from_millis(100),
            "cancelled after {latency:?}"
        );
        assert_eq!(outcome, Some(Err(RenderError::Cancelled.to_string())));
        assert!(files(dir.path()).is_empty(), "{:?}", files(dir.path()));
    }
}
