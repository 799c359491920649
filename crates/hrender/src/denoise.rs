//! Denoising a path-traced picture with Intel Open Image Denoise (OIDN),
//! guided by the first hit's albedo and normal (`aov.rs`).
//!
//! The library is loaded when a render first asks for it, never linked:
//! hscene builds and runs without it, and only a render that denoises
//! needs it. Where it is looked for, in order (docs/rendering.md
//! "Denoising"):
//!
//! 1. `HSCENE_OIDN`, the path of the library, when set: that file and no
//!    other (a user who names a file means it).
//! 2. The system's loader: `libOpenImageDenoise.so.2`, `.so.1`, `.so`
//!    (a distribution's package, `LD_LIBRARY_PATH`).
//! 3. The folder of the `oidn` Python package (`python3 -m pip install
//!    oidn`), found by asking `python3` where the package is without
//!    importing it (importing it fails on machines without Intel's TBB,
//!    which the wheel ships beside the library under a name its loader
//!    does not look for: we load that copy first).
//!
//! Only the small C API is used (device, filter `"RT"`, shared images),
//! which OIDN 1.x and 2.x both export.

use std::ffi::{CStr, c_char, c_void};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use thiserror::Error;

use crate::image::Image;

/// The environment variable naming the library file to load.
pub const OIDN_ENV: &str = "HSCENE_OIDN";

/// The command that installs the library where hscene finds it.
pub const OIDN_INSTALL: &str = "python3 -m pip install oidn";

/// Why a picture could not be denoised.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum DenoiseError {
    /// The library is not installed where it is looked for.
    #[error(
        "denoising needs Intel Open Image Denoise (libOpenImageDenoise), which was not found; install it with `{OIDN_INSTALL}` (or set {OIDN_ENV} to the library's path). Looked for: {}",
        tried.join("; ")
    )]
    NotInstalled {
        /// Each place looked in, with why it failed.
        tried: Vec<String>,
    },
    /// `HSCENE_OIDN` names a file that cannot be loaded.
    #[error(
        "{OIDN_ENV} names {path}, which cannot be loaded as Intel Open Image Denoise ({reason}); install the library with `{OIDN_INSTALL}` and unset {OIDN_ENV}, or point it at libOpenImageDenoise.so"
    )]
    BadEnvPath {
        /// The path the variable gives.
        path: PathBuf,
        /// The loader's reason.
        reason: String,
    },
    /// The library lacks a function of the C API (not OIDN, or too old).
    #[error("{path} is not a usable Intel Open Image Denoise: it lacks `{symbol}`")]
    MissingSymbol {
        /// The library loaded.
        path: PathBuf,
        /// The function it lacks.
        symbol: &'static str,
    },
    /// OIDN refused or failed, in its own words.
    #[error("the denoiser failed: {0}")]
    Failed(String),
    /// The guide layers do not match the picture (a bug in the caller).
    #[error("the denoiser's guide layers are {got} pixels, the picture {expected}")]
    GuideSize {
        /// The picture's pixels.
        expected: usize,
        /// The guides' pixels.
        got: usize,
    },
}

/// The albedo and normal of each pixel's first hit, the denoiser's guides
/// (row-major, as the picture).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Guides {
    /// Reflectance, each channel in `[0, 1]`.
    pub albedo: Vec<[f32; 3]>,
    /// Unit normals facing the eye (0 where nothing is met).
    pub normal: Vec<[f32; 3]>,
}

// The C API's types: opaque handles and enums as C ints.
type Handle = *mut c_void;
const DEVICE_TYPE_DEFAULT: i32 = 0;
const FORMAT_FLOAT3: i32 = 3;
const ERROR_NONE: i32 = 0;

type NewDevice = unsafe extern "C" fn(i32) -> Handle;
type DeviceFn = unsafe extern "C" fn(Handle);
type SetDeviceInt = unsafe extern "C" fn(Handle, *const c_char, i32);
type GetError = unsafe extern "C" fn(Handle, *mut *const c_char) -> i32;
type NewFilter = unsafe extern "C" fn(Handle, *const c_char) -> Handle;
type SetImage = unsafe extern "C" fn(
    Handle,
    *const c_char,
    *mut c_void,
    i32,
    usize,
    usize,
    usize,
    usize,
    usize,
);
type SetBool = unsafe extern "C" fn(Handle, *const c_char, bool);

