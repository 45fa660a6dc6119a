//! Motifs: the caller's own outlines as shapes (an SVG's filled paths, a font's glyphs).
//!
//! A [`Motif`] is a polygon with holes over caller-owned vertices: one or more simple rings
//! that do not cross, filled by the even-odd rule, of up to [`MAX_MOTIF_VERTICES`] vertices.
//! [`Motif::new_in`] moves the vertices in place so that the outline has area 1 and its
//! reference point (the shape's centre when placed) is the origin, and builds the edge tree a
//! polygon region builds, in scratch the caller lends. The reference point is the centre of a
//! large inscribed disc, found by a fixed search, so that the disc lies in the material: the
//! cell sampler's bounds and the engine's shortcut between two shapes whose inscribed discs
//! meet use it, and smaller shapes may still go into the motif's holes.
//!
//! A placed motif is [`Geo::Motif`]: the outline and a [`Frame`], the map `t + M p` of the
//! unit outline into the region (`M` a scaled rotation, or its mirror image under a wallpaper
//! group's reflection). Its vertices are computed in the scalar's arithmetic whenever a test
//! or a drawing asks for them ([`Motif::rings_at`]), the same way each time, so the outline
//! that is drawn is the outline that was tested.
//!
//! ## The exact tests
//!
//! Two outlines are separated by more than `gap` when no edge of one comes within `gap` of an
//! edge of the other and neither holds a ring of the other: with no edges that near, every
//! ring lies wholly inside or wholly outside the other shape's material, so one vertex of
//! each ring tells (a shape in a motif's hole is outside its material). As for two built-in
//! polygons, a pair of edges is tested exactly when their boxes come within `gap + m` of
//! each other, `m` being 10^-9 of the largest coordinate in play; farther pairs are never
//! near, and skipping them is part of the test (the floating-point segment test can call
//! four nearly collinear points far apart a crossing).
//!
//! The edge tree finds those pairs without visiting the others. Its nodes' boxes are in the
//! motif's own frame; a node is skipped when the box of the node's box as the frame maps it
//! (half widths `|m00| hx + |m01| hy` and `|m10| hx + |m11| hy` about the mapped centre),
//! grown by the frame's rounding (a relative 10^-9, or a hundred times the scalar's
//! [`Scalar::OUTLINE_SLACK`], and sixteen times its absolute part), lies farther than
//! `gap + m` from the box asked about: every edge inside lies farther still.
//!
//! Before any edge, two motifs compare their inner covers ([`Motif::cover`]): up to
//! [`COVER_DISCS`] discs in each material. Two discs that come within `gap` by far more than
//! any rounding (a relative 10^-6, 10^-9, and twice both frames' slack) show that the
//! materials do, which the edges would show too: the shortcut never changes an answer, and
//! most rejected candidates of a crowded fill end there instead of in the walk. The pairs
//! tested, and so every answer, are the same with or without a tree ([`Motif::new`] lends
//! none), on every scalar; the ray test of the even-odd rule skips nodes wholly left of,
//! above, or at or below the point in the same way.

use super::motif_search::{cover, pole};
use crate::geom::{boxes_meet, in_box, point_in_poly, ray_crosses, seg_box, seg_dist2, seg_seg_dist2, segments_intersect, Point};
use crate::region::{PolygonRegion, RegionError};
use crate::scalar::Scalar;

/// Most vertices a motif may have, all rings together.
pub const MAX_MOTIF_VERTICES: usize = 65_536;

/// Most discs in a motif's inner cover ([`Motif::cover`]).
pub const COVER_DISCS: usize = 32;

