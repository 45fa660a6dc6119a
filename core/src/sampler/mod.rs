//! The cell sampler: candidates drawn only where the next shape could fit, with exactly the
//! distribution of accepted placements of the paper's sampler.
//!
//! The paper's sampler (Shier and Bourke, "An Algorithm for Random Fractal Filling of
//! Space", section 2) draws centres uniformly over the whole region
//! and keeps the first that passes the exact tests. Late in a fill almost every candidate is
//! rejected: the trials per placement grow like `n^(c-1)`. This sampler keeps a set of
//! square-ish cells that covers every centre where the next shape could still go, and draws
//! candidates only inside them.
//!
//! ## The cells
//! The region's bounding box is cut into a grid of level-0 cells; a cell of level `k + 1` is a
//! quarter of one of level `k`. Let `d` be the smallest signed distance from a cell's centre
//! to the outside of the region and to the material of the (at most [`NEAR`]) placed shapes
//! the cell knows of (negative inside a shape). Leaving shapes out only makes `d` larger, so
//! `d` bounds the clearance at the centre from above whichever shapes a cell knows; knowing
//! the nearest ones makes it tight. Clearance is 1-Lipschitz, so no point of a cell whose half
//! diagonal is `h` has clearance above `d + h`: each cell stores such a bound `u` (a child
//! also keeps its parent's when that is lower). A known circle gives a tighter term: the
//! distance to a disc is convex, so over the cell it is largest at a corner, and the cell
//! takes its farthest corner's distance instead of the centre's plus `h` (up to `h` less for
//! a circle far larger than the cell; about 10% fewer trials at c = 1.3 and 17% at c = 1.4).
//!
//! Cells learn their neighbours from the trials themselves: a candidate that fails the exact
//! test names the shape it hit, and the cell it was drawn in adds that shape to its list (it
//! keeps the nearest [`NEAR`]); the cell that receives a shape learns it at once. A split cell's
//! children start with their parent's list. So bounds tighten as shapes are placed, mostly
//! without any search of the spatial index.
//!
//! The exception is a stubborn cell, one that has rejected eight candidates and is still
//! live: the shapes it learned do not close it. Before it splits it looks its neighbours up
//! in the index and keeps the [`NEAR`] nearest of those within `h / 2 + clearance` of its centre
//! (a farther shape cannot bring a child's bound below the clearance, since each child's centre
//! is `h / 2` from its parent's), and each child is bounded quarter by quarter: its bound is
//! the largest of its four quarters' bounds. Where shapes of like size crowd a cell (c = 1.4)
//! that halves the trials per placement; where stubborn cells are rare (c = 1.3) it costs
//! about 5% of the time.
//!
//! A shape whose inscribed disc has radius `r` can sit at a point only where the clearance is
//! at least its required clearance, `r + gap` (below simply `clearance`). So a cell with `u < clearance` holds no valid centre for the next
//! shape: it is put to sleep, and woken when a later, smaller shape's `clearance` falls to `u`.
//! Deep sleepers are kept unsorted below a floor `F` (each has `u < F`); when a shape's clearance
//! falls below `F`, one pass lowers the floor to 85% of the clearance and moves every cell at or
//! above it out, so a pass comes only when the clearance has shrunk by 15%. Cells between the floor
//! and the clearance wait in a small max-heap and wake as soon as the clearance reaches them. A cell
//! with `u <= 0` lies inside shape material and is dropped for good. A drawn cell whose half
//! diagonal is above 1.4 times the clearance, or that has rejected eight candidates, is split into
//! its four children; so cells refine as the shapes shrink, down to 23 levels below the first
//! grid.
//!
//! ## Why the accepted placements are exactly the reference's
//! Every trial draws a point uniformly over the union `U` of the live cells (a cell chosen
//! with probability proportional to its area, exactly, with integer weights; then a uniform
//! point in it), then accepts the point if and only if it is a valid centre: points in a cell
//! (or child) shown to be too tight are rejected, which is right because no valid centre lies
//! there; every other point meets the reference sampler's own range and exact tests. Cells are
//! only ever removed from `U` when they hold no valid centre, so `U` always contains the set
//! `V` of valid centres. Within one trial the chance of accepting a point is therefore
//! `1 / |U|` at every point of `V` and 0 elsewhere: given that a trial accepts, the accepted
//! centre is uniform over `V`. Splitting, sleeping and dropping cells change `U` between
//! trials but never this property, so the accepted centre of every placement is uniform over
//! `V` (and with the angle drawn uniformly and independently, uniform over the valid (centre,
//! angle) pairs), exactly as in the reference. (Cells are drawn eight at a time; within a step
//! cells are only retired or split, so a cell drawn earlier in the step is still a draw over a
//! union that holds `V`, and its point is still accepted exactly when valid.) When `U` is empty no centre is valid: the fill
//! halts, with certainty rather than after the trial limit. (When the last room shrinks to a
//! point of tangency, a set of no area, the cells around it refine to the finest level and
//! stay live; then the trial limit ends the fill, as it does for the reference.)
//!
//! The argument needs bounds that are never below the truth and cells that are exactly the
//! union of their children, in the scalar's own arithmetic. Each bound is computed rounded:
//! `f64` to nearest, a relative error far below what the sampler adds to every bound, the
//! slack ([`Scalar::BOUND_SLACK`]: 1e-9 of the region's size and 1e-12); fixed point rounds
//! its distances up, in exact 128-bit integers ([`Scalar::dist2_up`],
//! [`Scalar::seg_dist2_up`]), and its slack covers the rest (1e-8 of the region's size and
//! 2^-18 mm). Cells halve exactly: `f64` halves without rounding, and fixed point rounds the
//! first grid's cells up so that they halve 23 times without remainder
//! ([`Scalar::grid_step`]); where that makes the grid overhang a torus, a point drawn beyond
//! the period is rejected (wrapped, it would be drawn twice as often).
//!
//! Shapes without a clearance condition fall back to the reference sampler: a ring whose hole
//! is larger than its material (an earlier shape may sit in that hole, around the new
//! centre), or a ring in a region with holes (the ring may enclose one).
//!
//! ## Storage
//! The caller lends a slice of [`CellWords`] (32 bytes a cell, zeroed), [`cells_for`] its
//! capacity. Live cells sit at its start, grouped by level; deep sleepers at the end of its
//! first seven eighths; the waiting heap in the last eighth. The sampler holds at most [`CELLS_PER_SHAPE`] cells per placed
//! shape (plus a start); at that budget, or when the slice is full, cells are no longer split:
//! sampling stays exact, only slower. All the cells held, waiting ones included, always fit in
//! the first seven eighths, so a cell that wakes always has a place among the live ones (a
//! cell with nowhere to go would take its valid centres out of the union). Nothing allocates
//! or panics.
//!
//! Lent [`cells_for`] the engine's capacity or more, the sampler keeps no cell whose bound is
//! below the clearance of the smallest shape the engine has room for (less the slack): no
//! shape of the fill can use it. Such a cell still counts as held, so the budget decides as if
//! it were kept. The deep sleepers then sit at the pool's end and the waiting heap starts at
//! the end of the first seven eighths (which the budget keeps the live cells below); the heap
//! moves when the sleepers, or the live cells, need the other side's room. Every cell that
//! wakes goes through the heap, whose order (bound, then position word) is total, so cells
//! wake in an order that depends only on which wake, not on which cells were kept: the fill is
//! the same whatever the capacity and whatever the storage beyond `cells_for`. Lent less, every sleeper is kept in the layout
//! above, and deep sleepers that a pass finds due go live at once.
//!
//! ## Where things are
//! This file holds the sampler and its public face; `cell` packs a cell into its four
//! words; `pool` keeps the live cells, the sleepers and the waiting heap in the caller's
//! slice; `bound` lays out the grid and bounds the clearance over a cell; `trial` draws a
//! candidate, judges it by its cell, and learns from the exact test.

