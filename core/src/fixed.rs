//! The fixed-point scalar: [`Fixed`], 32.32 two's-complement fixed point for cores without an
//! FPU (Cortex-M0/M3), over `fixed::types::I32F32` from the `fixed` crate.
//!
//! The geometry is chosen by type: `Engine::<Fixed>` runs the same generic code as
//! `Engine::<f64>` with every operation below in integer arithmetic. No f64 code path changes.
//!
//! ## Range, resolution and the limits the engines enforce
//! - Values: `[-2^31, 2^31 - 2^-32]`, about ±2.1e9 (mm); resolution `2^-32` ≈ 2.3e-10 mm.
//! - **Regions: sides of at most 10,000 mm, lying within 10,000 mm of the origin**
//!   ([`Scalar::MAX_EXTENT`]; [`crate::Engine::new`] and [`crate::LineEngine::new`] refuse
//!   a larger one with [`crate::ParamError::Extent`]). The geometry squares lengths; across
//!   such a region (with a torus's images one period away) every product the tests and the
//!   cell sampler form stays below 10^9 mm², under half the range, so nothing saturates (a
//!   unit test counts saturated products through fills of every kind at that size). The
//!   squared cross product of a point's distance to an edge, a length to the fourth power, is
//!   formed exactly in 128 bits ([`Scalar::mul_div`]). Beyond the limit squares saturate and
//!   the tests stop being tests: 2,000 squares in a 500 m square overlapped by tens of metres.
//! - **Shapes: at most 10,000 mm across** (the diameter of the bounding circle, at most
//!   [`Scalar::MAX_EXTENT`]): only a torus lets a larger one in, wrapped around it, and its
//!   squared lengths saturate (a bar 127 m long on a 10 m torus was placed across a disc's
//!   image). The engines stop at one with [`crate::StepError::TooLarge`], and
//!   [`crate::check_largest`] finds it before a run.
//! - **Shapes: at least 10 µm wide** ([`Scalar::MIN_SIZE`]; the engines stop at a narrower
//!   one with [`crate::StepError::TooSmall`], and [`crate::check_smallest`] finds it before a
//!   run). The exact tests compare squared lengths and cross products to a resolution of
//!   `2^-32` mm²: they decide touching to within `2^-32 / w` mm for shapes `w` wide, 2.3e-8 mm
//!   at 10 µm, and a point inside a polygon is placed to within 1e-6 mm of an edge at least
//!   1e-3 mm long (the shortest of a 10 µm shape's edges). A polygon's drawn vertices lie up
//!   to 4.2e-9 of its size outside its exact outline (the rounded sine, cosine and vertices):
//!   its bounding radius grows by [`Scalar::OUTLINE_SLACK`], so that the tests that skip a
//!   pair whose bounding circles are apart never skip an overlap.
//! - The cell sampler's bounds on the clearance must never fall below the truth: their
//!   distances are rounded up ([`Scalar::dist2_up`], [`Scalar::seg_dist2_up`]: exact
//!   128-bit squares and cross products), its cells halve exactly ([`Scalar::grid_step`]), and
//!   what remains (floors of `sqrt` and `half`, the outline's departure from the inscribed
//!   radius) is covered by [`Scalar::BOUND_SLACK`].
//!
//! ## Arithmetic (deterministic on every target: integers only)
//! - `+ - neg` saturate; `*` is the `fixed` crate's saturating multiply (exact 128-bit
//!   product, rounded toward −∞); `/` is its saturating divide, and division by zero gives
//!   the saturated value of the dividend's sign (0 / 0 = 0): nothing panics.
//! - `sqrt`: the floor of the exact square root, `isqrt(raw << 32)` (0 for input <= 0).
//! - `mul_div`: the exact 128-bit product divided, rounded toward −∞, saturating;
//!   `dist2_up` and `seg_dist2_up`: exact squares and cross products in 128-bit integers,
//!   rounded up; `grid_step`: rounded up to a multiple of `2^halvings` raw units.
//! - `sin_cos`: the angle is reduced to a 32-bit phase in turns (`angle · 2^32 / 2π`, with a
//!   64-bit constant, exact modulo one turn), folded to `[0, π/4]`, evaluated by Taylor
//!   polynomials of degree 11 and 12 in 1.31 fixed point; error below 5e-9 (tested).
//! - `from_f64`: the `fixed` crate's conversion, rounding to nearest, ties to even, saturating
//!   (NaN gives 0); integer-only (it decodes the IEEE bits). `to_f64` is exact below 2^21 and
//!   rounds to nearest otherwise.
//! - `unit(bits)` (the [`crate::internals::rng`] mapping): the top 32 of the 64 random bits are the
//!   fraction, `u = (bits >> 32) · 2^-32`, in `[0, 1 - 2^-32]`.
//! - `digest_bits`: the raw two's-complement bits as `u64` (there is no negative zero).
//! - `floor_i64`: the integer part, `raw >> 32` (toward −∞).
//!
//! Results on [`Fixed`] differ from those on `f64` (DESIGN: each scalar is deterministic on
//! every target; results may differ between scalars).

