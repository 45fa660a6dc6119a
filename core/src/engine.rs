//! The placement engine: parameters (validated once), the placement step, stop conditions.
//!
//! This is the algorithm of Shier & Bourke (seed 001, section 2). Shape `i` has area
//! `A_i = A / (zeta(c, N) (i + N)^c)`. Each trial draws a candidate (angle if rotated, then a
//! centre uniform over the positions where the shape lies inside the region) and accepts it
//! when it keeps more than `gap` from every placed shape (and its periodic images) and at
//! least `gap` from the boundary. One [`Engine::step`] places the next shape and reports how
//! many trials it took, so a display can draw as the fill grows.
//!
//! Guarantees: same seed and parameters, same bits, on every target; the first `k` shapes
//! never depend on how many are asked for later (each step uses only the RNG stream and the
//! shapes before it); running out of storage, halting at the trial limit, and a first shape
//! that cannot fit are error values, never panics.

use crate::coverage::Coverage;
use crate::geom::{edges, point_in_poly, seg_dist2, separated, Geo, Point};
use crate::region::Region;
use crate::rng;
use crate::sampler::{CellSampler, Drawn, Field, Verdict, NEAR, NONE};
use crate::scalar::{powf, Scalar};
use crate::shape::{Placed, ShapeKind, ShapeList};
use crate::spatial::SpatialHash;
use rand_core::RngCore;

/// The parameters of a fill.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params {
    /// The power-law exponent c (> 1).
    pub c: f64,
    /// The offset N of the paper (> 0, need not be an integer).
    pub n_offset: f64,
    /// The shape placed, or a mix of shapes.
    pub shape: ShapeList,
    /// Random rotation (ignored for circles).
    pub rotate: bool,
    /// Minimum clearance between shapes and to the boundary (>= 0).
    pub gap: f64,
    /// Trial limit per placement (>= 1): reaching it halts the fill.
    pub max_trials: u64,
}

impl Params {
    /// Circles with the given exponent and offset, no gap, the default trial limit.
    pub fn circles(c: f64, n_offset: f64) -> Self {
        Params {
            c,
            n_offset,
            shape: ShapeKind::Circle.into(),
            rotate: false,
            gap: 0.0,
            max_trials: 10_000_000,
        }
    }

    /// c for a fractal dimension D in 2D (c = 2 / D).
    pub fn c_from_dimension(d: f64) -> f64 {
        2.0 / d
    }
}

/// What was wrong with the parameters, region or storage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ParamError {
    /// c must be finite and > 1.
    Exponent,
    /// N must be finite and > 0.
    Offset,
    /// The zeta function overflows for this (c, N).
    Zeta,
    /// A shape proportion is out of range (see [`ShapeKind::is_valid`]).
    Shape,
    /// Region sizes must be finite and > 0.
    Region,
    /// The gap must be finite and >= 0, and smaller than the region.
    Gap,
    /// The trial limit must be at least 1.
    MaxTrials,
    /// The storage holds no shape slot, or the index buffer is smaller than the shape buffer + 1.
    Storage,
}

impl core::fmt::Display for ParamError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            ParamError::Exponent => "c must be a finite number greater than 1",
            ParamError::Offset => "N must be a finite number greater than 0",
            ParamError::Zeta => "zeta(c, N) overflows: raise N",
            ParamError::Shape => "a shape proportion is out of range",
            ParamError::Region => "region sizes must be finite and greater than 0",
            ParamError::Gap => "the gap must be finite, at least 0, and smaller than the region",
            ParamError::MaxTrials => "the trial limit must be at least 1",
            ParamError::Storage => "the storage needs at least one shape slot and an index buffer longer than the shape buffer",
        })
    }
}

/// Why a step placed nothing. The engine keeps every shape placed before.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepError {
    /// The trial limit was reached at placement `index` after `trials` trials (halting).
    Halted {
        /// The placement that could not be made.
        index: u64,
        /// Trials spent on it.
        trials: u64,
    },
    /// The shape buffer is full.
    Capacity {
        /// Number of shape slots.
        capacity: u64,
    },
    /// Shape `index` is too large for the region in any orientation (for the first shape:
    /// lower c or raise N). Only detected where it is certain; otherwise the fill halts.
    CannotFit {
        /// The shape that cannot fit.
        index: u64,
    },
}

impl core::fmt::Display for StepError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            StepError::Halted { index, trials } => write!(f, "halted at placement {index} after {trials} trials"),
            StepError::Capacity { capacity } => write!(f, "storage for {capacity} shapes is full"),
            StepError::CannotFit { index } => write!(f, "shape {index} is larger than the region allows"),
        }
    }
}

/// One placement: the shape, its nominal area and the trials it took.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement<S> {
    /// Placement index i (0 for the largest shape).
    pub index: u64,
    /// The shape as stored.
    pub shape: Placed<S>,
    /// A_i.
    pub area: f64,
    /// Trials spent on this placement (>= 1).
    pub trials: u64,
}

