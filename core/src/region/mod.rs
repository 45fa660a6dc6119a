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
//!   the check as it stood (`internals::region::legacy`) rejected such outlines.
//! - The even-odd count only counts edges that span the point's height and reach right of
//!   it (an edge with no point to the right never counts, in any monotone rounding), so the
//!   tree skips boxes that do not: the same parity.
//! - Distances skip boxes whose lower bound, proven against `f64` rounding with a margin of
//!   2^17 over it, is beyond the reach or the best so far: the same minimum (distances are
//!   never NaN or `-0` there). On other scalars ([`Scalar::IS_F64`]) queries visit every edge.

pub mod legacy;
mod rings;
mod simple;
mod tree;

use crate::geom::{
    boxes_meet, edges, in_box, point_in_poly, ray_crosses, seg_box, seg_dist2, seg_seg_dist2, segments_intersect, separated, vbox, Geo,
    Point,
};
use crate::scalar::Scalar;
use core::cmp::Ordering;
use rings::Rings;
use tree::EdgeTree;

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

/// A validated polygonal region over caller-owned vertices: one or more simple rings that do
/// not cross, filled by the even-odd rule (a ring inside another is a hole).
///
/// Build it with [`PolygonRegion::new_in`] and a scratch slice of
/// [`PolygonRegion::scratch_words`] words (an edge tree: checks in about E log E, and queries
/// during a fill that look only at nearby edges), or with [`PolygonRegion::new`] and no
/// scratch (every pair of edges: for outlines of a few dozen vertices). Both accept and
/// reject the same outlines and give the same bits everywhere.
///
/// # Examples
///
/// ```
/// use std::f64::consts::{FRAC_PI_2, PI};
/// use zetafill::{Point, PolygonRegion, Region};
///
/// // A five-pointed star, outer radius 50, inner radius 20, centred at (50, 50).
/// let star: Vec<Point<f64>> = (0..10)
///     .map(|k| {
///         let a = FRAC_PI_2 + k as f64 * PI / 5.0;
///         let r = if k % 2 == 0 { 50.0 } else { 20.0 };
///         Point::new(50.0 + r * a.cos(), 50.0 + r * a.sin())
///     })
///     .collect();
/// let region = PolygonRegion::new(&star, &[10])?;
/// assert!((region.area() - 5.0 * 50.0 * 20.0 * (PI / 5.0).sin()).abs() < 1e-9);
///
/// // A 100 x 100 square with a 20 x 20 hole: two rings, split at index 4.
/// let p = Point::new;
/// let points = [
///     p(0.0, 0.0), p(100.0, 0.0), p(100.0, 100.0), p(0.0, 100.0),
///     p(40.0, 40.0), p(60.0, 40.0), p(60.0, 60.0), p(40.0, 60.0),
/// ];
/// let holed = PolygonRegion::new(&points, &[4, 8])?;
/// assert_eq!(holed.rings().count(), 2);
/// assert_eq!(holed.area(), 9600.0);
/// let region = Region::Polygon(holed);
/// assert!(region.point_inside(p(20.0, 50.0)));
/// assert!(!region.point_inside(p(50.0, 50.0)));
/// # Ok::<(), zetafill::RegionError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct PolygonRegion<'a> {
    points: &'a [Point<f64>],
    ring_ends: &'a [usize],
    area: f64,
    bbox: (f64, f64, f64, f64),
    tree: Option<EdgeTree<'a>>,
}

/// Two regions are equal when their rings, and so their area, are: the scratch lent does not
/// count (it changes no answer).
impl PartialEq for PolygonRegion<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.points == other.points && self.ring_ends == other.ring_ends && self.area == other.area
    }
}

fn ring_slices<'a>(points: &'a [Point<f64>], ends: &'a [usize]) -> impl Iterator<Item = &'a [Point<f64>]> + 'a {
    let starts = core::iter::once(0).chain(ends.iter().copied());
    starts.zip(ends.iter().copied()).map(move |(a, b)| points.get(a..b).unwrap_or(&[]))
}

