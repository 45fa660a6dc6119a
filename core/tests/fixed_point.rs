//! The fixed-point scalar at the edges of its range (the issue "Hardening").
//!
//! What it cannot compute exactly is refused: a region beyond `Fixed::MAX_EXTENT` (before,
//! squares in a 500 m square overlapped by tens of metres) and a shape narrower than
//! `Fixed::MIN_SIZE`. Inside the range its fills are exact: with large shapes in a 10,000 mm
//! region, both samplers, every pair of shapes keeps clear and every shape stays in its region,
//! checked against geometry written here in f64 (the fixed-point coordinates convert exactly).
//! And the cell sampler halts with certainty only where nothing fits: before, its bounds on the
//! clearance fell far below the truth for large polygons (a squared cross product saturated),
//! and it gave up on triangles at placement 9 that the reference sampler places to 2,000.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use zetafill::line::{Engine as LineEngine, Interval, Params as LineParams, Segment, Storage as LineStorage};
use zetafill::{
    cells_for, check_largest, check_smallest, rng_from_seed, AreaSequence, CellSampler, Engine, Fixed, Geo, ParamError, Params, Placed,
    Point, PolygonRegion, Region, Scalar, ShapeKind, StepError, Stop, StopReason,
};

// ---------------------------------------------------------------------------------------------
// Independent geometry in f64.

/// A placed shape in f64: a polygon keeps the centre it is star-shaped about.
#[derive(Debug, Clone)]
enum G {
    Circle([f64; 2], f64),
    Ring([f64; 2], f64, f64),
    Poly([f64; 2], Vec<[f64; 2]>),
}

/// Overlaps smaller than this (mm) count as touching.
const EPS: f64 = 1e-9;

fn to_g(g: &Geo<Fixed>, centre: [f64; 2]) -> G {
    let p = |q: &Point<Fixed>| [q.x.to_f64(), q.y.to_f64()];
    match g {
        Geo::Circle { c, r } => G::Circle(p(c), r.to_f64()),
        Geo::Ring { c, r, inner } => G::Ring(p(c), r.to_f64(), inner.to_f64()),
        Geo::Poly { v, .. } => G::Poly(centre, v.iter().map(p).collect()),
        Geo::Motif { .. } => panic!("these fills have no motifs (core/tests/motifs.rs checks them)"),
    }
}

fn shift(g: &G, dx: f64, dy: f64) -> G {
    let m = |p: &[f64; 2]| [p[0] + dx, p[1] + dy];
    match g {
        G::Circle(c, r) => G::Circle(m(c), *r),
        G::Ring(c, r, i) => G::Ring(m(c), *r, *i),
        G::Poly(c, v) => G::Poly(m(c), v.iter().map(m).collect()),
    }
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

fn seg_dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
    let len2 = ex * ex + ey * ey;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(p, [a[0] + t * ex, a[1] + t * ey])
}

fn edges(v: &[[f64; 2]]) -> impl Iterator<Item = ([f64; 2], [f64; 2])> + '_ {
    (0..v.len()).map(move |i| (v[i], v[(i + 1) % v.len()]))
}

fn in_poly(p: [f64; 2], v: &[[f64; 2]]) -> bool {
    let mut inside = false;
    for (a, b) in edges(v) {
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            inside = !inside;
        }
    }
    inside
}

fn boundary_dist(p: [f64; 2], v: &[[f64; 2]]) -> f64 {
    edges(v).map(|(a, b)| seg_dist(p, a, b)).fold(f64::INFINITY, f64::min)
}

/// The triangles of a polygon's fan about its centre (every shape's polygon is star-shaped
/// about its centre, so they cover it exactly).
fn fan(c: [f64; 2], v: &[[f64; 2]]) -> Vec<[[f64; 2]; 3]> {
    edges(v).map(|(a, b)| [c, a, b]).collect()
}

