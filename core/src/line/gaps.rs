//! The free gaps of a 1D fill, kept so that the next segment's start is drawn uniformly over
//! every valid start in O(log n): the storage and the order-statistics structure of the exact
//! sampler ([`crate::line::Engine::step_fast`], whose documentation carries the argument).
//!
//! A gap is the free stretch between two neighbouring segments (or a segment and an end of an
//! inclusive interval). Its *room* is its length less twice the clearance, counted in integer
//! units of `2^-56` of the power of two at or above `L`, rounded up and grown by a slack, so
//! that it is never below the true measure of the starts the gap offers a segment of length
//! `len`, which is `room - len` when positive. A gap is *active* when its room exceeds the
//! next segment's length (in units, rounded down): a Fenwick tree over blocks of 16 gap ids
//! holds the sum of the active rooms and their count, so the total measure
//! `sum(room) - len * count` of the next draw and the gap at any point of it are found in
//! O(log n) and a scan of one block, exactly, in integers. The others wait in a max-heap by room and become active as
//! the lengths fall (lengths only fall). A gap whose room is not above zero can never hold a
//! start and is forgotten.
//!
//! Nothing here allocates or panics: the gaps live in a slice of [`LineGap`] the caller lends.

use super::LineEngine;
use crate::scalar::Scalar;
use rand_core::RngCore;

/// The units of room: `2^-56` of the power of two at or above the interval's length.
const UNIT_BITS: i32 = 56;
/// The slack on each room: `2^-48` of that power of two (eight times the largest rounding of
/// the room's own arithmetic and of the tests that decide a start, each below `2^-52` of it).
const SLACK_BITS: i32 = 48;
/// Largest room in units (rooms are at most about `2^56`).
const ROOM_MAX: f64 = 2_305_843_009_213_693_952.0; // 2^61
/// A room word: the room in its low 62 bits, then these flags.
const WAITING: u64 = 1 << 62;
const WRAPS: u64 = 1 << 63;
const ROOM: u64 = WAITING - 1;

/// Gaps a node of the Fenwick tree sums: a draw finds a block in the tree (small enough to
/// stay in cache), then the gap by a scan of the block's 16 gaps (six cache lines, read in
/// order).
const BLOCK: usize = 16;

/// Words enough for a fill of `capacity` segments: one gap a segment, plus one (an inclusive
/// interval of `n` segments has `n + 1` gaps), and a little over five words a gap (see
/// [`LineGap`]).
pub const fn line_gaps_for(capacity: usize) -> usize {
    words_for(capacity + 1)
}

/// The words `gaps` gaps take: three each for the gap (its ends and its room), two each for
/// its place in the heap, two for each block's node of the Fenwick tree.
const fn words_for(gaps: usize) -> usize {
    5 * gaps + 2 * gaps.div_ceil(BLOCK)
}

/// One 8-byte word of the exact 1D sampler's storage, in a slice the caller lends
/// ([`line_gaps_for`]): the slice is cut into the gaps (ends and room, side by side, so that
/// the scan that finds a gap has its ends at hand), the Fenwick tree over blocks of
/// 16 gaps, and the heap of waiting gaps, each part dense in memory: 41 bytes a gap.
/// `LineGap::default()` is an empty word.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LineGap(u64);

/// The exact 1D sampler was lent too few words for two gaps ([`line_gaps_for`]`(1)`), or
/// more gaps than `u32` counts.
///
/// # Examples
///
/// ```
/// use zetafill::line::{Gap, Gaps, NoGaps};
///
/// assert_eq!(Gaps::<f64>::new(&mut [Gap::default(); 5]).err(), Some(NoGaps));
/// assert_eq!(NoGaps.to_string(), "the exact 1D sampler needs storage for at least two gaps");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct NoLineGaps;

impl core::fmt::Display for NoLineGaps {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("the exact 1D sampler needs storage for at least two gaps")
    }
}

impl core::error::Error for NoLineGaps {}

/// A gap as drawn: its id, ends, and whether it runs across the seam.
#[derive(Clone, Copy, Debug)]
pub(super) struct Gap<S> {
    pub id: u32,
    pub lo: S,
    pub hi: S,
    pub wraps: bool,
}

