//! Sampler benchmark: the cell sampler against the paper's sampler on circles in a 200 x 200
//! square, seed 1: c = 1.3 with N = 1, and c = 1.4 with N = 2 (with N = 1 the first circle
//! leaves room for the second only when it lands near a corner). For each c and n it prints the
//! time, the trials per placement, the memory per placed shape (shape record, index words and,
//! for the cell sampler, its cells at their peak), and for the cell sampler its estimate of the
//! paper's trials per placement (`CellSampler::paper_trials`, on in the timed runs). Run with `cargo bench -p zetafill --bench sampler`; flags:
//! `--quick` (n up to 10^4), `--max N` (largest n, default 10^6), `--c C` (one exponent),
//! `--no-reference-above N` (skip the reference sampler above n = N; by default above 10^6
//! for c = 1.3 and 10^5 for c = 1.4, where its trials per placement reach the tens of
//! thousands).
//! The reference sampler runs twice: with the coverage bitmap the CLI gives it (2 MiB), and
//! without (`paper + hash`: the paper's algorithm with only the spatial hash, the reference of
//! docs/performance.md), the latter up to `--no-bitmap-above N` (default 10^5 for c = 1.3, 10^4
//! for c = 1.4).
//! Up to n = 10^5 the cell sampler and the reference run three times each, in turn, and the
//! table gives each one's fastest run.
//! Prints a Markdown table for the README. It measures; it asserts nothing about time.

use std::time::Instant;
use zetafill::{cells_for, index_words, CellSampler, CellWords, Engine, Params, Placed, Region, Stop, StopReason, Storage};

const COVERAGE_WORDS: usize = 1 << 18;

struct Row {
    secs: f64,
    placed: u64,
    trials: u64,
    bytes_per_shape: f64,
    cells_per_shape: f64,
    /// The cell sampler's estimate of the paper's trials per placement.
    paper_estimate: Option<f64>,
}

#[derive(Clone, Copy, PartialEq)]
enum Sampler {
    Fast,
    Reference,
    PaperHash,
}

fn run(c: f64, n_offset: f64, n: u64, sampler: Sampler) -> Row {
    let fast = sampler == Sampler::Fast;
    let cap = n as usize;
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    // The storage the CLI lends each sampler: the bitmap to the reference only (the cell
    // sampler never reads it), `cells_for(n)` cells to the cell sampler.
    let mut coverage = vec![0u64; if sampler == Sampler::Reference { COVERAGE_WORDS } else { 0 }];
    let mut pool = vec![[0u64; 4]; if fast { cells_for(cap) } else { 1 }];
    let mut params = Params::circles(c, n_offset);
    params.max_trials = 1_000_000_000;
    let region = Region::Rect {
        width: 200.0,
        height: 200.0,
        periodic: false,
    };
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    let stop = Stop {
        count: Some(n),
        ..Stop::default()
    };
    let t = Instant::now();
    let mut e = Engine::<f64>::new(params, region, storage).expect("valid parameters");
    let mut rng = zetafill::rng_from_seed(1);
    let (reason, peak, paper) = if fast {
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        cells.estimate_paper_trials();
        let reason = e.run_fast(&mut cells, &mut rng, &stop, |_| {});
        (reason, cells.stats().peak, Some(cells.paper_trials()))
    } else {
        (e.run(&mut rng, &stop, |_| {}), 0, None)
    };
    let secs = t.elapsed().as_secs_f64();
    if reason != StopReason::Count {
        eprintln!("c {c} n {n}: stopped early: {reason:?}");
    }
    let s = e.stats();
    let core = std::mem::size_of::<Placed<f64>>() as f64 + 4.0 * (index_words(cap) - 1) as f64 / cap as f64;
    let cells = peak as f64 / s.placed.max(1) as f64;
    Row {
        secs,
        placed: s.placed,
        trials: s.trials,
        bytes_per_shape: core + cells * std::mem::size_of::<CellWords>() as f64,
        cells_per_shape: cells,
        paper_estimate: paper.map(|t| t / s.placed.max(1) as f64),
    }
}

/// The faster of a run so far and a new one (the same placements: only the time differs).
fn faster(best: Option<Row>, new: Row) -> Row {
    match best {
        Some(b) if b.secs <= new.secs => b,
        _ => new,
    }
}

fn arg<T: std::str::FromStr>(name: &str) -> Option<T> {
    std::env::args().skip_while(|a| a != name).nth(1).and_then(|v| v.parse().ok())
}

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let max: u64 = if quick { 10_000 } else { arg("--max").unwrap_or(1_000_000) };
    let no_ref_above: Option<u64> = arg("--no-reference-above");
    let no_bitmap_above: Option<u64> = arg("--no-bitmap-above");
    let cs: Vec<f64> = arg("--c").map_or(vec![1.3, 1.4], |c| vec![c]);
    println!("| c | N | n | sampler | time (s) | trials/placement | paper's, estimated | placements/s | cells/shape | bytes/shape |");
    println!("|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|");
    for &c in &cs {
        let n_offset = if c > 1.35 { 2.0 } else { 1.0 };
        let ref_max = no_ref_above.unwrap_or(if c > 1.35 { 100_000 } else { 1_000_000 });
        let bare_max = no_bitmap_above.unwrap_or(if c > 1.35 { 10_000 } else { 100_000 });
        let mut n = 1_000u64;
        while n <= max {
            // Up to 10^5 the two samplers run three times, in turn, and each keeps its fastest
            // run: a busy neighbour on a shared machine slows a run, never speeds it up.
            let rounds = if n <= 100_000 { 3 } else { 1 };
            let (mut fast, mut reference): (Option<Row>, Option<Row>) = (None, None);
            for _ in 0..rounds {
                fast = Some(faster(fast, run(c, n_offset, n, Sampler::Fast)));
                if n <= ref_max {
                    reference = Some(faster(reference, run(c, n_offset, n, Sampler::Reference)));
                }
            }
            let fast = fast.expect("one round at least");
            let bare = (n <= bare_max).then(|| run(c, n_offset, n, Sampler::PaperHash));
            for (name, r) in [
                ("fast", Some(&fast)),
                ("reference", reference.as_ref()),
                ("paper + hash", bare.as_ref()),
            ] {
                let Some(r) = r else { continue };
                println!(
                    "| {c} | {n_offset} | {} | {name} | {:.3} | {:.1} | {} | {:.0} | {:.1} | {:.0} |",
                    r.placed,
                    r.secs,
                    r.trials as f64 / r.placed as f64,
                    r.paper_estimate.map_or(String::new(), |t| format!("{t:.1}")),
                    r.placed as f64 / r.secs,
                    r.cells_per_shape,
                    r.bytes_per_shape
                );
            }
            if let Some(r) = &bare {
                println!(
                    "|  |  |  | speed-up over paper + hash | {:.1}x |  |  |  |  |  |",
                    r.secs / fast.secs
                );
            }
            if let Some(r) = &reference {
                println!("|  |  |  | speed-up over reference | {:.1}x |  |  |  |  |  |", r.secs / fast.secs);
            }
            n *= 10;
        }
    }
}
