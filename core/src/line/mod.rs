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
use crate::scalar::Scalar;
use crate::AreaSequence;
use rand_core::RngCore;

mod fast;
mod gaps;
mod hash;

pub use gaps::{line_gaps_for, LineGap, LineGaps, NoLineGaps};
use hash::LineHash;

/// Number of size levels of the index (cell lengths from `L` down to `L / 2^47`).
pub const LINE_LEVELS: usize = 48;

/// The empty-list marker.
const NIL: u32 = u32::MAX;

/// The parameters of a 1D fill. See [`LineEngine`] for a fill.
///
/// # Examples
///
/// ```
/// use zetafill::line::Params;
///
/// // Segments of fractal dimension 0.5, 0.1 apart.
/// let params = Params { gap: 0.1, ..Params::new(Params::c_from_dimension(0.5), 1.0) };
/// assert_eq!((params.c, params.n_offset, params.gap), (2.0, 1.0, 0.1));
/// ```
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
///
/// # Examples
///
/// On a circle of circumference 10 a segment may run past the end: it exists again from 0.
///
/// ```
/// use zetafill::{rng_from_seed, Stop};
/// use zetafill::line::{index_words, Engine, Interval, Params, Segment, Storage};
///
/// let mut segments = [Segment::<f64>::default(); 200];
/// let mut index = [0u32; index_words(200)];
/// let storage = Storage { segments: &mut segments, index: &mut index };
/// let circle = Interval { length: 10.0, periodic: true };
/// let mut line = Engine::new(Params::new(1.3, 1.0), circle, storage)?;
/// line.run(&mut rng_from_seed(6), &Stop { count: Some(200), ..Stop::default() }, |_| {});
/// let placed = line.placed();
/// assert!(placed.iter().all(|s| s.start >= 0.0 && s.start < 10.0));
/// // No two segments meet, measured around the circle.
/// for (i, a) in placed.iter().enumerate() {
///     for b in &placed[i + 1..] {
///         let (ab, ba) = ((b.start - a.start).rem_euclid(10.0), (a.start - b.start).rem_euclid(10.0));
///         assert!(ab > a.length && ba > b.length);
///     }
/// }
/// # Ok::<(), zetafill::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Interval {
    /// Length L, finite and > 0.
    pub length: f64,
    /// Periodic boundary (the interval is a circle of circumference L) when true.
    pub periodic: bool,
}

/// A placed segment `[start, start + length]`. `Segment::default()` is an empty slot (see
/// [`LineStorage`]).
///
/// # Examples
///
/// ```
/// use zetafill::line::Segment;
///
/// let s = Segment { start: 2.0, length: 0.5 };
/// assert_eq!(s.end(), 2.5);
/// ```
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

/// One placement: the segment, its nominal length and the trials it took
/// ([`LineEngine::step`]).
///
/// # Examples
///
/// ```
/// use zetafill::rng_from_seed;
/// use zetafill::line::{index_words, Engine, Interval, Params, Segment, Storage};
///
/// let mut segments = [Segment::<f64>::default(); 10];
/// let mut index = [0u32; index_words(10)];
/// let storage = Storage { segments: &mut segments, index: &mut index };
/// let interval = Interval { length: 100.0, periodic: false };
/// let mut line = Engine::new(Params::new(1.4, 1.0), interval, storage)?;
/// let mut rng = rng_from_seed(2);
/// let first = line.step(&mut rng)?;
/// assert_eq!((first.index, first.length), (0, line.length_of(0)));
/// assert_eq!(first.segment.length, first.length);
/// assert!(first.trials >= 1);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
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

/// Index words needed for `capacity` segments: one link each plus `2 * capacity` buckets (the
/// length of [`LineStorage::index`]; see [`LineEngine`] for an example).
pub const fn line_index_words(capacity: usize) -> usize {
    capacity * 3 + 1
}

/// The caller-owned storage of a [`LineEngine`] (see its example). An index no longer than
/// the segment slots is refused.
///
/// # Examples
///
/// ```
/// use zetafill::ParamError;
/// use zetafill::line::{Engine, Interval, Params, Segment, Storage};
///
/// let (mut segments, mut index) = ([Segment::<f64>::default(); 8], [0u32; 8]);
/// let storage = Storage { segments: &mut segments, index: &mut index };
/// let interval = Interval { length: 1.0, periodic: false };
/// assert_eq!(Engine::new(Params::new(1.4, 1.0), interval, storage).err(), Some(ParamError::Storage));
/// ```
#[derive(Debug)]
pub struct LineStorage<'a, S> {
    /// One slot per segment: its length is the capacity.
    pub segments: &'a mut [Segment<S>],
    /// The index: longer than `segments` ([`line_index_words`] recommends the size).
    pub index: &'a mut [u32],
}

