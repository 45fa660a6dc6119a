//! The up-front checks of `feasibility` against the numbers the command-line tool printed
//! for the same parameters before those checks moved into the core (its messages round them
//! to four decimals), and capacity against its definition.

use zetafill::line::capacity as segment_capacity;
use zetafill::{check_first_two, first_shape, shape_capacity, AreaSequence, CapacityError, FirstTwoError, Params, Region, ShapeKind, Stop};

fn params(kind: ShapeKind, c: f64, n_offset: f64, gap: f64) -> Params {
    let mut p = Params::circles(c, n_offset);
    p.shape = kind.into();
    p.gap = gap;
    p
}

fn rect(width: f64, height: f64) -> Region<'static> {
    Region::Rect {
        width,
        height,
        periodic: false,
    }
}

/// (shape, c, N, gap, width, height, the largest c the tool printed).
const EXPONENT_LIMITS: &[(ShapeKind, f64, f64, f64, f64, f64, &str)] = &[
    (ShapeKind::Square, 1.6, 1.0, 0.0, 200.0, 200.0, "1.5224"),
    (ShapeKind::Square, 1.53, 1.0, 0.0, 200.0, 200.0, "1.5224"),
    // Bug: from a huge c the bisection never left 1 and the message named the limit 1.0000.
    (ShapeKind::Square, 1e100, 1.0, 0.0, 200.0, 200.0, "1.5224"),
    (ShapeKind::Square, 40.0, 1.0, 0.0, 200.0, 200.0, "1.5224"),
    (ShapeKind::Square, f64::MAX, 3.0, 0.0, 200.0, 200.0, "2.2439"),
    (ShapeKind::Square, 2.5, 3.0, 0.0, 200.0, 200.0, "2.2439"),
    (ShapeKind::Ring { inner: 0.5 }, 1.5, 1.0, 0.0, 200.0, 200.0, "1.3784"),
    (ShapeKind::Square, 1.3, 1.0, 60.0, 200.0, 200.0, "1.0034"),
    (ShapeKind::Circle, 1.3, 1.0, 55.0, 200.0, 200.0, "1.0247"),
    (ShapeKind::Square, 1.3, 1.0, 40.0, 200.0, 100.0, "1.0202"),
    (ShapeKind::Circle, 3.0, 0.5, 30.0, 200.0, 200.0, "1.0881"),
    (ShapeKind::Square, 1.2, 0.2, 0.0, 200.0, 200.0, "1.1922"),
    (ShapeKind::Square, 1.3, 0.5, 62.0, 200.0, 200.0, "1.0010"),
    (ShapeKind::Circle, 1.3, 0.3, 58.0, 200.0, 200.0, "1.0069"),
    (ShapeKind::Square, 1.9, 0.3, 50.0, 200.0, 200.0, "1.0088"),
    (ShapeKind::Rect { aspect: 2.0 }, 1.3, 1.0, 45.0, 200.0, 100.0, "1.0101"),
    (ShapeKind::Circle, 1.3, 0.01, 0.0, 50.0, 50.0, "1.0321"),
    (ShapeKind::Square, 2.0, 0.05, 0.0, 200.0, 200.0, "1.0953"),
    (ShapeKind::Square, 1.3, 0.1, 66.0, 200.0, 200.0, "1.0000"),
    (ShapeKind::Circle, 1.3, 0.2, 73.0, 200.0, 200.0, "1.0000"),
    (ShapeKind::Circle, 1.3, 0.001, 73.8, 200.0, 200.0, "1.0000"),
];

#[test]
fn exponent_limits_match_the_tool() {
    for &(kind, c, n, gap, w, h, want) in EXPONENT_LIMITS {
        match check_first_two(&params(kind, c, n, gap), &rect(w, h)) {
            Err(FirstTwoError::Exponent { max_c, n_offset, .. }) => {
                assert_eq!(format!("{max_c:.4}"), want, "{kind:?} c {c} N {n} gap {gap}");
                assert_eq!(n_offset, n);
            }
            other => panic!("{kind:?} c {c} N {n} gap {gap}: {other:?}"),
        }
    }
}

#[test]
fn gap_and_offset_limits_match_the_tool() {
    let square = check_first_two(&params(ShapeKind::Square, 1.3, 1.0, 70.0), &rect(200.0, 200.0));
    assert!(matches!(square, Err(FirstTwoError::Gap { max_gap, .. }) if format!("{max_gap:.4}") == "66.6667"));
    let circle = check_first_two(&params(ShapeKind::Circle, 1.3, 1.0, 80.0), &rect(200.0, 200.0));
    assert!(matches!(circle, Err(FirstTwoError::Gap { max_gap, .. }) if format!("{max_gap:.4}") == "73.8796"));
    let offset = check_first_two(&params(ShapeKind::Square, 1.3, 0.001, 66.6), &rect(200.0, 200.0));
    assert_eq!(
        offset,
        Err(FirstTwoError::Offset {
            kind: ShapeKind::Square,
            n_offset: 0.001
        })
    );
}

