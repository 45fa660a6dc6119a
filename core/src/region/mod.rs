//! Regions to fill: where candidate centres are drawn and whether a shape lies inside.
//!
//! A rectangle `[0, W] x [0, H]` has an inclusive boundary (shapes stay inside, at least
//! `gap` from the edge) or a periodic one (a torus: a shape crossing an edge exists again at
//! x ± W, y ± H, and every test sees those images).

use crate::geom::{Geo, Point};
use crate::scalar::Scalar;

/// A region in its own frame (x right, y up, origin at the lower-left corner).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Region {
    /// The rectangle `[0, width] x [0, height]`.
    Rect {
        /// Width, finite and > 0.
        width: f64,
        /// Height, finite and > 0.
        height: f64,
        /// Toroidal boundary when true.
        periodic: bool,
    },
}

impl Region {
    /// Whether the dimensions are finite and positive.
    pub fn is_valid(&self) -> bool {
        match *self {
            Region::Rect { width, height, .. } => {
                width.is_finite() && height.is_finite() && width > 0.0 && height > 0.0
            }
        }
    }

    /// The region's area.
    pub fn area(&self) -> f64 {
        match *self {
            Region::Rect { width, height, .. } => width * height,
        }
    }

    /// Whether the boundary is periodic.
    pub fn periodic(&self) -> bool {
        match *self {
            Region::Rect { periodic, .. } => periodic,
        }
    }

    /// Width and height of the bounding box (the period when periodic).
    pub fn extent(&self) -> (f64, f64) {
        match *self {
            Region::Rect { width, height, .. } => (width, height),
        }
    }

    /// The ranges `[lo, hi]` for the centre of a shape whose half extents are `(ex, ey)`, or
    /// `None` when it cannot fit. Periodic regions give the whole period `[0, W)`.
    pub fn centre_range<S: Scalar>(&self, ex: S, ey: S, gap: S) -> Option<(S, S, S, S)> {
        let (w, h) = self.extent();
        let (w, h) = (S::from_f64(w), S::from_f64(h));
        if self.periodic() {
            return Some((S::ZERO, w, S::ZERO, h));
        }
        let (x0, x1) = (gap + ex, w - gap - ex);
        let (y0, y1) = (gap + ey, h - gap - ey);
        if x1 < x0 || y1 < y0 {
            None
        } else {
            Some((x0, x1, y0, y1))
        }
    }

    /// Whether a shape lies inside the region with at least `gap` to the boundary. Periodic
    /// regions accept every shape (its own images are tested by the engine).
    pub fn contains<S: Scalar>(&self, g: &Geo<S>, gap: S) -> bool {
        if self.periodic() {
            return true;
        }
        let (w, h) = self.extent();
        let (x0, y0, x1, y1) = g.bounds();
        x0 >= gap && y0 >= gap && x1 <= S::from_f64(w) - gap && y1 <= S::from_f64(h) - gap
    }

    /// The point `p` wrapped into the period `[0, W) x [0, H)` (unchanged when inclusive).
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
