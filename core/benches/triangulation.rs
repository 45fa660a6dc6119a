//! An experiment against the cell sampler: the valid centres of the next circle covered by the
//! triangles of a regular (power) triangulation of the placed circles' centres and the
//! region's corners, instead of by cells. Each triangle is drawn by the box of what its three
//! corner discs, grown by the need, leave of it (exact integer weights in a Fenwick tree over
//! blocks of 64 triangles); a triangle with no room waits until the need falls to the largest
//! clearance its three discs leave in it (a three-disc Apollonius centre, or a point of an
//! edge where two of the distances meet). A candidate is kept when it lies in its triangle,
//! clear of the three discs and of the edge, and passes an exact test through the library's
//! spatial hash (the engine's). Circles only, in the 200 x 200 rect, `f64`; not the library's sampler.
//!
//!     cargo bench -p zetafill --bench triangulation -- N [C N_OFFSET EPS] [--sweep] [--check]
//!
//! A live triangle's box holds for needs down to `(1 - EPS)` times the need it was made for.
//! Without `--sweep` each triangle is refreshed from a queue when the need falls below that;
//! with it, every triangle is refreshed in one sweep when the need falls below the last
//! sweep's. `--check` tests, every tenth placement, that 200 random valid centres lie in a
//! live triangle's box, and at the end that no two circles overlap (brute force: small N).
//! It prints the time, trials and their split; it asserts nothing about time.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

use rand_core::{RngCore, SeedableRng};
use rand_xoshiro::Xoshiro256PlusPlus as Rng;
use std::collections::BinaryHeap;
use std::time::Instant;
use zetafill::internals::spatial::SpatialHash;

const NONE: u32 = u32::MAX;

#[derive(Clone, Copy, Default)]
struct Tri {
    v: [u32; 3],
    n: [u32; 3],
}

#[derive(Default)]
struct Stats {
    trials: u64,
    out_tri: u64,
    in_vertex: u64,
    out_inset: u64,
    exact_rej: u64,
    refresh: u64,
    wakes: u64,
    flips: u64,
    hash_shapes: u64,
}

struct Sum {
    w: Vec<u64>,
    fen: Vec<u64>,
    total: u64,
}

const BLK: usize = 64;

impl Sum {
    fn new(slots: usize) -> Sum {
        let blocks = slots.div_ceil(BLK);
        Sum {
            w: vec![0; blocks * BLK],
            fen: vec![0; blocks.next_power_of_two() + 1],
            total: 0,
        }
    }
    fn set(&mut self, i: usize, w: u64) {
        let old = self.w[i];
        if old == w {
            return;
        }
        self.w[i] = w;
        let mut b = i / BLK + 1;
        let n = self.fen.len();
        while b < n {
            self.fen[b] = self.fen[b].wrapping_add(w).wrapping_sub(old);
            b += b & b.wrapping_neg();
        }
        self.total = self.total.wrapping_add(w).wrapping_sub(old);
    }
    fn rebuild(&mut self) {
        let n = self.fen.len();
        for f in self.fen.iter_mut() {
            *f = 0;
        }
        let mut total = 0u64;
        for (b, chunk) in self.w.chunks(BLK).enumerate() {
            let s: u64 = chunk.iter().sum();
            total += s;
            self.fen[b + 1] = s;
        }
        for i in 1..n {
            let p = i + (i & i.wrapping_neg());
            if p < n {
                let v = self.fen[i];
                self.fen[p] += v;
            }
        }
        self.total = total;
    }
    fn find(&self, mut x: u64) -> usize {
        let n = self.fen.len() - 1;
        let mut pos = 0;
        let mut step = n;
        while step > 0 {
            if pos + step <= n && self.fen[pos + step] <= x {
                pos += step;
                x -= self.fen[pos];
            }
            step >>= 1;
        }
        let base = pos * BLK;
        for k in 0..BLK {
            let w = self.w[base + k];
            if x < w {
                return base + k;
            }
            x -= w;
        }
        unreachable!()
    }
}

const BPO: f64 = 16.0;
const NB: usize = 64 * 16;