/// The free gaps of a 1D fill over caller-lent slots: the storage of
/// [`LineEngine::step_fast`] (see it for an example and for why the draws are exact).
#[derive(Debug)]
pub struct LineGaps<'g, S> {
    /// Gap `i` at words `3 i..3 i + 3`: its ends `lo` (the end of the segment before it, 0
    /// at the start of an inclusive interval) and `hi` (the start of the segment after it,
    /// `L` at the end of an inclusive interval) as the scalar's words, and its room word
    /// (room and flags; a dead gap's is 0).
    gaps: &'g mut [LineGap],
    /// Fenwick nodes `1..=blocks` (the rooms and count of the active gaps in a node's range
    /// of blocks), at words `2 (i - 1)` and `2 (i - 1) + 1`.
    fen: &'g mut [LineGap],
    /// The waiting gaps' 4-ary max-heap by room: (room, id), two words an entry.
    queue: &'g mut [LineGap],
    /// Gap slots.
    cap: usize,
    /// Gap ids in use: `0..ids`.
    ids: usize,
    /// Waiting gaps: heap entries `0..heap`.
    heap: usize,
    /// The active gaps' rooms and count.
    sum: u64,
    count: u64,
    /// Segments of the engine the gaps know of.
    known: usize,
    /// The interval and clearance the gaps were laid out for (length, periodic, gap).
    layout: Option<(f64, bool, f64)>,
    /// The interval's length and the clearance, in mm.
    total: f64,
    clearance: f64,
    /// Units per mm and mm per unit (powers of two), and the slack in mm.
    scale: f64,
    unit: f64,
    slack: f64,
    /// Every gap's ends are the neighbouring segments' ends as stored, so the neighbours
    /// decide a start; false once a segment placed elsewhere could not be located.
    exact: bool,
    /// The measure of the starts the last draw was made over, in units.
    last_weight: u64,
    rejected: u64,
    _scalar: core::marker::PhantomData<S>,
}

impl<'g, S: Scalar> LineGaps<'g, S> {
    /// The gaps over `slots` (at least [`line_gaps_for`]`(1)` words; [`line_gaps_for`] for a
    /// fill of a given capacity). They are laid out on the first [`LineEngine::step_fast`].
    pub fn new(slots: &'g mut [LineGap]) -> Result<Self, NoLineGaps> {
        let n = slots.len();
        let mut cap = n.saturating_mul(BLOCK) / (5 * BLOCK + 2) + 1;
        while cap > 0 && words_for(cap) > n {
            cap -= 1;
        }
        if cap < 2 || cap >= u32::MAX as usize {
            return Err(NoLineGaps);
        }
        let (gaps, rest) = slots.split_at_mut(3 * cap);
        let (queue, rest) = rest.split_at_mut(2 * cap);
        let fen = rest.get_mut(..2 * cap.div_ceil(BLOCK)).ok_or(NoLineGaps)?;
        Ok(LineGaps {
            gaps,
            fen,
            queue,
            cap,
            ids: 0,
            heap: 0,
            sum: 0,
            count: 0,
            known: 0,
            layout: None,
            total: 0.0,
            clearance: 0.0,
            scale: 1.0,
            unit: 1.0,
            slack: 0.0,
            exact: true,
            last_weight: 0,
            rejected: 0,
            _scalar: core::marker::PhantomData,
        })
    }

    /// The segments these slots can serve ([`line_gaps_for`] inverted).
    pub fn capacity(&self) -> usize {
        self.cap - 1
    }

    /// Active gaps: those the next segment may be drawn in.
    pub fn active(&self) -> u64 {
        self.count
    }

    /// Gaps waiting for a shorter segment.
    pub fn waiting(&self) -> usize {
        self.heap
    }

    /// The measure, in mm, of the starts the last placement was drawn over: the valid starts
    /// grown by at most a slack of `2^-48` of the interval's power of two per active gap
    /// (plus, for fixed point, its outline slack).
    pub fn last_measure(&self) -> f64 {
        self.last_weight as f64 * self.unit
    }

