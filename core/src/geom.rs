//! Points and the exact clearance tests between concrete shapes.
//!
//! A concrete shape ([`Geo`]) is a disc, a ring (annulus) or a simple polygon with its
//! vertices in counter-clockwise order, flagged convex or not. [`separated`] answers "is the
//! distance between the two shapes' material greater than `gap`?" exactly in the scalar's
//! arithmetic; with `gap = 0` touching counts as overlapping (the paper's "does not overlap or
//! touch"). A shape lying in a ring's hole is separated from the ring when it keeps `gap` from
//! the inner circle (nesting, the paper's Figure 2). The pair table is symmetric:
//! `separated(a, b, g) == separated(b, a, g)`.

use crate::scalar::Scalar;
use crate::shape::{Frame, Motif};

/// Whether motifs are built in (the `motif` feature): without it no engine accepts one, and
/// their tests are never linked (a motif then counts as meeting everything).
pub(crate) const MOTIFS: bool = cfg!(feature = "motif");

/// A point (or vector) in the plane, in the region's frame (x right, y up).
///
/// # Examples
///
/// ```
/// use zetafill::Point;
///
/// let (a, b) = (Point::new(1.0, 2.0), Point::new(4.0, 6.0));
/// assert_eq!(b.diff(a), Point::new(3.0, 4.0));
/// assert_eq!(a.dist2(b), 25.0);
/// assert_eq!(a.shift(1.0, -2.0), Point::new(2.0, 0.0));
/// assert_eq!(Point::new(1.0, 0.0).cross(Point::new(0.0, 1.0)), 1.0); // counter-clockwise
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Point<S> {
    /// x coordinate.
    pub x: S,
    /// y coordinate.
    pub y: S,
}

impl<S: Scalar> Point<S> {
    /// A point from its coordinates.
    #[inline]
    pub fn new(x: S, y: S) -> Self {
        Point { x, y }
    }
    /// The point moved by (dx, dy).
    #[inline]
    pub fn shift(self, dx: S, dy: S) -> Self {
        Point::new(self.x + dx, self.y + dy)
    }
    /// `self - o`.
    #[inline]
    pub fn diff(self, o: Self) -> Self {
        Point::new(self.x - o.x, self.y - o.y)
    }
    /// Dot product.
    #[inline]
    pub fn dot(self, o: Self) -> S {
        self.x * o.x + self.y * o.y
    }
    /// z of the cross product.
    #[inline]
    pub fn cross(self, o: Self) -> S {
        self.x * o.y - self.y * o.x
    }
    /// Squared distance to another point.
    #[inline]
    pub fn dist2(self, o: Self) -> S {
        let d = self.diff(o);
        d.dot(d)
    }
}

/// Most vertices a polygon may have (blobs use [`crate::shape::BLOB_VERTICES`]).
pub const MAX_VERTS: usize = 32;

/// A polygon's vertex list: at most [`MAX_VERTS`] points, kept in place (no heap).
///
/// # Examples
///
/// ```
/// use zetafill::{Geo, Point, Verts};
///
/// let mut v: Verts<f64> = Verts::new();
/// for (x, y) in [(0.0, 0.0), (4.0, 0.0), (0.0, 3.0)] {
///     v.push(Point::new(x, y)).expect("room for 32 vertices");
/// }
/// let triangle = Geo::Poly { v, convex: true };
/// assert_eq!(triangle.poly_area2(), 12.0);
/// ```
pub type Verts<S> = heapless::Vec<Point<S>, MAX_VERTS>;

