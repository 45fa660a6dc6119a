//! The placement engine: the algorithm of Shier and Bourke ("An Algorithm for Random Fractal
//! Filling of Space", section 2) over caller-owned storage.
//!
//! Shape `i` has area `A_i = A / (zeta(c, N) (i + N)^c)` (`AreaSequence`). The
//! paper's loop is [`Engine::step`]: draw a candidate (an angle if the shape is rotated, then a
//! centre uniform over the positions where the shape lies inside the region's box), test it,
//! and place the shape at the first candidate that keeps more than `gap` from every placed
//! shape (and its periodic images) and at least `gap` from the boundary. One step places one
//! shape and reports how many trials it took, so a display can draw as the fill grows.
//!
//! The rest of this module only makes that loop fast without changing a single accepted
//! placement:
//! - `clearance`: the exact tests, through the spatial hash, with shortcuts (two circles,
//!   inscribed discs that meet) whose answer never differs from the full test;
//! - `fit`: what stays fixed over a placement's trials, and the shapes that certainly
//!   cannot fit;
//! - `cells`: the engine as the cell sampler sees it ([`crate::CellSampler`],
//!   [`Engine::step_fast`]): same distribution of accepted placements, far fewer trials.
//!
//! With a density ([`Engine::set_density`]) both samplers keep each candidate with
//! probability `rho(centre)` before testing it (one more unit value from the generator, drawn
//! only when there is a density), so the accepted centre is drawn with probability
//! proportional to `rho` over the valid centres: see [`Density`].
//!
//! The reference sampler may also consult a coverage bitmap (`coverage`)
//! that rejects candidates whose centre is certainly inside a placed shape; it never rejects a
//! valid one.
//!
//! Guarantees: same seed and parameters, same bits, on every target; the first `k` shapes
//! never depend on how many are asked for later (each step uses only the RNG stream and the
//! shapes before it); running out of storage, halting at the trial limit, and a first shape
//! that cannot fit are error values, never panics.

mod batch;
mod build;
mod cells;
mod clearance;
mod density;
mod fit;
mod orbit;

use crate::coverage::Coverage;
use crate::geom::{Geo, Point};
pub use crate::params::{ParamError, Params, StepError, Stop, StopReason};
use crate::region::Region;
use crate::rng;
use crate::scalar::Scalar;
use crate::shape::{Motif, Placed, ShapeKind};
use crate::spatial::SpatialHash;
use crate::AreaSequence;
pub use batch::{Batches, Lane, NoLanes, Plan, DEFAULT_BATCH, LANE_EVENTS};
pub use density::Density;
use density::{kept_at, Thinning};
use fit::NextShape;
use rand_core::RngCore;

/// One placement: the shape, its nominal area and the trials it took. [`Engine::step`]
/// returns it, and [`Engine::run`] hands each one to its callback.
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Placement, Region, Stop, Storage};
///
/// let mut shapes = [Placed::<f64>::default(); 40];
/// let mut index = [0u32; index_words(40)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
/// let mut seen: Vec<Placement<f64>> = Vec::new();
/// engine.run(&mut rng_from_seed(3), &Stop { count: Some(40), ..Stop::default() }, |p| seen.push(*p));
/// // In placement order, each with the area of the power law and the trials it took.
/// for (i, p) in seen.iter().enumerate() {
///     assert_eq!(p.index, i as u64);
///     assert_eq!(p.area, engine.area_of(p.index));
///     assert_eq!(p.shape, engine.placed()[i]);
/// }
/// assert_eq!(seen.iter().map(|p| p.trials).sum::<u64>(), engine.stats().trials);
/// # Ok::<(), zetafill::ParamError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement<S> {
    /// Placement index i (0 for the largest shape).
    pub index: u64,
    /// The shape as stored.
    pub shape: Placed<S>,
    /// A_i.
    pub area: f64,
    /// Trials spent on this placement (>= 1).
    pub trials: u64,
}

