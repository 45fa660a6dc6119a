use super::*;

#[test]
fn blob_area_stays_below_the_bound_the_cell_sampler_uses() {
    // Twice a unit blob's area is at most 32 sin(2 pi / 32) (1 + 1.5 delta^2) for every
    // phase (the engine's `need` for blobs rests on it); and it comes close.
    for delta in [0.0, 0.1, 0.2, 0.33] {
        let bound = 32.0 * libm::sin(core::f64::consts::TAU / 32.0) * (1.0 + 1.5 * delta * delta);
        let mut most = 0.0f64;
        for k in 0..20_000u32 {
            let angle = f64::from(k) * 0.000_314_159;
            let (_, a2) = blob_unit::<f64>(delta, angle);
            assert!(a2 <= bound * (1.0 + 1e-12), "delta {delta} angle {angle}: {a2} > {bound}");
            most = most.max(a2);
        }
        assert!(most > bound * 0.95, "delta {delta}: the bound is loose ({most} of {bound})");
    }
}

fn area(g: &Geo<f64>) -> f64 {
    match *g {
        Geo::Circle { r, .. } => core::f64::consts::PI * r * r,
        Geo::Ring { r, inner, .. } => core::f64::consts::PI * (r * r - inner * inner),
        Geo::Poly { .. } | Geo::Motif { .. } => g.poly_area2() / 2.0,
    }
}

#[test]
fn every_kind_has_the_area_asked_for_and_is_ccw() {
    let kinds = [
        ShapeKind::Circle,
        ShapeKind::Square,
        ShapeKind::Rect { aspect: 2.5 },
        ShapeKind::Triangle,
        ShapeKind::Polygon { sides: 7 },
        ShapeKind::Star { points: 5, inner: 0.4 },
        ShapeKind::Ring { inner: 0.6 },
        ShapeKind::Blob { delta: 0.2 },
    ];
    for k in kinds {
        assert!(k.is_valid());
        for angle in [0.0, 0.7, 4.0] {
            let s: f64 = k.scale_for(123.0, angle);
            let g = k.geo(Point::new(1.0, 2.0), s, angle);
            assert!((area(&g) - 123.0).abs() < 1e-9, "{k:?} {angle}: {}", area(&g));
            if let Geo::Poly { .. } = g {
                assert!(g.poly_area2() > 0.0);
                let r = k.bounding_radius(s);
                assert!(g.max_dist2(Point::new(1.0, 2.0)) <= r * r * (1.0 + 1e-12), "{k:?}");
            }
        }
    }
}

#[test]
fn invalid_proportions_are_rejected() {
    assert!(!ShapeKind::Ring { inner: 1.0 }.is_valid());
    assert!(!ShapeKind::Star { points: 1, inner: 0.5 }.is_valid());
    assert!(!ShapeKind::Star { points: 5, inner: 0.0 }.is_valid());
    assert!(!ShapeKind::Polygon { sides: 2 }.is_valid());
    assert!(!ShapeKind::Polygon { sides: 49 }.is_valid());
    assert!(!ShapeKind::Blob { delta: 1.0 / 3.0 }.is_valid());
    assert!(!ShapeKind::Blob { delta: f64::NAN }.is_valid());
    assert!(!ShapeKind::Rect { aspect: 0.0 }.is_valid());
}

#[test]
fn a_mix_holds_one_to_max_mix_kinds_and_cycles_through_them() {
    let (c, s, t) = (ShapeKind::Circle, ShapeKind::Square, ShapeKind::Triangle);
    let eight = [c, s, t, c, c, s, t, c];
    assert_eq!(ShapeList::mix(&[], MixOrder::Cycle, 0), None);
    assert_eq!(ShapeList::mix(&[ShapeKind::Square; MAX_MIX + 1], MixOrder::Cycle, 0), None);
    let Some(full) = ShapeList::mix(&eight, MixOrder::Cycle, 0) else {
        panic!("eight kinds are a mix")
    };
    assert_eq!(full.kinds(), &eight);
    assert!(full.is_valid());
    assert_eq!(full.kind_of(9), ShapeKind::Square);
    let one = ShapeList::from(ShapeKind::Triangle);
    assert_eq!(one.kinds(), &[ShapeKind::Triangle]);
    assert_eq!(one.kind_of(12_345), ShapeKind::Triangle);
    // A random mix's choice is fixed by the salt and the index (SplitMix64's output mod n).
    let Some(two) = ShapeList::mix(&[ShapeKind::Circle, ShapeKind::Square], MixOrder::Random, 7) else {
        panic!("two kinds are a mix")
    };
    for i in 0..64 {
        let want = if mix64(i ^ 7) % 2 == 0 {
            ShapeKind::Circle
        } else {
            ShapeKind::Square
        };
        assert_eq!(two.kind_of(i), want);
    }
}

#[test]
fn blob_phases_change_with_the_angle() {
    let k = ShapeKind::Blob { delta: 0.25 };
    let a = k.geo(Point::new(0.0, 0.0), 1.0f64, 0.3);
    let b = k.geo(Point::new(0.0, 0.0), 1.0f64, 0.30000000001);
    assert_ne!(a, b);
    assert_eq!(a, k.geo(Point::new(0.0, 0.0), 1.0f64, 0.3));
}
