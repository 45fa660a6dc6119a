//! Polygon region benchmark, in one run: the time to validate an outline before the edge tree
//! (`core/tests/oracles/legacy_region.rs`: every pair of edges, an O(R) ring lookup per edge), with no
//! scratch (`PolygonRegion::new`: every pair of edges) and with the tree
//! (`PolygonRegion::new_in`); then fills of 200 circles (c = 1.25, N = 3, seed 1) in a wavy
//! outline with and without the tree, with the cell sampler and with the reference sampler
//! and its coverage bitmap, as the CLI runs them. The fills with and without the tree must
//! give the same digest (asserted: it is the point of the tree).
//!
//! Run with `cargo bench -p zetafill --bench region`. Flags: `--quick` (skip the rows that
//! take minutes), `--only NAME` (rows whose label starts with NAME), `--size N` (rows of N
//! vertices or squares), `--way WAY` (`before`, `pairs`, `tree` or `fill`: one way only, for
//! `valgrind --tool=callgrind --toggle-collect='*legacy::validate*'` or
//! `'*PolygonRegion::new_in*'`). Prints Markdown. It measures; it asserts nothing about time.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

#[path = "../tests/oracles/legacy_region.rs"]
mod legacy;

use std::time::Instant;
use zetafill::{
    cells_for, index_words, rng_from_seed, CellSampler, Engine, Params, Placed, Point, PolygonRegion, Region, Stop, StopReason, Storage,
};

/// Vertices, ring after ring, and the end of each ring.
type Outline = (Vec<Point<f64>>, Vec<usize>);

/// One wavy closed outline of `n` vertices about (100, 100), radius 60 to 100 (star-shaped,
/// so simple).
fn outline(n: usize) -> Outline {
    let pts = (0..n)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / n as f64;
            let r = 80.0 + 20.0 * (7.0 * t).sin();
            Point::new(100.0 + r * t.cos(), 100.0 + r * t.sin())
        })
        .collect();
    (pts, vec![n])
}

/// `k` squares of side 1 on a square lattice of pitch 2 (islands, one ring each).
fn squares(k: usize) -> Outline {
    let side = (k as f64).sqrt().ceil() as usize;
    let (mut pts, mut ends) = (Vec::with_capacity(4 * k), Vec::with_capacity(k));
    for i in 0..k {
        let (x, y) = (2.0 * (i % side) as f64, 2.0 * (i / side) as f64);
        pts.extend([
            Point::new(x, y),
            Point::new(x + 1.0, y),
            Point::new(x + 1.0, y + 1.0),
            Point::new(x, y + 1.0),
        ]);
        ends.push(pts.len());
    }
    (pts, ends)
}

/// One row: an input, and which quadratic ways to run on it.
struct Case {
    label: &'static str,
    make: fn(usize) -> Outline,
    size: usize,
    before: bool,
    pairs: bool,
}

impl Case {
    fn new(label: &'static str, make: fn(usize) -> Outline, size: usize, before: bool, pairs: bool) -> Self {
        Case {
            label,
            make,
            size,
            before,
            pairs,
        }
    }
}

fn secs<T>(f: impl FnOnce() -> T) -> (f64, T) {
    let t = Instant::now();
    let v = f();
    (t.elapsed().as_secs_f64(), v)
}

fn arg(name: &str) -> Option<String> {
    std::env::args().skip_while(|a| a != name).nth(1)
}

