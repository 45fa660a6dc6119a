//! A bitmap of grid cells where no candidate centre can be valid: an O(1) early reject.
//!
//! Late in a fill most candidate centres fall inside a shape that is already placed, and such
//! a candidate always overlaps it. After each placement the engine marks the cells of a
//! `G x G` grid over the region's bounding box that lie entirely inside the new shape's
//! material (a disc, a convex polygon, or the inscribed disc of a concave one; a ring marks
//! nothing), with a safety margin far above rounding error; at the start it marks the cells
//! that lie entirely outside the region. A candidate whose centre falls in a marked cell is
//! rejected before any geometric test. This changes no result: the exact tests would reject
//! the same candidate, and the random draws are the same. It only makes rejections cheap.
//!
//! Storage: the caller's `u64` words (an empty slice turns the bitmap off); `G` is the largest
//! power of two with `G * G <= 64 * words`, at most 2^15. Never panics.

use crate::geom::{Geo, Point};
use crate::region::Region;
use crate::scalar::Scalar;

/// The coverage bitmap.
#[derive(Debug)]
pub struct Coverage<'a, S> {
    bits: &'a mut [u64],
    g: i64,
    origin: Point<S>,
    cw: S,
    ch: S,
    inv_w: S,
    inv_h: S,
    margin: S,
}

impl<'a, S: Scalar> Coverage<'a, S> {
    /// A bitmap over the box `[x0, x0 + w] x [y0, y0 + h]` in the given words (all cleared).
    pub fn new(bits: &'a mut [u64], origin: Point<S>, w: S, h: S) -> Self {
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
        Coverage {
            bits,
            g,
            origin,
            cw,
            ch,
            inv_w: S::ONE / cw,
            inv_h: S::ONE / ch,
            margin,
        }
    }

