//! The 3D cell sampler: candidates drawn only where the next solid could still go, with exactly
//! the distribution of accepted placements of the paper's sampler ([`SpaceEngine::step`]).
//!
//! It is the octree version of the 2D cell sampler ([`crate::CellSampler`]; the argument is
//! written out in full in its documentation and in `docs/sampler.md`).
//!
//! ## The cells
//! The region's bounding box is covered by a grid of cubes of side `L / 16` (`L` its largest
//! side; coarser when the lent cells could not hold that grid twice over); a cell of level `k + 1` is an eighth of one of level `k`, down to [`SPACE_CELL_LEVELS`]
//! levels. Let `f(p)` be the least of the signed distance from `p` to the outside of the region
//! and, over the solids a cell knows of (at most [`SPACE_NEAR`]), an upper bound of the signed
//! distance from `p` to the solid's material:
//! - a sphere or shell: the exact distance;
//! - a cube, tetrahedron or octahedron: the distance to its inscribed ball, `|p - c| - r_in`
//!   (the ball lies in the solid, so the solid is at least that near);
//! - a torus: the distance to the smooth torus its beads hold (tube `a - 2 R sin(pi / 2n)`,
//!   see the module on tori), which lies in the union of its beads.
//!
//! `f` is 1-Lipschitz (a least of 1-Lipschitz functions), so over a cell whose centre is `m`
//! and whose half diagonal is `h`, `f <= f(m) + h`. Each cell keeps such a bound `u`, grown by
//! the scalar's slack ([`crate::Scalar::BOUND_SLACK`] and [`crate::Scalar::OUTLINE_SLACK`], for
//! the rounding of the bound's own arithmetic and of the solids as stored); knowing more solids
//! only lowers it.
//!
//! A solid whose inscribed ball about its centre has radius `r` can only be centred where
//! `f >= need = r + gap`: it must keep more than `gap` from every solid and lie in the region
//! at least `gap` from its boundary, and it holds that ball. A shell holds its whole outer ball
//! when nothing could sit in its hole: when the hole's volume is at most the shell's own (so
//! no earlier, larger solid fits in it) and the region has no removed ball that fits in it
//! either; then `r` is its outer radius. A torus has no such ball (its centre is in its hole,
//! where another ring may pass), nor has a shell with a larger hole: those placements use the
//! paper's sampler, and the cells stay as they are (a bound is never made wrong by more solids).
//!
//! A drawn cell with `u < need` holds no valid centre: it goes to sleep in a max-heap until a
//! later solid's `need` falls to `u` (in a mix a cell may be live with `u < need`, which costs a
//! trial, never exactness), or is dropped when `u` is below the floor `F`. The cells are built
//! from the first grid for the first solid, and built anew whenever a need falls below `F`;
//! each build sets `F` to 0.6 times the need it serves. Between two builds every need is at
//! least `F`, so a dropped cell (`u < F`) holds no valid centre for any of them, and the next
//! build starts again from the whole grid: nothing dropped is lost for the smaller solids
//! after it. A build refines every cell larger than the need, keeps the cells with `u >= F`
//! (live when `u >= need`), and looks up, for each cell of about the need's size, the
//! [`SPACE_NEAR`] solids nearest its centre. So no cell far below the need is ever stored.
//! Between builds a drawn cell whose half diagonal is above the need, or that has rejected
//! eight candidates, is split into its eight children, which start with their parent's solids
//! and bound and look up their nearest solids.
//!
//! Cells learn their solids from the trials: a candidate that hits a solid teaches the drawn
//! cell that solid, and the cell that receives a solid learns it at once. A candidate nearer
//! than the need to a solid its cell knows is rejected without the spatial index.
//!
//! ## Why the accepted placements are exactly the reference's
//! Each trial draws a cell with probability proportional to its volume (exact integer weights
//! and Lemire's unbiased bounded draw), a uniform point in it, then accepts the point if and
//! only if it is a valid centre: a point in a child shown too tight is rejected, which is
//! right because no valid centre lies there; every other point meets the paper's own range and
//! exact tests, with the rotation drawn independently. Cells leave the union `U` of the live
//! cells only when they hold no valid centre, so `U` contains the set `V` of valid centres, and
//! a trial accepts each point of `V` with the same density `1 / |U|`: the accepted centre is
//! uniform over `V`, as the paper's sampler's is. When no cell is live, `V` is empty and the
//! fill halts at once (a proven halt: [`StepError::Halted`] with fewer trials than the limit).
//!
//! ## Storage and determinism
//! The caller lends the cells ([`SpaceCell`], 40 bytes each). The live cells sit at the start
//! of the slice grouped by level, the sleeping ones in a heap at its end. At most
//! `SPACE_CELLS_BASE + SPACE_CELLS_PER_SOLID * placed` cells exist at once, so a fill lent
//! [`space_cells_for`]`(capacity)` cells never depends on the storage; lent fewer, cells stop
//! splitting when the slice is full, and sampling stays exact, only slower. The two samplers
//! use the random numbers differently: the same seed gives different fills, each reproducible
//! bit for bit and prefix-stable.

use super::engine::{Next, SpaceEngine, SpacePlacement};
use super::region::SpaceRegion;
use super::solid::Solid;
use super::vec3::{columns, V3};
use super::PlacedSolid;
use crate::params::{StepError, Stop, StopReason};
use crate::scalar::Scalar;
use rand_core::RngCore;

