//! # zetafill
//!
//! Random fractal space filling after Shier and Bourke ("An Algorithm for Random Fractal
//! Filling of Space"; Bourke, "A space filling algorithm for generating procedural geometry and
//! texture"): a region of area `A` is filled with non-overlapping shapes whose areas follow the
//! power law `A_i = A / (zeta(c, N) (i + N)^c)`, `i = 0, 1, 2, ...`, where `zeta` is the
//! Hurwitz zeta function ([`AreaSequence`]). Each shape is placed at a uniformly random
//! position where it touches nothing.
//!
//! ```
//! use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Region, Stop, StopReason, Storage};
//!
//! let mut shapes = [Placed::<f64>::default(); 100];
//! let mut index = [0u32; index_words(100)];
//! let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
//! let region = Region::Rect { width: 200.0, height: 200.0, periodic: false };
//! let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
//! let stop = Stop { count: Some(100), ..Stop::default() };
//! let reason = engine.run(&mut rng_from_seed(1), &stop, |p| {
//!     let _ = (p.index, p.shape.x, p.shape.y, p.area, p.trials); // draw it here
//! });
//! assert_eq!(reason, StopReason::Count);
//! assert_eq!(engine.placed().len(), 100);
//! # Ok::<(), zetafill::ParamError>(())
//! ```
//!
//! ## The public names
//! Each has an example in its documentation (or in the one it links to).
//! - A fill: [`Engine`] over caller-owned [`Storage`] (sized with [`index_words`]), set up by
//!   [`Params`] and a [`Region`] ([`PolygonRegion`] for outlines, [`RegionError`]), with shapes
//!   from [`ShapeKind`] / [`ShapeList`] (mixes of up to [`MAX_MIX`] kinds, [`MixOrder`]); each
//!   step gives a [`Placement`] of a [`Placed`] shape, whose exact outline is a [`Geo`] of
//!   [`Point`]s (a polygon's in [`Verts`]).
//! - Stopping and failing: [`Stop`], [`StopReason`], [`StepError`], [`ParamError`], [`Stats`].
//! - Symmetric fills: [`Region::Wallpaper`] over a [`Wallpaper`] (one of the 17 [`Group`]s on
//!   its [`LatticeKind`] of lattice; [`WallpaperError`]), whose first shape
//!   [`check_first_orbit`] checks up front ([`FirstOrbitError`]); each placement stores its
//!   orbit's [`Engine::images`].
//! - Samplers: the paper's uniform sampler is [`Engine::step`]; the cell sampler
//!   [`CellSampler`] (storage [`CellWords`], sized with [`cells_for`]; [`NoCells`] when there
//!   is none) draws from exactly the same distribution with far fewer trials
//!   ([`Engine::step_fast`]).
//! - Before a fill: [`AreaSequence`] (the areas, zeta computed once; [`ZetaError`]),
//!   [`shape_capacity`] (the slots a stop condition needs, or a
//!   [`CapacityError`]), [`check_first_two`] and [`first_shape`] (first shapes that cannot
//!   fit, with the largest c that works: [`FirstTwoError`], [`FirstShape`]), [`check_smallest`]
//!   (last shapes narrower than the scalar resolves, [`TooSmall`]) and [`check_largest`]
//!   (first shapes wider than it computes exactly, [`TooLarge`]).
//! - 1D and 3D: the modules [`line`](mod@line) and [`space`](mod@space) hold the same names for an interval and a
//!   volume: `Params`, `Engine`, `Storage` (sized with `index_words`), `Placement`, the
//!   regions [`line::Interval`] and [`space::Region`], `capacity`, and each one's exact
//!   sampler ([`line::Gaps`], the free gaps; [`space::CellSampler`], the octree of cells).
//! - Numbers and randomness: [`Scalar`] (`f64`, or [`Fixed`] for cores without an FPU),
//!   [`rng_from_seed`] / [`ZetaRng`], and [`digest`] (the determinism digest).
//!
//! Everything else is under [`internals`]: not a stable API, there for zetafill's own crates
//! (the command-line tool, the display and firmware crates, the tests and benchmarks).
//!
//! ## Layers
//! - scalars: the number type geometry is written over (the only caller of `libm`), and the
//!   32.32 fixed-point scalar;
//! - zeta: Hurwitz zeta, partial sums, and a build-time table;
//! - the generator and the fixed mapping from random bits to numbers;
//! - geometry, shapes and regions, with exact clearance tests;
//! - the fixed-capacity multi-level spatial hash and the coverage bitmap;
//! - the engine (the paper's loop, then its optimisations) and the cell sampler;
//! - the 1D fill over its own 1D multi-level hash, and its exact sampler over the free gaps;
//! - the 3D fill (solids, regions, exact tests, its 3D multi-level hash; the paper's sampler
//!   and the octree cell sampler);
//! - statistics: the gasket width of the paper's Table 1, exact dimensions, power-law fits;
//!   and the up-front checks ([`AreaSequence`], capacity, first-shape feasibility).
//!
//! ## Determinism contract
//! - The same seed and parameters give the same bits on every target (x86-64, Cortex-M), for
//!   each scalar. Floating-point maths goes only through IEEE basic operations and `libm`; no
//!   fused multiply-add, no intrinsics, no hash-map iteration order. The generator
//!   (xoshiro256++) and the mapping of its bits to coordinates and angles are fixed.
//! - Prefix stability: the first `k` shapes of a seed never depend on how many are asked for.
//! - The storage lent never changes a result, as long as it is large enough; nor does the
//!   coverage bitmap.
//! - Changing any produced value is a version-level event; [`digest`] pins them.
//!
//! ## Guarantees
//! - `no_std`, no allocator: the caller owns every buffer ([`Engine::new`] borrows a shape
//!   slice and an index slice; see [`index_words`]).
//! - No public function panics on any input: invalid input is an error value; running out of
//!   storage and halting are error values with everything placed so far intact.
//! - What a scalar cannot compute exactly is refused: a region beyond
//!   [`Scalar::MAX_EXTENT`] ([`ParamError::Extent`]), a shape wider than it (on a torus,
//!   [`StepError::TooLarge`]) and a shape narrower than [`Scalar::MIN_SIZE`]
//!   ([`StepError::TooSmall`]) are limits of [`Fixed`]; on `f64` a shape narrower than
//!   [`Scalar::MIN_SIZE_RELATIVE`] (2^-40) of the region's largest coordinate is refused
//!   ([`StepError::TooSmall`]): its outline would round to zero area.
//! - With the `defmt` feature, the error types and key types derive `defmt::Format`.
//!
//! ## Memory
//! A placed shape takes `size_of::<Placed<f64>>()` = 32 bytes plus 12 bytes of index
//! (one link and two buckets), 44 bytes in all with the recommended [`index_words`].
//! The cell sampler borrows a slice of 32-byte [`CellWords`] besides; circle fills of c = 1.3
//! hold at most about 15 of them per placed shape. The 3D cell sampler borrows 40-byte [`space::Cell`]s: at most
//! 64 per placed solid over a start of 16,384 ([`space::cells_for`]); sphere fills of c = 1.15
//! reach that budget from about 30,000 solids on (2 to 3 KB per solid). A polygon region's edge tree borrows 24
//! bytes a vertex ([`PolygonRegion::scratch_words`]), or nothing ([`PolygonRegion::new`]).
//! A segment takes 16 bytes plus 12 of index ([`line::index_words`]); the exact 1D sampler
//! adds 41 bytes per segment: a little over five 8-byte [`line::Gap`] words ([`line::gaps_for`]).

