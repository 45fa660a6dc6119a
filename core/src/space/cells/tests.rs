//! The invariant the exactness rests on, and the heap.

extern crate std;
use super::*;
use crate::space3d::body::Body;
use crate::space3d::vec3::random_rotation;
use crate::space3d::{space_index_words, SpaceParams, SpaceStorage};
use std::vec;

/// The live cells, by level and position.
fn live_set(cells: &SpaceCells<'_>) -> std::collections::HashSet<(u8, [u32; 3])> {
    (0..cells.live()).map(|i| cells.get(i)).map(|c| (c.level, c.at)).collect()
}

/// Whether `p` lies in a live cell (on a face: either side counts).
fn covered(cells: &SpaceCells<'_>, live: &std::collections::HashSet<(u8, [u32; 3])>, p: [f64; 3]) -> bool {
    (0..SPACE_CELL_LEVELS as u8).any(|k| {
        let s = cells.side(k);
        let lo = p.map(|v| libm::floor(v / s) as u32);
        let on = p.map(|v| libm::floor(v / s) == v / s);
        (0..8u32).any(|b| {
            let at: [u32; 3] = core::array::from_fn(|a| if on[a] && (b >> a) & 1 == 1 { lo[a].wrapping_sub(1) } else { lo[a] });
            live.contains(&(k, at))
        })
    })
}

/// The invariant the exactness argument rests on: before every placement's draws, every
/// valid centre of the next solid (found by the engine's own exact test at random points
/// with random rotations) lies in a live cell. Checked for every kind the sampler serves,
/// in every region kind, with and without a gap, with the storage ample and scarce.
#[test]
fn every_valid_centre_lies_in_a_live_cell() {
    let kinds = [
        Solid::Sphere,
        Solid::Cube,
        Solid::Tetrahedron,
        Solid::Octahedron,
        Solid::Shell { inner: 0.6 },
    ];
    let regions = [
        SpaceRegion::Box {
            width: 30.0,
            height: 24.0,
            depth: 27.0,
            periodic: false,
        },
        SpaceRegion::Box {
            width: 30.0,
            height: 30.0,
            depth: 30.0,
            periodic: true,
        },
        SpaceRegion::Ball { radius: 15.0 },
        SpaceRegion::BoxMinusBall {
            width: 30.0,
            height: 30.0,
            depth: 30.0,
            centre: [15.0, 15.0, 15.0],
            radius: 6.0,
        },
    ];
    let mut checked = 0usize;
    for (ki, kind) in kinds.iter().enumerate() {
        for (ri, region) in regions.iter().enumerate() {
            for (gap, pool_len) in [(0.0, space_cells_for(60)), (0.4, 600)] {
                let n = 60;
                let mut solids = vec![PlacedSolid::<f64>::default(); n];
                let mut index = vec![0u32; space_index_words(n)];
                let mut pool = vec![SpaceCell::default(); pool_len];
                let storage = SpaceStorage {
                    solids: &mut solids,
                    index: &mut index,
                };
                let params = SpaceParams {
                    solids: (*kind).into(),
                    rotate: true,
                    gap,
                    max_trials: 100_000,
                    ..SpaceParams::spheres(1.2, 6.0)
                };
                let mut e = SpaceEngine::new(params, *region, storage).unwrap();
                let mut cells = SpaceCells::new(&mut pool).unwrap();
                let mut rng = crate::rng_from_seed(100 + ki as u64 * 10 + ri as u64);
                let mut probe = crate::rng_from_seed(7);
                for _ in 0..n {
                    let next = e.next().unwrap();
                    cells.prepare(&e, e.need(&next).unwrap());
                    let live = live_set(&cells);
                    for _ in 0..800 {
                        let p: [f64; 3] = core::array::from_fn(|a| {
                            let (l, h) = (next.lo[a], next.hi[a]);
                            crate::rng::uniform(&mut probe, l, h)
                        });
                        let q = random_rotation(&mut probe);
                        let body = Body::new(&next.kind, V3::new(p[0], p[1], p[2]), next.scale, &q);
                        if e.fits(&body, next.bound) {
                            checked += 1;
                            assert!(
                                covered(&cells, &live, p),
                                "{kind:?} in {region:?}: valid centre {p:?} outside the live cells"
                            );
                        }
                    }
                    if e.step_fast(&mut cells, &mut rng).is_err() {
                        break;
                    }
                }
            }
        }
    }
    assert!(checked > 10_000, "too few valid centres probed: {checked}");
}

