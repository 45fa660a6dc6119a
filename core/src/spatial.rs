//! A fixed-capacity, multi-level spatial hash over caller-provided storage.
//!
//! Shapes span many orders of magnitude in size, so one grid cannot serve them all. Level `l`
//! is a grid of square cells of side `s_l = s_0 / 2^l` (`s_0` is the region's larger side);
//! a shape of bounding radius `r` lives at the finest level with `r <= s_l / 2`, in the cell
//! holding its centre. The cells of every level share one table of buckets, indexed by a hash
//! of (level, cell x, cell y), each bucket the head of an intrusive list through `next`.
//!
//! A query visits, level by level, the cells within reach of the candidate (the candidate's
//! radius plus the largest radius stored at that level plus the gap): since shapes are placed
//! from large to small, that is a 2x2 or 3x3 block per occupied level, so a trial costs O(1)
//! expected whatever the spread of sizes. Bucket collisions only add work, never change an
//! answer: every listed shape is tested exactly, so results do not depend on the table size.
//!
//! Storage: one `u32` per shape slot (`next`) plus the bucket table, both borrowed from the
//! caller. Nothing here allocates or panics.

use crate::scalar::Scalar;

/// Number of size levels (cell sides from `s_0` down to `s_0 / 2^27`; smaller shapes share
/// the finest level, which only costs time). 28 levels reach shapes a 2^28th of the region's
/// size, past a million shapes at any c, and keep the engine 384 bytes smaller on the board
/// than 40 would.
pub const LEVELS: usize = 28;

/// The empty-list marker.
const NIL: u32 = u32::MAX;

#[derive(Clone, Copy, Debug)]
struct Level<S> {
    cell: S,
    inv: S,
    count: u32,
    max_r: S,
}

/// The spatial hash. `heads` holds the buckets (its largest power-of-two prefix is used),
/// `next` one link per shape slot.
#[derive(Debug)]
pub struct SpatialHash<'a, S> {
    heads: &'a mut [u32],
    next: &'a mut [u32],
    mask: usize,
    levels: [Level<S>; LEVELS],
}

/// Why the hash could not be built.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NoBuckets;

impl<'a, S: Scalar> SpatialHash<'a, S> {
    /// A hash over `heads` (at least one bucket) and `next` (one per shape slot), for a region
    /// whose larger side is `extent`.
    pub fn new(heads: &'a mut [u32], next: &'a mut [u32], extent: S) -> Result<Self, NoBuckets> {
        if heads.is_empty() {
            return Err(NoBuckets);
        }
        let mut pow = 1usize;
        while pow <= heads.len() / 2 {
            pow *= 2;
        }
        for h in heads.iter_mut() {
            *h = NIL;
        }
        for n in next.iter_mut() {
            *n = NIL;
        }
        let mut levels = [Level {
            cell: extent,
            inv: S::ONE,
            count: 0,
            max_r: S::ZERO,
        }; LEVELS];
        let mut cell = extent;
        for lv in levels.iter_mut() {
            lv.cell = cell;
            // Cell coordinates are `x * inv` everywhere (insert and query alike), so the
            // mapping is monotone and consistent whatever the rounding of `inv`.
            lv.inv = S::ONE / cell;
            cell = cell.half();
        }
        Ok(SpatialHash {
            heads,
            next,
            mask: pow - 1,
            levels,
        })
    }

    /// The level a shape of bounding radius `r` is stored at.
    pub fn level_for(&self, r: S) -> usize {
        let mut l = 0usize;
        while l + 1 < LEVELS {
            let next_cell = self.levels.get(l + 1).map_or(S::ZERO, |v| v.cell);
            if r + r <= next_cell {
                l += 1;
            } else {
                break;
            }
        }
        l
    }

