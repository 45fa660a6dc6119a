//! The statistics of Shier and Bourke, "An Algorithm for Random Fractal Filling of Space", against the paper: Table 1 (the gasket width for circles,
//! N = 1) to its four decimals, the monotonicity of b in n and c, the halting limit of
//! section 3, and exact dimensions. Each checker is shown to fail on a wrong input.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
// The checks are written `!(a < b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use zetafill::internals::stats::{exact_dimension, gasket_width, pair_limit, PairShape};
use zetafill::internals::zeta::{hurwitz_zeta, partial_sum};

/// Table 1 of Shier and Bourke: b(c, 1, n) for n = 10 ... 10^6 (rows) and c = 1.24, 1.32, 1.40, 1.48.
const TABLE1_C: [f64; 4] = [1.24, 1.32, 1.40, 1.48];
const TABLE1: [(u64, [f64; 4]); 6] = [
    (10, [0.6024, 0.4314, 0.3291, 0.2613]),
    (100, [0.4602, 0.3209, 0.2379, 0.1831]),
    (1_000, [0.4200, 0.2881, 0.2096, 0.1579]),
    (10_000, [0.4055, 0.2754, 0.1979, 0.1469]),
    (100_000, [0.3998, 0.2700, 0.1926, 0.1415]),
    (1_000_000, [0.3975, 0.2676, 0.1900, 0.1387]),
];

/// The entries of Table 1 that `b` does not give when rounded to four decimals.
fn table1_mismatches(b: impl Fn(f64, u64) -> f64) -> Vec<String> {
    let mut bad = Vec::new();
    for (n, row) in TABLE1 {
        for (c, want) in TABLE1_C.iter().zip(row) {
            let got = b(*c, n);
            // Rounded to the table's four decimals, the value must be the printed one.
            if (got * 1e4).round() != (want * 1e4).round() {
                bad.push(format!("c={c} n={n}: got {got:.6}, table {want}"));
            }
        }
    }
    bad
}

#[test]
fn table1_is_reproduced_to_four_decimals() {
    let bad = table1_mismatches(|c, n| gasket_width(c, 1.0, n).unwrap_or(f64::NAN));
    assert!(bad.is_empty(), "Table 1 mismatches:\n{}", bad.join("\n"));
}

/// The checker fails on the other convention: eq. 8 as printed (sums over i = 0..=n, next
/// circle n + 1, that is our b one placement later) misses Table 1.
#[test]
fn table1_checker_rejects_the_printed_index_convention() {
    let bad = table1_mismatches(|c, n| gasket_width(c, 1.0, n + 1).unwrap_or(f64::NAN));
    assert!(bad.len() >= 10, "the printed convention should miss most entries, missed {bad:?}");
    // And a value off by 1e-4 is caught.
    let bad = table1_mismatches(|c, n| gasket_width(c, 1.0, n).unwrap_or(f64::NAN) + 1.2e-4);
    assert_eq!(bad.len(), 24);
}

/// Table 1's b with plain partial sums (no tail trick): n placements, shapes 0..n-1.
fn gasket_direct(c: f64, big_n: f64, n: u64) -> f64 {
    let z = hurwitz_zeta(c, big_n).unwrap_or(f64::NAN);
    let p = partial_sum(c, big_n, n - 1).unwrap_or(f64::NAN);
    let q = partial_sum(c / 2.0, big_n, n - 1).unwrap_or(f64::NAN);
    0.25 * (z - p) / ((n as f64 + big_n).powf(-c / 2.0) * q)
}

#[test]
fn gasket_agrees_with_its_definition_summed_term_by_term() {
    for &(c, big_n) in &[(1.1, 1.0), (1.3, 2.0), (1.5, 0.5), (2.5, 3.0)] {
        for n in [1u64, 2, 5, 50, 500] {
            // Term by term, no Euler–Maclaurin: the definition itself.
            let z: f64 = hurwitz_zeta(c, big_n).unwrap_or(f64::NAN);
            let p: f64 = (0..n).map(|i| (i as f64 + big_n).powf(-c)).sum();
            let q: f64 = (0..n).map(|i| (i as f64 + big_n).powf(-c / 2.0)).sum();
            let want = 0.25 * (z - p) / ((n as f64 + big_n).powf(-c / 2.0) * q);
            let got = gasket_width(c, big_n, n).unwrap_or(f64::NAN);
            assert!(((got - want) / want).abs() < 1e-11, "c={c} N={big_n} n={n}: {got} vs {want}");
            let direct = gasket_direct(c, big_n, n);
            assert!(((got - direct) / direct).abs() < 1e-10);
        }
    }
}

