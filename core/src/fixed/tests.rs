use super::*;

fn f(v: f64) -> Fixed {
    Fixed::from_f64(v)
}

#[test]
fn unit_uses_the_top_32_bits() {
    assert_eq!(Fixed::unit(0), Fixed::ZERO);
    assert_eq!(Fixed::unit(u64::MAX), Fixed::ONE - Fixed::DELTA);
    assert_eq!(Fixed::unit(1 << 63).to_f64(), 0.5);
    assert_eq!(Fixed::unit(0xffff_ffff), Fixed::ZERO);
}

#[test]
fn conversions_round_and_saturate_without_panicking() {
    assert_eq!(f(f64::NAN), Fixed::ZERO);
    assert_eq!(f(f64::INFINITY), Fixed::MAX);
    assert_eq!(f(f64::NEG_INFINITY), Fixed::MIN);
    assert_eq!(f(1e300), Fixed::MAX);
    assert_eq!(f(-2.5).to_f64(), -2.5);
    assert_eq!(f(200.0).to_bits(), 200 << 32);
    assert_eq!(f(-0.0).digest_bits(), 0);
    // 0.1 rounds to the nearest multiple of 2^-32.
    assert!((f(0.1).to_f64() - 0.1).abs() <= 0.5 / 4_294_967_296.0);
}

#[test]
fn arithmetic_saturates_and_division_by_zero_is_defined() {
    assert_eq!(Fixed::MAX + Fixed::ONE, Fixed::MAX);
    assert_eq!(Fixed::MIN - Fixed::ONE, Fixed::MIN);
    assert_eq!(-Fixed::MIN, Fixed::MAX);
    assert_eq!(f(70_000.0) * f(70_000.0), Fixed::MAX);
    assert_eq!(f(-70_000.0) * f(70_000.0), Fixed::MIN);
    assert_eq!(Fixed::ONE / Fixed::ZERO, Fixed::MAX);
    assert_eq!(-Fixed::ONE / Fixed::ZERO, Fixed::MIN);
    assert_eq!(Fixed::ZERO / Fixed::ZERO, Fixed::ZERO);
    assert_eq!(Fixed::MIN / -Fixed::DELTA, Fixed::MAX);
    assert_eq!(f(3.0) * f(-1.5), f(-4.5));
    assert_eq!(f(1.0) / f(4.0), f(0.25));
}

#[test]
fn floor_and_half() {
    assert_eq!(f(-2.5).floor_i64(), -3);
    assert_eq!(f(2.999).floor_i64(), 2);
    assert_eq!(Fixed::MIN.floor_i64(), -(1 << 31));
    assert_eq!(f(3.0).half(), f(1.5));
}

#[test]
fn sqrt_is_the_floor_of_the_exact_root() {
    assert_eq!(f(4.0).sqrt(), f(2.0));
    assert_eq!(f(-4.0).sqrt(), Fixed::ZERO);
    assert_eq!(Fixed::ZERO.sqrt(), Fixed::ZERO);
    for v in [2.0, 0.001, 12345.678, 2.0e9, 1e-9] {
        let r = f(v).sqrt();
        // r is the largest value with r² <= v (checked exactly in integers).
        let raw = i128::from(f(v).to_bits()) << 32;
        let rr = i128::from(r.to_bits());
        assert!(rr * rr <= raw && (rr + 1) * (rr + 1) > raw, "{v}");
        assert!((r.to_f64() - libm::sqrt(f(v).to_f64())).abs() <= 2.4e-10, "{v}");
    }
}

#[test]
fn sin_cos_within_5e9_of_libm_for_every_quadrant_and_wrap() {
    let mut worst = 0.0f64;
    let mut a = -40.0;
    while a < 40.0 {
        let (s, c) = f(a).sin_cos();
        let x = f(a).to_f64();
        worst = worst.max((s.to_f64() - libm::sin(x)).abs()).max((c.to_f64() - libm::cos(x)).abs());
        a += 0.000_913;
    }
    assert!(worst < 5e-9, "worst error {worst}");
    assert_eq!(Fixed::ZERO.sin_cos(), (Fixed::ZERO, Fixed::ONE));
    let (s, c) = f(core::f64::consts::FRAC_PI_2).sin_cos();
    assert!((s - Fixed::ONE).abs() < f(5e-9) && c.abs() < f(5e-9));
    let (s, c) = Fixed::MAX.sin_cos();
    assert!(s.abs() <= Fixed::ONE && c.abs() <= Fixed::ONE);
}