/// The loaded library and the functions hscene calls.
pub struct Denoiser {
    path: PathBuf,
    new_device: NewDevice,
    commit_device: DeviceFn,
    release_device: DeviceFn,
    set_device_int: SetDeviceInt,
    get_error: GetError,
    new_filter: NewFilter,
    set_image: SetImage,
    set_bool: SetBool,
    commit_filter: DeviceFn,
    execute_filter: DeviceFn,
    release_filter: DeviceFn,
    // Kept loaded for as long as the functions above may be called; the
    // TBB copy the Python wheel ships must outlive the library using it.
    _library: libloading::Library,
    _tbb: Option<libloading::Library>,
}

impl std::fmt::Debug for Denoiser {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Denoiser")
            .field("path", &self.path)
            .finish()
    }
}

/// The denoiser, loaded once per process (the search runs `python3`).
pub fn denoiser() -> Result<&'static Denoiser, DenoiseError> {
    static LOADED: OnceLock<Result<Denoiser, DenoiseError>> = OnceLock::new();
    LOADED.get_or_init(load).as_ref().map_err(Clone::clone)
}

/// Whether the library can be loaded (a viewer denoises its still frames
/// only then).
pub fn denoiser_available() -> bool {
    denoiser().is_ok()
}

/// The search of the module docs.
fn load() -> Result<Denoiser, DenoiseError> {
    if let Some(path) = std::env::var_os(OIDN_ENV).filter(|p| !p.is_empty()) {
        let path = PathBuf::from(path);
        return open(&path, None).map_err(|reason| match reason {
            Opened::Load(reason) => DenoiseError::BadEnvPath { path, reason },
            Opened::Symbol(e) => e,
        });
    }
    let mut tried = Vec::new();
    for name in [
        "libOpenImageDenoise.so.2",
        "libOpenImageDenoise.so.1",
        "libOpenImageDenoise.so",
    ] {
        match open(Path::new(name), None) {
            Ok(d) => return Ok(d),
            Err(Opened::Symbol(e)) => return Err(e),
            Err(Opened::Load(_)) => {}
        }
    }
    tried.push("the system's library path (libOpenImageDenoise.so.2, .so.1, .so)".to_string());
    match python_package_dir() {
        Some(dir) => match wheel_library(&dir) {
            Some((library, tbb)) => {
                return open(&library, tbb.as_deref()).map_err(|e| match e {
                    Opened::Load(reason) => DenoiseError::NotInstalled {
                        tried: vec![format!("{}: {reason}", library.display())],
                    },
                    Opened::Symbol(e) => e,
                });
            }
            None => tried.push(format!(
                "the `oidn` Python package in {} (no libOpenImageDenoise.so* under it)",
                dir.display()
            )),
        },
        None => tried.push("the `oidn` Python package (python3 does not find it)".to_string()),
    }
    Err(DenoiseError::NotInstalled { tried })
}

/// Why [`open`] failed: the loader's reason, or a library without the API.
enum Opened {
    Load(String),
    Symbol(DenoiseError),
}

