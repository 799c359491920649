//! What the rays of a render did: counted per row, summed for the image.

/// Per-ray outcome counters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Rays traced (primary, secondary, shadow).
    pub rays: u64,
    /// Numeric failures: rays or hits that were not finite, and shading
    /// results that were not finite. Each is replaced by the background and
    /// counted, never silently.
    pub failures: u64,
    /// Primary rays whose ray tree the [`RayBudget`](crate::RayBudget) cut
    /// short.
    pub cut_trees: u64,
}

impl TraceStats {
    /// Sum two counters.
    pub fn merge(self, o: TraceStats) -> TraceStats {
        TraceStats {
            rays: self.rays + o.rays,
            failures: self.failures + o.failures,
            cut_trees: self.cut_trees + o.cut_trees,
        }
    }
}
