//! The grid and the bounds: the level-0 grid over the region's box, each level's cell size,
//! and the bound on the clearance anywhere in a cell from the outside of the region and the
//! shapes the cell knows (see the module docs of [`crate::CellSampler`] for why it is a bound).

use super::{ceil_u32, far_corner, Cell, CellSampler, Field, LevelGeom, CELL_LEVELS, GRID0, NEAR, NONE};
use crate::geom::Point;
use crate::scalar::Scalar;

impl<S: Scalar> CellSampler<'_, S> {
    #[inline]
    pub(super) fn lg(&self, level: u32) -> LevelGeom<S> {
        self.geom.get(level as usize).copied().unwrap_or_default()
    }

    /// The centre of a cell.
    pub(super) fn centre(&self, c: &Cell<S>) -> Point<S> {
        let g = self.lg(c.level());
        let half = S::ONE.half();
        Point::new(
            self.origin.x + (S::from_f64(f64::from(c.ix())) + half) * g.w,
            self.origin.y + (S::from_f64(f64::from(c.iy())) + half) * g.h,
        )
    }

    /// The bound on the clearance anywhere in the cell (with the rounding slack).
    #[inline]
    pub(super) fn upper(&self, c: &Cell<S>) -> S {
        c.u + self.slack
    }

    /// The bound on the clearance anywhere in the cell at `centre` of level geometry `g`, from
    /// the outside of the region and the shapes `near`: the clearance at the centre is at most
    /// each of their distances, and clearance is 1-Lipschitz (for circles, see
    /// [`Field::box_dist`]).
    pub(super) fn bound(f: &impl Field<S>, near: &[u32; NEAR], centre: Point<S>, g: &LevelGeom<S>) -> S {
        let (hw, hh) = (g.w.half(), g.h.half());
        near.iter().filter(|&&j| j != NONE).fold(f.edge(centre) + g.half_diag, |m, &j| {
            m.min(f.box_dist(j, centre, hw, hh).unwrap_or_else(|| f.dist(j, centre) + g.half_diag))
        })
    }

    /// [`CellSampler::bound`] taken over each quarter of the cell at `centre` (whose quarters
    /// have level geometry `q`), and the largest kept: no point of the cell is clearer than
    /// the bound of the quarter it lies in. Tighter where different shapes close different
    /// quarters, for four bounds' work.
    pub(super) fn bound_by_quarters(f: &impl Field<S>, near: &[u32; NEAR], centre: Point<S>, q: &LevelGeom<S>) -> S {
        let (hw, hh) = (q.w.half(), q.h.half());
        let quarters = [(-hw, -hh), (hw, -hh), (-hw, hh), (hw, hh)].map(|(dx, dy)| centre.shift(dx, dy));
        let mut u = quarters.map(|p| f.edge(p) + q.half_diag);
        // Each known shape is looked up once for the four quarters.
        for &j in near.iter().filter(|&&j| j != NONE) {
            let disc = f.disc(j, centre);
            for (ui, &p) in u.iter_mut().zip(quarters.iter()) {
                let d = match disc {
                    Some((o, r)) => far_corner(o, p, hw, hh) - r,
                    None => f.dist(j, p) + q.half_diag,
                };
                *ui = ui.min(d);
            }
        }
        u.into_iter().fold(S::from_f64(f64::MIN), |m, b| m.max(b))
    }

    /// Lays out the level-0 grid over the box `(x0, y0, w, h)`, bounding each cell by its
    /// distance to the outside of the region, and drops the cells outside the region.
    pub(crate) fn init(&mut self, x0: S, y0: S, w: S, h: S, f: &impl Field<S>) {
        let (wf, hf) = (w.to_f64(), h.to_f64());
        let side = wf.max(hf) / f64::from(GRID0);
        let (mut nx, mut ny) = (ceil_u32(wf / side).clamp(1, GRID0), ceil_u32(hf / side).clamp(1, GRID0));
        if (nx * ny) as usize > self.main {
            (nx, ny) = (1, 1);
        }
        self.origin = Point::new(x0, y0);
        let (mut cw, mut ch) = (w / S::from_f64(f64::from(nx)), h / S::from_f64(f64::from(ny)));
        for g in self.geom.iter_mut() {
            *g = LevelGeom {
                w: cw,
                h: ch,
                half_diag: (cw * cw + ch * ch).sqrt().half(),
            };
            cw = cw.half();
            ch = ch.half();
        }
        self.slack = S::from_f64(1e-9 * wf.max(hf)) + S::from_f64(1e-12);
        self.starts = [0; CELL_LEVELS + 1];
        self.asleep = 0;
        self.waiting = 0;
        self.weight = 0;
        for iy in 0..ny {
            for ix in 0..nx {
                let mut c = Cell {
                    xl: ix,
                    yr: iy,
                    ..Cell::default()
                };
                c.u = Self::bound(f, &c.near, self.centre(&c), &self.lg(0));
                if self.upper(&c) > S::ZERO {
                    self.insert_live(c);
                } else {
                    self.stats.dropped += 1;
                }
            }
        }
        self.ready = true;
    }
}
