//! The 1D multi-level hash of placed segments: level `l` cuts the interval into cells of
//! length `L / 2^l`; a segment lives at the finest level whose cells are at least its length
//! long, in the cell of its start. Buckets and links are borrowed from the caller; nothing here
//! allocates or panics.

use super::{LINE_LEVELS, NIL};
use crate::scalar::Scalar;

#[derive(Clone, Copy, Debug)]
struct Level<S> {
    cell: S,
    inv: S,
    count: u32,
    max_len: S,
}

/// The multi-level 1D hash over borrowed buckets and links.
#[derive(Debug)]
pub(super) struct LineHash<'a, S> {
    heads: &'a mut [u32],
    next: &'a mut [u32],
    mask: usize,
    levels: [Level<S>; LINE_LEVELS],
}

impl<'a, S: Scalar> LineHash<'a, S> {
    pub(super) fn new(heads: &'a mut [u32], next: &'a mut [u32], extent: S) -> Option<Self> {
        if heads.is_empty() {
            return None;
        }
        let mut pow = 1usize;
        while pow <= heads.len() / 2 {
            pow *= 2;
        }
        heads.iter_mut().for_each(|h| *h = NIL);
        next.iter_mut().for_each(|n| *n = NIL);
        let mut levels = [Level {
            cell: extent,
            inv: S::ONE,
            count: 0,
            max_len: S::ZERO,
        }; LINE_LEVELS];
        let mut cell = extent;
        for lv in levels.iter_mut() {
            lv.cell = cell;
            lv.inv = S::ONE / cell;
            cell = cell.half();
        }
        Some(LineHash {
            heads,
            next,
            mask: pow - 1,
            levels,
        })
    }

    fn level_for(&self, len: S) -> usize {
        let mut l = 0usize;
        while l + 1 < LINE_LEVELS && self.levels.get(l + 1).is_some_and(|v| len <= v.cell) {
            l += 1;
        }
        l
    }

    #[inline]
    fn bucket(&self, level: usize, cx: i64) -> usize {
        let mut h = (cx as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ (level as u64).wrapping_mul(0x1656_67B1_9E37_79F9);
        h ^= h >> 29;
        h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        h ^= h >> 32;
        (h as usize) & self.mask
    }

    pub(super) fn insert(&mut self, idx: u32, start: S, len: S) {
        let l = self.level_for(len);
        let Some(lv) = self.levels.get(l).copied() else { return };
        let b = self.bucket(l, (start * lv.inv).floor_i64());
        let (Some(head), Some(link)) = (self.heads.get(b).copied(), self.next.get_mut(idx as usize)) else {
            return;
        };
        *link = head;
        if let Some(h) = self.heads.get_mut(b) {
            *h = idx;
        }
        if let Some(lv) = self.levels.get_mut(l) {
            lv.count = lv.count.saturating_add(1);
            lv.max_len = lv.max_len.max(len);
        }
    }

    /// Calls `f` for every segment index that may meet `[lo, hi]` (those whose start lies in
    /// `[lo - longest at its level, hi]`, and possibly others), coarsest level first: a random
    /// candidate most often lands in one of the long, early segments, so it is rejected after
    /// a look at a few coarse cells. Stops as soon as `f` returns `false`.
    pub(super) fn query(&self, lo: S, hi: S, total: u32, mut f: impl FnMut(u32) -> bool) -> bool {
        for (level, lv) in self.levels.iter().enumerate() {
            if lv.count == 0 {
                continue;
            }
            let c0 = ((lo - lv.max_len) * lv.inv).floor_i64();
            let c1 = (hi * lv.inv).floor_i64();
            if c1.saturating_sub(c0) >= i64::from(total) {
                return (0..total).all(f);
            }
            // An inclusive range: `c1` may be `i64::MAX` (a saturated coordinate), where a
            // counter stepped past it would wrap around and never stop.
            for cx in c0..=c1 {
                let mut j = self.heads.get(self.bucket(level, cx)).copied().unwrap_or(NIL);
                while j != NIL {
                    if !f(j) {
                        return false;
                    }
                    j = self.next.get(j as usize).copied().unwrap_or(NIL);
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
        let Some(mut h) = LineHash::<f64>::new(&mut heads, &mut next, 100.0) else {
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
