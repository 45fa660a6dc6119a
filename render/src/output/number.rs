//! Numbers as text, appended to one buffer, with exactly the bytes of the standard
//! formatting they replace:
//!
//! - [`push_fixed`]: at most `places` decimals, no trailing zeros, never `-0` (SVG, G-code):
//!   the bytes of [`fixed_std`], which is `format!("{v:.places$}")` trimmed. The fast path is
//!   exact integer arithmetic: a finite `v` is `m * 2^e` exactly, so `v * 10^places` is
//!   `m * 10^places * 2^e`, an integer shifted right by `-e`; the bits shifted out decide the
//!   rounding exactly, ties to even, as the standard formatter rounds the exact binary value.
//!   What does not fit in 128 bits (|v| above about 10^17 mm, more than nine places) and
//!   NaN or infinity take the standard path itself.
//! - [`push_shortest`]: `v.to_string()` (CSV): the shortest digits that read back as `v`, laid
//!   out without an exponent. The digits come from `zmij` (a Ryu-class shortest round-trip
//!   formatter). Among equally short digit strings both the standard library and `zmij` take
//!   the one closest to `v`; they differ only on an exact tie, where `v`'s own decimal
//!   expansion is one digit longer than the shortest and ends in 5. Such a `v` has at most 18
//!   significant decimal digits, which is cheap to detect from its bits; those values (and NaN
//!   and infinity) take the standard path.
//! - [`push_json`]: the bytes `serde_json` writes for an `f64`: `zmij`'s form, `null` for NaN
//!   and infinity. `zmij` is pinned in `Cargo.toml`, since it decides these bytes.
//!
//! The property tests at the bottom compare each against its standard twin on millions of
//! values; `cli/tests/writers.rs` compares whole files.

use std::fmt::Write as _;