/// What is wrong with a motif's outline ([`Motif::new_in`]).
///
/// # Examples
///
/// ```
/// use zetafill::{Motif, MotifError, Point, RegionError};
///
/// let p = Point::new;
/// let mut bow_tie = [p(0.0, 0.0), p(10.0, 10.0), p(10.0, 0.0), p(0.0, 10.0)];
/// let e = Motif::new(&mut bow_tie, &[4]).err();
/// assert_eq!(e, Some(MotifError::Outline(RegionError::SelfIntersecting)));
/// assert_eq!(e.map(|e| e.to_string()).as_deref(), Some("the outline crosses itself (or two outlines meet)"));
/// let mut many = vec![p(0.0, 0.0); zetafill::MAX_MOTIF_VERTICES + 1];
/// let ends = [many.len()];
/// assert_eq!(Motif::new(&mut many, &ends).err(), Some(MotifError::TooManyVertices));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum MotifError {
    /// The rings are not a valid polygon with holes (the reason is the region's).
    Outline(RegionError),
    /// More than [`MAX_MOTIF_VERTICES`] vertices.
    TooManyVertices,
    /// No point of the material was found with room about it (a sliver thinner than the
    /// search resolves).
    NoInterior,
}

impl core::fmt::Display for MotifError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            MotifError::Outline(e) => e.fmt(f),
            MotifError::TooManyVertices => write!(f, "the outline has more than {MAX_MOTIF_VERTICES} vertices"),
            MotifError::NoInterior => f.write_str("the outline has no room inside it (it is thinner than 1e-6 of its size)"),
        }
    }
}

impl core::error::Error for MotifError {}

impl From<RegionError> for MotifError {
    fn from(e: RegionError) -> Self {
        MotifError::Outline(e)
    }
}

/// A motif: the unit outline of a shape of the caller's own (area 1, reference point at the
/// origin), with its edge tree. See the module documentation.
///
/// # Examples
///
/// A square frame (a square with a square hole) becomes a motif of area 1; placed, it keeps a
/// disc out of its material but holds one in its hole.
///
/// ```
/// use zetafill::internals::geom::separated;
/// use zetafill::{Geo, Motif, Point};
///
/// let p = Point::new;
/// let mut frame = vec![
///     p(0.0, 0.0), p(10.0, 0.0), p(10.0, 10.0), p(0.0, 10.0),
///     p(3.0, 3.0), p(7.0, 3.0), p(7.0, 7.0), p(3.0, 7.0),
/// ];
/// let ends = [4, 8];
/// let mut scratch = vec![0u32; Motif::scratch_words(frame.len())];
/// let motif = Motif::new_in(&mut frame, &ends, &mut scratch)?;
/// assert!((motif.area() - 1.0).abs() < 1e-12);
/// // Its reference point lies in a corner of the frame, where a disc of radius
/// // 3 sqrt(2) / (1 + sqrt(2)) (about 1.757) touches two sides and the hole's corner.
/// let best = 3.0 * 2f64.sqrt() / (1.0 + 2f64.sqrt());
/// assert!((motif.inner() * 84f64.sqrt() - best).abs() < 1e-5);
/// let hole = motif.to_unit(p(5.0, 5.0));
///
/// let motifs = [motif];
/// let kind = motifs[0].kind(0);
/// let at = p(50.0, 50.0);
/// let scale = kind.scale_for_area(84.0); // the frame's own size again
/// let g: Geo<f64> = kind.geo_in(&motifs, at, scale, 0.0);
/// assert!((g.poly_area2() / 2.0 - 84.0).abs() < 1e-9);
/// // The hole's centre, placed: a disc of radius 1.9 fits, 2.1 does not.
/// let hole = p(50.0 + hole.x * scale, 50.0 + hole.y * scale);
/// assert!(separated(&g, &Geo::Circle { c: hole, r: 1.9 }, 0.0));
/// assert!(!separated(&g, &Geo::Circle { c: hole, r: 2.1 }, 0.0));
/// assert!(!separated(&g, &Geo::Circle { c: hole, r: 1.9 }, 0.2));
/// # Ok::<(), zetafill::MotifError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motif<'a> {
    outline: PolygonRegion<'a>,
    bound: f64,
    inner: f64,
    /// The reference point in the caller's coordinates, and the factor that scaled them.
    pole: Point<f64>,
    unit: f64,
    /// Discs in the material (centre and radius, in the unit outline's frame); the first
    /// `discs` are used.
    cover: [(Point<f64>, f64); COVER_DISCS],
    discs: u8,
}

