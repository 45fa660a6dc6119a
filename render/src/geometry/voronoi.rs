//! Plane geometry shared by the territory renders and the cobblestones: exact clipping of
//! segments to a region (rectangle, disc, annulus, polygon with holes), the Voronoi edges of a
//! spade triangulation as dual segments with shared vertex ids, the merging of edges into long
//! polylines (every edge exactly once), and convex cells by half-plane clipping.
//!
//! Deterministic: every loop runs in index order; no hash-map iteration decides an output.

use crate::model::doc::RegionDoc;
use spade::handles::{FixedVertexHandle, VertexHandle};
use spade::{HasPosition, Point2, Triangulation};

/// A point (x, y) in mm, in the region's frame (y up).
pub type Pt = [f64; 2];

/// A region that segments are clipped to: the same set the core's regions describe.
#[derive(Debug, Clone, PartialEq)]
pub enum Clip {
    /// The box `[x0, x1] x [y0, y1]`.
    Rect {
        /// Left.
        x0: f64,
        /// Bottom.
        y0: f64,
        /// Right.
        x1: f64,
        /// Top.
        y1: f64,
    },
    /// A disc.
    Circle {
        /// Centre.
        c: Pt,
        /// Radius.
        r: f64,
    },
    /// The ring between two circles.
    Annulus {
        /// Centre.
        c: Pt,
        /// Outer radius.
        ro: f64,
        /// Inner radius.
        ri: f64,
    },
    /// Closed outlines filled by the even-odd rule.
    Polygon {
        /// Rings of vertices (each implicitly closed).
        rings: Vec<Vec<Pt>>,
    },
}

impl Clip {
    /// The clip region of a document's region (periodic rectangles clip to their tile).
    pub fn from_doc(r: &RegionDoc) -> Clip {
        match r {
            RegionDoc::Rect { width, height, .. } | RegionDoc::Wallpaper { width, height, .. } => Clip::Rect {
                x0: 0.0,
                y0: 0.0,
                x1: *width,
                y1: *height,
            },
            RegionDoc::Circle { center, radius } => Clip::Circle { c: *center, r: *radius },
            RegionDoc::Annulus {
                center,
                radius_outer,
                radius_inner,
            } => Clip::Annulus {
                c: *center,
                ro: *radius_outer,
                ri: *radius_inner,
            },
            RegionDoc::Polygon { vertices, holes, outers } => Clip::Polygon {
                rings: std::iter::once(vertices).chain(outers).chain(holes).cloned().collect(),
            },
        }
    }

    /// Bounding box (x0, y0, x1, y1).
    pub fn bbox(&self) -> (f64, f64, f64, f64) {
        match self {
            Clip::Rect { x0, y0, x1, y1 } => (*x0, *y0, *x1, *y1),
            Clip::Circle { c, r } | Clip::Annulus { c, ro: r, .. } => (c[0] - r, c[1] - r, c[0] + r, c[1] + r),
            Clip::Polygon { rings } => rings.iter().flatten().fold((f64::MAX, f64::MAX, f64::MIN, f64::MIN), |b, v| {
                (b.0.min(v[0]), b.1.min(v[1]), b.2.max(v[0]), b.3.max(v[1]))
            }),
        }
    }

    /// Whether the region is its own bounding box (so clipping a cell to the box is exact).
    pub fn is_rect(&self) -> bool {
        matches!(self, Clip::Rect { .. })
    }

    /// Whether `p` is inside (boundary points count as inside for rectangles and discs).
    pub fn inside(&self, p: Pt) -> bool {
        match self {
            Clip::Rect { x0, y0, x1, y1 } => p[0] >= *x0 && p[0] <= *x1 && p[1] >= *y0 && p[1] <= *y1,
            Clip::Circle { c, r } => dist2(p, *c) <= r * r,
            Clip::Annulus { c, ro, ri } => {
                let d = dist2(p, *c);
                d <= ro * ro && d >= ri * ri
            }
            Clip::Polygon { rings } => {
                let mut inside = false;
                for ring in rings {
                    let n = ring.len();
                    for i in 0..n {
                        let (a, b) = (ring[i], ring[(i + 1) % n]);
                        if (a[1] > p[1]) != (b[1] > p[1]) {
                            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                            if p[0] < x {
                                inside = !inside;
                            }
                        }
                    }
                }
                inside
            }
        }
    }