/// The folder of the `oidn` Python package, asked of `python3` without
/// importing the package.
fn python_package_dir() -> Option<PathBuf> {
    let out = std::process::Command::new("python3")
        .args([
            "-c",
            "import importlib.util, os\n\
             s = importlib.util.find_spec('oidn')\n\
             print(os.path.dirname(s.origin) if s and s.origin else '')",
        ])
        .stdin(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .output()
        .ok()?;
    let text = String::from_utf8(out.stdout).ok()?;
    let dir = text.trim();
    (out.status.success() && !dir.is_empty()).then(|| PathBuf::from(dir))
}

/// The library in the wheel's folder `dir` (under `lib.linux.x64/`, or
/// `dir` itself), and the TBB beside it if any.
fn wheel_library(dir: &Path) -> Option<(PathBuf, Option<PathBuf>)> {
    for sub in [
        dir.join("lib.linux.x64"),
        dir.join("lib"),
        dir.to_path_buf(),
    ] {
        let Ok(entries) = std::fs::read_dir(&sub) else {
            continue;
        };
        let mut names: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        names.sort();
        let named = |prefix: &str| {
            names
                .iter()
                .find(|p| {
                    p.file_name()
                        .and_then(|n| n.to_str())
                        .is_some_and(|n| n.starts_with(prefix))
                })
                .cloned()
        };
        if let Some(library) = named("libOpenImageDenoise.so") {
            return Some((library, named("libtbb.so")));
        }
    }
    None
}

/// Loads `path` (after `tbb`, made visible to it) and looks up the API.
fn open(path: &Path, tbb: Option<&Path>) -> Result<Denoiser, Opened> {
    let tbb = match tbb {
        Some(t) => Some(load_global(t).map_err(Opened::Load)?),
        None => None,
    };
    let library = load_global(path).map_err(Opened::Load)?;
    let missing = |symbol| {
        Opened::Symbol(DenoiseError::MissingSymbol {
            path: path.to_path_buf(),
            symbol,
        })
    };
    // SAFETY: each symbol is the C function of OIDN's API with the
    // signature its alias spells (OpenImageDenoise/oidn.h, 1.x and 2.x).
    unsafe {
        macro_rules! get {
            ($name:literal) => {
                *library
                    .get(concat!($name, "\0").as_bytes())
                    .map_err(|_| missing($name))?
            };
        }
        let set_bool: SetBool = match library.get(b"oidnSetFilterBool\0") {
            Ok(f) => *f,
            Err(_) => get!("oidnSetFilter1b"),
        };
        let set_device_int: SetDeviceInt = match library.get(b"oidnSetDeviceInt\0") {
            Ok(f) => *f,
            Err(_) => get!("oidnSetDevice1i"),
        };
        Ok(Denoiser {
            path: path.to_path_buf(),
            new_device: get!("oidnNewDevice"),
            commit_device: get!("oidnCommitDevice"),
            release_device: get!("oidnReleaseDevice"),
            set_device_int,
            get_error: get!("oidnGetDeviceError"),
            new_filter: get!("oidnNewFilter"),
            set_image: get!("oidnSetSharedFilterImage"),
            set_bool,
            commit_filter: get!("oidnCommitFilter"),
            execute_filter: get!("oidnExecuteFilter"),
            release_filter: get!("oidnReleaseFilter"),
            _library: library,
            _tbb: tbb,
        })
    }
}

/// `dlopen` with the library's symbols visible to those loaded after it
/// (the wheel's TBB must satisfy OIDN's `libtbb.so.12`).
fn load_global(path: &Path) -> Result<libloading::Library, String> {
    #[cfg(unix)]
    {
        use libloading::os::unix::{Library, RTLD_GLOBAL, RTLD_NOW};
        // SAFETY: loading runs the library's initialisers; OIDN's and TBB's
        // have no preconditions on the caller.
        unsafe { Library::open(Some(path), RTLD_NOW | RTLD_GLOBAL) }
            .map(libloading::Library::from)
            .map_err(|e| e.to_string())
    }
    #[cfg(not(unix))]
    {
        // SAFETY: as above.
        unsafe { libloading::Library::new(path) }.map_err(|e| e.to_string())
    }
}

/// A device or filter handle released when dropped, on every path out.
struct Released<'d> {
    handle: Handle,
    release: DeviceFn,
    _denoiser: std::marker::PhantomData<&'d Denoiser>,
}

impl Drop for Released<'_> {
    fn drop(&mut self) {
        if !self.handle.is_null() {
            // SAFETY: a handle OIDN returned, released once.
            unsafe { (self.release)(self.handle) }
        }
    }
}

