//! The shapes that can be placed: how area maps to scale, bounding and inscribed radii, and
//! the concrete [`Geo`] that is both tested and drawn.
//!
//! A placed shape is stored compactly as [`Placed`]: centre, scale and angle (32 bytes with
//! `f64`). Its kind is not stored: the engine knows it from the placement index (see
//! [`ShapeList`]). The scale is, per kind:
//! - circle, ring: the (outer) radius;
//! - square, rectangle: the half height (the half width is `aspect` times it);
//! - triangle, regular polygon, star, blob: the circumradius (for a blob, the base radius R
//!   of eq. 9, chosen per trial so that the polygon's area is exactly the area asked for).
//!
//! Polygons and stars point up when unrotated (their first vertex at 90°). Curved outlines
//! are never approximated: circles and rings are tested as true circles; a blob *is* its
//! polygon of [`BLOB_VERTICES`] vertices (tested and drawn alike).

mod blob;
mod list;
mod motif;
mod motif_search;

pub use list::{mix64, MixOrder, ShapeList};
pub(crate) use motif::pair_near;
pub use motif::{Frame, Motif, MotifError, COVER_DISCS, MAX_MOTIF_VERTICES};

use crate::geom::{Geo, Point, Verts, MAX_VERTS};
use crate::scalar::Scalar;
use blob::{blob_unit, noisy_unit};

/// Vertices of a blob's polygon.
pub const BLOB_VERTICES: usize = 32;
const _: () = assert!(BLOB_VERTICES <= MAX_VERTS, "a blob must fit a polygon's vertex list");

/// Most shapes in a mix: 32 with the `motif` feature (a word's letters, each a motif), 8
/// without (a mix of the built-in kinds, in a smaller list).
///
/// # Examples
///
/// ```
/// use zetafill::{MixOrder, ShapeKind, ShapeList, MAX_MIX};
///
/// assert!(ShapeList::mix(&[ShapeKind::Circle; MAX_MIX], MixOrder::Cycle, 0).is_some());
/// assert!(ShapeList::mix(&[ShapeKind::Circle; MAX_MIX + 1], MixOrder::Cycle, 0).is_none());
/// ```
pub const MAX_MIX: usize = if cfg!(feature = "motif") { 32 } else { 8 };

