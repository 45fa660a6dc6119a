//! The 3D cell sampler against the paper's sampler.
//!
//! Exactness is tested statistically, as in 2D (`sampler.rs`): for spheres, randomly rotated
//! cubes and shells, in an inclusive box, a periodic box and a ball, many fills are run with
//! each sampler (from disjoint seed sets) and the distributions of trial-free statistics of
//! chosen solids (the coordinates of solid `i`'s centre and the distance to the nearest other
//! centre) are compared with the two-sample Kolmogorov–Smirnov test. The family of all
//! comparisons is held at significance 0.01 (Bonferroni). The seeds are fixed, so the outcome
//! is the same on every run. The same comparison must reject a biased input (fills of a box
//! 10% narrower), which shows it can fail.
//!
//! Every fill of the cell sampler is also checked for overlaps and containment by the
//! independent checker of `space_fills.rs`, and the invariant the argument rests on (every
//! valid centre lies in a live cell) is checked directly in the core's unit tests.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::ks;
use zetafill::internals::space::{apart, Body, V3};
use zetafill::space::{
    cells_for as space_cells_for, index_words as space_index_words, Cell as SpaceCell, CellSampler as SpaceCells, Engine as SpaceEngine,
    Params as SpaceParams, Placed as PlacedSolid, Region as SpaceRegion, Solid, Storage as SpaceStorage,
};
use zetafill::{rng_from_seed, Fixed, Scalar, StepError, Stop, StopReason};

const COUNT: u64 = 40;
const RUNS: u64 = 400;
/// The solids whose statistics are compared.
const PICKS: [usize; 2] = [8, 30];
const STAT_NAMES: [&str; 4] = ["x", "y", "z", "nearest centre"];
const FAMILY_ALPHA: f64 = 0.01;

#[derive(Clone, Copy, PartialEq, Debug)]
enum Sampler {
    Reference,
    Fast,
    /// The paper's sampler in a box 10% narrower: a biased input for the checker.
    Narrow,
}

fn regions() -> [SpaceRegion; 3] {
    [
        SpaceRegion::Box {
            width: 40.0,
            height: 40.0,
            depth: 40.0,
            periodic: false,
        },
        SpaceRegion::Box {
            width: 40.0,
            height: 40.0,
            depth: 40.0,
            periodic: true,
        },
        SpaceRegion::Ball { radius: 20.0 },
    ]
}

fn params(kind: Solid) -> SpaceParams {
    SpaceParams {
        solids: kind.into(),
        rotate: true,
        max_trials: 1_000_000,
        ..SpaceParams::spheres(1.15, 8.0)
    }
}

type Rec = (Solid, [f64; 3], f64, [f64; 4]);

/// One fill of `count` solids; its solids and how it stopped.
fn fill<S: Scalar>(kind: Solid, region: SpaceRegion, sampler: Sampler, seed: u64, count: u64) -> (Vec<Rec>, StopReason) {
    fill_with::<S>(params(kind), region, sampler, seed, count, space_cells_for(count as usize))
}

fn fill_with<S: Scalar>(
    params: SpaceParams,
    region: SpaceRegion,
    sampler: Sampler,
    seed: u64,
    count: u64,
    cells: usize,
) -> (Vec<Rec>, StopReason) {
    let cap = count as usize;
    let mut solids = vec![PlacedSolid::<S>::default(); cap];
    let mut index = vec![0u32; space_index_words(cap)];
    let mut pool = vec![SpaceCell::default(); cells];
    let region = match (sampler, region) {
        (
            Sampler::Narrow,
            SpaceRegion::Box {
                height, depth, periodic, ..
            },
        ) => SpaceRegion::Box {
            width: 36.0,
            height,
            depth,
            periodic,
        },
        (_, r) => r,
    };
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    let mut e = SpaceEngine::<S>::new(params, region, storage).expect("valid");
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    let mut rng = rng_from_seed(seed);
    let reason = if sampler == Sampler::Fast {
        let mut cells = SpaceCells::new(&mut pool).expect("cells");
        e.run_fast(&mut cells, &mut rng, &stop, |_| {})
    } else {
        e.run(&mut rng, &stop, |_| {})
    };
    let out = e
        .placed()
        .iter()
        .enumerate()
        .map(|(i, p)| {
            (
                e.kind_of(i as u64),
                [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()],
                p.scale.to_f64(),
                p.rotation.map(|v| v.to_f64()),
            )
        })
        .collect();
    (out, reason)
}

fn centre_dist(a: [f64; 3], b: [f64; 3], periodic: bool) -> f64 {
    let fold = |d: f64| if periodic { d.abs().min(40.0 - d.abs()) } else { d };
    (0..3).map(|k| fold(a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
}

fn statistics(solids: &[Rec], periodic: bool) -> Vec<f64> {
    let mut out = Vec::new();
    for &i in &PICKS {
        let c = solids[i].1;
        let nearest = solids
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, s)| centre_dist(c, s.1, periodic))
            .fold(f64::INFINITY, f64::min);
        out.extend([c[0], c[1], c[2], nearest]);
    }
    out
}

