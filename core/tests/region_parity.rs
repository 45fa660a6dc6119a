//! Parity of a polygon region's two ways: through the edge tree (`PolygonRegion::new_in` with
//! scratch, full or too small for small leaves) and over every pair of edges
//! (`PolygonRegion::new`), on outlines built to be degenerate (shared vertices, collinear
//! overlaps, touching rings, folds, holes, rings crossing, zero-length edges, nearly collinear
//! floating-point vertices): the same accept or reject, the same area bits, the same holes,
//! and the same answer and bits from every query a fill asks. Both are also held to the check
//! as it stood before the tree (`oracles/legacy_region.rs`), which may only differ by
//! rejecting a pair of edges whose boxes lie far apart (a rounding artefact), and region
//! containment to the test as it stood before.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

#[path = "oracles/legacy_region.rs"]
mod legacy;

use zetafill::internals::geom::{point_in_poly, seg_seg_dist2, segments_intersect};
use zetafill::{Fixed, Geo, Point, PolygonRegion, Region, RegionError, Scalar, ShapeKind};

/// splitmix64: a small, fixed generator for the cases.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn f(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in lo..hi.
    fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next() % (hi - lo) as u64) as usize
    }
}

/// Vertices, ring after ring, and the end of each ring.
type Outline = (Vec<Point<f64>>, Vec<usize>);

fn push(o: &mut Outline, ring: impl IntoIterator<Item = Point<f64>>) {
    o.0.extend(ring);
    o.1.push(o.0.len());
}

/// 1 to 4 rings of 3 to 7 vertices on a 7 x 7 lattice: exact arithmetic, and nearly every
/// degenerate case (shared vertices, collinear overlaps, touching, folds, repeated vertices).
fn lattice(r: &mut Mix) -> Outline {
    let mut o = (Vec::new(), Vec::new());
    for _ in 0..r.int(1, 5) {
        let n = r.int(3, 8);
        let ring: Vec<Point<f64>> = (0..n).map(|_| Point::new(r.int(0, 7) as f64, r.int(0, 7) as f64)).collect();
        push(&mut o, ring);
    }
    o
}

/// A star-shaped ring (simple) about `c` with radii in [lo, hi] and `n` vertices.
fn star(r: &mut Mix, c: Point<f64>, lo: f64, hi: f64, n: usize, snap: bool) -> Vec<Point<f64>> {
    let mut angles: Vec<f64> = (0..n).map(|_| r.f() * std::f64::consts::TAU).collect();
    angles.sort_by(f64::total_cmp);
    angles
        .iter()
        .map(|t| {
            let rad = lo + (hi - lo) * r.f();
            let p = Point::new(c.x + rad * t.cos(), c.y + rad * t.sin());
            if snap {
                Point::new(p.x.round(), p.y.round())
            } else {
                p
            }
        })
        .collect()
}

/// An outer star with holes (stars inside it) and islands (stars beside it), sometimes on
/// the integer lattice (so rings may touch or cross), sometimes crossing on purpose.
fn stars(r: &mut Mix) -> Outline {
    let snap = r.next() % 3 == 0;
    let mut o = (Vec::new(), Vec::new());
    let n = r.int(3, 300);
    let outer = star(r, Point::new(50.0, 50.0), 30.0, 45.0, n, snap);
    push(&mut o, outer);
    for _ in 0..r.int(0, 6) {
        // Inside the outer star's inner radius, or overlapping its edge now and then.
        let (d, t) = (if r.next() % 8 == 0 { 30.0 } else { 18.0 * r.f() }, r.f() * std::f64::consts::TAU);
        let c = Point::new(50.0 + d * t.cos(), 50.0 + d * t.sin());
        let (hi, n) = (2.0 + 8.0 * r.f(), r.int(3, 40));
        let hole = star(r, c, 1.0, hi, n, snap);
        push(&mut o, hole);
    }
    if r.next() % 2 == 0 {
        let n = r.int(3, 60);
        let island = star(r, Point::new(120.0, 50.0), 5.0, 15.0, n, snap);
        push(&mut o, island);
    }
    o
}

