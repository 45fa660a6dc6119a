//! Motifs (the caller's own outlines): the exact test against an independent polygon library
//! (`geo`) on random pairs, with a twin that must fail; the same answers with and without the
//! edge tree; fills with a non-convex motif with a hole in every kind of region, on both
//! samplers and both scalars, checked by `geo` for overlaps and containment.

#![allow(clippy::disallowed_methods)]

mod common;

use common::Buffers;
use geo::{BooleanOps, Contains, Coord, Distance, Euclidean, Intersects, LineString, MultiPolygon, Polygon};
use zetafill::internals::geom::separated;
use zetafill::{
    rng_from_seed, CellSampler, Engine, Fixed, Frame, Geo, Group, Motif, Params, Point, PolygonRegion, Region, Scalar, ShapeKind, Stop,
    StopReason, Wallpaper,
};

/// A letter-like outline with a hole: a 'P' of 200 vertices (a stem and a bowl with a round
/// counter), non-convex.
fn letter_p() -> (Vec<Point<f64>>, Vec<usize>) {
    // Outer: stem from (0,0) to (0,10), bowl arc around (3,7) radius 3, back down at x = 2.
    let mut pts = vec![
        Point::new(0.0, 0.0),
        Point::new(2.0, 0.0),
        Point::new(2.0, 4.0),
        Point::new(3.0, 4.0),
    ];
    let n = 150;
    for k in 1..=n {
        let t = -std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * k as f64 / n as f64;
        pts.push(Point::new(3.0 + 3.0 * t.cos(), 7.0 + 3.0 * t.sin()));
    }
    pts.push(Point::new(0.0, 10.0));
    let outer = pts.len();
    // Counter: a circle of radius 1.4 about (3, 7), 44 vertices, clockwise.
    for k in 0..44 {
        let t = -(k as f64) * std::f64::consts::TAU / 44.0;
        pts.push(Point::new(3.0 + 1.4 * t.cos(), 7.0 + 1.4 * t.sin()));
    }
    let total = pts.len();
    (pts, vec![outer, total])
}

/// A comb: a non-convex outline with deep notches, 42 vertices.
fn comb() -> (Vec<Point<f64>>, Vec<usize>) {
    let mut pts = vec![Point::new(0.0, 0.0), Point::new(10.0, 0.0)];
    for k in (0..10).rev() {
        let x = k as f64;
        pts.extend([
            Point::new(x + 1.0, 6.0),
            Point::new(x + 0.5, 6.0),
            Point::new(x + 0.5, 1.0),
            Point::new(x, 1.0),
        ]);
    }
    let n = pts.len();
    (pts, vec![n])
}

struct Owned {
    points: Vec<Point<f64>>,
    ends: Vec<usize>,
    scratch: Vec<u32>,
}

impl Owned {
    fn new((points, ends): (Vec<Point<f64>>, Vec<usize>)) -> Self {
        let scratch = vec![0; Motif::scratch_words(points.len())];
        Owned { points, ends, scratch }
    }
    fn with_tree(&mut self) -> Motif<'_> {
        Motif::new_in(&mut self.points, &self.ends, &mut self.scratch).expect("a valid motif")
    }
    fn without_tree(&mut self) -> Motif<'_> {
        Motif::new(&mut self.points, &self.ends).expect("a valid motif")
    }
}

fn mp_of(g: &Geo<'_, f64>) -> MultiPolygon<f64> {
    let ring = |v: Vec<Point<f64>>| LineString::from(v.iter().map(|p| Coord { x: p.x, y: p.y }).collect::<Vec<_>>());
    let disc = |c: Point<f64>, r: f64| -> Vec<Point<f64>> {
        // Inscribed in the circle by a hair less than the tests' tolerance.
        (0..720)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 720.0;
                Point::new(c.x + r * t.cos(), c.y + r * t.sin())
            })
            .collect()
    };
    match g {
        Geo::Circle { c, r } => MultiPolygon::new(vec![Polygon::new(ring(disc(*c, *r)), vec![])]),
        Geo::Ring { c, r, inner } => MultiPolygon::new(vec![Polygon::new(ring(disc(*c, *r)), vec![ring(disc(*c, *inner))])]),
        Geo::Poly { v, .. } => MultiPolygon::new(vec![Polygon::new(ring(v.to_vec()), vec![])]),
        Geo::Motif { m, f } => {
            // Even-odd: the union of rings' interiors by symmetric difference.
            let mut acc = MultiPolygon::new(vec![]);
            for r in m.rings_at(f) {
                let p = MultiPolygon::new(vec![Polygon::new(ring(r.collect()), vec![])]);
                acc = acc.xor(&p);
            }
            acc
        }
    }
}