mod bound;
mod cell;
mod frozen;
mod pool;
mod trial;

use crate::geom::Point;
use crate::scalar::Scalar;
pub(crate) use cell::Cell;
use core::num::NonZeroUsize;
pub(crate) use frozen::{Event, What};
pub(crate) use trial::{Drawn, Verdict};

/// Number of cell levels (a level-0 cell split 23 times at most).
pub const CELL_LEVELS: usize = 24;

/// How many placed shapes a cell keeps track of.
pub const NEAR: usize = 4;

/// Density classes: with a density, a cell of class `j` has `rho <= 2^-j` all over it (the
/// last class holds every cell whose bound is at most `2^-(CLASSES - 1)`).
pub const CLASSES: u32 = 4;

/// Runs of live cells: one per level and density class.
const RUNS: usize = CELL_LEVELS * CLASSES as usize;
/// [`CLASSES`] as the divisor of a run's index.
const CLASSES_NZ: NonZeroUsize = match NonZeroUsize::new(CLASSES as usize) {
    Some(k) => k,
    None => NonZeroUsize::MIN,
};

/// At most this many level-0 cells along a side.
const GRID0: u32 = 16;

/// A drawn cell whose half diagonal is above `SPLIT * clearance` is split.
const SPLIT: f64 = 1.4;

