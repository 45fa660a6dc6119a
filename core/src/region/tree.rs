//! The edge tree: a bounding-box hierarchy over a polygon region's edges, in caller-owned
//! words, that finds the edges a test must look at without visiting the others.
//!
//! Layout (all `u32` words): the next vertex of each vertex (`n`), the edges sorted along a
//! Z-order curve of their first vertex (`n`), then the nodes of a complete binary tree in heap
//! order (node `k` has children `2k + 1` and `2k + 2`; the last `L` nodes are the leaves, each
//! holding `leaf` consecutive sorted edges), each node's box as four `f64` in eight words.
//! A node's box is the exact union (min and max, no rounding) of its edges' boxes.
//!
//! The tree never decides an answer: a query skips a node only when a test on its box proves
//! that every edge inside gives the answer a skipped edge gives, and runs the caller's exact
//! per-edge test on all the others. The proofs (in the callers) use that comparisons and
//! monotone rounding preserve order: a box inside the node's box is at least as far. Nothing
//! here panics; the order of the visits never changes a result (each query is a parity, a
//! minimum of values that are never `-0` or NaN, or an "any").

use super::rings::Rings;
use crate::scalar::Scalar;

/// A box: min x, min y, max x, max y.
pub(crate) type Bbox = (f64, f64, f64, f64);

/// Edges per leaf at full size.
const LEAF: usize = 4;
/// Words per node (four `f64`).
const NODE: usize = 8;
/// Pending nodes of a walk: at most 2^30 edges make fewer than 2^29 nodes, 29 levels, and a
/// walk holds at most one pending node a level and the one it pops.
const STACK: usize = 64;

/// Words of scratch the tree needs for `n` edges at full size: `2n` for the tables and at
/// most `2 ceil(n / 4) - 1` nodes of 8 words.
pub(crate) const fn words(n: usize) -> usize {
    n.saturating_mul(6).saturating_add(NODE)
}

/// 2^e for a normal exponent.
const fn pow2(e: i64) -> f64 {
    f64::from_bits(((1023 + e) as u64) << 52)
}
/// Largest coordinate magnitude (and query-point magnitude) for which distance pruning holds.
const METRIC_MAX: f64 = pow2(60);
/// Shortest non-zero edge (squared length) for which distance pruning holds.
const METRIC_MIN_LEN2: f64 = pow2(-600);
/// The relative margin of distance pruning, about 2^17 times the rounding it covers.
const MARGIN: f64 = pow2(-30);
/// Lower bounds below this are taken as zero (far from underflow of the squared distances).
const LB_FLOOR: f64 = pow2(-400);

/// The tree over its words (kept small: a region is copied by value, and on a
/// microcontroller every copy is stack).
#[derive(Clone, Copy)]
pub(crate) struct EdgeTree<'a> {
    /// The table of next vertices, the sorted edges, then the nodes.
    words: &'a [u32],
    /// Edges.
    n: u32,
    /// Edges per leaf.
    leaf: u32,
    /// Leaves (the last `leaves` nodes).
    leaves: u32,
    /// Whether `f64` distance queries may prune (coordinates within 2^60, every edge of zero
    /// length or at least 2^-300 long).
    metric: bool,
}

impl core::fmt::Debug for EdgeTree<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("EdgeTree")
            .field("edges", &self.n)
            .field("leaves", &self.leaves)
            .field("leaf", &self.leaf)
            .field("metric", &self.metric)
            .finish()
    }
}

fn put(words: &mut [u32], at: usize, v: f64) {
    let b = v.to_bits();
    if let Some(w) = words.get_mut(at..at + 2) {
        w.copy_from_slice(&[b as u32, (b >> 32) as u32]);
    }
}

fn get(words: &[u32], at: usize) -> f64 {
    match words.get(at..at + 2) {
        Some(&[lo, hi]) => f64::from_bits(u64::from(lo) | u64::from(hi) << 32),
        _ => 0.0,
    }
}

fn union(a: Bbox, b: Bbox) -> Bbox {
    (a.0.min(b.0), a.1.min(b.1), a.2.max(b.2), a.3.max(b.3))
}

/// Spreads the 16 low bits of `v` to the even bits.
fn spread(v: u32) -> u32 {
    let mut x = v & 0xffff;
    x = (x | (x << 8)) & 0x00ff_00ff;
    x = (x | (x << 4)) & 0x0f0f_0f0f;
    x = (x | (x << 2)) & 0x3333_3333;
    (x | (x << 1)) & 0x5555_5555
}

