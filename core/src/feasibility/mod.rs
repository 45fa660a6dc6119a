//! The numbers a program needs before it fills: the area of every shape ([`AreaSequence`]),
//! the shape slots a stop condition can need ([`capacity`]), whether the first shapes can
//! fit at all ([`first_two_fit`], [`check_first_two`], [`first_shape`]), and whether the last
//! ones are wide enough for the scalar ([`check_smallest`]).
//!
//! These are the checks a front end makes up front so that a hopeless run is refused with a
//! message instead of halting after millions of trials. They use the same formulas, in the same
//! order of operations, as the engines: an area or width computed here is bit for bit the one
//! the engine uses. Nothing here allocates or panics.

use crate::params::Stop;
use crate::region::Region;
use crate::scalar::{powf, Scalar};
use crate::shape::{ShapeKind, ShapeList};
use crate::zeta::{self, ZetaError};

mod first;
pub(crate) use first::bisect;
pub use first::{check_first_orbit, check_first_two, first_shape, first_two_fit, FirstOrbitError, FirstShape, FirstTwoError};

/// The power-law sequence of areas (lengths in 1D, volumes in 3D)
/// `A_i = A / (zeta(c, N) (i + N)^c)`, `i = 0, 1, 2, ...`, whose sum is `A`; `zeta(c, N)` is
/// computed once. Its areas are bit for bit the engine's ([`crate::Engine::area_of`]).
///
/// # Examples
///
/// ```
/// use zetafill::AreaSequence;
/// let seq = AreaSequence::new(40_000.0, 1.3, 1.0)?;
/// assert!((seq.zeta() - 3.9319).abs() < 1e-4);
/// assert_eq!(seq.area(0), 40_000.0 / seq.zeta());
/// assert!(seq.area(1) < seq.area(0));
/// // The first shape alone covers 1 / zeta(c, N) of the region; all of them cover it.
/// assert!((seq.covered(1) - 1.0 / seq.zeta()).abs() < 1e-12);
/// assert!(seq.covered(1_000_000) > 0.9);
/// # Ok::<(), zetafill::ZetaError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct AreaSequence {
    total: f64,
    c: f64,
    n_offset: f64,
    zeta: f64,
}

impl AreaSequence {
    /// The sequence for a region of area (length, volume) `total`, exponent `c > 1` and offset
    /// `N > 0`. Fails as [`zeta::zeta`] does: on a bad `c` or `N`, or when `zeta(c, N)`
    /// overflows.
    pub fn new(total: f64, c: f64, n_offset: f64) -> Result<Self, ZetaError> {
        let zeta = zeta::zeta(c, n_offset)?;
        Ok(AreaSequence { total, c, n_offset, zeta })
    }

    /// `A_i = A / (zeta(c, N) (i + N)^c)`.
    #[inline]
    pub fn area(&self, i: u64) -> f64 {
        self.total / (self.zeta * powf(i as f64 + self.n_offset, self.c))
    }

    /// `zeta(c, N)`.
    pub fn zeta(&self) -> f64 {
        self.zeta
    }

    /// The total `A`.
    pub fn total(&self) -> f64 {
        self.total
    }

    /// The exponent `c`.
    pub fn c(&self) -> f64 {
        self.c
    }

    /// The offset `N`.
    pub fn n_offset(&self) -> f64 {
        self.n_offset
    }

    /// The fraction of `A` the first `k` shapes cover: `1 - zeta(c, N + k) / zeta(c, N)`.
    pub fn covered(&self, k: u64) -> f64 {
        1.0 - zeta::hurwitz_zeta(self.c, self.n_offset + k as f64).unwrap_or(0.0) / self.zeta
    }
}

/// Why no number of slots up to the limit serves a stop condition ([`shape_capacity`],
/// [`segment_capacity`]).
///
/// # Examples
///
/// ```
/// use zetafill::{shape_capacity, AreaSequence, CapacityError, ShapeKind, Stop};
///
/// // At c = 1.3 a million circles cover about 98.7% of the region: 99% needs more.
/// let seq = AreaSequence::new(10_000.0, 1.3, 1.0)?;
/// let stop = Stop { fill: Some(0.99), ..Stop::default() };
/// let e = shape_capacity(&seq, &ShapeKind::Circle.into(), &stop, 1_000_000);
/// assert_eq!(e, Err(CapacityError::Fill { fill: 0.99, max: 1_000_000 }));
/// assert_eq!(e.map_err(|e| e.to_string()), Err("a fill of 0.99 needs more than 1000000 shapes at this c".to_string()));
/// # Ok::<(), zetafill::ZetaError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum CapacityError {
    /// Covering `fill` of the region takes more than `max` shapes (at this c).
    Fill {
        /// The fill fraction asked for.
        fill: f64,
        /// The limit on the number of shapes.
        max: u64,
    },
    /// Shapes stay at least `min_size` wide beyond `max` of them.
    MinSize {
        /// The minimum size asked for.
        min_size: f64,
        /// The limit on the number of shapes.
        max: u64,
    },
}

