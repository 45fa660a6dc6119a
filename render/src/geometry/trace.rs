//! The dark areas of a picture as rings (`--region mask:FILE`): marching squares over a
//! luminance grid. A pure function of the grid and the threshold: the same picture gives the
//! same rings, bit for bit, and never panics.
//!
//! The samples are the pixel centres, pixel `(i, j)` at `(i + 0.5, j + 0.5)` in pixel units
//! (x right, y down, as the picture is stored). A sample is dark when its luminance is below
//! the threshold. The grid is padded with one light sample on every side, so every contour
//! closes and the rings lie within half a pixel of the picture.
//!
//! - Along a cell edge from a dark to a light sample, the vertex is where the linear
//!   interpolation between them meets the threshold, kept at least 1/100 of a pixel from
//!   either sample, so that two edges never give the same point.
//! - A saddle (two dark samples diagonally opposite) joins its dark corners when the mean of
//!   its four samples is dark, and keeps them apart otherwise: each cell decides by its own
//!   samples, so its two neighbours always agree about the edge they share.
//! - Every ring walks with the dark side on its right: outlines clockwise and holes
//!   counter-clockwise as the picture shows them (a positive shoelace area in pixel
//!   coordinates for an outline, a negative one for a hole).
//! - A ring enclosing less than [`MIN_RING_AREA`] square pixels is a speck and is dropped
//!   (with everything inside it, which is smaller still): a dark speck vanishes, a light
//!   speck inside a dark area fills in.

use zetafill::Point;

/// The smallest area a traced ring keeps, in square pixels: a dark dot of fewer than about
/// 2 x 2 pixels, or a light one in a dark area, is taken as noise (of a scan or of JPEG).
pub const MIN_RING_AREA: f64 = 4.0;

/// The nearest a vertex comes to a sample, in pixels.
const EDGE_MARGIN: f64 = 0.01;

/// Closed rings, vertex after vertex, with the exclusive end of each ring.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Rings {
    /// Vertices, ring after ring (a ring's last vertex joins its first).
    pub points: Vec<Point<f64>>,
    /// The exclusive end of each ring in `points`.
    pub ends: Vec<usize>,
}

impl Rings {
    /// The rings, as slices of their vertices.
    pub fn iter(&self) -> impl Iterator<Item = &[Point<f64>]> + '_ {
        let starts = std::iter::once(0).chain(self.ends.iter().copied());
        starts.zip(&self.ends).map(|(a, &b)| self.points.get(a..b).unwrap_or(&[]))
    }

    /// Appends a ring.
    pub fn push(&mut self, ring: &[Point<f64>]) {
        self.points.extend_from_slice(ring);
        self.ends.push(self.points.len());
    }
}

/// A traced picture outgrew a limit of the caller's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TooDetailed {
    /// The limit on vertices, before simplification, that was passed.
    pub vertices: usize,
}

/// A picture's luminance, padded with light, and the threshold below which a sample is dark.
struct Grid<'a> {
    luma: &'a [f32],
    width: usize,
    height: usize,
    threshold: f32,
}

