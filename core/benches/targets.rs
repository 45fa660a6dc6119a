//! The fills the speed targets are set for, in one run: for each, the thread's CPU seconds
//! (`CLOCK_THREAD_CPUTIME_ID`) against its target, microseconds
//! and trials per placement, and the bytes per shape of the storage used at its peak (shape
//! record, index words and, for the cell sampler, its cells at their peak; the 1D gap
//! sampler's gap slots). 2D fills are in the 200 x 200 rect, the 1D fill in a 200 mm
//! interval, seed 1, with the default samplers (the cell sampler, the gap sampler).
//!
//!     cargo bench -p zetafill --bench targets [-- --scale 10] [-- --one NAME]
//!
//! `--scale K` divides every count by K (a quick look); `--one NAME` runs one row (for a
//! profiler: `circles`, `circles-lean`, `circles-1.4`, `squares`, `stars`, `segments`). It
//! measures; it asserts nothing about time.
//!
//! `-- --budgets` fills the first target's circles lent `cells_for(n)`, then 12, 8, 4 and 2.3
//! cells a shape, and prints a row for each.
//!
//! `-- --latency` measures what the placements wait on: the time of a load that depends on the
//! one before (a chase through a random cycle of 64-byte lines, one chain), and of loads that
//! do not (eight chains at once), in working sets from 16 KiB to 512 MiB.
//!
//! `circles-lean` is the first fill with 2.3 cells a shape lent to the sampler (`zetafill fill
//! --cells`) instead of `cells_for(n)`: the budget that keeps its storage within the memory
//! target of 120 bytes a shape. Lent less, the sampler stops splitting sooner and stays exact;
//! its fill is another one, equally reproducible.

use zetafill::line::{
    gaps_for as line_gaps_for, index_words as line_index_words, Engine as LineEngine, Gap as LineGap, Gaps as LineGaps, Interval,
    Params as LineParams, Segment, Storage as LineStorage,
};
use zetafill::{rng_from_seed, CellWords, Params, ShapeKind, Stop};

mod common;
use common::{cell_fill, cell_fill_lent, cpu_seconds};

/// One fill the targets name.
struct Target {
    name: &'static str,
    what: &'static str,
    count: u64,
    /// The target, in CPU seconds.
    secs: f64,
    c: f64,
    n_offset: f64,
    shape: Option<ShapeKind>,
    /// Cells lent a shape, when not `cells_for(n)`.
    cells_per_shape: Option<f64>,
}

const TARGETS: [Target; 6] = [
    Target {
        name: "circles",
        what: "circles, c 1.3, N 1",
        count: 1_000_000,
        secs: 2.0,
        c: 1.3,
        n_offset: 1.0,
        shape: Some(ShapeKind::Circle),
        cells_per_shape: None,
    },
    Target {
        name: "circles-lean",
        what: "circles, c 1.3, N 1, 2.3 cells a shape lent",
        count: 1_000_000,
        secs: 2.0,
        c: 1.3,
        n_offset: 1.0,
        shape: Some(ShapeKind::Circle),
        cells_per_shape: Some(2.3),
    },
    Target {
        name: "circles-1.4",
        what: "circles, c 1.4, N 2",
        count: 1_000_000,
        secs: 10.0,
        c: 1.4,
        n_offset: 2.0,
        shape: Some(ShapeKind::Circle),
        cells_per_shape: None,
    },
    Target {
        name: "squares",
        what: "squares, random rotation, c 1.3, N 1",
        count: 100_000,
        secs: 1.0,
        c: 1.3,
        n_offset: 1.0,
        shape: Some(ShapeKind::Square),
        cells_per_shape: None,
    },
    Target {
        name: "stars",
        what: "stars 5:0.45, random rotation, c 1.2, N 3",
        count: 100_000,
        secs: 5.0,
        c: 1.2,
        n_offset: 3.0,
        shape: Some(ShapeKind::Star { points: 5, inner: 0.45 }),
        cells_per_shape: None,
    },
    Target {
        name: "segments",
        what: "segments (`line`), c 1.4, N 1",
        count: 1_000_000,
        secs: 0.5,
        c: 1.4,
        n_offset: 1.0,
        shape: None,
        cells_per_shape: None,
    },
];

/// What one fill measured.
struct Measured {
    secs: f64,
    placed: u64,
    trials: u64,
    bytes_per_shape: f64,
}

/// A 2D fill of `t` with the cell sampler and the storage the CLI lends.
fn fill_2d(t: &Target, kind: ShapeKind, count: u64) -> Measured {
    let mut params = Params::circles(t.c, t.n_offset);
    params.shape = kind.into();
    params.rotate = kind != ShapeKind::Circle;
    let r = match t.cells_per_shape {
        Some(k) => cell_fill_lent(params, count as usize, count, (k * count as f64) as usize),
        None => cell_fill(params, count as usize, count),
    };
    let cells = r.cells.peak as f64 * std::mem::size_of::<CellWords>() as f64 / r.placed.max(1) as f64;
    Measured {
        secs: r.secs,
        placed: r.placed,
        trials: r.trials,
        bytes_per_shape: r.record_bytes + cells,
    }
}

