//! Sugihara's territory competing (Procedure 1) on a spade Delaunay triangulation, with the
//! connectivity repair of section 4.1 and the density control of section 4.2.
//!
//! Site `i` is spade vertex `i` (sites are only ever inserted, never removed, and coincident
//! sites are refused), so a territory is a set of vertex indices. The first `k` sites are the
//! seeds; seed `t` owns territory `t` and never changes hands.
//!
//! **Procedure 1.** A new point joins the territory of its nearest site (spade's nearest
//! neighbour walk, started from a hierarchy of coarser triangulations: O(log n) expected).
//!
//! **Connectivity (4.1), incremental.** Inserting P (territory j) removes only Delaunay edges
//! between neighbours of P, so another territory l can only split if its sites among P's
//! neighbours fall into two or more runs that are not joined through the triangles around P.
//! Then one breadth-first search per run is advanced in lockstep over l's sites; searches that
//! meet merge, a search that runs out has found a whole component, and everything stops when at
//! most one search is left unfinished. Components without l's seed go to j. The work is bounded
//! by the size of the smaller components (those that change hands, or those that the lockstep
//! finishes first), not by the number of sites: the benchmark reports it per point.
//!
//! **Density (4.2).** From the `n0`-th point on, the region's bounding box is cut into
//! m x m buckets, m = floor(log2(s i)) for the i-th point (the paper's eq. 8). A bucket holding
//! sites of two or more territories is a boundary bucket. A new point picks a bucket with
//! probability proportional to its weight (`boost` for boundary buckets, 1 for the others),
//! then a uniform position inside it. Bucket membership is kept up to date on every insertion
//! and every change of territory, and rebuilt when m grows (when i doubles), so drawing costs
//! O(1) per point.
//!
//! **Random mapping (fixed; changing it changes every output).** With the core's RNG
//! (`zetafill::rng_from_seed`, one `next_u64` per unit value): a uniform position is x then y
//! over the bounding box, redrawn until inside the region and not on an existing site. With
//! buckets, one more unit value u first: with B boundary and R other buckets and
//! T = boost B + R, t = u T picks boundary bucket floor(t / boost) if t < boost B, else other
//! bucket floor(t - boost B) (each class in its own maintained order); then x, y inside the
//! bucket; a rejected draw starts again from u.

use crate::geometry::site::SiteError;
use crate::geometry::voronoi::{p2, Clip, Pt};
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, HierarchyHintGenerator, Point2, Triangulation};
use std::collections::VecDeque;
use zetafill::internals::rng::uniform;
use zetafill::ZetaRng;

/// The triangulation: positions only, with an O(log n) point-location hierarchy.
pub type Tri = DelaunayTriangulation<Point2<f64>, (), (), (), HierarchyHintGenerator<f64>>;

/// The growth parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Growth {
    /// Total number of sites, seeds included.
    pub points: usize,
    /// Density control starts at the `n0`-th point.
    pub n0: usize,
    /// The paper's s: m = floor(log2(s i)) buckets a side.
    pub s: f64,
    /// Sampling weight of a boundary bucket relative to another bucket (>= 1).
    pub boost: f64,
    /// No density control: every point uniform over the region.
    pub uniform: bool,
}

impl Default for Growth {
    fn default() -> Self {
        Growth {
            points: 7000,
            n0: 1000,
            s: 0.1,
            boost: 8.0,
            uniform: false,
        }
    }
}

/// Counters of a run.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Counters {
    /// Sites that changed territory in connectivity repairs.
    pub reassigned: u64,
    /// Insertions after which a repair handed at least one component over.
    pub repairs: u64,
    /// Sites visited by repair searches, in all.
    pub visited: u64,
    /// The most sites one insertion's repair visited.
    pub max_visited: u64,
    /// Insertions that had to check connectivity with a search.
    pub searches: u64,
    /// Random draws rejected (outside the region or on a site).
    pub rejected: u64,
}