impl Grid<'_> {
    /// The padded sample `(x, y)`: `x` in `0..=width + 1`, `y` in `0..=height + 1`.
    fn at(&self, x: usize, y: usize) -> f32 {
        if x == 0 || y == 0 || x > self.width || y > self.height {
            return 1.0;
        }
        self.luma.get((y - 1) * self.width + (x - 1)).copied().unwrap_or(1.0)
    }

    fn dark(&self, x: usize, y: usize) -> bool {
        self.at(x, y) < self.threshold
    }

    /// Where the threshold crosses the edge from sample `a` to sample `b`, as a fraction of
    /// the way from `a`.
    fn crossing(&self, a: f32, b: f32) -> f64 {
        let t = (f64::from(self.threshold) - f64::from(a)) / (f64::from(b) - f64::from(a));
        if t.is_finite() {
            t.clamp(EDGE_MARGIN, 1.0 - EDGE_MARGIN)
        } else {
            0.5
        }
    }

    /// The vertex on edge `edge` (0 top, 1 right, 2 bottom, 3 left) of the cell whose top left
    /// sample is `(x, y)`, in pixel units. Each edge is computed from its own two samples in
    /// one order, so the two cells that share it get the same bits.
    fn vertex(&self, x: usize, y: usize, edge: u8) -> Point<f64> {
        // The edge's first sample (left or top end) and whether it runs along x.
        let (sx, sy, along_x) = match edge {
            0 => (x, y, true),
            1 => (x + 1, y, false),
            2 => (x, y + 1, true),
            _ => (x, y, false),
        };
        let a = self.at(sx, sy);
        let (b, ox, oy) = if along_x {
            (self.at(sx + 1, sy), 1.0, 0.0)
        } else {
            (self.at(sx, sy + 1), 0.0, 1.0)
        };
        let t = self.crossing(a, b);
        Point::new(sx as f64 - 0.5 + ox * t, sy as f64 - 0.5 + oy * t)
    }

    /// The contour segments of the cell whose top left sample is `(x, y)`, each as (entry
    /// edge, exit edge), at most two. Corners are numbered clockwise on the picture from the
    /// top left (0 top left, 1 top right, 2 bottom right, 3 bottom left); corner `k` lies
    /// between edge `k - 1` and edge `k`.
    fn segments(&self, x: usize, y: usize) -> [Option<(u8, u8)>; 2] {
        let corners = [(x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1)];
        let dark = corners.map(|(cx, cy)| self.dark(cx, cy));
        let bits = dark.iter().enumerate().fold(0u8, |b, (k, &d)| b | (u8::from(d) << k));
        let around = |k: u8, keep_dark: bool| {
            // Cutting off corner k alone: the dark side stays on the right.
            if keep_dark {
                Some((k, (k + 3) % 4))
            } else {
                Some(((k + 3) % 4, k))
            }
        };
        match bits {
            0 | 15 => [None, None],
            5 | 10 => {
                let sum: f32 = corners.iter().map(|&(cx, cy)| self.at(cx, cy)).sum();
                let joined = sum / 4.0 < self.threshold;
                // Joined: cut off the two light corners; apart: the two dark ones.
                let first = if (bits == 5) == joined { 1 } else { 0 };
                [around(first, !joined), around(first + 2, !joined)]
            }
            _ => {
                // One run of dark corners, clockwise from `a` to `b`.
                let is_dark = |k: u8| dark[usize::from(k % 4)];
                let a = (0..4u8).find(|&k| is_dark(k) && !is_dark(k + 3)).unwrap_or(0);
                let b = (0..4u8).find(|&k| is_dark(k) && !is_dark(k + 1)).unwrap_or(0);
                [Some((b, (a + 3) % 4)), None]
            }
        }
    }
}

/// The rings of the dark areas of a `width x height` picture (`luma` row by row from the top,
/// values in `[0, 1]`) at `threshold`, in pixel units (x right, y down), specks dropped.
/// Refuses, once the rings kept reach more than `max_vertices` vertices, before going on.
pub fn trace(luma: &[f32], width: usize, height: usize, threshold: f32, max_vertices: usize) -> Result<Rings, TooDetailed> {
    let grid = Grid {
        luma,
        width,
        height,
        threshold,
    };
    // Cells: one per 2 x 2 block of padded samples.
    let (cols, rows) = (width + 1, height + 1);
    let mut seen = vec![0u64; (cols * rows * 2).div_ceil(64)];
    let mut rings = Rings::default();
    let mut ring = Vec::new();
    for y in 0..rows {
        for x in 0..cols {
            for (slot, seg) in grid.segments(x, y).into_iter().enumerate() {
                let id = (y * cols + x) * 2 + slot;
                if seg.is_none() || seen[id / 64] & (1 << (id % 64)) != 0 {
                    continue;
                }
                walk(&grid, (x, y, slot), cols, &mut seen, &mut ring);
                if area(&ring).abs() >= MIN_RING_AREA {
                    if rings.points.len() + ring.len() > max_vertices {
                        return Err(TooDetailed { vertices: max_vertices });
                    }
                    rings.push(&ring);
                }
            }
        }
    }
    Ok(rings)
}

