//! A bitmap of grid cells known to lie entirely inside a placed shape: an O(1) early reject.
//!
//! Late in a fill most candidate centres fall inside a shape that is already placed, and such
//! a candidate always overlaps it. The engine marks, after each placement, the cells of a
//! `G x G` grid over the region that lie entirely inside the new shape (with a safety margin
//! far above rounding error), and rejects a candidate whose centre falls in a marked cell
//! before any geometric test. This changes no result: the exact tests would reject the same
//! candidate, and the random draws are the same. It only makes rejections cheap.
//!
//! Storage: the caller's `u64` words (an empty slice turns the bitmap off); `G` is the largest
//! power of two with `G * G <= 64 * words`, at most 2^15. Never panics.

use crate::geom::{Geo, Point};
use crate::scalar::Scalar;

/// The coverage bitmap.
#[derive(Debug)]
pub struct Coverage<'a, S> {
    fine: Grid<'a, S>,
}

impl<'a, S: Scalar> Coverage<'a, S> {
    /// A bitmap over `[0, w] x [0, h]` in the given words (all cleared).
    pub fn new(bits: &'a mut [u64], w: S, h: S) -> Self {
        Coverage { fine: Grid::new(bits, w, h) }
    }

    /// Whether (x, y) lies in a marked cell, hence strictly inside a placed shape.
    #[inline]
    pub fn covered(&self, x: S, y: S) -> bool {
        self.fine.covered(x, y)
    }

    /// Marks every cell lying entirely inside `geo` (or, with `period`, inside any of its nine
    /// images shifted by multiples of the period).
    pub fn mark(&mut self, geo: &Geo<S>, period: Option<(S, S)>) {
        self.fine.mark(geo, period);
    }

    /// Fraction of the region marked in the fine grid.
    pub fn marked_fraction(&self) -> f64 {
        self.fine.marked_fraction()
    }
}

/// One grid of the bitmap.
#[derive(Debug)]
struct Grid<'a, S> {
    bits: &'a mut [u64],
    g: i64,
    cw: S,
    ch: S,
    inv_w: S,
    inv_h: S,
    margin: S,
}

impl<'a, S: Scalar> Grid<'a, S> {
    /// A grid over `[0, w] x [0, h]` in the given words (all cleared).
    pub fn new(bits: &'a mut [u64], w: S, h: S) -> Self {
        let cells = (bits.len() as u64).saturating_mul(64);
        let mut g: i64 = 1;
        while g < (1 << 15) && ((g * 2) as u64) * ((g * 2) as u64) <= cells {
            g *= 2;
        }
        if bits.is_empty() {
            g = 0;
        }
        for b in bits.iter_mut() {
            *b = 0;
        }
        let gs = S::from_f64(g.max(1) as f64);
        let (cw, ch) = (w / gs, h / gs);
        // A margin of 2^-16 cell keeps marking conservative far beyond rounding error.
        let margin = cw.min(ch) * S::from_f64(1.0 / 65536.0);
        Grid { bits, g, cw, ch, inv_w: S::ONE / cw, inv_h: S::ONE / ch, margin }
    }

    /// Fraction of the grid's cells that are marked.
    pub fn marked_fraction(&self) -> f64 {
        if self.g == 0 {
            return 0.0;
        }
        let ones: u64 = self.bits.iter().map(|w| u64::from(w.count_ones())).sum();
        ones as f64 / (self.g * self.g) as f64
    }

    #[inline]
    fn cell(&self, x: S, y: S) -> Option<usize> {
        // A point within rounding of a cell edge may be mapped to the neighbour cell; marked
        // cells lie inside their shape by a margin far larger than that rounding.
        let (cx, cy) = ((x * self.inv_w).floor_i64(), (y * self.inv_h).floor_i64());
        if cx < 0 || cy < 0 || cx >= self.g || cy >= self.g {
            None
        } else {
            Some((cy * self.g + cx) as usize)
        }
    }

    /// Whether (x, y) lies in a marked cell, hence strictly inside a placed shape.
    #[inline]
    pub fn covered(&self, x: S, y: S) -> bool {
        match self.cell(x, y) {
            Some(i) => self.bits.get(i / 64).is_some_and(|w| w >> (i % 64) & 1 == 1),
            None => false,
        }
    }

