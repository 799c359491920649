//! The files a compile reads (meshes, texture images), kept for the next
//! compile of the same scene.
//!
//! Within one compile a file named by forty statements is read and parsed
//! once. A caller that compiles the same scene again and again (the
//! language server, on every edit) keeps one cache per scene: a file is
//! read again only when its size, modification time or inode changed, and
//! the files the last compile did not use are let go, so the cache never
//! holds more than one compile needs.
//!
//! An animation's frames are compiled one by one, and a file read for the
//! first must not be missing or different by the seventh: a cache made with
//! [`FileCache::pinned`] keeps every file as first read, whatever happens
//! to it on disk, so every frame sees the same files and none fails late.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::SystemTime;

use hscene_ir::TextureImage;

use crate::mesh_file::MeshData;

/// A shared cache of parsed files; clones share it.
#[derive(Clone, Default)]
pub struct FileCache {
    inner: Arc<Mutex<Inner>>,
}

impl std::fmt::Debug for FileCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let inner = self.lock();
        f.debug_struct("FileCache")
            .field("meshes", &inner.meshes.len())
            .field("images", &inner.images.len())
            .finish()
    }
}

#[derive(Default)]
struct Inner {
    /// Bumped by every compile; an entry remembers the last that used it.
    generation: u64,
    /// Files are kept as first read, never read again nor let go.
    pinned: bool,
    meshes: HashMap<PathBuf, Entry<MeshData>>,
    images: HashMap<PathBuf, Entry<TextureImage>>,
}

struct Entry<T> {
    stamp: Stamp,
    used: u64,
    value: Arc<T>,
}

/// What tells a file changed without reading it.
#[derive(Clone, Copy, PartialEq, Eq)]
struct Stamp {
    len: u64,
    modified: Option<SystemTime>,
    inode: u64,
}

impl Stamp {
    fn of(path: &Path) -> Option<Stamp> {
        let meta = std::fs::metadata(path).ok()?;
        #[cfg(unix)]
        let inode = std::os::unix::fs::MetadataExt::ino(&meta);
        #[cfg(not(unix))]
        let inode = 0;
        Some(Stamp {
            len: meta.len(),
            modified: meta.modified().ok(),
            inode,
        })
    }
}

/// The value for `path`, from the map if its stamp is unchanged. The stamp
/// is taken before the read, so a file changed during the read shows a
/// different stamp next time and is read again.
fn cached<T, E>(
    map: &mut HashMap<PathBuf, Entry<T>>,
    (generation, pinned): (u64, bool),
    path: &Path,
    load: impl FnOnce(&Path) -> Result<T, E>,
) -> Result<Arc<T>, E> {
    if pinned && let Some(entry) = map.get_mut(path) {
        entry.used = generation;
        return Ok(Arc::clone(&entry.value));
    }
    let stamp = Stamp::of(path);
    if let (Some(stamp), Some(entry)) = (stamp, map.get_mut(path))
        && entry.stamp == stamp
    {
        entry.used = generation;
        return Ok(Arc::clone(&entry.value));
    }
    let value = Arc::new(load(path)?);
    match stamp {
        Some(stamp) => {
            map.insert(
                path.to_path_buf(),
                Entry {
                    stamp,
                    used: generation,
                    value: Arc::clone(&value),
                },
            );
        }
        // A pinned cache keeps even a file it cannot stamp.
        None if pinned => {
            let stamp = Stamp {
                len: 0,
                modified: None,
                inode: 0,
            };
            map.insert(
                path.to_path_buf(),
                Entry {
                    stamp,
                    used: generation,
                    value: Arc::clone(&value),
                },
            );
        }
        None => {
            map.remove(path);
        }
    }
    Ok(value)
}

impl FileCache {
    /// A cache that keeps every file as first read (module docs), for the
    /// compiles of one animation.
    pub fn pinned() -> FileCache {
        let cache = FileCache::default();
        cache.lock().pinned = true;
        cache
    }

    fn lock(&self) -> MutexGuard<'_, Inner> {
        // A panic while holding the lock leaves maps that are still whole.
        self.inner
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Starts a compile: what the compile before did not use is let go.
    pub(crate) fn start_compile(&self) {
        let mut inner = self.lock();
        let last = inner.generation;
        inner.generation += 1;
        if inner.pinned {
            return;
        }
        inner.meshes.retain(|_, e| e.used == last);
        inner.images.retain(|_, e| e.used == last);
    }

    /// The mesh at `path`, read by `load` unless it is cached and unchanged.
    pub(crate) fn mesh<E>(
        &self,
        path: &Path,
        load: impl FnOnce(&Path) -> Result<MeshData, E>,
    ) -> Result<Arc<MeshData>, E> {
        let mut inner = self.lock();
        let key = (inner.generation, inner.pinned);
        cached(&mut inner.meshes, key, path, load)
    }

    /// The image at `path`, read by `load` unless it is cached and unchanged.
    pub(crate) fn image<E>(
        &self,
        path: &Path,
        load: impl FnOnce(&Path) -> Result<TextureImage, E>,
    ) -> Result<Arc<TextureImage>, E> {
        let mut inner = self.lock();
        let key = (inner.generation, inner.pinned);
        cached(&mut inner.images, key, path, load)
    }

    /// How many files are held (meshes and images).
    pub fn len(&self) -> usize {
        let inner = self.lock();
        inner.meshes.len() + inner.images.len()
    }

    /// Whether no file is held.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mesh_load(count: &std::cell::Cell<u32>) -> impl FnOnce(&Path) -> Result<MeshData, ()> + '_ {
        move |path| {
            count.set(count.get() + 1);
            crate::mesh_file::load(path).map_err(|_| ())
        }
    }

    #[test]
    fn a_file_is_read_again_only_when_it_changed() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.obj");
        std::fs::write(&path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        let cache = FileCache::default();
        let reads = std::cell::Cell::new(0);
        cache.start_compile();
        for _ in 0..40 {
            cache.mesh(&path, mesh_load(&reads)).unwrap();
        }
        assert_eq!(reads.get(), 1, "forty uses in one compile read once");
        cache.start_compile();
        cache.mesh(&path, mesh_load(&reads)).unwrap();
        assert_eq!(reads.get(), 1, "the next compile reuses it");
        // A different length is a different file.
        std::fs::write(&path, "v 0 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\n\n").unwrap();
        cache.start_compile();
        let mesh = cache.mesh(&path, mesh_load(&reads)).unwrap();
        assert_eq!(reads.get(), 2);
        assert!(mesh.positions.iter().any(|p| p.x == 2.0));
        // A compile that does not use it lets it go.
        cache.start_compile();
        cache.start_compile();
        assert!(cache.is_empty());
    }

    #[test]
    fn a_pinned_cache_keeps_files_deleted_or_changed_since() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.obj");
        std::fs::write(&path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        let cache = FileCache::pinned();
        let reads = std::cell::Cell::new(0);
        cache.start_compile();
        cache.mesh(&path, mesh_load(&reads)).unwrap();
        std::fs::write(&path, "v 0 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\n\n").unwrap();
        cache.start_compile();
        let mesh = cache.mesh(&path, mesh_load(&reads)).unwrap();
        assert!(mesh.positions.iter().all(|p| p.x != 2.0));
        std::fs::remove_file(&path).unwrap();
        cache.start_compile();
        cache.start_compile();
        assert!(cache.mesh(&path, mesh_load(&reads)).is_ok());
        assert_eq!(reads.get(), 1);
    }
}