impl<'a> Motif<'a> {
    /// A motif from rings given as `points` split at the exclusive indices `ring_ends` (as
    /// [`PolygonRegion::new`] takes them), with no scratch: every test visits every edge. For
    /// outlines of a few dozen vertices; [`Motif::new_in`] gives the same answers faster.
    /// The points are moved in place (see [`Motif::new_in`]).
    pub fn new(points: &'a mut [Point<f64>], ring_ends: &'a [usize]) -> Result<Self, MotifError> {
        Self::build(points, ring_ends, None)
    }

    /// A motif from rings as [`Motif::new`] takes them, with an edge tree in `scratch`
    /// ([`Motif::scratch_words`] words; fewer give larger leaves, never another answer).
    ///
    /// The points are moved in place: translated so that the reference point is the origin
    /// and scaled so that the outline's area (holes excluded) is 1. The reference point is
    /// the best centre of an inscribed disc found on a 48 x 48 grid over the outline's box
    /// (and just inside the middle of every edge, for slender outlines), refined by a pattern
    /// search; the search is fixed, so a motif is the same on every target.
    pub fn new_in(points: &'a mut [Point<f64>], ring_ends: &'a [usize], scratch: &'a mut [u32]) -> Result<Self, MotifError> {
        Self::build(points, ring_ends, Some(scratch))
    }

    fn build(points: &'a mut [Point<f64>], ring_ends: &'a [usize], scratch: Option<&'a mut [u32]>) -> Result<Self, MotifError> {
        if points.len() > MAX_MOTIF_VERTICES {
            return Err(MotifError::TooManyVertices);
        }
        let mut scratch = scratch;
        let (area, pole) = {
            let raw = match scratch.as_deref_mut() {
                Some(s) => PolygonRegion::new_in(&*points, ring_ends, s)?,
                None => PolygonRegion::new(&*points, ring_ends)?,
            };
            (raw.area(), pole(&raw).ok_or(MotifError::NoInterior)?)
        };
        let k = 1.0 / crate::scalar::sqrtf(area);
        for p in points.iter_mut() {
            *p = Point::new((p.x - pole.x) * k, (p.y - pole.y) * k);
        }
        let points: &'a [Point<f64>] = points;
        let outline = match scratch {
            Some(s) => PolygonRegion::new_in(points, ring_ends, s)?,
            None => PolygonRegion::new(points, ring_ends)?,
        };
        let origin = Point::new(0.0, 0.0);
        if !outline.inside(origin) {
            return Err(MotifError::NoInterior);
        }
        let inner = crate::scalar::sqrtf(outline.dist2(origin)) * (1.0 - 1e-6);
        let far = points.iter().fold(0.0f64, |m, p| m.max(p.dist2(origin)));
        let bound = crate::scalar::sqrtf(far) * (1.0 + 1e-12);
        if inner.is_nan() || inner <= bound * 1e-6 {
            return Err(MotifError::NoInterior);
        }
        let (cover, discs) = cover(&outline, inner);
        Ok(Motif {
            outline,
            bound,
            inner,
            pole,
            unit: k,
            cover,
            discs,
        })
    }

    /// The words of scratch [`Motif::new_in`] needs for `vertices` vertices (as
    /// [`PolygonRegion::scratch_words`]).
    pub const fn scratch_words(vertices: usize) -> usize {
        PolygonRegion::scratch_words(vertices)
    }

    /// The shape kind of this motif, numbered `id` in the table of motifs an engine is given
    /// ([`crate::Engine::with_motifs`]): the table's entry `id` must be this motif.
    pub fn kind(&self, id: u8) -> crate::ShapeKind {
        crate::ShapeKind::Motif {
            id,
            area: self.area(),
            bound: self.bound,
            inner: self.inner,
        }
    }

