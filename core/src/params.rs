//! The parameters of a fill and the error values of the engines: [`Params`] (validated once
//! by [`crate::Engine::new`]), the stop conditions [`Stop`], and why a fill stopped
//! ([`StopReason`], [`StepError`]) or could not start ([`ParamError`]).
//!
//! Plain data: nothing here allocates, panics or depends on the target.

use crate::shape::{ShapeKind, ShapeList};

/// The parameters of a fill. `Clone` but not `Copy` (its [`ShapeList`] holds up to
/// [`crate::MAX_MIX`] kinds): the engine keeps the one it is given.
///
/// Start from [`Params::circles`] and change the fields you need; give a fractal dimension
/// instead of c with [`Params::c_from_dimension`]. [`crate::Engine::new`] checks them.
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, Engine, MixOrder, Params, Placed, Region, ShapeKind, ShapeList, Storage};
///
/// let circles = Params::circles(1.3, 1.0);
/// assert_eq!((circles.c, circles.n_offset, circles.gap, circles.rotate), (1.3, 1.0, 0.0, false));
/// assert_eq!(circles.shape.kinds(), &[ShapeKind::Circle]);
///
/// // Randomly rotated squares and triangles in turn, 0.5 apart, of fractal dimension 1.6.
/// let mut params = Params::circles(Params::c_from_dimension(1.6), 2.0);
/// assert_eq!(params.c, 1.25);
/// params.shape = ShapeList::mix(&[ShapeKind::Square, ShapeKind::Triangle], MixOrder::Cycle, 0).expect("two kinds");
/// params.rotate = true;
/// params.gap = 0.5;
/// params.max_trials = 1_000_000;
///
/// let mut shapes = [Placed::<f64>::default(); 10];
/// let mut index = [0u32; index_words(10)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let engine = Engine::new(params.clone(), region, storage)?;
/// assert_eq!(engine.params(), &params);
/// assert_eq!(engine.kind_of(1), ShapeKind::Triangle);
/// # Ok::<(), zetafill::ParamError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
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

/// What was wrong with the parameters, region or storage: [`crate::Engine::new`] and
/// [`crate::line::Engine::new`] check everything once and say which value to change.
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, Engine, ParamError, Params, Placed, Region, Storage};
///
/// fn start(params: Params) -> Result<(), ParamError> {
///     let mut shapes = [Placed::<f64>::default(); 4];
///     let mut index = [0u32; index_words(4)];
///     let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
///     Engine::new(params, Region::Circle { radius: 10.0 }, storage).map(|_| ())
/// }
/// assert_eq!(start(Params::circles(1.3, 1.0)), Ok(()));
/// // c must be above 1: the areas would not add up to the region's.
/// assert_eq!(start(Params::circles(0.9, 1.0)), Err(ParamError::Exponent));
/// assert_eq!(start(Params::circles(f64::NAN, 1.0)), Err(ParamError::Exponent));
/// assert_eq!(ParamError::Exponent.to_string(), "c must be a finite number greater than 1");
/// assert_eq!(start(Params::circles(1.3, 0.0)), Err(ParamError::Offset));
/// assert_eq!(start(Params { gap: 10.0, ..Params::circles(1.3, 1.0) }), Err(ParamError::Gap));
/// ```
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

/// The power law's two numbers as every engine checks them first: c > 1 (else the areas do
/// not sum) and N > 0, both finite.
pub(crate) fn check_power_law(c: f64, n_offset: f64) -> Result<(), ParamError> {
    if !(c.is_finite() && c > 1.0) {
        return Err(ParamError::Exponent);
    }
    if !(n_offset.is_finite() && n_offset > 0.0) {
        return Err(ParamError::Offset);
    }
    Ok(())
}

