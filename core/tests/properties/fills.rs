//! Whole fills: valid, independent of storage sizes, prefix-stable, deterministic.

use super::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, failure_persistence: None, rng_seed: RngSeed::Fixed(0x2f11), ..ProptestConfig::default() })]

    /// Random fills are valid, and the coverage bitmap never changes a result.
    #[test]
    fn random_fills_are_valid(case in case_strategy(), k in 50u64..400) {
        let with_cov = run(&case, k, 1 << 12);
        let without = run(&case, k, 0);
        prop_assert!(
            matches!(
                with_cov.reason,
                StopReason::Count | StopReason::Step(StepError::Halted { .. }) | StopReason::Step(StepError::CannotFit { .. })
            ),
            "unexpected stop {:?}", with_cov.reason
        );
        if with_cov.reason == StopReason::Count {
            prop_assert_eq!(with_cov.placed.len() as u64, k);
        }
        if let Err(e) = same_run(&with_cov, &without) {
            return Err(TestCaseError::fail(format!("coverage changed the result: {e}")));
        }
        if let Err(e) = check_run(&case, &with_cov) {
            return Err(TestCaseError::fail(format!("{case:?} k={k}: {e}")));
        }
    }
}

#[test]
fn coverage_sizes_never_change_results() {
    for case in varied_cases() {
        let reference = run(&case, 300, 0);
        check_run(&case, &reference).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        for words in [1usize, 3, 64, 1 << 12, 1 << 14] {
            let r = run(&case, 300, words);
            same_run(&reference, &r).unwrap_or_else(|e| panic!("{case:?} coverage {words} words: {e}"));
        }
    }
}

#[test]
fn prefix_stability() {
    for (j, base) in varied_cases().into_iter().enumerate() {
        for k in [1u64, 37, 150] {
            let case = Case {
                seed: base.seed + 100 * j as u64 + k,
                ..base
            };
            let short = run(&case, k, 1 << 12);
            let long = run(&case, 2 * k, 1 << 12);
            assert_eq!(short.reason, StopReason::Count, "{case:?}");
            assert_eq!(short.placed.len() as u64, k);
            assert!(long.placed.len() as u64 >= k);
            for i in 0..k as usize {
                assert_eq!(placed_bits(&short.placed[i]), placed_bits(&long.placed[i]), "{case:?}: shape {i}");
                assert_eq!(
                    placement_bits(&short.placements[i]),
                    placement_bits(&long.placements[i]),
                    "{case:?}: placement {i}"
                );
            }
            let t: u64 = long.placements[..k as usize].iter().map(|p| p.trials).sum();
            assert_eq!(short.stats.trials, t);
        }
    }
}

#[test]
fn determinism() {
    for case in varied_cases() {
        let a = run(&case, 200, 1 << 12);
        let b = run(&case, 200, 1 << 12);
        same_run(&a, &b).unwrap_or_else(|e| panic!("{case:?}: same seed, different runs: {e}"));
        let other = run(
            &Case {
                seed: case.seed ^ 0x5555,
                ..case
            },
            200,
            1 << 12,
        );
        assert!(same_run(&a, &other).is_err(), "{case:?}: different seeds gave the same run");
        assert_ne!(placed_bits(&a.placed[0]), placed_bits(&other.placed[0]), "{case:?}");
    }
}

#[test]
fn spatial_hash_parity_with_single_bucket() {
    for case in varied_cases() {
        let k = 300u64;
        let stop = case.stop(k);
        let full = run_with(&case, k as usize, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        let one = run_with(&case, k as usize, &stop, 1 << 12, IndexSize::OneBucket).unwrap_or_else(|e| panic!("{e:?}"));
        same_run(&full, &one).unwrap_or_else(|e| panic!("{case:?}: hash size changed the result: {e}"));
        // A bigger capacity (more buckets) must not change the result either.
        let big = run_with(&case, 4 * k as usize, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        same_run(&full, &big).unwrap_or_else(|e| panic!("{case:?}: capacity changed the result: {e}"));
        check_run(&case, &full).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    }
}

// Regression: images more than one period away.
// ---------------------------------------------------------------------------------------------

/// A rotated elongated shape in a narrow torus can reach more than one period. `Engine::clear`
/// once tested only the images one period away, so shape 1's image two periods to the right,
/// (x + 2W, y), overlapped shape 0 and was accepted. Now every image within reach is tested.
#[test]
fn periodic_images_beyond_one_period_are_tested() {
    let case = Case {
        seed: 19,
        c: 1.3,
        n: 2.0,
        shape: ShapeKind::Rect { aspect: 4.0 },
        rotate: true,
        gap: 0.0,
        w: 30.0,
        h: 200.0,
        periodic: true,
        max_trials: 100_000,
    };
    let r = run(&case, 2, 0);
    assert_eq!(r.reason, StopReason::Count);
    check_fill(&r.items, case.w, case.h, case.gap, case.periodic).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    // More of the same: narrow tori, rotated rectangles within the proptest's ranges.
    for (aspect, w) in [(4.0, 25.0), (5.0, 25.0), (3.0, 25.0)] {
        for seed in 0..100u64 {
            let case = Case {
                seed,
                shape: ShapeKind::Rect { aspect },
                w,
                ..case
            };
            let r = run(&case, 100, 0);
            check_fill(&r.items, case.w, case.h, case.gap, case.periodic).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        }
    }
}
