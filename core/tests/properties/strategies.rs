//! Strategies: random and fixed configurations of fills.

use super::*;

pub(super) fn shape_strategy() -> impl Strategy<Value = ShapeKind> {
    prop_oneof![
        Just(ShapeKind::Circle),
        Just(ShapeKind::Square),
        (0.2f64..5.0).prop_map(|aspect| ShapeKind::Rect { aspect }),
    ]
}

pub(super) fn case_strategy() -> impl Strategy<Value = Case> {
    (
        any::<u64>(),
        1.1f64..1.45,
        0.5f64..5.0,
        shape_strategy(),
        any::<bool>(),
        prop_oneof![Just(0.0), 0.001f64..0.5],
        20.0f64..300.0,
        20.0f64..300.0,
        any::<bool>(),
    )
        .prop_map(|(seed, c, n, shape, rotate, gap, w, h, periodic)| Case {
            seed,
            c,
            n,
            shape,
            rotate,
            gap,
            w,
            h,
            periodic,
            max_trials: 200_000,
        })
}

pub(super) fn base_case() -> Case {
    Case {
        seed: 7,
        c: 1.3,
        n: 1.0,
        shape: ShapeKind::Circle,
        rotate: false,
        gap: 0.0,
        w: 100.0,
        h: 100.0,
        periodic: false,
        max_trials: 1_000_000,
    }
}

/// A spread of configurations for the fixed-case tests.
pub(super) fn varied_cases() -> Vec<Case> {
    let b = base_case();
    vec![
        b,
        Case {
            seed: 11,
            shape: ShapeKind::Square,
            rotate: true,
            gap: 0.1,
            ..b
        },
        Case {
            seed: 12,
            shape: ShapeKind::Rect { aspect: 3.0 },
            rotate: true,
            periodic: true,
            w: 80.0,
            h: 50.0,
            ..b
        },
        Case {
            seed: 13,
            c: 1.2,
            n: 2.0,
            periodic: true,
            gap: 0.05,
            w: 60.0,
            h: 120.0,
            ..b
        },
        Case {
            seed: 14,
            shape: ShapeKind::Rect { aspect: 0.4 },
            c: 1.4,
            n: 1.5,
            w: 40.0,
            h: 150.0,
            ..b
        },
        Case {
            seed: 15,
            shape: ShapeKind::Square,
            periodic: true,
            c: 1.35,
            n: 0.6,
            ..b
        },
    ]
}
