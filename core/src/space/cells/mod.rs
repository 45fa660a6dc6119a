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

mod build;
mod step;
#[cfg(test)]
mod tests;

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
/// use zetafill::rng_from_seed;
/// use zetafill::space::{cells_for, index_words, Cell, CellSampler, Placed};
/// use zetafill::{Stop, StopReason};
/// use zetafill::space::{Engine, Params, Region, Storage};
///
/// let mut solids = vec![Placed::<f64>::default(); 500];
/// let mut index = vec![0u32; index_words(500)];
/// let mut pool = vec![Cell::default(); cells_for(500)];
/// let region = Region::Box { width: 50.0, height: 50.0, depth: 50.0, periodic: false };
/// let storage = Storage { solids: &mut solids, index: &mut index };
/// let mut engine = Engine::new(Params::spheres(1.15, 2.0), region, storage)?;
/// let mut cells = CellSampler::new(&mut pool)?;
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
    fn draw<R: RngCore + ?Sized>(&self, rng: &mut R) -> Option<(usize, [f64; 3])> {
        let total = self.weight;
        if total == 0 {
            return None;
        }
        // Lemire's method: a uniform integer below `total` without bias.
        let mut r = crate::rng::below(rng, total);
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
    fn budget(&self, placed: usize) -> usize {
        SPACE_CELLS_BASE.saturating_add(SPACE_CELLS_PER_SOLID.saturating_mul(placed))
    }

    fn note_reject(&mut self, slot: usize) {
        if let Some(c) = self.pool.get_mut(slot) {
            c.rejects = c.rejects.saturating_add(1);
        }
    }
}