/// `geo`'s verdict: the materials' distance, 0 when they meet.
fn geo_distance(a: &Geo<'_, f64>, b: &Geo<'_, f64>) -> f64 {
    let (pa, pb) = (mp_of(a), mp_of(b));
    if pa.intersects(&pb) {
        return 0.0;
    }
    Euclidean.distance(&pa, &pb)
}

/// A small rng for the pairs.
struct Lcg(u64);
impl Lcg {
    fn f(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn frame(r: &mut Lcg, scale: f64, spread: f64) -> Frame<f64> {
    let a = r.f() * std::f64::consts::TAU;
    Frame::new(
        Point::new(50.0 + spread * (r.f() - 0.5), 50.0 + spread * (r.f() - 0.5)),
        scale,
        a.sin(),
        a.cos(),
    )
}

/// Random pairs of a motif and another shape near it: the core's answer, the same without a
/// tree, and `geo`'s, for pairs `geo` decides clearly (farther than 1e-6 from the gap).
/// Returns how many pairs were decided and how many of them met.
fn pairs(sep: impl Fn(&Geo<'_, f64>, &Geo<'_, f64>, f64) -> bool, n: usize) -> (usize, usize, Vec<String>) {
    let (mut p1, mut p2, mut c1, mut c2) = (
        Owned::new(letter_p()),
        Owned::new(letter_p()),
        Owned::new(comb()),
        Owned::new(comb()),
    );
    let (tp, np, tc, nc) = (p1.with_tree(), p2.without_tree(), c1.with_tree(), c2.without_tree());
    let mut r = Lcg(7);
    let (mut decided, mut met, mut wrong) = (0, 0, Vec::new());
    for i in 0..n {
        let gap = if i % 3 == 0 { 0.0 } else { 0.3 * r.f() };
        let fa = frame(&mut r, 8.0, 12.0);
        let a_tree = Geo::Motif { m: &tp, f: fa };
        let a_flat = Geo::Motif { m: &np, f: fa };
        let other_at = Point::new(50.0 + 14.0 * (r.f() - 0.5), 50.0 + 14.0 * (r.f() - 0.5));
        let sb = 2.0 + 6.0 * r.f();
        let fb = Frame {
            t: other_at,
            ..frame(&mut r, sb, 0.0)
        };
        let (b_tree, b_flat) = match i % 5 {
            0 => (
                Geo::Circle {
                    c: other_at,
                    r: 0.2 + 2.0 * r.f(),
                },
                Geo::Circle { c: other_at, r: 0.0 },
            ),
            1 => {
                let rr = 1.0 + 3.0 * r.f();
                (
                    Geo::Ring {
                        c: other_at,
                        r: rr,
                        inner: rr * 0.8,
                    },
                    Geo::Circle { c: other_at, r: 0.0 },
                )
            }
            2 => (
                ShapeKind::Star { points: 5, inner: 0.4 }.geo(other_at, 1.0 + 3.0 * r.f(), r.f()),
                Geo::Circle { c: other_at, r: 0.0 },
            ),
            3 => (Geo::Motif { m: &tc, f: fb }, Geo::Motif { m: &nc, f: fb }),
            _ => (Geo::Motif { m: &tp, f: fb }, Geo::Motif { m: &np, f: fb }),
        };
        // The twin without trees, where there is one, must agree bit for bit.
        let got = sep(&a_tree, &b_tree, gap);
        let flat_b = if matches!(b_flat, Geo::Motif { .. }) { &b_flat } else { &b_tree };
        assert_eq!(got, sep(&a_flat, flat_b, gap), "pair {i}: the tree changed the answer");
        assert_eq!(got, sep(&b_tree, &a_tree, gap), "pair {i}: not symmetric");
        let d = geo_distance(&a_tree, &b_tree);
        // Discs are polygons of 720 sides in `geo`: 1e-4 of a radius of 4 covers them.
        if (d - gap).abs() < 1e-3 || (gap == 0.0 && d < 1e-3 && d > 0.0) {
            continue;
        }
        decided += 1;
        let truth = d > gap;
        if !truth {
            met += 1;
        }
        if got != truth {
            wrong.push(format!("pair {i}: core {got}, geo distance {d} with gap {gap}"));
        }
    }
    (decided, met, wrong)
}

#[test]
fn the_exact_test_agrees_with_an_independent_polygon_library() {
    let (decided, met, wrong) = pairs(separated, 1500);
    assert!(
        wrong.is_empty(),
        "{} of {decided} pairs disagree: {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(5)]
    );
    // The pairs are a real test: many meet, many do not.
    assert!(decided > 1200 && met > 200 && decided - met > 200, "{decided} decided, {met} met");
}

#[test]
fn a_twin_that_skips_the_containment_step_fails() {
    // Without asking whether one outline holds a ring of the other, a small shape deep inside
    // a motif's material (or a motif inside a ring's material) passes.
    let twin = |a: &Geo<'_, f64>, b: &Geo<'_, f64>, gap: f64| {
        let inside = |g: &Geo<'_, f64>, q: Point<f64>| mp_of(g).contains(&geo::Point::new(q.x, q.y));
        let first = |g: &Geo<'_, f64>| match g {
            Geo::Circle { c, .. } | Geo::Ring { c, .. } => *c,
            Geo::Poly { v, .. } => v[0],
            Geo::Motif { m, f } => m.rings_at(f).next().and_then(|mut r| r.next()).unwrap_or(f.t),
        };
        let hold = inside(a, first(b)) || inside(b, first(a));
        separated(a, b, gap) || hold
    };
    let (_, _, wrong) = pairs(twin, 1500);
    assert!(!wrong.is_empty(), "the twin passed every pair: the pairs never test containment");
}

/// The heart ring of the speed benchmark: a heart with a heart-shaped hole off its centre,
/// 100 vertices each.
fn heart_ring() -> (Vec<Point<f64>>, Vec<usize>) {
    let heart = |s: f64, cx: f64, cy: f64, rev: bool| -> Vec<Point<f64>> {
        let mut v: Vec<Point<f64>> = (0..100)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 100.0;
                let x = 16.0 * t.sin().powi(3);
                let y = 13.0 * t.cos() - 5.0 * (2.0 * t).cos() - 2.0 * (3.0 * t).cos() - (4.0 * t).cos();
                Point::new(cx + s * x, cy + s * y)
            })
            .collect();
        if rev {
            v.reverse();
        }
        v
    };
    let mut pts = heart(1.5, 50.0, 52.0, false);
    pts.extend(heart(0.7, 50.0, 55.0, true));
    (pts, vec![100, 200])
}