/// A bucket queue of (radius key, triangle, generation), popped in decreasing key as the need
/// falls: buckets by the key's logarithm, the current one a small heap.
struct Wake {
    r0: f64,
    buckets: Vec<Vec<(u64, u32, u32)>>,
    cur: usize,
    heap: BinaryHeap<(u64, u32, u32)>,
    len: usize,
}

impl Wake {
    fn new(r0: f64) -> Wake {
        Wake {
            r0,
            buckets: (0..NB).map(|_| Vec::new()).collect(),
            cur: 0,
            heap: BinaryHeap::new(),
            len: 0,
        }
    }
    fn bucket(&self, key: f64) -> usize {
        let b = (-(key / self.r0).log2() * BPO).floor();
        if b < 0.0 {
            0
        } else {
            (b as usize).min(NB - 1)
        }
    }
    fn push(&mut self, e: (u64, u32, u32)) {
        self.len += 1;
        let b = self.bucket(f64::from_bits(e.0));
        if b <= self.cur {
            self.heap.push(e);
        } else {
            self.buckets[b].push(e);
        }
    }
    /// The next entry whose key is at least `need`.
    fn pop_at_least(&mut self, need: f64) -> Option<(u64, u32, u32)> {
        let b = self.bucket(need);
        while self.cur < b {
            self.cur += 1;
            let v = core::mem::take(&mut self.buckets[self.cur]);
            self.heap.extend(v);
        }
        match self.heap.peek() {
            Some(&e) if f64::from_bits(e.0) >= need => {
                self.len -= 1;
                self.heap.pop()
            }
            _ => None,
        }
    }
}

struct Fill {
    sites: Vec<[f64; 3]>,
    tris: Vec<Tri>,
    rt: Vec<f64>,
    bx: Vec<[f64; 4]>,
    gen: Vec<u32>,
    sum: Sum,
    heap: Wake,
    unit: f64,
    w: f64,
    h: f64,
    // The library's spatial hash, the one the engine's exact tests use.
    hash: SpatialHash<'static, f64>,
    st: Stats,
    eps: f64,
    epochs: bool,
    q_epoch: f64,
}

