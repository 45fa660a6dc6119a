//! The static k-d tree of the greedy step: points with radii (a circle's centre and radius,
//! or a path end with radius 0), with deletion, and nearest and k-nearest queries by outline
//! distance. Each query and deletion is O(log n) expected.

use super::dist;
use crate::model::Pt;

/// No node, no neighbour.
pub(super) const NONE: u32 = u32::MAX;
const LEAF: usize = 8;

#[derive(Debug, Clone)]
struct Node {
    lo: u32,
    hi: u32,
    min: Pt,
    max: Pt,
    rmax: f64,
    alive: u32,
    left: u32,
    right: u32,
    parent: u32,
}

/// A static k-d tree over points with radii (a point is a circle of radius 0), supporting
/// deletion, nearest and k-nearest queries by outline distance `| |q - p| - r |`.
#[derive(Debug, Clone)]
pub struct PointIndex {
    pts: Vec<Pt>,
    rad: Vec<f64>,
    ids: Vec<u32>,
    tags: Vec<u32>,
    alive: Vec<bool>,
    leaf: Vec<u32>,
    nodes: Vec<Node>,
    /// Position in the tree of each input item.
    pos_of: Vec<u32>,
}

impl PointIndex {
    /// Builds the tree over `(point, radius, id, tag)` items.
    pub fn new(items: &[(Pt, f64, u32, u32)]) -> PointIndex {
        let n = items.len();
        let mut perm: Vec<u32> = (0..n as u32).collect();
        let mut nodes = Vec::with_capacity(2 * n / LEAF + 2);
        if n > 0 {
            build(items, &mut perm, 0, n, NONE, &mut nodes);
        }
        let pts: Vec<Pt> = perm.iter().map(|&i| items[i as usize].0).collect();
        let rad: Vec<f64> = perm.iter().map(|&i| items[i as usize].1).collect();
        let ids: Vec<u32> = perm.iter().map(|&i| items[i as usize].2).collect();
        let tags: Vec<u32> = perm.iter().map(|&i| items[i as usize].3).collect();
        let mut pos_of = vec![0u32; n];
        for (p, &i) in perm.iter().enumerate() {
            pos_of[i as usize] = p as u32;
        }
        let mut leaf = vec![0u32; n];
        for (k, nd) in nodes.iter().enumerate() {
            if nd.left == NONE {
                for p in nd.lo..nd.hi {
                    leaf[p as usize] = k as u32;
                }
            }
        }
        PointIndex {
            pts,
            rad,
            ids,
            tags,
            alive: vec![true; n],
            leaf,
            nodes,
            pos_of,
        }
    }

    /// The tree position of input item `i`.
    pub fn position(&self, i: usize) -> usize {
        self.pos_of[i] as usize
    }

    /// The id and tag stored at a position.
    pub fn item(&self, pos: usize) -> (u32, u32) {
        (self.ids[pos], self.tags[pos])
    }

    /// Whether anything is left.
    pub fn is_empty(&self) -> bool {
        self.nodes.first().is_none_or(|n| n.alive == 0)
    }

    /// Deletes the item at `pos` (no-op if already deleted).
    pub fn remove(&mut self, pos: usize) {
        if !self.alive[pos] {
            return;
        }
        self.alive[pos] = false;
        let had_radius = self.rad[pos] > 0.0;
        let mut k = self.leaf[pos];
        let leaf = &mut self.nodes[k as usize];
        leaf.alive -= 1;
        if had_radius {
            let (lo, hi) = (leaf.lo as usize, leaf.hi as usize);
            let r = (lo..hi).filter(|&p| self.alive[p]).map(|p| self.rad[p]).fold(0.0, f64::max);
            self.nodes[k as usize].rmax = r;
        }
        loop {
            let parent = self.nodes[k as usize].parent;
            if parent == NONE {
                break;
            }
            k = parent;
            let (l, r) = (self.nodes[k as usize].left as usize, self.nodes[k as usize].right as usize);
            let rmax = if had_radius {
                self.nodes[l].rmax.max(self.nodes[r].rmax)
            } else {
                self.nodes[k as usize].rmax
            };
            let nd = &mut self.nodes[k as usize];
            nd.alive -= 1;
            nd.rmax = rmax;
        }
    }

    fn point_dist(&self, q: Pt, p: usize) -> f64 {
        let d = dist(q, self.pts[p]);
        if self.rad[p] > 0.0 {
            (d - self.rad[p]).abs()
        } else {
            d
        }
    }

    fn lower(&self, n: &Node, q: Pt) -> f64 {
        let dx = (n.min[0] - q[0]).max(q[0] - n.max[0]).max(0.0);
        let dy = (n.min[1] - q[1]).max(q[1] - n.max[1]).max(0.0);
        ((dx * dx + dy * dy).sqrt() - n.rmax).max(0.0)
    }

    /// The position of the nearest live item and its distance.
    pub fn nearest(&self, q: Pt) -> Option<(usize, f64)> {
        let mut best = (f64::INFINITY, usize::MAX);
        if !self.nodes.is_empty() {
            self.nearest_rec(0, q, &mut best);
        }
        (best.1 != usize::MAX).then_some((best.1, best.0))
    }