    /// Fraction of the grid's cells that are marked (0 when off).
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
        // cells are inside their shape by a margin far larger than that rounding.
        let cx = ((x - self.origin.x) * self.inv_w).floor_i64();
        let cy = ((y - self.origin.y) * self.inv_h).floor_i64();
        if cx < 0 || cy < 0 || cx >= self.g || cy >= self.g {
            None
        } else {
            Some((cy * self.g + cx) as usize)
        }
    }

    /// Whether (x, y) lies in a marked cell, hence cannot be a valid centre.
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

    fn cell_x(&self, cx: i64) -> S {
        self.origin.x + S::from_f64(cx as f64) * self.cw
    }

    fn cell_y(&self, cy: i64) -> S {
        self.origin.y + S::from_f64(cy as f64) * self.ch
    }

    /// Marks the cells lying entirely outside `region`, by recursive subdivision of the grid:
    /// a block whose centre is farther from the boundary than its half diagonal lies wholly
    /// on one side. Cost: about the boundary's length in cells times the edges near a block
    /// (every edge of a polygon without an edge tree).
    pub fn mark_outside(&mut self, region: &Region<'_>) {
        if self.g == 0 || matches!(region, Region::Rect { .. }) {
            return;
        }
        self.outside_block(region, 0, 0, self.g);
    }

    fn outside_block(&mut self, region: &Region<'_>, cx: i64, cy: i64, size: i64) {
        let half = S::from_f64(size as f64 / 2.0);
        let (hw, hh) = (self.cw * half, self.ch * half);
        let centre = Point::new(self.cell_x(cx) + hw, self.cell_y(cy) + hh);
        let reach = (hw * hw + hh * hh).sqrt() + self.margin;
        if region.boundary_beyond(centre, reach * reach) {
            if !region.point_inside(centre) {
                for y in cy..cy + size {
                    for x in cx..cx + size {
                        self.set(x, y);
                    }
                }
            }
            return;
        }
        if size == 1 {
            return;
        }
        let s = size / 2;
        for (dx, dy) in [(0, 0), (s, 0), (0, s), (s, s)] {
            self.outside_block(region, cx + dx, cy + dy, s);
        }
    }

    /// Marks every cell lying entirely inside `geo`'s material (`inscribed`: the radius of a
    /// disc about `centre` inside a concave polygon, used instead of the polygon), or, with
    /// `period`, inside any of its nine images shifted by multiples of the period.
    pub fn mark(&mut self, geo: &Geo<S>, centre: Point<S>, inscribed: S, period: Option<(S, S)>) {
        if self.g == 0 {
            return;
        }
        let disc;
        let solid = match geo {
            Geo::Ring { .. } => return,
            Geo::Poly { convex: false, .. } | Geo::Motif { .. } => {
                disc = Geo::Circle { c: centre, r: inscribed };
                &disc
            }
            other => other,
        };
        let offsets: &[(i8, i8)] = match period {
            Some(_) => &[(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)],
            None => &[(0, 0)],
        };
        let (pw, ph) = period.unwrap_or((S::ZERO, S::ZERO));
        for &(ox, oy) in offsets {
            let dx = match ox {
                1 => pw,
                -1 => -pw,
                _ => S::ZERO,
            };
            let dy = match oy {
                1 => ph,
                -1 => -ph,
                _ => S::ZERO,
            };
            if ox == 0 && oy == 0 {
                self.mark_one(solid);
            } else {
                self.mark_one(&solid.shift(dx, dy));
            }
        }
    }

    fn mark_one(&mut self, geo: &Geo<S>) {
        let (x0, y0, x1, y1) = geo.bounds();
        let (o, iw, ih) = (self.origin, self.inv_w, self.inv_h);
        let to_cx = move |v: S| ((v - o.x) * iw).floor_i64();
        let to_cy = move |v: S| ((v - o.y) * ih).floor_i64();
        let (cx0, cx1, cy0, cy1) = (to_cx(x0), to_cx(x1), to_cy(y0), to_cy(y1));
        if cx1 < 0 || cy1 < 0 || cx0 >= self.g || cy0 >= self.g {
            return;
        }
        // A shape narrower than two cells holds no whole cell worth a scan.
        if cx1 - cx0 < 2 || cy1 - cy0 < 2 {
            return;
        }
        let clamp = |v: i64| v.min(self.g - 1).max(0);
        let (cx0, cx1, cy0, cy1) = (clamp(cx0), clamp(cx1), clamp(cy0), clamp(cy1));
        for cy in cy0..=cy1 {
            let ya = self.cell_y(cy);
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
                    // Cells with left edge >= c.x - hc and right edge <= c.x + hc.
                    let first = (to_cx(c.x - hc) + 1).max(0);
                    let last = (to_cx(c.x + hc) - 1).min(self.g - 1);
                    let mut cx = first;
                    while cx <= last {
                        self.set(cx, cy);
                        cx += 1;
                    }
                }
                Geo::Poly { .. } => {
                    // Convex: the left boundary x = L(y) is convex and the right one R(y)
                    // concave, so over the band [ya - m, yb + m] the inner interval is fixed
                    // by the band's two edges. Cells inside [L + m, R - m] lie inside the
                    // polygon with margin m on every side.
                    let vs = geo.vertices();
                    let m = self.margin;
                    let (Some((l0, r0)), Some((l1, r1))) = (x_range(vs, ya - m), x_range(vs, yb + m)) else {
                        continue;
                    };
                    let (lo, hi) = (l0.max(l1) + m, r0.min(r1) - m);
                    if hi <= lo {
                        continue;
                    }
                    let first = (to_cx(lo) + 1).max(cx0);
                    let last = (to_cx(hi) - 1).min(cx1);
                    let mut cx = first;
                    while cx <= last {
                        self.set(cx, cy);
                        cx += 1;
                    }
                }
                Geo::Ring { .. } | Geo::Motif { .. } => return,
            }
        }
    }
}

/// The x-interval where the horizontal line at `y` crosses a convex polygon, or `None` when
/// the line misses its interior (outside the polygon's y-range).
fn x_range<S: Scalar>(vs: &[Point<S>], y: S) -> Option<(S, S)> {
    let mut range: Option<(S, S)> = None;
    for (a, b) in crate::geom::edges(vs) {
        let (lo, hi) = if a.y <= b.y { (a, b) } else { (b, a) };
        if y < lo.y || y > hi.y || hi.y == lo.y {
            continue;
        }
        let x = lo.x + (hi.x - lo.x) * ((y - lo.y) / (hi.y - lo.y));
        range = Some(match range {
            None => (x, x),
            Some((l, r)) => (l.min(x), r.max(x)),
        });
    }
    range.filter(|(l, r)| r > l)
}