impl<'a> EdgeTree<'a> {
    /// Builds the tree with the smallest leaves (4 edges, doubled until it fits) that
    /// `scratch` holds; `None` when it cannot hold one leaf of every edge, or the edges are
    /// too many for `u32` indices. `bbox` bounds every vertex.
    pub fn build(rings: &Rings<'_>, bbox: Bbox, scratch: &'a mut [u32]) -> Option<Self> {
        let n = rings.len();
        if n == 0 || n > (u32::MAX / 4) as usize {
            return None;
        }
        let mut leaf = LEAF;
        let leaves = loop {
            let leaves = n.div_ceil(leaf);
            let need = n.saturating_mul(2).saturating_add(NODE.saturating_mul(2 * leaves - 1));
            if need <= scratch.len() {
                break leaves;
            }
            if leaves == 1 {
                return None;
            }
            leaf = leaf.saturating_mul(2);
        };
        let used = 2 * n + NODE * (2 * leaves - 1);
        let scratch = scratch.get_mut(..used)?;
        let metric = {
            let (next, rest) = scratch.split_at_mut_checked(n)?;
            let (order, nodes) = rest.split_at_mut_checked(n)?;
            rings.fill_next(next);
            let rings = Rings { next: &*next, ..*rings };
            // Z-order of the first vertices, 16 bits an axis over the bounding box.
            let axis = |lo: f64, hi: f64| {
                let s = 65535.0 / (hi - lo);
                if s.is_finite() {
                    s
                } else {
                    0.0
                }
            };
            let (sx, sy) = (axis(bbox.0, bbox.2), axis(bbox.1, bbox.3));
            let key = |i: u32| {
                let p = rings.points.get(i as usize).copied().unwrap_or_default();
                let q = |v: f64, lo: f64, s: f64| ((v - lo) * s).floor_i64().clamp(0, 65535) as u32;
                spread(q(p.x, bbox.0, sx)) | (spread(q(p.y, bbox.1, sy)) << 1)
            };
            for (k, o) in order.iter_mut().enumerate() {
                *o = k as u32;
            }
            // The keys once each in the room the nodes will take, when it holds them.
            match nodes.get_mut(..n) {
                Some(keys) => {
                    for (k, slot) in keys.iter_mut().enumerate() {
                        *slot = key(k as u32);
                    }
                    let keys = &*keys;
                    order.sort_unstable_by_key(|&i| keys.get(i as usize).copied().unwrap_or(0));
                }
                None => order.sort_unstable_by_key(|&i| key(i)),
            }
            // Leaves, then each parent from its two children.
            let first = leaves - 1;
            for j in 0..leaves {
                let edges = order.get(j * leaf..((j + 1) * leaf).min(n)).unwrap_or(&[]);
                let b = edges.iter().map(|&e| rings.bbox(e as usize)).reduce(union).unwrap_or_default();
                Self::store(nodes, first + j, b);
            }
            for k in (0..first).rev() {
                let b = union(Self::load(nodes, 2 * k + 1), Self::load(nodes, 2 * k + 2));
                Self::store(nodes, k, b);
            }
            let scale = 1.0f64.max(bbox.0.abs()).max(bbox.1.abs()).max(bbox.2.abs()).max(bbox.3.abs());
            scale <= METRIC_MAX
                && (0..n).all(|i| {
                    let (a, b) = rings.edge(i);
                    let d = b.diff(a);
                    let len2 = d.dot(d);
                    len2 == 0.0 || len2 >= METRIC_MIN_LEN2
                })
        };
        let words: &'a [u32] = scratch;
        Some(EdgeTree {
            words,
            n: n as u32,
            leaf: u32::try_from(leaf).ok()?,
            leaves: leaves as u32,
            metric,
        })
    }

    fn store(nodes: &mut [u32], k: usize, b: Bbox) {
        let at = k * NODE;
        put(nodes, at, b.0);
        put(nodes, at + 2, b.1);
        put(nodes, at + 4, b.2);
        put(nodes, at + 6, b.3);
    }

    fn load(nodes: &[u32], k: usize) -> Bbox {
        let at = k * NODE;
        (get(nodes, at), get(nodes, at + 2), get(nodes, at + 4), get(nodes, at + 6))
    }