    /// Candidates the exact tests turned down so far (only rounding slack can be turned
    /// down).
    pub fn rejected(&self) -> u64 {
        self.rejected
    }

    /// Brings the gaps up to date with `engine`: lays them out on first use (or for another
    /// interval), then splits the gaps of the segments placed since they last looked (by
    /// [`LineEngine::step`]; O(gaps) each). `None` when the slots run out.
    pub(super) fn sync(&mut self, engine: &LineEngine<'_, S>) -> Option<()> {
        let iv = engine.interval;
        let layout = (iv.length, iv.periodic, engine.params.gap);
        if self.layout != Some(layout) || self.known > engine.len {
            self.lay_out(engine, layout)?;
        }
        while self.known < engine.len {
            let s = engine.segments.get(self.known).copied()?;
            let (a, b) = (s.start, s.end());
            if !self.has_room() {
                return None;
            }
            match self.find(a) {
                Some(g) => self.split(g, a, b, 0)?,
                None => self.exact = false,
            }
            self.known += 1;
        }
        Some(())
    }

    /// Starts afresh: the whole inclusive interval as one gap, or on a circle the gap from
    /// the first segment's end around to its start.
    fn lay_out(&mut self, engine: &LineEngine<'_, S>, layout: (f64, bool, f64)) -> Option<()> {
        self.fen.iter_mut().for_each(|s| *s = LineGap::default());
        self.gaps.iter_mut().for_each(|s| *s = LineGap::default());
        let (_, e) = libm::frexp(layout.0);
        self.scale = libm::ldexp(1.0, UNIT_BITS - e);
        self.unit = libm::ldexp(1.0, e - UNIT_BITS);
        self.slack = libm::ldexp(1.0, e - SLACK_BITS) + S::OUTLINE_SLACK[1];
        (self.total, self.clearance) = (engine.total.to_f64(), engine.gap.to_f64());
        (self.ids, self.heap, self.sum, self.count, self.known) = (0, 0, 0, 0, 0);
        self.exact = true;
        self.layout = Some(layout);
        if layout.1 {
            let s = engine.segments.get(..engine.len)?.first().copied()?;
            self.known = 1;
            self.add(s.end(), s.start, true, 0)
        } else {
            self.add(S::ZERO, engine.total, false, 0)
        }
    }

    /// Whether `scale` is usable (an interval of a normal size).
    pub(super) fn usable(&self) -> bool {
        self.scale.is_finite() && self.unit > 0.0
    }

    /// Whether every gap's ends are its neighbours' as stored.
    pub(super) fn exact(&self) -> bool {
        self.exact
    }

    /// Whether one more gap fits in the slots.
    pub(super) fn has_room(&self) -> bool {
        self.ids < self.cap
    }

    /// A length in units, rounded down.
    pub(super) fn len_units(&self, len: S) -> u64 {
        let v = libm::floor(len.to_f64() * self.scale);
        if v > 0.0 {
            v.min(ROOM_MAX) as u64
        } else {
            0
        }
    }

    /// A gap's room in units: its length less twice the clearance, plus the slack, rounded
    /// up; 0 when that is not positive.
    fn room(&self, lo: S, hi: S, wraps: bool) -> u64 {
        let span = if wraps {
            (hi.to_f64() + self.total) - lo.to_f64()
        } else {
            hi.to_f64() - lo.to_f64()
        };
        let v = libm::ceil((span - 2.0 * self.clearance + self.slack) * self.scale);
        if v > 0.0 {
            v.min(ROOM_MAX) as u64
        } else {
            0
        }
    }

    /// Gap `id`'s room word.
    fn word(&self, id: usize) -> u64 {
        self.gaps.get(3 * id + 2).map_or(0, |s| s.0)
    }

    fn set_word(&mut self, id: usize, w: u64) {
        if let Some(s) = self.gaps.get_mut(3 * id + 2) {
            s.0 = w;
        }
    }

