//! Orbits: the engine on a wallpaper group's torus ([`crate::Region::Wallpaper`]).
//!
//! Each placement is one orbit, stored as `m` entries (the group's order): entry `i m + k` is
//! image `k` of placement `i` at its wrapped centre, image 0 the shape itself. Every test
//! sees the entries as placed shapes, with the lattice's translates of each, so a candidate
//! is tested exactly against every image near it. A candidate is accepted only when:
//! - the shape keeps its gap from every stored image and its translates (the tests of an
//!   ordinary torus);
//! - no two members of its own orbit (any two images, or an image and a translate of itself
//!   or of another image) come within the gap; an image that coincides with the shape (a
//!   shape centred on a rotation centre, or on a mirror) counts as meeting it, so such a
//!   candidate is refused (it is a set of measure zero: uniform centres never land there);
//! - each of its images keeps its gap from every stored image, tested as drawn (in exact
//!   arithmetic this follows from the first rule by symmetry; testing it keeps rounding from
//!   ever letting two drawn images meet).

use super::Engine;
use crate::geom::{separated, Geo, Point};
use crate::scalar::Scalar;
use crate::shape::{Placed, ShapeKind};

impl<'a, S: Scalar> Engine<'a, S> {
    /// The placement that stored entry `j` belongs to.
    #[inline(always)]
    pub(super) fn owner(&self, j: u32) -> u64 {
        if self.images.get() == 1 {
            u64::from(j)
        } else {
            u64::from(j / self.images)
        }
    }

    /// The placements made: the entries stored over the entries a placement takes.
    #[inline(always)]
    pub(super) fn orbits(&self) -> usize {
        self.len / self.per()
    }

    /// Entries a placement takes, as a divisor that cannot be 0.
    #[inline(always)]
    pub(super) fn per(&self) -> core::num::NonZeroUsize {
        core::num::NonZeroUsize::new(self.images.get() as usize).unwrap_or(core::num::NonZeroUsize::MIN)
    }

    /// The kind of stored entry `j`.
    #[inline(always)]
    pub(super) fn entry_kind(&self, j: u32) -> ShapeKind {
        self.kind_of(self.owner(j))
    }

    /// The outline of stored entry `j` (`p` is its slot), moved by `(ox, oy)`, into `out`: the
    /// shape itself, or for an image, the group's operation applied to the shape's outline.
    #[inline(always)]
    pub(super) fn entry_geo_into(&self, j: u32, p: &Placed<S>, ox: S, oy: S, out: &mut Geo<'a, S>) {
        let kind = self.entry_kind(j);
        let k = if self.images.get() == 1 { 0 } else { j % self.images };
        if k == 0 {
            kind.geo_into_in(self.motifs, out, Point::new(p.x + ox, p.y + oy), p.scale, p.angle);
        } else {
            self.image_geo_into(kind, j - k, k as usize, Point::new(p.x + ox, p.y + oy), out);
        }
    }

    /// Image `k` of the shape stored at entry `first` (a kind of `kind`), centred at `centre`.
    #[inline(never)]
    fn image_geo_into(&self, kind: ShapeKind, first: u32, k: usize, centre: Point<S>, out: &mut Geo<'a, S>) {
        let (Some(w), Some(rep)) = (self.region.wallpaper(), self.shapes.get(first as usize)) else {
            return;
        };
        let c = Point::new(rep.x, rep.y);
        kind.geo_into_in(self.motifs, out, c, rep.scale, rep.angle);
        w.image_in_place(k, out, c, centre);
    }

    /// The lattice translates `(dx, dy)` of the torus that bring a point at `(x, y)` within
    /// `reach` of a point at `(qx, qy)`, zero included; `f` is called with each until it
    /// returns false.
    fn translates_near(&self, (x, y): (S, S), (qx, qy): (S, S), reach: S, mut f: impl FnMut(S, S) -> bool) {
        let (w, h) = self.period;
        let ky = super::clearance::periods(reach, h);
        let kx = super::clearance::periods(reach, w);
        for l in -ky..=ky {
            let lf = S::from_f64(l as f64);
            let (sx, dy) = (self.shear * lf, h * lf);
            for k in -(kx + l.abs())..=(kx + l.abs()) {
                let dx = w * S::from_f64(k as f64) + sx;
                let (ex, ey) = (x + dx - qx, y + dy - qy);
                if ex.abs() > reach || ey.abs() > reach {
                    continue;
                }
                if !f(dx, dy) {
                    return;
                }
            }
        }
    }