    /// Where a point given in the outline's original coordinates lies in the unit outline's
    /// (the map [`Motif::new_in`] moved the vertices by): for what is drawn with a motif but
    /// not tested, such as a butterfly's antennas.
    pub fn to_unit(&self, p: Point<f64>) -> Point<f64> {
        Point::new((p.x - self.pole.x) * self.unit, (p.y - self.pole.y) * self.unit)
    }

    /// The unit outline (area 1, reference point at the origin) as a polygon region.
    pub fn outline(&self) -> &PolygonRegion<'a> {
        &self.outline
    }

    /// The unit outline's area (1 up to rounding).
    pub fn area(&self) -> f64 {
        self.outline.area()
    }

    /// The distance from the reference point to the farthest vertex (grown by 10^-12).
    pub fn bound(&self) -> f64 {
        self.bound
    }

    /// The radius of a disc about the reference point inside the material (the distance to
    /// the nearest edge, less 10^-6 of it).
    pub fn inner(&self) -> f64 {
        self.inner
    }

    /// The inner cover: up to [`COVER_DISCS`] discs in the material of the unit outline
    /// (centre and radius), the inscribed disc about the reference point first. Two placed
    /// motifs with discs that meet by far more than any rounding overlap, which the exact test
    /// would find only after walking their edges; so the test looks at the discs first (the
    /// answer is the same).
    pub fn cover(&self) -> &[(Point<f64>, f64)] {
        self.cover.get(..usize::from(self.discs)).unwrap_or(&[])
    }

    /// Vertices, all rings together.
    pub fn vertices(&self) -> usize {
        self.outline.points().len()
    }

    /// The rings placed by `f`: each ring's vertices as a test sees them.
    pub fn rings_at<'s, S: Scalar>(&'s self, f: &'s Frame<S>) -> impl Iterator<Item = impl Iterator<Item = Point<S>> + 's> + 's {
        // (None without the `motif` feature: nothing that draws a motif is linked.)
        self.outline
            .rings()
            .filter(|_| crate::geom::MOTIFS)
            .map(move |ring| ring.iter().map(move |&p| f.apply(p)))
    }

    /// The box holding every vertex placed by `f` (a disc's box: cheap and never smaller).
    pub(crate) fn world_box<S: Scalar>(&self, f: &Frame<S>) -> [S; 4] {
        let e = f.norm * S::from_f64(self.bound) + slack(self, f);
        [f.t.x - e, f.t.y - e, f.t.x + e, f.t.y + e]
    }

    /// Calls `visit` with the placed ends of every edge that may lie within `reach` of the
    /// box `b`, and whether it starts its ring (see the module documentation), until `visit`
    /// returns true (then returns true).
    pub(crate) fn edges_near<S: Scalar>(
        &self,
        f: &Frame<S>,
        b: [S; 4],
        reach: S,
        mut visit: impl FnMut(Point<S>, Point<S>, bool) -> bool,
    ) -> bool {
        let s = slack(self, f);
        self.outline.walk_edges(
            |n| boxes_meet(node_box(f, n, s), b, reach),
            |p, q, first| visit(f.apply(p), f.apply(q), first),
        )
    }

    /// The first vertex of each ring, placed by `f`.
    pub(crate) fn ring_starts<'s, S: Scalar>(&'s self, f: &'s Frame<S>) -> impl Iterator<Item = Point<S>> + 's {
        self.outline.rings().filter_map(move |r| r.first().map(|&p| f.apply(p)))
    }

    /// Whether `q` lies in the material placed by `f` (the even-odd parity of the placed edges
    /// [`ray_crosses`] counts; points on the outline may go either way).
    pub(crate) fn holds<S: Scalar>(&self, f: &Frame<S>, q: Point<S>) -> bool {
        let s = slack(self, f);
        let mut odd = false;
        self.outline.walk_edges(
            |n| {
                let [_, y0, x1, y1] = node_box(f, n, s);
                // Wholly left of q, above it, or at or below it: no edge inside crosses.
                !(x1 <= q.x || y0 > q.y || y1 <= q.y)
            },
            |a, b, _| {
                odd ^= ray_crosses(q, f.apply(a), f.apply(b));
                false
            },
        );
        odd
    }

    /// Whether the motif placed by `f` keeps more than `gap` from the disc (`c`, `r`).
    #[inline(never)]
    pub(crate) fn clear_of_disc<S: Scalar>(&self, f: &Frame<S>, c: Point<S>, r: S, gap: S) -> bool {
        if self.holds(f, c) {
            return false;
        }
        let reach = r + gap.max(S::ZERO);
        let m = margin(&[self.world_box(f), [c.x, c.y, c.x, c.y]]);
        let at = [c.x, c.y, c.x, c.y];
        !self.edges_near(f, at, reach + m, |a, b, _| {
            boxes_meet(seg_box(a, b), at, reach + m) && seg_dist2(c, a, b) <= reach * reach
        })
    }

    /// Whether the motif placed by `f` keeps more than `gap` from the simple polygon `vs`.
    #[inline(never)]
    pub(crate) fn clear_of_poly<S: Scalar>(&self, f: &Frame<S>, vs: &[Point<S>], convex: bool, gap: S) -> bool {
        let (mb, pb) = (self.world_box(f), crate::geom::vbox(vs));
        let m = margin(&[mb, pb]);
        let reach = gap.max(S::ZERO) + m;
        if !boxes_meet(mb, pb, reach) {
            return true;
        }
        let both = [mb[0].max(pb[0]), mb[1].max(pb[1]), mb[2].min(pb[2]), mb[3].min(pb[3])];
        for (p1, p2) in crate::geom::edges(vs) {
            let eb = seg_box(p1, p2);
            if boxes_meet(eb, both, reach)
                && self.edges_near(f, eb, reach, |a, b, _| {
                    boxes_meet(seg_box(a, b), eb, reach) && pair_near(a, b, p1, p2, gap)
                })
            {
                return false;
            }
        }
        let in_vs = |v: Point<S>| {
            in_box(v, pb, m)
                && if convex {
                    crate::geom::edges(vs).all(|(a, b)| b.diff(a).cross(v.diff(a)) >= S::ZERO)
                } else {
                    point_in_poly(v, vs)
                }
        };
        !(vs.first().is_some_and(|&v| in_box(v, mb, m) && self.holds(f, v)) || self.ring_starts(f).any(in_vs))
    }

    /// Whether the motif placed by `f` keeps more than `gap` from motif `o` placed by `g`.
    #[inline(never)]
    pub(crate) fn clear_of_motif<S: Scalar>(&self, f: &Frame<S>, o: &Motif<'_>, g: &Frame<S>, gap: S) -> bool {
        let (ba, bb) = (self.world_box(f), o.world_box(g));
        let m = margin(&[ba, bb]);
        let reach = gap.max(S::ZERO) + m;
        if !boxes_meet(ba, bb, reach) {
            return true;
        }
        if self.covers_meet(f, o, g, gap) {
            return false;
        }
        // Each reference point lies in its own motif's material (the centre of an inscribed
        // disc): one in the other's material is an overlap, found by one ray, where the walk
        // below would find no near edge in a motif wholly inside the other's material and
        // come to the same answer by a ring's first vertex only after visiting every pair.
        if (in_box(f.t, bb, m) && o.holds(g, f.t)) || (in_box(g.t, ba, m) && self.holds(f, g.t)) {
            return false;
        }
        // Only edges near both boxes can come near each other; the two trees are walked
        // together, each pair of nodes kept while their placed boxes come within reach.
        let both = [ba[0].max(bb[0]), ba[1].max(bb[1]), ba[2].min(bb[2]), ba[3].min(bb[3])];
        let (sa, sb) = (slack(self, f), slack(o, g));
        crate::counters::walk();
        let hit = self.outline.walk_edge_pairs(
            &o.outline,
            |na, nb| {
                let (wa, wb) = (node_box(f, na, sa), node_box(g, nb, sb));
                boxes_meet(wa, both, reach) && boxes_meet(wb, both, reach) && boxes_meet(wa, wb, reach)
            },
            |(a1, a2), (b1, b2)| {
                let (a1, a2, b1, b2) = (f.apply(a1), f.apply(a2), g.apply(b1), g.apply(b2));
                let ea = seg_box(a1, a2);
                boxes_meet(ea, seg_box(b1, b2), reach) && pair_near(a1, a2, b1, b2, gap)
            },
        );
        if hit {
            return false;
        }
        !(self.ring_starts(f).any(|v| in_box(v, bb, m) && o.holds(g, v)) || o.ring_starts(g).any(|v| in_box(v, ba, m) && self.holds(f, v)))
    }

    /// Whether a disc of this motif's cover placed by `f` comes within `gap` of one of `o`'s
    /// placed by `g` by far more than any rounding: then the two materials come within `gap`
    /// (each disc lies in its material; the placed vertices and centres lie within the
    /// frames' slack of where the exact maps put them), and the exact test finds it.
    fn covers_meet<S: Scalar>(&self, f: &Frame<S>, o: &Motif<'_>, g: &Frame<S>, gap: S) -> bool {
        let slop = slack(self, f) + slack(o, g);
        let slop = slop + slop;
        let gap = gap.max(S::ZERO);
        // `o`'s discs that reach this motif's bounding disc, placed once.
        let mut theirs: heapless::Vec<(Point<S>, S), COVER_DISCS> = heapless::Vec::new();
        let mine = f.norm * S::from_f64(self.bound);
        for &(c, r) in o.cover() {
            let (c, r) = (g.apply(c), g.norm * S::from_f64(r));
            let lim = mine + r + gap;
            if c.dist2(f.t) < lim * lim {
                let _ = theirs.push((c, r));
            }
        }
        if theirs.is_empty() {
            return false;
        }
        let keep = S::from_f64(1.0 - 1e-6);
        let tiny = S::from_f64(1e-9);
        self.cover().iter().any(|&(c, r)| {
            let (c, r) = (f.apply(c), f.norm * S::from_f64(r));
            theirs.iter().any(|&(d, s)| {
                let contact = (r + s + gap) * keep - tiny - slop;
                contact > S::ZERO && c.dist2(d) < contact * contact
            })
        })
    }

    /// A distance from `c` no vertex placed by `f` lies beyond.
    pub(crate) fn reach_from<S: Scalar>(&self, f: &Frame<S>, c: Point<S>) -> S {
        let d = f.t.diff(c);
        S::dist2_up(d.x, d.y).sqrt() + f.norm * S::from_f64(self.bound) + slack(self, f)
    }

    /// Whether every vertex placed by `f` lies within `room` of `c` (strictly): the shortcut
    /// of the bounding disc first, which never changes the answer.
    pub(crate) fn within<S: Scalar>(&self, f: &Frame<S>, c: Point<S>, room: S) -> bool {
        if self.reach_from(f, c) < room {
            return true;
        }
        let r2 = room * room;
        self.rings_at(f).all(|mut ring| ring.all(|v| v.dist2(c) < r2))
    }

    /// Twice the area of the outline placed by `f` (holes subtracted).
    pub(crate) fn area2_at<S: Scalar>(&self, f: &Frame<S>) -> S {
        let mut total = S::ZERO;
        for (k, ring) in self.outline.rings().enumerate() {
            let mut a = S::ZERO;
            let n = ring.len();
            for i in 0..n {
                let (Some(&p), Some(&q)) = (ring.get(i), ring.get((i + 1) % n)) else {
                    continue;
                };
                a = a + f.apply(p).cross(f.apply(q));
            }
            let a = a.abs();
            total = if self.outline.is_hole(k) { total - a } else { total + a };
        }
        total
    }
}

