//! The 1D engine under the same property tests as 2D: no two segments overlap or come within
//! the gap (periodic images included), every segment inside the interval, lengths exactly the
//! power law, prefix stability, byte-identical reruns, the index against a single list, stop
//! conditions, halting, capacity and no panic on any input. Two independent checkers (an
//! O(n^2) pairwise one and an O(n log n) sorted one) are each shown to fail on broken fills.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
// The checks are written `!(a < b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::type_complexity)]

mod common;

use common::{check_pairs, check_sorted};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use zetafill::internals::line::line_digest;
use zetafill::internals::zeta::hurwitz_zeta;
use zetafill::line::{
    index_words as line_index_words, Engine as LineEngine, Interval, Params as LineParams, Segment, Storage as LineStorage,
};
use zetafill::rng_from_seed;
use zetafill::{ParamError, StepError, Stop, StopReason};

// ---------------------------------------------------------------------------------------------
// Checkers, written without the engine (the segment checkers are in `common`).
// ---------------------------------------------------------------------------------------------

/// Both checkers, and lengths equal to L / (zeta(c, N) (i+N)^c) computed here.
fn check_all(f: &Fill, case: &Case) -> Result<(), String> {
    let segs: Vec<(f64, f64)> = f.segs.iter().map(|s| (s.start, s.length)).collect();
    check_pairs(&segs, case.l, case.gap, case.periodic)?;
    check_sorted(&segs, case.l, case.gap, case.periodic)?;
    let z = hurwitz_zeta(case.c, case.n).map_err(|e| e.to_string())?;
    for (i, s) in f.segs.iter().enumerate() {
        let want = case.l / (z * (i as f64 + case.n).powf(case.c));
        if ((s.length - want) / want).abs() > 1e-12 {
            return Err(format!("segment {i} has length {} instead of {want}", s.length));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Running the engine.
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug)]
struct Case {
    seed: u64,
    c: f64,
    n: f64,
    gap: f64,
    l: f64,
    periodic: bool,
    max_trials: u64,
}

impl Case {
    fn new(seed: u64, c: f64, periodic: bool) -> Self {
        Case {
            seed,
            c,
            n: 1.0,
            gap: 0.0,
            l: 200.0,
            periodic,
            max_trials: 10_000_000,
        }
    }
    fn params(&self) -> LineParams {
        LineParams {
            c: self.c,
            n_offset: self.n,
            gap: self.gap,
            max_trials: self.max_trials,
        }
    }
    fn interval(&self) -> Interval {
        Interval {
            length: self.l,
            periodic: self.periodic,
        }
    }
}

#[derive(Debug)]
struct Fill {
    segs: Vec<Segment<f64>>,
    trials: Vec<u64>,
    reason: StopReason,
    digest: (u64, u64),
    fill_fraction: f64,
}

fn run_with(case: &Case, stop: &Stop, cap: usize, index_len: usize) -> Result<Fill, ParamError> {
    let mut segs = vec![Segment::<f64>::default(); cap];
    let mut index = vec![0u32; index_len];
    let mut e = LineEngine::new(
        case.params(),
        case.interval(),
        LineStorage {
            segments: &mut segs,
            index: &mut index,
        },
    )?;
    let mut rng = rng_from_seed(case.seed);
    let mut trials = Vec::new();
    let reason = e.run(&mut rng, stop, |p| trials.push(p.trials));
    let digest = line_digest(&e);
    let fill_fraction = e.stats().fill_fraction;
    Ok(Fill {
        segs: e.placed().to_vec(),
        trials,
        reason,
        digest,
        fill_fraction,
    })
}

fn run(case: &Case, k: usize) -> Fill {
    let stop = Stop {
        count: Some(k as u64),
        ..Stop::default()
    };
    run_with(case, &stop, k + 1, line_index_words(k + 1)).unwrap_or_else(|e| panic!("{case:?}: {e}"))
}

// ---------------------------------------------------------------------------------------------
// Properties.
// ---------------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, failure_persistence: None, rng_seed: RngSeed::Fixed(0x1d01), ..ProptestConfig::default() })]

    #[test]
    fn fills_are_valid(seed in any::<u64>(), c in 1.05f64..2.6, n in 0.3f64..6.0, gap in prop_oneof![Just(0.0), 0.0f64..0.05],
                       l in prop_oneof![Just(200.0), 0.5f64..1000.0], periodic in any::<bool>(), k in 1usize..400) {
        let case = Case { seed, c, n, gap: gap * l, l, periodic, max_trials: 20_000 };
        let f = run(&case, k);
        // Halting at high c is allowed; what was placed must be valid.
        if let Err(e) = check_all(&f, &case) {
            return Err(TestCaseError::fail(format!("{case:?}: {e}")));
        }
        match f.reason {
            StopReason::Count => prop_assert_eq!(f.segs.len(), k),
            StopReason::Step(StepError::Halted { index, trials }) => {
                prop_assert_eq!(index as usize, f.segs.len());
                prop_assert_eq!(trials, case.max_trials);
            }
            StopReason::Step(StepError::CannotFit { index }) => prop_assert_eq!(index as usize, f.segs.len()),
            r => prop_assert!(false, "unexpected stop {:?}", r),
        }
        prop_assert!(f.trials.iter().all(|&t| t >= 1 && t <= case.max_trials));
    }

    #[test]
    fn prefixes_are_stable_and_reruns_identical(seed in any::<u64>(), c in 1.1f64..2.0, periodic in any::<bool>(), k in 1usize..200) {
        let case = Case { max_trials: 100_000, ..Case::new(seed, c, periodic) };
        let long = run(&case, k + 50);
        let short = run(&case, k);
        let m = short.segs.len();
        prop_assert_eq!(&long.segs[..m.min(long.segs.len())], &short.segs[..m.min(long.segs.len())]);
        let again = run(&case, k);
        prop_assert_eq!(again.digest, short.digest);
        prop_assert_eq!(again.segs, short.segs);
    }

    #[test]
    fn index_agrees_with_a_single_list(seed in any::<u64>(), c in 1.1f64..2.2, periodic in any::<bool>(), k in 1usize..300) {
        let case = Case { max_trials: 100_000, ..Case::new(seed, c, periodic) };
        let stop = Stop { count: Some(k as u64), ..Stop::default() };
        let full = run_with(&case, &stop, k + 1, line_index_words(k + 1)).map_err(|e| TestCaseError::fail(e.to_string()))?;
        // One bucket: every query walks every segment.
        let one = run_with(&case, &stop, k + 1, k + 2).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(full.digest, one.digest);
        prop_assert_eq!(full.trials, one.trials);
    }

    /// Arbitrary numbers, including NaN and infinities, give an error or a valid fill, never a panic.
    #[test]
    fn no_input_panics(c in prop_oneof![any::<f64>(), 1.0f64..4.0], n in prop_oneof![any::<f64>(), 0.0f64..10.0],
                       gap in prop_oneof![any::<f64>(), 0.0f64..1.0], l in prop_oneof![any::<f64>(), 0.0f64..10.0],
                       periodic in any::<bool>(), max_trials in 0u64..50, cap in 0usize..20, idx in 0usize..80, seed in any::<u64>()) {
        let mut segs = vec![Segment::<f64>::default(); cap];
        let mut index = vec![0u32; idx];
        let params = LineParams { c, n_offset: n, gap, max_trials };
        if let Ok(mut e) = LineEngine::new(params, Interval { length: l, periodic }, LineStorage { segments: &mut segs, index: &mut index }) {
            let mut rng = rng_from_seed(seed);
            let _ = e.run(&mut rng, &Stop { count: Some(30), fill: Some(0.5), min_size: Some(1e-9) }, |_| {});
            for _ in 0..3 {
                let _ = e.step(&mut rng);
            }
            let segs: Vec<(f64, f64)> = e.placed().iter().map(|s| (s.start, s.length)).collect();
            prop_assert!(check_pairs(&segs, l, gap, periodic).is_ok());
        }
    }
}

