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

mod kdtree;

pub use kdtree::PointIndex;
use kdtree::NONE;

use crate::model::{polar, Path, Pt};
use std::collections::VecDeque;
use std::f64::consts::TAU;

/// Euclidean distance (`sqrt`, not `hypot`: no overflow is possible at plotter sizes and it
/// is several times faster, which matters in the inner loops).
fn dist(a: Pt, b: Pt) -> f64 {
    let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
    (dx * dx + dy * dy).sqrt()
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
            let a = if dx == 0.0 && dy == 0.0 { 0.0 } else { libm::atan2(dy, dx) };
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
                    let ang = |q: Pt| libm::atan2(q[1] - c[1], q[0] - c[0]);
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
