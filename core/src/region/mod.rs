//! Regions to fill: where candidate centres are drawn and whether a shape lies inside.
//!
//! - `Rect`: `[0, W] x [0, H]`, with an inclusive boundary (shapes stay inside, at least
//!   `gap` from the edge; touching the edge is allowed when `gap = 0`) or a periodic one (a
//!   torus: a shape crossing an edge exists again at x ± W, y ± H, and every test sees those
//!   images).
//! - `Circle`: the disc of radius R centred at (R, R); `Annulus`: the ring between R and r
//!   centred at (R, R) (its hole is outside the region).
//! - `Polygon`: any set of simple closed rings (outlines) that do not cross, filled by the
//!   even-odd rule, so a ring inside another is a hole (the borrowed vertices belong to the
//!   caller). A shape must keep more than `gap` from every edge.
//!
//! The area `A` of the power law is the region's true area. Nothing here panics.
//!
//! ## Polygons: the edge tree in caller-owned scratch
//!
//! A polygon is checked when built (no two edges meet, each ring's even-odd depth) and asked
//! during a fill whether a point is inside, how far the boundary is, and whether a shape keeps
//! its gap from every edge. Done edge by edge, the check is O(E²) and every query O(E): an
//! outline of 10^5 vertices took 92 s to check and a fill of 200 circles in it minutes.
//!
//! [`PolygonRegion::new_in`] builds an edge tree in a `u32` slice the caller lends
//! ([`PolygonRegion::scratch_words`]: 6 words a vertex), since the core has no allocator: a
//! bounding-box hierarchy over the edges sorted along a Z-order curve, leaves of 4 edges
//! (see `tree`). The check then asks, for each leaf, only the edges whose boxes come near it
//! (O(E log E) for outlines whose edges' boxes overlap few others; at worst every pair whose
//! boxes overlap), and each ring's depth counts only the edges level with its first vertex;
//! queries visit the few edges near the point or shape. A tree was chosen over a uniform
//! grid because it also answers "how far is the nearest edge" from deep inside a large
//! region in logarithmic time, where a grid walks rings of empty cells; and over a sweep
//! because a sweep's order needs exact predicates, which would change what is accepted.
//! [`PolygonRegion::new`] lends no scratch and tests every pair: for outlines of a few
//! dozen vertices (a microcontroller's star). Less scratch than asked gives larger leaves;
//! too little for one leaf of every edge gives [`PolygonRegion::new`]'s way.
//!
//! Both ways give the same answers and the same bits on every input, because both run the
//! same exact test on every edge that could change an answer and skip the same others:
//! - The check skips pairs of edges whose boxes lie farther apart than `m` (10^-9 of the
//!   largest coordinate magnitude), and a polygon shape's test skips pairs of a region edge
//!   and a shape edge whose boxes lie farther apart than the gap and `m`, and rings whose
//!   first vertex lies farther than `m` outside the shape's box (as the shape-against-shape
//!   test already did). Such edges never meet; the floating-point segment test can still call
//!   four nearly collinear points far apart a crossing, which no index could reproduce short
//!   of asking every pair. Skipping them is the one change from the checks before the tree:
//!   the check as it stood (kept as a test oracle, `core/tests/oracles/legacy_region.rs`) rejected
//!   such outlines.
//! - The even-odd count only counts edges that span the point's height and reach right of
//!   it (an edge with no point to the right never counts, in any monotone rounding), so the
//!   tree skips boxes that do not: the same parity.
//! - Distances skip boxes whose lower bound, proven against `f64` rounding with a margin of
//!   2^17 over it, is beyond the reach or the best so far: the same minimum (distances are
//!   never NaN or `-0` there). On other scalars ([`Scalar::IS_F64`]) queries visit every edge.

mod polygon;
mod rings;
mod simple;
mod tree;
mod wallpaper;

pub use polygon::PolygonRegion;
pub use wallpaper::{Group, Iso, LatticeKind, Wallpaper, WallpaperError, MAX_IMAGES};

use crate::geom::{separated, Geo, Point};
use crate::scalar::Scalar;

