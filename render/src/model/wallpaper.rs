//! The drawing of a symmetric fill: each orbit's images (from the representative the document
//! holds, by the core's own operations, so every image is the outline the engine tested), at
//! every lattice translate that meets the window: `--repeat` cells, or the bounding box of the
//! region it is cut to.

use super::doc::{FillDoc, ShapeDoc};
use super::shape::shape_bounds;
use super::Bounds;
use zetafill::{Geo, Point, Verts, Wallpaper};

/// One image of a representative: the representative's position in the document, the image
/// at its centre in the fundamental domain, and the lattice shifts at which it meets the
/// window.
pub struct Image {
    /// The representative's position in [`FillDoc::shapes`].
    pub of: usize,
    /// The image, centred in the fundamental domain.
    pub shape: ShapeDoc,
    /// The lattice translates that meet the window, in rows from the bottom.
    pub shifts: Vec<(f64, f64)>,
}

/// `--lattice` as written for `w`: as many of its sides and angle as its lattice takes.
pub fn lattice_arg(w: &Wallpaper) -> String {
    let (a, b, angle) = w.sides();
    let all = [a, b, angle].map(|v| v.to_string());
    all[..w.group().lattice().arity().min(3)].join(":")
}

/// The outline a document records for a shape.
fn geo_of(sh: &ShapeDoc) -> Geo<'static, f64> {
    let c = Point::new(sh.center[0], sh.center[1]);
    match (sh.radius, sh.inner_radius) {
        (Some(r), Some(inner)) => Geo::Ring { c, r, inner },
        (Some(r), None) => Geo::Circle { c, r },
        _ => {
            let mut v = Verts::new();
            for p in sh.vertices.as_deref().unwrap_or(&[]) {
                // A document's polygons have at most as many vertices as the core's.
                let _ = v.push(Point::new(p[0], p[1]));
            }
            Geo::Poly { v, convex: false }
        }
    }
}

/// Image `k` of `sh` as a document shape (its index, area and trials are the
/// representative's).
pub fn image_doc(w: &Wallpaper, sh: &ShapeDoc, k: usize) -> ShapeDoc {
    if k == 0 {
        return sh.clone();
    }
    let c = Point::new(sh.center[0], sh.center[1]);
    let centre = w.image_centre(k, c);
    let mut out = geo_of(sh);
    w.image_in_place(k, &mut out, c, centre);
    let vertices = match &out {
        Geo::Poly { v, .. } => Some(v.iter().map(|p| [p.x, p.y]).collect()),
        _ => None,
    };
    // A motif's rings and decorations go by the same map: centre + M (v - c).
    let mapped = |lines: &Option<Vec<Vec<[f64; 2]>>>| -> Option<Vec<Vec<[f64; 2]>>> {
        let lines = lines.as_ref()?;
        let iso = w.iso(k)?;
        let [m00, m01, m10, m11] = iso.m;
        let map = |p: &[f64; 2]| {
            let (dx, dy) = (p[0] - c.x, p[1] - c.y);
            [centre.x + (m00 * dx + m01 * dy), centre.y + (m10 * dx + m11 * dy)]
        };
        Some(lines.iter().map(|r| r.iter().map(map).collect()).collect())
    };
    let (outlines, decorations) = (mapped(&sh.outlines), mapped(&sh.decorations));
    // The angle of an image is not one number (a mirror image has none): it is left out,
    // the vertices say it all.
    ShapeDoc {
        center: [centre.x, centre.y],
        angle: None,
        vertices,
        outlines,
        decorations,
        ..sh.clone()
    }
}

/// The lattice shifts `k a + l b` at which a shape's bounding box meets the box `win`, row
/// by row from the bottom.
fn shifts(w: &Wallpaper, sh: &ShapeDoc, win: &Bounds) -> Vec<(f64, f64)> {
    let (ax, bx, by) = w.lattice();
    let b = shape_bounds(sh);
    let mut out = Vec::new();
    let (l0, l1) = (((win.y0 - b.y1) / by).floor() as i64, ((win.y1 - b.y0) / by).ceil() as i64);
    for l in l0..=l1 {
        let (sx, dy) = (l as f64 * bx, l as f64 * by);
        if !(b.y1 + dy > win.y0 && b.y0 + dy < win.y1) {
            continue;
        }
        let (k0, k1) = (
            ((win.x0 - b.x1 - sx) / ax).floor() as i64,
            ((win.x1 - b.x0 - sx) / ax).ceil() as i64,
        );
        for k in k0..=k1 {
            let dx = k as f64 * ax + sx;
            if b.x1 + dx > win.x0 && b.x0 + dx < win.x1 {
                out.push((dx, dy));
            }
        }
    }
    out
}

/// Every image of every representative that shows in the window, orbit by orbit; `None`
/// for a document without symmetry.
pub fn images(doc: &FillDoc) -> Option<Vec<Image>> {
    let w = doc.wallpaper()?;
    let (x0, y0, x1, y1) = doc.bbox();
    let window = Bounds { x0, y0, x1, y1 };
    let mut out = Vec::with_capacity(doc.shapes.len() * w.order());
    for (of, sh) in doc.shapes.iter().enumerate() {
        for k in 0..w.order() {
            let shape = image_doc(&w, sh, k);
            let shifts = shifts(&w, &shape, &window);
            if !shifts.is_empty() {
                out.push(Image { of, shape, shifts });
            }
        }
    }
    Some(out)
}

/// The shapes of a symmetric fill as drawn in its window: every visible image at its place
/// (for the height map, which samples the window only); `None` without symmetry.
pub fn placed_images(doc: &FillDoc) -> Option<Vec<ShapeDoc>> {
    let shift = |sh: &ShapeDoc, (dx, dy): (f64, f64)| ShapeDoc {
        center: [sh.center[0] + dx, sh.center[1] + dy],
        vertices: sh.vertices.as_ref().map(|v| v.iter().map(|p| [p[0] + dx, p[1] + dy]).collect()),
        outlines: sh.outlines.as_ref().map(|r| shift_lines(r, (dx, dy))),
        decorations: sh.decorations.as_ref().map(|r| shift_lines(r, (dx, dy))),
        ..sh.clone()
    };
    Some(
        images(doc)?
            .into_iter()
            .flat_map(|im| im.shifts.iter().map(|&d| shift(&im.shape, d)).collect::<Vec<_>>())
            .collect(),
    )
}

/// Polylines moved by `(dx, dy)`.
fn shift_lines(lines: &[Vec<[f64; 2]>], (dx, dy): (f64, f64)) -> Vec<Vec<[f64; 2]>> {
    lines.iter().map(|v| v.iter().map(|p| [p[0] + dx, p[1] + dy]).collect()).collect()
}
