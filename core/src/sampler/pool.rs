//! Where the cells live in the caller's slice: the live cells at its start, grouped in runs by
//! level and density class (so a cell is drawn by its run's weight without a search); the deep
//! sleepers at the end of its first seven eighths; the waiting max-heap in the last eighth.
//! Moving a cell never loses one: a cell with nowhere to go stays live, which is always exact.

use super::{Cell, CellSampler, Field, CELLS_BASE, CELL_LEVELS, FLOOR, WAITING_PER_SHAPE};
use crate::scalar::Scalar;

impl<S: Scalar> CellSampler<'_, S> {
    #[inline]
    pub(super) fn start(&self, k: usize) -> usize {
        self.starts.get(k).map_or(0, |&v| v as usize)
    }

    /// A cell of level `level` weighs `4^(CELL_LEVELS - 1 - level)`: its area in cells of the
    /// finest level.
    #[inline]
    pub(super) fn shift(level: usize) -> u32 {
        2 * (CELL_LEVELS - 1 - level) as u32
    }

    /// The runs of live cells in use: one per level, times the density classes.
    #[inline]
    pub(super) fn runs(&self) -> usize {
        CELL_LEVELS * self.classes.get()
    }

    /// The run of the cells of `level` and density `class`.
    #[inline]
    pub(super) fn run(&self, level: u32, class: u32) -> usize {
        level as usize * self.classes.get() + class as usize
    }

    /// A cell of run `r` weighs its area in cells of the finest level times its density bound
    /// `2^-class`, in units of the lowest bound: `4^(CELL_LEVELS - 1 - level) 2^(classes - 1 -
    /// class)`.
    #[inline]
    pub(super) fn run_shift(&self, r: usize) -> u32 {
        let k = self.classes;
        Self::shift(r / k) + (k.get() - 1 - r % k) as u32
    }

    /// The run that holds the live cell at `slot` (the runs are contiguous, in order).
    pub(super) fn run_of(&self, slot: usize) -> usize {
        let (mut lo, mut hi) = (0, self.runs());
        // The last run whose start is at or before `slot` (empty runs start where the next
        // one does).
        while lo + 1 < hi {
            let mid = (lo + hi) / 2;
            if self.start(mid) <= slot {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    }

    /// The density class of run `r`.
    #[inline]
    pub(super) fn class_of_run(&self, r: usize) -> u32 {
        (r % self.classes) as u32
    }

    /// The density class of `c` (see [`Field::class`]); None when no centre can be kept
    /// anywhere in it. Always class 0 without a density.
    pub(super) fn class_of(&self, f: &impl Field<S>, c: &Cell<S>) -> Option<u32> {
        if self.classes.get() == 1 {
            return Some(0);
        }
        f.class(cell_box(self.grid_f64, c.level(), c.ix(), c.iy()), self.classes.get() as u32)
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

    /// Adds a live cell of density class `class` at the end of its run, moving one cell of
    /// each later run. Returns its slot (cells of its run keep their slots while others of
    /// that run are added).
    pub(super) fn insert_live(&mut self, c: Cell<S>, class: u32) -> usize {
        let runs = self.runs();
        let k = self.run(c.level(), class);
        if k >= runs || !self.live_room() {
            return usize::MAX;
        }
        // Runs after the last one in use are empty: nothing of theirs moves.
        let mut hole = self.start(runs);
        for j in (k + 1..=self.hi as usize).rev() {
            let first = self.start(j);
            if first != hole {
                self.copy(first, hole);
            }
            hole = first;
        }
        if let Some(later) = self.starts.get_mut(k + 1..=runs) {
            later.iter_mut().for_each(|v| *v = v.wrapping_add(1));
        }
        self.put(hole, c);
        self.lo = self.lo.min(k as u32);
        self.hi = self.hi.max(k as u32);
        self.weight += 1u64 << self.run_shift(k);
        self.stats.finest_level = self.stats.finest_level.max(c.level());
        self.note_peak();
        hole
    }

    /// Removes the live cell (of `level`) at `slot`, filling the gap from the end of its run
    /// and moving one cell of each later run back. Returns the cell's density class.
    pub(super) fn remove_live(&mut self, slot: usize, level: u32) -> u32 {
        // Without a density a level is a run: no search.
        let k = if self.classes.get() == 1 {
            level as usize
        } else {
            self.run_of(slot)
        };
        let runs = self.runs();
        let mut hole = slot;
        for j in k..=(self.hi as usize).max(k) {
            let last = self.start(j + 1).saturating_sub(1);
            if last != hole {
                self.copy(last, hole);
            }
            hole = last;
        }
        if let Some(later) = self.starts.get_mut(k + 1..=runs) {
            later.iter_mut().for_each(|v| *v = v.wrapping_sub(1));
        }
        self.weight -= 1u64 << self.run_shift(k);
        // Narrow the runs in use past the ones left empty (only this one can have emptied).
        let emptied = self.start(k) == self.start(k + 1);
        if emptied && self.live() == 0 {
            (self.lo, self.hi) = (runs as u32, 0);
        } else if emptied {
            while self.lo < self.hi && self.start(self.lo as usize) == self.start(self.lo as usize + 1) {
                self.lo += 1;
            }
            while self.hi > self.lo && self.start(self.hi as usize) == self.start(self.hi as usize + 1) {
                self.hi -= 1;
            }
        }
        self.class_of_run(k)
    }

    /// Retires a cell (of density class `class`) too tight for the current clearance: dropped
    /// when it lies inside shape material, a deep sleeper when its bound is below the floor,
    /// otherwise waiting. (With no room left it stays live: never exact to drop a cell that
    /// could hold a shape.)
    pub(super) fn retire(&mut self, c: Cell<S>, class: u32) {
        let u = self.upper(&c);
        if u <= S::ZERO {
            self.stats.dropped += 1;
            return;
        }
        if u < self.never {
            self.outlived += 1;
            self.stats.outlived += 1;
            return;
        }
        if u < self.floor && self.deep_room() {
            self.put(self.deep_top() - 1 - self.asleep, c);
            self.asleep += 1;
            self.note_peak();
        } else if !self.push_waiting(c) {
            self.insert_live(c, class);
        }
    }

    /// Where the deep sleepers end: entry `i` is `pool[deep_top() - 1 - i]`. At `main`, below
    /// the waiting heap; with ample storage at the end of the pool, above it.
    #[inline]
    fn deep_top(&self) -> usize {
        if self.ample {
            self.pool.len()
        } else {
            self.main
        }
    }

    /// Whether a deep sleeper can be added.
    fn deep_room(&mut self) -> bool {
        if self.ample {
            self.sleeper_room()
        } else {
            self.live() + self.asleep < self.main
        }
    }

    /// With ample storage, whether a sleeper (deep or waiting) can be added, moving the
    /// boundary `main` with the live cells down when their side has room to spare.
    fn sleeper_room(&mut self) -> bool {
        if self.main + self.waiting + self.asleep < self.pool.len() {
            return true;
        }
        let spare = self.main.saturating_sub(self.live());
        self.move_heap(false, spare.div_ceil(2))
    }

    /// Whether a live cell can be added; with ample storage, moving `main` up when the
    /// sleepers' side has room to spare.
    fn live_room(&mut self) -> bool {
        if !self.ample {
            return self.live() + self.asleep < self.main;
        }
        if self.live() < self.main {
            return true;
        }
        let spare = self.pool.len().saturating_sub(self.main + self.waiting + self.asleep);
        self.move_heap(true, spare.div_ceil(2))
    }

    /// Moves the waiting heap, and `main` with it, `by` cells up or down (ample storage:
    /// nothing else lies between the live cells and the deep sleepers). False when `by` is 0.
    fn move_heap(&mut self, up: bool, by: usize) -> bool {
        if by == 0 {
            return false;
        }
        let from = self.main;
        if up {
            for k in (0..self.waiting).rev() {
                self.copy(from + k, from + by + k);
            }
            self.main += by;
        } else {
            for k in 0..self.waiting {
                self.copy(from + k, from - by + k);
            }
            self.main -= by;
        }
        true
    }

    pub(super) fn waiting_key(&self, k: usize) -> S {
        self.pool.get(self.main + k).map_or(S::ZERO, |w| S::from_word(w[3]) + self.slack)
    }

    /// Whether waiting cell `a` wakes before `b`: the higher bound, and with ample storage,
    /// between equal bounds (siblings often share their parent's), the higher position word,
    /// so that cells wake in an order that depends only on which of them wake, not on where
    /// the heap keeps them.
    fn wakes_before(&self, a: usize, b: usize) -> bool {
        let (Some(wa), Some(wb)) = (self.pool.get(self.main + a), self.pool.get(self.main + b)) else {
            return false;
        };
        let (ka, kb) = (S::from_word(wa[3]) + self.slack, S::from_word(wb[3]) + self.slack);
        ka > kb || (self.ample && ka == kb && wa[0] > wb[0])
    }

    pub(super) fn swap_waiting(&mut self, a: usize, b: usize) {
        let (a, b) = (self.main + a, self.main + b);
        if a < self.pool.len() && b < self.pool.len() {
            self.pool.swap(a, b);
        }
    }

    /// Adds a waiting cell; false when the heap is full.
    pub(super) fn push_waiting(&mut self, c: Cell<S>) -> bool {
        let full = if self.ample {
            !self.sleeper_room()
        } else {
            self.waiting >= WAITING_PER_SHAPE.saturating_mul(self.placed.saturating_add(CELLS_BASE))
        };
        if full {
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
            if !self.wakes_before(i, parent) {
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
            if l < self.waiting && self.wakes_before(l, big) {
                big = l;
            }
            if r < self.waiting && self.wakes_before(r, big) {
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
    /// reaches `clearance` wake. A cell that wakes gets its density class again from `f`.
    pub(crate) fn wake(&mut self, clearance: S, placed: usize, f: &impl Field<S>) {
        self.placed = placed;
        if clearance < self.floor {
            self.floor = clearance * S::from_f64(FLOOR);
            let top = self.deep_top();
            let mut i = 0;
            while i < self.asleep {
                let Some(c) = self.cell(top - 1 - i) else {
                    break;
                };
                if self.upper(&c) >= self.floor {
                    // Fill entry i with the last deep sleeper, then move c up. With ample
                    // storage every such cell waits, so that the cells that wake now do so
                    // in the heap's order, whichever of them were deep.
                    self.copy(top - self.asleep, top - 1 - i);
                    self.asleep -= 1;
                    let now = self.upper(&c) >= clearance && !self.ample;
                    if now || !self.push_waiting(c) {
                        self.make_live(c, f);
                    }
                } else {
                    i += 1;
                }
            }
        }
        while self.waiting > 0 && self.waiting_key(0) >= clearance {
            match self.pop_waiting() {
                Some(c) => self.make_live(c, f),
                None => break,
            }
        }
    }

    /// Makes `c` live in its density class, or drops it where no centre can be kept.
    pub(super) fn make_live(&mut self, c: Cell<S>, f: &impl Field<S>) {
        match self.class_of(f, &c) {
            Some(class) => {
                self.insert_live(c, class);
            }
            None => self.stats.dropped += 1,
        }
    }

    /// Forgets the cells drawn ahead.
    pub(super) fn flush(&mut self) {
        self.ahead_len = 0;
        self.ahead_pos = 0;
    }
}

/// The box `[x0, y0, x1, y1]` of the cell of `level` at `(ix, iy)` in a grid `[x0, y0, w, h,
/// pad]` (origin, level-0 cell sides, a widening), in f64: one copy for every scalar, widened
/// by `pad` over the few units of rounding between the grid in f64 and in the scalar's own
/// arithmetic. (A level's sides are the first's halved, exactly in f64.)
#[inline(never)]
fn cell_box(grid: [f64; 5], level: u32, ix: u32, iy: u32) -> [f64; 4] {
    let [x0, y0, w, h, pad] = grid;
    let scale = 1.0 / f64::from(1u32 << level.min(31));
    let (w, h) = (w * scale, h * scale);
    let (x, y) = (x0 + f64::from(ix) * w - pad, y0 + f64::from(iy) * h - pad);
    [x, y, x + w + 2.0 * pad, y + h + 2.0 * pad]
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::indexing_slicing, clippy::panic)]
mod tests {
    use super::super::{NEAR, NONE};
    use super::*;

    /// Forty cells at distinct positions, their bounds repeating (as siblings share their
    /// parent's), in no order.
    fn cells() -> [Cell<f64>; 40] {
        core::array::from_fn(|i| Cell {
            xl: i as u32,
            yr: 0,
            near: [NONE; NEAR],
            u: ((i * 7) % 13) as f64,
        })
    }

    /// Pushes the cells (with ample storage, into a pool of 64 cells, so that the heap has to
    /// move; otherwise into one with room for them), moves the heap up and back, and pops
    /// them all: their bounds and positions in the order they woke.
    fn wake_order(ample: bool) -> [(f64, u32); 40] {
        let mut pool = [[0u64; 4]; 400];
        let len = if ample { 64 } else { 400 };
        let mut s = CellSampler::<f64>::new(&mut pool[..len]).unwrap();
        s.ample = ample;
        for c in cells() {
            assert!(s.push_waiting(c));
        }
        if ample {
            // Forty waiting cells do not fit past `main` (56 of 64): the heap moved down.
            assert!(s.main <= 64 - 40, "main {}", s.main);
            assert!(s.move_heap(true, 3) && s.move_heap(false, 2));
            assert!(!s.move_heap(true, 0));
        }
        let mut woke = [(0.0, 0); 40];
        for w in woke.iter_mut() {
            let c = s.pop_waiting().unwrap();
            *w = (c.u, c.xl);
        }
        assert!(s.pop_waiting().is_none());
        woke
    }

    #[test]
    fn the_heap_moves_whole_and_wakes_in_one_order() {
        let woke = wake_order(true);
        // Every cell, the highest bound first and equal bounds by the higher position:
        // strictly decreasing pairs.
        assert!(woke.windows(2).all(|w| w[0] > w[1]), "{woke:?}");
        let mut xs = woke.map(|(_, x)| x);
        xs.sort_unstable();
        assert_eq!(xs, core::array::from_fn(|i| i as u32));
        // The control: without ample storage equal bounds wake in the heap's own order,
        // which the same check tells apart.
        let older = wake_order(false);
        assert!(older.windows(2).all(|w| w[0].0 >= w[1].0));
        assert!(!older.windows(2).all(|w| w[0] > w[1]), "{older:?}");
    }
}
