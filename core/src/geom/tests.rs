use super::*;

fn sq(cx: f64, cy: f64, h: f64) -> Geo<'static, f64> {
    let p = |x, y| Point::new(x, y);
    let v = Verts::from_slice(&[p(cx - h, cy - h), p(cx + h, cy - h), p(cx + h, cy + h), p(cx - h, cy + h)]).unwrap();
    Geo::Poly { v, convex: true }
}

fn as_concave(g: Geo<f64>) -> Geo<f64> {
    match g {
        Geo::Poly { v, .. } => Geo::Poly { v, convex: false },
        other => other,
    }
}

/// The general polygon test without skipping anything.
fn poly_poly_all(pa: &[Point<f64>], ca: bool, pb: &[Point<f64>], cb: bool, gap: f64) -> bool {
    if pa.iter().any(|&v| in_poly(v, pb, cb)) || pb.iter().any(|&v| in_poly(v, pa, ca)) {
        return false;
    }
    !edges(pa).any(|(a1, a2)| {
        edges(pb).any(|(b1, b2)| {
            if gap <= 0.0 {
                segments_intersect(a1, a2, b1, b2)
            } else {
                seg_seg_dist2(a1, a2, b1, b2) <= gap * gap
            }
        })
    })
}

/// Skipping the vertices and edges out of reach never changes the answer: star-shaped
/// polygons of 3 to 32 vertices, placed so that their bounds overlap, with and without a
/// gap.
#[test]
fn skipping_far_edges_changes_no_answer() {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut apart, mut overlapping, mut inside) = (0, 0, 0);
    for case in 0..20_000 {
        // Every fourth case a small polygon near the other's centre: often inside it.
        let small = case % 4 == 3;
        let poly = |cx: f64, cy: f64, size: f64, next: &mut dyn FnMut() -> f64| {
            let n = 3 + (next() * 30.0) as usize;
            let mut v = [Point::default(); MAX_VERTS];
            let phase = next();
            for (k, p) in v.iter_mut().take(n).enumerate() {
                let a = (k as f64 + phase) * core::f64::consts::TAU / n as f64;
                let r = size * (0.4 + 0.6 * next());
                *p = Point::new(cx + r * libm::cos(a), cy + r * libm::sin(a));
            }
            (v, n)
        };
        let (va, na) = poly(0.0, 0.0, 1.0, &mut next);
        let d = if small { 0.3 * next() } else { 0.3 + 1.6 * next() };
        let t = next() * core::f64::consts::TAU;
        let (vb, nb) = poly(d * libm::cos(t), d * libm::sin(t), if small { 0.2 } else { 1.0 }, &mut next);
        let gap = if case % 2 == 0 { 0.0 } else { 0.2 * next() };
        let (pa, pb) = (&va[..na], &vb[..nb]);
        let got = poly_poly(pa, false, pb, false, gap);
        assert_eq!(got, poly_poly_all(pa, false, pb, false, gap), "case {case}");
        if got {
            apart += 1;
        } else {
            overlapping += 1;
        }
        if small && pb.iter().all(|&v| point_in_poly(v, pa)) {
            inside += 1;
        }
    }
    assert!(
        apart > 2000 && overlapping > 2000 && inside > 1000,
        "{apart} {overlapping} {inside}"
    );
}

#[test]
fn touching_is_not_separated() {
    let a = Geo::Circle {
        c: Point::new(0.0, 0.0),
        r: 1.0,
    };
    let b = Geo::Circle {
        c: Point::new(2.0, 0.0),
        r: 1.0,
    };
    assert!(!separated(&a, &b, 0.0));
    assert!(separated(&a, &b.shift(1e-9, 0.0), 0.0));
    for conv in [false, true] {
        let f = |g| if conv { g } else { as_concave(g) };
        assert!(!separated(&f(sq(0.0, 0.0, 1.0)), &f(sq(2.0, 0.0, 1.0)), 0.0));
        assert!(separated(&f(sq(0.0, 0.0, 1.0)), &f(sq(2.0 + 1e-9, 0.0, 1.0)), 0.0));
        assert!(!separated(&a, &f(sq(2.0, 0.0, 1.0)), 0.0));
    }
}

#[test]
fn gap_between_squares_is_exact_at_corners() {
    let d = libm::sqrt(0.5);
    for conv in [false, true] {
        let f = |g| if conv { g } else { as_concave(g) };
        let (a, b) = (f(sq(0.0, 0.0, 1.0)), f(sq(2.5, 2.5, 1.0)));
        assert!(separated(&a, &b, d - 1e-12));
        assert!(!separated(&a, &b, d + 1e-12));
    }
}

#[test]
fn containment_is_overlap() {
    let a = Geo::Circle {
        c: Point::new(0.0, 0.0),
        r: 0.1,
    };
    assert!(!separated(&a, &sq(0.0, 0.0, 1.0), 0.0));
    assert!(!separated(&sq(0.0, 0.0, 1.0), &a, 0.0));
    assert!(!separated(&as_concave(sq(0.0, 0.0, 0.1)), &as_concave(sq(0.0, 0.0, 1.0)), 0.0));
}

#[test]
fn shapes_nest_in_a_ring_hole() {
    let ring = Geo::Ring {
        c: Point::new(0.0, 0.0),
        r: 3.0,
        inner: 2.0,
    };
    let small = Geo::Circle {
        c: Point::new(0.5, 0.0),
        r: 1.0,
    };
    assert!(separated(&ring, &small, 0.0));
    assert!(separated(&small, &ring, 0.4));
    assert!(!separated(&small, &ring, 0.5));
    assert!(!separated(
        &ring,
        &Geo::Circle {
            c: Point::new(0.0, 0.0),
            r: 2.5
        },
        0.0
    ));
    assert!(separated(&ring, &sq(0.0, 0.0, 1.0), 0.0));
    assert!(!separated(&ring, &sq(0.0, 0.0, 1.5), 0.0));
    let inner_ring = Geo::Ring {
        c: Point::new(0.2, 0.0),
        r: 1.5,
        inner: 1.0,
    };
    assert!(separated(&ring, &inner_ring, 0.0));
    assert!(separated(&inner_ring, &ring, 0.0));
    assert!(!separated(
        &ring,
        &Geo::Ring {
            c: Point::new(1.0, 0.0),
            r: 1.5,
            inner: 1.0
        },
        0.0
    ));
}