/// A drawn cell that has rejected this many candidates through the exact test is split
/// whatever its size, so that a cell holding no valid centre is eventually retired.
const STUBBORN: u32 = 8;

/// A wake pass lowers the floor to this fraction of the clearance.
const FLOOR: f64 = 0.85;

/// The empty list entry.
pub(crate) const NONE: u32 = u32::MAX;

/// Cells drawn at once: their memory loads overlap, so a trial rarely waits for one.
const AHEAD: usize = 8;

/// The cells a sampler may hold once `n` shapes are placed: `CELLS_PER_SHAPE * (n +
/// CELLS_BASE)`, of which at most `WAITING_PER_SHAPE * (n + CELLS_BASE)` waiting. Splits stop
/// at this budget (sampling stays exact), whatever the storage lent, so a fill never depends
/// on the storage as long as it holds [`cells_for`] the capacity.
pub const CELLS_PER_SHAPE: usize = 24;
const WAITING_PER_SHAPE: usize = 3;
const CELLS_BASE: usize = 4096;

/// Cells to lend a sampler for fills of up to `shapes` shapes: enough that only the budget
/// (see [`CELLS_PER_SHAPE`]) ever limits it.
///
/// # Examples
///
/// ```
/// use zetafill::{cells_for, CellSampler, CellWords};
///
/// // 32 bytes a cell; zeroed memory, so the system maps only the cells the sampler writes.
/// assert_eq!(core::mem::size_of::<CellWords>(), 32);
/// assert!(cells_for(1000) > cells_for(100));
/// let mut pool: Vec<CellWords> = vec![[0; 4]; cells_for(1000)];
/// assert!(CellSampler::<f64>::new(&mut pool).is_ok());
/// ```
pub const fn cells_for(shapes: usize) -> usize {
    28 * (shapes + CELLS_BASE)
}

/// Bits of a packed cell word that hold the x or y index (the level, or the number of
/// rejected candidates, sits above them).
const X_BITS: u32 = 27;

/// The storage of one cell: four 64-bit words (grid position and level, the rejected-candidate
/// count, the four shapes it knows of, the bound). All-zero words are an empty cell, so a pool
/// can be zeroed memory, which the operating system maps only where the sampler writes:
/// `vec![[0u64; 4]; cells_for(n)]` costs the cells used, not the cells lent. See
/// [`cells_for`] for an example.
pub type CellWords = [u64; 4];

/// What the cells clearance to know of the fill: distances to the outside of the region and to
/// placed shapes.
pub(crate) trait Field<S: Scalar> {
    /// The signed distance from `p` to the outside of the region (positive inside).
    fn edge(&self, p: Point<S>) -> S;
    /// An upper bound of the signed distance from `p` to the material of shape `j`.
    fn dist(&self, j: u32, p: Point<S>) -> S;
    /// [`Field::dist`] from each of four points: the same values, where a shape's outline is
    /// built once for the four.
    fn dists(&self, j: u32, ps: &[Point<S>; 4]) -> [S; 4] {
        ps.map(|p| self.dist(j, p))
    }
    /// When shape `j` is a disc, its centre (in the periodic image nearest `p`) and radius.
    fn disc(&self, j: u32, p: Point<S>) -> Option<(Point<S>, S)> {
        let _ = (j, p);
        None
    }
    /// A bound tighter than `dist(j, c) + hd` (distance is 1-Lipschitz) of the signed
    /// distance to the material of shape `j` from any point of the box centred on `c` with
    /// half sides `hw`, `hh`, where the shape is a disc: the distance to a disc is convex, so
    /// over the box it is largest at the farthest corner. None for other shapes.
    fn box_dist(&self, j: u32, c: Point<S>, hw: S, hh: S) -> Option<S> {
        self.disc(j, c).map(|(o, r)| far_corner(o, c, hw, hh) - r)
    }
    /// Replaces `near` by the [`NEAR`] placed shapes nearest to `c` (by [`Field::dist`])
    /// among those that come within `reach` of it; by default, leaves `near` as it is.
    fn gather(&self, c: Point<S>, reach: S, near: &mut [u32; NEAR]) {
        let _ = (c, reach, near);
    }
    /// What identifies the density candidates are thinned by (0: none). Cells are laid out
    /// again when it changes, since their classes belong to it.
    fn density_key(&self) -> usize {
        0
    }
    /// The density class of the box `[x0, y0, x1, y1]`, among `classes`: the largest `j`
    /// below `classes` such that the density is at most `2^-j` all over the box, or None when
    /// it is 0 all over it (no candidate can be kept there). By default class 0.
    fn class(&self, bbox: [f64; 4], classes: u32) -> Option<u32> {
        let _ = (bbox, classes);
        Some(0)
    }
}