/// Statistics of a fill so far ([`Engine::stats`]).
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Region, Stats, Stop, Storage};
///
/// let mut shapes = [Placed::<f64>::default(); 100];
/// let mut index = [0u32; index_words(100)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Circle { radius: 50.0 };
/// let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
/// assert_eq!(engine.stats().trials_per_placement(), 0.0);
/// engine.run(&mut rng_from_seed(5), &Stop { count: Some(100), ..Stop::default() }, |_| {});
/// let Stats { placed, trials, fill_fraction } = engine.stats();
/// assert_eq!(placed, 100);
/// assert!(trials >= 100);
/// assert_eq!(engine.stats().trials_per_placement(), trials as f64 / 100.0);
/// // The nominal areas placed, over the region's area.
/// let sum: f64 = (0..100).map(|i| engine.area_of(i)).sum();
/// assert!((fill_fraction - sum / engine.total_area()).abs() < 1e-12);
/// # Ok::<(), zetafill::ParamError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Stats {
    /// Shapes placed.
    pub placed: u64,
    /// Trials made in all (including those of a halted placement).
    pub trials: u64,
    /// Sum of placed nominal areas over the region's area.
    pub fill_fraction: f64,
}

impl Stats {
    /// Average trials per placement (0 when nothing is placed).
    pub fn trials_per_placement(&self) -> f64 {
        if self.placed == 0 {
            0.0
        } else {
            self.trials as f64 / self.placed as f64
        }
    }
}

/// The fill engine over caller-provided storage: [`Engine::new`] checks the [`Params`] and
/// the [`Region`] once, then each [`Engine::step`] places the next shape (a [`Placement`]) and
/// [`Engine::run`] steps until a [`Stop`] condition holds. [`Engine::step_fast`] and
/// [`Engine::run_fast`] do the same with the cell sampler ([`crate::CellSampler`]).
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Region, StepError, Storage};
///
/// // Room for 20 shapes, owned by the caller.
/// let mut shapes = [Placed::<f64>::default(); 20];
/// let mut index = [0u32; index_words(20)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
/// let mut rng = rng_from_seed(7);
/// for i in 0..20 {
///     let p = engine.step(&mut rng)?;
///     assert_eq!(p.index, i);
///     // A circle's scale is its radius; it lies inside the region.
///     let r = p.shape.scale;
///     assert!(p.shape.x >= r && p.shape.x <= 100.0 - r && p.shape.y >= r && p.shape.y <= 100.0 - r);
/// }
/// // Every slot is used: the next step is an error, and the fill is intact.
/// assert_eq!(engine.step(&mut rng), Err(StepError::Capacity { capacity: 20 }));
/// assert_eq!(engine.placed().len(), 20);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Engine<'a, S: Scalar> {
    params: Params,
    region: Region<'a>,
    shapes: &'a mut [Placed<S>],
    len: usize,
    hash: SpatialHash<'a, S>,
    coverage: Coverage<'a, S>,
    /// The areas `A_i`, over the region's area.
    seq: AreaSequence,
    placed_area: f64,
    trials: u64,
    gap: S,
    period: (S, S),
    /// The narrowest shape the scalar resolves in this region ([`crate::Region::magnitude`]).
    min_size: f64,
    /// Where centres are wanted, when not uniformly.
    density: Option<Thinning<'a>>,
    /// Entries stored per placement: the images of an orbit on a wallpaper torus, else 1
    /// (never 0: a division by it cannot fail).
    images: core::num::NonZeroU32,
    /// The x of the torus's second lattice vector (0 for a rectangle's).
    shear: S,
    /// The motifs the shape kinds name ([`Engine::with_motifs`]).
    motifs: &'a [Motif<'a>],
}

/// Index words needed for `capacity` shapes: one link each plus at least `2 * capacity`
/// buckets, a power of two of them (the length of [`Storage::index`]; the hash uses the
/// largest power of two of buckets the index holds, so a length of `3 * capacity` would leave
/// up to half its buckets unused).
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Region, Stop, Storage};
///
/// assert_eq!(index_words(1000), 1000 + 2048);
/// // Any index longer than the shape slots works: fewer buckets only make queries slower.
/// let fill = |index: &mut [u32]| {
///     let mut shapes = [Placed::<f64>::default(); 50];
///     let storage = Storage { shapes: &mut shapes, index, coverage: &mut [] };
///     let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
///     let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage).expect("valid");
///     engine.run(&mut rng_from_seed(9), &Stop { count: Some(50), ..Stop::default() }, |_| {});
///     engine.placed().to_vec()
/// };
/// assert_eq!(fill(&mut [0; index_words(50)]), fill(&mut [0; 51]));
/// ```
pub const fn index_words(capacity: usize) -> usize {
    let buckets = match capacity.saturating_mul(2).checked_next_power_of_two() {
        Some(b) => b,
        None => usize::MAX,
    };
    capacity.saturating_add(buckets)
}

