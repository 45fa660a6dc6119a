//! The polygon check as it stood before the edge tree, kept word for word as a test oracle
//! and as the region benchmark's "before": every pair of edges through the floating-point
//! test alone (no bounding-box test first), each edge's ring found by a walk over the ring
//! ends, and each ring's depth from its first vertex against every other ring. O(E² R) time;
//! no scratch. It lives with the tests, not in the library.
//!
//! It differs from `PolygonRegion::new_in` and `PolygonRegion::new` only where the
//! floating-point test reports two edges whose boxes lie farther apart than the region's
//! margin (10^-9 of the largest coordinate) as crossing, four nearly collinear points far
//! apart: it rejects those outlines, the region accepts them.

use zetafill::internals::geom::{edges, point_in_poly, segments_intersect};
use zetafill::{Point, RegionError};

/// The rings of `points`, split at the exclusive indices `ends`.
fn ring_slices<'a>(points: &'a [Point<f64>], ends: &'a [usize]) -> impl Iterator<Item = &'a [Point<f64>]> + 'a {
    let starts = core::iter::once(0).chain(ends.iter().copied());
    starts.zip(ends.iter().copied()).map(move |(a, b)| points.get(a..b).unwrap_or(&[]))
}

/// Validates rings as the region did before the edge tree and returns the area (holes
/// subtracted), or the same errors in the same order of checks.
pub fn validate(points: &[Point<f64>], ring_ends: &[usize]) -> Result<f64, RegionError> {
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
    let rings = Rings { points, ends: ring_ends };
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
    Ok(area)
}

/// Edge lookup over the rings (index i = the edge from vertex i to the next in its ring).
struct Rings<'a> {
    points: &'a [Point<f64>],
    ends: &'a [usize],
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
    fn next(&self, i: usize) -> usize {
        let (_, s, e) = self.ring_of(i);
        if i + 1 >= e {
            s
        } else {
            i + 1
        }
    }

    /// The edge starting at vertex `i` and its ring number.
    fn edge(&self, i: usize) -> (Point<f64>, Point<f64>, usize) {
        let (r, _, _) = self.ring_of(i);
        let a = self.points.get(i).copied().unwrap_or_default();
        let b = self.points.get(self.next(i)).copied().unwrap_or_default();
        (a, b, r)
    }
}