/// A kind of shape, with its fixed proportions. A fill places one kind, or a mix of them
/// ([`ShapeList`]); the kind maps area to scale and back, and gives the exact outline.
///
/// # Examples
///
/// ```
/// use zetafill::{Geo, Point, ShapeKind};
///
/// let star = ShapeKind::Star { points: 5, inner: 0.4 };
/// assert!(star.is_valid());
/// assert!(!ShapeKind::Star { points: 5, inner: 1.5 }.is_valid());
/// // Scale (a star's circumradius) and area are each other's inverse.
/// let scale = star.scale_for_area(50.0);
/// assert!((star.area_for_scale(scale) - 50.0).abs() < 1e-12);
/// // Its outline at a place and angle: 10 vertices, none beyond the bounding radius.
/// let centre = Point::new(20.0, 30.0);
/// let outline: Geo<f64> = star.geo(centre, scale, 0.3);
/// assert_eq!(outline.vertices().len(), 10);
/// let r = star.bounding_radius(scale);
/// assert!(outline.vertices().iter().all(|v| v.dist2(centre) <= r * r * (1.0 + 1e-12)));
/// // A ring is tested as two true circles, never a polygon.
/// let ring = ShapeKind::Ring { inner: 0.5 }.geo(centre, 4.0, 0.0);
/// assert_eq!(ring, Geo::Ring { c: centre, r: 4.0, inner: 2.0 });
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ShapeKind {
    /// A disc.
    Circle,
    /// A square.
    Square,
    /// A rectangle whose width is `aspect` times its height.
    Rect {
        /// Width over height, finite and > 0.
        aspect: f64,
    },
    /// An equilateral triangle.
    Triangle,
    /// A regular polygon.
    Polygon {
        /// Number of sides, 3..=32.
        sides: u8,
    },
    /// A star with `points` points; the inner vertices lie at `inner` times the outer radius.
    Star {
        /// Points, 2..=16.
        points: u8,
        /// Inner radius over outer radius, in (0, 1).
        inner: f64,
    },
    /// An annulus; its hole is free space where smaller shapes may be placed.
    Ring {
        /// Inner radius over outer radius, in (0, 1).
        inner: f64,
    },
    /// The irregular blob of eq. 9: r(θ) = R (1 + δ Σ_{j=2..4} cos(jθ + φ_j)), with new random
    /// phases φ_j at every trial.
    Blob {
        /// δ in [0, 1/3): r(θ) stays positive for every phase.
        delta: f64,
    },
    /// A blob whose radius follows periodic 1D noise: r(θ) = R (1 + a (2 g(θ) - 1)), with g
    /// Perlin gradient noise in [0, 1] that goes round the outline `features` times (its
    /// first octave) and is drawn anew at every trial.
    Noisy {
        /// a in [0, 0.9]: the radius stays within R (1 ± a).
        amplitude: f64,
        /// Lattice cells of the first octave around the outline, 2..=16.
        features: u8,
        /// Octaves, 1..=4, with `features << (octaves - 1)` at most 16 (two vertices a cell
        /// of the finest octave).
        octaves: u8,
    },
    /// The caller's own outline: entry `id` of the engine's table of motifs
    /// ([`crate::Engine::with_motifs`]), with the numbers every placement needs copied from
    /// it ([`Motif::kind`] gives them). The scale is the factor applied to the unit outline.
    Motif {
        /// The motif's place in the table.
        id: u8,
        /// The unit outline's area ([`Motif::area`]).
        area: f64,
        /// Its bounding radius about the reference point ([`Motif::bound`]).
        bound: f64,
        /// Its inscribed radius about the reference point ([`Motif::inner`]).
        inner: f64,
    },
}

/// A shape as stored by the engine. `Placed::default()` is an empty slot for storage.
///
/// Its kind is not stored: [`crate::Engine::kind_of`] gives it from the placement index, and
/// [`crate::Engine::geo`] gives the exact outline, the one that was tested.
///
/// # Examples
///
/// ```
/// use zetafill::{index_words, rng_from_seed, Engine, Geo, Params, Placed, Point, Region, ShapeKind, Stop, Storage};
///
/// let mut shapes = [Placed::<f64>::default(); 30];
/// let mut index = [0u32; index_words(30)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let params = Params { shape: ShapeKind::Square.into(), rotate: true, ..Params::circles(1.3, 1.0) };
/// let mut engine = Engine::new(params, region, storage)?;
/// engine.run(&mut rng_from_seed(8), &Stop { count: Some(30), ..Stop::default() }, |_| {});
/// for (i, p) in engine.placed().iter().enumerate() {
///     let Some(Geo::Poly { v, convex: true }) = engine.geo(i) else { panic!("a square is a convex polygon") };
///     // A square's scale is its half side: its corners lie scale * sqrt(2) from its centre.
///     let centre = Point::new(p.x, p.y);
///     assert_eq!(v.len(), 4);
///     let corner2 = 2.0 * p.scale * p.scale;
///     assert!(v.iter().all(|q| (q.dist2(centre) - corner2).abs() < 1e-12 * corner2));
///     // The outline has the area of the power law.
///     let area = engine.geo(i).map_or(0.0, |g| g.poly_area2() / 2.0);
///     assert!((area - engine.area_of(i as u64)).abs() < 1e-9 * area);
/// }
/// # Ok::<(), zetafill::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Placed<S> {
    /// Centre x.
    pub x: S,
    /// Centre y.
    pub y: S,
    /// Scale (see the module docs).
    pub scale: S,
    /// Rotation in radians, counter-clockwise (0 when unrotated). For a blob it also selects
    /// the phases φ_j.
    pub angle: S,
}