impl<'a> PolygonRegion<'a> {
    /// Validates rings given as `points` split at the exclusive indices `ring_ends` (the last
    /// must be `points.len()`), with no scratch: every pair of edges is tested, O(E²) in the
    /// number of edges, and every query during a fill visits every edge. For outlines of a
    /// few dozen vertices; larger ones want [`PolygonRegion::new_in`] (same answers).
    pub fn new(points: &'a [Point<f64>], ring_ends: &'a [usize]) -> Result<Self, RegionError> {
        // Not through `new_in`: a firmware that never lends scratch links no tree building.
        Self::checked(points, ring_ends, |_, _| None)
    }

    /// Validates rings as [`PolygonRegion::new`] does, building an edge tree in `scratch`:
    /// the check then takes about E log E (one outline of 10^5 vertices, or 10^4 small rings,
    /// in tens of milliseconds), and the region's queries during a fill look only at the
    /// edges near the point or shape asked about. The region borrows the tree.
    ///
    /// Give it [`PolygonRegion::scratch_words`]`(points.len())` words. With fewer it builds a
    /// tree of larger leaves (slower, never wrong); with too few for one leaf of every edge
    /// it works as [`PolygonRegion::new`]. The answers and every result of a fill are the
    /// same whatever the scratch.
    ///
    /// # Examples
    ///
    /// ```
    /// use zetafill::{Point, PolygonRegion, RegionError};
    ///
    /// // A 64-gon with 100 square holes in a 10 x 10 grid.
    /// let mut points: Vec<Point<f64>> = (0..64)
    ///     .map(|k| {
    ///         let t = k as f64 * std::f64::consts::TAU / 64.0;
    ///         Point::new(100.0 + 100.0 * t.cos(), 100.0 + 100.0 * t.sin())
    ///     })
    ///     .collect();
    /// let mut ends = vec![points.len()];
    /// for i in 0..100 {
    ///     let (x, y) = (55.0 + (i % 10) as f64 * 10.0, 55.0 + (i / 10) as f64 * 10.0);
    ///     points.extend([Point::new(x, y), Point::new(x, y + 4.0), Point::new(x + 4.0, y + 4.0), Point::new(x + 4.0, y)]);
    ///     ends.push(points.len());
    /// }
    /// let mut scratch = vec![0u32; PolygonRegion::scratch_words(points.len())];
    /// let region = PolygonRegion::new_in(&points, &ends, &mut scratch)?;
    /// assert!(region.is_hole(1) && !region.is_hole(0));
    /// assert_eq!(region.area(), PolygonRegion::new(&points, &ends)?.area());
    ///
    /// // A hole that touches its neighbour is refused, as without the tree.
    /// points[64 + 4] = Point::new(59.0, 55.0);
    /// let mut scratch = vec![0u32; PolygonRegion::scratch_words(points.len())];
    /// assert_eq!(PolygonRegion::new_in(&points, &ends, &mut scratch).err(), Some(RegionError::SelfIntersecting));
    /// # Ok::<(), RegionError>(())
    /// ```
    pub fn new_in(points: &'a [Point<f64>], ring_ends: &'a [usize], scratch: &'a mut [u32]) -> Result<Self, RegionError> {
        Self::checked(points, ring_ends, |rings, bbox| EdgeTree::build(rings, bbox, scratch))
    }

