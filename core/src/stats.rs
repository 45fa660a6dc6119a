//! The statistics of the papers: the dimensionless average gasket width `b(c, N, n)` (Shier
//! and Bourke, "An Algorithm for Random Fractal Filling of Space", section 4, eq. 8, Table 1), the exact fractal dimension, the hard limits on c set by
//! the first two shapes (section 3), and a least-squares fit for power laws.
//!
//! Everything is computed from the Hurwitz zeta function and its partial sums
//! ([`crate::internals::zeta`]), with `libm` only; nothing here allocates or panics.
//!
//! ## The gasket width and its index convention
//! Eq. 8 as printed sums over `i = 0..=n` and divides by the radius of circle `n + 1`. Table 1
//! does not follow that reading: its values are those of `n` *placements* done, the shapes
//! `0, 1, ..., n - 1`, with the next circle being number `n`:
//!
//! ```text
//! b(c, N, n) = 1/4 * (zeta(c, N) - sum_{i=0}^{n-1} (i+N)^-c)
//!                  / ((n+N)^(-c/2) * sum_{i=0}^{n-1} (i+N)^(-c/2))      (n >= 1)
//! ```
//!
//! that is eq. 8 evaluated at `n - 1`. This reproduces all 24 values of Table 1 to its four
//! decimals; the printed indexing misses most of them (`core/tests/stats.rs` checks both).
//! The numerator is the tail `zeta(c, N + n)` ([`crate::zeta::tail_sum`]), so there is no
//! cancellation however large `n` is; the sum of `(i+N)^(-c/2)` (exponent below 1, a
//! divergent series) is [`crate::zeta::partial_sum`], Euler–Maclaurin beyond its first terms.

use crate::zeta::{self, ZetaError};

/// Why a gasket width could not be computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GasketError {
    /// c or N is out of range (see [`ZetaError`]).
    Zeta(ZetaError),
    /// `n` must be at least 1: before the first placement there is no perimeter.
    NoPlacement,
}

impl core::fmt::Display for GasketError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            GasketError::Zeta(e) => write!(f, "{e}"),
            GasketError::NoPlacement => f.write_str("n must be at least 1 (no perimeter before the first placement)"),
        }
    }
}

impl From<ZetaError> for GasketError {
    fn from(e: ZetaError) -> Self {
        GasketError::Zeta(e)
    }
}

/// The dimensionless average gasket width `b(c, N, n)` for circles once `n >= 1` placements
/// are done (Table 1's convention; see the module docs). `c > 1`, `N > 0`.
pub fn gasket_width(c: f64, n_offset: f64, n: u64) -> Result<f64, GasketError> {
    if !(c.is_finite() && c > 1.0) {
        return Err(ZetaError::Exponent.into());
    }
    let last = n.checked_sub(1).ok_or(GasketError::NoPlacement)?;
    // zeta(c, N) - sum_{i<n} (i+N)^-c = zeta(c, N + n), without cancellation.
    let tail = zeta::tail_sum(c, n_offset, last)?;
    let radii = zeta::partial_sum(c / 2.0, n_offset, last)?;
    let next = n as f64 + n_offset;
    // (n+N)^(-c/2) in the denominator, written as a factor (n+N)^(c/2) above.
    let b = 0.25 * tail * libm::pow(next, c / 2.0) / radii;
    if b.is_finite() {
        Ok(b)
    } else {
        Err(ZetaError::Overflow.into())
    }
}

/// The exact fractal dimension `D = d / c` of a fill in `d` dimensions (1, 2 or 3): the area
/// (length, volume) sequence is an exact power law (section 5).
pub fn exact_dimension(c: f64, d: u32) -> f64 {
    f64::from(d) / c
}

/// The exponent c for a fractal dimension `D` in `d` dimensions: `c = d / D`.
pub fn c_for_dimension(dim: f64, d: u32) -> f64 {
    f64::from(d) / dim
}

/// The shapes for which [`pair_limit`] knows the geometry of the first two placements.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PairShape {
    /// Axis-aligned squares in a square: both fit only if `s_0 + s_1 <= W` (opposite corners).
    Square,
    /// Circles in a square: both fit only if `r_0 + r_1 <= (2 - sqrt 2) W` (opposite corners).
    Circle,
}

