//! The tile's own picture (what a texture holds): model [`Path`]s in the tile's frame, whole
//! circles, open polylines (arcs and Voronoi edges cut exactly at the tile's edges) and closed
//! polylines (filled shapes cut to the tile). It shows every disc of the plane that reaches
//! into the tile, copies from the neighbouring tiles and rows included, so copies of the
//! picture meet without a seam. The mosaic and the planet lay copies of it out
//! ([`crate::model::tile::layout`]).

use super::model::{images, Image, Tile};
use crate::error::CliError;
use crate::geometry::voronoi::{self as geom, Clip, Pt};
use crate::model::tile::{Render, Style, TOLERANCE};
use crate::model::Path;
use spade::{DelaunayTriangulation, Triangulation};
use std::f64::consts::TAU;

/// Which disc of the tile a piece belongs to (a disc, part of one, or its cobblestone), and
/// that disc's radius where the piece shows it (in the tile's frame: an image from the row
/// above is half the size).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tag {
    /// The tile disc's index.
    pub disc: usize,
    /// Its radius as drawn in the tile's frame.
    pub r: f64,
}

/// Points on the circle `(c, r)` from angle `a0` to `a1` (counter-clockwise), both ends
/// included, with chords within [`TOLERANCE`] of the arc.
fn arc_points(c: Pt, r: f64, a0: f64, a1: f64) -> Vec<Pt> {
    let step = 2.0 * libm::acos(1.0 - (TOLERANCE / r).min(1.0));
    let n = (((a1 - a0) / step.max(1e-3)).ceil() as usize).clamp(2, 4096);
    (0..=n)
        .map(|k| {
            // The ends exactly: a crossing point must be the same in every piece that uses it.
            let a = if k == n { a1 } else { a0 + (a1 - a0) * k as f64 / n as f64 };
            [c[0] + r * libm::cos(a), c[1] + r * libm::sin(a)]
        })
        .collect()
}