    /// The checks, with the tree `tree` builds (if any) over the rings and their box.
    fn checked(
        points: &'a [Point<f64>],
        ring_ends: &'a [usize],
        tree: impl FnOnce(&Rings<'a>, tree::Bbox) -> Option<EdgeTree<'a>>,
    ) -> Result<Self, RegionError> {
        let mut start = 0usize;
        for &e in ring_ends {
            if e < start.saturating_add(3) || e > points.len() {
                return Err(RegionError::TooFewVertices);
            }
            start = e;
        }
        if ring_ends.is_empty() || start != points.len() {
            return Err(RegionError::TooFewVertices);
        }
        if points.iter().any(|p| !(p.x.is_finite() && p.y.is_finite())) {
            return Err(RegionError::NotFinite);
        }
        let mut bbox = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
        for p in points {
            bbox = (bbox.0.min(p.x), bbox.1.min(p.y), bbox.2.max(p.x), bbox.3.max(p.y));
        }
        let rings = Rings {
            points,
            ends: ring_ends,
            next: &[],
        };
        let tree = tree(&rings, bbox);
        let m = simple::margin(scale_of(bbox));
        match &tree {
            Some(t) => simple::check_tree(&t.rings(&rings), t, m)?,
            None => simple::check_pairs(&rings, m)?,
        }
        let mut region = PolygonRegion {
            points,
            ring_ends,
            area: 0.0,
            bbox,
            tree,
        };
        // Area by the even-odd rule: a ring inside an odd number of others is a hole.
        let mut area = 0.0f64;
        for (r, ring) in region.rings().enumerate() {
            let a = edges(ring).fold(0.0, |s, (p, q)| s + p.cross(q)) / 2.0;
            area += if region.is_hole(r) { -a.abs() } else { a.abs() };
        }
        if !(area > 0.0 && area.is_finite()) {
            return Err(RegionError::ZeroArea);
        }
        region.area = area;
        Ok(region)
    }

    /// The words of scratch [`PolygonRegion::new_in`] needs for an outline of `vertices`
    /// vertices (all rings together) to build its edge tree with the smallest leaves:
    /// `6 * vertices + 8` (24 bytes a vertex).
    ///
    /// # Examples
    ///
    /// ```
    /// use zetafill::PolygonRegion;
    ///
    /// // A fixed buffer for outlines of up to 200 vertices (a `const fn`, so it sizes arrays).
    /// let scratch = [0u32; PolygonRegion::scratch_words(200)];
    /// assert_eq!(scratch.len(), 1208);
    /// ```
    pub const fn scratch_words(vertices: usize) -> usize {
        tree::words(vertices)
    }

    /// Whether ring `ring` (numbered as in [`PolygonRegion::ring_ends`]) is a hole: inside an
    /// odd number of the other rings. False for a ring that does not exist.
    ///
    /// # Examples
    ///
    /// ```
    /// use zetafill::{Point, PolygonRegion};
    ///
    /// let p = Point::new;
    /// // A hole, the outline around it, and an island inside the hole.
    /// let points = [
    ///     p(2.0, 2.0), p(8.0, 2.0), p(8.0, 8.0), p(2.0, 8.0),
    ///     p(0.0, 0.0), p(10.0, 0.0), p(10.0, 10.0), p(0.0, 10.0),
    ///     p(4.0, 4.0), p(6.0, 4.0), p(6.0, 6.0), p(4.0, 6.0),
    /// ];
    /// let region = PolygonRegion::new(&points, &[4, 8, 12])?;
    /// let holes: Vec<bool> = (0..4).map(|r| region.is_hole(r)).collect();
    /// assert_eq!(holes, [true, false, false, false]);
    /// assert_eq!(region.area(), 100.0 - 36.0 + 4.0);
    /// # Ok::<(), zetafill::RegionError>(())
    /// ```
    pub fn is_hole(&self, ring: usize) -> bool {
        let rings = self.ring_index();
        if ring >= self.ring_ends.len() {
            return false;
        }
        match &self.tree {
            Some(t) => simple::odd_depth_tree(&rings, t, ring),
            None => simple::odd_depth_pairs(&rings, ring),
        }
    }

    fn ring_index(&self) -> Rings<'a> {
        Rings {
            points: self.points,
            ends: self.ring_ends,
            next: self.tree.map_or(&[], |t| t.next()),
        }
    }

