//! Exact clipping to a rectangle, so that a periodic tile's images end exactly at its edges.
//!
//! - Strokes ([`clip_path`]): segments by Liang–Barsky, circles and arcs cut at their
//!   crossings into arcs. This is what a pen draws.
//! - Areas ([`clip_area`]): a polygon clipped polygon against rectangle (Sutherland–Hodgman),
//!   a disc into one closed loop of arcs joined along the rectangle's edges. This is what a
//!   filled shape covers.
//!
//! Cut points lie on the rectangle's edges (areas: exactly; strokes: up to rounding).

use super::path::dist;
use super::{polar, Bounds, Path, Pt};
use std::f64::consts::{PI, TAU};

/// The parameter range `[t0, t1]` of segment `a -> b` inside `r` (Liang–Barsky), if any.
pub fn clip_segment(a: Pt, b: Pt, r: &Bounds) -> Option<(f64, f64)> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-dx, a[0] - r.x0), (dx, r.x1 - a[0]), (-dy, a[1] - r.y0), (dy, r.y1 - a[1])] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 < t1).then_some((t0, t1))
}

pub(super) fn lerp(a: Pt, b: Pt, t: f64) -> Pt {
    if t == 0.0 {
        a
    } else if t == 1.0 {
        b
    } else {
        [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]
    }
}

/// A path cut to the parts inside `r` (edges on the boundary count as inside).
pub fn clip_path(p: &Path, r: &Bounds) -> Vec<Path> {
    if p.bounds().inside(r, 0.0) {
        return vec![p.clone()];
    }
    match p {
        Path::Polyline { points, closed } => clip_polyline(points, *closed, r),
        Path::Arc {
            center,
            radius,
            start,
            sweep,
        } => clip_arc(*center, *radius, *start, *sweep, r),
    }
}

fn clip_polyline(points: &[Pt], closed: bool, r: &Bounds) -> Vec<Path> {
    let n = points.len();
    if n < 2 {
        return vec![];
    }
    let inside = |p: &Pt| p[0] >= r.x0 && p[0] <= r.x1 && p[1] >= r.y0 && p[1] <= r.y1;
    // A closed polyline is walked from a vertex outside, so no piece is split at the seam.
    let (first, edges) = if closed {
        (points.iter().position(|p| !inside(p)).unwrap_or(0), n)
    } else {
        (0, n - 1)
    };
    let mut out = Vec::new();
    let mut cur: Vec<Pt> = Vec::new();
    for k in 0..edges {
        let (a, b) = (points[(first + k) % n], points[(first + k + 1) % n]);
        match clip_segment(a, b, r) {
            Some((t0, t1)) => {
                if t0 > 0.0 || cur.is_empty() {
                    if cur.len() >= 2 {
                        out.push(Path::polyline(std::mem::take(&mut cur), false));
                    }
                    cur.clear();
                    cur.push(lerp(a, b, t0));
                }
                cur.push(lerp(a, b, t1));
                if t1 < 1.0 {
                    out.push(Path::polyline(std::mem::take(&mut cur), false));
                }
            }
            None => {
                if cur.len() >= 2 {
                    out.push(Path::polyline(std::mem::take(&mut cur), false));
                }
                cur.clear();
            }
        }
    }
    if cur.len() >= 2 {
        out.push(Path::polyline(cur, false));
    }
    out
}

/// Normalises an angle into [0, 2π).
pub(super) fn norm_angle(a: f64) -> f64 {
    let t = a.rem_euclid(TAU);
    if t >= TAU {
        0.0
    } else {
        t
    }
}

fn clip_arc(c: Pt, rad: f64, start: f64, sweep: f64, r: &Bounds) -> Vec<Path> {
    // Work counter-clockwise; a clockwise arc is clipped reversed and turned back.
    if sweep < 0.0 && sweep.abs() < TAU {
        return clip_arc(c, rad, start + sweep, -sweep, r)
            .into_iter()
            .rev()
            .map(|p| p.reversed())
            .collect();
    }
    let full = sweep >= TAU;
    let (s0, span) = if full { (0.0, TAU) } else { (norm_angle(start), sweep) };
    // Angles where the circle crosses the rectangle's edge lines, relative to s0.
    let mut cuts: Vec<f64> = vec![0.0, span];
    let mut add = |a: f64| {
        let rel = norm_angle(a - s0);
        if rel > 0.0 && rel < span {
            cuts.push(rel);
        }
    };
    for (x, vertical) in [(r.x0, true), (r.x1, true), (r.y0, false), (r.y1, false)] {
        let d = if vertical { x - c[0] } else { x - c[1] };
        if d.abs() < rad {
            let base = if vertical { libm::acos(d / rad) } else { libm::asin(d / rad) };
            if vertical {
                add(base);
                add(-base);
            } else {
                add(base);
                add(PI - base);
            }
        }
    }
    arc_pieces(c, rad, s0, full, cuts, |p| {
        p[0] >= r.x0 && p[0] <= r.x1 && p[1] >= r.y0 && p[1] <= r.y1
    })
}

