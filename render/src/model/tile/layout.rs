//! How copies of the tile's picture are laid out on a sheet (the "Fractal Tiles" post): the
//! tile alone; the `mosaic`, rows of tiles each half the size of the row below; the `planet`,
//! rings of tiles each holding twice as many as the ring inside it, through a conformal map
//! that bends the rows into rings.

use super::TOLERANCE;
use crate::model::{Path, Pt};
use std::f64::consts::{PI, TAU};

/// What is laid out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// The tile alone (the texture).
    Tile,
    /// Rows of tiles, each row half the scale of the one below, showing how the tile meets its
    /// copies.
    Mosaic,
    /// Rings of tiles around a disc, each ring with twice as many tiles as the one inside it.
    Planet,
}

/// The size (mm) of a layout's drawing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sheet {
    /// Width.
    pub width: f64,
    /// Height.
    pub height: f64,
}

/// How the copies are laid out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arrangement {
    /// The layout.
    pub layout: Layout,
    /// Rows of tiles (mosaic, planet).
    pub rows: u32,
    /// Tiles in the bottom row (mosaic) or the innermost ring (planet).
    pub columns: u32,
    /// The planet's outer radius (mm): where the rings pile up.
    pub radius: f64,
}

/// Why an [`Arrangement`] cannot be drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LayoutError {
    /// A planet needs at least `need` tiles in its inner ring, or its rings would cross the
    /// centre.
    InnerRing {
        /// The fewest tiles the inner ring may hold.
        need: u32,
    },
}

/// The squared distance between two points.
fn dist2(a: Pt, b: Pt) -> f64 {
    let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
    dx * dx + dy * dy
}

impl Arrangement {
    /// The ring-0 thickness of the planet: rings are conformal at the surface, so a tile's
    /// height over its width there is the tile's own.
    pub fn ring_height(&self, w: f64, h: f64) -> f64 {
        TAU * self.radius * h / (f64::from(self.columns) * w)
    }

    /// Why the arrangement cannot be drawn: a planet whose inner ring has too few tiles.
    pub fn check(&self, w: f64, h: f64) -> Result<(), LayoutError> {
        if self.layout == Layout::Planet {
            let need = (2.0 * TAU * h / w).floor() as u32 + 1;
            if self.columns < need {
                return Err(LayoutError::InnerRing { need });
            }
        }
        Ok(())
    }

    /// How many copies of the tile's picture the layout draws.
    pub fn copies(&self) -> u64 {
        match self.layout {
            Layout::Tile => 1,
            _ => u64::from(self.columns).saturating_mul((1u64 << self.rows) - 1),
        }
    }

    /// The drawing's size.
    pub fn sheet(&self, w: f64, h: f64) -> Sheet {
        match self.layout {
            Layout::Tile => Sheet { width: w, height: h },
            Layout::Mosaic => Sheet {
                width: f64::from(self.columns) * w,
                height: 2.0 * h * (1.0 - 0.5f64.powi(self.rows as i32)),
            },
            Layout::Planet => Sheet {
                width: 2.0 * self.radius,
                height: 2.0 * self.radius,
            },
        }
    }

    /// The planet's map from the plane of rows to the sheet: x around, y outwards.
    fn polar(&self, w: f64, h: f64, p: Pt) -> Pt {
        let theta = TAU * p[0] / (f64::from(self.columns) * w);
        let rho = self.radius - (2.0 * h - p[1]) * self.ring_height(w, h) / h;
        [self.radius + rho * libm::cos(theta), self.radius + rho * libm::sin(theta)]
    }

    /// The copies of the tile's picture, on the sheet.
    ///
    /// With `whole` (the tile's own shapes, whole), a mosaic also lays out
    /// the copies just outside the sheet (a column each side, a row below and above), whose
    /// shapes reach in across its edges; the sheet's edge cuts them.
    pub fn lay_out(&self, pieces: &[Path], w: f64, h: f64, whole: bool) -> Vec<Path> {
        self.lay_out_scaled(pieces, w, h, whole).0
    }

    /// [`Arrangement::lay_out`], with the scale of the copy each laid-out piece is in (1 for
    /// the bottom row, 1/2 for the next, ...). Piece `j` of the result is a copy of piece
    /// `j mod pieces.len()`.
    pub fn lay_out_scaled(&self, pieces: &[Path], w: f64, h: f64, whole: bool) -> (Vec<Path>, Vec<f64>) {
        if self.layout == Layout::Tile {
            return (pieces.to_vec(), vec![1.0; pieces.len()]);
        }
        let rim = whole && self.layout == Layout::Mosaic;
        let rows: Vec<i32> = if rim {
            (-1..=self.rows as i32).collect()
        } else {
            (0..self.rows as i32).collect()
        };
        let mut out = Vec::new();
        let mut scales = Vec::new();
        for k in rows {
            let s = 0.5f64.powi(k);
            let y0 = 2.0 * h * (1.0 - s);
            // Tiles across the sheet in row k (a row below has half as many, rounded up).
            let count = if k >= 0 {
                i64::from(self.columns) << k
            } else {
                (i64::from(self.columns) + 1) / 2
            };
            let (first, last) = if rim { (-1, count) } else { (0, count - 1) };
            for i in first..=last {
                let x0 = i as f64 * w * s;
                let plane = |p: Pt| [x0 + s * p[0], y0 + s * p[1]];
                for piece in pieces {
                    out.push(match self.layout {
                        Layout::Planet => self.bend(piece, s, w, h, plane),
                        _ => piece.transformed(s, s, x0, y0),
                    });
                }
                scales.resize(out.len(), s);
            }
        }
        (out, scales)
    }

    /// A piece through the planet's map: circles (the tile's only arcs) become polygons, and
    /// straight segments are cut short enough to follow the curve.
    fn bend(&self, piece: &Path, s: f64, w: f64, h: f64, plane: impl Fn(Pt) -> Pt) -> Path {
        let map = |p: Pt| self.polar(w, h, plane(p));
        // Segment length (tile frame) that keeps the bent chord within the tolerance.
        let step = w / 64.0;
        let dense = |l: &[Pt], closed: bool| -> Vec<Pt> {
            let mut out = Vec::new();
            let n = l.len();
            let segs = if closed { n } else { n.saturating_sub(1) };
            for i in 0..segs {
                let (a, b) = (l[i], l[(i + 1) % n]);
                let len = dist2(a, b).sqrt();
                let m = ((len / step).ceil() as usize).max(1);
                for j in 0..m {
                    let t = j as f64 / m as f64;
                    out.push(map([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]));
                }
            }
            if !closed {
                if let Some(&last) = l.last() {
                    out.push(map(last));
                }
            }
            out
        };
        match piece {
            Path::Arc { center: c, radius: r, .. } => {
                // As many sides as the circle needs at its drawn size (at least 12).
                let drawn = r * s * self.ring_height(w, h) / h;
                let n = ((PI / libm::acos(1.0 - (TOLERANCE / drawn).min(1.0))).ceil() as usize).clamp(12, 256);
                let ring: Vec<Pt> = (0..n)
                    .map(|k| {
                        let a = TAU * k as f64 / n as f64;
                        map([c[0] + r * libm::cos(a), c[1] + r * libm::sin(a)])
                    })
                    .collect();
                Path::polyline(ring, true)
            }
            Path::Polyline { points, closed } => Path::polyline(dense(points, *closed), *closed),
        }
    }
}