/// `v` with at most `places` decimals, no trailing zeros, never `-0`: the formatting the fast
/// path replaces, kept as its fallback and as the control the tests compare with.
pub fn fixed_std(v: f64, places: usize) -> String {
    let s = format!("{v:.places$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// Appends `v` with at most `places` decimals, no trailing zeros, never `-0` (the bytes of
/// [`fixed_std`]).
pub fn push_fixed(out: &mut String, v: f64, places: usize) {
    match fixed_digits(v, places) {
        Some((0, _)) => out.push('0'),
        Some((q, neg)) => {
            if neg {
                out.push('-');
            }
            // `places <= 9` here, so the power and the fraction fit in a u64.
            let pow = 10u64.pow(places as u32);
            let int = q / u128::from(pow);
            let mut frac = (q % u128::from(pow)) as u64;
            match u64::try_from(int) {
                Ok(i) => out.push_str(itoa::Buffer::new().format(i)),
                Err(_) => {
                    let _ = write!(out, "{int}");
                }
            }
            if frac != 0 {
                let mut width = places;
                while frac % 10 == 0 {
                    frac /= 10;
                    width -= 1;
                }
                out.push('.');
                let digits = itoa::Buffer::new().format(frac).len();
                for _ in digits..width {
                    out.push('0');
                }
                out.push_str(itoa::Buffer::new().format(frac));
            }
        }
        None => out.push_str(&fixed_std(v, places)),
    }
}

/// `round_half_even(|v| * 10^places)` and the sign, exactly; `None` where the fast path does
/// not reach (not finite, more than nine places, too large for 128 bits).
fn fixed_digits(v: f64, places: usize) -> Option<(u128, bool)> {
    if !v.is_finite() || places > 9 {
        return None;
    }
    let (m, e, neg) = parts(v);
    let x = u128::from(m) * u128::from(10u64.pow(places as u32)); // < 2^83
    if m == 0 {
        return Some((0, neg));
    }
    if e >= 0 {
        // x << e stays below 2^127 for e <= 44.
        return (e <= 44).then(|| (x << e, neg));
    }
    let s = e.unsigned_abs();
    if s > 83 {
        // x < 2^83 <= half of 2^s: rounds to zero.
        return Some((0, neg));
    }
    let q = x >> s;
    let r = x & ((1u128 << s) - 1);
    let half = 1u128 << (s - 1);
    let up = r > half || (r == half && q & 1 == 1);
    Some((q + u128::from(up), neg))
}

/// `v = ±m * 2^e` exactly, with the sign.
fn parts(v: f64) -> (u64, i32, bool) {
    let bits = v.to_bits();
    let neg = bits >> 63 != 0;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    if biased == 0 {
        (frac, -1074, neg)
    } else {
        (frac | (1u64 << 52), biased - 1075, neg)
    }
}

/// Whether `v`'s exact decimal expansion has at most 18 significant digits, the only values
/// where two equally short digit strings can be equally close to `v` (an integer-valued `v`
/// never can: see the module docs).
fn short_expansion(v: f64) -> bool {
    let (m, e, _) = parts(v);
    if m == 0 {
        return false;
    }
    let tz = m.trailing_zeros();
    let (m, e) = (m >> tz, e + tz as i32);
    if e >= 0 {
        return false;
    }
    // v = m * 5^j / 10^j, so its significant digits are those of m * 5^j (m odd).
    let j = e.unsigned_abs();
    j <= 26 && u128::from(m) * 5u128.pow(j) < 1_000_000_000_000_000_000
}

/// Appends `v` exactly as `v.to_string()` writes it: the shortest round-trip digits, without
/// an exponent (`1e-7` is `0.0000001`, `2.0` is `2`, `-0.0` is `-0`).
pub fn push_shortest(out: &mut String, v: f64) {
    if !v.is_finite() || short_expansion(v) {
        let _ = write!(out, "{v}");
        return;
    }
    let mut buf = zmij::Buffer::new();
    let s = buf.format_finite(v).as_bytes();
    let (neg, s) = match s.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, s),
    };
    // zmij writes `DIGITS[.DIGITS][e[+-]EXP]`: gather the digits and where the point falls.
    let mut digits = [0u8; 24];
    let mut n = 0;
    let mut point = None;
    let mut exp = 0i32;
    let mut i = 0;
    while i < s.len() {
        match s[i] {
            b'.' => point = Some(n),
            b'e' => {
                let tail = std::str::from_utf8(&s[i + 1..]).unwrap_or("0");
                exp = tail.trim_start_matches('+').parse().unwrap_or(0);
                break;
            }
            d => {
                if n < digits.len() {
                    digits[n] = d;
                    n += 1;
                }
            }
        }
        i += 1;
    }
    let mut pos = point.unwrap_or(n) as i32 + exp;
    let mut lead = 0;
    while lead < n && digits[lead] == b'0' {
        lead += 1;
        pos -= 1;
    }
    while n > lead && digits[n - 1] == b'0' {
        n -= 1;
    }
    if neg {
        out.push('-');
    }
    let d = &digits[lead..n];
    if d.is_empty() {
        out.push('0');
        return;
    }
    let len = d.len() as i32;
    // The digits are ASCII.
    let text = std::str::from_utf8(d).unwrap_or("");
    if pos <= 0 {
        out.push_str("0.");
        for _ in 0..-pos {
            out.push('0');
        }
        out.push_str(text);
    } else if pos < len {
        let (a, b) = text.split_at(pos as usize);
        out.push_str(a);
        out.push('.');
        out.push_str(b);
    } else {
        out.push_str(text);
        for _ in 0..pos - len {
            out.push('0');
        }
    }
}

/// Appends `v` as `serde_json` writes an `f64`: shortest round-trip form (`zmij`), `null`
/// for NaN and infinity.
pub fn push_json(out: &mut String, v: f64) {
    if v.is_finite() {
        out.push_str(zmij::Buffer::new().format_finite(v));
    } else {
        out.push_str("null");
    }
}

