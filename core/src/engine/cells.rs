//! The engine as the cell sampler sees it ([`crate::CellSampler`]): the clearance the next shape
//! needs at its centre, signed distances to placed shapes, the nearest shapes to a point, and
//! the step that draws candidates from the sampler's live cells ([`Engine::step_fast`]).

use super::{Density, Engine, NextShape, Placement, Thinning};
use crate::geom::{edges, point_in_poly, seg_dist2, Geo, Point};
use crate::params::{StepError, Stop, StopReason};
use crate::region::Region;
use crate::rng;
use crate::sampler::{CellSampler, Drawn, Field, Verdict, NEAR, NONE};
use crate::scalar::Scalar;
use crate::shape::{Placed, ShapeKind};
use rand_core::RngCore;

/// The signed distance from `q` to a polygon's material: its edges' distance rounded up
/// outside, down inside (see [`Engine::shape_dist`]). Out of line: the circles' bounds stay
/// lean.
#[inline(never)]
fn poly_dist<S: Scalar>(g: &Geo<S>, q: Point<S>) -> S {
    let vs = g.vertices();
    // The smallest of `dist2` over the edges (one loop for each rounding).
    let nearest = |dist2: fn(Point<S>, Point<S>, Point<S>) -> S| {
        edges(vs)
            .fold(None, |m: Option<S>, (a, b)| {
                let d = dist2(q, a, b);
                Some(m.map_or(d, |m| m.min(d)))
            })
            .unwrap_or(S::ZERO)
            .sqrt()
    };
    if point_in_poly(q, vs) {
        -nearest(seg_dist2)
    } else {
        nearest(S::seg_dist2_up)
    }
}

/// The engine as the cell sampler sees it.
pub(super) struct FieldOf<'e, 'a, S: Scalar>(pub(super) &'e Engine<'a, S>);

impl<S: Scalar> Field<S> for FieldOf<'_, '_, S> {
    fn edge(&self, p: Point<S>) -> S {
        self.0.region.signed_clearance(p)
    }

    fn dist(&self, j: u32, p: Point<S>) -> S {
        self.0.shape_dist(j, p)
    }

    fn dists(&self, j: u32, ps: &[Point<S>; 4]) -> [S; 4] {
        let e = self.0;
        match e.shapes.get(j as usize) {
            // On hosts a polygon's outline is built once for the four points, as
            // `shape_dist` builds it for one (a board keeps the flash this would take).
            Some(s)
                if cfg!(not(target_os = "none"))
                    && !matches!(
                        e.entry_kind(j),
                        ShapeKind::Circle | ShapeKind::Ring { .. } | ShapeKind::Motif { .. }
                    ) =>
            {
                let mut outline = Geo::Circle {
                    c: Point::new(s.x, s.y),
                    r: s.scale,
                };
                e.entry_geo_into(j, s, S::ZERO, S::ZERO, &mut outline);
                ps.map(|p| poly_dist(&outline, e.image_near(p, s)))
            }
            _ => ps.map(|p| e.shape_dist(j, p)),
        }
    }

    fn disc(&self, j: u32, p: Point<S>) -> Option<(Point<S>, S)> {
        self.0.disc(j, p)
    }

    fn gather(&self, c: Point<S>, reach: S, near: &mut [u32; NEAR]) {
        self.0.gather(c, reach, near);
    }

    fn density_key(&self) -> usize {
        self.0
            .density
            .map_or(0, |Thinning(d)| (d as *const dyn Density).cast::<()>() as usize)
    }

    fn class(&self, bbox: [f64; 4], classes: u32) -> Option<u32> {
        match self.0.density {
            Some(Thinning(d)) => density_class(d, bbox, classes),
            None => Some(0),
        }
    }
}

/// The density class of a box (see [`Field::class`]): one copy for every scalar.
#[inline(never)]
fn density_class(d: &dyn Density, bbox: [f64; 4], classes: u32) -> Option<u32> {
    let [x0, y0, x1, y1] = bbox;
    let b = d.max_over(x0, y0, x1, y1);
    if b <= 0.0 {
        return None;
    }
    // NaN, or any bound above 1/2, is class 0.
    let below = [0.5, 0.25, 0.125, 0.0625].iter().take_while(|&&h| b <= h).count() as u32;
    Some(below.min(classes.saturating_sub(1)))
}