/// A concrete shape at its place, ready for exact tests and for drawing.
///
/// Not `Copy` (a polygon carries up to [`MAX_VERTS`] vertices): clone it where a copy is
/// meant, and prefer [`crate::ShapeKind::geo_into`] to rewrite one in place.
///
/// # Examples
///
/// ```
/// use zetafill::{Geo, Point, ShapeKind};
///
/// let c = Point::new(10.0, 10.0);
/// // A unit square (half side 1) turned by 45 degrees: a diamond.
/// let diamond = ShapeKind::Square.geo(c, 1.0, std::f64::consts::FRAC_PI_4);
/// match &diamond {
///     Geo::Poly { v, convex } => assert!(*convex && v.len() == 4),
///     other => panic!("a square is a polygon, not {other:?}"),
/// }
/// let (x0, y0, x1, y1) = diamond.bounds();
/// let half_diagonal = 2f64.sqrt();
/// assert!((x1 - x0 - 2.0 * half_diagonal).abs() < 1e-12 && (y1 - y0 - 2.0 * half_diagonal).abs() < 1e-12);
/// assert!((diamond.poly_area2() / 2.0 - 4.0).abs() < 1e-12);
/// // A circle is a true circle.
/// assert_eq!(ShapeKind::Circle.geo(c, 2.0, 0.0), Geo::Circle { c, r: 2.0 });
/// assert_eq!(diamond.shift(1.0, 0.0).bounds().0, x0 + 1.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Geo<'m, S> {
    /// A disc.
    Circle {
        /// Centre.
        c: Point<S>,
        /// Radius.
        r: S,
    },
    /// An annulus: the material between two concentric circles; its hole is free space.
    Ring {
        /// Centre.
        c: Point<S>,
        /// Outer radius.
        r: S,
        /// Inner radius (0 < inner < r).
        inner: S,
    },
    /// A simple polygon, vertices counter-clockwise.
    Poly {
        /// Vertices (3..=MAX_VERTS of them).
        v: Verts<S>,
        /// Whether the polygon is convex (enables the faster separating-axis test).
        convex: bool,
    },
    /// A motif (a polygon with holes of up to [`crate::MAX_MOTIF_VERTICES`] vertices) placed
    /// by a frame: its vertices are computed from the unit outline when asked for
    /// ([`Motif::rings_at`]).
    Motif {
        /// The unit outline.
        m: &'m Motif<'m>,
        /// Where it is placed.
        f: Frame<S>,
    },
}

impl<S: Scalar> Geo<'_, S> {
    /// The shape moved by (dx, dy).
    pub fn shift(&self, dx: S, dy: S) -> Self {
        match *self {
            Geo::Circle { c, r } => Geo::Circle { c: c.shift(dx, dy), r },
            Geo::Ring { c, r, inner } => Geo::Ring {
                c: c.shift(dx, dy),
                r,
                inner,
            },
            Geo::Poly { ref v, convex } => {
                let mut v = v.clone();
                for p in v.iter_mut() {
                    *p = p.shift(dx, dy);
                }
                Geo::Poly { v, convex }
            }
            Geo::Motif { m, f } => Geo::Motif {
                m,
                f: Frame { t: f.t.shift(dx, dy), ..f },
            },
        }
    }

    /// The shape as a value that borrows nothing, for a built-in kind (a motif borrows its
    /// outline: `None`).
    pub fn owned(&self) -> Option<Geo<'static, S>> {
        match *self {
            Geo::Circle { c, r } => Some(Geo::Circle { c, r }),
            Geo::Ring { c, r, inner } => Some(Geo::Ring { c, r, inner }),
            Geo::Poly { ref v, convex } => Some(Geo::Poly { v: v.clone(), convex }),
            Geo::Motif { .. } => None,
        }
    }

    /// The vertices of a polygon (empty for circles, rings and motifs: see
    /// [`Motif::rings_at`]).
    pub fn vertices(&self) -> &[Point<S>] {
        match self {
            Geo::Poly { v, .. } => v,
            _ => &[],
        }
    }

    /// Axis-aligned bounds (min x, min y, max x, max y).
    pub fn bounds(&self) -> (S, S, S, S) {
        match *self {
            Geo::Circle { c, r } | Geo::Ring { c, r, .. } => (c.x - r, c.y - r, c.x + r, c.y + r),
            Geo::Poly { .. } => {
                let vs = self.vertices();
                let first = vs.first().copied().unwrap_or(Point::new(S::ZERO, S::ZERO));
                let mut b = (first.x, first.y, first.x, first.y);
                for p in vs {
                    b = (b.0.min(p.x), b.1.min(p.y), b.2.max(p.x), b.3.max(p.y));
                }
                b
            }
            Geo::Motif { m, ref f } => {
                let mut b = (f.t.x, f.t.y, f.t.x, f.t.y);
                for ring in m.rings_at(f).filter(|_| MOTIFS) {
                    for p in ring {
                        b = (b.0.min(p.x), b.1.min(p.y), b.2.max(p.x), b.3.max(p.y));
                    }
                }
                b
            }
        }
    }

    /// The largest squared distance from `p` to a point of the shape (for a circle, its
    /// centre's distance rounded up: see [`Scalar::dist2_up`]).
    pub fn max_dist2(&self, p: Point<S>) -> S {
        match *self {
            Geo::Circle { c, r } | Geo::Ring { c, r, .. } => {
                let e = c.diff(p);
                let d = S::dist2_up(e.x, e.y).sqrt() + r;
                d * d
            }
            Geo::Poly { .. } => self.vertices().iter().fold(S::ZERO, |m, v| m.max(v.dist2(p))),
            Geo::Motif { m, ref f } if MOTIFS => m.rings_at(f).flatten().fold(S::ZERO, |m, v| m.max(v.dist2(p))),
            Geo::Motif { .. } => S::ZERO,
        }
    }

    /// Twice the signed area of a polygon, twice the area of a motif (holes subtracted), 0
    /// for circles and rings.
    pub fn poly_area2(&self) -> S {
        match self {
            Geo::Motif { m, f } if MOTIFS => m.area2_at(f),
            Geo::Motif { .. } => S::ZERO,
            _ => edges(self.vertices()).fold(S::ZERO, |s, (a, b)| s + a.cross(b)),
        }
    }
}

