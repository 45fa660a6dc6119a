//! Fill benchmark: placements and trials per second of the reference sampler (c = 1.3, N = 1;
//! stars, rings and blobs, whose largest usable c is lower: c = 1.2, N = 3), and bytes of core
//! storage per shape. Run with `cargo bench -p zetafill --bench fill` (add `-- --quick` to
//! stop at n = 10^4, `-- --only NAME` to run the rows whose label starts with NAME). Prints a
//! Markdown table for the README. It measures; it asserts nothing about time.

use std::time::Instant;
use zetafill::{index_words, Engine, Params, Placed, Region, ShapeKind, Stop, Storage};

const COVERAGE_WORDS: usize = 1 << 18;

struct Row {
    label: String,
    n: u64,
    secs: f64,
    trials: u64,
    fill: f64,
}

fn run(label: &str, shape: ShapeKind, n: u64, periodic: bool) -> Row {
    let c = if matches!(shape, ShapeKind::Star { .. } | ShapeKind::Blob { .. } | ShapeKind::Ring { .. }) {
        1.2
    } else {
        1.3
    };
    let cap = n as usize;
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    let mut coverage = vec![0u64; COVERAGE_WORDS];
    // Concave shapes need room for their first placements: N = 3 (with N = 1 the first stars
    // often cannot all fit, and the fill halts).
    let n_offset = if matches!(shape, ShapeKind::Star { .. } | ShapeKind::Blob { .. } | ShapeKind::Ring { .. }) {
        3.0
    } else {
        1.0
    };
    let mut params = Params::circles(c, n_offset);
    params.shape = shape.into();
    params.rotate = shape.rotates();
    params.max_trials = 100_000_000;
    let region = Region::Rect {
        width: 200.0,
        height: 200.0,
        periodic,
    };
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    let t = Instant::now();
    let mut e = Engine::<f64>::new(params, region, storage).expect("valid parameters");
    let mut rng = zetafill::rng_from_seed(1);
    let _ = e.run(
        &mut rng,
        &Stop {
            count: Some(n),
            ..Stop::default()
        },
        |_| {},
    );
    let secs = t.elapsed().as_secs_f64();
    let s = e.stats();
    Row {
        label: label.into(),
        n: s.placed,
        secs,
        trials: s.trials,
        fill: s.fill_fraction,
    }
}

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let ns: &[u64] = if quick { &[1_000, 10_000] } else { &[1_000, 10_000, 100_000] };
    println!("| run | n | time (s) | trials | trials/placement | placements/s | trials/s | ns/trial | fill |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    // The largest and most concave shapes run to 10^4 only (their trials are far dearer).
    let cases: Vec<(&str, ShapeKind, bool, u64)> = vec![
        ("circles", ShapeKind::Circle, false, u64::MAX),
        ("circles periodic", ShapeKind::Circle, true, u64::MAX),
        ("squares rotated", ShapeKind::Square, false, u64::MAX),
        ("stars 5:0.45 rotated", ShapeKind::Star { points: 5, inner: 0.45 }, false, 10_000),
        ("rings 0.6", ShapeKind::Ring { inner: 0.6 }, false, 10_000),
        ("blobs 0.2", ShapeKind::Blob { delta: 0.2 }, false, 10_000),
    ];
    let only: Option<String> = std::env::args().skip_while(|a| a != "--only").nth(1);
    for (label, shape, periodic, max_n) in cases {
        if only.as_deref().is_some_and(|o| !label.starts_with(o)) {
            continue;
        }
        for &n in ns.iter().filter(|&&n| n <= max_n) {
            let r = run(label, shape, n, periodic);
            println!(
                "| {} | {} | {:.3} | {} | {:.1} | {:.0} | {:.3e} | {:.1} | {:.4} |",
                r.label,
                r.n,
                r.secs,
                r.trials,
                r.trials as f64 / r.n as f64,
                r.n as f64 / r.secs,
                r.trials as f64 / r.secs,
                r.secs * 1e9 / r.trials as f64,
                r.fill
            );
        }
    }
    let per_shape = std::mem::size_of::<Placed<f64>>() + 4 * (index_words(1000) - 1) / 1000;
    println!();
    println!(
        "core storage per shape: {} bytes ({} shape record + {} index words); coverage bitmap {} KiB fixed",
        per_shape,
        std::mem::size_of::<Placed<f64>>(),
        (index_words(1000) - 1) / 1000,
        COVERAGE_WORDS * 8 / 1024
    );
}