impl core::fmt::Display for CapacityError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            CapacityError::Fill { fill, max } => write!(f, "a fill of {fill} needs more than {max} shapes at this c"),
            CapacityError::MinSize { min_size, max } => write!(f, "a minimum size of {min_size} needs more than {max} shapes"),
        }
    }
}

impl core::error::Error for CapacityError {}

/// How many slots the stop conditions can need, with one to spare, at most `max`: at most
/// `stop.count`; for `stop.fill = f` the first power of two `k` with
/// `zeta(c, N + k) <= (1 - f) zeta(c, N)` (the first `k` shapes cover `f` of the region); for
/// `stop.min_size = m` the first power of two `k` whose width `width(k)` (decreasing in `k`)
/// is below `m`. Each search doubles `k`, so it errs high by at most 2x. With no condition at
/// all, `max`.
///
/// [`shape_capacity`] and [`segment_capacity`] supply the width of 2D shapes and of segments.
pub fn capacity(seq: &AreaSequence, stop: &Stop, max: u64, width: impl Fn(u64) -> f64) -> Result<u64, CapacityError> {
    // The smallest power of two at which `more` fails, or None past the limit.
    let first_failing = |more: &dyn Fn(u64) -> bool| {
        let mut k = 1u64;
        while more(k) && k <= max {
            k = k.saturating_mul(2);
        }
        (k <= max).then_some(k)
    };
    let mut slots = stop.count.unwrap_or(u64::MAX);
    if let Some(f) = stop.fill {
        let target = (1.0 - f) * seq.zeta;
        let tail = |k: u64| zeta::hurwitz_zeta(seq.c, seq.n_offset + k as f64).unwrap_or(0.0);
        let k = first_failing(&|k| tail(k) > target).ok_or(CapacityError::Fill { fill: f, max })?;
        slots = slots.min(k);
    }
    if let Some(m) = stop.min_size {
        let k = first_failing(&|k| width(k) >= m).ok_or(CapacityError::MinSize { min_size: m, max })?;
        slots = slots.min(k);
    }
    Ok(slots.saturating_add(1).min(max))
}

/// [`capacity`] for 2D shapes: the width of shape `k` is its narrowest width
/// ([`ShapeKind::min_width`]) at area `seq.area(k)`.
///
/// # Examples
///
/// ```
/// use zetafill::{shape_capacity, AreaSequence, ShapeKind, Stop};
/// let seq = AreaSequence::new(40_000.0, 1.3, 1.0)?;
/// let stop = Stop { fill: Some(0.5), ..Stop::default() };
/// let slots = shape_capacity(&seq, &ShapeKind::Circle.into(), &stop, 20_000_000)?;
/// assert!(seq.covered(slots - 1) >= 0.5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn shape_capacity(seq: &AreaSequence, shapes: &ShapeList, stop: &Stop, max: u64) -> Result<u64, CapacityError> {
    capacity(seq, stop, max, |k| {
        let kind = shapes.kind_of(k);
        kind.min_width(kind.scale_for_area(seq.area(k)))
    })
}

/// [`capacity`] for the 1D fill: the width of segment `k` is its length `seq.area(k)`.
///
/// # Examples
///
/// ```
/// use zetafill::{AreaSequence, Stop};
/// use zetafill::line::capacity;
///
/// let seq = AreaSequence::new(100.0, 1.4, 1.0)?;
/// // A count needs its own number of slots, plus one to spare.
/// assert_eq!(capacity(&seq, &Stop { count: Some(50), ..Stop::default() }, 1_000), Ok(51));
/// // Segments down to 0.5 long: every one of them has a slot.
/// let slots = capacity(&seq, &Stop { min_size: Some(0.5), ..Stop::default() }, 1_000)?;
/// assert!(seq.area(slots - 1) < 0.5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn segment_capacity(seq: &AreaSequence, stop: &Stop, max: u64) -> Result<u64, CapacityError> {
    capacity(seq, stop, max, |k| seq.area(k))
}

/// Whether a shape of this kind and area is wider (its bounding circle's diameter, in f64)
/// than [`Scalar::MAX_EXTENT`]: the engines' and [`check_largest`]'s test.
pub(crate) fn too_large<S: Scalar>(kind: ShapeKind, area: f64) -> bool {
    S::MAX_EXTENT < f64::MAX && 2.0 * kind.bounding_radius(kind.scale_for_area(area)) > S::MAX_EXTENT
}