/// Whether some disc of `a`'s inner cover, placed by `fa`, meets one of `b`'s placed by `fb`
/// within `gap` (the test's own computation, from the cover the motif reports), with every
/// radius grown by `grow`.
fn covers_meet(a: &Motif<'_>, fa: &Frame<f64>, b: &Motif<'_>, fb: &Frame<f64>, gap: f64, grow: f64) -> bool {
    a.cover().iter().any(|&(ca, ra)| {
        b.cover().iter().any(|&(cb, rb)| {
            let d = fa.apply(ca).dist2(fb.apply(cb)).sqrt();
            d < (ra * fa.norm + rb * fb.norm) * grow + gap
        })
    })
}

#[test]
fn the_inner_cover_lies_in_the_material_and_decides_pairs_the_inscribed_disc_does_not() {
    for (name, outline) in [("letter P", letter_p()), ("comb", comb()), ("heart ring", heart_ring())] {
        let mut owned = Owned::new(outline);
        let m = owned.with_tree();
        let cover = m.cover();
        assert!(cover.len() >= 8, "{name}: only {} discs", cover.len());
        assert_eq!(
            cover[0],
            (Point::new(0.0, 0.0), m.inner()),
            "{name}: the inscribed disc comes first"
        );
        // Each disc lies in the material, by geo: its centre inside, the outline no nearer
        // than its radius.
        let placed = Geo::Motif {
            m: &m,
            f: Frame::new(Point::new(0.0, 0.0), 1.0, 0.0, 1.0),
        };
        let material = mp_of(&placed);
        let boundary: Vec<LineString<f64>> = material
            .iter()
            .flat_map(|p| std::iter::once(p.exterior().clone()).chain(p.interiors().iter().cloned()))
            .collect();
        for (k, &(c, r)) in cover.iter().enumerate() {
            let gc = geo::Point::new(c.x, c.y);
            assert!(material.contains(&gc), "{name}: disc {k}'s centre is outside the material");
            let edge = boundary.iter().map(|l| Euclidean.distance(&gc, l)).fold(f64::MAX, f64::min);
            assert!(edge >= r, "{name}: disc {k} of radius {r} pokes out ({edge} from the outline)");
            // No disc holds the centre of another.
            for &(d, s) in &cover[..k] {
                assert!(c.dist2(d).sqrt() >= r.max(s) * (1.0 - 1e-12), "{name}: discs overlap centres");
            }
        }
    }
    // Random pairs of heart rings: every pair whose covers meet meets by geo, and many pairs
    // are decided by the cover that the inscribed discs alone leave to the edges.
    let (mut a, mut b) = (Owned::new(heart_ring()), Owned::new(heart_ring()));
    let (ma, mb) = (a.with_tree(), b.with_tree());
    let mut r = Lcg(11);
    let (mut by_cover, mut beyond_inner, mut grown_wrong) = (0, 0, 0);
    for i in 0..600 {
        let gap = if i % 2 == 0 { 0.0 } else { 0.5 * r.f() };
        let sb = 6.0 + 6.0 * r.f();
        let (fa, fb) = (frame(&mut r, 10.0, 40.0), frame(&mut r, sb, 40.0));
        let (ga, gb) = (Geo::Motif { m: &ma, f: fa }, Geo::Motif { m: &mb, f: fb });
        let d = geo_distance(&ga, &gb);
        if covers_meet(&ma, &fa, &mb, &fb, gap, 1.0) {
            by_cover += 1;
            assert!(d <= gap, "pair {i}: the covers meet but geo finds the rings {d} apart (gap {gap})");
            assert!(!separated(&ga, &gb, gap), "pair {i}: the covers meet but the exact test passes");
            let inner = fa.t.dist2(fb.t).sqrt() < (ma.inner() * fa.norm + mb.inner() * fb.norm) + gap;
            if !inner {
                beyond_inner += 1;
            }
        }
        // The twin: covers grown by a fifth claim overlaps that are not there.
        if covers_meet(&ma, &fa, &mb, &fb, gap, 1.2) && d > gap + 1e-3 {
            grown_wrong += 1;
        }
    }
    assert!(
        by_cover > 100 && beyond_inner > 50,
        "{by_cover} pairs decided by the covers, {beyond_inner} beyond the inscribed discs"
    );
    assert!(
        grown_wrong > 0,
        "a cover grown by 20% passed every pair: the pairs never come near a disc's rim"
    );
}