use crate::geom::Point;
use crate::scalar::Scalar;
use ::fixed::types::I32F32;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// A 32.32 fixed-point number (see the module documentation for range and resolution).
///
/// # Examples
///
/// A fill on the fixed-point scalar, as a core without an FPU runs it: chosen by type, the
/// same code, integer arithmetic only; the same seed gives the same bits on every target.
///
/// ```
/// use zetafill::digest::engine_digest;
/// use zetafill::{index_words, rng_from_seed, Engine, Fixed, Params, Placed, Region, Scalar, Stop, StopReason, Storage};
///
/// fn fill(seed: u64) -> (StopReason, Vec<Placed<Fixed>>, (u64, u64)) {
///     let mut shapes = [Placed::<Fixed>::default(); 100];
///     let mut index = [0u32; index_words(100)];
///     let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
///     let region = Region::Rect { width: 200.0, height: 200.0, periodic: false };
///     let mut engine = Engine::<Fixed>::new(Params::circles(1.3, 1.0), region, storage).expect("valid");
///     let reason = engine.run(&mut rng_from_seed(seed), &Stop { count: Some(100), ..Stop::default() }, |_| {});
///     (reason, engine.placed().to_vec(), engine_digest(&engine))
/// }
/// let (reason, circles, digest) = fill(1);
/// assert_eq!(reason, StopReason::Count);
/// assert_eq!(digest, fill(1).2);
/// for c in &circles {
///     let (x, y, r) = (c.x.to_f64(), c.y.to_f64(), c.scale.to_f64());
///     assert!(x >= r && x <= 200.0 - r && y >= r && y <= 200.0 - r);
/// }
/// // Exact integer arithmetic: the square root is the floor of the exact one.
/// let two = Fixed::from_f64(2.0);
/// assert!((two.sqrt().to_f64() - 2f64.sqrt()).abs() < 1e-9);
/// assert_eq!(Fixed::from_f64(0.5).to_bits(), 1 << 31);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Fixed(pub I32F32);

impl Fixed {
    /// The largest value, 2^31 - 2^-32.
    pub const MAX: Fixed = Fixed(I32F32::MAX);
    /// The smallest value, -2^31.
    pub const MIN: Fixed = Fixed(I32F32::MIN);
    /// The resolution, 2^-32.
    pub const DELTA: Fixed = Fixed(I32F32::DELTA);

    /// The value whose raw two's-complement bits are `bits` (value = bits · 2^-32).
    #[inline]
    pub const fn from_bits(bits: i64) -> Self {
        Fixed(I32F32::from_bits(bits))
    }

    /// The raw two's-complement bits (value = bits · 2^-32).
    #[inline]
    pub const fn to_bits(self) -> i64 {
        self.0.to_bits()
    }
}

impl Add for Fixed {
    type Output = Fixed;
    #[inline]
    fn add(self, o: Fixed) -> Fixed {
        Fixed(self.0.saturating_add(o.0))
    }
}

impl Sub for Fixed {
    type Output = Fixed;
    #[inline]
    fn sub(self, o: Fixed) -> Fixed {
        Fixed(self.0.saturating_sub(o.0))
    }
}

impl Mul for Fixed {
    type Output = Fixed;
    #[inline]
    fn mul(self, o: Fixed) -> Fixed {
        #[cfg(test)]
        tally::note(self.0.checked_mul(o.0).is_none());
        Fixed(self.0.saturating_mul(o.0))
    }
}

impl Div for Fixed {
    type Output = Fixed;
    #[inline]
    fn div(self, o: Fixed) -> Fixed {
        if o.0 == I32F32::ZERO {
            return if self.0 > I32F32::ZERO {
                Fixed::MAX
            } else if self.0 < I32F32::ZERO {
                Fixed::MIN
            } else {
                Fixed(I32F32::ZERO)
            };
        }
        #[cfg(test)]
        tally::note(self.0.checked_div(o.0).is_none());
        Fixed(self.0.saturating_div(o.0))
    }
}

impl Neg for Fixed {
    type Output = Fixed;
    #[inline]
    fn neg(self) -> Fixed {
        Fixed(self.0.saturating_neg())
    }
}

/// `c` in 1.31 fixed point, rounded to nearest (compile time only).
const fn q31(num: i64, den: i64) -> i64 {
    ((num << 31) + den / 2) / den
}

