//! The 1D walk of the multi-level hash ([`crate::internals::spatial::MultiHash`]) over placed
//! segments: level `l` cuts the interval into cells of length `L / 2^l`; a segment lives at the
//! finest level whose cells are at least its length long, in the cell of its start. Buckets and
//! links are borrowed from the caller; nothing here allocates or panics.

use super::LINE_LEVELS;
use crate::scalar::Scalar;
use crate::spatial::MultiHash;

/// The multi-level 1D hash over borrowed buckets and links.
pub(super) type LineHash<'a, S> = MultiHash<'a, S, 1, LINE_LEVELS>;

impl<S: Scalar> LineHash<'_, S> {
    /// Adds segment `idx` starting at `start`, of length `len`.
    pub(super) fn insert(&mut self, idx: u32, start: S, len: S) {
        self.insert_at(idx, [start], len, len);
    }

    /// Calls `f` for every segment index that may meet `[lo, hi]` (those whose start lies in
    /// `[lo - longest at its level, hi]`, and possibly others), coarsest level first: a random
    /// candidate most often lands in one of the long, early segments, so it is rejected after
    /// a look at a few coarse cells. Stops as soon as `f` returns `false`.
    // Inlined into the test that asks it, as the 2D query is: a call per candidate costs the
    // paper's sampler a fifth more instructions.
    #[inline(always)]
    pub(super) fn query(&self, lo: S, hi: S, total: u32, mut f: impl FnMut(u32) -> bool) -> bool {
        // A plain loop over every level: through the filtered iterator the paper's sampler
        // spills registers on each level and takes 6% more instructions.
        for (level, lv) in self.levels().iter().enumerate() {
            if lv.is_empty() {
                continue;
            }
            let ([c0], [c1]) = (lv.cell([lo - lv.max]), lv.cell([hi]));
            if c1.saturating_sub(c0) >= i64::from(total) {
                return (0..total).all(f);
            }
            // An inclusive range: `c1` may be `i64::MAX` (a saturated coordinate), where a
            // counter stepped past it would wrap around and never stop.
            for cx in c0..=c1 {
                if !self.walk(level, [cx], &mut f) {
                    return false;
                }
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_query_at_the_end_of_the_coordinate_range_stops() {
        // Coordinates this large saturate to i64::MAX cells; the scan must end there.
        let (mut heads, mut next) = ([0u32; 8], [0u32; 4]);
        let Ok(mut h) = LineHash::<f64>::new(&mut heads, &mut next, 100.0) else {
            panic!("hash")
        };
        h.insert(0, 10.0, 1.0);
        let mut seen = 0;
        assert!(h.query(f64::MAX, f64::MAX, 4, |_| {
            seen += 1;
            true
        }));
        assert!(seen <= 4);
    }
}
