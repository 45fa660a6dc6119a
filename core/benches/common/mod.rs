//! What the benchmarks share: the thread's CPU clock and a 2D fill with the cell sampler.

use std::time::Instant;
use zetafill::internals::sampler::CellStats;
use zetafill::{cells_for, index_words, CellSampler, Engine, Params, Placed, Region, Stop, StopReason, Storage};

/// The thread's CPU time in seconds (Linux), or the wall time since `start`.
pub fn cpu_seconds(start: Instant) -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next().and_then(|ns| ns.parse::<f64>().ok()))
        .map_or_else(|| start.elapsed().as_secs_f64(), |ns| ns * 1e-9)
}

/// The 200 x 200 rect the 2D benchmarks fill.
pub const RECT: Region<'static> = Region::Rect {
    width: 200.0,
    height: 200.0,
    periodic: false,
};

/// What a fill with the cell sampler measured.
#[allow(dead_code)] // (each benchmark reads what it prints)
pub struct CellFill {
    /// The thread's CPU seconds.
    pub secs: f64,
    pub placed: u64,
    pub trials: u64,
    pub cells: CellStats,
    /// Shape record and index words per shape slot, in bytes.
    pub record_bytes: f64,
}

/// `count` shapes of `params` in [`RECT`], seed 1, with the cell sampler and the storage the
/// CLI lends it for `cap` shapes (`cells_for(cap)` cells, no coverage bitmap).
#[allow(dead_code)] // (not every benchmark fills in 2D)
pub fn cell_fill(params: Params, cap: usize, count: u64) -> CellFill {
    cell_fill_lent(params, cap, count, cells_for(cap.max(1)))
}

/// [`cell_fill`] with `cells` cells lent to the sampler instead (`zetafill fill --cells`).
#[allow(dead_code)] // (not every benchmark fills in 2D)
pub fn cell_fill_lent(mut params: Params, cap: usize, count: u64, cells: usize) -> CellFill {
    let cap = cap.max(1);
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    let mut pool = vec![[0u64; 4]; cells.max(1)];
    params.max_trials = 1_000_000_000;
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    let clock = Instant::now();
    let start = cpu_seconds(clock);
    let mut e = Engine::<f64>::new(params, RECT, storage).expect("valid parameters");
    let mut rng = zetafill::rng_from_seed(1);
    let mut cells = CellSampler::new(&mut pool).expect("cells");
    let reason = e.run_fast(&mut cells, &mut rng, &stop, |_| {});
    let secs = cpu_seconds(clock) - start;
    if reason != StopReason::Count {
        eprintln!("n {count}: stopped early: {reason:?}");
    }
    let s = e.stats();
    CellFill {
        secs,
        placed: s.placed,
        trials: s.trials,
        cells: cells.stats(),
        record_bytes: std::mem::size_of::<Placed<f64>>() as f64 + 4.0 * index_words(cap) as f64 / cap as f64,
    }
}