fn samples(kind: Solid, region: SpaceRegion, sampler: Sampler, first_seed: u64) -> Vec<Vec<f64>> {
    let mut cols: Vec<Vec<f64>> = Vec::new();
    for seed in first_seed..first_seed + RUNS {
        let (solids, reason) = fill::<f64>(kind, region, sampler, seed, COUNT);
        assert_eq!(reason, StopReason::Count, "{kind:?} {sampler:?} seed {seed}");
        let st = statistics(&solids, region.periodic());
        cols.resize(st.len(), Vec::new());
        for (c, v) in cols.iter_mut().zip(st) {
            c.push(v);
        }
    }
    cols
}

fn cases() -> Vec<(Solid, SpaceRegion)> {
    let kinds = [Solid::Sphere, Solid::Cube, Solid::Shell { inner: 0.6 }];
    kinds.iter().flat_map(|&k| regions().map(|r| (k, r))).collect()
}

fn compare(kind: Solid, region: SpaceRegion, sampler: Sampler) -> Vec<(String, f64)> {
    let reference = samples(kind, region, Sampler::Reference, 1);
    let other = samples(kind, region, sampler, 1_000_001);
    reference
        .iter()
        .zip(&other)
        .enumerate()
        .map(|(k, (a, b))| {
            let (d, p) = ks(a, b);
            let label = format!(
                "{kind:?} in {region:?}: solid {} {} (D = {d:.3})",
                PICKS[k / STAT_NAMES.len()],
                STAT_NAMES[k % STAT_NAMES.len()]
            );
            (label, p)
        })
        .collect()
}