fn rot<S: Scalar>(p: Point<S>, s: S, c: S) -> Point<S> {
    Point::new(p.x * c - p.y * s, p.x * s + p.y * c)
}

impl ShapeKind {
    /// Whether the proportions are valid.
    pub fn is_valid(&self) -> bool {
        let unit_open = |v: f64| v.is_finite() && v > 0.0 && v < 1.0;
        match *self {
            ShapeKind::Rect { aspect } => aspect.is_finite() && aspect > 0.0,
            ShapeKind::Polygon { sides } => (3..=MAX_VERTS as u8).contains(&sides),
            ShapeKind::Star { points, inner } => (2..=(MAX_VERTS / 2) as u8).contains(&points) && unit_open(inner),
            ShapeKind::Ring { inner } => unit_open(inner),
            ShapeKind::Blob { delta } => delta.is_finite() && (0.0..1.0 / 3.0).contains(&delta),
            ShapeKind::Noisy {
                amplitude,
                features,
                octaves,
            } => {
                cfg!(feature = "noisy-blob")
                    && amplitude.is_finite()
                    && (0.0..=0.9).contains(&amplitude)
                    && (2..=16).contains(&features)
                    && (1..=4).contains(&octaves)
                    && u32::from(features) << (octaves - 1) <= 16
            }
            ShapeKind::Motif { area, bound, inner, .. } => {
                cfg!(feature = "motif")
                    && area.is_finite()
                    && area > 0.0
                    && bound.is_finite()
                    && inner.is_finite()
                    && inner > 0.0
                    && inner <= bound
            }
            ShapeKind::Circle | ShapeKind::Square | ShapeKind::Triangle => true,
        }
    }

    /// Whether rotating the shape changes it (and so whether `--rotate random` draws angles).
    pub fn rotates(&self) -> bool {
        !matches!(self, ShapeKind::Circle | ShapeKind::Ring { .. })
    }

    /// Whether the shape's polygon is convex.
    pub fn convex(&self) -> bool {
        !matches!(
            self,
            ShapeKind::Star { .. } | ShapeKind::Blob { .. } | ShapeKind::Noisy { .. } | ShapeKind::Motif { .. }
        )
    }

    /// Whether the outline is drawn anew at every trial from its angle (a blob or a noisy
    /// blob): its size is then known only through bounds before the trial.
    pub fn is_blob(&self) -> bool {
        matches!(self, ShapeKind::Blob { .. } | ShapeKind::Noisy { .. })
    }

    fn aspect(&self) -> f64 {
        match *self {
            ShapeKind::Rect { aspect } => aspect,
            _ => 1.0,
        }
    }

    fn sides(&self) -> usize {
        match *self {
            ShapeKind::Triangle => 3,
            ShapeKind::Polygon { sides } => usize::from(sides),
            ShapeKind::Star { points, .. } => 2 * usize::from(points),
            _ => 4,
        }
    }

    /// Area at scale 1 (for a blob: of the round blob, δ = 0; the true area depends on the
    /// phases and is met exactly by [`ShapeKind::scale_for`]).
    pub fn unit_area(&self) -> f64 {
        use core::f64::consts::PI;
        match *self {
            ShapeKind::Circle => PI,
            ShapeKind::Ring { inner } => PI * (1.0 - inner * inner),
            ShapeKind::Square | ShapeKind::Rect { .. } => 4.0 * self.aspect(),
            ShapeKind::Triangle | ShapeKind::Polygon { .. } | ShapeKind::Blob { .. } | ShapeKind::Noisy { .. } => {
                let n = if self.is_blob() { BLOB_VERTICES } else { self.sides() } as f64;
                0.5 * n * libm::sin(2.0 * PI / n)
            }
            ShapeKind::Star { points, inner } => f64::from(points) * inner * libm::sin(PI / f64::from(points)),
            ShapeKind::Motif { area, .. } => area,
        }
    }

