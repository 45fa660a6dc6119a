//! Regions to fill: where candidate centres are drawn and whether a shape lies inside.
//!
//! - `Rect`: `[0, W] x [0, H]`, with an inclusive boundary (shapes stay inside, at least
//!   `gap` from the edge; touching the edge is allowed when `gap = 0`) or a periodic one (a
//!   torus: a shape crossing an edge exists again at x ± W, y ± H, and every test sees those
//!   images).
//! - `Circle`: the disc of radius R centred at (R, R); `Annulus`: the ring between R and r
//!   centred at (R, R) (its hole is outside the region).
//! - `Polygon`: any set of simple closed rings (outlines) that do not cross, filled by the
//!   even-odd rule, so a ring inside another is a hole (the borrowed vertices belong to the
//!   caller). A shape must keep more than `gap` from every edge.
//!
//! The area `A` of the power law is the region's true area. Nothing here panics.

use crate::geom::{edges, point_in_poly, seg_dist2, seg_seg_dist2, segments_intersect, separated, Geo, Point};
use crate::scalar::Scalar;

/// What is wrong with a polygon region.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum RegionError {
    /// A ring has fewer than 3 vertices, or the ring ends are not increasing.
    TooFewVertices,
    /// A coordinate is not finite.
    NotFinite,
    /// Two edges cross or touch (the outline is not simple, or two rings meet).
    SelfIntersecting,
    /// The area is zero.
    ZeroArea,
}

impl core::fmt::Display for RegionError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            RegionError::TooFewVertices => "every outline needs at least 3 vertices",
            RegionError::NotFinite => "a vertex coordinate is not a finite number",
            RegionError::SelfIntersecting => "the outline crosses itself (or two outlines meet)",
            RegionError::ZeroArea => "the outline encloses no area",
        })
    }
}

impl core::error::Error for RegionError {}

/// A validated polygonal region over caller-owned vertices.
///
/// ```
/// use zetafill::{Point, PolygonRegion, Region};
///
/// // An L: a 100 x 100 square without its 60 x 60 upper right corner.
/// let p = Point::new;
/// let points = [p(0.0, 0.0), p(100.0, 0.0), p(100.0, 40.0), p(40.0, 40.0), p(40.0, 100.0), p(0.0, 100.0)];
/// let ends = [points.len()];
/// let region = Region::Polygon(PolygonRegion::new(&points, &ends)?);
/// assert!((region.area() - 6400.0).abs() < 1e-9);
/// # Ok::<(), zetafill::RegionError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PolygonRegion<'a> {
    points: &'a [Point<f64>],
    ring_ends: &'a [usize],
    area: f64,
    bbox: (f64, f64, f64, f64),
}

fn ring_slices<'a>(points: &'a [Point<f64>], ends: &'a [usize]) -> impl Iterator<Item = &'a [Point<f64>]> + 'a {
    let starts = core::iter::once(0).chain(ends.iter().copied());
    starts.zip(ends.iter().copied()).map(move |(a, b)| points.get(a..b).unwrap_or(&[]))
}

