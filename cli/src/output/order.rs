//! Path order: cuts pen-up travel without touching what is drawn.
//!
//! 1. **Greedy nearest neighbour** through a static k-d tree with deletion ([`PointIndex`]):
//!    from the pen, go to the nearest remaining entry point. Open paths are indexed by both
//!    ends (entering at the far end reverses the path), closed polylines by every vertex (the
//!    path is rotated to start there), circles by their centre and radius (the distance to a
//!    circle is `|d - r|`, and the pen enters at its radial projection, the exact nearest
//!    point). Each query and deletion is O(log n) expected.
//! 2. **2-opt** on the greedy tour closed through the pen's home point, with neighbour lists
//!    (the K nearest path ends) and a queue of nodes to revisit; reversing a stretch of the
//!    tour reverses each path in it. The work is bounded by a budget of move evaluations and
//!    of reversed elements proportional to n (no clock: the result never depends on speed).
//! 3. **Polish**: each closed path's start is re-chosen between its neighbours, each open path
//!    flipped where that is shorter; the better of the greedy and the improved order is kept,
//!    so `improved` is never worse than `greedy`.
//!
//! Deterministic: no hashing, no clock, ties broken by position.

use crate::model::{polar, Path, Pt};
use std::collections::VecDeque;
use std::f64::consts::TAU;

const NONE: u32 = u32::MAX;
const LEAF: usize = 8;