/// Levels of cells below the first grid.
pub const SPACE_CELL_LEVELS: usize = 16;
/// The solids a cell knows of.
pub const SPACE_NEAR: usize = 4;
/// Cells along the region's largest side at level 0.
const GRID: f64 = 16.0;
/// The cells a fill may hold before any solid is placed (the level-0 grid and its first
/// splits).
pub const SPACE_CELLS_BASE: usize = 16 * 16 * 16 * 4;
/// The cells a fill may hold per placed solid.
pub const SPACE_CELLS_PER_SOLID: usize = 64;
/// The floor, as a fraction of the need at a build: cells below it are dropped, and the cells
/// are built anew when a need falls below it.
const FLOOR: f64 = 0.6;
/// Cells whose half diagonal is at most this many needs look up their nearest solids in a
/// rebuild (larger ones pass theirs down).
const ASK: f64 = 1.0;
/// The depth-first stack of a rebuild: eight children a level.
const STACK: usize = 8 * SPACE_CELL_LEVELS + 8;
/// Rejections after which a cell splits whatever its size.
const STUBBORN: u8 = 8;
const NIL: u32 = u32::MAX;

/// Cells enough for a fill of `capacity` solids never to be limited by its storage.
pub const fn space_cells_for(capacity: usize) -> usize {
    SPACE_CELLS_BASE + SPACE_CELLS_PER_SOLID * capacity + 8
}

/// One cell of the 3D cell sampler, in storage the caller lends. `SpaceCell::default()` is an
/// empty slot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpaceCell {
    at: [u32; 3],
    level: u8,
    rejects: u8,
    u: f64,
    known: [u32; SPACE_NEAR],
}

impl Default for SpaceCell {
    fn default() -> Self {
        SpaceCell {
            at: [0; 3],
            level: 0,
            rejects: 0,
            u: 0.0,
            known: [NIL; SPACE_NEAR],
        }
    }
}

/// The sampler lent no cells.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct NoSpaceCells;

impl core::fmt::Display for NoSpaceCells {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("the 3D cell sampler needs at least 16 cells")
    }
}

impl core::error::Error for NoSpaceCells {}

/// The 3D cell sampler over caller-lent cells; see the module for how and why it is exact.
///
/// # Examples
///
/// ```
/// use zetafill::{rng_from_seed, space_cells_for, space_index_words, PlacedSolid, SpaceCell, SpaceCells};
/// use zetafill::{SpaceEngine, SpaceParams, SpaceRegion, SpaceStorage, Stop, StopReason};
///
/// let mut solids = vec![PlacedSolid::<f64>::default(); 500];
/// let mut index = vec![0u32; space_index_words(500)];
/// let mut pool = vec![SpaceCell::default(); space_cells_for(500)];
/// let region = SpaceRegion::Box { width: 50.0, height: 50.0, depth: 50.0, periodic: false };
/// let storage = SpaceStorage { solids: &mut solids, index: &mut index };
/// let mut engine = SpaceEngine::new(SpaceParams::spheres(1.15, 2.0), region, storage)?;
/// let mut cells = SpaceCells::new(&mut pool)?;
/// let stop = Stop { count: Some(500), ..Stop::default() };
/// let reason = engine.run_fast(&mut cells, &mut rng_from_seed(3), &stop, |_| {});
/// assert_eq!(reason, StopReason::Count);
/// // No two spheres touch.
/// let s = engine.placed();
/// for (i, a) in s.iter().enumerate() {
///     for b in &s[i + 1..] {
///         let d2 = (a.x - b.x).powi(2) + (a.y - b.y).powi(2) + (a.z - b.z).powi(2);
///         assert!(d2 > (a.scale + b.scale).powi(2));
///     }
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct SpaceCells<'c> {
    pool: &'c mut [SpaceCell],
    /// Level `k`'s live cells are `pool[starts[k]..starts[k + 1]]`.
    starts: [u32; SPACE_CELL_LEVELS + 1],
    /// Sleeping cells: a max-heap by `u`, element `h` at `pool[len - 1 - h]`.
    heap: usize,
    /// The live cells' volume in cells of the finest level.
    weight: u64,
    side0: f64,
    slack: f64,
    started: bool,
    peak: usize,
    /// Cells whose bound is below the floor are dropped; when a need falls below it, the
    /// cells are rebuilt from the first grid.
    floor: f64,
    /// The first grid's cells along each axis.
    grid: [u32; 3],
    rebuilds: u32,
}

/// The outcome of restructuring a drawn cell.
enum Drawn {
    /// The point cannot be valid.
    Reject,
    /// Test it; the cell holding it is at this slot.
    Test(usize),
}

impl<'c> SpaceCells<'c> {
    /// A sampler over the lent cells (at least 16; [`space_cells_for`] for a fill that never
    /// depends on them).
    pub fn new(pool: &'c mut [SpaceCell]) -> Result<Self, NoSpaceCells> {
        if pool.len() < 16 || pool.len() >= u32::MAX as usize {
            return Err(NoSpaceCells);
        }
        Ok(SpaceCells {
            pool,
            starts: [0; SPACE_CELL_LEVELS + 1],
            heap: 0,
            weight: 0,
            side0: 0.0,
            slack: 0.0,
            started: false,
            peak: 0,
            floor: f64::INFINITY,
            grid: [1; 3],
            rebuilds: 0,
        })
    }

    /// Live cells.
    pub fn live(&self) -> usize {
        self.starts.get(SPACE_CELL_LEVELS).map_or(0, |&v| v as usize)
    }