#[test]
fn same_distribution_as_reference() {
    let cases = cases();
    let alpha = FAMILY_ALPHA / (cases.len() * PICKS.len() * STAT_NAMES.len()) as f64;
    let mut failures = Vec::new();
    for (kind, region) in cases {
        for (label, p) in compare(kind, region, Sampler::Fast) {
            if p < alpha {
                failures.push(format!("{label}: p = {p:.2e} < {alpha:.1e}"));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "the 3D cell sampler differs from the reference:\n{}",
        failures.join("\n")
    );
}

#[test]
fn a_biased_input_fails_the_same_test() {
    let alpha = FAMILY_ALPHA / (cases().len() * PICKS.len() * STAT_NAMES.len()) as f64;
    let results = compare(Solid::Sphere, regions()[0], Sampler::Narrow);
    let worst = results.iter().map(|(_, p)| *p).fold(1.0, f64::min);
    assert!(worst < alpha, "the biased input passed (smallest p = {worst:.2e}): {results:?}");
}

/// Whether no two solids of a fill touch (by the core's exact test, which `space_fills.rs`
/// checks against an independent one) and every one keeps `gap`.
fn clear(solids: &[Rec], region: &SpaceRegion, gap: f64) -> bool {
    let ext = region.extent();
    let body =
        |r: &Rec, shift: [f64; 3]| Body::<f64>::new(&r.0, V3::new(r.1[0] + shift[0], r.1[1] + shift[1], r.1[2] + shift[2]), r.2, &r.3);
    let shifts: Vec<[f64; 3]> = if region.periodic() {
        let mut v = Vec::new();
        for a in [-1.0, 0.0, 1.0] {
            for b in [-1.0, 0.0, 1.0] {
                for c in [-1.0, 0.0, 1.0] {
                    v.push([a * ext[0], b * ext[1], c * ext[2]]);
                }
            }
        }
        v
    } else {
        vec![[0.0; 3]]
    };
    solids.iter().all(|r| region.holds(&body(r, [0.0; 3]), gap))
        && solids.iter().enumerate().all(|(i, a)| {
            solids[i + 1..]
                .iter()
                .all(|b| shifts.iter().all(|&s| apart(&body(a, [0.0; 3]), &body(b, s), gap)))
        })
}

#[test]
fn every_kind_in_every_region_is_clear_with_both_scalars() {
    let kinds = [
        Solid::Sphere,
        Solid::Cube,
        Solid::Tetrahedron,
        Solid::Octahedron,
        Solid::Shell { inner: 0.6 },
        Solid::Shell { inner: 0.9 },
        Solid::Torus { ratio: 0.3 },
    ];
    let mut regions = regions().to_vec();
    regions.push(SpaceRegion::BoxMinusBall {
        width: 40.0,
        height: 40.0,
        depth: 40.0,
        centre: [20.0, 20.0, 20.0],
        radius: 8.0,
    });
    for (ki, &kind) in kinds.iter().enumerate() {
        for (ri, &region) in regions.iter().enumerate() {
            for gap in [0.0, 0.3] {
                let p = SpaceParams {
                    gap,
                    max_trials: 200_000,
                    ..params(kind)
                };
                let seed = 5 + ki as u64 * 7 + ri as u64;
                let (solids, reason) = fill_with::<f64>(p.clone(), region, Sampler::Fast, seed, 60, space_cells_for(60));
                assert!(
                    matches!(reason, StopReason::Count | StopReason::Step(StepError::Halted { .. })),
                    "{kind:?} in {region:?}: {reason:?}"
                );
                assert!(
                    solids.len() >= 3 || matches!(kind, Solid::Shell { .. }),
                    "{kind:?} in {region:?}: {} solids",
                    solids.len()
                );
                assert!(clear(&solids, &region, gap), "{kind:?} in {region:?} gap {gap}");
                let (solids, _) = fill_with::<Fixed>(p, region, Sampler::Fast, seed, 20, space_cells_for(20));
                assert!(clear(&solids, &region, gap), "fixed {kind:?} in {region:?} gap {gap}");
            }
        }
    }
}

#[test]
fn the_clearance_check_fails_on_an_overlap() {
    let region = regions()[0];
    let id = [1.0, 0.0, 0.0, 0.0];
    let ok = vec![
        (Solid::Sphere, [10.0, 10.0, 10.0], 2.0, id),
        (Solid::Cube, [20.0, 10.0, 10.0], 2.0, id),
    ];
    assert!(clear(&ok, &region, 0.0));
    let bad = vec![
        (Solid::Sphere, [10.0, 10.0, 10.0], 2.0, id),
        (Solid::Cube, [13.0, 10.0, 10.0], 2.0, id),
    ];
    assert!(!clear(&bad, &region, 0.0));
    // Touching opposite faces: clear in an inclusive box, touching across a periodic one.
    let across = vec![
        (Solid::Sphere, [2.0, 10.0, 10.0], 2.0, id),
        (Solid::Sphere, [38.0, 10.0, 10.0], 2.0, id),
    ];
    assert!(clear(&across, &region, 0.0));
    assert!(
        !clear(&across, &regions()[1], 0.0),
        "a periodic overlap across a face went unnoticed"
    );
}

/// Lent `space_cells_for(capacity)` cells, a fill never depends on the storage: the first
/// 300 solids of a 300- and a 1,000-solid fill are the same bits (prefix stability too), and
/// reruns are identical.
#[test]
fn fills_do_not_depend_on_the_storage_and_prefixes_are_stable() {
    let p = SpaceParams {
        solids: Solid::Cube.into(),
        rotate: true,
        ..SpaceParams::spheres(1.15, 2.0)
    };
    let region = regions()[0];
    let (short, _) = fill_with::<f64>(p.clone(), region, Sampler::Fast, 3, 300, space_cells_for(300));
    let (long, _) = fill_with::<f64>(p.clone(), region, Sampler::Fast, 3, 1000, space_cells_for(1000));
    let (again, _) = fill_with::<f64>(p, region, Sampler::Fast, 3, 1000, space_cells_for(1000));
    assert_eq!(short[..], long[..300]);
    assert_eq!(long, again);
}

/// A halt before the trial limit is proven: no valid centre is left. Where the second sphere
/// cannot fit beside the first, the cell sampler halts in fewer trials than the limit, and the
/// paper's sampler spends its whole limit at the same placement.
#[test]
fn a_proven_halt_spends_fewer_trials_than_the_limit_and_the_reference_agrees() {
    let region = SpaceRegion::Box {
        width: 20.0,
        height: 20.0,
        depth: 20.0,
        periodic: false,
    };
    // c = 1.1, N = 0.14: the first sphere has radius 9.55 in a 20 mm cube, the second 4.43,
    // which fits neither in a corner (at most 3.13) nor along an edge (at most 1.9).
    let p = SpaceParams {
        max_trials: 200_000,
        ..SpaceParams::spheres(1.1, 0.14)
    };
    let run = |fast: bool| {
        let mut solids = vec![PlacedSolid::<f64>::default(); 4];
        let mut index = vec![0u32; space_index_words(4)];
        let mut pool = vec![SpaceCell::default(); space_cells_for(4)];
        let storage = SpaceStorage {
            solids: &mut solids,
            index: &mut index,
        };
        let mut e = SpaceEngine::<f64>::new(p.clone(), region, storage).expect("valid");
        let mut rng = rng_from_seed(1);
        let mut cells = SpaceCells::new(&mut pool).expect("cells");
        let mut out = Vec::new();
        for _ in 0..3 {
            let r = if fast {
                e.step_fast(&mut cells, &mut rng)
            } else {
                e.step(&mut rng)
            };
            out.push(r.map(|_| ()));
            if r.is_err() {
                break;
            }
        }
        out
    };
    let fast = run(true);
    let reference = run(false);
    let halted_at = |v: &[Result<(), StepError>]| v.iter().position(|r| r.is_err());
    assert_eq!(halted_at(&fast), halted_at(&reference), "fast {fast:?} reference {reference:?}");
    match fast.last() {
        Some(Err(StepError::Halted { trials, .. })) => assert!(*trials < 200_000, "not proven: {fast:?}"),
        other => panic!("expected a halt, got {other:?}"),
    }
}