/// The narrowest shape the scalar resolves in `region`: the larger of
/// [`Scalar::MIN_SIZE`] and [`Scalar::MIN_SIZE_RELATIVE`] of its largest coordinate.
pub(crate) fn min_size<S: Scalar>(region: &Region<'_>) -> f64 {
    S::MIN_SIZE.max(S::MIN_SIZE_RELATIVE * region.magnitude())
}

/// A run would place a shape narrower than its scalar resolves ([`Scalar::MIN_SIZE`]), where
/// the exact tests are no longer exact: found by [`check_smallest`] before the run, which the
/// engine would otherwise stop at ([`crate::StepError::TooSmall`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TooSmall {
    /// The first shape the run would reach that is too narrow (its placement index).
    pub index: u64,
    /// Its narrowest width ([`ShapeKind::min_width`]).
    pub width: f64,
    /// The narrowest width the scalar resolves, [`Scalar::MIN_SIZE`].
    pub limit: f64,
}

impl core::fmt::Display for TooSmall {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let TooSmall { index, width, limit } = self;
        write!(
            f,
            "shape {index} would be {width} mm wide, narrower than the {limit} mm this number type resolves"
        )
    }
}

impl core::error::Error for TooSmall {}

/// The smallest `i < max` for which `below(i)` holds, where `below` is false and then true as
/// `i` grows (doubling, then halving the last step).
fn first_where(max: u64, below: impl Fn(u64) -> bool) -> Option<u64> {
    if max == 0 {
        return None;
    }
    if below(0) {
        return Some(0);
    }
    let (mut lo, mut hi) = (0u64, 1u64);
    while hi < max && !below(hi) {
        lo = hi;
        hi = hi.saturating_mul(2);
    }
    if hi >= max {
        hi = max - 1;
        if hi == lo || !below(hi) {
            return None;
        }
    }
    // below(lo) is false, below(hi) true.
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if below(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

/// The first shape below `max` whose narrowest width is below `limit`. Each kind's widths
/// shrink with the index; in a mix, a kind's first such shape is its first placement at or
/// after the index where its width falls below `limit` (looked for over at most 2^16
/// placements: past them the index itself is taken, which only errs early).
fn first_narrower(seq: &AreaSequence, shapes: &ShapeList, limit: f64, max: u64) -> Option<u64> {
    let mut first: Option<u64> = None;
    for &kind in shapes.kinds() {
        let below = |i: u64| kind.min_width(kind.scale_for_area(seq.area(i))) < limit;
        let Some(from) = first_where(max, below) else { continue };
        let placed = (from..max.min(from.saturating_add(1 << 16)))
            .find(|&i| shapes.kind_of(i) == kind)
            .unwrap_or(from);
        first = Some(first.map_or(placed, |f| f.min(placed)));
    }
    first
}

/// Whether a run stops before shape `index`: at `stop.count`, once the first `index` shapes
/// cover `stop.fill`, or at a shape up to `index` narrower than `stop.min_size` (the engine's
/// own rules, on the areas it uses).
fn stops_before(seq: &AreaSequence, shapes: &ShapeList, stop: &Stop, index: u64) -> bool {
    stop.count.is_some_and(|k| index >= k)
        || stop.fill.is_some_and(|f| seq.covered(index) >= f)
        || stop
            .min_size
            .is_some_and(|m| first_narrower(seq, shapes, m, index.saturating_add(1)).is_some())
}

/// Refuses a run whose stop conditions let it reach a shape narrower than its scalar resolves
/// in `region` (the larger of [`Scalar::MIN_SIZE`] and [`Scalar::MIN_SIZE_RELATIVE`] of the
/// region's largest coordinate, [`Region::magnitude`]), with the first such shape. `capacity`
/// is the engine's number of shape slots. The run reaches shape `i` when `i` is below
/// `capacity` and `stop.count`, the first `i` shapes cover less than `stop.fill`, and no shape
/// up to `i` is narrower than `stop.min_size` (the engine's own rules, on the areas it uses).
///
/// ```
/// use zetafill::{check_smallest, AreaSequence, Fixed, Region, ShapeKind, Stop};
/// let region = Region::Rect { width: 200.0, height: 200.0, periodic: false };
/// let seq = AreaSequence::new(200.0 * 200.0, 1.3, 1.0)?;
/// let circles = ShapeKind::Circle.into();
/// let few = Stop { count: Some(2000), ..Stop::default() };
/// assert_eq!(check_smallest::<Fixed>(&seq, &circles, &few, 1 << 24, &region), Ok(()));
/// let many = Stop { count: Some(10_000_000), ..Stop::default() };
/// let err = check_smallest::<Fixed>(&seq, &circles, &many, 1 << 24, &region).unwrap_err();
/// assert!(err.width < 0.01 && err.index < 10_000_000);
/// // Stopping at 0.01 mm keeps every shape resolved.
/// let sized = Stop { min_size: Some(0.01), ..many };
/// assert_eq!(check_smallest::<Fixed>(&seq, &circles, &sized, 1 << 24, &region), Ok(()));
/// assert_eq!(check_smallest::<f64>(&seq, &circles, &many, 1 << 24, &region), Ok(()));
/// // On f64 the limit follows the coordinates: at c = 50 the sixth shape is 1e-12 of the first.
/// let steep = AreaSequence::new(200.0 * 200.0, 50.0, 2.0)?;
/// let err = check_smallest::<f64>(&steep, &circles, &few, 1 << 24, &region).unwrap_err();
/// assert_eq!(err.limit, 200.0 / 1_099_511_627_776.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn check_smallest<S: Scalar>(
    seq: &AreaSequence,
    shapes: &ShapeList,
    stop: &Stop,
    capacity: u64,
    region: &Region<'_>,
) -> Result<(), TooSmall> {
    let limit = min_size::<S>(region);
    if limit <= 0.0 || limit.is_nan() {
        return Ok(());
    }
    let Some(index) = first_narrower(seq, shapes, limit, capacity) else {
        return Ok(());
    };
    if stops_before(seq, shapes, stop, index) {
        return Ok(());
    }
    let kind = shapes.kind_of(index);
    Err(TooSmall {
        index,
        width: kind.min_width(kind.scale_for_area(seq.area(index))),
        limit,
    })
}

/// A run would place a shape wider than its scalar computes exactly ([`Scalar::MAX_EXTENT`],
/// the diameter of its bounding circle): found by [`check_largest`] before the run, which the
/// engine would otherwise stop at ([`crate::StepError::TooLarge`]). Only a torus lets such a
/// shape in, wrapped around it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TooLarge {
    /// The first shape the run would reach that is too wide (its placement index).
    pub index: u64,
    /// The diameter of its bounding circle.
    pub width: f64,
    /// The widest shape the scalar computes exactly, [`Scalar::MAX_EXTENT`].
    pub limit: f64,
}

