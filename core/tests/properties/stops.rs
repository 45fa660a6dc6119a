//! Stop conditions, capacity, halting and shapes that cannot fit.

use super::*;

#[test]
fn capacity_stops_with_all_shapes_valid() {
    for case in varied_cases() {
        let r = run_with(&case, 10, &case.stop(20), 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.reason, StopReason::Step(StepError::Capacity { capacity: 10 }), "{case:?}");
        assert_eq!(r.placed.len(), 10);
        check_run(&case, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        // Same shapes as a run that was asked for exactly 10.
        let exact = run(&case, 10, 1 << 12);
        for (p, q) in r.placed.iter().zip(&exact.placed) {
            assert_eq!(placed_bits(p), placed_bits(q));
        }
    }
    // Stepping a full engine keeps failing the same way and changes nothing.
    let case = base_case();
    let mut shapes = vec![Placed::<f64>::default(); 3];
    let mut idx = vec![0u32; index_words(3)];
    let mut e = Engine::<f64>::new(
        case.params(),
        case.region(),
        Storage {
            shapes: &mut shapes,
            index: &mut idx,
            coverage: &mut [],
        },
    )
    .unwrap_or_else(|e| panic!("{e:?}"));
    let mut rng = rng_from_seed(1);
    for _ in 0..3 {
        assert!(e.step(&mut rng).is_ok());
    }
    let before: Vec<_> = e.placed().iter().map(placed_bits).collect();
    let stats = e.stats();
    for _ in 0..3 {
        assert_eq!(e.step(&mut rng), Err(StepError::Capacity { capacity: 3 }));
    }
    assert_eq!(e.placed().iter().map(placed_bits).collect::<Vec<_>>(), before);
    assert_eq!(stats_bits(&e.stats()), stats_bits(&stats));
}

#[test]
fn fill_fraction_stop() {
    for case in varied_cases() {
        let stop = Stop {
            fill: Some(0.5),
            ..Stop::default()
        };
        let r = run_with(&case, 5000, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.reason, StopReason::Fill, "{case:?}");
        check_run(&case, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        let n = r.placed.len();
        assert!(n >= 1);
        assert!(r.stats.fill_fraction >= 0.5, "{:?}", r.stats);
        // The area before the last placement was below half (accumulated as the engine does).
        let mut sum = 0.0f64;
        for p in &r.placements[..n - 1] {
            sum += p.area;
        }
        assert!(
            sum < 0.5 * r.area,
            "{case:?}: already {} filled before the last shape",
            sum / r.area
        );
        assert!(sum + r.placements[n - 1].area >= 0.5 * r.area);
        // One fewer shape: the fill stop does not hold yet.
        let fewer = run_with(
            &case,
            5000,
            &Stop {
                count: Some(n as u64 - 1),
                ..stop
            },
            1 << 12,
            IndexSize::Full,
        )
        .unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(fewer.reason, StopReason::Count, "{case:?}");
        assert!(fewer.stats.fill_fraction < 0.5, "{:?}", fewer.stats);
        // count and fill together: whichever holds first.
        let both = run_with(
            &case,
            5000,
            &Stop {
                count: Some(n as u64 + 5),
                ..stop
            },
            1 << 12,
            IndexSize::Full,
        )
        .unwrap_or_else(|e| panic!("{e:?}"));
        same_run(&r, &both).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    }
}

#[test]
fn min_size_stop() {
    for case in varied_cases() {
        // A minimum width that the 40th shape is just above and the 41st below (roughly).
        let kind = case.shape;
        let width_of = |i: u64| {
            let a = case.w * case.h
                / (zetafill::internals::zeta::hurwitz_zeta(case.c, case.n).unwrap_or(f64::NAN) * (i as f64 + case.n).powf(case.c));
            kind.min_width(kind.scale_for_area(a))
        };
        let m = 0.5 * (width_of(40) + width_of(41));
        let stop = Stop {
            min_size: Some(m),
            ..Stop::default()
        };
        let r = run_with(&case, 5000, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.reason, StopReason::MinSize, "{case:?}");
        check_run(&case, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        assert_eq!(r.placed.len(), 41, "{case:?}");
        for p in &r.placed {
            assert!(kind.min_width(p.scale) >= m);
        }
        let area_of = engine_area_of(&case);
        let next = kind.min_width(kind.scale_for_area(area_of(r.placed.len() as u64)));
        assert!(next < m, "{case:?}: next shape width {next} >= {m}");
        // A minimum exactly at a shape's width keeps that shape (stop is strictly below).
        let exact = kind.min_width(kind.scale_for_area(area_of(10)));
        let r = run_with(
            &case,
            5000,
            &Stop {
                min_size: Some(exact),
                ..stop
            },
            1 << 12,
            IndexSize::Full,
        )
        .unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.placed.len(), 11, "{case:?}");
    }
}

#[test]
fn stop_conditions_checked_before_the_first_step() {
    let case = base_case();
    for stop in [
        Stop {
            count: Some(0),
            ..Stop::default()
        },
        Stop {
            min_size: Some(f64::INFINITY),
            ..Stop::default()
        },
        Stop {
            fill: Some(0.0),
            ..Stop::default()
        },
    ] {
        let r = run_with(&case, 10, &stop, 0, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert!(r.placed.is_empty(), "{stop:?}");
        assert_eq!(r.stats.trials, 0);
        assert_ne!(r.reason, StopReason::Step(StepError::Capacity { capacity: 10 }));
    }
}

#[test]
fn halting_at_one_trial_keeps_everything_before() {
    for case in varied_cases() {
        let halting = Case { max_trials: 1, ..case };
        let r = run_with(&halting, 5000, &halting.stop(5000), 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        let StopReason::Step(StepError::Halted { index, trials }) = r.reason else {
            panic!("{case:?}: expected a halt, got {:?}", r.reason);
        };
        assert_eq!(trials, 1);
        assert_eq!(index, r.placed.len() as u64);
        assert!(r.placements.iter().all(|p| p.trials == 1));
        assert_eq!(r.stats.trials, index + 1);
        check_run(&halting, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        // The same shapes as an unlimited run: each of them took one trial there too.
        let full = run(&case, index + 1, 1 << 12);
        for i in 0..index as usize {
            assert_eq!(placed_bits(&r.placed[i]), placed_bits(&full.placed[i]));
        }
        assert!(full.placements[index as usize].trials > 1);
    }
}

#[test]
fn step_after_halt_continues() {
    // A halted step places nothing; stepping again draws new candidates.
    let case = Case {
        max_trials: 1,
        ..base_case()
    };
    let mut shapes = vec![Placed::<f64>::default(); 100];
    let mut idx = vec![0u32; index_words(100)];
    let mut e = Engine::<f64>::new(
        case.params(),
        case.region(),
        Storage {
            shapes: &mut shapes,
            index: &mut idx,
            coverage: &mut [],
        },
    )
    .unwrap_or_else(|e| panic!("{e:?}"));
    let mut rng = rng_from_seed(3);
    let mut halts = 0;
    let mut trials = 0;
    while e.placed().len() < 30 && halts < 100_000 {
        trials += 1;
        match e.step(&mut rng) {
            Ok(p) => assert_eq!(p.index + 1, e.placed().len() as u64),
            Err(StepError::Halted { index, trials: 1 }) => {
                assert_eq!(index, e.placed().len() as u64);
                halts += 1;
            }
            Err(other) => panic!("{other:?}"),
        }
    }
    assert_eq!(e.placed().len(), 30);
    assert!(halts > 0);
    assert_eq!(e.stats().trials, trials);
    let items = items_of(&e);
    check_fill(&items, case.w, case.h, case.gap, case.periodic).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn first_shape_too_large_cannot_fit() {
    // A square of almost the whole area cannot fit in a thin region.
    let case = Case {
        c: 1.9,
        n: 0.05,
        shape: ShapeKind::Square,
        w: 100.0,
        h: 10.0,
        ..base_case()
    };
    let r = run_with(&case, 10, &case.stop(10), 0, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(r.reason, StopReason::Step(StepError::CannotFit { index: 0 }));
    assert!(r.placed.is_empty());
    assert_eq!(r.stats.trials, 0);
}

// ---------------------------------------------------------------------------------------------
