//! `zetafill stats trials`: cumulative trials against placements for 2D fills (the paper's
//! Figure 5), as CSV or a log-log SVG chart, with the exponent of a power law fitted to the
//! large-n part (the paper finds it close to c). Also the one 2D run helper that
//! `stats halting` shares.
//!
//! With `--sampler fast` the trials are not counted but estimated: the cell sampler places the
//! shapes and says, without bias, how many trials the paper's sampler would have needed
//! (`CellSampler::paper_trials`), so curves to a million shapes take seconds, not hours.
//!
//! Runs are reproducible: run `r` (0-based) of the `k`-th value of `--c` uses the seed
//! `seed + k * runs + r` (wrapping), and every run is independent of the others, so they are
//! spread over the cores with rayon and collected in order.

use super::chart::{self, TrialsSeries};
use crate::error::CliError;
use crate::plan::format::ChartFormat;
use crate::plan::stats::{exponent_error, Scene, TrialsPlan};
use rayon::prelude::*;
use std::fmt::Write as _;
use zetafill::StepError;
use zetafill::{cells_for, index_words, CellSampler, Engine, Params, Placed, Region, ShapeKind, Stop, StopReason, Storage};

/// What one 2D run is.
#[derive(Debug, Clone, Copy)]
pub struct RunSpec {
    /// Shape, rotation and region.
    pub scene: Scene,
    /// Exponent c.
    pub c: f64,
    /// Offset N.
    pub n_offset: f64,
    /// Shapes to place.
    pub count: u64,
    /// Trial limit per placement.
    pub max_trials: u64,
    /// Seed.
    pub seed: u64,
    /// Estimate the paper's trials with the cell sampler instead of running the paper's.
    pub estimate: bool,
}

/// What one 2D run did.
#[derive(Debug, Clone)]
pub struct RunResult {
    /// Trials of each placement, in order (estimated ones are fractional).
    pub trials: Vec<f64>,
    /// The placement at which the run halted (trial limit reached, or the shape cannot fit
    /// the region at all), if it did.
    pub halted_at: Option<u64>,
    /// Trials spent on the placement that halted (0 if none; estimated, the paper's sampler
    /// would have made the trial limit).
    pub halted_trials: f64,
}

/// Words of the coverage bitmap per run (256 KiB): it only makes rejections cheaper.
const COVERAGE_WORDS: usize = 1 << 15;

/// Runs the core's 2D engine once.
pub fn run_2d(r: &RunSpec) -> Result<RunResult, CliError> {
    let scene = &r.scene;
    let mut params = Params::circles(r.c, r.n_offset);
    params.shape = scene.shape.into();
    params.rotate = scene.rotate && scene.shape.rotates();
    params.max_trials = r.max_trials;
    let region = Region::Rect {
        width: scene.size.0,
        height: scene.size.1,
        periodic: scene.periodic,
    };
    let cap = r.count.saturating_add(1) as usize;
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    let mut coverage = vec![0u64; COVERAGE_WORDS];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    let mut engine = Engine::<f64>::new(params, region, storage).map_err(exponent_error)?;
    let mut rng = zetafill::rng_from_seed(r.seed);
    let mut trials = Vec::with_capacity(cap);
    let stop = Stop {
        count: Some(r.count),
        ..Stop::default()
    };
    let reason = if r.estimate {
        let mut pool = vec![[0u64; 4]; cells_for(cap)];
        let mut cells = CellSampler::new(&mut pool).map_err(|_| CliError::Io("internal: no cells".into()))?;
        cells.estimate_paper_trials();
        // Stepped one by one: each placement's estimate is read from the sampler.
        loop {
            if trials.len() as u64 >= r.count {
                break StopReason::Count;
            }
            match engine.step_fast(&mut cells, &mut rng) {
                Ok(_) => trials.push(cells.last_paper_trials()),
                Err(e) => break StopReason::Step(e),
            }
        }
    } else {
        engine.run(&mut rng, &stop, |p| trials.push(p.trials as f64))
    };
    let (halted_at, halted_trials) = match reason {
        StopReason::Step(StepError::Halted { index, trials: t }) => (Some(index), if r.estimate { r.max_trials as f64 } else { t as f64 }),
        StopReason::Step(StepError::CannotFit { index }) => (Some(index), 0.0),
        StopReason::Step(StepError::Capacity { .. }) => return Err(CliError::Io("internal: storage full".into())),
        _ => (None, 0.0),
    };
    Ok(RunResult {
        trials,
        halted_at,
        halted_trials,
    })
}

/// One run's summary.
#[derive(Debug, Clone, serde::Serialize)]
pub struct SeriesDoc {
    /// Exponent c.
    pub c: f64,
    /// Run number for this c.
    pub run: u64,
    /// Seed.
    pub seed: u64,
    /// Shapes placed.
    pub placed: u64,
    /// Trials in all (including a halted placement's): a count, or with `--sampler fast` an
    /// estimate.
    pub trials: serde_json::Number,
    /// Fitted exponent of cumulative trials against n over the fit range.
    pub exponent: Option<f64>,
    /// The placement at which the run halted, if it did.
    pub halted_at: Option<u64>,
}

