//! The grid and the bounds: the level-0 grid over the region's box, each level's cell size,
//! and the bound on the clearance anywhere in a cell from the outside of the region and the
//! shapes the cell knows (see the module docs of [`crate::CellSampler`] for why it is a bound).

use super::{ceil_u32, cells_for, far_corner, Cell, CellSampler, Field, LevelGeom, CELL_LEVELS, CLASSES_NZ, GRID0, NEAR, NONE, RUNS};
use crate::geom::Point;
use crate::scalar::Scalar;
use core::num::NonZeroUsize;

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

    /// Tells the sampler, after [`CellSampler::init`], the least clearance any shape of the
    /// engine's `capacity` will need. With ample storage ([`cells_for`] the capacity) a cell
    /// too tight for all of them is then counted instead of kept asleep.
    pub(crate) fn set_lowest(&mut self, clearance: S, capacity: usize) {
        self.ample = self.pool.len() >= cells_for(capacity);
        let never = clearance - self.slack;
        self.never = if self.ample && never > S::ZERO { never } else { S::ZERO };
    }

    /// The bound on the clearance anywhere in the cell (with the rounding slack).
    #[inline]
    pub(super) fn upper(&self, c: &Cell<S>) -> S {
        c.u + self.slack
    }

    /// Whether a drawn point lies where the grid overhangs a torus by more than the slack (see
    /// `overhang`): it is no centre of the region.
    #[inline]
    pub(crate) fn overhangs(&self, p: Point<S>) -> bool {
        self.overhang.is_some_and(|end| p.x >= end.x || p.y >= end.y)
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
            // On hosts the four distances to a polygon come from one outline (a board keeps
            // the flash the batch would take).
            let batch = (cfg!(not(target_os = "none")) && disc.is_none()).then(|| f.dists(j, &quarters));
            for (k, (ui, &p)) in u.iter_mut().zip(quarters.iter()).enumerate() {
                let d = match (disc, batch.and_then(|b| b.get(k).copied())) {
                    (Some((o, r)), _) => far_corner(o, p, hw, hh) - r,
                    (None, Some(d)) => d + q.half_diag,
                    (None, None) => f.dist(j, p) + q.half_diag,
                };
                *ui = ui.min(d);
            }
        }
        u.into_iter().fold(S::from_f64(f64::MIN), |m, b| m.max(b))
    }

    /// Lays out the level-0 grid over the box `(x0, y0, w, h)` (the period of a torus when
    /// `wraps`), bounding each cell by its distance to the outside of the region, and drops
    /// the cells outside the region (and, with a density, those where it is 0). Called again
    /// when the density changes, it starts the cells afresh: their bounds from the region
    /// alone are true bounds whatever was placed, and they learn the shapes again.
    pub(crate) fn init(&mut self, x0: S, y0: S, w: S, h: S, wraps: bool, f: &impl Field<S>) {
        let (wf, hf) = (w.to_f64(), h.to_f64());
        let side = wf.max(hf) / f64::from(GRID0);
        let (mut nx, mut ny) = (ceil_u32(wf / side).clamp(1, GRID0), ceil_u32(hf / side).clamp(1, GRID0));
        if (nx * ny) as usize > self.main {
            (nx, ny) = (1, 1);
        }
        self.origin = Point::new(x0, y0);
        // Level-0 sides that halve exactly down to the finest level, so that every cell is
        // exactly the union of its four children and the grid covers the whole box.
        let fine = CELL_LEVELS as u32 - 1;
        let (mut cw, mut ch) = (w.grid_step(nx, fine), h.grid_step(ny, fine));
        let [rel, abs] = S::BOUND_SLACK;
        self.slack = S::from_f64(rel * wf.max(hf)) + S::from_f64(abs);
        let over = |side: S, n: u32, total: S| side * S::from_f64(f64::from(n)) - total > self.slack;
        // (Elsewhere a point beyond the box is outside the region, and the exact test says so.)
        self.overhang = (wraps && (over(cw, nx, w) || over(ch, ny, h))).then(|| Point::new(x0 + w, y0 + h));
        for g in self.geom.iter_mut() {
            *g = LevelGeom {
                w: cw,
                h: ch,
                half_diag: S::dist2_up(cw, ch).sqrt().half(),
            };
            cw = cw.half();
            ch = ch.half();
        }
        self.starts = [0; RUNS + 1];
        self.main = self.pool.len() - self.pool.len() / 8;
        self.asleep = 0;
        self.waiting = 0;
        (self.ample, self.never, self.outlived) = (false, S::ZERO, 0);
        self.weight = 0;
        self.floor = S::from_f64(f64::MAX);
        self.flush();
        self.batch_weight = 0;
        self.key = f.density_key();
        self.classes = if self.key == 0 { NonZeroUsize::MIN } else { CLASSES_NZ };
        let g0 = self.lg(0);
        self.grid_f64 = [x0.to_f64(), y0.to_f64(), g0.w.to_f64(), g0.h.to_f64(), self.slack.to_f64()];
        (self.lo, self.hi) = (self.runs() as u32, 0);
        for iy in 0..ny {
            for ix in 0..nx {
                let mut c = Cell {
                    xl: ix,
                    yr: iy,
                    ..Cell::default()
                };
                c.u = Self::bound(f, &c.near, self.centre(&c), &self.lg(0));
                if self.upper(&c) > S::ZERO {
                    self.make_live(c, f);
                } else {
                    self.stats.dropped += 1;
                }
            }
        }
        self.ready = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Fixed;

    /// A region that is its box, with no shapes.
    struct Box0(f64, f64);

    impl<S: Scalar> Field<S> for Box0 {
        fn edge(&self, p: Point<S>) -> S {
            p.x.min(p.y).min(S::from_f64(self.0) - p.x).min(S::from_f64(self.1) - p.y)
        }
        fn dist(&self, _: u32, _: Point<S>) -> S {
            S::from_f64(f64::MAX)
        }
    }

    /// On fixed point every cell is exactly two of its children wide and high at every level,
    /// and the first grid covers the box: before, a side that did not halve exactly lost a bit
    /// at each level, and the children of a cell far along the grid sat up to 0.03 mm off
    /// their parent, leaving a strip of it, valid centres included, in no cell.
    #[test]
    fn fixed_point_cells_halve_exactly_and_cover_the_box() {
        for (w, h, wraps) in [
            (9_876.543_21, 7_654.321, false),
            (123.456_789, 0.987_654, true),
            (200.0, 120.0, false),
        ] {
            let mut pool = [[0u64; 4]; 64];
            let mut cells = CellSampler::<Fixed>::new(&mut pool).unwrap();
            let (fw, fh) = (Fixed::from_f64(w), Fixed::from_f64(h));
            cells.init(Fixed::ZERO, Fixed::ZERO, fw, fh, wraps, &Box0(w, h));
            for k in 1..CELL_LEVELS as u32 {
                let (parent, child) = (cells.lg(k - 1), cells.lg(k));
                assert_eq!((child.w + child.w, child.h + child.h), (parent.w, parent.h), "{w} x {h}, level {k}");
                // The half diagonal is not below the exact one.
                let exact = libm::sqrt(child.w.to_f64().powi(2) + child.h.to_f64().powi(2)) / 2.0;
                assert!(child.half_diag.to_f64() + cells.slack.to_f64() >= exact, "{w} x {h}, level {k}");
            }
            let side = libm::ceil(w.max(h) / f64::from(GRID0));
            let (nx, ny) = (libm::ceil(w / side).max(1.0), libm::ceil(h / side).max(1.0));
            let g = cells.lg(0);
            assert!(g.w.to_f64() * nx >= w && g.h.to_f64() * ny >= h, "{w} x {h}");
            // A torus overhung by more than the slack rejects points beyond its period.
            let end = Point::new(fw, fh);
            assert_eq!(cells.overhangs(end), wraps, "{w} x {h}");
        }
    }

    /// Far-corner distances on fixed point are never below the exact ones, down to the finest
    /// cells: before, squares floored to 2^-32 mm² made a cell 2^-20 mm across a point.
    #[test]
    fn fixed_point_corner_distances_round_up() {
        let f = Fixed::from_f64;
        for (ox, oy, cx, cy, hw) in [
            (0.0, 0.0, 0.0, 0.0, 1.0 / 1_048_576.0),
            (0.0, 0.0, 3e-6, -2e-6, 7e-7),
            (100.0, 100.0, 5_000.0, 9_000.0, 0.5),
            (1.0, 2.0, 1.000_01, 2.000_02, 1e-5),
        ] {
            let got = far_corner(Point::new(f(ox), f(oy)), Point::new(f(cx), f(cy)), f(hw), f(hw)).to_f64();
            let (ax, ay) = (
                (f(cx).to_f64() - f(ox).to_f64()).abs() + f(hw).to_f64(),
                (f(cy).to_f64() - f(oy).to_f64()).abs() + f(hw).to_f64(),
            );
            let exact = libm::sqrt(ax * ax + ay * ay);
            // Up to the floor of the square root; above by at most the root of the square's
            // rounding (2^-16 mm near zero).
            assert!(got + 2.0 * Fixed::DELTA.to_f64() >= exact, "{got} < {exact}");
            assert!(got <= exact + 1.0 / 65_536.0, "{got} far above {exact}");
        }
    }
}
