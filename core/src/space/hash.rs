//! The 3D walk of the multi-level spatial hash ([`crate::internals::spatial::MultiHash`]):
//! level `l` cuts space into cubes of side `L / 2^l` (`L` the region's largest side); a solid
//! of bounding radius `b` lives at the finest level whose cells are at least `2b` wide, in the
//! cell of its centre. A query looks, level by level, at the cells its reach can touch (or at
//! every solid, when that is fewer), so a test costs O(levels) whatever the number of solids.
//! Bucket collisions only add work: every solid listed is tested exactly. Centres of a
//! periodic box lie in the period; the engine queries each periodic image of a candidate that
//! can reach into it.

use crate::scalar::Scalar;
use crate::spatial::MultiHash;

/// Number of size levels.
pub const SPACE_LEVELS: usize = 40;

pub(crate) use crate::spatial::NIL;

/// The multi-level hash over borrowed buckets and links.
pub(crate) type Hash3<'a, S> = MultiHash<'a, S, 3, SPACE_LEVELS>;

impl<S: Scalar> Hash3<'_, S> {
    /// Adds solid `idx` with centre `p` and bounding radius `r`.
    pub fn insert(&mut self, idx: u32, p: [S; 3], r: S) {
        self.insert_at(idx, p, r + r, r);
    }

    /// The largest bounding radius stored.
    pub fn max_r(&self) -> S {
        self.max_reach()
    }

    /// Calls `f` for every solid whose bounding ball may come within `reach` of `p` (and
    /// possibly others), coarsest level first; stops and returns false as soon as `f` does.
    pub fn query(&self, p: [S; 3], reach: S, total: u32, mut f: impl FnMut(u32) -> bool) -> bool {
        for (level, lv) in self.levels().iter().enumerate() {
            if lv.is_empty() {
                continue;
            }
            let m = reach + lv.max;
            let lo = lv.cell([p[0] - m, p[1] - m, p[2] - m]);
            let hi = lv.cell([p[0] + m, p[1] + m, p[2] + m]);
            let span = |a: i64, b: i64| b.saturating_sub(a).saturating_add(1);
            let cells = span(lo[0], hi[0])
                .saturating_mul(span(lo[1], hi[1]))
                .saturating_mul(span(lo[2], hi[2]));
            if cells >= i64::from(total) {
                return (0..total).all(f);
            }
            for cx in lo[0]..=hi[0] {
                for cy in lo[1]..=hi[1] {
                    for cz in lo[2]..=hi[2] {
                        if !self.walk(level, [cx, cy, cz], &mut f) {
                            return false;
                        }
                    }
                }
            }
        }
        true
    }
}