#[test]
fn digest_bits_are_the_raw_bits() {
    assert_eq!(f(1.0).digest_bits(), 1 << 32);
    assert_eq!(f(-1.0).digest_bits(), (-(1i64 << 32)) as u64);
}

#[test]
fn engine_fills_without_overlap_on_fixed_point() {
    use crate::{index_words, Engine, Params, Placed, Region, Stop, Storage};
    let mut shapes = [Placed::<Fixed>::default(); 200];
    let mut index = [0u32; index_words(200)];
    let region = Region::Rect {
        width: 200.0,
        height: 200.0,
        periodic: false,
    };
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut e = Engine::<Fixed>::new(Params::circles(1.3, 1.0), region, storage).unwrap();
    let mut rng = crate::rng_from_seed(1);
    let stop = e.run(
        &mut rng,
        &Stop {
            count: Some(200),
            ..Stop::default()
        },
        |_| {},
    );
    assert_eq!(stop, crate::StopReason::Count);
    let placed = e.placed();
    for (i, p) in placed.iter().enumerate() {
        assert!(p.x - p.scale >= Fixed::ZERO && p.x + p.scale <= f(200.0), "{i}");
        for q in &placed[..i] {
            let (dx, dy, r) = (p.x - q.x, p.y - q.y, p.scale + q.scale);
            assert!(dx * dx + dy * dy > r * r, "{i} overlaps");
        }
    }
}

/// The exact quotient of two `i128` rationals rounded toward −∞, for checks.
fn floor_div(p: i128, c: i128) -> i128 {
    p.div_euclid(c) - if c < 0 && p.rem_euclid(c) != 0 { 1 } else { 0 }
}

#[test]
fn mul_div_keeps_the_product_exact() {
    // 10^6 x 10^6 / 10^6: the product alone would saturate.
    assert_eq!(f(1e6).mul_div(f(1e6), f(1e6)), f(1e6));
    assert_eq!(tally::take(), 0);
    assert_eq!(f(1e6) * f(1e6) / f(1e6), Fixed::MAX / f(1e6));
    assert_eq!(tally::take(), 1);
    assert_eq!(f(3.0).mul_div(f(-5.0), f(2.0)), f(-7.5));
    // Rounded toward −∞, like `*`.
    assert_eq!(Fixed::DELTA.mul_div(Fixed::DELTA, Fixed::ONE), Fixed::ZERO);
    assert_eq!((-Fixed::DELTA).mul_div(Fixed::DELTA, Fixed::ONE), -Fixed::DELTA);
    assert_eq!(f(2.0).mul_div(f(3.0), Fixed::ZERO), Fixed::MAX);
    assert_eq!(f(-2.0).mul_div(f(3.0), Fixed::ZERO), Fixed::MIN);
    assert_eq!(Fixed::ZERO.mul_div(f(3.0), Fixed::ZERO), Fixed::ZERO);
    assert_eq!(Fixed::MAX.mul_div(Fixed::MAX, Fixed::DELTA), Fixed::MAX);
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s as i64) >> (s % 40)
    };
    for _ in 0..10_000 {
        let (a, b, c) = (next(), next(), next());
        if c == 0 {
            continue;
        }
        let q = floor_div(i128::from(a) * i128::from(b), i128::from(c));
        let want = q.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64;
        let got = Fixed::from_bits(a).mul_div(Fixed::from_bits(b), Fixed::from_bits(c));
        assert_eq!(got.to_bits(), want, "{a} {b} {c}");
    }
    tally::take();
}

/// Exact `x² + y²` in units of 2^-64.
fn exact_sq(x: Fixed, y: Fixed) -> i128 {
    let (x, y) = (i128::from(x.to_bits()), i128::from(y.to_bits()));
    x * x + y * y
}