/// The arcs of the circle `(c, rad)` between consecutive `cuts` (angles after `s0`, the arc's
/// ends among them) whose middle is `inside`, pieces that meet joined; for a `full` circle
/// the piece through its start continues across the seam, and a circle kept all round is
/// the whole circle.
pub(super) fn arc_pieces(c: Pt, rad: f64, s0: f64, full: bool, mut cuts: Vec<f64>, inside: impl Fn(Pt) -> bool) -> Vec<Path> {
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut pieces: Vec<(f64, f64)> = Vec::new();
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b <= a || !inside(polar(c, rad, s0 + 0.5 * (a + b))) {
            continue;
        }
        match pieces.last_mut() {
            Some(last) if last.1 == a => last.1 = b,
            _ => pieces.push((a, b)),
        }
    }
    if full && pieces.len() > 1 {
        // The piece through angle 0 continues across the seam.
        let (first, last) = (pieces[0], pieces[pieces.len() - 1]);
        if first.0 == 0.0 && last.1 == TAU {
            pieces.pop();
            pieces[0] = (last.0 - TAU, first.1);
        }
    }
    if full && pieces.len() == 1 && pieces[0].1 - pieces[0].0 >= TAU {
        return vec![Path::circle(c, rad)];
    }
    pieces
        .into_iter()
        .map(|(a, b)| Path::Arc {
            center: c,
            radius: rad,
            start: s0 + a,
            sweep: b - a,
        })
        .collect()
}

/// The part of a closed path's area inside `r`, as closed loops, each a chain of pieces that
/// meet end to start: a closed polyline clipped polygon against rectangle ([`clip_polygon`]),
/// a full circle cut into arcs joined by pieces of the rectangle's edges (the intersection of
/// two convex sets, so one loop, counter-clockwise like the circle). An open path has no area
/// and gives nothing.
pub fn clip_area(p: &Path, r: &Bounds) -> Vec<Vec<Path>> {
    match p {
        Path::Polyline { points, closed: true } => {
            let poly = clip_polygon(points, r);
            if poly.is_empty() {
                vec![]
            } else {
                vec![vec![Path::polyline(poly, true)]]
            }
        }
        Path::Arc { center, radius, sweep, .. } if sweep.abs() >= TAU => {
            let lp = clip_disc(*center, *radius, r);
            if lp.is_empty() {
                vec![]
            } else {
                vec![lp]
            }
        }
        _ => vec![],
    }
}

/// A polygon clipped to `r` (Sutherland–Hodgman, against each edge line in turn): the
/// vertices inside, and the crossings, which lie exactly on the edges. A concave polygon cut
/// into several parts stays one polygon whose parts are joined along the edge by zero-width
/// seams, which cover nothing. Empty when fewer than three vertices are left.
pub fn clip_polygon(points: &[Pt], r: &Bounds) -> Vec<Pt> {
    let mut poly: Vec<Pt> = points.to_vec();
    // (axis, edge, keep the side above it)
    for (axis, at, above) in [(0, r.x0, true), (0, r.x1, false), (1, r.y0, true), (1, r.y1, false)] {
        let n = poly.len();
        if n == 0 {
            break;
        }
        let inside = |p: &Pt| if above { p[axis] >= at } else { p[axis] <= at };
        let cross = |a: Pt, b: Pt| -> Pt {
            let t = (at - a[axis]) / (b[axis] - a[axis]);
            let other = 1 - axis;
            let mut q = [0.0; 2];
            q[axis] = at;
            q[other] = a[other] + (b[other] - a[other]) * t;
            q
        };
        let mut out = Vec::with_capacity(n + 4);
        for i in 0..n {
            let (a, b) = (poly[(i + n - 1) % n], poly[i]);
            match (inside(&a), inside(&b)) {
                (true, true) => out.push(b),
                (true, false) => out.push(cross(a, b)),
                (false, true) => {
                    out.push(cross(a, b));
                    out.push(b);
                }
                (false, false) => {}
            }
        }
        out.dedup();
        while out.len() > 1 && out.first() == out.last() {
            out.pop();
        }
        poly = out;
    }
    if poly.len() < 3 {
        poly.clear();
    }
    poly
}

