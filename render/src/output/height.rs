//! Height maps: a fill as 2.5-dimensional surface roughness (P. Bourke, *A space filling
//! algorithm for generating procedural geometry and texture*: the algorithm "for procedurally generating ... 2 dimensional textures and 2.5 dimensional texture
//! roughness"). Every shape is a raised stone on a floor of zero (the gasket, and everything
//! outside the region); its height at a point grows with the point's depth inside it (the
//! distance to its outline), and its top is as high as the stone's own half-width, so the
//! relief is as self-similar as the fill. A periodic fill gives a map that tiles seamlessly;
//! the fractal tile's map ([`render_shapes`] with the stones of its plane) repeats as the tile
//! does.
//!
//! Written as a 16-bit greyscale PNG (white is the highest stone; the text chunks say how
//! many mm that is, and give the command that reproduces the file). Each pixel is the mean of
//! a 4 x 4 grid of samples, so outlines are smooth.

use crate::error::CliError;
use crate::model::doc::{FillDoc, ShapeDoc};
#[cfg(feature = "parallel")]
use rayon::prelude::*;
use zetafill::internals::geom::{edges, point_in_poly, seg_dist2};
use zetafill::Point;

/// Samples per pixel along each axis.
const SUB: usize = 4;

/// Pixel rows rendered together by one thread.
const BAND: usize = 8;

/// The largest height map written, in pixels.
pub const MAX_PIXELS: u64 = 64_000_000;

/// The profile of a stone: its height at a point `d` inside its outline, for a stone whose
/// deepest point lies `rho` inside (dome: `sqrt(s (2 rho - s))` with `s = min(d, rho)`; cone:
/// `min(d, rho)`; flat: `rho`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relief {
    /// A round top: a circle becomes a hemisphere.
    Dome,
    /// The height is the distance to the outline: a circle becomes a cone, a polygon a
    /// hipped roof.
    Cone,
    /// A flat top as high as the stone's deepest point is deep, with sheer sides.
    Flat,
}

impl Relief {
    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Relief::Dome => "dome",
            Relief::Cone => "cone",
            Relief::Flat => "flat",
        }
    }

    /// The height at depth `d > 0` inside a stone whose deepest point is `rho` inside.
    pub fn height(self, d: f64, rho: f64) -> f64 {
        let s = d.min(rho);
        match self {
            Relief::Dome => (s * (2.0 * rho - s)).max(0.0).sqrt(),
            Relief::Cone => s,
            Relief::Flat => rho,
        }
    }
}

/// A height map too large to make: `nx` x `ny` pixels, more than [`MAX_PIXELS`] (or not a
/// finite number); `pixels` says its size was asked as the longer side in pixels, not as a
/// resolution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TooLarge {
    /// Width in pixels.
    pub nx: f64,
    /// Height in pixels.
    pub ny: f64,
    /// The size was given in pixels (else in pixels per inch).
    pub pixels: bool,
}

/// The pixel grid of a height map over a `w` x `h` box: the longer side `raster.pixels` long
/// when given, otherwise `raster.dpi` pixels per inch.
pub fn grid((w, h): (f64, f64), raster: &super::png::Raster) -> Result<(usize, usize), TooLarge> {
    let (nx, ny) = match raster.pixels {
        Some(n) => {
            let n = f64::from(n);
            if w >= h {
                (n, (n * h / w).round().max(1.0))
            } else {
                ((n * w / h).round().max(1.0), n)
            }
        }
        None => ((w / 25.4 * raster.dpi).round().max(1.0), (h / 25.4 * raster.dpi).round().max(1.0)),
    };
    if nx * ny > MAX_PIXELS as f64 || !(nx * ny).is_finite() {
        return Err(TooLarge {
            nx,
            ny,
            pixels: raster.pixels.is_some(),
        });
    }
    Ok((nx as usize, ny as usize))
}

/// One shape as the renderer sees it.
struct Stone {
    centre: Point<f64>,
    outline: Outline,
    /// Depth of the deepest point (the ring's middle, a polygon's centre).
    rho: f64,
}