/// The angles in `[0, 2 pi)` where the circle `(c, r)` crosses the lines of the box's edges
/// inside the box's range, sorted.
fn crossings(c: Pt, r: f64, w: f64, h: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let norm = |a: f64| if a < 0.0 { a + TAU } else { a };
    for (axis, at, lo, hi) in [(0usize, 0.0, 0.0, h), (0, w, 0.0, h), (1, 0.0, 0.0, w), (1, h, 0.0, w)] {
        let d = at - c[axis];
        if d.abs() >= r {
            continue;
        }
        let half = (r * r - d * d).sqrt();
        for s in [-half, half] {
            let other = c[1 - axis] + s;
            if other < lo || other > hi {
                continue;
            }
            let (dx, dy) = if axis == 0 { (d, s) } else { (s, d) };
            out.push(norm(libm::atan2(dy, dx)));
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}

/// A disc's part of the tile's picture: the whole circle, or the arcs inside the tile (open),
/// or the disc cut to the tile (closed).
fn disc_pieces(c: Pt, r: f64, w: f64, h: f64, style: Style, out: &mut Vec<Path>) {
    if c[0] - r >= 0.0 && c[0] + r <= w && c[1] - r >= 0.0 && c[1] + r <= h {
        out.push(Path::circle(c, r));
        return;
    }
    if c[0] + r <= 0.0 || c[0] - r >= w || c[1] + r <= 0.0 || c[1] - r >= h {
        return;
    }
    let cuts = crossings(c, r, w, h);
    if cuts.is_empty() {
        // The circle misses the tile's edges: the disc holds the whole tile, or misses it.
        let (dx, dy) = (0.5 * w - c[0], 0.5 * h - c[1]);
        if style == Style::Filled && dx * dx + dy * dy < r * r {
            out.push(Path::polyline(vec![[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]], true));
        }
        return;
    }
    let inside = |a: f64| {
        let p = [c[0] + r * libm::cos(a), c[1] + r * libm::sin(a)];
        p[0] >= 0.0 && p[0] <= w && p[1] >= 0.0 && p[1] <= h
    };
    let n = cuts.len();
    let mut arcs = Vec::new();
    for i in 0..n {
        let a0 = cuts[i];
        let a1 = if i + 1 < n { cuts[i + 1] } else { cuts[0] + TAU };
        if inside(0.5 * (a0 + a1)) {
            arcs.push(arc_points(c, r, a0, a1));
        }
    }
    match style {
        Style::Outline => out.extend(arcs.into_iter().map(|a| Path::polyline(a, false))),
        Style::Filled => {
            // The whole circle through the crossing points, cut by the tile's four sides.
            let mut ring: Vec<Pt> = Vec::new();
            for i in 0..n {
                let a0 = cuts[i];
                let a1 = if i + 1 < n { cuts[i + 1] } else { cuts[0] + TAU };
                let mut arc = arc_points(c, r, a0, a1);
                arc.pop();
                ring.extend(arc);
            }
            let poly = cut_to_box(ring, w, h);
            if poly.len() >= 3 {
                out.push(Path::polyline(poly, true));
            }
        }
    }
}

/// A convex polygon cut to the box `[0, w] x [0, h]`.
fn cut_to_box(mut poly: Vec<Pt>, w: f64, h: f64) -> Vec<Pt> {
    for (m, n) in [
        ([0.0, 0.0], [-1.0, 0.0]),
        ([w, 0.0], [1.0, 0.0]),
        ([0.0, 0.0], [0.0, -1.0]),
        ([0.0, h], [0.0, 1.0]),
    ] {
        if poly.is_empty() {
            break;
        }
        poly = geom::clip_half_plane(&poly, m, n);
    }
    // Snap the cut points onto the box, so that pieces of neighbouring tiles meet exactly.
    let snap = |v: f64, hi: f64| {
        if v.abs() < 1e-9 * hi {
            0.0
        } else if (v - hi).abs() < 1e-9 * hi {
            hi
        } else {
            v
        }
    };
    poly.into_iter().map(|p| [snap(p[0], w), snap(p[1], h)]).collect()
}

/// The tile's picture.
pub fn tile_pieces(tile: &Tile, render: Render, style: Style) -> Result<Vec<Path>, CliError> {
    tagged_pieces(tile, render, style).map(|(pieces, _)| pieces)
}

/// The tile's picture and the [`Tag`] of each piece; no tags for cobblestone outlines, whose
/// edges each belong to two cells.
pub fn tagged_pieces(tile: &Tile, render: Render, style: Style) -> Result<(Vec<Path>, Vec<Tag>), CliError> {
    let (w, h) = (tile.spec.width, tile.spec.height);
    let mut out = Vec::new();
    let mut tags = Vec::new();
    match render {
        Render::Discs => {
            for im in images(tile, 0.0) {
                disc_pieces(im.c, im.r, w, h, style, &mut out);
                tags.resize(out.len(), Tag { disc: im.disc, r: im.r });
            }
        }
        Render::Voronoi => {
            let (sites, tri) = plane_diagram(tile)?;
            if tri.num_vertices() < 3 {
                return Ok((out, tags));
            }
            let clip = Clip::Rect {
                x0: 0.0,
                y0: 0.0,
                x1: w,
                y1: h,
            };
            match style {
                Style::Outline => {
                    let dual = geom::Dual::of(&tri, clip.bbox());
                    out.extend(
                        geom::polylines(&dual, 0..dual.edges.len(), &clip)
                            .into_iter()
                            .map(|l| Path::polyline(l, false)),
                    );
                }
                Style::Filled => {
                    for (v, im) in sites.iter().enumerate() {
                        let poly = cut_to_box(inset_cell(tile, &tri, &sites, v), w, h);
                        if poly.len() >= 3 {
                            out.push(Path::polyline(poly, true));
                            tags.push(Tag { disc: im.disc, r: im.r });
                        }
                    }
                }
            }
        }
    }
    Ok((out, tags))
}

type Tri = DelaunayTriangulation<spade::Point2<f64>>;

/// The Delaunay triangulation of every centre of the plane whose cell can reach the tile: in a
/// grown tile the cells are a few disc spacings wide, well inside half a tile side (the seam
/// check would catch a tile too sparse for that). The sites are the discs' images, the tile's
/// own first, in order; vertex v of the triangulation is site v.
fn plane_diagram(tile: &Tile) -> Result<(Vec<Image>, Tri), CliError> {
    let (w, h) = (tile.spec.width, tile.spec.height);
    let sites = images(tile, 0.5 * w.min(h));
    let pts = sites.iter().map(|im| geom::p2(im.c)).collect();
    let tri = Tri::bulk_load_stable(pts).map_err(|e| CliError::Io(format!("internal: cannot triangulate the centres: {e}")))?;
    Ok((sites, tri))
}

/// The Voronoi cell of site `v`, each bisector moved towards the site by half the gap of the
/// pair (so the lines between cells follow the size law).
fn inset_cell(tile: &Tile, tri: &Tri, sites: &[Image], v: usize) -> Vec<Pt> {
    let (w, h) = (tile.spec.width, tile.spec.height);
    let s = sites[v].c;
    let mut poly = vec![[-w, -h], [2.0 * w, -h], [2.0 * w, 2.0 * h], [-w, 2.0 * h]];
    for o in geom::neighbours(tri, v) {
        let q = sites[o].c;
        let n = [q[0] - s[0], q[1] - s[1]];
        let len = (n[0] * n[0] + n[1] * n[1]).sqrt();
        if len == 0.0 || poly.is_empty() {
            continue;
        }
        let inset = 0.5 * tile.spec.gap_between(s[1], q[1]);
        let t = (0.5 * len - inset).max(0.0) / len;
        poly = geom::clip_half_plane(&poly, [s[0] + t * n[0], s[1] + t * n[1]], n);
    }
    poly
}

/// The stones of the tile's height map: every disc of the plane that reaches the tile, or
/// every inset cell of a centre whose cell can, whole (the map's edge cuts them, so a stone
/// crossing an edge goes on in the copy beyond it).
pub fn stones(tile: &Tile, render: Render) -> Result<Vec<crate::model::doc::ShapeDoc>, CliError> {
    let (w, h) = (tile.spec.width, tile.spec.height);
    let stone = |index: usize, c: Pt, radius: Option<f64>, vertices: Option<Vec<Pt>>| crate::model::doc::ShapeDoc {
        index: index as u64,
        kind: if radius.is_some() { "circle" } else { "polygon" },
        center: c,
        radius,
        inner_radius: None,
        angle: None,
        area: 0.0,
        trials: 0,
        vertices,
        outlines: None,
        decorations: None,
    };
    Ok(match render {
        Render::Discs => images(tile, 0.0)
            .iter()
            .enumerate()
            .map(|(i, im)| stone(i, im.c, Some(im.r), None))
            .collect(),
        Render::Voronoi => {
            let (sites, tri) = plane_diagram(tile)?;
            if tri.num_vertices() < 3 {
                return Ok(Vec::new());
            }
            (0..tri.num_vertices())
                .filter_map(|v| {
                    let cell = inset_cell(tile, &tri, &sites, v);
                    let reaches = cell.len() >= 3
                        && cell.iter().any(|p| p[0] > 0.0)
                        && cell.iter().any(|p| p[0] < w)
                        && cell.iter().any(|p| p[1] > 0.0)
                        && cell.iter().any(|p| p[1] < h);
                    reaches.then(|| stone(v, sites[v].c, None, Some(cell)))
                })
                .collect()
        }
    })
}

/// The tile's own shapes, whole and filled: its discs, or the inset cells of its centres. Laid
/// out, every shape of the plane is drawn once and whole, so copies meet without the hairline
/// seams that anti-aliasing leaves where two cut pieces abut.
pub fn own_pieces(tile: &Tile, render: Render) -> Result<(Vec<Path>, Vec<Tag>), CliError> {
    let tag = |disc: usize| Tag {
        disc,
        r: tile.discs.get(disc).map_or(0.0, |d| d.r),
    };
    match render {
        Render::Discs => Ok(tile.discs.iter().enumerate().map(|(i, d)| (Path::circle(d.c, d.r), tag(i))).unzip()),
        Render::Voronoi => {
            let (sites, tri) = plane_diagram(tile)?;
            if tri.num_vertices() < 3 {
                return Ok((Vec::new(), Vec::new()));
            }
            // The identity map comes first: the first sites are the tile's own centres.
            Ok((0..tile.discs.len().min(tri.num_vertices()))
                .map(|v| (inset_cell(tile, &tri, &sites, v), tag(v)))
                .filter(|(p, _)| p.len() >= 3)
                .map(|(p, t)| (Path::polyline(p, true), t))
                .unzip())
        }
    }
}

/// Where the tile's picture crosses its edges, for the seam checks: the x of every open piece's
/// end on the bottom and the top edge, and the y of every end on the left and the right edge
/// (each list sorted).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Ends {
    /// On y = 0.
    pub bottom: Vec<f64>,
    /// On y = H.
    pub top: Vec<f64>,
    /// On x = 0.
    pub left: Vec<f64>,
    /// On x = W.
    pub right: Vec<f64>,
}

/// The ends of the open pieces on the tile's edges.
pub fn ends(pieces: &[Path], w: f64, h: f64) -> Ends {
    let mut e = Ends::default();
    let tol = 1e-9 * w.max(h);
    for p in pieces {
        let Path::Polyline { points: l, closed: false } = p else { continue };
        for q in [l.first(), l.last()].into_iter().flatten() {
            if q[1].abs() <= tol {
                e.bottom.push(q[0]);
            } else if (q[1] - h).abs() <= tol {
                e.top.push(q[0]);
            } else if q[0].abs() <= tol {
                e.left.push(q[1]);
            } else if (q[0] - w).abs() <= tol {
                e.right.push(q[1]);
            }
        }
    }
    for v in [&mut e.bottom, &mut e.top, &mut e.left, &mut e.right] {
        v.sort_by(f64::total_cmp);
    }
    e
}

/// How far the picture is from meeting its copies: the largest distance between matching
/// ends (left against right; the top's left half and right half each against the bottom at
/// half scale), or infinity when their numbers differ. Zero up to rounding for a tile that
/// tiles.
pub fn seam_gaps(e: &Ends, w: f64) -> f64 {
    let worst = |a: &[f64], b: &[f64]| -> f64 {
        if a.len() != b.len() {
            return f64::INFINITY;
        }
        a.iter().zip(b).fold(0.0, |m: f64, (x, y)| m.max((x - y).abs()))
    };
    let half: Vec<f64> = e.bottom.iter().map(|x| 0.5 * x).collect();
    let (lo, hi): (Vec<f64>, Vec<f64>) = e.top.iter().partition(|&&x| x < 0.5 * w);
    let hi: Vec<f64> = hi.iter().map(|x| x - 0.5 * w).collect();
    worst(&e.left, &e.right).max(worst(&half, &lo)).max(worst(&half, &hi))
}

#[cfg(test)]
mod tests;
