//! Rings made lighter without making them cross: Douglas–Peucker on each closed ring, then
//! every edge checked against every edge near it, and a ring whose simplified form meets an
//! edge (its own or another ring's) simplified again at half the tolerance, then a quarter,
//! then left as it was. A pure function: the same rings give the same bits.
//!
//! Guarantee: every vertex of a ring lies within the tolerance of the ring it becomes (the
//! Douglas–Peucker bound, measured to the edge that replaced it). When the given rings are
//! simple and meet nowhere, so are the rings returned: a ring is left simplified only if none
//! of its edges touches another edge.
//!
//! What is not checked: which side of a ring another ring lies on. A ring swept whole from one
//! side of a simplified edge to the other would have to lie within the tolerance of that
//! edge, so be thinner than twice the tolerance (a pixel, for a mask); the region is then still
//! valid, with that sliver on the other side of the even-odd rule.

use super::trace::Rings;
use zetafill::Point;

/// The tolerances tried in turn, as fractions of the one asked for; 0 keeps the ring.
const STEPS: [f64; 4] = [1.0, 0.5, 0.25, 0.0];

/// The rings simplified within `tolerance` (their units), none of them crossing another or
/// itself, in the same order.
pub fn simplify(rings: &Rings, tolerance: f64) -> Rings {
    let given: Vec<&[Point<f64>]> = rings.iter().collect();
    let mut step = vec![0usize; given.len()];
    let mut out: Vec<Vec<Point<f64>>> = given.iter().map(|r| ring_at(r, tolerance)).collect();
    loop {
        let bad = crossing_rings(&out);
        let mut changed = false;
        for (i, _) in bad.iter().enumerate().filter(|(_, b)| **b) {
            if step[i] + 1 < STEPS.len() {
                step[i] += 1;
                out[i] = ring_at(given[i], tolerance * STEPS[step[i]]);
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    let mut done = Rings::default();
    for r in &out {
        done.push(r);
    }
    done
}

/// One ring simplified within `tolerance` (unchanged at 0, or when fewer than 3 vertices
/// would be left).
fn ring_at(ring: &[Point<f64>], tolerance: f64) -> Vec<Point<f64>> {
    if tolerance <= 0.0 || ring.len() <= 3 {
        return ring.to_vec();
    }
    let kept = douglas_peucker(ring, tolerance);
    if kept.len() < 3 {
        ring.to_vec()
    } else {
        kept
    }
}

/// Douglas–Peucker on a closed ring: anchored at its first vertex and at the vertex farthest
/// from it, each half simplified on its own (with a stack, so a long ring cannot overflow).
pub fn douglas_peucker(ring: &[Point<f64>], tolerance: f64) -> Vec<Point<f64>> {
    let n = ring.len();
    let Some(&first) = ring.first() else { return Vec::new() };
    let far = (1..n)
        .max_by(|&a, &b| dist2(ring[a], first).total_cmp(&dist2(ring[b], first)))
        .unwrap_or(0);
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[far] = true;
    // Spans (a, b) of indices, b possibly n (the first vertex again).
    let mut stack = vec![(0, far), (far, n)];
    while let Some((a, b)) = stack.pop() {
        let (p, q) = (ring[a % n], ring[b % n]);
        let worst = (a + 1..b)
            .map(|i| (i, segment_distance(ring[i], p, q)))
            .max_by(|x, y| x.1.total_cmp(&y.1));
        if let Some((i, d)) = worst {
            if d > tolerance {
                keep[i] = true;
                stack.push((a, i));
                stack.push((i, b));
            }
        }
    }
    ring.iter().zip(&keep).filter(|(_, k)| **k).map(|(p, _)| *p).collect()
}

fn dist2(a: Point<f64>, b: Point<f64>) -> f64 {
    (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)
}

/// The distance from `p` to the segment `a b`.
pub fn segment_distance(p: Point<f64>, a: Point<f64>, b: Point<f64>) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.x - a.x) * dx + (p.y - a.y) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist2(p, Point::new(a.x + t * dx, a.y + t * dy)).sqrt()
}

/// Which rings have an edge that touches or crosses another edge (of any ring, itself
/// included, edges that follow each other aside unless they fold back). Edges are binned in
/// a grid of cells about as wide as an average edge, each edge in every cell it passes
/// through, and only edges sharing a cell are compared.
pub fn crossing_rings(rings: &[Vec<Point<f64>>]) -> Vec<bool> {
    let mut bad = vec![false; rings.len()];
    let edges: Vec<(usize, usize)> = rings
        .iter()
        .enumerate()
        .flat_map(|(r, ring)| (0..ring.len()).map(move |k| (r, k)))
        .collect();
    let ends = |&(r, k): &(usize, usize)| {
        let ring = &rings[r];
        (ring[k], ring[(k + 1) % ring.len()])
    };
    let Some(grid) = Bins::new(rings, edges.len()) else {
        return bad;
    };
    let mut binned: Vec<(u64, u32)> = Vec::new();
    for (i, e) in edges.iter().enumerate() {
        let (a, b) = ends(e);
        grid.cells(a, b, |cell| binned.push((cell, i as u32)));
    }
    binned.sort_unstable();
    for group in binned.chunk_by(|x, y| x.0 == y.0) {
        for (n, &(_, i)) in group.iter().enumerate() {
            for &(_, j) in &group[n + 1..] {
                let (ei, ej) = (edges[i as usize], edges[j as usize]);
                if meet(ei, ej, rings, ends(&ei), ends(&ej)) {
                    bad[ei.0] = true;
                    bad[ej.0] = true;
                }
            }
        }
    }
    // A ring of fewer than 3 vertices, or of no area, is no ring.
    for (r, ring) in rings.iter().enumerate() {
        if ring.len() < 3 || super::trace::area(ring) == 0.0 {
            bad[r] = true;
        }
    }
    bad
}

/// Whether edges `ei` and `ej` (ring, index of the first vertex) touch where they should not.
fn meet(
    ei: (usize, usize),
    ej: (usize, usize),
    rings: &[Vec<Point<f64>>],
    (a, b): (Point<f64>, Point<f64>),
    (c, d): (Point<f64>, Point<f64>),
) -> bool {
    if ei.0 == ej.0 {
        let n = rings[ei.0].len();
        // Edges that follow each other share a vertex: they meet wrongly only by folding back.
        if (ei.1 + 1) % n == ej.1 {
            return folds(a, b, d);
        }
        if (ej.1 + 1) % n == ei.1 {
            return folds(c, d, b);
        }
    }
    segments_meet(a, b, c, d)
}

/// Whether the path `a b c` turns straight back over itself.
fn folds(a: Point<f64>, b: Point<f64>, c: Point<f64>) -> bool {
    orient(a, b, c) == 0.0 && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) <= 0.0
}