/// Follows the contour from segment `slot` of cell `(x, y)` round to where it started,
/// marking each segment seen and writing its entry vertices into `ring`.
fn walk(grid: &Grid<'_>, start: (usize, usize, usize), cols: usize, seen: &mut [u64], ring: &mut Vec<Point<f64>>) {
    ring.clear();
    let (mut x, mut y, mut slot) = start;
    loop {
        let id = (y * cols + x) * 2 + slot;
        if let Some(w) = seen.get_mut(id / 64) {
            *w |= 1 << (id % 64);
        }
        let Some((entry, exit)) = grid.segments(x, y).get(slot).copied().flatten() else {
            return;
        };
        ring.push(grid.vertex(x, y, entry));
        // Into the neighbour across the exit edge (the padding keeps every contour inside).
        match exit {
            0 => y = y.wrapping_sub(1),
            1 => x += 1,
            2 => y += 1,
            _ => x = x.wrapping_sub(1),
        }
        let back = (exit + 2) % 4;
        let segs = grid.segments(x, y);
        slot = match segs {
            [Some((e, _)), _] if e == back => 0,
            [_, Some((e, _))] if e == back => 1,
            // Cannot happen on a padded grid: a contour always continues.
            _ => return,
        };
        if (x, y, slot) == start {
            return;
        }
    }
}

/// Twice the signed area of a ring, halved: the shoelace formula.
pub fn area(ring: &[Point<f64>]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| {
            let (p, q) = (ring[i], ring[(i + 1) % n]);
            p.x * q.y - q.x * p.y
        })
        .sum::<f64>()
        / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A picture from rows of `#` (dark) and `.` (light).
    fn picture(rows: &[&str]) -> (Vec<f32>, usize, usize) {
        let luma = rows
            .iter()
            .flat_map(|r| r.chars().map(|c| if c == '#' { 0.0 } else { 1.0 }))
            .collect();
        (luma, rows[0].len(), rows.len())
    }

    fn traced(rows: &[&str]) -> Rings {
        let (luma, w, h) = picture(rows);
        trace(&luma, w, h, 0.5, usize::MAX).unwrap_or_default()
    }

    #[test]
    fn a_square_traces_to_one_counter_clockwise_outline() {
        let r = traced(&["......", ".####.", ".####.", ".####.", ".####.", "......"]);
        assert_eq!(r.ends.len(), 1);
        // Half way between the dark and light centres: the pixel edges, corners cut.
        let a = area(&r.points);
        assert!((a - (16.0 - 4.0 * 0.125)).abs() < 1e-9, "{a}");
        assert!(r.points.iter().all(|p| p.x >= 1.0 && p.x <= 5.0 && p.y >= 1.0 && p.y <= 5.0));
    }

    #[test]
    fn a_frame_is_an_outline_and_a_hole_of_opposite_turn() {
        let r = traced(&["#######", "#.....#", "#.....#", "#.....#", "#.....#", "#.....#", "#######"]);
        assert_eq!(r.ends.len(), 2);
        let areas: Vec<f64> = r.iter().map(area).collect();
        assert!(areas[0] * areas[1] < 0.0, "{areas:?}");
        // The light border closes the outline at the picture's edge.
        assert!(r.points.iter().any(|p| p.x == 0.0));
    }

    #[test]
    fn saddles_join_by_the_mean_and_specks_are_dropped() {
        // Two 3x3 blocks touching at a corner: with pure black and white the mean of a saddle
        // is 0.5, light at threshold 0.5 (apart), dark at 0.6 (joined).
        let rows = ["###...", "###...", "###...", "...###", "...###", "...###"];
        let (luma, w, h) = picture(&rows);
        let apart = trace(&luma, w, h, 0.5, usize::MAX).unwrap_or_default();
        let joined = trace(&luma, w, h, 0.6, usize::MAX).unwrap_or_default();
        assert_eq!((apart.ends.len(), joined.ends.len()), (2, 1));
        // A lone dark pixel is a speck; so is a lone light pixel in a dark block.
        assert!(traced(&["...", ".#.", "..."]).ends.is_empty());
        assert_eq!(traced(&["#####", "#####", "##.##", "#####", "#####"]).ends.len(), 1);
        // The checks can fail: a 4x4 light hole is kept.
        let holed = ["########", "##....##", "##....##", "##....##", "##....##", "########"];
        assert_eq!(traced(&holed).ends.len(), 2);
    }

    #[test]
    fn the_vertex_limit_stops_the_trace() {
        let (luma, w, h) = picture(&["......", ".####.", ".####.", ".####.", ".####.", "......"]);
        assert_eq!(trace(&luma, w, h, 0.5, 10), Err(TooDetailed { vertices: 10 }));
        assert!(trace(&luma, w, h, 0.5, 100).is_ok());
    }
}
