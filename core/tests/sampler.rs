//! The cell sampler against the reference sampler.
//!
//! Exactness is tested statistically: for circles, squares and rings, in an inclusive and in a
//! periodic square, many fills are run with each sampler (from disjoint seed sets) and the
//! distributions of trial-free statistics of chosen shapes (the position of shape `i`, the
//! room its bounding circle had when placed, the distance to the nearest other centre) are
//! compared with the two-sample Kolmogorov–Smirnov test. The family of all comparisons is held
//! at significance 0.01 (Bonferroni: each test at 0.01 / number of tests); with 500 fills a
//! side, a test rejects when the distribution functions differ by more than about 0.14. The
//! seeds are fixed, so the outcome is the same on every run. The same comparison must reject
//! a biased input (fills of a region 10% narrower), which shows it can fail.
//!
//! The invariant the exactness argument rests on (every valid centre lies in a live cell) is
//! checked directly in `live_cells.rs`.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{ks, params, Buffers};
use zetafill::internals::geom::separated;

use zetafill::{
    cells_for, rng_from_seed, Batches, CellSampler, Engine, Lane, Params, Placed, Region, ShapeKind, StepError, Stop, StopReason,
};

const COUNT: u64 = 60;
const RUNS: u64 = 500;
/// The shapes whose statistics are compared.
const PICKS: [usize; 2] = [12, 45];
/// Family-wise significance of all the comparisons in `same_distribution_as_reference`.
const FAMILY_ALPHA: f64 = 0.01;

#[derive(Clone, Copy, PartialEq)]
enum Sampler {
    Reference,
    Fast,
    /// The batched cell sampler.
    Batched,
    /// The reference sampler in a region 10% narrower: a biased input for the checker.
    Narrow,
}

fn region(periodic: bool) -> Region<'static> {
    Region::Rect {
        width: 100.0,
        height: 100.0,
        periodic,
    }
}

fn narrow(periodic: bool) -> Region<'static> {
    Region::Rect {
        width: 90.0,
        height: 100.0,
        periodic,
    }
}

/// One fill; the placed shapes (all `COUNT`, or the test fails).
fn fill(kind: ShapeKind, periodic: bool, sampler: Sampler, seed: u64, count: u64) -> Vec<Placed<f64>> {
    let cap = count as usize;
    let mut buffers = Buffers::<f64>::new(cap);
    let mut cov = vec![0u64; 1 << 10];
    let storage = buffers.storage(&mut cov);
    let r = if sampler == Sampler::Narrow {
        narrow(periodic)
    } else {
        region(periodic)
    };
    let mut e = Engine::<f64>::new(params(kind), r, storage).expect("valid parameters");
    let mut rng = rng_from_seed(seed);
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    // One pool size for every count: a fill's shapes depend on the pool only once it is
    // full (then it stops refining), and this one never fills.
    let mut pool = vec![[0u64; 4]; cells_for(200)];
    let reason = match sampler {
        Sampler::Reference | Sampler::Narrow => e.run(&mut rng, &stop, |_| {}),
        Sampler::Fast => {
            let mut cells = CellSampler::new(&mut pool).expect("cells");
            e.run_fast(&mut cells, &mut rng, &stop, |_| {})
        }
        Sampler::Batched => {
            let mut cells = CellSampler::new(&mut pool).expect("cells");
            let mut lanes = vec![Lane::default(); 64];
            let mut batches = Batches::new(&mut lanes, seed, 64).expect("lanes");
            e.run_batched(&mut cells, &mut batches, &stop, |_| {})
        }
    };
    assert_eq!(reason, StopReason::Count, "{kind:?} periodic {periodic} seed {seed}");
    e.placed().to_vec()
}

/// Centre distance, to the nearest image in a periodic square of side 100.
fn centre_dist(a: &Placed<f64>, b: &Placed<f64>, periodic: bool) -> f64 {
    let fold = |d: f64| if periodic { d.abs().min(100.0 - d.abs()) } else { d };
    let (dx, dy) = (fold(a.x - b.x), fold(a.y - b.y));
    (dx * dx + dy * dy).sqrt()
}