    /// Sleeping cells.
    pub fn asleep(&self) -> usize {
        self.heap
    }

    /// How many times the cells were rebuilt.
    pub fn rebuilds(&self) -> u32 {
        self.rebuilds
    }

    /// The most cells held at once, live and asleep (the storage a fill needed).
    pub fn peak(&self) -> usize {
        self.peak
    }

    fn start(&self, k: usize) -> usize {
        self.starts.get(k).map_or(0, |&v| v as usize)
    }

    fn bump(&mut self, k: usize, up: bool) {
        if let Some(v) = self.starts.get_mut(k) {
            *v = if up { v.saturating_add(1) } else { v.saturating_sub(1) };
        }
    }

    fn shift(level: usize) -> u32 {
        3 * (SPACE_CELL_LEVELS - 1 - level.min(SPACE_CELL_LEVELS - 1)) as u32
    }

    fn side(&self, level: u8) -> f64 {
        self.side0 / f64::from(1u32 << u32::from(level).min(31))
    }

    fn centre(&self, c: &SpaceCell) -> [f64; 3] {
        let s = self.side(c.level);
        c.at.map(|i| (f64::from(i) + 0.5) * s)
    }

    fn half_diagonal(&self, level: u8) -> f64 {
        // sqrt(3) / 2 rounded up.
        self.side(level) * 0.866_025_403_784_438_7
    }

    fn get(&self, i: usize) -> SpaceCell {
        self.pool.get(i).copied().unwrap_or_default()
    }

    fn put(&mut self, i: usize, c: SpaceCell) {
        if let Some(w) = self.pool.get_mut(i) {
            *w = c;
        }
    }

    /// Adds a live cell at the end of its level's run (moving the first cell of each finer
    /// level to the end of that level's run) and returns its slot, or `None` when full.
    fn insert_live(&mut self, c: SpaceCell) -> Option<usize> {
        let k = usize::from(c.level);
        if k >= SPACE_CELL_LEVELS || self.live() + self.heap >= self.pool.len() {
            return None;
        }
        let mut hole = self.live();
        for j in (k + 1..SPACE_CELL_LEVELS).rev() {
            let first = self.start(j);
            if first != hole {
                let moved = self.get(first);
                self.put(hole, moved);
            }
            hole = first;
            self.bump(j, true);
        }
        self.put(hole, c);
        self.bump(SPACE_CELL_LEVELS, true);
        self.peak = self.peak.max(self.live() + self.heap);
        self.weight = self.weight.saturating_add(1u64 << Self::shift(k));
        Some(hole)
    }

    /// Takes the live cell at `slot` out (the last of its level's run fills the hole, and the
    /// last of each finer level moves down by one).
    fn remove_live(&mut self, slot: usize) -> SpaceCell {
        let c = self.get(slot);
        let k = usize::from(c.level).min(SPACE_CELL_LEVELS - 1);
        let mut hole = slot;
        for j in k..SPACE_CELL_LEVELS {
            let last = self.start(j + 1).saturating_sub(1);
            if last != hole {
                let moved = self.get(last);
                self.put(hole, moved);
            }
            hole = last;
            if j > k {
                self.bump(j, false);
            }
        }
        self.bump(SPACE_CELL_LEVELS, false);
        self.weight = self.weight.saturating_sub(1u64 << Self::shift(k));
        c
    }

    fn heap_at(&self, h: usize) -> usize {
        self.pool.len().wrapping_sub(1).wrapping_sub(h)
    }

    fn heap_u(&self, h: usize) -> f64 {
        self.pool.get(self.heap_at(h)).map_or(f64::NEG_INFINITY, |c| c.u)
    }

    fn heap_swap(&mut self, a: usize, b: usize) {
        let (ia, ib) = (self.heap_at(a), self.heap_at(b));
        let (ca, cb) = (self.get(ia), self.get(ib));
        self.put(ia, cb);
        self.put(ib, ca);
    }

    /// Puts a cell to sleep (there is always room: it was live).
    fn push_sleep(&mut self, c: SpaceCell) {
        if self.live() + self.heap >= self.pool.len() {
            return;
        }
        let mut h = self.heap;
        self.heap += 1;
        let at = self.heap_at(h);
        self.put(at, c);
        while h > 0 {
            let parent = (h - 1) / 2;
            if self.heap_u(parent) >= self.heap_u(h) {
                break;
            }
            self.heap_swap(parent, h);
            h = parent;
        }
    }

    fn pop_sleep(&mut self) -> Option<SpaceCell> {
        if self.heap == 0 {
            return None;
        }
        let top = self.get(self.heap_at(0));
        self.heap -= 1;
        if self.heap > 0 {
            self.heap_swap(0, self.heap);
            let mut h = 0;
            loop {
                let (l, r) = (2 * h + 1, 2 * h + 2);
                let mut m = h;
                if l < self.heap && self.heap_u(l) > self.heap_u(m) {
                    m = l;
                }
                if r < self.heap && self.heap_u(r) > self.heap_u(m) {
                    m = r;
                }
                if m == h {
                    break;
                }
                self.heap_swap(h, m);
                h = m;
            }
        }
        Some(top)
    }

    /// Retires a live cell too tight for `need`: asleep, or dropped when it lies in material.
    fn retire(&mut self, slot: usize) {
        let c = self.remove_live(slot);
        if c.u >= self.floor && c.u > 0.0 {
            self.push_sleep(c);
        }
    }

