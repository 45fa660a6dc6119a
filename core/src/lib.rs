//! # zetafill
//!
//! Random fractal space filling after Shier & Bourke's "statistical geometry": a region of
//! area `A` is filled with non-overlapping shapes whose areas follow the power law
//! `A_i = A / (zeta(c, N) (i + N)^c)`, `i = 0, 1, 2, ...`, where `zeta` is the Hurwitz zeta
//! function. Each shape is placed at a uniformly random position where it touches nothing.
//!
//! ## Layers
//! - [`scalar`]: the number type geometry is written over (the only caller of `libm`);
//! - [`fixed`](mod@fixed): [`Fixed`], the 32.32 fixed-point scalar for cores without an FPU;
//! - [`zeta`]: Hurwitz zeta, partial sums, and a build-time table;
//! - [`rng`]: the generator and the fixed mapping from random bits to numbers;
//! - [`geom`], [`shape`], [`region`]: concrete shapes and their exact clearance tests;
//! - [`spatial`]: the fixed-capacity multi-level spatial hash;
//! - [`engine`]: parameters, the placement step, stop conditions, statistics;
//! - [`sampler`]: the cell sampler, candidates only where the next shape could fit;
//! - [`line`](mod@line): the 1D fill (segments in an interval) over its own 1D multi-level hash;
//! - [`stats`]: the gasket width of the paper's Table 1, exact dimensions, power-law fits.
//!
//! ## Guarantees
//! - `no_std`, no allocator: the caller owns every buffer ([`engine::Engine::new`] borrows a
//!   shape slice and an index slice; see [`engine::index_words`]).
//! - No public function panics on any input: invalid input is an error value; running out of
//!   storage and halting are error values with everything placed so far intact.
//! - Determinism: the same seed and parameters give the same bits on every target (x86-64,
//!   Cortex-M). Floating-point maths goes only through IEEE basic operations and `libm`; no
//!   fused multiply-add, no intrinsics, no hash-map iteration order.
//! - Prefix stability: the first `k` shapes of a seed never depend on how many are asked for.
//!
//! ## Memory
//! A placed shape takes `size_of::<Placed<f64>>()` = 32 bytes plus 12 bytes of index
//! (one link and two buckets), 44 bytes in all with the recommended [`engine::index_words`].
//! The cell sampler ([`sampler`]) borrows a slice of 32-byte [`CellWords`] besides; circle fills
//! of c = 1.3 hold at most about 15 of them per placed shape.

#![no_std]
#![deny(missing_docs, unsafe_code)]
#![deny(clippy::unwrap_used, clippy::expect_used, clippy::panic, clippy::indexing_slicing)]
// Unit tests may index and panic: a failing test should.
#![cfg_attr(test, allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, clippy::indexing_slicing))]

pub mod coverage;
pub mod digest;
pub mod engine;
pub mod fixed;
pub mod geom;
pub mod line;
mod params;
pub mod region;
pub mod rng;
pub mod sampler;
pub mod scalar;
pub mod shape;
pub mod spatial;
pub mod stats;
pub mod zeta;

pub use self::fixed::Fixed;
pub use engine::{index_words, Engine, ParamError, Params, Placement, StepError, Stop, StopReason, Storage};
pub use geom::{Geo, Point};
pub use line::{line_index_words, Interval, LineEngine, LineParams, LinePlacement, LineStorage, Segment};
pub use region::{PolygonRegion, Region, RegionError};
pub use rng::{rng_from_seed, ZetaRng};
pub use sampler::{cells_for, CellSampler, CellStats, CellWords};
pub use scalar::Scalar;
pub use shape::{MixOrder, Placed, ShapeKind, ShapeList, MAX_MIX};