impl<'a> PolygonRegion<'a> {
    /// Validates rings given as `points` split at the exclusive indices `ring_ends` (the last
    /// must be `points.len()`). O(E²) in the number of edges.
    pub fn new(points: &'a [Point<f64>], ring_ends: &'a [usize]) -> Result<Self, RegionError> {
        let mut start = 0usize;
        for &e in ring_ends {
            if e < start.saturating_add(3) || e > points.len() {
                return Err(RegionError::TooFewVertices);
            }
            start = e;
        }
        if ring_ends.is_empty() || start != points.len() {
            return Err(RegionError::TooFewVertices);
        }
        if points.iter().any(|p| !(p.x.is_finite() && p.y.is_finite())) {
            return Err(RegionError::NotFinite);
        }
        // Every pair of edges that are not neighbours in one ring must not meet; neighbours
        // must meet only at their shared vertex.
        let rings: ring_index::Rings<'a> = ring_index::Rings { points, ends: ring_ends };
        let n = points.len();
        for i in 0..n {
            let (a1, a2, ri) = rings.edge(i);
            for j in (i + 1)..n {
                let (b1, b2, rj) = rings.edge(j);
                let neighbours = ri == rj && (rings.next(i) == j || rings.next(j) == i);
                if neighbours {
                    // Folding back onto the previous edge (collinear overlap) is not simple.
                    let shared = if rings.next(i) == j { a2 } else { a1 };
                    let (p, q) = if rings.next(i) == j { (a1, b2) } else { (b1, a2) };
                    let (u, v) = (p.diff(shared), q.diff(shared));
                    if u.cross(v) == 0.0 && u.dot(v) > 0.0 {
                        return Err(RegionError::SelfIntersecting);
                    }
                    continue;
                }
                if segments_intersect(a1, a2, b1, b2) {
                    return Err(RegionError::SelfIntersecting);
                }
            }
        }
        // Area by the even-odd rule: a ring inside an odd number of others is a hole.
        let mut area = 0.0f64;
        for ring in ring_slices(points, ring_ends) {
            let a = edges(ring).fold(0.0, |s, (p, q)| s + p.cross(q)) / 2.0;
            let probe = ring.first().copied().unwrap_or_default();
            let depth = ring_slices(points, ring_ends)
                .filter(|r| !core::ptr::eq(*r, ring) && point_in_poly(probe, r))
                .count();
            area += if depth % 2 == 0 { a.abs() } else { -a.abs() };
        }
        if !(area > 0.0 && area.is_finite()) {
            return Err(RegionError::ZeroArea);
        }
        let mut bbox = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
        for p in points {
            bbox = (bbox.0.min(p.x), bbox.1.min(p.y), bbox.2.max(p.x), bbox.3.max(p.y));
        }
        Ok(PolygonRegion {
            points,
            ring_ends,
            area,
            bbox,
        })
    }

    /// The vertices, all rings one after another.
    pub fn points(&self) -> &'a [Point<f64>] {
        self.points
    }

    /// The exclusive end index of each ring in [`PolygonRegion::points`].
    pub fn ring_ends(&self) -> &'a [usize] {
        self.ring_ends
    }

    /// The rings.
    pub fn rings(&self) -> impl Iterator<Item = &'a [Point<f64>]> + 'a {
        ring_slices(self.points, self.ring_ends)
    }

    /// The area (holes subtracted).
    pub fn area(&self) -> f64 {
        self.area
    }

    fn edges_s<S: Scalar>(&self) -> impl Iterator<Item = (Point<S>, Point<S>)> + 'a {
        self.rings().flat_map(edges).map(|(a, b)| (conv(a), conv(b)))
    }

    /// [`Region::signed_clearance`] of the polygon: its edges' distance rounded up inside,
    /// down outside.
    fn signed_clearance<S: Scalar>(&self, q: Point<S>) -> S {
        let inside = self.inside(q);
        let d = self
            .edges_s::<S>()
            .map(|(a, b)| if inside { S::seg_dist2_up(q, a, b) } else { seg_dist2(q, a, b) })
            .fold(None, |m: Option<S>, d| Some(m.map_or(d, |m| m.min(d))))
            .unwrap_or(S::ZERO)
            .sqrt();
        if inside {
            d
        } else {
            -d
        }
    }

    fn inside<S: Scalar>(&self, p: Point<S>) -> bool {
        let mut inside = false;
        for ring in self.rings() {
            let mut buf_in = false;
            for (a, b) in edges(ring) {
                let (a, b): (Point<S>, Point<S>) = (conv(a), conv(b));
                if (a.y > p.y) != (b.y > p.y) {
                    let lhs = (p.x - a.x) * (b.y - a.y);
                    let rhs = (b.x - a.x) * (p.y - a.y);
                    if if b.y > a.y { lhs < rhs } else { lhs > rhs } {
                        buf_in = !buf_in;
                    }
                }
            }
            inside ^= buf_in;
        }
        inside
    }
}

/// Edge lookup over the rings (index i = the edge from vertex i to the next in its ring).
mod ring_index {
    use crate::geom::Point;

    pub struct Rings<'a> {
        pub points: &'a [Point<f64>],
        pub ends: &'a [usize],
    }

    impl Rings<'_> {
        fn ring_of(&self, i: usize) -> (usize, usize, usize) {
            let mut start = 0;
            for (r, &e) in self.ends.iter().enumerate() {
                if i < e {
                    return (r, start, e);
                }
                start = e;
            }
            (usize::MAX, 0, 0)
        }

        /// Index of the vertex after `i` in its ring.
        pub fn next(&self, i: usize) -> usize {
            let (_, s, e) = self.ring_of(i);
            if i + 1 >= e {
                s
            } else {
                i + 1
            }
        }

        /// The edge starting at vertex `i` and its ring number.
        pub fn edge(&self, i: usize) -> (Point<f64>, Point<f64>, usize) {
            let (r, _, _) = self.ring_of(i);
            let a = self.points.get(i).copied().unwrap_or_default();
            let b = self.points.get(self.next(i)).copied().unwrap_or_default();
            (a, b, r)
        }
    }
}

