//! Polygon regions: validated rings of caller-owned vertices, filled by the even-odd rule,
//! and the region queries on them (inside, clearance, distance to the boundary).

use super::rings::Rings;
use super::tree::{self, EdgeTree};
use super::{simple, RegionError};
use crate::geom::{
    boxes_meet, edges, in_box, point_in_poly, ray_crosses, seg_box, seg_dist2, seg_seg_dist2, segments_intersect, vbox, Point,
};
use crate::scalar::Scalar;
use crate::shape::{pair_near, Frame, Motif};
use core::cmp::Ordering;

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
    pub(super) bbox: (f64, f64, f64, f64),
    tree: Option<EdgeTree<'a>>,
}

/// Two regions are equal when their rings, and so their area, are: the scratch lent does not
/// count (it changes no answer).
impl PartialEq for PolygonRegion<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.points == other.points && self.ring_ends == other.ring_ends && self.area == other.area
    }
}

pub(super) fn ring_slices<'a>(points: &'a [Point<f64>], ends: &'a [usize]) -> impl Iterator<Item = &'a [Point<f64>]> + 'a {
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
    pub(super) fn checked(
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

    pub(super) fn ring_index(&self) -> Rings<'a> {
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

    pub(super) fn edges_s<S: Scalar>(&self) -> impl Iterator<Item = (Point<S>, Point<S>)> + 'a {
        self.rings().flat_map(edges).map(|(a, b)| (conv(a), conv(b)))
    }

    /// The box of every vertex (min x, min y, max x, max y).
    pub(crate) fn bounds(&self) -> tree::Bbox {
        self.bbox
    }

    /// Calls `edge` with the ends of every edge in the tree's nodes whose box `enter`
    /// accepts (of every edge, without a tree) and whether it starts its ring, until `edge`
    /// returns true (then returns true). Whatever the scalar: the caller's pruning proves
    /// itself ([`crate::Motif`]'s tests bound their own rounding).
    pub(crate) fn walk_edges(
        &self,
        enter: impl FnMut(tree::Bbox) -> bool,
        mut edge: impl FnMut(Point<f64>, Point<f64>, bool) -> bool,
    ) -> bool {
        if let Some(t) = &self.tree {
            let rings = self.ring_index();
            return t.walk(enter, |k| {
                let (a, b) = rings.edge(k);
                edge(a, b, t.is_start(k))
            });
        }
        self.rings()
            .any(|ring| edges(ring).enumerate().any(|(k, (a, b))| edge(a, b, k == 0)))
    }

    /// Calls `pair` with the ends of a pair of edges, one of this outline (with whether it
    /// starts its ring) and one of `other`, for every pair of the two trees' nodes that `enter`
    /// accepts (for every pair without both trees), until `pair` returns true.
    pub(crate) fn walk_edge_pairs(
        &self,
        other: &PolygonRegion<'_>,
        enter: impl FnMut(tree::Bbox, tree::Bbox) -> bool,
        mut pair: impl FnMut((Point<f64>, Point<f64>), (Point<f64>, Point<f64>)) -> bool,
    ) -> bool {
        if let (Some(ta), Some(tb)) = (&self.tree, &other.tree) {
            let (ra, rb) = (self.ring_index(), other.ring_index());
            return ta.walk_pairs(tb, enter, |i, j| pair(ra.edge(i), rb.edge(j)));
        }
        self.rings()
            .any(|r| edges(r).any(|ea| other.rings().any(|q| edges(q).any(|eb| pair(ea, eb)))))
    }

    /// [`Region::signed_clearance`] of the polygon: its edges' distance rounded up inside,
    /// down outside. On `f64` (the only scalar the tree serves) the rounded-up distance is
    /// the plain one, so the tree's nearest edge gives it.
    pub(super) fn signed_clearance<S: Scalar>(&self, q: Point<S>) -> S {
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
    pub(super) fn tree_for<S: Scalar>(&self) -> Option<&EdgeTree<'a>> {
        self.tree.as_ref().filter(|_| S::IS_F64)
    }

    /// Even-odd: the parity of the edges [`ray_crosses`] counts from `p`.
    pub(crate) fn inside<S: Scalar>(&self, p: Point<S>) -> bool {
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
    pub(super) fn clear_of<S: Scalar>(&self, c: Point<S>, r2: S) -> bool {
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
    pub(crate) fn dist2<S: Scalar>(&self, q: Point<S>) -> S {
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
    pub(super) fn clear_of_poly<S: Scalar>(&self, vs: &[Point<S>], gap: S) -> bool {
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
        self.all_edges_clear(sb, reach + m, edge_clear, ring_clear)
    }

    /// Whether every edge of the region passes `edge_clear` and the first vertex of every
    /// ring passes `ring_clear`, where neither can fail for an edge whose box keeps `wide`
    /// from the box `sb`: the edge tree skips those.
    fn all_edges_clear<S: Scalar>(
        &self,
        sb: [S; 4],
        wide: S,
        edge_clear: impl Fn(Point<S>, Point<S>) -> bool,
        ring_clear: impl Fn(Point<S>) -> bool,
    ) -> bool {
        if let Some(t) = self.tree_for::<S>() {
            let rings = self.ring_index();
            let f = |v: S| v.to_f64();
            let sbf = (f(sb[0]), f(sb[1]), f(sb[2]), f(sb[3]));
            let wide = f(wide);
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

impl PolygonRegion<'_> {
    /// Whether a motif placed by `f` lies inside the region with `gap` to every edge: the
    /// first vertex of each of its rings inside, no edge near (as [`PolygonRegion::clear_of_poly`]
    /// asks of a polygon) and no ring of the region in its material. Its bounding disc clear
    /// of every edge, about a centre inside, answers first (it never changes the answer).
    pub(super) fn holds_motif<S: Scalar>(&self, m: &Motif<'_>, f: &Frame<S>, gap: S) -> bool {
        let reach = m.reach_from(f, f.t) + gap;
        if self.inside(f.t) && self.clear_of(f.t, reach * reach) {
            return true;
        }
        m.ring_starts(f).all(|v| self.inside(v)) && self.clear_of_motif(m, f, gap)
    }

    #[inline(never)]
    fn clear_of_motif<S: Scalar>(&self, m: &Motif<'_>, f: &Frame<S>, gap: S) -> bool {
        let sb = m.world_box(f);
        let big = sb.iter().fold(S::ONE.max(S::from_f64(scale_of(self.bbox))), |m, &v| m.max(v.abs()));
        let mm = big * S::from_f64(1e-9);
        let reach = gap.max(S::ZERO) + mm;
        let edge_clear = |a: Point<S>, b: Point<S>| {
            let eb = seg_box(a, b);
            !boxes_meet(eb, sb, reach)
                || !m.edges_near(f, eb, reach, |c, d, _| {
                    boxes_meet(eb, seg_box(c, d), reach) && pair_near(a, b, c, d, gap)
                })
        };
        let ring_clear = |q: Point<S>| !(in_box(q, sb, mm) && m.holds(f, q));
        // Wider than both tests above: a box outside it holds no edge either looks at.
        self.all_edges_clear(sb, reach + mm, edge_clear, ring_clear)
    }
}

/// The largest coordinate magnitude in a box, at least 1 (it sets the margins of the box
/// tests).
pub(super) fn scale_of(b: (f64, f64, f64, f64)) -> f64 {
    1.0f64.max(b.0.abs()).max(b.1.abs()).max(b.2.abs()).max(b.3.abs())
}

#[inline]
pub(super) fn conv<S: Scalar>(p: Point<f64>) -> Point<S> {
    Point::new(S::from_f64(p.x), S::from_f64(p.y))
}
