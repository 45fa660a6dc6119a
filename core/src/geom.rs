//! Points and the exact clearance tests between concrete shapes.
//!
//! A concrete shape ([`Geo`]) is a circle or a convex polygon with its vertices in
//! counter-clockwise order. [`separated`] answers "is the distance between the two shapes
//! greater than `gap`?" exactly in the scalar's arithmetic: with `gap = 0` touching counts as
//! overlapping (the paper's "does not overlap or touch"). The pair table is symmetric:
//! `separated(a, b, g) == separated(b, a, g)`.

use crate::scalar::Scalar;

/// A point (or vector) in the plane, in the region's frame (x right, y up).
#[derive(Clone, Copy, Debug, PartialEq)]
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
    #[inline]
    fn sub(self, o: Self) -> Self {
        Point::new(self.x - o.x, self.y - o.y)
    }
    #[inline]
    fn dot(self, o: Self) -> S {
        self.x * o.x + self.y * o.y
    }
    #[inline]
    fn cross(self, o: Self) -> S {
        self.x * o.y - self.y * o.x
    }
}

/// Most vertices a convex polygon may have here.
pub const MAX_VERTS: usize = 4;

/// A concrete shape at its place, ready for exact tests.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Geo<S> {
    /// A disc.
    Circle {
        /// Centre.
        c: Point<S>,
        /// Radius.
        r: S,
    },
    /// A convex polygon, vertices counter-clockwise; only the first `n` are used.
    Convex {
        /// Vertices.
        v: [Point<S>; MAX_VERTS],
        /// Number of vertices used.
        n: usize,
    },
}

impl<S: Scalar> Geo<S> {
    /// The shape moved by (dx, dy).
    pub fn shift(&self, dx: S, dy: S) -> Self {
        match *self {
            Geo::Circle { c, r } => Geo::Circle { c: c.shift(dx, dy), r },
            Geo::Convex { mut v, n } => {
                for p in v.iter_mut() {
                    *p = p.shift(dx, dy);
                }
                Geo::Convex { v, n }
            }
        }
    }

    /// The vertices of a polygon (empty for a circle).
    pub fn vertices(&self) -> &[Point<S>] {
        match self {
            Geo::Circle { .. } => &[],
            Geo::Convex { v, n } => v.get(..*n).unwrap_or(&[]),
        }
    }

    /// Axis-aligned bounds (min x, min y, max x, max y).
    pub fn bounds(&self) -> (S, S, S, S) {
        match *self {
            Geo::Circle { c, r } => (c.x - r, c.y - r, c.x + r, c.y + r),
            Geo::Convex { .. } => {
                let vs = self.vertices();
                let first = vs.first().copied().unwrap_or(Point::new(S::ZERO, S::ZERO));
                let mut b = (first.x, first.y, first.x, first.y);
                for p in vs {
                    b = (b.0.min(p.x), b.1.min(p.y), b.2.max(p.x), b.3.max(p.y));
                }
                b
            }
        }
    }
}

/// Squared distance from `p` to the segment `a`–`b`.
fn seg_dist2<S: Scalar>(p: Point<S>, a: Point<S>, b: Point<S>) -> S {
    let ab = b.sub(a);
    let ap = p.sub(a);
    let len2 = ab.dot(ab);
    let t = ap.dot(ab);
    if t <= S::ZERO || len2 <= S::ZERO {
        return ap.dot(ap);
    }
    if t >= len2 {
        let bp = p.sub(b);
        return bp.dot(bp);
    }
    // Distance to the line: cross^2 / len2 (non-negative by construction).
    let cr = ab.cross(ap);
    cr * cr / len2
}

/// Iterates the edges (a, b) of a closed polygon.
fn edges<S: Scalar>(vs: &[Point<S>]) -> impl Iterator<Item = (Point<S>, Point<S>)> + '_ {
    vs.iter()
        .copied()
        .zip(vs.iter().copied().cycle().skip(1))
}

/// Whether `p` is inside or on a counter-clockwise convex polygon.
fn in_convex<S: Scalar>(p: Point<S>, vs: &[Point<S>]) -> bool {
    edges(vs).all(|(a, b)| b.sub(a).cross(p.sub(a)) >= S::ZERO)
}