    /// Image `k` of the candidate (`g`, centred at `c`) written into `out`, with its centre
    /// (the candidate itself for `k = 0`).
    fn candidate_image<'m>(&self, k: usize, g: &Geo<'m, S>, c: Point<S>, out: &mut Geo<'m, S>) -> Point<S> {
        match self.region.wallpaper() {
            Some(w) if k > 0 => {
                let centre = w.image_centre(k, c);
                out.clone_from(g);
                w.image_in_place(k, out, c, centre);
                centre
            }
            _ => {
                out.clone_from(g);
                c
            }
        }
    }

    /// Whether the candidate (`g`, centred at `c`, bounding radius `r`, inscribed radius
    /// `solid`) is refused on a wallpaper torus for its own orbit: two of its members meet, or
    /// one of its images meets a stored image. The stored image hit, when that was it (named
    /// as [`Engine::blocker`] names it with `lowest`).
    pub(super) fn orbit_refuses(&self, g: &Geo<S>, c: Point<S>, (r, solid): (S, Option<S>), lowest: bool) -> Option<Option<u32>> {
        if self.orbit_meets_itself(g, c, r) {
            return Some(None);
        }
        self.image_blocked(g, c, (r, solid), lowest).map(Some)
    }

    /// Whether two members of the candidate's orbit (an image and a translate of itself, or
    /// of a later image) come within the gap. Out of line, as is [`Engine::image_blocked`]:
    /// each holds its own outlines, and a board's stack holds one of them at a time.
    #[inline(never)]
    fn orbit_meets_itself(&self, g: &Geo<S>, c: Point<S>, r: S) -> bool {
        let n = self.images.get() as usize;
        let reach = r + r + self.gap;
        let (mut gi, mut gl) = (Geo::Circle { c, r }, Geo::Circle { c, r });
        for i in 0..n {
            let ci = self.candidate_image(i, g, c, &mut gi);
            for l in i..n {
                let cl = self.candidate_image(l, g, c, &mut gl);
                let mut meets = false;
                self.translates_near((cl.x, cl.y), (ci.x, ci.y), reach, |dx, dy| {
                    if i == l && dx == S::ZERO && dy == S::ZERO {
                        return true;
                    }
                    let (ex, ey) = (cl.x + dx - ci.x, cl.y + dy - ci.y);
                    if ex * ex + ey * ey > reach * reach {
                        return true;
                    }
                    meets = !separated(&gi, &gl.shift(dx, dy), self.gap);
                    !meets
                });
                if meets {
                    return true;
                }
            }
        }
        false
    }

    /// The stored image that one of the candidate's images (1.., as drawn) meets, if any.
    #[inline(never)]
    fn image_blocked(&self, g: &Geo<S>, c: Point<S>, (r, solid): (S, Option<S>), lowest: bool) -> Option<u32> {
        let mut gi = Geo::Circle { c, r };
        for k in 1..self.images.get() as usize {
            let ck = self.candidate_image(k, g, c, &mut gi);
            if let Some(j) = self.blocker(&gi, ck.x, ck.y, (r, solid), lowest) {
                return Some(j);
            }
        }
        None
    }

    /// Whether a shape of `kind` whose inscribed disc has radius `inr` meets its own
    /// translates wherever it is: its disc is wider than the shortest lattice vector.
    pub(super) fn wider_than_lattice(&self, inr: S) -> bool {
        let Some(w) = self.region.wallpaper() else { return false };
        let (ax, bx, by) = w.lattice();
        let len = |x: f64, y: f64| libm::sqrt(x * x + y * y);
        let shortest = ax.min(len(bx, by)).min(len(bx - ax, by)).min(len(bx + ax, by));
        (inr + inr + self.gap).to_f64() >= shortest
    }
}