const Q31_ONE: i64 = 1 << 31;
/// round(2^64 / 2π): radians in 32.32 to turns in 0.64, keeping the top 32 bits of the turn.
const TURNS_PER_RADIAN_Q64: i128 = 2_935_890_503_282_001_226;
/// round(π · 2^32).
const PI_Q32: u64 = 13_493_037_705;

/// Product of two 1.31 values (|a|, |b| <= 2^31), rounded to nearest.
#[inline]
fn mul31(a: i64, b: i64) -> i64 {
    (a * b + (1 << 30)) >> 31
}

/// sin and cos of `theta` in `[0, π/4]`, all in 1.31 fixed point.
fn sin_cos_octant(theta: i64) -> (i64, i64) {
    const S: [i64; 5] = [q31(1, 6), q31(1, 120), q31(1, 5040), q31(1, 362_880), q31(1, 39_916_800)];
    const C: [i64; 6] = [
        q31(1, 2),
        q31(1, 24),
        q31(1, 720),
        q31(1, 40_320),
        q31(1, 3_628_800),
        q31(1, 479_001_600),
    ];
    let t = mul31(theta, theta);
    // sin θ = θ (1 - t/6 + t²/120 - ...), Horner from the highest term, alternating signs.
    let mut acc = 0i64;
    for (k, c) in S.iter().enumerate().rev() {
        let c = if k % 2 == 0 { -*c } else { *c };
        acc = c + mul31(acc, t);
    }
    let sin = mul31(theta, Q31_ONE + mul31(acc, t));
    let mut acc = 0i64;
    for (k, c) in C.iter().enumerate().rev() {
        let c = if k % 2 == 0 { -*c } else { *c };
        acc = c + mul31(acc, t);
    }
    let cos = Q31_ONE + mul31(acc, t);
    (sin.clamp(-Q31_ONE, Q31_ONE), cos.clamp(-Q31_ONE, Q31_ONE))
}

/// `x² + y²` of raw values (each squared exactly), in units of 2^-64, saturated to `u128`.
#[inline]
fn raw_sq_sum(x: i128, y: i128) -> u128 {
    let sq = |v: i128| {
        let a = v.unsigned_abs();
        a.saturating_mul(a)
    };
    sq(x).saturating_add(sq(y))
}

/// A value in units of 2^-64 as a [`Fixed`] (units of 2^-32), rounded up and saturated.
#[inline]
fn from_wide_up(v: u128) -> Fixed {
    let raw = (v >> 32) + u128::from(v & 0xffff_ffff != 0);
    Fixed::from_bits(i64::try_from(raw).unwrap_or(i64::MAX))
}

/// Differences of raw coordinates at least this large (2^30 mm, far beyond
/// [`Scalar::MAX_EXTENT`]) are not measured: the bound is then simply the largest value.
const FAR: i128 = 1 << 62;

impl Scalar for Fixed {
    #[inline]
    fn to_word(self) -> u64 {
        self.to_bits() as u64
    }

    #[inline]
    fn from_word(w: u64) -> Self {
        Fixed::from_bits(w as i64)
    }

    const ZERO: Self = Fixed(I32F32::ZERO);
    const ONE: Self = Fixed(I32F32::ONE);
    const MAX_EXTENT: f64 = 10_000.0;
    const MIN_SIZE: f64 = 0.01;
    /// Measured: vertices lie up to 4.2e-9 of the scale outside the exact outline (the 1.31
    /// sine and cosine, and the rotation that steps from vertex to vertex), and up to 2.2e-8 mm
    /// at 10 µm (a rectangle's bounding radius is a floored root of floored squares).
    const OUTLINE_SLACK: [f64; 2] = [1e-8, 1.0 / 16_777_216.0];
    /// A millionth of a millimetre and more (2^-18 mm, ~3.8e-6): the floors of `sqrt` and
    /// `half` and the cell corners' rounding (a few 2^-32 each), and the distance of a point to
    /// a polygon's edge in the few cases not rounded up (a point inside a shape, whose edges at
    /// the narrowest shape are at least 1e-3 mm long: below 1e-6 mm). And 1e-8 of the region:
    /// a polygon's drawn outline departs from the inscribed radius by up to 4e-9 of its size
    /// (the 1.31 sine and cosine).
    const BOUND_SLACK: [f64; 2] = [1e-8, 1.0 / 262_144.0];

    #[inline]
    fn from_f64(v: f64) -> Self {
        // NaN (exponent all ones, mantissa non-zero) maps to 0; the check is on the bits so
        // that no soft-float comparison is needed.
        if v.to_bits() & 0x7fff_ffff_ffff_ffff > 0x7ff0_0000_0000_0000 {
            return Fixed(I32F32::ZERO);
        }
        Fixed(I32F32::saturating_from_num(v))
    }

