//! One trial as the cells see it: draw a live cell by area and a uniform point in it
//! ([`CellSampler::draw`]), judge the point by its cell (retire a cell too tight, split one
//! too large or too stubborn: [`CellSampler::judge`]), and learn from the exact test the shape
//! a candidate hit ([`CellSampler::learn`]). Also the estimate of the paper's trials.

use super::{Cell, CellSampler, Field, AHEAD, CELLS_BASE, CELLS_PER_SHAPE, CELL_LEVELS, NEAR, NONE, SPLIT, STUBBORN, X_BITS};
use crate::geom::Point;
use crate::scalar::Scalar;
use rand_core::RngCore;

/// A trial's draw: the cell's slot and the cell as drawn, the point, and which quarter of the
/// cell the point is in.
pub(crate) struct Drawn<S> {
    pub(crate) slot: usize,
    pub(crate) cell: Cell<S>,
    pub(crate) point: Point<S>,
    pub(crate) quarter: (bool, bool),
    /// The cell's density class `j`: it was drawn with weight its area times `2^-j`, and the
    /// density is at most `2^-j` all over it.
    pub(crate) class: u32,
}

/// What a trial learns from the cell it drew.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Verdict {
    /// The point holds no valid centre.
    Reject,
    /// The point must go through the exact tests; it lies in the live cell at this slot.
    Test(usize),
}

