//! The cell sampler: candidates drawn only where the next shape could fit, with exactly the
//! distribution of accepted placements of the paper's sampler.
//!
//! The paper's sampler (seed 001, section 2) draws centres uniformly over the whole region
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
//! in the index and keeps the [`NEAR`] nearest of those within `h / 2 + need` of its centre
//! (a farther shape cannot bring a child's bound below the need, since each child's centre
//! is `h / 2` from its parent's), and each child is bounded quarter by quarter: its bound is
//! the largest of its four quarters' bounds. Where shapes of like size crowd a cell (c = 1.4)
//! that halves the trials per placement; where stubborn cells are rare (c = 1.3) it costs
//! about 5% of the time.
//!
//! A shape whose inscribed disc has radius `r` can sit at a point only where the clearance is
//! at least `need = r + gap`. So a cell with `u < need` holds no valid centre for the next
//! shape: it is put to sleep, and woken when a later, smaller shape's `need` falls to `u`.
//! Deep sleepers are kept unsorted below a floor `F` (each has `u < F`); when a shape's need
//! falls below `F`, one pass lowers the floor to 85% of the need and moves every cell at or
//! above it out, so a pass comes only when the need has shrunk by 15%. Cells between the floor
//! and the need wait in a small max-heap and wake as soon as the need reaches them. A cell
//! with `u <= 0` lies inside shape material and is dropped for good. A drawn cell whose half
//! diagonal is above 1.4 times the need, or that has rejected eight candidates, is split into
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

use crate::geom::Point;
use crate::scalar::Scalar;
use rand_core::RngCore;

/// Number of cell levels (a level-0 cell split 23 times at most).
pub const CELL_LEVELS: usize = 24;

/// How many placed shapes a cell keeps track of.
pub const NEAR: usize = 4;

/// At most this many level-0 cells along a side.
const GRID0: u32 = 16;

/// A drawn cell whose half diagonal is above `SPLIT * need` is split.
const SPLIT: f64 = 1.4;

/// A drawn cell that has rejected this many candidates through the exact test is split
/// whatever its size, so that a cell holding no valid centre is eventually retired.
const STUBBORN: u32 = 8;

/// A wake pass lowers the floor to this fraction of the need.
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
pub const fn cells_for(shapes: usize) -> usize {
    28 * (shapes + CELLS_BASE)
}

/// Bits of a packed cell word that hold the x or y index (the level, or the number of
/// rejected candidates, sits above them).
const X_BITS: u32 = 27;

/// The storage of one cell: four 64-bit words (grid position and level, the rejected-candidate
/// count, the four shapes it knows of, the bound). All-zero words are an empty cell, so a pool
/// can be zeroed memory, which the operating system maps only where the sampler writes:
/// `vec![[0u64; 4]; cells_for(n)]` costs the cells used, not the cells lent.
pub type CellWords = [u64; 4];

/// One cell: its level and grid position, the shapes it knows of, and the bound on the
/// clearance anywhere in it (stored as [`CellWords`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cell<S> {
    /// The x index in the low [`X_BITS`] bits, the level above.
    xl: u32,
    /// The y index in the low [`X_BITS`] bits, the candidates rejected above.
    yr: u32,
    near: [u32; NEAR],
    /// The bound on the clearance anywhere in the cell, from the outside of the region and
    /// the known shapes.
    u: S,
}

impl<S: Scalar> Default for Cell<S> {
    fn default() -> Self {
        Cell {
            xl: 0,
            yr: 0,
            near: [NONE; NEAR],
            u: S::ZERO,
        }
    }
}

impl<S: Scalar> Cell<S> {
    /// The cell stored in `w` (shape indices are kept plus one, so that zero is none).
    #[inline]
    fn load(w: &CellWords) -> Self {
        let [a, b, c, d] = *w;
        let dec = |x: u64| (x as u32).wrapping_sub(1);
        Cell {
            xl: a as u32,
            yr: (a >> 32) as u32,
            near: [dec(b), dec(b >> 32), dec(c), dec(c >> 32)],
            u: S::from_word(d),
        }
    }