/// The statistics of one fill: for each picked shape, x, y, its margin (the room its bounding
/// circle had: the distance to the nearest bounding circle placed before it, or to the edge),
/// and the distance to the nearest centre placed at all.
fn statistics(kind: ShapeKind, shapes: &[Placed<f64>], periodic: bool) -> Vec<f64> {
    let mut out = Vec::new();
    for &i in &PICKS {
        let s = &shapes[i];
        let radius = |p: &Placed<f64>| kind.bounding_radius(p.scale);
        let edge = if periodic {
            f64::INFINITY
        } else {
            s.x.min(100.0 - s.x).min(s.y).min(100.0 - s.y)
        };
        let margin = shapes[..i]
            .iter()
            .map(|o| centre_dist(s, o, periodic) - radius(o))
            .fold(edge, f64::min)
            - radius(s);
        let nearest = shapes
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, o)| centre_dist(s, o, periodic))
            .fold(f64::INFINITY, f64::min);
        out.extend([s.x, s.y, margin, nearest]);
    }
    out
}

const STAT_NAMES: [&str; 4] = ["x", "y", "margin", "nearest centre"];

/// Every statistic's samples over `RUNS` fills (seeds from `first_seed`).
fn samples(kind: ShapeKind, periodic: bool, sampler: Sampler, first_seed: u64) -> Vec<Vec<f64>> {
    let mut cols: Vec<Vec<f64>> = Vec::new();
    for seed in first_seed..first_seed + RUNS {
        let st = statistics(kind, &fill(kind, periodic, sampler, seed, COUNT), periodic);
        cols.resize(st.len(), Vec::new());
        for (c, v) in cols.iter_mut().zip(st) {
            c.push(v);
        }
    }
    cols
}

fn cases() -> Vec<(ShapeKind, bool)> {
    let kinds = [ShapeKind::Circle, ShapeKind::Square, ShapeKind::Ring { inner: 0.5 }];
    kinds.iter().flat_map(|&k| [(k, false), (k, true)]).collect()
}

/// (label, p) of every comparison between `sampler` and the reference for one case.
fn compare(kind: ShapeKind, periodic: bool, sampler: Sampler) -> Vec<(String, f64)> {
    let reference = samples(kind, periodic, Sampler::Reference, 1);
    let other = samples(kind, periodic, sampler, 1_000_001);
    let mut out = Vec::new();
    for (k, (a, b)) in reference.iter().zip(&other).enumerate() {
        let (d, p) = ks(a, b);
        let label = format!(
            "{kind:?} periodic {periodic}: shape {} {} (D = {d:.3})",
            PICKS[k / STAT_NAMES.len()],
            STAT_NAMES[k % STAT_NAMES.len()]
        );
        out.push((label, p));
    }
    out
}

