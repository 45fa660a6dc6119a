//! The number type the geometry is written over, and the only place that calls `libm`.
//!
//! Every geometric computation in the core goes through [`Scalar`]. `f64` is the default
//! scalar; a fixed-point scalar can implement the same trait. Each implementation is
//! deterministic across targets: `f64` uses IEEE-754 basic operations (which are exactly
//! rounded everywhere) plus `libm`, a pure-Rust maths library whose results do not depend on
//! the platform. No fused multiply-add, no intrinsics, no SIMD.
//!
//! A scalar also states what it cannot compute exactly: the largest region
//! ([`Scalar::MAX_EXTENT`]) and the narrowest shape ([`Scalar::MIN_SIZE`]), which the engines
//! refuse; and it rounds the few computations whose direction matters upward
//! ([`Scalar::dist2_up`], [`Scalar::seg_dist2_up`]: the cell sampler's bounds must never fall
//! below the truth). For `f64` those are the plain formulas: its rounding is relative and far
//! below the sampler's slack ([`Scalar::BOUND_SLACK`]).

use crate::geom::{seg_dist2, Point};
use core::fmt::Debug;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// A deterministic number type for geometry: `f64`, or [`crate::Fixed`] for cores without an
/// FPU. The engines are generic over it (`Engine::<S>`), so code written over `S: Scalar` runs
/// on either.
///
/// Implementations must give bit-identical results on every target for the same inputs.
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Fixed, Params, Placed, Region, Scalar, Stop, Storage};
///
/// /// The largest circle's radius after a short fill, on scalar `S`.
/// fn largest<S: Scalar>() -> f64 {
///     let mut shapes = [Placed::<S>::default(); 20];
///     let mut index = [0u32; index_words(20)];
///     let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
///     let region = Region::Circle { radius: 100.0 };
///     let mut engine = Engine::<S>::new(Params::circles(1.3, 1.0), region, storage).expect("valid");
///     engine.run(&mut rng_from_seed(3), &Stop { count: Some(20), ..Stop::default() }, |_| {});
///     engine.placed()[0].scale.to_f64()
/// }
/// // The first circle's radius comes from its area, the same on both scalars to within the
/// // fixed-point resolution; positions may differ between scalars.
/// assert!((largest::<f64>() - largest::<Fixed>()).abs() < 1e-6);
/// assert_eq!(f64::from_f64(0.25).sqrt(), 0.5);
/// ```
pub trait Scalar:
    sealed::Sealed
    + Copy
    + Send
    + Sync
    + Default
    + Debug
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
    /// The largest region the geometry is exact for, in mm: a region's bounding box must have
    /// sides of at most this and lie within this of the origin on each axis (a 1D interval:
    /// at most this long). [`crate::Engine::new`] and [`crate::line::Engine::new`] refuse a
    /// larger one ([`crate::ParamError::Extent`]). `f64`: no limit.
    const MAX_EXTENT: f64;
    /// The narrowest shape (shortest segment) the geometry resolves, in mm: the engines place
    /// none narrower ([`crate::StepError::TooSmall`]) and [`crate::check_smallest`] finds,
    /// before a run, whether its stop conditions would reach one. `f64`: 0 (no limit).
    const MIN_SIZE: f64;
    /// The narrowest shape the geometry resolves, as a fraction of the largest coordinate of
    /// the region's bounding box ([`crate::Region::magnitude`]): for a floating-point scalar,
    /// whose resolution grows with the coordinates. The engines place no shape narrower than
    /// the larger of this limit and [`Scalar::MIN_SIZE`] ([`crate::StepError::TooSmall`]).
    /// `f64`: 2^-40, at least 4,096 units in the last place of the coordinates, so that a
    /// polygon's vertices stay distinct and its drawn outline is the power-law shape (a
    /// narrower rectangle's sides round onto each other: an outline of zero area). Fixed
    /// point resolves an absolute width: 0 (the default).
    const MIN_SIZE_RELATIVE: f64 = 0.0;
    /// Whether the type is `f64` itself (IEEE-754 binary64, rounding to nearest). A polygon
    /// region's edge tree answers queries on such a scalar by visiting only the edges near
    /// the point or shape asked about: its proofs that the skipped edges change nothing bound
    /// `f64` rounding. On any other scalar every query visits every edge (same answers,
    /// slower). Other implementations leave it `false`.
    ///
    /// ```
    /// use zetafill::{Fixed, Scalar};
    ///
    /// assert!(f64::IS_F64 && !Fixed::IS_F64);
    /// ```
    const IS_F64: bool = false;
    /// How far a polygon drawn in this arithmetic may lie outside its exact outline,
    /// `[relative to its scale, absolute]` in mm: its sines, cosines and vertices are rounded.
    /// Bounding radii grow by it ([`crate::ShapeKind::bounding_radius`]), so that the tests
    /// that skip a pair whose bounding circles are apart never skip an overlap. `f64`: none
    /// (its relative error, a few 1e-16, is below every tolerance).
    const OUTLINE_SLACK: [f64; 2];
    /// What the cell sampler adds to every bound on the clearance for the rounding of its own
    /// arithmetic, `[relative, absolute]`: `relative` times the region's larger side plus
    /// `absolute` mm (see [`crate::CellSampler`]).
    const BOUND_SLACK: [f64; 2];
    /// Converts from `f64` (rounding or saturating as the type requires).
    fn from_f64(v: f64) -> Self;
    /// Converts to `f64` (exactly where the type allows).
    fn to_f64(self) -> f64;
    /// Square root; returns zero for negative input.
    fn sqrt(self) -> Self;
    /// Sine and cosine of an angle in radians.
    fn sin_cos(self) -> (Self, Self);
    /// The sine and cosine of `2π / n`, the turn between the vertices of a regular polygon
    /// with `n` of them (`n` at least 1): `from_f64(2π / n).sin_cos()`, exactly.
    #[inline]
    fn turn_step(n: usize) -> (Self, Self) {
        Self::from_f64(core::f64::consts::TAU / n as f64).sin_cos()
    }
    /// Largest integer not above `self`, saturated to the `i64` range (NaN gives 0).
    fn floor_i64(self) -> i64;
    /// A value uniform in `[0, 1)` made from 64 random bits (see [`crate::internals::rng`]).
    fn unit(bits: u64) -> Self;
    /// The bits that identify this value in a digest, with `-0` written as `+0`.
    fn digest_bits(self) -> u64;
    /// Whether the value is finite (always true for fixed point).
    fn is_finite(self) -> bool;
    /// The value's 64 bits, for storage ([`crate::sampler::CellWords`]); `from_word` reads them
    /// back exactly. Zero is stored as all-zero bits.
    fn to_word(self) -> u64;
    /// The value stored by [`Scalar::to_word`].
    fn from_word(w: u64) -> Self;
    /// Absolute value.
    #[inline]
    fn abs(self) -> Self {
        if self < Self::ZERO {
            -self
        } else {
            self
        }
    }
    /// The smaller of two values.
    #[inline]
    fn min(self, o: Self) -> Self {
        if o < self {
            o
        } else {
            self
        }
    }
    /// The larger of two values.
    #[inline]
    fn max(self, o: Self) -> Self {
        if o > self {
            o
        } else {
            self
        }
    }
    /// Half of the value.
    #[inline]
    fn half(self) -> Self {
        self / (Self::ONE + Self::ONE)
    }
    /// `self * b / c` with the product kept exact where the type allows it, so that it cannot
    /// saturate while the quotient fits (`f64`: `(self * b) / c`).
    #[inline]
    fn mul_div(self, b: Self, c: Self) -> Self {
        self * b / c
    }
    /// `x² + y²` rounded up: never below the exact value (`f64`: `x * x + y * y`, rounded to
    /// nearest like every `f64` operation).
    #[inline]
    fn dist2_up(x: Self, y: Self) -> Self {
        x * x + y * y
    }
    /// The squared distance from `p` to the closed segment `a`–`b` rounded up: never below
    /// the exact value, whatever the segment's length (`f64`: [`seg_dist2`]).
    #[inline]
    fn seg_dist2_up(p: Point<Self>, a: Point<Self>, b: Point<Self>) -> Self {
        seg_dist2(p, a, b)
    }
    /// A step at least `self / n` that can be halved `halvings` times without rounding, so
    /// that `n` steps cover `self` and each step is exactly two of its halves (`f64`:
    /// `self / n`, which halves exactly).
    #[inline]
    fn grid_step(self, n: u32, halvings: u32) -> Self {
        let _ = halvings;
        self / Self::from_f64(f64::from(n))
    }
}