    /// The words that store the cell.
    #[inline]
    fn store(&self) -> CellWords {
        let enc = |j: u32| u64::from(j.wrapping_add(1));
        let [n0, n1, n2, n3] = self.near;
        [
            u64::from(self.xl) | (u64::from(self.yr) << 32),
            enc(n0) | (enc(n1) << 32),
            enc(n2) | (enc(n3) << 32),
            self.u.to_word(),
        ]
    }
}

impl<S> Cell<S> {
    #[inline]
    fn level(&self) -> u32 {
        self.xl >> X_BITS
    }

    #[inline]
    fn ix(&self) -> u32 {
        self.xl & ((1 << X_BITS) - 1)
    }

    #[inline]
    fn iy(&self) -> u32 {
        self.yr & ((1 << X_BITS) - 1)
    }

    #[inline]
    fn rejects(&self) -> u32 {
        self.yr >> X_BITS
    }

    /// The shapes the cell knows of.
    pub(crate) fn near(&self) -> [u32; NEAR] {
        self.near
    }

    /// Whether two cells are the same cell (level and position), whatever their bounds.
    #[inline]
    fn same(&self, o: &Self) -> bool {
        self.xl == o.xl && self.iy() == o.iy()
    }
}

/// What the cells need to know of the fill: distances to the outside of the region and to
/// placed shapes.
pub(crate) trait Field<S: Scalar> {
    /// The signed distance from `p` to the outside of the region (positive inside).
    fn edge(&self, p: Point<S>) -> S;
    /// An upper bound of the signed distance from `p` to the material of shape `j`.
    fn dist(&self, j: u32, p: Point<S>) -> S;
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
}

#[derive(Clone, Copy, Debug, Default)]
struct LevelGeom<S> {
    w: S,
    h: S,
    half_diag: S,
}

/// Counters of the cell sampler, for benchmarks and tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
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

/// A trial's draw: the cell's slot and the cell as drawn, the point, and which quarter of the
/// cell the point is in.
pub(crate) struct Drawn<S> {
    pub(crate) slot: usize,
    pub(crate) cell: Cell<S>,
    pub(crate) point: Point<S>,
    pub(crate) quarter: (bool, bool),
}

/// What a trial learns from the cell it drew.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Verdict {
    /// The point holds no valid centre.
    Reject,
    /// The point must go through the exact tests; it lies in the live cell at this slot.
    Test(usize),
}

/// The cell structure over caller-provided storage. Build it with [`CellSampler::new`] and
/// pass it to [`crate::Engine::step_fast`] or [`crate::Engine::run_fast`]; one sampler serves
/// one engine.
#[derive(Debug)]
pub struct CellSampler<'c, S> {
    pool: &'c mut [CellWords],
    /// Level `k`'s live cells are `pool[starts[k]..starts[k + 1]]`; `starts[CELL_LEVELS]` is
    /// the number of live cells.
    starts: [u32; CELL_LEVELS + 1],
    /// Cells `pool[..main]` hold the live cells (from the start) and the deep sleepers (from
    /// the end); `pool[main..]` holds the waiting heap.
    main: usize,
    /// Deep sleepers, unsorted: entry `i` is `pool[main - 1 - i]`. Every one's bound is below
    /// `floor`.
    asleep: usize,
    /// Every deep sleeper's bound is below this.
    floor: S,
    /// Shapes placed when the current step began (for the budget).
    placed: usize,
    /// Waiting cells, a max-heap by bound in `pool[main..main + waiting]`: too tight for the
    /// current need but at or above the floor, so they must wake as soon as the need falls to
    /// their bound.
    waiting: usize,
    /// Sum over live cells of their area in units of the finest level's cell.
    weight: u64,
    origin: Point<S>,
    geom: [LevelGeom<S>; CELL_LEVELS],
    slack: S,
    /// Cells drawn ahead within the current step (slot and copy as drawn); see
    /// [`CellSampler::draw`].
    ahead: [(usize, Cell<S>); AHEAD],
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
}

