//! Every shape kind against every other, and every shape in every region.
//!
//! The pair table checks `geom::separated` for each unordered pair of kinds against an
//! independent distance: both outlines sampled densely, overlap decided by point-in-material
//! tests written here. The fills check, by brute force over all pairs (and periodic images),
//! that no two shapes come within the gap, and, by sampling each outline against region
//! membership written here, that every shape lies inside its region with its gap.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use zetafill::internals::geom::separated;
use zetafill::{
    index_words, rng_from_seed, CellSampler, Engine, Geo, Params, Placed, Point, PolygonRegion, Region, ShapeKind, Stop, StopReason,
    Storage,
};

const KINDS: [ShapeKind; 9] = [
    ShapeKind::Circle,
    ShapeKind::Square,
    ShapeKind::Rect { aspect: 2.5 },
    ShapeKind::Triangle,
    ShapeKind::Polygon { sides: 6 },
    ShapeKind::Star { points: 5, inner: 0.45 },
    ShapeKind::Ring { inner: 0.6 },
    ShapeKind::Blob { delta: 0.2 },
    ShapeKind::Noisy {
        amplitude: 0.35,
        features: 5,
        octaves: 2,
    },
];

// ---------------------------------------------------------------------------------------------
// Independent geometry: outlines as point samples, and material membership.

fn outline(g: &Geo<f64>, per_edge: usize) -> Vec<Point<f64>> {
    let circle = |c: Point<f64>, r: f64, n: usize| -> Vec<Point<f64>> {
        (0..n)
            .map(|k| {
                let t = k as f64 / n as f64 * std::f64::consts::TAU;
                Point::new(c.x + r * t.cos(), c.y + r * t.sin())
            })
            .collect()
    };
    match *g {
        Geo::Circle { c, r } => circle(c, r, per_edge * 16),
        Geo::Ring { c, r, inner } => {
            let mut v = circle(c, r, per_edge * 16);
            v.extend(circle(c, inner, per_edge * 16));
            v
        }
        Geo::Poly { ref v, .. } => {
            let n = v.len();
            let mut out = Vec::new();
            for i in 0..n {
                let (a, b) = (v[i], v[(i + 1) % n]);
                for k in 0..per_edge {
                    let t = k as f64 / per_edge as f64;
                    out.push(Point::new(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t));
                }
            }
            out
        }
        Geo::Motif { m, ref f } => m.rings_at(f).flat_map(|r| outline(&poly_of(r.collect()), per_edge)).collect(),
    }
}

fn poly_of(v: Vec<Point<f64>>) -> Geo<'static, f64> {
    Geo::Poly {
        v: v.iter().copied().collect(),
        convex: false,
    }
}