/// 2^-53: the spacing of the 53-bit uniform grid used for `f64`.
const TWO_POW_M53: f64 = 1.0 / 9_007_199_254_740_992.0;

/// `libm::sincos(2π / n)` for `n` = 3 ... 32 as bits, `(sin, cos)`: every outline of a
/// regular polygon or a star turns by one of these, and a test checks each against `libm`.
const TURN_STEPS: [(u64, u64); 30] = [
    (0x3febb67ae8584cab, 0xbfdffffffffffffc),
    (0x3ff0000000000000, 0x3c91a62633145c07),
    (0x3fee6f0e134454ff, 0x3fd3c6ef372fe950),
    (0x3febb67ae8584caa, 0x3fe0000000000001),
    (0x3fe904c37505de4b, 0x3fe3f3a0e28bedd2),
    (0x3fe6a09e667f3bcc, 0x3fe6a09e667f3bcd),
    (0x3fe491b7523c161c, 0x3fe8836fa2cf5039),
    (0x3fe2cf2304755a5e, 0x3fe9e3779b97f4a8),
    (0x3fe14cedf8bb580b, 0x3feaeb8c8764f0ba),
    (0x3fdfffffffffffff, 0x3febb67ae8584cab),
    (0x3fddbe064267c47b, 0x3fec55a7e00740e9),
    (0x3fdbc4c04d71abc1, 0x3fecd4bca9cb5c71),
    (0x3fda07f921061ad0, 0x3fed3bc3aeff7f95),
    (0x3fd87de2a6aea963, 0x3fed906bcf328d46),
    (0x3fd71e955d8e7cdc, 0x3fedd6d000370991),
    (0x3fd5e3a8748a0bf5, 0x3fee11f642522d1c),
    (0x3fd4c7e04850cfa9, 0x3fee442285231be1),
    (0x3fd3c6ef372fe94f, 0x3fee6f0e134454ff),
    (0x3fd2dd44ce9afba7, 0x3fee940d6bb98cc5),
    (0x3fd207e7fd768dbf, 0x3feeb42a9bcd5057),
    (0x3fd14459ad2be466, 0x3feed037ea3d2dbc),
    (0x3fd0907dc1930690, 0x3feee8dd4748bf15),
    (0x3fcfd511fa1c0796, 0x3feefea21d101ee0),
    (0x3fcea1e54bc48dbe, 0x3fef11f493053d00),
    (0x3fcd84d223638000, 0x3fef232eff15c9e6),
    (0x3fcc7b90e3024582, 0x3fef329c0558e969),
    (0x3fcb8426c12812bc, 0x3fef4079c06c0992),
    (0x3fca9cd9ac4258f5, 0x3fef4cfc327a0080),
    (0x3fc9c4266041ca8e, 0x3fef584f2ce43b84),
    (0x3fc8f8b83c69a60a, 0x3fef6297cff75cb0),
];

