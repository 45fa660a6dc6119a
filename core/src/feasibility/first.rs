//! Whether the first shapes of a fill can fit at all: the first shape described for messages
//! ([`first_shape`]), and the first two placed side by side in the region's box
//! ([`first_two_fit`], [`check_first_two`]).

use super::AreaSequence;
use crate::params::Params;
use crate::region::{Region, Wallpaper};
use crate::scalar::sqrtf;
use crate::shape::{ShapeKind, ShapeList};

/// The first shape of a fill: its kind, area and narrowest width, for messages about a first
/// shape that does not fit (the engine reports that as [`crate::StepError::CannotFit`] or a
/// halt at placement 0). See [`first_shape`] for an example.
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
///
/// # Examples
///
/// ```
/// use zetafill::{first_shape, AreaSequence, FirstShape, ShapeKind};
///
/// // The first square of a 100 x 100 fill at c = 1.3, N = 1.
/// let seq = AreaSequence::new(10_000.0, 1.3, 1.0)?;
/// let FirstShape { kind, area, width } = first_shape(&seq, &ShapeKind::Square.into());
/// assert_eq!(kind, ShapeKind::Square);
/// assert_eq!(area, seq.area(0));
/// assert!((width - area.sqrt()).abs() < 1e-9); // a square's narrowest width is its side
/// # Ok::<(), zetafill::ZetaError>(())
/// ```
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
/// other), circles and rings (in opposite corners), motifs (their inscribed discs, as circles).
/// True for every other kind (no known limit).
pub fn first_two_fit(kind: &ShapeKind, a0: f64, a1: f64, width: f64, height: f64, gap: f64) -> bool {
    let (w, h) = (width - 2.0 * gap, height - 2.0 * gap);
    match kind {
        ShapeKind::Square | ShapeKind::Rect { .. } => {
            let (s0, s1) = (kind.scale_for_area(a0), kind.scale_for_area(a1));
            let aspect = if let ShapeKind::Rect { aspect } = kind { *aspect } else { 1.0 };
            let (w0, h0, w1, h1) = (2.0 * aspect * s0, 2.0 * s0, 2.0 * aspect * s1, 2.0 * s1);
            w0 <= w && h0 <= h && (w0 + w1 + gap < w || h0 + h1 + gap < h)
        }
        ShapeKind::Circle | ShapeKind::Ring { .. } | ShapeKind::Motif { .. } => {
            // A motif holds its inscribed disc: where two such discs cannot both lie, the two
            // motifs cannot either, whatever their angles.
            let f = if let ShapeKind::Motif { inner, .. } = kind { *inner } else { 1.0 };
            let (r0, r1) = (f * kind.scale_for_area(a0), f * kind.scale_for_area(a1));
            let (dx, dy) = ((w - r0 - r1).max(0.0), (h - r0 - r1).max(0.0));
            2.0 * r0 <= w.min(h) && dx * dx + dy * dy > (r0 + r1 + gap) * (r0 + r1 + gap)
        }
        _ => true,
    }
}

/// Why the first two shapes of a fill certainly cannot both be placed (so every run would halt
/// at placement 1), with the numbers a message needs. See [`check_first_two`] for an example.
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
/// # Examples
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
    // (A motif's bound comes from its inscribed disc, which turns with it.)
    if params.rotate && kind.rotates() && !matches!(kind, ShapeKind::Motif { .. }) {
        return Ok(());
    }
    let n_offset = params.n_offset;
    let fits = |c: f64| {
        let Ok(seq) = AreaSequence::new(width * height, c, n_offset) else {
            return false;
        };
        first_two_fit(&kind, seq.area(0), seq.area(1), width, height, params.gap)
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
        // c - 1 is bisected on a ratio scale, so a c of any size gives the limit to full
        // precision (an arithmetic bisection from c = 1e100 never left 1).
        max_c: 1.0 + bisect_ratio(lowest - 1.0, params.c - 1.0, |t| fits(1.0 + t)),
    })
}

