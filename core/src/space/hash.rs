//! The 3D multi-level spatial hash over caller storage (the 3D version of
//! [`crate::internals::spatial`]): level `l` cuts space into cubes of side `L / 2^l` (`L` the
//! region's largest side); a solid of bounding radius `b` lives at the finest level whose cells
//! are at least `2b` wide, in the cell of its centre. A query looks, level by level, at the
//! cells its reach can touch (or at every solid, when that is fewer), so a test costs
//! O(levels) whatever the number of solids. Bucket collisions only add work: every solid listed
//! is tested exactly. Centres of a periodic box lie in the period; the engine queries each
//! periodic image of a candidate that can reach into it.

use crate::scalar::Scalar;

/// Number of size levels.
pub const SPACE_LEVELS: usize = 40;

/// The empty-list marker.
pub(crate) const NIL: u32 = u32::MAX;

#[derive(Clone, Copy, Debug)]
struct Level<S> {
    cell: S,
    inv: S,
    count: u32,
    max_r: S,
}

/// The multi-level hash over borrowed buckets and links.
#[derive(Debug)]
pub(crate) struct Hash3<'a, S> {
    heads: &'a mut [u32],
    next: &'a mut [u32],
    mask: usize,
    levels: [Level<S>; SPACE_LEVELS],
}

impl<'a, S: Scalar> Hash3<'a, S> {
    pub fn new(heads: &'a mut [u32], next: &'a mut [u32], extent: S) -> Option<Self> {
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
            max_r: S::ZERO,
        }; SPACE_LEVELS];
        let mut cell = extent;
        for lv in levels.iter_mut() {
            lv.cell = cell;
            lv.inv = if cell > S::ZERO { S::ONE / cell } else { S::ZERO };
            cell = cell.half();
        }
        Some(Hash3 {
            heads,
            next,
            mask: pow - 1,
            levels,
        })
    }

    fn level_for(&self, r: S) -> usize {
        let d = r + r;
        let mut l = 0usize;
        while l + 1 < SPACE_LEVELS && self.levels.get(l + 1).is_some_and(|v| d <= v.cell) {
            l += 1;
        }
        l
    }

    #[inline]
    fn bucket(&self, level: usize, c: [i64; 3]) -> usize {
        let mut h = (c[0] as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
            ^ (c[1] as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
            ^ (c[2] as u64).wrapping_mul(0x1656_67B1_9E37_79F9)
            ^ (level as u64).wrapping_mul(0x27D4_EB2F_1656_67C5);
        h ^= h >> 29;
        h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        h ^= h >> 32;
        (h as usize) & self.mask
    }

    fn cell_of(lv: &Level<S>, p: [S; 3]) -> [i64; 3] {
        [
            (p[0] * lv.inv).floor_i64(),
            (p[1] * lv.inv).floor_i64(),
            (p[2] * lv.inv).floor_i64(),
        ]
    }

    /// Adds solid `idx` with centre `p` and bounding radius `r`.
    pub fn insert(&mut self, idx: u32, p: [S; 3], r: S) {
        let l = self.level_for(r);
        let Some(lv) = self.levels.get(l).copied() else { return };
        let b = self.bucket(l, Self::cell_of(&lv, p));
        let (Some(head), Some(link)) = (self.heads.get(b).copied(), self.next.get_mut(idx as usize)) else {
            return;
        };
        *link = head;
        if let Some(h) = self.heads.get_mut(b) {
            *h = idx;
        }
        if let Some(lv) = self.levels.get_mut(l) {
            lv.count = lv.count.saturating_add(1);
            lv.max_r = lv.max_r.max(r);
        }
    }

    /// The largest bounding radius stored.
    pub fn max_r(&self) -> S {
        self.levels.iter().fold(S::ZERO, |m, l| m.max(l.max_r))
    }

    /// Calls `f` for every solid whose bounding ball may come within `reach` of `p` (and
    /// possibly others), coarsest level first; stops and returns false as soon as `f` does.
    pub fn query(&self, p: [S; 3], reach: S, total: u32, mut f: impl FnMut(u32) -> bool) -> bool {
        for (level, lv) in self.levels.iter().enumerate() {
            if lv.count == 0 {
                continue;
            }
            let m = reach + lv.max_r;
            let lo = Self::cell_of(lv, [p[0] - m, p[1] - m, p[2] - m]);
            let hi = Self::cell_of(lv, [p[0] + m, p[1] + m, p[2] + m]);
            let span = |a: usize| {
                hi.get(a)
                    .copied()
                    .unwrap_or(0)
                    .saturating_sub(lo.get(a).copied().unwrap_or(0))
                    .saturating_add(1)
            };
            let cells = span(0).saturating_mul(span(1)).saturating_mul(span(2));
            if cells >= i64::from(total) {
                return (0..total).all(f);
            }
            for cx in lo[0]..=hi[0] {
                for cy in lo[1]..=hi[1] {
                    for cz in lo[2]..=hi[2] {
                        let mut j = self.heads.get(self.bucket(level, [cx, cy, cz])).copied().unwrap_or(NIL);
                        while j != NIL {
                            if !f(j) {
                                return false;
                            }
                            j = self.next.get(j as usize).copied().unwrap_or(NIL);
                        }
                    }
                }
            }
        }
        true
    }
}