/// What is wrong with a polygon region ([`PolygonRegion::new`]).
///
/// # Examples
///
/// ```
/// use zetafill::{Point, PolygonRegion, RegionError};
///
/// let p = Point::new;
/// // Two vertices are no outline; ring ends must cover every vertex.
/// assert_eq!(PolygonRegion::new(&[p(0.0, 0.0), p(1.0, 0.0)], &[2]).err(), Some(RegionError::TooFewVertices));
/// let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
/// assert_eq!(PolygonRegion::new(&square, &[3]).err(), Some(RegionError::TooFewVertices));
/// assert!(PolygonRegion::new(&square, &[4]).is_ok());
/// // A bow tie crosses itself.
/// let bow_tie = [p(0.0, 0.0), p(10.0, 10.0), p(10.0, 0.0), p(0.0, 10.0)];
/// let e = PolygonRegion::new(&bow_tie, &[4]).err();
/// assert_eq!(e, Some(RegionError::SelfIntersecting));
/// assert_eq!(e.map(|e| e.to_string()).as_deref(), Some("the outline crosses itself (or two outlines meet)"));
/// let nan = [p(0.0, 0.0), p(f64::NAN, 0.0), p(0.0, 1.0)];
/// assert_eq!(PolygonRegion::new(&nan, &[3]).err(), Some(RegionError::NotFinite));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum RegionError {
    /// A ring has fewer than 3 vertices, or the ring ends are not increasing.
    TooFewVertices,
    /// A coordinate is not finite.
    NotFinite,
    /// Two edges cross or touch (the outline is not simple, or two rings meet).
    SelfIntersecting,
    /// The area is zero.
    ZeroArea,
}

impl core::fmt::Display for RegionError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            RegionError::TooFewVertices => "every outline needs at least 3 vertices",
            RegionError::NotFinite => "a vertex coordinate is not a finite number",
            RegionError::SelfIntersecting => "the outline crosses itself (or two outlines meet)",
            RegionError::ZeroArea => "the outline encloses no area",
        })
    }
}

impl core::error::Error for RegionError {}

/// A region in its own frame (x right, y up). The power law's area `A` is the region's true
/// area ([`Region::area`]).
///
/// # Examples
///
/// Every kind of region, each filled with 30 circles that all lie inside it (on a torus a
/// circle may cross an edge: it exists again on the other side).
///
/// ```
/// use std::f64::consts::PI;
/// use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Point, PolygonRegion, Region, Stop, StopReason, Storage};
///
/// let p = Point::new;
/// let outline = [
///     p(0.0, 0.0), p(100.0, 0.0), p(100.0, 60.0), p(0.0, 60.0),
///     p(40.0, 20.0), p(60.0, 20.0), p(60.0, 40.0), p(40.0, 40.0),
/// ];
/// let regions = [
///     (Region::Rect { width: 100.0, height: 60.0, periodic: false }, 6000.0),
///     (Region::Rect { width: 100.0, height: 60.0, periodic: true }, 6000.0),
///     (Region::Circle { radius: 50.0 }, PI * 2500.0),
///     (Region::Annulus { outer: 50.0, inner: 10.0 }, PI * 2400.0),
///     (Region::Polygon(PolygonRegion::new(&outline, &[4, 8])?), 5600.0),
/// ];
/// for (region, area) in regions {
///     assert!((region.area() - area).abs() < 1e-9);
///     let mut shapes = [Placed::<f64>::default(); 30];
///     let mut index = [0u32; index_words(30)];
///     let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
///     let mut engine = Engine::new(Params::circles(1.3, 3.0), region, storage)?;
///     let stop = Stop { count: Some(30), ..Stop::default() };
///     assert_eq!(engine.run(&mut rng_from_seed(1), &stop, |_| {}), StopReason::Count);
///     assert!((0..30).all(|i| engine.geo(i).is_some_and(|g| region.contains(&g, 0.0))));
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Region<'a> {
    /// The rectangle `[0, width] x [0, height]`.
    Rect {
        /// Width, finite and > 0.
        width: f64,
        /// Height, finite and > 0.
        height: f64,
        /// Toroidal boundary when true.
        periodic: bool,
    },
    /// The disc of this radius centred at (radius, radius).
    Circle {
        /// Radius, finite and > 0.
        radius: f64,
    },
    /// The ring between `outer` and `inner` centred at (outer, outer).
    Annulus {
        /// Outer radius.
        outer: f64,
        /// Inner radius, 0 < inner < outer.
        inner: f64,
    },
    /// A polygon with optional holes.
    Polygon(PolygonRegion<'a>),
    /// The plane with the symmetry of a wallpaper group: a fill places orbits (a shape and
    /// its images), on the torus of the group's lattice; the power law divides the area of the
    /// fundamental region.
    Wallpaper(Wallpaper),
}