    /// The scale for an area (blobs: of the round blob; see [`ShapeKind::scale_for`]).
    pub fn scale_for_area(&self, area: f64) -> f64 {
        crate::scalar::sqrtf(area / self.unit_area())
    }

    /// The area of the shape at a scale (blobs: of the round blob).
    pub fn area_for_scale(&self, scale: f64) -> f64 {
        self.unit_area() * scale * scale
    }

    /// The scale that gives exactly `area` for the shape drawn at `angle` (only blobs depend
    /// on the angle, through their phases).
    pub fn scale_for<S: Scalar>(&self, area: f64, angle: S) -> S {
        match *self {
            ShapeKind::Blob { .. } | ShapeKind::Noisy { .. } => {
                let (_, a2) = self.blob_outline(angle);
                S::from_f64(crate::scalar::sqrtf(2.0 * area / a2.to_f64()))
            }
            _ => S::from_f64(self.scale_for_area(area)),
        }
    }

    /// Radius of the smallest circle about the centre that holds the shape: for a polygon, as
    /// drawn in the scalar's arithmetic (grown by [`Scalar::OUTLINE_SLACK`]).
    pub fn bounding_radius<S: Scalar>(&self, scale: S) -> S {
        let r = match *self {
            ShapeKind::Circle | ShapeKind::Ring { .. } => return scale,
            ShapeKind::Square | ShapeKind::Rect { .. } => {
                let hw = scale * S::from_f64(self.aspect());
                (hw * hw + scale * scale).sqrt()
            }
            ShapeKind::Blob { delta } => scale * S::from_f64(1.0 + 3.0 * delta),
            ShapeKind::Noisy { amplitude, .. } => scale * S::from_f64(1.0 + amplitude),
            ShapeKind::Motif { bound, .. } => scale * S::from_f64(bound),
            _ => scale,
        };
        let [rel, abs] = S::OUTLINE_SLACK;
        if rel > 0.0 || abs > 0.0 {
            r + scale * S::from_f64(rel) + S::from_f64(abs)
        } else {
            r
        }
    }

    /// A radius of a circle about the centre that lies inside the shape's material or
    /// outline (a lower bound of the inscribed radius; for a ring, its outer radius, the disc
    /// it keeps others out of except for its hole).
    pub fn inradius<S: Scalar>(&self, scale: S) -> S {
        use core::f64::consts::PI;
        let f = match *self {
            ShapeKind::Circle | ShapeKind::Ring { .. } => 1.0,
            ShapeKind::Square | ShapeKind::Rect { .. } => self.aspect().min(1.0),
            ShapeKind::Triangle | ShapeKind::Polygon { .. } => libm::cos(PI / self.sides() as f64),
            ShapeKind::Star { points, inner } => {
                // Distance from the centre to the line through an outer and an inner vertex.
                let t = PI / f64::from(points);
                let (bx, by) = (inner * libm::cos(t), inner * libm::sin(t));
                let len = libm::sqrt((bx - 1.0) * (bx - 1.0) + by * by);
                (by / len).min(inner) * 0.999_999
            }
            ShapeKind::Blob { delta } => (1.0 - 3.0 * delta) * libm::cos(PI / BLOB_VERTICES as f64) * 0.999_999,
            // Every vertex lies at least (1 - a) from the centre, and an edge spans 2 pi / n,
            // so every point of an edge lies at least (1 - a) cos(pi / n) from it.
            ShapeKind::Noisy { amplitude, .. } => (1.0 - amplitude) * libm::cos(PI / BLOB_VERTICES as f64) * 0.999_999,
            // Already a lower bound, by 1e-6 of it (the drawn outline's rounding is far below).
            ShapeKind::Motif { inner, .. } => inner,
        };
        scale * S::from_f64(f)
    }