    /// The parameter intervals `[t0, t1]` of the segment `a + t (b - a)`, `0 <= t <= 1`, that
    /// lie inside the region, in increasing order. Exact up to rounding: the crossings with the
    /// boundary are solved analytically (lines, circles) and each piece between two crossings
    /// is kept when its midpoint is inside.
    pub fn segment(&self, a: Pt, b: Pt) -> Vec<(f64, f64)> {
        let d = [b[0] - a[0], b[1] - a[1]];
        if let Clip::Rect { x0, y0, x1, y1 } = self {
            // Liang–Barsky: one interval at most.
            let (mut t0, mut t1) = (0.0f64, 1.0f64);
            for (p, q) in [(-d[0], a[0] - x0), (d[0], x1 - a[0]), (-d[1], a[1] - y0), (d[1], y1 - a[1])] {
                if p == 0.0 {
                    if q < 0.0 {
                        return Vec::new();
                    }
                } else {
                    let r = q / p;
                    if p < 0.0 {
                        t0 = t0.max(r);
                    } else {
                        t1 = t1.min(r);
                    }
                }
            }
            return if t0 < t1 { vec![(t0, t1)] } else { Vec::new() };
        }
        let mut ts = vec![0.0, 1.0];
        let mut circle = |c: Pt, r: f64| {
            // |a + t d - c|^2 = r^2.
            let f = [a[0] - c[0], a[1] - c[1]];
            let qa = d[0] * d[0] + d[1] * d[1];
            if qa == 0.0 {
                return;
            }
            let qb = f[0] * d[0] + f[1] * d[1];
            let qc = f[0] * f[0] + f[1] * f[1] - r * r;
            let disc = qb * qb - qa * qc;
            if disc > 0.0 {
                let s = disc.sqrt();
                // The numerically stable pair of roots.
                let q = if qb >= 0.0 { -(qb + s) } else { -qb + s };
                for t in [q / qa, if q != 0.0 { qc / q } else { 0.0 }] {
                    if t > 0.0 && t < 1.0 {
                        ts.push(t);
                    }
                }
            }
        };
        match self {
            Clip::Rect { .. } => {}
            Clip::Circle { c, r } => circle(*c, *r),
            Clip::Annulus { c, ro, ri } => {
                circle(*c, *ro);
                circle(*c, *ri);
            }
            Clip::Polygon { rings } => {
                for ring in rings {
                    let n = ring.len();
                    for i in 0..n {
                        if let Some(t) = cross_param(a, d, ring[i], ring[(i + 1) % n]) {
                            ts.push(t);
                        }
                    }
                }
            }
        }
        ts.sort_by(f64::total_cmp);
        ts.dedup();
        let mut out: Vec<(f64, f64)> = Vec::new();
        for w in ts.windows(2) {
            let (t0, t1) = (w[0], w[1]);
            if t1 <= t0 {
                continue;
            }
            let tm = 0.5 * (t0 + t1);
            if self.inside([a[0] + tm * d[0], a[1] + tm * d[1]]) {
                match out.last_mut() {
                    Some(last) if last.1 == t0 => last.1 = t1,
                    _ => out.push((t0, t1)),
                }
            }
        }
        out
    }

    /// The point at parameter `t` of `a -> b`, snapped onto a rectangle's side when it lies
    /// within rounding of it (so that pieces of a periodic tile meet exactly).
    pub fn at(&self, a: Pt, b: Pt, t: f64) -> Pt {
        if t == 0.0 {
            return a;
        }
        if t == 1.0 {
            return b;
        }
        let mut p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
        if let Clip::Rect { x0, y0, x1, y1 } = self {
            let tol = 1e-9 * (x1 - x0).abs().max(y1 - y0).max(1.0);
            let snap = |v: f64, lo: f64, hi: f64| {
                if (v - lo).abs() <= tol {
                    lo
                } else if (v - hi).abs() <= tol {
                    hi
                } else {
                    v
                }
            };
            p = [snap(p[0], *x0, *x1), snap(p[1], *y0, *y1)];
        }
        p
    }

