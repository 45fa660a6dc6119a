//! The fixed-point scalar: [`Fixed`], 32.32 two's-complement fixed point for cores without an
//! FPU (Cortex-M0/M3), over `fixed::types::I32F32` from the `fixed` crate.
//!
//! The geometry is chosen by type: `Engine::<Fixed>` runs the same generic code as
//! `Engine::<f64>` with every operation below in integer arithmetic. No f64 code path changes.
//!
//! ## Range, resolution and the limits the engines enforce
//! - Values: `[-2^31, 2^31 - 2^-32]`, about ±2.1e9 (mm); resolution `2^-32` ≈ 2.3e-10 mm.
//! - **Regions: sides of at most 10,000 mm, lying within 10,000 mm of the origin**
//!   ([`Scalar::MAX_EXTENT`]; [`crate::Engine::new`] and [`crate::line::Engine::new`] refuse
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
//! Results on [`Fixed`] differ from those on `f64` (the determinism contract: each scalar is deterministic on
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
pub struct Fixed(pub(crate) I32F32);

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
mod tests;