    /// The vertex after each vertex.
    #[inline]
    pub fn next(&self) -> &'a [u32] {
        self.words.get(..self.n as usize).unwrap_or(&[])
    }

    /// The edges in the tree's order.
    #[inline]
    fn order(&self) -> &'a [u32] {
        let n = self.n as usize;
        self.words.get(n..2 * n).unwrap_or(&[])
    }

    /// The nodes' words.
    #[inline]
    fn nodes(&self) -> &'a [u32] {
        self.words.get(2 * self.n as usize..).unwrap_or(&[])
    }

    /// The rings with this tree's table of next vertices.
    pub fn rings<'r>(&self, rings: &Rings<'r>) -> Rings<'r>
    where
        'a: 'r,
    {
        Rings {
            next: self.next(),
            ..*rings
        }
    }

    /// The edges of each leaf, in the tree's order.
    pub fn leaves(&self) -> impl Iterator<Item = &'a [u32]> + 'a {
        self.order().chunks(self.leaf as usize)
    }

    /// The edges of leaf node `k`, or none for an inner node.
    fn leaf_edges(&self, k: usize) -> &'a [u32] {
        match k.checked_sub(self.leaves as usize - 1) {
            Some(j) => {
                let (order, leaf) = (self.order(), self.leaf as usize);
                order.get(j * leaf..((j + 1) * leaf).min(order.len())).unwrap_or(&[])
            }
            None => &[],
        }
    }

    /// Visits, depth first, every node whose box `enter` accepts, and calls `edge` on each
    /// edge of every leaf visited, until `edge` returns true (then returns true). Out of line,
    /// like [`EdgeTree::min`]: their pending-node arrays stay off the stack of a region
    /// without a tree.
    #[inline(never)]
    pub fn walk(&self, mut enter: impl FnMut(Bbox) -> bool, mut edge: impl FnMut(usize) -> bool) -> bool {
        let mut stack = [0u32; STACK];
        let mut top = 1usize;
        let (first, nodes) = (self.leaves as usize - 1, self.nodes());
        while let Some(t) = top.checked_sub(1) {
            top = t;
            let k = stack.get(t).copied().unwrap_or(0) as usize;
            if !enter(Self::load(nodes, k)) {
                continue;
            }
            if k >= first {
                for &e in self.leaf_edges(k) {
                    if edge(e as usize) {
                        return true;
                    }
                }
                continue;
            }
            for c in [2 * k + 2, 2 * k + 1] {
                // Never full: one pending sibling per level.
                if let Some(s) = stack.get_mut(top) {
                    *s = c as u32;
                    top += 1;
                }
            }
        }
        false
    }

    /// Visits, depth first, every pair of a node of this tree and a node of `other` whose
    /// boxes `enter` accepts, splitting the larger of the two (a leaf never), and calls `pair`
    /// on each pair of edges of two leaves visited, until `pair` returns true (then returns
    /// true): the pairs of two shapes' edges that come near, without a walk per edge.
    #[inline(never)]
    pub fn walk_pairs(
        &self,
        other: &EdgeTree<'_>,
        mut enter: impl FnMut(Bbox, Bbox) -> bool,
        mut pair: impl FnMut(usize, usize) -> bool,
    ) -> bool {
        // Each pop pushes at most two pairs, each one level deeper on one side: never more
        // pending than the two trees' depths together.
        let mut stack = [(0u32, 0u32); 2 * STACK];
        let mut top = 1usize;
        let (fa, na) = (self.leaves as usize - 1, self.nodes());
        let (fb, nb) = (other.leaves as usize - 1, other.nodes());
        let size = |b: Bbox| (b.2 - b.0).max(b.3 - b.1);
        while let Some(t) = top.checked_sub(1) {
            top = t;
            let (i, j) = stack.get(t).map_or((0, 0), |&(i, j)| (i as usize, j as usize));
            let (bi, bj) = (Self::load(na, i), Self::load(nb, j));
            if !enter(bi, bj) {
                continue;
            }
            let (leaf_i, leaf_j) = (i >= fa, j >= fb);
            if leaf_i && leaf_j {
                for &e in self.leaf_edges(i) {
                    for &f in other.leaf_edges(j) {
                        if pair(e as usize, f as usize) {
                            return true;
                        }
                    }
                }
                continue;
            }
            let split_i = !leaf_i && (leaf_j || size(bi) >= size(bj));
            let children = if split_i {
                [(2 * i + 2, j), (2 * i + 1, j)]
            } else {
                [(i, 2 * j + 2), (i, 2 * j + 1)]
            };
            for (a, b) in children {
                if let Some(s) = stack.get_mut(top) {
                    *s = (a as u32, b as u32);
                    top += 1;
                }
            }
        }
        false
    }

    /// The smallest `edge(e)` over every edge whose leaf's lower bound (`bound`, which must
    /// not exceed `edge(e)` for any edge in the box) is below the best so far, nearer boxes
    /// first. `None` with no edges.
    #[inline(never)]
    pub fn min<S: Scalar>(&self, bound: impl Fn(Bbox) -> S, mut edge: impl FnMut(usize) -> S) -> Option<S> {
        let mut best: Option<S> = None;
        let mut stack = [0u32; STACK];
        let mut top = 1usize;
        let (first, nodes) = (self.leaves as usize - 1, self.nodes());
        while let Some(t) = top.checked_sub(1) {
            top = t;
            let k = stack.get(t).copied().unwrap_or(0) as usize;
            if best.is_some_and(|b| bound(Self::load(nodes, k)) >= b) {
                continue;
            }
            if k >= first {
                for &e in self.leaf_edges(k) {
                    let d = edge(e as usize);
                    best = Some(best.map_or(d, |m| m.min(d)));
                }
                continue;
            }
            let (l, r) = (2 * k + 1, 2 * k + 2);
            let (lb, rb) = (bound(Self::load(nodes, l)), bound(Self::load(nodes, r)));
            // The nearer child goes on top.
            let pair = if rb < lb { [l, r] } else { [r, l] };
            for c in pair {
                if let Some(s) = stack.get_mut(top) {
                    *s = c as u32;
                    top += 1;
                }
            }
        }
        best
    }

    /// [`lower_bound`] for this tree's edges, whose coordinates are at most `scale` in
    /// magnitude: zero unless its guards hold (see `metric`).
    #[inline]
    pub fn lower_bound(&self, q: (f64, f64), b: Bbox, scale: f64) -> f64 {
        if self.metric {
            lower_bound(q, b, scale)
        } else {
            0.0
        }
    }

    /// Whether every distance from `q` to an edge is a number (no overflow: coordinates and
    /// `q` within 2^60), so the smallest is the same in any order.
    pub fn exact_min(&self, q: (f64, f64)) -> bool {
        self.metric && q.0.abs() <= METRIC_MAX && q.1.abs() <= METRIC_MAX
    }

    /// Whether vertex `i` is the first of its ring.
    #[inline]
    pub fn is_start(&self, i: usize) -> bool {
        match i.checked_sub(1) {
            None => true,
            Some(p) => self.next().get(p).is_none_or(|&n| n as usize != i),
        }
    }
}