#[derive(Clone, Copy, Debug, Default)]
struct LevelGeom<S> {
    w: S,
    h: S,
    half_diag: S,
}

/// Counters of the cell sampler ([`CellSampler::stats`]), for benchmarks and tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CellStats {
    /// Live cells (candidates are drawn in them).
    pub live: usize,
    /// Sleeping cells (too tight for the shapes so far).
    pub sleeping: usize,
    /// The most cells held at once.
    pub peak: usize,
    /// Splits made.
    pub splits: u64,
    /// Splits skipped because the storage was full.
    pub refused_splits: u64,
    /// Cells dropped for good (inside shape material or outside the region).
    pub dropped: u64,
    /// Cells too tight for every shape the engine has room for, not kept (with ample
    /// storage only; see [`cells_for`]).
    pub outlived: u64,
    /// The finest level in use.
    pub finest_level: u32,
    /// Trials rejected by their cell alone (too tight, or in a too tight quarter).
    pub cell_rejects: u64,
    /// Trials rejected by a shape their cell knew.
    pub known_rejects: u64,
    /// Trials rejected by a shape their cell did not know (it learns it).
    pub learned: u64,
    /// Stubborn cells that looked their neighbours up in the spatial index before splitting.
    pub gathers: u64,
}

/// The cell structure over caller-provided storage. Build it with [`CellSampler::new`] and
/// pass it to [`crate::Engine::step_fast`] or [`crate::Engine::run_fast`]; one sampler serves
/// one engine.
///
/// # Examples
///
/// ```
/// use zetafill::{cells_for, index_words, rng_from_seed, CellSampler, CellWords, Engine, Params, Placed, Region, Stop, StopReason, Storage};
///
/// let n = 1000;
/// // Room for n circles and the next one.
/// let mut shapes = vec![Placed::<f64>::default(); n + 1];
/// let mut index = vec![0u32; index_words(n + 1)];
/// // Zeroed memory: the operating system maps only the cells the sampler writes.
/// let mut pool: Vec<CellWords> = vec![[0; 4]; cells_for(n + 1)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 200.0, height: 200.0, periodic: false };
/// let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
/// let mut cells = CellSampler::new(&mut pool)?;
/// let stop = Stop { count: Some(n as u64), ..Stop::default() };
/// let reason = engine.run_fast(&mut cells, &mut rng_from_seed(1), &stop, |_| {});
/// assert_eq!(reason, StopReason::Count);
/// // Every centre where circle n fits lies in a live cell: a small part of the region.
/// assert!(engine.prepare_fast(&mut cells));
/// assert!(cells.live_area() < 0.1 * engine.total_area());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct CellSampler<'c, S> {
    pool: &'c mut [CellWords],
    /// Run `r`'s live cells (level `r / classes`, density class `r % classes`) are
    /// `pool[starts[r]..starts[r + 1]]`; `starts[CELL_LEVELS * classes]` is the number of live
    /// cells.
    starts: [u32; RUNS + 1],
    /// Density classes in use: 1 without a density, [`CLASSES`] with one.
    classes: NonZeroUsize,
    /// Every run that holds live cells is in `lo..=hi` (none when `lo > hi`).
    lo: u32,
    hi: u32,
    /// The [`Field::density_key`] the cells were laid out for.
    key: usize,
    /// The grid in f64 for the density's bounds: origin, level-0 cell sides, the slack.
    grid_f64: [f64; 5],
    /// Cells `pool[..main]` hold the live cells (from the start) and the deep sleepers (from
    /// the end); `pool[main..]` holds the waiting heap.
    main: usize,
    /// Deep sleepers, unsorted: entry `i` is `pool[main - 1 - i]`. Every one's bound is below
    /// `floor`.
    asleep: usize,
    /// Every deep sleeper's bound is below this.
    floor: S,
    /// Whether the pool holds [`cells_for`] the engine's capacity (see
    /// [`CellSampler::set_lowest`]): then the deep sleepers sit at its end, and share the
    /// room past `main` with the waiting heap.
    ample: bool,
    /// With ample storage, a cell whose bound is below this is too tight for every shape the
    /// engine has room for: it is not kept, only counted in `outlived`. Zero otherwise.
    never: S,
    /// Cells too tight for every shape the engine has room for. They count as held, as they
    /// would if they were kept, so that the budget's decisions do not depend on the capacity.
    outlived: usize,
    /// Shapes placed when the current step began (for the budget).
    placed: usize,
    /// Waiting cells, a max-heap by bound in `pool[main..main + waiting]`: too tight for the
    /// current clearance but at or above the floor, so they must wake as soon as the clearance falls to
    /// their bound.
    waiting: usize,
    /// Sum over live cells of their area in units of the finest level's cell.
    weight: u64,
    origin: Point<S>,
    geom: [LevelGeom<S>; CELL_LEVELS],
    slack: S,
    /// Cells drawn ahead within the current step (slot, copy as drawn and density class); see
    /// [`CellSampler::draw`].
    ahead: [(usize, Cell<S>, u32); AHEAD],
    ahead_len: usize,
    ahead_pos: usize,
    /// The total weight the current batch was drawn from (0: no batch in this step yet).
    batch_weight: u64,
    /// This step's finished batches: the sum of draws used over the weight drawn from.
    step_inv: f64,
    /// Whether the paper's trials are estimated (see [`CellSampler::estimate_paper_trials`]).
    estimating: bool,
    /// See [`CellSampler::paper_trials`] and [`CellSampler::last_paper_trials`].
    paper: f64,
    last_paper: f64,
    ready: bool,
    stats: CellStats,
    /// On a torus that the grid overhangs by more than the slack (fixed point rounds its cells
    /// up so that they halve exactly; f64 never does), points drawn at or beyond this lie
    /// outside the period: wrapped, they would fall on others and be drawn twice as often.
    overhang: Option<Point<S>>,
}