impl<S: Scalar> Engine<'_, S> {
    /// The clearance the next shape needs at its centre: the radius of a disc about the
    /// centre that it keeps free of other shapes and of the outside (its inscribed disc, at
    /// the smallest scale it can take), plus the gap. `None` when no such disc exists: a ring
    /// whose hole could hold an earlier shape or a hole of the region.
    pub(super) fn clearance_needed(&self, next: &NextShape<S>) -> Option<S> {
        let r = match next.kind {
            ShapeKind::Ring { inner } => {
                // Earlier shapes are larger than this ring's material, so none fits in a hole
                // of at most that area.
                let hole_small = inner * inner <= 1.0 - inner * inner;
                let hole_r = next.base_scale * S::from_f64(inner);
                let region_simple = match self.region {
                    Region::Annulus { inner: hole, .. } => hole_r < S::from_f64(hole) + self.gap,
                    Region::Polygon(p) => p.ring_ends().len() <= 1,
                    _ => true,
                };
                if !(hole_small && region_simple) {
                    return None;
                }
                next.base_scale
            }
            ShapeKind::Blob { delta } => {
                // The smallest scale over all phases. A unit blob's vertices sit at equal
                // angles 2 pi / n apart with radii r_k, so twice its area is
                // sin(2 pi / n) sum r_k r_(k+1) <= sin(2 pi / n) sum r_k^2, and over n = 32
                // samples the three harmonics are orthogonal: sum r_k^2 = n (1 + 1.5 delta^2)
                // whatever the phases. (With a margin for rounding.)
                let n = crate::shape::BLOB_VERTICES as f64;
                let twice_area = n * libm::sin(core::f64::consts::TAU / n) * (1.0 + 1.5 * delta * delta) * (1.0 + 1e-6);
                let min_scale = crate::scalar::sqrtf(2.0 * next.area / twice_area);
                next.kind.inradius(S::from_f64(min_scale))
            }
            ShapeKind::Noisy { amplitude, .. } => {
                // Every radius is at most 1 + a, so twice a unit outline's area is at most
                // n sin(2 pi / n) (1 + a)^2 whatever the noise. (With a margin for rounding.)
                let n = crate::shape::BLOB_VERTICES as f64;
                let twice_area = n * libm::sin(core::f64::consts::TAU / n) * (1.0 + amplitude) * (1.0 + amplitude) * (1.0 + 1e-6);
                let min_scale = crate::scalar::sqrtf(2.0 * next.area / twice_area);
                next.kind.inradius(S::from_f64(min_scale))
            }
            _ => next.kind.inradius(next.base_scale),
        };
        Some(r + self.gap)
    }

    /// A lower bound of the clearance any shape the storage has room for will need
    /// ([`Engine::clearance_needed`]): that of the last, the smallest, over the kinds it may
    /// take, as areas fall with the index and a kind's inscribed disc with its area. Zero
    /// (no bound) when a ring, blob or noisy outline may come, whose clearance is found
    /// otherwise.
    fn lowest_clearance(&self, last: u64) -> S {
        let area = self.area_of(last);
        let mut lowest: Option<S> = None;
        for &kind in self.params.shape.kinds() {
            if matches!(kind, ShapeKind::Ring { .. } | ShapeKind::Blob { .. } | ShapeKind::Noisy { .. }) {
                return S::ZERO;
            }
            let r = kind.inradius(kind.scale_for(area, S::ZERO)) + self.gap;
            lowest = Some(lowest.map_or(r, |m| m.min(r)));
        }
        lowest.unwrap_or(S::ZERO)
    }

    /// When shape `j` is a circle, its centre in the periodic image nearest `p` (seen from
    /// `p`) and its radius. None for other kinds: their inscribed discs give looser cell
    /// bounds than their distances do.
    pub(super) fn disc(&self, j: u32, p: Point<S>) -> Option<(Point<S>, S)> {
        let s = self.shapes.get(j as usize)?;
        if self.entry_kind(j) != ShapeKind::Circle {
            return None;
        }
        // `image_near` moves `p` next to the circle; the circle moves by the opposite shift.
        let q = self.image_near(p, s);
        Some((Point::new(s.x - (q.x - p.x), s.y - (q.y - p.y)), s.scale))
    }

    /// Replaces `near` by the [`NEAR`] shapes nearest to `c` by [`Engine::shape_dist`], among
    /// those that come within `reach` of `c` (of one of its images, on a torus): the ones
    /// `near` holds and the ones the spatial hash lists.
    pub(super) fn gather(&self, c: Point<S>, reach: S, near: &mut [u32; NEAR]) {
        // The shapes kept and their distances, in the order they were kept: a shape within
        // `reach` is kept while there is room; then it takes the place of the first of the
        // farthest kept if it is nearer.
        let mut best: heapless::Vec<(S, u32), NEAR> = heapless::Vec::new();
        let mut offer = |j: u32| {
            if best.iter().any(|b| b.1 == j) {
                return;
            }
            // With every place taken, a polygon whose bounding disc lies beyond the farthest
            // kept (by far more than any rounding) cannot take a place: on hosts its outline
            // is not built (a board keeps the flash).
            if cfg!(not(target_os = "none")) && best.is_full() && self.entry_kind(j) != ShapeKind::Circle {
                let far = best.iter().fold(S::from_f64(f64::MIN), |m, b| m.max(b.0));
                if self.dist_floor(j, c).is_some_and(|lo| lo > far + S::from_f64(1e-6)) {
                    return;
                }
            }
            let d = self.shape_dist(j, c);
            if d < reach && best.push((d, j)).is_err() {
                let far = best.iter_mut().fold(None, |m: Option<&mut (S, u32)>, b| match m {
                    Some(m) if m.0 >= b.0 => Some(m),
                    _ => Some(b),
                });
                if let Some(f) = far.filter(|f| d < f.0) {
                    *f = (d, j);
                }
            }
        };
        for &j in near.iter().filter(|&&j| j != NONE) {
            offer(j);
        }
        let total = self.len as u32;
        let periodic = self.region.periodic();
        for (level, max_r) in self.hash.occupied() {
            let rr = reach + max_r;
            let mut look = |qx: S, qy: S| {
                self.hash.query(level, [qx - rr, qy - rr, qx + rr, qy + rr], total, |j| {
                    if let Some(p) = self.shapes.get(j as usize) {
                        let contact = reach + self.entry_kind(j).bounding_radius(p.scale);
                        let (dx, dy) = (p.x - qx, p.y - qy);
                        if dx * dx + dy * dy < contact * contact {
                            offer(j);
                        }
                    }
                    true
                })
            };
            if !periodic {
                look(c.x, c.y);
            } else {
                self.each_image(c.x, c.y, rr, |ox, oy| look(c.x + ox, c.y + oy));
            }
        }
        let kept = best.iter().map(|b| b.1).chain(core::iter::repeat(NONE));
        for (n, j) in near.iter_mut().zip(kept) {
            *n = j;
        }
    }

    /// A lower bound of [`Engine::shape_dist`] from `p` to placed shape `j`: the distance to
    /// its centre (of its image nearest `p`) less its bounding radius.
    fn dist_floor(&self, j: u32, p: Point<S>) -> Option<S> {
        let s = self.shapes.get(j as usize)?;
        let q = self.image_near(p, s);
        Some(Point::new(s.x, s.y).dist2(q).sqrt() - self.entry_kind(j).bounding_radius(s.scale))
    }

    /// `p`, or on a torus its copy nearest the centre of `s`.
    pub(super) fn image_near(&self, p: Point<S>, s: &Placed<S>) -> Point<S> {
        if !self.region.periodic() {
            return p;
        }
        if self.shear != S::ZERO {
            // The shift `nearest_image` moves the shape by, the other way.
            let ((ox, oy), _) = self.nearest_image(s, p);
            return p.shift(S::ZERO - ox, S::ZERO - oy);
        }
        let (w, h) = self.period;
        // Shift p by the period that brings it nearest to the shape's centre.
        let shift = |a: S, c: S, m: S| {
            let hm = m.half();
            if a - c > hm {
                -m
            } else if c - a > hm {
                m
            } else {
                S::ZERO
            }
        };
        p.shift(shift(p.x, s.x, w), shift(p.y, s.y, h))
    }

    /// The signed distance from `p` to the material of placed shape `j` (in a periodic region,
    /// to its image nearest to `p` by centre): negative inside. An upper bound of the distance
    /// to the nearest image by material, which is all the cell sampler needs; so a distance
    /// that counts positive is rounded up, one that counts negative down (in fixed point; `f64`
    /// rounds to nearest, which the sampler's slack covers).
    pub(super) fn shape_dist(&self, j: u32, p: Point<S>) -> S {
        let Some(s) = self.shapes.get(j as usize) else {
            return S::from_f64(f64::MAX);
        };
        let kind = self.entry_kind(j);
        let q = self.image_near(p, s);
        let centre = Point::new(s.x, s.y);
        let d = centre.diff(q);
        // The distance from the centre rounded up; rounded down is `centre.dist2(q).sqrt()`.
        let far = S::dist2_up(d.x, d.y).sqrt();
        match kind {
            ShapeKind::Circle => far - s.scale,
            ShapeKind::Ring { inner } => {
                let hole = s.scale * S::from_f64(inner);
                if far >= s.scale {
                    far - s.scale
                } else {
                    let near = centre.dist2(q).sqrt();
                    if near <= hole {
                        hole - near
                    } else {
                        -(near - hole).min(s.scale - far)
                    }
                }
            }
            // The distance to the inscribed disc, which lies in the material: never below the
            // distance to the material (inside the disc, never below its signed depth).
            ShapeKind::Motif { inner, .. } => far - s.scale * S::from_f64(inner),
            _ => {
                let mut outline = Geo::Circle { c: centre, r: s.scale };
                self.entry_geo_into(j, s, S::ZERO, S::ZERO, &mut outline);
                poly_dist(&outline, q)
            }
        }
    }

    /// Brings `cells` up to date for the next shape, as a step of [`Engine::step_fast`] does
    /// before its first candidate: afterwards every centre where the next shape fits lies in
    /// a live cell ([`CellSampler::live_boxes`]). Says whether the next shape is placed with
    /// the cells (false when it falls back to the reference sampler, or none is left).
    pub fn prepare_fast(&self, cells: &mut CellSampler<'_, S>) -> bool {
        self.next_shape().ok().and_then(|next| self.prepare_cells(&next, cells)).is_some()
    }

    /// Lays out the grid on first use and wakes the cells for the next shape's clearance; none
    /// when the shape has no clearance condition.
    pub(super) fn prepare_cells(&self, next: &NextShape<S>, cells: &mut CellSampler<'_, S>) -> Option<S> {
        let clearance = self.clearance_needed(next)?;
        let field = FieldOf(self);
        if !cells.ready(field.density_key()) {
            let (x0, y0, _, _) = self.region.bbox();
            let (w, h) = self.period;
            cells.init(S::from_f64(x0), S::from_f64(y0), w, h, self.region.periodic(), &field);
            cells.set_lowest(self.lowest_clearance(self.shapes.len().saturating_sub(1) as u64), self.shapes.len());
        }
        cells.wake(clearance, self.len, &field);
        cells.begin_step();
        Some(clearance)
    }

    /// [`Engine::prepare_cells`] for a batch whose shapes need at least `clearance`; `last_of`
    /// names the last placement of the batch that holds a given one (the cells of the fill's
    /// last batch may serve shapes past the storage's last).
    pub(super) fn prepare_batch(&self, cells: &mut CellSampler<'_, S>, clearance: S, last_of: impl FnOnce(u64) -> u64) {
        let field = FieldOf(self);
        if !cells.ready(field.density_key()) {
            let (x0, y0, _, _) = self.region.bbox();
            let (w, h) = self.period;
            cells.init(S::from_f64(x0), S::from_f64(y0), w, h, self.region.periodic(), &field);
            let last = last_of(self.shapes.len().saturating_sub(1) as u64);
            cells.set_lowest(self.lowest_clearance(last), self.shapes.len());
        }
        cells.wake(clearance, self.len, &field);
        cells.begin_step();
    }

    /// Places the next shape with the cell sampler: the same distribution of accepted
    /// placements as [`Engine::step`], far fewer trials late in a fill (see
    /// [`crate::CellSampler`]). Halts at the trial limit, or at once when no cell can hold the
    /// shape. Use one sampler per engine, for every step after the first that uses it.
    ///
    /// # Examples
    ///
    /// ```
    /// use zetafill::{cells_for, index_words, rng_from_seed, CellSampler, Engine, Params, Placed, Region, Storage};
    ///
    /// let mut shapes = vec![Placed::<f64>::default(); 300];
    /// let mut index = vec![0u32; index_words(300)];
    /// let mut pool = vec![[0u64; 4]; cells_for(300)];
    /// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
    /// let region = Region::Rect { width: 100.0, height: 100.0, periodic: true };
    /// let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage)?;
    /// let mut cells = CellSampler::new(&mut pool)?;
    /// let mut rng = rng_from_seed(11);
    /// for i in 0..300 {
    ///     let p = engine.step_fast(&mut cells, &mut rng)?;
    ///     assert_eq!(p.index, i);
    /// }
    /// // No two circles overlap or touch, across the torus's edges too.
    /// let placed = engine.placed();
    /// let wrap = |d: f64| d.abs().min(100.0 - d.abs());
    /// for (i, a) in placed.iter().enumerate() {
    ///     for b in &placed[i + 1..] {
    ///         let (dx, dy) = (wrap(a.x - b.x), wrap(a.y - b.y));
    ///         assert!(dx * dx + dy * dy > (a.scale + b.scale) * (a.scale + b.scale));
    ///     }
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn step_fast<R: RngCore + ?Sized>(&mut self, cells: &mut CellSampler<'_, S>, rng: &mut R) -> Result<Placement<S>, StepError> {
        let next = self.next_shape()?;
        let Some(clearance) = self.prepare_cells(&next, cells) else {
            let placed = self.step_reference(&next, rng);
            if let Ok(p) = &placed {
                cells.end_step_paper(p.trials);
            }
            return placed;
        };
        self.fast_trials(cells, &next, clearance, rng, 0)
    }

    /// The trials of [`Engine::step_fast`] once the cells are up to date, counted from
    /// `trials`: cells are judged (retired, split) for `clearance`, which may be below the
    /// shape's own, and learn from the exact tests.
    pub(super) fn fast_trials<R: RngCore + ?Sized>(
        &mut self,
        cells: &mut CellSampler<'_, S>,
        next: &NextShape<S>,
        clearance: S,
        rng: &mut R,
        mut trials: u64,
    ) -> Result<Placement<S>, StepError> {
        loop {
            if trials >= self.params.max_trials || cells.is_empty() {
                return Err(StepError::Halted { index: next.index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let Some(Drawn {
                slot,
                cell: drawn,
                point: p,
                quarter,
                class,
            }) = cells.draw(rng)
            else {
                continue;
            };
            // On hosts, a new batch's known shapes are loaded together: their memory
            // latencies overlap (a board's memory has none to hide).
            if cfg!(not(target_os = "none")) {
                if let Some(known) = cells.batch_known() {
                    let mut sum = S::ZERO;
                    for j in known {
                        if let Some(s) = self.shapes.get(j as usize) {
                            sum = sum + s.scale;
                        }
                    }
                    core::hint::black_box(sum);
                }
            }
            let angle = if next.rotated { rng::angle::<S, R>(rng) } else { S::ZERO };
            if cells.overhangs(p) {
                continue;
            }
            let slot = match cells.judge(slot, &drawn, quarter, clearance, &FieldOf(self)) {
                Verdict::Reject => continue,
                Verdict::Test(s) => s,
            };
            let c = self.region.wrap(p);
            let (x0, x1, y0, y1) = next.range;
            if c.x < x0 || c.x > x1 || c.y < y0 || c.y > y1 {
                cells.note_reject(slot, false);
                continue;
            }
            // Thinned by the density, over the bound its cell was drawn with: says nothing
            // about the cell.
            if !self.kept(c, class, rng) {
                continue;
            }
            let known = if slot == usize::MAX { drawn.near() } else { cells.known(slot) };
            match self.try_at(next, c, angle, trials, Some(&known)) {
                Ok(placed) => {
                    // The shape placed is the first entry of its orbit.
                    cells.learn(slot, next.index as u32 * self.images.get(), clearance, &FieldOf(self));
                    cells.end_step(x1 - x0, y1 - y0);
                    return Ok(placed);
                }
                Err(Some(j)) if known.contains(&j) => cells.note_reject(slot, true),
                Err(Some(j)) => {
                    cells.note_learned(slot);
                    cells.learn(slot, j, clearance, &FieldOf(self));
                }
                Err(None) => cells.note_reject(slot, false),
            }
        }
    }

    /// [`Engine::run`] with the cell sampler ([`Engine::step_fast`]).
    pub fn run_fast<R: RngCore + ?Sized>(
        &mut self,
        cells: &mut CellSampler<'_, S>,
        rng: &mut R,
        stop: &Stop,
        on_place: impl FnMut(&Placement<S>),
    ) -> StopReason {
        self.run_with(stop, on_place, |e| e.step_fast(cells, rng))
    }
}
