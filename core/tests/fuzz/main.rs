//! Fuzzing the engine: arbitrary parameters (c, N, gap, every shape and mixes of them, every
//! region kind with polygons of many forms, every stop condition, small trial limits and
//! storage, seeds) on both scalars (`f64` and [`Fixed`]) with both samplers
//! ([`Engine::step`] and [`Engine::step_fast`] over a [`CellSampler`]). proptest is the
//! engine (libFuzzer needs a nightly toolchain).
//!
//! Each case must not panic, must draw no more random numbers than its trial limits allow
//! (a bound on the work, so a runaway loop is caught), must stop for a reason that holds
//! (the count reached, the storage full, a halt at the placement it names, ...), must give
//! every shape its power-law area, and must pass [`checker::check`]: an independent exact
//! check, in `f64`, that no two shapes (or periodic images) come within the gap and that
//! every shape lies inside the region with its gap. Fixed-point fills are checked on their
//! outlines converted to `f64`.
//!
//! `ZETAFILL_FUZZ_CASES` sets the number of cases of each test (default: a few hundred, a
//! few seconds in release mode); `ZETAFILL_FUZZ_SEED` changes the seed (default fixed, so the
//! default run is the same on every machine). A failure is shrunk, then its seed is kept in
//! `core/proptest-regressions/` and tried first on later runs. See docs/testing.md.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
// Negated comparisons are deliberate: they treat NaN as a failure.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod checker;
mod strategies;
mod twins;

use checker::{Area, Fill, Mat, Tolerance};
use proptest::test_runner::{Config, FileFailurePersistence, RngSeed, TestCaseError, TestRunner};
use rand_core::RngCore;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use strategies::{Case, Drive, RegionGen, Sampler, Scal};
use zetafill::{
    index_words, rng_from_seed, CellSampler, Engine, Fixed, Placed, Placement, PolygonRegion, Region, Scalar, StepError, StopReason,
    Storage, ZetaRng,
};

/// The number of cases of a test: `ZETAFILL_FUZZ_CASES`, or `default`.
fn cases(default: u32) -> u32 {
    std::env::var("ZETAFILL_FUZZ_CASES")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(default)
}

/// The runner of the test `name`: its cases, the seed, and its own regression file.
fn runner(name: &'static str, default_cases: u32) -> TestRunner {
    let seed = std::env::var("ZETAFILL_FUZZ_SEED")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(0x5eed_f022);
    let file: &'static str = Box::leak(format!("{}/proptest-regressions/fuzz/{name}.txt", env!("CARGO_MANIFEST_DIR")).into_boxed_str());
    TestRunner::new(Config {
        cases: cases(default_cases),
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(file))),
        rng_seed: RngSeed::Fixed(seed),
        max_shrink_iters: 4096,
        ..Config::default()
    })
}

/// The generator of a case with a budget: drawing more numbers than the case's trial limits
/// allow is a runaway loop.
struct BudgetRng {
    inner: ZetaRng,
    left: u64,
}

impl RngCore for BudgetRng {
    fn next_u32(&mut self) -> u32 {
        self.next_u64() as u32
    }
    fn next_u64(&mut self) -> u64 {
        if self.left == 0 {
            panic!("the engine drew more random numbers than its trial limits allow");
        }
        self.left -= 1;
        self.inner.next_u64()
    }
    fn fill_bytes(&mut self, dst: &mut [u8]) {
        for chunk in dst.chunks_mut(8) {
            let b = self.next_u64().to_le_bytes();
            chunk.copy_from_slice(&b[..chunk.len()]);
        }
    }
}

/// What the cases did, for the summary each test prints (and checks, so that a generator
/// that drifts into refused inputs is noticed).
#[derive(Default)]
struct Tally {
    cases: AtomicU64,
    refused: AtomicU64,
    fills: AtomicU64,
    shapes: AtomicU64,
    halted: AtomicU64,
}

impl Tally {
    fn report(&self, what: &str) {
        let get = |a: &AtomicU64| a.load(Relaxed);
        eprintln!(
            "{what}: {} cases, {} refused up front, {} fills with {} shapes in all, {} halted",
            get(&self.cases),
            get(&self.refused),
            get(&self.fills),
            get(&self.shapes),
            get(&self.halted)
        );
        assert!(
            get(&self.fills) * 5 >= get(&self.cases) * 2,
            "{what}: fewer than 40% of the cases placed a shape; the generator has drifted"
        );
    }
}

/// The independent checker's view of the region.
fn area_of(r: &RegionGen) -> Area {
    match r {
        RegionGen::Rect { w, h, periodic: false } => Area::Rect { w: *w, h: *h },
        RegionGen::Rect { w, h, periodic: true } => Area::Torus { w: *w, h: *h },
        RegionGen::Circle { r } => Area::Disc { r: *r },
        RegionGen::Annulus { outer, inner } => Area::Annulus {
            outer: *outer,
            inner: *inner,
        },
        RegionGen::Polygon { points, ends } => {
            let mut rings = Vec::new();
            let mut start = 0;
            for &e in ends {
                rings.push(points[start..e].iter().map(|p| [p.x, p.y]).collect());
                start = e;
            }
            Area::Polygon(rings)
        }
    }
}