/// When [`Engine::run`] stops: the first condition given that holds stops it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stop {
    /// Stop once this many shapes are placed.
    pub count: Option<u64>,
    /// Stop once the placed area reaches this fraction of the region (0 < f < 1).
    pub fill: Option<f64>,
    /// Stop before the first shape whose narrowest width is below this.
    pub min_size: Option<f64>,
}

/// Why [`Engine::run`] stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopReason {
    /// The count was reached.
    Count,
    /// The fill fraction was reached.
    Fill,
    /// The next shape is smaller than the minimum size.
    MinSize,
    /// A step failed; see [`StepError`].
    Step(StepError),
}

/// Statistics of a fill so far.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stats {
    /// Shapes placed.
    pub placed: u64,
    /// Trials made in all (including those of a halted placement).
    pub trials: u64,
    /// Sum of placed nominal areas over the region's area.
    pub fill_fraction: f64,
}

impl Stats {
    /// Average trials per placement (0 when nothing is placed).
    pub fn trials_per_placement(&self) -> f64 {
        if self.placed == 0 {
            0.0
        } else {
            self.trials as f64 / self.placed as f64
        }
    }
}

/// How many periods of length `p` a reach can span (at least 1, at most 64).
fn periods<S: Scalar>(reach: S, p: S) -> i64 {
    if p <= S::ZERO {
        return 1;
    }
    (reach / p).floor_i64().saturating_add(1).clamp(1, 64)
}

/// What a placement needs that stays fixed over its trials.
struct Next<S> {
    index: u64,
    kind: ShapeKind,
    area: f64,
    base_scale: S,
    base_r: S,
    rotated: bool,
    is_blob: bool,
    /// The radius of the inscribed disc at the base scale ([`ShapeKind::solid_radius`]).
    base_solid: Option<S>,
    /// The centre range (x0, x1, y0, y1).
    range: (S, S, S, S),
}

/// The engine as the cell sampler sees it.
struct FieldOf<'e, 'a, S: Scalar>(&'e Engine<'a, S>);

impl<S: Scalar> Field<S> for FieldOf<'_, '_, S> {
    fn edge(&self, p: Point<S>) -> S {
        self.0.region.signed_clearance(p)
    }

    fn dist(&self, j: u32, p: Point<S>) -> S {
        self.0.shape_dist(j, p)
    }

    fn disc(&self, j: u32, p: Point<S>) -> Option<(Point<S>, S)> {
        self.0.disc(j, p)
    }

    fn gather(&self, c: Point<S>, reach: S, near: &mut [u32; NEAR]) {
        self.0.gather(c, reach, near);
    }
}

/// The fill engine over caller-provided storage.
#[derive(Debug)]
pub struct Engine<'a, S: Scalar> {
    params: Params,
    region: Region<'a>,
    shapes: &'a mut [Placed<S>],
    len: usize,
    hash: SpatialHash<'a, S>,
    coverage: Coverage<'a, S>,
    zeta: f64,
    area: f64,
    placed_area: f64,
    trials: u64,
    gap: S,
    period: (S, S),
}

/// Index words needed for `capacity` shapes: one link each plus `2 * capacity` buckets.
pub const fn index_words(capacity: usize) -> usize {
    capacity * 3 + 1
}

/// The caller-owned storage of an engine.
#[derive(Debug)]
pub struct Storage<'a, S> {
    /// One slot per shape: its length is the capacity.
    pub shapes: &'a mut [Placed<S>],
    /// The spatial hash: longer than `shapes` ([`index_words`] recommends the size; any
    /// number of buckets works, fewer only make queries slower).
    pub index: &'a mut [u32],
    /// The coverage bitmap (see [`crate::coverage`]); may be empty. It speeds up rejections
    /// and never changes a result.
    pub coverage: &'a mut [u64],
}