    fn nearest_rec(&self, k: usize, q: Pt, best: &mut (f64, usize)) {
        let n = &self.nodes[k];
        if n.alive == 0 || self.lower(n, q) >= best.0 {
            return;
        }
        if n.left == NONE {
            for p in n.lo as usize..n.hi as usize {
                if self.alive[p] {
                    let d = self.point_dist(q, p);
                    if d < best.0 {
                        *best = (d, p);
                    }
                }
            }
            return;
        }
        let (l, r) = (n.left as usize, n.right as usize);
        let (dl, dr) = (self.lower(&self.nodes[l], q), self.lower(&self.nodes[r], q));
        let (first, second) = if dl <= dr { (l, r) } else { (r, l) };
        self.nearest_rec(first, q, best);
        self.nearest_rec(second, q, best);
    }

    /// The `k` nearest live items as (distance, position), nearest first.
    pub fn k_nearest(&self, q: Pt, k: usize, out: &mut Vec<(f64, usize)>) {
        out.clear();
        if k == 0 || self.nodes.is_empty() {
            return;
        }
        if self.nodes[0].rmax == 0.0 {
            // Points only: squared distances throughout, one square root per result.
            let dist2 = |q: Pt, p: usize| {
                let (dx, dy) = (q[0] - self.pts[p][0], q[1] - self.pts[p][1]);
                dx * dx + dy * dy
            };
            self.knn_by(0, q, k, out, &Self::lower2, &dist2);
            for e in out.iter_mut() {
                e.0 = e.0.sqrt();
            }
        } else {
            self.knn_by(0, q, k, out, &|n, q| self.lower(n, q), &|q, p| self.point_dist(q, p));
        }
    }

    /// The `k` nearest below `node` into `out` (sorted), by the distance `dist` from `q` to an
    /// item and its lower bound `lower` from `q` to a node's box: exact or squared, the same
    /// walk.
    fn knn_by(
        &self,
        node: usize,
        q: Pt,
        k: usize,
        out: &mut Vec<(f64, usize)>,
        lower: &impl Fn(&Node, Pt) -> f64,
        dist: &impl Fn(Pt, usize) -> f64,
    ) {
        let n = &self.nodes[node];
        let bound = if out.len() == k { out[k - 1].0 } else { f64::INFINITY };
        if n.alive == 0 || lower(n, q) >= bound {
            return;
        }
        if n.left == NONE {
            for p in n.lo as usize..n.hi as usize {
                if !self.alive[p] {
                    continue;
                }
                let d = dist(q, p);
                if out.len() == k && d >= out[k - 1].0 {
                    continue;
                }
                let at = out.partition_point(|e| e.0 <= d);
                out.insert(at, (d, p));
                out.truncate(k);
            }
            return;
        }
        let (l, r) = (n.left as usize, n.right as usize);
        let (dl, dr) = (lower(&self.nodes[l], q), lower(&self.nodes[r], q));
        let (first, second) = if dl <= dr { (l, r) } else { (r, l) };
        self.knn_by(first, q, k, out, lower, dist);
        self.knn_by(second, q, k, out, lower, dist);
    }

    /// Squared distance from `q` to a node's box (valid as a bound when no radii are left).
    fn lower2(n: &Node, q: Pt) -> f64 {
        let dx = (n.min[0] - q[0]).max(q[0] - n.max[0]).max(0.0);
        let dy = (n.min[1] - q[1]).max(q[1] - n.max[1]).max(0.0);
        dx * dx + dy * dy
    }
}

fn build(items: &[(Pt, f64, u32, u32)], perm: &mut [u32], lo: usize, hi: usize, parent: u32, nodes: &mut Vec<Node>) -> u32 {
    let (mut min, mut max, mut rmax) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2], 0.0f64);
    for &i in &perm[lo..hi] {
        let (p, r) = (items[i as usize].0, items[i as usize].1);
        min = [min[0].min(p[0]), min[1].min(p[1])];
        max = [max[0].max(p[0]), max[1].max(p[1])];
        rmax = rmax.max(r);
    }
    let k = nodes.len() as u32;
    nodes.push(Node {
        lo: lo as u32,
        hi: hi as u32,
        min,
        max,
        rmax,
        alive: (hi - lo) as u32,
        left: NONE,
        right: NONE,
        parent,
    });
    if hi - lo > LEAF {
        let axis = usize::from(max[1] - min[1] > max[0] - min[0]);
        let mid = (lo + hi) / 2;
        perm[lo..hi].select_nth_unstable_by(mid - lo, |&a, &b| {
            items[a as usize].0[axis].total_cmp(&items[b as usize].0[axis]).then(a.cmp(&b))
        });
        let l = build(items, perm, lo, mid, k, nodes);
        let r = build(items, perm, mid, hi, k, nodes);
        nodes[k as usize].left = l;
        nodes[k as usize].right = r;
    }
    k
}