impl Denoiser {
    /// The library file loaded.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// `color` denoised, guided by `guides` (same size), on `threads`
    /// threads (`None`: OIDN's choice, every core). The picture is HDR
    /// (unclamped linear radiance).
    pub fn denoise(
        &self,
        color: &Image,
        guides: &Guides,
        threads: Option<usize>,
    ) -> Result<Image, DenoiseError> {
        let n = color.pixels().len();
        for got in [guides.albedo.len(), guides.normal.len()] {
            if got != n {
                return Err(DenoiseError::GuideSize { expected: n, got });
            }
        }
        let (w, h) = (color.width() as usize, color.height() as usize);
        // OIDN takes mutable pointers for its inputs too; it only reads
        // them, but copies keep the caller's buffers out of it.
        let mut input = color.pixels().to_vec();
        let mut albedo = guides.albedo.clone();
        let mut normal = guides.normal.clone();
        let mut output = vec![[0.0f32; 3]; n];
        // SAFETY: the functions are OIDN's C API (see `open`); the images
        // are `w * h` packed float triples that outlive the filter's
        // execution; names are NUL-terminated.
        unsafe {
            let device = Released {
                handle: (self.new_device)(DEVICE_TYPE_DEFAULT),
                release: self.release_device,
                _denoiser: std::marker::PhantomData,
            };
            if device.handle.is_null() {
                return Err(DenoiseError::Failed(
                    "it could not create a device".to_string(),
                ));
            }
            if let Some(t) = threads {
                let t = i32::try_from(t).unwrap_or(i32::MAX);
                (self.set_device_int)(device.handle, c"numThreads".as_ptr(), t);
            }
            (self.commit_device)(device.handle);
            self.check(device.handle)?;
            let filter = Released {
                handle: (self.new_filter)(device.handle, c"RT".as_ptr()),
                release: self.release_filter,
                _denoiser: std::marker::PhantomData,
            };
            self.check(device.handle)?;
            if filter.handle.is_null() {
                return Err(DenoiseError::Failed("it has no \"RT\" filter".to_string()));
            }
            for (name, buffer) in [
                (c"color", input.as_mut_ptr()),
                (c"albedo", albedo.as_mut_ptr()),
                (c"normal", normal.as_mut_ptr()),
                (c"output", output.as_mut_ptr()),
            ] {
                (self.set_image)(
                    filter.handle,
                    name.as_ptr(),
                    buffer.cast(),
                    FORMAT_FLOAT3,
                    w,
                    h,
                    0,
                    0,
                    0,
                );
            }
            (self.set_bool)(filter.handle, c"hdr".as_ptr(), true);
            (self.commit_filter)(filter.handle);
            self.check(device.handle)?;
            (self.execute_filter)(filter.handle);
            self.check(device.handle)?;
            drop(filter);
        }
        // OIDN can return NaN where its input held extreme values; the
        // renderer's promise is that no pixel is NaN or infinite.
        let noisy = color.pixels();
        for (out, before) in output.iter_mut().zip(noisy) {
            if !out.iter().all(|v| v.is_finite()) {
                *out = *before;
            }
        }
        Ok(Image::from_pixels(color.width(), color.height(), output))
    }

    /// OIDN's error since the last check, if any.
    ///
    /// # Safety
    /// `device` is a live device of this library.
    unsafe fn check(&self, device: Handle) -> Result<(), DenoiseError> {
        let mut message: *const c_char = std::ptr::null();
        // SAFETY: the caller's promise; OIDN leaves `message` null or
        // pointing at a NUL-terminated string valid until the next call.
        let code = unsafe { (self.get_error)(device, &mut message) };
        if code == ERROR_NONE {
            return Ok(());
        }
        let text = if message.is_null() {
            format!("error code {code}")
        } else {
            // SAFETY: as above.
            unsafe { CStr::from_ptr(message) }
                .to_string_lossy()
                .into_owned()
        };
        Err(DenoiseError::Failed(text))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The refusal names the command that installs the library, and the
    /// variable that points at it.
    #[test]
    fn refusal_names_the_install_command() {
        let e = DenoiseError::NotInstalled {
            tried: vec!["here".into()],
        };
        let text = e.to_string();
        assert!(text.contains("python3 -m pip install oidn"), "{text}");
        assert!(text.contains("HSCENE_OIDN"), "{text}");
        let e = DenoiseError::BadEnvPath {
            path: "/nowhere/lib.so".into(),
            reason: "no such file".into(),
        };
        assert!(e.to_string().contains("python3 -m pip install oidn"));
    }

    /// A wheel's layout: the library under `lib.linux.x64/` with TBB
    /// beside it, both found.
    #[test]
    fn wheel_layout_is_found() {
        let dir = tempfile::tempdir().unwrap();
        let lib = dir.path().join("lib.linux.x64");
        std::fs::create_dir(&lib).unwrap();
        std::fs::write(lib.join("libOpenImageDenoise.so.1.4.3"), b"").unwrap();
        std::fs::write(lib.join("libtbb.so.12.5"), b"").unwrap();
        let (l, t) = wheel_library(dir.path()).unwrap();
        assert!(l.ends_with("libOpenImageDenoise.so.1.4.3"));
        assert!(t.unwrap().ends_with("libtbb.so.12.5"));
        assert!(wheel_library(&dir.path().join("none")).is_none());
    }

    /// A file that is not a library is refused with the loader's reason,
    /// not a crash.
    #[test]
    fn a_non_library_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("libOpenImageDenoise.so");
        std::fs::write(&path, b"not an ELF file").unwrap();
        assert!(matches!(open(&path, None), Err(Opened::Load(_))));
    }
}