    /// The radius of a disc about the centre that lies inside the shape's material (its
    /// inscribed disc, see [`ShapeKind::inradius`]), for the kinds where it is tight:
    /// circles, squares, rectangles, regular polygons and motifs (whose reference point is
    /// chosen for it). None for the others (a ring's centre is in its hole; a star's or a
    /// blob's disc is loose and dearer to compute).
    pub fn solid_radius<S: Scalar>(&self, scale: S) -> Option<S> {
        match self {
            ShapeKind::Circle
            | ShapeKind::Square
            | ShapeKind::Rect { .. }
            | ShapeKind::Triangle
            | ShapeKind::Polygon { .. }
            | ShapeKind::Motif { .. } => Some(self.inradius(scale)),
            _ => None,
        }
    }

    /// The narrowest width of the shape (what `--min-size` compares against): a ring's band,
    /// otherwise twice the inscribed radius.
    pub fn min_width(&self, scale: f64) -> f64 {
        match *self {
            ShapeKind::Ring { inner } => scale * (1.0 - inner),
            _ => 2.0 * self.inradius(scale),
        }
    }

    /// The sine and cosine the shape uses for an angle (exactly 0 and 1 for angle 0).
    pub fn sin_cos<S: Scalar>(angle: S) -> (S, S) {
        if angle == S::ZERO {
            (S::ZERO, S::ONE)
        } else {
            angle.sin_cos()
        }
    }

    /// A blob's or a noisy blob's outline at scale 1 about the origin for `angle`, and twice
    /// its area (a point for other kinds).
    fn blob_outline<S: Scalar>(&self, angle: S) -> ([Point<S>; BLOB_VERTICES], S) {
        match *self {
            ShapeKind::Noisy {
                amplitude,
                features,
                octaves,
            } => noisy_unit(amplitude, features, octaves, angle),
            ShapeKind::Blob { delta } => blob_unit(delta, angle),
            _ => ([Point::default(); BLOB_VERTICES], S::ZERO),
        }
    }