fn orient(ax: f64, ay: f64, bx: f64, by: f64, cx: f64, cy: f64) -> f64 {
    (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
}

impl Fill {
    fn p(&self, i: u32) -> (f64, f64, f64) {
        let i = i as usize;
        let [x, y, r] = self.sites[i];
        (x, y, r)
    }

    fn new_tri(&mut self) -> u32 {
        // (Triangles are only ever split or flipped: none is freed.)
        self.tris.push(Tri::default());
        self.rt.push(0.0);
        self.bx.push([0.0; 4]);
        self.gen.push(0);
        (self.tris.len() - 1) as u32
    }

    fn in_tri(&self, t: u32, x: f64, y: f64, tol: f64) -> bool {
        let v = self.tris[t as usize].v;
        for k in 0..3 {
            let (ax, ay, _) = self.p(v[(k + 1) % 3]);
            let (bx, by, _) = self.p(v[(k + 2) % 3]);
            if orient(ax, ay, bx, by, x, y) < -tol {
                return false;
            }
        }
        true
    }

    /// The largest clearance from the three vertex discs anywhere in the triangle.
    fn max_clear(&self, t: u32) -> f64 {
        let v = self.tris[t as usize].v;
        let p: [(f64, f64, f64); 3] = [self.p(v[0]), self.p(v[1]), self.p(v[2])];
        let f = |x: f64, y: f64| {
            p.iter()
                .map(|&(cx, cy, r)| ((x - cx).powi(2) + (y - cy).powi(2)).sqrt() - r)
                .fold(f64::MAX, f64::min)
        };
        let mut best = f64::MIN;
        // Apollonius centres.
        let (x0, y0, r0) = p[0];
        let q1 = (p[1].0 - x0, p[1].1 - y0);
        let q2 = (p[2].0 - x0, p[2].1 - y0);
        let b1 = q1.0 * q1.0 + q1.1 * q1.1 - p[1].2 * p[1].2 + r0 * r0;
        let b2 = q2.0 * q2.0 + q2.1 * q2.1 - p[2].2 * p[2].2 + r0 * r0;
        let e1 = -2.0 * (p[1].2 - r0);
        let e2 = -2.0 * (p[2].2 - r0);
        let det = 2.0 * (q1.0 * q2.1 - q1.1 * q2.0) * 2.0;
        if det != 0.0 {
            // A = [[2q1x, 2q1y],[2q2x, 2q2y]]; inverse = 1/det [[2q2y, -2q1y],[-2q2x, 2q1x]]
            let solve = |b1: f64, b2: f64| {
                (
                    (2.0 * q2.1 * b1 - 2.0 * q1.1 * b2) / det,
                    (-2.0 * q2.0 * b1 + 2.0 * q1.0 * b2) / det,
                )
            };
            let u = solve(b1, b2);
            let w = solve(e1, e2);
            let a = w.0 * w.0 + w.1 * w.1 - 1.0;
            let b = 2.0 * (u.0 * w.0 + u.1 * w.1 - r0);
            let c = u.0 * u.0 + u.1 * u.1 - r0 * r0;
            let mut roots = [f64::NAN; 2];
            if a.abs() < 1e-300 {
                if b != 0.0 {
                    roots[0] = -c / b;
                }
            } else {
                let disc = b * b - 4.0 * a * c;
                if disc >= 0.0 {
                    let s = disc.sqrt();
                    roots = [(-b - s) / (2.0 * a), (-b + s) / (2.0 * a)];
                }
            }
            for rho in roots {
                if rho.is_finite() {
                    let x = x0 + u.0 + rho * w.0;
                    let y = y0 + u.1 + rho * w.1;
                    if self.in_tri(t, x, y, 0.0) {
                        best = best.max(f(x, y));
                    }
                }
            }
        }
        // Edges.
        for k in 0..3 {
            let (i, j, o) = (p[(k + 1) % 3], p[(k + 2) % 3], p[k]);
            let d = (j.0 - i.0, j.1 - i.1);
            let l = (d.0 * d.0 + d.1 * d.1).sqrt();
            let mut ts = [f64::NAN; 3];
            ts[0] = (i.2 + (l - i.2 - j.2) / 2.0) / l;
            for (s, (a, bpt)) in [(i, j), (j, i)].into_iter().enumerate() {
                let dd = (bpt.0 - a.0, bpt.1 - a.1);
                let dk = o.2 - a.2;
                let bb = 2.0 * (dd.0 * (a.0 - o.0) + dd.1 * (a.1 - o.1));
                let cc = (a.0 - o.0).powi(2) + (a.1 - o.1).powi(2);
                let den = 2.0 * l * dk - bb;
                if den != 0.0 {
                    let t = (cc - dk * dk) / den;
                    ts[1 + s] = if s == 0 { t } else { 1.0 - t };
                }
            }
            for t in ts {
                if (0.0..=1.0).contains(&t) {
                    best = best.max(f(i.0 + t * d.0, i.1 + t * d.1));
                }
            }
        }
        best
    }

    /// The box of the points of triangle t at least `q` from its vertex discs, in the inset.
    fn rem_box(&self, t: u32, q: f64) -> Option<[f64; 4]> {
        let v = self.tris[t as usize].v;
        let p: [(f64, f64, f64); 3] = [self.p(v[0]), self.p(v[1]), self.p(v[2])];
        let rho = [p[0].2 + q, p[1].2 + q, p[2].2 + q];
        let scale = self.w.max(self.h);
        let tol = 1e-12 * scale * scale;
        let mut b = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
        let mut any = false;
        let outside = |x: f64, y: f64, skip: usize| {
            (0..3).all(|k| k == skip || (x - p[k].0).powi(2) + (y - p[k].1).powi(2) >= rho[k] * rho[k] * (1.0 - 1e-9))
        };
        let add = |x: f64, y: f64, b: &mut [f64; 4], any: &mut bool| {
            b[0] = b[0].min(x);
            b[1] = b[1].min(y);
            b[2] = b[2].max(x);
            b[3] = b[3].max(y);
            *any = true;
        };
        // Edges against the three circles.
        for k in 0..3 {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            let d = (p[j].0 - p[i].0, p[j].1 - p[i].1);
            let l2 = d.0 * d.0 + d.1 * d.1;
            for c in 0..3 {
                let a = (p[i].0 - p[c].0, p[i].1 - p[c].1);
                let bb = 2.0 * (d.0 * a.0 + d.1 * a.1);
                let cc = a.0 * a.0 + a.1 * a.1 - rho[c] * rho[c];
                let disc = bb * bb - 4.0 * l2 * cc;
                if disc < 0.0 {
                    continue;
                }
                let s = disc.sqrt();
                for tt in [(-bb - s) / (2.0 * l2), (-bb + s) / (2.0 * l2)] {
                    if (0.0..=1.0).contains(&tt) {
                        let (x, y) = (p[i].0 + tt * d.0, p[i].1 + tt * d.1);
                        if outside(x, y, c) {
                            add(x, y, &mut b, &mut any);
                        }
                    }
                }
            }
        }
        // Circle pairs.
        for k in 0..3 {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            let d = (p[j].0 - p[i].0, p[j].1 - p[i].1);
            let l2 = d.0 * d.0 + d.1 * d.1;
            let l = l2.sqrt();
            if l >= rho[i] + rho[j] || l <= (rho[i] - rho[j]).abs() {
                continue;
            }
            let a = (rho[i] * rho[i] - rho[j] * rho[j] + l2) / (2.0 * l);
            let hh = (rho[i] * rho[i] - a * a).max(0.0).sqrt();
            let (mx, my) = (p[i].0 + a * d.0 / l, p[i].1 + a * d.1 / l);
            for sg in [-1.0, 1.0] {
                let (x, y) = (mx - sg * hh * d.1 / l, my + sg * hh * d.0 / l);
                if self.in_tri(t, x, y, tol) && outside(x, y, k) {
                    add(x, y, &mut b, &mut any);
                }
            }
        }
        // Extreme points of the circles.
        for k in 0..3 {
            for (dx, dy) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
                let (x, y) = (p[k].0 + dx * rho[k], p[k].1 + dy * rho[k]);
                if self.in_tri(t, x, y, tol) && outside(x, y, k) {
                    add(x, y, &mut b, &mut any);
                }
            }
        }
        if !any {
            return None;
        }
        b[0] = b[0].max(q);
        b[1] = b[1].max(q);
        b[2] = b[2].min(self.w - q);
        b[3] = b[3].min(self.h - q);
        if b[0] >= b[2] || b[1] >= b[3] {
            return None;
        }
        Some(b)
    }

    /// The weight of triangle t for the epoch's radius, set in place (no sum update).
    fn weigh_epoch(&mut self, t: u32) -> u64 {
        let q = self.q_epoch;
        if self.rt[t as usize] < q {
            return 0;
        }
        match self.rem_box(t, q) {
            None => 0,
            Some(b) => {
                self.bx[t as usize] = b;
                let a = (b[2] - b[0]) * (b[3] - b[1]);
                ((a / self.unit).ceil() as u64).max(1)
            }
        }
    }

    fn sweep(&mut self, need: f64) {
        self.q_epoch = need * (1.0 - self.eps);
        for t in 0..self.tris.len() as u32 {
            let w = self.weigh_epoch(t);
            self.sum.w[t as usize] = w;
        }
        self.sum.rebuild();
        self.st.refresh += 1;
    }

    fn update(&mut self, t: u32, need: f64) {
        if self.epochs {
            let w = self.weigh_epoch(t);
            self.sum.set(t as usize, w);
            return;
        }
        let g = self.gen[t as usize];
        let rt = self.rt[t as usize];
        if rt < need {
            self.sum.set(t as usize, 0);
            if rt > 0.0 {
                self.heap.push((rt.to_bits(), t, g));
            }
            return;
        }
        let q = need * (1.0 - self.eps);
        match self.rem_box(t, q) {
            None => self.sum.set(t as usize, 0),
            Some(b) => {
                self.bx[t as usize] = b;
                let a = (b[2] - b[0]) * (b[3] - b[1]);
                self.sum.set(t as usize, ((a / self.unit).ceil() as u64).max(1));
            }
        }
        self.heap.push((q.to_bits(), t, g));
    }

    fn touch(&mut self, t: u32) {
        self.gen[t as usize] = self.gen[t as usize].wrapping_add(1);
        self.rt[t as usize] = self.max_clear(t) * (1.0 + 1e-9) + 1e-12;
    }

    fn hash_insert(&mut self, s: u32) {
        let (x, y, r) = self.p(s);
        self.hash.insert(s, x, y, r);
    }

    fn blocked(&mut self, x: f64, y: f64, r: f64, skip: [u32; 3]) -> bool {
        let total = self.sites.len() as u32;
        let mut visits = 0u64;
        let mut hit = false;
        for (level, max_r) in self.hash.occupied() {
            let reach = r + max_r;
            let sites = &self.sites;
            self.hash.query(level, [x - reach, y - reach, x + reach, y + reach], total, |j| {
                visits += 1;
                if skip.contains(&j) {
                    return true;
                }
                let [cx, cy, cr] = sites[j as usize];
                let s = cr + r;
                hit = (cx - x).powi(2) + (cy - y).powi(2) < s * s;
                !hit
            });
            if hit {
                break;
            }
        }
        self.st.hash_shapes += visits;
        hit
    }

    fn legalize(&mut self, stack: &mut Vec<(u32, u32)>, touched: &mut Vec<u32>) {
        while let Some((t, s)) = stack.pop() {
            let tr = self.tris[t as usize];
            let k = tr.v.iter().position(|&v| v == s).expect("the new vertex is a corner");
            let u = tr.n[k];
            if u == NONE {
                continue;
            }
            let pv = tr.v[(k + 1) % 3];
            let qv = tr.v[(k + 2) % 3];
            let ur = self.tris[u as usize];
            let m = ur.n.iter().position(|&x| x == t).expect("neighbours point at each other");
            let d = ur.v[m];
            // power in-circle test of d against (s, p, q)
            let (sx, sy, sr) = self.p(s);
            let (px, py, pr) = self.p(pv);
            let (qx, qy, qr) = self.p(qv);
            let (dx, dy, dr) = self.p(d);
            let lift = |x: f64, y: f64, r: f64| (x - dx, y - dy, (x - dx).powi(2) + (y - dy).powi(2) - r * r + dr * dr);
            let a = lift(sx, sy, sr);
            let b = lift(px, py, pr);
            let c = lift(qx, qy, qr);
            let det = a.0 * (b.1 * c.2 - b.2 * c.1) - a.1 * (b.0 * c.2 - b.2 * c.0) + a.2 * (b.0 * c.1 - b.1 * c.0);
            if det <= 0.0 {
                continue;
            }
            // convex quad s, p, d, q?
            if orient(sx, sy, px, py, dx, dy) <= 0.0 || orient(sx, sy, dx, dy, qx, qy) <= 0.0 {
                continue;
            }
            self.st.flips += 1;
            let up = ur.n[(m + 1) % 3]; // across edge p-d (opposite q in u)
            let uq = ur.n[(m + 2) % 3]; // across edge d-q (opposite p in u)
            let tq = tr.n[(k + 2) % 3]; // across s-p (opposite q in t)
            let tp = tr.n[(k + 1) % 3]; // across q-s (opposite p in t)
            self.tris[t as usize] = Tri {
                v: [s, pv, d],
                n: [up, u, tq],
            };
            self.tris[u as usize] = Tri {
                v: [s, d, qv],
                n: [uq, tp, t],
            };
            self.repoint(up, u, t);
            self.repoint(tp, t, u);
            touched.push(t);
            touched.push(u);
            stack.push((t, s));
            stack.push((u, s));
        }
    }

    /// Makes triangle `nbr` (none on the hull) name `new` where it named `old` as a neighbour.
    fn repoint(&mut self, nbr: u32, old: u32, new: u32) {
        if nbr == NONE {
            return;
        }
        let x = &mut self.tris[nbr as usize];
        let i = x.n.iter().position(|&y| y == old).expect("neighbours point at each other");
        x.n[i] = new;
    }

    fn insert(&mut self, s: u32, t: u32, need: f64) {
        let tr = self.tris[t as usize];
        let [a, b, c] = tr.v;
        let [na, nb, nc] = tr.n;
        let t1 = self.new_tri();
        let t2 = self.new_tri();
        self.tris[t as usize] = Tri {
            v: [s, b, c],
            n: [na, t1, t2],
        };
        self.tris[t1 as usize] = Tri {
            v: [a, s, c],
            n: [t, nb, t2],
        };
        self.tris[t2 as usize] = Tri {
            v: [a, b, s],
            n: [t, t1, nc],
        };
        self.repoint(nb, t, t1);
        self.repoint(nc, t, t2);
        let mut touched = vec![t, t1, t2];
        let mut stack = vec![(t, s), (t1, s), (t2, s)];
        self.legalize(&mut stack, &mut touched);
        touched.sort_unstable();
        touched.dedup();
        for &x in &touched {
            self.touch(x);
            self.update(x, need);
        }
    }

    fn find_tri(&self, x: f64, y: f64) -> Option<u32> {
        (0..self.tris.len() as u32).find(|&t| self.in_tri(t, x, y, 0.0))
    }
}