/// Seals [`Scalar`]: the cell sampler's exactness argument rests on the rounding of the two
/// scalars zetafill implements, so no other crate can add one.
mod sealed {
    /// Implemented for `f64` and [`crate::Fixed`] only.
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for crate::fixed::Fixed {}
}

impl Scalar for f64 {
    /// From the table on hosts (a sine and a cosine less for each outline built: 4 to 10% of
    /// the instructions of a fill of stars, hexagons or triangles); a board computes them and
    /// keeps the flash.
    #[inline]
    fn turn_step(n: usize) -> (Self, Self) {
        match TURN_STEPS.get(n.wrapping_sub(3)) {
            Some(&(s, c)) if cfg!(not(target_os = "none")) => (f64::from_bits(s), f64::from_bits(c)),
            _ => libm::sincos(core::f64::consts::TAU / n as f64),
        }
    }
    #[inline]
    fn to_word(self) -> u64 {
        self.to_bits()
    }

    #[inline]
    fn from_word(w: u64) -> Self {
        f64::from_bits(w)
    }

    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const MAX_EXTENT: f64 = f64::MAX;
    const MIN_SIZE: f64 = 0.0;
    const MIN_SIZE_RELATIVE: f64 = 1.0 / 1_099_511_627_776.0;
    const IS_F64: bool = true;
    const OUTLINE_SLACK: [f64; 2] = [0.0, 0.0];
    const BOUND_SLACK: [f64; 2] = [1e-9, 1e-12];
    #[inline]
    fn from_f64(v: f64) -> Self {
        v
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline]
    fn sqrt(self) -> Self {
        if self > 0.0 {
            libm::sqrt(self)
        } else {
            0.0
        }
    }
    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        libm::sincos(self)
    }
    #[inline]
    fn floor_i64(self) -> i64 {
        // `as` truncates toward zero, saturates and maps NaN to 0: never panics. Correct the
        // truncation for negative non-integers; exact for every finite input.
        let t = self as i64;
        if (t as f64) > self {
            t.saturating_sub(1)
        } else {
            t
        }
    }
    #[inline]
    fn unit(bits: u64) -> Self {
        // The value is below 2^53, so the signed conversion is exact (and faster than u64).
        ((bits >> 11) as i64) as f64 * TWO_POW_M53
    }
    #[inline]
    fn digest_bits(self) -> u64 {
        if self == 0.0 {
            0
        } else {
            self.to_bits()
        }
    }
    #[inline]
    fn is_finite(self) -> bool {
        f64::is_finite(self)
    }
}