#[inline]
fn conv<S: Scalar>(p: Point<f64>) -> Point<S> {
    Point::new(S::from_f64(p.x), S::from_f64(p.y))
}

/// A region in its own frame (x right, y up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Region<'a> {
    /// The rectangle `[0, width] x [0, height]`.
    Rect {
        /// Width, finite and > 0.
        width: f64,
        /// Height, finite and > 0.
        height: f64,
        /// Toroidal boundary when true.
        periodic: bool,
    },
    /// The disc of this radius centred at (radius, radius).
    Circle {
        /// Radius, finite and > 0.
        radius: f64,
    },
    /// The ring between `outer` and `inner` centred at (outer, outer).
    Annulus {
        /// Outer radius.
        outer: f64,
        /// Inner radius, 0 < inner < outer.
        inner: f64,
    },
    /// A polygon with optional holes.
    Polygon(PolygonRegion<'a>),
}

impl Region<'_> {
    /// Whether the dimensions are finite and positive (polygons are validated when built).
    pub fn is_valid(&self) -> bool {
        let ok = |v: f64| v.is_finite() && v > 0.0;
        match *self {
            Region::Rect { width, height, .. } => ok(width) && ok(height),
            Region::Circle { radius } => ok(radius),
            Region::Annulus { outer, inner } => ok(outer) && ok(inner) && inner < outer,
            Region::Polygon(_) => true,
        }
    }

    /// The region's area.
    pub fn area(&self) -> f64 {
        use core::f64::consts::PI;
        match *self {
            Region::Rect { width, height, .. } => width * height,
            Region::Circle { radius } => PI * radius * radius,
            Region::Annulus { outer, inner } => PI * (outer * outer - inner * inner),
            Region::Polygon(p) => p.area(),
        }
    }

    /// Whether the boundary is periodic.
    pub fn periodic(&self) -> bool {
        matches!(self, Region::Rect { periodic: true, .. })
    }

    /// Bounding box (min x, min y, max x, max y).
    pub fn bbox(&self) -> (f64, f64, f64, f64) {
        match *self {
            Region::Rect { width, height, .. } => (0.0, 0.0, width, height),
            Region::Circle { radius: r } | Region::Annulus { outer: r, .. } => (0.0, 0.0, 2.0 * r, 2.0 * r),
            Region::Polygon(p) => p.bbox,
        }
    }

    /// Whether the bounding box has sides of at most `max` and lies within `max` of the
    /// origin on each axis (see [`Scalar::MAX_EXTENT`]).
    pub fn within(&self, max: f64) -> bool {
        let (x0, y0, x1, y1) = self.bbox();
        let (w, h) = self.extent();
        w <= max && h <= max && [x0, y0, x1, y1].iter().all(|v| v.abs() <= max)
    }

    /// Width and height of the bounding box (the period when periodic).
    pub fn extent(&self) -> (f64, f64) {
        let (x0, y0, x1, y1) = self.bbox();
        (x1 - x0, y1 - y0)
    }

    fn centre<S: Scalar>(&self) -> Point<S> {
        let (x0, y0, x1, y1) = self.bbox();
        Point::new(S::from_f64((x0 + x1) / 2.0), S::from_f64((y0 + y1) / 2.0))
    }

    /// The ranges `[lo, hi]` for the centre of a shape whose half extents are `(ex, ey)`:
    /// the bounding box shrunk by them and the gap (a superset of the valid centres, exact
    /// for rectangles), or `None` when empty. Periodic regions give the whole period.
    pub fn centre_range<S: Scalar>(&self, ex: S, ey: S, gap: S) -> Option<(S, S, S, S)> {
        let (bx0, by0, bx1, by1) = self.bbox();
        let (bx0, by0, bx1, by1) = (S::from_f64(bx0), S::from_f64(by0), S::from_f64(bx1), S::from_f64(by1));
        if self.periodic() {
            return Some((bx0, bx1, by0, by1));
        }
        let (x0, x1) = (bx0 + gap + ex, bx1 - gap - ex);
        let (y0, y1) = (by0 + gap + ey, by1 - gap - ey);
        if x1 < x0 || y1 < y0 {
            None
        } else {
            Some((x0, x1, y0, y1))
        }
    }

    /// Whether a shape lies inside the region with its gap to the boundary. Periodic regions
    /// accept every shape (its own images are tested by the engine).
    pub fn contains<S: Scalar>(&self, g: &Geo<S>, gap: S) -> bool {
        match *self {
            Region::Rect { periodic: true, .. } => true,
            Region::Rect { width, height, .. } => {
                let (x0, y0, x1, y1) = g.bounds();
                x0 >= gap && y0 >= gap && x1 <= S::from_f64(width) - gap && y1 <= S::from_f64(height) - gap
            }
            Region::Circle { radius } => {
                let room = S::from_f64(radius) - gap;
                room > S::ZERO && g.max_dist2(self.centre()) <= room * room
            }
            Region::Annulus { outer, inner } => {
                let room = S::from_f64(outer) - gap;
                let c = self.centre();
                room > S::ZERO && g.max_dist2(c) <= room * room && separated(g, &Geo::Circle { c, r: S::from_f64(inner) }, gap)
            }
            Region::Polygon(p) => poly_contains(&p, g, gap),
        }
    }

    /// Whether a point is inside the region (the even-odd rule for polygons; boundary points
    /// may go either way).
    pub fn point_inside<S: Scalar>(&self, q: Point<S>) -> bool {
        match *self {
            Region::Rect { width, height, .. } => {
                q.x >= S::ZERO && q.y >= S::ZERO && q.x <= S::from_f64(width) && q.y <= S::from_f64(height)
            }
            Region::Circle { radius } => q.dist2(self.centre()) <= S::from_f64(radius * radius),
            Region::Annulus { outer, inner } => {
                let d = q.dist2(self.centre());
                d <= S::from_f64(outer * outer) && d >= S::from_f64(inner * inner)
            }
            Region::Polygon(p) => p.inside(q),
        }
    }

    /// The squared distance from a point to the region's boundary.
    pub fn boundary_dist2<S: Scalar>(&self, q: Point<S>) -> S {
        match *self {
            Region::Rect { width, height, .. } => {
                let dx = q.x.abs().min((S::from_f64(width) - q.x).abs());
                let dy = q.y.abs().min((S::from_f64(height) - q.y).abs());
                let d = dx.min(dy);
                d * d
            }
            Region::Circle { radius } => {
                let d = q.dist2(self.centre()).sqrt() - S::from_f64(radius);
                d * d
            }
            Region::Annulus { outer, inner } => {
                let r = q.dist2(self.centre()).sqrt();
                let (a, b) = (r - S::from_f64(outer), r - S::from_f64(inner));
                (a * a).min(b * b)
            }
            Region::Polygon(p) => {
                let mut best: Option<S> = None;
                for (a, b) in p.edges_s::<S>() {
                    let d = seg_dist2(q, a, b);
                    best = Some(best.map_or(d, |m| m.min(d)));
                }
                best.unwrap_or(S::ZERO)
            }
        }
    }

    /// The signed distance from a point to the outside of the region: positive inside,
    /// negative outside; a periodic region has no outside (a distance larger than it). Rounded
    /// up where the scalar rounds (an upper bound, as the cell sampler needs).
    pub fn signed_clearance<S: Scalar>(&self, q: Point<S>) -> S {
        match *self {
            Region::Rect {
                periodic: true,
                width,
                height,
            } => S::from_f64(4.0 * width.max(height)),
            Region::Rect { width, height, .. } => q.x.min(S::from_f64(width) - q.x).min(q.y).min(S::from_f64(height) - q.y),
            // The distance from the centre rounded down where it is subtracted, up where added.
            Region::Circle { radius } => S::from_f64(radius) - q.dist2(self.centre()).sqrt(),
            Region::Annulus { outer, inner } => {
                let c = self.centre();
                let d = q.diff(c);
                let (near, far) = (q.dist2(c).sqrt(), S::dist2_up(d.x, d.y).sqrt());
                (S::from_f64(outer) - near).min(far - S::from_f64(inner))
            }
            Region::Polygon(p) => p.signed_clearance(q),
        }
    }

    /// The point `p` wrapped into the period (unchanged unless periodic).
    pub fn wrap<S: Scalar>(&self, p: Point<S>) -> Point<S> {
        if !self.periodic() {
            return p;
        }
        let (w, h) = self.extent();
        let (w, h) = (S::from_f64(w), S::from_f64(h));
        let fold = |v: S, m: S| {
            let mut v = v;
            if v < S::ZERO {
                v = v + m;
            }
            if v >= m {
                v = v - m;
            }
            v
        };
        Point::new(fold(p.x, w), fold(p.y, h))
    }
}

