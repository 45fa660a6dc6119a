//! Exact cutting to any region, for a symmetric fill drawn inside `--region`: strokes and
//! areas are cut at their crossings with the region's outline (closed polylines and full
//! circles, filled by the even-odd rule). A rectangle keeps the cut of [`super::clip`].
//!
//! - Strokes ([`Window::cut_path`]): each segment or arc split at every crossing with an
//!   outline edge, the pieces kept whose middle lies inside, and pieces that meet joined
//!   again. What a pen draws.
//! - Areas ([`Window::cut_area`]): the boundary of a closed path's area inside the region is
//!   the path's pieces inside the region and the region's outline pieces inside the path;
//!   they are chained end to end into closed loops. What a filled shape covers.
//!
//! Cut points are computed on both sides of each crossing; a loop joins them by nearness,
//! and writers draw a loop from piece end to piece end, so the join leaves no gap.

use super::clip::{arc_pieces, lerp, norm_angle};
use super::path::dist;
use super::{polar, Bounds, Path, Pt};
use std::f64::consts::TAU;

/// One edge of an outline.
#[derive(Debug, Clone, Copy)]
enum Edge {
    /// A segment.
    Seg(Pt, Pt),
    /// A full circle: centre and radius.
    Circle(Pt, f64),
}

/// Whether two boxes share a point.
fn meet(a: &Bounds, b: &Bounds) -> bool {
    a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1
}

fn cross(a: Pt, b: Pt) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn sub(a: Pt, b: Pt) -> Pt {
    [a[0] - b[0], a[1] - b[1]]
}

/// The parameters `t` in `[0, 1]` at which segment `a -> b` crosses the circle `(c, r)`;
/// a tangent touch is no crossing.
fn seg_circle(a: Pt, b: Pt, c: Pt, r: f64, out: &mut Vec<f64>) {
    let (d, f) = (sub(b, a), sub(a, c));
    let qa = d[0] * d[0] + d[1] * d[1];
    let qb = 2.0 * (f[0] * d[0] + f[1] * d[1]);
    let qc = f[0] * f[0] + f[1] * f[1] - r * r;
    let disc = qb * qb - 4.0 * qa * qc;
    if qa == 0.0 || disc <= 0.0 {
        return;
    }
    // The root without cancellation first, the other from the product of the roots.
    let q = -0.5 * (qb + disc.sqrt().copysign(qb));
    for t in [q / qa, if q != 0.0 { qc / q } else { f64::NAN }] {
        if (0.0..=1.0).contains(&t) {
            out.push(t);
        }
    }
}

/// The parameter `t` in `[0, 1]` at which segment `a -> b` crosses segment `p -> q`
/// (parallel segments do not cross).
fn seg_seg(a: Pt, b: Pt, p: Pt, q: Pt) -> Option<f64> {
    let (d, e, ap) = (sub(b, a), sub(q, p), sub(p, a));
    let den = cross(d, e);
    if den == 0.0 {
        return None;
    }
    let (t, u) = (cross(ap, e) / den, cross(ap, d) / den);
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some(t)
}

/// A run of kept pieces of a polyline: its points, and where it starts and ends (segment,
/// parameter along it).
type Run = (Vec<Pt>, (usize, f64), (usize, f64));

/// The region inside a set of outlines (closed polylines and full circles) by the even-odd
/// rule, ready to cut paths to.
#[derive(Debug, Clone)]
pub struct Window {
    rings: Vec<Path>,
    edges: Vec<(Edge, Bounds)>,
    bounds: Bounds,
}

impl Window {
    /// The region inside `rings` by the even-odd rule. Open pieces and arcs short of a full
    /// circle bound nothing and are left out.
    pub fn new(rings: &[Path]) -> Window {
        let mut edges = Vec::new();
        let mut bounds = Bounds::EMPTY;
        let rings: Vec<Path> = rings.iter().filter(|r| r.is_closed()).cloned().collect();
        for r in &rings {
            match r {
                Path::Polyline { points, .. } => {
                    let n = points.len();
                    for i in 0..n {
                        let (a, b) = (points[i], points[(i + 1) % n]);
                        let mut eb = Bounds::EMPTY;
                        eb.add(a);
                        eb.add(b);
                        edges.push((Edge::Seg(a, b), eb));
                    }
                }
                Path::Arc { center, radius, .. } => edges.push((Edge::Circle(*center, *radius), r.bounds())),
            }
            let rb = r.bounds();
            bounds.add([rb.x0, rb.y0]);
            bounds.add([rb.x1, rb.y1]);
        }
        Window { rings, edges, bounds }
    }

