//! The numbers a program needs before it fills: the area of every shape ([`AreaSequence`]),
//! the shape slots a stop condition can need ([`capacity`]), whether the first shapes can
//! fit at all ([`first_two_fit`], [`check_first_two`], [`first_shape`]), and whether the last
//! ones are wide enough for the scalar ([`check_smallest`]).
//!
//! These are the checks a front end makes up front so that a hopeless run is refused with a
//! message instead of halting after millions of trials. They use the same formulas, in the same
//! order of operations, as the engines: an area or width computed here is bit for bit the one
//! the engine uses. Nothing here allocates or panics.

use crate::params::{Params, Stop};
use crate::region::Region;
use crate::scalar::{powf, Scalar};
use crate::shape::{ShapeKind, ShapeList};
use crate::zeta::{self, ZetaError};

/// The power-law sequence of areas (lengths in 1D, volumes in 3D)
/// `A_i = A / (zeta(c, N) (i + N)^c)`, `i = 0, 1, 2, ...`, whose sum is `A`; `zeta(c, N)` is
/// computed once.
///
/// ```
/// use zetafill::AreaSequence;
/// let seq = AreaSequence::new(40_000.0, 1.3, 1.0)?;
/// assert!((seq.zeta() - 3.9319).abs() < 1e-4);
/// assert_eq!(seq.area(0), 40_000.0 / seq.zeta());
/// assert!(seq.area(1) < seq.area(0));
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

/// Why no number of slots up to the limit serves a stop condition.
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
pub fn segment_capacity(seq: &AreaSequence, stop: &Stop, max: u64) -> Result<u64, CapacityError> {
    capacity(seq, stop, max, |k| seq.area(k))
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

/// Refuses a run whose stop conditions let it reach a shape narrower than its scalar resolves
/// ([`Scalar::MIN_SIZE`]; `f64` has no limit), with the first such shape. `capacity` is the
/// engine's number of shape slots. The run reaches shape `i` when `i` is below `capacity` and
/// `stop.count`, the first `i` shapes cover less than `stop.fill`, and no shape up to `i` is
/// narrower than `stop.min_size` (the engine's own rules, on the areas it uses).
///
/// ```
/// use zetafill::{check_smallest, AreaSequence, Fixed, ShapeKind, Stop};
/// let seq = AreaSequence::new(200.0 * 200.0, 1.3, 1.0)?;
/// let circles = ShapeKind::Circle.into();
/// let few = Stop { count: Some(2000), ..Stop::default() };
/// assert_eq!(check_smallest::<Fixed>(&seq, &circles, &few, 1 << 24), Ok(()));
/// let many = Stop { count: Some(10_000_000), ..Stop::default() };
/// let err = check_smallest::<Fixed>(&seq, &circles, &many, 1 << 24).unwrap_err();
/// assert!(err.width < 0.01 && err.index < 10_000_000);
/// // Stopping at 0.01 mm keeps every shape resolved.
/// let sized = Stop { min_size: Some(0.01), ..many };
/// assert_eq!(check_smallest::<Fixed>(&seq, &circles, &sized, 1 << 24), Ok(()));
/// assert_eq!(check_smallest::<f64>(&seq, &circles, &many, 1 << 24), Ok(()));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn check_smallest<S: Scalar>(seq: &AreaSequence, shapes: &ShapeList, stop: &Stop, capacity: u64) -> Result<(), TooSmall> {
    let limit = S::MIN_SIZE;
    if limit <= 0.0 {
        return Ok(());
    }
    let Some(index) = first_narrower(seq, shapes, limit, capacity) else {
        return Ok(());
    };
    let stopped = stop.count.is_some_and(|k| index >= k)
        || stop.fill.is_some_and(|f| seq.covered(index) >= f)
        || stop.min_size.is_some_and(|m| first_narrower(seq, shapes, m, index + 1).is_some());
    if stopped {
        return Ok(());
    }
    let kind = shapes.kind_of(index);
    Err(TooSmall {
        index,
        width: kind.min_width(kind.scale_for_area(seq.area(index))),
        limit,
    })
}

/// The first shape of a fill: its kind, area and narrowest width, for messages about a first
/// shape that does not fit (the engine reports that as [`crate::StepError::CannotFit`] or a
/// halt at placement 0).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FirstShape {
    /// Its kind.
    pub kind: ShapeKind,
    /// Its area `A_0`.
    pub area: f64,
    /// Its narrowest width ([`ShapeKind::min_width`]).
    pub width: f64,
}

/// The first shape of `shapes` in the sequence `seq`.
pub fn first_shape(seq: &AreaSequence, shapes: &ShapeList) -> FirstShape {
    let kind = shapes.kind_of(0);
    let area = seq.area(0);
    FirstShape {
        kind,
        area,
        width: kind.min_width(kind.scale_for_area(area)),
    }
}