impl core::fmt::Display for TooLarge {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let TooLarge { index, width, limit } = self;
        write!(
            f,
            "shape {index} would be {width} mm across, wider than the {limit} mm this number type computes exactly"
        )
    }
}

impl core::error::Error for TooLarge {}

/// Refuses a run whose stop conditions let it reach a shape wider than its scalar computes
/// exactly ([`Scalar::MAX_EXTENT`]; `f64` has no limit), with the first such shape: its
/// squared lengths would saturate and the exact tests stop being tests. Each kind's widest
/// shape is its first placement (looked for over at most 2^16 placements: past them the
/// 2^16-th shape stands for it, which only errs early). `capacity` and `stop` as in
/// [`check_smallest`].
///
/// ```
/// use zetafill::{check_largest, AreaSequence, Fixed, ShapeKind, ShapeList, Stop, MixOrder};
/// // A 10 m torus at c = 1.05: the second shape, a rectangle of aspect 1e-4, is 127 m long.
/// let seq = AreaSequence::new(1e8, 1.05, 2.0)?;
/// let mix = ShapeList::mix(&[ShapeKind::Circle, ShapeKind::Rect { aspect: 1e-4 }], MixOrder::Cycle, 0).ok_or("mix")?;
/// let two = Stop { count: Some(2), ..Stop::default() };
/// let err = check_largest::<Fixed>(&seq, &mix, &two, 100).unwrap_err();
/// assert_eq!((err.index, err.limit), (1, 10_000.0));
/// assert!(err.width > 120_000.0);
/// // One circle, 1.8 m across, is fine; so is any shape on f64.
/// assert_eq!(check_largest::<Fixed>(&seq, &mix, &Stop { count: Some(1), ..two }, 100), Ok(()));
/// assert_eq!(check_largest::<f64>(&seq, &mix, &two, 100), Ok(()));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn check_largest<S: Scalar>(seq: &AreaSequence, shapes: &ShapeList, stop: &Stop, capacity: u64) -> Result<(), TooLarge> {
    if S::MAX_EXTENT >= f64::MAX {
        return Ok(());
    }
    let window = capacity.min(1 << 16);
    let mut first: Option<u64> = None;
    for &kind in shapes.kinds() {
        let Some(i) = (0..window)
            .find(|&i| shapes.kind_of(i) == kind)
            .or((window < capacity).then_some(window))
        else {
            continue;
        };
        if too_large::<S>(kind, seq.area(i)) {
            first = Some(first.map_or(i, |f| f.min(i)));
        }
    }
    let Some(index) = first else { return Ok(()) };
    if stops_before(seq, shapes, stop, index) {
        return Ok(());
    }
    let kind = shapes.kind_of(index);
    Err(TooLarge {
        index,
        width: 2.0 * kind.bounding_radius(kind.scale_for_area(seq.area(index))),
        limit: S::MAX_EXTENT,
    })
}