/// Squared distance from `p` to the segment `a`–`b`. The cross product is squared with
/// [`Scalar::mul_div`], so it never saturates while the distance itself fits.
pub fn seg_dist2<S: Scalar>(p: Point<S>, a: Point<S>, b: Point<S>) -> S {
    let ab = b.diff(a);
    let ap = p.diff(a);
    let len2 = ab.dot(ab);
    let t = ap.dot(ab);
    if t <= S::ZERO || len2 <= S::ZERO {
        return ap.dot(ap);
    }
    if t >= len2 {
        return p.dist2(b);
    }
    let cr = ab.cross(ap);
    cr.mul_div(cr, len2)
}

/// Iterates the edges (a, b) of a closed polygon.
pub fn edges<S: Scalar>(vs: &[Point<S>]) -> impl Iterator<Item = (Point<S>, Point<S>)> + '_ {
    vs.iter().copied().zip(vs.iter().copied().cycle().skip(1))
}

/// Sign of the orientation of (a, b, c): 1 counter-clockwise, -1 clockwise, 0 collinear.
fn orient<S: Scalar>(a: Point<S>, b: Point<S>, c: Point<S>) -> i8 {
    let v = b.diff(a).cross(c.diff(a));
    if v > S::ZERO {
        1
    } else if v < S::ZERO {
        -1
    } else {
        0
    }
}

fn on_segment<S: Scalar>(a: Point<S>, b: Point<S>, p: Point<S>) -> bool {
    p.x >= a.x.min(b.x) && p.x <= a.x.max(b.x) && p.y >= a.y.min(b.y) && p.y <= a.y.max(b.y)
}

/// Whether the closed segments p1–p2 and q1–q2 share a point.
pub fn segments_intersect<S: Scalar>(p1: Point<S>, p2: Point<S>, q1: Point<S>, q2: Point<S>) -> bool {
    let (d1, d2) = (orient(q1, q2, p1), orient(q1, q2, p2));
    let (d3, d4) = (orient(p1, p2, q1), orient(p1, p2, q2));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    (d1 == 0 && on_segment(q1, q2, p1))
        || (d2 == 0 && on_segment(q1, q2, p2))
        || (d3 == 0 && on_segment(p1, p2, q1))
        || (d4 == 0 && on_segment(p1, p2, q2))
}

/// Squared distance between two closed segments.
pub fn seg_seg_dist2<S: Scalar>(p1: Point<S>, p2: Point<S>, q1: Point<S>, q2: Point<S>) -> S {
    if segments_intersect(p1, p2, q1, q2) {
        return S::ZERO;
    }
    seg_dist2(p1, q1, q2)
        .min(seg_dist2(p2, q1, q2))
        .min(seg_dist2(q1, p1, p2))
        .min(seg_dist2(q2, p1, p2))
}

/// Whether `p` is inside a simple polygon (even-odd rule; points on the boundary may go
/// either way, callers test boundary distance separately).
pub fn point_in_poly<S: Scalar>(p: Point<S>, vs: &[Point<S>]) -> bool {
    let mut inside = false;
    for (a, b) in edges(vs) {
        if ray_crosses(p, a, b) {
            inside = !inside;
        }
    }
    inside
}

/// Whether the edge `a`–`b` crosses the ray from `p` towards +x, as the even-odd rule counts:
/// one end above `p.y` and the other not, meeting that height to the right of `p` (x of the
/// edge at height `p.y`, compared without division).
///
/// In any monotone rounding an edge with no point to the right of `p` (`a.x, b.x <= p.x`)
/// never crosses: then `p.x - a.x >= max(b.x - a.x, 0)` and `|b.y - a.y| >= |p.y - a.y|`,
/// so the two products compare the wrong way. A polygon region's edge tree relies on this.
#[inline]
pub fn ray_crosses<S: Scalar>(p: Point<S>, a: Point<S>, b: Point<S>) -> bool {
    if (a.y > p.y) == (b.y > p.y) {
        return false;
    }
    let lhs = (p.x - a.x) * (b.y - a.y);
    let rhs = (b.x - a.x) * (p.y - a.y);
    if b.y > a.y {
        lhs < rhs
    } else {
        lhs > rhs
    }
}