    /// The vertices, all rings one after another.
    pub fn points(&self) -> &'a [Point<f64>] {
        self.points
    }

    /// The exclusive end index of each ring in [`PolygonRegion::points`].
    pub fn ring_ends(&self) -> &'a [usize] {
        self.ring_ends
    }

    /// The rings.
    pub fn rings(&self) -> impl Iterator<Item = &'a [Point<f64>]> + 'a {
        ring_slices(self.points, self.ring_ends)
    }

    /// The area (holes subtracted).
    pub fn area(&self) -> f64 {
        self.area
    }

    fn edges_s<S: Scalar>(&self) -> impl Iterator<Item = (Point<S>, Point<S>)> + 'a {
        self.rings().flat_map(edges).map(|(a, b)| (conv(a), conv(b)))
    }

    /// [`Region::signed_clearance`] of the polygon: its edges' distance rounded up inside,
    /// down outside. On `f64` (the only scalar the tree serves) the rounded-up distance is
    /// the plain one, so the tree's nearest edge gives it.
    fn signed_clearance<S: Scalar>(&self, q: Point<S>) -> S {
        let inside = self.inside(q);
        let d2 = if inside && self.tree_for::<S>().is_none() {
            self.edges_s::<S>()
                .map(|(a, b)| S::seg_dist2_up(q, a, b))
                .fold(None, |m: Option<S>, d| Some(m.map_or(d, |m| m.min(d))))
                .unwrap_or(S::ZERO)
        } else {
            self.dist2(q)
        };
        let d = d2.sqrt();
        if inside {
            d
        } else {
            -d
        }
    }

    /// The tree, when queries on `S` may use it (`f64` only: its pruning is proven for
    /// `f64` rounding).
    fn tree_for<S: Scalar>(&self) -> Option<&EdgeTree<'a>> {
        self.tree.as_ref().filter(|_| S::IS_F64)
    }

    /// Even-odd: the parity of the edges [`ray_crosses`] counts from `p`.
    fn inside<S: Scalar>(&self, p: Point<S>) -> bool {
        if let Some(t) = self.tree_for::<S>() {
            let (rings, pf) = (self.ring_index(), Point::new(p.x.to_f64(), p.y.to_f64()));
            let mut odd = false;
            t.walk(
                |b| simple::ray_box(b, pf),
                |k| {
                    let (a, b) = rings.edge(k);
                    odd ^= ray_crosses(p, conv(a), conv(b));
                    false
                },
            );
            return odd;
        }
        let mut inside = false;
        for ring in self.rings() {
            let mut buf_in = false;
            for (a, b) in edges(ring) {
                if ray_crosses(p, conv(a), conv(b)) {
                    buf_in = !buf_in;
                }
            }
            inside ^= buf_in;
        }
        inside
    }

    /// Whether every edge is farther than `sqrt(r2)` from `c` (as [`seg_dist2`] computes).
    fn clear_of<S: Scalar>(&self, c: Point<S>, r2: S) -> bool {
        if let Some(t) = self.tree_for::<S>() {
            let (rings, q, r2f, scale) = (self.ring_index(), (c.x.to_f64(), c.y.to_f64()), r2.to_f64(), scale_of(self.bbox));
            // A box whose bound exceeds r2 holds only edges that pass; an edge fails unless
            // its distance exceeds r2 (so a NaN r2 fails every edge, as without the tree).
            let beyond = |d: Option<Ordering>| d == Some(Ordering::Greater);
            return !t.walk(
                |b| !beyond(t.lower_bound(q, b, scale).partial_cmp(&r2f)),
                |k| {
                    let (a, b) = rings.edge(k);
                    !beyond(seg_dist2(c, conv(a), conv(b)).partial_cmp(&r2))
                },
            );
        }
        self.edges_s::<S>().all(|(a, b)| seg_dist2(c, a, b) > r2)
    }

    /// The smallest [`seg_dist2`] from `q` to an edge.
    fn dist2<S: Scalar>(&self, q: Point<S>) -> S {
        let qf = (q.x.to_f64(), q.y.to_f64());
        // Through the tree only where no distance can overflow to NaN (a minimum with a NaN
        // in it depends on the order of the edges).
        if let Some(t) = self.tree_for::<S>().filter(|t| t.exact_min(qf)) {
            let (rings, scale) = (self.ring_index(), scale_of(self.bbox));
            let best = t.min(
                |b| S::from_f64(t.lower_bound(qf, b, scale)),
                |k| {
                    let (a, b) = rings.edge(k);
                    seg_dist2(q, conv(a), conv(b))
                },
            );
            return best.unwrap_or(S::ZERO);
        }
        let mut best: Option<S> = None;
        for (a, b) in self.edges_s::<S>() {
            let d = seg_dist2(q, a, b);
            best = Some(best.map_or(d, |m| m.min(d)));
        }
        best.unwrap_or(S::ZERO)
    }

    /// Whether a polygon shape (its vertices `vs`, all inside the region) keeps `gap` from
    /// every edge and holds no ring (see the module documentation for the pairs skipped).
    fn clear_of_poly<S: Scalar>(&self, vs: &[Point<S>], gap: S) -> bool {
        let sb = vbox(vs);
        let big = sb.iter().fold(S::ONE.max(S::from_f64(scale_of(self.bbox))), |m, &v| m.max(v.abs()));
        let m = big * S::from_f64(1e-9);
        let reach = gap.max(S::ZERO) + m;
        let g2 = gap * gap;
        let edge_clear = |a: Point<S>, b: Point<S>| {
            let eb = seg_box(a, b);
            !boxes_meet(eb, sb, reach)
                || edges(vs).all(|(c, d)| {
                    !boxes_meet(eb, seg_box(c, d), reach)
                        || if gap <= S::ZERO {
                            !segments_intersect(a, b, c, d)
                        } else {
                            seg_seg_dist2(a, b, c, d) > g2
                        }
                })
        };
        // No outline (a hole) may lie wholly inside the shape: its first vertex tells.
        let ring_clear = |q: Point<S>| !(in_box(q, sb, m) && point_in_poly(q, vs));
        if let Some(t) = self.tree_for::<S>() {
            let rings = self.ring_index();
            let f = |v: S| v.to_f64();
            let sbf = (f(sb[0]), f(sb[1]), f(sb[2]), f(sb[3]));
            // Wider than both tests above: a box outside it holds no edge either looks at.
            let wide = f(reach) + f(m);
            return !t.walk(
                |b| simple::near(b, sbf, wide),
                |k| {
                    let (a, b) = rings.edge(k);
                    let (a, b) = (conv::<S>(a), conv::<S>(b));
                    !edge_clear(a, b) || (t.is_start(k) && !ring_clear(a))
                },
            );
        }
        self.edges_s::<S>().all(|(a, b)| edge_clear(a, b)) && self.rings().all(|ring| ring.first().is_none_or(|&q| ring_clear(conv(q))))
    }
}

