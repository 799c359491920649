//! A fuzz target for the front end's memory: scenes grown from statements
//! of every section, right and broken (repeated, mixed, cut, spliced,
//! bit-flipped), each compiled and formatted under a counting allocator.
//! (What geometry costs is bounded apart, by the primitives budget.) The peak heap of a
//! compile must stay within [`BYTES_PER_INPUT_BYTE`] times the input plus a
//! fixed allowance, whatever the input: the figure `docs/limits.md` gives.
//! Runs for `HSCENE_FUZZ_SECONDS` (CI: 60), else 24 inputs. A mutation
//! loop from a fixed seed, not coverage-guided: `cargo fuzz` needs a
//! nightly compiler, and CI has the stable one.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use hscene_test_support::{FuzzClock, SplitMix64};

/// Counts the bytes allocated now and the most at once since the last reset.
struct Counting;

static NOW: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is passed to the system allocator unchanged; the
// counters are only arithmetic.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = NOW.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        p
    }
    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        unsafe { System.dealloc(p, layout) };
        NOW.fetch_sub(layout.size(), Ordering::Relaxed);
    }
    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let q = unsafe { System.realloc(p, layout, new_size) };
        if !q.is_null() {
            if new_size >= layout.size() {
                let now = NOW.fetch_add(new_size - layout.size(), Ordering::Relaxed) + new_size
                    - layout.size();
                PEAK.fetch_max(now, Ordering::Relaxed);
            } else {
                NOW.fetch_sub(layout.size() - new_size, Ordering::Relaxed);
            }
        }
        q
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The most heap a compile may hold per byte of its input (the worst
/// valid inputs measured near 90: `docs/limits.md`).
const BYTES_PER_INPUT_BYTE: usize = 128;
/// Plus this much whatever the input (tables, the report).
const ALLOWANCE: usize = 16 << 20;

const PIECES: &[&str] = &[
    ";",
    "p = (1,1,1); ",
    "Sphere (0.1,0.2,0.3), 0.01, #1; ",
    "Sphere %q, 1, #2; ",
    "a ",
    "(((((1))))); ",
    "x: hline((0,0,0), (0,0.5,0)); ",
    "%1->Rotate(%x, 0.1), animate; ",
    "Honeycomb {4,3,5}, #1, depth = 1; ",
    "/* c */ ",
    "\"unterminated ",
    "1e999 ",
    "glass: ambient = (0.1,0.1,0.1), diffuse = (0.2,0.2,0.2), alpha = 0.1; ",
    "(0, 0.3, 0.1), (1, 1, 1), (1, 1, 1); ",
    "from = (0,0,0); to = (0,0,0.3); fov = 1e308; ",
    "Polygon ((0,0,0), (0.1,0,0), (0,0.1,0)), #1; ",
    "Rod (0,0,0), (0.1,0,0), 0.01, #1; ",
    "b: Cube 0.1, #1, edges = 40; ",
    "Mesh \"missing.obj\", 0.2, #1; ",
    "@b->Translate(%x, 1); ",
];

fn input(rng: &mut SplitMix64) -> String {
    let target = 1 << (14 + rng.below(5)); // 16 KiB to 256 KiB
    let mut text = String::new();
    let sections = [
        "Points",
        "Objects",
        "BRDFs",
        "Transformations",
        "Globals",
        "Lights",
    ];
    while text.len() < target {
        text.push_str(sections[rng.below(sections.len())]);
        text.push_str(" { ");
        let piece = PIECES[rng.below(PIECES.len())];
        let stop = text.len() + rng.below(target);
        while text.len() < stop.min(target) {
            text.push_str(piece);
            if rng.below(16) == 0 {
                text.push_str(PIECES[rng.below(PIECES.len())]);
            }
        }
        text.push_str("} ");
    }
    let mut bytes = text.into_bytes();
    for _ in 0..rng.below(4) {
        let at = rng.below(bytes.len());
        match rng.below(3) {
            0 => bytes[at] = b"{};,()%#@ \n"[rng.below(11)],
            1 => bytes.truncate(at.max(1)),
            _ => {
                let end = (at + rng.below(4096)).min(bytes.len());
                let piece = bytes[at..end].to_vec();
                let to = rng.below(bytes.len());
                bytes.splice(to..to, piece);
            }
        }
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

#[test]
fn fuzz_front_end_memory() {
    let mut clock = FuzzClock::new(24);
    let mut rng = SplitMix64::new(41);
    let mut worst = 0.0f64;
    while clock.next_input() {
        let text = input(&mut rng);
        let base = NOW.load(Ordering::Relaxed);
        PEAK.store(base, Ordering::Relaxed);
        let compiled = hscene_lang::compile(&text);
        let _ = hscene_lang::format(&text);
        drop(compiled);
        let peak = PEAK.load(Ordering::Relaxed).saturating_sub(base);
        // Fixed costs blur the ratio of small inputs.
        if text.len() >= 1 << 17 {
            worst = worst.max(peak as f64 / text.len() as f64);
        }
        assert!(
            peak <= BYTES_PER_INPUT_BYTE * text.len() + ALLOWANCE,
            "{} bytes of input held {peak} bytes at the peak; it starts {:?}",
            text.len(),
            &text[..text.len().min(200)]
        );
    }
    eprintln!(
        "fuzz_front_end_memory: {} inputs, worst {worst:.0} bytes per input byte (inputs of 128 KiB and more)",
        clock.runs()
    );
}

/// The nodes a scene of many statements is made of stay as small as the
/// memory work left them (docs/performance.md, "Memory of scenes of many
/// objects"): a tuple of three numbers holds three values, a material's
/// statement five clauses, and the lowered scene one material per
/// statement. A field that grows one of them grows every such scene.
#[test]
fn syntax_nodes_and_materials_stay_small() {
    use hscene_lang::syntax::{Clause, Ident, Statement, Value};
    use std::mem::size_of;
    assert_eq!(size_of::<hscene_lang::Span>(), 8);
    assert_eq!(size_of::<Ident>(), 32);
    assert_eq!(size_of::<Value>(), 40);
    assert_eq!(size_of::<Clause>(), 88);
    assert_eq!(size_of::<Statement>(), 56);
    assert_eq!(size_of::<hscene_lang::ir::Material>(), 192);
}
