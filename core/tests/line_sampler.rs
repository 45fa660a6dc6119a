//! The exact 1D sampler (`LineEngine::step_fast`) against the paper's sampler.
//!
//! Exactness is tested statistically, as in 2D and 3D (`sampler.rs`, `space_sampler.rs`): on
//! an inclusive interval, a periodic one and an inclusive one with a clearance, many fills are
//! run with each sampler (from disjoint seed sets) and the distributions of trial-free
//! statistics of chosen segments (the start of segment `i`, and the free length from its end
//! to the next segment or the end) are compared with the two-sample Kolmogorov–Smirnov test.
//! The family of all comparisons is held at significance 0.01 (Bonferroni). The seeds are
//! fixed, so the outcome is the same on every run. The same comparison must reject a biased
//! input (the paper's sampler on an interval 10% shorter), which shows it can fail.
//!
//! Besides: every fill of the exact sampler passes the two independent checkers of
//! `line.rs` (both scalars, both boundaries, with and without a clearance); the measure it
//! draws from is, at every step, the measure of valid starts found by brute force, never less
//! and more only by the slack; a halt it reports with fewer trials than the limit is checked to
//! leave no room; prefixes, reruns and larger storage give the same fill; too little storage
//! stops with an error after the same placements; steps of both samplers may be mixed.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
// The checks are written `!(a < b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod common;

use common::{check_pairs, check_sorted, ks};
use zetafill::internals::line::line_digest;
use zetafill::line::Segment;
use zetafill::line::{
    gaps_for as line_gaps_for, index_words as line_index_words, Engine as LineEngine, Gap as LineGap, Gaps as LineGaps, Interval,
    Params as LineParams, Storage as LineStorage,
};
use zetafill::{rng_from_seed, Fixed};
use zetafill::{Scalar, StepError, Stop, StopReason};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Sampler {
    Reference,
    Fast,
    /// The paper's sampler on an interval 10% shorter: a biased input for the checker.
    Short,
}

#[derive(Clone, Copy, Debug)]
struct Case {
    c: f64,
    n: f64,
    gap: f64,
    l: f64,
    periodic: bool,
}

impl Case {
    fn params(&self) -> LineParams {
        LineParams {
            gap: self.gap,
            max_trials: 1_000_000,
            ..LineParams::new(self.c, self.n)
        }
    }
}

/// A fill: the segments as f64 (start, length), the trials of each placement, why it stopped,
/// the digest, and the measure each placement of the exact sampler was drawn from.
struct Fill {
    segs: Vec<(f64, f64)>,
    trials: Vec<u64>,
    reason: StopReason,
    digest: (u64, u64),
    measures: Vec<f64>,
}

fn fill<S: Scalar>(case: &Case, sampler: Sampler, seed: u64, stop: &Stop, cap: usize, slots: usize) -> Fill {
    let mut segments = vec![Segment::<S>::default(); cap];
    let mut index = vec![0u32; line_index_words(cap)];
    let mut words = vec![LineGap::default(); slots];
    let l = if sampler == Sampler::Short { 0.9 * case.l } else { case.l };
    let storage = LineStorage {
        segments: &mut segments,
        index: &mut index,
    };
    let interval = Interval {
        length: l,
        periodic: case.periodic,
    };
    let mut e = LineEngine::new(case.params(), interval, storage).unwrap_or_else(|err| panic!("{case:?}: {err}"));
    let mut rng = rng_from_seed(seed);
    let (mut trials, mut measures) = (Vec::new(), Vec::new());
    let reason = if sampler == Sampler::Fast {
        let mut gaps = LineGaps::new(&mut words).expect("slots");
        loop {
            if stop.count.is_some_and(|k| e.placed().len() as u64 >= k) {
                break StopReason::Count;
            }
            if stop.min_size.is_some_and(|m| e.length_of(e.placed().len() as u64) < m) {
                break StopReason::MinSize;
            }
            match e.step_fast(&mut gaps, &mut rng) {
                Ok(p) => {
                    trials.push(p.trials);
                    measures.push(gaps.last_measure());
                }
                Err(err) => break StopReason::Step(err),
            }
        }
    } else {
        e.run(&mut rng, stop, |p| trials.push(p.trials))
    };
    Fill {
        segs: e.placed().iter().map(|s| (s.start.to_f64(), s.length.to_f64())).collect(),
        trials,
        reason,
        digest: line_digest(&e),
        measures,
    }
}

