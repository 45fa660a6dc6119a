//! What the benchmarks share: the thread's CPU clock and a 2D fill with the cell sampler.

use zetafill::internals::sampler::CellStats;
use zetafill::{cells_for, index_words, CellSampler, Engine, Params, Placed, Region, Stop, StopReason, Storage};

/// The thread's CPU time in seconds, to the nanosecond (`CLOCK_THREAD_CPUTIME_ID`). The
/// scheduler's account in `/proc/thread-self/schedstat` only moves at its ticks, 4 ms apart
/// on the CI machine: the whole of a fill of 10^3 circles.
pub fn cpu_seconds() -> f64 {
    let t = rustix::time::clock_gettime(rustix::time::ClockId::ThreadCPUTime);
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
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

/// Writes one element of every 4 KiB of `v`, with its own value, so the kernel maps the pages.
fn touch_pages<T: Copy>(v: &mut [T]) {
    let step = (4096 / std::mem::size_of::<T>().max(1)).max(1);
    for i in (0..v.len()).step_by(step) {
        v[i] = std::hint::black_box(v[i]);
    }
}

/// `count` shapes of `params` in [`RECT`], seed 1, with the cell sampler and the storage the
/// CLI lends it for `cap` shapes (`cells_for(cap)` cells, no coverage bitmap).
#[allow(dead_code)] // (not every benchmark fills in 2D)
pub fn cell_fill(params: Params, cap: usize, count: u64) -> CellFill {
    cell_fill_lent(params, cap, count, cells_for(cap.max(1)))
}

/// [`cell_fill`] with `cells` cells lent to the sampler instead (`zetafill fill --cells`).
#[allow(dead_code)] // (not every benchmark fills in 2D)
pub fn cell_fill_lent(params: Params, cap: usize, count: u64, cells: usize) -> CellFill {
    cell_fill_in(RECT, params, cap, count, cells)
}

/// [`cell_fill_lent`] in `region`, with `cap` entries of storage (a wallpaper group's
/// placements take one entry per image).
#[allow(dead_code)] // (not every benchmark fills in 2D)
pub fn cell_fill_in(region: Region<'_>, mut params: Params, cap: usize, count: u64, cells: usize) -> CellFill {
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
    // The pages of the storage are touched before the clock starts: the first touch of a
    // page is the kernel's work, which would otherwise land on whichever placement first
    // writes there (most of a small fill's time).
    touch_pages(storage.shapes);
    touch_pages(storage.index);
    touch_pages(&mut pool);
    let start = cpu_seconds();
    let mut e = Engine::<f64>::new(params, region, storage).expect("valid parameters");
    let mut rng = zetafill::rng_from_seed(1);
    let mut cells = CellSampler::new(&mut pool).expect("cells");
    let reason = e.run_fast(&mut cells, &mut rng, &stop, |_| {});
    let secs = cpu_seconds() - start;
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