/// The territory pattern being grown.
#[derive(Debug)]
pub struct Model {
    /// The Delaunay triangulation of the sites (vertex i = site i).
    pub tri: Tri,
    /// Site positions.
    pub sites: Vec<Pt>,
    /// Territory of each site.
    pub territory: Vec<u32>,
    /// Number of seeds (= territories).
    pub k: usize,
    /// Counters.
    pub counters: Counters,
    /// Per-site stamp of the insertion whose repair search visited it last.
    mark: Vec<u32>,
    /// Per-site search group (valid when `mark` is current).
    owner: Vec<u32>,
    epoch: u32,
    buckets: Option<Buckets>,
}

impl Model {
    /// The model with its seeds: seed t owns territory t.
    pub fn new(seeds: &[Pt]) -> Result<Model, SiteError> {
        if seeds.len() < 2 {
            return Err(SiteError::TooFewSeeds);
        }
        let mut m = Model {
            tri: Tri::new(),
            sites: Vec::new(),
            territory: Vec::new(),
            k: seeds.len(),
            counters: Counters::default(),
            mark: Vec::new(),
            owner: Vec::new(),
            epoch: 0,
            buckets: None,
        };
        for (t, &p) in seeds.iter().enumerate() {
            if let Some(i) = m.sites.iter().position(|&q| q == p) {
                return Err(SiteError::Coincident { index: i });
            }
            m.push(p, t as u32)?;
        }
        Ok(m)
    }

    /// Number of sites.
    pub fn len(&self) -> usize {
        self.sites.len()
    }

    /// Whether there are no sites (never, once built).
    pub fn is_empty(&self) -> bool {
        self.sites.is_empty()
    }

    fn push(&mut self, p: Pt, t: u32) -> Result<usize, SiteError> {
        let i = self.sites.len();
        let h = self.tri.insert(p2(p)).map_err(|e| SiteError::Coordinate(e.to_string()))?;
        if h.index() != i {
            return Err(SiteError::Coincident { index: h.index() });
        }
        self.sites.push(p);
        self.territory.push(t);
        self.mark.push(0);
        self.owner.push(0);
        Ok(i)
    }

    /// The site nearest to `p` (Procedure 1, step 4), if any.
    pub fn nearest(&self, p: Pt) -> Option<usize> {
        self.tri.nearest_neighbor(p2(p)).map(|v| v.fix().index())
    }

    /// Adds a point (Procedure 1, steps 4 and 5) and repairs connectivity (section 4.1).
    /// Returns the new site's index.
    pub fn add(&mut self, p: Pt) -> Result<usize, SiteError> {
        let near = self.nearest(p).ok_or(SiteError::TooFewSeeds)?;
        if self.sites[near] == p {
            return Err(SiteError::Coincident { index: near });
        }
        let t = self.territory[near];
        let i = self.sites.len();
        let h = self
            .tri
            .insert_with_hint(p2(p), FixedVertexHandle::from_index(near))
            .map_err(|e| SiteError::Coordinate(e.to_string()))?;
        if h.index() != i {
            return Err(SiteError::Coincident { index: h.index() });
        }
        self.sites.push(p);
        self.territory.push(t);
        self.mark.push(0);
        self.owner.push(0);
        if let Some(b) = &mut self.buckets {
            b.add(p, t);
        }
        self.repair(i);
        Ok(i)
    }

    /// Section 4.1 after inserting site `p`.
    fn repair(&mut self, p: usize) {
        let j = self.territory[p];
        let v = self.tri.vertex(FixedVertexHandle::from_index(p));
        // P's neighbours, and which of them are joined by an edge of a triangle around P.
        let mut nb: Vec<usize> = Vec::with_capacity(8);
        let mut joined: Vec<(usize, usize)> = Vec::with_capacity(8);
        for e in v.out_edges() {
            let a = e.to().fix().index();
            nb.push(a);
            if !e.face().is_outer() {
                joined.push((a, e.next().to().fix().index()));
            }
        }
        // Territories other than j among the neighbours, in first-seen order.
        let mut others: Vec<u32> = Vec::new();
        for &a in &nb {
            let l = self.territory[a];
            if l != j && !others.contains(&l) {
                others.push(l);
            }
        }
        let mut visited_here = 0u64;
        for l in others {
            // Runs: l-neighbours joined through triangles around P (tiny union-find).
            let members: Vec<usize> = nb.iter().copied().filter(|&a| self.territory[a] == l).collect();
            if members.len() < 2 {
                continue;
            }
            let mut parent: Vec<usize> = (0..members.len()).collect();
            fn find(parent: &mut [usize], mut x: usize) -> usize {
                while parent[x] != x {
                    parent[x] = parent[parent[x]];
                    x = parent[x];
                }
                x
            }
            for &(a, b) in &joined {
                if let (Some(ia), Some(ib)) = (members.iter().position(|&m| m == a), members.iter().position(|&m| m == b)) {
                    let (ra, rb) = (find(&mut parent, ia), find(&mut parent, ib));
                    if ra != rb {
                        parent[ra.max(rb)] = ra.min(rb);
                    }
                }
            }
            let mut sources: Vec<usize> = Vec::new();
            for (i, &m) in members.iter().enumerate() {
                if find(&mut parent, i) == i {
                    sources.push(m);
                }
            }
            if sources.len() < 2 {
                continue;
            }
            self.counters.searches += 1;
            visited_here += self.split_search(l, j, &sources);
        }
        self.counters.visited += visited_here;
        self.counters.max_visited = self.counters.max_visited.max(visited_here);
    }