/// The fit over `n >= from`: `(k, a)` of `cum = a n^k`.
fn fit(cum: &[(f64, f64)], from: f64) -> Option<(f64, f64)> {
    let pts: Vec<(f64, f64)> = cum
        .iter()
        .filter(|p| p.0 >= from && p.1 > 0.0)
        .map(|p| (libm::log(p.0), libm::log(p.1)))
        .collect();
    zetafill::internals::stats::least_squares(&pts).map(|(k, b)| (k, libm::exp(b)))
}

/// `zetafill stats trials`.
pub fn run(a: &TrialsPlan) -> Result<(), CliError> {
    let from = a.fit_from;
    let jobs: Vec<(usize, u64, RunSpec)> =
        a.c.iter()
            .enumerate()
            .flat_map(|(k, &c)| {
                (0..a.runs).map(move |r| {
                    let seed = a.seed.wrapping_add((k as u64).wrapping_mul(a.runs)).wrapping_add(r);
                    let spec = RunSpec {
                        scene: a.scene,
                        c,
                        n_offset: a.n_offset,
                        count: a.count,
                        max_trials: a.max_trials,
                        seed,
                        estimate: a.estimate,
                    };
                    (k, r, spec)
                })
            })
            .collect();
    let results: Vec<Result<RunResult, CliError>> = jobs.par_iter().map(|(_, _, s)| run_2d(s)).collect();
    let mut docs = Vec::new();
    let mut curves = Vec::new();
    let mut csv = String::from("c,run,seed,n,trials,cumulative_trials\n");
    for ((_, r, spec), res) in jobs.iter().zip(results) {
        let res = res?;
        let mut total = 0f64;
        let mut cum = Vec::with_capacity(res.trials.len());
        let placed = res.trials.len() as u64;
        // Counted trials are whole numbers, written as such; estimates to three decimals.
        let num = |v: f64| if spec.estimate { format!("{v:.3}") } else { format!("{v}") };
        for (i, &t) in res.trials.iter().enumerate() {
            total += t;
            cum.push(((i + 1) as f64, total));
            let _ = writeln!(csv, "{},{},{},{},{},{}", spec.c, r, spec.seed, i + 1, num(t), num(total));
        }
        total += res.halted_trials;
        let f = fit(&cum, from as f64);
        let label = format!("c = {}{}", spec.c, if a.runs > 1 { format!(", run {r}") } else { String::new() });
        curves.push(TrialsSeries {
            label,
            fit: f.map(|(k, amp)| (k, amp, from as f64, placed.max(1) as f64)),
            points: cum,
        });
        docs.push(SeriesDoc {
            c: spec.c,
            run: *r,
            seed: spec.seed,
            placed,
            trials: if spec.estimate {
                serde_json::Number::from_f64(total).unwrap_or_else(|| 0.into())
            } else {
                (total as u64).into()
            },
            exponent: f.map(|x| x.0),
            halted_at: res.halted_at,
        });
    }
    if let Some((dest, f)) = &a.output {
        let bytes = match f {
            ChartFormat::Svg => {
                let title = format!("cumulative trials, {} N = {}", shape_label(&a.scene.shape), a.n_offset);
                chart::trials_chart(&curves, &title)?
            }
            ChartFormat::Csv => csv.into_bytes(),
        };
        dest.write(&bytes)?;
    }
    let first = docs.first().cloned();
    if a.json {
        let f = first.as_ref();
        let v = serde_json::json!({
            "exponent": f.and_then(|d| d.exponent),
            "placed": f.map(|d| d.placed),
            "trials": f.map(|d| d.trials.clone()),
            "c": f.map(|d| d.c),
            "fit_from": from,
            "series": docs,
        });
        println!("{v}");
    } else {
        for d in &docs {
            let e = d.exponent.map_or("n/a".to_string(), |e| format!("{e:.4}"));
            let halt = d.halted_at.map_or(String::new(), |i| format!(", halted at placement {i}"));
            println!(
                "c = {} run {} (seed {}): {} placed, {} trials, exponent {e} (n >= {from}){halt}",
                d.c, d.run, d.seed, d.placed, d.trials
            );
        }
    }
    Ok(())
}

/// A shape's name for titles.
pub fn shape_label(k: &ShapeKind) -> String {
    match k {
        ShapeKind::Circle => "circles,".into(),
        ShapeKind::Square => "squares,".into(),
        ShapeKind::Rect { aspect } => format!("rectangles {aspect}:1,"),
        #[allow(unreachable_patterns)]
        _ => "shapes,".into(),
    }
}