impl<'a, S: Scalar> Engine<'a, S> {
    /// Validates the parameters and builds an engine over the caller's storage.
    pub fn new(params: Params, region: Region<'a>, storage: Storage<'a, S>) -> Result<Self, ParamError> {
        let Storage { shapes, index, coverage } = storage;
        if !(params.c.is_finite() && params.c > 1.0) {
            return Err(ParamError::Exponent);
        }
        if !(params.n_offset.is_finite() && params.n_offset > 0.0) {
            return Err(ParamError::Offset);
        }
        if !params.shape.is_valid() {
            return Err(ParamError::Shape);
        }
        if !region.is_valid() {
            return Err(ParamError::Region);
        }
        let (w, h) = region.extent();
        if !(params.gap.is_finite() && params.gap >= 0.0 && 2.0 * params.gap < w.min(h)) {
            return Err(ParamError::Gap);
        }
        if params.max_trials == 0 {
            return Err(ParamError::MaxTrials);
        }
        if shapes.is_empty() || index.len() <= shapes.len() {
            return Err(ParamError::Storage);
        }
        let zeta = crate::zeta::zeta(params.c, params.n_offset).map_err(|_| ParamError::Zeta)?;
        let (next, heads) = index.split_at_mut(shapes.len());
        let hash = SpatialHash::new(heads, next, S::from_f64(w.max(h))).map_err(|_| ParamError::Storage)?;
        let (x0, y0, _, _) = region.bbox();
        let mut coverage = Coverage::new(
            coverage,
            Point::new(S::from_f64(x0), S::from_f64(y0)),
            S::from_f64(w),
            S::from_f64(h),
        );
        coverage.mark_outside(&region);
        Ok(Engine {
            params,
            region,
            shapes,
            len: 0,
            hash,
            coverage,
            zeta,
            area: region.area(),
            placed_area: 0.0,
            trials: 0,
            gap: S::from_f64(params.gap),
            period: (S::from_f64(w), S::from_f64(h)),
        })
    }