    /// Lockstep searches over territory `l` from `sources`; hands every component without
    /// l's seed to territory `j`. Returns the number of sites visited.
    fn split_search(&mut self, l: u32, j: u32, sources: &[usize]) -> u64 {
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            self.mark.iter_mut().for_each(|m| *m = 0);
            self.epoch = 1;
        }
        let epoch = self.epoch;
        let seed = l as usize;
        struct Group {
            queue: VecDeque<usize>,
            members: Vec<usize>,
            has_seed: bool,
            root: usize,
            done: bool,
        }
        let mut groups: Vec<Group> = Vec::with_capacity(sources.len());
        for (g, &s) in sources.iter().enumerate() {
            self.mark[s] = epoch;
            self.owner[s] = g as u32;
            groups.push(Group {
                queue: VecDeque::from([s]),
                members: vec![s],
                has_seed: s == seed,
                root: g,
                done: false,
            });
        }
        fn root(groups: &mut [Group], mut g: usize) -> usize {
            while groups[g].root != g {
                let r = groups[groups[g].root].root;
                groups[g].root = r;
                g = r;
            }
            g
        }
        let mut visited = 0u64;
        let mut nbuf: Vec<usize> = Vec::with_capacity(12);
        loop {
            let live: Vec<usize> = (0..groups.len()).filter(|&g| groups[g].root == g && !groups[g].done).collect();
            if live.len() <= 1 {
                break;
            }
            for g in live {
                let g = root(&mut groups, g);
                if groups[g].done {
                    continue;
                }
                let Some(v) = groups[g].queue.pop_front() else {
                    groups[g].done = true;
                    continue;
                };
                visited += 1;
                nbuf.clear();
                nbuf.extend(crate::geometry::voronoi::neighbours(&self.tri, v));
                for &w in &nbuf {
                    if self.territory[w] != l {
                        continue;
                    }
                    if self.mark[w] != epoch {
                        self.mark[w] = epoch;
                        self.owner[w] = g as u32;
                        groups[g].queue.push_back(w);
                        groups[g].members.push(w);
                        groups[g].has_seed |= w == seed;
                    } else {
                        let h = root(&mut groups, self.owner[w] as usize);
                        if h != g {
                            // The searches met: one component. Fold h into g (at most one
                            // fold per source, so the copying stays within the visited sites).
                            let q = std::mem::take(&mut groups[h].queue);
                            let mm = std::mem::take(&mut groups[h].members);
                            let hs = groups[h].has_seed;
                            groups[g].queue.extend(q);
                            groups[g].members.extend(mm);
                            groups[g].has_seed |= hs;
                            groups[h].root = g;
                        }
                    }
                }
                let g = root(&mut groups, g);
                if groups[g].queue.is_empty() {
                    groups[g].done = true;
                }
            }
        }
        // Components: finished root groups are whole; at most one root group is unfinished.
        let roots: Vec<usize> = (0..groups.len()).filter(|&g| groups[g].root == g).collect();
        let seed_found = roots.iter().any(|&g| groups[g].done && groups[g].has_seed);
        let mut handed: Vec<usize> = Vec::new();
        for &g in &roots {
            if groups[g].done {
                if !groups[g].has_seed {
                    handed.append(&mut groups[g].members);
                }
            } else if seed_found {
                // The unfinished group is cut off from the seed: finish it, then hand it over.
                while let Some(v) = groups[g].queue.pop_front() {
                    visited += 1;
                    nbuf.clear();
                    nbuf.extend(crate::geometry::voronoi::neighbours(&self.tri, v));
                    for &w in &nbuf {
                        if self.territory[w] == l && self.mark[w] != epoch {
                            self.mark[w] = epoch;
                            groups[g].queue.push_back(w);
                            groups[g].members.push(w);
                        }
                    }
                }
                handed.append(&mut groups[g].members);
            }
        }
        if !handed.is_empty() {
            self.counters.repairs += 1;
            self.counters.reassigned += handed.len() as u64;
            for v in handed {
                self.territory[v] = j;
                if let Some(b) = &mut self.buckets {
                    b.change(self.sites[v], l, j);
                }
            }
        }
        visited
    }

    /// Draws one new point as section 4.2 says (or uniformly) and adds it.
    pub fn grow_one(&mut self, clip: &Clip, g: &Growth, rng: &mut ZetaRng) -> Result<usize, SiteError> {
        let i = self.sites.len() + 1; // the paper's i: this is P_i
        if !g.uniform && i >= g.n0 {
            let m = bucket_side(g.s, i);
            if self.buckets.as_ref().map(|b| b.m) != Some(m) {
                self.buckets = Some(Buckets::build(m, clip.bbox(), &self.sites, &self.territory));
            }
        } else {
            self.buckets = None;
        }
        let bbox = clip.bbox();
        for _ in 0..10_000_000u32 {
            let p = match &self.buckets {
                Some(b) if b.m > 1 => b.draw(bbox, g.boost, rng),
                _ => [uniform(rng, bbox.0, bbox.2), uniform(rng, bbox.1, bbox.3)],
            };
            if !clip.inside(p) {
                self.counters.rejected += 1;
                continue;
            }
            match self.add(p) {
                Err(SiteError::Coincident { .. }) => self.counters.rejected += 1,
                r => return r,
            }
        }
        Err(SiteError::Coordinate("no point of the region could be drawn".into()))
    }

    /// Grows the pattern until it has `g.points` sites; `tick` runs after each point.
    pub fn grow(&mut self, clip: &Clip, g: &Growth, rng: &mut ZetaRng, mut tick: impl FnMut(usize)) -> Result<(), SiteError> {
        while self.sites.len() < g.points {
            let i = self.grow_one(clip, g, rng)?;
            tick(i);
        }
        Ok(())
    }

    /// The number of buckets a side in use (0 before density control starts).
    pub fn bucket_side(&self) -> usize {
        self.buckets.as_ref().map_or(0, |b| b.m)
    }

    /// The number of boundary buckets now (0 before density control starts).
    pub fn boundary_buckets(&self) -> usize {
        self.buckets.as_ref().map_or(0, |b| b.boundary.len())
    }
}