/// The caller-owned storage of an engine: a static array on a microcontroller, a `Vec` on a
/// host. The storage never changes a result, as long as it is large enough.
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, ParamError, Params, Placed, Region, Stop, Storage};
///
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let fill = |coverage: &mut [u64]| {
///     let mut shapes = vec![Placed::<f64>::default(); 200];
///     let mut index = vec![0u32; index_words(200)];
///     let storage = Storage { shapes: &mut shapes, index: &mut index, coverage };
///     let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
///     engine.run(&mut rng_from_seed(2), &Stop { count: Some(200), ..Stop::default() }, |_| {});
///     Ok::<_, ParamError>(engine.placed().to_vec())
/// };
/// // The coverage bitmap speeds up rejections and changes nothing else.
/// assert_eq!(fill(&mut [0u64; 4096])?, fill(&mut [])?);
///
/// // An index no longer than the shape slots is refused.
/// let (mut shapes, mut index) = ([Placed::<f64>::default(); 8], [0u32; 8]);
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// assert_eq!(Engine::new(Params::circles(1.3, 1.0), region, storage).err(), Some(ParamError::Storage));
/// # Ok::<(), ParamError>(())
/// ```
#[derive(Debug)]
pub struct Storage<'a, S> {
    /// One slot per shape: its length is the capacity.
    pub shapes: &'a mut [Placed<S>],
    /// The spatial hash: longer than `shapes` ([`index_words`] recommends the size; any
    /// number of buckets works, fewer only make queries slower).
    pub index: &'a mut [u32],
    /// The coverage bitmap (see [`crate::internals::coverage`]); may be empty. It speeds up rejections
    /// and never changes a result.
    pub coverage: &'a mut [u64],
}

impl<'a, S: Scalar> Engine<'a, S> {
    /// Draws centres with probability proportional to `density` over the valid ones from the
    /// next step on (`None`: uniformly, the paper's rule). See [`Density`].
    pub fn set_density(&mut self, density: Option<&'a dyn Density>) {
        self.density = density.map(Thinning);
    }

    /// Whether a candidate centre survives the density's thinning (always, without one; the
    /// unit value is drawn only with one). The candidate was drawn where the density is at
    /// most `2^-class`, with a weight to match, so it is kept with probability `rho 2^class`.
    fn kept<R: RngCore + ?Sized>(&self, c: Point<S>, class: u32, rng: &mut R) -> bool {
        let Some(Thinning(d)) = self.density else { return true };
        kept_at(d, c.x.to_f64(), c.y.to_f64(), class, rng::unit(rng))
    }