    /// The concrete shape at a place. A motif needs its table: see [`ShapeKind::geo_in`]
    /// (without it, a motif's inscribed disc stands in for it).
    pub fn geo<S: Scalar>(&self, c: Point<S>, scale: S, angle: S) -> Geo<'static, S> {
        self.geo_in(&[], c, scale, angle)
    }

    /// The concrete shape at a place, a motif taken from `motifs` (entry `id` of the table).
    pub fn geo_in<'m, S: Scalar>(&self, motifs: &'m [Motif<'m>], c: Point<S>, scale: S, angle: S) -> Geo<'m, S> {
        let mut g = Geo::Circle { c, r: scale };
        self.geo_into_in(motifs, &mut g, c, scale, angle);
        g
    }

    /// [`ShapeKind::geo`] written into `out`. When `out` already holds a polygon its vertex
    /// list is refilled in place: only the vertices in use are written, no 512-byte array is
    /// zeroed or copied, which is what most exact tests would spend.
    pub fn geo_into<S: Scalar>(&self, out: &mut Geo<'_, S>, c: Point<S>, scale: S, angle: S) {
        self.geo_into_in(&[], out, c, scale, angle);
    }

    /// [`ShapeKind::geo_in`] written into `out`, as [`ShapeKind::geo_into`] does.
    pub fn geo_into_in<'m, S: Scalar>(&self, motifs: &'m [Motif<'m>], out: &mut Geo<'m, S>, c: Point<S>, scale: S, angle: S) {
        match *self {
            ShapeKind::Blob { .. } | ShapeKind::Noisy { .. } => {
                let (u, _) = self.blob_outline(angle);
                set_poly(out, false, |v| {
                    for p in u.iter() {
                        // Cannot fail: BLOB_VERTICES <= MAX_VERTS (checked at compile time).
                        let _ = v.push(Point::new(c.x + p.x * scale, c.y + p.y * scale));
                    }
                });
            }
            _ => {
                let (sin, cos) = Self::sin_cos(angle);
                self.geo_sc_into_in(motifs, out, c, scale, sin, cos);
            }
        }
    }

    /// The concrete shape at a place, rotation given by [`ShapeKind::sin_cos`] of its angle
    /// (not for blobs, whose outline depends on the angle itself: use [`ShapeKind::geo`]).
    pub fn geo_sc<S: Scalar>(&self, c: Point<S>, scale: S, sin: S, cos: S) -> Geo<'static, S> {
        let mut g = Geo::Circle { c, r: scale };
        self.geo_sc_into(&mut g, c, scale, sin, cos);
        g
    }

    /// [`ShapeKind::geo_sc`] written into `out`, as [`ShapeKind::geo_into`] does.
    pub fn geo_sc_into<S: Scalar>(&self, out: &mut Geo<'_, S>, c: Point<S>, scale: S, sin: S, cos: S) {
        self.geo_sc_into_in(&[], out, c, scale, sin, cos);
    }

    /// [`ShapeKind::geo_sc_into`], a motif taken from `motifs`.
    pub fn geo_sc_into_in<'m, S: Scalar>(&self, motifs: &'m [Motif<'m>], out: &mut Geo<'m, S>, c: Point<S>, scale: S, sin: S, cos: S) {
        match *self {
            ShapeKind::Motif { id, inner, .. } => {
                *out = match motifs.get(usize::from(id)) {
                    Some(m) => Geo::Motif {
                        m,
                        f: Frame::new(c, scale, sin, cos),
                    },
                    None => Geo::Circle {
                        c,
                        r: scale * S::from_f64(inner),
                    },
                }
            }
            ShapeKind::Circle => *out = Geo::Circle { c, r: scale },
            ShapeKind::Ring { inner } => {
                *out = Geo::Ring {
                    c,
                    r: scale,
                    inner: scale * S::from_f64(inner),
                }
            }
            ShapeKind::Square | ShapeKind::Rect { .. } => {
                let (hw, hh) = (scale * S::from_f64(self.aspect()), scale);
                let corner = |sx: S, sy: S| {
                    let (dx, dy) = (sx * hw, sy * hh);
                    Point::new(c.x + dx * cos - dy * sin, c.y + dx * sin + dy * cos)
                };
                let (m, p) = (-S::ONE, S::ONE);
                set_poly(out, true, |v| {
                    for q in [corner(m, m), corner(p, m), corner(p, p), corner(m, p)] {
                        // Cannot fail: 4 <= MAX_VERTS.
                        let _ = v.push(q);
                    }
                });
            }
            ShapeKind::Triangle | ShapeKind::Polygon { .. } | ShapeKind::Star { .. } => {
                let n = self.sides().min(MAX_VERTS);
                let (ss, cs) = S::turn_step(n);
                let inner = match *self {
                    ShapeKind::Star { inner, .. } => S::from_f64(inner),
                    _ => S::ONE,
                };
                // First vertex straight up, then counter-clockwise by 2π/n (a recurrence:
                // deterministic, and the drawn polygon is the tested one).
                set_poly(out, self.convex(), |v| {
                    let mut dir = Point::new(-sin, cos);
                    for k in 0..n {
                        let rad = if k % 2 == 1 { scale * inner } else { scale };
                        // Cannot fail: n <= MAX_VERTS (clamped above).
                        let _ = v.push(Point::new(c.x + dir.x * rad, c.y + dir.y * rad));
                        dir = rot(dir, ss, cs);
                    }
                });
            }
            ShapeKind::Blob { .. } | ShapeKind::Noisy { .. } => self.geo_into_in(motifs, out, c, scale, S::ZERO),
        }
    }
}

/// Makes `out` a polygon with no vertices (keeping its vertex storage in place when it
/// already held one) and lets `fill` push the vertices.
fn set_poly<S: Scalar>(out: &mut Geo<'_, S>, convex: bool, fill: impl FnOnce(&mut Verts<S>)) {
    // The list is filled where it lies: building it aside and moving it in would copy it.
    if !matches!(out, Geo::Poly { .. }) {
        *out = Geo::Poly { v: Verts::new(), convex };
    }
    if let Geo::Poly { v, convex: oc } = out {
        v.clear();
        *oc = convex;
        fill(v);
    }
}

#[cfg(test)]
mod tests;