fn orient(a: Point<f64>, b: Point<f64>, c: Point<f64>) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

/// Whether the closed segments `a b` and `c d` have a point in common.
pub fn segments_meet(a: Point<f64>, b: Point<f64>, c: Point<f64>, d: Point<f64>) -> bool {
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        return true;
    }
    let within = |p: Point<f64>, q: Point<f64>, r: Point<f64>| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    (d1 == 0.0 && within(c, d, a)) || (d2 == 0.0 && within(c, d, b)) || (d3 == 0.0 && within(a, b, c)) || (d4 == 0.0 && within(a, b, d))
}

/// A grid of square cells over the rings' box.
struct Bins {
    x0: f64,
    y0: f64,
    side: f64,
    cols: u64,
    rows: u64,
}

impl Bins {
    /// Cells about as wide as an average edge, at most 4096 a side.
    fn new(rings: &[Vec<Point<f64>>], edges: usize) -> Option<Bins> {
        let all = || rings.iter().flatten();
        let (x0, x1) = all().fold((f64::MAX, f64::MIN), |(lo, hi), p| (lo.min(p.x), hi.max(p.x)));
        let (y0, y1) = all().fold((f64::MAX, f64::MIN), |(lo, hi), p| (lo.min(p.y), hi.max(p.y)));
        if edges == 0 || !(x1 >= x0 && y1 >= y0) {
            return None;
        }
        let length: f64 = rings
            .iter()
            .flat_map(|r| (0..r.len()).map(move |k| dist2(r[k], r[(k + 1) % r.len()]).sqrt()))
            .sum();
        let extent = (x1 - x0).max(y1 - y0).max(f64::MIN_POSITIVE);
        let side = (length / edges as f64).max(extent / 4096.0);
        let count = |span: f64| (span / side).floor() as u64 + 1;
        Some(Bins {
            x0,
            y0,
            side,
            cols: count(x1 - x0),
            rows: count(y1 - y0),
        })
    }