/// Figure 3's fill: 30,000 segments at c = 1.4, N = 1, periodic. Checked in full by the sorted
/// checker (and the first 2000 pairwise).
#[test]
fn thirty_thousand_segments_at_c_1_4() {
    for periodic in [true, false] {
        let case = Case::new(1, 1.4, periodic);
        let f = run(&case, 30_000);
        assert_eq!(f.reason, StopReason::Count, "{periodic}");
        assert_eq!(f.segs.len(), 30_000);
        let segs: Vec<(f64, f64)> = f.segs.iter().map(|s| (s.start, s.length)).collect();
        check_sorted(&segs, case.l, 0.0, periodic).unwrap_or_else(|e| panic!("{e}"));
        check_pairs(&segs[..2000], case.l, 0.0, periodic).unwrap_or_else(|e| panic!("{e}"));
        // The placed length is the partial sum of the power law.
        let z = hurwitz_zeta(1.4, 1.0).unwrap_or(0.0);
        let tail = hurwitz_zeta(1.4, 30_001.0).unwrap_or(0.0);
        assert!((f.fill_fraction - (1.0 - tail / z)).abs() < 1e-9, "{}", f.fill_fraction);
        assert!(f.fill_fraction > 0.98);
    }
}

/// A periodic fill has segments that wrap past L, and they are kept clear of the segments
/// near 0.
#[test]
fn periodic_segments_wrap() {
    let mut wrapped = 0;
    for seed in 0..40 {
        let case = Case::new(seed, 1.3, true);
        let f = run(&case, 300);
        let segs: Vec<(f64, f64)> = f.segs.iter().map(|s| (s.start, s.length)).collect();
        check_pairs(&segs, case.l, 0.0, true).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        wrapped += f.segs.iter().filter(|s| s.start + s.length > case.l).count();
    }
    assert!(wrapped > 0, "no segment ever crossed the periodic boundary");
}