/// Whether `p` is inside or on a counter-clockwise convex polygon.
fn in_convex<S: Scalar>(p: Point<S>, vs: &[Point<S>]) -> bool {
    edges(vs).all(|(a, b)| b.diff(a).cross(p.diff(a)) >= S::ZERO)
}

fn in_poly<S: Scalar>(p: Point<S>, vs: &[Point<S>], convex: bool) -> bool {
    if convex {
        in_convex(p, vs)
    } else {
        point_in_poly(p, vs)
    }
}

/// Smallest squared distance from any vertex of `p` to any edge of `q`, starting from `best`.
fn vert_edge_dist2<S: Scalar>(p: &[Point<S>], q: &[Point<S>], mut best: S) -> S {
    for &v in p {
        for (a, b) in edges(q) {
            best = best.min(seg_dist2(v, a, b));
        }
    }
    best
}

/// Whether an edge normal of convex `p` strictly separates `p` from `q`.
fn has_separating_edge<S: Scalar>(p: &[Point<S>], q: &[Point<S>]) -> bool {
    edges(p).any(|(a, b)| {
        let e = b.diff(a);
        q.iter().all(|&v| e.cross(v.diff(a)) < S::ZERO)
    })
}

/// Disc (centre `c`, radius `r`) against a polygon.
fn disc_poly<S: Scalar>(c: Point<S>, r: S, vs: &[Point<S>], convex: bool, gap: S) -> bool {
    if in_poly(c, vs, convex) {
        return false;
    }
    let reach = r + gap;
    edges(vs).all(|(p, q)| seg_dist2(c, p, q) > reach * reach)
}

fn poly_poly<S: Scalar>(pa: &[Point<S>], ca: bool, pb: &[Point<S>], cb: bool, gap: S) -> bool {
    if ca && cb {
        if !(has_separating_edge(pa, pb) || has_separating_edge(pb, pa)) {
            return false;
        }
        if gap <= S::ZERO {
            return true;
        }
        // Disjoint convex polygons: the distance is reached between a vertex and an edge.
        let inf = gap * gap + S::ONE;
        return vert_edge_dist2(pb, pa, vert_edge_dist2(pa, pb, inf)) > gap * gap;
    }
    // General simple polygons: overlapping ones have crossing (or touching) edges, or one
    // lies inside the other. Only edges whose bounds come within `gap` of each other can
    // cross or come that near, so the other pairs are skipped: their tests would all fail
    // (a margin far above rounding keeps the skipping exact).
    let (ba, bb) = (vbox(pa), vbox(pb));
    let m = (ba.iter().chain(bb.iter()).fold(S::ONE, |m, &v| m.max(v.abs()))) * S::from_f64(1e-9);
    let reach = gap.max(S::ZERO) + m;
    // The edges of b that come near a's bounds (their first vertices' indices: a board's
    // stack has no room for more).
    let mut near_b: heapless::Vec<u8, MAX_VERTS> = heapless::Vec::new();
    for (k, (b1, b2)) in edges(pb).enumerate() {
        if boxes_meet(seg_box(b1, b2), ba, reach) {
            // Cannot fail: `pb` is a polygon's vertex list, so it has at most MAX_VERTS edges.
            let _ = near_b.push(k as u8);
        }
    }
    let g2 = gap * gap;
    for (a1, a2) in edges(pa) {
        let ea = seg_box(a1, a2);
        if !boxes_meet(ea, bb, reach) {
            continue;
        }
        for &k in &near_b {
            let k = usize::from(k);
            let (Some(&b1), Some(&b2)) = (pb.get(k), pb.get((k + 1).checked_rem(pb.len()).unwrap_or(0))) else {
                continue;
            };
            if !boxes_meet(ea, seg_box(b1, b2), reach) {
                continue;
            }
            if gap <= S::ZERO {
                if segments_intersect(a1, a2, b1, b2) {
                    return false;
                }
            } else if seg_seg_dist2(a1, a2, b1, b2) <= g2 {
                return false;
            }
        }
    }
    // No edges cross: each polygon's boundary lies wholly inside or wholly outside the
    // other, so one vertex of each tells whether one holds the other.
    let holds = |v: Option<&Point<S>>, b: [S; 4], q: &[Point<S>], cq: bool| v.is_some_and(|&v| in_box(v, b, m) && in_poly(v, q, cq));
    !(holds(pa.first(), bb, pb, cb) || holds(pb.first(), ba, pa, ca))
}