    /// Clips a polyline: the pieces inside, in order. Consecutive inside segments stay one
    /// piece.
    pub fn polyline(&self, pts: &[Pt]) -> Vec<Vec<Pt>> {
        let mut out: Vec<Vec<Pt>> = Vec::new();
        let mut open = false;
        for w in pts.windows(2) {
            let (a, b) = (w[0], w[1]);
            let pieces = self.segment(a, b);
            let last = pieces.len();
            for (i, (t0, t1)) in pieces.into_iter().enumerate() {
                let (p0, p1) = (self.at(a, b, t0), self.at(a, b, t1));
                if t0 == 0.0 && open {
                    if let Some(cur) = out.last_mut() {
                        cur.push(p1);
                    }
                } else {
                    out.push(vec![p0, p1]);
                }
                open = t1 == 1.0 && i + 1 == last;
            }
            if last == 0 {
                open = false;
            }
        }
        out
    }
}

/// The parameter t in (0, 1) where `a + t d` crosses the segment `p -> q`, if it does.
fn cross_param(a: Pt, d: Pt, p: Pt, q: Pt) -> Option<f64> {
    let e = [q[0] - p[0], q[1] - p[1]];
    let den = d[0] * e[1] - d[1] * e[0];
    if den == 0.0 {
        return None;
    }
    let ap = [p[0] - a[0], p[1] - a[1]];
    let t = (ap[0] * e[1] - ap[1] * e[0]) / den;
    let u = (ap[0] * d[1] - ap[1] * d[0]) / den;
    (t > 0.0 && t < 1.0 && (0.0..=1.0).contains(&u)).then_some(t)
}

/// The signed area of a polygon (positive when counter-clockwise).
pub fn area(poly: &[Pt]) -> f64 {
    let n = poly.len();
    (0..n)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        / 2.0
}

/// Squared distance.
pub fn dist2(a: Pt, b: Pt) -> f64 {
    let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
    dx * dx + dy * dy
}

/// One Voronoi edge: the dual of the Delaunay edge between sites `sites.0` and `sites.1`,
/// running between the vertices `ends` (indices into [`Dual::points`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DualEdge {
    /// The two sites (vertex indices) the edge separates, smaller first.
    pub sites: (usize, usize),
    /// The edge's two end vertices.
    pub ends: (usize, usize),
}

/// The Voronoi diagram of a triangulation as edges over shared vertices: a circumcentre per
/// inner face (shared by the three edges that meet there, so polylines join exactly), and a
/// far point per unbounded ray (beyond the clip box, so clipping cuts it where it leaves).
#[derive(Debug, Clone, Default)]
pub struct Dual {
    /// Vertex positions.
    pub points: Vec<Pt>,
    /// One edge per Delaunay edge, in spade's undirected-edge order.
    pub edges: Vec<DualEdge>,
}

