//! The exact tests of a candidate against the placed shapes and the region's periodic
//! images, through the spatial hash. The shortcuts (two circles within reach, inscribed discs
//! that meet by a margin far above rounding) give the same answer as the full test, so they
//! never change a placement.

use super::Engine;
use crate::geom::{separated, Geo, Point};
use crate::scalar::Scalar;
use crate::shape::{Placed, ShapeKind};

/// How many periods of length `p` a reach can span (at least 1, at most 64).
pub(super) fn periods<S: Scalar>(reach: S, p: S) -> i64 {
    if p <= S::ZERO {
        return 1;
    }
    (reach / p).floor_i64().saturating_add(1).clamp(1, 64)
}

impl<'a, S: Scalar> Engine<'a, S> {
    /// A placed shape that `g` (centred at `(x, y)`, bounding radius `r`) comes within its gap
    /// of (or of an image of, in a periodic region); `None` when it keeps clear of all.
    ///
    /// With `lowest`, the answer does not depend on the hash table's size: the lowest-indexed
    /// shape hit among those stored at the finest level where any is hit (a bucket may also
    /// list shapes of other levels; they are named at their own level). Otherwise the first
    /// one found.
    pub(super) fn blocker(&self, g: &Geo<S>, x: S, y: S, (r, solid): (S, Option<S>), lowest: bool) -> Option<u32> {
        let hit: core::cell::Cell<Option<u32>> = core::cell::Cell::new(None);
        let total = self.len as u32;
        let circle = matches!(g, Geo::Circle { .. });
        let gap = self.gap;
        // The neighbour's outline, rebuilt in place for each shape tested.
        let mut other = Geo::Circle { c: Point::new(x, y), r };
        // Tests candidate `image`, centred at (qx, qy), against every shape the hash lists.
        let mut test = |level: usize, reach: S, image: &Geo<S>, qx: S, qy: S| {
            self.hash
                .query(level, [qx - reach, qy - reach, qx + reach, qy + reach], total, |j| {
                    let Some(p) = self.shapes.get(j as usize) else { return true };
                    let kind = self.entry_kind(j);
                    let their_r = kind.bounding_radius(p.scale);
                    let contact = r + their_r + gap;
                    let (dx, dy) = (p.x - qx, p.y - qy);
                    let d2 = dx * dx + dy * dy;
                    // Two circles within reach overlap, and so do two shapes whose inscribed
                    // discs meet: no geometry to build.
                    let ok = d2 > contact * contact
                        || (!((circle && kind == ShapeKind::Circle) || self.solids_meet(d2, solid, kind, p.scale)) && {
                            self.entry_geo_into(j, p, S::ZERO, S::ZERO, &mut other);
                            crate::counters::exact();
                            separated(image, &other, gap)
                        });
                    if !ok && (!lowest || self.hash.level_for(their_r + their_r) == level) {
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
                    if ox == S::ZERO && oy == S::ZERO {
                        test(level, reach, g, x + ox, y + oy);
                    } else {
                        test(level, reach, &g.shift(ox, oy), x + ox, y + oy);
                    }
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
    /// On a wallpaper torus the shifts are its lattice's vectors `k a + l b`.
    pub(super) fn each_image(&self, x: S, y: S, reach: S, mut f: impl FnMut(S, S) -> bool) {
        let (w, h) = self.period;
        let (kx, ky) = (periods(reach, w), periods(reach, h));
        let sheared = self.shear != S::ZERO;
        for l in -ky..=ky {
            // A sheared row is moved by l b: a's that many more may bring it back.
            let (sx, kx) = if sheared {
                (self.shear * S::from_f64(l as f64), kx + l.abs())
            } else {
                (S::ZERO, kx)
            };
            for k in -kx..=kx {
                let (ox, oy) = (w * S::from_f64(k as f64), h * S::from_f64(l as f64));
                let ox = if sheared { ox + sx } else { ox };
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
    pub(super) fn hits(&self, g: &Geo<S>, c: Point<S>, (r, solid): (S, Option<S>), j: u32, other: &mut Geo<'a, S>) -> bool {
        let Some(p) = self.shapes.get(j as usize) else { return false };
        let kind = self.entry_kind(j);
        let ((ox, oy), (dx, dy)) = self.nearest_image(p, c);
        let contact = r + kind.bounding_radius(p.scale) + self.gap;
        let d2 = dx * dx + dy * dy;
        if d2 > contact * contact {
            return false;
        }
        if (kind == ShapeKind::Circle && matches!(g, Geo::Circle { .. })) || self.solids_meet(d2, solid, kind, p.scale) {
            return true;
        }
        self.entry_geo_into(j, p, ox, oy, other);
        crate::counters::exact();
        !separated(g, other, self.gap)
    }

    /// Whether a shape whose inscribed disc has radius `solid` comes within the gap of a
    /// shape of `kind` at `scale` whose centre is `sqrt(d2)` away, judged by their inscribed
    /// discs alone: true only when those discs come within the gap by a margin far above any
    /// rounding of the exact test, so the answer never differs from it. False when either
    /// shape has no inscribed disc about its centre (a ring).
    pub(super) fn solids_meet(&self, d2: S, solid: Option<S>, kind: ShapeKind, scale: S) -> bool {
        let (Some(a), Some(b)) = (solid, kind.solid_radius(scale)) else {
            return false;
        };
        let contact = (a + b + self.gap) * S::from_f64(1.0 - 1e-6) - S::from_f64(1e-9);
        contact > S::ZERO && d2 < contact * contact
    }

    /// Whether a circle of radius `r` at `c` comes within the gap of placed shape `j` when
    /// that is a circle too (of its image nearest by centre, in a periodic region); false
    /// when `j` is another kind. The same answer as [`Engine::hits`] for two circles.
    pub(super) fn circles_meet(&self, c: Point<S>, r: S, j: u32) -> bool {
        let Some(p) = self.shapes.get(j as usize) else { return false };
        if self.entry_kind(j) != ShapeKind::Circle {
            return false;
        }
        let (_, (dx, dy)) = self.nearest_image(p, c);
        let contact = r + p.scale + self.gap;
        dx * dx + dy * dy <= contact * contact
    }

    /// The shift (zero, or a period each way) that brings placed shape `p` to its image nearest
    /// to `c` by centre (in a periodic region; none otherwise), and the offset from `c` to that
    /// image's centre.
    pub(super) fn nearest_image(&self, p: &Placed<S>, c: Point<S>) -> ((S, S), (S, S)) {
        let (dx, dy) = (p.x - c.x, p.y - c.y);
        let (mut ox, mut oy) = (S::ZERO, S::ZERO);
        if self.shear != S::ZERO {
            // A sheared lattice: the row first (moving by b), then along a.
            let (w, h) = self.period;
            if dy > h.half() {
                (ox, oy) = (-self.shear, -h);
            } else if -dy > h.half() {
                (ox, oy) = (self.shear, h);
            }
            let ex = dx + ox;
            if ex > w.half() {
                ox = ox - w;
            } else if -ex > w.half() {
                ox = ox + w;
            }
        } else if self.region.periodic() {
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
    pub(super) fn self_overlaps(&self, g: &Geo<S>, r: S) -> bool {
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
}
