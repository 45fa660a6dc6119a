//! Building the cells: the first grid, a build anew below the floor, waking, bounds, learning
//! and splitting.

use super::*;

impl SpaceCells<'_> {
    pub(super) fn begin<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>) {
        if self.started {
            return;
        }
        self.started = true;
        let ext = e.region.extent();
        let largest = ext.iter().fold(0.0f64, |m, &v| m.max(v));
        // The first grid: 16 cells along the largest side, fewer when the lent cells could
        // not hold it twice over (the fill then depends on the storage, as documented).
        let mut grid = GRID;
        while grid > 1.0 && 2.0 * grid * grid * grid > self.pool.len() as f64 {
            grid /= 2.0;
        }
        self.side0 = largest / grid;
        let [rel, abs] = S::BOUND_SLACK;
        let [orel, oabs] = S::OUTLINE_SLACK;
        self.slack = (rel + orel) * largest + abs + oabs;
        self.grid = ext.map(|v| libm::ceil(v / self.side0).clamp(1.0, grid) as u32);
    }

    /// Builds the cells anew from the first grid for a solid that needs `need`: every cell
    /// whose bound is at least the new floor (`FLOOR` times `need`) is kept, live when it
    /// admits `need`, asleep otherwise; a cell larger than the need is refined first (while
    /// the storage lets every cell still to be visited find a place, so none is lost). Each
    /// cell near the need's size looks up the solids nearest its centre.
    pub(super) fn rebuild<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, need: f64) {
        self.rebuilds = self.rebuilds.saturating_add(1);
        self.starts = [0; SPACE_CELL_LEVELS + 1];
        self.heap = 0;
        self.weight = 0;
        self.floor = FLOOR * need;
        let limit = self.pool.len().min(self.budget(e.len));
        let mut stack = [SpaceCell::default(); STACK];
        let [nx, ny, nz] = self.grid;
        for ix in 0..nx {
            for iy in 0..ny {
                for iz in 0..nz {
                    let root = SpaceCell {
                        at: [ix, iy, iz],
                        u: f64::INFINITY,
                        ..SpaceCell::default()
                    };
                    let mut top = 0usize;
                    if let Some(s) = stack.get_mut(0) {
                        *s = root;
                        top = 1;
                    }
                    while top > 0 {
                        top -= 1;
                        let mut c = stack.get(top).copied().unwrap_or_default();
                        let (m, h) = (self.centre(&c), self.half_diagonal(c.level));
                        c.u = self.bound_at(e, &c.known, m, c.level).min(c.u);
                        // What the parent knew may already drop the cell; otherwise a cell
                        // near the need's size looks its nearest solids up.
                        if h <= ASK * need && c.u >= self.floor {
                            c.known = nearest(e, m, h + need, &c.known);
                            c.u = self.bound_at(e, &c.known, m, c.level).min(c.u);
                        }
                        if c.u < self.floor || c.u <= 0.0 {
                            continue;
                        }
                        let pending = top + (nx * ny * nz) as usize;
                        let room = self.live() + self.heap + pending + 8 <= limit;
                        if h > need && usize::from(c.level) + 1 < SPACE_CELL_LEVELS && room && top + 8 <= STACK {
                            for child in 0..8u32 {
                                let bits = [child & 1, (child >> 1) & 1, (child >> 2) & 1];
                                let k = SpaceCell {
                                    at: core::array::from_fn(|a| {
                                        c.at.get(a).copied().unwrap_or(0).wrapping_mul(2) + bits.get(a).copied().unwrap_or(0)
                                    }),
                                    level: c.level + 1,
                                    rejects: 0,
                                    u: c.u,
                                    known: c.known,
                                };
                                if let Some(s) = stack.get_mut(top) {
                                    *s = k;
                                    top += 1;
                                }
                            }
                        } else if c.u >= need {
                            let _ = self.insert_live(c);
                        } else {
                            self.push_sleep(c);
                        }
                    }
                }
            }
        }
    }

    /// Readies the cells for a solid that needs `need` (before the slack): rebuilds them when
    /// the need fell below the floor, wakes the sleepers it admits otherwise. Returns the need
    /// the cells are compared with.
    pub(super) fn prepare<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, need: f64) -> f64 {
        self.begin(e);
        let need = need - self.slack;
        if need < self.floor {
            self.rebuild(e, need);
        } else {
            self.wake(need);
        }
        need
    }

    /// Wakes every sleeping cell whose bound admits `need`.
    pub(super) fn wake(&mut self, need: f64) {
        while self.heap > 0 && self.heap_u(0) >= need {
            match self.pop_sleep() {
                Some(c) => {
                    if self.insert_live(c).is_none() {
                        self.push_sleep(c);
                        return;
                    }
                }
                None => return,
            }
        }
    }

    /// Draws a live cell with probability proportional to its volume and a uniform point in
    /// it: `(slot, unit offsets)`.
    pub(super) fn bound_at<S: Scalar>(&self, e: &SpaceEngine<'_, S>, known: &[u32; SPACE_NEAR], centre: [f64; 3], level: u8) -> f64 {
        let (half, h) = (0.5 * self.side(level), self.half_diagonal(level));
        let mut f = edge(&e.region, centre) + h;
        for &j in known.iter().filter(|&&j| j != NIL) {
            f = f.min(e.dist_over(j, centre, half, h));
        }
        f + self.slack
    }

    /// Teaches the cell at `slot` solid `j`; says whether it knew it already.
    pub(super) fn learn<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, slot: usize, j: u32) -> bool {
        let mut c = self.get(slot);
        if c.known.contains(&j) {
            return true;
        }
        let m = self.centre(&c);
        let d = e.dist_up(j, m);
        let t = e.dist_over(j, m, 0.5 * self.side(c.level), self.half_diagonal(c.level)) + self.slack;
        if t < c.u {
            c.u = t;
        }
        // Keep the nearest SPACE_NEAR: an empty slot, or the farthest if it is farther.
        let mut worst = (0usize, f64::NEG_INFINITY);
        for (i, &k) in c.known.iter().enumerate() {
            let dk = if k == NIL { f64::INFINITY } else { e.dist_up(k, m) };
            if dk > worst.1 {
                worst = (i, dk);
            }
        }
        if worst.1 > d {
            if let Some(w) = c.known.get_mut(worst.0) {
                *w = j;
            }
        }
        self.put(slot, c);
        false
    }

    /// Splits or retires the drawn cell as `need` asks, and says whether the drawn point
    /// (offsets `units` in it) can still be valid, and in which live cell it lies.
    pub(super) fn restructure<S: Scalar>(&mut self, e: &SpaceEngine<'_, S>, slot: usize, units: [f64; 3], need: f64) -> Drawn {
        let c = self.get(slot);
        if c.u < need {
            self.retire(slot);
            return Drawn::Reject;
        }
        let level = usize::from(c.level);
        let big = self.half_diagonal(c.level) > need;
        let room = self.live() + self.heap + 7 <= self.pool.len().min(self.budget(e.len));
        if level + 1 >= SPACE_CELL_LEVELS || !(big || c.rejects >= STUBBORN) || !room {
            return Drawn::Test(slot);
        }
        let mut parent = self.remove_live(slot);
        parent.known = nearest(e, self.centre(&parent), self.half_diagonal(parent.level) + need, &parent.known);
        let pick = units.map(|u| u32::from(u >= 0.5));
        let mut at = None;
        for child in 0..8u32 {
            let bits = [child & 1, (child >> 1) & 1, (child >> 2) & 1];
            let mut k = SpaceCell {
                at: core::array::from_fn(|a| parent.at.get(a).copied().unwrap_or(0).wrapping_mul(2) + bits.get(a).copied().unwrap_or(0)),
                level: parent.level + 1,
                rejects: 0,
                u: 0.0,
                known: parent.known,
            };
            k.u = self.bound_at(e, &k.known, self.centre(&k), k.level).min(parent.u);
            let live = if k.u >= need {
                self.insert_live(k)
            } else {
                if k.u > 0.0 && k.u >= self.floor {
                    self.push_sleep(k);
                }
                None
            };
            if bits == pick {
                at = live;
            }
        }
        match at {
            Some(s) => Drawn::Test(s),
            None => Drawn::Reject,
        }
    }
}