    /// Sets the grid up on the first call.
    fn begin<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>) {
        if self.started {
            return;
        }
        self.started = true;
        let ext = e.region.extent();
        let largest = ext.iter().fold(0.0f64, |m, &v| m.max(v));
        // The first grid: 16 cells along the largest side, fewer when the lent cells could
        // not hold it twice over (the fill then depends on the storage, as documented).
        let mut grid = GRID;
        while grid > 1.0 && 2.0 * grid * grid * grid > self.pool.len() as f64 {
            grid /= 2.0;
        }
        self.side0 = largest / grid;
        let [rel, abs] = S::BOUND_SLACK;
        let [orel, oabs] = S::OUTLINE_SLACK;
        self.slack = (rel + orel) * largest + abs + oabs;
        self.grid = ext.map(|v| libm::ceil(v / self.side0).clamp(1.0, grid) as u32);
    }

    /// Builds the cells anew from the first grid for a solid that needs `need`: every cell
    /// whose bound is at least the new floor (`FLOOR` times `need`) is kept, live when it
    /// admits `need`, asleep otherwise; a cell larger than the need is refined first (while
    /// the storage lets every cell still to be visited find a place, so none is lost). Each
    /// cell near the need's size looks up the solids nearest its centre.
    fn rebuild<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, need: f64) {
        self.rebuilds = self.rebuilds.saturating_add(1);
        self.starts = [0; SPACE_CELL_LEVELS + 1];
        self.heap = 0;
        self.weight = 0;
        self.floor = FLOOR * need;
        let limit = self.pool.len().min(self.budget(e.len));
        let mut stack = [SpaceCell::default(); STACK];
        let [nx, ny, nz] = self.grid;
        for ix in 0..nx {
            for iy in 0..ny {
                for iz in 0..nz {
                    let root = SpaceCell {
                        at: [ix, iy, iz],
                        u: f64::INFINITY,
                        ..SpaceCell::default()
                    };
                    let mut top = 0usize;
                    if let Some(s) = stack.get_mut(0) {
                        *s = root;
                        top = 1;
                    }
                    while top > 0 {
                        top -= 1;
                        let mut c = stack.get(top).copied().unwrap_or_default();
                        let (m, h) = (self.centre(&c), self.half_diagonal(c.level));
                        c.u = self.bound_at(e, &c.known, m, c.level).min(c.u);
                        // What the parent knew may already drop the cell; otherwise a cell
                        // near the need's size looks its nearest solids up.
                        if h <= ASK * need && c.u >= self.floor {
                            c.known = nearest(e, m, h + need, &c.known);
                            c.u = self.bound_at(e, &c.known, m, c.level).min(c.u);
                        }
                        if c.u < self.floor || c.u <= 0.0 {
                            continue;
                        }
                        let pending = top + (nx * ny * nz) as usize;
                        let room = self.live() + self.heap + pending + 8 <= limit;
                        if h > need && usize::from(c.level) + 1 < SPACE_CELL_LEVELS && room && top + 8 <= STACK {
                            for child in 0..8u32 {
                                let bits = [child & 1, (child >> 1) & 1, (child >> 2) & 1];
                                let k = SpaceCell {
                                    at: core::array::from_fn(|a| {
                                        c.at.get(a).copied().unwrap_or(0).wrapping_mul(2) + bits.get(a).copied().unwrap_or(0)
                                    }),
                                    level: c.level + 1,
                                    rejects: 0,
                                    u: c.u,
                                    known: c.known,
                                };
                                if let Some(s) = stack.get_mut(top) {
                                    *s = k;
                                    top += 1;
                                }
                            }
                        } else if c.u >= need {
                            let _ = self.insert_live(c);
                        } else {
                            self.push_sleep(c);
                        }
                    }
                }
            }
        }
    }

    /// Readies the cells for a solid that needs `need` (before the slack): rebuilds them when
    /// the need fell below the floor, wakes the sleepers it admits otherwise. Returns the need
    /// the cells are compared with.
    fn prepare<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, need: f64) -> f64 {
        self.begin(e);
        let need = need - self.slack;
        if need < self.floor {
            self.rebuild(e, need);
        } else {
            self.wake(need);
        }
        need
    }

    /// Wakes every sleeping cell whose bound admits `need`.
    fn wake(&mut self, need: f64) {
        while self.heap > 0 && self.heap_u(0) >= need {
            match self.pop_sleep() {
                Some(c) => {
                    if self.insert_live(c).is_none() {
                        self.push_sleep(c);
                        return;
                    }
                }
                None => return,
            }
        }
    }

    /// Draws a live cell with probability proportional to its volume and a uniform point in
    /// it: `(slot, unit offsets)`.
    fn draw<R: RngCore + ?Sized>(&self, rng: &mut R) -> Option<(usize, [f64; 3])> {
        let total = self.weight;
        if total == 0 {
            return None;
        }
        // Lemire's method: a uniform integer below `total` without bias.
        let threshold = total.wrapping_neg() % total;
        let mut r = loop {
            let m = u128::from(rng.next_u64()) * u128::from(total);
            if (m as u64) >= threshold {
                break (m >> 64) as u64;
            }
        };
        let units: [f64; 3] = core::array::from_fn(|_| crate::rng::unit::<f64, R>(rng));
        for k in 0..SPACE_CELL_LEVELS {
            let count = (self.start(k + 1) - self.start(k)) as u64;
            let w = count << Self::shift(k);
            if r < w {
                return Some((self.start(k) + (r >> Self::shift(k)) as usize, units));
            }
            r -= w;
        }
        None
    }

    /// The bound a cell with these known solids has at `centre` over half diagonal `h`.
    fn bound_at<S: Scalar>(&self, e: &SpaceEngine<'_, S>, known: &[u32; SPACE_NEAR], centre: [f64; 3], level: u8) -> f64 {
        let (half, h) = (0.5 * self.side(level), self.half_diagonal(level));
        let mut f = edge(&e.region, centre) + h;
        for &j in known.iter().filter(|&&j| j != NIL) {
            f = f.min(e.dist_over(j, centre, half, h));
        }
        f + self.slack
    }

    /// Teaches the cell at `slot` solid `j`; says whether it knew it already.
    fn learn<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, slot: usize, j: u32) -> bool {
        let mut c = self.get(slot);
        if c.known.contains(&j) {
            return true;
        }
        let m = self.centre(&c);
        let d = e.dist_up(j, m);
        let t = e.dist_over(j, m, 0.5 * self.side(c.level), self.half_diagonal(c.level)) + self.slack;
        if t < c.u {
            c.u = t;
        }
        // Keep the nearest SPACE_NEAR: an empty slot, or the farthest if it is farther.
        let mut worst = (0usize, f64::NEG_INFINITY);
        for (i, &k) in c.known.iter().enumerate() {
            let dk = if k == NIL { f64::INFINITY } else { e.dist_up(k, m) };
            if dk > worst.1 {
                worst = (i, dk);
            }
        }
        if worst.1 > d {
            if let Some(w) = c.known.get_mut(worst.0) {
                *w = j;
            }
        }
        self.put(slot, c);
        false
    }

    /// Splits or retires the drawn cell as `need` asks, and says whether the drawn point
    /// (offsets `units` in it) can still be valid, and in which live cell it lies.
    fn restructure<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, slot: usize, units: [f64; 3], need: f64) -> Drawn {
        let c = self.get(slot);
        if c.u < need {
            self.retire(slot);
            return Drawn::Reject;
        }
        let level = usize::from(c.level);
        let big = self.half_diagonal(c.level) > need;
        let room = self.live() + self.heap + 7 <= self.pool.len().min(self.budget(e.len));
        if level + 1 >= SPACE_CELL_LEVELS || !(big || c.rejects >= STUBBORN) || !room {
            return Drawn::Test(slot);
        }
        let mut parent = self.remove_live(slot);
        parent.known = nearest(e, self.centre(&parent), self.half_diagonal(parent.level) + need, &parent.known);
        let pick = units.map(|u| u32::from(u >= 0.5));
        let mut at = None;
        for child in 0..8u32 {
            let bits = [child & 1, (child >> 1) & 1, (child >> 2) & 1];
            let mut k = SpaceCell {
                at: core::array::from_fn(|a| parent.at.get(a).copied().unwrap_or(0).wrapping_mul(2) + bits.get(a).copied().unwrap_or(0)),
                level: parent.level + 1,
                rejects: 0,
                u: 0.0,
                known: parent.known,
            };
            k.u = self.bound_at(e, &k.known, self.centre(&k), k.level).min(parent.u);
            let live = if k.u >= need {
                self.insert_live(k)
            } else {
                if k.u > 0.0 && k.u >= self.floor {
                    self.push_sleep(k);
                }
                None
            };
            if bits == pick {
                at = live;
            }
        }
        match at {
            Some(s) => Drawn::Test(s),
            None => Drawn::Reject,
        }
    }

    fn budget(&self, placed: usize) -> usize {
        SPACE_CELLS_BASE.saturating_add(SPACE_CELLS_PER_SOLID.saturating_mul(placed))
    }

    fn note_reject(&mut self, slot: usize) {
        if let Some(c) = self.pool.get_mut(slot) {
            c.rejects = c.rejects.saturating_add(1);
        }
    }
}