    #[inline]
    fn to_f64(self) -> f64 {
        self.0.to_num::<f64>()
    }

    fn sqrt(self) -> Self {
        let raw = self.to_bits();
        if raw <= 0 {
            return Fixed::ZERO;
        }
        // sqrt(raw · 2^-32) · 2^32 = sqrt(raw · 2^32); below 2^47.5, so the cast is exact.
        let root = ((raw as u128) << 32).isqrt();
        Fixed::from_bits(root as i64)
    }

    fn sin_cos(self) -> (Self, Self) {
        // The angle in turns, modulo one turn, as a 32-bit phase (two's complement wraps).
        let phase = ((i128::from(self.to_bits()) * TURNS_PER_RADIAN_Q64) >> 64) as u32;
        let quadrant = phase >> 30;
        let r = u64::from(phase & ((1 << 30) - 1));
        // θ = r / 2^30 · π/2 radians; in 1.31 that is r · π. Fold to [0, π/4].
        let folded = r > 1 << 29;
        let r = if folded { (1 << 30) - r } else { r };
        let theta = ((r * PI_Q32) >> 32) as i64;
        let (s, c) = sin_cos_octant(theta);
        let (s, c) = if folded { (c, s) } else { (s, c) };
        let (s, c) = match quadrant {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        };
        // 1.31 to 32.32.
        (Fixed::from_bits(s << 1), Fixed::from_bits(c << 1))
    }

    #[inline]
    fn floor_i64(self) -> i64 {
        self.to_bits() >> 32
    }

    #[inline]
    fn unit(bits: u64) -> Self {
        Fixed::from_bits((bits >> 32) as i64)
    }

    #[inline]
    fn digest_bits(self) -> u64 {
        self.to_bits() as u64
    }

    #[inline]
    fn is_finite(self) -> bool {
        true
    }

    #[inline]
    fn half(self) -> Self {
        Fixed::from_bits(self.to_bits() >> 1)
    }

    /// The exact 128-bit product divided by `c`, rounded toward −∞ and saturated (`c = 0`
    /// as in `/`).
    fn mul_div(self, b: Self, c: Self) -> Self {
        let (a, b, c) = (i128::from(self.to_bits()), i128::from(b.to_bits()), i128::from(c.to_bits()));
        // |a|, |b| <= 2^63: the product fits.
        let p = a * b;
        if c == 0 {
            return Fixed::from_bits(p.signum() as i64) / Fixed::ZERO;
        }
        let q = p / c;
        let q = if p % c != 0 && ((p < 0) != (c < 0)) { q - 1 } else { q };
        #[cfg(test)]
        tally::note(i64::try_from(q).is_err());
        Fixed::from_bits(q.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64)
    }

    /// Exact squares of the raw values, their sum rounded up.
    fn dist2_up(x: Self, y: Self) -> Self {
        from_wide_up(raw_sq_sum(i128::from(x.to_bits()), i128::from(y.to_bits())))
    }

    /// In exact integers: the projection's position decides the branch, the distance to the
    /// line is `|cross| / |ab|` with the cross product exact, `|ab|` rounded down and the
    /// quotient rounded up, and no bound exceeds the nearer endpoint's (so a very short edge,
    /// whose line is poorly defined, is bounded by its endpoints).
    fn seg_dist2_up(p: Point<Self>, a: Point<Self>, b: Point<Self>) -> Self {
        let w = |v: Fixed| i128::from(v.to_bits());
        let (abx, aby) = (w(b.x) - w(a.x), w(b.y) - w(a.y));
        let (apx, apy) = (w(p.x) - w(a.x), w(p.y) - w(a.y));
        let (bpx, bpy) = (w(p.x) - w(b.x), w(p.y) - w(b.y));
        if [abx, aby, apx, apy, bpx, bpy].iter().any(|v| v.abs() >= FAR) {
            return Fixed::MAX;
        }
        // Below 2^125 each: no overflow.
        let (to_a, to_b) = (raw_sq_sum(apx, apy), raw_sq_sum(bpx, bpy));
        let len2 = abx * abx + aby * aby;
        let t = apx * abx + apy * aby;
        if t <= 0 || len2 == 0 {
            return from_wide_up(to_a);
        }
        if t >= len2 {
            return from_wide_up(to_b);
        }
        let cross = (abx * apy - aby * apx).unsigned_abs();
        // |ab| in units of 2^-32, rounded down: the root of len2 (units of 2^-64) cut to units
        // of 2^-32, through `sqrt` (which floors too).
        let Ok(len2) = i64::try_from(len2 >> 32) else {
            return Fixed::MAX;
        };
        let len = Fixed::from_bits(len2).sqrt().to_bits().unsigned_abs();
        // The distance to the line in units of 2^-32, rounded up.
        let d = cross.div_ceil(u128::from(len.max(1)));
        let line = if d >= 1 << 63 { u128::MAX } else { d * d };
        from_wide_up(line.min(to_a).min(to_b))
    }