    /// Calls `f` with every cell the segment `a b` passes through (and the cells beside them,
    /// so that rounding cannot lose one), row by row.
    fn cells(&self, a: Point<f64>, b: Point<f64>, mut f: impl FnMut(u64)) {
        let col = |x: f64| ((x - self.x0) / self.side).floor().clamp(0.0, (self.cols - 1) as f64) as u64;
        let row = |y: f64| ((y - self.y0) / self.side).floor().clamp(0.0, (self.rows - 1) as f64) as u64;
        let (lo, hi) = if a.y <= b.y { (a, b) } else { (b, a) };
        let (r0, r1) = (row(lo.y), row(hi.y));
        for r in r0.saturating_sub(1)..=(r1 + 1).min(self.rows - 1) {
            // The part of the segment within this row's band of y.
            let band = |y: f64| y.clamp(lo.y, hi.y);
            let (ya, yb) = (band(self.y0 + r as f64 * self.side), band(self.y0 + (r + 1) as f64 * self.side));
            let x_at = |y: f64| {
                if hi.y > lo.y {
                    lo.x + (hi.x - lo.x) * (y - lo.y) / (hi.y - lo.y)
                } else {
                    lo.x
                }
            };
            let (xa, xb) = if hi.y > lo.y { (x_at(ya), x_at(yb)) } else { (a.x, b.x) };
            let (c0, c1) = (col(xa.min(xb)), col(xa.max(xb)));
            for c in c0.saturating_sub(1)..=(c1 + 1).min(self.cols - 1) {
                f(r * self.cols + c);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(xy: &[(f64, f64)]) -> Vec<Point<f64>> {
        xy.iter().map(|&(x, y)| Point::new(x, y)).collect()
    }

    /// A circle of radius `r` as `n` vertices.
    fn circle(cx: f64, cy: f64, r: f64, n: usize) -> Vec<Point<f64>> {
        (0..n)
            .map(|k| {
                let t = k as f64 / n as f64 * std::f64::consts::TAU;
                Point::new(cx + r * libm::cos(t), cy + r * libm::sin(t))
            })
            .collect()
    }

    /// The largest distance from a vertex of `from` to the ring `to`.
    fn farthest(from: &[Point<f64>], to: &[Point<f64>]) -> f64 {
        from.iter()
            .map(|&p| {
                (0..to.len())
                    .map(|k| segment_distance(p, to[k], to[(k + 1) % to.len()]))
                    .fold(f64::MAX, f64::min)
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn every_vertex_stays_within_the_tolerance() {
        let c = circle(0.0, 0.0, 50.0, 2000);
        let s = douglas_peucker(&c, 0.5);
        assert!(s.len() < 100, "{}", s.len());
        assert!(farthest(&c, &s) <= 0.5);
        // The check can fail: a coarser ring is farther than half a unit.
        let coarse = douglas_peucker(&c, 3.0);
        assert!(farthest(&c, &coarse) > 0.5);
    }

    #[test]
    fn crossings_are_found_and_repaired() {
        // Two squares touching at a corner, a bow tie, and two apart.
        let a = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let b = ring(&[(1.0, 1.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0)]);
        let tie = ring(&[(5.0, 0.0), (6.0, 1.0), (6.0, 0.0), (5.0, 1.0)]);
        let far = ring(&[(9.0, 9.0), (10.0, 9.0), (10.0, 10.0)]);
        assert_eq!(crossing_rings(&[a, b, tie, far]), [true, true, true, false]);
        // A square with a notch in its top, and a sliver of a triangle standing in the notch:
        // at 1.5 units the notch goes and the top edge cuts the triangle; the repair keeps
        // the notch (at 0.75) and drops the rest.
        let notched = ring(&[
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 10.0),
            (5.5, 10.0),
            (5.0, 9.0),
            (4.5, 10.0),
            (0.0, 10.0),
        ]);
        let sliver = ring(&[(4.9, 9.5), (5.1, 9.5), (5.0, 10.5)]);
        assert_eq!(crossing_rings(&[notched.clone(), sliver.clone()]), [false, false]);
        let rough = vec![douglas_peucker(&notched, 1.5), sliver.clone()];
        assert_eq!(crossing_rings(&rough), [true, true], "the twin does not cross");
        let mut rings = Rings::default();
        rings.push(&notched);
        rings.push(&sliver);
        let fine = simplify(&rings, 1.5);
        let out: Vec<Vec<Point<f64>>> = fine.iter().map(<[_]>::to_vec).collect();
        assert_eq!(crossing_rings(&out), [false, false]);
        assert!(out[0].contains(&Point::new(5.0, 9.0)));
    }
}
