//! Paths and drawings: what a pen or beam draws, in mm, as open or closed polylines and
//! circular arcs, with their bounding boxes, lengths and reversals. Plain data, no I/O.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// A point in mm.
pub type Pt = [f64; 2];

/// One stroke of the pen or beam, in mm.
#[derive(Debug, Clone, PartialEq)]
pub enum Path {
    /// Straight segments through `points`; `closed` adds the segment back to the first point.
    Polyline {
        /// The vertices.
        points: Vec<Pt>,
        /// Whether the last point joins the first.
        closed: bool,
    },
    /// A circular arc from angle `start` (radians, counter-clockwise from +x) over `sweep`
    /// (positive counter-clockwise, negative clockwise); `|sweep| >= 2π` is a full circle.
    Arc {
        /// Centre.
        center: Pt,
        /// Radius (> 0).
        radius: f64,
        /// Start angle.
        start: f64,
        /// Signed sweep.
        sweep: f64,
    },
}

/// An axis-aligned box (min x, min y, max x, max y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Minimum x.
    pub x0: f64,
    /// Minimum y.
    pub y0: f64,
    /// Maximum x.
    pub x1: f64,
    /// Maximum y.
    pub y1: f64,
}

impl Bounds {
    /// The empty box (adding any point makes it that point).
    pub const EMPTY: Bounds = Bounds {
        x0: f64::INFINITY,
        y0: f64::INFINITY,
        x1: f64::NEG_INFINITY,
        y1: f64::NEG_INFINITY,
    };

    /// Grows the box to hold `p`.
    pub fn add(&mut self, p: Pt) {
        self.x0 = self.x0.min(p[0]);
        self.y0 = self.y0.min(p[1]);
        self.x1 = self.x1.max(p[0]);
        self.y1 = self.y1.max(p[1]);
    }

    /// Whether nothing was added.
    pub fn is_empty(&self) -> bool {
        self.x0 > self.x1
    }

    /// Width.
    pub fn width(&self) -> f64 {
        self.x1 - self.x0
    }

    /// Height.
    pub fn height(&self) -> f64 {
        self.y1 - self.y0
    }

    /// Whether this box lies inside `outer`, allowing `eps` mm of rounding.
    pub fn inside(&self, outer: &Bounds, eps: f64) -> bool {
        self.is_empty()
            || (self.x0 >= outer.x0 - eps && self.y0 >= outer.y0 - eps && self.x1 <= outer.x1 + eps && self.y1 <= outer.y1 + eps)
    }
}

/// The distance between two points.
pub(crate) fn dist(a: Pt, b: Pt) -> f64 {
    libm::hypot(a[0] - b[0], a[1] - b[1])
}

impl Path {
    /// A polyline.
    pub fn polyline(points: Vec<Pt>, closed: bool) -> Path {
        Path::Polyline { points, closed }
    }

    /// A full circle drawn counter-clockwise from angle 0.
    pub fn circle(center: Pt, radius: f64) -> Path {
        Path::Arc {
            center,
            radius,
            start: 0.0,
            sweep: TAU,
        }
    }

    /// Whether the path ends where it starts (and may start anywhere on it).
    pub fn is_closed(&self) -> bool {
        match self {
            Path::Polyline { closed, .. } => *closed,
            Path::Arc { sweep, .. } => sweep.abs() >= TAU,
        }
    }

    /// Where the pen goes down.
    pub fn start_point(&self) -> Pt {
        match self {
            Path::Polyline { points, .. } => points.first().copied().unwrap_or([0.0, 0.0]),
            Path::Arc { center, radius, start, .. } => polar(*center, *radius, *start),
        }
    }