/// How the run ended.
enum End {
    /// `run` / `run_fast` returned this.
    Stopped(StopReason),
    /// `step` / `step_fast` reached the count, or failed with this.
    Stepped(Option<StepError>),
}

/// Runs a case and checks it. `Ok(false)`: the inputs were refused (by `PolygonRegion::new`,
/// `Engine::new` or `CellSampler::new`) with an error value.
fn run_case<S: Scalar>(case: &Case, tally: &Tally) -> Result<bool, String> {
    let region = match &case.region {
        RegionGen::Rect { w, h, periodic } => Region::Rect {
            width: *w,
            height: *h,
            periodic: *periodic,
        },
        RegionGen::Circle { r } => Region::Circle { radius: *r },
        RegionGen::Annulus { outer, inner } => Region::Annulus {
            outer: *outer,
            inner: *inner,
        },
        RegionGen::Polygon { points, ends } => match PolygonRegion::new(points, ends) {
            Ok(p) => Region::Polygon(p),
            Err(e) => {
                let _ = e.to_string();
                return Ok(false);
            }
        },
    };
    let p = &case.params;
    let mut shapes = vec![Placed::<S>::default(); case.capacity];
    let mut index = vec![0u32; index_words(case.capacity)];
    let mut coverage = vec![0u64; case.coverage];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    let mut e = match Engine::<S>::new(p.clone(), region, storage) {
        Ok(e) => e,
        Err(err) => {
            let _ = err.to_string();
            return Ok(false);
        }
    };
    let cells = match case.sampler {
        Sampler::Reference => 0,
        Sampler::Cells(n) => n.unwrap_or(0),
    };
    let mut pool = vec![[0u64; 4]; cells];
    let mut sampler = match case.sampler {
        Sampler::Reference => None,
        Sampler::Cells(_) => match CellSampler::<S>::new(&mut pool) {
            Ok(c) => Some(c),
            Err(err) => {
                let _ = err.to_string();
                return Ok(false);
            }
        },
    };
    // Placements the run may make, and the trials each may take (one more after a halt).
    let most = case.stop.count.unwrap_or(u64::MAX).min(case.capacity as u64);
    let budget = 64u64.saturating_mul(most + 2).saturating_mul(p.max_trials).saturating_add(100_000);
    let mut rng = BudgetRng {
        inner: rng_from_seed(case.seed),
        left: budget,
    };
    let mut seen: Vec<Placement<S>> = Vec::new();
    let end = match case.drive {
        Drive::Run => End::Stopped(match sampler.as_mut() {
            Some(c) => e.run_fast(c, &mut rng, &case.stop, |q| seen.push(*q)),
            None => e.run(&mut rng, &case.stop, |q| seen.push(*q)),
        }),
        Drive::Step => {
            let mut failed = None;
            let mut retried = false;
            while (e.placed().len() as u64) < case.stop.count.unwrap_or(case.capacity as u64 + 1) {
                // The smallest shape stops the steps as it stops a run.
                let next = e.placed().len() as u64;
                let kind = e.kind_of(next);
                if case
                    .stop
                    .min_size
                    .is_some_and(|m| kind.min_width(kind.scale_for_area(e.area_of(next))) < m)
                {
                    break;
                }
                let r = match sampler.as_mut() {
                    Some(c) => e.step_fast(c, &mut rng),
                    None => e.step(&mut rng),
                };
                match r {
                    Ok(q) => seen.push(q),
                    Err(StepError::Halted { .. }) if !retried => retried = true,
                    Err(err) => {
                        failed = Some(err);
                        break;
                    }
                }
            }
            End::Stepped(failed)
        }
    };
    let n = e.placed().len();
    let stats = e.stats();
    // The placements reported are the shapes stored, in order, each within its trial limit.
    if seen.len() != n || stats.placed != n as u64 {
        return Err(format!("{} placements reported, {n} stored, stats {stats:?}", seen.len()));
    }
    let mut trials = 0u64;
    for (i, q) in seen.iter().enumerate() {
        if q.index != i as u64 || q.shape != e.placed()[i] || q.trials == 0 || q.trials > p.max_trials || q.area != e.area_of(i as u64) {
            return Err(format!("placement {i} inconsistent: {q:?} / {:?}", e.placed()[i]));
        }
        trials += q.trials;
    }
    if stats.trials < trials {
        return Err(format!("stats count {} trials, the placements {trials}", stats.trials));
    }
    // The run stopped for a reason that holds.
    let halt_ok = |index: u64, t: u64| index == n as u64 && t <= p.max_trials && (sampler.is_some() || t == p.max_trials);
    let reason_ok = match end {
        End::Stopped(StopReason::Count) => case.stop.count == Some(n as u64),
        End::Stopped(StopReason::Fill) => case.stop.fill.is_some_and(|f| stats.fill_fraction >= f),
        End::Stopped(StopReason::MinSize) => case.stop.min_size.is_some() && case.stop.count.is_none_or(|k| (n as u64) < k),
        End::Stopped(StopReason::Step(err)) | End::Stepped(Some(err)) => match err {
            StepError::Halted { index, trials } => {
                tally.halted.fetch_add(1, Relaxed);
                halt_ok(index, trials)
            }
            StepError::Capacity { capacity } => capacity == case.capacity as u64 && n == case.capacity,
            StepError::CannotFit { index } => index == n as u64,
            // Fixed point has a narrowest shape; f64 one relative to the region's coordinates.
            StepError::TooSmall { index } => index == n as u64,
            // Only fixed point has a widest shape.
            StepError::TooLarge { index } => index == n as u64 && matches!(case.scalar, Scal::Fixed),
        },
        End::Stepped(None) => case.stop.count.is_none_or(|k| n as u64 == k) || case.stop.min_size.is_some(),
    };
    if !reason_ok {
        return Err(format!("the run stopped after {n} shapes for a reason that does not hold"));
    }
    // Every shape has its power-law area, and the fill passes the independent check.
    // Fixed point rounds every coordinate to 2^-32: a shape's area moves by up to about its
    // perimeter times that.
    // Each vertex is rounded where it lies (to an f64 ulp of its coordinates, or to 2^-32 on
    // fixed point, whose sine and cosine are also off by up to 5e-9): a shape's area moves by
    // up to its perimeter times that.
    let area_slack = |m: &Mat, want: f64| {
        let b = m.bbox();
        let (size, far) = (b[2] - b[0] + b[3] - b[1], b.iter().fold(0.0f64, |f, v| f.max(v.abs())));
        match case.scalar {
            Scal::F64 => 1e-9 * want + 8.0 * size * f64::EPSILON * far,
            Scal::Fixed => 1e-6 * want + 4.0 * size * (16.0 * Fixed::DELTA.to_f64() + 1e-8 * size),
        }
    };
    let mut fill = Fill {
        shapes: Vec::with_capacity(n),
        area: area_of(&case.region),
        gap: p.gap,
    };
    for (i, s) in e.placed().iter().enumerate() {
        let g = e.geo(i).ok_or_else(|| format!("no outline for shape {i}"))?;
        let m = Mat::from_geo(&g);
        let (want, got) = (e.area_of(i as u64), m.area());
        if !((got - want).abs() <= area_slack(&m, want)) {
            return Err(format!("shape {i} has area {got:e}, the power law asks {want:e}: {m:?}"));
        }
        fill.shapes.push(([s.x.to_f64(), s.y.to_f64()], m));
    }
    let tol = match case.scalar {
        Scal::F64 => Tolerance { rel: 1e-12, abs: 0.0 },
        Scal::Fixed => Tolerance {
            rel: 1e-12,
            abs: 64.0 * Fixed::DELTA.to_f64(),
        },
    };
    checker::check(&fill, tol)?;
    tally.fills.fetch_add(u64::from(n > 0), Relaxed);
    tally.shapes.fetch_add(n as u64, Relaxed);
    let _ = (e.stats().trials_per_placement(), e.coverage_fraction(), sampler.map(|c| c.stats()));
    Ok(true)
}