    /// The raw quotient rounded up, then up to a multiple of `2^halvings` (saturating; `n = 0`
    /// counts as 1).
    fn grid_step(self, n: u32, halvings: u32) -> Self {
        let unit = 1i128 << halvings.min(62);
        let q = i128::from(self.to_bits()).div_euclid(i128::from(n.max(1)));
        let q = if q * i128::from(n.max(1)) < i128::from(self.to_bits()) {
            q + 1
        } else {
            q
        };
        let up = (q + unit - 1).div_euclid(unit) * unit;
        Fixed::from_bits(up.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64)
    }
}

/// Counts, per thread, the products and quotients that saturated (unit tests only): the
/// geometry must never saturate one within the supported range.
#[cfg(test)]
mod tally {
    extern crate std;

    std::thread_local! {
        static SATURATED: core::cell::Cell<u64> = const { core::cell::Cell::new(0) };
    }

    pub(super) fn note(saturated: bool) {
        if saturated {
            SATURATED.with(|c| c.set(c.get() + 1));
        }
    }

    /// The count so far, reset to zero.
    pub(super) fn take() -> u64 {
        SATURATED.with(|c| c.replace(0))
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::indexing_slicing, clippy::panic)]
mod tests {
    use super::*;

    fn f(v: f64) -> Fixed {
        Fixed::from_f64(v)
    }

    #[test]
    fn unit_uses_the_top_32_bits() {
        assert_eq!(Fixed::unit(0), Fixed::ZERO);
        assert_eq!(Fixed::unit(u64::MAX), Fixed::ONE - Fixed::DELTA);
        assert_eq!(Fixed::unit(1 << 63).to_f64(), 0.5);
        assert_eq!(Fixed::unit(0xffff_ffff), Fixed::ZERO);
    }

    #[test]
    fn conversions_round_and_saturate_without_panicking() {
        assert_eq!(f(f64::NAN), Fixed::ZERO);
        assert_eq!(f(f64::INFINITY), Fixed::MAX);
        assert_eq!(f(f64::NEG_INFINITY), Fixed::MIN);
        assert_eq!(f(1e300), Fixed::MAX);
        assert_eq!(f(-2.5).to_f64(), -2.5);
        assert_eq!(f(200.0).to_bits(), 200 << 32);
        assert_eq!(f(-0.0).digest_bits(), 0);
        // 0.1 rounds to the nearest multiple of 2^-32.
        assert!((f(0.1).to_f64() - 0.1).abs() <= 0.5 / 4_294_967_296.0);
    }

    #[test]
    fn arithmetic_saturates_and_division_by_zero_is_defined() {
        assert_eq!(Fixed::MAX + Fixed::ONE, Fixed::MAX);
        assert_eq!(Fixed::MIN - Fixed::ONE, Fixed::MIN);
        assert_eq!(-Fixed::MIN, Fixed::MAX);
        assert_eq!(f(70_000.0) * f(70_000.0), Fixed::MAX);
        assert_eq!(f(-70_000.0) * f(70_000.0), Fixed::MIN);
        assert_eq!(Fixed::ONE / Fixed::ZERO, Fixed::MAX);
        assert_eq!(-Fixed::ONE / Fixed::ZERO, Fixed::MIN);
        assert_eq!(Fixed::ZERO / Fixed::ZERO, Fixed::ZERO);
        assert_eq!(Fixed::MIN / -Fixed::DELTA, Fixed::MAX);
        assert_eq!(f(3.0) * f(-1.5), f(-4.5));
        assert_eq!(f(1.0) / f(4.0), f(0.25));
    }

    #[test]
    fn floor_and_half() {
        assert_eq!(f(-2.5).floor_i64(), -3);
        assert_eq!(f(2.999).floor_i64(), 2);
        assert_eq!(Fixed::MIN.floor_i64(), -(1 << 31));
        assert_eq!(f(3.0).half(), f(1.5));
    }

    #[test]
    fn sqrt_is_the_floor_of_the_exact_root() {
        assert_eq!(f(4.0).sqrt(), f(2.0));
        assert_eq!(f(-4.0).sqrt(), Fixed::ZERO);
        assert_eq!(Fixed::ZERO.sqrt(), Fixed::ZERO);
        for v in [2.0, 0.001, 12345.678, 2.0e9, 1e-9] {
            let r = f(v).sqrt();
            // r is the largest value with r² <= v (checked exactly in integers).
            let raw = i128::from(f(v).to_bits()) << 32;
            let rr = i128::from(r.to_bits());
            assert!(rr * rr <= raw && (rr + 1) * (rr + 1) > raw, "{v}");
            assert!((r.to_f64() - libm::sqrt(f(v).to_f64())).abs() <= 2.4e-10, "{v}");
        }
    }

