//! The parameters of a fill and the error values of the engines: [`Params`] (validated once
//! by [`crate::Engine::new`]), the stop conditions [`Stop`], and why a fill stopped
//! ([`StopReason`], [`StepError`]) or could not start ([`ParamError`]).
//!
//! Plain data: nothing here allocates, panics or depends on the target.

use crate::shape::{ShapeKind, ShapeList};

/// The parameters of a fill.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Params {
    /// The power-law exponent c (> 1).
    pub c: f64,
    /// The offset N of the paper (> 0, need not be an integer).
    pub n_offset: f64,
    /// The shape placed, or a mix of shapes.
    pub shape: ShapeList,
    /// Random rotation (ignored for circles).
    pub rotate: bool,
    /// Minimum clearance between shapes and to the boundary (>= 0).
    pub gap: f64,
    /// Trial limit per placement (>= 1): reaching it halts the fill.
    pub max_trials: u64,
}

impl Params {
    /// Circles with the given exponent and offset, no gap, the default trial limit.
    pub fn circles(c: f64, n_offset: f64) -> Self {
        Params {
            c,
            n_offset,
            shape: ShapeKind::Circle.into(),
            rotate: false,
            gap: 0.0,
            max_trials: 10_000_000,
        }
    }

    /// c for a fractal dimension D in 2D (c = 2 / D).
    pub fn c_from_dimension(d: f64) -> f64 {
        2.0 / d
    }
}

/// What was wrong with the parameters, region or storage.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ParamError {
    /// c must be finite and > 1.
    Exponent,
    /// N must be finite and > 0.
    Offset,
    /// The zeta function overflows for this (c, N).
    Zeta,
    /// A shape proportion is out of range (see [`ShapeKind::is_valid`]).
    Shape,
    /// Region sizes must be finite and > 0.
    Region,
    /// The region is larger than the scalar computes exactly: its bounding box must have sides
    /// of at most [`crate::Scalar::MAX_EXTENT`] and lie within that of the origin on each axis
    /// (an interval: be at most that long).
    Extent,
    /// The gap must be finite and >= 0, and smaller than the region.
    Gap,
    /// The trial limit must be at least 1.
    MaxTrials,
    /// The storage holds no shape slot, or the index buffer is smaller than the shape buffer + 1.
    Storage,
}

impl core::fmt::Display for ParamError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            ParamError::Exponent => "c must be a finite number greater than 1",
            ParamError::Offset => "N must be a finite number greater than 0",
            ParamError::Zeta => "zeta(c, N) overflows: raise N",
            ParamError::Shape => "a shape proportion is out of range",
            ParamError::Region => "region sizes must be finite and greater than 0",
            ParamError::Extent => "the region is larger than this number type computes exactly (see its MAX_EXTENT)",
            ParamError::Gap => "the gap must be finite, at least 0, and smaller than the region",
            ParamError::MaxTrials => "the trial limit must be at least 1",
            ParamError::Storage => "the storage needs at least one shape slot and an index buffer longer than the shape buffer",
        })
    }
}

impl core::error::Error for ParamError {}

/// Why a step placed nothing. The engine keeps every shape placed before.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum StepError {
    /// The trial limit was reached at placement `index` after `trials` trials (halting).
    Halted {
        /// The placement that could not be made.
        index: u64,
        /// Trials spent on it.
        trials: u64,
    },
    /// The shape buffer is full.
    Capacity {
        /// Number of shape slots.
        capacity: u64,
    },
    /// Shape `index` is too large for the region in any orientation (for the first shape:
    /// lower c or raise N). Only detected where it is certain; otherwise the fill halts.
    CannotFit {
        /// The shape that cannot fit.
        index: u64,
    },
    /// Shape (segment) `index` is narrower than the scalar resolves
    /// ([`crate::Scalar::MIN_SIZE`]); [`crate::check_smallest`] finds this before a run.
    TooSmall {
        /// The shape that is too small.
        index: u64,
    },
}

impl core::fmt::Display for StepError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            StepError::Halted { index, trials } => write!(f, "halted at placement {index} after {trials} trials"),
            StepError::Capacity { capacity } => write!(f, "storage for {capacity} shapes is full"),
            StepError::CannotFit { index } => write!(f, "shape {index} is larger than the region allows"),
            StepError::TooSmall { index } => write!(f, "shape {index} is narrower than this number type resolves"),
        }
    }
}

impl core::error::Error for StepError {}

/// When [`crate::Engine::run`] stops: the first condition given that holds stops it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Stop {
    /// Stop once this many shapes are placed.
    pub count: Option<u64>,
    /// Stop once the placed area reaches this fraction of the region (0 < f < 1).
    pub fill: Option<f64>,
    /// Stop before the first shape whose narrowest width is below this.
    pub min_size: Option<f64>,
}

/// Why [`crate::Engine::run`] stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum StopReason {
    /// The count was reached.
    Count,
    /// The fill fraction was reached.
    Fill,
    /// The next shape is smaller than the minimum size.
    MinSize,
    /// A step failed; see [`StepError`].
    Step(StepError),
}
