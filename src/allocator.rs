//! The process's allocator: the system's, with a clean end when memory runs
//! out. Rust's default on a failed allocation is to abort (SIGABRT, a core,
//! and whatever temporary output file was being written left behind). Here
//! the temporary outputs are removed, one line says what happened, and the
//! process exits with status 2 like any other I/O failure. Memory is
//! bounded by the documented limits (docs/limits.md), so this is met only
//! under an address-space limit (`ulimit -v`) or on a machine too small
//! for the scene. An allocation whose failure its caller handles (the
//! image's, `hrender::allocation_is_fallible`) gets the failure back.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, Ordering};

use crate::exit::EXIT_USAGE_OR_IO;

pub struct Allocator;

/// One malloc arena for every thread (glibc). By default each thread that
/// allocates gets an arena of its own: the scene's preparation runs on the
/// render threads, so it could not reuse the pages the front end had just
/// freed (its syntax tree) in the main thread's arena, and peak memory was
/// both summed. Measured (docs/performance.md, "Memory of scenes of many
/// objects"): peak resident memory of 10,000 spheres at 800x800 from 53.5
/// to 42.5 MiB, 100,000 spheres at 8x8 from 247 to 169 MiB, with the same
/// CPU time (the render loop does not allocate per ray).
pub fn share_one_arena() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets a tuning parameter of glibc's malloc; it is
    // called before any thread other than main exists.
    unsafe {
        libc::mallopt(libc::M_ARENA_MAX, 1);
    }
}

/// Set by the first failure: a second one (the cleanup's own small
/// allocations failing too) exits at once.
static FAILING: AtomicBool = AtomicBool::new(false);

// SAFETY: every call goes to the system allocator unchanged; a null result
// returns only where its caller handles it, else the process exits.
unsafe impl GlobalAlloc for Allocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if p.is_null() && !hrender::allocation_is_fallible() {
            out_of_memory(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if p.is_null() && !hrender::allocation_is_fallible() {
            out_of_memory(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        unsafe { System.dealloc(p, layout) }
    }

    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let q = unsafe { System.realloc(p, layout, new_size) };
        if q.is_null() && !hrender::allocation_is_fallible() {
            out_of_memory(new_size);
        }
        q
    }
}

/// Removes the temporary outputs, says so on stderr, and exits with status
/// 2, allocating nothing itself (the number is formatted on the stack and
/// written with `write(2)`).
#[cold]
fn out_of_memory(bytes: usize) -> ! {
    if !FAILING.swap(true, Ordering::SeqCst) {
        hrender::try_remove_unfinished_outputs();
    }
    let mut line = [0u8; 96];
    let head = b"error: out of memory (an allocation of ";
    let tail = b" bytes failed); see docs/limits.md\n";
    let mut digits = [0u8; 20];
    let mut n = bytes;
    let mut k = digits.len();
    loop {
        k -= 1;
        digits[k] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    let mut len = 0;
    for part in [&head[..], &digits[k..], &tail[..]] {
        line[len..len + part.len()].copy_from_slice(part);
        len += part.len();
    }
    // SAFETY: writing a stack buffer to stderr, then ending the process
    // without running anything else (no destructor, no allocation).
    unsafe {
        libc::write(2, line.as_ptr().cast(), len);
        libc::_exit(i32::from(EXIT_USAGE_OR_IO));
    }
}
