//! The numbers of G-code words, as text: coordinates and feeds as grid integers formatted by
//! hand with a fixed number of decimals, powers as integers. Never exponent notation, NaN or
//! `-0`, whatever the input.
//!
//! A feed is written on its own grid, [`Units::feed_decimals`]: whole mm/min in mm, and
//! 10^-5 in/min in inches. Every feed a profile or `--feed` may ask for is at least
//! [`MIN_FEED`] = 1 mm/min, 0.03937 in/min, so the inch grid moves it by at most
//! 0.5 / 3937, 0.013 %; and a feed never rounds to 0 (it is at least one grid step).

use crate::output::machine::{Units, MIN_FEED};

/// A grid integer as a plain decimal with exactly `dec` decimals (never `-0`).
pub fn fixed(q: i64, dec: u32) -> String {
    let p = 10i64.pow(dec);
    let sign = if q < 0 { "-" } else { "" };
    let a = q.unsigned_abs();
    if dec == 0 {
        return format!("{sign}{a}");
    }
    format!("{sign}{}.{:0width$}", a / p as u64, a % p as u64, width = dec as usize)
}

/// A power as a plain integer (at least `min`).
pub fn int(v: f64, min: i64) -> String {
    let r = v.round();
    let r = if r.is_finite() { (r as i64).max(min) } else { min };
    r.to_string()
}

/// A feed in mm/min as the number of an `F` word in `units`: on the feed grid of `units`,
/// at least one step of it.
pub fn feed(mm_per_min: f64, units: Units) -> String {
    let dec = units.feed_decimals();
    let q = (mm_per_min * units.per_mm() * 10i64.pow(dec) as f64).round();
    let q = if q.is_finite() { (q as i64).max(1) } else { 1 };
    fixed(q, dec)
}

/// The largest relative error of `feed` over the feeds a profile may hold, for docs and
/// tests: half a grid step over the smallest feed.
pub fn feed_error_bound(units: Units) -> f64 {
    0.5 / (MIN_FEED * units.per_mm() * 10i64.pow(units.feed_decimals()) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::machine::MAX_FEED;

    #[test]
    fn fixed_numbers_are_plain() {
        assert_eq!(fixed(0, 3), "0.000");
        assert_eq!(fixed(-1, 3), "-0.001");
        assert_eq!(fixed(123456, 3), "123.456");
        assert_eq!(fixed(-2000, 3), "-2.000");
        assert_eq!(fixed(5, 4), "0.0005");
        assert_eq!(fixed(7, 0), "7");
        assert_eq!(int(f64::NAN, 1), "1");
        assert_eq!(int(-0.2, 0), "0");
    }

    /// Bug pinned here: in inches feeds were whole in/min, so `--feed 30` (mm/min) became `F1`
    /// (25.4 mm/min), 1 to 13 mm/min all `F1`, and 1000 mm/min `F39`.
    #[test]
    fn inch_feeds_keep_what_was_asked() {
        assert_eq!(feed(30.0, Units::Inch), "1.18110");
        assert_eq!(feed(1.0, Units::Inch), "0.03937");
        assert_eq!(feed(13.0, Units::Inch), "0.51181");
        assert_eq!(feed(37.0, Units::Inch), "1.45669");
        assert_eq!(feed(1000.0, Units::Inch), "39.37008");
        assert_eq!(feed(MAX_FEED, Units::Inch), "39370.07874");
        assert!(feed_error_bound(Units::Inch) < 2e-4);
        // Feeds from 1 to 10^6 mm/min, log-spaced, and just above the integers near the bottom.
        let mut asks: Vec<f64> = (0..=6000).map(|i| libm::pow(10.0, f64::from(i) / 1000.0)).collect();
        asks.extend((1..2000).map(|i| f64::from(i) / 100.0 + 1.0));
        for f in asks {
            let s = feed(f, Units::Inch);
            let back = s.parse::<f64>().unwrap_or(f64::NAN) * 25.4;
            assert!((back - f).abs() <= 1e-3 * f, "{f} mm/min written F{s} ({back} mm/min)");
            assert!(s.split_once('.').is_some_and(|(_, d)| d.len() == 5), "{s}");
        }
    }

    /// mm feeds are whole mm/min, the bytes they always had; nothing rounds to 0.
    #[test]
    fn mm_feeds_are_whole_and_never_zero() {
        assert_eq!(feed(3000.0, Units::Mm), "3000");
        assert_eq!(feed(1499.5, Units::Mm), "1500");
        assert_eq!(feed(1.0, Units::Mm), "1");
        for units in [Units::Mm, Units::Inch] {
            for v in [0.0, -5.0, 1e-300, f64::NAN, f64::INFINITY] {
                let s = feed(v, units);
                assert!(s.parse::<f64>().is_ok_and(|x| x > 0.0) && !s.contains('e'), "{v}: {s}");
            }
        }
    }
}