/// The [`SPACE_NEAR`] solids nearest `p` (by [`SpaceEngine::dist_up`]) among `known` and those
/// the spatial index lists within `reach` of it.
fn nearest<S: Scalar>(e: &SpaceEngine<'_, S>, p: [f64; 3], reach: f64, known: &[u32; SPACE_NEAR]) -> [u32; SPACE_NEAR] {
    let mut best = [(f64::INFINITY, NIL); SPACE_NEAR];
    let mut offer = |j: u32| {
        if best.iter().any(|b| b.1 == j) {
            return;
        }
        let d = e.dist_up(j, p);
        // Only solids truly within reach, whatever else the index lists: the choice must not
        // depend on its layout.
        if d > reach {
            return;
        }
        // The largest by (distance, index), so that the four kept never depend on the order
        // the index lists them in.
        let mut worst = 0usize;
        for (i, b) in best.iter().enumerate() {
            if best.get(worst).is_some_and(|w| b.0 > w.0 || (b.0 == w.0 && b.1 > w.1)) {
                worst = i;
            }
        }
        if let Some(w) = best.get_mut(worst) {
            if d < w.0 || (d == w.0 && j < w.1) {
                *w = (d, j);
            }
        }
    };
    for &j in known.iter().filter(|&&j| j != NIL) {
        offer(j);
    }
    e.near(p, reach, &mut offer);
    best.map(|b| b.1)
}

/// The signed distance from `p` to the outside of the region (large for a periodic box).
fn edge(region: &SpaceRegion, p: [f64; 3]) -> f64 {
    region.edge::<f64>(V3::new(p[0], p[1], p[2]))
}