enum Outline {
    Circle(f64),
    Ring(f64, f64),
    /// The vertices and the squared radius of the circle about the centre that holds them.
    Polygon(Vec<Point<f64>>, f64),
}

impl Stone {
    fn new(sh: &ShapeDoc) -> Stone {
        let centre = Point::new(sh.center[0], sh.center[1]);
        let outline = match (sh.radius, sh.inner_radius, sh.vertices.as_deref()) {
            (Some(r), None, _) => Outline::Circle(r),
            (Some(r), Some(inner), _) => Outline::Ring(r, inner),
            (None, _, vs) => {
                let vs: Vec<Point<f64>> = vs.unwrap_or(&[]).iter().map(|v| Point::new(v[0], v[1])).collect();
                let reach = vs.iter().map(|v| centre.dist2(*v)).fold(0.0, f64::max);
                Outline::Polygon(vs, reach)
            }
        };
        let mut stone = Stone { centre, outline, rho: 0.0 };
        stone.rho = match stone.outline {
            Outline::Circle(r) => r,
            Outline::Ring(r, inner) => 0.5 * (r - inner),
            Outline::Polygon(..) => stone.depth(centre).unwrap_or(0.0),
        };
        stone
    }

    /// The depth of `p` inside the stone (its distance to the outline); `None` outside or
    /// on the outline.
    fn depth(&self, p: Point<f64>) -> Option<f64> {
        let d = match &self.outline {
            Outline::Circle(r) => r - self.centre.dist2(p).sqrt(),
            Outline::Ring(r, inner) => {
                let e = self.centre.dist2(p).sqrt();
                (r - e).min(e - inner)
            }
            Outline::Polygon(vs, reach) => {
                if self.centre.dist2(p) >= *reach {
                    return None;
                }
                if !point_in_poly(p, vs) {
                    return None;
                }
                edges(vs).map(|(a, b)| seg_dist2(p, a, b)).fold(f64::MAX, f64::min).sqrt()
            }
        };
        (d > 0.0).then_some(d)
    }
}

/// The samples `k < n` of spacing `step` whose centres `(k + 0.5) step` lie in `[lo, hi]`.
fn span(lo: f64, hi: f64, step: f64, n: usize) -> Option<(usize, usize)> {
    let first = (lo / step - 0.5).ceil().max(0.0);
    let last = (hi / step - 0.5).floor().min(n as f64 - 1.0);
    (last >= first).then_some((first as usize, last as usize))
}

/// Renders the height map of `doc`: `nx` by `ny` pixels over the region's bounding box, with
/// the command that reproduces it in a text chunk.
pub fn render(doc: &FillDoc, relief: Relief, size: (usize, usize), command: &str) -> Result<Vec<u8>, CliError> {
    match crate::model::wallpaper::placed_images(doc) {
        Some(shapes) => render_shapes(&shapes, doc.bbox(), false, relief, size, command),
        None => render_shapes(&doc.shapes, doc.bbox(), doc.periodic(), relief, size, command),
    }
}