/// Rings whose vertices lie on (or within rounding of) a few lines, in floating point:
/// collinear overlaps, and the nearly collinear quadruples where the floating-point test
/// reports crossings that are not there.
fn collinear(r: &mut Mix) -> Outline {
    let lines: Vec<(Point<f64>, Point<f64>)> = (0..r.int(1, 4))
        .map(|_| {
            let o = Point::new(100.0 * r.f() - 50.0, 100.0 * r.f() - 50.0);
            let t = r.f() * std::f64::consts::TAU;
            (o, Point::new(t.cos(), t.sin()))
        })
        .collect();
    let mut o = (Vec::new(), Vec::new());
    for _ in 0..r.int(1, 4) {
        let n = r.int(3, 9);
        let ring: Vec<Point<f64>> = (0..n)
            .map(|_| {
                let (p, d) = lines[r.int(0, lines.len())];
                let t = 100.0 * r.f();
                Point::new(p.x + t * d.x, p.y + t * d.y)
            })
            .collect();
        push(&mut o, ring);
    }
    o
}

/// A `k x k` block of squares of side 1 at a pitch of 1 (touching), 1.5 or 2, some moved by
/// half a unit (then they may overlap), in a frame or not.
fn squares(r: &mut Mix) -> Outline {
    let k = r.int(1, 12);
    let pitch = [1.0, 1.5, 2.0, 2.0][r.int(0, 4)];
    let mut o = (Vec::new(), Vec::new());
    if r.next() % 2 == 0 {
        let w = pitch * k as f64 + 2.0;
        push(
            &mut o,
            [Point::new(-1.0, -1.0), Point::new(w, -1.0), Point::new(w, w), Point::new(-1.0, w)],
        );
    }
    for i in 0..k * k {
        let shift = if r.next() % 20 == 0 { 0.5 } else { 0.0 };
        let (x, y) = (pitch * (i % k) as f64 + shift, pitch * (i / k) as f64);
        push(
            &mut o,
            [
                Point::new(x, y),
                Point::new(x + 1.0, y),
                Point::new(x + 1.0, y + 1.0),
                Point::new(x, y + 1.0),
            ],
        );
    }
    o
}

/// What a region says about itself: its area's bits and which rings are holes.
type Summary = Result<(u64, Vec<bool>), RegionError>;

fn summary(r: Result<PolygonRegion<'_>, RegionError>) -> Summary {
    r.map(|p| (p.area().to_bits(), (0..p.ring_ends().len()).map(|i| p.is_hole(i)).collect()))
}

/// Whether two ways agree, or a message naming the case where they do not.
fn agree(case: &str, way: &str, a: &Summary, b: &Summary) -> Result<(), String> {
    if a == b {
        Ok(())
    } else {
        Err(format!("{case}: every pair of edges says {a:?}, {way} says {b:?}"))
    }
}