/// The separating-axis gap of two triangles: positive when they are apart, minus their
/// penetration when they overlap.
fn sat_gap(a: &[[f64; 2]; 3], b: &[[f64; 2]; 3]) -> f64 {
    let mut best = f64::NEG_INFINITY;
    for tri in [a, b] {
        for (p, q) in edges(tri) {
            let (nx, ny) = (q[1] - p[1], p[0] - q[0]);
            let len = nx.hypot(ny);
            if len == 0.0 {
                continue;
            }
            let proj = |t: &[[f64; 2]; 3]| {
                t.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |m, v| {
                    let d = (v[0] * nx + v[1] * ny) / len;
                    (m.0.min(d), m.1.max(d))
                })
            };
            let ((a0, a1), (b0, b1)) = (proj(a), proj(b));
            best = best.max((b0 - a1).max(a0 - b1));
        }
    }
    best
}

/// The distance from `p` to a triangle (0 inside).
fn tri_dist(p: [f64; 2], t: &[[f64; 2]; 3]) -> f64 {
    if in_poly(p, t) {
        0.0
    } else {
        boundary_dist(p, t)
    }
}

/// The largest distance from `c` to a point of `g`.
fn reach(g: &G, c: [f64; 2]) -> f64 {
    match g {
        G::Circle(o, r) | G::Ring(o, r, _) => dist(*o, c) + r,
        G::Poly(_, v) => v.iter().map(|&p| dist(p, c)).fold(0.0, f64::max),
    }
}

/// Whether the materials of `a` and `b` overlap by more than `EPS` (a shape in a ring's hole
/// does not overlap the ring).
fn overlap(a: &G, b: &G) -> bool {
    match (a, b) {
        (G::Ring(c, r, i), other) | (other, G::Ring(c, r, i)) => {
            if reach(other, *c) <= i + EPS {
                return false;
            }
            if let G::Ring(c2, r2, i2) = other {
                if dist(*c, *c2) + r <= i2 + EPS {
                    return false;
                }
                return overlap(&G::Circle(*c, *r), &G::Circle(*c2, *r2));
            }
            overlap(&G::Circle(*c, *r), other)
        }
        (G::Circle(c1, r1), G::Circle(c2, r2)) => dist(*c1, *c2) < r1 + r2 - EPS,
        (G::Circle(c, r), G::Poly(o, v)) | (G::Poly(o, v), G::Circle(c, r)) => fan(*o, v).iter().any(|t| tri_dist(*c, t) < r - EPS),
        (G::Poly(oa, va), G::Poly(ob, vb)) => {
            let tb = fan(*ob, vb);
            fan(*oa, va).iter().any(|ta| tb.iter().any(|t| sat_gap(ta, t) < -EPS))
        }
    }
}

/// The points of a shape's outline to test against a region.
fn outline(g: &G) -> Vec<[f64; 2]> {
    match g {
        G::Circle(c, r) | G::Ring(c, r, _) => (0..64)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 64.0;
                [c[0] + r * t.cos(), c[1] + r * t.sin()]
            })
            .collect(),
        G::Poly(_, v) => v.clone(),
    }
}

fn centre_of(g: &G) -> [f64; 2] {
    match g {
        G::Circle(c, _) | G::Ring(c, _, _) | G::Poly(c, _) => *c,
    }
}

