//! The Hurwitz zeta function zeta(s, a) = sum_{i>=0} (i+a)^(-s), its partial sums, and a table
//! of precomputed values.
//!
//! The method is Euler–Maclaurin summation: the first terms up to a + m >= 12 are added
//! directly (smallest first), the rest is the Euler–Maclaurin expansion with ten Bernoulli
//! terms. Relative error is below 1e-13 for s in (1, 4] and a in (0, 10^6] (tested against
//! 50-digit values from mpmath, `core/tests/data/`). Only `libm` and IEEE basic operations are
//! used, so every target computes the same bits.
//!
//! The table (`ZETA_TABLE`) is generated at build time by `build.rs` from this same code, for
//! c = 1.01, 1.02, ..., 1.60 and 1.65, 1.70, ..., 2.00 and N in {1, 2, 3, 4, 5, 10}; firmware
//! that uses those parameters does no series evaluation at start-up. A test checks that every
//! table entry equals the run-time value bit for bit.
//!
//! Nothing here panics: invalid arguments give a [`ZetaError`].

include!("zeta_math.rs");

include!(concat!(env!("OUT_DIR"), "/zeta_table.rs"));

/// What was wrong with the arguments of a zeta computation ([`crate::AreaSequence::new`]).
///
/// # Examples
///
/// ```
/// use zetafill::{AreaSequence, ZetaError};
///
/// assert_eq!(AreaSequence::new(100.0, 1.0, 1.0).err(), Some(ZetaError::Exponent));
/// assert_eq!(AreaSequence::new(100.0, 1.3, 0.0).err(), Some(ZetaError::Offset));
/// assert_eq!(AreaSequence::new(100.0, 4.0, 1e-90).err(), Some(ZetaError::Overflow));
/// assert_eq!(ZetaError::Exponent.to_string(), "the exponent must be a finite number greater than 1");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ZetaError {
    /// The exponent must be finite and greater than 1 (greater than 0 for partial sums).
    Exponent,
    /// The offset must be finite and greater than 0.
    Offset,
    /// The value overflows `f64` (offset too close to zero for this exponent).
    Overflow,
}

impl core::fmt::Display for ZetaError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ZetaError::Exponent => f.write_str("the exponent must be a finite number greater than 1"),
            ZetaError::Offset => f.write_str("the offset N must be a finite number greater than 0"),
            ZetaError::Overflow => f.write_str("zeta overflows: the offset N is too small for this exponent"),
        }
    }
}

impl core::error::Error for ZetaError {}

fn check_offset(a: f64) -> Result<(), ZetaError> {
    if a.is_finite() && a > 0.0 {
        Ok(())
    } else {
        Err(ZetaError::Offset)
    }
}

fn check_result(v: f64) -> Result<f64, ZetaError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(ZetaError::Overflow)
    }
}

/// The Hurwitz zeta function zeta(s, a), computed by series (never from the table).
pub fn hurwitz_zeta(s: f64, a: f64) -> Result<f64, ZetaError> {
    if !(s.is_finite() && s > 1.0) {
        return Err(ZetaError::Exponent);
    }
    check_offset(a)?;
    check_result(hurwitz_raw(s, a))
}

/// zeta(s, a) from the precomputed table when (s, a) is on its grid, else by series.
/// Both give the same bits.
pub fn zeta(s: f64, a: f64) -> Result<f64, ZetaError> {
    match table_lookup(s, a) {
        Some(v) => Ok(v),
        None => hurwitz_zeta(s, a),
    }
}

/// The table entry for exactly (s, a), if there is one.
pub fn table_lookup(s: f64, a: f64) -> Option<f64> {
    let (sb, ab) = (s.to_bits(), a.to_bits());
    ZETA_TABLE.iter().find(|e| e.0 == sb && e.1 == ab).map(|e| f64::from_bits(e.2))
}

/// The precomputed table as (s, a, zeta(s, a)) bit patterns.
pub fn table() -> &'static [(u64, u64, u64)] {
    &ZETA_TABLE
}

/// The partial sum sum_{k=0}^{n} (a+k)^(-s) for any finite s > 0 (including s <= 1, where the
/// infinite series diverges) and finite a > 0. Terms up to a+k = 12+64 are added directly, the
/// rest by Euler–Maclaurin, so the cost does not grow with n.
pub fn partial_sum(s: f64, a: f64, n: u64) -> Result<f64, ZetaError> {
    if !(s.is_finite() && s > 0.0) {
        return Err(ZetaError::Exponent);
    }
    check_offset(a)?;
    check_result(partial_raw(s, a, n))
}

/// The tail sum_{k>n} (a+k)^(-s) = zeta(s, a+n+1), without cancellation.
pub fn tail_sum(s: f64, a: f64, n: u64) -> Result<f64, ZetaError> {
    check_offset(a)?;
    hurwitz_zeta(s, a + (n as f64) + 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn riemann_values() {
        let z2 = hurwitz_zeta(2.0, 1.0).unwrap_or(0.0);
        assert!((z2 - core::f64::consts::PI * core::f64::consts::PI / 6.0).abs() < 1e-15);
    }

    #[test]
    fn bad_arguments_are_errors() {
        assert_eq!(hurwitz_zeta(1.0, 1.0), Err(ZetaError::Exponent));
        assert_eq!(hurwitz_zeta(f64::NAN, 1.0), Err(ZetaError::Exponent));
        assert_eq!(hurwitz_zeta(1.3, 0.0), Err(ZetaError::Offset));
        assert_eq!(hurwitz_zeta(1.3, f64::INFINITY), Err(ZetaError::Offset));
        assert_eq!(hurwitz_zeta(4.0, 1e-300), Err(ZetaError::Overflow));
        assert_eq!(partial_sum(0.0, 1.0, 3), Err(ZetaError::Exponent));
    }

    #[test]
    fn table_equals_series_bit_for_bit() {
        assert!(table().len() >= 400);
        for &(s, a, z) in table() {
            let v = hurwitz_zeta(f64::from_bits(s), f64::from_bits(a));
            assert_eq!(v.map(f64::to_bits), Ok(z), "s={} a={}", f64::from_bits(s), f64::from_bits(a));
        }
    }

    #[test]
    fn table_is_used_for_grid_points() {
        assert!(table_lookup(1.3, 1.0).is_some());
        assert!(table_lookup(1.30000001, 1.0).is_none());
        assert_eq!(zeta(1.3, 1.0), hurwitz_zeta(1.3, 1.0));
    }

    #[test]
    fn partial_plus_tail_is_zeta() {
        for &(s, a, n) in &[(1.3, 1.0, 5u64), (1.3, 1.0, 100_000), (2.0, 0.5, 1000)] {
            let p = partial_sum(s, a, n).unwrap_or(0.0);
            let t = tail_sum(s, a, n).unwrap_or(0.0);
            let z = hurwitz_zeta(s, a).unwrap_or(1.0);
            assert!(((p + t) - z).abs() / z < 1e-14);
        }
    }
}