/// Whether two edges come within `gap` (share a point, with no gap).
#[inline]
pub(crate) fn pair_near<S: Scalar>(a1: Point<S>, a2: Point<S>, b1: Point<S>, b2: Point<S>, gap: S) -> bool {
    if gap <= S::ZERO {
        segments_intersect(a1, a2, b1, b2)
    } else {
        seg_seg_dist2(a1, a2, b1, b2) <= gap * gap
    }
}

/// `m` of the module documentation: 10^-9 of the largest coordinate of the boxes (at least 1).
fn margin<S: Scalar>(boxes: &[[S; 4]]) -> S {
    boxes.iter().flatten().fold(S::ONE, |m, &v| m.max(v.abs())) * S::from_f64(1e-9)
}

/// How far a placed vertex may lie from where the frame's exact map puts it.
fn slack<S: Scalar>(m: &Motif<'_>, f: &Frame<S>) -> S {
    let [rel, abs] = S::OUTLINE_SLACK;
    let size = f.t.x.abs().max(f.t.y.abs()) + f.norm * S::from_f64(m.bound);
    size * S::from_f64(1e-9 + 100.0 * rel) + S::from_f64(16.0 * abs)
}

/// The box, in the region's frame, about a node's box `n` of the unit outline: the box of the
/// node's box as the frame's matrix maps it (half widths `|m00| hx + |m01| hy` and
/// `|m10| hx + |m11| hy` about the mapped centre), grown by `s`.
fn node_box<S: Scalar>(f: &Frame<S>, n: (f64, f64, f64, f64), s: S) -> [S; 4] {
    let c = Point::new(0.5 * (n.0 + n.2), 0.5 * (n.1 + n.3));
    let grow = 1.0 + 1e-12;
    let (hx, hy) = (S::from_f64(0.5 * (n.2 - n.0) * grow), S::from_f64(0.5 * (n.3 - n.1) * grow));
    let [m00, m01, m10, m11] = f.m;
    let w = f.apply(c);
    let (ex, ey) = (m00.abs() * hx + m01.abs() * hy + s, m10.abs() * hx + m11.abs() * hy + s);
    [w.x - ex, w.y - ey, w.x + ex, w.y + ey]
}

