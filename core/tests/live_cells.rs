//! The invariant the cell sampler's exactness rests on, checked by brute force: through whole
//! fills in every kind of region, every valid centre of the next shape lies in a live cell.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{params, Buffers};
use rand_core::RngCore;
use zetafill::internals::geom::separated;
use zetafill::{cells_for, rng_from_seed, Batches, CellSampler, Engine, Lane, Point, PolygonRegion, Region, Scalar, ShapeKind, Stop};

/// Whether shape `n` of the fill of `e` fits at `p` at one of `angles`, next to every shape
/// placed so far (and their periodic images), checked by brute force with the exact pair test.
fn valid_centre_of<S: Scalar>(e: &Engine<'_, S>, n: u64, p: Point<S>, angles: &[f64]) -> bool {
    let gap = S::from_f64(e.params().gap);
    let region = e.region();
    let (_, _, w, h) = region.bbox();
    let shifts: &[(f64, f64)] = if region.periodic() {
        &[
            (0.0, 0.0),
            (w, 0.0),
            (-w, 0.0),
            (0.0, h),
            (0.0, -h),
            (w, h),
            (w, -h),
            (-w, h),
            (-w, -h),
        ]
    } else {
        &[(0.0, 0.0)]
    };
    let kind = e.kind_of(n);
    angles.iter().any(|&angle| {
        let angle = S::from_f64(angle);
        let scale: S = kind.scale_for(e.area_of(n), angle);
        let cand = kind.geo(p, scale, angle);
        let reach = kind.bounding_radius(scale) + gap;
        if !region.periodic() && !region.contains(&cand, gap) {
            return false;
        }
        e.placed().iter().enumerate().all(|(i, s)| {
            let far = reach + e.kind_of(i as u64).bounding_radius(s.scale);
            let g = e.geo(i).expect("placed");
            shifts.iter().all(|&(dx, dy)| {
                let (dx, dy) = (S::from_f64(dx), S::from_f64(dy));
                let (cx, cy) = (s.x + dx - p.x, s.y + dy - p.y);
                cx * cx + cy * cy > far * far || separated(&cand, &g.shift(dx, dy), gap)
            })
        })
    })
}

/// Checks that every valid centre among `points` lies in one of `boxes`; returns the number of
/// valid points seen, or the first one left out.
fn cells_hold_every_valid_centre<S: Scalar>(
    e: &Engine<'_, S>,
    boxes: &[[f64; 4]],
    points: &[Point<S>],
    angles: &[f64],
) -> Result<usize, Point<S>> {
    cells_hold_centres_of(e, e.placed().len() as u64, boxes, points, angles)
}

/// [`cells_hold_every_valid_centre`] for shape `n`.
fn cells_hold_centres_of<S: Scalar>(
    e: &Engine<'_, S>,
    n: u64,
    boxes: &[[f64; 4]],
    points: &[Point<S>],
    angles: &[f64],
) -> Result<usize, Point<S>> {
    let mut valid = 0;
    for &p in points {
        if valid_centre_of(e, n, p, angles) {
            valid += 1;
            let (x, y) = (p.x.to_f64(), p.y.to_f64());
            if !boxes.iter().any(|b| x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3]) {
                return Err(p);
            }
        }
    }
    Ok(valid)
}

/// The boxes each shrunk by a tenth about its centre: the broken input of the checks.
fn shrunk(boxes: &[[f64; 4]]) -> Vec<[f64; 4]> {
    boxes
        .iter()
        .map(|b| {
            let (dx, dy) = ((b[2] - b[0]) * 0.05, (b[3] - b[1]) * 0.05);
            [b[0] + dx, b[1] + dy, b[2] - dx, b[3] - dy]
        })
        .collect()
}

/// What [`check_invariant`] runs: fills of `kind` in each of `regions` with each (gap, cell
/// pool) of `configs`, checked before the first five placements and every `every`-th on
/// `points` uniform points, each tried at `angles` angles.
#[derive(Clone, Copy)]
struct Probe<'r> {
    kind: ShapeKind,
    regions: &'r [Region<'r>],
    configs: &'r [(f64, usize)],
    every: usize,
    points: usize,
    angles: usize,
}

