//! Motif benchmark: a heart with a heart-shaped hole (200 vertices, non-convex) filled into
//! the 200 x 200 mm square with the cell sampler, random rotations, seed 1: CPU time, trials,
//! exact tests (a candidate against one placed shape, past the bounding discs) and edge-tree
//! walks (exact tests the inner covers did not decide) per placement. Run with
//! `cargo bench -p zetafill --bench motif --features counters` (add `-- --quick` to stop at
//! 10^3 shapes). Prints a Markdown table; it asserts nothing about time.

mod common;

use common::{cpu_seconds, RECT};
use zetafill::{cells_for, counters, index_words, CellSampler, Engine, Motif, Params, Placed, Point, Stop, StopReason, Storage};

/// The outline of `examples/motifs/heart-ring.svg` in its own coordinates (y down): the heart
/// x = 16 sin^3 t, y = 13 cos t - 5 cos 2t - 2 cos 3t - cos 4t at scale 1.5 about (50, 48),
/// with the same heart at scale 0.7 about (50, 45) as its hole, 100 vertices each.
fn heart_ring() -> (Vec<Point<f64>>, Vec<usize>) {
    let heart = |s: f64, cx: f64, cy: f64| -> Vec<Point<f64>> {
        (0..100)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 100.0;
                let x = 16.0 * libm::pow(libm::sin(t), 3.0);
                let y = 13.0 * libm::cos(t) - 5.0 * libm::cos(2.0 * t) - 2.0 * libm::cos(3.0 * t) - libm::cos(4.0 * t);
                Point::new(cx + s * x, cy - s * y)
            })
            .collect()
    };
    let mut pts = heart(1.5, 50.0, 48.0);
    pts.extend(heart(0.7, 50.0, 45.0).into_iter().rev());
    (pts, vec![100, 200])
}

fn row(c: f64, n_offset: f64, count: u64) -> String {
    let (mut pts, ends) = heart_ring();
    let mut scratch = vec![0u32; Motif::scratch_words(pts.len())];
    let motifs = [Motif::new_in(&mut pts, &ends, &mut scratch).expect("a valid motif")];
    let params = Params {
        shape: motifs[0].kind(0).into(),
        rotate: true,
        max_trials: 100_000_000,
        ..Params::circles(c, n_offset)
    };
    let cap = count as usize;
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    let mut pool = vec![[0u64; 4]; cells_for(cap)];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    counters::reset();
    let t = cpu_seconds();
    let mut e = Engine::<f64>::with_motifs(params, RECT, storage, &motifs).expect("valid parameters");
    let mut cells = CellSampler::new(&mut pool).expect("cells");
    let stop = e.run_fast(
        &mut cells,
        &mut zetafill::rng_from_seed(1),
        &Stop {
            count: Some(count),
            ..Stop::default()
        },
        |_| {},
    );
    let secs = cpu_seconds() - t;
    let s = e.stats();
    assert_eq!(stop, StopReason::Count, "the fill stopped early");
    let per = |v: u64| v as f64 / s.placed as f64;
    format!(
        "| {} | {c} | {n_offset} | {:.3} | {:.1} | {:.1} | {:.1} | {:.1}% |",
        s.placed,
        secs,
        s.trials_per_placement(),
        per(counters::exact_tests()),
        per(counters::edge_walks()),
        100.0 * s.fill_fraction
    )
}

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    println!("| heart rings | c | N | CPU s | trials / placement | exact tests / placement | edge walks / placement | filled |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut rows = vec![(1.15, 4.0, 1_000), (1.3, 4.0, 100)];
    if !quick {
        rows.push((1.15, 4.0, 10_000));
    }
    for (c, n, count) in rows {
        println!("{}", row(c, n, count));
    }
}