    #[test]
    fn sin_cos_within_5e9_of_libm_for_every_quadrant_and_wrap() {
        let mut worst = 0.0f64;
        let mut a = -40.0;
        while a < 40.0 {
            let (s, c) = f(a).sin_cos();
            let x = f(a).to_f64();
            worst = worst.max((s.to_f64() - libm::sin(x)).abs()).max((c.to_f64() - libm::cos(x)).abs());
            a += 0.000_913;
        }
        assert!(worst < 5e-9, "worst error {worst}");
        assert_eq!(Fixed::ZERO.sin_cos(), (Fixed::ZERO, Fixed::ONE));
        let (s, c) = f(core::f64::consts::FRAC_PI_2).sin_cos();
        assert!((s - Fixed::ONE).abs() < f(5e-9) && c.abs() < f(5e-9));
        let (s, c) = Fixed::MAX.sin_cos();
        assert!(s.abs() <= Fixed::ONE && c.abs() <= Fixed::ONE);
    }

    #[test]
    fn digest_bits_are_the_raw_bits() {
        assert_eq!(f(1.0).digest_bits(), 1 << 32);
        assert_eq!(f(-1.0).digest_bits(), (-(1i64 << 32)) as u64);
    }

    #[test]
    fn engine_fills_without_overlap_on_fixed_point() {
        use crate::{index_words, Engine, Params, Placed, Region, Stop, Storage};
        let mut shapes = [Placed::<Fixed>::default(); 200];
        let mut index = [0u32; index_words(200)];
        let region = Region::Rect {
            width: 200.0,
            height: 200.0,
            periodic: false,
        };
        let storage = Storage {
            shapes: &mut shapes,
            index: &mut index,
            coverage: &mut [],
        };
        let mut e = Engine::<Fixed>::new(Params::circles(1.3, 1.0), region, storage).unwrap();
        let mut rng = crate::rng_from_seed(1);
        let stop = e.run(
            &mut rng,
            &Stop {
                count: Some(200),
                ..Stop::default()
            },
            |_| {},
        );
        assert_eq!(stop, crate::StopReason::Count);
        let placed = e.placed();
        for (i, p) in placed.iter().enumerate() {
            assert!(p.x - p.scale >= Fixed::ZERO && p.x + p.scale <= f(200.0), "{i}");
            for q in &placed[..i] {
                let (dx, dy, r) = (p.x - q.x, p.y - q.y, p.scale + q.scale);
                assert!(dx * dx + dy * dy > r * r, "{i} overlaps");
            }
        }
    }

    /// The exact quotient of two `i128` rationals rounded toward −∞, for checks.
    fn floor_div(p: i128, c: i128) -> i128 {
        p.div_euclid(c) - if c < 0 && p.rem_euclid(c) != 0 { 1 } else { 0 }
    }