/// Runs `probe`, checking at each check that every valid centre among the points lies in a
/// live cell. Returns the checks
/// made, the valid points seen, and how many checks found valid points outside the same cells
/// shrunk by a tenth about their centres.
fn check_invariant<S: Scalar>(probe: &Probe<'_>) -> (usize, usize, usize) {
    let Probe {
        kind,
        regions,
        configs,
        every,
        points,
        angles,
    } = *probe;
    let mut rng = rng_from_seed(99);
    let mut unit = || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    let (mut checked, mut valid_seen, mut broken_caught) = (0, 0, 0);
    let angles: Vec<f64> = if kind.rotates() {
        (0..angles)
            .map(|k| std::f64::consts::TAU * (k as f64 + 0.5) / angles as f64)
            .collect()
    } else {
        vec![0.0]
    };
    for (ri, region) in regions.iter().enumerate() {
        for &(gap, pool_len) in configs {
            let cap = 400;
            let mut b = Buffers::<S>::new(cap);
            let mut p = params(kind);
            p.gap = gap;
            // A fill that halts ends its checks; let it halt soon.
            p.max_trials = 200_000;
            let mut none: [u64; 0] = [];
            let mut e = Engine::<S>::new(p, *region, b.storage(&mut none)).expect("valid");
            let mut pool = vec![[0u64; 4]; pool_len];
            let mut cells = CellSampler::new(&mut pool).expect("cells");
            let mut frng = rng_from_seed(7 + ri as u64);
            let (x0, y0, w, h) = region.bbox();
            for step in 1..=cap {
                if e.step_fast(&mut cells, &mut frng).is_err() {
                    break;
                }
                if !(step < 5 || step % every == 0) || !e.prepare_fast(&mut cells) {
                    continue;
                }
                let pts: Vec<Point<S>> = (0..points)
                    .map(|_| Point::new(S::from_f64(x0 + unit() * w), S::from_f64(y0 + unit() * h)))
                    .collect();
                let boxes: Vec<[f64; 4]> = cells.live_boxes().collect();
                match cells_hold_every_valid_centre(&e, &boxes, &pts, &angles) {
                    Ok(v) => valid_seen += v,
                    Err(q) => {
                        panic!("{kind:?}, region {ri}, gap {gap}, pool {pool_len}, after {step} shapes: valid centre {q:?} in no live cell")
                    }
                }
                checked += 1;
                // The broken input: the same cells, each shrunk by a tenth.
                let shrunk = shrunk(&boxes);
                if cells_hold_every_valid_centre(&e, &shrunk, &pts, &angles).is_err() {
                    broken_caught += 1;
                }
            }
        }
    }
    (checked, valid_seen, broken_caught)
}

/// The least a run of [`check_invariant`] must show: checks made, valid points seen, and the
/// share of checks (one in `caught_one_in`) where the shrunk cells were caught.
struct Least {
    checks: usize,
    valid: usize,
    caught_one_in: usize,
}

/// Runs [`check_invariant`] and asserts that it checked enough and that its checker failed
/// on the broken input often enough.
fn assert_invariant<S: Scalar>(probe: &Probe<'_>, least: Least) {
    let (checked, valid_seen, broken_caught) = check_invariant::<S>(probe);
    let what = format!("{:?} ({})", probe.kind, std::any::type_name::<S>());
    println!("{what}: checks {checked}, valid points {valid_seen}, shrunk cells caught {broken_caught}");
    assert!(checked >= least.checks, "{what}: checks made: {checked}");
    assert!(valid_seen >= least.valid, "{what}: valid points seen: {valid_seen}");
    assert!(
        broken_caught * least.caught_one_in >= checked,
        "{what}: shrunk cells caught in {broken_caught} of {checked} checks"
    );
}