fn fuzz(name: &'static str, scal: Scal, sizes: (f64, f64), min_shape: f64, default_cases: u32) {
    let tally = Tally::default();
    let result = runner(name, default_cases).run(&strategies::case(scal, sizes, min_shape), |case| {
        tally.cases.fetch_add(1, Relaxed);
        let ran = match case.scalar {
            Scal::F64 => run_case::<f64>(&case, &tally),
            Scal::Fixed => run_case::<Fixed>(&case, &tally),
        }
        .map_err(TestCaseError::fail)?;
        tally.refused.fetch_add(u64::from(!ran), Relaxed);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{name}: {e}");
    }
    tally.report(name);
}

#[test]
fn fuzz_engine_f64() {
    fuzz("engine_f64", Scal::F64, (0.0, f64::INFINITY), 0.0, 300);
}

/// On fixed point, the regions and shapes its documentation supports (core/src/fixed.rs):
/// sides from 1 to 10,000 mm, every coordinate within ±10,000 mm, and shapes of at least
/// 0.01 mm. Beyond that the squared lengths saturate: in `Region::Circle { radius: 50_000.0 }`
/// the reference sampler places the first circle of c = 1.05, N = 2 (seed
/// 7259034912180892806, `max_trials` 2) at (11493.1, 80450.9) with radius 7852.6, 6,945 mm
/// outside the disc.
#[test]
fn fuzz_engine_fixed() {
    fuzz("engine_fixed", Scal::Fixed, (1.0, 10_000.0), 0.01, 300);
}