/// Why a cell sampler could not be set up: its storage is empty (or beyond `u32` indices).
///
/// # Examples
///
/// ```
/// use zetafill::{CellSampler, NoCells};
///
/// assert_eq!(CellSampler::<f64>::new(&mut []).err(), Some(NoCells));
/// assert_eq!(NoCells.to_string(), "the cell sampler needs at least one cell");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct NoCells;

impl core::fmt::Display for NoCells {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("the cell sampler needs at least one cell")
    }
}

impl core::error::Error for NoCells {}

impl<'c, S: Scalar> CellSampler<'c, S> {
    /// A sampler over `pool` (at least one cell; the README gives the cells a fill needs per
    /// shape). It lays out its grid on the first step.
    pub fn new(pool: &'c mut [CellWords]) -> Result<Self, NoCells> {
        if pool.is_empty() || pool.len() > u32::MAX as usize {
            return Err(NoCells);
        }
        Ok(CellSampler {
            main: pool.len() - (pool.len() / 8),
            pool,
            starts: [0; RUNS + 1],
            classes: NonZeroUsize::MIN,
            lo: RUNS as u32,
            hi: 0,
            key: 0,
            grid_f64: [0.0; 5],
            asleep: 0,
            floor: S::from_f64(f64::MAX),
            ample: false,
            never: S::ZERO,
            outlived: 0,
            placed: 0,
            waiting: 0,
            weight: 0,
            origin: Point::new(S::ZERO, S::ZERO),
            geom: [LevelGeom::default(); CELL_LEVELS],
            slack: S::ZERO,
            ahead: [(usize::MAX, Cell::default(), 0); AHEAD],
            ahead_len: 0,
            ahead_pos: 0,
            batch_weight: 0,
            step_inv: 0.0,
            estimating: false,
            paper: 0.0,
            last_paper: 0.0,
            ready: false,
            stats: CellStats::default(),
            overhang: None,
        })
    }

