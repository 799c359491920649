//! Allocations whose failure the renderer handles itself (the image, with
//! `try_reserve`): a process's allocator that ends the process when memory
//! runs out (the `hscene` binary's does) asks
//! [`allocation_is_fallible`] first and, inside such an allocation, returns
//! the failure to the caller instead.

use std::cell::Cell;

thread_local! {
    // `const`, with no destructor: reading it never allocates, so the
    // allocator itself may read it.
    static FALLIBLE: Cell<bool> = const { Cell::new(false) };
}

/// Whether the allocation now being made on this thread is one whose
/// failure its caller handles.
pub fn allocation_is_fallible() -> bool {
    FALLIBLE.try_with(Cell::get).unwrap_or(false)
}

/// Runs `f`, its allocations marked as handled by it.
pub(crate) fn fallibly<T>(f: impl FnOnce() -> T) -> T {
    let _ = FALLIBLE.try_with(|c| c.set(true));
    let out = f();
    let _ = FALLIBLE.try_with(|c| c.set(false));
    out
}