/// Every kind of region with a motif fill: both samplers, both scalars.
fn regions() -> Vec<(&'static str, Region<'static>)> {
    vec![
        (
            "rect",
            Region::Rect {
                width: 200.0,
                height: 200.0,
                periodic: false,
            },
        ),
        (
            "torus",
            Region::Rect {
                width: 200.0,
                height: 200.0,
                periodic: true,
            },
        ),
        ("circle", Region::Circle { radius: 100.0 }),
        ("annulus", Region::Annulus { outer: 100.0, inner: 40.0 }),
    ]
}

/// Fills `count` motifs (the letter P, rotated) and returns the outlines.
fn fill<S: Scalar>(region: Region<'_>, count: usize, fast: bool, gap: f64) -> (Vec<MultiPolygon<f64>>, StopReason) {
    let mut owned = Owned::new(letter_p());
    let motifs = [owned.with_tree()];
    let params = Params {
        shape: motifs[0].kind(0).into(),
        rotate: true,
        gap,
        ..Params::circles(1.25, 2.0)
    };
    let images = region.wallpaper().map_or(1, |w| w.order());
    let mut buffers = Buffers::<S>::new(count * images);
    let mut e = Engine::<S>::with_motifs(params, region, buffers.storage(&mut []), &motifs).expect("valid");
    let stop = Stop {
        count: Some(count as u64),
        ..Stop::default()
    };
    let mut rng = rng_from_seed(5);
    let reason = if fast {
        let mut pool = vec![[0u64; 4]; 1 << 14];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        e.run_fast(&mut cells, &mut rng, &stop, |_| {})
    } else {
        e.run(&mut rng, &stop, |_| {})
    };
    let to_f64 = |g: Geo<'_, S>| -> MultiPolygon<f64> {
        let ring = |v: Vec<[f64; 2]>| LineString::from(v.iter().map(|p| Coord { x: p[0], y: p[1] }).collect::<Vec<_>>());
        match g {
            Geo::Motif { m, f } => {
                let mut acc = MultiPolygon::new(vec![]);
                for r in m.rings_at(&f) {
                    let p = MultiPolygon::new(vec![Polygon::new(ring(r.map(|q| [q.x.to_f64(), q.y.to_f64()]).collect()), vec![])]);
                    acc = acc.xor(&p);
                }
                acc
            }
            other => panic!("a motif fill placed {other:?}"),
        }
    };
    ((0..e.placed().len()).filter_map(|i| e.geo(i)).map(to_f64).collect(), reason)
}