/// Bounds of a vertex list: [min x, min y, max x, max y].
pub(crate) fn vbox<S: Scalar>(vs: &[Point<S>]) -> [S; 4] {
    let first = vs.first().copied().unwrap_or_default();
    vs.iter().fold([first.x, first.y, first.x, first.y], |b, v| {
        [b[0].min(v.x), b[1].min(v.y), b[2].max(v.x), b[3].max(v.y)]
    })
}

/// Bounds of a segment.
pub(crate) fn seg_box<S: Scalar>(a: Point<S>, b: Point<S>) -> [S; 4] {
    [a.x.min(b.x), a.y.min(b.y), a.x.max(b.x), a.y.max(b.y)]
}

/// Whether `p` is within `m` of the bounds `b`.
pub(crate) fn in_box<S: Scalar>(p: Point<S>, b: [S; 4], m: S) -> bool {
    p.x >= b[0] - m && p.x <= b[2] + m && p.y >= b[1] - m && p.y <= b[3] + m
}

/// Whether two bounds come within `d` of each other (per axis).
pub(crate) fn boxes_meet<S: Scalar>(a: [S; 4], b: [S; 4], d: S) -> bool {
    a[0] <= b[2] + d && b[0] <= a[2] + d && a[1] <= b[3] + d && b[1] <= a[3] + d
}

/// Whether `g` lies in the hole of a ring (centre `c`, inner radius `inner`) with `gap` to
/// the inner circle.
fn in_hole<S: Scalar>(g: &Geo<'_, S>, c: Point<S>, inner: S, gap: S) -> bool {
    let room = inner - gap;
    if room <= S::ZERO {
        return false;
    }
    match *g {
        Geo::Circle { c: gc, r } | Geo::Ring { c: gc, r, .. } => {
            let d = room - r;
            d > S::ZERO && gc.dist2(c) < d * d
        }
        Geo::Poly { .. } => g.vertices().iter().all(|v| v.dist2(c) < room * room),
        Geo::Motif { m, ref f } => MOTIFS && m.within(f, c, room),
    }
}

/// Whether the distance between `a` and `b` is greater than `gap` (`gap >= 0`).
pub fn separated<S: Scalar>(a: &Geo<'_, S>, b: &Geo<'_, S>, gap: S) -> bool {
    match (a, b) {
        (Geo::Motif { .. }, _) | (_, Geo::Motif { .. }) if !MOTIFS => false,
        (Geo::Motif { m: ma, f: fa }, Geo::Motif { m: mb, f: fb }) => ma.clear_of_motif(fa, mb, fb, gap),
        (Geo::Circle { c: c1, r: r1 }, Geo::Circle { c: c2, r: r2 }) => {
            let reach = *r1 + *r2 + gap;
            c1.dist2(*c2) > reach * reach
        }
        (Geo::Ring { c: c1, r: r1, inner: i1 }, Geo::Ring { c: c2, r: r2, inner: i2 }) => {
            // Either ring may sit in the other's hole.
            let (o1, o2) = (Geo::Circle { c: *c1, r: *r1 }, Geo::Circle { c: *c2, r: *r2 });
            in_hole(&o2, *c1, *i1, gap) || in_hole(&o1, *c2, *i2, gap) || separated(&o1, &o2, gap)
        }
        (Geo::Ring { c, r, inner }, other) | (other, Geo::Ring { c, r, inner }) => {
            in_hole(other, *c, *inner, gap) || separated(&Geo::Circle { c: *c, r: *r }, other, gap)
        }
        (Geo::Circle { c, r }, Geo::Motif { m, f }) | (Geo::Motif { m, f }, Geo::Circle { c, r }) => m.clear_of_disc(f, *c, *r, gap),
        (poly @ Geo::Poly { convex, .. }, Geo::Motif { m, f }) | (Geo::Motif { m, f }, poly @ Geo::Poly { convex, .. }) => {
            m.clear_of_poly(f, poly.vertices(), *convex, gap)
        }
        (Geo::Circle { c, r }, poly @ Geo::Poly { convex, .. }) | (poly @ Geo::Poly { convex, .. }, Geo::Circle { c, r }) => {
            disc_poly(*c, *r, poly.vertices(), *convex, gap)
        }
        (Geo::Poly { convex: ca, .. }, Geo::Poly { convex: cb, .. }) => poly_poly(a.vertices(), *ca, b.vertices(), *cb, gap),
    }
}

#[cfg(test)]
mod tests;
