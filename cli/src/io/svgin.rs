//! Reading a region from an SVG file (`--region svg:FILE`): every closed subpath of every
//! path, in document order, flattened to a polygon, in mm, in the region frame (y up).
//!
//! The file is parsed by usvg, which resolves transforms, units and shapes (rect, circle,
//! ellipse, polygon are paths to it). Coordinates come out in CSS pixels (96 per inch) and
//! are converted to mm (25.4 / 96 mm per px), with y flipped about the document's height.
//! Coordinates are rounded to 1e-4 mm (usvg computes in f32). Curves are flattened so that no chord is longer than 0.5 mm, with at least 8 pieces per
//! curve. Rings inside other rings are holes (the even-odd rule). Subpaths that are not
//! closed are ignored; a file with none is an error.

use resvg::usvg;
use std::path::Path;
use zetafill::Point;

const MM_PER_PX: f64 = 25.4 / 96.0;
const MAX_CHORD_MM: f64 = 0.5;

/// Why a file holds no outline. The caller says which flag named the file.
#[derive(Debug)]
pub enum OutlineError {
    /// The file cannot be read.
    Read(std::io::Error),
    /// The file is not SVG that usvg can parse.
    Svg(usvg::Error),
    /// The file has no closed path.
    NoClosedPath,
}

/// Rings of the outline: vertices, ring after ring, and the exclusive end of each ring.
pub fn read_outline(path: &Path) -> Result<(Vec<Point<f64>>, Vec<usize>), OutlineError> {
    let data = crate::io::read::read_limited(path, crate::io::read::MAX_SVG_BYTES, "an SVG outline").map_err(OutlineError::Read)?;
    let tree = usvg::Tree::from_data(&data, &usvg::Options::default()).map_err(OutlineError::Svg)?;
    let height = f64::from(tree.size().height());
    let mut rings: Vec<Vec<Point<f64>>> = Vec::new();
    collect(tree.root(), height, &mut rings);
    rings.retain(|r| r.len() >= 3);
    if rings.is_empty() {
        return Err(OutlineError::NoClosedPath);
    }
    let mut points = Vec::new();
    let mut ends = Vec::new();
    for r in rings {
        points.extend(r);
        ends.push(points.len());
    }
    Ok((points, ends))
}

fn collect(group: &usvg::Group, height: f64, rings: &mut Vec<Vec<Point<f64>>>) {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => collect(g, height, rings),
            usvg::Node::Path(p) => flatten(p, height, rings),
            _ => {}
        }
    }
}

fn flatten(p: &usvg::Path, height: f64, rings: &mut Vec<Vec<Point<f64>>>) {
    let ts = p.abs_transform();
    let map = |x: f32, y: f32| {
        let (x, y) = (f64::from(x), f64::from(y));
        let (sx, ky, kx, sy, tx, ty) = (
            f64::from(ts.sx),
            f64::from(ts.ky),
            f64::from(ts.kx),
            f64::from(ts.sy),
            f64::from(ts.tx),
            f64::from(ts.ty),
        );
        let (px, py) = (sx * x + kx * y + tx, ky * x + sy * y + ty);
        // usvg works in f32: round to 1e-4 mm (0.1 µm) so that "90" reads back as 90.
        let snap = |v: f64| (v * 1e4).round() / 1e4;
        Point::new(snap(px * MM_PER_PX), snap((height - py) * MM_PER_PX))
    };
    let mut cur: Vec<Point<f64>> = Vec::new();
    let mut last = Point::new(0.0, 0.0);
    fn push_ring(rings: &mut Vec<Vec<Point<f64>>>, cur: &mut Vec<Point<f64>>, closed: bool) {
        let mut r = std::mem::take(cur);
        if closed {
            if r.len() >= 2 && r.first() == r.last() {
                r.pop();
            }
            r.dedup();
            rings.push(r);
        }
    }
    for seg in p.data().segments() {
        use usvg::tiny_skia_path::PathSegment as S;
        match seg {
            S::MoveTo(a) => {
                let open_closed = cur.len() >= 3 && cur.first() == cur.last();
                push_ring(rings, &mut cur, open_closed);
                last = map(a.x, a.y);
                cur.push(last);
            }
            S::LineTo(a) => {
                last = map(a.x, a.y);
                cur.push(last);
            }
            S::QuadTo(b, c) => {
                let (b, c) = (map(b.x, b.y), map(c.x, c.y));
                let n = pieces(&[last, b, c]);
                for k in 1..=n {
                    let t = k as f64 / n as f64;
                    let u = 1.0 - t;
                    cur.push(Point::new(
                        u * u * last.x + 2.0 * u * t * b.x + t * t * c.x,
                        u * u * last.y + 2.0 * u * t * b.y + t * t * c.y,
                    ));
                }
                last = c;
            }
            S::CubicTo(b, c, d) => {
                let (b, c, d) = (map(b.x, b.y), map(c.x, c.y), map(d.x, d.y));
                let n = pieces(&[last, b, c, d]);
                for k in 1..=n {
                    let t = k as f64 / n as f64;
                    let u = 1.0 - t;
                    let (w0, w1, w2, w3) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
                    cur.push(Point::new(
                        w0 * last.x + w1 * b.x + w2 * c.x + w3 * d.x,
                        w0 * last.y + w1 * b.y + w2 * c.y + w3 * d.y,
                    ));
                }
                last = d;
            }
            S::Close => {
                let start = cur.first().copied().unwrap_or(last);
                push_ring(rings, &mut cur, true);
                last = start;
            }
        }
    }
    let open_closed = cur.len() >= 3 && cur.first() == cur.last();
    push_ring(rings, &mut cur, open_closed);
}

/// Pieces for a curve with this control polygon: chords of at most 0.5 mm, at least 8.
fn pieces(ctrl: &[Point<f64>]) -> usize {
    let len: f64 = ctrl
        .windows(2)
        .map(|w| ((w[1].x - w[0].x).powi(2) + (w[1].y - w[0].y).powi(2)).sqrt())
        .sum();
    ((len / MAX_CHORD_MM).ceil() as usize).clamp(8, 10_000)
}
