//! The engine's side of the exact 1D sampler: the placement loop over [`LineGaps`] and the
//! test that decides a start by its gap's two neighbours. Why its placements have exactly the
//! paper's distribution is written out on [`LineEngine::step_fast`].

use super::gaps::Gap;
use super::{LineEngine, LineGaps, LinePlacement};
use crate::params::{StepError, Stop, StopReason};
use crate::scalar::Scalar;
use rand_core::RngCore;

impl<S: Scalar> LineEngine<'_, S> {
    /// Places the next segment with the exact sampler: its start is drawn uniformly over the
    /// starts where it fits, from the free gaps kept in `gaps`, in O(log n) and almost always
    /// at the first trial. The placements have the same distribution as [`LineEngine::step`]'s
    /// (the paper's sampler), not the same values: the two use the random numbers differently.
    ///
    /// ## Why the distribution is the paper's
    /// The paper's sampler draws starts uniformly over `[lo, hi]` (see [`LineEngine`]) and keeps
    /// the first that passes the exact test, so its placement is uniform over the set `V` of
    /// valid starts. Here, for a segment of length `len` and clearance `gap`, a gap of length
    /// `g` between two neighbours (or a neighbour and an end of an inclusive interval) offers
    /// the starts `(lo + gap, hi - gap - len)`, of measure `g - 2 gap - len` when positive; on a
    /// circle the gap across `L` runs on past it. Each gap's *room* `g - 2 gap` is kept in
    /// integer units (`2^-56` of the power of two at or above `L`), rounded up and grown by a
    /// slack (`2^-48` of that power of two, plus fixed point's outline slack) that bounds the
    /// rounding of the room and of the tests below; the length is rounded down. So each gap's
    /// weight `room - len` is never below the measure of its valid starts: rounding can only
    /// overcount. A trial draws an integer uniformly below the total weight `W` (the crate's
    /// bounded draw, [`crate::internals::rng::below`]), finds the gap it falls in and the
    /// offset in it (a Fenwick tree over blocks of 16 gaps holds the sums and counts of the
    /// rooms that exceed `len`, exact in integers, then a scan of the block), and tests the start
    /// `lo + gap + offset` exactly; a start that fails is thrown away and the trial repeated.
    /// The draws cover a set `U` that holds `V` (every valid start lies in its gap's stretch),
    /// each point of `U` with the same chance, and a trial keeps a point exactly when it is
    /// valid: given that a trial keeps one, it is uniform over `V`, as the paper's is. The
    /// offsets are a lattice of `2^-56` of the interval's power of two, finer than the `f64`
    /// starts the paper's sampler draws (`2^-53` of the interval) and than fixed point's.
    ///
    /// The exact test is the paper's sampler's own comparison, made with the two neighbours:
    /// a start `a` in the gap after segment `p` and before segment `q` is valid when
    /// `a > p.end + gap` and `a + len + gap < q.start` (with the range test of an inclusive
    /// interval at its ends). The others need no look: a segment `s` left of `p` was tested
    /// against `p` when the later of the two was placed, so `s.end + gap < p.start <= p.end +
    /// gap < a` in the scalar's own rounding (each step is monotone), and likewise on the
    /// right. On a circle, a start that needs its periodic images tested (it lies in the gap
    /// across `L`, or within the clearance of a segment that wraps) goes through the full
    /// test of the spatial index, as in [`LineEngine::step`].
    ///
    /// ## Halting
    /// A gap whose room (grown by the slack) is not above `len` holds no valid start, so when
    /// no gap's is (`W = 0`) the fill cannot go on: the step returns [`StepError::Halted`]
    /// at once, with fewer trials than the limit (often none) — a proven halt. Only a last
    /// room within the slack of `len` (a few representable starts or none) is left to the
    /// trial limit, as in the paper's sampler.
    ///
    /// ## Storage
    /// [`LineGaps`] borrows a little over five 8-byte [`LineGap`](crate::line::Gap) words per
    /// segment ([`line_gaps_for`](crate::line::gaps_for)), 41 bytes: each gap's ends and room,
    /// its place in the heap, and a Fenwick node per 16 gaps. The first step lays the gaps
    /// out and later steps keep them, so they must go with one engine. A segment placed by
    /// [`LineEngine::step`] in between is found by a scan of the gaps. Slots too few for the
    /// next gap stop the fill with [`StepError::Capacity`] (the segments it could serve), with
    /// everything placed so far intact: the fill never depends on the storage otherwise.
    /// On error nothing is placed and the engine may be stepped again.
    ///
    /// # Examples
    ///
    /// ```
    /// use zetafill::rng_from_seed;
    /// use zetafill::line::{gaps_for, index_words, Engine, Gap, Gaps, Interval};
    /// use zetafill::{Stop, StopReason};
    /// use zetafill::line::{Params, Segment, Storage};
    ///
    /// let mut segments = vec![Segment::<f64>::default(); 10_000];
    /// let mut index = vec![0u32; index_words(10_000)];
    /// let mut slots = vec![Gap::default(); gaps_for(10_000)];
    /// let storage = Storage { segments: &mut segments, index: &mut index };
    /// let interval = Interval { length: 100.0, periodic: false };
    /// let mut line = Engine::new(Params::new(1.4, 1.0), interval, storage)?;
    /// let mut gaps = Gaps::new(&mut slots)?;
    /// let stop = Stop { count: Some(10_000), ..Stop::default() };
    /// assert_eq!(line.run_fast(&mut gaps, &mut rng_from_seed(1), &stop, |_| {}), StopReason::Count);
    /// // About one trial a placement (the paper's sampler needs about 50 here).
    /// assert!(line.stats().trials < 10_100);
    /// let mut s: Vec<_> = line.placed().to_vec();
    /// s.sort_by(|a, b| a.start.total_cmp(&b.start));
    /// assert!(s.windows(2).all(|w| w[0].end() < w[1].start));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// A proven halt: the first segment and its clearance leave 0.39 of the interval, and the
    /// second needs 0.41 on one side.
    ///
    /// ```
    /// use zetafill::rng_from_seed;
    /// use zetafill::line::{gaps_for, index_words, Engine, Gap, Gaps, Interval};
    /// use zetafill::StepError;
    /// use zetafill::line::{Params, Segment, Storage};
    ///
    /// let (mut segments, mut index) = ([Segment::<f64>::default(); 4], [0u32; index_words(4)]);
    /// let mut slots = [Gap::default(); gaps_for(4)];
    /// let storage = Storage { segments: &mut segments, index: &mut index };
    /// let interval = Interval { length: 1.0, periodic: false };
    /// let mut line = Engine::new(Params { gap: 0.13, ..Params::new(2.0, 1.0) }, interval, storage)?;
    /// let mut gaps = Gaps::new(&mut slots)?;
    /// let mut rng = rng_from_seed(1);
    /// line.step_fast(&mut gaps, &mut rng)?;
    /// assert!(matches!(line.step_fast(&mut gaps, &mut rng), Err(StepError::Halted { index: 1, trials: 0 })));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn step_fast<R: RngCore + ?Sized>(&mut self, gaps: &mut LineGaps<'_, S>, rng: &mut R) -> Result<LinePlacement<S>, StepError> {
        let (index, length, len) = self.next()?;
        if self.len == 0 && self.interval.periodic {
            // On an empty circle every start is valid: the paper's first draw is exact, and
            // it takes one trial.
            return self.step(rng);
        }
        let full = StepError::Capacity {
            capacity: gaps.capacity() as u64,
        };
        gaps.sync(self).ok_or(full)?;
        if !gaps.usable() {
            return self.step(rng);
        }
        if !gaps.has_room() {
            return Err(full);
        }
        let units = gaps.len_units(len);
        gaps.activate(units);
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials || gaps.weight(units) == 0 {
                return Err(StepError::Halted { index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let Some((g, offset)) = gaps.draw(rng, units) else {
                gaps.reject();
                continue;
            };
            let mut a = g.lo + self.gap + gaps.offset(offset);
            if g.wraps && a >= self.total {
                a = a - self.total;
                if a >= self.total {
                    gaps.reject();
                    continue;
                }
            }
            let b = a + len;
            if !self.fits_in(&g, a, len, gaps.exact()) {
                gaps.reject();
                continue;
            }
            // On an inclusive interval the neighbours decide every start (while the gaps are
            // exact): the hash is left behind until a test needs it. On a circle some tests
            // need it, so it is kept.
            let placed = self.commit(a, len, length, trials, self.interval.periodic);
            gaps.split(g, a, b, units).ok_or(full)?;
            gaps.caught_up(self.len);
            return Ok(placed);
        }
    }

    /// Whether the start `a` (segment `[a, b]`) drawn in gap `g` is valid: the paper's exact
    /// test, decided by the gap's neighbours when they decide it (see
    /// [`LineEngine::step_fast`]), or by the spatial index.
    fn fits_in(&mut self, g: &Gap<S>, a: S, len: S, exact: bool) -> bool {
        let (gap, b) = (self.gap, a + len);
        if !self.interval.periodic {
            if !self.in_range(a, len) {
                return false;
            }
            if !exact {
                self.catch_up();
                return self.clear(a, b);
            }
            // The ends of an inclusive interval are no segments: the range test covers them.
            let left = g.lo == S::ZERO || a > g.lo + gap;
            let right = g.hi == self.total || b + gap < g.hi;
            return left && right;
        }
        let images = b + gap >= self.total || a - gap <= self.max_end - self.total;
        if g.wraps || images || !exact {
            self.catch_up();
            return self.clear(a, b);
        }
        a > g.lo + gap && b + gap < g.hi
    }

    /// [`LineEngine::run`] with the exact sampler ([`LineEngine::step_fast`]).
    pub fn run_fast<R: RngCore + ?Sized>(
        &mut self,
        gaps: &mut LineGaps<'_, S>,
        rng: &mut R,
        stop: &Stop,
        on_place: impl FnMut(&LinePlacement<S>),
    ) -> StopReason {
        self.run_with(stop, on_place, |e| e.step_fast(gaps, rng))
    }
}