#[test]
fn dist2_up_is_the_ceiling() {
    for (x, y) in [(0.0, 0.0), (3.0, 4.0), (1e-9, 0.0), (-2.5e-5, 7e-6), (9999.123, -8765.4321)] {
        let d = Fixed::dist2_up(f(x), f(y));
        let exact = exact_sq(f(x), f(y));
        let raw = i128::from(d.to_bits()) << 32;
        assert!(raw >= exact && raw - exact < 1 << 32, "{x} {y}");
    }
    // The plain product rounds down: near zero its square root is far too small.
    let tiny = Fixed::from_bits(40_000);
    assert_eq!((tiny * tiny).sqrt(), Fixed::ZERO);
    assert!(Fixed::dist2_up(tiny, Fixed::ZERO).sqrt().to_bits() >= 40_000 - 1);
    assert_eq!(Fixed::dist2_up(Fixed::MAX, Fixed::MAX), Fixed::MAX);
}

#[test]
fn seg_dist2_up_never_falls_below_the_exact_distance() {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = |scale: f64| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * scale
    };
    let mut tight = 0;
    for case in 0..20_000 {
        // Long and very short edges, points near and far, up to the supported range.
        let scale = [10_000.0, 100.0, 1e-3, 1e-7][case % 4];
        let a = Point::new(f(5000.0 + next(10_000.0)), f(5000.0 + next(10_000.0)));
        let b = Point::new(a.x + f(next(scale)), a.y + f(next(scale)));
        let p = Point::new(a.x + f(next(2.0 * scale)), a.y + f(next(2.0 * scale)));
        let up = Fixed::seg_dist2_up(p, a, b).to_f64();
        // The exact squared distance, from the exact (f64) coordinates, in f64.
        let g = |q: Point<Fixed>| (q.x.to_f64(), q.y.to_f64());
        let ((px, py), (ax, ay), (bx, by)) = (g(p), g(a), g(b));
        let (ex, ey) = (bx - ax, by - ay);
        let len2 = ex * ex + ey * ey;
        let t = if len2 > 0.0 {
            (((px - ax) * ex + (py - ay) * ey) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let (dx, dy) = (px - ax - t * ex, py - ay - t * ey);
        let exact = dx * dx + dy * dy;
        assert!(up >= exact * (1.0 - 1e-12), "case {case}: {up} < {exact}");
        if up <= exact * (1.0 + 1e-6) + 1e-8 {
            tight += 1;
        }
    }
    assert!(tight > 19_000, "the bound is loose: {tight}");
    // Beyond the range it is simply the largest value.
    let far = Point::new(Fixed::MAX, Fixed::MAX);
    let o = Point::new(Fixed::MIN, Fixed::MIN);
    assert_eq!(Fixed::seg_dist2_up(far, o, o), Fixed::MAX);
}

#[test]
fn grid_steps_cover_and_halve_exactly() {
    for (w, n) in [(200.0, 16), (123.456_789, 16), (9_876.543_21, 13), (0.02, 1), (10_000.0, 16)] {
        let step = f(w).grid_step(n, 23);
        assert!(step.to_bits() % (1 << 23) == 0, "{w}");
        assert!(i128::from(step.to_bits()) * i128::from(n) >= i128::from(f(w).to_bits()), "{w}");
        assert!(step.to_f64() * f64::from(n) - w < f64::from(n) * 2.0f64.powi(-9), "{w}");
        let mut s = step;
        for _ in 0..23 {
            let h = s.half();
            assert_eq!(h + h, s);
            s = h;
        }
    }
    // A step that is already exact stays.
    assert_eq!(f(200.0).grid_step(16, 23), f(12.5));
    assert_eq!(200.0f64.grid_step(16, 23), 12.5);
}

/// No product or quotient saturates in fills at the largest supported size: every kind,
/// in every kind of region 10,000 mm across, with and without a gap, with both samplers.
/// (Before, a circle's distance to a polygon's edge squared a cross product of up to
/// 10^8 mm², and it saturated.) The counter itself is seen to count above.
#[test]
fn nothing_saturates_within_the_supported_range() {
    use crate::{
        cells_for, index_words, rng_from_seed, CellSampler, Engine, Params, Placed, Point, PolygonRegion, Region, ShapeKind, Stop, Storage,
    };
    extern crate std;
    use std::vec;
    let hex: std::vec::Vec<Point<f64>> = (0..6)
        .map(|k| {
            let t = f64::from(k) * core::f64::consts::FRAC_PI_3 + 0.1;
            Point::new(5000.0 + 5000.0 * libm::cos(t), 5000.0 + 5000.0 * libm::sin(t))
        })
        .collect();
    let ends = [6];
    let poly = PolygonRegion::new(&hex, &ends).unwrap();
    let regions = [
        Region::Rect {
            width: 10_000.0,
            height: 10_000.0,
            periodic: false,
        },
        Region::Rect {
            width: 10_000.0,
            height: 7_777.7,
            periodic: true,
        },
        Region::Circle { radius: 5_000.0 },
        Region::Annulus {
            outer: 5_000.0,
            inner: 1_500.0,
        },
        Region::Polygon(poly),
    ];
    let kinds = [
        ShapeKind::Circle,
        ShapeKind::Square,
        ShapeKind::Rect { aspect: 3.0 },
        ShapeKind::Triangle,
        ShapeKind::Polygon { sides: 7 },
        ShapeKind::Star { points: 5, inner: 0.45 },
        ShapeKind::Ring { inner: 0.5 },
        ShapeKind::Blob { delta: 0.2 },
    ];
    tally::take();
    let n = 40;
    for (ri, region) in regions.iter().enumerate() {
        for (ki, &kind) in kinds.iter().enumerate() {
            for (gap, fast) in [(0.0, false), (0.0, true), (20.0, true)] {
                let mut shapes = vec![Placed::<Fixed>::default(); n];
                let mut index = vec![0u32; index_words(n)];
                let mut coverage = vec![0u64; if fast { 0 } else { 4096 }];
                let mut params = Params::circles(1.2, 3.0);
                params.shape = kind.into();
                params.rotate = true;
                params.gap = gap;
                params.max_trials = 100_000;
                let storage = Storage {
                    shapes: &mut shapes,
                    index: &mut index,
                    coverage: &mut coverage,
                };
                let mut e = Engine::<Fixed>::new(params, *region, storage).unwrap();
                let mut rng = rng_from_seed(ri as u64 * 10 + ki as u64);
                let stop = Stop {
                    count: Some(n as u64),
                    ..Stop::default()
                };
                if fast {
                    let mut pool = vec![[0u64; 4]; cells_for(n)];
                    let mut cells = CellSampler::new(&mut pool).unwrap();
                    e.run_fast(&mut cells, &mut rng, &stop, |_| {});
                } else {
                    e.run(&mut rng, &stop, |_| {});
                }
                assert!(e.placed().len() >= 10, "{kind:?} in region {ri}: {}", e.placed().len());
                assert_eq!(
                    tally::take(),
                    0,
                    "{kind:?} in region {ri}, gap {gap}, cells {fast}: a value saturated"
                );
            }
        }
    }
}

/// Every vertex of every polygon drawn on fixed point lies within its bounding radius, from
/// 5 µm to 9 m, at 2,000 angles: the exact tests skip a pair whose bounding circles are
/// apart. (Before, vertices lay up to 4e-9 of the scale outside, 2e-5 mm for a 5 m
/// polygon: two drawn that way, vertex to vertex, could overlap unseen.)
#[test]
fn polygons_lie_within_their_bounding_radius() {
    use crate::ShapeKind;
    let kinds = [
        ShapeKind::Square,
        ShapeKind::Rect { aspect: 2.5 },
        ShapeKind::Rect { aspect: 0.1 },
        ShapeKind::Triangle,
        ShapeKind::Polygon { sides: 7 },
        ShapeKind::Polygon { sides: 32 },
        ShapeKind::Star { points: 5, inner: 0.45 },
        ShapeKind::Star { points: 16, inner: 0.9 },
        ShapeKind::Blob { delta: 0.2 },
    ];
    let c = Point::new(f(4321.123), f(1234.567));
    for kind in kinds {
        for scale in [0.005, 0.05, 1.0, 37.3, 700.0, 5000.0, 9000.0] {
            let s = f(scale);
            let r = i128::from(kind.bounding_radius(s).to_bits());
            for i in 0..2000 {
                let angle = f(f64::from(i) * 0.003_141 + 0.000_1);
                for v in kind.geo(c, s, angle).vertices() {
                    // Exactly, in integers.
                    let (dx, dy) = (i128::from((v.x - c.x).to_bits()), i128::from((v.y - c.y).to_bits()));
                    assert!(dx * dx + dy * dy <= r * r, "{kind:?} at {scale} mm, angle {i}");
                }
            }
        }
    }
}
