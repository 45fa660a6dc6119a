//! The fixed-point scalar: [`Fixed`], 32.32 two's-complement fixed point for cores without an
//! FPU (Cortex-M0/M3), over `fixed::types::I32F32` from the `fixed` crate.
//!
//! The geometry is chosen by type: `Engine::<Fixed>` runs the same generic code as
//! `Engine::<f64>` with every operation below in integer arithmetic. No f64 code path changes.
//!
//! ## Range, resolution and supported regions
//! - Values: `[-2^31, 2^31 - 2^-32]`, about ±2.1e9 (mm); resolution `2^-32` ≈ 2.3e-10 mm.
//! - The geometry squares lengths (squared distances, `reach²`), so lengths must stay below
//!   `sqrt(2^31)` ≈ 46,000 mm for exact answers. **Supported regions: sides from about 1 mm up
//!   to 10,000 mm** (a diagonal of 14,142 mm squares to 2e8, a tenth of the range). The
//!   circle-against-polygon and gap tests square a cross product (a length to the fourth
//!   power), exact while a polygon's half size stays below about 150 mm; beyond that the value
//!   saturates, which makes the test *conservative* (a valid candidate may be rejected, an
//!   overlap is never accepted).
//! - Small shapes: a squared length has an absolute resolution of `2^-32` mm², so touching
//!   decisions are exact to about `1e-7` mm for 1 µm shapes; keep shapes above 10 µm.
//!
//! ## Arithmetic (deterministic on every target: integers only)
//! - `+ - neg` saturate; `*` is the `fixed` crate's saturating multiply (exact 128-bit
//!   product, rounded toward −∞); `/` is its saturating divide, and division by zero gives
//!   the saturated value of the dividend's sign (0 / 0 = 0): nothing panics.
//! - `sqrt`: the floor of the exact square root, `isqrt(raw << 32)` (0 for input <= 0).
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
}