    /// The bounding box of the outlines.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }

    /// Whether `p` lies inside (an odd number of outlines around it).
    pub fn contains(&self, p: Pt) -> bool {
        let mut inside = false;
        for (e, _) in &self.edges {
            match *e {
                Edge::Seg(a, b) => {
                    if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) {
                        inside = !inside;
                    }
                }
                Edge::Circle(c, r) => {
                    let d = sub(p, c);
                    if d[0] * d[0] + d[1] * d[1] < r * r {
                        inside = !inside;
                    }
                }
            }
        }
        inside
    }

    /// Whether an outline edge's box meets `b` (otherwise what lies in `b` is wholly inside
    /// or wholly outside).
    pub fn meets(&self, b: &Bounds) -> bool {
        meet(b, &self.bounds) && self.edges.iter().any(|(_, eb)| meet(b, eb))
    }

    fn near(&self, b: &Bounds) -> Vec<Edge> {
        self.edges.iter().filter(|(_, eb)| meet(b, eb)).map(|(e, _)| *e).collect()
    }

    /// The pieces of `p` inside the region (what a pen draws of it there): `p` itself when
    /// no outline crosses it and it lies inside, nothing when it lies outside.
    pub fn cut_path(&self, p: &Path) -> Vec<Path> {
        let b = p.bounds();
        if !meet(&b, &self.bounds) {
            return vec![];
        }
        let near = self.near(&b);
        let whole = || if self.contains(p.start_point()) { vec![p.clone()] } else { vec![] };
        if near.is_empty() {
            return whole();
        }
        match p {
            Path::Polyline { points, closed } => self.cut_polyline(points, *closed, &near).unwrap_or_else(whole),
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => self.cut_arc(*center, *radius, *start, *sweep, &near).unwrap_or_else(whole),
        }
    }

    /// A polyline's pieces inside; `None` when no edge crosses it.
    fn cut_polyline(&self, points: &[Pt], closed: bool, near: &[Edge]) -> Option<Vec<Path>> {
        let n = points.len();
        let m = if closed { n } else { n.saturating_sub(1) };
        if m == 0 || n < 2 {
            return Some(vec![]);
        }
        let mut crossed = false;
        // Runs of kept pieces: their points, where they start (segment, t) and end.
        let mut runs: Vec<Run> = Vec::new();
        let mut ts = Vec::new();
        for i in 0..m {
            let (a, b) = (points[i], points[(i + 1) % n]);
            ts.clear();
            ts.push(0.0);
            ts.push(1.0);
            for e in near {
                match *e {
                    Edge::Seg(p, q) => ts.extend(seg_seg(a, b, p, q)),
                    Edge::Circle(c, r) => seg_circle(a, b, c, r, &mut ts),
                }
            }
            ts.sort_by(f64::total_cmp);
            ts.dedup();
            crossed |= ts.len() > 2;
            for w in ts.windows(2) {
                let (t0, t1) = (w[0], w[1]);
                if t1 <= t0 || !self.contains(lerp(a, b, 0.5 * (t0 + t1))) {
                    continue;
                }
                // A piece continues the last run where that ended: at this cut, or at the
                // end of the segment before.
                let joins = matches!(runs.last(), Some((_, _, end)) if *end == (i, t0) || t0 == 0.0 && i > 0 && *end == (i - 1, 1.0));
                match runs.last_mut() {
                    Some((pts, _, end)) if joins => {
                        pts.push(lerp(a, b, t1));
                        *end = (i, t1);
                    }
                    _ => runs.push((vec![lerp(a, b, t0), lerp(a, b, t1)], (i, t0), (i, t1))),
                }
            }
        }
        if !crossed {
            return None;
        }
        if closed && runs.len() > 1 {
            // A run through the first vertex continues across the seam.
            let (first_start, last_end) = (runs[0].1, runs[runs.len() - 1].2);
            if first_start == (0, 0.0) && last_end == (m - 1, 1.0) {
                if let Some((mut tail, start, _)) = runs.pop() {
                    tail.extend(runs[0].0.iter().skip(1));
                    runs[0].0 = tail;
                    runs[0].1 = start;
                }
            }
        }
        Some(runs.into_iter().map(|(pts, _, _)| Path::polyline(pts, false)).collect())
    }

    /// An arc's pieces inside; `None` when no edge crosses it.
    fn cut_arc(&self, c: Pt, rad: f64, start: f64, sweep: f64, near: &[Edge]) -> Option<Vec<Path>> {
        // Work counter-clockwise; a clockwise arc is cut reversed and turned back.
        if sweep < 0.0 && sweep.abs() < TAU {
            return self
                .cut_arc(c, rad, start + sweep, -sweep, near)
                .map(|v| v.into_iter().rev().map(|p| p.reversed()).collect());
        }
        let full = sweep >= TAU;
        let (s0, span) = if full { (0.0, TAU) } else { (norm_angle(start), sweep) };
        let mut cuts: Vec<f64> = vec![0.0, span];
        let mut add = |p: Pt| {
            let rel = norm_angle(libm::atan2(p[1] - c[1], p[0] - c[0]) - s0);
            if rel > 0.0 && rel < span {
                cuts.push(rel);
            }
        };
        let mut ts = Vec::new();
        for e in near {
            match *e {
                Edge::Seg(p, q) => {
                    ts.clear();
                    seg_circle(p, q, c, rad, &mut ts);
                    for &t in &ts {
                        add(lerp(p, q, t));
                    }
                }
                Edge::Circle(c2, r2) => {
                    let d = dist(c, c2);
                    if d > 0.0 && d < rad + r2 && d > (rad - r2).abs() {
                        let along = (rad * rad - r2 * r2 + d * d) / (2.0 * d);
                        let base = libm::atan2(c2[1] - c[1], c2[0] - c[0]);
                        let delta = libm::acos((along / rad).clamp(-1.0, 1.0));
                        for a in [base - delta, base + delta] {
                            add(polar(c, rad, a));
                        }
                    }
                }
            }
        }
        if cuts.len() == 2 {
            return None;
        }
        Some(arc_pieces(c, rad, s0, full, cuts, |p| self.contains(p)))
    }

    /// The part of a closed path's area inside the region, as closed loops, each a chain of
    /// pieces that meet end to start: the path itself when it lies inside, the outlines it
    /// holds whole, and otherwise its pieces inside joined by the outline's pieces inside it.
    /// An open path has no area and gives nothing.
    pub fn cut_area(&self, p: &Path) -> Vec<Vec<Path>> {
        if !p.is_closed() {
            return vec![];
        }
        let mine = self.cut_path(p);
        // The outlines' pieces inside the path (an outline it holds whole is a loop of its
        // own: a hole of the region inside the shape).
        let shape = Window::new(std::slice::from_ref(p));
        let pb = p.bounds();
        let theirs = self.rings.iter().filter(|r| meet(&r.bounds(), &pb)).flat_map(|r| shape.cut_path(r));
        let mut loops = Vec::new();
        let mut open = Vec::new();
        for piece in mine.into_iter().chain(theirs) {
            if piece.is_closed() {
                loops.push(vec![piece]);
            } else {
                open.push(piece);
            }
        }
        // Each loop is closed by the piece whose end lies nearest the last one's end, until
        // its own start is the nearest.
        open.reverse();
        while let Some(first) = open.pop() {
            let begin = first.start_point();
            let mut end = first.end_point();
            let mut lp = vec![first];
            loop {
                let best = open
                    .iter()
                    .enumerate()
                    .flat_map(|(i, q)| [(i, false, dist(q.start_point(), end)), (i, true, dist(q.end_point(), end))])
                    .min_by(|a, b| a.2.total_cmp(&b.2));
                match best {
                    Some((i, rev, d)) if d < dist(begin, end) => {
                        let q = open.remove(i);
                        let q = if rev { q.reversed() } else { q };
                        end = q.end_point();
                        lp.push(q);
                    }
                    _ => break,
                }
            }
            loops.push(lp);
        }
        loops
    }
}