/// Where a motif's unit outline goes: `t + M p` for each of its points `p`, computed in the
/// scalar's arithmetic (`M` a scaled rotation, or a reflection of one).
///
/// # Examples
///
/// ```
/// use zetafill::{Frame, Point};
///
/// // Scale 2, a quarter turn, centred at (10, 0): (1, 0) goes to (10, 2).
/// let f = Frame::new(Point::new(10.0, 0.0), 2.0, 1.0, 0.0);
/// assert_eq!(f.apply(Point::new(1.0, 0.0)), Point::new(10.0, 2.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<S> {
    /// Where the reference point goes (the shape's centre).
    pub t: Point<S>,
    /// The matrix, row by row: `[m00, m01, m10, m11]`.
    pub m: [S; 4],
    /// The scale: how far the matrix stretches a unit vector.
    pub norm: S,
}

impl<S: Scalar> Frame<S> {
    /// Centred at `c`, scaled by `scale`, turned by the angle whose sine and cosine are given.
    pub fn new(c: Point<S>, scale: S, sin: S, cos: S) -> Self {
        let (a, b) = (scale * cos, scale * sin);
        Frame {
            t: c,
            m: [a, S::ZERO - b, b, a],
            norm: scale,
        }
    }

    /// Where the point `p` of the unit outline goes.
    #[inline]
    pub fn apply(&self, p: Point<f64>) -> Point<S> {
        let (x, y) = (S::from_f64(p.x), S::from_f64(p.y));
        let [m00, m01, m10, m11] = self.m;
        Point::new(self.t.x + (m00 * x + m01 * y), self.t.y + (m10 * x + m11 * y))
    }

    /// The frame followed by the isometry `v -> centre + R (v - t)` (`r` its matrix, row by
    /// row): a wallpaper group's image.
    pub fn then(&self, r: [S; 4], centre: Point<S>) -> Self {
        let [a, b, c, d] = self.m;
        let [r00, r01, r10, r11] = r;
        Frame {
            t: centre,
            m: [r00 * a + r01 * c, r00 * b + r01 * d, r10 * a + r11 * c, r10 * b + r11 * d],
            norm: self.norm,
        }
    }
}