/// The exactness argument's invariant, checked directly: throughout circle fills of 400 in
/// every kind of region (with and without a gap, with a pool that fills up, and with one too
/// small to refine), every point where the next circle fits lies in a live cell, once the
/// cells are brought up to date for that circle. Checked before the first five placements
/// and every sixteenth, on 4000 uniform points each, their validity decided by brute force
/// against every placed shape (and its periodic images). The same checker, given the cells
/// shrunk by a tenth about their centres, finds valid points left out: it can fail. It also
/// catches bounds that are too low by a tenth of a cell's half diagonal where a cell learns a
/// shape, and a stubborn cell's children bounded over three of their quarters only.
#[test]
fn live_cells_hold_every_valid_centre() {
    let (pts, ends) = common::star_with_hole();
    let regions = common::every_kind(PolygonRegion::new(&pts, &ends).expect("a star with a hole"));
    let configs = [(0.0, cells_for(400)), (0.8, cells_for(400)), (0.0, 3000), (0.0, 6)];
    let least = Least {
        checks: 200,
        valid: 20_000,
        caught_one_in: 2,
    };
    let probe = Probe {
        kind: ShapeKind::Circle,
        regions: &regions,
        configs: &configs,
        every: 16,
        points: 4000,
        angles: 1,
    };
    assert_invariant::<f64>(&probe, least);
}

/// The same invariant for the shapes whose bounds come from polygon and ring distances and
/// whose room depends on their angle: rotated squares, stars and blobs, and rings, in every
/// kind of region, without a gap, and with a gap and a pool that fills up. A centre counts as
/// valid when the shape fits there at one of 12 angles.
fn cells_hold_centres_of_kinds(kinds: &[ShapeKind]) {
    let (pts, ends) = common::star_with_hole();
    let regions = common::every_kind(PolygonRegion::new(&pts, &ends).expect("a star with a hole"));
    for &kind in kinds {
        let least = Least {
            checks: 30,
            valid: 2000,
            caught_one_in: 3,
        };
        let probe = Probe {
            kind,
            regions: &regions,
            configs: &[(0.0, cells_for(400)), (0.6, 4000)],
            every: 24,
            points: 1000,
            angles: 12,
        };
        assert_invariant::<f64>(&probe, least);
    }
}

/// [`cells_hold_centres_of_kinds`] for rotated squares, stars and blobs (and the next test for
/// the rest: two tests, so that the test threads share the work).
#[test]
fn live_cells_hold_every_valid_centre_of_other_shapes() {
    cells_hold_centres_of_kinds(&[
        ShapeKind::Square,
        ShapeKind::Star { points: 5, inner: 0.5 },
        ShapeKind::Blob { delta: 0.1 },
    ]);
}

/// [`live_cells_hold_every_valid_centre_of_other_shapes`] for noisy blobs and rings.
#[test]
fn live_cells_hold_every_valid_centre_of_noisy_blobs_and_rings() {
    cells_hold_centres_of_kinds(&[
        ShapeKind::Noisy {
            amplitude: 0.3,
            features: 4,
            octaves: 2,
        },
        ShapeKind::Ring { inner: 0.5 },
    ]);
}

/// The same invariant on 32.32 fixed point, the board's scalar, where every bound is rounded:
/// circles and rotated squares in an inclusive and a periodic rectangle, with a pool that
/// fills up.
#[test]
fn live_cells_hold_every_valid_centre_on_fixed_point() {
    let (pts, ends) = common::star_with_hole();
    let [rect, torus, ..] = common::every_kind(PolygonRegion::new(&pts, &ends).expect("a star with a hole"));
    for kind in [ShapeKind::Circle, ShapeKind::Square] {
        let least = Least {
            checks: 30,
            valid: 2000,
            caught_one_in: 3,
        };
        let probe = Probe {
            kind,
            regions: &[rect, torus],
            configs: &[(0.0, cells_for(400)), (0.6, 3000)],
            every: 24,
            points: 1000,
            angles: 12,
        };
        assert_invariant::<zetafill::Fixed>(&probe, least);
    }
}