#[test]
fn golden_digests() {
    // Re-mint (only for a deliberate, version-level change of output) by printing the digests.
    let a = run(&Case::new(1, 1.4, false), 1000).digest;
    let b = run(&Case::new(7, 1.25, true), 1000).digest;
    assert_eq!((a, b), GOLDEN, "the 1D output changed: {a:?} {b:?}");
}

const GOLDEN: ((u64, u64), (u64, u64)) = ((1000, 288420426839745559), (1000, 10557110336802879849));

#[test]
fn the_first_start_is_uniform() {
    // One segment of length L_0 in [0, 200]: its start is uniform over [0, 200 - L_0].
    let case = Case::new(0, 1.5, false);
    let l0 = 200.0 / hurwitz_zeta(1.5, 1.0).unwrap_or(1.0);
    let span = 200.0 - l0;
    let n = 4000;
    let mut bins = [0u32; 10];
    for seed in 0..n {
        let f = run(&Case { seed, ..case }, 1);
        let s = f.segs[0].start;
        assert!((0.0..=span).contains(&s));
        bins[((s / span * 10.0) as usize).min(9)] += 1;
        assert_eq!(f.trials, vec![1], "the first segment always fits at once");
    }
    // Chi-square with 9 degrees of freedom: 27.9 is the 0.1% point.
    let e = n as f64 / 10.0;
    let chi2: f64 = bins.iter().map(|&b| (b as f64 - e).powi(2) / e).sum();
    assert!(chi2 < 27.9, "{bins:?} chi2 {chi2}");
}