fn check(name: &str, shapes: &[MultiPolygon<f64>], region: &MultiPolygon<f64>, periodic: Option<(f64, f64)>) {
    assert!(shapes.len() > 10, "{name}: {} shapes", shapes.len());
    for (i, a) in shapes.iter().enumerate() {
        if periodic.is_none() {
            // Every vertex in the region, and no overlap with a hole of it.
            for p in
                a.0.iter()
                    .flat_map(|poly| std::iter::once(poly.exterior()).chain(poly.interiors()))
                    .flat_map(|r| r.0.iter())
            {
                assert!(
                    region.intersects(&geo::Point::new(p.x, p.y)),
                    "{name}: shape {i} has a vertex {p:?} outside the region"
                );
            }
            for hole in region.0.iter().flat_map(|poly| poly.interiors()) {
                let hole = Polygon::new(hole.clone(), vec![]);
                let common: f64 = geo::Area::unsigned_area(&a.intersection(&MultiPolygon::new(vec![hole])));
                assert!(common < 1e-9, "{name}: shape {i} covers {common} mm² of a hole");
            }
        }
        for (j, b) in shapes.iter().enumerate().take(i) {
            let shifts: Vec<(f64, f64)> = match periodic {
                Some((w, h)) => [-1.0, 0.0, 1.0]
                    .iter()
                    .flat_map(|&k| [-1.0, 0.0, 1.0].map(move |l| (k * w, l * h)))
                    .collect(),
                None => vec![(0.0, 0.0)],
            };
            for (dx, dy) in shifts {
                let bs = geo::Translate::translate(b, dx, dy);
                let (Some(ra), Some(rb)) = (geo::BoundingRect::bounding_rect(a), geo::BoundingRect::bounding_rect(&bs)) else {
                    continue;
                };
                if !ra.intersects(&rb) {
                    continue;
                }
                let common: f64 = geo::Area::unsigned_area(&a.intersection(&bs));
                assert!(common < 1e-9, "{name}: shapes {j} and {i} overlap by {common} mm²");
            }
        }
    }
}

fn rect_mp(w: f64, h: f64) -> MultiPolygon<f64> {
    let r = LineString::from(vec![(0.0, 0.0), (w, 0.0), (w, h), (0.0, h), (0.0, 0.0)]);
    MultiPolygon::new(vec![Polygon::new(r, vec![])])
}

fn disc_mp(c: f64, r: f64, hole: Option<f64>) -> MultiPolygon<f64> {
    // Circumscribed polygons: every shape inside the true disc lies inside them.
    let ring = |r: f64, n: usize, grow: bool| {
        let k = if grow { 1.0 / (std::f64::consts::PI / n as f64).cos() } else { 1.0 };
        LineString::from(
            (0..=n)
                .map(|i| {
                    let t = i as f64 * std::f64::consts::TAU / n as f64;
                    (c + r * k * t.cos(), c + r * k * t.sin())
                })
                .collect::<Vec<_>>(),
        )
    };
    MultiPolygon::new(vec![Polygon::new(
        ring(r, 2000, true),
        hole.map(|h| vec![ring(h, 2000, false)]).unwrap_or_default(),
    )])
}

#[test]
fn motif_fills_keep_apart_and_inside_on_both_samplers_and_scalars() {
    for (name, region) in regions() {
        let mp = match region {
            Region::Circle { radius } => disc_mp(radius, radius, None),
            Region::Annulus { outer, inner } => disc_mp(outer, outer, Some(inner)),
            _ => rect_mp(200.0, 200.0),
        };
        let periodic = region.periodic().then_some((200.0, 200.0));
        for fast in [false, true] {
            let (shapes, reason) = fill::<f64>(region, 100, fast, 0.0);
            assert_eq!(reason, StopReason::Count, "{name}");
            check(&format!("{name} f64 fast={fast}"), &shapes, &mp, periodic);
        }
        let (shapes, reason) = fill::<Fixed>(region, 30, true, 0.5);
        assert_eq!(reason, StopReason::Count, "{name} fixed");
        check(&format!("{name} fixed"), &shapes, &mp, periodic);
    }
}

