//! The 3D samplers side by side in one process: spheres at c = 1.15, N = 1 in a 100 mm cube,
//! seed 1, the paper's sampler (`SpaceEngine::step`) against the octree cell sampler
//! (`SpaceEngine::step_fast`). For each size: CPU time, trials per placement over the whole
//! run and over its last tenth, the cell sampler's peak cells and rebuilds, and the bytes per
//! solid its storage needed (solid record, index words and peak cells). The paper's sampler
//! runs up to 10^4 solids.
//!
//! With `rings`, the paper's Figure 1 instead: rings (`Solid::Torus { ratio: 0.3 }`) at
//! c = 1.1, N = 2 in a 60 mm cube, seed 1, with the paper's sampler (tori take no cells),
//! at 300 and 1,000 rings: CPU time, trials per placement, and time per trial.
//!
//!     cargo bench -p zetafill --bench space [-- N N ... | -- rings]

use std::time::Instant;
use zetafill::space::{
    cells_for as space_cells_for, index_words as space_index_words, Cell as SpaceCell, CellSampler as SpaceCells, Engine as SpaceEngine,
    Params as SpaceParams, Placed as PlacedSolid, Region as SpaceRegion, Solid, Storage as SpaceStorage,
};
use zetafill::{rng_from_seed, Stop};

/// An inclusive cube of side `side` mm.
fn cube(side: f64) -> SpaceRegion {
    SpaceRegion::Box {
        width: side,
        height: side,
        depth: side,
        periodic: false,
    }
}

fn rings(n: usize) {
    let mut solids = vec![PlacedSolid::<f64>::default(); n];
    let mut index = vec![0u32; space_index_words(n)];
    let region = cube(60.0);
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    let params = SpaceParams {
        solids: Solid::Torus { ratio: 0.3 }.into(),
        rotate: true,
        ..SpaceParams::spheres(1.1, 2.0)
    };
    let mut e = SpaceEngine::new(params, region, storage).expect("valid");
    let stop = Stop {
        count: Some(n as u64),
        ..Stop::default()
    };
    let mut rng = rng_from_seed(1);
    let mut trials = 0u64;
    let t = Instant::now();
    e.run(&mut rng, &stop, |p| trials += p.trials);
    let secs = t.elapsed().as_secs_f64();
    println!(
        "| {n} | {secs:.2} | {:.0} | {:.2} | {:.4} |",
        trials as f64 / n as f64,
        secs * 1e6 / trials as f64,
        e.stats().fill_fraction
    );
}

fn run(n: usize, fast: bool) {
    let mut solids = vec![PlacedSolid::<f64>::default(); n];
    let mut index = vec![0u32; space_index_words(n)];
    let mut pool = if fast {
        vec![SpaceCell::default(); space_cells_for(n)]
    } else {
        Vec::new()
    };
    let region = cube(100.0);
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    let mut e = SpaceEngine::new(SpaceParams::spheres(1.15, 1.0), region, storage).expect("valid");
    let stop = Stop {
        count: Some(n as u64),
        ..Stop::default()
    };
    let mut rng = rng_from_seed(1);
    let mut trials = Vec::with_capacity(n);
    let t = Instant::now();
    let (peak, rebuilds) = if fast {
        let mut cells = SpaceCells::new(&mut pool).expect("cells");
        e.run_fast(&mut cells, &mut rng, &stop, |p| trials.push(p.trials));
        (cells.peak(), cells.rebuilds())
    } else {
        e.run(&mut rng, &stop, |p| trials.push(p.trials));
        (0, 0)
    };
    let secs = t.elapsed().as_secs_f64();
    let all = trials.iter().sum::<u64>() as f64 / trials.len().max(1) as f64;
    let tail = &trials[trials.len() - trials.len() / 10..];
    let last = tail.iter().sum::<u64>() as f64 / tail.len().max(1) as f64;
    let record = std::mem::size_of::<PlacedSolid<f64>>() + 4 * space_index_words(n) / n;
    let bytes = record + peak * std::mem::size_of::<SpaceCell>() / n;
    println!(
        "| {n} | {} | {secs:.2} | {:.1} | {all:.0} | {last:.0} | {} | {} | {bytes} |",
        if fast { "cells" } else { "paper" },
        secs * 1e6 / n as f64,
        if fast { peak.to_string() } else { "-".into() },
        if fast { rebuilds.to_string() } else { "-".into() }
    );
}

fn main() {
    if std::env::args().any(|a| a == "rings") {
        println!("| rings | s | trials/placement | us/trial | fill |");
        println!("|---:|---:|---:|---:|---:|");
        rings(300);
        rings(1_000);
        return;
    }
    let sizes: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() {
        vec![1_000, 10_000, 30_000, 100_000]
    } else {
        sizes
    };
    println!("| solids | sampler | s | us/placement | trials/placement | last tenth | peak cells | rebuilds | bytes/solid |");
    println!("|---:|---|---:|---:|---:|---:|---:|---:|---:|");
    for &n in &sizes {
        if n <= 10_000 {
            run(n, false);
        }
        run(n, true);
    }
}