/// The cell sampler and the batched one, each against the reference, as one family (the
/// batches of these 60-shape fills grow to 7 placements, so later shapes are often committed
/// after an earlier one of their batch took their screened candidate's room).
#[test]
fn same_distribution_as_reference() {
    let cases = cases();
    let samplers = [Sampler::Fast, Sampler::Batched];
    let tests = samplers.len() * cases.len() * PICKS.len() * STAT_NAMES.len();
    let alpha = FAMILY_ALPHA / tests as f64;
    let mut failures = Vec::new();
    for sampler in samplers {
        for &(kind, periodic) in &cases {
            for (label, p) in compare(kind, periodic, sampler) {
                if p < alpha {
                    let name = if sampler == Sampler::Fast { "cells" } else { "batched" };
                    failures.push(format!("{name}, {label}: p = {p:.2e} < {alpha:.1e}"));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "a sampler differs from the reference:\n{}",
        failures.join("\n")
    );
}

#[test]
fn a_biased_input_fails_the_same_test() {
    let tests = 2 * cases().len() * PICKS.len() * STAT_NAMES.len();
    let alpha = FAMILY_ALPHA / tests as f64;
    let results = compare(ShapeKind::Circle, false, Sampler::Narrow);
    let worst = results.iter().map(|(_, p)| *p).fold(1.0, f64::min);
    assert!(worst < alpha, "the biased input passed (smallest p = {worst:.2e}): {results:?}");
}

#[test]
fn ks_test_separates_distributions_and_accepts_equal_ones() {
    // Deterministic uniform-looking samples from the engine's generator.
    let mut rng = rng_from_seed(7);
    let mut u = || zetafill::internals::rng::unit::<f64, _>(&mut rng);
    let a: Vec<f64> = (0..2000).map(|_| u()).collect();
    let b: Vec<f64> = (0..2000).map(|_| u()).collect();
    let shifted: Vec<f64> = (0..2000).map(|_| u() * 0.9 + 0.1).collect();
    assert!(ks(&a, &b).1 > 0.01, "equal distributions rejected: {:?}", ks(&a, &b));
    assert!(ks(&a, &shifted).1 < 1e-4, "a shifted distribution accepted: {:?}", ks(&a, &shifted));
}

/// The trials of one fill of `COUNT` shapes by the reference sampler, or (`fast`) the cell
/// sampler's estimate of them ([`CellSampler::paper_trials`]).
fn paper_trials(kind: ShapeKind, periodic: bool, fast: bool, seed: u64) -> f64 {
    let cap = COUNT as usize;
    let mut buffers = Buffers::<f64>::new(cap);
    let mut cov = vec![0u64; 1 << 10];
    let storage = buffers.storage(&mut cov);
    let mut e = Engine::<f64>::new(params(kind), region(periodic), storage).expect("valid parameters");
    let mut rng = rng_from_seed(seed);
    let stop = Stop {
        count: Some(COUNT),
        ..Stop::default()
    };
    let mut pool = vec![[0u64; 4]; cells_for(200)];
    let mut cells = CellSampler::new(&mut pool).expect("cells");
    cells.estimate_paper_trials();
    let mut trials = 0u64;
    let reason = if fast {
        e.run_fast(&mut cells, &mut rng, &stop, |_| {})
    } else {
        e.run(&mut rng, &stop, |p| trials += p.trials)
    };
    assert_eq!(reason, StopReason::Count, "{kind:?} periodic {periodic} seed {seed}");
    if fast {
        cells.paper_trials()
    } else {
        trials as f64
    }
}

/// Welch's two-sample test of equal means: the statistic and its two-sided p-value (normal
/// approximation, right for samples of hundreds).
fn welch(a: &[f64], b: &[f64]) -> (f64, f64) {
    let moments = |v: &[f64]| {
        let n = v.len() as f64;
        let mean = v.iter().sum::<f64>() / n;
        (mean, v.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1.0) / n)
    };
    let ((ma, va), (mb, vb)) = (moments(a), moments(b));
    let t = (ma - mb) / (va + vb).sqrt();
    (t, libm::erfc(t.abs() / core::f64::consts::SQRT_2))
}

/// Significance of the whole family of mean comparisons below (Bonferroni over the cases).
const TRIALS_ALPHA: f64 = 0.01;
const TRIALS_RUNS: u64 = 400;

/// (label, p) of comparing the mean trials of the reference's fills with the mean estimate of
/// the cell sampler's, each estimate multiplied by `scale` (1 but for the biased input).
fn compare_trials(kind: ShapeKind, periodic: bool, scale: f64) -> (String, f64) {
    let reference: Vec<f64> = (1..=TRIALS_RUNS).map(|s| paper_trials(kind, periodic, false, s)).collect();
    let fast: Vec<f64> = (1_000_001..=1_000_000 + TRIALS_RUNS)
        .map(|s| scale * paper_trials(kind, periodic, true, s))
        .collect();
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (t, p) = welch(&reference, &fast);
    let label = format!(
        "{kind:?} periodic {periodic}: reference {:.1} trials a fill, estimate {:.1} (t = {t:.2})",
        mean(&reference),
        mean(&fast)
    );
    (label, p)
}

fn trial_cases() -> [(ShapeKind, bool); 3] {
    [
        (ShapeKind::Circle, false),
        (ShapeKind::Square, true),
        (ShapeKind::Ring { inner: 0.5 }, false),
    ]
}

#[test]
fn the_cell_sampler_estimates_the_papers_trials() {
    let alpha = TRIALS_ALPHA / trial_cases().len() as f64;
    let failures: Vec<String> = trial_cases()
        .iter()
        .map(|&(kind, periodic)| compare_trials(kind, periodic, 1.0))
        .inspect(|(label, p)| eprintln!("{label}: p = {p:.3}"))
        .filter(|(_, p)| *p < alpha)
        .map(|(label, p)| format!("{label}: p = {p:.2e} < {alpha:.1e}"))
        .collect();
    assert!(
        failures.is_empty(),
        "the estimate misses the paper's trials:\n{}",
        failures.join("\n")
    );
}

#[test]
fn estimating_the_papers_trials_changes_no_placement() {
    let run = |estimate: bool| {
        let mut buffers = Buffers::<f64>::new(300);
        let storage = buffers.storage(&mut []);
        let mut e = Engine::<f64>::new(params(ShapeKind::Circle), region(true), storage).expect("valid");
        let mut pool = vec![[0u64; 4]; cells_for(300)];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        if estimate {
            cells.estimate_paper_trials();
        }
        let stop = Stop {
            count: Some(300),
            ..Stop::default()
        };
        let mut trials = Vec::new();
        e.run_fast(&mut cells, &mut rng_from_seed(5), &stop, |p| trials.push(p.trials));
        let (paper, last) = (cells.paper_trials(), cells.last_paper_trials());
        (e.placed().to_vec(), trials, paper, last)
    };
    let (with, without) = (run(true), run(false));
    assert_eq!(with.0, without.0, "the placements differ");
    assert_eq!(with.1, without.1, "the trials differ");
    assert_eq!((without.2, without.3), (0.0, 0.0), "an estimate made while off");
    // Each placement's estimate is positive, so the total exceeds the last one.
    assert!(with.2 > with.3 && with.3 > 0.0, "estimates {} and {}", with.2, with.3);
}

#[test]
fn an_estimate_ten_percent_high_fails_the_same_test() {
    let alpha = TRIALS_ALPHA / trial_cases().len() as f64;
    let (label, p) = compare_trials(ShapeKind::Circle, false, 1.1);
    assert!(p < alpha, "the biased estimate passed: {label}, p = {p:.2e}");
}

/// Also with a storage sized to each count: the first shapes depend on neither.
#[test]
fn fast_fills_are_deterministic_and_prefix_stable() {
    for sampler in [Sampler::Fast, Sampler::Batched] {
        for (kind, periodic) in cases() {
            let a = fill(kind, periodic, sampler, 99, 200);
            let b = fill(kind, periodic, sampler, 99, 200);
            assert_eq!(a, b, "{kind:?} periodic {periodic}: reruns differ");
            // 83 ends inside a batch (80 .. 90).
            for k in [80, 83] {
                let prefix = fill(kind, periodic, sampler, 99, k);
                assert_eq!(&a[..k as usize], &prefix[..], "{kind:?} periodic {periodic}: prefix of {k} differs");
            }
        }
    }
}

#[test]
fn fast_sampler_takes_far_fewer_trials_late_in_a_fill() {
    let run = |fast: bool| {
        let cap = 4000;
        let mut buffers = Buffers::<f64>::new(cap);
        let mut cov = vec![0u64; 1 << 12];
        let storage = buffers.storage(&mut cov);
        let mut e = Engine::<f64>::new(Params::circles(1.3, 1.0), region(false), storage).expect("valid");
        let mut rng = rng_from_seed(3);
        let mut pool = vec![[0u64; 4]; cells_for(cap)];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        let stop = Stop {
            count: Some(cap as u64),
            ..Stop::default()
        };
        let mut late = 0u64;
        let reason = if fast {
            e.run_fast(&mut cells, &mut rng, &stop, |p| late += if p.index >= 3000 { p.trials } else { 0 })
        } else {
            e.run(&mut rng, &stop, |p| late += if p.index >= 3000 { p.trials } else { 0 })
        };
        assert_eq!(reason, StopReason::Count);
        late as f64 / 1000.0
    };
    let (reference, fast) = (run(false), run(true));
    assert!(fast * 4.0 < reference, "trials per placement: fast {fast}, reference {reference}");
}

#[test]
fn halts_with_certainty_when_nothing_fits() {
    // Large gaps in a small square: a few circles fit, then none can. The cell sampler
    // usually finds that out long before the trial limit (its live cells run out); when the
    // last room shrinks to a point of tangency, cells refine to the finest level and the trial
    // limit ends the fill, as it does for the reference.
    let limit = 2_000_000;
    let mut certain = 0;
    for seed in 1..=7 {
        let cap = 100;
        let mut buffers = Buffers::<f64>::new(cap);
        let storage = buffers.storage(&mut []);
        let mut p = Params::circles(1.05, 1.0);
        p.gap = 2.0;
        p.max_trials = limit;
        let square = Region::Rect {
            width: 20.0,
            height: 20.0,
            periodic: false,
        };
        let mut e = Engine::<f64>::new(p, square, storage).expect("valid");
        let mut rng = rng_from_seed(seed);
        let mut pool = vec![[0u64; 4]; 100_000];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        match e.run_fast(&mut cells, &mut rng, &Stop::default(), |_| {}) {
            StopReason::Step(StepError::Halted { index, trials }) => {
                assert!(index >= 2, "seed {seed}: halted at {index}");
                if trials < limit {
                    assert_eq!(cells.stats().live, 0, "seed {seed}: halted early with live cells");
                    certain += 1;
                }
            }
            other => panic!("seed {seed}: expected a halt, got {other:?}"),
        }
    }
    assert!(certain >= 5, "only {certain} of 7 fills halted before the trial limit");
}

#[test]
fn fixed_point_fast_fills_are_valid_and_deterministic() {
    // The scalar the firmware uses without an FPU: the cell sampler must keep every exact
    // guarantee with it too.
    use zetafill::{Fixed, Scalar};
    let run = || {
        let cap = 400;
        let mut buffers = Buffers::<Fixed>::new(cap);
        let storage = buffers.storage(&mut []);
        let mut e = Engine::<Fixed>::new(params(ShapeKind::Circle), region(false), storage).expect("valid");
        let mut rng = rng_from_seed(21);
        let mut pool = vec![[0u64; 4]; 1 << 14];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        let stop = Stop {
            count: Some(cap as u64),
            ..Stop::default()
        };
        assert_eq!(e.run_fast(&mut cells, &mut rng, &stop, |_| {}), StopReason::Count);
        (0..cap).filter_map(|i| e.geo(i).and_then(|g| g.owned())).collect::<Vec<_>>()
    };
    let geos = run();
    assert_eq!(geos.len(), 400);
    for (i, a) in geos.iter().enumerate() {
        for b in &geos[i + 1..] {
            assert!(separated(a, b, Fixed::from_f64(0.0)), "overlap in a fixed-point fast fill");
        }
        let (x0, y0, x1, y1) = a.bounds();
        assert!(x0.to_f64() >= 0.0 && y0.to_f64() >= 0.0 && x1.to_f64() <= 100.0 && y1.to_f64() <= 100.0);
    }
    assert_eq!(geos, run(), "fixed-point reruns differ");
}

#[test]
fn memory_per_shape_is_as_stated() {
    // The library's docs: a cell takes 32 bytes (`CellWords`, four u64), and circle fills at
    // c = 1.3 lent `cells_for` their capacity hold 5 to 6 cells per shape at their peak (the
    // cells too tight for every shape of the fill are not kept), far below the sampler's
    // budget, so nothing limits their refinement.
    let cap = 20_000;
    let mut buffers = Buffers::<f64>::new(cap);
    let storage = buffers.storage(&mut []);
    let region = Region::Rect {
        width: 200.0,
        height: 200.0,
        periodic: false,
    };
    let mut e = Engine::<f64>::new(Params::circles(1.3, 1.0), region, storage).expect("valid");
    let mut rng = rng_from_seed(1);
    let mut pool = vec![[0u64; 4]; cells_for(cap)];
    let mut cells = CellSampler::new(&mut pool).expect("cells");
    let stop = Stop {
        count: Some(cap as u64),
        ..Stop::default()
    };
    assert_eq!(e.run_fast(&mut cells, &mut rng, &stop, |_| {}), StopReason::Count);
    let st = cells.stats();
    let per_shape = st.peak as f64 / cap as f64;
    assert!(per_shape <= 8.0, "{per_shape} cells per shape at the peak ({st:?})");
    assert_eq!(st.refused_splits, 0, "the pool ran out");
}