fn count(k: u64) -> Stop {
    Stop {
        count: Some(k),
        ..Stop::default()
    }
}

fn fast<S: Scalar>(case: &Case, seed: u64, stop: &Stop, cap: usize) -> Fill {
    fill::<S>(case, Sampler::Fast, seed, stop, cap, line_gaps_for(cap))
}

// ---------------------------------------------------------------------------------------------
// The distribution.
// ---------------------------------------------------------------------------------------------

const COUNT: u64 = 60;
const RUNS: u64 = 400;
/// The segments whose statistics are compared.
const PICKS: [usize; 3] = [2, 10, 40];
const STAT_NAMES: [&str; 2] = ["start", "free length after it"];
const FAMILY_ALPHA: f64 = 0.01;

fn cases() -> [Case; 3] {
    let base = Case {
        c: 1.4,
        n: 1.0,
        gap: 0.0,
        l: 100.0,
        periodic: false,
    };
    [base, Case { periodic: true, ..base }, Case { gap: 0.02, ..base }]
}

/// Segment `i`'s start and the free length from its end to the next segment (around the
/// circle when periodic, else to the end).
fn statistics(segs: &[(f64, f64)], case: &Case) -> Vec<f64> {
    let mut out = Vec::new();
    for &i in &PICKS {
        let (a, len) = segs[i];
        let end = a + len;
        let next = segs
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, s)| if case.periodic { (s.0 - end).rem_euclid(case.l) } else { s.0 - end })
            .filter(|&d| d > 0.0)
            .fold(if case.periodic { f64::INFINITY } else { case.l - end }, f64::min);
        out.extend([a, next]);
    }
    out
}

fn compare(case: &Case, sampler: Sampler) -> Vec<(String, f64)> {
    let columns = |sampler: Sampler, first: u64| {
        let mut cols: Vec<Vec<f64>> = Vec::new();
        for seed in first..first + RUNS {
            let f = fill::<f64>(case, sampler, seed, &count(COUNT), COUNT as usize, line_gaps_for(COUNT as usize));
            assert_eq!(f.reason, StopReason::Count, "{case:?} {sampler:?} seed {seed}");
            let st = statistics(&f.segs, case);
            cols.resize(st.len(), Vec::new());
            for (c, v) in cols.iter_mut().zip(st) {
                c.push(v);
            }
        }
        cols
    };
    let (reference, other) = (columns(Sampler::Reference, 1), columns(sampler, 1_000_001));
    reference
        .iter()
        .zip(&other)
        .enumerate()
        .map(|(k, (a, b))| {
            let (d, p) = ks(a, b);
            let name = STAT_NAMES[k % STAT_NAMES.len()];
            (format!("{case:?}: segment {} {name} (D = {d:.3})", PICKS[k / STAT_NAMES.len()]), p)
        })
        .collect()
}

fn alpha() -> f64 {
    FAMILY_ALPHA / (cases().len() * PICKS.len() * STAT_NAMES.len()) as f64
}

