//! The 1D samplers side by side in one process: segments at c = 1.4, N = 1 in a 200 mm
//! interval (inclusive, and periodic), seed 1, the paper's sampler (`LineEngine::step`)
//! against the exact gap sampler (`LineEngine::step_fast`). For each size: CPU time (the
//! thread's time on a CPU, `CLOCK_THREAD_CPUTIME_ID`), trials per
//! placement over the whole run and over its last tenth, the gap sampler's rejected
//! candidates, and the bytes per segment its storage takes (segment record, index words and
//! gap slots). The paper's sampler runs up to 10^5 segments.
//!
//!     cargo bench -p zetafill --bench line [-- N N ...]

mod common;
use common::cpu_seconds;
use zetafill::line::{
    gaps_for as line_gaps_for, index_words as line_index_words, Engine as LineEngine, Gap as LineGap, Gaps as LineGaps, Interval,
    Params as LineParams, Segment, Storage as LineStorage,
};
use zetafill::{rng_from_seed, Stop};

/// One fill of `n` segments: its trials, the gap sampler's rejections, and the CPU seconds.
fn fill(n: usize, fast: bool, periodic: bool) -> (Vec<u64>, String, f64) {
    let mut segments = vec![Segment::<f64>::default(); n];
    let mut index = vec![0u32; line_index_words(n)];
    let mut slots = if fast {
        vec![LineGap::default(); line_gaps_for(n)]
    } else {
        Vec::new()
    };
    let storage = LineStorage {
        segments: &mut segments,
        index: &mut index,
    };
    let interval = Interval { length: 200.0, periodic };
    let mut e = LineEngine::new(LineParams::new(1.4, 1.0), interval, storage).expect("valid");
    let stop = Stop {
        count: Some(n as u64),
        ..Stop::default()
    };
    let mut rng = rng_from_seed(1);
    let mut trials = Vec::with_capacity(n);
    let t0 = cpu_seconds();
    let rejected = if fast {
        let mut gaps = LineGaps::new(&mut slots).expect("slots");
        e.run_fast(&mut gaps, &mut rng, &stop, |p| trials.push(p.trials));
        gaps.rejected().to_string()
    } else {
        e.run(&mut rng, &stop, |p| trials.push(p.trials));
        "-".into()
    };
    (trials, rejected, cpu_seconds() - t0)
}

fn run(n: usize, fast: bool, periodic: bool) {
    // Short fills are repeated (the CPU clock is coarse) and their time averaged.
    let reps = (100_000 / n).max(1);
    let (trials, rejected, mut secs) = fill(n, fast, periodic);
    for _ in 1..reps {
        secs += fill(n, fast, periodic).2;
    }
    let secs = secs / reps as f64;
    assert_eq!(trials.len(), n, "the fill stopped early");
    let all = trials.iter().sum::<u64>() as f64 / n as f64;
    let tail = &trials[n - n / 10..];
    let last = tail.iter().sum::<u64>() as f64 / tail.len().max(1) as f64;
    let mut bytes = std::mem::size_of::<Segment<f64>>() as f64 + 4.0 * line_index_words(n) as f64 / n as f64;
    if fast {
        bytes += (std::mem::size_of::<LineGap>() * line_gaps_for(n)) as f64 / n as f64;
    }
    println!(
        "| {n} | {} | {} | {secs:.3} | {:.2} | {all:.3} | {last:.3} | {rejected} | {bytes:.0} |",
        if periodic { "periodic" } else { "inclusive" },
        if fast { "gaps" } else { "paper" },
        secs * 1e6 / n as f64,
    );
}

fn main() {
    let sizes: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() {
        vec![10_000, 100_000, 1_000_000]
    } else {
        sizes
    };
    println!("| segments | interval | sampler | s | us/placement | trials/placement | last tenth | rejected | bytes/segment |");
    println!("|---:|---|---|---:|---:|---:|---:|---:|---:|");
    for periodic in [false, true] {
        for &n in &sizes {
            if n <= 100_000 {
                run(n, false, periodic);
            }
            run(n, true, periodic);
        }
    }
}
