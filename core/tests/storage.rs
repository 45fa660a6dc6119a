//! What the cell sampler's storage may and may not change.
//!
//! Lent [`cells_for`] the engine's capacity or more ("ample"), a fill depends on its parameters
//! alone: not on the count asked for (which sets the capacity, and so which cells are too
//! tight for every shape the fill can place and are only counted), nor on how many cells are
//! lent beyond that. Those cells take no memory. Lent fewer, the sampler keeps every sleeping
//! cell in the older layout, whose fills are another, equally exact, sequence.

// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::Buffers;
use zetafill::internals::sampler::CellStats;
use zetafill::{cells_for, rng_from_seed, CellSampler, Engine, Params, Placed, Region, ShapeKind, Stop, StopReason};

const REGION: Region<'static> = Region::Rect {
    width: 200.0,
    height: 200.0,
    periodic: false,
};

/// Fills `count` shapes of `params` with room for `cap` and `pool` cells: the shapes and the
/// sampler's counters.
fn fill(params: Params, cap: usize, pool: usize, count: u64) -> (Vec<Placed<f64>>, CellStats) {
    let mut buffers = Buffers::<f64>::new(cap);
    let storage = buffers.storage(&mut []);
    let mut e = Engine::<f64>::new(params, REGION, storage).expect("valid parameters");
    let mut pool = vec![[0u64; 4]; pool];
    let mut cells = CellSampler::new(&mut pool).expect("cells");
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    let reason = e.run_fast(&mut cells, &mut rng_from_seed(11), &stop, |_| {});
    assert_eq!(reason, StopReason::Count);
    (e.placed().to_vec(), cells.stats())
}

fn cases() -> [(&'static str, Params); 3] {
    let mut squares = Params::circles(1.3, 1.0);
    squares.shape = ShapeKind::Square.into();
    squares.rotate = true;
    [
        ("circles, c 1.3", Params::circles(1.3, 1.0)),
        ("circles, c 1.4, N 2", Params::circles(1.4, 2.0)),
        ("rotated squares", squares),
    ]
}

#[test]
fn ample_fills_depend_on_neither_the_count_nor_the_cells_lent() {
    let k = 3000;
    for (name, p) in cases() {
        let (short, st) = fill(p.clone(), k, cells_for(k), k as u64);
        // Cells too tight for the last of k shapes were counted, not kept...
        assert!(st.outlived > 0, "{name}: nothing outlived the fill ({st:?})");
        // ...and yet the first k shapes of a longer fill, and of one lent twice the cells,
        // are the same.
        let (long, _) = fill(p.clone(), 2 * k, cells_for(2 * k), 2 * k as u64);
        assert_eq!(&long[..k], &short[..], "{name}: a longer fill starts otherwise");
        let (roomy, _) = fill(p.clone(), k, 2 * cells_for(k), k as u64);
        assert_eq!(roomy, short, "{name}: more cells lent changed the fill");
        // The control: one cell fewer than ample keeps every sleeper in the older layout,
        // whose shapes differ, so the comparisons above can tell fills apart.
        let (older, ot) = fill(p, k, cells_for(k) - 1, k as u64);
        assert_eq!(ot.outlived, 0, "{name}");
        assert_ne!(older, short, "{name}: the older layout gave the same shapes");
    }
}

#[test]
fn cells_that_outlive_the_fill_take_no_memory() {
    // Where circles of like size crowd (c = 1.4, N = 2) most cells held are asleep, and most
    // of those are too tight for every shape of the fill.
    let n = 20_000;
    let p = Params::circles(1.4, 2.0);
    let (_, ample) = fill(p.clone(), n, cells_for(n), n as u64);
    let (_, older) = fill(p, n, cells_for(n) - 1, n as u64);
    let per_shape = |s: &CellStats| s.peak as f64 / n as f64;
    println!(
        "cells a shape at the peak: {:.2} ample, {:.2} older",
        per_shape(&ample),
        per_shape(&older)
    );
    assert!(
        per_shape(&ample) < 0.4 * per_shape(&older),
        "{:.1} cells a shape at the peak against {:.1}",
        per_shape(&ample),
        per_shape(&older)
    );
    assert!(per_shape(&ample) < 8.0, "{ample:?}");
    // The budget saw the same cells: nothing was refused in either.
    assert_eq!((ample.refused_splits, older.refused_splits), (0, 0));
}
