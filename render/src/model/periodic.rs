//! Periodic images: in a periodic (toroidal) fill, a shape near an edge shows again across
//! it. One function finds the shifts of every image that meets the tile, for every writer
//! (SVG, G-code, height maps), the shape itself first, then its images nearest first.

use super::doc::ShapeDoc;
use super::shape::shape_bounds;
use super::Bounds;

/// The (dx, dy) shifts of a shape's images whose bounding boxes meet the `w` x `h` tile:
/// the shape itself first.
pub fn periodic_images(b: &Bounds, w: f64, h: f64) -> Vec<(f64, f64)> {
    let shifts = |lo: f64, hi: f64, p: f64| -> Vec<f64> {
        let k0 = (-hi / p).floor() as i64;
        let k1 = ((p - lo) / p).ceil() as i64;
        let mut ks: Vec<i64> = (k0..=k1).collect();
        ks.sort_by_key(|k| (k.abs(), -k));
        ks.into_iter()
            .map(|k| k as f64 * p)
            .filter(|&d| hi + d > 0.0 && lo + d < p)
            .collect()
    };
    let (xs, ys) = (shifts(b.x0, b.x1, w), shifts(b.y0, b.y1, h));
    ys.iter().flat_map(|&dy| xs.iter().map(move |&dx| (dx, dy))).collect()
}

/// The (dx, dy) images of a shape that can show inside a periodic `w` x `h` region: the
/// shifts of [`periodic_images`] for the shape's bounding box.
pub fn shape_images(sh: &ShapeDoc, w: f64, h: f64) -> Vec<(f64, f64)> {
    periodic_images(&shape_bounds(sh), w, h)
}