/// Why a cell sampler could not be set up: its storage is empty (or beyond `u32` indices).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NoCells;

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
            starts: [0; CELL_LEVELS + 1],
            asleep: 0,
            floor: S::from_f64(f64::MAX),
            placed: 0,
            waiting: 0,
            weight: 0,
            origin: Point::new(S::ZERO, S::ZERO),
            geom: [LevelGeom::default(); CELL_LEVELS],
            slack: S::ZERO,
            ahead: [(usize::MAX, Cell::default()); AHEAD],
            ahead_len: 0,
            ahead_pos: 0,
            batch_weight: 0,
            step_inv: 0.0,
            estimating: false,
            paper: 0.0,
            last_paper: 0.0,
            ready: false,
            stats: CellStats::default(),
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
        self.weight as f64 * (g.w * g.h).to_f64()
    }

    /// The counters so far.
    pub fn stats(&self) -> CellStats {
        let mut s = self.stats;
        s.live = self.live();
        s.sleeping = self.asleep + self.waiting;
        s
    }

    /// Whether the grid has been laid out.
    pub(crate) fn ready(&self) -> bool {
        self.ready
    }

    #[inline]
    fn live(&self) -> usize {
        self.start(CELL_LEVELS)
    }

    /// Whether no live cell is left.
    pub(crate) fn is_empty(&self) -> bool {
        self.live() == 0
    }

    #[inline]
    fn start(&self, k: usize) -> usize {
        self.starts.get(k).map_or(0, |&v| v as usize)
    }

    #[inline]
    fn bump(&mut self, k: usize, up: bool) {
        if let Some(v) = self.starts.get_mut(k) {
            *v = if up { v.saturating_add(1) } else { v.saturating_sub(1) };
        }
    }

    /// A cell of level `level` weighs `4^(CELL_LEVELS - 1 - level)`: its area in cells of the
    /// finest level.
    #[inline]
    fn shift(level: usize) -> u32 {
        2 * (CELL_LEVELS - 1 - level) as u32
    }

    #[inline]
    fn lg(&self, level: u32) -> LevelGeom<S> {
        self.geom.get(level as usize).copied().unwrap_or_default()
    }

    /// The centre of a cell.
    fn centre(&self, c: &Cell<S>) -> Point<S> {
        let g = self.lg(c.level());
        let half = S::ONE.half();
        Point::new(
            self.origin.x + (S::from_f64(f64::from(c.ix())) + half) * g.w,
            self.origin.y + (S::from_f64(f64::from(c.iy())) + half) * g.h,
        )
    }

    /// The bound on the clearance anywhere in the cell (with the rounding slack).
    #[inline]
    fn upper(&self, c: &Cell<S>) -> S {
        c.u + self.slack
    }

    /// The bound on the clearance anywhere in the cell at `centre` of level geometry `g`, from
    /// the outside of the region and the shapes `near`: the clearance at the centre is at most
    /// each of their distances, and clearance is 1-Lipschitz (for circles, see
    /// [`Field::box_dist`]).
    fn bound(f: &impl Field<S>, near: &[u32; NEAR], centre: Point<S>, g: &LevelGeom<S>) -> S {
        let (hw, hh) = (g.w.half(), g.h.half());
        near.iter().filter(|&&j| j != NONE).fold(f.edge(centre) + g.half_diag, |m, &j| {
            m.min(f.box_dist(j, centre, hw, hh).unwrap_or_else(|| f.dist(j, centre) + g.half_diag))
        })
    }

    /// [`CellSampler::bound`] taken over each quarter of the cell at `centre` (whose quarters
    /// have level geometry `q`), and the largest kept: no point of the cell is clearer than
    /// the bound of the quarter it lies in. Tighter where different shapes close different
    /// quarters, for four bounds' work.
    fn bound_by_quarters(f: &impl Field<S>, near: &[u32; NEAR], centre: Point<S>, q: &LevelGeom<S>) -> S {
        let (hw, hh) = (q.w.half(), q.h.half());
        let quarters = [(-hw, -hh), (hw, -hh), (-hw, hh), (hw, hh)].map(|(dx, dy)| centre.shift(dx, dy));
        let mut u = quarters.map(|p| f.edge(p) + q.half_diag);
        // Each known shape is looked up once for the four quarters.
        for &j in near.iter().filter(|&&j| j != NONE) {
            let disc = f.disc(j, centre);
            for (ui, &p) in u.iter_mut().zip(quarters.iter()) {
                let d = match disc {
                    Some((o, r)) => far_corner(o, p, hw, hh) - r,
                    None => f.dist(j, p) + q.half_diag,
                };
                *ui = ui.min(d);
            }
        }
        u.into_iter().fold(S::from_f64(f64::MIN), |m, b| m.max(b))
    }

    /// Lays out the level-0 grid over the box `(x0, y0, w, h)`, bounding each cell by its
    /// distance to the outside of the region, and drops the cells outside the region.
    pub(crate) fn init(&mut self, x0: S, y0: S, w: S, h: S, f: &impl Field<S>) {
        let (wf, hf) = (w.to_f64(), h.to_f64());
        let side = wf.max(hf) / f64::from(GRID0);
        let (mut nx, mut ny) = (ceil_u32(wf / side).clamp(1, GRID0), ceil_u32(hf / side).clamp(1, GRID0));
        if (nx * ny) as usize > self.main {
            (nx, ny) = (1, 1);
        }
        self.origin = Point::new(x0, y0);
        let (mut cw, mut ch) = (w / S::from_f64(f64::from(nx)), h / S::from_f64(f64::from(ny)));
        for g in self.geom.iter_mut() {
            *g = LevelGeom {
                w: cw,
                h: ch,
                half_diag: (cw * cw + ch * ch).sqrt().half(),
            };
            cw = cw.half();
            ch = ch.half();
        }
        self.slack = S::from_f64(1e-9 * wf.max(hf)) + S::from_f64(1e-12);
        self.starts = [0; CELL_LEVELS + 1];
        self.asleep = 0;
        self.waiting = 0;
        self.weight = 0;
        for iy in 0..ny {
            for ix in 0..nx {
                let mut c = Cell {
                    xl: ix,
                    yr: iy,
                    ..Cell::default()
                };
                c.u = Self::bound(f, &c.near, self.centre(&c), &self.lg(0));
                if self.upper(&c) > S::ZERO {
                    self.insert_live(c);
                } else {
                    self.stats.dropped += 1;
                }
            }
        }
        self.ready = true;
    }

    /// The cell at `i`.
    #[inline]
    fn cell(&self, i: usize) -> Option<Cell<S>> {
        self.pool.get(i).map(Cell::load)
    }

    /// Stores `c` at `i` (nothing when `i` is out of range).
    #[inline]
    fn put(&mut self, i: usize, c: Cell<S>) {
        if let Some(w) = self.pool.get_mut(i) {
            *w = c.store();
        }
    }

    /// Copies the cell at `from` to `to`.
    #[inline]
    fn copy(&mut self, from: usize, to: usize) {
        if let Some(w) = self.pool.get(from).copied() {
            if let Some(t) = self.pool.get_mut(to) {
                *t = w;
            }
        }
    }

    fn note_peak(&mut self) {
        self.stats.peak = self.stats.peak.max(self.live() + self.asleep + self.waiting);
    }

    /// Adds a live cell at the end of its level's run, moving one cell of each finer level.
    /// Returns its slot (cells of its level keep their slots while others of that level are
    /// added).
    fn insert_live(&mut self, c: Cell<S>) -> usize {
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
    fn remove_live(&mut self, slot: usize, k: usize) {
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

    /// Retires a cell too tight for the current need: dropped when it lies inside shape
    /// material, a deep sleeper when its bound is below the floor, otherwise waiting. (With
    /// no room left it stays live: never exact to drop a cell that could hold a shape.)
    fn retire(&mut self, c: Cell<S>) {
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

    fn waiting_key(&self, k: usize) -> S {
        self.pool.get(self.main + k).map_or(S::ZERO, |w| S::from_word(w[3]) + self.slack)
    }

    fn swap_waiting(&mut self, a: usize, b: usize) {
        let (a, b) = (self.main + a, self.main + b);
        if a < self.pool.len() && b < self.pool.len() {
            self.pool.swap(a, b);
        }
    }

    /// Adds a waiting cell; false when the heap is full.
    fn push_waiting(&mut self, c: Cell<S>) -> bool {
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

    fn pop_waiting(&mut self) -> Option<Cell<S>> {
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

    /// Makes every cell that could hold a shape needing `need` live. When `need` is below the
    /// floor, one pass over the deep sleepers lowers the floor to a fraction of `need` and
    /// moves every cell at or above it out (live, or waiting); then waiting cells whose bound
    /// reaches `need` wake.
    pub(crate) fn wake(&mut self, need: S, placed: usize) {
        self.placed = placed;
        if need < self.floor {
            self.floor = need * S::from_f64(FLOOR);
            let mut i = 0;
            while i < self.asleep {
                let Some(c) = self.cell(self.main - 1 - i) else {
                    break;
                };
                if self.upper(&c) >= self.floor {
                    // Fill entry i with the last deep sleeper, then move c up.
                    self.copy(self.main - self.asleep, self.main - 1 - i);
                    self.asleep -= 1;
                    if self.upper(&c) >= need || !self.push_waiting(c) {
                        self.insert_live(c);
                    }
                } else {
                    i += 1;
                }
            }
        }
        while self.waiting > 0 && self.waiting_key(0) >= need {
            match self.pop_waiting() {
                Some(c) => {
                    self.insert_live(c);
                }
                None => break,
            }
        }
    }

    /// Forgets the cells drawn ahead.
    fn flush(&mut self) {
        self.ahead_len = 0;
        self.ahead_pos = 0;
    }

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
        // A weight unit is a cell of the finest level: a 4^23th of a level-0 cell.
        let unit = g.w.to_f64() * g.h.to_f64() / (1u64 << Self::shift(0)) as f64;
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

    /// The live cell that weight `r` (below the total weight) falls in.
    fn slot_of(&self, mut r: u64) -> Option<usize> {
        for k in 0..CELL_LEVELS {
            let count = (self.start(k + 1) - self.start(k)) as u64;
            let w = count << Self::shift(k);
            if r < w {
                return Some(self.start(k) + (r >> Self::shift(k)) as usize);
            }
            r -= w;
        }
        None
    }

    /// Draws a live cell with probability proportional to its area (exactly: integer weights
    /// and an unbiased bounded draw) and a uniform point in it.
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
            let mut slots = [0usize; AHEAD];
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
            for (entry, &slot) in self.ahead.iter_mut().zip(slots.iter()) {
                *entry = (slot, self.pool.get(slot).map(Cell::load)?);
            }
            self.ahead_len = AHEAD;
        }
        let (slot, c) = self.ahead.get(self.ahead_pos).copied()?;
        self.ahead_pos += 1;
        let g = self.lg(c.level());
        let ux: S = crate::rng::unit(rng);
        let uy: S = crate::rng::unit(rng);
        let p = Point::new(
            self.origin.x + (S::from_f64(f64::from(c.ix())) + ux) * g.w,
            self.origin.y + (S::from_f64(f64::from(c.iy())) + uy) * g.h,
        );
        let half = S::ONE.half();
        Some(Drawn {
            slot,
            cell: c,
            point: p,
            quarter: (ux >= half, uy >= half),
        })
    }

    /// Restructures the drawn cell: a cell too tight for `need` is retired; a cell much larger
    /// than `need` is split into children that inherit its shapes. Says whether the drawn
    /// point (in quarter `quarter` of the cell) can still be valid, and in which live cell it
    /// lies.
    ///
    /// `drawn` is the cell as it was drawn; if `slot` no longer holds it (it moved, or was
    /// split or retired since), the point is simply tested, without bookkeeping.
    pub(crate) fn judge(&mut self, slot: usize, drawn: &Cell<S>, quarter: (bool, bool), need: S, f: &impl Field<S>) -> Verdict {
        let Some(c) = self.cell(slot).filter(|c| slot < self.live() && c.same(drawn)) else {
            return Verdict::Test(usize::MAX);
        };
        let level = c.level();
        let g = self.lg(level);
        if self.upper(&c) < need {
            self.stats.cell_rejects += 1;
            self.remove_live(slot, level as usize);
            self.retire(c);
            return Verdict::Reject;
        }
        let big = g.half_diag > need * S::from_f64(SPLIT);
        if !((big || c.rejects() >= STUBBORN) && (level as usize) + 1 < CELL_LEVELS) {
            return Verdict::Test(slot);
        }
        // Every cell held must fit in the live and deep-sleeper part of the pool, waiting ones
        // included: a waiting cell that wakes needs a place there, and a cell with nowhere to
        // go would leave the union without its valid centres.
        let held = self.live() + self.asleep + self.waiting + 3;
        let budget = CELLS_PER_SHAPE.saturating_mul(self.placed.saturating_add(CELLS_BASE));
        if held > self.main || held > budget {
            self.stats.refused_splits += 1;
            return Verdict::Test(slot);
        }
        self.stats.splits += 1;
        self.remove_live(slot, level as usize);
        let cg = self.lg(level + 1);
        // A stubborn cell keeps missing: the shapes it learned from its trials do not close
        // it. It looks its neighbours up in the index, and its children are bounded quarter
        // by quarter.
        let stubborn = c.rejects() >= STUBBORN && (level as usize) + 2 < CELL_LEVELS;
        let mut c = c;
        if stubborn {
            self.stats.gathers += 1;
            f.gather(self.centre(&c), g.half_diag.half() + need, &mut c.near);
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
            if self.upper(&child) < need {
                self.retire(child);
            } else {
                let at = self.insert_live(child);
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
    /// bound, and is retired if that leaves no room for `need`.
    pub(crate) fn learn(&mut self, slot: usize, j: u32, need: S, f: &impl Field<S>) {
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
        if self.upper(&c) < need {
            self.remove_live(slot, c.level() as usize);
            self.retire(c);
        }
    }

    /// Counts a trial whose cell learned the shape it hit.
    pub(crate) fn note_learned(&mut self, slot: usize) {
        self.stats.learned += 1;
        self.note_reject(slot, false);
    }
}

/// The distance from `o` to the corner farthest from it of the box centred on `c` with half
/// sides `hw`, `hh`.
#[inline]
fn far_corner<S: Scalar>(o: Point<S>, c: Point<S>, hw: S, hh: S) -> S {
    let (ax, ay) = ((c.x - o.x).abs() + hw, (c.y - o.y).abs() + hh);
    (ax * ax + ay * ay).sqrt()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Fixed;

    fn round_trip<S: Scalar>(u: S) {
        for (xl, yr, near) in [
            (0, 0, [NONE; NEAR]),
            ((5 << X_BITS) | 12345, (3 << X_BITS) | CHECK_Y, [0, 1, NONE, u32::MAX - 1]),
            (u32::MAX, u32::MAX, [7, NONE, 0, 99]),
        ] {
            let c = Cell { xl, yr, near, u };
            assert_eq!(Cell::<S>::load(&c.store()), c);
        }
    }

    const CHECK_Y: u32 = (1 << X_BITS) - 1;

    #[test]
    fn cells_read_back_what_was_stored() {
        for u in [0.0, -0.0, 1.5e-300, -3.25, f64::MAX] {
            round_trip(u);
        }
        for u in [0.0, -7.5, 1e-9, 2e9] {
            round_trip(Fixed::from_f64(u));
        }
    }

    #[test]
    fn zero_words_are_an_empty_cell() {
        let c = Cell::<f64>::load(&[0; 4]);
        assert_eq!(c, Cell::default());
        assert_eq!(c.near, [NONE; NEAR]);
        assert_eq!(Cell::<Fixed>::load(&[0; 4]), Cell::default());
    }
}