/// The largest coordinate magnitude in a box, at least 1 (it sets the margins of the box
/// tests).
fn scale_of(b: (f64, f64, f64, f64)) -> f64 {
    1.0f64.max(b.0.abs()).max(b.1.abs()).max(b.2.abs()).max(b.3.abs())
}

#[inline]
fn conv<S: Scalar>(p: Point<f64>) -> Point<S> {
    Point::new(S::from_f64(p.x), S::from_f64(p.y))
}

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
}

impl Region<'_> {
    /// Whether the dimensions are finite and positive (polygons are validated when built).
    pub fn is_valid(&self) -> bool {
        let ok = |v: f64| v.is_finite() && v > 0.0;
        match *self {
            Region::Rect { width, height, .. } => ok(width) && ok(height),
            Region::Circle { radius } => ok(radius),
            Region::Annulus { outer, inner } => ok(outer) && ok(inner) && inner < outer,
            Region::Polygon(_) => true,
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
        }
    }

    /// Whether the boundary is periodic.
    pub fn periodic(&self) -> bool {
        matches!(self, Region::Rect { periodic: true, .. })
    }

    /// Bounding box (min x, min y, max x, max y).
    pub fn bbox(&self) -> (f64, f64, f64, f64) {
        match *self {
            Region::Rect { width, height, .. } => (0.0, 0.0, width, height),
            Region::Circle { radius: r } | Region::Annulus { outer: r, .. } => (0.0, 0.0, 2.0 * r, 2.0 * r),
            Region::Polygon(p) => p.bbox,
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
            Region::Rect { periodic: true, .. } => true,
            Region::Rect { width, height, .. } => {
                let (x0, y0, x1, y1) = g.bounds();
                x0 >= gap && y0 >= gap && x1 <= S::from_f64(width) - gap && y1 <= S::from_f64(height) - gap
            }
            Region::Circle { radius } => {
                let room = S::from_f64(radius) - gap;
                room > S::ZERO && g.max_dist2(self.centre()) <= room * room
            }
            Region::Annulus { outer, inner } => {
                let room = S::from_f64(outer) - gap;
                let c = self.centre();
                room > S::ZERO && g.max_dist2(c) <= room * room && separated(g, &Geo::Circle { c, r: S::from_f64(inner) }, gap)
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
        }
    }

    /// The point `p` wrapped into the period (unchanged unless periodic).
    pub fn wrap<S: Scalar>(&self, p: Point<S>) -> Point<S> {
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
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> [Point<f64>; 8] {
        let mut out = [Point::default(); 8];
        for (o, &(x, y)) in out.iter_mut().zip(v) {
            *o = Point::new(x, y);
        }
        out
    }

    #[test]
    fn square_with_square_hole_has_the_right_area_and_inside() {
        let p = pts(&[
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 10.0),
            (0.0, 10.0),
            (4.0, 4.0),
            (4.0, 6.0),
            (6.0, 6.0),
            (6.0, 4.0),
        ]);
        let ends = [4, 8];
        let r = PolygonRegion::new(&p, &ends).map(Region::Polygon);
        let Ok(r) = r else { panic!("valid region rejected") };
        assert_eq!(r.area(), 96.0);
        assert!(r.point_inside(Point::new(1.0, 1.0)));
        assert!(!r.point_inside(Point::new(5.0, 5.0)));
        let small = Geo::Circle {
            c: Point::new(2.0, 2.0),
            r: 1.0,
        };
        assert!(r.contains(&small, 0.5));
        assert!(!r.contains(&small, 1.0));
        assert!(!r.contains(
            &Geo::Circle {
                c: Point::new(5.0, 5.0),
                r: 0.5
            },
            0.0
        ));
        // A circle around the hole is not inside.
        assert!(!r.contains(
            &Geo::Circle {
                c: Point::new(5.0, 5.0),
                r: 2.0
            },
            0.0
        ));
    }

    #[test]
    fn bad_polygons_are_rejected() {
        let bow = pts(&[(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
        assert_eq!(PolygonRegion::new(&bow[..4], &[4]).err(), Some(RegionError::SelfIntersecting));
        assert_eq!(PolygonRegion::new(&bow[..2], &[2]).err(), Some(RegionError::TooFewVertices));
        let line = pts(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]);
        assert!(PolygonRegion::new(&line[..3], &[3]).is_err());
        let nan = pts(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)]);
        assert_eq!(PolygonRegion::new(&nan[..3], &[3]).err(), Some(RegionError::NotFinite));
    }

    #[test]
    fn circle_and_annulus_contain_exactly() {
        let c = Region::Circle { radius: 10.0 };
        assert!(c.contains(
            &Geo::Circle {
                c: Point::new(10.0, 15.0),
                r: 5.0
            },
            0.0
        ));
        assert!(!c.contains(
            &Geo::Circle {
                c: Point::new(10.0, 15.0),
                r: 5.0
            },
            0.1
        ));
        let a = Region::Annulus { outer: 10.0, inner: 4.0 };
        assert!(!a.contains(
            &Geo::Circle {
                c: Point::new(10.0, 10.0),
                r: 1.0
            },
            0.0
        ));
        assert!(a.contains(
            &Geo::Circle {
                c: Point::new(10.0, 17.0),
                r: 2.0
            },
            0.0
        ));
        assert!(a.contains(
            &Geo::Ring {
                c: Point::new(10.0, 10.0),
                r: 9.0,
                inner: 5.0
            },
            0.5
        ));
    }
}