/// Whether shapes 0 and 1 can both lie in a unit-area square (inclusive boundary) at `(c, N)`.
fn pair_fits(shape: PairShape, c: f64, n_offset: f64) -> Result<bool, ZetaError> {
    let z = zeta::zeta(c, n_offset)?;
    // Linear size of shape i in a square of side 1: sqrt(A_i) up to the shape's constant.
    let a0 = libm::pow(n_offset, -c) / z;
    let a1 = libm::pow(n_offset + 1.0, -c) / z;
    Ok(match shape {
        PairShape::Square => libm::sqrt(a0) + libm::sqrt(a1) <= 1.0,
        PairShape::Circle => {
            let r = |a: f64| libm::sqrt(a / core::f64::consts::PI);
            r(a0) + r(a1) <= 2.0 - core::f64::consts::SQRT_2
        }
    })
}

/// The exponent above which the first two shapes (axis-aligned, inclusive boundary, square
/// region) cannot both be placed, so every run halts at placement 1: the hard upper limit of
/// section 3 (1.5224 for squares with N = 1). Found by bisection in `(1, 8]` to 1e-12;
/// `None` when the pair still fits at c = 8.
pub fn pair_limit(shape: PairShape, n_offset: f64) -> Result<Option<f64>, ZetaError> {
    if !(n_offset.is_finite() && n_offset > 0.0) {
        return Err(ZetaError::Offset);
    }
    let (mut lo, mut hi) = (1.0 + 1e-9, 8.0);
    if pair_fits(shape, hi, n_offset)? {
        return Ok(None);
    }
    if !pair_fits(shape, lo, n_offset)? {
        return Ok(Some(lo));
    }
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if pair_fits(shape, mid, n_offset)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(0.5 * (lo + hi)))
}

/// The least-squares line `y = slope * x + intercept` through `points`; `None` with fewer than
/// two distinct x or a non-finite result.
pub fn least_squares(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return None;
    }
    let (sx, sy) = points.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n, sy / n);
    let (mut sxx, mut sxy) = (0.0, 0.0);
    for &(x, y) in points {
        sxx += (x - mx) * (x - mx);
        sxy += (x - mx) * (y - my);
    }
    if sxx.is_nan() || sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    (slope.is_finite() && intercept.is_finite()).then_some((slope, intercept))
}

/// The exponent `k` of a power law `y = a x^k` fitted by least squares on log-log axes
/// (natural logs). Points with a non-positive or non-finite coordinate are skipped; `None`
/// with fewer than two distinct usable x.
pub fn power_law_exponent(points: &[(f64, f64)]) -> Option<f64> {
    let usable = |p: &&(f64, f64)| p.0 > 0.0 && p.1 > 0.0 && p.0.is_finite() && p.1.is_finite();
    let logs = || points.iter().filter(usable).map(|p| (libm::log(p.0), libm::log(p.1)));
    let n = logs().count();
    if n < 2 {
        return None;
    }
    let (sx, sy) = logs().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n as f64, sy / n as f64);
    let (sxx, sxy) = logs().fold((0.0, 0.0), |(a, b), (x, y)| (a + (x - mx) * (x - mx), b + (x - mx) * (y - my)));
    let k = sxy / sxx;
    (sxx > 0.0 && k.is_finite()).then_some(k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn least_squares_recovers_a_line() {
        let pts = [(1.0, 3.0), (2.0, 5.0), (3.0, 7.0)];
        assert_eq!(least_squares(&pts), Some((2.0, 1.0)));
        assert_eq!(least_squares(&pts[..1]), None);
        assert_eq!(least_squares(&[(1.0, 1.0), (1.0, 2.0)]), None);
    }

    #[test]
    fn power_law_exponent_recovers_exponents() {
        let pts: [(f64, f64); 999] = core::array::from_fn(|i| ((i + 1) as f64, 3.0 * libm::pow((i + 1) as f64, 1.37)));
        let k = power_law_exponent(&pts);
        assert!(k.is_some_and(|k| (k - 1.37).abs() < 1e-9), "{k:?}");
    }

    #[test]
    fn bad_arguments_are_errors() {
        assert_eq!(gasket_width(1.0, 1.0, 10), Err(GasketError::Zeta(ZetaError::Exponent)));
        assert_eq!(gasket_width(f64::NAN, 1.0, 10), Err(GasketError::Zeta(ZetaError::Exponent)));
        assert_eq!(gasket_width(1.3, 0.0, 10), Err(GasketError::Zeta(ZetaError::Offset)));
        assert_eq!(gasket_width(1.3, 1.0, 0), Err(GasketError::NoPlacement));
        assert_eq!(pair_limit(PairShape::Square, -1.0), Err(ZetaError::Offset));
    }
}