#[test]
fn motif_fills_in_a_polygon_with_a_hole() {
    let p = Point::new;
    let outline = [
        p(0.0, 0.0),
        p(200.0, 0.0),
        p(200.0, 200.0),
        p(100.0, 120.0),
        p(0.0, 200.0),
        p(60.0, 40.0),
        p(60.0, 80.0),
        p(140.0, 80.0),
        p(140.0, 40.0),
    ];
    let ends = [5, 9];
    let mut scratch = vec![0u32; PolygonRegion::scratch_words(outline.len())];
    let region = Region::Polygon(PolygonRegion::new_in(&outline, &ends, &mut scratch).expect("a region"));
    let ring = |v: &[Point<f64>]| LineString::from(v.iter().chain(v.first()).map(|q| (q.x, q.y)).collect::<Vec<_>>());
    let mp = MultiPolygon::new(vec![Polygon::new(ring(&outline[..5]), vec![ring(&outline[5..])])]);
    for fast in [false, true] {
        let (shapes, reason) = fill::<f64>(region, 120, fast, 0.2);
        assert_eq!(reason, StopReason::Count);
        check(&format!("polygon fast={fast}"), &shapes, &mp, None);
    }
}

#[test]
fn motif_fills_under_a_wallpaper_group_keep_every_image_apart() {
    // p4g has mirrors and quarter turns: the images of a motif are turned and reflected.
    let w = Wallpaper::new(Group::P4g, 120.0, 120.0, 90.0).expect("a lattice");
    let (shapes, reason) = fill::<f64>(Region::Wallpaper(w), 40, true, 0.0);
    assert_eq!(reason, StopReason::Count);
    assert_eq!(shapes.len(), 40 * 8);
    check("p4g", &shapes, &rect_mp(120.0, 120.0), Some((120.0, 120.0)));
}

#[test]
fn a_placed_motif_has_the_area_asked_for_and_mirrors_keep_it() {
    let mut owned = Owned::new(letter_p());
    let m = owned.with_tree();
    let f = Frame::new(Point::new(10.0, 20.0), 3.0, 0.6, 0.8);
    let g = Geo::Motif { m: &m, f };
    assert!((g.poly_area2() / 2.0 - 9.0).abs() < 1e-9);
    // A reflection (a mirror of a wallpaper group) keeps the area and the answers.
    let mirrored = Geo::Motif {
        m: &m,
        f: f.then([1.0, 0.0, 0.0, -1.0], Point::new(10.0, 20.0)),
    };
    assert!((mirrored.poly_area2() / 2.0 - 9.0).abs() < 1e-9);
    assert!(!separated(&g, &mirrored, 0.0), "both hold their reference point's disc");
    // Bad outlines are refused.
    let mut few = vec![Point::new(0.0, 0.0), Point::new(1.0, 0.0)];
    assert!(Motif::new(&mut few, &[2]).is_err());
}

#[test]
fn first_two_motifs_that_cannot_fit_are_refused_with_the_largest_c() {
    use zetafill::{check_first_two, FirstTwoError};
    let mut owned = Owned::new(letter_p());
    let m = owned.with_tree();
    // A strip so low that the first P's inscribed disc (radius inner sqrt(A_0)) is taller:
    // 2 inner sqrt(200 h / zeta) > h for h below 800 inner^2 / zeta(1.3, 1).
    let h = 400.0 * m.inner() * m.inner() / zetafill::AreaSequence::new(1.0, 1.3, 1.0).expect("zeta").zeta();
    let region = Region::Rect {
        width: 200.0,
        height: h,
        periodic: false,
    };
    let params = |c: f64| Params {
        shape: m.kind(0).into(),
        rotate: true,
        ..Params::circles(c, 1.0)
    };
    let Err(FirstTwoError::Exponent { max_c, .. }) = check_first_two(&params(1.3), &region) else {
        panic!("the first P is too tall for the strip")
    };
    // At the limit the first two inscribed discs just fit; a hair above, they do not.
    assert!(max_c > 1.0 && max_c < 1.3);
    assert!(check_first_two(&params(max_c), &region).is_ok());
    assert!(check_first_two(&params(max_c * (1.0 + 1e-6)), &region).is_err());
}