    /// The bucket of cell (cx, cy) at `level`: a hash of the level and the row, plus the
    /// column. Cells side by side in a row share cache lines, so a query's 2x2 or 3x3 block
    /// touches two or three lines instead of four or nine.
    #[inline]
    fn bucket(&self, level: usize, cx: i64, cy: i64) -> usize {
        let mut h = (cy as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F) ^ (level as u64).wrapping_mul(0x1656_67B1_9E37_79F9);
        h ^= h >> 29;
        h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        h ^= h >> 32;
        (h.wrapping_add(cx as u64) as usize) & self.mask
    }

    /// Adds shape `idx` centred at (x, y) with bounding radius `r`. `idx` must be below the
    /// length of `next`; otherwise nothing is stored and `false` is returned.
    pub fn insert(&mut self, idx: u32, x: S, y: S, r: S) -> bool {
        let l = self.level_for(r);
        let Some(lv) = self.levels.get(l).copied() else { return false };
        let b = self.bucket(l, (x * lv.inv).floor_i64(), (y * lv.inv).floor_i64());
        let (Some(head), Some(link)) = (self.heads.get(b).copied(), self.next.get_mut(idx as usize)) else {
            return false;
        };
        *link = head;
        if let Some(h) = self.heads.get_mut(b) {
            *h = idx;
        }
        if let Some(lv) = self.levels.get_mut(l) {
            lv.count = lv.count.saturating_add(1);
            lv.max_r = lv.max_r.max(r);
        }
        true
    }

    /// The levels that hold shapes, finest first, as `(level, largest radius)`. Finest first
    /// pays: a candidate that reaches the exact tests usually sits in the gasket, next to the
    /// small shapes that were placed last.
    pub fn occupied(&self) -> impl Iterator<Item = (usize, S)> + '_ {
        self.levels
            .iter()
            .enumerate()
            .rev()
            .filter(|(_, v)| v.count > 0)
            .map(|(i, v)| (i, v.max_r))
    }

    /// Calls `f` with every shape index at `level` whose cell meets the box
    /// `[x0, x1] x [y0, y1]` given as `[x0, y0, x1, y1]` (and possibly others). Stops and returns `false` as soon as `f`
    /// does. When the box spans more cells than `total` shapes, calls `f` for every index in
    /// `0..total` instead, which is cheaper and still complete.
    // Inlined into each caller's closure: left to itself the compiler sometimes keeps an
    // out-of-line copy per caller, which costs a 20,000-circle fill 0.5% more instructions.
    #[inline(always)]
    pub fn query(&self, level: usize, bbox: [S; 4], total: u32, mut f: impl FnMut(u32) -> bool) -> bool {
        let [x0, y0, x1, y1] = bbox;
        let Some(lv) = self.levels.get(level) else { return true };
        let (cx0, cx1) = ((x0 * lv.inv).floor_i64(), (x1 * lv.inv).floor_i64());
        let (cy0, cy1) = ((y0 * lv.inv).floor_i64(), (y1 * lv.inv).floor_i64());
        let span = cx1
            .saturating_sub(cx0)
            .saturating_add(1)
            .saturating_mul(cy1.saturating_sub(cy0).saturating_add(1));
        if span > i64::from(total) {
            return (0..total).all(f);
        }
        // Inclusive ranges: a bound may be `i64::MAX` (a saturated coordinate), where a counter
        // stepped past it would wrap around and never stop.
        for cy in cy0..=cy1 {
            for cx in cx0..=cx1 {
                let mut j = self.heads.get(self.bucket(level, cx, cy)).copied().unwrap_or(NIL);
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
        let Ok(mut h) = SpatialHash::<f64>::new(&mut heads, &mut next, 100.0) else {
            panic!("hash")
        };
        assert!(h.insert(0, 10.0, 10.0, 1.0));
        let mut seen = 0;
        let far = f64::MAX;
        assert!(h.query(0, [far, far, far, far], 4, |_| {
            seen += 1;
            true
        }));
        assert!(seen <= 4);
    }
}