/// The same invariant on fixed point at the largest supported size: triangles and rings in a
/// rectangle and a torus nearly 10,000 mm across whose sides are no multiple of the grid.
/// There the bounds square lengths up to 10^8 mm² (a squared cross product once saturated and
/// put them far below the truth, and the sampler halted as if certain where shapes still
/// fitted), and a grid cell's four children once missed a strip of it (its side did not halve
/// exactly).
#[test]
fn live_cells_hold_every_valid_centre_on_fixed_point_at_full_size() {
    let (w, h) = (9_876.543_21, 7_654.321);
    let regions = [
        Region::Rect {
            width: w,
            height: h,
            periodic: false,
        },
        Region::Rect {
            width: w,
            height: h,
            periodic: true,
        },
    ];
    for kind in [ShapeKind::Triangle, ShapeKind::Ring { inner: 0.5 }] {
        let least = Least {
            checks: 20,
            valid: 300,
            caught_one_in: 6,
        };
        let probe = Probe {
            kind,
            regions: &regions,
            configs: &[(0.0, cells_for(400))],
            every: 48,
            points: 400,
            angles: 6,
        };
        assert_invariant::<zetafill::Fixed>(&probe, least);
    }
}

/// The batched sampler's invariant: before each batch is screened (the first eight, then every
/// fourth), every point where the batch's first or last shape fits next to the shapes placed
/// before the batch lies in a live cell: the cells every trial of the batch draws from hold
/// every valid centre of each of its shapes. Circle fills of 400 in every kind of region, with
/// and without a gap, with ample cells and with a pool that fills up; the same checker finds
/// valid points outside the cells shrunk by a tenth.
#[test]
fn batched_cells_hold_every_valid_centre_of_the_batch() {
    let (pts, ends) = common::star_with_hole();
    let regions = common::every_kind(PolygonRegion::new(&pts, &ends).expect("a star with a hole"));
    let mut rng = rng_from_seed(98);
    let mut unit = || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    let (mut checked, mut valid_seen, mut caught) = (0usize, 0usize, 0usize);
    for (ri, region) in regions.iter().enumerate() {
        for (gap, pool_len) in [(0.0, cells_for(400)), (0.8, cells_for(400)), (0.0, 3000)] {
            let mut b = Buffers::<f64>::new(400);
            let mut p = params(ShapeKind::Circle);
            p.gap = gap;
            p.max_trials = 200_000;
            let mut e = Engine::<f64>::new(p, *region, b.storage(&mut [])).expect("valid");
            let mut pool = vec![[0u64; 4]; pool_len];
            let mut cells = CellSampler::new(&mut pool).expect("cells");
            let mut lanes = vec![Lane::default(); 32];
            let mut batches = Batches::new(&mut lanes, 7 + ri as u64, 32).expect("lanes");
            let (x0, y0, w, h) = region.bbox();
            let mut batch = 0;
            let stop = Stop {
                count: Some(400),
                ..Stop::default()
            };
            e.run_batched_with(
                &mut cells,
                &mut batches,
                &stop,
                |_| {},
                |e, c, plan, lanes| {
                    batch += 1;
                    if batch <= 8 || batch % 4 == 0 {
                        let pts: Vec<Point<f64>> = (0..2000).map(|_| Point::new(x0 + unit() * w, y0 + unit() * h)).collect();
                        let boxes: Vec<[f64; 4]> = c.live_boxes().collect();
                        let shrunk = shrunk(&boxes);
                        for n in [plan.first, plan.end - 1] {
                            match cells_hold_centres_of(e, n, &boxes, &pts, &[0.0]) {
                                Ok(v) => valid_seen += v,
                                Err(q) => panic!(
                                    "region {ri}, gap {gap}, pool {pool_len}, batch at {}: shape {n}'s valid centre {q:?} in no live cell",
                                    plan.first
                                ),
                            }
                            caught += usize::from(cells_hold_centres_of(e, n, &shrunk, &pts, &[0.0]).is_err());
                            checked += 1;
                        }
                    }
                    e.screen(c, plan, lanes);
                },
            );
        }
    }
    println!("checks {checked}, valid points {valid_seen}, shrunk cells caught {caught}");
    assert!(checked >= 300, "checks made: {checked}");
    assert!(valid_seen >= 20_000, "valid points seen: {valid_seen}");
    assert!(caught * 2 >= checked, "shrunk cells caught in {caught} of {checked} checks");
}