/// Where `p` (on the rectangle's edge) is along its perimeter, counter-clockwise from the
/// corner (x0, y0).
fn perimeter_at(p: Pt, r: &Bounds) -> f64 {
    let (w, h) = (r.width(), r.height());
    let gaps = [(p[1] - r.y0).abs(), (r.x1 - p[0]).abs(), (r.y1 - p[1]).abs(), (p[0] - r.x0).abs()];
    let edge = (0..4).fold(0, |best, k| if gaps[k] < gaps[best] { k } else { best });
    match edge {
        0 => (p[0] - r.x0).clamp(0.0, w),
        1 => w + (p[1] - r.y0).clamp(0.0, h),
        2 => w + h + (r.x1 - p[0]).clamp(0.0, w),
        _ => 2.0 * w + h + (r.y1 - p[1]).clamp(0.0, h),
    }
}

/// The rectangle's corners passed going counter-clockwise along its edge from `a` to `b`.
fn corners_between(a: Pt, b: Pt, r: &Bounds) -> Vec<Pt> {
    let (w, h) = (r.width(), r.height());
    let perimeter = 2.0 * (w + h);
    let corners = [
        ([r.x0, r.y0], 0.0),
        ([r.x1, r.y0], w),
        ([r.x1, r.y1], w + h),
        ([r.x0, r.y1], 2.0 * w + h),
    ];
    let t0 = perimeter_at(a, r);
    let mut t1 = perimeter_at(b, r);
    if t1 < t0 {
        t1 += perimeter;
    }
    (0..8)
        .map(|k| (corners[k % 4].0, corners[k % 4].1 + if k < 4 { 0.0 } else { perimeter }))
        .filter(|&(_, t)| t > t0 && t < t1)
        .map(|(c, _)| c)
        .collect()
}

