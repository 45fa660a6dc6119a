//! The fixed searches that place a motif: its reference point (the centre of a large
//! inscribed disc) and its inner cover ([`super::Motif::cover`]), on one grid of probes. Both
//! are the same on every target.

use super::motif::COVER_DISCS;
use crate::geom::Point;
use crate::region::PolygonRegion;

/// Where the pole search looks first: a grid of this many cells a side over the box.
const POLE_GRID: usize = 48;

/// The best centre of an inscribed disc the fixed search finds, or none when no probe lies
/// inside.
pub(super) fn pole(region: &PolygonRegion<'_>) -> Option<Point<f64>> {
    let (x0, y0, x1, y1) = region.bounds();
    let clear = |p: Point<f64>| if region.inside(p) { region.dist2(p) } else { -1.0 };
    let mut best: Option<(f64, Point<f64>)> = None;
    let mut offer = |p: Point<f64>| {
        let d = clear(p);
        if d > 0.0 && best.is_none_or(|(b, _)| d > b) {
            best = Some((d, p));
        }
    };
    let (w, h) = (x1 - x0, y1 - y0);
    for k in 0..POLE_GRID * POLE_GRID {
        offer(probe(k, x0, y0, w, h));
    }
    // Just off the middle of every edge, both sides: a slender outline the grid misses.
    for ring in region.rings() {
        for (a, b) in crate::geom::edges(ring) {
            let (mid, d) = (Point::new(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)), b.diff(a));
            for side in [0.05, -0.05] {
                offer(Point::new(mid.x - d.y * side, mid.y + d.x * side));
            }
        }
    }
    let (mut d, mut p) = best?;
    // A pattern search: the eight neighbours at a step, halved when none is better.
    let (mut sx, mut sy) = (w / POLE_GRID as f64, h / POLE_GRID as f64);
    for _ in 0..200 {
        let mut moved = false;
        for (dx, dy) in [
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, 1.0),
            (0.0, -1.0),
            (1.0, 1.0),
            (1.0, -1.0),
            (-1.0, 1.0),
            (-1.0, -1.0),
        ] {
            let q = Point::new(p.x + dx * sx, p.y + dy * sy);
            let e = clear(q);
            if e > d {
                (d, p, moved) = (e, q, true);
            }
        }
        if !moved {
            (sx, sy) = (sx * 0.5, sy * 0.5);
            if sx <= w * 1e-9 && sy <= h * 1e-9 {
                break;
            }
        }
    }
    Some(p)
}

/// The inner cover of a unit outline whose inscribed disc about the origin has radius
/// `inner` ([`Motif::cover`]): that disc, then greedily the probe of a 48 x 48 grid over the
/// box with the most room about it, among those outside every disc taken whose own disc
/// holds no centre taken. Each radius is the probe's distance to the outline less 10^-6 of it.
/// The search is fixed: the same discs on every target.
pub(super) fn cover(region: &PolygonRegion<'_>, inner: f64) -> ([(Point<f64>, f64); COVER_DISCS], u8) {
    let mut cover = [(Point::new(0.0, 0.0), 0.0); COVER_DISCS];
    let mut n = 0usize;
    if let Some(first) = cover.first_mut() {
        *first = (Point::new(0.0, 0.0), inner);
        n = 1;
    }
    let (x0, y0, x1, y1) = region.bounds();
    let (w, h) = (x1 - x0, y1 - y0);
    // The room about each probe inside (in single precision, for the ranking: 9 KB of
    // stack); a probe covered, or outside, has a room of 0.
    let room_at = |p: Point<f64>| crate::scalar::sqrtf(region.dist2(p)) * (1.0 - 1e-6);
    let mut room = [0.0f32; POLE_GRID * POLE_GRID];
    for (k, r) in room.iter_mut().enumerate() {
        let p = probe(k, x0, y0, w, h);
        if region.inside(p) {
            *r = room_at(p) as f32;
        }
    }
    while n < COVER_DISCS {
        let taken = cover.get(..n).unwrap_or(&[]);
        let mut best: Option<(usize, f32)> = None;
        for (k, r) in room.iter_mut().enumerate() {
            if *r <= 0.0 {
                continue;
            }
            let p = probe(k, x0, y0, w, h);
            let own = f64::from(*r);
            if taken.iter().any(|&(c, cr)| c.dist2(p) < cr.max(own) * cr.max(own)) {
                *r = 0.0;
            } else if best.is_none_or(|(_, b)| *r > b) {
                best = Some((k, *r));
            }
        }
        let Some((k, _)) = best else { break };
        let p = probe(k, x0, y0, w, h);
        if let Some(slot) = cover.get_mut(n) {
            *slot = (p, room_at(p));
        }
        if let Some(r) = room.get_mut(k) {
            *r = 0.0;
        }
        n += 1;
    }
    (cover, n as u8)
}

/// Probe `k` of the pole search's grid over the box at `(x0, y0)` of size `w` by `h`.
fn probe(k: usize, x0: f64, y0: f64, w: f64, h: f64) -> Point<f64> {
    let (i, j) = (k % POLE_GRID, k / POLE_GRID);
    let (u, v) = ((i as f64 + 0.5) / POLE_GRID as f64, (j as f64 + 0.5) / POLE_GRID as f64);
    Point::new(x0 + u * w, y0 + v * h)
}
