//! `zetafill stats halting`: the fraction of runs that halt at each c (the paper's Figure 6),
//! as CSV or an SVG chart.
//!
//! A run places `--count` shapes; it *halts* when a placement reaches `--max-trials` trials or
//! a shape cannot lie in the region at all (the paper: "non-halting if it did not halt in
//! 8,000,000 trials at any placement"; most halts come in the first 50 placements).
//! The values of c are `c_from + k * c_step` for `k = 0, 1, ...` up to `c_to` (inclusive, to
//! within 1e-9 of a step). Run `r` (0-based) at the `k`-th value uses the seed
//! `seed + k * runs + r` (wrapping): every run is independent, so the runs are spread over all
//! cores (rayon) and the result does not depend on the number of threads.

use super::chart::{self, HaltingSeries};
use super::trials::{run_2d, shape_label, RunSpec};
use crate::error::CliError;
use crate::plan::format::ChartFormat;
use crate::plan::stats::HaltingPlan;
use rayon::prelude::*;
use std::fmt::Write as _;

/// One value of c.
#[derive(Debug, Clone, serde::Serialize)]
pub struct PointDoc {
    /// Exponent c.
    pub c: f64,
    /// Runs made.
    pub runs: u64,
    /// Runs that halted.
    pub halted: u64,
    /// halted / runs.
    pub fraction: f64,
    /// Median placement at which the halted runs halted (absent when none halted).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub median_halt: Option<u64>,
}

/// Runs the scan: one point per value of c.
pub fn scan(a: &HaltingPlan) -> Result<Vec<PointDoc>, CliError> {
    let cs = &a.c;
    let jobs: Vec<(usize, RunSpec)> = cs
        .iter()
        .enumerate()
        .flat_map(|(k, &c)| {
            (0..a.runs).map(move |r| {
                let seed = a.seed.wrapping_add((k as u64).wrapping_mul(a.runs)).wrapping_add(r);
                (
                    k,
                    RunSpec {
                        scene: a.scene,
                        c,
                        n_offset: a.n_offset,
                        count: a.count,
                        max_trials: a.max_trials,
                        seed,
                        estimate: false,
                    },
                )
            })
        })
        .collect();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(a.threads)
        .build()
        .map_err(|e| CliError::Io(format!("cannot start worker threads: {e}")))?;
    let bar = crate::cmd::progress::bar(a.quiet, Some(jobs.len() as u64), "runs");
    let results: Vec<Result<Option<u64>, CliError>> = pool.install(|| {
        jobs.par_iter()
            .map(|(_, s)| {
                let r = run_2d(s).map(|r| r.halted_at);
                if let Some(b) = &bar {
                    b.inc(1);
                }
                r
            })
            .collect()
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let mut halts: Vec<Vec<u64>> = vec![Vec::new(); cs.len()];
    for ((k, _), res) in jobs.iter().zip(results) {
        if let (Some(v), Some(i)) = (halts.get_mut(*k), res?) {
            v.push(i);
        }
    }
    Ok(cs
        .iter()
        .zip(halts)
        .map(|(&c, mut h)| {
            h.sort_unstable();
            let halted = h.len() as u64;
            PointDoc {
                c,
                runs: a.runs,
                halted,
                fraction: halted as f64 / a.runs as f64,
                median_halt: h.get(h.len() / 2).copied(),
            }
        })
        .collect())
}

/// `zetafill stats halting`.
pub fn run(a: &HaltingPlan) -> Result<(), CliError> {
    let points = scan(a)?;
    if let Some((dest, f)) = &a.output {
        let bytes = match f {
            ChartFormat::Svg => {
                let label = format!(
                    "{}{} N = {}",
                    if a.scene.periodic { "periodic, " } else { "inclusive, " },
                    shape_label(&a.scene.shape),
                    a.n_offset
                );
                let series = [HaltingSeries {
                    label,
                    points: points.iter().map(|p| (p.c, p.fraction)).collect(),
                }];
                let title = format!(
                    "halting: {} runs per c, {} shapes, {} trials per placement at most",
                    a.runs, a.count, a.max_trials
                );
                chart::halting_chart(&series, &title)?
            }
            ChartFormat::Csv => {
                let mut s = String::from("c,runs,halted,fraction\n");
                for p in &points {
                    let _ = writeln!(s, "{},{},{},{}", p.c, p.runs, p.halted, p.fraction);
                }
                s.into_bytes()
            }
        };
        dest.write(&bytes)?;
    }
    if a.json {
        println!("{}", serde_json::json!({ "points": points }));
    } else {
        for p in &points {
            let m = p.median_halt.map_or(String::new(), |m| format!(" (median halt at placement {m})"));
            println!("c = {:.4}: {}/{} runs halted, fraction {}{m}", p.c, p.halted, p.runs, p.fraction);
        }
    }
    Ok(())
}
