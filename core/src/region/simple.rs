//! The checks behind [`super::PolygonRegion::new_in`]: no two edges meet, and each ring's
//! even-odd depth, each either over every pair (no scratch) or through the edge tree.
//!
//! Both ways ask the same question of the same pairs, so they give the same answer on every
//! input (the core's `region_parity` tests hold them to it):
//! - Two edges that are neighbours in one ring may share only their common vertex: the ring
//!   must not fold back onto itself (the far ends collinear with it, on the same side).
//! - Any other two edges whose bounding boxes come within `m` of each other (`m` is 10^-9 of
//!   the largest coordinate magnitude, at least 10^-9) must not share a point
//!   ([`segments_intersect`]). Edges with boxes farther apart share no point and are not
//!   asked: the floating-point test can call four nearly collinear points far apart a
//!   crossing, a rounding artefact no index could reproduce without asking every pair. The
//!   tree finds each near pair from its lower-numbered edge, skipping the nodes whose box is
//!   farther than `m` from that edge's box (every box inside is farther still).
//! - A ring's depth is the number of the other rings around its first vertex; its parity is
//!   the parity of the other rings' edges that [`ray_crosses`] counts from that vertex. Such
//!   an edge straddles the vertex's height and reaches right of it, so the tree skips the
//!   nodes whose box does not.

use super::rings::Rings;
use super::tree::{Bbox, EdgeTree};
use super::RegionError;
use crate::geom::{point_in_poly, ray_crosses, segments_intersect, Point};

/// Whether two boxes come within `m` of each other along both axes. If a box passes, so
/// does any box containing it.
#[inline]
pub(crate) fn near(a: Bbox, b: Bbox, m: f64) -> bool {
    a.0 <= b.2 + m && b.0 <= a.2 + m && a.1 <= b.3 + m && b.1 <= a.3 + m
}

/// The margin of [`near`] for an outline whose largest coordinate magnitude is `scale`.
pub(crate) fn margin(scale: f64) -> f64 {
    scale * 1e-9
}

/// Whether edges `i < j` meet (see the module documentation); `bi`, `bj` are their boxes.
#[inline]
fn pair_meets(r: &Rings<'_>, i: usize, j: usize, bi: Bbox, bj: Bbox, m: f64) -> bool {
    if !near(bi, bj, m) {
        return false;
    }
    let (ni, nj) = (r.next(i), r.next(j));
    let at = |k: usize| r.points.get(k).copied().unwrap_or_default();
    let (a1, a2, b1, b2) = (at(i), at(ni), at(j), at(nj));
    // Neighbours in one ring (the next vertex never leaves its ring).
    if ni == j || nj == i {
        // Folding back onto the previous edge (collinear overlap) is not simple.
        let shared = if ni == j { a2 } else { a1 };
        let (p, q) = if ni == j { (a1, b2) } else { (b1, a2) };
        let (u, v) = (p.diff(shared), q.diff(shared));
        return u.cross(v) == 0.0 && u.dot(v) > 0.0;
    }
    segments_intersect(a1, a2, b1, b2)
}

/// Every pair of edges: O(E²).
pub(crate) fn check_pairs(r: &Rings<'_>, m: f64) -> Result<(), RegionError> {
    for i in 0..r.len() {
        let bi = r.bbox(i);
        for j in (i + 1)..r.len() {
            if pair_meets(r, i, j, bi, r.bbox(j), m) {
                return Err(RegionError::SelfIntersecting);
            }
        }
    }
    Ok(())
}

/// The near pairs, found through the tree: one walk per leaf, for the nodes near the leaf's
/// box (a pair is asked in the walk of its lower-numbered edge's leaf).
pub(crate) fn check_tree(r: &Rings<'_>, t: &EdgeTree<'_>, m: f64) -> Result<(), RegionError> {
    for leaf in t.leaves() {
        let boxes = leaf.iter().map(|&i| r.bbox(i as usize));
        let Some(lb) = boxes.reduce(|a, b| (a.0.min(b.0), a.1.min(b.1), a.2.max(b.2), a.3.max(b.3))) else {
            continue;
        };
        let hit = t.walk(
            |b| near(b, lb, m),
            |j| {
                let bj = r.bbox(j);
                leaf.iter().any(|&i| {
                    let i = i as usize;
                    i < j && pair_meets(r, i, j, r.bbox(i), bj, m)
                })
            },
        );
        if hit {
            return Err(RegionError::SelfIntersecting);
        }
    }
    Ok(())
}

/// Whether ring `ring` lies inside an odd number of the others (a hole), testing its first
/// vertex against every other ring: O(E).
pub(crate) fn odd_depth_pairs(r: &Rings<'_>, ring: usize) -> bool {
    let Some(&probe) = r.slice(ring).first() else {
        return false;
    };
    (0..r.ends.len()).filter(|&q| q != ring && point_in_poly(probe, r.slice(q))).count() % 2 == 1
}

/// Whether a box can hold an edge that [`ray_crosses`] counts from `p`: it spans `p`'s height
/// and reaches right of `p` (see [`ray_crosses`] for why an edge that does not never counts).
#[inline]
pub(crate) fn ray_box(b: Bbox, p: Point<f64>) -> bool {
    b.1 <= p.y && p.y <= b.3 && b.2 > p.x
}

/// [`odd_depth_pairs`] through the tree.
pub(crate) fn odd_depth_tree(r: &Rings<'_>, t: &EdgeTree<'_>, ring: usize) -> bool {
    let (s, e) = r.ring(ring);
    let Some(&p) = r.points.get(s) else {
        return false;
    };
    let mut odd = false;
    t.walk(
        |b| ray_box(b, p),
        |k| {
            if !(s..e).contains(&k) {
                let (a, b) = r.edge(k);
                odd ^= ray_crosses(p, a, b);
            }
            false
        },
    );
    odd
}