/// `x^y` in `f64` through `libm` (the one power function the core uses).
#[inline]
pub fn powf(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

/// Square root in `f64` through `libm`.
#[inline]
pub fn sqrtf(x: f64) -> f64 {
    libm::sqrt(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_covers_zero_and_stays_below_one() {
        assert_eq!(f64::unit(0), 0.0);
        assert!(f64::unit(u64::MAX) < 1.0);
        assert_eq!(f64::unit(u64::MAX), 1.0 - TWO_POW_M53);
    }

    #[test]
    fn digest_bits_canonicalise_negative_zero() {
        assert_eq!((-0.0f64).digest_bits(), 0.0f64.digest_bits());
        assert_ne!(1.0f64.digest_bits(), (-1.0f64).digest_bits());
    }

    /// The first `n` whose step in `table` (which starts at `n` = 3) differs from libm's.
    fn first_mismatch(table: &[(u64, u64)]) -> Option<usize> {
        (3..).zip(table).find_map(|(n, &(s, c))| {
            let (ls, lc) = libm::sincos(core::f64::consts::TAU / n as f64);
            ((s, c) != (ls.to_bits(), lc.to_bits())).then_some(n)
        })
    }

    #[test]
    fn the_turn_steps_are_libms_bits() {
        assert_eq!(first_mismatch(&TURN_STEPS), None);
        let mut broken = TURN_STEPS;
        broken[7].1 ^= 1;
        assert_eq!(first_mismatch(&broken), Some(10));
        // Inside the table and past it, the step is libm's.
        for n in 1..=40usize {
            let (s, c) = libm::sincos(core::f64::consts::TAU / n as f64);
            let (ts, tc) = f64::turn_step(n);
            assert_eq!((ts.to_bits(), tc.to_bits()), (s.to_bits(), c.to_bits()), "n = {n}");
        }
        // Fixed point computes its own, as before.
        assert_eq!(
            crate::Fixed::turn_step(5),
            crate::Fixed::from_f64(core::f64::consts::TAU / 5.0).sin_cos()
        );
    }

    #[test]
    fn floor_saturates_and_never_panics() {
        assert_eq!(f64::NAN.floor_i64(), 0);
        assert_eq!(f64::INFINITY.floor_i64(), i64::MAX);
        assert_eq!((-2.5f64).floor_i64(), -3);
    }
}