    /// Gap `id` as stored.
    fn gap(&self, id: usize) -> Option<Gap<S>> {
        match self.gaps.get(3 * id..3 * id + 3)? {
            [lo, hi, w] => Some(Gap {
                id: id as u32,
                lo: S::from_word(lo.0),
                hi: S::from_word(hi.0),
                wraps: w.0 & WRAPS != 0,
            }),
            _ => None,
        }
    }

    /// Makes a new gap of the stretch `(lo, hi)`; see [`Self::put`].
    fn add(&mut self, lo: S, hi: S, wraps: bool, len: u64) -> Option<()> {
        let id = self.ids;
        self.ids += 1;
        self.put(id, lo, hi, wraps, len)
    }

    /// Makes gap `id` the stretch `(lo, hi)`: active when its room exceeds `len` units,
    /// waiting when it is smaller, forgotten when it has none.
    fn put(&mut self, id: usize, lo: S, hi: S, wraps: bool, len: u64) -> Option<()> {
        let room = self.room(lo, hi, wraps);
        if let [l, h, _] = self.gaps.get_mut(3 * id..3 * id + 3)? {
            (l.0, h.0) = (lo.to_word(), hi.to_word());
        }
        let flag = if wraps { WRAPS } else { 0 };
        if room == 0 {
            self.set_word(id, 0);
        } else if room > len {
            self.set_word(id, room | flag);
            self.fenwick(id, room, true);
        } else {
            self.set_word(id, room | flag | WAITING);
            self.push(room, id as u32);
        }
        Some(())
    }

    /// Splits gap `g` around the segment `[a, b]` placed in it: the left part keeps the id,
    /// the right part takes a new one. `len` is the current length in units.
    pub(super) fn split(&mut self, g: Gap<S>, a: S, b: S, len: u64) -> Option<()> {
        let id = g.id as usize;
        let w = self.word(id);
        if w & WAITING != 0 {
            self.unqueue(id as u32);
        } else if w != 0 {
            self.fenwick(id, w & ROOM, false);
        }
        // On the gap across the seam, a start before `lo` lies past the seam.
        let past = g.wraps && a < g.lo;
        self.put(id, g.lo, a, g.wraps && past, len)?;
        self.add(b, g.hi, g.wraps && !past, len)
    }

    /// Notes that the engine now holds `placed` segments, all known to the gaps.
    pub(super) fn caught_up(&mut self, placed: usize) {
        self.known = placed;
    }

    /// The live gap holding a start `a` (O(gaps)), for segments placed by the paper's
    /// sampler.
    fn find(&self, a: S) -> Option<Gap<S>> {
        (0..self.ids).find_map(|id| {
            let g = self.gap(id)?;
            let inside = if g.wraps { a >= g.lo || a < g.hi } else { a >= g.lo && a < g.hi };
            (self.word(id) != 0 && inside).then_some(g)
        })
    }

    /// Activates the waiting gaps whose room exceeds `len` units.
    pub(super) fn activate(&mut self, len: u64) {
        while self.heap > 0 {
            let (room, id) = self.key(0);
            if room <= len {
                return;
            }
            self.remove_at(0);
            let id = id as usize;
            let w = self.word(id);
            self.set_word(id, w & !WAITING);
            self.fenwick(id, room, true);
        }
    }

    /// The measure of the starts of a segment of `len` units, in units: every active gap's
    /// room less `len`.
    pub(super) fn weight(&self, len: u64) -> u64 {
        // Each active room exceeds `len`, so the product is below the sum: no overflow.
        self.sum.saturating_sub(len.wrapping_mul(self.count))
    }