/// Why a step placed nothing. The engine keeps every shape placed before.
///
/// # Examples
///
/// A trial limit so low that the fill soon halts: the error names the placement that found
/// no place and the trials spent on it, and every shape before it stays placed.
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Region, StepError, Stop, StopReason, Storage};
///
/// let mut shapes = [Placed::<f64>::default(); 500];
/// let mut index = [0u32; index_words(500)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let params = Params { max_trials: 3, ..Params::circles(1.3, 1.0) };
/// let mut engine = Engine::new(params, region, storage)?;
/// let stop = Stop { count: Some(500), ..Stop::default() };
/// match engine.run(&mut rng_from_seed(1), &stop, |_| {}) {
///     StopReason::Step(e @ StepError::Halted { index, trials }) => {
///         assert_eq!(trials, 3);
///         assert_eq!(engine.placed().len() as u64, index);
///         assert_eq!(e.to_string(), format!("halted at placement {index} after 3 trials"));
///     }
///     other => panic!("expected a halt, got {other:?}"),
/// }
/// # Ok::<(), zetafill::ParamError>(())
/// ```
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
    /// ([`crate::Scalar::MIN_SIZE`], or [`crate::Scalar::MIN_SIZE_RELATIVE`] of the region's
    /// coordinates); [`crate::check_smallest`] finds this before a run.
    TooSmall {
        /// The shape that is too small.
        index: u64,
    },
    /// Shape `index` is wider (its bounding circle's diameter) than the scalar computes
    /// exactly ([`crate::Scalar::MAX_EXTENT`]): only a torus lets such a shape in, wrapped
    /// around it; [`crate::check_largest`] finds this before a run.
    TooLarge {
        /// The shape that is too large.
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
            StepError::TooLarge { index } => write!(f, "shape {index} is wider than this number type computes exactly"),
        }
    }
}

impl core::error::Error for StepError {}

/// When [`crate::Engine::run`] stops: the first condition given that holds stops it.
/// `Stop::default()` has none (the fill runs until its storage is full or it halts).
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Region, Stop, StopReason, Storage};
///
/// let mut shapes = [Placed::<f64>::default(); 100];
/// let mut index = [0u32; index_words(100)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
/// let mut rng = rng_from_seed(4);
///
/// // Half the region covered (a few large circles do that).
/// let half = Stop { fill: Some(0.5), ..Stop::default() };
/// assert_eq!(engine.run(&mut rng, &half, |_| {}), StopReason::Fill);
/// assert!(engine.stats().fill_fraction >= 0.5);
///
/// // Then on, until the next circle would be less than 10 wide.
/// let wide = Stop { min_size: Some(10.0), ..Stop::default() };
/// assert_eq!(engine.run(&mut rng, &wide, |_| {}), StopReason::MinSize);
/// assert!(engine.placed().iter().all(|c| 2.0 * c.scale >= 10.0));
/// let next = engine.placed().len() as u64;
/// assert!(2.0 * (engine.area_of(next) / std::f64::consts::PI).sqrt() < 10.0);
///
/// // The first condition that holds stops the run: half the region is still covered.
/// let both = Stop { count: Some(next + 5), ..half };
/// assert_eq!(engine.run(&mut rng, &both, |_| {}), StopReason::Fill);
/// assert_eq!(engine.placed().len() as u64, next);
///
/// // A count counts every shape placed, those of earlier runs too.
/// let five_more = Stop { count: Some(next + 5), ..Stop::default() };
/// assert_eq!(engine.run(&mut rng, &five_more, |_| {}), StopReason::Count);
/// assert_eq!(engine.placed().len() as u64, next + 5);
/// # Ok::<(), zetafill::ParamError>(())
/// ```
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

impl Stop {
    /// The condition that holds before placement `n`, given the area (length, volume)
    /// `covered` of the first `n` out of `total`, in the one order every engine checks them:
    /// the count, then the covered fraction, then the next shape's narrowest width
    /// (`next_width`, asked only when a minimum size is set).
    pub(crate) fn holds(&self, n: u64, covered: f64, total: f64, next_width: impl FnOnce() -> f64) -> Option<StopReason> {
        if self.count.is_some_and(|k| n >= k) {
            return Some(StopReason::Count);
        }
        if self.fill.is_some_and(|f| covered >= f * total) {
            return Some(StopReason::Fill);
        }
        if self.min_size.is_some_and(|m| next_width() < m) {
            return Some(StopReason::MinSize);
        }
        None
    }
}

/// The loop of every engine's `run`: steps `engine` until `stops` names a reason or a step
/// fails, calling `on_place` after each placement.
pub(crate) fn run_until<E, P>(
    engine: &mut E,
    stops: impl Fn(&E) -> Option<StopReason>,
    mut on_place: impl FnMut(&P),
    mut step: impl FnMut(&mut E) -> Result<P, StepError>,
) -> StopReason {
    loop {
        if let Some(reason) = stops(engine) {
            return reason;
        }
        match step(engine) {
            Ok(p) => on_place(&p),
            Err(e) => return StopReason::Step(e),
        }
    }
}

/// Why [`crate::Engine::run`] stopped: one of the [`Stop`] conditions (see its example), or
/// a [`StepError`] (see its example).
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
