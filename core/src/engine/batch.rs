//! Batched placement: many candidates in flight, on one core or on many, with the
//! distribution of the paper's sampler and the same bits whatever the number of threads.
//!
//! Write `S_b` for the fill after `b` placements and `V_j` for the valid (centre, angle) pairs of
//! shape `j` given `S_j`. Placements are taken in batches `b .. e` whose size depends on `b`
//! alone ([`Batches`]). Before a batch the cells are woken for the smallest clearance any shape
//! of the batch needs, whatever the count asked for, and then left as they are until the
//! batch is done: their union holds `V_j` for every `j` of the batch, as `V_j` only shrinks as
//! shapes are placed and a smaller clearance only wakes more cells.
//!
//! Each placement has its own random stream, seeded from the fill's seed and its index
//! ([`Batches::stream_seed`]), so what it draws never depends on how many draws another took.
//! Screening ([`Engine::screen`]) draws each placement's candidates from the frozen cells and
//! tests them against the frozen `S_b`, until one passes: a pure function of shared state, so
//! any number of threads may screen disjoint lanes at once, and one thread screens a lane with
//! eight cells in flight. Committing then takes the placements in order: placement `j` keeps
//! its screened candidate if it also clears the shapes `b .. j` placed earlier in the batch;
//! otherwise it draws on from its own stream, over the same cells, tested against `S_j`.
//!
//! Why it is exact: every trial of placement `j` draws a point uniformly over a union of cells
//! that holds `V_j`, and the candidate kept is the first of them in `V_j` (a candidate that
//! failed against `S_b` fails against `S_j`, which holds `S_b`). The trials are independent and
//! identically distributed, so the accepted pair is uniform over `V_j`, exactly as in the
//! paper's sampler. Nothing a screen finds is used before the commit, and the commit reads
//! only the lanes in index order: the result is a function of the seed, the parameters and the
//! batch sizes, the same for one thread or sixty-four, and on a board that screens on one core.
//!
//! What the trials learned about their cells (a shape hit, a cell too tight, a cell drawn too
//! often in vain) is kept in each lane and replayed into the cells after the commit, in index
//! order, for the next batch's clearance: the cells restructure as [`Engine::step_fast`]'s do,
//! a batch later. A lane keeps at most [`LANE_EVENTS`] of them; the rest only cost trials.

use super::{Engine, NextShape, Placement};
use crate::geom::{Geo, Point};
use crate::params::{StepError, Stop, StopReason};
use crate::rng::{self, ZetaRng};
use crate::sampler::{CellSampler, Drawn, Event, What};
use crate::scalar::Scalar;
use crate::shape::Placed;

/// Events a lane keeps for the cells' replay (see [`Batches`]).
pub const LANE_EVENTS: usize = 40;

/// Trials a placement is screened for against frozen cells; a placement that needs more goes
/// on with cells that restructure as it draws (see [`Engine::commit`]).
const SCREEN_TRIALS: u64 = 4096;

/// Cells a screen draws at once: their loads are in flight together.
const DRAWN_AT_ONCE: usize = 8;

/// The largest batch the CLI fills with, and the lanes it lends.
pub const DEFAULT_BATCH: usize = 64;

/// A candidate that passed the screen.
#[derive(Clone, Copy, Debug)]
struct Found<S> {
    shape: Placed<S>,
    /// The trial's cell, for the replay.
    event: Event,
    /// The shapes placed when it was tested: it clears `S_upto`.
    upto: usize,
}

/// One placement of a batch: its random stream, its trials, the candidate it screened and
/// what its trials learned about the cells. Lent by the caller ([`Batches::new`]).
#[derive(Clone, Debug)]
pub struct Lane<S> {
    index: u64,
    /// What the placement needs, and the clearance it needs (None: no clearance condition),
    /// or why it cannot be made.
    next: Result<(NextShape<S>, Option<S>), StepError>,
    rng: ZetaRng,
    trials: u64,
    found: Option<Found<S>>,
    events: heapless::Vec<Event, LANE_EVENTS>,
}

impl<S> Default for Lane<S> {
    fn default() -> Self {
        Lane {
            index: 0,
            next: Err(StepError::Capacity { capacity: 0 }),
            rng: crate::rng::rng_from_seed(0),
            trials: 0,
            found: None,
            events: heapless::Vec::new(),
        }
    }
}