/// m = floor(log2(s i)), at least 1.
pub fn bucket_side(s: f64, i: usize) -> usize {
    let v = libm::log2(s * i as f64).floor();
    if v.is_finite() && v >= 1.0 {
        (v as usize).min(4096)
    } else {
        1
    }
}

/// The bucket grid of section 4.2.
#[derive(Debug, Clone)]
struct Buckets {
    m: usize,
    x0: f64,
    y0: f64,
    bw: f64,
    bh: f64,
    /// Per bucket: (territory, count) for each territory present.
    counts: Vec<Vec<(u32, u32)>>,
    /// Per bucket: its position in `boundary` or `other`.
    slot: Vec<usize>,
    boundary: Vec<usize>,
    other: Vec<usize>,
}

impl Buckets {
    fn build(m: usize, bbox: (f64, f64, f64, f64), sites: &[Pt], territory: &[u32]) -> Buckets {
        let (x0, y0, x1, y1) = bbox;
        let mut b = Buckets {
            m,
            x0,
            y0,
            bw: (x1 - x0) / m as f64,
            bh: (y1 - y0) / m as f64,
            counts: vec![Vec::new(); m * m],
            slot: (0..m * m).collect(),
            boundary: Vec::new(),
            other: (0..m * m).collect(),
        };
        for (p, t) in sites.iter().zip(territory) {
            b.add(*p, *t);
        }
        b
    }