/// [`bisect`] for positive `ok < bad` far apart: each step halves `bad / ok` on a log scale
/// (the geometric mean), then 60 arithmetic halvings finish.
fn bisect_ratio(mut ok: f64, mut bad: f64, works: impl Fn(f64) -> bool) -> f64 {
    while bad > 2.0 * ok {
        let mid = sqrtf(ok * bad);
        if !(mid > ok && mid < bad) {
            break;
        }
        if works(mid) {
            ok = mid;
        } else {
            bad = mid;
        }
    }
    bisect(ok, bad, works)
}

/// Where `works` turns false between `ok` (where it holds) and `bad` (where it does not): the
/// last value found to work after 60 halvings.
pub(crate) fn bisect(mut ok: f64, mut bad: f64, works: impl Fn(f64) -> bool) -> f64 {
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

/// Why the first shape of a symmetric fill can never clear its own images
/// ([`check_first_orbit`]).
///
/// # Examples
///
/// ```
/// use zetafill::{check_first_orbit, FirstOrbitError, Group, Params, Wallpaper};
///
/// // A disc in p4m on a 60 mm square has room for a radius of about 8.79 mm.
/// let w = Wallpaper::new(Group::P4m, 60.0, 60.0, 90.0)?;
/// assert!(check_first_orbit(&Params::circles(1.3, 3.0), &w).is_ok());
/// let Err(FirstOrbitError::Exponent { max_c, room, .. }) = check_first_orbit(&Params::circles(1.3, 0.3), &w) else {
///     panic!("the first circle is too large");
/// };
/// assert!((room - 8.7868).abs() < 1e-4 && max_c > 1.0 && max_c < 1.3);
/// # Ok::<(), zetafill::WallpaperError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum FirstOrbitError {
    /// With this gap no point has room for a shape at all, whatever c and N; `max_gap` is the
    /// largest gap that leaves some.
    Gap {
        /// The shape kind.
        kind: ShapeKind,
        /// The gap asked for.
        gap: f64,
        /// Twice the largest disc that clears its orbit.
        max_gap: f64,
    },
    /// The first shape's inscribed disc is wider than the room any point keeps from its own
    /// images (`room`, a radius); up to `max_c` its bounding disc clears them.
    Exponent {
        /// The shape kind.
        kind: ShapeKind,
        /// The exponent asked for.
        c: f64,
        /// The largest c found at which the first shape certainly fits (60 halvings).
        max_c: f64,
        /// The radius of the largest disc that clears its own orbit, less half the gap.
        room: f64,
    },
}

impl core::fmt::Display for FirstOrbitError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            FirstOrbitError::Gap { gap, max_gap, .. } => {
                write!(
                    f,
                    "a gap of {gap} leaves no shape room to clear its own images; at most {max_gap} does"
                )
            }
            FirstOrbitError::Exponent { c, max_c, .. } => {
                write!(
                    f,
                    "the first shape cannot clear its own images when c = {c}; it does up to c = {max_c}"
                )
            }
        }
    }
}

impl core::error::Error for FirstOrbitError {}

/// Checks that the first shape of a fill with the symmetry of `w` can clear its own images
/// somewhere: refused when its inscribed disc (with the gap) is wider than the largest disc
/// that clears its orbit ([`Wallpaper::largest_disc`]), which no position or angle can help.
pub fn check_first_orbit(params: &Params, w: &Wallpaper) -> Result<(), FirstOrbitError> {
    let kind = params.shape.kind_of(0);
    let disc = w.largest_disc();
    let room = disc - params.gap / 2.0;
    if room <= 0.0 {
        return Err(FirstOrbitError::Gap {
            kind,
            gap: params.gap,
            max_gap: 2.0 * disc,
        });
    }
    let first = |c: f64| {
        let seq = AreaSequence::new(w.fundamental_area(), c, params.n_offset).ok()?;
        Some(kind.scale_for_area(seq.area(0)))
    };
    let Some(scale) = first(params.c) else { return Ok(()) };
    if kind.inradius(scale) < room {
        return Ok(());
    }
    let lowest = 1.0 + 1e-9;
    let fits = |c: f64| first(c).is_some_and(|s| kind.bounding_radius(s) < room);
    Err(FirstOrbitError::Exponent {
        kind,
        c: params.c,
        max_c: 1.0 + bisect_ratio(lowest - 1.0, params.c - 1.0, |t| fits(1.0 + t)),
        room,
    })
}