impl<S> Lane<S> {
    /// The placement this lane is screening.
    pub fn index(&self) -> u64 {
        self.index
    }

    fn note(&mut self, e: Event) {
        // The last place is kept for the placement's own event.
        if self.events.len() + 1 < LANE_EVENTS {
            let _ = self.events.push(e);
        }
    }
}

/// What a batch's screen needs to know, fixed for the batch ([`Engine::screen`]).
#[derive(Clone, Copy, Debug)]
pub struct Plan<S> {
    /// The batch's first placement and the one after its last.
    pub first: u64,
    /// See `first`.
    pub end: u64,
    /// The least clearance of the batch's shapes, which the cells were woken for; None when
    /// no shape of the batch uses the cells.
    clearance: Option<S>,
}

/// The batches of a fill: the fill's seed, the largest batch, and the lanes lent by the caller
/// (at least one per placement of the largest batch).
///
/// The batch that starts at placement `b` holds `clamp(b / 8, 1, size)` placements: one at a
/// time while the shapes are few and large (where each placement changes the room left most),
/// then more, up to `size`. The fill is a function of the seed, the parameters and `size`.
///
/// # Examples
///
/// ```
/// use zetafill::{cells_for, index_words, Batches, CellSampler, Engine, Lane, Params, Placed, Region, Stop, StopReason, Storage};
///
/// let fill = |threads: usize| {
///     let mut shapes = vec![Placed::<f64>::default(); 500];
///     let mut index = vec![0u32; index_words(500)];
///     let mut pool = vec![[0u64; 4]; cells_for(500)];
///     let mut lanes = vec![Lane::default(); 16];
///     let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
///     let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
///     let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage).unwrap();
///     let mut cells = CellSampler::new(&mut pool).unwrap();
///     let mut batches = Batches::new(&mut lanes, 7, 16).unwrap();
///     let stop = Stop { count: Some(500), ..Stop::default() };
///     // The lanes of each batch screened by `threads` threads.
///     let reason = engine.run_batched_with(&mut cells, &mut batches, &stop, |_| {}, |e, c, plan, lanes| {
///         let per = lanes.len().div_ceil(threads);
///         std::thread::scope(|s| {
///             for part in lanes.chunks_mut(per) {
///                 s.spawn(move || e.screen(c, plan, part));
///             }
///         });
///     });
///     assert_eq!(reason, StopReason::Count);
///     engine.placed().to_vec()
/// };
/// // The same bits for one thread and three.
/// assert_eq!(fill(1), fill(3));
/// ```
#[derive(Debug)]
pub struct Batches<'l, S> {
    lanes: &'l mut [Lane<S>],
    seed: u64,
    size: usize,
}

/// Why [`Batches::new`] refused: the largest batch is 0, or more lanes than were lent.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct NoLanes;

impl core::fmt::Display for NoLanes {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("a batch needs at least one placement and a lane for each")
    }
}

impl core::error::Error for NoLanes {}

impl<'l, S: Scalar> Batches<'l, S> {
    /// Batches of at most `size` placements over `lanes` (at least `size` of them) for the
    /// fill of `seed`.
    pub fn new(lanes: &'l mut [Lane<S>], seed: u64, size: usize) -> Result<Self, NoLanes> {
        if size == 0 || lanes.len() < size {
            return Err(NoLanes);
        }
        Ok(Batches { lanes, seed, size })
    }

    /// The number of placements of the batch that starts at placement `first`.
    pub fn size_at(&self, first: u64) -> u64 {
        batch_size(first, self.size)
    }

    /// The last placement of the batch that holds placement `i`, for a fill batched from its
    /// first placement.
    pub fn last_of(&self, i: u64) -> u64 {
        let mut first = 0u64;
        loop {
            let end = first.saturating_add(self.size_at(first));
            if i < end || end == u64::MAX {
                return end - 1;
            }
            first = end;
        }
    }

    /// The seed of placement `j`'s stream: SplitMix64's finaliser over the fill's seed, then
    /// over that xor `j` (a bijection for each, so no two placements of a fill share a
    /// stream). The stream is [`crate::rng_from_seed`] of it.
    pub fn stream_seed(seed: u64, j: u64) -> u64 {
        mix64(mix64(seed) ^ j)
    }
}