#[test]
fn same_distribution_as_reference() {
    let mut failures = Vec::new();
    for case in cases() {
        for (label, p) in compare(&case, Sampler::Fast) {
            if p < alpha() {
                failures.push(format!("{label}: p = {p:.2e} < {:.1e}", alpha()));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "the exact 1D sampler differs from the paper's:\n{}",
        failures.join("\n")
    );
}

#[test]
fn a_biased_input_fails_the_same_test() {
    let results = compare(&cases()[0], Sampler::Short);
    let worst = results.iter().map(|(_, p)| *p).fold(1.0, f64::min);
    assert!(worst < alpha(), "the biased input passed (smallest p = {worst:.2e}): {results:?}");
}

// ---------------------------------------------------------------------------------------------
// Valid fills, with both scalars.
// ---------------------------------------------------------------------------------------------

fn valid(f: &Fill, case: &Case) -> Result<(), String> {
    check_pairs(&f.segs, case.l, case.gap, case.periodic)?;
    check_sorted(&f.segs, case.l, case.gap, case.periodic)
}

#[test]
fn fills_are_valid_with_both_scalars() {
    for periodic in [false, true] {
        for gap in [0.0, 0.01] {
            for c in [1.15, 1.4, 2.0] {
                for seed in 1..4 {
                    let case = Case {
                        c,
                        n: 1.0,
                        gap,
                        l: 200.0,
                        periodic,
                    };
                    let f = fast::<f64>(&case, seed, &count(3000), 3000);
                    valid(&f, &case).unwrap_or_else(|e| panic!("f64 {case:?} seed {seed}: {e}"));
                    // Fixed point resolves 0.01 mm: stop before that.
                    let stop = Stop {
                        min_size: Some(0.02),
                        ..count(3000)
                    };
                    let g = fast::<Fixed>(&case, seed, &stop, 3000);
                    valid(&g, &case).unwrap_or_else(|e| panic!("Fixed {case:?} seed {seed}: {e}"));
                    for r in [f.reason, g.reason] {
                        assert!(
                            matches!(
                                r,
                                StopReason::Count | StopReason::MinSize | StopReason::Step(StepError::Halted { .. })
                            ),
                            "{case:?}: {r:?}"
                        );
                    }
                    assert!(
                        f.segs.len() > 50 && g.segs.len() > 50,
                        "{case:?}: {} / {}",
                        f.segs.len(),
                        g.segs.len()
                    );
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The measure drawn from is the valid measure.
// ---------------------------------------------------------------------------------------------

/// The measure of valid starts of a segment of length `len` among `segs`, by brute force:
/// the sum over the free stretches (sorted) of their length less `len + 2 gap`, when positive.
fn valid_measure(segs: &[(f64, f64)], len: f64, case: &Case) -> f64 {
    let mut v = segs.to_vec();
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut free = Vec::new();
    if case.periodic {
        if v.is_empty() {
            return case.l;
        }
        for w in v.windows(2) {
            free.push(w[1].0 - (w[0].0 + w[0].1));
        }
        let (first, last) = (v[0], v[v.len() - 1]);
        free.push(first.0 + case.l - (last.0 + last.1));
    } else {
        let mut at = 0.0;
        for s in &v {
            free.push(s.0 - at);
            at = s.0 + s.1;
        }
        free.push(case.l - at);
    }
    free.iter().map(|g| (g - len - 2.0 * case.gap).max(0.0)).sum()
}

/// Each placement's measure against the brute-force one: never below it, above it by at most
/// `slack` per segment placed.
fn check_measures(f: &Fill, case: &Case, first: usize) -> Result<(), String> {
    let slack = 1e-12 * case.l;
    for (i, &m) in f.measures.iter().enumerate().skip(first) {
        let want = valid_measure(&f.segs[..i], f.segs[i].1, case);
        if !(m >= want - 1e-9 * slack && m <= want + (i + 2) as f64 * slack) {
            return Err(format!("placement {i}: measure {m} against {want}"));
        }
    }
    Ok(())
}

#[test]
fn the_measure_drawn_from_is_the_valid_measure() {
    for case in cases() {
        for c in [1.3, 1.8] {
            let case = Case { c, ..case };
            let f = fast::<f64>(&case, 7, &count(400), 400);
            // On a circle the first placement is the paper's draw.
            let first = usize::from(case.periodic);
            assert_eq!(f.measures.len(), f.segs.len());
            check_measures(&f, &case, first).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        }
    }
}

#[test]
fn the_measure_check_fails_on_a_wrong_measure() {
    let case = cases()[0];
    let mut f = fast::<f64>(&case, 7, &count(200), 200);
    assert!(check_measures(&f, &case, 0).is_ok());
    f.measures[150] *= 0.999;
    assert!(check_measures(&f, &case, 0).is_err(), "a measure too small passed");
    f.measures[150] /= 0.999 * 0.999;
    assert!(check_measures(&f, &case, 0).is_err(), "a measure too large passed");
}

// ---------------------------------------------------------------------------------------------
// Halting.
// ---------------------------------------------------------------------------------------------

/// Whether no start is left for segment `next` (of length `len`): the brute-force measure is
/// zero.
fn no_room(segs: &[(f64, f64)], len: f64, case: &Case) -> bool {
    valid_measure(segs, len, case) <= 1e-12 * case.l
}

#[test]
fn a_proven_halt_leaves_no_room() {
    let mut halts = 0;
    for periodic in [false, true] {
        for seed in 1..40 {
            // A clearance that the segments soon fall below: the fills halt.
            let case = Case {
                c: 1.4,
                n: 1.0,
                gap: 0.3,
                l: 100.0,
                periodic,
            };
            let f = fast::<f64>(&case, seed, &count(2000), 2000);
            if let StopReason::Step(StepError::Halted { index, trials }) = f.reason {
                assert!(trials < 1_000_000, "seed {seed}: a halt after the trial limit");
                let len = 100.0 / (zeta(1.4, 1.0) * (index as f64 + 1.0).powf(1.4));
                assert!(no_room(&f.segs, len, &case), "seed {seed}: halted at {index} with room left");
                halts += 1;
            }
        }
    }
    assert!(halts > 60, "too few halts to test ({halts})");
}

#[test]
fn the_no_room_check_fails_where_there_is_room() {
    let case = cases()[0];
    let f = fast::<f64>(&case, 3, &count(100), 100);
    assert!(!no_room(&f.segs, 1e-3, &case));
}

/// Where the second segment cannot fit whatever the first does, both samplers halt there: the
/// exact one at once, the paper's after its trial limit.
#[test]
fn a_certain_halt_is_found_at_once_and_the_paper_agrees() {
    let case = Case {
        c: 2.0,
        n: 1.0,
        gap: 0.13,
        l: 1.0,
        periodic: false,
    };
    let f = fast::<f64>(&case, 1, &count(10), 10);
    assert_eq!(f.reason, StopReason::Step(StepError::Halted { index: 1, trials: 0 }));
    let r = fill::<f64>(&case, Sampler::Reference, 1, &count(10), 10, 0);
    assert_eq!(
        r.reason,
        StopReason::Step(StepError::Halted {
            index: 1,
            trials: 1_000_000
        })
    );
}

fn zeta(c: f64, n: f64) -> f64 {
    zetafill::internals::zeta::hurwitz_zeta(c, n).expect("zeta")
}

// ---------------------------------------------------------------------------------------------
// Determinism and storage.
// ---------------------------------------------------------------------------------------------

#[test]
fn prefixes_reruns_and_storage_give_the_same_fill() {
    for case in &cases()[..2] {
        let long = fast::<f64>(case, 11, &count(3000), 3000);
        let short = fast::<f64>(case, 11, &count(500), 500);
        assert_eq!(&long.segs[..500], &short.segs[..], "{case:?}: prefix");
        let again = fast::<f64>(case, 11, &count(3000), 3000);
        assert_eq!((again.digest, &again.trials), (long.digest, &long.trials), "{case:?}: rerun");
        let roomy = fill::<f64>(case, Sampler::Fast, 11, &count(3000), 5000, 3 * line_gaps_for(5000));
        assert_eq!(roomy.digest, long.digest, "{case:?}: more storage");
        // Too little: the same placements, then an error.
        let tight = fill::<f64>(case, Sampler::Fast, 11, &count(3000), 3000, line_gaps_for(999));
        assert!(
            matches!(tight.reason, StopReason::Step(StepError::Capacity { capacity: 999 })),
            "{case:?}: {:?}",
            tight.reason
        );
        assert_eq!(&long.segs[..tight.segs.len()], &tight.segs[..]);
        assert!(tight.segs.len() >= 999);
        // Fixed point too.
        let stop = Stop {
            min_size: Some(0.05),
            ..count(3000)
        };
        let a = fast::<Fixed>(case, 5, &stop, 3000);
        let b = fast::<Fixed>(case, 5, &stop, 3000);
        assert_eq!(a.digest, b.digest);
    }
    // With a clearance the fill halts; prefixes still hold, to the halt.
    let case = cases()[2];
    let long = fast::<f64>(&case, 11, &count(3000), 3000);
    let short = fast::<f64>(&case, 11, &count(40), 3000);
    assert_eq!(&long.segs[..40], &short.segs[..]);
}

#[test]
fn the_two_samplers_may_take_turns() {
    for case in cases() {
        let mut segments = vec![Segment::<f64>::default(); 600];
        let mut index = vec![0u32; line_index_words(600)];
        let mut words = vec![LineGap::default(); line_gaps_for(600)];
        let storage = LineStorage {
            segments: &mut segments,
            index: &mut index,
        };
        let interval = Interval {
            length: case.l,
            periodic: case.periodic,
        };
        let mut e = LineEngine::new(case.params(), interval, storage).expect("engine");
        let mut gaps = LineGaps::new(&mut words).expect("slots");
        let mut rng = rng_from_seed(3);
        for i in 0..600 {
            let r = if (i / 7) % 2 == 0 {
                e.step_fast(&mut gaps, &mut rng)
            } else {
                e.step(&mut rng)
            };
            match r {
                Ok(_) => {}
                Err(StepError::Halted { .. }) if case.gap > 0.0 && i > 40 => break,
                Err(err) => panic!("{case:?} step {i}: {err}"),
            }
        }
        let segs: Vec<(f64, f64)> = e.placed().iter().map(|s| (s.start, s.length)).collect();
        let f = Fill {
            segs,
            trials: Vec::new(),
            reason: StopReason::Count,
            digest: (0, 0),
            measures: Vec::new(),
        };
        valid(&f, &case).unwrap_or_else(|err| panic!("{case:?}: {err}"));
    }
}

// ---------------------------------------------------------------------------------------------
// No input panics.
// ---------------------------------------------------------------------------------------------

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 256,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x1d02),
        ..proptest::prelude::ProptestConfig::default()
    })]

    /// Arbitrary numbers (NaN and infinities included) and storage of any size, the samplers in
    /// turn: an error or a valid fill, never a panic.
    #[test]
    fn no_input_panics(c in proptest::prop_oneof![proptest::prelude::any::<f64>(), 1.0f64..4.0],
                       n in proptest::prop_oneof![proptest::prelude::any::<f64>(), 0.0f64..10.0],
                       gap in proptest::prop_oneof![proptest::prelude::any::<f64>(), 0.0f64..1.0],
                       l in proptest::prop_oneof![proptest::prelude::any::<f64>(), 1e-300f64..1e-290, 0.0f64..10.0],
                       periodic in proptest::prelude::any::<bool>(), max_trials in 0u64..50, cap in 0usize..40,
                       words in 0usize..300, seed in proptest::prelude::any::<u64>()) {
        let mut segs = vec![Segment::<f64>::default(); cap];
        let mut index = vec![0u32; line_index_words(cap)];
        let mut slots = vec![LineGap::default(); words];
        let params = LineParams { c, n_offset: n, gap, max_trials };
        let storage = LineStorage { segments: &mut segs, index: &mut index };
        if let (Ok(mut e), Ok(mut gaps)) = (LineEngine::new(params, Interval { length: l, periodic }, storage), LineGaps::new(&mut slots)) {
            let mut rng = rng_from_seed(seed);
            let stop = Stop { count: Some(30), fill: Some(0.9), min_size: Some(1e-12) };
            let _ = e.run_fast(&mut gaps, &mut rng, &stop, |_| {});
            for _ in 0..3 {
                let _ = e.step(&mut rng);
                let _ = e.step_fast(&mut gaps, &mut rng);
            }
            let segs: Vec<(f64, f64)> = e.placed().iter().map(|s| (s.start, s.length)).collect();
            proptest::prop_assert!(check_pairs(&segs, l, gap, periodic).is_ok());
        }
    }
}