/// `b` falls as n grows (at a slowing rate) and as c grows.
fn monotone_violations(b: impl Fn(f64, u64) -> f64) -> Vec<String> {
    let mut bad = Vec::new();
    let cs: Vec<f64> = (0..=40).map(|k| 1.05 + 0.025 * k as f64).collect();
    let ns: Vec<u64> = [
        1u64,
        2,
        3,
        5,
        10,
        30,
        100,
        1_000,
        10_000,
        100_000,
        1_000_000,
        10_000_000,
        1_000_000_000,
    ]
    .to_vec();
    for &c in &cs {
        for w in ns.windows(2) {
            let (a, z) = (b(c, w[0]), b(c, w[1]));
            if !(z < a) {
                bad.push(format!("not decreasing in n at c={c}: b({})={a} b({})={z}", w[0], w[1]));
            }
        }
    }
    for &n in &ns {
        for w in cs.windows(2) {
            let (a, z) = (b(w[0], n), b(w[1], n));
            if !(z < a) {
                bad.push(format!("not decreasing in c at n={n}: b({})={a} b({})={z}", w[0], w[1]));
            }
        }
    }
    bad
}

#[test]
fn gasket_falls_with_n_and_with_c() {
    let bad = monotone_violations(|c, n| gasket_width(c, 1.0, n).unwrap_or(f64::NAN));
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    let bad = monotone_violations(|c, n| gasket_width(c, 3.0, n).unwrap_or(f64::NAN));
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    // The paper: at c = 1.32, b drops by only 0.9 percent from n = 10^5 to 10^6.
    let (a, z) = (
        gasket_width(1.32, 1.0, 100_000).unwrap_or(0.0),
        gasket_width(1.32, 1.0, 1_000_000).unwrap_or(0.0),
    );
    assert!(((a - z) / a - 0.009).abs() < 0.0015, "{a} {z}");
}

#[test]
fn monotone_checker_fails_on_a_rising_function() {
    assert!(!monotone_violations(|c, n| c + n as f64).is_empty());
    assert!(!monotone_violations(|c, n| 1.0 / (c * (n as f64 + 1.0)) + if n == 100 && c > 1.5 { 1.0 } else { 0.0 }).is_empty());
}

#[test]
fn gasket_rejects_bad_arguments_without_panicking() {
    for (c, n) in [
        (1.0, 1.0),
        (0.5, 1.0),
        (f64::NAN, 1.0),
        (f64::INFINITY, 1.0),
        (1.3, 0.0),
        (1.3, -1.0),
        (1.3, f64::NAN),
    ] {
        assert!(gasket_width(c, n, 10).is_err(), "c={c} N={n}");
    }
    assert!(gasket_width(1.3, 1.0, 0).is_err(), "no perimeter before the first placement");
    assert!(gasket_width(1.3, 1.0, u64::MAX).is_ok_and(|b| b.is_finite() && b > 0.0));
}

/// Section 3: with N = 1 the first two squares cannot both fit for c > 1.5224.
#[test]
fn square_pair_limit_is_1_5224() {
    let c = pair_limit(PairShape::Square, 1.0).ok().flatten().unwrap_or(f64::NAN);
    assert_eq!((c * 1e4).round() / 1e4, 1.5224, "{c}");
    // Larger N relaxes it (section 3: up to about 1.57 for squares).
    let c3 = pair_limit(PairShape::Square, 3.0).ok().flatten().unwrap_or(f64::NAN);
    assert!(c3 > c, "{c3} vs {c}");
    // Circles: two discs fit in opposite corners up to c = 1.5938 (a looser bound than for
    // squares; circles halt earlier for other reasons, Figure 6).
    let cc = pair_limit(PairShape::Circle, 1.0).ok().flatten().unwrap_or(f64::NAN);
    assert_eq!((cc * 1e4).round() / 1e4, 1.5938, "{cc}");
}

#[test]
fn exact_dimensions() {
    assert_eq!(exact_dimension(1.25, 2), 1.6);
    assert_eq!(exact_dimension(1.25, 1), 0.8);
    assert_eq!(exact_dimension(1.5, 3), 2.0);
}
