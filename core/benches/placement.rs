//! Placement benchmark: what one placement of the cell sampler (the default 2D sampler) costs
//! as the fill grows. Circles at c = 1.3, N = 1 in a 200 x 200 rect, seed 1, with the storage
//! the CLI lends (no coverage bitmap, `cells_for(n)` cells), for n = 10^3 ... 10^6. For each n
//! it prints a Markdown row: the thread's CPU seconds (`CLOCK_THREAD_CPUTIME_ID`, the storage's
//! pages touched before the clock starts; fastest of three runs up to 10^5, one run at 10^6),
//! microseconds per placement and their growth over n = 10^3, trials per placement, the
//! acceptance per draw (placements over trials), and where the rejected trials went
//! (`CellSampler::stats`: by a shape the drawn cell knew, by the cell's bound, by a shape the
//! cell then learned; the rest, the region's and the candidates that left the grid, by
//! difference).
//!
//!     cargo bench -p zetafill --bench placement [-- MAX_N]
//!
//! `--one N` runs one fill of N circles and prints its counts; `--one N --setup` does the same
//! but places nothing (the storage for N and the engine only). The difference of the two under
//! a cache simulator is the fill's own memory traffic. It measures; it asserts nothing about
//! time.

use zetafill::Params;

mod common;
use common::{cell_fill, CellFill};

/// One fill of `count` circles with the storage for `cap`, as the CLI lends it.
fn fill(cap: usize, count: u64) -> CellFill {
    cell_fill(Params::circles(1.3, 1.0), cap, count)
}

fn arg<T: std::str::FromStr>(name: &str) -> Option<T> {
    std::env::args().skip_while(|a| a != name).nth(1).and_then(|v| v.parse().ok())
}

fn main() {
    if let Some(n) = arg::<u64>("--one") {
        let setup = std::env::args().any(|a| a == "--setup");
        let r = fill(n as usize, if setup { 0 } else { n });
        println!("n {n} placed {} trials {} cpu {:.3} s", r.placed, r.trials, r.secs);
        return;
    }
    // The first bare number caps n (cargo passes `--bench` too).
    let max: u64 = std::env::args().skip(1).find_map(|a| a.parse().ok()).unwrap_or(1_000_000);
    println!("| n | CPU (s) | us/placement | vs 10^3 | trials/placement | acceptance/draw | known shape | cell bound | learned shape | region, other |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut base: Option<f64> = None;
    let mut n = 1_000u64;
    while n <= max {
        // A busy neighbour on a shared machine slows a run, never speeds it up: the fastest
        // of three (the same placements: only the time differs).
        let rounds = if n <= 100_000 { 3 } else { 1 };
        let r = (0..rounds)
            .map(|_| fill(n as usize, n))
            .min_by(|a, b| a.secs.total_cmp(&b.secs))
            .expect("one round at least");
        let p = r.placed.max(1) as f64;
        let us = r.secs * 1e6 / p;
        let base_us = *base.get_or_insert(us);
        let c = &r.cells;
        let other = r.trials - r.placed - c.known_rejects - c.cell_rejects - c.learned;
        println!(
            "| {} | {:.3} | {us:.2} | {:.2}x | {:.2} | {:.2}% | {:.2} | {:.2} | {:.2} | {:.2} |",
            r.placed,
            r.secs,
            us / base_us,
            r.trials as f64 / p,
            100.0 * r.placed as f64 / r.trials as f64,
            c.known_rejects as f64 / p,
            c.cell_rejects as f64 / p,
            c.learned as f64 / p,
            other as f64 / p,
        );
        n *= 10;
    }
}
