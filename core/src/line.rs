//! The one-dimensional fill: segments in an interval (Shier and Bourke, "An Algorithm for
//! Random Fractal Filling of Space", Figure 3).
//!
//! Segment `i` has length `L_i = L / (zeta(c, N) (i + N)^c)` in an interval `[0, L]`, so the
//! lengths add up to `L`. Each trial draws one unit value `u` (see [`crate::internals::rng`]) and puts the
//! segment's start at `lo + u (hi - lo)`: with an inclusive boundary `lo = gap`,
//! `hi = L - gap - L_i` (the starts where the segment lies inside, at least `gap` from each
//! end); with a periodic boundary (a circle of circumference `L`) `lo = 0`, `hi = L`, and a
//! segment that runs past `L` exists again at `start - L`. A candidate is accepted when it keeps
//! more than `gap` from every placed segment and its periodic images (touching is overlapping
//! when `gap = 0`), exactly as in 2D.
//!
//! Placed segments are indexed by a one-dimensional version of the multi-level spatial hash of
//! [`crate::internals::spatial`]: level `l` cuts the interval into cells of length `L / 2^l`; a segment of
//! length `len` lives at the finest level whose cells are at least `len` long, in the cell of
//! its start. A query looks, level by level (coarsest first), at the two or three cells its
//! reach can touch, so
//! a trial costs O(levels) = O(log(L_0 / L_n)) whatever the number of segments, and an
//! insertion is O(1). Bucket collisions only add work; every listed segment is tested exactly.
//!
//! Guarantees, as for the 2D engine: the caller owns the storage (a segment slice and an index
//! slice, [`line_index_words`]); no public function panics on any input (bad parameters are a
//! [`ParamError`], running out of storage, halting and a first segment that cannot fit are a
//! [`StepError`] with everything placed so far intact); the same seed and parameters give the
//! same bits on every target; the first `k` segments never depend on how many are asked for.

use crate::digest::{add_shape, Fnv1a};
use crate::engine::Stats;
use crate::params::{ParamError, StepError, Stop, StopReason};
use crate::rng;
use crate::scalar::{powf, Scalar};
use rand_core::RngCore;

/// Number of size levels of the index (cell lengths from `L` down to `L / 2^47`).
pub const LINE_LEVELS: usize = 48;

/// The empty-list marker.
const NIL: u32 = u32::MAX;

/// The parameters of a 1D fill.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LineParams {
    /// The power-law exponent c (> 1).
    pub c: f64,
    /// The offset N of the paper (> 0, need not be an integer).
    pub n_offset: f64,
    /// Minimum clearance between segments and to the ends of the interval (>= 0).
    pub gap: f64,
    /// Trial limit per placement (>= 1): reaching it halts the fill.
    pub max_trials: u64,
}

impl LineParams {
    /// Exponent and offset, no gap, the default trial limit (10^7).
    pub fn new(c: f64, n_offset: f64) -> Self {
        LineParams {
            c,
            n_offset,
            gap: 0.0,
            max_trials: 10_000_000,
        }
    }

    /// c for a fractal dimension D in 1D (c = 1 / D).
    pub fn c_from_dimension(d: f64) -> f64 {
        1.0 / d
    }
}

/// The interval `[0, length]`, inclusive or periodic.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Interval {
    /// Length L, finite and > 0.
    pub length: f64,
    /// Periodic boundary (the interval is a circle of circumference L) when true.
    pub periodic: bool,
}

/// A placed segment `[start, start + length]`. `Segment::default()` is an empty slot.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Segment<S> {
    /// Left end; in `[0, L)` for a periodic interval.
    pub start: S,
    /// Length (> 0).
    pub length: S,
}

impl<S: Scalar> Segment<S> {
    /// Right end `start + length` (beyond `L` when a periodic segment wraps).
    pub fn end(&self) -> S {
        self.start + self.length
    }
}