/// Every shape inside the region (its bounds in a rectangle, its reach in a disc, its
/// vertices or its disc in a convex polygon), and no two shapes (nor periodic images)
/// overlapping. Returns the first fault.
fn check(geos: &[G], region: &Region<'_>) -> Result<(), String> {
    let (w, h) = region.extent();
    let shifts: Vec<(f64, f64)> = if region.periodic() {
        (-1..=1).flat_map(|i| (-1..=1).map(move |j| (i as f64 * w, j as f64 * h))).collect()
    } else {
        vec![(0.0, 0.0)]
    };
    let bound: Vec<([f64; 2], f64)> = geos.iter().map(|g| (centre_of(g), reach(g, centre_of(g)))).collect();
    for (i, a) in geos.iter().enumerate() {
        for (j, b) in geos.iter().enumerate().skip(i) {
            for &(dx, dy) in &shifts {
                if i == j && dx == 0.0 && dy == 0.0 {
                    continue;
                }
                let (ca, ra) = bound[i];
                let (cb, rb) = bound[j];
                if dist(ca, [cb[0] + dx, cb[1] + dy]) > ra + rb + 1e-6 {
                    continue;
                }
                if overlap(a, &shift(b, dx, dy)) {
                    return Err(format!("shapes {i} and {j} (shifted by {dx}, {dy}) overlap: {a:?} {b:?}"));
                }
            }
        }
        let out = match (*region, a) {
            (Region::Rect { periodic: true, .. } | Region::Wallpaper(_), _) => None,
            (Region::Rect { width, height, .. }, _) => outline(a)
                .into_iter()
                .find(|p| p[0] < -EPS || p[1] < -EPS || p[0] > width + EPS || p[1] > height + EPS),
            (Region::Circle { radius }, _) => (reach(a, [radius, radius]) > radius + EPS).then(|| centre_of(a)),
            (Region::Polygon(p), G::Circle(c, r) | G::Ring(c, r, _)) => {
                let v: Vec<[f64; 2]> = p.points().iter().map(|q| [q.x, q.y]).collect();
                (!in_poly(*c, &v) || boundary_dist(*c, &v) < r - EPS).then_some(*c)
            }
            (Region::Polygon(p), G::Poly(_, va)) => {
                let v: Vec<[f64; 2]> = p.points().iter().map(|q| [q.x, q.y]).collect();
                va.iter().copied().find(|&q| !in_poly(q, &v) && boundary_dist(q, &v) > EPS)
            }
            (Region::Annulus { .. }, _) => None,
        };
        if let Some(p) = out {
            return Err(format!("shape {i} leaves the region near {p:?}: {a:?}"));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Fills.

/// A fill on fixed point: the reference sampler (with its coverage bitmap) or the cell
/// sampler. Returns the shapes as f64 geometry and why the fill stopped.
fn fill(kind: ShapeKind, region: Region<'_>, c: f64, n_offset: f64, count: u64, seed: u64, fast: bool) -> (Vec<G>, StopReason) {
    let cap = count as usize + 1;
    let mut b = common::Buffers::<Fixed>::new(cap);
    let mut coverage = vec![0u64; if fast { 0 } else { 1 << 14 }];
    let params = Params {
        c,
        n_offset,
        shape: kind.into(),
        rotate: kind.rotates(),
        gap: 0.0,
        max_trials: 10_000_000,
    };
    let mut e = Engine::<Fixed>::new(params, region, b.storage(&mut coverage)).expect("a valid fill");
    let mut rng = rng_from_seed(seed);
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    let reason = if fast {
        let mut pool = vec![[0u64; 4]; cells_for(cap)];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        e.run_fast(&mut cells, &mut rng, &stop, |_| {})
    } else {
        e.run(&mut rng, &stop, |_| {})
    };
    let geos = e
        .placed()
        .iter()
        .enumerate()
        .map(|(i, p)| to_g(&e.geo(i).expect("placed"), [p.x.to_f64(), p.y.to_f64()]))
        .collect();
    (geos, reason)
}

/// A hexagon of radius 5,000 mm about (5,000, 5,000): long edges, whose distances square
/// cross products of 10^7 mm².
fn hexagon() -> Vec<Point<f64>> {
    (0..6)
        .map(|k| {
            let t = k as f64 * std::f64::consts::FRAC_PI_3 + 0.1;
            Point::new(5000.0 + 5000.0 * t.cos(), 5000.0 + 5000.0 * t.sin())
        })
        .collect()
}

/// The fixed-point clearance tests stay exact at the largest supported size: shapes up to
/// 8% of a 10,000 mm region (a first square 2.8 m a side; c = 1.25, N = 3), in a rectangle, a
/// torus, a disc and a hexagon, with both samplers; every pair and every shape's place in its region is
/// checked in f64. (Before, a circle's distance to a polygon's edge squared a cross product
/// of up to 10^8 mm² and saturated: conservative, so no overlap, but every circle more than
/// about 20 mm from a large polygon's edge was refused.)
#[test]
fn large_shapes_keep_clear_on_fixed_point() {
    let hex = hexagon();
    let ends = [hex.len()];
    let poly = PolygonRegion::new(&hex, &ends).expect("a hexagon");
    let regions = [
        Region::Rect {
            width: 10_000.0,
            height: 10_000.0,
            periodic: false,
        },
        Region::Rect {
            width: 10_000.0,
            height: 7_500.0,
            periodic: true,
        },
        Region::Circle { radius: 5_000.0 },
        Region::Polygon(poly),
    ];
    // Stars pack slowly: fewer of them, at a lower c.
    let kinds = [
        (ShapeKind::Circle, 1.25, 150),
        (ShapeKind::Square, 1.25, 150),
        (ShapeKind::Triangle, 1.25, 150),
        (ShapeKind::Star { points: 5, inner: 0.45 }, 1.2, 80),
        (ShapeKind::Ring { inner: 0.5 }, 1.25, 150),
        (ShapeKind::Blob { delta: 0.2 }, 1.25, 100),
        (
            ShapeKind::Noisy {
                amplitude: 0.3,
                features: 6,
                octaves: 1,
            },
            1.25,
            100,
        ),
    ];
    let mut checked = 0;
    for (ri, region) in regions.iter().enumerate() {
        for (ki, &(kind, c, count)) in kinds.iter().enumerate() {
            for fast in [false, true] {
                let seed = 100 + 10 * ri as u64 + ki as u64;
                let (geos, reason) = fill(kind, *region, c, 3.0, count, seed, fast);
                let what = format!("{kind:?} in region {ri}, {} sampler", if fast { "cell" } else { "reference" });
                assert_eq!(reason, StopReason::Count, "{what}: {} shapes", geos.len());
                check(&geos, region).unwrap_or_else(|e| panic!("{what}: {e}"));
                checked += geos.len();
            }
        }
    }
    assert_eq!(checked, 8 * (4 * 150 + 80 + 100 + 100));
}

/// The checker above finds an overlap (along an edge, at a corner, of crossing bars with no
/// vertex inside the other), a shape left outside, and a shape in a ring's hole that crosses
/// its inner circle; it accepts shapes that touch.
#[test]
fn the_checker_can_fail() {
    let rect = Region::Rect {
        width: 100.0,
        height: 100.0,
        periodic: false,
    };
    let poly = |v: &[[f64; 2]]| {
        let n = v.len() as f64;
        G::Poly(
            [v.iter().map(|p| p[0]).sum::<f64>() / n, v.iter().map(|p| p[1]).sum::<f64>() / n],
            v.to_vec(),
        )
    };
    let sq = |x: f64, y: f64, s: f64| poly(&[[x - s, y - s], [x + s, y - s], [x + s, y + s], [x - s, y + s]]);
    assert!(check(&[sq(20.0, 20.0, 10.0), sq(40.0, 20.0, 10.0)], &rect).is_ok());
    assert!(check(&[sq(20.0, 20.0, 10.0), sq(39.99, 20.0, 10.0)], &rect).is_err());
    assert!(check(&[sq(20.0, 20.0, 10.0), sq(39.99, 39.99, 10.0)], &rect).is_err());
    assert!(check(&[sq(20.0, 20.0, 10.0), G::Circle([35.0, 35.0], 7.2)], &rect).is_err());
    assert!(check(&[sq(20.0, 20.0, 10.0), G::Circle([35.0, 20.0], 5.0)], &rect).is_ok());
    assert!(check(&[sq(5.0, 50.0, 6.0)], &rect).is_err());
    let ring = G::Ring([50.0, 50.0], 30.0, 15.0);
    assert!(check(&[ring.clone(), G::Circle([50.0, 50.0], 10.0)], &rect).is_ok());
    assert!(check(&[ring.clone(), sq(50.0, 50.0, 10.0)], &rect).is_ok());
    assert!(check(&[ring, G::Circle([55.0, 50.0], 12.0)], &rect).is_err());
    let a = poly(&[[10.0, 49.0], [90.0, 49.0], [90.0, 51.0], [10.0, 51.0]]);
    let b = poly(&[[49.0, 10.0], [51.0, 10.0], [51.0, 90.0], [49.0, 90.0]]);
    assert!(check(&[a, b], &rect).is_err());
}

/// The second case: the cell sampler on fixed point halted at placement 9 (of 2,000
/// triangles in a 5,000 mm square, c = 1.3, N = 2, seed 67), a halt it reports as certain,
/// and at 27 for squares in a 10,000 mm square; the reference sampler places all 2,000. Both
/// samplers must place all 2,000, without overlap.
#[test]
fn the_cell_sampler_places_what_the_reference_places_on_fixed_point() {
    let cases = [(ShapeKind::Triangle, 5_000.0, 67), (ShapeKind::Square, 10_000.0, 67)];
    for (kind, side, seed) in cases {
        let region = Region::Rect {
            width: side,
            height: side,
            periodic: false,
        };
        for fast in [true, false] {
            let (geos, reason) = fill(kind, region, 1.3, 2.0, 2000, seed, fast);
            let what = format!(
                "{kind:?} in {side} mm, seed {seed}, {} sampler",
                if fast { "cell" } else { "reference" }
            );
            assert_eq!(reason, StopReason::Count, "{what}: stopped after {} shapes", geos.len());
            check(&geos, &region).unwrap_or_else(|e| panic!("{what}: {e}"));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// What fixed point cannot compute is refused.

/// Regions beyond 10,000 mm a side, or farther than that from the origin, are refused by
/// both engines on fixed point; f64 has no limit.
#[test]
fn regions_beyond_the_fixed_range_are_refused() {
    let new = |region: Region<'_>| -> Result<(), ParamError> {
        let mut b = common::Buffers::<Fixed>::new(10);
        Engine::<Fixed>::new(Params::circles(1.3, 2.0), region, b.storage(&mut [])).map(|_| ())
    };
    let rect = |w: f64, h: f64| Region::Rect {
        width: w,
        height: h,
        periodic: false,
    };
    let too_large = Err(ParamError::Extent);
    assert_eq!(Fixed::MAX_EXTENT, 10_000.0);
    assert_eq!(new(rect(500_000.0, 500_000.0)), too_large);
    assert_eq!(new(rect(10_000.001, 100.0)), too_large);
    assert_eq!(new(Region::Circle { radius: 5_000.001 }), too_large);
    assert_eq!(new(rect(10_000.0, 10_000.0)), Ok(()));
    assert_eq!(new(Region::Circle { radius: 5_000.0 }), Ok(()));
    // A small outline far from the origin.
    let far: Vec<Point<f64>> = [(20_000.0, 0.0), (20_100.0, 0.0), (20_100.0, 100.0)]
        .iter()
        .map(|&(x, y)| Point::new(x, y))
        .collect();
    let ends = [3];
    assert_eq!(
        new(Region::Polygon(PolygonRegion::new(&far, &ends).expect("a triangle"))),
        too_large
    );
    // f64 takes them all.
    let mut b = common::Buffers::<f64>::new(10);
    assert!(Engine::<f64>::new(Params::circles(1.3, 2.0), rect(500_000.0, 500_000.0), b.storage(&mut [])).is_ok());
    // The 1D engine: an interval of at most 10,000 mm.
    let mut segs = [Segment::<Fixed>::default(); 4];
    let mut index = [0u32; 64];
    let line = |length: f64, segs: &mut [Segment<Fixed>], index: &mut [u32]| {
        let storage = LineStorage { segments: segs, index };
        LineEngine::<Fixed>::new(LineParams::new(1.3, 2.0), Interval { length, periodic: false }, storage).map(|_| ())
    };
    assert_eq!(line(20_000.0, &mut segs, &mut index), too_large);
    assert_eq!(line(10_000.0, &mut segs, &mut index), Ok(()));
}

/// Shapes narrower than 10 µm are refused before a run (`check_smallest`, which names the
/// first one the stop conditions reach) and by the engine itself, which stops there; f64 has
/// no limit.
#[test]
fn shapes_below_the_fixed_resolution_are_refused() {
    // Circles in a 1 mm square fall below 10 µm wide at about placement 500.
    let region = Region::Rect {
        width: 1.0,
        height: 1.0,
        periodic: false,
    };
    let seq = AreaSequence::new(1.0, 1.3, 1.0).expect("a sequence");
    let circles = ShapeKind::Circle.into();
    let width = |i: u64| ShapeKind::Circle.min_width(ShapeKind::Circle.scale_for_area(seq.area(i)));
    let stop = |count: Option<u64>, fill: Option<f64>, min_size: Option<f64>| Stop { count, fill, min_size };
    let err = check_smallest::<Fixed>(&seq, &circles, &stop(Some(2000), None, None), 4000, &region).expect_err("too small");
    let first = err.index;
    assert!(width(first) < 0.01 && width(first - 1) >= 0.01, "{err:?}");
    assert_eq!((err.width, err.limit), (width(first), 0.01));
    // Stops (or storage) that end the run before it are fine.
    for (ok, capacity) in [
        (stop(Some(first), None, None), 4000),
        (stop(Some(2000), None, Some(0.01)), 4000),
        (stop(None, Some(seq.covered(first)), None), 4000),
        (stop(Some(2000), None, None), first),
    ] {
        assert_eq!(check_smallest::<Fixed>(&seq, &circles, &ok, capacity, &region), Ok(()), "{ok:?}");
    }
    assert!(check_smallest::<Fixed>(&seq, &circles, &stop(None, None, Some(0.009)), 4000, &region).is_err());
    assert_eq!(
        check_smallest::<f64>(&seq, &circles, &stop(Some(2000), None, None), 4000, &region),
        Ok(())
    );
    // A mix: the first shape of either kind that is too narrow (a ring's band is a fifth of
    // its radius, narrower than a circle of its area).
    let mix = zetafill::ShapeList::mix(&[ShapeKind::Circle, ShapeKind::Ring { inner: 0.8 }], zetafill::MixOrder::Cycle, 0).expect("a mix");
    let err = check_smallest::<Fixed>(&seq, &mix, &stop(Some(2000), None, None), 4000, &region).expect_err("too small");
    assert!(err.index < first && err.index % 2 == 1, "{err:?}");

    // The engine stops at the same shape, every shape placed before it at least 10 µm wide.
    let mut b = common::Buffers::<Fixed>::new(2000);
    let mut e = Engine::<Fixed>::new(Params::circles(1.3, 1.0), region, b.storage(&mut [])).expect("valid");
    let reason = e.run(&mut rng_from_seed(3), &stop(Some(2000), None, None), |_| {});
    match reason {
        StopReason::Step(StepError::TooSmall { index }) => assert_eq!(index, first),
        // A fill this small may halt earlier; it must not get past the limit.
        StopReason::Step(StepError::Halted { index, .. }) => assert!(index <= first),
        other => panic!("{other:?}"),
    }
    assert!(e.placed().iter().all(|p: &Placed<Fixed>| 2.0 * p.scale.to_f64() >= 0.01));
    // f64 goes on.
    let mut b = common::Buffers::<f64>::new(2000);
    let mut e = Engine::<f64>::new(Params::circles(1.3, 1.0), region, b.storage(&mut [])).expect("valid");
    let reason = e.run(&mut rng_from_seed(3), &stop(Some(first + 20), None, None), |_| {});
    assert!(!matches!(reason, StopReason::Step(StepError::TooSmall { .. })), "{reason:?}");
    // The 1D engine stops at its first segment shorter than 10 µm.
    let mut segs = vec![Segment::<Fixed>::default(); 4000];
    let mut index = vec![0u32; zetafill::line::index_words(4000)];
    let storage = LineStorage {
        segments: &mut segs,
        index: &mut index,
    };
    let mut line = LineEngine::<Fixed>::new(
        LineParams::new(1.3, 1.0),
        Interval {
            length: 1.0,
            periodic: false,
        },
        storage,
    )
    .expect("valid");
    let reason = line.run(&mut rng_from_seed(3), &stop(Some(4000), None, None), |_| {});
    let StopReason::Step(StepError::TooSmall { index }) = reason else {
        panic!("{reason:?}")
    };
    assert!(line.length_of(index) < 0.01 && line.length_of(index - 1) >= 0.01);
}

/// Fuzz seed `engine_fixed` (core/proptest-regressions/fuzz/engine_fixed.txt): on a
/// 10,000 mm torus at c = 1.05, N = 2, the mix [circle, rect of aspect 1e-4, circle] makes
/// shape 1 a bar 127,000 mm long and 12 mm wide. Its squared lengths saturate on fixed point,
/// and the reference sampler placed it across the first disc's image four periods away. A
/// shape wider than `Fixed::MAX_EXTENT` is now refused before the run (`check_largest`) and
/// by the engine, which stops there with every shape before it placed.
#[test]
fn fixed_bar_longer_than_the_torus_crossed_a_disc_image() {
    let region = Region::Rect {
        width: 10_000.0,
        height: 10_000.0,
        periodic: true,
    };
    let kinds = [ShapeKind::Circle, ShapeKind::Rect { aspect: 1e-4 }, ShapeKind::Circle];
    let mix = zetafill::ShapeList::mix(&kinds, zetafill::MixOrder::Cycle, 0).expect("a mix");
    let params = Params {
        c: 1.05,
        n_offset: 2.0,
        shape: mix.clone(),
        rotate: true,
        gap: 0.0,
        max_trials: 7,
    };
    let seq = AreaSequence::new(1e8, 1.05, 2.0).expect("a sequence");
    let stop = Stop {
        count: Some(2),
        min_size: Some(0.01),
        ..Stop::default()
    };
    let err = check_largest::<Fixed>(&seq, &mix, &stop, 2).expect_err("too large");
    assert_eq!((err.index, err.limit), (1, 10_000.0), "{err:?}");
    assert!(err.width > 120_000.0, "{err:?}");
    assert_eq!(check_largest::<Fixed>(&seq, &mix, &Stop { count: Some(1), ..stop }, 2), Ok(()));
    assert_eq!(check_largest::<f64>(&seq, &mix, &stop, 2), Ok(()));

    let mut b = common::Buffers::<Fixed>::new(2);
    let mut e = Engine::<Fixed>::new(params.clone(), region, b.storage(&mut [])).expect("valid");
    let mut rng = rng_from_seed(1571467049953998411);
    let mut last = Ok(());
    for _ in 0..4 {
        match e.step(&mut rng) {
            Ok(_) => {}
            Err(StepError::Halted { index: 0, .. }) => continue,
            Err(err) => {
                last = Err(err);
                break;
            }
        }
    }
    assert_eq!(last, Err(StepError::TooLarge { index: 1 }));
    assert_eq!(e.placed().len(), 1);
    // A run stops there too.
    let mut b = common::Buffers::<Fixed>::new(2);
    let mut e = Engine::<Fixed>::new(
        Params {
            max_trials: 10_000,
            ..params
        },
        region,
        b.storage(&mut []),
    )
    .expect("valid");
    let reason = e.run(&mut rng_from_seed(1571467049953998411), &stop, |_| {});
    assert_eq!(reason, StopReason::Step(StepError::TooLarge { index: 1 }));
}