/// Smallest squared distance from any vertex of `p` to any edge of `q`.
fn vert_edge_dist2<S: Scalar>(p: &[Point<S>], q: &[Point<S>], mut best: S) -> S {
    for &v in p {
        for (a, b) in edges(q) {
            best = best.min(seg_dist2(v, a, b));
        }
    }
    best
}

/// Whether an edge normal of `p` strictly separates `p` from `q` (q entirely outside).
fn has_separating_edge<S: Scalar>(p: &[Point<S>], q: &[Point<S>]) -> bool {
    edges(p).any(|(a, b)| {
        let e = b.sub(a);
        // Outward normal of a CCW polygon's edge is (e.y, -e.x); q is separated when every
        // vertex of q is strictly on the outer side of the edge line.
        q.iter().all(|&v| e.cross(v.sub(a)) < S::ZERO)
    })
}

/// Whether the distance between `a` and `b` is greater than `gap` (`gap >= 0`).
pub fn separated<S: Scalar>(a: &Geo<S>, b: &Geo<S>, gap: S) -> bool {
    match (a, b) {
        (Geo::Circle { c: c1, r: r1 }, Geo::Circle { c: c2, r: r2 }) => {
            let d = c1.sub(*c2);
            let reach = *r1 + *r2 + gap;
            d.dot(d) > reach * reach
        }
        (Geo::Circle { c, r }, poly @ Geo::Convex { .. })
        | (poly @ Geo::Convex { .. }, Geo::Circle { c, r }) => {
            let vs = poly.vertices();
            if in_convex(*c, vs) {
                return false;
            }
            let reach = *r + gap;
            edges(vs).all(|(p, q)| seg_dist2(*c, p, q) > reach * reach)
        }
        (Geo::Convex { .. }, Geo::Convex { .. }) => {
            let (pa, pb) = (a.vertices(), b.vertices());
            if !(has_separating_edge(pa, pb) || has_separating_edge(pb, pa)) {
                return false;
            }
            if gap <= S::ZERO {
                return true;
            }
            // Disjoint convex polygons: the distance is reached between a vertex and an edge.
            let inf = gap * gap + S::ONE;
            let d2 = vert_edge_dist2(pb, pa, vert_edge_dist2(pa, pb, inf));
            d2 > gap * gap
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sq(cx: f64, cy: f64, h: f64) -> Geo<f64> {
        let p = |x, y| Point::new(x, y);
        Geo::Convex { v: [p(cx - h, cy - h), p(cx + h, cy - h), p(cx + h, cy + h), p(cx - h, cy + h)], n: 4 }
    }

    #[test]
    fn touching_is_not_separated() {
        let a = Geo::Circle { c: Point::new(0.0, 0.0), r: 1.0 };
        let b = Geo::Circle { c: Point::new(2.0, 0.0), r: 1.0 };
        assert!(!separated(&a, &b, 0.0));
        assert!(separated(&a, &b.shift(1e-9, 0.0), 0.0));
        assert!(!separated(&sq(0.0, 0.0, 1.0), &sq(2.0, 0.0, 1.0), 0.0));
        assert!(separated(&sq(0.0, 0.0, 1.0), &sq(2.0 + 1e-9, 0.0, 1.0), 0.0));
        assert!(!separated(&a, &sq(2.0, 0.0, 1.0), 0.0));
    }

    #[test]
    fn gap_between_squares_is_exact_at_corners() {
        // Corner to corner along the diagonal: distance sqrt(2)*0.5.
        let a = sq(0.0, 0.0, 1.0);
        let b = sq(2.5, 2.5, 1.0);
        let d = libm::sqrt(0.5);
        assert!(separated(&a, &b, d - 1e-12));
        assert!(!separated(&a, &b, d + 1e-12));
    }

    #[test]
    fn circle_inside_square_overlaps() {
        let a = Geo::Circle { c: Point::new(0.0, 0.0), r: 0.1 };
        assert!(!separated(&a, &sq(0.0, 0.0, 1.0), 0.0));
        assert!(!separated(&sq(0.0, 0.0, 1.0), &a, 0.0));
    }
}