/// Euclidean distance (`sqrt`, not `hypot`: no overflow is possible at plotter sizes and it
/// is several times faster, which matters in the inner loops).
fn dist(a: Pt, b: Pt) -> f64 {
    let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
    (dx * dx + dy * dy).sqrt()
}

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
            self.knn2_rec(0, q, k, out);
            for e in out.iter_mut() {
                e.0 = e.0.sqrt();
            }
        } else {
            self.knn_rec(0, q, k, out);
        }
    }

    fn knn2_rec(&self, node: usize, q: Pt, k: usize, out: &mut Vec<(f64, usize)>) {
        let n = &self.nodes[node];
        let bound = if out.len() == k { out[k - 1].0 } else { f64::INFINITY };
        if n.alive == 0 || Self::lower2(n, q) >= bound {
            return;
        }
        if n.left == NONE {
            for p in n.lo as usize..n.hi as usize {
                if !self.alive[p] {
                    continue;
                }
                let (dx, dy) = (q[0] - self.pts[p][0], q[1] - self.pts[p][1]);
                let d = dx * dx + dy * dy;
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
        let (dl, dr) = (Self::lower2(&self.nodes[l], q), Self::lower2(&self.nodes[r], q));
        let (first, second) = if dl <= dr { (l, r) } else { (r, l) };
        self.knn2_rec(first, q, k, out);
        self.knn2_rec(second, q, k, out);
    }

    /// Squared distance from `q` to a node's box (valid as a bound when no radii are left).
    fn lower2(n: &Node, q: Pt) -> f64 {
        let dx = (n.min[0] - q[0]).max(q[0] - n.max[0]).max(0.0);
        let dy = (n.min[1] - q[1]).max(q[1] - n.max[1]).max(0.0);
        dx * dx + dy * dy
    }

    fn knn_rec(&self, node: usize, q: Pt, k: usize, out: &mut Vec<(f64, usize)>) {
        let n = &self.nodes[node];
        let bound = if out.len() == k { out[k - 1].0 } else { f64::INFINITY };
        if n.alive == 0 || self.lower(n, q) >= bound {
            return;
        }
        if n.left == NONE {
            for p in n.lo as usize..n.hi as usize {
                if !self.alive[p] {
                    continue;
                }
                let d = self.point_dist(q, p);
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
        let (dl, dr) = (self.lower(&self.nodes[l], q), self.lower(&self.nodes[r], q));
        let (first, second) = if dl <= dr { (l, r) } else { (r, l) };
        self.knn_rec(first, q, k, out);
        self.knn_rec(second, q, k, out);
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

// -------------------------------------------------------------------------------------------
// Oriented paths

/// Where a path is entered: open paths forwards or backwards, closed paths at a vertex or
/// an angle.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Entry {
    Forward,
    Backward,
    Vertex(usize, bool),
    Angle(f64, bool),
}

fn closed_polyline(p: &Path) -> Option<&[Pt]> {
    match p {
        Path::Polyline { points, closed: true } if points.len() > 1 => Some(points),
        _ => None,
    }
}

fn full_circle(p: &Path) -> Option<(Pt, f64)> {
    match p {
        Path::Arc { center, radius, sweep, .. } if sweep.abs() >= TAU => Some((*center, *radius)),
        _ => None,
    }
}

/// Entry and exit points of `p` entered as `e`.
fn ends(p: &Path, e: Entry) -> [Pt; 2] {
    match e {
        Entry::Forward => [p.start_point(), p.end_point()],
        Entry::Backward => [p.end_point(), p.start_point()],
        Entry::Vertex(v, _) => {
            let q = closed_polyline(p)
                .and_then(|pts| pts.get(v).copied())
                .unwrap_or_else(|| p.start_point());
            [q, q]
        }
        Entry::Angle(a, _) => {
            let q = full_circle(p).map(|(c, r)| polar(c, r, a)).unwrap_or_else(|| p.start_point());
            [q, q]
        }
    }
}

fn flip(e: Entry) -> Entry {
    match e {
        Entry::Forward => Entry::Backward,
        Entry::Backward => Entry::Forward,
        Entry::Vertex(v, f) => Entry::Vertex(v, !f),
        Entry::Angle(a, f) => Entry::Angle(a, !f),
    }
}

/// The path drawn from its entry.
fn materialize(p: &Path, e: Entry) -> Path {
    match e {
        Entry::Forward => p.clone(),
        Entry::Backward => p.reversed(),
        Entry::Vertex(v, rev) => {
            let mut q = p.clone();
            if let Path::Polyline { points, .. } = &mut q {
                let v = v.min(points.len().saturating_sub(1));
                points.rotate_left(v);
            }
            if rev {
                q.reversed()
            } else {
                q
            }
        }
        Entry::Angle(a, rev) => match p {
            Path::Arc { center, radius, sweep, .. } => {
                let q = Path::Arc {
                    center: *center,
                    radius: *radius,
                    start: a,
                    sweep: sweep.abs(),
                };
                if rev {
                    q.reversed()
                } else {
                    q
                }
            }
            other => other.clone(),
        },
    }
}

/// The default entry of a path (as written).
fn natural(p: &Path) -> Entry {
    match p {
        Path::Arc { start, sweep, .. } if sweep.abs() >= TAU => Entry::Angle(*start, *sweep < 0.0),
        _ => Entry::Forward,
    }
}

fn cost(paths: &[Path], seq: &[(usize, Entry)], home: Pt) -> f64 {
    let mut at = home;
    let mut t = 0.0;
    for &(i, e) in seq {
        let [a, b] = ends(&paths[i], e);
        t += dist(at, a);
        at = b;
    }
    t
}

// -------------------------------------------------------------------------------------------
// Greedy

fn greedy(paths: &[Path], home: Pt) -> Vec<(usize, Entry)> {
    let mut items: Vec<(Pt, f64, u32, u32)> = Vec::with_capacity(paths.len() * 2);
    let mut first = Vec::with_capacity(paths.len() + 1);
    for (i, p) in paths.iter().enumerate() {
        first.push(items.len() as u32);
        let id = i as u32;
        if let Some((c, r)) = full_circle(p) {
            items.push((c, r, id, 0));
        } else if let Some(pts) = closed_polyline(p) {
            items.extend(pts.iter().enumerate().map(|(v, q)| (*q, 0.0, id, v as u32)));
        } else {
            items.push((p.start_point(), 0.0, id, 0));
            items.push((p.end_point(), 0.0, id, 1));
        }
    }
    first.push(items.len() as u32);
    let mut index = PointIndex::new(&items);
    let mut seq = Vec::with_capacity(paths.len());
    let mut pen = home;
    while let Some((pos, _)) = index.nearest(pen) {
        let (id, tag) = index.item(pos);
        let i = id as usize;
        let p = &paths[i];
        let e = if let Some((c, _)) = full_circle(p) {
            let (dx, dy) = (pen[0] - c[0], pen[1] - c[1]);
            let a = if dx == 0.0 && dy == 0.0 { 0.0 } else { dy.atan2(dx) };
            Entry::Angle(a, false)
        } else if closed_polyline(p).is_some() {
            Entry::Vertex(tag as usize, false)
        } else if tag == 1 {
            Entry::Backward
        } else {
            Entry::Forward
        };
        for k in first[i]..first[i + 1] {
            let pos = index.position(k as usize);
            index.remove(pos);
        }
        pen = ends(p, e)[1];
        seq.push((i, e));
    }
    seq
}

// -------------------------------------------------------------------------------------------
// 2-opt

/// Neighbours per node in the 2-opt.
const K: usize = 8;

/// Longest stretch one 2-opt move may reverse (the shorter side of the tour): long
/// reversals cost O(n) each and rarely pay for themselves in a greedy tour.
const MAX_REVERSAL: usize = 25_000;

struct Tour<'a> {
    paths: &'a [Path],
    entry: Vec<Entry>,
    ends: Vec<[Pt; 2]>,
    t: Vec<u32>,
    pos: Vec<u32>,
    swaps: u64,
}

impl Tour<'_> {
    fn m(&self) -> usize {
        self.t.len()
    }

    fn at(&self, i: usize) -> usize {
        self.t[i % self.m()] as usize
    }

    fn flip_node(&mut self, v: usize) {
        if v < self.paths.len() {
            self.entry[v] = flip(self.entry[v]);
        }
        self.ends[v].swap(0, 1);
    }

    /// Reverses the cyclic stretch of positions `s ..= e` (length `len`).
    fn reverse(&mut self, s: usize, len: usize) {
        let m = self.m();
        for k in 0..len / 2 {
            let (i, j) = ((s + k) % m, (s + len - 1 - k) % m);
            self.t.swap(i, j);
            self.pos[self.t[i] as usize] = i as u32;
            self.pos[self.t[j] as usize] = j as u32;
        }
        for k in 0..len {
            let v = self.t[(s + k) % m] as usize;
            self.flip_node(v);
        }
        self.swaps += len as u64;
    }

    /// Tries reversing positions `i+1 ..= j`; applies it when it shortens the tour.
    fn try_move(&mut self, i: usize, j: usize) -> Option<[usize; 4]> {
        let m = self.m();
        let (i, j) = (i % m, j % m);
        if i == j {
            return None;
        }
        let (a, b, c, d) = (self.at(i), self.at(i + 1), self.at(j), self.at(j + 1));
        let delta = dist(self.ends[a][1], self.ends[c][1]) + dist(self.ends[b][0], self.ends[d][0])
            - dist(self.ends[a][1], self.ends[b][0])
            - dist(self.ends[c][1], self.ends[d][0]);
        if delta >= -1e-9 {
            return None;
        }
        let len = (j + m - i) % m;
        if len.min(m - len) > MAX_REVERSAL {
            return None;
        }
        if 2 * len <= m {
            self.reverse((i + 1) % m, len);
        } else {
            self.reverse((j + 1) % m, m - len);
        }
        Some([a, b, c, d])
    }
}

fn two_opt(paths: &[Path], seq: &[(usize, Entry)], home: Pt) -> Vec<(usize, Entry)> {
    let n = seq.len();
    if n < 3 {
        return seq.to_vec();
    }
    let depot = n;
    let mut entry = vec![Entry::Forward; n];
    let mut ends_v = vec![[home, home]; n + 1];
    for &(i, e) in seq {
        entry[i] = e;
        ends_v[i] = ends(&paths[i], e);
    }
    // Neighbour lists: the K nearest other paths by their ends.
    let mut items = Vec::with_capacity(2 * n);
    for (i, e) in ends_v.iter().enumerate().take(n) {
        items.push((e[0], 0.0, i as u32, 0));
        if dist(e[0], e[1]) > 0.0 {
            items.push((e[1], 0.0, i as u32, 1));
        }
    }
    let index = PointIndex::new(&items);
    let mut nbr = vec![NONE; n * K];
    let mut found = Vec::new();
    let mut cand: Vec<(f64, u32)> = Vec::with_capacity(4 * K);
    for i in 0..n {
        cand.clear();
        let [e0, e1] = ends_v[i];
        let both = [e0, e1];
        // A closed path's two ends are one point: one query.
        let queries = if e0 == e1 { &both[..1] } else { &both[..] };
        for q in queries {
            index.k_nearest(*q, K + 2, &mut found);
            cand.extend(found.iter().map(|&(d, p)| (d, index.item(p).0)).filter(|&(_, id)| id as usize != i));
        }
        cand.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut k = 0;
        for &(_, id) in cand.iter() {
            if k == K {
                break;
            }
            if !nbr[i * K..i * K + k].contains(&id) {
                nbr[i * K + k] = id;
                k += 1;
            }
        }
    }
    let mut t: Vec<u32> = Vec::with_capacity(n + 1);
    t.push(depot as u32);
    t.extend(seq.iter().map(|&(i, _)| i as u32));
    let mut pos = vec![0u32; n + 1];
    for (p, &v) in t.iter().enumerate() {
        pos[v as usize] = p as u32;
    }
    let mut tour = Tour {
        paths,
        entry,
        ends: ends_v,
        t,
        pos,
        swaps: 0,
    };
    // Budgets, not a clock: the same input always does the same work.
    let max_evals = 60 * (n as u64) * K as u64;
    let max_swaps = 200 * n as u64 + 2_000_000;
    let mut evals = 0u64;
    let mut queue: VecDeque<u32> = (0..n as u32).map(|k| seq[k as usize].0 as u32).collect();
    let mut queued = vec![true; n + 1];
    while let Some(a) = queue.pop_front() {
        let a = a as usize;
        queued[a] = false;
        if evals >= max_evals || tour.swaps >= max_swaps {
            break;
        }
        for k in 0..K {
            let c = nbr[a * K + k];
            if c == NONE {
                break;
            }
            let c = c as usize;
            evals += 2;
            let m = tour.m();
            let (pa, pc) = (tour.pos[a] as usize, tour.pos[c] as usize);
            let moved = tour.try_move(pa, pc).or_else(|| tour.try_move(pa + m - 1, pc + m - 1));
            if let Some(touched) = moved {
                for v in touched.into_iter().chain([a]) {
                    if v < n && !queued[v] {
                        queued[v] = true;
                        queue.push_back(v as u32);
                    }
                }
                break;
            }
        }
    }
    // Read the cycle from the depot both ways; drop the longer of the two depot edges.
    let m = tour.m();
    let p0 = tour.pos[depot] as usize;
    let fwd: Vec<(usize, Entry)> = (1..m).map(|k| tour.at(p0 + k)).map(|v| (v, tour.entry[v])).collect();
    let bwd: Vec<(usize, Entry)> = (1..m).map(|k| tour.at(p0 + m - k)).map(|v| (v, flip(tour.entry[v]))).collect();
    if cost(paths, &bwd, home) < cost(paths, &fwd, home) {
        bwd
    } else {
        fwd
    }
}

/// Re-chooses each closed path's start between its neighbours and flips open paths where
/// that is shorter. Only ever shortens.
fn polish(paths: &[Path], seq: &mut [(usize, Entry)], home: Pt) {
    let n = seq.len();
    for k in 0..n {
        let prev = if k == 0 {
            home
        } else {
            ends(&paths[seq[k - 1].0], seq[k - 1].1)[1]
        };
        let next = if k + 1 < n {
            Some(ends(&paths[seq[k + 1].0], seq[k + 1].1)[0])
        } else {
            None
        };
        let (i, e) = seq[k];
        let p = &paths[i];
        let through = |q: [Pt; 2]| dist(prev, q[0]) + next.map_or(0.0, |x| dist(q[1], x));
        let mut best = (through(ends(p, e)), e);
        let mut consider = |cand: Entry| {
            let c = through(ends(p, cand));
            if c < best.0 - 1e-12 {
                best = (c, cand);
            }
        };
        match e {
            Entry::Forward | Entry::Backward => consider(flip(e)),
            Entry::Vertex(_, rev) => {
                if let Some(pts) = closed_polyline(p) {
                    for v in 0..pts.len() {
                        consider(Entry::Vertex(v, rev));
                    }
                }
            }
            Entry::Angle(_, rev) => {
                if let Some((c, _)) = full_circle(p) {
                    let ang = |q: Pt| (q[1] - c[1]).atan2(q[0] - c[0]);
                    consider(Entry::Angle(ang(prev), rev));
                    if let Some(x) = next {
                        consider(Entry::Angle(ang(x), rev));
                        consider(Entry::Angle(ang([(prev[0] + x[0]) / 2.0, (prev[1] + x[1]) / 2.0]), rev));
                    }
                }
            }
        }
        seq[k].1 = best.1;
    }
}

/// How paths are ordered before they are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathOrder {
    /// Placement order, as the shapes were placed.
    None,
    /// Greedy nearest neighbour (with reversal and closed-path start choice).
    Greedy,
    /// Greedy, then 2-opt improvement.
    Improved,
}

/// The order to draw in: `none` keeps the paths as they are, `greedy` and `improved` as
/// described in the module docs. Returns the paths re-ordered, rotated and reversed.
pub fn order(paths: &[Path], home: Pt, mode: PathOrder) -> Vec<Path> {
    let seq: Vec<(usize, Entry)> = match mode {
        PathOrder::None => return paths.to_vec(),
        PathOrder::Greedy => greedy(paths, home),
        PathOrder::Improved => {
            let g = greedy(paths, home);
            let mut better = two_opt(paths, &g, home);
            polish(paths, &mut better, home);
            if cost(paths, &better, home) <= cost(paths, &g, home) {
                better
            } else {
                g
            }
        }
    };
    seq.into_iter().map(|(i, e)| materialize(&paths[i], e)).collect()
}

/// Paths in their written order with their written entries, for comparisons.
pub fn natural_travel(paths: &[Path], home: Pt) -> f64 {
    let seq: Vec<(usize, Entry)> = paths.iter().enumerate().map(|(i, p)| (i, natural(p))).collect();
    cost(paths, &seq, home)
}

#[cfg(test)]
mod tests;