    /// Where the pen comes up.
    pub fn end_point(&self) -> Pt {
        match self {
            Path::Polyline { points, closed } => {
                if *closed {
                    points.first().copied().unwrap_or([0.0, 0.0])
                } else {
                    points.last().copied().unwrap_or([0.0, 0.0])
                }
            }
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                if sweep.abs() >= TAU {
                    polar(*center, *radius, *start)
                } else {
                    polar(*center, *radius, start + sweep)
                }
            }
        }
    }

    /// Pen-down length in mm.
    pub fn length(&self) -> f64 {
        match self {
            Path::Polyline { points, closed } => {
                let open: f64 = points.windows(2).map(|w| dist(w[0], w[1])).sum();
                match (closed, points.first(), points.last()) {
                    (true, Some(a), Some(b)) if points.len() > 2 => open + dist(*a, *b),
                    _ => open,
                }
            }
            Path::Arc { radius, sweep, .. } => radius * sweep.abs().min(TAU),
        }
    }

    /// The exact bounding box (arcs: their end points and every axis extreme they pass).
    pub fn bounds(&self) -> Bounds {
        let mut b = Bounds::EMPTY;
        match self {
            Path::Polyline { points, .. } => points.iter().for_each(|p| b.add(*p)),
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                b.add(self.start_point());
                b.add(self.end_point());
                for a in arc_extremes(*start, *sweep) {
                    b.add(polar(*center, *radius, a));
                }
            }
        }
        b
    }

    /// The same stroke drawn the other way.
    pub fn reversed(&self) -> Path {
        match self {
            Path::Polyline { points, closed } => {
                let mut p = points.clone();
                if *closed && p.len() > 1 {
                    // Keep the start point: reverse the cycle after it.
                    p[1..].reverse();
                } else {
                    p.reverse();
                }
                Path::Polyline {
                    points: p,
                    closed: *closed,
                }
            }
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => Path::Arc {
                center: *center,
                radius: *radius,
                // A whole circle keeps its start; an arc starts where it ended.
                start: if sweep.abs() >= TAU { *start } else { start + sweep },
                sweep: -sweep,
            },
        }
    }

    /// Applies `p -> (s x + dx, sy y + dy)` where `sy = ±s` (a negative `sy` mirrors y and
    /// turns arcs the other way).
    pub fn transformed(&self, s: f64, sy: f64, dx: f64, dy: f64) -> Path {
        let f = |p: &Pt| [s * p[0] + dx, sy * p[1] + dy];
        match self {
            Path::Polyline { points, closed } => Path::Polyline {
                points: points.iter().map(f).collect(),
                closed: *closed,
            },
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                let (start, sweep) = if sy < 0.0 { (-start, -sweep) } else { (*start, *sweep) };
                Path::Arc {
                    center: f(center),
                    radius: radius * s,
                    start,
                    sweep,
                }
            }
        }
    }
}

/// The point at angle `a` on the circle.
pub fn polar(c: Pt, r: f64, a: f64) -> Pt {
    [c[0] + r * libm::cos(a), c[1] + r * libm::sin(a)]
}

/// The multiples of π/2 strictly inside an arc's sweep (where x or y is extreme).
pub fn arc_extremes(start: f64, sweep: f64) -> Vec<f64> {
    if sweep.abs() >= TAU {
        return vec![0.0, FRAC_PI_2, PI, 3.0 * FRAC_PI_2];
    }
    let (lo, hi) = if sweep >= 0.0 {
        (start, start + sweep)
    } else {
        (start + sweep, start)
    };
    let k0 = (lo / FRAC_PI_2).ceil() as i64;
    let k1 = (hi / FRAC_PI_2).floor() as i64;
    (k0..=k1).map(|k| k as f64 * FRAC_PI_2).collect()
}

/// Everything a pen or beam draws, in mm in the bed frame.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Drawing {
    /// The strokes, in drawing order.
    pub paths: Vec<Path>,
}

impl Drawing {
    /// The bounding box of every path.
    pub fn bounds(&self) -> Bounds {
        let mut b = Bounds::EMPTY;
        for p in &self.paths {
            let q = p.bounds();
            if !q.is_empty() {
                b.add([q.x0, q.y0]);
                b.add([q.x1, q.y1]);
            }
        }
        b
    }

    /// Total pen-down length in mm.
    pub fn pen_down_length(&self) -> f64 {
        self.paths.iter().map(Path::length).sum()
    }

    /// Pen-up travel in mm from `home` through every path in order (not back home).
    pub fn travel_from(&self, home: Pt) -> f64 {
        let mut at = home;
        let mut t = 0.0;
        for p in &self.paths {
            t += dist(at, p.start_point());
            at = p.end_point();
        }
        t
    }

    /// The drawing under `p -> placement.apply(p)`.
    pub fn placed(&self, pl: &super::Placement) -> Drawing {
        Drawing {
            paths: self.paths.iter().map(|p| p.transformed(pl.scale, pl.scale, pl.dx, pl.dy)).collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arc_bounds_see_the_extremes() {
        let p = Path::Arc {
            center: [0.0, 0.0],
            radius: 1.0,
            start: -0.1,
            sweep: 0.2,
        };
        let b = p.bounds();
        assert!((b.x1 - 1.0).abs() < 1e-15, "passes angle 0: {b:?}");
        let q = Path::Arc {
            center: [0.0, 0.0],
            radius: 1.0,
            start: 0.1,
            sweep: 0.2,
        };
        assert!(q.bounds().x1 < 1.0);
    }

    #[test]
    fn reversal_keeps_closed_starts_and_flips_arcs() {
        let p = Path::polyline(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], true);
        let r = p.reversed();
        assert_eq!(r.start_point(), [0.0, 0.0]);
        assert_eq!(r, Path::polyline(vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0]], true));
        let a = Path::Arc {
            center: [0.0, 0.0],
            radius: 1.0,
            start: 0.0,
            sweep: 1.0,
        };
        let ra = a.reversed();
        assert!(dist(ra.start_point(), a.end_point()) < 1e-15);
        assert!(dist(ra.end_point(), a.start_point()) < 1e-15);
    }
}