fn cell(v: Option<f64>) -> String {
    v.map_or(String::new(), |s| format!("{s:.4}"))
}

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let only = arg("--only");
    let way = arg("--way");
    let want = |w: &str| way.as_deref().is_none_or(|x| x == w);
    let only_size: Option<usize> = arg("--size").and_then(|v| v.parse().ok());
    let size_filter = |n: usize| only_size.is_some_and(|s| s != n);
    let picked = |label: &str| only.as_deref().is_none_or(|o| label.starts_with(o));
    // The quadratic ways stop where they take minutes (before the tree, 10^4 squares would
    // take about an hour).
    let cases = [
        Case::new("outline", outline, 1_000, true, true),
        Case::new("outline", outline, 10_000, true, true),
        Case::new("outline", outline, 100_000, !quick, !quick),
        Case::new("squares", squares, 100, true, true),
        Case::new("squares", squares, 1_000, true, true),
        Case::new("squares", squares, 3_600, !quick, true),
        Case::new("squares", squares, 10_000, false, !quick),
    ];
    println!("| input | vertices | rings | before (s) | no scratch (s) | tree (s) | tree vs before | tree vs no scratch |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    for c in &cases {
        let (label, size) = (c.label, c.size);
        if !picked(label) || size_filter(size) {
            continue;
        }
        let (pts, ends) = (c.make)(size);
        let mut area = None;
        let mut same = |a: Option<f64>| {
            assert!(area.is_none() || a == area, "{label} {size}: the areas differ");
            area = a;
        };
        let before = (c.before && want("before")).then(|| {
            let (t, a) = secs(|| legacy::validate(&pts, &ends));
            same(a.ok());
            t
        });
        let pairs = (c.pairs && want("pairs")).then(|| {
            let (t, a) = secs(|| PolygonRegion::new(&pts, &ends).map(|r| r.area()));
            same(a.ok());
            t
        });
        let tree = want("tree").then(|| {
            let mut scratch = vec![0u32; PolygonRegion::scratch_words(pts.len())];
            let (t, a) = secs(|| PolygonRegion::new_in(&pts, &ends, &mut scratch).map(|r| r.area()));
            same(a.ok());
            t
        });
        let ratio = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => format!("{:.0}x", a / b),
            _ => String::new(),
        };
        println!(
            "| {label} | {} | {} | {} | {} | {} | {} | {} |",
            pts.len(),
            ends.len(),
            cell(before),
            cell(pairs),
            cell(tree),
            ratio(before, tree),
            ratio(pairs, tree)
        );
    }
    if picked("fill") && want("fill") {
        fills(quick);
    }
}

/// Fills of 200 circles in wavy outlines, with and without the tree.
fn fills(quick: bool) {
    println!();
    println!("| fill of 200 circles | vertices | sampler | no scratch (s) | tree (s) | speed-up | trials | digest |");
    println!("|---|---:|---|---:|---:|---:|---:|---|");
    for (n, fast, without_too) in [
        (10_000, true, true),
        (10_000, false, true),
        (100_000, true, !quick),
        (100_000, false, !quick),
    ] {
        let (pts, ends) = outline(n);
        let mut scratch = vec![0u32; PolygonRegion::scratch_words(pts.len())];
        let with = PolygonRegion::new_in(&pts, &ends, &mut scratch).expect("a simple outline");
        let (t_tree, trials, digest) = fill(with, fast);
        let t_pairs = without_too.then(|| {
            let without = PolygonRegion::new(&pts, &ends).expect("a simple outline");
            let (t, trials_b, digest_b) = fill(without, fast);
            assert_eq!((trials, digest), (trials_b, digest_b), "the tree changed the fill");
            t
        });
        println!(
            "| wavy outline | {n} | {} | {} | {:.3} | {} | {trials} | {:016x} |",
            if fast { "cells" } else { "reference" },
            cell(t_pairs),
            t_tree,
            t_pairs.map_or(String::new(), |t| format!("{:.0}x", t / t_tree)),
            digest.1
        );
    }
}

fn fill(poly: PolygonRegion<'_>, fast: bool) -> (f64, u64, (u64, u64)) {
    let n = 200usize;
    let mut shapes = vec![Placed::<f64>::default(); n];
    let mut index = vec![0u32; index_words(n)];
    let mut coverage = vec![0u64; if fast { 0 } else { 1 << 18 }];
    let mut pool = vec![[0u64; 4]; if fast { cells_for(n) } else { 1 }];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    let stop = Stop {
        count: Some(n as u64),
        ..Stop::default()
    };
    let (t, (reason, e)) = secs(|| {
        let mut e = Engine::<f64>::new(Params::circles(1.25, 3.0), Region::Polygon(poly), storage).expect("valid parameters");
        let mut rng = rng_from_seed(1);
        let reason = if fast {
            let mut cells = CellSampler::new(&mut pool).expect("cells");
            e.run_fast(&mut cells, &mut rng, &stop, |_| {})
        } else {
            e.run(&mut rng, &stop, |_| {})
        };
        (reason, e)
    });
    assert_eq!(reason, StopReason::Count, "the fill stopped early");
    (t, e.stats().trials, zetafill::digest::engine_digest(&e))
}
