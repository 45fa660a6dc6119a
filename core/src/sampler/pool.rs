//! Where the cells live in the caller's slice: the live cells at its start, grouped by level
//! (so a cell is drawn by its level's weight without a search); the deep sleepers at the end
//! of its first seven eighths; the waiting max-heap in the last eighth. Moving a cell never
//! loses one: a cell with nowhere to go stays live, which is always exact.

use super::{Cell, CellSampler, CELLS_BASE, CELL_LEVELS, FLOOR, WAITING_PER_SHAPE};
use crate::scalar::Scalar;

impl<S: Scalar> CellSampler<'_, S> {
    #[inline]
    pub(super) fn start(&self, k: usize) -> usize {
        self.starts.get(k).map_or(0, |&v| v as usize)
    }

    #[inline]
    pub(super) fn bump(&mut self, k: usize, up: bool) {
        if let Some(v) = self.starts.get_mut(k) {
            *v = if up { v.saturating_add(1) } else { v.saturating_sub(1) };
        }
    }

    /// A cell of level `level` weighs `4^(CELL_LEVELS - 1 - level)`: its area in cells of the
    /// finest level.
    #[inline]
    pub(super) fn shift(level: usize) -> u32 {
        2 * (CELL_LEVELS - 1 - level) as u32
    }

    /// The cell at `i`.
    #[inline]
    pub(super) fn cell(&self, i: usize) -> Option<Cell<S>> {
        self.pool.get(i).map(Cell::load)
    }

    /// Stores `c` at `i` (nothing when `i` is out of range).
    #[inline]
    pub(super) fn put(&mut self, i: usize, c: Cell<S>) {
        if let Some(w) = self.pool.get_mut(i) {
            *w = c.store();
        }
    }

    /// Copies the cell at `from` to `to`.
    #[inline]
    pub(super) fn copy(&mut self, from: usize, to: usize) {
        if let Some(w) = self.pool.get(from).copied() {
            if let Some(t) = self.pool.get_mut(to) {
                *t = w;
            }
        }
    }

    pub(super) fn note_peak(&mut self) {
        self.stats.peak = self.stats.peak.max(self.live() + self.asleep + self.waiting);
    }

    /// Adds a live cell at the end of its level's run, moving one cell of each finer level.
    /// Returns its slot (cells of its level keep their slots while others of that level are
    /// added).
    pub(super) fn insert_live(&mut self, c: Cell<S>) -> usize {
        let k = c.level() as usize;
        if self.live() + self.asleep >= self.main || k >= CELL_LEVELS {
            return usize::MAX;
        }
        let mut hole = self.start(CELL_LEVELS);
        for j in (k + 1..CELL_LEVELS).rev() {
            let first = self.start(j);
            if first != hole {
                self.copy(first, hole);
            }
            hole = first;
            self.bump(j, true);
        }
        self.put(hole, c);
        self.bump(CELL_LEVELS, true);
        self.weight += 1u64 << Self::shift(k);
        self.stats.finest_level = self.stats.finest_level.max(c.level());
        self.note_peak();
        hole
    }

    /// Removes the live cell at `slot` (of level `k`), filling the gap from the end of its
    /// level's run and moving one cell of each finer level back.
    pub(super) fn remove_live(&mut self, slot: usize, k: usize) {
        let mut hole = slot;
        for j in k..CELL_LEVELS {
            let last = self.start(j + 1).saturating_sub(1);
            if last != hole {
                self.copy(last, hole);
            }
            hole = last;
            if j + 1 < CELL_LEVELS {
                self.bump(j + 1, false);
            }
        }
        self.bump(CELL_LEVELS, false);
        self.weight -= 1u64 << Self::shift(k);
    }

    /// Retires a cell too tight for the current clearance: dropped when it lies inside shape
    /// material, a deep sleeper when its bound is below the floor, otherwise waiting. (With
    /// no room left it stays live: never exact to drop a cell that could hold a shape.)
    pub(super) fn retire(&mut self, c: Cell<S>) {
        let u = self.upper(&c);
        if u <= S::ZERO {
            self.stats.dropped += 1;
            return;
        }
        if u < self.floor && self.live() + self.asleep < self.main {
            self.put(self.main - 1 - self.asleep, c);
            self.asleep += 1;
            self.note_peak();
        } else if !self.push_waiting(c) {
            self.insert_live(c);
        }
    }

    pub(super) fn waiting_key(&self, k: usize) -> S {
        self.pool.get(self.main + k).map_or(S::ZERO, |w| S::from_word(w[3]) + self.slack)
    }

    pub(super) fn swap_waiting(&mut self, a: usize, b: usize) {
        let (a, b) = (self.main + a, self.main + b);
        if a < self.pool.len() && b < self.pool.len() {
            self.pool.swap(a, b);
        }
    }

    /// Adds a waiting cell; false when the heap is full.
    pub(super) fn push_waiting(&mut self, c: Cell<S>) -> bool {
        if self.waiting >= WAITING_PER_SHAPE.saturating_mul(self.placed.saturating_add(CELLS_BASE)) {
            return false;
        }
        let Some(slot) = self.pool.get_mut(self.main + self.waiting) else {
            return false;
        };
        *slot = c.store();
        let mut i = self.waiting;
        self.waiting += 1;
        while i > 0 {
            let parent = (i - 1) / 2;
            if self.waiting_key(parent) >= self.waiting_key(i) {
                break;
            }
            self.swap_waiting(parent, i);
            i = parent;
        }
        self.note_peak();
        true
    }

    pub(super) fn pop_waiting(&mut self) -> Option<Cell<S>> {
        if self.waiting == 0 {
            return None;
        }
        let top = self.cell(self.main)?;
        self.swap_waiting(0, self.waiting - 1);
        self.waiting -= 1;
        let mut i = 0;
        loop {
            let (l, r) = (2 * i + 1, 2 * i + 2);
            let mut big = i;
            if l < self.waiting && self.waiting_key(l) > self.waiting_key(big) {
                big = l;
            }
            if r < self.waiting && self.waiting_key(r) > self.waiting_key(big) {
                big = r;
            }
            if big == i {
                break;
            }
            self.swap_waiting(i, big);
            i = big;
        }
        Some(top)
    }

    /// Makes every cell that could hold a shape needing `clearance` live. When `clearance` is below the
    /// floor, one pass over the deep sleepers lowers the floor to a fraction of `clearance` and
    /// moves every cell at or above it out (live, or waiting); then waiting cells whose bound
    /// reaches `clearance` wake.
    pub(crate) fn wake(&mut self, clearance: S, placed: usize) {
        self.placed = placed;
        if clearance < self.floor {
            self.floor = clearance * S::from_f64(FLOOR);
            let mut i = 0;
            while i < self.asleep {
                let Some(c) = self.cell(self.main - 1 - i) else {
                    break;
                };
                if self.upper(&c) >= self.floor {
                    // Fill entry i with the last deep sleeper, then move c up.
                    self.copy(self.main - self.asleep, self.main - 1 - i);
                    self.asleep -= 1;
                    if self.upper(&c) >= clearance || !self.push_waiting(c) {
                        self.insert_live(c);
                    }
                } else {
                    i += 1;
                }
            }
        }
        while self.waiting > 0 && self.waiting_key(0) >= clearance {
            match self.pop_waiting() {
                Some(c) => {
                    self.insert_live(c);
                }
                None => break,
            }
        }
    }

    /// Forgets the cells drawn ahead.
    pub(super) fn flush(&mut self) {
        self.ahead_len = 0;
        self.ahead_pos = 0;
    }
}