#[test]
fn stop_conditions() {
    let case = Case::new(3, 1.3, false);
    let f = run_with(
        &case,
        &Stop {
            fill: Some(0.8),
            ..Stop::default()
        },
        10_000,
        line_index_words(10_000),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(f.reason, StopReason::Fill);
    assert!(f.fill_fraction >= 0.8);
    let len = f.segs.len();
    let z = hurwitz_zeta(1.3, 1.0).unwrap_or(0.0);
    let before: f64 = (0..len - 1).map(|i| 1.0 / (z * (i as f64 + 1.0).powf(1.3))).sum();
    assert!(before < 0.8, "stopped late");
    let f = run_with(
        &case,
        &Stop {
            min_size: Some(0.5),
            ..Stop::default()
        },
        10_000,
        line_index_words(10_000),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(f.reason, StopReason::MinSize);
    assert!(f.segs.iter().all(|s| s.length >= 0.5));
    let next = 200.0 / (z * (f.segs.len() as f64 + 1.0).powf(1.3));
    assert!(next < 0.5);
}

#[test]
fn halting_capacity_and_cannot_fit_are_errors() {
    // At c = 3 the third segment rarely finds room within 50 trials... or any: run until halt.
    let case = Case {
        max_trials: 50,
        ..Case::new(1, 3.0, false)
    };
    let f = run(&case, 2000);
    match f.reason {
        StopReason::Step(StepError::Halted { index, trials }) => {
            assert_eq!(index as usize, f.segs.len());
            assert_eq!(trials, 50);
        }
        r => panic!("expected a halt, got {r:?}"),
    }
    // Capacity: 5 slots, asked for 10.
    let f = run_with(
        &Case::new(1, 1.3, false),
        &Stop {
            count: Some(10),
            ..Stop::default()
        },
        5,
        line_index_words(5),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(f.reason, StopReason::Step(StepError::Capacity { capacity: 5 }));
    assert_eq!(f.segs.len(), 5);
    // A gap that leaves no room for the first segment.
    let f = run(
        &Case {
            gap: 80.0,
            ..Case::new(1, 1.3, false)
        },
        10,
    );
    assert_eq!(f.reason, StopReason::Step(StepError::CannotFit { index: 0 }));
    // Periodic: a first segment that would meet its own image.
    let f = run(
        &Case {
            gap: 10.0,
            n: 0.3,
            ..Case::new(1, 3.0, true)
        },
        10,
    );
    assert_eq!(f.reason, StopReason::Step(StepError::CannotFit { index: 0 }));
}

#[test]
fn bad_parameters_are_named() {
    let ok = Case::new(1, 1.3, false);
    let try_new = |case: Case, cap: usize, idx: usize| {
        let mut segs = vec![Segment::<f64>::default(); cap];
        let mut index = vec![0u32; idx];
        LineEngine::new(
            case.params(),
            case.interval(),
            LineStorage {
                segments: &mut segs,
                index: &mut index,
            },
        )
        .map(|_| ())
    };
    assert_eq!(try_new(Case { c: 1.0, ..ok }, 4, 13), Err(ParamError::Exponent));
    assert_eq!(try_new(Case { c: f64::NAN, ..ok }, 4, 13), Err(ParamError::Exponent));
    assert_eq!(try_new(Case { n: 0.0, ..ok }, 4, 13), Err(ParamError::Offset));
    assert_eq!(try_new(Case { l: 0.0, ..ok }, 4, 13), Err(ParamError::Region));
    assert_eq!(try_new(Case { l: f64::INFINITY, ..ok }, 4, 13), Err(ParamError::Region));
    assert_eq!(try_new(Case { gap: -1.0, ..ok }, 4, 13), Err(ParamError::Gap));
    assert_eq!(try_new(Case { gap: 100.0, ..ok }, 4, 13), Err(ParamError::Gap));
    assert_eq!(try_new(Case { max_trials: 0, ..ok }, 4, 13), Err(ParamError::MaxTrials));
    assert_eq!(try_new(ok, 0, 13), Err(ParamError::Storage));
    assert_eq!(try_new(ok, 4, 4), Err(ParamError::Storage));
    assert_eq!(try_new(Case { n: 1e-300, c: 4.0, ..ok }, 4, 13), Err(ParamError::Zeta));
    assert_eq!(try_new(ok, 4, 13), Ok(()));
}

// ---------------------------------------------------------------------------------------------
// The checkers fail on broken fills.
// ---------------------------------------------------------------------------------------------

#[test]
fn checkers_catch_broken_fills() {
    let l = 10.0;
    let good = [(0.0, 2.0), (3.0, 1.0), (6.0, 0.5)];
    for periodic in [false, true] {
        assert!(check_pairs(&good, l, 0.0, periodic).is_ok());
        assert!(check_sorted(&good, l, 0.0, periodic).is_ok());
    }
    let broken: [(&str, Vec<(f64, f64)>, f64, bool); 7] = [
        ("overlap", vec![(0.0, 2.0), (1.5, 1.0)], 0.0, false),
        ("touching", vec![(0.0, 2.0), (2.0, 1.0)], 0.0, false),
        ("within the gap", vec![(1.0, 2.0), (3.05, 1.0)], 0.1, false),
        ("outside", vec![(9.5, 1.0)], 0.0, false),
        ("inside the gap to the end", vec![(0.05, 1.0)], 0.1, false),
        ("wraps onto the first", vec![(0.5, 1.0), (9.0, 2.0)], 0.0, true),
        ("start outside the period", vec![(10.0, 1.0)], 0.0, true),
    ];
    for (what, segs, gap, periodic) in broken {
        assert!(check_pairs(&segs, l, gap, periodic).is_err(), "pairwise checker missed: {what}");
        assert!(check_sorted(&segs, l, gap, periodic).is_err(), "sorted checker missed: {what}");
    }
    // The length check catches a wrong power law.
    let case = Case::new(1, 1.3, false);
    let mut f = run(&case, 20);
    assert!(check_all(&f, &case).is_ok());
    f.segs[7].length *= 1.0 + 1e-9;
    assert!(check_all(&f, &case).is_err());
}