impl Dual {
    /// The dual of `tri`; rays are cut at a distance that takes them past the box `bbox`.
    pub fn of<T>(tri: &T, bbox: (f64, f64, f64, f64)) -> Dual
    where
        T: Triangulation,
        T::Vertex: HasPosition<Scalar = f64>,
    {
        let nf = tri.num_all_faces();
        let mut face_point = vec![usize::MAX; nf];
        let mut points: Vec<Pt> = Vec::with_capacity(tri.num_inner_faces() + 64);
        for f in tri.inner_faces() {
            let c = f.circumcenter();
            face_point[f.fix().index()] = points.len();
            points.push([c.x, c.y]);
        }
        let (bx0, by0, bx1, by1) = bbox;
        let centre = [0.5 * (bx0 + bx1), 0.5 * (by0 + by1)];
        let span = ((bx1 - bx0).powi(2) + (by1 - by0).powi(2)).sqrt().max(1.0);
        // A point along `dir` from `from` that lies beyond every point of the box.
        let far = |from: Pt, dir: Pt| -> Pt {
            let len = (dir[0] * dir[0] + dir[1] * dir[1]).sqrt();
            let reach = dist2(from, centre).sqrt() + 2.0 * span;
            [from[0] + dir[0] / len * reach, from[1] + dir[1] / len * reach]
        };
        let mut edges = Vec::with_capacity(tri.num_undirected_edges());
        for e in tri.undirected_edges() {
            let d = e.as_directed();
            let (u, v) = (d.from(), d.to());
            let (pu, pv) = (pos(&u), pos(&v));
            let mid = [0.5 * (pu[0] + pv[0]), 0.5 * (pu[1] + pv[1])];
            // Perpendicular to u -> v, pointing to the right of it (towards d.rev()'s face).
            let right = [pv[1] - pu[1], -(pv[0] - pu[0])];
            let lf = d.face().as_inner().map(|f| face_point[f.fix().index()]);
            let rf = d.rev().face().as_inner().map(|f| face_point[f.fix().index()]);
            let add = |p: Pt, pts: &mut Vec<Pt>| {
                pts.push(p);
                pts.len() - 1
            };
            let ends = match (lf, rf) {
                (Some(a), Some(b)) => (a, b),
                // Hull edge with its triangle on the left: the ray goes right (outwards).
                (Some(a), None) => {
                    let p = far(points[a], right);
                    (a, add(p, &mut points))
                }
                (None, Some(b)) => {
                    let p = far(points[b], [-right[0], -right[1]]);
                    (add(p, &mut points), b)
                }
                // All sites on one line: the whole bisector.
                (None, None) => {
                    let p = far(mid, right);
                    let q = far(mid, [-right[0], -right[1]]);
                    (add(p, &mut points), add(q, &mut points))
                }
            };
            let (a, b) = (u.fix().index(), v.fix().index());
            edges.push(DualEdge {
                sites: (a.min(b), a.max(b)),
                ends,
            });
        }
        Dual { points, edges }
    }
}

fn pos<V: HasPosition<Scalar = f64>, DE: Default, UE: Default, F: Default>(v: &VertexHandle<'_, V, DE, UE, F>) -> Pt {
    let p = v.position();
    [p.x, p.y]
}