    /// The motifs the shape kinds name.
    pub fn motifs(&self) -> &'a [Motif<'a>] {
        self.motifs
    }

    /// The parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// The region.
    pub fn region(&self) -> &Region<'a> {
        &self.region
    }

    /// zeta(c, N) used for the area sequence.
    pub fn zeta(&self) -> f64 {
        self.seq.zeta()
    }

    /// The region's area A.
    pub fn total_area(&self) -> f64 {
        self.seq.total()
    }

    /// A_i = A / (zeta(c, N) (i + N)^c).
    pub fn area_of(&self, i: u64) -> f64 {
        self.seq.area(i)
    }

    /// The shape kind of placement `i`.
    #[inline]
    pub fn kind_of(&self, i: u64) -> ShapeKind {
        self.params.shape.kind_of(i)
    }

    /// The shapes placed so far, in placement order. On a wallpaper torus
    /// ([`Region::Wallpaper`]) each placement is its orbit's [`Engine::images`] entries in a
    /// row: the shape, then its images under the group's operations, each at its centre in
    /// the fundamental domain.
    pub fn placed(&self) -> &[Placed<S>] {
        self.shapes.get(..self.len).unwrap_or(&[])
    }

    /// Entries of [`Engine::placed`] per placement: the group's order on a wallpaper torus,
    /// otherwise 1.
    pub fn images(&self) -> usize {
        self.images.get() as usize
    }

    /// The concrete geometry of entry `i` of [`Engine::placed`]: exactly what was tested, and
    /// what to draw (on a wallpaper torus, the image the entry holds).
    pub fn geo(&self, i: usize) -> Option<Geo<'a, S>> {
        let p = self.placed().get(i)?;
        let mut g = Geo::Circle {
            c: Point::new(p.x, p.y),
            r: p.scale,
        };
        self.entry_geo_into(i as u32, p, S::ZERO, S::ZERO, &mut g);
        Some(g)
    }

    /// Statistics so far.
    pub fn stats(&self) -> Stats {
        Stats {
            placed: self.orbits() as u64,
            trials: self.trials,
            fill_fraction: self.placed_area / self.seq.total(),
        }
    }

    /// Fraction of the region's bounding box marked in the coverage bitmap (0 without one).
    pub fn coverage_fraction(&self) -> f64 {
        self.coverage.marked_fraction()
    }

    /// The storage capacity in shapes.
    pub fn capacity(&self) -> usize {
        self.shapes.len()
    }

    // The paper's loop.

    /// Places the next shape, drawing candidates from `rng` until one fits or the trial limit
    /// is reached. On error nothing is placed and the engine may be stepped again.
    pub fn step<R: RngCore + ?Sized>(&mut self, rng: &mut R) -> Result<Placement<S>, StepError> {
        let next = self.next_shape()?;
        self.step_reference(&next, rng)
    }

    /// The paper's sampler: candidates uniform over the whole centre range.
    fn step_reference<R: RngCore + ?Sized>(&mut self, next: &NextShape<S>, rng: &mut R) -> Result<Placement<S>, StepError> {
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials {
                return Err(StepError::Halted { index: next.index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let angle = if next.rotated { rng::angle::<S, R>(rng) } else { S::ZERO };
            let ux: S = rng::unit(rng);
            let uy: S = rng::unit(rng);
            let (x0, x1, y0, y1) = next.range;
            let c = self.region.wrap(Point::new(x0 + ux * (x1 - x0), y0 + uy * (y1 - y0)));
            if self.coverage.covered(c.x, c.y) || !self.kept(c, 0, rng) {
                continue;
            }
            if let Ok(p) = self.try_at(next, c, angle, trials, None) {
                return Ok(p);
            }
        }
    }

    /// Runs the exact tests on a candidate centre and angle, and places the shape there if it
    /// passes. On failure, names the placed shape the candidate hit when that was the reason.
    /// The cell sampler passes `known`, the shapes its cell knows of: they are tested first, and
    /// the shape named on failure does not depend on the hash table's size.
    #[inline(always)]
    fn try_at(
        &mut self,
        next: &NextShape<S>,
        c: Point<S>,
        angle: S,
        trials: u64,
        known: Option<&[u32]>,
    ) -> Result<Placement<S>, Option<u32>> {
        let mut g = Geo::Circle { c, r: next.base_r };
        let shape = self.check_into(next, c, angle, known, &mut g)?;
        Ok(self.place(next, shape, &g, trials, known.is_none()))
    }

    /// The exact tests of [`Engine::try_at`], without placing: the shape as it would be stored
    /// (its outline left in `g`), or the placed shape the candidate hit when that was the
    /// reason it fails.
    #[inline(always)]
    fn check_into(
        &self,
        next: &NextShape<S>,
        c: Point<S>,
        angle: S,
        known: Option<&[u32]>,
        g: &mut Geo<'a, S>,
    ) -> Result<Placed<S>, Option<u32>> {
        let kind = next.kind;
        // A circle against known circles needs no geometry: most of the cell sampler's
        // rejections end here.
        if kind == ShapeKind::Circle {
            if let Some(&j) = known.unwrap_or(&[]).iter().find(|&&j| self.circles_meet(c, next.base_r, j)) {
                return Err(Some(j));
            }
        }
        let (scale, r, solid) = if next.is_blob {
            let s: S = kind.scale_for(next.area, angle);
            kind.geo_into_in(self.motifs, g, c, s, angle);
            (s, kind.bounding_radius(s), kind.solid_radius(s))
        } else {
            let (sin, cos) = if next.rotated {
                ShapeKind::sin_cos(angle)
            } else {
                (S::ZERO, S::ONE)
            };
            kind.geo_sc_into_in(self.motifs, g, c, next.base_scale, sin, cos);
            (next.base_scale, next.base_r, next.base_solid)
        };
        // (Known circles were tested above for a circle.)
        let tested = |j: u32| kind == ShapeKind::Circle && self.entry_kind(j) == ShapeKind::Circle;
        let mut other = Geo::Circle { c, r };
        if let Some(&j) = known
            .unwrap_or(&[])
            .iter()
            .find(|&&j| !tested(j) && self.hits(g, c, (r, solid), j, &mut other))
        {
            return Err(Some(j));
        }
        if !self.region.contains(g, self.gap) {
            return Err(None);
        }
        if self.region.wallpaper().is_some() {
            if let Some(j) = self.blocker(g, c.x, c.y, (r, solid), known.is_some()) {
                return Err(Some(j));
            }
            if let Some(hit) = self.orbit_refuses(g, c, (r, solid), known.is_some()) {
                return Err(hit);
            }
        } else {
            if self.region.periodic() && self.self_overlaps(g, r) {
                return Err(None);
            }
            if let Some(j) = self.blocker(g, c.x, c.y, (r, solid), known.is_some()) {
                return Err(Some(j));
            }
        }
        Ok(Placed {
            x: c.x,
            y: c.y,
            scale,
            angle,
        })
    }

    /// Places `shape` (outline `g`), which passed the exact tests, as the next shape; `mark`
    /// marks it in the coverage bitmap too (the paper's sampler asks that bitmap, the cell
    /// sampler never does: a bitmap that misses shapes only rejects fewer candidates, never a
    /// valid one).
    fn place(&mut self, next: &NextShape<S>, shape: Placed<S>, g: &Geo<S>, trials: u64, mark: bool) -> Placement<S> {
        let kind = next.kind;
        let r = if next.is_blob {
            kind.bounding_radius(shape.scale)
        } else {
            next.base_r
        };
        let i = self.len;
        if let Some(slot) = self.shapes.get_mut(i) {
            *slot = shape;
        }
        let c = Point::new(shape.x, shape.y);
        self.hash.insert(i as u32, c.x, c.y, r);
        if mark {
            let period = if self.region.periodic() { Some(self.period) } else { None };
            self.coverage.mark(g, c, kind.inradius(shape.scale), period);
        }
        self.len += 1;
        // The orbit's other images, each at its centre in the domain.
        if let Some(w) = self.region.wallpaper() {
            for k in 1..w.order() {
                let q = w.image_centre(k, c);
                let j = self.len;
                if let Some(slot) = self.shapes.get_mut(j) {
                    *slot = Placed { x: q.x, y: q.y, ..shape };
                }
                self.hash.insert(j as u32, q.x, q.y, r);
                self.len += 1;
            }
        }
        self.placed_area += next.area;
        Placement {
            index: next.index,
            shape,
            area: next.area,
            trials,
        }
    }

    /// Steps until a stop condition holds or a step fails, calling `on_place` after each
    /// placement.
    pub fn run<R: RngCore + ?Sized>(&mut self, rng: &mut R, stop: &Stop, on_place: impl FnMut(&Placement<S>)) -> StopReason {
        self.run_with(stop, on_place, |e| e.step(rng))
    }

    /// The stop condition that holds before the next placement, if any.
    fn stops(&self, stop: &Stop) -> Option<StopReason> {
        let n = self.orbits() as u64;
        stop.holds(n, self.placed_area, self.seq.total(), || {
            let kind = self.kind_of(n);
            kind.min_width(kind.scale_for_area(self.area_of(n)))
        })
    }

    fn run_with(
        &mut self,
        stop: &Stop,
        on_place: impl FnMut(&Placement<S>),
        step: impl FnMut(&mut Self) -> Result<Placement<S>, StepError>,
    ) -> StopReason {
        crate::params::run_until(self, |e| e.stops(stop), on_place, step)
    }
}