/// One placement: the segment, its nominal length and the trials it took.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinePlacement<S> {
    /// Placement index i (0 for the longest segment).
    pub index: u64,
    /// The segment as stored.
    pub segment: Segment<S>,
    /// L_i.
    pub length: f64,
    /// Trials spent on this placement (>= 1).
    pub trials: u64,
}

/// Index words needed for `capacity` segments: one link each plus `2 * capacity` buckets.
pub const fn line_index_words(capacity: usize) -> usize {
    capacity * 3 + 1
}

/// The caller-owned storage of a [`LineEngine`].
#[derive(Debug)]
pub struct LineStorage<'a, S> {
    /// One slot per segment: its length is the capacity.
    pub segments: &'a mut [Segment<S>],
    /// The index: longer than `segments` ([`line_index_words`] recommends the size).
    pub index: &'a mut [u32],
}

#[derive(Clone, Copy, Debug)]
struct Level<S> {
    cell: S,
    inv: S,
    count: u32,
    max_len: S,
}

/// The multi-level 1D hash over borrowed buckets and links.
#[derive(Debug)]
struct LineHash<'a, S> {
    heads: &'a mut [u32],
    next: &'a mut [u32],
    mask: usize,
    levels: [Level<S>; LINE_LEVELS],
}

impl<'a, S: Scalar> LineHash<'a, S> {
    fn new(heads: &'a mut [u32], next: &'a mut [u32], extent: S) -> Option<Self> {
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

    fn insert(&mut self, idx: u32, start: S, len: S) {
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
    fn query(&self, lo: S, hi: S, total: u32, mut f: impl FnMut(u32) -> bool) -> bool {
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

/// The 1D fill engine over caller-provided storage.
///
/// ```
/// use zetafill::{line_index_words, rng_from_seed, Interval, LineEngine, LineParams, LineStorage, Segment, Stop, StopReason};
///
/// let mut segments = [Segment::<f64>::default(); 50];
/// let mut index = [0u32; line_index_words(50)];
/// let storage = LineStorage { segments: &mut segments, index: &mut index };
/// let interval = Interval { length: 100.0, periodic: false };
/// let mut line = LineEngine::new(LineParams::new(1.4, 1.0), interval, storage)?;
/// let stop = Stop { count: Some(50), ..Stop::default() };
/// assert_eq!(line.run(&mut rng_from_seed(1), &stop, |_| {}), StopReason::Count);
/// assert!(line.placed().iter().all(|s| s.start >= 0.0 && s.end() <= 100.0));
/// # Ok::<(), zetafill::ParamError>(())
/// ```
#[derive(Debug)]
pub struct LineEngine<'a, S: Scalar> {
    params: LineParams,
    interval: Interval,
    segments: &'a mut [Segment<S>],
    len: usize,
    hash: LineHash<'a, S>,
    zeta: f64,
    placed_length: f64,
    trials: u64,
    gap: S,
    total: S,
    /// The largest right end of any placed segment.
    max_end: S,
}

impl<'a, S: Scalar> LineEngine<'a, S> {
    /// Validates the parameters and builds an engine over the caller's storage. An interval
    /// longer than the scalar computes exactly ([`Scalar::MAX_EXTENT`]) is refused.
    pub fn new(params: LineParams, interval: Interval, storage: LineStorage<'a, S>) -> Result<Self, ParamError> {
        let LineStorage { segments, index } = storage;
        if !(params.c.is_finite() && params.c > 1.0) {
            return Err(ParamError::Exponent);
        }
        if !(params.n_offset.is_finite() && params.n_offset > 0.0) {
            return Err(ParamError::Offset);
        }
        let l = interval.length;
        if !(l.is_finite() && l > 0.0) {
            return Err(ParamError::Region);
        }
        if l > S::MAX_EXTENT {
            return Err(ParamError::Extent);
        }
        if !(params.gap.is_finite() && params.gap >= 0.0 && 2.0 * params.gap < l) {
            return Err(ParamError::Gap);
        }
        if params.max_trials == 0 {
            return Err(ParamError::MaxTrials);
        }
        if segments.is_empty() || index.len() <= segments.len() || segments.len() >= NIL as usize {
            return Err(ParamError::Storage);
        }
        let zeta = crate::zeta::zeta(params.c, params.n_offset).map_err(|_| ParamError::Zeta)?;
        let (next, heads) = index.split_at_mut(segments.len());
        let hash = LineHash::new(heads, next, S::from_f64(l)).ok_or(ParamError::Storage)?;
        Ok(LineEngine {
            params,
            interval,
            segments,
            len: 0,
            hash,
            zeta,
            placed_length: 0.0,
            trials: 0,
            gap: S::from_f64(params.gap),
            total: S::from_f64(l),
            max_end: S::ZERO,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &LineParams {
        &self.params
    }

    /// The interval.
    pub fn interval(&self) -> &Interval {
        &self.interval
    }

    /// zeta(c, N) used for the length sequence.
    pub fn zeta(&self) -> f64 {
        self.zeta
    }

    /// L_i = L / (zeta(c, N) (i + N)^c).
    pub fn length_of(&self, i: u64) -> f64 {
        self.interval.length / (self.zeta * powf(i as f64 + self.params.n_offset, self.params.c))
    }

    /// The segments placed so far, in placement order.
    pub fn placed(&self) -> &[Segment<S>] {
        self.segments.get(..self.len).unwrap_or(&[])
    }

    /// Statistics so far (`fill_fraction` is placed length over L).
    pub fn stats(&self) -> Stats {
        Stats {
            placed: self.len as u64,
            trials: self.trials,
            fill_fraction: self.placed_length / self.interval.length,
        }
    }

    /// The storage capacity in segments.
    pub fn capacity(&self) -> usize {
        self.segments.len()
    }

    /// Whether the candidate `[a, b]` keeps more than `gap` from every placed segment.
    fn clear_at(&self, a: S, b: S) -> bool {
        let gap = self.gap;
        self.hash
            .query(a - gap, b + gap, self.len as u32, |j| match self.segments.get(j as usize) {
                Some(s) => a > s.end() + gap || b + gap < s.start,
                None => true,
            })
    }

    /// Whether the candidate `[a, b]` (with `a` in `[0, L)`) is clear, with every periodic
    /// image of it in a periodic interval.
    fn clear(&self, a: S, b: S) -> bool {
        if !self.clear_at(a, b) {
            return false;
        }
        if !self.interval.periodic {
            return true;
        }
        let l = self.total;
        // The image at a - L meets segments near 0 when the candidate runs past L; the image
        // at a + L meets segments that run past L.
        if b + self.gap >= l && !self.clear_at(a - l, b - l) {
            return false;
        }
        if a - self.gap <= self.max_end - l && !self.clear_at(a + l, b + l) {
            return false;
        }
        true
    }

    /// Whether a segment of length `len` can lie in the interval at all.
    fn can_fit(&self, len: S) -> bool {
        if self.interval.periodic {
            // It must keep its gap from its own image at +L.
            len + self.gap < self.total
        } else {
            len + self.gap + self.gap <= self.total
        }
    }

    /// Places the next segment, drawing candidates from `rng` until one fits or the trial
    /// limit is reached. On error nothing is placed and the engine may be stepped again.
    pub fn step<R: RngCore + ?Sized>(&mut self, rng: &mut R) -> Result<LinePlacement<S>, StepError> {
        let i = self.len;
        let index = i as u64;
        if i >= self.segments.len() {
            return Err(StepError::Capacity {
                capacity: self.segments.len() as u64,
            });
        }
        let length = self.length_of(index);
        if S::MIN_SIZE > 0.0 && length < S::MIN_SIZE {
            return Err(StepError::TooSmall { index });
        }
        let len = S::from_f64(length);
        if !(len > S::ZERO && len.is_finite() && self.can_fit(len)) {
            return Err(StepError::CannotFit { index });
        }
        let (lo, hi) = if self.interval.periodic {
            (S::ZERO, self.total)
        } else {
            (self.gap, self.total - self.gap - len)
        };
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials {
                return Err(StepError::Halted { index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let u: S = rng::unit(rng);
            let mut a = lo + u * (hi - lo);
            if self.interval.periodic {
                if a >= self.total {
                    a = a - self.total;
                }
            } else if !(a >= self.gap && a + len <= self.total - self.gap) {
                continue;
            }
            let b = a + len;
            if !self.clear(a, b) {
                continue;
            }
            let segment = Segment { start: a, length: len };
            if let Some(slot) = self.segments.get_mut(i) {
                *slot = segment;
            }
            self.hash.insert(i as u32, a, len);
            self.max_end = self.max_end.max(b);
            self.len += 1;
            self.placed_length += length;
            return Ok(LinePlacement {
                index,
                segment,
                length,
                trials,
            });
        }
    }

    /// Steps until a stop condition holds or a step fails, calling `on_place` after each
    /// placement. `Stop::min_size` is compared with the next segment's length.
    pub fn run<R: RngCore + ?Sized>(&mut self, rng: &mut R, stop: &Stop, mut on_place: impl FnMut(&LinePlacement<S>)) -> StopReason {
        loop {
            let n = self.len as u64;
            if stop.count.is_some_and(|k| n >= k) {
                return StopReason::Count;
            }
            if stop.fill.is_some_and(|f| self.placed_length >= f * self.interval.length) {
                return StopReason::Fill;
            }
            if stop.min_size.is_some_and(|m| self.length_of(n) < m) {
                return StopReason::MinSize;
            }
            match self.step(rng) {
                Ok(p) => on_place(&p),
                Err(e) => return StopReason::Step(e),
            }
        }
    }
}

/// The determinism digest of a 1D fill: FNV-1a 64 over, for every placed segment in order,
/// the bits of its start, 0, its nominal length L_i and 0 (the 2D digest's record with
/// y = angle = 0), `-0.0` written as `0.0`. Returns `(count, hash)`.
pub fn line_digest<S: Scalar>(e: &LineEngine<'_, S>) -> (u64, u64) {
    let mut h = Fnv1a::default();
    for (i, s) in e.placed().iter().enumerate() {
        add_shape(&mut h, s.start, S::ZERO, e.length_of(i as u64), S::ZERO);
    }
    (e.placed().len() as u64, h.finish())
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

    fn run(periodic: bool, k: usize, seed: u64) -> (u64, u64) {
        let mut segs = [Segment::<f64>::default(); 64];
        let mut idx = [0u32; line_index_words(64)];
        let storage = LineStorage {
            segments: &mut segs,
            index: &mut idx,
        };
        let Ok(mut e) = LineEngine::new(LineParams::new(1.4, 1.0), Interval { length: 100.0, periodic }, storage) else {
            return (0, 0);
        };
        let mut rng = crate::rng_from_seed(seed);
        e.run(
            &mut rng,
            &Stop {
                count: Some(k as u64),
                ..Stop::default()
            },
            |_| {},
        );
        line_digest(&e)
    }

    #[test]
    fn runs_and_is_deterministic() {
        let a = run(false, 50, 3);
        assert_eq!(a.0, 50);
        assert_eq!(a, run(false, 50, 3));
        assert_ne!(a, run(false, 50, 4));
        assert_eq!(run(true, 50, 3).0, 50);
    }

    #[test]
    fn lengths_sum_to_the_interval() {
        let mut segs = [Segment::<f64>::default(); 1];
        let mut idx = [0u32; 4];
        let storage = LineStorage {
            segments: &mut segs,
            index: &mut idx,
        };
        let Ok(e) = LineEngine::new(
            LineParams::new(2.0, 1.0),
            Interval {
                length: 1.0,
                periodic: false,
            },
            storage,
        ) else {
            panic!("engine")
        };
        let s: f64 = (0..100_000u64).rev().map(|i| e.length_of(i)).sum();
        assert!((s - 1.0).abs() < 2e-5, "{s}");
    }
}