#![no_std]
#![deny(missing_docs, unsafe_code)]
#![deny(clippy::unwrap_used, clippy::expect_used, clippy::panic, clippy::indexing_slicing)]
// Unit tests may index and panic: a failing test should.
#![cfg_attr(test, allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, clippy::indexing_slicing))]

/// Counts of the engine's work, for benchmarks (the `counters` feature).
pub mod counters;
mod coverage;
pub mod digest;
mod engine;
mod feasibility;
mod fixed;
mod geom;
#[path = "line/mod.rs"]
mod line1d;
mod noise;
mod params;
mod region;
mod rng;
mod sampler;
mod scalar;
mod shape;
#[path = "space/mod.rs"]
mod space3d;
mod spatial;
mod stats;
mod zeta;

pub use self::fixed::Fixed;
pub use engine::{index_words, Batches, Density, Engine, Lane, NoLanes, Placement, Plan, Stats, Storage, DEFAULT_BATCH, LANE_EVENTS};
pub use feasibility::{
    check_first_orbit, check_first_two, check_largest, check_smallest, first_shape, shape_capacity, AreaSequence, CapacityError,
    FirstOrbitError, FirstShape, FirstTwoError, TooLarge, TooSmall,
};
pub use geom::{Geo, Point, Verts};
pub use noise::{Noise, NoiseError, NoiseKind, MAX_OCTAVES};
pub use params::{ParamError, Params, StepError, Stop, StopReason};
pub use region::{Group, LatticeKind, PolygonRegion, Region, RegionError, Wallpaper, WallpaperError};
pub use rng::{rng_from_seed, ZetaRng};
pub use sampler::{cells_for, CellSampler, CellWords, NoCells};
pub use scalar::Scalar;
pub use shape::{Frame, MixOrder, Motif, MotifError, Placed, ShapeKind, ShapeList, COVER_DISCS, MAX_MIX, MAX_MOTIF_VERTICES};
pub use zeta::ZetaError;