/// The number of placements of the batch that starts at `first`, for batches of at most `size`.
fn batch_size(first: u64, size: usize) -> u64 {
    (first / 8).clamp(1, size as u64)
}

/// SplitMix64's output function.
fn mix64(z: u64) -> u64 {
    let z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    let z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

impl<'a, S: Scalar> Engine<'a, S> {
    /// The least clearance of the shapes `first .. end` that use the cells (None when none
    /// does). Shapes that cannot be placed at all count for nothing: the fill ends at them.
    fn batch_clearance(&self, first: u64, end: u64) -> Option<S> {
        (first..end)
            .filter_map(|j| self.shape_at(j).ok().and_then(|n| self.clearance_needed(&n)))
            .fold(None, |m: Option<S>, c| Some(m.map_or(c, |m| m.min(c))))
    }

    /// Screens the placements of `lanes` (part of the batch `plan`, in any order and on any
    /// thread): draws each one's candidates from the frozen cells until one passes the exact
    /// tests against the shapes placed before the batch, or the trial limit. Changes only the
    /// lanes.
    pub fn screen(&self, cells: &CellSampler<'_, S>, plan: &Plan<S>, lanes: &mut [Lane<S>]) {
        let Some(clearance) = plan.clearance else { return };
        for lane in lanes.iter_mut() {
            if lane.index < plan.first || lane.index >= plan.end || lane.found.is_some() {
                continue;
            }
            if let Ok((next, Some(_))) = lane.next {
                self.screen_lane(cells, &next, clearance, lane, SCREEN_TRIALS);
            }
        }
    }

    /// Draws candidates for one lane until one passes the exact tests against the shapes
    /// placed now, the trial limit is reached or no cell is live.
    fn screen_lane(&self, cells: &CellSampler<'_, S>, next: &NextShape<S>, clearance: S, lane: &mut Lane<S>, limit: u64) {
        let limit = limit.min(self.params.max_trials);
        let mut g = Geo::Circle {
            c: Point::new(S::ZERO, S::ZERO),
            r: next.base_r,
        };
        loop {
            // Cells drawn together, loaded together, and the shapes they know loaded
            // together (on hosts: a board's memory has no latency to hide).
            let mut drawn = [(0usize, 0u32); DRAWN_AT_ONCE];
            for d in drawn.iter_mut() {
                match cells.draw_frozen(&mut lane.rng) {
                    Some(slot) => *d = slot,
                    None => return,
                }
            }
            if cfg!(not(target_os = "none")) {
                let mut sum = S::ZERO;
                for &(slot, _) in &drawn {
                    for j in cells.known(slot) {
                        if let Some(s) = self.shapes.get(j as usize) {
                            sum = sum + s.scale;
                        }
                    }
                }
                core::hint::black_box(sum);
            }
            for &(slot, class) in &drawn {
                if lane.trials >= limit {
                    return;
                }
                lane.trials += 1;
                let Some(d) = cells.point_in(slot, class, &mut lane.rng) else {
                    continue;
                };
                let angle = if next.rotated {
                    rng::angle::<S, ZetaRng>(&mut lane.rng)
                } else {
                    S::ZERO
                };
                if let Some(found) = self.trial(cells, next, clearance, &d, angle, lane, &mut g) {
                    lane.found = Some(found);
                    return;
                }
            }
        }
    }

    /// One screened trial at the drawn point `d`: the candidate if it passes, otherwise what
    /// its cell learns, noted in the lane.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn trial(
        &self,
        cells: &CellSampler<'_, S>,
        next: &NextShape<S>,
        clearance: S,
        d: &Drawn<S>,
        angle: S,
        lane: &mut Lane<S>,
        g: &mut Geo<'a, S>,
    ) -> Option<Found<S>> {
        if cells.overhangs(d.point) {
            return None;
        }
        if cells.too_tight(&d.cell, clearance) {
            lane.note(Event::of(d, What::Tight));
            return None;
        }
        let c = self.region.wrap(d.point);
        let (x0, x1, y0, y1) = next.range;
        if c.x < x0 || c.x > x1 || c.y < y0 || c.y > y1 {
            lane.note(Event::of(d, What::Other));
            return None;
        }
        if !self.kept(c, d.class, &mut lane.rng) {
            return None;
        }
        let known = d.cell.near();
        match self.check_into(next, c, angle, Some(&known), g) {
            Ok(shape) => Some(Found {
                shape,
                event: Event::of(d, What::Placed(next.index as u32 * self.images.get())),
                upto: self.len,
            }),
            Err(Some(j)) if known.contains(&j) => {
                lane.note(Event::of(d, What::Known));
                None
            }
            Err(Some(j)) => {
                lane.note(Event::of(d, What::Hit(j)));
                None
            }
            Err(None) => {
                lane.note(Event::of(d, What::Other));
                None
            }
        }
    }

    /// Whether `shape` (of placement `next`) keeps its gap from the shapes placed since
    /// `from`; the shape it hits otherwise.
    fn clears_since(&self, next: &NextShape<S>, shape: &Placed<S>, from: usize) -> Result<(), Option<u32>> {
        if from >= self.len {
            return Ok(());
        }
        let kind = next.kind;
        let c = Point::new(shape.x, shape.y);
        let g = kind.geo_in(self.motifs, c, shape.scale, shape.angle);
        let r = kind.bounding_radius(shape.scale);
        let solid = kind.solid_radius(shape.scale);
        let mut other = Geo::Circle { c, r };
        if self.region.wallpaper().is_some() {
            // The whole test again: the orbit against every stored image, those since included.
            if let Some(k) = self.blocker(&g, c.x, c.y, (r, solid), true) {
                return Err(Some(k));
            }
            return self.orbit_refuses(&g, c, (r, solid), true).map_or(Ok(()), Err);
        }
        for j in from..self.len {
            let j = j as u32;
            // On a torus the nearest image by centre is the only one in reach while two
            // shapes' reach is below half the period; past that the full test decides.
            if self.region.periodic() {
                let their = self
                    .shapes
                    .get(j as usize)
                    .map_or(S::ZERO, |p| self.kind_of(u64::from(j)).bounding_radius(p.scale));
                let (w, h) = self.period;
                if (r + their + self.gap) + (r + their + self.gap) >= w.min(h) {
                    return match self.blocker(&g, c.x, c.y, (r, solid), true) {
                        Some(k) => Err(Some(k)),
                        None => Ok(()),
                    };
                }
            }
            if self.hits(&g, c, (r, solid), j, &mut other) {
                return Err(Some(j));
            }
        }
        Ok(())
    }

    /// Places the lane's placement: its screened candidate if it clears the batch's earlier
    /// shapes, or the first that passes of those it draws on from its own stream.
    fn commit(&mut self, cells: &mut CellSampler<'_, S>, plan: &Plan<S>, lane: &mut Lane<S>) -> Result<Placement<S>, StepError> {
        if self.len + self.per().get() > self.shapes.len() {
            return Err(StepError::Capacity {
                capacity: (self.shapes.len() / self.per()) as u64,
            });
        }
        let (next, own) = lane.next?;
        let clearance = own.and(plan.clearance);
        let Some(clearance) = clearance else {
            // No clearance condition: the paper's sampler, on the placement's own stream.
            return self.step_reference(&next, &mut lane.rng);
        };
        loop {
            if let Some(found) = lane.found.take() {
                match self.clears_since(&next, &found.shape, found.upto) {
                    Ok(()) => {
                        self.trials = self.trials.saturating_add(lane.trials);
                        let _ = lane.events.push(found.event);
                        let c = Point::new(found.shape.x, found.shape.y);
                        let g = next.kind.geo_in(self.motifs, c, found.shape.scale, found.shape.angle);
                        return Ok(self.place(&next, found.shape, &g, lane.trials, false));
                    }
                    Err(j) => {
                        let what = j.map_or(What::Other, What::Hit);
                        lane.note(Event { what, ..found.event });
                    }
                }
            }
            if lane.trials >= self.params.max_trials || cells.is_empty() {
                self.trials = self.trials.saturating_add(lane.trials);
                return Err(StepError::Halted {
                    index: next.index,
                    trials: lane.trials,
                });
            }
            if lane.trials < SCREEN_TRIALS {
                self.screen_lane(cells, &next, clearance, lane, SCREEN_TRIALS);
                continue;
            }
            // A placement that is hard to make: the cells restructure as it draws, as the cell
            // sampler's do, for the batch's least clearance, so that none is retired while a
            // later shape of the batch may still fit in it.
            cells.begin_step();
            // (The trials from here on are counted as they are made.)
            self.trials = self.trials.saturating_add(lane.trials);
            let placed = self.fast_trials(cells, &next, clearance, &mut lane.rng, lane.trials);
            if let Ok(p) = &placed {
                lane.trials = p.trials;
            }
            return placed;
        }
    }

    /// Wakes the cells for a batch and seeds its lanes: the plan of the batch at the next
    /// placement.
    fn begin_batch(&self, cells: &mut CellSampler<'_, S>, batches: &mut Batches<'_, S>) -> Plan<S> {
        let first = self.orbits() as u64;
        let end = first + batches.size_at(first);
        let mut clearance: Option<S> = None;
        for (k, lane) in batches.lanes.iter_mut().take((end - first) as usize).enumerate() {
            let j = first + k as u64;
            let next = self.shape_at(j).map(|n| (n, self.clearance_needed(&n)));
            if let Ok((_, Some(c))) = next {
                clearance = Some(clearance.map_or(c, |m: S| m.min(c)));
            }
            *lane = Lane {
                index: j,
                next,
                rng: rng::rng_from_seed(Batches::<S>::stream_seed(batches.seed, j)),
                trials: 0,
                found: None,
                events: heapless::Vec::new(),
            };
        }
        if let Some(c) = clearance {
            self.prepare_batch(cells, c, |i| batches.last_of(i));
        }
        Plan { first, end, clearance }
    }

    /// Runs batches until a stop condition holds or a placement fails, calling `on_place`
    /// after each placement, with the lanes screened on this thread (see [`Batches`]).
    pub fn run_batched(
        &mut self,
        cells: &mut CellSampler<'_, S>,
        batches: &mut Batches<'_, S>,
        stop: &Stop,
        on_place: impl FnMut(&Placement<S>),
    ) -> StopReason {
        self.run_batched_with(cells, batches, stop, on_place, |e, c, plan, lanes| e.screen(c, plan, lanes))
    }

    /// [`Engine::run_batched`] with the lanes of each batch screened by `screen`, which must
    /// call [`Engine::screen`] on every lane it is handed (on as many threads as it likes,
    /// each lane once): the fill is the same whichever way it splits them.
    pub fn run_batched_with(
        &mut self,
        cells: &mut CellSampler<'_, S>,
        batches: &mut Batches<'_, S>,
        stop: &Stop,
        mut on_place: impl FnMut(&Placement<S>),
        mut screen: impl FnMut(&Self, &CellSampler<'_, S>, &Plan<S>, &mut [Lane<S>]),
    ) -> StopReason {
        loop {
            if let Some(reason) = self.stops(stop) {
                return reason;
            }
            let plan = self.begin_batch(cells, batches);
            // Placements past the count asked for are not screened (nor placed).
            let wanted = stop.count.map_or(plan.end, |k| k.min(plan.end)).max(plan.first + 1);
            let lanes = batches.lanes.get_mut(..(wanted - plan.first) as usize).unwrap_or(&mut []);
            screen(self, cells, &plan, lanes);
            let mut result = None;
            for lane in lanes.iter_mut() {
                if lane.index > plan.first {
                    if let Some(reason) = self.stops(stop) {
                        result = Some(reason);
                        break;
                    }
                }
                match self.commit(cells, &plan, lane) {
                    Ok(p) => on_place(&p),
                    Err(e) => {
                        result = Some(StopReason::Step(e));
                        break;
                    }
                }
            }
            let next = self.orbits() as u64;
            let size = batch_size(next, batches.size);
            if let Some(c) = self.batch_clearance(next, next + size).or(plan.clearance) {
                cells.begin_replay();
                let field = super::cells::FieldOf(self);
                for lane in lanes.iter() {
                    for e in &lane.events {
                        cells.replay(e, c, &field);
                    }
                }
            }
            if let Some(reason) = result {
                return reason;
            }
        }
    }
}