/// Merges edges over vertices `0..n` into polylines of vertex ids that use every edge exactly
/// once: walks start at odd-degree vertices (ends and triple junctions) first, then close the
/// remaining loops; at each step the unused edge with the smallest index is taken.
pub fn merge(n: usize, edges: &[(usize, usize)]) -> Vec<Vec<usize>> {
    // Compressed adjacency: for each vertex its incident edge indices in order.
    let mut start = vec![0usize; n + 1];
    for &(a, b) in edges {
        start[a + 1] += 1;
        start[b + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut inc = vec![0usize; start[n]];
    for (i, &(a, b)) in edges.iter().enumerate() {
        inc[fill[a]] = i;
        fill[a] += 1;
        inc[fill[b]] = i;
        fill[b] += 1;
    }
    let mut cursor = start.clone();
    let mut used = vec![false; edges.len()];
    let mut left: Vec<usize> = (0..n).map(|v| start[v + 1] - start[v]).collect();
    let mut out = Vec::new();
    let walk = |v0: usize, used: &mut Vec<bool>, left: &mut Vec<usize>, cursor: &mut Vec<usize>| {
        let mut line = vec![v0];
        let mut v = v0;
        loop {
            let mut next = None;
            while cursor[v] < start[v + 1] {
                let e = inc[cursor[v]];
                cursor[v] += 1;
                if !used[e] {
                    next = Some(e);
                    break;
                }
            }
            let Some(e) = next else { break };
            used[e] = true;
            let (a, b) = edges[e];
            left[a] -= 1;
            left[b] -= 1;
            v = if a == v { b } else { a };
            line.push(v);
        }
        line
    };
    for v in 0..n {
        if (start[v + 1] - start[v]) % 2 == 1 {
            while left[v] > 0 {
                out.push(walk(v, &mut used, &mut left, &mut cursor));
            }
        }
    }
    for v in 0..n {
        while left[v] > 0 {
            out.push(walk(v, &mut used, &mut left, &mut cursor));
        }
    }
    out
}

/// The Voronoi edges `dual.edges[i]` for the indices `pick`, merged into polylines and clipped
/// to `clip`.
pub fn polylines(dual: &Dual, pick: impl Iterator<Item = usize>, clip: &Clip) -> Vec<Vec<Pt>> {
    let edges: Vec<(usize, usize)> = pick.map(|i| dual.edges[i].ends).collect();
    let lines = merge(dual.points.len(), &edges);
    let mut out = Vec::new();
    for l in lines {
        let pts: Vec<Pt> = l.iter().map(|&v| dual.points[v]).collect();
        // Drop pieces of zero length (an edge that only touches the region's outline).
        out.extend(clip.polyline(&pts).into_iter().filter(|p| p.windows(2).any(|w| w[0] != w[1])));
    }
    out
}

/// Clips a convex polygon (counter-clockwise) to the half-plane `n . (p - m) <= 0`.
pub fn clip_half_plane(poly: &[Pt], m: Pt, n: Pt) -> Vec<Pt> {
    let side = |p: Pt| n[0] * (p[0] - m[0]) + n[1] * (p[1] - m[1]);
    let mut out = Vec::with_capacity(poly.len() + 1);
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let (sa, sb) = (side(a), side(b));
        if sa <= 0.0 {
            out.push(a);
        }
        if (sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0) {
            let t = sa / (sa - sb);
            out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
    }
    out
}

/// The Voronoi cell of `site` among `others`, clipped to the box: the box cut by the bisector
/// half-plane of each other site.
pub fn cell(site: Pt, others: impl Iterator<Item = Pt>, bbox: (f64, f64, f64, f64)) -> Vec<Pt> {
    let (x0, y0, x1, y1) = bbox;
    let mut poly = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
    for o in others {
        if poly.is_empty() {
            break;
        }
        let m = [0.5 * (site[0] + o[0]), 0.5 * (site[1] + o[1])];
        poly = clip_half_plane(&poly, m, [o[0] - site[0], o[1] - site[1]]);
    }
    poly
}

/// The Delaunay neighbours of vertex `v`.
pub fn neighbours<T>(tri: &T, v: usize) -> impl Iterator<Item = usize> + '_
where
    T: Triangulation,
{
    tri.vertex(FixedVertexHandle::from_index(v))
        .out_edges()
        .map(|e| e.to().fix().index())
}

/// A site position as spade's point.
pub fn p2(p: Pt) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rect_clip_is_one_interval() {
        let c = Clip::Rect {
            x0: 0.0,
            y0: 0.0,
            x1: 10.0,
            y1: 10.0,
        };
        assert_eq!(c.segment([-5.0, 5.0], [15.0, 5.0]), vec![(0.25, 0.75)]);
        assert!(c.segment([-5.0, -5.0], [-1.0, 20.0]).is_empty());
        assert_eq!(
            c.polyline(&[[-5.0, 5.0], [5.0, 5.0], [5.0, 15.0]]),
            vec![vec![[0.0, 5.0], [5.0, 5.0], [5.0, 10.0]]]
        );
    }

    #[test]
    fn annulus_clip_splits_a_chord() {
        let c = Clip::Annulus {
            c: [0.0, 0.0],
            ro: 2.0,
            ri: 1.0,
        };
        let iv = c.segment([-3.0, 0.0], [3.0, 0.0]);
        assert_eq!(iv.len(), 2);
        let pts: Vec<f64> = iv.iter().flat_map(|&(a, b)| [-3.0 + 6.0 * a, -3.0 + 6.0 * b]).collect();
        for (g, w) in pts.iter().zip([-2.0, -1.0, 1.0, 2.0]) {
            assert!((g - w).abs() < 1e-12, "{pts:?}");
        }
    }

    #[test]
    fn polygon_clip_handles_concave_outlines() {
        // A U shape: the segment across the notch leaves and re-enters.
        let u = vec![
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 3.0],
            [2.0, 3.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 3.0],
            [0.0, 3.0],
        ];
        let c = Clip::Polygon { rings: vec![u] };
        let iv = c.segment([-1.0, 2.0], [4.0, 2.0]);
        assert_eq!(iv.len(), 2, "{iv:?}");
    }

    #[test]
    fn merge_uses_every_edge_once_and_joins_chains() {
        // A path 0-1-2-3 given out of order, plus a triangle 4-5-6.
        let edges = [(2, 3), (0, 1), (1, 2), (4, 5), (5, 6), (6, 4)];
        let lines = merge(7, &edges);
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0], vec![0, 1, 2, 3]);
        assert_eq!(lines[1].len(), 4);
        assert_eq!(lines[1].first(), lines[1].last());
    }
}
