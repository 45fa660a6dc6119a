//! The geometry of one placed shape as the document holds it: its bounding box and width.

use super::doc::ShapeDoc;
use super::path::dist;
use super::{Bounds, Pt};

/// The width of a shape: diameter for circles and rings, the smallest caliper width of the
/// convex hull of a polygon's vertices.
pub fn shape_width(sh: &ShapeDoc) -> f64 {
    if let Some(r) = sh.radius {
        return 2.0 * r;
    }
    if let Some(rings) = &sh.outlines {
        let all: Vec<Pt> = rings.iter().flatten().copied().collect();
        return polygon_width(&all);
    }
    let vs = sh.vertices.as_deref().unwrap_or(&[]);
    polygon_width(vs)
}

/// Smallest caliper width of a polygon (over the directions of its edges; exact for convex
/// polygons, the hull's width otherwise up to the edge directions).
pub fn polygon_width(vs: &[Pt]) -> f64 {
    let n = vs.len();
    if n < 3 {
        return 0.0;
    }
    let mut best = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (vs[i], vs[(i + 1) % n]);
        let len = dist(a, b);
        if len == 0.0 {
            continue;
        }
        let (nx, ny) = ((b[1] - a[1]) / len, (a[0] - b[0]) / len);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in vs {
            let d = (v[0] - a[0]) * nx + (v[1] - a[1]) * ny;
            lo = lo.min(d);
            hi = hi.max(d);
        }
        best = best.min(hi - lo);
    }
    best
}

/// The bounding box of a shape (its outer outline).
pub fn shape_bounds(sh: &ShapeDoc) -> Bounds {
    let mut b = Bounds::EMPTY;
    if let Some(r) = sh.radius {
        b.add([sh.center[0] - r, sh.center[1] - r]);
        b.add([sh.center[0] + r, sh.center[1] + r]);
    } else {
        for v in sh.vertices.iter().flatten().chain(sh.outlines.iter().flatten().flatten()) {
            b.add(*v);
        }
    }
    b
}