/// Whether the outline has two edges, not neighbours, whose boxes lie farther apart than the
/// region's margin and which the floating-point test calls meeting: the one way the check
/// before the tree may reject what the region accepts.
fn has_far_artefact(o: &Outline) -> bool {
    let edges: Vec<(usize, Point<f64>, Point<f64>)> = {
        let mut v = Vec::new();
        let mut start = 0;
        for &e in &o.1 {
            for i in start..e {
                let j = if i + 1 == e { start } else { i + 1 };
                v.push((i, o.0[i], o.0[j]));
            }
            start = e;
        }
        v
    };
    let scale = o.0.iter().fold(1f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let m = scale * 1e-9;
    let near = |a: (Point<f64>, Point<f64>), b: (Point<f64>, Point<f64>)| {
        a.0.x.min(a.1.x) <= b.0.x.max(b.1.x) + m
            && b.0.x.min(b.1.x) <= a.0.x.max(a.1.x) + m
            && a.0.y.min(a.1.y) <= b.0.y.max(b.1.y) + m
            && b.0.y.min(b.1.y) <= a.0.y.max(a.1.y) + m
    };
    edges.iter().enumerate().any(|(k, &(_, a1, a2))| {
        edges[k + 1..].iter().any(|&(_, b1, b2)| {
            let shared = a1 == b1 || a1 == b2 || a2 == b1 || a2 == b2;
            !shared && !near((a1, a2), (b1, b2)) && segments_intersect(a1, a2, b1, b2)
        })
    })
}

/// Validates `o` every way and compares; returns whether it is valid.
fn check(case: &str, o: &Outline, artefacts: &mut u32) -> Result<bool, String> {
    let (pts, ends) = (&o.0[..], &o.1[..]);
    let pairs = summary(PolygonRegion::new(pts, ends));
    let mut full = vec![0u32; PolygonRegion::scratch_words(pts.len())];
    agree(case, "the tree", &pairs, &summary(PolygonRegion::new_in(pts, ends, &mut full)))?;
    // Scratch for one leaf of every edge, and for leaves of 16 or so.
    let mut one = vec![0u32; 2 * pts.len() + 8];
    agree(
        case,
        "the one-leaf tree",
        &pairs,
        &summary(PolygonRegion::new_in(pts, ends, &mut one)),
    )?;
    let mut some = vec![0u32; 2 * pts.len() + 8 * (2 * pts.len().div_ceil(16)) + 8];
    agree(case, "a small tree", &pairs, &summary(PolygonRegion::new_in(pts, ends, &mut some)))?;
    // Too small for any tree: every pair.
    let mut none = vec![0u32; pts.len()];
    agree(case, "no room", &pairs, &summary(PolygonRegion::new_in(pts, ends, &mut none)))?;
    let before = legacy::validate(pts, ends);
    match (&before, &pairs) {
        (Ok(a), Ok((bits, _))) if a.to_bits() == *bits => {}
        (Err(a), Err(b)) if a == b => {}
        (Err(RegionError::SelfIntersecting), Ok(_)) if has_far_artefact(o) => *artefacts += 1,
        _ => return Err(format!("{case}: the check before the tree says {before:?}, now {pairs:?}")),
    }
    Ok(pairs.is_ok())
}

/// Region containment of a polygon shape as it stood before the tree: every pair of a region
/// edge and a shape edge tested, every ring's first vertex tested.
fn contains_before(region: &Region<'_>, p: &PolygonRegion<'_>, g: &Geo<f64>, gap: f64) -> bool {
    let vs = g.vertices();
    if !vs.iter().all(|&v| region.point_inside(v)) {
        return false;
    }
    let ring_edges = |ring: &[Point<f64>]| {
        let n = ring.len();
        (0..n).map(move |i| (ring[i], ring[(i + 1) % n])).collect::<Vec<_>>()
    };
    let shape = ring_edges(vs);
    for ring in p.rings() {
        for (a, b) in ring_edges(ring) {
            for &(c, d) in &shape {
                let clear = if gap <= 0.0 {
                    !segments_intersect(a, b, c, d)
                } else {
                    seg_seg_dist2(a, b, c, d) > gap * gap
                };
                if !clear {
                    return false;
                }
            }
        }
    }
    p.rings().all(|ring| ring.first().is_none_or(|&q| !point_in_poly(q, vs)))
}

/// Asks both regions every query a fill asks, at points and shapes in and around them.
fn queries(case: &str, o: &Outline, r: &mut Mix) -> Result<(), String> {
    let (pts, ends) = (&o.0[..], &o.1[..]);
    let mut full = vec![0u32; PolygonRegion::scratch_words(pts.len())];
    let (Ok(with), Ok(without)) = (PolygonRegion::new_in(pts, ends, &mut full), PolygonRegion::new(pts, ends)) else {
        return Err(format!("{case}: not valid"));
    };
    let (a, b) = (Region::Polygon(with), Region::Polygon(without));
    let (x0, y0, x1, y1) = a.bbox();
    let (w, h) = (x1 - x0, y1 - y0);
    for k in 0..24 {
        let q = Point::new(x0 - 0.2 * w + 1.4 * w * r.f(), y0 - 0.2 * h + 1.4 * h * r.f());
        // Vertices, and points on edges, too.
        let q = match k % 6 {
            0 => pts[r.int(0, pts.len())],
            1 => {
                let i = r.int(0, pts.len() - 1);
                let t = r.f();
                Point::new(pts[i].x + t * (pts[i + 1].x - pts[i].x), pts[i].y + t * (pts[i + 1].y - pts[i].y))
            }
            _ => q,
        };
        let same = |what: &str, x: u64, y: u64| {
            if x == y {
                Ok(())
            } else {
                Err(format!("{case}: {what} at {q:?} differs with the tree: {x:#x} against {y:#x}"))
            }
        };
        same("point_inside", u64::from(a.point_inside(q)), u64::from(b.point_inside(q)))?;
        same("boundary_dist2", a.boundary_dist2(q).to_bits(), b.boundary_dist2(q).to_bits())?;
        same("signed_clearance", a.signed_clearance(q).to_bits(), b.signed_clearance(q).to_bits())?;
        let qf = Point::new(Fixed::from_f64(q.x), Fixed::from_f64(q.y));
        same("fixed point_inside", u64::from(a.point_inside(qf)), u64::from(b.point_inside(qf)))?;
        same(
            "fixed boundary_dist2",
            a.boundary_dist2(qf).to_word(),
            b.boundary_dist2(qf).to_word(),
        )?;
        let size = w.max(h) * [0.001, 0.01, 0.05, 0.2][k % 4] * (0.5 + r.f());
        let gap = [0.0, 0.0, size * 0.1, w.max(h) * 1e-12][k / 4 % 4];
        let circle = Geo::Circle { c: q, r: size };
        same(
            "circle contains",
            u64::from(a.contains(&circle, gap)),
            u64::from(b.contains(&circle, gap)),
        )?;
        let ring = Geo::Ring {
            c: q,
            r: size,
            inner: size / 2.0,
        };
        same(
            "ring contains",
            u64::from(a.contains(&ring, gap)),
            u64::from(b.contains(&ring, gap)),
        )?;
        let kind = [
            ShapeKind::Square,
            ShapeKind::Star { points: 5, inner: 0.4 },
            ShapeKind::Polygon { sides: 7 },
        ][k % 3];
        let shape = kind.geo(q, size, r.f() * 7.0);
        let (ca, cb) = (a.contains(&shape, gap), b.contains(&shape, gap));
        same("polygon contains", u64::from(ca), u64::from(cb))?;
        same(
            "polygon contains before the tree",
            u64::from(contains_before(&b, &without, &shape, gap)),
            u64::from(cb),
        )?;
        let fshape = kind.geo(qf, Fixed::from_f64(size), Fixed::from_f64(0.3));
        let fgap = Fixed::from_f64(gap);
        same(
            "fixed polygon contains",
            u64::from(a.contains(&fshape, fgap)),
            u64::from(b.contains(&fshape, fgap)),
        )?;
        let fcircle = Geo::Circle {
            c: qf,
            r: Fixed::from_f64(size),
        };
        same(
            "fixed circle contains",
            u64::from(a.contains(&fcircle, fgap)),
            u64::from(b.contains(&fcircle, fgap)),
        )?;
    }
    Ok(())
}

fn run(name: &str, cases: u32, seed: u64, make: fn(&mut Mix) -> Outline) -> (u32, u32) {
    let mut r = Mix(seed);
    let (mut valid, mut artefacts) = (0u32, 0u32);
    for k in 0..cases {
        let o = make(&mut r);
        let case = format!("{name} case {k}");
        match check(&case, &o, &mut artefacts) {
            Ok(true) => {
                valid += 1;
                queries(&case, &o, &mut r).unwrap_or_else(|e| panic!("{e}"));
            }
            Ok(false) => {}
            Err(e) => panic!("{e}"),
        }
    }
    (valid, artefacts)
}

#[test]
fn lattice_outlines_agree_every_way() {
    let (valid, artefacts) = run("lattice", 30_000, 1, lattice);
    // Exact arithmetic: no artefacts; a fair share of valid outlines among the degenerate.
    assert_eq!(artefacts, 0);
    assert!(valid > 1_000, "only {valid} valid lattice outlines");
}

#[test]
fn stars_with_holes_and_islands_agree_every_way() {
    let (valid, _) = run("stars", 1_500, 2, stars);
    assert!(valid > 300, "only {valid} valid star outlines");
}

#[test]
fn nearly_collinear_outlines_agree_every_way() {
    let (valid, artefacts) = run("collinear", 20_000, 3, collinear);
    eprintln!("collinear: {valid} valid, {artefacts} rejected before the tree only for far artefacts");
    assert!(valid > 100, "only {valid} valid collinear outlines");
}

#[test]
fn blocks_of_squares_agree_every_way() {
    let (valid, _) = run("squares", 600, 4, squares);
    assert!(valid > 100, "only {valid} valid blocks");
}

#[test]
fn outlines_at_extreme_scales_agree_every_way() {
    // Beyond the range where the tree prunes distances (coordinates above 2^60, edges shorter
    // than 2^-300) and queries beyond it (far, infinite, NaN points): still the same bits.
    let mut r = Mix(5);
    for scale in [1e-310, 1e-200, 1e-150, 1e-20, 1e20, 1e100, 1e154, 1e200, 1e300] {
        for k in 0..20 {
            let (pts, ends) = stars(&mut r);
            let pts: Vec<Point<f64>> = pts.iter().map(|p| Point::new(p.x * scale, p.y * scale)).collect();
            let o = (pts, ends);
            let case = format!("scale {scale:e} case {k}");
            let mut artefacts = 0;
            if !check(&case, &o, &mut artefacts).unwrap_or_else(|e| panic!("{e}")) {
                continue;
            }
            queries(&case, &o, &mut r).unwrap_or_else(|e| panic!("{e}"));
            let mut full = vec![0u32; PolygonRegion::scratch_words(o.0.len())];
            let with = Region::Polygon(PolygonRegion::new_in(&o.0, &o.1, &mut full).unwrap_or_else(|e| panic!("{e}")));
            let without = Region::Polygon(PolygonRegion::new(&o.0, &o.1).unwrap_or_else(|e| panic!("{e}")));
            for q in [
                Point::new(1e306, -1e306),
                Point::new(f64::MAX, 0.0),
                Point::new(f64::INFINITY, 1.0),
                Point::new(1.0, f64::NEG_INFINITY),
                Point::new(f64::NAN, 0.0),
                Point::new(0.0, f64::NAN),
            ] {
                assert_eq!(with.point_inside(q), without.point_inside(q), "{case}: inside {q:?}");
                assert_eq!(
                    with.boundary_dist2(q).to_bits(),
                    without.boundary_dist2(q).to_bits(),
                    "{case}: distance {q:?}"
                );
                let circle = Geo::Circle { c: q, r: scale };
                assert_eq!(with.contains(&circle, 0.0), without.contains(&circle, 0.0), "{case}: circle {q:?}");
            }
        }
    }
}

#[test]
fn a_crossing_outline_is_rejected_by_the_tree() {
    // A bow tie, and a square whose hole pokes through its edge, and two touching squares.
    let p = Point::new;
    let bad: [Outline; 3] = [
        (vec![p(0.0, 0.0), p(10.0, 10.0), p(10.0, 0.0), p(0.0, 10.0)], vec![4]),
        (
            vec![
                p(0.0, 0.0),
                p(10.0, 0.0),
                p(10.0, 10.0),
                p(0.0, 10.0),
                p(8.0, 4.0),
                p(12.0, 4.0),
                p(12.0, 6.0),
                p(8.0, 6.0),
            ],
            vec![4, 8],
        ),
        (
            vec![
                p(0.0, 0.0),
                p(1.0, 0.0),
                p(1.0, 1.0),
                p(0.0, 1.0),
                p(1.0, 0.5),
                p(2.0, 0.5),
                p(2.0, 1.5),
                p(1.0, 1.5),
            ],
            vec![4, 8],
        ),
    ];
    for (pts, ends) in &bad {
        let mut scratch = vec![0u32; PolygonRegion::scratch_words(pts.len())];
        assert_eq!(
            PolygonRegion::new_in(pts, ends, &mut scratch).err(),
            Some(RegionError::SelfIntersecting)
        );
    }
}

#[test]
fn the_comparison_reports_a_doctored_oracle() {
    // A square with a hole touching its edge: invalid. An oracle doctored to accept it (as a
    // check that skipped touching would), or to call the hole an outline, is caught.
    let p = Point::new;
    let (pts, ends) = (
        vec![
            p(0.0, 0.0),
            p(10.0, 0.0),
            p(10.0, 10.0),
            p(0.0, 10.0),
            p(4.0, 0.0),
            p(6.0, 4.0),
            p(4.0, 4.0),
        ],
        vec![4, 7],
    );
    let mut scratch = vec![0u32; PolygonRegion::scratch_words(pts.len())];
    let tree = summary(PolygonRegion::new_in(&pts, &ends, &mut scratch));
    assert_eq!(tree, Err(RegionError::SelfIntersecting));
    let doctored: Summary = Ok((96.0f64.to_bits(), vec![false, true]));
    let e = agree("touching hole", "the tree", &doctored, &tree).expect_err("a doctored oracle must be reported");
    assert!(e.contains("touching hole") && e.contains("SelfIntersecting"), "{e}");
    // On a valid outline, a hole flag flipped.
    let (pts, ends) = (
        vec![
            p(0.0, 0.0),
            p(10.0, 0.0),
            p(10.0, 10.0),
            p(0.0, 10.0),
            p(4.0, 1.0),
            p(6.0, 4.0),
            p(4.0, 4.0),
        ],
        vec![4, 7],
    );
    let mut scratch = vec![0u32; PolygonRegion::scratch_words(pts.len())];
    let tree = summary(PolygonRegion::new_in(&pts, &ends, &mut scratch));
    let Ok((bits, holes)) = tree.clone() else {
        panic!("valid outline refused")
    };
    assert_eq!(holes, [false, true]);
    assert!(agree("hole", "the tree", &Ok((bits, vec![false, false])), &tree).is_err());
    // The harness passes the valid outline itself.
    let mut artefacts = 0;
    assert!(check("valid", &(pts.clone(), ends.clone()), &mut artefacts).is_ok_and(|v| v));
}

#[test]
fn the_check_before_the_tree_rejects_a_far_artefact_the_region_accepts() {
    // Found by search over nearly collinear quadruples: the floating-point test calls these
    // two segments crossing though their boxes lie apart (x up to 4.04 against from 4.92).
    let p = Point::new;
    let (a1, a2) = (p(-27.267004829358545, -53.24209186584993), p(4.035234232043948, -16.5261377751876));
    let (b1, b2) = (p(4.921356105485259, -15.486761328020911), p(9.50287504290629, -10.112869746595052));
    assert!(segments_intersect(a1, a2, b1, b2));
    // Two thin triangles with those edges, far apart.
    let pts = vec![a1, a2, p(-27.0, -60.0), b1, b2, p(9.5, -20.0)];
    let ends = vec![3, 6];
    assert_eq!(legacy::validate(&pts, &ends), Err(RegionError::SelfIntersecting));
    let mut scratch = vec![0u32; PolygonRegion::scratch_words(pts.len())];
    assert!(PolygonRegion::new_in(&pts, &ends, &mut scratch).is_ok());
    assert!(PolygonRegion::new(&pts, &ends).is_ok());
}