/// A 1D fill of `t` with the gap sampler.
fn fill_1d(t: &Target, count: u64) -> Measured {
    let n = count as usize;
    let mut segments = vec![Segment::<f64>::default(); n];
    let mut index = vec![0u32; line_index_words(n)];
    let mut slots = vec![LineGap::default(); line_gaps_for(n)];
    let storage = LineStorage {
        segments: &mut segments,
        index: &mut index,
    };
    let interval = Interval {
        length: 200.0,
        periodic: false,
    };
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    let start = cpu_seconds();
    let mut e = LineEngine::new(LineParams::new(t.c, t.n_offset), interval, storage).expect("valid parameters");
    let mut rng = rng_from_seed(1);
    let mut gaps = LineGaps::new(&mut slots).expect("slots");
    let mut trials = 0u64;
    let mut placed = 0u64;
    e.run_fast(&mut gaps, &mut rng, &stop, |p| {
        trials += p.trials;
        placed += 1;
    });
    let secs = cpu_seconds() - start;
    let bytes = std::mem::size_of::<Segment<f64>>() as f64
        + 4.0 * line_index_words(n) as f64 / n as f64
        + (std::mem::size_of::<LineGap>() * line_gaps_for(n)) as f64 / n as f64;
    Measured {
        secs,
        placed,
        trials,
        bytes_per_shape: bytes,
    }
}

fn measure(t: &Target, scale: u64) -> Measured {
    let count = (t.count / scale).max(1);
    match t.shape {
        Some(kind) => fill_2d(t, kind, count),
        None => fill_1d(t, count),
    }
}

fn arg(name: &str) -> Option<String> {
    std::env::args().skip_while(|a| a != name).nth(1)
}

/// Nanoseconds a load takes in a working set of `bytes`, one 64-byte line a step through a
/// random cycle (Sattolo's shuffle, so the cycle holds every line): with `chains` walks at
/// once, each load depends only on the one before in its own chain.
fn chase(bytes: usize, chains: usize) -> f64 {
    use rand_core::RngCore;
    const LINE: usize = 8; // u64 words a 64-byte line
    let lines = bytes / 64;
    let mut next = vec![0u64; lines * LINE];
    let mut order: Vec<usize> = (0..lines).collect();
    let mut rng = rng_from_seed(7);
    for i in (1..lines).rev() {
        let j = (rng.next_u64() % i as u64) as usize;
        order.swap(i, j);
    }
    for k in 0..lines {
        next[order[k] * LINE] = (order[(k + 1) % lines] * LINE) as u64;
    }
    let steps = 20_000_000 / chains;
    // Chains start a cycle's share apart, so they do not share lines.
    let mut at: Vec<usize> = (0..chains).map(|c| order[c * lines / chains] * LINE).collect();
    let before = cpu_seconds();
    for _ in 0..steps {
        for a in at.iter_mut() {
            *a = next[*a] as usize;
        }
    }
    let secs = cpu_seconds() - before;
    std::hint::black_box(&at);
    secs * 1e9 / (steps * chains) as f64
}

/// The load times placements wait on, by working set (`-- --latency`).
fn latency() {
    println!("| working set | ns a dependent load | ns a load, eight chains at once |");
    println!("|---:|---:|---:|");
    for (label, bytes) in [
        ("16 KiB", 16 << 10),
        ("512 KiB", 512 << 10),
        ("4 MiB", 4 << 20),
        ("8 MiB", 8 << 20),
        ("16 MiB", 16 << 20),
        ("32 MiB", 32 << 20),
        ("128 MiB", 128 << 20),
        ("512 MiB", 512 << 20),
    ] {
        println!("| {label} | {:.1} | {:.1} |", chase(bytes, 1), chase(bytes, 8));
    }
}

/// Circles at c 1.3 (the first target's fill) with each number of cells a shape lent, and
/// with `cells_for(n)`: the time and memory a budget buys (`-- --budgets`).
fn budgets(scale: u64) {
    let t = &TARGETS[0];
    let count = (t.count / scale).max(1);
    println!("| cells lent a shape | CPU s | us/placement | trials/placement | bytes/shape |");
    println!("|---|---:|---:|---:|---:|");
    for k in [None, Some(12.0), Some(8.0), Some(4.0), Some(2.3)] {
        let lent = Target { cells_per_shape: k, ..*t };
        let m = fill_2d(&lent, ShapeKind::Circle, count);
        let placed = m.placed.max(1) as f64;
        let what = k.map_or("`cells_for(n)`".to_string(), |k| format!("{k}"));
        println!(
            "| {what} | {:.2} | {:.2} | {:.1} | {:.0} |",
            m.secs,
            m.secs * 1e6 / placed,
            m.trials as f64 / placed,
            m.bytes_per_shape
        );
    }
}

fn main() {
    let scale: u64 = arg("--scale").and_then(|s| s.parse().ok()).unwrap_or(1).max(1);
    if std::env::args().any(|a| a == "--budgets") {
        budgets(scale);
        return;
    }
    if std::env::args().any(|a| a == "--latency") {
        latency();
        return;
    }
    if let Some(name) = arg("--one") {
        let t = TARGETS.iter().find(|t| t.name == name).expect("a target's name");
        let m = measure(t, scale);
        println!("{}: {} placed, {} trials, {:.3} s", t.name, m.placed, m.trials, m.secs);
        return;
    }
    println!("| fill | n | CPU s | target s | x target | us/placement | trials/placement | bytes/shape |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    for t in &TARGETS {
        let m = measure(t, scale);
        let placed = m.placed.max(1) as f64;
        // A target scaled down with the count, as the time per placement would be if flat.
        let target = t.secs / scale as f64;
        println!(
            "| {} | {} | {:.2} | {target:.2} | {:.1} | {:.2} | {:.1} | {:.0} |",
            t.what,
            m.placed,
            m.secs,
            m.secs / target,
            m.secs * 1e6 / placed,
            m.trials as f64 / placed,
            m.bytes_per_shape,
        );
    }
}