fn in_polygon(p: Point<f64>, vs: &[Point<f64>]) -> bool {
    let mut inside = false;
    let n = vs.len();
    for i in 0..n {
        let (a, b) = (vs[i], vs[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}

/// Whether `p` is in the shape's material (closed).
fn in_material(p: Point<f64>, g: &Geo<f64>) -> bool {
    let d = |c: Point<f64>| ((p.x - c.x).powi(2) + (p.y - c.y).powi(2)).sqrt();
    match *g {
        Geo::Circle { c, r } => d(c) <= r,
        Geo::Ring { c, r, inner } => d(c) <= r && d(c) >= inner,
        Geo::Poly { ref v, .. } => in_polygon(p, v),
        Geo::Motif { m, ref f } => {
            m.rings_at(f)
                .filter(|_| true)
                .map(|r| in_polygon(p, &r.collect::<Vec<_>>()))
                .filter(|&h| h)
                .count()
                % 2
                == 1
        }
    }
}

/// Distance between the materials of two shapes, to the sampling resolution (0 if they
/// overlap).
fn sampled_distance(a: &Geo<f64>, b: &Geo<f64>) -> f64 {
    let (oa, ob) = (outline(a, 200), outline(b, 200));
    if oa.iter().any(|&p| in_material(p, b)) || ob.iter().any(|&p| in_material(p, a)) {
        return 0.0;
    }
    let mut best = f64::INFINITY;
    for p in &oa {
        for q in &ob {
            best = best.min((p.x - q.x).powi(2) + (p.y - q.y).powi(2));
        }
    }
    best.sqrt()
}

fn at(kind: ShapeKind, x: f64, y: f64, area: f64, angle: f64) -> Geo<'static, f64> {
    let s: f64 = kind.scale_for(area, angle);
    kind.geo(Point::new(x, y), s, angle)
}

// ---------------------------------------------------------------------------------------------
// The pair table.

#[test]
fn pair_table_every_kind_against_every_kind() {
    let mut rows = 0;
    for (i, &ka) in KINDS.iter().enumerate() {
        for &kb in &KINDS[i..] {
            for &(angle_a, angle_b) in &[(0.0, 0.0), (0.4, 1.9)] {
                let a = at(ka, 0.0, 0.0, 10.0, angle_a);
                // Overlapping: B on A's material (a ring's band, not its hole).
                let band = if let ShapeKind::Ring { .. } = ka {
                    ka.scale_for_area(10.0) * 0.8
                } else {
                    0.0
                };
                let b = at(kb, band, 0.0, 4.0, angle_b);
                assert!(!separated(&a, &b, 0.0) && !separated(&b, &a, 0.0), "{ka:?} / {kb:?} overlap missed");
                // Far apart.
                let far = at(kb, 40.0, 3.0, 4.0, angle_b);
                assert!(separated(&a, &far, 0.5) && separated(&far, &a, 0.5), "{ka:?} / {kb:?} far apart");
                // Near: the exact test agrees with the sampled distance on either side of it.
                for dy in [0.0, 1.3] {
                    let near = at(kb, 5.5, dy, 4.0, angle_b);
                    let d = sampled_distance(&a, &near);
                    if d > 0.05 {
                        for (gap, expect) in [(d * 0.9, true), (d * 1.1, false)] {
                            assert_eq!(separated(&a, &near, gap), expect, "{ka:?} / {kb:?} at gap {gap} (distance {d})");
                            assert_eq!(separated(&near, &a, gap), expect, "{kb:?} / {ka:?} symmetry at gap {gap}");
                        }
                        rows += 1;
                    } else if d == 0.0 {
                        assert!(!separated(&a, &near, 0.0), "{ka:?} / {kb:?} sampled overlap missed");
                    }
                }
            }
        }
    }
    assert!(rows >= 36, "only {rows} near configurations exercised");
}

/// Whether every point at distance `rho` from the centre of `kind` (area `area`, angle
/// `angle`), in 720 directions, lies in its material (the independent membership test).
fn disc_inside(kind: ShapeKind, area: f64, angle: f64, rho: f64) -> bool {
    let g = at(kind, 0.0, 0.0, area, angle);
    (0..720).all(|k| {
        let t = k as f64 * std::f64::consts::TAU / 720.0;
        in_material(Point::new(rho * t.cos(), rho * t.sin()), &g)
    })
}

/// The engine decides that two shapes meet, without building them, when their inscribed
/// discs (`ShapeKind::solid_radius`) come within the gap by a relative margin of 1e-6. That
/// is sound only if each disc lies inside its shape, which this checks against the
/// independent membership test over random sizes and angles; and two shapes whose centres
/// sit just inside the margin must not be `separated`. Circles, squares, rectangles and
/// regular polygons have such a disc; the check fails for discs 1% too large.
#[test]
fn inscribed_discs_lie_inside_their_shapes() {
    let mut rng = rng_from_seed(77);
    let mut unit = || zetafill::internals::rng::unit::<f64, _>(&mut rng);
    for &kind in &KINDS {
        let Some(_) = kind.solid_radius(1.0f64) else {
            assert!(
                matches!(kind, ShapeKind::Ring { .. } | ShapeKind::Star { .. }) || kind.is_blob(),
                "{kind:?} has an inscribed disc"
            );
            continue;
        };
        let mut too_big = 0;
        for _ in 0..40 {
            let (area, angle) = (0.5 + 20.0 * unit(), std::f64::consts::TAU * unit());
            let scale: f64 = kind.scale_for(area, angle);
            let solid = kind.solid_radius(scale).unwrap_or(0.0);
            assert!(
                disc_inside(kind, area, angle, solid * (1.0 - 1e-6)),
                "{kind:?} at area {area}, angle {angle}"
            );
            if !disc_inside(kind, area, angle, solid * 1.01) {
                too_big += 1;
            }
        }
        assert!(too_big > 0, "{kind:?}: a 1% larger disc is never caught");
    }
    for &ka in &KINDS {
        for &kb in &KINDS {
            for _ in 0..20 {
                let (aa, ab, ta, tb) = (1.0 + 10.0 * unit(), 1.0 + 10.0 * unit(), 6.3 * unit(), 6.3 * unit());
                let (sa, sb): (f64, f64) = (ka.scale_for(aa, ta), kb.scale_for(ab, tb));
                let (Some(ra), Some(rb)) = (ka.solid_radius(sa), kb.solid_radius(sb)) else {
                    continue;
                };
                let gap = if unit() < 0.5 { 0.0 } else { unit() };
                let d = (ra + rb + gap) * (1.0 - 1e-6) - 1e-9;
                let dir = 6.3 * unit();
                let (a, b) = (at(ka, 0.0, 0.0, aa, ta), at(kb, d * dir.cos(), d * dir.sin(), ab, tb));
                assert!(!separated(&a, &b, gap), "{ka:?} / {kb:?}: inscribed discs meet, shapes do not");
            }
        }
    }
}

#[test]
fn every_kind_nests_in_a_ring_hole() {
    let ring = at(ShapeKind::Ring { inner: 0.8 }, 0.0, 0.0, 100.0, 0.0);
    let Geo::Ring { inner, .. } = ring else { panic!("not a ring") };
    for &k in &KINDS {
        for angle in [0.0, 0.9] {
            // Scaled so that the bounding radius is 60% of the hole.
            let s = 0.6 * inner / k.bounding_radius(1.0);
            let small = k.geo(Point::new(0.1, -0.2), s, angle);
            assert!(separated(&ring, &small, 0.0) && separated(&small, &ring, 0.0), "{k:?} in the hole");
            let room = inner - small.max_dist2(Point::new(0.0, 0.0)).sqrt();
            assert!(separated(&ring, &small, room * 0.9), "{k:?} gap inside the hole");
            assert!(!separated(&ring, &small, room * 1.1), "{k:?} gap inside the hole too large");
            // Too large for the hole: it touches the band.
            let big = k.geo(Point::new(0.0, 0.0), 1.3 * inner / k.inradius(1.0).max(1e-9), angle);
            assert!(!separated(&ring, &big, 0.0), "{k:?} larger than the hole");
        }
    }
}

#[test]
fn sampled_distance_detects_overlap_and_measures_gaps() {
    // The independent measure itself: two unit circles 3 apart are 1 apart; overlapping ones 0.
    let a = Geo::Circle {
        c: Point::new(0.0, 0.0),
        r: 1.0,
    };
    let b = Geo::Circle {
        c: Point::new(3.0, 0.0),
        r: 1.0,
    };
    assert!((sampled_distance(&a, &b) - 1.0).abs() < 1e-3);
    assert_eq!(
        sampled_distance(
            &a,
            &Geo::Circle {
                c: Point::new(1.5, 0.0),
                r: 1.0
            }
        ),
        0.0
    );
}

// ---------------------------------------------------------------------------------------------
// Fills of every shape in every region.

fn region_inside(r: &Region<'_>, p: Point<f64>, pts: &[Point<f64>], ends: &[usize]) -> bool {
    match *r {
        Region::Rect { width, height, .. } => p.x >= 0.0 && p.y >= 0.0 && p.x <= width && p.y <= height,
        Region::Circle { radius } => (p.x - radius).hypot(p.y - radius) <= radius,
        Region::Annulus { outer, inner } => {
            let d = (p.x - outer).hypot(p.y - outer);
            d <= outer && d >= inner
        }
        Region::Polygon(_) => {
            let mut inside = false;
            let mut start = 0;
            for &e in ends {
                inside ^= in_polygon(p, &pts[start..e]);
                start = e;
            }
            inside
        }
        Region::Wallpaper(_) => true,
    }
}

fn point_segment(p: Point<f64>, a: Point<f64>, b: Point<f64>) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let t = (((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    (p.x - (a.x + t * dx)).hypot(p.y - (a.y + t * dy))
}

/// Distance from a point to the region's boundary, computed here analytically.
fn boundary_distance(r: &Region<'_>, p: Point<f64>, pts: &[Point<f64>], ends: &[usize]) -> f64 {
    match *r {
        Region::Rect { width, height, .. } => p.x.min(width - p.x).min(p.y).min(height - p.y).abs(),
        Region::Circle { radius } => (radius - (p.x - radius).hypot(p.y - radius)).abs(),
        Region::Annulus { outer, inner } => {
            let d = (p.x - outer).hypot(p.y - outer);
            (outer - d).abs().min((d - inner).abs())
        }
        Region::Polygon(_) => {
            let mut best = f64::INFINITY;
            let mut start = 0;
            for &e in ends {
                let ring = &pts[start..e];
                for i in 0..ring.len() {
                    best = best.min(point_segment(p, ring[i], ring[(i + 1) % ring.len()]));
                }
                start = e;
            }
            best
        }
        Region::Wallpaper(_) => f64::INFINITY,
    }
}

/// Brute-force check of a finished fill. Returns the number of shapes checked.
fn check(geos: &[Geo<f64>], region: &Region<'_>, gap: f64, pts: &[Point<f64>], ends: &[usize]) -> Result<usize, String> {
    let periodic = region.periodic();
    let (w, h) = region.extent();
    let shifts: Vec<(f64, f64)> = if periodic {
        (-2..=2).flat_map(|i| (-2..=2).map(move |j| (i as f64 * w, j as f64 * h))).collect()
    } else {
        vec![(0.0, 0.0)]
    };
    for (i, a) in geos.iter().enumerate() {
        for (j, b) in geos.iter().enumerate().skip(i) {
            for &(dx, dy) in &shifts {
                if i == j && dx == 0.0 && dy == 0.0 {
                    continue;
                }
                if !separated(a, &b.shift(dx, dy), gap) {
                    return Err(format!("shapes {i} and {j} (shift {dx},{dy}) closer than {gap}"));
                }
            }
        }
    }
    if !periodic {
        for (i, g) in geos.iter().enumerate() {
            for p in outline(g, 24) {
                if !region_inside(region, p, pts, ends) {
                    return Err(format!("shape {i} leaves the region at ({}, {})", p.x, p.y));
                }
                let d = boundary_distance(region, p, pts, ends);
                if d < gap * (1.0 - 1e-9) {
                    return Err(format!("shape {i} is {d} from the boundary, gap {gap}"));
                }
            }
        }
    }
    Ok(geos.len())
}

/// A fill with the reference sampler, or (`fast`) with the cell sampler over a pool of
/// `cells` cells.
fn fill_with(
    kind: ShapeKind,
    region: Region<'_>,
    gap: f64,
    count: u64,
    seed: u64,
    fast: Option<usize>,
) -> (Vec<Geo<'static, f64>>, StopReason) {
    let cap = count as usize;
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    let mut cov = vec![0u64; 1 << 12];
    let params = Params {
        c: 1.2,
        n_offset: 4.0,
        shape: kind.into(),
        rotate: true,
        gap,
        max_trials: 200_000,
    };
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut cov,
    };
    let mut e = Engine::<f64>::new(params, region, storage).unwrap_or_else(|err| panic!("{kind:?}: {err}"));
    let mut rng = rng_from_seed(seed);
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    let reason = match fast {
        None => e.run(&mut rng, &stop, |_| {}),
        Some(n) => {
            let mut pool = vec![[0u64; 4]; n];
            let mut cells = CellSampler::new(&mut pool).unwrap_or_else(|_| panic!("cells"));
            e.run_fast(&mut cells, &mut rng, &stop, |_| {})
        }
    };
    (
        (0..e.placed().len()).filter_map(|i| e.geo(i).and_then(|g| g.owned())).collect(),
        reason,
    )
}

fn fill(kind: ShapeKind, region: Region<'_>, gap: f64, count: u64, seed: u64) -> (Vec<Geo<'static, f64>>, StopReason) {
    fill_with(kind, region, gap, count, seed, None)
}

#[test]
fn every_shape_in_every_region() {
    // A star-shaped polygon with a square hole.
    let (pts, ends) = common::star_with_hole();
    let poly = PolygonRegion::new(&pts, &ends).unwrap_or_else(|e| panic!("{e}"));
    let regions = common::every_kind(poly);
    let mut total = 0;
    // The reference sampler, the cell sampler, and the cell sampler with a pool too small to
    // refine (it must stay correct).
    for fast in [None, Some(100_000), Some(6)] {
        for (ri, region) in regions.iter().enumerate() {
            for (ki, &kind) in KINDS.iter().chain(&[ShapeKind::Ring { inner: 0.75 }]).enumerate() {
                // A ring with a hole larger than its material (the cell sampler's fallback)
                // is too large for the annulus's band.
                if ki == KINDS.len() && matches!(region, Region::Annulus { .. }) {
                    continue;
                }
                for gap in [0.0, 0.8] {
                    let (geos, reason) = fill_with(kind, *region, gap, 100, 1 + ri as u64 * 10 + ki as u64, fast);
                    assert!(
                        !matches!(reason, StopReason::Step(zetafill::StepError::CannotFit { .. })),
                        "{kind:?} in region {ri}: {reason:?}"
                    );
                    assert!(
                        geos.len() >= 20,
                        "{kind:?} in region {ri} gap {gap} cells {fast:?}: only {} shapes ({reason:?})",
                        geos.len()
                    );
                    total += check(&geos, region, gap, &pts, &ends)
                        .unwrap_or_else(|e| panic!("{kind:?} in region {ri} gap {gap} cells {fast:?}: {e}"));
                }
            }
        }
    }
    assert!(total > 3 * 4500, "{total} shapes checked");
}

#[test]
fn rings_nest_in_fills() {
    let region = Region::Rect {
        width: 200.0,
        height: 200.0,
        periodic: false,
    };
    let (geos, _) = fill(ShapeKind::Ring { inner: 0.7 }, region, 0.0, 600, 5);
    let nested = geos
        .iter()
        .enumerate()
        .filter(|(i, g)| {
            let (Geo::Ring { c, .. } | Geo::Circle { c, .. }) = g else {
                return false;
            };
            geos[..*i]
                .iter()
                .any(|o| matches!(o, Geo::Ring { c: oc, inner, .. } if oc.dist2(*c).sqrt() < *inner))
        })
        .count();
    assert!(nested > 10, "only {nested} rings placed inside another ring's hole");
}

#[test]
fn the_fill_checker_can_fail() {
    let region = Region::Rect {
        width: 100.0,
        height: 100.0,
        periodic: false,
    };
    let a = Geo::Circle {
        c: Point::new(30.0, 30.0),
        r: 10.0,
    };
    let b = Geo::Circle {
        c: Point::new(45.0, 30.0),
        r: 6.0,
    };
    assert!(check(&[a.clone(), b.clone()], &region, 0.0, &[], &[]).is_err(), "overlap not found");
    assert!(check(&[a.clone(), b.shift(2.0, 0.0)], &region, 0.0, &[], &[]).is_ok());
    assert!(check(&[a, b.shift(2.0, 0.0)], &region, 1.5, &[], &[]).is_err(), "gap not enforced");
    let out = Geo::Circle {
        c: Point::new(95.0, 50.0),
        r: 6.0,
    };
    assert!(check(&[out], &region, 0.0, &[], &[]).is_err(), "outside not found");
    let near = Geo::Circle {
        c: Point::new(93.0, 50.0),
        r: 6.0,
    };
    assert!(check(std::slice::from_ref(&near), &region, 0.0, &[], &[]).is_ok());
    assert!(check(&[near], &region, 1.5, &[], &[]).is_err(), "boundary gap not enforced");
    let torus = Region::Rect {
        width: 100.0,
        height: 100.0,
        periodic: true,
    };
    let edge = Geo::Circle {
        c: Point::new(2.0, 50.0),
        r: 5.0,
    };
    let other = Geo::Circle {
        c: Point::new(97.0, 50.0),
        r: 4.0,
    };
    assert!(
        check(&[edge, other], &torus, 0.0, &[], &[]).is_err(),
        "overlap across the edge not found"
    );
}

/// Fuzz seed `engine_f64` (core/proptest-regressions/fuzz/engine_f64.txt): at c = 50 in a
/// 1 x 1.7458 torus, shape 5 of a random mix of six circles and a rectangle of aspect 1e-6 is
/// a rectangle 3e-17 wide, a fifth of an f64 ulp of its coordinates: its four vertices
/// rounded onto two points, an outline of zero area, and the engine placed it. A shape
/// narrower than 2^-40 of the region's largest coordinate is now refused before the run
/// (`check_smallest`) and by the engine, which stops there.
#[test]
fn f64_rect_narrower_than_an_ulp_was_placed_with_zero_area() {
    use zetafill::{check_smallest, AreaSequence, MixOrder, ShapeList, StepError};
    let height = 1.7458006789965368;
    let region = Region::Rect {
        width: 1.0,
        height,
        periodic: true,
    };
    let mut kinds = vec![ShapeKind::Circle; 6];
    kinds.push(ShapeKind::Rect { aspect: 1e-6 });
    let mix = ShapeList::mix(&kinds, MixOrder::Random, 17408239503747695232).expect("a mix");
    assert_eq!(mix.kind_of(5), ShapeKind::Rect { aspect: 1e-6 });
    let params = Params {
        c: 50.0,
        n_offset: 2.0,
        shape: mix.clone(),
        rotate: true,
        gap: 0.0,
        max_trials: 1,
    };
    let stop = Stop {
        count: Some(6),
        ..Stop::default()
    };
    let seq = AreaSequence::new(height, 50.0, 2.0).expect("a sequence");
    let err = check_smallest::<f64>(&seq, &mix, &stop, 6, &region).expect_err("too small");
    assert_eq!((err.index, err.limit), (5, height / 1_099_511_627_776.0), "{err:?}");
    assert!(err.width < 1e-16, "{err:?}");
    assert_eq!(
        check_smallest::<f64>(&seq, &mix, &Stop { count: Some(5), ..stop }, 6, &region),
        Ok(())
    );

    let mut shapes = vec![Placed::<f64>::default(); 6];
    let mut index = vec![0u32; index_words(6)];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut e = Engine::<f64>::new(params, region, storage).expect("valid");
    let reason = e.run(&mut rng_from_seed(15794296920101147133), &stop, |_| {});
    assert_eq!(reason, StopReason::Step(StepError::TooSmall { index: 5 }));
    assert_eq!(e.placed().len(), 5);
}