fn poly_contains<S: Scalar>(p: &PolygonRegion<'_>, g: &Geo<S>, gap: S) -> bool {
    match *g {
        Geo::Circle { c, r } | Geo::Ring { c, r, .. } => {
            let reach = r + gap;
            p.inside(c) && p.edges_s::<S>().all(|(a, b)| seg_dist2(c, a, b) > reach * reach)
        }
        Geo::Poly { .. } => {
            let vs = g.vertices();
            if !vs.iter().all(|&v| p.inside(v)) {
                return false;
            }
            let g2 = gap * gap;
            for (a, b) in p.edges_s::<S>() {
                for (c, d) in edges(vs) {
                    let clear = if gap <= S::ZERO {
                        !segments_intersect(a, b, c, d)
                    } else {
                        seg_seg_dist2(a, b, c, d) > g2
                    };
                    if !clear {
                        return false;
                    }
                }
            }
            // No outline (a hole) may lie wholly inside the shape.
            p.rings().all(|ring| ring.first().is_none_or(|&q| !point_in_poly(conv::<S>(q), vs)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> [Point<f64>; 8] {
        let mut out = [Point::default(); 8];
        for (o, &(x, y)) in out.iter_mut().zip(v) {
            *o = Point::new(x, y);
        }
        out
    }

    #[test]
    fn square_with_square_hole_has_the_right_area_and_inside() {
        let p = pts(&[
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 10.0),
            (0.0, 10.0),
            (4.0, 4.0),
            (4.0, 6.0),
            (6.0, 6.0),
            (6.0, 4.0),
        ]);
        let ends = [4, 8];
        let r = PolygonRegion::new(&p, &ends).map(Region::Polygon);
        let Ok(r) = r else { panic!("valid region rejected") };
        assert_eq!(r.area(), 96.0);
        assert!(r.point_inside(Point::new(1.0, 1.0)));
        assert!(!r.point_inside(Point::new(5.0, 5.0)));
        let small = Geo::Circle {
            c: Point::new(2.0, 2.0),
            r: 1.0,
        };
        assert!(r.contains(&small, 0.5));
        assert!(!r.contains(&small, 1.0));
        assert!(!r.contains(
            &Geo::Circle {
                c: Point::new(5.0, 5.0),
                r: 0.5
            },
            0.0
        ));
        // A circle around the hole is not inside.
        assert!(!r.contains(
            &Geo::Circle {
                c: Point::new(5.0, 5.0),
                r: 2.0
            },
            0.0
        ));
    }

    #[test]
    fn bad_polygons_are_rejected() {
        let bow = pts(&[(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
        assert_eq!(PolygonRegion::new(&bow[..4], &[4]).err(), Some(RegionError::SelfIntersecting));
        assert_eq!(PolygonRegion::new(&bow[..2], &[2]).err(), Some(RegionError::TooFewVertices));
        let line = pts(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]);
        assert!(PolygonRegion::new(&line[..3], &[3]).is_err());
        let nan = pts(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)]);
        assert_eq!(PolygonRegion::new(&nan[..3], &[3]).err(), Some(RegionError::NotFinite));
    }

    #[test]
    fn circle_and_annulus_contain_exactly() {
        let c = Region::Circle { radius: 10.0 };
        assert!(c.contains(
            &Geo::Circle {
                c: Point::new(10.0, 15.0),
                r: 5.0
            },
            0.0
        ));
        assert!(!c.contains(
            &Geo::Circle {
                c: Point::new(10.0, 15.0),
                r: 5.0
            },
            0.1
        ));
        let a = Region::Annulus { outer: 10.0, inner: 4.0 };
        assert!(!a.contains(
            &Geo::Circle {
                c: Point::new(10.0, 10.0),
                r: 1.0
            },
            0.0
        ));
        assert!(a.contains(
            &Geo::Circle {
                c: Point::new(10.0, 17.0),
                r: 2.0
            },
            0.0
        ));
        assert!(a.contains(
            &Geo::Ring {
                c: Point::new(10.0, 10.0),
                r: 9.0,
                inner: 5.0
            },
            0.5
        ));
    }
}