    #[test]
    fn mul_div_keeps_the_product_exact() {
        // 10^6 x 10^6 / 10^6: the product alone would saturate.
        assert_eq!(f(1e6).mul_div(f(1e6), f(1e6)), f(1e6));
        assert_eq!(tally::take(), 0);
        assert_eq!(f(1e6) * f(1e6) / f(1e6), Fixed::MAX / f(1e6));
        assert_eq!(tally::take(), 1);
        assert_eq!(f(3.0).mul_div(f(-5.0), f(2.0)), f(-7.5));
        // Rounded toward −∞, like `*`.
        assert_eq!(Fixed::DELTA.mul_div(Fixed::DELTA, Fixed::ONE), Fixed::ZERO);
        assert_eq!((-Fixed::DELTA).mul_div(Fixed::DELTA, Fixed::ONE), -Fixed::DELTA);
        assert_eq!(f(2.0).mul_div(f(3.0), Fixed::ZERO), Fixed::MAX);
        assert_eq!(f(-2.0).mul_div(f(3.0), Fixed::ZERO), Fixed::MIN);
        assert_eq!(Fixed::ZERO.mul_div(f(3.0), Fixed::ZERO), Fixed::ZERO);
        assert_eq!(Fixed::MAX.mul_div(Fixed::MAX, Fixed::DELTA), Fixed::MAX);
        let mut s = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s as i64) >> (s % 40)
        };
        for _ in 0..10_000 {
            let (a, b, c) = (next(), next(), next());
            if c == 0 {
                continue;
            }
            let q = floor_div(i128::from(a) * i128::from(b), i128::from(c));
            let want = q.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64;
            let got = Fixed::from_bits(a).mul_div(Fixed::from_bits(b), Fixed::from_bits(c));
            assert_eq!(got.to_bits(), want, "{a} {b} {c}");
        }
        tally::take();
    }

    /// Exact `x² + y²` in units of 2^-64.
    fn exact_sq(x: Fixed, y: Fixed) -> i128 {
        let (x, y) = (i128::from(x.to_bits()), i128::from(y.to_bits()));
        x * x + y * y
    }

    #[test]
    fn dist2_up_is_the_ceiling() {
        for (x, y) in [(0.0, 0.0), (3.0, 4.0), (1e-9, 0.0), (-2.5e-5, 7e-6), (9999.123, -8765.4321)] {
            let d = Fixed::dist2_up(f(x), f(y));
            let exact = exact_sq(f(x), f(y));
            let raw = i128::from(d.to_bits()) << 32;
            assert!(raw >= exact && raw - exact < 1 << 32, "{x} {y}");
        }
        // The plain product rounds down: near zero its square root is far too small.
        let tiny = Fixed::from_bits(40_000);
        assert_eq!((tiny * tiny).sqrt(), Fixed::ZERO);
        assert!(Fixed::dist2_up(tiny, Fixed::ZERO).sqrt().to_bits() >= 40_000 - 1);
        assert_eq!(Fixed::dist2_up(Fixed::MAX, Fixed::MAX), Fixed::MAX);
    }

    #[test]
    fn seg_dist2_up_never_falls_below_the_exact_distance() {
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |scale: f64| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * scale
        };
        let mut tight = 0;
        for case in 0..20_000 {
            // Long and very short edges, points near and far, up to the supported range.
            let scale = [10_000.0, 100.0, 1e-3, 1e-7][case % 4];
            let a = Point::new(f(5000.0 + next(10_000.0)), f(5000.0 + next(10_000.0)));
            let b = Point::new(a.x + f(next(scale)), a.y + f(next(scale)));
            let p = Point::new(a.x + f(next(2.0 * scale)), a.y + f(next(2.0 * scale)));
            let up = Fixed::seg_dist2_up(p, a, b).to_f64();
            // The exact squared distance, from the exact (f64) coordinates, in f64.
            let g = |q: Point<Fixed>| (q.x.to_f64(), q.y.to_f64());
            let ((px, py), (ax, ay), (bx, by)) = (g(p), g(a), g(b));
            let (ex, ey) = (bx - ax, by - ay);
            let len2 = ex * ex + ey * ey;
            let t = if len2 > 0.0 {
                (((px - ax) * ex + (py - ay) * ey) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let (dx, dy) = (px - ax - t * ex, py - ay - t * ey);
            let exact = dx * dx + dy * dy;
            assert!(up >= exact * (1.0 - 1e-12), "case {case}: {up} < {exact}");
            if up <= exact * (1.0 + 1e-6) + 1e-8 {
                tight += 1;
            }
        }
        assert!(tight > 19_000, "the bound is loose: {tight}");
        // Beyond the range it is simply the largest value.
        let far = Point::new(Fixed::MAX, Fixed::MAX);
        let o = Point::new(Fixed::MIN, Fixed::MIN);
        assert_eq!(Fixed::seg_dist2_up(far, o, o), Fixed::MAX);
    }

    #[test]
    fn grid_steps_cover_and_halve_exactly() {
        for (w, n) in [(200.0, 16), (123.456_789, 16), (9_876.543_21, 13), (0.02, 1), (10_000.0, 16)] {
            let step = f(w).grid_step(n, 23);
            assert!(step.to_bits() % (1 << 23) == 0, "{w}");
            assert!(i128::from(step.to_bits()) * i128::from(n) >= i128::from(f(w).to_bits()), "{w}");
            assert!(step.to_f64() * f64::from(n) - w < f64::from(n) * 2.0f64.powi(-9), "{w}");
            let mut s = step;
            for _ in 0..23 {
                let h = s.half();
                assert_eq!(h + h, s);
                s = h;
            }
        }
        // A step that is already exact stays.
        assert_eq!(f(200.0).grid_step(16, 23), f(12.5));
        assert_eq!(200.0f64.grid_step(16, 23), 12.5);
    }

    /// No product or quotient saturates in fills at the largest supported size: every kind,
    /// in every kind of region 10,000 mm across, with and without a gap, with both samplers.
    /// (Before, a circle's distance to a polygon's edge squared a cross product of up to
    /// 10^8 mm², and it saturated.) The counter itself is seen to count above.
    #[test]
    fn nothing_saturates_within_the_supported_range() {
        use crate::{
            cells_for, index_words, rng_from_seed, CellSampler, Engine, Params, Placed, Point, PolygonRegion, Region, ShapeKind, Stop,
            Storage,
        };
        extern crate std;
        use std::vec;
        let hex: std::vec::Vec<Point<f64>> = (0..6)
            .map(|k| {
                let t = f64::from(k) * core::f64::consts::FRAC_PI_3 + 0.1;
                Point::new(5000.0 + 5000.0 * libm::cos(t), 5000.0 + 5000.0 * libm::sin(t))
            })
            .collect();
        let ends = [6];
        let poly = PolygonRegion::new(&hex, &ends).unwrap();
        let regions = [
            Region::Rect {
                width: 10_000.0,
                height: 10_000.0,
                periodic: false,
            },
            Region::Rect {
                width: 10_000.0,
                height: 7_777.7,
                periodic: true,
            },
            Region::Circle { radius: 5_000.0 },
            Region::Annulus {
                outer: 5_000.0,
                inner: 1_500.0,
            },
            Region::Polygon(poly),
        ];
        let kinds = [
            ShapeKind::Circle,
            ShapeKind::Square,
            ShapeKind::Rect { aspect: 3.0 },
            ShapeKind::Triangle,
            ShapeKind::Polygon { sides: 7 },
            ShapeKind::Star { points: 5, inner: 0.45 },
            ShapeKind::Ring { inner: 0.5 },
            ShapeKind::Blob { delta: 0.2 },
        ];
        tally::take();
        let n = 40;
        for (ri, region) in regions.iter().enumerate() {
            for (ki, &kind) in kinds.iter().enumerate() {
                for (gap, fast) in [(0.0, false), (0.0, true), (20.0, true)] {
                    let mut shapes = vec![Placed::<Fixed>::default(); n];
                    let mut index = vec![0u32; index_words(n)];
                    let mut coverage = vec![0u64; if fast { 0 } else { 4096 }];
                    let mut params = Params::circles(1.2, 3.0);
                    params.shape = kind.into();
                    params.rotate = true;
                    params.gap = gap;
                    params.max_trials = 100_000;
                    let storage = Storage {
                        shapes: &mut shapes,
                        index: &mut index,
                        coverage: &mut coverage,
                    };
                    let mut e = Engine::<Fixed>::new(params, *region, storage).unwrap();
                    let mut rng = rng_from_seed(ri as u64 * 10 + ki as u64);
                    let stop = Stop {
                        count: Some(n as u64),
                        ..Stop::default()
                    };
                    if fast {
                        let mut pool = vec![[0u64; 4]; cells_for(n)];
                        let mut cells = CellSampler::new(&mut pool).unwrap();
                        e.run_fast(&mut cells, &mut rng, &stop, |_| {});
                    } else {
                        e.run(&mut rng, &stop, |_| {});
                    }
                    assert!(e.placed().len() >= 10, "{kind:?} in region {ri}: {}", e.placed().len());
                    assert_eq!(
                        tally::take(),
                        0,
                        "{kind:?} in region {ri}, gap {gap}, cells {fast}: a value saturated"
                    );
                }
            }
        }
    }

    /// Every vertex of every polygon drawn on fixed point lies within its bounding radius, from
    /// 5 µm to 9 m, at 2,000 angles: the exact tests skip a pair whose bounding circles are
    /// apart. (Before, vertices lay up to 4e-9 of the scale outside, 2e-5 mm for a 5 m
    /// polygon: two drawn that way, vertex to vertex, could overlap unseen.)
    #[test]
    fn polygons_lie_within_their_bounding_radius() {
        use crate::ShapeKind;
        let kinds = [
            ShapeKind::Square,
            ShapeKind::Rect { aspect: 2.5 },
            ShapeKind::Rect { aspect: 0.1 },
            ShapeKind::Triangle,
            ShapeKind::Polygon { sides: 7 },
            ShapeKind::Polygon { sides: 32 },
            ShapeKind::Star { points: 5, inner: 0.45 },
            ShapeKind::Star { points: 16, inner: 0.9 },
            ShapeKind::Blob { delta: 0.2 },
        ];
        let c = Point::new(f(4321.123), f(1234.567));
        for kind in kinds {
            for scale in [0.005, 0.05, 1.0, 37.3, 700.0, 5000.0, 9000.0] {
                let s = f(scale);
                let r = i128::from(kind.bounding_radius(s).to_bits());
                for i in 0..2000 {
                    let angle = f(f64::from(i) * 0.003_141 + 0.000_1);
                    for v in kind.geo(c, s, angle).vertices() {
                        // Exactly, in integers.
                        let (dx, dy) = (i128::from((v.x - c.x).to_bits()), i128::from((v.y - c.y).to_bits()));
                        assert!(dx * dx + dy * dy <= r * r, "{kind:?} at {scale} mm, angle {i}");
                    }
                }
            }
        }
    }
}