impl<S: Scalar> CellSampler<'_, S> {
    /// Begins a step, after [`CellSampler::wake`] may have added cells: forgets the cells
    /// drawn ahead and the step's draws.
    pub(crate) fn begin_step(&mut self) {
        self.flush();
        self.batch_weight = 0;
        self.step_inv = 0.0;
    }

    /// Ends a step whose shape was placed; `w` by `h` is the box the paper's sampler draws
    /// its centres from. Adds `w h / |U|` for each of the step's trials, `|U|` being the live
    /// area its cell was drawn from (see [`CellSampler::paper_trials`]).
    pub(crate) fn end_step(&mut self, w: S, h: S) {
        if !self.estimating {
            return;
        }
        let range = w.to_f64() * h.to_f64();
        let mut inv = self.step_inv;
        if self.batch_weight > 0 {
            inv += self.ahead_pos as f64 / self.batch_weight as f64;
        }
        let g = self.lg(0);
        // A weight unit is a cell of the finest level (a 4^23th of a level-0 cell) times the
        // lowest density bound: the sum of `|R| / W` over the trials, `W` the live cells'
        // area weighted by their density bounds, has expectation `|R|` over the integral of
        // the density over the valid centres, the paper's expected trials with thinning.
        let unit = g.w.to_f64() * g.h.to_f64() / (1u64 << (Self::shift(0) + self.classes.get() as u32 - 1)) as f64;
        let est = if unit > 0.0 { range * inv / unit } else { 0.0 };
        self.last_paper = est;
        self.paper += est;
    }

    /// Ends a step placed without cells (the shape has no clearance condition), with the
    /// trials of the paper's sampler that placed it.
    pub(crate) fn end_step_paper(&mut self, trials: u64) {
        if !self.estimating {
            return;
        }
        self.last_paper = trials as f64;
        self.paper += self.last_paper;
    }

    /// The live cell that weight `r` (below the total weight) falls in, and its density class.
    pub(super) fn slot_of(&self, mut r: u64) -> Option<(usize, u32)> {
        let classes = self.classes;
        // Without a density a run is a level: a shorter loop, on hosts (a board keeps the flash
        // it would take; both find the same cell).
        if classes.get() == 1 && cfg!(not(target_os = "none")) {
            for k in self.lo as usize..=self.hi as usize {
                let count = (self.start(k + 1) - self.start(k)) as u64;
                let w = count << Self::shift(k);
                if r < w {
                    return Some((self.start(k) + (r >> Self::shift(k)) as usize, 0));
                }
                r -= w;
            }
            return None;
        }
        // The run's level and class kept as counters: no division per run.
        let (mut level, mut class) = (self.lo as usize / classes, self.lo as usize % classes);
        for k in self.lo as usize..=self.hi as usize {
            let count = (self.start(k + 1) - self.start(k)) as u64;
            let shift = Self::shift(level) + (classes.get() - 1 - class) as u32;
            let w = count << shift;
            if r < w {
                return Some((self.start(k) + (r >> shift) as usize, class as u32));
            }
            r -= w;
            class += 1;
            if class == classes.get() {
                (level, class) = (level + 1, 0);
            }
        }
        None
    }

    /// Draws a live cell with probability proportional to its area times its density bound
    /// (exactly: integer weights and an unbiased bounded draw) and a uniform point in it.
    ///
    /// Cells are drawn [`AHEAD`] at a time, at the first trial and whenever the batch is used
    /// up, and handed out in order. Within a step the live cells only shrink (cells are
    /// retired) or are split (the same union), so each is still a draw over a union that
    /// holds every valid centre, and the trial's acceptance is still exactly "the point is
    /// valid": the accepted placement stays uniform. A cell that has moved or gone since it
    /// was drawn is tested without bookkeeping (see [`CellSampler::judge`]).
    pub(crate) fn draw<R: RngCore + ?Sized>(&mut self, rng: &mut R) -> Option<Drawn<S>> {
        if self.ahead_pos >= self.ahead_len {
            if self.estimating && self.batch_weight > 0 {
                self.step_inv += self.ahead_pos as f64 / self.batch_weight as f64;
            }
            self.flush();
            let total = self.weight;
            self.batch_weight = total;
            if total == 0 {
                return None;
            }
            // Lemire's method: a uniform integer below `total` without bias.
            let threshold = total.wrapping_neg() % total;
            let mut slots = [(0usize, 0u32); AHEAD];
            for slot in slots.iter_mut() {
                let r = loop {
                    let m = u128::from(rng.next_u64()) * u128::from(total);
                    if (m as u64) >= threshold {
                        break (m >> 64) as u64;
                    }
                };
                *slot = self.slot_of(r)?;
            }
            // The loads in a loop of their own, so that they are in flight together.
            for (entry, &(slot, class)) in self.ahead.iter_mut().zip(slots.iter()) {
                *entry = (slot, self.pool.get(slot).map(Cell::load)?, class);
            }
            self.ahead_len = AHEAD;
        }
        let (slot, c, class) = self.ahead.get(self.ahead_pos).copied()?;
        self.ahead_pos += 1;
        Some(self.drawn_in(slot, c, class, rng))
    }

    /// A uniform point in cell `c` (at `slot`, of density class `class`) from two unit values,
    /// x then y.
    #[inline]
    pub(super) fn drawn_in<R: RngCore + ?Sized>(&self, slot: usize, c: Cell<S>, class: u32, rng: &mut R) -> Drawn<S> {
        let g = self.lg(c.level());
        let ux: S = crate::rng::unit(rng);
        let uy: S = crate::rng::unit(rng);
        let p = Point::new(
            self.origin.x + (S::from_f64(f64::from(c.ix())) + ux) * g.w,
            self.origin.y + (S::from_f64(f64::from(c.iy())) + uy) * g.h,
        );
        let half = S::ONE.half();
        Drawn {
            slot,
            cell: c,
            point: p,
            quarter: (ux >= half, uy >= half),
            class,
        }
    }

    /// Restructures the drawn cell: a cell too tight for `clearance` is retired; a cell much larger
    /// than `clearance` is split into children that inherit its shapes. Says whether the drawn
    /// point (in quarter `quarter` of the cell) can still be valid, and in which live cell it
    /// lies.
    ///
    /// `drawn` is the cell as it was drawn; if `slot` no longer holds it (it moved, or was
    /// split or retired since), the point is simply tested, without bookkeeping.
    pub(crate) fn judge(&mut self, slot: usize, drawn: &Cell<S>, quarter: (bool, bool), clearance: S, f: &impl Field<S>) -> Verdict {
        let Some(c) = self.cell(slot).filter(|c| slot < self.live() && c.same(drawn)) else {
            return Verdict::Test(usize::MAX);
        };
        let level = c.level();
        let g = self.lg(level);
        if self.upper(&c) < clearance {
            self.stats.cell_rejects += 1;
            let class = self.remove_live(slot, level);
            self.retire(c, class);
            return Verdict::Reject;
        }
        let big = g.half_diag > clearance * S::from_f64(SPLIT);
        if !((big || c.rejects() >= STUBBORN) && (level as usize) + 1 < CELL_LEVELS) {
            return Verdict::Test(slot);
        }
        // Every cell held must fit in the live and deep-sleeper part of the pool, waiting ones
        // included: a waiting cell that wakes needs a place there, and a cell with nowhere to
        // go would leave the union without its valid centres.
        // With ample storage the cells that outlived the fill count too, and only the budget
        // limits (it always leaves room in the pool).
        let held = self.live() + self.asleep + self.waiting + self.outlived + 3;
        let budget = CELLS_PER_SHAPE.saturating_mul(self.placed.saturating_add(CELLS_BASE));
        let room = if self.ample { self.pool.len() } else { self.main };
        if held > room || held > budget {
            self.stats.refused_splits += 1;
            return Verdict::Test(slot);
        }
        self.split(slot, c, quarter, clearance, f)
    }

    /// Splits the live cell `c` at `slot` into its children (see [`CellSampler::judge`]), and
    /// says whether the drawn point (in quarter `quarter`) can still be valid, and in which
    /// live cell it lies. Kept out of line: splits are rare beside trials, and the trial loop
    /// stays small.
    #[inline(never)]
    fn split(&mut self, slot: usize, c: Cell<S>, quarter: (bool, bool), clearance: S, f: &impl Field<S>) -> Verdict {
        let level = c.level();
        let g = self.lg(level);
        self.stats.splits += 1;
        let class = self.remove_live(slot, level);
        let cg = self.lg(level + 1);
        // A stubborn cell keeps missing: the shapes it learned from its trials do not close
        // it. It looks its neighbours up in the index, and its children are bounded quarter
        // by quarter.
        let stubborn = c.rejects() >= STUBBORN && (level as usize) + 2 < CELL_LEVELS;
        let mut c = c;
        if stubborn {
            self.stats.gathers += 1;
            f.gather(self.centre(&c), g.half_diag.half() + clearance, &mut c.near);
        }
        let qg = self.lg(level + 2);
        let mut verdict = Verdict::Reject;
        for q in 0..4u32 {
            let (qx, qy) = (q & 1 == 1, q & 2 == 2);
            let mut child = Cell {
                xl: ((level + 1) << X_BITS) | (c.ix() * 2 + u32::from(qx)),
                yr: c.iy() * 2 + u32::from(qy),
                near: c.near,
                u: S::ZERO,
            };
            // A child's bound is also at most its parent's.
            let centre = self.centre(&child);
            let b = if stubborn {
                Self::bound_by_quarters(f, &child.near, centre, &qg)
            } else {
                Self::bound(f, &child.near, centre, &cg)
            };
            child.u = b.min(c.u);
            // The parent's density bound holds over the child too.
            let Some(child_class) = self.class_of(f, &child).map(|k| k.max(class)) else {
                self.stats.dropped += 1;
                continue;
            };
            if self.upper(&child) < clearance {
                self.retire(child, child_class);
            } else {
                let at = self.insert_live(child, child_class);
                if (qx, qy) == quarter {
                    verdict = Verdict::Test(at);
                }
            }
        }
        if verdict == Verdict::Reject {
            self.stats.cell_rejects += 1;
        }
        verdict
    }

    /// The shapes known to the cells of a batch drawn by the last [`CellSampler::draw`], when
    /// that call drew a new batch: the engine loads their records then, all at once, rather
    /// than one by one as each trial needs them.
    pub(crate) fn batch_known(&self) -> Option<impl Iterator<Item = u32> + '_> {
        (self.ahead_pos == 1).then(|| {
            self.ahead
                .iter()
                .take(self.ahead_len)
                .flat_map(|(_, c, _)| c.near)
                .filter(|&j| j != NONE)
        })
    }

    /// The shapes the live cell at `slot` knows of.
    pub(crate) fn known(&self, slot: usize) -> [u32; NEAR] {
        self.cell(slot).map_or([NONE; NEAR], |c| c.near)
    }

    /// Counts a trial in the live cell at `slot` rejected by a shape the cell knew (`known`)
    /// or by the exact test otherwise.
    pub(crate) fn note_reject(&mut self, slot: usize, known: bool) {
        if known {
            self.stats.known_rejects += 1;
        }
        if let Some(mut c) = self.cell(slot) {
            if c.rejects() < STUBBORN {
                c.yr += 1 << X_BITS;
                self.put(slot, c);
            }
        }
    }

    /// Tells the live cell at `slot` of shape `j` (hit by a candidate drawn in it, or placed
    /// in it): the cell keeps it if it is among the [`NEAR`] nearest it knows, lowers its
    /// bound, and is retired if that leaves no room for `clearance`.
    pub(crate) fn learn(&mut self, slot: usize, j: u32, clearance: S, f: &impl Field<S>) {
        let Some(mut c) = self.cell(slot) else { return };
        if j == NONE || c.near.contains(&j) {
            return;
        }
        let centre = self.centre(&c);
        let dj = f.dist(j, centre);
        let g = self.lg(c.level());
        // Keep j in place of the farthest known shape (or a free entry) if it is nearer.
        let mut worst: Option<(usize, S)> = None;
        for (i, &n) in c.near.iter().enumerate() {
            let dn = if n == NONE { S::from_f64(f64::MAX) } else { f.dist(n, centre) };
            if worst.is_none_or(|(_, w)| dn > w) {
                worst = Some((i, dn));
            }
        }
        if let Some((i, w)) = worst.filter(|&(_, w)| dj < w) {
            let _ = w;
            if let Some(e) = c.near.get_mut(i) {
                *e = j;
            }
        }
        c.u = c.u.min(f.box_dist(j, centre, g.w.half(), g.h.half()).unwrap_or(dj + g.half_diag));
        self.put(slot, c);
        if self.upper(&c) < clearance {
            let class = self.remove_live(slot, c.level());
            self.retire(c, class);
        }
    }

    /// Counts a trial whose cell learned the shape it hit.
    pub(crate) fn note_learned(&mut self, slot: usize) {
        self.stats.learned += 1;
        self.note_reject(slot, false);
    }
}