/// The disc of centre `c` and radius `rad` cut to `r`, as one closed loop: the circle's arcs
/// inside, counter-clockwise, each joined to the next by the rectangle's edge (through its
/// corners). The whole circle when it lies inside, the rectangle when the disc holds it, and
/// nothing when they miss.
fn clip_disc(c: Pt, rad: f64, r: &Bounds) -> Vec<Path> {
    let arcs = clip_arc(c, rad, 0.0, TAU, r);
    if arcs.is_empty() {
        // The circle does not cross the inside: the disc holds the rectangle, or misses it.
        let m = [0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1)];
        return if dist(m, c) < rad {
            vec![Path::polyline(vec![[r.x0, r.y0], [r.x1, r.y0], [r.x1, r.y1], [r.x0, r.y1]], true)]
        } else {
            vec![]
        };
    }
    if arcs.len() == 1 && arcs[0].is_closed() {
        return arcs;
    }
    let touch = 1e-12 * (r.width() + r.height() + rad);
    let mut out = Vec::with_capacity(2 * arcs.len());
    for (i, arc) in arcs.iter().enumerate() {
        out.push(arc.clone());
        let (a, b) = (arc.end_point(), arcs[(i + 1) % arcs.len()].start_point());
        let corners = if dist(a, b) <= touch { vec![] } else { corners_between(a, b, r) };
        if !corners.is_empty() || dist(a, b) > touch {
            let mut edge = Vec::with_capacity(corners.len() + 2);
            edge.push(a);
            edge.extend(corners);
            edge.push(b);
            out.push(Path::polyline(edge, false));
        }
    }
    out
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    fn unit() -> Bounds {
        Bounds {
            x0: 0.0,
            y0: 0.0,
            x1: 10.0,
            y1: 10.0,
        }
    }

    #[test]
    fn circle_crossing_a_corner_is_cut_into_arcs_inside() {
        let c = Path::circle([0.0, 5.0], 2.0);
        let parts = clip_path(&c, &unit());
        assert_eq!(parts.len(), 1, "{parts:?}");
        let b = parts[0].bounds();
        assert!(b.inside(&unit(), 1e-12), "{b:?}");
        assert!((parts[0].length() - PI * 2.0).abs() < 1e-9, "half the circle");
        // Through the corner: a quarter.
        let q = clip_path(&Path::circle([0.0, 0.0], 3.0), &unit());
        assert_eq!(q.len(), 1);
        assert!((q[0].length() - 0.5 * PI * 3.0).abs() < 1e-9);
        // Inside: unchanged; outside: nothing.
        assert_eq!(clip_path(&Path::circle([5.0, 5.0], 1.0), &unit()).len(), 1);
        assert!(clip_path(&Path::circle([20.0, 5.0], 1.0), &unit()).is_empty());
    }

    #[test]
    fn polygon_crossing_an_edge_is_cut_into_one_open_piece() {
        let sq = Path::polyline(vec![[-1.0, 4.0], [1.0, 4.0], [1.0, 6.0], [-1.0, 6.0]], true);
        let parts = clip_path(&sq, &unit());
        assert_eq!(parts.len(), 1, "{parts:?}");
        assert!((parts[0].length() - 4.0).abs() < 1e-12, "1 + 2 + 1 mm inside");
        assert!(parts[0].bounds().inside(&unit(), 0.0));
    }

    /// The area inside a loop of pieces (Green's theorem: ½∮ x dy − y dx).
    pub(in crate::model) fn loop_area(pieces: &[Path]) -> f64 {
        let mut a = 0.0;
        for p in pieces {
            match p {
                Path::Polyline { points, closed } => {
                    let n = points.len();
                    let k = if *closed { n } else { n - 1 };
                    for i in 0..k {
                        let (p, q) = (points[i], points[(i + 1) % n]);
                        a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
                    }
                }
                Path::Arc {
                    center: c,
                    radius: r,
                    start,
                    sweep,
                } => {
                    let (t0, t1) = (*start, start + sweep);
                    a += 0.5 * (r * c[0] * (libm::sin(t1) - libm::sin(t0)) - r * c[1] * (libm::cos(t1) - libm::cos(t0)) + r * r * sweep);
                }
            }
        }
        a
    }

    /// Whether each piece starts where the one before it ends, around the loop.
    pub(in crate::model) fn chained(pieces: &[Path]) -> bool {
        let n = pieces.len();
        (0..n).all(|i| dist(pieces[i].end_point(), pieces[(i + 1) % n].start_point()) < 1e-12)
    }

    #[test]
    fn disc_cut_by_the_rectangle_is_one_loop_of_arcs_and_edges() {
        let r = unit();
        // (centre, radius, area inside)
        let cases = [
            ([0.0, 5.0], 2.0, 0.5 * PI * 4.0),
            ([0.0, 0.0], 3.0, 0.25 * PI * 9.0),
            ([10.0, 10.0], 3.0, 0.25 * PI * 9.0),
            ([5.0, 5.0], 1.0, PI),
            ([5.0, 5.0], 20.0, 100.0),
            ([20.0, 5.0], 1.0, 0.0),
        ];
        for (c, rad, want) in cases {
            let loops = clip_area(&Path::circle(c, rad), &r);
            let got: f64 = loops.iter().map(|l| loop_area(l)).sum();
            assert!((got - want).abs() < 1e-9, "{c:?} {rad}: {got} != {want}");
            assert!(loops.len() <= 1 && loops.iter().all(|l| chained(l)), "{loops:?}");
            for p in loops.iter().flatten() {
                assert!(p.bounds().inside(&r, 1e-12), "{p:?}");
            }
        }
        // Across a corner and an edge at once: the area by a fine polygon of the circle.
        let (c, rad) = ([1.0, 3.0], 4.0);
        let ring: Vec<Pt> = (0..20000).map(|k| polar(c, rad, TAU * k as f64 / 20000.0)).collect();
        let want = loop_area(&[Path::polyline(clip_polygon(&ring, &r), true)]);
        let loops = clip_area(&Path::circle(c, rad), &r);
        assert_eq!(loops.len(), 1);
        assert!(chained(&loops[0]));
        assert!((loop_area(&loops[0]) - want).abs() < 1e-3, "{} {want}", loop_area(&loops[0]));
    }

    #[test]
    fn polygon_area_is_clipped_onto_the_edges() {
        let r = unit();
        let sq = [[-1.0, 4.0], [1.0, 4.0], [1.0, 6.0], [-1.0, 6.0]];
        let cut = clip_polygon(&sq, &r);
        assert_eq!(cut, vec![[0.0, 4.0], [1.0, 4.0], [1.0, 6.0], [0.0, 6.0]]);
        // A concave star cut into two parts keeps the area of both.
        let star: Vec<Pt> = (0..10)
            .map(|k| polar([0.0, 5.0], if k % 2 == 0 { 4.0 } else { 1.5 }, 0.1 + PI * k as f64 / 5.0))
            .collect();
        let whole = loop_area(&[Path::polyline(star.clone(), true)]);
        let right = clip_polygon(&star, &r);
        let left = clip_polygon(
            &star,
            &Bounds {
                x0: -10.0,
                y0: 0.0,
                x1: 0.0,
                y1: 10.0,
            },
        );
        let parts = loop_area(&[Path::polyline(right.clone(), true)]) + loop_area(&[Path::polyline(left, true)]);
        assert!((parts - whole).abs() < 1e-12, "{parts} {whole}");
        assert!(right.iter().all(|p| p[0] >= 0.0), "{right:?}");
        assert!(clip_polygon(&[[20.0, 0.0], [21.0, 0.0], [21.0, 1.0]], &r).is_empty());
    }
}