    fn set(&mut self, cx: i64, cy: i64) {
        let i = (cy * self.g + cx) as usize;
        if let Some(w) = self.bits.get_mut(i / 64) {
            *w |= 1u64 << (i % 64);
        }
    }

    /// Marks every cell lying entirely inside `geo` (or, with `period`, inside any of its nine
    /// images shifted by multiples of the period).
    pub fn mark(&mut self, geo: &Geo<S>, period: Option<(S, S)>) {
        if self.g == 0 {
            return;
        }
        let offsets: &[(i8, i8)] = match period {
            Some(_) => &[(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)],
            None => &[(0, 0)],
        };
        let (pw, ph) = period.unwrap_or((S::ZERO, S::ZERO));
        for &(ox, oy) in offsets {
            let dx = match ox { 1 => pw, -1 => -pw, _ => S::ZERO };
            let dy = match oy { 1 => ph, -1 => -ph, _ => S::ZERO };
            let g = if ox == 0 && oy == 0 { *geo } else { geo.shift(dx, dy) };
            self.mark_one(&g);
        }
    }

    fn mark_one(&mut self, geo: &Geo<S>) {
        let (x0, y0, x1, y1) = geo.bounds();
        let clamp = |v: i64| v.clamp(0, self.g - 1);
        let (cx0, cx1) = ((x0 / self.cw).floor_i64(), (x1 / self.cw).floor_i64());
        let (cy0, cy1) = ((y0 / self.ch).floor_i64(), (y1 / self.ch).floor_i64());
        if cx1 < 0 || cy1 < 0 || cx0 >= self.g || cy0 >= self.g {
            return;
        }
        // A shape narrower than two cells holds no whole cell worth a scan.
        if cx1 - cx0 < 2 || cy1 - cy0 < 2 {
            return;
        }
        let (cx0, cx1, cy0, cy1) = (clamp(cx0), clamp(cx1), clamp(cy0), clamp(cy1));
        for cy in cy0..=cy1 {
            let ya = S::from_f64(cy as f64) * self.ch;
            let yb = ya + self.ch;
            match *geo {
                Geo::Circle { c, r } => {
                    let re = r - self.margin;
                    if re <= S::ZERO {
                        return;
                    }
                    let dy = (ya - c.y).abs().max((yb - c.y).abs());
                    let rem = re * re - dy * dy;
                    if rem <= S::ZERO {
                        continue;
                    }
                    let hc = rem.sqrt();
                    // Cells with x0 >= c.x - hc and x0 + cw <= c.x + hc.
                    let first = ((c.x - hc) / self.cw).floor_i64() + 1;
                    let last = ((c.x + hc) / self.cw).floor_i64() - 1;
                    let (first, last) = (first.max(0), last.min(self.g - 1));
                    let mut cx = first;
                    while cx <= last {
                        self.set(cx, cy);
                        cx += 1;
                    }
                }
                Geo::Convex { .. } => {
                    let vs = geo.vertices();
                    for cx in cx0..=cx1 {
                        let xa = S::from_f64(cx as f64) * self.cw;
                        let xb = xa + self.cw;
                        let corners = [Point::new(xa, ya), Point::new(xb, ya), Point::new(xb, yb), Point::new(xa, yb)];
                        if corners.iter().all(|&p| inside_with_margin(p, vs, self.margin)) {
                            self.set(cx, cy);
                        }
                    }
                }
            }
        }
    }
}

/// Whether `p` is inside a counter-clockwise convex polygon by more than `m` from every edge.
fn inside_with_margin<S: Scalar>(p: Point<S>, vs: &[Point<S>], m: S) -> bool {
    let n = vs.len();
    (0..n).all(|i| {
        let (Some(&a), Some(&b)) = (vs.get(i), vs.get((i + 1) % n)) else { return false };
        let (ex, ey) = (b.x - a.x, b.y - a.y);
        let cross = ex * (p.y - a.y) - ey * (p.x - a.x);
        cross > m * (ex.abs() + ey.abs())
    })
}
