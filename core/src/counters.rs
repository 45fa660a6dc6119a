//! Counts of the engine's geometric work, for benchmarks: with the `counters` feature, every
//! exact test of a candidate against one placed shape (past the bounding discs) and every
//! walk of two motifs' edge trees is counted in a process-wide atomic; without it the
//! counting compiles to nothing. Counting never changes a result.

#[cfg(feature = "counters")]
mod on {
    use core::sync::atomic::{AtomicU64, Ordering};

    pub(super) static EXACT: AtomicU64 = AtomicU64::new(0);
    pub(super) static WALKS: AtomicU64 = AtomicU64::new(0);

    pub(crate) fn bump(c: &AtomicU64) {
        c.fetch_add(1, Ordering::Relaxed);
    }

    /// Exact tests of a candidate against one placed shape since the last [`reset`].
    pub fn exact_tests() -> u64 {
        EXACT.load(Ordering::Relaxed)
    }

    /// Walks of two motifs' edge trees (exact tests the inner covers did not decide) since
    /// the last [`reset`].
    pub fn edge_walks() -> u64 {
        WALKS.load(Ordering::Relaxed)
    }

    /// Sets both counts to zero.
    pub fn reset() {
        EXACT.store(0, Ordering::Relaxed);
        WALKS.store(0, Ordering::Relaxed);
    }
}

#[cfg(feature = "counters")]
pub use on::{edge_walks, exact_tests, reset};

/// Counts an exact test.
#[inline(always)]
pub(crate) fn exact() {
    #[cfg(feature = "counters")]
    on::bump(&on::EXACT);
}

/// Counts a walk of two edge trees.
#[inline(always)]
pub(crate) fn walk() {
    #[cfg(feature = "counters")]
    on::bump(&on::WALKS);
}