#[test]
fn the_tool_accepts_what_the_core_accepts() {
    // Runs the tool accepted (or left to the engine): fitting pairs, rotated shapes, kinds
    // without a known limit, other regions.
    let ok = [
        (params(ShapeKind::Rect { aspect: 2.0 }, 1.5, 1.0, 0.0), rect(200.0, 200.0)),
        (params(ShapeKind::Rect { aspect: 0.3 }, 1.45, 1.5, 0.0), rect(200.0, 200.0)),
        (params(ShapeKind::Circle, 1.5, 1.0, 0.0), rect(200.0, 200.0)),
        (params(ShapeKind::Circle, 1.9, 2.0, 0.0), rect(200.0, 200.0)),
        (params(ShapeKind::Rect { aspect: 3.0 }, 1.3, 1.0, 0.0), rect(300.0, 80.0)),
        (params(ShapeKind::Triangle, 1.5, 0.05, 0.0), rect(200.0, 200.0)),
        (params(ShapeKind::Circle, 1.3, 0.01, 0.0), Region::Circle { radius: 50.0 }),
    ];
    for (p, r) in ok {
        assert_eq!(check_first_two(&p, &r), Ok(()), "{p:?}");
    }
    let mut rotated = params(ShapeKind::Square, 1.6, 1.0, 0.0);
    rotated.rotate = true;
    assert_eq!(check_first_two(&rotated, &rect(200.0, 200.0)), Ok(()));
}

#[test]
fn first_shapes_match_the_tool() {
    // (shape, c, N, region area, width and area the tool printed)
    let pi = core::f64::consts::PI;
    let cases = [
        (ShapeKind::Triangle, 1.5, 0.05, 40_000.0, "173.0586", "38905.2693"),
        (ShapeKind::Square, 1.3, 0.001, 2500.0 * pi, "88.6008", "7850.0977"),
        (ShapeKind::Circle, 1.3, 0.001, (10_000.0 - 3600.0) * pi, "159.9604", "20096.2500"),
    ];
    for (kind, c, n, area, width, a0) in cases {
        let seq = AreaSequence::new(area, c, n).expect("valid c and N");
        let first = first_shape(&seq, &kind.into());
        assert_eq!(
            (format!("{:.4}", first.width), format!("{:.4}", first.area)),
            (width.into(), a0.into())
        );
        assert_eq!(first.kind, kind);
    }
}

#[test]
fn areas_sum_to_the_total_and_match_the_engine() {
    let seq = AreaSequence::new(40_000.0, 1.3, 1.0).expect("valid c and N");
    let region = rect(200.0, 200.0);
    let mut shapes = vec![zetafill::Placed::<f64>::default(); 4];
    let mut index = vec![0u32; zetafill::index_words(4)];
    let storage = zetafill::Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let engine = zetafill::Engine::new(Params::circles(1.3, 1.0), region, storage).expect("valid parameters");
    for i in [0, 1, 2, 10, 1000, 1 << 40] {
        assert_eq!(seq.area(i).to_bits(), engine.area_of(i).to_bits());
    }
    assert_eq!(seq.zeta().to_bits(), engine.zeta().to_bits());
    let head: f64 = (0..100_000).map(|i| seq.area(i)).sum();
    assert!((head / 40_000.0 - seq.covered(100_000)).abs() < 1e-9);
}

#[test]
fn capacity_covers_every_stop_condition() {
    let (c, n, area) = (1.3, 1.0, 40_000.0);
    let seq = AreaSequence::new(area, c, n).expect("valid c and N");
    let circle = ShapeKind::Circle.into();
    let count = Stop {
        count: Some(500),
        ..Stop::default()
    };
    assert_eq!(shape_capacity(&seq, &circle, &count, 1 << 20), Ok(501));
    for f in [0.1, 0.5, 0.8, 0.9] {
        let stop = Stop {
            fill: Some(f),
            ..Stop::default()
        };
        let k = shape_capacity(&seq, &circle, &stop, 1 << 20).expect("within the limit");
        // The first k - 1 shapes cover f; half as many do not (the search doubles).
        assert!(seq.covered(k - 1) >= f && seq.covered((k - 1) / 2) < f, "f {f} k {k}");
    }
    for m in [20.0, 5.0, 1.0] {
        let stop = Stop {
            min_size: Some(m),
            ..Stop::default()
        };
        let k = shape_capacity(&seq, &circle, &stop, 1 << 20).expect("within the limit");
        let width = |i: u64| 2.0 * libm::sqrt(seq.area(i) / core::f64::consts::PI);
        assert!(width(k - 1) < m && width((k - 1) / 2) >= m, "m {m} k {k}");
    }
    let too_much = Stop {
        fill: Some(0.999),
        ..Stop::default()
    };
    assert_eq!(
        shape_capacity(&seq, &circle, &too_much, 1 << 10),
        Err(CapacityError::Fill { fill: 0.999, max: 1 << 10 })
    );
    let too_small = Stop {
        min_size: Some(1e-6),
        ..Stop::default()
    };
    assert_eq!(
        segment_capacity(&seq, &too_small, 1 << 10),
        Err(CapacityError::MinSize {
            min_size: 1e-6,
            max: 1 << 10
        })
    );
    assert_eq!(segment_capacity(&seq, &Stop::default(), 77), Ok(77));
}