impl<S: Scalar> SpaceEngine<'_, S> {
    /// An upper bound of the signed distance from `p` to placed solid `j`'s material, in
    /// `f64` (the nearest periodic image for a periodic box); see [`SpaceCells`].
    pub(crate) fn dist_up(&self, j: u32, p: [f64; 3]) -> f64 {
        let Some(s) = self.placed().get(j as usize) else {
            return f64::INFINITY;
        };
        let kind = self.kind_of(u64::from(j));
        let d = self.offset(s, p);
        let r = libm::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        let scale = s.scale.to_f64();
        match kind {
            Solid::Sphere => r - scale,
            Solid::Shell { inner } => {
                let hole = scale * inner;
                if r >= scale {
                    r - scale
                } else if r <= hole {
                    hole - r
                } else {
                    -(r - hole).min(scale - r)
                }
            }
            Solid::Torus { ratio } => torus_dist(s, ratio, kind.beads(), d, r),
            _ => r - kind.support(scale),
        }
    }

    /// An upper bound of [`Self::dist_up`] over the cube of centre `m` and half side `half`
    /// (half diagonal `h`): for a sphere, and the inscribed ball of a polyhedron, the largest
    /// over the cube's corners (the distance to a ball is convex, so no point of the cube is
    /// farther than its farthest corner); for the others the centre's plus `h` (1-Lipschitz).
    pub(crate) fn dist_over(&self, j: u32, m: [f64; 3], half: f64, h: f64) -> f64 {
        let Some(s) = self.placed().get(j as usize) else {
            return f64::INFINITY;
        };
        let kind = self.kind_of(u64::from(j));
        let ball = match kind {
            Solid::Sphere | Solid::Cube | Solid::Tetrahedron | Solid::Octahedron => kind.support(s.scale.to_f64()),
            _ => return self.dist_up(j, m) + h,
        };
        let d = self.offset(s, m);
        let far = |v: f64| {
            let a = libm::fabs(v) + half;
            a * a
        };
        libm::sqrt(far(d[0]) + far(d[1]) + far(d[2])) - ball
    }

    /// `p` less the solid's centre (the nearest periodic image's, for a periodic box).
    fn offset(&self, s: &PlacedSolid<S>, p: [f64; 3]) -> [f64; 3] {
        let mut d = [p[0] - s.x.to_f64(), p[1] - s.y.to_f64(), p[2] - s.z.to_f64()];
        if self.region.periodic() {
            for (v, &period) in d.iter_mut().zip(self.region.extent().iter()) {
                *v -= period * libm::round(*v / period);
            }
        }
        d
    }

    /// Calls `f` with every placed solid that may come within `reach` of `p` (each periodic
    /// image of `p` that can reach into the box, for a periodic box).
    pub(crate) fn near(&self, p: [f64; 3], reach: f64, mut f: impl FnMut(u32)) {
        let total = self.len as u32;
        let r = S::from_f64(reach);
        let at = |q: [f64; 3], f: &mut dyn FnMut(u32)| {
            self.hash.query(q.map(S::from_f64), r, total, |j| {
                f(j);
                true
            });
        };
        if !self.region.periodic() {
            at(p, &mut f);
            return;
        }
        let ext = self.region.extent();
        let m = reach + self.hash.max_r().to_f64();
        let shifts = |a: usize| {
            let (v, w) = (p.get(a).copied().unwrap_or(0.0), ext.get(a).copied().unwrap_or(0.0));
            [(-w, v + m >= w), (0.0, true), (w, v - m < 0.0)]
        };
        for (dx, ox) in shifts(0) {
            for (dy, oy) in shifts(1) {
                for (dz, oz) in shifts(2) {
                    if ox && oy && oz {
                        at([p[0] + dx, p[1] + dy, p[2] + dz], &mut f);
                    }
                }
            }
        }
    }

    /// The clearance every valid centre of the next solid has, or `None` when it has no
    /// usable one (see [`SpaceCells`]).
    fn need(&self, next: &Next<S>) -> Option<f64> {
        let scale = next.scale.to_f64();
        let r = match next.kind {
            Solid::Torus { .. } => return None,
            Solid::Shell { inner } => {
                let hole = scale * inner;
                let ball_fits = self.region.ball_radius().is_some_and(|b| b < hole);
                if 2.0 * inner * inner * inner > 1.0 || ball_fits {
                    return None;
                }
                scale
            }
            k => k.support(scale),
        };
        Some(r + self.params.gap)
    }

    /// Places the next solid with the cell sampler: the same distribution of placements as
    /// [`SpaceEngine::step`], drawn only where it could fit (see [`SpaceCells`]). A halt
    /// with fewer trials than the limit is proven: no valid centre is left. On error nothing is
    /// placed and the engine may be stepped again.
    pub fn step_fast<R: RngCore + ?Sized>(&mut self, cells: &mut SpaceCells<'_>, rng: &mut R) -> Result<SpacePlacement<S>, StepError> {
        let next = self.next()?;
        let Some(need) = self.need(&next) else {
            return self.step(rng);
        };
        let need = cells.prepare(self, need);
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials || cells.weight == 0 {
                return Err(StepError::Halted { index: next.index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let Some((slot, units)) = cells.draw(rng) else { continue };
            let cell = cells.get(slot);
            let side = cells.side(cell.level);
            let point: [f64; 3] =
                core::array::from_fn(|a| (f64::from(cell.at.get(a).copied().unwrap_or(0)) + units.get(a).copied().unwrap_or(0.0)) * side);
            let slot = match cells.restructure(self, slot, units, need) {
                Drawn::Reject => continue,
                Drawn::Test(s) => s,
            };
            let c = V3::<S>::from_f64(point[0], point[1], point[2]);
            let inside = |v: S, a: usize| next.lo.get(a).is_some_and(|&l| v >= l) && next.hi.get(a).is_some_and(|&h| v <= h);
            if !(inside(c.x, 0) && inside(c.y, 1) && inside(c.z, 2)) {
                cells.note_reject(slot);
                continue;
            }
            // A point nearer than the need to a solid the cell knows cannot be valid (the
            // distance used is an upper bound): rejected without the index.
            let known = cells.get(slot).known;
            if known.iter().any(|&j| j != NIL && self.dist_up(j, point) + cells.slack < need) {
                cells.note_reject(slot);
                continue;
            }
            let q = if next.rotated {
                super::vec3::random_rotation(rng)
            } else {
                super::vec3::identity()
            };
            let body = super::body::Body::new(&next.kind, c, next.scale, &q);
            match self.fits_hit(&body, next.bound, true) {
                Ok(()) => {
                    let placed = self.place(&next, &body, q, trials);
                    cells.learn(self, slot, next.index as u32);
                    if cells.get(slot).u < need {
                        cells.retire(slot);
                    }
                    return Ok(placed);
                }
                Err(Some(j)) => {
                    cells.learn(self, slot, j);
                    cells.note_reject(slot);
                    if cells.get(slot).u < need {
                        cells.retire(slot);
                    }
                }
                Err(None) => cells.note_reject(slot),
            }
        }
    }

    /// [`SpaceEngine::run`] with the cell sampler ([`SpaceEngine::step_fast`]).
    pub fn run_fast<R: RngCore + ?Sized>(
        &mut self,
        cells: &mut SpaceCells<'_>,
        rng: &mut R,
        stop: &Stop,
        on_place: impl FnMut(&SpacePlacement<S>),
    ) -> StopReason {
        self.run_with(stop, on_place, |e| e.step_fast(cells, rng))
    }
}

/// The distance from `d` (the point less the torus's centre, `r = |d|`) to the smooth torus
/// held by the beads of a torus of major radius `s.scale`.
fn torus_dist<S: Scalar>(s: &PlacedSolid<S>, ratio: f64, beads: usize, d: [f64; 3], r: f64) -> f64 {
    let big = s.scale.to_f64();
    let q = s.rotation.map(|v| v.to_f64());
    let axis = columns::<f64>(&q)[2];
    let n2 = axis.norm2();
    let z = if n2 > 0.0 {
        (axis.x * d[0] + axis.y * d[1] + axis.z * d[2]) / libm::sqrt(n2)
    } else {
        0.0
    };
    let rho = libm::sqrt((r * r - z * z).max(0.0));
    let n = beads.max(1) as f64;
    let tube = ratio * big - 2.0 * big * libm::sin(core::f64::consts::PI / (2.0 * n));
    let dr = rho - big;
    libm::sqrt(dr * dr + z * z) - tube
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::space::body::Body;
    use crate::space::vec3::random_rotation;
    use crate::space::{space_index_words, SpaceParams, SpaceStorage};
    use std::vec;

    /// The live cells, by level and position.
    fn live_set(cells: &SpaceCells<'_>) -> std::collections::HashSet<(u8, [u32; 3])> {
        (0..cells.live()).map(|i| cells.get(i)).map(|c| (c.level, c.at)).collect()
    }

    /// Whether `p` lies in a live cell (on a face: either side counts).
    fn covered(cells: &SpaceCells<'_>, live: &std::collections::HashSet<(u8, [u32; 3])>, p: [f64; 3]) -> bool {
        (0..SPACE_CELL_LEVELS as u8).any(|k| {
            let s = cells.side(k);
            let lo = p.map(|v| libm::floor(v / s) as u32);
            let on = p.map(|v| libm::floor(v / s) == v / s);
            (0..8u32).any(|b| {
                let at: [u32; 3] = core::array::from_fn(|a| if on[a] && (b >> a) & 1 == 1 { lo[a].wrapping_sub(1) } else { lo[a] });
                live.contains(&(k, at))
            })
        })
    }

    /// The invariant the exactness argument rests on: before every placement's draws, every
    /// valid centre of the next solid (found by the engine's own exact test at random points
    /// with random rotations) lies in a live cell. Checked for every kind the sampler serves,
    /// in every region kind, with and without a gap, with the storage ample and scarce.
    #[test]
    fn every_valid_centre_lies_in_a_live_cell() {
        let kinds = [
            Solid::Sphere,
            Solid::Cube,
            Solid::Tetrahedron,
            Solid::Octahedron,
            Solid::Shell { inner: 0.6 },
        ];
        let regions = [
            SpaceRegion::Box {
                width: 30.0,
                height: 24.0,
                depth: 27.0,
                periodic: false,
            },
            SpaceRegion::Box {
                width: 30.0,
                height: 30.0,
                depth: 30.0,
                periodic: true,
            },
            SpaceRegion::Ball { radius: 15.0 },
            SpaceRegion::BoxMinusBall {
                width: 30.0,
                height: 30.0,
                depth: 30.0,
                centre: [15.0, 15.0, 15.0],
                radius: 6.0,
            },
        ];
        let mut checked = 0usize;
        for (ki, kind) in kinds.iter().enumerate() {
            for (ri, region) in regions.iter().enumerate() {
                for (gap, pool_len) in [(0.0, space_cells_for(60)), (0.4, 600)] {
                    let n = 60;
                    let mut solids = vec![PlacedSolid::<f64>::default(); n];
                    let mut index = vec![0u32; space_index_words(n)];
                    let mut pool = vec![SpaceCell::default(); pool_len];
                    let storage = SpaceStorage {
                        solids: &mut solids,
                        index: &mut index,
                    };
                    let params = SpaceParams {
                        solids: (*kind).into(),
                        rotate: true,
                        gap,
                        max_trials: 100_000,
                        ..SpaceParams::spheres(1.2, 6.0)
                    };
                    let mut e = SpaceEngine::new(params, *region, storage).unwrap();
                    let mut cells = SpaceCells::new(&mut pool).unwrap();
                    let mut rng = crate::rng_from_seed(100 + ki as u64 * 10 + ri as u64);
                    let mut probe = crate::rng_from_seed(7);
                    for _ in 0..n {
                        let next = e.next().unwrap();
                        cells.prepare(&e, e.need(&next).unwrap());
                        let live = live_set(&cells);
                        for _ in 0..800 {
                            let p: [f64; 3] = core::array::from_fn(|a| {
                                let (l, h) = (next.lo[a], next.hi[a]);
                                crate::rng::uniform(&mut probe, l, h)
                            });
                            let q = random_rotation(&mut probe);
                            let body = Body::new(&next.kind, V3::new(p[0], p[1], p[2]), next.scale, &q);
                            if e.fits(&body, next.bound) {
                                checked += 1;
                                assert!(
                                    covered(&cells, &live, p),
                                    "{kind:?} in {region:?}: valid centre {p:?} outside the live cells"
                                );
                            }
                        }
                        if e.step_fast(&mut cells, &mut rng).is_err() {
                            break;
                        }
                    }
                }
            }
        }
        assert!(checked > 10_000, "too few valid centres probed: {checked}");
    }

    /// The same check must fail when a cell is taken out wrongly: a sampler that drops its
    /// largest live cell loses valid centres.
    #[test]
    fn the_invariant_check_catches_a_dropped_cell() {
        let n = 10;
        let mut solids = vec![PlacedSolid::<f64>::default(); n];
        let mut index = vec![0u32; space_index_words(n)];
        let mut pool = vec![SpaceCell::default(); space_cells_for(n)];
        let region = SpaceRegion::Box {
            width: 30.0,
            height: 30.0,
            depth: 30.0,
            periodic: false,
        };
        let storage = SpaceStorage {
            solids: &mut solids,
            index: &mut index,
        };
        let mut e = SpaceEngine::new(SpaceParams::spheres(1.2, 6.0), region, storage).unwrap();
        let mut cells = SpaceCells::new(&mut pool).unwrap();
        let mut rng = crate::rng_from_seed(1);
        for _ in 0..n - 1 {
            e.step_fast(&mut cells, &mut rng).unwrap();
        }
        let next = e.next().unwrap();
        let mut probe = crate::rng_from_seed(8);
        let valid = (0..100_000)
            .map(|_| core::array::from_fn::<f64, 3, _>(|a| crate::rng::uniform(&mut probe, next.lo[a], next.hi[a])))
            .find(|p| {
                e.fits(
                    &Body::new(&next.kind, V3::new(p[0], p[1], p[2]), next.scale, &crate::space::vec3::identity()),
                    next.bound,
                )
            })
            .unwrap();
        assert!(covered(&cells, &live_set(&cells), valid));
        // Take out the live cell that holds it, as a wrong retirement would.
        let holder = (0..cells.live())
            .find(|&i| {
                let c = cells.get(i);
                let s = cells.side(c.level);
                (0..3).all(|a| valid[a] >= f64::from(c.at[a]) * s && valid[a] <= f64::from(c.at[a] + 1) * s)
            })
            .unwrap();
        let _ = cells.remove_live(holder);
        let live = live_set(&cells);
        // Unless a neighbour shares the face it lies on, the check now fails.
        assert!(
            !covered(&cells, &live, valid),
            "removing the cell that holds a valid centre went unnoticed"
        );
    }

    #[test]
    fn the_heap_wakes_cells_in_order_of_their_bound() {
        let mut pool = vec![SpaceCell::default(); 64];
        let mut cells = SpaceCells::new(&mut pool).unwrap();
        cells.side0 = 1.0;
        let bounds = [0.3, 0.9, 0.1, 0.7, 0.5, 0.8, 0.2];
        for (i, &u) in bounds.iter().enumerate() {
            let c = SpaceCell {
                at: [i as u32, 0, 0],
                u,
                ..SpaceCell::default()
            };
            cells.push_sleep(c);
        }
        cells.wake(0.6);
        assert_eq!(cells.live(), 3);
        assert_eq!(cells.asleep(), 4);
        let mut woken: std::vec::Vec<f64> = (0..cells.live()).map(|i| cells.get(i).u).collect();
        woken.sort_by(f64::total_cmp);
        assert_eq!(woken, [0.7, 0.8, 0.9]);
        let c = cells.remove_live(1);
        assert_eq!(cells.live(), 2);
        assert!(c.u >= 0.7);
        cells.wake(0.0);
        assert_eq!((cells.live(), cells.asleep()), (6, 0));
    }
}