    /// The live cells' boxes, `[x0, y0, x1, y1]`: candidates are drawn only inside them, so
    /// every centre where the next shape fits must lie in one. For checks and pictures; O(live
    /// cells).
    pub fn live_boxes(&self) -> impl Iterator<Item = [f64; 4]> + '_ {
        self.pool.iter().take(self.live()).map(|w| {
            let c = Cell::<S>::load(w);
            let g = self.lg(c.level());
            let (x0, y0) = (
                self.origin.x + S::from_f64(f64::from(c.ix())) * g.w,
                self.origin.y + S::from_f64(f64::from(c.iy())) * g.h,
            );
            [x0.to_f64(), y0.to_f64(), (x0 + g.w).to_f64(), (y0 + g.h).to_f64()]
        })
    }

    /// The total area of the live cells.
    pub fn live_area(&self) -> f64 {
        let g = self.lg(CELL_LEVELS as u32 - 1);
        let k = self.classes;
        let cells = (0..self.runs()).fold(0u64, |sum, r| {
            let count = (self.start(r + 1) - self.start(r)) as u64;
            sum + (count << Self::shift(r / k))
        });
        cells as f64 * (g.w * g.h).to_f64()
    }

    /// The counters so far, for benchmarks and tests
    /// ([`CellStats`](crate::internals::sampler::CellStats)).
    pub fn stats(&self) -> CellStats {
        let mut s = self.stats;
        s.live = self.live();
        s.sleeping = self.asleep + self.waiting;
        s
    }

    /// Whether the grid has been laid out, for the density `key` ([`Field::density_key`]).
    pub(crate) fn ready(&self, key: usize) -> bool {
        self.ready && self.key == key
    }

    #[inline]
    fn live(&self) -> usize {
        self.start(self.runs())
    }

    /// Whether no live cell is left.
    pub(crate) fn is_empty(&self) -> bool {
        self.live() == 0
    }

    /// Estimates, from now on, the trials the paper's sampler would have needed (see
    /// [`CellSampler::paper_trials`]). Off by default: it costs a floating-point division per
    /// eight trials, which a board without an FPU feels.
    pub fn estimate_paper_trials(&mut self) {
        self.estimating = true;
    }

    /// An unbiased estimate of the trials the paper's sampler would have needed for the
    /// placements made since [`CellSampler::estimate_paper_trials`]: the sum, over every
    /// trial, of `|R| / |U|`, where `R` is the box the paper's sampler draws centres from and
    /// `U` the union of live cells the trial's cell was drawn from.
    ///
    /// Why: with `V` the valid centres, a trial drawn from `U` is accepted with probability
    /// `|V| / |U|` whatever came before it in the step, so the sum of those probabilities over
    /// a step's trials has expectation 1 (the step ends at its one acceptance: a martingale
    /// stopped at an integrable time). Multiplied by `|R| / |V|`, the sum of `|R| / |U|` has
    /// expectation `|R| / |V|`, which is the expected number of trials of the paper's sampler
    /// from the same fill (its trials are geometric with success `|V| / |R|`). As the two
    /// samplers' fills have the same distribution, the estimate's expectation over a whole
    /// run is the paper's expected trials over a run (without its trial limit; a placement
    /// the limit would halt is not estimated).
    pub fn paper_trials(&self) -> f64 {
        self.paper
    }

    /// [`CellSampler::paper_trials`] of the last placement alone.
    pub fn last_paper_trials(&self) -> f64 {
        self.last_paper
    }
}

/// The distance from `o` to the corner farthest from it of the box centred on `c` with half
/// sides `hw`, `hh` (its square rounded up: see [`Scalar::dist2_up`]).
#[inline]
fn far_corner<S: Scalar>(o: Point<S>, c: Point<S>, hw: S, hh: S) -> S {
    let (ax, ay) = ((c.x - o.x).abs() + hw, (c.y - o.y).abs() + hh);
    S::dist2_up(ax, ay).sqrt()
}

/// `ceil(v)` as a `u32` (0 for NaN or negative, saturating above).
fn ceil_u32(v: f64) -> u32 {
    let f = libm::ceil(v);
    if f.is_nan() || f <= 0.0 {
        0
    } else if f >= f64::from(u32::MAX) {
        u32::MAX
    } else {
        f as u32
    }
}