impl Region<'_> {
    /// Whether the dimensions are finite and positive (polygons are validated when built).
    pub fn is_valid(&self) -> bool {
        let ok = |v: f64| v.is_finite() && v > 0.0;
        match *self {
            Region::Rect { width, height, .. } => ok(width) && ok(height),
            Region::Circle { radius } => ok(radius),
            Region::Annulus { outer, inner } => ok(outer) && ok(inner) && inner < outer,
            Region::Polygon(_) | Region::Wallpaper(_) => true,
        }
    }

    /// The region's area.
    pub fn area(&self) -> f64 {
        use core::f64::consts::PI;
        match *self {
            Region::Rect { width, height, .. } => width * height,
            Region::Circle { radius } => PI * radius * radius,
            Region::Annulus { outer, inner } => PI * (outer * outer - inner * inner),
            Region::Polygon(p) => p.area(),
            Region::Wallpaper(w) => w.fundamental_area(),
        }
    }

    /// Whether the region has no boundary: a periodic rectangle (a torus) or a wallpaper
    /// group's torus.
    pub fn periodic(&self) -> bool {
        matches!(self, Region::Rect { periodic: true, .. } | Region::Wallpaper(_))
    }

    /// The wallpaper group, for a symmetric fill.
    pub fn wallpaper(&self) -> Option<&Wallpaper> {
        match self {
            Region::Wallpaper(w) => Some(w),
            _ => None,
        }
    }

    /// Bounding box (min x, min y, max x, max y).
    pub fn bbox(&self) -> (f64, f64, f64, f64) {
        match *self {
            Region::Rect { width, height, .. } => (0.0, 0.0, width, height),
            Region::Circle { radius: r } | Region::Annulus { outer: r, .. } => (0.0, 0.0, 2.0 * r, 2.0 * r),
            Region::Polygon(p) => p.bbox,
            Region::Wallpaper(w) => {
                let (ax, _, by) = w.lattice();
                (0.0, 0.0, ax, by)
            }
        }
    }

    /// The largest absolute coordinate of the bounding box: where a floating-point scalar's
    /// resolution is coarsest (see [`Scalar::MIN_SIZE_RELATIVE`]).
    pub fn magnitude(&self) -> f64 {
        let (x0, y0, x1, y1) = self.bbox();
        [x0, y0, x1, y1].iter().fold(0.0f64, |m, v| m.max(v.abs()))
    }

    /// Whether the bounding box has sides of at most `max` and lies within `max` of the
    /// origin on each axis (see [`Scalar::MAX_EXTENT`]).
    pub fn within(&self, max: f64) -> bool {
        let (x0, y0, x1, y1) = self.bbox();
        let (w, h) = self.extent();
        w <= max && h <= max && [x0, y0, x1, y1].iter().all(|v| v.abs() <= max)
    }

    /// Width and height of the bounding box (the period when periodic).
    pub fn extent(&self) -> (f64, f64) {
        let (x0, y0, x1, y1) = self.bbox();
        (x1 - x0, y1 - y0)
    }

    fn centre<S: Scalar>(&self) -> Point<S> {
        let (x0, y0, x1, y1) = self.bbox();
        Point::new(S::from_f64((x0 + x1) / 2.0), S::from_f64((y0 + y1) / 2.0))
    }

    /// The ranges `[lo, hi]` for the centre of a shape whose half extents are `(ex, ey)`:
    /// the bounding box shrunk by them and the gap (a superset of the valid centres, exact
    /// for rectangles), or `None` when empty. Periodic regions give the whole period.
    pub fn centre_range<S: Scalar>(&self, ex: S, ey: S, gap: S) -> Option<(S, S, S, S)> {
        let (bx0, by0, bx1, by1) = self.bbox();
        let (bx0, by0, bx1, by1) = (S::from_f64(bx0), S::from_f64(by0), S::from_f64(bx1), S::from_f64(by1));
        if self.periodic() {
            return Some((bx0, bx1, by0, by1));
        }
        let (x0, x1) = (bx0 + gap + ex, bx1 - gap - ex);
        let (y0, y1) = (by0 + gap + ey, by1 - gap - ey);
        if x1 < x0 || y1 < y0 {
            None
        } else {
            Some((x0, x1, y0, y1))
        }
    }

    /// Whether a shape lies inside the region with its gap to the boundary. Periodic regions
    /// accept every shape (its own images are tested by the engine).
    pub fn contains<S: Scalar>(&self, g: &Geo<S>, gap: S) -> bool {
        match *self {
            Region::Rect { periodic: true, .. } | Region::Wallpaper(_) => true,
            Region::Rect { width, height, .. } => {
                let inside = |(x0, y0, x1, y1): (S, S, S, S)| {
                    x0 >= gap && y0 >= gap && x1 <= S::from_f64(width) - gap && y1 <= S::from_f64(height) - gap
                };
                // A motif's bounding box first: it holds every vertex, so it never changes
                // the answer, and most motifs lie well inside.
                if let Geo::Motif { m, f } = g {
                    if !crate::geom::MOTIFS {
                        return false;
                    }
                    let [x0, y0, x1, y1] = m.world_box(f);
                    if inside((x0, y0, x1, y1)) {
                        return true;
                    }
                }
                inside(g.bounds())
            }
            Region::Circle { radius } => {
                let room = S::from_f64(radius) - gap;
                room > S::ZERO && (motif_within(g, self.centre(), room) || g.max_dist2(self.centre()) <= room * room)
            }
            Region::Annulus { outer, inner } => {
                let room = S::from_f64(outer) - gap;
                let c = self.centre();
                room > S::ZERO
                    && (motif_within(g, c, room) || g.max_dist2(c) <= room * room)
                    && separated(g, &Geo::Circle { c, r: S::from_f64(inner) }, gap)
            }
            Region::Polygon(p) => poly_contains(&p, g, gap),
        }
    }

    /// Whether a point is inside the region (the even-odd rule for polygons; boundary points
    /// may go either way).
    pub fn point_inside<S: Scalar>(&self, q: Point<S>) -> bool {
        match *self {
            Region::Rect { width, height, .. } => {
                q.x >= S::ZERO && q.y >= S::ZERO && q.x <= S::from_f64(width) && q.y <= S::from_f64(height)
            }
            Region::Circle { radius } => q.dist2(self.centre()) <= S::from_f64(radius * radius),
            Region::Annulus { outer, inner } => {
                let d = q.dist2(self.centre());
                d <= S::from_f64(outer * outer) && d >= S::from_f64(inner * inner)
            }
            Region::Polygon(p) => p.inside(q),
            Region::Wallpaper(_) => true,
        }
    }

    /// The squared distance from a point to the region's boundary.
    pub fn boundary_dist2<S: Scalar>(&self, q: Point<S>) -> S {
        match *self {
            Region::Rect { width, height, .. } => {
                let dx = q.x.abs().min((S::from_f64(width) - q.x).abs());
                let dy = q.y.abs().min((S::from_f64(height) - q.y).abs());
                let d = dx.min(dy);
                d * d
            }
            Region::Circle { radius } => {
                let d = q.dist2(self.centre()).sqrt() - S::from_f64(radius);
                d * d
            }
            Region::Annulus { outer, inner } => {
                let r = q.dist2(self.centre()).sqrt();
                let (a, b) = (r - S::from_f64(outer), r - S::from_f64(inner));
                (a * a).min(b * b)
            }
            Region::Polygon(p) => p.dist2(q),
            // No boundary: farther than any shape reaches.
            Region::Wallpaper(w) => {
                let (ax, _, by) = w.lattice();
                let d = S::from_f64(4.0 * ax.max(by));
                d * d
            }
        }
    }

    /// Whether the boundary lies farther than `sqrt(r2)` from `q`: the same answer as
    /// `self.boundary_dist2(q) > r2`, found for a polygon without the nearest edge (the
    /// first edge within reach ends the search).
    ///
    /// # Examples
    ///
    /// ```
    /// use zetafill::{Point, PolygonRegion, Region};
    ///
    /// let p = Point::new;
    /// let square = [p(0.0, 0.0), p(10.0, 0.0), p(10.0, 10.0), p(0.0, 10.0)];
    /// let region = Region::Polygon(PolygonRegion::new(&square, &[4])?);
    /// // The centre is 5 from every edge.
    /// assert!(region.boundary_beyond(p(5.0, 5.0), 24.9));
    /// assert!(!region.boundary_beyond(p(5.0, 5.0), 25.0));
    /// assert_eq!(region.boundary_beyond(p(5.0, 5.0), 25.0), region.boundary_dist2(p(5.0, 5.0)) > 25.0);
    /// # Ok::<(), zetafill::RegionError>(())
    /// ```
    pub fn boundary_beyond<S: Scalar>(&self, q: Point<S>, r2: S) -> bool {
        match *self {
            Region::Polygon(p) => p.clear_of(q, r2),
            _ => self.boundary_dist2(q) > r2,
        }
    }

    /// The signed distance from a point to the outside of the region: positive inside,
    /// negative outside; a periodic region has no outside (a distance larger than it). Rounded
    /// up where the scalar rounds (an upper bound, as the cell sampler needs).
    pub fn signed_clearance<S: Scalar>(&self, q: Point<S>) -> S {
        match *self {
            Region::Rect {
                periodic: true,
                width,
                height,
            } => S::from_f64(4.0 * width.max(height)),
            Region::Rect { width, height, .. } => q.x.min(S::from_f64(width) - q.x).min(q.y).min(S::from_f64(height) - q.y),
            // The distance from the centre rounded down where it is subtracted, up where added.
            Region::Circle { radius } => S::from_f64(radius) - q.dist2(self.centre()).sqrt(),
            Region::Annulus { outer, inner } => {
                let c = self.centre();
                let d = q.diff(c);
                let (near, far) = (q.dist2(c).sqrt(), S::dist2_up(d.x, d.y).sqrt());
                (S::from_f64(outer) - near).min(far - S::from_f64(inner))
            }
            Region::Polygon(p) => p.signed_clearance(q),
            Region::Wallpaper(w) => {
                let (ax, _, by) = w.lattice();
                S::from_f64(4.0 * ax.max(by))
            }
        }
    }

    /// The point `p` wrapped into the period (unchanged unless periodic).
    pub fn wrap<S: Scalar>(&self, p: Point<S>) -> Point<S> {
        if let Region::Wallpaper(w) = self {
            return w.wrap(p);
        }
        if !self.periodic() {
            return p;
        }
        let (w, h) = self.extent();
        let (w, h) = (S::from_f64(w), S::from_f64(h));
        let fold = |v: S, m: S| {
            let mut v = v;
            if v < S::ZERO {
                v = v + m;
            }
            if v >= m {
                v = v - m;
            }
            v
        };
        Point::new(fold(p.x, w), fold(p.y, h))
    }
}

/// Whether `g` is a motif whose bounding disc lies within `room` of `c` (then every vertex
/// does: a shortcut that never changes the answer).
fn motif_within<S: Scalar>(g: &Geo<'_, S>, c: Point<S>, room: S) -> bool {
    match g {
        Geo::Motif { m, f } => crate::geom::MOTIFS && m.reach_from(f, c) <= room,
        _ => false,
    }
}

// Out of line: its frame stays off the stack of the other regions' tests.
#[inline(never)]
fn poly_contains<S: Scalar>(p: &PolygonRegion<'_>, g: &Geo<S>, gap: S) -> bool {
    match *g {
        Geo::Circle { c, r } | Geo::Ring { c, r, .. } => {
            let reach = r + gap;
            p.inside(c) && p.clear_of(c, reach * reach)
        }
        Geo::Poly { .. } => {
            let vs = g.vertices();
            vs.iter().all(|&v| p.inside(v)) && p.clear_of_poly(vs, gap)
        }
        Geo::Motif { m, ref f } => crate::geom::MOTIFS && p.holds_motif(m, f, gap),
    }
}

#[cfg(test)]
mod tests;