/// Whether shapes 0 and 1, of areas `a0` and `a1`, can both lie in a `width` x `height`
/// rectangle (inclusive boundary) at least `gap` from the boundary and from each other, for the
/// kinds whose limit is known: unrotated squares and rectangles (side by side or one above the
/// other), circles and rings (in opposite corners). True for every other kind (no known limit).
pub fn first_two_fit(kind: &ShapeKind, a0: f64, a1: f64, width: f64, height: f64, gap: f64) -> bool {
    let (w, h) = (width - 2.0 * gap, height - 2.0 * gap);
    match kind {
        ShapeKind::Square | ShapeKind::Rect { .. } => {
            let (s0, s1) = (kind.scale_for_area(a0), kind.scale_for_area(a1));
            let aspect = if let ShapeKind::Rect { aspect } = kind { *aspect } else { 1.0 };
            let (w0, h0, w1, h1) = (2.0 * aspect * s0, 2.0 * s0, 2.0 * aspect * s1, 2.0 * s1);
            w0 <= w && h0 <= h && (w0 + w1 + gap < w || h0 + h1 + gap < h)
        }
        ShapeKind::Circle | ShapeKind::Ring { .. } => {
            let (r0, r1) = (kind.scale_for_area(a0), kind.scale_for_area(a1));
            let (dx, dy) = ((w - r0 - r1).max(0.0), (h - r0 - r1).max(0.0));
            2.0 * r0 <= w.min(h) && dx * dx + dy * dy > (r0 + r1 + gap) * (r0 + r1 + gap)
        }
        _ => true,
    }
}

/// Why the first two shapes of a fill certainly cannot both be placed (so every run would halt
/// at placement 1), with the numbers a message needs.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum FirstTwoError {
    /// The gap alone leaves no room for two shapes of this kind in the region, whatever c and
    /// N; `max_gap` is the largest gap found to leave room.
    Gap {
        /// The shape kind.
        kind: ShapeKind,
        /// The gap asked for.
        gap: f64,
        /// The largest gap that leaves room (60 halvings of `[0, gap]`).
        max_gap: f64,
        /// The region's width.
        width: f64,
        /// The region's height.
        height: f64,
    },
    /// No c > 1 lets both fit at this N: raise N (or lower the gap).
    Offset {
        /// The shape kind.
        kind: ShapeKind,
        /// The offset N asked for.
        n_offset: f64,
    },
    /// Both fit only when c is at most `max_c`: the paper's hard limit (Shier and Bourke,
    /// section 3).
    Exponent {
        /// The shape kind.
        kind: ShapeKind,
        /// The offset N asked for.
        n_offset: f64,
        /// The exponent asked for.
        c: f64,
        /// The largest c found to work (60 halvings of `[1 + 1e-9, c]`).
        max_c: f64,
    },
}

impl core::fmt::Display for FirstTwoError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            FirstTwoError::Gap { gap, max_gap, .. } => {
                write!(
                    f,
                    "a gap of {gap} leaves no room for the first two shapes whatever c and N; the largest that does is {max_gap}"
                )
            }
            FirstTwoError::Offset { n_offset, .. } => write!(f, "with N = {n_offset} the first two shapes cannot both fit for any c"),
            FirstTwoError::Exponent { n_offset, max_c, .. } => {
                write!(f, "with N = {n_offset} the first two shapes cannot both fit when c > {max_c}")
            }
        }
    }
}

impl core::error::Error for FirstTwoError {}

/// Refuses parameters whose first two shapes certainly cannot both fit, for the cases whose
/// limit is known exactly: a single kind (no mix), unrotated (or a kind that does not rotate),
/// in an inclusive rectangle (see [`first_two_fit`]). Every other case is `Ok`: the engine
/// then finds out by trials (or reports [`crate::StepError::CannotFit`] for a shape too large
/// in any orientation).
///
/// ```
/// use zetafill::{check_first_two, FirstTwoError, Params, Region, ShapeKind};
/// let region = Region::Rect { width: 200.0, height: 200.0, periodic: false };
/// let mut params = Params::circles(1.3, 1.0);
/// params.shape = ShapeKind::Square.into();
/// assert_eq!(check_first_two(&params, &region), Ok(()));
/// params.c = 1.6; // above the squares' limit of about 1.5224 at N = 1
/// match check_first_two(&params, &region) {
///     Err(FirstTwoError::Exponent { max_c, .. }) => assert!((max_c - 1.5224).abs() < 1e-4),
///     other => panic!("{other:?}"),
/// }
/// ```
pub fn check_first_two(params: &Params, region: &Region<'_>) -> Result<(), FirstTwoError> {
    let (
        Region::Rect {
            width,
            height,
            periodic: false,
        },
        [kind],
    ) = (region, params.shape.kinds())
    else {
        return Ok(());
    };
    let (kind, width, height) = (*kind, *width, *height);
    if params.rotate && kind.rotates() {
        return Ok(());
    }
    let n_offset = params.n_offset;
    let fits = |c: f64| {
        let Ok(z) = zeta::zeta(c, n_offset) else {
            return false;
        };
        let a = |i: f64| width * height / (z * powf(i + n_offset, c));
        first_two_fit(&kind, a(0.0), a(1.0), width, height, params.gap)
    };
    if fits(params.c) {
        return Ok(());
    }
    // However small the shapes (N large), the gap alone may leave no room for two.
    let room = |gap: f64| first_two_fit(&kind, 0.0, 0.0, width, height, gap);
    if !room(params.gap) {
        return Err(FirstTwoError::Gap {
            kind,
            gap: params.gap,
            max_gap: bisect(0.0, params.gap, room),
            width,
            height,
        });
    }
    let lowest = 1.0 + 1e-9;
    if !fits(lowest) {
        return Err(FirstTwoError::Offset { kind, n_offset });
    }
    Err(FirstTwoError::Exponent {
        kind,
        n_offset,
        c: params.c,
        max_c: bisect(lowest, params.c, fits),
    })
}

/// Where `works` turns false between `ok` (where it holds) and `bad` (where it does not): the
/// last value found to work after 60 halvings.
fn bisect(mut ok: f64, mut bad: f64, works: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..60 {
        let mid = 0.5 * (ok + bad);
        if works(mid) {
            ok = mid;
        } else {
            bad = mid;
        }
    }
    ok
}
