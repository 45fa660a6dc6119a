//! The cells as a batch of placements sees them (see [`crate::Batches`]): drawn from without
//! change while the batch's candidates are screened, by any number of threads, and told
//! afterwards, in one ordered pass, what the batch's trials learned ([`CellSampler::replay`]).

use super::{Cell, CellSampler, Drawn, Field, Verdict, NEAR, NONE};
use crate::scalar::Scalar;
use rand_core::RngCore;

/// What one trial of a batch found in the cell it drew: kept by the lane that drew it and
/// replayed into the cells after the batch ([`CellSampler::replay`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Event {
    /// The slot the cell was drawn at, and which cell it was (level and position).
    pub(crate) slot: u32,
    pub(crate) xl: u32,
    pub(crate) iy: u32,
    /// The quarter of the cell the point fell in (bit 0: right half, bit 1: upper half).
    pub(crate) quarter: u8,
    pub(crate) what: What,
}

/// A trial's outcome, as far as its cell is concerned.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum What {
    /// The cell's bound was below the shape's clearance.
    #[default]
    Tight,
    /// Rejected by a shape the cell knew.
    Known,
    /// Rejected by the region or the exact test with no shape to learn.
    Other,
    /// Rejected by a placed shape the cell did not know.
    Hit(u32),
    /// The shape placed here.
    Placed(u32),
}

impl Event {
    /// The event of a trial drawn as `d`.
    pub(crate) fn of(d: &Drawn<impl Scalar>, what: What) -> Self {
        Event {
            slot: d.slot as u32,
            xl: d.cell.xl,
            iy: d.cell.iy(),
            quarter: u8::from(d.quarter.0) | (u8::from(d.quarter.1) << 1),
            what,
        }
    }
}

impl<S: Scalar> CellSampler<'_, S> {
    /// Draws a live cell with probability proportional to its area times its density bound (as
    /// [`CellSampler::draw`] does, from one unbiased bounded integer) and a uniform point in
    /// it, changing nothing: the cells a batch draws from stay as they are until its replay.
    /// None when no cell is live.
    #[inline]
    pub(crate) fn draw_frozen<R: RngCore + ?Sized>(&self, rng: &mut R) -> Option<(usize, u32)> {
        let total = self.weight;
        if total == 0 {
            return None;
        }
        self.slot_of(crate::rng::below(rng, total))
    }

    /// The cell at `slot` as drawn by [`CellSampler::draw_frozen`] with density class `class`,
    /// and a uniform point in it from two unit values.
    #[inline]
    pub(crate) fn point_in<R: RngCore + ?Sized>(&self, slot: usize, class: u32, rng: &mut R) -> Option<Drawn<S>> {
        let c = self.cell(slot)?;
        Some(self.drawn_in(slot, c, class, rng))
    }

    /// Whether a cell drawn from is too tight for a shape needing `clearance`: no point of it
    /// is a valid centre.
    #[inline]
    pub(crate) fn too_tight(&self, c: &Cell<S>, clearance: S) -> bool {
        self.upper(c) < clearance
    }

    /// Tells the cells what one trial of a batch found, as [`crate::Engine::step_fast`]'s trial
    /// would have, for shapes needing `clearance` (the least of the next batch's): the drawn
    /// cell is retired if too tight, split if too large or stubborn, counts the rejection, and
    /// learns the shape that was hit or placed. An event whose cell has since moved, split or
    /// gone is skipped: it only ever tightens bounds, so skipping it costs trials, never
    /// exactness.
    pub(crate) fn replay(&mut self, e: &Event, clearance: S, f: &impl Field<S>) {
        let slot = e.slot as usize;
        let drawn = Cell::<S> {
            xl: e.xl,
            yr: e.iy,
            near: [NONE; NEAR],
            u: S::ZERO,
        };
        let quarter = (e.quarter & 1 == 1, e.quarter & 2 == 2);
        let slot = match self.judge(slot, &drawn, quarter, clearance, f) {
            Verdict::Test(s) if s != usize::MAX => s,
            _ => return,
        };
        match e.what {
            What::Tight => {}
            What::Known => self.note_reject(slot, true),
            What::Other => self.note_reject(slot, false),
            What::Hit(j) => {
                self.note_learned(slot);
                self.learn(slot, j, clearance, f);
            }
            What::Placed(j) => self.learn(slot, j, clearance, f),
        }
    }

    /// Begins the replay of a batch: the counters of the step begin afresh.
    pub(crate) fn begin_replay(&mut self) {
        self.flush();
    }
}