fn uniform(rng: &mut Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

fn bounded(rng: &mut Rng, n: u64) -> u64 {
    // Lemire's unbiased bounded draw
    let mut x = rng.next_u64();
    let mut m = (x as u128) * (n as u128);
    let mut l = m as u64;
    if l < n {
        let t = n.wrapping_neg() % n;
        while l < t {
            x = rng.next_u64();
            m = (x as u128) * (n as u128);
            l = m as u64;
        }
    }
    (m >> 64) as u64
}

fn main() {
    // Numbers in order (cargo passes `--bench` too), then the flags.
    let nums: Vec<f64> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let flag = |f: &str| std::env::args().any(|a| a == f);
    let n = nums.first().map_or(10_000, |&v| v as usize);
    let c = nums.get(1).copied().unwrap_or(1.3);
    let nn = nums.get(2).copied().unwrap_or(1.0);
    let eps = nums.get(3).copied().unwrap_or(0.1);
    let check = flag("--check");
    let (w, h) = (200.0, 200.0);
    let zeta = zetafill::internals::zeta::hurwitz_zeta(c, nn).expect("c > 1, N > 0");
    let radius = |i: usize| (w * h / (zeta * (i as f64 + nn).powf(c)) / std::f64::consts::PI).sqrt();
    let r0 = radius(0);
    let slots = 2 * n + 16;
    let mut f = Fill {
        sites: vec![[0.0, 0.0, 0.0], [w, 0.0, 0.0], [w, h, 0.0], [0.0, h, 0.0]],
        tris: Vec::new(),
        rt: Vec::new(),
        bx: Vec::new(),
        gen: Vec::new(),
        sum: Sum::new(slots),
        heap: Wake::new(r0),
        unit: w * h / (1u64 << 40) as f64,
        w,
        h,
        hash: SpatialHash::new(
            Vec::leak(vec![NONE; (2 * n + 8).next_power_of_two()]),
            Vec::leak(vec![NONE; n + 8]),
            w.max(h),
        )
        .expect("buckets"),
        st: Stats::default(),
        eps,
        epochs: flag("--sweep"),
        q_epoch: f64::MAX,
    };
    let t0 = f.new_tri();
    let t1 = f.new_tri();
    f.tris[t0 as usize] = Tri {
        v: [0, 1, 2],
        n: [NONE, t1, NONE],
    };
    f.tris[t1 as usize] = Tri {
        v: [0, 2, 3],
        n: [NONE, NONE, t0],
    };
    let need0 = radius(0);
    for t in [t0, t1] {
        f.touch(t);
        f.update(t, need0);
    }
    let mut rng = Rng::seed_from_u64(1);
    let start = Instant::now();
    let mut placed = 0;
    let mut checked_bad = 0u64;
    'outer: for i in 0..n {
        let need = radius(i);
        if f.epochs && need < f.q_epoch {
            f.sweep(need);
        }
        while let Some((_, t, g)) = f.heap.pop_at_least(need) {
            if f.gen[t as usize] != g {
                continue;
            }
            f.st.refresh += 1;
            if f.rt[t as usize] >= need && f.sum.w[t as usize] == 0 {
                f.st.wakes += 1;
            }
            f.update(t, need);
        }
        if check && i % 10 == 0 {
            // every valid point must be covered
            for _ in 0..200 {
                let (x, y) = (uniform(&mut rng) * w, uniform(&mut rng) * h);
                let valid = x >= need
                    && x <= w - need
                    && y >= need
                    && y <= h - need
                    && (4..f.sites.len())
                        .all(|j| (f.sites[j][0] - x).powi(2) + (f.sites[j][1] - y).powi(2) >= (f.sites[j][2] + need).powi(2));
                if valid {
                    let t = f.find_tri(x, y).expect("the triangles cover the rect");
                    let b = f.bx[t as usize];
                    if f.sum.w[t as usize] == 0 || x < b[0] || x > b[2] || y < b[1] || y > b[3] {
                        checked_bad += 1;
                    }
                }
            }
        }
        loop {
            if f.sum.total == 0 {
                println!("halt at {i}: no room");
                break 'outer;
            }
            f.st.trials += 1;
            let t = f.sum.find(bounded(&mut rng, f.sum.total)) as u32;
            let b = f.bx[t as usize];
            let x = b[0] + uniform(&mut rng) * (b[2] - b[0]);
            let y = b[1] + uniform(&mut rng) * (b[3] - b[1]);
            if !f.in_tri(t, x, y, 0.0) {
                f.st.out_tri += 1;
                continue;
            }
            let v = f.tris[t as usize].v;
            if v.iter().any(|&j| {
                let (cx, cy, cr) = f.p(j);
                (cx - x).powi(2) + (cy - y).powi(2) < (cr + need).powi(2)
            }) {
                f.st.in_vertex += 1;
                continue;
            }
            if x < need || x > w - need || y < need || y > h - need {
                f.st.out_inset += 1;
                continue;
            }
            if f.blocked(x, y, need, v) {
                f.st.exact_rej += 1;
                continue;
            }
            let s = f.sites.len() as u32;
            f.sites.push([x, y, need]);
            f.hash_insert(s);
            f.insert(s, t, need);
            placed += 1;
            break;
        }
    }
    let el = start.elapsed().as_secs_f64();
    let st = &f.st;
    let p = placed as f64;
    let per = |v: u64| v as f64 / p;
    println!(
        "{placed} circles, c {c}, N {nn}, eps {eps}, {}: {el:.3} s, {:.2} us a placement",
        if f.epochs { "sweeps" } else { "queue" },
        el * 1e6 / p
    );
    println!(
        "trials {:.2} a placement: outside the triangle {:.2}, in a corner disc {:.2}, beyond the edge {:.2}, failed the exact test {:.2}",
        per(st.trials),
        per(st.out_tri),
        per(st.in_vertex),
        per(st.out_inset),
        per(st.exact_rej)
    );
    println!(
        "{} a placement {:.2}, wakes {:.2}, flips {:.2}, shapes the exact test visits {:.1}; triangles {} ({} live), queued {}",
        if f.epochs { "sweeps" } else { "refreshes" },
        per(st.refresh),
        per(st.wakes),
        per(st.flips),
        per(st.hash_shapes),
        f.tris.len(),
        f.sum.w.iter().filter(|&&w| w > 0).count(),
        f.heap.len
    );
    if check {
        println!("valid centres found outside every live box: {checked_bad}");
        if placed <= 20_000 {
            let m = f.sites.len();
            let mut bad = 0;
            for a in 4..m {
                for b in a + 1..m {
                    let (p, q) = (f.sites[a], f.sites[b]);
                    if (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) < (p[2] + q[2]).powi(2) * (1.0 - 1e-12) {
                        bad += 1;
                    }
                }
            }
            println!("overlapping pairs: {bad}");
        }
    }
}