/// Renders the height map of `shapes` over the box `(x0, y0, x1, y1)`, `nx` by `ny` pixels;
/// with `periodic` (a box at the origin) the shapes' images across its edges too.
pub fn render_shapes(
    shapes: &[ShapeDoc],
    (x0, y0, x1, y1): (f64, f64, f64, f64),
    periodic: bool,
    relief: Relief,
    (nx, ny): (usize, usize),
    command: &str,
) -> Result<Vec<u8>, CliError> {
    let (w, h) = (x1 - x0, y1 - y0);
    let (sx_n, sy_n) = (SUB * nx, SUB * ny);
    let (sw, sh) = (w / sx_n as f64, h / sy_n as f64);
    // Each stone (and periodic image) with its samples: columns i0..=i1, rows j0..=j1
    // counted down from the top.
    let mut pieces = Vec::new();
    let mut stones = Vec::with_capacity(shapes.len());
    let mut top = 0.0f64;
    for shape in shapes {
        let stone = Stone::new(shape);
        top = top.max(relief.height(stone.rho, stone.rho));
        let shifts = if periodic {
            crate::model::shape_images(shape, w, h)
        } else {
            vec![(0.0, 0.0)]
        };
        let b = crate::model::shape_bounds(shape);
        let (bx0, by0, bx1, by1) = (b.x0, b.y0, b.x1, b.y1);
        let k = stones.len();
        for (dx, dy) in shifts {
            if let (Some(cols), Some(rows)) = (
                span(bx0 + dx - x0, bx1 + dx - x0, sw, sx_n),
                span(y1 - (by1 + dy), y1 - (by0 + dy), sh, sy_n),
            ) {
                pieces.push((k, (dx, dy), cols, rows));
            }
        }
        stones.push(stone);
    }
    // Bands of pixel rows, rendered in parallel; within a band the stones come in placement
    // order, so every pixel sums its samples in the same order whatever the threads.
    let band_rows = BAND * SUB;
    let mut bands: Vec<Vec<usize>> = vec![Vec::new(); ny.div_ceil(BAND)];
    for (p, &(_, _, _, (j0, j1))) in pieces.iter().enumerate() {
        for list in bands.iter_mut().take(j1 / band_rows + 1).skip(j0 / band_rows) {
            list.push(p);
        }
    }
    let mut sum = vec![0.0f64; nx * ny];
    #[cfg(feature = "parallel")]
    let rows = sum.par_chunks_mut(BAND * nx).zip(bands.par_iter()).enumerate();
    #[cfg(not(feature = "parallel"))]
    let rows = sum.chunks_mut(BAND * nx).zip(bands.iter()).enumerate();
    rows.for_each(|(b, (rows, list))| {
        let (lo, hi) = (b * band_rows, (b + 1) * band_rows - 1);
        for &p in list {
            let Some(&(k, (dx, dy), (i0, i1), (j0, j1))) = pieces.get(p) else {
                continue;
            };
            let Some(stone) = stones.get(k) else { continue };
            for j in j0.max(lo)..=j1.min(hi) {
                let y = y1 - (j as f64 + 0.5) * sh - dy;
                for i in i0..=i1 {
                    let x = x0 + (i as f64 + 0.5) * sw - dx;
                    if let Some(d) = stone.depth(Point::new(x, y)) {
                        if let Some(s) = rows.get_mut((j / SUB - b * BAND) * nx + i / SUB) {
                            *s += relief.height(d, stone.rho);
                        }
                    }
                }
            }
        }
    });
    let samples = (SUB * SUB) as f64;
    let scale = if top > 0.0 { 65535.0 / (top * samples) } else { 0.0 };
    let mut data = Vec::with_capacity(2 * nx * ny);
    for s in &sum {
        let v = (s * scale).round().clamp(0.0, 65535.0) as u16;
        data.extend_from_slice(&v.to_be_bytes());
    }
    let comment = format!(
        "height map: white (65535) is {} mm above black (0); pixels {} x {} mm",
        super::num(top, 6),
        super::num(w / nx as f64, 6),
        super::num(h / ny as f64, 6)
    );
    encode(&data, nx, ny, &comment, command)
}

/// A 16-bit greyscale PNG of big-endian samples, with its text chunks.
fn encode(data: &[u8], nx: usize, ny: usize, comment: &str, command: &str) -> Result<Vec<u8>, CliError> {
    let fail = |e: png::EncodingError| CliError::Io(format!("cannot encode PNG: {e}"));
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, nx as u32, ny as u32);
        enc.set_color(png::ColorType::Grayscale);
        enc.set_depth(png::BitDepth::Sixteen);
        enc.add_text_chunk("Software".into(), format!("zetafill {}", env!("CARGO_PKG_VERSION")))
            .map_err(fail)?;
        enc.add_text_chunk("Comment".into(), comment.into()).map_err(fail)?;
        enc.add_text_chunk("Description".into(), command.into()).map_err(fail)?;
        let mut writer = enc.write_header().map_err(fail)?;
        writer.write_image_data(data).map_err(fail)?;
        writer.finish().map_err(fail)?;
    }
    Ok(out)
}