/// The same check must fail when a cell is taken out wrongly: a sampler that drops its
/// largest live cell loses valid centres.
#[test]
fn the_invariant_check_catches_a_dropped_cell() {
    let n = 10;
    let mut solids = vec![PlacedSolid::<f64>::default(); n];
    let mut index = vec![0u32; space_index_words(n)];
    let mut pool = vec![SpaceCell::default(); space_cells_for(n)];
    let region = SpaceRegion::Box {
        width: 30.0,
        height: 30.0,
        depth: 30.0,
        periodic: false,
    };
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    let mut e = SpaceEngine::new(SpaceParams::spheres(1.2, 6.0), region, storage).unwrap();
    let mut cells = SpaceCells::new(&mut pool).unwrap();
    let mut rng = crate::rng_from_seed(1);
    for _ in 0..n - 1 {
        e.step_fast(&mut cells, &mut rng).unwrap();
    }
    let next = e.next().unwrap();
    let mut probe = crate::rng_from_seed(8);
    let valid = (0..100_000)
        .map(|_| core::array::from_fn::<f64, 3, _>(|a| crate::rng::uniform(&mut probe, next.lo[a], next.hi[a])))
        .find(|p| {
            e.fits(
                &Body::new(&next.kind, V3::new(p[0], p[1], p[2]), next.scale, &crate::space3d::vec3::identity()),
                next.bound,
            )
        })
        .unwrap();
    assert!(covered(&cells, &live_set(&cells), valid));
    // Take out the live cell that holds it, as a wrong retirement would.
    let holder = (0..cells.live())
        .find(|&i| {
            let c = cells.get(i);
            let s = cells.side(c.level);
            (0..3).all(|a| valid[a] >= f64::from(c.at[a]) * s && valid[a] <= f64::from(c.at[a] + 1) * s)
        })
        .unwrap();
    let _ = cells.remove_live(holder);
    let live = live_set(&cells);
    // Unless a neighbour shares the face it lies on, the check now fails.
    assert!(
        !covered(&cells, &live, valid),
        "removing the cell that holds a valid centre went unnoticed"
    );
}

#[test]
fn the_heap_wakes_cells_in_order_of_their_bound() {
    let mut pool = vec![SpaceCell::default(); 64];
    let mut cells = SpaceCells::new(&mut pool).unwrap();
    cells.side0 = 1.0;
    let bounds = [0.3, 0.9, 0.1, 0.7, 0.5, 0.8, 0.2];
    for (i, &u) in bounds.iter().enumerate() {
        let c = SpaceCell {
            at: [i as u32, 0, 0],
            u,
            ..SpaceCell::default()
        };
        cells.push_sleep(c);
    }
    cells.wake(0.6);
    assert_eq!(cells.live(), 3);
    assert_eq!(cells.asleep(), 4);
    let mut woken: std::vec::Vec<f64> = (0..cells.live()).map(|i| cells.get(i).u).collect();
    woken.sort_by(f64::total_cmp);
    assert_eq!(woken, [0.7, 0.8, 0.9]);
    let c = cells.remove_live(1);
    assert_eq!(cells.live(), 2);
    assert!(c.u >= 0.7);
    cells.wake(0.0);
    assert_eq!((cells.live(), cells.asleep()), (6, 0));
}