/// The [`SPACE_NEAR`] solids nearest `p` (by [`SpaceEngine::dist_up`]) among `known` and those
/// the spatial index lists within `reach` of it.
fn nearest<S: Scalar>(e: &SpaceEngine<'_, S>, p: [f64; 3], reach: f64, known: &[u32; SPACE_NEAR]) -> [u32; SPACE_NEAR] {
    let mut best = [(f64::INFINITY, NIL); SPACE_NEAR];
    let mut offer = |j: u32| {
        if best.iter().any(|b| b.1 == j) {
            return;
        }
        let d = e.dist_up(j, p);
        // Only solids truly within reach, whatever else the index lists: the choice must not
        // depend on its layout.
        if d > reach {
            return;
        }
        // The largest by (distance, index), so that the four kept never depend on the order
        // the index lists them in.
        let mut worst = 0usize;
        for (i, b) in best.iter().enumerate() {
            if best.get(worst).is_some_and(|w| b.0 > w.0 || (b.0 == w.0 && b.1 > w.1)) {
                worst = i;
            }
        }
        if let Some(w) = best.get_mut(worst) {
            if d < w.0 || (d == w.0 && j < w.1) {
                *w = (d, j);
            }
        }
    };
    for &j in known.iter().filter(|&&j| j != NIL) {
        offer(j);
    }
    e.near(p, reach, &mut offer);
    best.map(|b| b.1)
}

/// The signed distance from `p` to the outside of the region (large for a periodic box).
fn edge(region: &SpaceRegion, p: [f64; 3]) -> f64 {
    region.edge::<f64>(V3::new(p[0], p[1], p[2]))
}