/// A lower bound on the squared distance [`crate::geom::seg_dist2`] computes in `f64` from
/// `q` to any edge whose box lies inside `b`, for vertices of magnitude at most `scale`:
/// zero when none is proven.
///
/// The box lies `dx` and `dy` from `q` along the axes (computed; zero inside its span), so
/// the segment lies at least `D = sqrt(dx² + dy²)` away. A distance `seg_dist2` takes to an
/// end point is at least `dx² + dy²` computed, by monotone rounding (each coordinate differs
/// by at least as much). Its perpendicular branch, `cross² / len²`, is within `11 eps W` of
/// the exact distance, where `W = |q.x| + |q.y| + 8 scale` bounds the lengths in play and
/// `eps = 2^-53`: the cross product's rounding is below `8 eps |ab| |ap|`, and the rounded
/// projection test lets the foot fall outside the segment by at most `3 eps (|ap| + |ab|)`;
/// so it computes at least `D² (1 - 11 eps) - 46 eps W (dx + dy)`. The bound
/// `(dx² + dy²) (1 - 2^-30) - 2^-30 W (dx + dy)` keeps a margin of 2^17 over both terms. It
/// needs no overflow (coordinates and `q` within 2^60) and no underflow (edges of zero length
/// or squared length at least 2^-600, bounds below 2^-400 taken as zero).
pub(crate) fn lower_bound(q: (f64, f64), b: Bbox, scale: f64) -> f64 {
    if !(q.0.abs() <= METRIC_MAX && q.1.abs() <= METRIC_MAX && scale <= METRIC_MAX) {
        return 0.0;
    }
    let dx = (b.0 - q.0).max(q.0 - b.2).max(0.0);
    let dy = (b.1 - q.1).max(q.1 - b.3).max(0.0);
    let w = q.0.abs() + q.1.abs() + 8.0 * scale;
    let lb = (dx * dx + dy * dy) * (1.0 - MARGIN) - MARGIN * w * (dx + dy);
    if lb < LB_FLOOR {
        0.0
    } else {
        lb
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{ray_crosses, seg_dist2, Point};

    /// splitmix64: a small, fixed generator for the cases.
    struct Mix(u64);

    impl Mix {
        fn next(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        }
        /// Uniform in [-1, 1).
        fn f(&mut self) -> f64 {
            (self.next() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        }
    }

    fn bbox(a: Point<f64>, b: Point<f64>) -> Bbox {
        (a.x.min(b.x), a.y.min(b.y), a.x.max(b.x), a.y.max(b.y))
    }

    #[test]
    fn the_lower_bound_never_exceeds_what_seg_dist2_computes() {
        let mut r = Mix(7);
        let mut pruned = 0u32;
        for k in 0..400_000u32 {
            let s = [1e-6, 1e-3, 1.0, 7.0, 1e3, 1e6, 1e12][(k % 7) as usize];
            let a = Point::new(s * r.f(), s * r.f());
            // Long, short, axis-aligned and nearly parallel edges.
            let b = match k % 5 {
                0 => Point::new(s * r.f(), s * r.f()),
                1 => Point::new(a.x + s * 1e-9 * r.f(), a.y + s * 1e-9 * r.f()),
                2 => Point::new(a.x + s * r.f(), a.y),
                3 => Point::new(a.x + s * r.f(), a.y + s * 1e-12 * r.f()),
                _ => Point::new(a.x, a.y + s * r.f()),
            };
            // Query points near the edge's line and its extension, and anywhere.
            let t = 3.0 * r.f();
            let off = s * [0.0, 1e-15, 1e-9, 1e-3, 0.3][(k / 5 % 5) as usize] * r.f();
            let q = if k % 3 == 0 {
                Point::new(s * 2.0 * r.f(), s * 2.0 * r.f())
            } else {
                Point::new(a.x + t * (b.x - a.x) - off * (b.y - a.y), a.y + t * (b.y - a.y) + off * (b.x - a.x))
            };
            let scale = 1f64.max(a.x.abs()).max(a.y.abs()).max(b.x.abs()).max(b.y.abs());
            // The edge's own box, and a box holding it.
            let e = bbox(a, b);
            let grow = s * 0.1 * r.f().abs();
            for bx in [e, (e.0 - grow, e.1 - grow, e.2 + grow, e.3 + grow)] {
                let lb = lower_bound((q.x, q.y), bx, scale + 2.0 * grow);
                let d = seg_dist2(q, a, b);
                assert!(d >= lb, "case {k}: seg_dist2 {d:e} below bound {lb:e} (a {a:?}, b {b:?}, q {q:?})");
                pruned += u32::from(lb > 0.0);
            }
        }
        assert!(pruned > 100_000, "the bound proves too little: {pruned}");
    }

    #[test]
    fn the_lower_bound_is_tight_enough_to_prune() {
        // A box 10 from the point, coordinates up to 100: the bound is 100 to within 1e-4.
        let lb = lower_bound((0.0, 0.0), (10.0, -1.0, 20.0, 1.0), 100.0);
        assert!(lb <= 100.0 && lb > 100.0 - 1e-4, "{lb}");
        // No bound beyond the guarded range, or inside the box.
        assert_eq!(lower_bound((1e19, 0.0), (10.0, -1.0, 20.0, 1.0), 100.0), 0.0);
        assert_eq!(lower_bound((15.0, 0.0), (10.0, -1.0, 20.0, 1.0), 100.0), 0.0);
        assert_eq!(lower_bound((f64::NAN, 0.0), (10.0, -1.0, 20.0, 1.0), 100.0), 0.0);
    }

    #[test]
    fn an_edge_with_no_point_right_of_the_ray_never_crosses_it() {
        let mut r = Mix(11);
        for k in 0..300_000u32 {
            let s = [1e-300, 1e-9, 1.0, 1e9, 1e300][(k % 5) as usize];
            let (a, b) = (Point::new(s * r.f(), s * r.f()), Point::new(s * r.f(), s * r.f()));
            // At or just right of the edge's rightmost point, at a height inside its span.
            let x = a.x.max(b.x);
            let px = if k % 2 == 0 { x } else { x + x.abs() * 1e-16 * r.f().abs() };
            let py = match k % 3 {
                0 => a.y,
                1 => b.y,
                _ => a.y + (b.y - a.y) * r.f().abs(),
            };
            assert!(!ray_crosses(Point::new(px, py), a, b), "case {k}: {a:?} {b:?} ({px}, {py})");
        }
    }
}