/// The 1D fill engine over caller-provided storage.
///
/// # Examples
///
/// ```
/// use zetafill::{rng_from_seed, Stop, StopReason};
/// use zetafill::line::{index_words, Engine, Interval, Params, Segment, Storage};
///
/// let mut segments = [Segment::<f64>::default(); 50];
/// let mut index = [0u32; index_words(50)];
/// let storage = Storage { segments: &mut segments, index: &mut index };
/// let interval = Interval { length: 100.0, periodic: false };
/// let mut line = Engine::new(Params::new(1.4, 1.0), interval, storage)?;
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
    /// Segments `0..hashed` are in the hash; the exact sampler leaves the rest out until a
    /// test needs them ([`LineEngine::catch_up`]).
    hashed: usize,
    /// The lengths `L_i`, over the interval's length.
    seq: AreaSequence,
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
        crate::params::check_power_law(params.c, params.n_offset)?;
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
        let seq = AreaSequence::new(interval.length, params.c, params.n_offset).map_err(|_| ParamError::Zeta)?;
        let (next, heads) = index.split_at_mut(segments.len());
        let hash = LineHash::new(heads, next, S::from_f64(l)).map_err(|_| ParamError::Storage)?;
        Ok(LineEngine {
            params,
            interval,
            segments,
            len: 0,
            hash,
            hashed: 0,
            seq,
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
        self.seq.zeta()
    }

    /// L_i = L / (zeta(c, N) (i + N)^c).
    pub fn length_of(&self, i: u64) -> f64 {
        self.seq.area(i)
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

    /// Puts the segments the exact sampler placed without the hash into it.
    fn catch_up(&mut self) {
        while self.hashed < self.len {
            let Some(s) = self.segments.get(self.hashed).copied() else { return };
            self.hash.insert(self.hashed as u32, s.start, s.length);
            self.hashed += 1;
        }
    }

    /// Whether the candidate `[a, b]` keeps more than `gap` from every placed segment (the
    /// hash must hold them all: [`LineEngine::catch_up`]).
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

    /// The next segment's index, nominal length L_i and stored length, or why it cannot be
    /// placed (the storage is full, or it is too short for the scalar or too long to fit).
    fn next(&self) -> Result<(u64, f64, S), StepError> {
        let index = self.len as u64;
        if self.len >= self.segments.len() {
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
        Ok((index, length, len))
    }

    /// Stores the accepted segment `[a, a + len]` (`a` in `[0, L)`) as the next one, in the
    /// hash too when `hash` and the hash is up to date.
    fn commit(&mut self, a: S, len: S, length: f64, trials: u64, hash: bool) -> LinePlacement<S> {
        let i = self.len;
        let segment = Segment { start: a, length: len };
        if let Some(slot) = self.segments.get_mut(i) {
            *slot = segment;
        }
        if hash && self.hashed == i {
            self.hash.insert(i as u32, a, len);
            self.hashed += 1;
        }
        self.max_end = self.max_end.max(segment.end());
        self.len += 1;
        self.placed_length += length;
        LinePlacement {
            index: i as u64,
            segment,
            length,
            trials,
        }
    }

    /// Places the next segment, drawing candidates from `rng` until one fits or the trial
    /// limit is reached: the paper's sampler. On error nothing is placed and the engine may be
    /// stepped again.
    pub fn step<R: RngCore + ?Sized>(&mut self, rng: &mut R) -> Result<LinePlacement<S>, StepError> {
        let (index, length, len) = self.next()?;
        self.catch_up();
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
            } else if !self.in_range(a, len) {
                continue;
            }
            if self.clear(a, a + len) {
                return Ok(self.commit(a, len, length, trials, true));
            }
        }
    }

    /// Whether a segment of length `len` starting at `a` lies in an inclusive interval at
    /// least `gap` from each end.
    fn in_range(&self, a: S, len: S) -> bool {
        a >= self.gap && a + len <= self.total - self.gap
    }

    /// Steps until a stop condition holds or a step fails, calling `on_place` after each
    /// placement. `Stop::min_size` is compared with the next segment's length.
    pub fn run<R: RngCore + ?Sized>(&mut self, rng: &mut R, stop: &Stop, on_place: impl FnMut(&LinePlacement<S>)) -> StopReason {
        self.run_with(stop, on_place, |e| e.step(rng))
    }

    /// The stop conditions around any step function.
    fn run_with(
        &mut self,
        stop: &Stop,
        on_place: impl FnMut(&LinePlacement<S>),
        step: impl FnMut(&mut Self) -> Result<LinePlacement<S>, StepError>,
    ) -> StopReason {
        let stops = |e: &Self| {
            let n = e.len as u64;
            stop.holds(n, e.placed_length, e.interval.length, || e.length_of(n))
        };
        crate::params::run_until(self, stops, on_place, step)
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