    /// Draws a point uniformly over the measure of starts: the gap it falls in and its
    /// offset from the gap's first start, in units. The Fenwick tree finds the block, a scan
    /// of its rooms the gap.
    pub(super) fn draw<R: RngCore + ?Sized>(&mut self, rng: &mut R, len: u64) -> Option<(Gap<S>, u64)> {
        let total = self.weight(len);
        self.last_weight = total;
        let mut rest = crate::rng::below(rng, total);
        let n = self.fen.len() / 2;
        let mut pos = 0usize;
        let mut step = 1usize << (usize::BITS - 1 - n.leading_zeros());
        while step > 0 {
            let next = pos + step;
            if let Some([sum, count]) = self.fen.get(2 * next.wrapping_sub(1)..2 * next) {
                let w = sum.0.saturating_sub(len.wrapping_mul(count.0));
                if w <= rest {
                    pos = next;
                    rest -= w;
                }
            }
            step >>= 1;
        }
        let first = pos * BLOCK;
        let block = self.gaps.get(3 * first..3 * (first + BLOCK).min(self.cap))?;
        for (k, g) in block.chunks_exact(3).enumerate() {
            let [lo, hi, w] = [g.first()?.0, g.get(1)?.0, g.get(2)?.0];
            if w & WAITING != 0 || w == 0 {
                continue;
            }
            let weight = (w & ROOM).saturating_sub(len);
            if rest < weight {
                let gap = Gap {
                    id: (first + k) as u32,
                    lo: S::from_word(lo),
                    hi: S::from_word(hi),
                    wraps: w & WRAPS != 0,
                };
                return Some((gap, rest));
            }
            rest -= weight;
        }
        None
    }

    /// A rejected candidate.
    pub(super) fn reject(&mut self) {
        self.rejected = self.rejected.saturating_add(1);
    }

    /// The offset of `units` in mm.
    pub(super) fn offset(&self, units: u64) -> S {
        S::from_f64(units as f64 * self.unit)
    }

    /// Adds or removes an active gap's room in the Fenwick tree (at its block's leaf).
    fn fenwick(&mut self, id: usize, room: u64, add: bool) {
        let mut i = id / BLOCK + 1;
        while let Some([sum, count]) = self.fen.get_mut(2 * (i - 1)..2 * i) {
            if add {
                (sum.0, count.0) = (sum.0.wrapping_add(room), count.0.wrapping_add(1));
            } else {
                (sum.0, count.0) = (sum.0.wrapping_sub(room), count.0.wrapping_sub(1));
            }
            i += i & i.wrapping_neg();
        }
        if add {
            self.sum = self.sum.wrapping_add(room);
            self.count += 1;
        } else {
            self.sum = self.sum.wrapping_sub(room);
            self.count = self.count.saturating_sub(1);
        }
    }

    fn key(&self, h: usize) -> (u64, u32) {
        match self.queue.get(2 * h..2 * h + 2) {
            Some([room, id]) => (room.0, id.0 as u32),
            _ => (0, 0),
        }
    }

    fn set(&mut self, h: usize, key: (u64, u32)) {
        if let Some([room, id]) = self.queue.get_mut(2 * h..2 * h + 2) {
            (room.0, id.0) = (key.0, u64::from(key.1));
        }
    }

    /// Pushes a waiting gap (the heap has a place for every gap).
    fn push(&mut self, room: u64, id: u32) {
        let mut h = self.heap;
        self.heap += 1;
        while h > 0 {
            let parent = (h - 1) / 4;
            let up = self.key(parent);
            if up >= (room, id) {
                break;
            }
            self.set(h, up);
            h = parent;
        }
        self.set(h, (room, id));
    }

    /// Removes a waiting gap from the heap (O(waiting): only for segments placed elsewhere).
    fn unqueue(&mut self, id: u32) {
        if let Some(h) = (0..self.heap).find(|&h| self.key(h).1 == id) {
            self.remove_at(h);
        }
    }

    /// Removes heap entry `h`, moving the last entry into its place.
    fn remove_at(&mut self, h: usize) {
        if h >= self.heap {
            return;
        }
        self.heap -= 1;
        let last = self.key(self.heap);
        if h == self.heap {
            return;
        }
        let mut h = h;
        while h > 0 {
            let parent = (h - 1) / 4;
            let up = self.key(parent);
            if up >= last {
                break;
            }
            self.set(h, up);
            h = parent;
        }
        loop {
            let (mut big, mut best) = (h, last);
            for c in 4 * h + 1..(4 * h + 5).min(self.heap) {
                let k = self.key(c);
                if k > best {
                    (big, best) = (c, k);
                }
            }
            if big == h {
                break;
            }
            let k = self.key(big);
            self.set(h, k);
            h = big;
        }
        self.set(h, last);
    }
}