/// The 1D fill: segments on an interval whose lengths follow the power law, placed by the
/// paper's loop or by the exact sampler over the free gaps. The same names as the 2D fill at
/// the crate root, for a line.
///
/// ```
/// use zetafill::line::{index_words, Engine, Interval, Params, Segment, Storage};
/// use zetafill::{rng_from_seed, Stop, StopReason};
///
/// let mut segments = [Segment::<f64>::default(); 100];
/// let mut index = [0u32; index_words(100)];
/// let storage = Storage { segments: &mut segments, index: &mut index };
/// let mut engine = Engine::new(Params::new(1.3, 1.0), Interval { length: 200.0, periodic: false }, storage)?;
/// let stop = Stop { count: Some(100), ..Stop::default() };
/// assert_eq!(engine.run(&mut rng_from_seed(1), &stop, |_| {}), StopReason::Count);
/// assert_eq!(engine.placed().len(), 100);
/// # Ok::<(), zetafill::ParamError>(())
/// ```
pub mod line {
    pub use crate::feasibility::segment_capacity as capacity;
    pub use crate::line1d::{
        line_gaps_for as gaps_for, line_index_words as index_words, Interval, LineEngine as Engine, LineGap as Gap, LineGaps as Gaps,
        LineParams as Params, LinePlacement as Placement, LineStorage as Storage, NoLineGaps as NoGaps, Segment,
    };
}

/// The 3D fill: solids in a box or a ball whose volumes follow the power law, placed by the
/// paper's loop or by the octree cell sampler. The same names as the 2D fill at the crate
/// root, for a volume.
///
/// ```
/// use zetafill::space::{index_words, Engine, Params, Placed, Region, Storage};
/// use zetafill::{rng_from_seed, Stop, StopReason};
///
/// let mut solids = [Placed::<f64>::default(); 50];
/// let mut index = [0u32; index_words(50)];
/// let storage = Storage { solids: &mut solids, index: &mut index };
/// let region = Region::Box { width: 100.0, height: 100.0, depth: 100.0, periodic: false };
/// let mut engine = Engine::new(Params::spheres(1.2, 2.0), region, storage)?;
/// let stop = Stop { count: Some(50), ..Stop::default() };
/// assert_eq!(engine.run(&mut rng_from_seed(1), &stop, |_| {}), StopReason::Count);
/// # Ok::<(), zetafill::ParamError>(())
/// ```
pub mod space {
    pub use crate::space3d::{
        check_first_solid as check_first, check_first_two_solids as check_first_two, space_capacity as capacity,
        space_cells_for as cells_for, space_index_words as index_words, FirstSolidError as FirstError,
        FirstTwoSolidsError as FirstTwoError, NoSpaceCells as NoCells, PlacedSolid as Placed, Solid, SolidList, SpaceCell as Cell,
        SpaceCells as CellSampler, SpaceEngine as Engine, SpaceParams as Params, SpacePlacement as Placement, SpaceRegion as Region,
        SpaceStorage as Storage,
    };
}

/// The building blocks under the public API, for zetafill's own crates (the command-line
/// tool, the display and firmware crates, the tests and benchmarks).
///
/// **Not a stable API**: anything here may change or go in any release. A library user needs
/// only the names at the crate root.
pub mod internals {
    /// The coverage bitmap that speeds up the reference sampler's rejections.
    pub mod coverage {
        pub use crate::coverage::*;
    }
    /// The 32.32 fixed-point scalar.
    pub mod fixed {
        pub use crate::fixed::*;
    }
    /// Points, concrete outlines and exact separation tests.
    pub mod geom {
        pub use crate::geom::*;
    }
    /// The 1D fill and its digest.
    pub mod line {
        pub use crate::line1d::*;
    }
    /// Regions and their clearance tests.
    pub mod region {
        pub use crate::region::*;
    }
    /// The generator and the fixed mapping from random bits to numbers.
    pub mod rng {
        pub use crate::rng::*;
    }
    /// The cell sampler's constants and its counters ([`CellStats`](crate::internals::sampler::CellStats)).
    pub mod sampler {
        pub use crate::sampler::*;
    }
    /// The scalar trait and the libm functions it is written over.
    pub mod scalar {
        pub use crate::scalar::*;
    }
    /// Shape kinds, mixes and their geometry.
    pub mod shape {
        pub use crate::shape::*;
    }
    /// The up-front checks' building blocks: the capacity search for any width function, and
    /// the first-two-shapes test for given areas.
    pub mod feasibility {
        pub use crate::feasibility::{capacity, first_two_fit};
    }
    /// The 3D fill's building blocks: points and rotations, solids in place and their exact
    /// tests, the 3D hash's constants.
    pub mod space {
        pub use crate::space3d::*;
    }
    /// The fixed-capacity multi-level spatial hash.
    pub mod spatial {
        pub use crate::spatial::*;
    }
    /// The gasket width of the paper's Table 1, exact dimensions, power-law fits.
    pub mod stats {
        pub use crate::stats::*;
    }
    /// Hurwitz zeta, partial sums and the build-time table.
    pub mod zeta {
        pub use crate::zeta::*;
    }
}