#[cfg(test)]
mod tests {
    use super::super::clip::tests::chained;
    use super::*;
    use std::f64::consts::PI;

    fn disc(r: f64) -> Window {
        Window::new(&[Path::circle([0.0, 0.0], r)])
    }

    /// The area a loop of pieces bounds, its sign dropped.
    fn loop_area(pieces: &[Path]) -> f64 {
        super::super::clip::tests::loop_area(pieces).abs()
    }

    #[test]
    fn a_square_across_a_disc_is_cut_at_the_circle() {
        let w = disc(10.0);
        // Half in, half out, across the circle at x = 10.
        let sq = Path::polyline(vec![[9.0, -1.0], [11.0, -1.0], [11.0, 1.0], [9.0, 1.0]], true);
        let parts = w.cut_path(&sq);
        assert_eq!(parts.len(), 1, "{parts:?}");
        for p in &parts {
            let b = p.bounds();
            assert!(libm::hypot(b.x1, b.y1.abs().max(b.y0.abs())) <= 10.0 + 1e-12, "{b:?}");
        }
        // Inside: itself; outside: nothing.
        let inner = Path::polyline(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], true);
        assert_eq!(w.cut_path(&inner), vec![inner.clone()]);
        let far = Path::polyline(vec![[20.0, 0.0], [21.0, 0.0], [21.0, 1.0]], true);
        assert!(w.cut_path(&far).is_empty());
    }

    #[test]
    fn an_area_cut_to_a_disc_has_the_area_of_the_intersection() {
        let w = disc(10.0);
        // The square [0, 20] x [-5, 5] meets the disc in a segment of it; its area by
        // integration: the band |y| <= 5 of the right half-disc.
        let sq = Path::polyline(vec![[0.0, -5.0], [20.0, -5.0], [20.0, 5.0], [0.0, 5.0]], true);
        let loops = w.cut_area(&sq);
        assert_eq!(loops.len(), 1, "{loops:?}");
        assert!(chained(&loops[0]), "{loops:?}");
        let (r, h): (f64, f64) = (10.0, 5.0);
        let band = h * (r * r - h * h).sqrt() + r * r * libm::asin(h / r);
        assert!((loop_area(&loops[0]) - band).abs() < 1e-9, "{} vs {band}", loop_area(&loops[0]));
    }

    #[test]
    fn two_discs_meet_in_a_lens() {
        let w = disc(5.0);
        let other = Path::circle([6.0, 0.0], 5.0);
        let loops = w.cut_area(&other);
        assert_eq!(loops.len(), 1);
        assert!(chained(&loops[0]));
        // The lens of two radius-5 discs 6 apart: 2 r² acos(d / 2r) - (d / 2) sqrt(4 r² - d²).
        let lens = 2.0 * 25.0 * libm::acos(0.6) - 3.0 * (100.0f64 - 36.0).sqrt();
        assert!((loop_area(&loops[0]) - lens).abs() < 1e-9);
        // The strokes: the arc of the other circle inside this one, a third of it and a bit.
        let arcs = w.cut_path(&other);
        assert_eq!(arcs.len(), 1);
        assert!((arcs[0].length() - 5.0 * 2.0 * libm::acos(0.6)).abs() < 1e-9);
    }

    #[test]
    fn a_hole_in_the_region_cuts_a_hole_in_the_area() {
        // An annulus 2..10; a disc of radius 4 at the centre keeps the ring 2..4.
        let w = Window::new(&[Path::circle([0.0, 0.0], 10.0), Path::circle([0.0, 0.0], 2.0)]);
        let loops = w.cut_area(&Path::circle([0.0, 0.0], 4.0));
        let mut areas: Vec<f64> = loops.iter().map(|l| loop_area(l)).collect();
        areas.sort_by(f64::total_cmp);
        assert_eq!(loops.len(), 2, "{loops:?}");
        assert!((areas[1] - areas[0] - PI * (16.0 - 4.0)).abs() < 1e-9, "{areas:?}");
        assert!(!w.contains([0.0, 0.0]) && w.contains([5.0, 0.0]) && !w.contains([11.0, 0.0]));
    }

    #[test]
    fn a_concave_region_splits_a_stroke_in_two() {
        // A U: the square [0, 30]^2 less the notch [10, 20] x [10, 30].
        let u = Path::polyline(
            vec![
                [0.0, 0.0],
                [30.0, 0.0],
                [30.0, 30.0],
                [20.0, 30.0],
                [20.0, 10.0],
                [10.0, 10.0],
                [10.0, 30.0],
                [0.0, 30.0],
            ],
            true,
        );
        let w = Window::new(&[u]);
        let line = Path::polyline(vec![[5.0, 20.0], [25.0, 20.0]], false);
        let parts = w.cut_path(&line);
        assert_eq!(parts.len(), 2, "{parts:?}");
        assert!((parts.iter().map(Path::length).sum::<f64>() - 10.0).abs() < 1e-12);
        // The area of a bar across the notch: two loops of 5 x 2 each.
        let bar = Path::polyline(vec![[5.0, 19.0], [25.0, 19.0], [25.0, 21.0], [5.0, 21.0]], true);
        let loops = w.cut_area(&bar);
        assert_eq!(loops.len(), 2, "{loops:?}");
        for l in &loops {
            assert!(chained(l));
            assert!((loop_area(l) - 10.0).abs() < 1e-9, "{}", loop_area(l));
        }
        // A circle around the notch's floor, crossing three edges.
        let arcs = w.cut_path(&Path::circle([15.0, 10.0], 3.0));
        let inside: f64 = arcs.iter().map(Path::length).sum();
        assert!((inside - 3.0 * PI).abs() < 1e-9, "the lower half: {inside}");
    }
}