/// Appends an integer.
pub fn push_int(out: &mut String, v: u64) {
    out.push_str(itoa::Buffer::new().format(v));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A xorshift stream of test values: raw bit patterns (every exponent, subnormals, NaN,
    /// infinities), millimetre-sized coordinates, and the odd multiples of small powers of
    /// two that are exact decimal ties.
    fn values(count: usize) -> impl Iterator<Item = f64> {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        (0..count).map(move |i| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let unit = (x >> 11) as f64 / (1u64 << 53) as f64;
            match i % 6 {
                0 => f64::from_bits(x),
                1 => unit * 400.0 - 200.0,
                2 => (unit - 0.5) * 10f64.powi((x % 40) as i32 - 20),
                3 => ((x >> 20) as i64 % 2_000_001 - 1_000_000) as f64 / f64::from(1u32 << (x % 24)),
                4 => ((x >> 30) as i64 % 20_001 - 10_000) as f64 / 10f64.powi((x % 8) as i32),
                _ => f64::from_bits(x & 0x801F_FFFF_FFFF_FFFF | (((x >> 52) % 2047) << 52)),
            }
        })
    }

    fn edges() -> Vec<f64> {
        let mut v = vec![
            0.0,
            -0.0,
            f64::NAN,
            -f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            f64::from_bits(1),
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            0.5,
            1.5,
            2.5,
            0.125,
            0.375,
            0.03125,
            -0.03125,
            0.00005,
            -0.00005,
            0.00004999999999999999,
            1e-7,
            1e15,
            1e16,
            1e17,
            1e21,
            1e22,
            123.456789,
            589638.3813476562,
            9007199254740993.0,
            1.8446744073709552e19,
            3.402823466e38,
        ];
        for k in -1100..1100 {
            v.push(2f64.powi(k));
            v.push(-(2f64.powi(k)) * 1.5);
            v.push(10f64.powi(k / 3));
        }
        v
    }

    #[test]
    fn fixed_matches_the_standard_formatter() {
        let mut s = String::new();
        for v in edges().into_iter().chain(values(3_000_000)) {
            for places in [0, 1, 3, 4, 6, 9, 12] {
                s.clear();
                push_fixed(&mut s, v, places);
                assert_eq!(s, fixed_std(v, places), "{v:e} ({:#x}) to {places} places", v.to_bits());
            }
        }
    }

    #[test]
    fn fixed_ties_go_to_even() {
        // Every odd multiple of 1/32 is an exact tie at four places.
        let mut s = String::new();
        for k in -200_000..200_000 {
            let v = f64::from(2 * k + 1) / 32.0;
            s.clear();
            push_fixed(&mut s, v, 4);
            assert_eq!(s, fixed_std(v, 4), "{v}");
        }
        assert_eq!(fixed_std(0.03125, 4), "0.0312");
        assert_eq!(fixed_std(0.09375, 4), "0.0938");
    }

    #[test]
    fn shortest_matches_display() {
        let mut s = String::new();
        for v in edges().into_iter().chain(values(3_000_000)) {
            s.clear();
            push_shortest(&mut s, v);
            assert_eq!(s, v.to_string(), "{v:e} ({:#x})", v.to_bits());
        }
    }

    #[test]
    fn shortest_ties_are_caught() {
        // Two 16-digit strings are equally close to this value; Display takes the upper one,
        // zmij the even one.
        // 589638.38134765625, exactly.
        let v = 589_638.0 + 781.0 / 2048.0;
        assert_eq!(zmij::Buffer::new().format_finite(v), "589638.3813476562");
        assert!(short_expansion(v));
        let mut s = String::new();
        push_shortest(&mut s, v);
        assert_eq!(s, "589638.3813476563");
    }

    #[test]
    fn json_numbers_match_serde_json() {
        let mut s = String::new();
        for v in edges().into_iter().chain(values(1_000_000)) {
            s.clear();
            push_json(&mut s, v);
            assert_eq!(s, serde_json::to_string(&v).unwrap_or_default(), "{v:e}");
        }
    }
}