    /// The parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// The region.
    pub fn region(&self) -> &Region<'a> {
        &self.region
    }

    /// zeta(c, N) used for the area sequence.
    pub fn zeta(&self) -> f64 {
        self.zeta
    }

    /// The region's area A.
    pub fn total_area(&self) -> f64 {
        self.area
    }

    /// A_i = A / (zeta(c, N) (i + N)^c).
    pub fn area_of(&self, i: u64) -> f64 {
        self.area / (self.zeta * powf(i as f64 + self.params.n_offset, self.params.c))
    }

    /// The shape kind of placement `i`.
    #[inline]
    pub fn kind_of(&self, i: u64) -> ShapeKind {
        self.params.shape.kind_of(i)
    }

    /// The shapes placed so far, in placement order.
    pub fn placed(&self) -> &[Placed<S>] {
        self.shapes.get(..self.len).unwrap_or(&[])
    }

    /// The concrete geometry of placed shape `i`: exactly what was tested, and what to draw.
    pub fn geo(&self, i: usize) -> Option<Geo<S>> {
        let p = self.placed().get(i)?;
        Some(self.kind_of(i as u64).geo(Point::new(p.x, p.y), p.scale, p.angle))
    }

    /// Statistics so far.
    pub fn stats(&self) -> Stats {
        Stats {
            placed: self.len as u64,
            trials: self.trials,
            fill_fraction: self.placed_area / self.area,
        }
    }

    /// Fraction of the region's bounding box marked in the coverage bitmap (0 without one).
    pub fn coverage_fraction(&self) -> f64 {
        self.coverage.marked_fraction()
    }

    /// The storage capacity in shapes.
    pub fn capacity(&self) -> usize {
        self.shapes.len()
    }

    /// A placed shape that `g` (centred at `(x, y)`, bounding radius `r`) comes within its gap
    /// of (or of an image of, in a periodic region); `None` when it keeps clear of all.
    ///
    /// With `lowest`, the answer does not depend on the hash table's size: the lowest-indexed
    /// shape hit among those stored at the finest level where any is hit (a bucket may also
    /// list shapes of other levels; they are named at their own level). Otherwise the first
    /// one found.
    fn blocker(&self, g: &Geo<S>, x: S, y: S, (r, solid): (S, Option<S>), lowest: bool) -> Option<u32> {
        let hit: core::cell::Cell<Option<u32>> = core::cell::Cell::new(None);
        let total = self.len as u32;
        let circle = matches!(g, Geo::Circle { .. });
        let gap = self.gap;
        // The neighbour's outline, rebuilt in place for each shape tested.
        let mut other = Geo::Circle { c: Point::new(x, y), r };
        // Tests candidate `gi`, centred at (qx, qy), against every shape the hash lists.
        let mut test = |level: usize, reach: S, gi: &Geo<S>, qx: S, qy: S| {
            self.hash
                .query(level, [qx - reach, qy - reach, qx + reach, qy + reach], total, |j| {
                    let Some(p) = self.shapes.get(j as usize) else { return true };
                    let kind = self.kind_of(u64::from(j));
                    let pr = kind.bounding_radius(p.scale);
                    let lim = r + pr + gap;
                    let (dx, dy) = (p.x - qx, p.y - qy);
                    let d2 = dx * dx + dy * dy;
                    // Two circles within reach overlap, and so do two shapes whose inscribed
                    // discs meet: no geometry to build.
                    let ok = d2 > lim * lim
                        || (!((circle && kind == ShapeKind::Circle) || self.solids_meet(d2, solid, kind, p.scale)) && {
                            kind.geo_into(&mut other, Point::new(p.x, p.y), p.scale, p.angle);
                            separated(gi, &other, gap)
                        });
                    if !ok && (!lowest || self.hash.level_for(pr) == level) {
                        hit.set(Some(hit.get().map_or(j, |h| h.min(j))));
                    }
                    ok || lowest
                })
        };
        let periodic = self.region.periodic();
        for (level, max_r) in self.hash.occupied() {
            let reach = r + max_r + gap;
            if !periodic {
                test(level, reach, g, x, y);
            } else {
                self.each_image(x, y, reach, |ox, oy| {
                    let gi = if ox == S::ZERO && oy == S::ZERO { *g } else { g.shift(ox, oy) };
                    test(level, reach, &gi, x + ox, y + oy);
                    hit.get().is_none() || lowest
                });
                if hit.get().is_some() && !lowest {
                    return hit.get();
                }
            }
            if hit.get().is_some() {
                return hit.get();
            }
        }
        None
    }

    /// On a torus, the shifts `(k W, l H)` that bring `(x, y)` (a point of the region) within
    /// `reach` of the region's box, where stored shapes' images may lie: one period each way
    /// unless a long shape in a narrow torus reaches further.
    /// Calls `f` with each, in order, until it returns false.
    fn each_image(&self, x: S, y: S, reach: S, mut f: impl FnMut(S, S) -> bool) {
        let (w, h) = self.period;
        let (kx, ky) = (periods(reach, w), periods(reach, h));
        for l in -ky..=ky {
            for k in -kx..=kx {
                let (ox, oy) = (w * S::from_f64(k as f64), h * S::from_f64(l as f64));
                let (qx, qy) = (x + ox, y + oy);
                if qx + reach < S::ZERO || qx - reach > w || qy + reach < S::ZERO || qy - reach > h {
                    continue;
                }
                if !f(ox, oy) {
                    return;
                }
            }
        }
    }

    /// Whether `g` (centred at `c`, bounding radius `r`) comes within the gap of placed shape
    /// `j` (of its image nearest by centre, in a periodic region): the exact test of
    /// [`Engine::blocker`] for one shape.
    fn hits(&self, g: &Geo<S>, c: Point<S>, (r, solid): (S, Option<S>), j: u32, other: &mut Geo<S>) -> bool {
        let Some(p) = self.shapes.get(j as usize) else { return false };
        let kind = self.kind_of(u64::from(j));
        let ((ox, oy), (dx, dy)) = self.nearest_image(p, c);
        let lim = r + kind.bounding_radius(p.scale) + self.gap;
        let d2 = dx * dx + dy * dy;
        if d2 > lim * lim {
            return false;
        }
        if (kind == ShapeKind::Circle && matches!(g, Geo::Circle { .. })) || self.solids_meet(d2, solid, kind, p.scale) {
            return true;
        }
        kind.geo_into(other, Point::new(p.x + ox, p.y + oy), p.scale, p.angle);
        !separated(g, other, self.gap)
    }

    /// Whether a shape whose inscribed disc has radius `solid` comes within the gap of a
    /// shape of `kind` at `scale` whose centre is `sqrt(d2)` away, judged by their inscribed
    /// discs alone: true only when those discs come within the gap by a margin far above any
    /// rounding of the exact test, so the answer never differs from it. False when either
    /// shape has no inscribed disc about its centre (a ring).
    fn solids_meet(&self, d2: S, solid: Option<S>, kind: ShapeKind, scale: S) -> bool {
        let (Some(a), Some(b)) = (solid, kind.solid_radius(scale)) else {
            return false;
        };
        let lim = (a + b + self.gap) * S::from_f64(1.0 - 1e-6) - S::from_f64(1e-9);
        lim > S::ZERO && d2 < lim * lim
    }

    /// Whether a circle of radius `r` at `c` comes within the gap of placed shape `j` when
    /// that is a circle too (of its image nearest by centre, in a periodic region); false
    /// when `j` is another kind. The same answer as [`Engine::hits`] for two circles.
    fn circles_meet(&self, c: Point<S>, r: S, j: u32) -> bool {
        let Some(p) = self.shapes.get(j as usize) else { return false };
        if self.kind_of(u64::from(j)) != ShapeKind::Circle {
            return false;
        }
        let (_, (dx, dy)) = self.nearest_image(p, c);
        let lim = r + p.scale + self.gap;
        dx * dx + dy * dy <= lim * lim
    }

    /// The shift (zero, or a period each way) that brings placed shape `p` to its image nearest
    /// to `c` by centre (in a periodic region; none otherwise), and the offset from `c` to that
    /// image's centre.
    fn nearest_image(&self, p: &Placed<S>, c: Point<S>) -> ((S, S), (S, S)) {
        let (dx, dy) = (p.x - c.x, p.y - c.y);
        let (mut ox, mut oy) = (S::ZERO, S::ZERO);
        if self.region.periodic() {
            let (w, h) = self.period;
            if dx > w.half() {
                ox = -w;
            } else if -dx > w.half() {
                ox = w;
            }
            if dy > h.half() {
                oy = -h;
            } else if -dy > h.half() {
                oy = h;
            }
        }
        ((ox, oy), (dx + ox, dy + oy))
    }

    /// Whether a shape overlaps its own periodic images (all of them within its reach).
    fn self_overlaps(&self, g: &Geo<S>, r: S) -> bool {
        let (w, h) = self.period;
        let reach = r + r + self.gap;
        if reach < w.min(h) {
            return false;
        }
        let (kx, ky) = (periods(reach, w), periods(reach, h));
        for l in 0..=ky {
            for k in -kx..=kx {
                // Half of the lattice suffices: the image at -v overlaps iff the one at v does.
                if l == 0 && k <= 0 {
                    continue;
                }
                let (dx, dy) = (w * S::from_f64(k as f64), h * S::from_f64(l as f64));
                if !separated(g, &g.shift(dx, dy), self.gap) {
                    return true;
                }
            }
        }
        false
    }

    /// Whether a shape of this area certainly cannot lie in the region in any orientation.
    /// Kept out of line: its scratch geometry would otherwise sit in every step's stack frame.
    #[inline(never)]
    fn cannot_fit(&self, kind: ShapeKind, area: f64) -> bool {
        let scale: S = kind.scale_for(area, S::ZERO);
        let inr = kind.inradius(scale);
        if self.region.centre_range(inr, inr, self.gap).is_none() {
            return true;
        }
        match self.region {
            Region::Rect {
                periodic: false,
                width,
                height,
            } => {
                // Rectangles: the narrowest bounding boxes are at 0 and 90 degrees (or only at
                // 0 when unrotated); every other kind is tested at angle 0 and reported only if
                // its inscribed circle cannot fit (above).
                if !matches!(
                    kind,
                    ShapeKind::Square | ShapeKind::Rect { .. } | ShapeKind::Circle | ShapeKind::Ring { .. }
                ) {
                    return false;
                }
                let quarter = S::from_f64(core::f64::consts::FRAC_PI_2);
                let angles: &[S] = if self.params.rotate && kind.rotates() {
                    &[S::ZERO, quarter]
                } else {
                    &[S::ZERO]
                };
                let (w, h) = (S::from_f64(width), S::from_f64(height));
                !angles.iter().any(|&a| {
                    let (x0, y0, x1, y1) = kind.geo(Point::new(S::ZERO, S::ZERO), scale, a).bounds();
                    x1 - x0 + self.gap + self.gap <= w && y1 - y0 + self.gap + self.gap <= h
                })
            }
            Region::Rect { periodic: true, .. } => {
                matches!(kind, ShapeKind::Circle | ShapeKind::Ring { .. })
                    && self.self_overlaps(&kind.geo(Point::new(S::ZERO, S::ZERO), scale, S::ZERO), scale)
            }
            // A regular shape's smallest enclosing circle is its circumcircle (a blob's is not
            // known, so only its inscribed circle is used).
            Region::Circle { radius } => {
                let r = if matches!(kind, ShapeKind::Blob { .. }) {
                    kind.inradius(scale)
                } else {
                    kind.bounding_radius(scale)
                };
                r + self.gap > S::from_f64(radius)
            }
            Region::Annulus { outer, inner } => {
                // In the band, or (a ring) around the hole.
                let band = S::from_f64(outer - inner);
                let in_band = inr + inr + self.gap + self.gap <= band;
                let around = match kind {
                    ShapeKind::Ring { inner: ri } => {
                        scale * S::from_f64(ri) >= S::from_f64(inner) + self.gap && scale + self.gap <= S::from_f64(outer)
                    }
                    _ => false,
                };
                !(in_band || around)
            }
            Region::Polygon(_) => false,
        }
    }

    /// What the next placement needs that stays fixed over its trials, or why it cannot be
    /// made.
    fn next_shape(&self) -> Result<Next<S>, StepError> {
        let i = self.len;
        let index = i as u64;
        if i >= self.shapes.len() {
            return Err(StepError::Capacity {
                capacity: self.shapes.len() as u64,
            });
        }
        let kind = self.kind_of(index);
        let area = self.area_of(index);
        let base_scale: S = kind.scale_for(area, S::ZERO);
        if !(base_scale > S::ZERO && base_scale.is_finite()) || self.cannot_fit(kind, area) {
            return Err(StepError::CannotFit { index });
        }
        let rotated = self.params.rotate && kind.rotates();
        let is_blob = matches!(kind, ShapeKind::Blob { .. });
        // The centre is drawn uniformly over the positions where the shape can lie inside the
        // region's bounding box: for an unrotated shape its exact extents set the range; a
        // rotated one may lie anywhere its inscribed circle fits, and the exact containment
        // test decides. So accepted placements are uniform over all valid (position, angle)
        // pairs.
        let (ex, ey) = if rotated || is_blob {
            let inr = kind.inradius(base_scale);
            (inr, inr)
        } else {
            let (x0, y0, x1, y1) = kind.geo(Point::new(S::ZERO, S::ZERO), base_scale, S::ZERO).bounds();
            ((-x0).max(x1), (-y0).max(y1))
        };
        let range = self
            .region
            .centre_range(ex, ey, self.gap)
            .unwrap_or((S::ZERO, S::ZERO, S::ZERO, S::ZERO));
        Ok(Next {
            index,
            kind,
            area,
            base_scale,
            base_r: kind.bounding_radius(base_scale),
            rotated,
            is_blob,
            base_solid: kind.solid_radius(base_scale),
            range,
        })
    }

    /// Runs the exact tests on a candidate centre and angle, and places the shape there if it
    /// passes.
    #[inline(always)]
    /// On failure, names the placed shape the candidate hit when that was the reason.
    /// The cell sampler passes `known`, the shapes its cell knows of: they are tested first, and
    /// the shape named on failure does not depend on the hash table's size.
    fn try_at(&mut self, nx: &Next<S>, c: Point<S>, angle: S, trials: u64, known: Option<&[u32]>) -> Result<Placement<S>, Option<u32>> {
        let kind = nx.kind;
        // A circle against known circles needs no geometry: most of the cell sampler's
        // rejections end here.
        if kind == ShapeKind::Circle {
            if let Some(&j) = known.unwrap_or(&[]).iter().find(|&&j| self.circles_meet(c, nx.base_r, j)) {
                return Err(Some(j));
            }
        }
        let mut g = Geo::Circle { c, r: nx.base_r };
        let (scale, r, solid) = if nx.is_blob {
            let s: S = kind.scale_for(nx.area, angle);
            kind.geo_into(&mut g, c, s, angle);
            (s, kind.bounding_radius(s), kind.solid_radius(s))
        } else {
            let (sin, cos) = if nx.rotated { ShapeKind::sin_cos(angle) } else { (S::ZERO, S::ONE) };
            kind.geo_sc_into(&mut g, c, nx.base_scale, sin, cos);
            (nx.base_scale, nx.base_r, nx.base_solid)
        };
        // (Known circles were tested above for a circle.)
        let tested = |j: u32| kind == ShapeKind::Circle && self.kind_of(u64::from(j)) == ShapeKind::Circle;
        let mut other = Geo::Circle { c, r };
        if let Some(&j) = known
            .unwrap_or(&[])
            .iter()
            .find(|&&j| !tested(j) && self.hits(&g, c, (r, solid), j, &mut other))
        {
            return Err(Some(j));
        }
        if !self.region.contains(&g, self.gap) {
            return Err(None);
        }
        let period = if self.region.periodic() { Some(self.period) } else { None };
        if period.is_some() && self.self_overlaps(&g, r) {
            return Err(None);
        }
        if let Some(j) = self.blocker(&g, c.x, c.y, (r, solid), known.is_some()) {
            return Err(Some(j));
        }
        let i = self.len;
        let shape = Placed {
            x: c.x,
            y: c.y,
            scale,
            angle,
        };
        if let Some(slot) = self.shapes.get_mut(i) {
            *slot = shape;
        }
        self.hash.insert(i as u32, c.x, c.y, r);
        // The cell sampler never asks the bitmap; a bitmap that misses shapes only rejects
        // fewer candidates of the reference sampler, never a valid one.
        if known.is_none() {
            self.coverage.mark(&g, c, kind.inradius(scale), period);
        }
        self.len += 1;
        self.placed_area += nx.area;
        Ok(Placement {
            index: nx.index,
            shape,
            area: nx.area,
            trials,
        })
    }

    /// Places the next shape, drawing candidates from `rng` until one fits or the trial limit
    /// is reached. On error nothing is placed and the engine may be stepped again.
    pub fn step<R: RngCore + ?Sized>(&mut self, rng: &mut R) -> Result<Placement<S>, StepError> {
        let nx = self.next_shape()?;
        self.step_reference(&nx, rng)
    }

    /// The paper's sampler: candidates uniform over the whole centre range.
    fn step_reference<R: RngCore + ?Sized>(&mut self, nx: &Next<S>, rng: &mut R) -> Result<Placement<S>, StepError> {
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials {
                return Err(StepError::Halted { index: nx.index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let angle = if nx.rotated { rng::angle::<S, R>(rng) } else { S::ZERO };
            let ux: S = rng::unit(rng);
            let uy: S = rng::unit(rng);
            let (x0, x1, y0, y1) = nx.range;
            let c = self.region.wrap(Point::new(x0 + ux * (x1 - x0), y0 + uy * (y1 - y0)));
            if self.coverage.covered(c.x, c.y) {
                continue;
            }
            if let Ok(p) = self.try_at(nx, c, angle, trials, None) {
                return Ok(p);
            }
        }
    }

    /// The clearance the next shape needs at its centre: the radius of a disc about the
    /// centre that it keeps free of other shapes and of the outside (its inscribed disc, at
    /// the smallest scale it can take), plus the gap. `None` when no such disc exists: a ring
    /// whose hole could hold an earlier shape or a hole of the region.
    fn need(&self, nx: &Next<S>) -> Option<S> {
        let r = match nx.kind {
            ShapeKind::Ring { inner } => {
                // Earlier shapes are larger than this ring's material, so none fits in a hole
                // of at most that area.
                let hole_small = inner * inner <= 1.0 - inner * inner;
                let hole_r = nx.base_scale * S::from_f64(inner);
                let region_simple = match self.region {
                    Region::Annulus { inner: hole, .. } => hole_r < S::from_f64(hole) + self.gap,
                    Region::Polygon(p) => p.ring_ends().len() <= 1,
                    _ => true,
                };
                if !(hole_small && region_simple) {
                    return None;
                }
                nx.base_scale
            }
            ShapeKind::Blob { delta } => {
                // The smallest scale over all phases. A unit blob's vertices sit at equal
                // angles 2 pi / n apart with radii r_k, so twice its area is
                // sin(2 pi / n) sum r_k r_(k+1) <= sin(2 pi / n) sum r_k^2, and over n = 32
                // samples the three harmonics are orthogonal: sum r_k^2 = n (1 + 1.5 delta^2)
                // whatever the phases. (With a margin for rounding.)
                let n = crate::shape::BLOB_VERTICES as f64;
                let twice_area = n * libm::sin(core::f64::consts::TAU / n) * (1.0 + 1.5 * delta * delta) * (1.0 + 1e-6);
                let min_scale = crate::scalar::sqrtf(2.0 * nx.area / twice_area);
                nx.kind.inradius(S::from_f64(min_scale))
            }
            _ => nx.kind.inradius(nx.base_scale),
        };
        Some(r + self.gap)
    }

    /// When shape `j` is a circle, its centre in the periodic image nearest `p` (seen from
    /// `p`) and its radius. None for other kinds: their inscribed discs give looser cell
    /// bounds than their distances do.
    fn disc(&self, j: u32, p: Point<S>) -> Option<(Point<S>, S)> {
        let s = self.shapes.get(j as usize)?;
        if self.kind_of(u64::from(j)) != ShapeKind::Circle {
            return None;
        }
        // `image_near` moves `p` next to the circle; the circle moves by the opposite shift.
        let q = self.image_near(p, s);
        Some((Point::new(s.x - (q.x - p.x), s.y - (q.y - p.y)), s.scale))
    }

    /// Replaces `near` by the [`NEAR`] shapes nearest to `c` by [`Engine::shape_dist`], among
    /// those that come within `reach` of `c` (of one of its images, on a torus): the ones
    /// `near` holds and the ones the spatial hash lists.
    fn gather(&self, c: Point<S>, reach: S, near: &mut [u32; NEAR]) {
        // The shapes kept and their distances; a shape nearer than the farthest kept takes
        // its place.
        let mut best = [(reach, NONE); NEAR];
        let mut offer = |j: u32| {
            if best.iter().any(|b| b.1 == j) {
                return;
            }
            let d = self.shape_dist(j, c);
            let far = best.iter_mut().fold(None, |m: Option<&mut (S, u32)>, b| match m {
                Some(m) if m.0 >= b.0 => Some(m),
                _ => Some(b),
            });
            if let Some(f) = far.filter(|f| d < f.0) {
                *f = (d, j);
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
                        let lim = reach + self.kind_of(u64::from(j)).bounding_radius(p.scale);
                        let (dx, dy) = (p.x - qx, p.y - qy);
                        if dx * dx + dy * dy < lim * lim {
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
        for (n, b) in near.iter_mut().zip(best.iter()) {
            *n = b.1;
        }
    }

    /// `p`, or on a torus its copy nearest the centre of `s`.
    fn image_near(&self, p: Point<S>, s: &Placed<S>) -> Point<S> {
        if !self.region.periodic() {
            return p;
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
    /// to the nearest image by material, which is all the cell sampler needs.
    fn shape_dist(&self, j: u32, p: Point<S>) -> S {
        let Some(s) = self.shapes.get(j as usize) else {
            return S::from_f64(f64::MAX);
        };
        let kind = self.kind_of(u64::from(j));
        let q = self.image_near(p, s);
        let centre = Point::new(s.x, s.y);
        let dist = centre.dist2(q).sqrt();
        match kind {
            ShapeKind::Circle => dist - s.scale,
            ShapeKind::Ring { inner } => {
                let hole = s.scale * S::from_f64(inner);
                if dist >= s.scale {
                    dist - s.scale
                } else if dist <= hole {
                    hole - dist
                } else {
                    -(dist - hole).min(s.scale - dist)
                }
            }
            _ => {
                let g = kind.geo(centre, s.scale, s.angle);
                let vs = g.vertices();
                let m = edges(vs).fold(None, |m: Option<S>, (a, b)| {
                    let d = seg_dist2(q, a, b);
                    Some(m.map_or(d, |m| m.min(d)))
                });
                let d = m.unwrap_or(S::ZERO).sqrt();
                if point_in_poly(q, vs) {
                    -d
                } else {
                    d
                }
            }
        }
    }

    /// Brings `cells` up to date for the next shape, as a step of [`Engine::step_fast`] does
    /// before its first candidate: afterwards every centre where the next shape fits lies in
    /// a live cell ([`CellSampler::live_boxes`]). Says whether the next shape is placed with
    /// the cells (false when it falls back to the reference sampler, or none is left).
    pub fn prepare_fast(&self, cells: &mut CellSampler<'_, S>) -> bool {
        self.next_shape().ok().and_then(|nx| self.prepare_cells(&nx, cells)).is_some()
    }

    /// Lays out the grid on first use and wakes the cells for the next shape's need; none
    /// when the shape has no clearance condition.
    fn prepare_cells(&self, nx: &Next<S>, cells: &mut CellSampler<'_, S>) -> Option<S> {
        let need = self.need(nx)?;
        if !cells.ready() {
            let (x0, y0, _, _) = self.region.bbox();
            let (w, h) = self.period;
            cells.init(S::from_f64(x0), S::from_f64(y0), w, h, &FieldOf(self));
        }
        cells.wake(need, self.len);
        cells.begin_step();
        Some(need)
    }

    /// Places the next shape with the cell sampler: the same distribution of accepted
    /// placements as [`Engine::step`], far fewer trials late in a fill (see
    /// [`crate::sampler`]). Halts at the trial limit, or at once when no cell can hold the
    /// shape. Use one sampler per engine, for every step after the first that uses it.
    pub fn step_fast<R: RngCore + ?Sized>(&mut self, cells: &mut CellSampler<'_, S>, rng: &mut R) -> Result<Placement<S>, StepError> {
        let nx = self.next_shape()?;
        let Some(need) = self.prepare_cells(&nx, cells) else {
            let placed = self.step_reference(&nx, rng);
            if let Ok(p) = &placed {
                cells.end_step_paper(p.trials);
            }
            return placed;
        };
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials || cells.is_empty() {
                return Err(StepError::Halted { index: nx.index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let Some(Drawn {
                slot,
                cell: drawn,
                point: p,
                quarter,
            }) = cells.draw(rng)
            else {
                continue;
            };
            let angle = if nx.rotated { rng::angle::<S, R>(rng) } else { S::ZERO };
            let slot = match cells.judge(slot, &drawn, quarter, need, &FieldOf(self)) {
                Verdict::Reject => continue,
                Verdict::Test(s) => s,
            };
            let c = self.region.wrap(p);
            let (x0, x1, y0, y1) = nx.range;
            if c.x < x0 || c.x > x1 || c.y < y0 || c.y > y1 {
                cells.note_reject(slot, false);
                continue;
            }
            let known = if slot == usize::MAX { drawn.near() } else { cells.known(slot) };
            match self.try_at(&nx, c, angle, trials, Some(&known)) {
                Ok(placed) => {
                    cells.learn(slot, nx.index as u32, need, &FieldOf(self));
                    cells.end_step(x1 - x0, y1 - y0);
                    return Ok(placed);
                }
                Err(Some(j)) if known.contains(&j) => cells.note_reject(slot, true),
                Err(Some(j)) => {
                    cells.note_learned(slot);
                    cells.learn(slot, j, need, &FieldOf(self));
                }
                Err(None) => cells.note_reject(slot, false),
            }
        }
    }

    /// Steps until a stop condition holds or a step fails, calling `on_place` after each
    /// placement.
    pub fn run<R: RngCore + ?Sized>(&mut self, rng: &mut R, stop: &Stop, on_place: impl FnMut(&Placement<S>)) -> StopReason {
        self.run_with(stop, on_place, |e| e.step(rng))
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

    fn run_with(
        &mut self,
        stop: &Stop,
        mut on_place: impl FnMut(&Placement<S>),
        mut step: impl FnMut(&mut Self) -> Result<Placement<S>, StepError>,
    ) -> StopReason {
        loop {
            let n = self.len as u64;
            if stop.count.is_some_and(|k| n >= k) {
                return StopReason::Count;
            }
            if stop.fill.is_some_and(|f| self.placed_area >= f * self.area) {
                return StopReason::Fill;
            }
            if let Some(m) = stop.min_size {
                let kind = self.kind_of(n);
                if kind.min_width(kind.scale_for_area(self.area_of(n))) < m {
                    return StopReason::MinSize;
                }
            }
            match step(self) {
                Ok(p) => on_place(&p),
                Err(e) => return StopReason::Step(e),
            }
        }
    }
}