    fn index(&self, p: Pt) -> usize {
        let cx = (((p[0] - self.x0) / self.bw).floor().max(0.0) as usize).min(self.m - 1);
        let cy = (((p[1] - self.y0) / self.bh).floor().max(0.0) as usize).min(self.m - 1);
        cy * self.m + cx
    }

    fn set_class(&mut self, b: usize, was: bool) {
        let now = self.counts[b].len() >= 2;
        if now == was {
            return;
        }
        let (from, to) = if now {
            (&mut self.other, &mut self.boundary)
        } else {
            (&mut self.boundary, &mut self.other)
        };
        let s = self.slot[b];
        from.swap_remove(s);
        if let Some(&moved) = from.get(s) {
            self.slot[moved] = s;
        }
        self.slot[b] = to.len();
        to.push(b);
    }

    fn add(&mut self, p: Pt, t: u32) {
        let b = self.index(p);
        let was = self.counts[b].len() >= 2;
        match self.counts[b].iter_mut().find(|e| e.0 == t) {
            Some(e) => e.1 += 1,
            None => self.counts[b].push((t, 1)),
        }
        self.set_class(b, was);
    }

    fn change(&mut self, p: Pt, from: u32, to: u32) {
        let b = self.index(p);
        let was = self.counts[b].len() >= 2;
        if let Some(k) = self.counts[b].iter().position(|e| e.0 == from) {
            self.counts[b][k].1 -= 1;
            if self.counts[b][k].1 == 0 {
                self.counts[b].remove(k);
            }
        }
        match self.counts[b].iter_mut().find(|e| e.0 == to) {
            Some(e) => e.1 += 1,
            None => self.counts[b].push((to, 1)),
        }
        self.set_class(b, was);
    }

    fn draw(&self, bbox: (f64, f64, f64, f64), boost: f64, rng: &mut ZetaRng) -> Pt {
        let (nb, no) = (self.boundary.len(), self.other.len());
        let heavy = boost * nb as f64;
        let t = uniform(rng, 0.0, heavy + no as f64);
        let b = if t < heavy && nb > 0 {
            self.boundary[((t / boost) as usize).min(nb - 1)]
        } else if no > 0 {
            self.other[((t - heavy).max(0.0) as usize).min(no - 1)]
        } else {
            self.boundary[0]
        };
        let (cx, cy) = ((b % self.m) as f64, (b / self.m) as f64);
        let (bx0, by0) = (self.x0 + cx * self.bw, self.y0 + cy * self.bh);
        // The last row and column end exactly on the box (no rounding gap).
        let bx1 = if b % self.m == self.m - 1 { bbox.2 } else { bx0 + self.bw };
        let by1 = if b / self.m == self.m - 1 { bbox.3 } else { by0 + self.bh };
        [uniform(rng, bx0, bx1), uniform(rng, by0, by1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bucket_side_follows_eq_8() {
        assert_eq!(bucket_side(0.1, 1000), 6);
        assert_eq!(bucket_side(0.1, 1279), 6);
        assert_eq!(bucket_side(0.1, 1280), 7);
        assert_eq!(bucket_side(0.1, 2559), 7);
        assert_eq!(bucket_side(0.1, 2560), 8);
        assert_eq!(bucket_side(0.1, 5), 1);
    }

    #[test]
    fn coincident_seeds_are_refused() {
        assert!(matches!(
            Model::new(&[[1.0, 1.0], [1.0, 1.0]]),
            Err(SiteError::Coincident { index: 0 })
        ));
        assert!(matches!(Model::new(&[[1.0, 1.0]]), Err(SiteError::TooFewSeeds)));
        let mut m = Model::new(&[[1.0, 1.0], [2.0, 2.0]]).unwrap_or_else(|e| panic!("{e}"));
        assert!(matches!(m.add([2.0, 2.0]), Err(SiteError::Coincident { index: 1 })));
        assert_eq!(m.len(), 2);
    }
}
