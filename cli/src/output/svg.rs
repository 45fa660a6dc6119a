//! SVG output in physical units: `width`/`height` in mm with a matching `viewBox`, so one user
//! unit is one millimetre. The region's frame has y up; SVG has y down, so every y is written
//! as `H - y` (no transform, which keeps the file simple for plotter tools). Numbers have four
//! decimals (0.1 µm). The parameters and seed are in `<title>` and `<desc>`; there is no
//! timestamp, so the same run gives the same bytes.
//!
//! For plotters, [`SvgOptions::page`] puts the drawing on a page (`--page`, margins,
//! `--center`, `--fit`) and [`SvgOptions::layers`] splits the shapes into Inkscape layers by
//! size band (`--layers size-bands:K`, one pen per layer). [`SvgOptions::colours`] paints
//! each shape in its own colour (`--palette`) and [`SvgOptions::background`] lays a colour
//! behind the drawing. Without them the output is exactly the region-sized drawing above
//! (the gallery pins it byte for byte).

use crate::model::doc::{FillDoc, RegionDoc, ShapeDoc};
use crate::output::num;
use svg::node::element::{Circle, ClipPath, Definitions, Description, Group, Path, Polygon, Rectangle, Title};
use svg::node::Text;
use svg::{Document, Node};

/// How shapes are painted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// Stroke-only outlines (pen plotters, laser cutting).
    Outline,
    /// Filled shapes without stroke (screens, prints).
    Filled,
}

impl Style {
    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Style::Outline => "outline",
            Style::Filled => "filled",
        }
    }
}

/// SVG options.
#[derive(Debug, Clone)]
pub struct SvgOptions {
    /// Painting style.
    pub style: Style,
    /// Stroke width in mm for outlines.
    pub pen_width: f64,
    /// Draw the region's outline too.
    pub boundary: bool,
    /// A page to place the drawing on (`--page`); `None`: the page is the region's box.
    pub page: Option<PageLayout>,
    /// `Some(K)`: the shapes in K Inkscape layers by size, largest first (`--layers`).
    pub layers: Option<u32>,
    /// Hatching, outlines left out (`--hatch-only`), shapes narrower than the pen left out.
    pub build: crate::output::drawing::BuildOptions,
    /// The drawing flags given (page, layers, hatching, style, ...), written after the fill's
    /// command line in `<desc>` so that it reproduces the file.
    pub flags: String,
    /// Each shape's colour (`--palette`): its fill, or its stroke for outlines; `None`:
    /// black.
    pub colours: Option<Vec<crate::output::palette::Colour>>,
    /// A rectangle of this colour behind everything (`--background`).
    pub background: Option<crate::output::palette::Colour>,
    /// `Some(palette)`: the shapes in one Inkscape layer per palette colour, in its order
    /// (`--layers colours`), each shape in the layer of its colour.
    pub colour_layers: Option<Vec<crate::output::palette::Colour>>,
}

/// Where the drawing goes on a page: page point = `scale * p + (dx, dy)` for a region point
/// `p`, in a page frame with y up from the page's bottom edge (the SVG flips it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageLayout {
    /// Page width in mm.
    pub width: f64,
    /// Page height in mm.
    pub height: f64,
    /// Scale (1 unless `--fit`).
    pub scale: f64,
    /// Shift in x (mm).
    pub dx: f64,
    /// Shift in y (mm, y up).
    pub dy: f64,
}

const P: usize = 4;

/// The page frame: SVG x = ox + s (x - x0), SVG y = oy + s (y1 - y) (y flipped about the
/// region's top). Without a page, s = 1 and ox = oy = 0.
#[derive(Debug, Clone, Copy)]
struct Frame {
    x0: f64,
    y1: f64,
    s: f64,
    ox: f64,
    oy: f64,
}

impl Frame {
    fn x(&self, x: f64) -> String {
        num(self.ox + self.s * (x - self.x0), P)
    }
    fn y(&self, y: f64) -> String {
        num(self.oy + self.s * (self.y1 - y), P)
    }
    fn len(&self, r: f64) -> String {
        num(self.s * r, P)
    }
}

/// A closed circle as path data (two half arcs), for rings drawn as one even-odd path.
fn circle_d(f: &Frame, cx: f64, cy: f64, r: f64) -> String {
    format!(
        "M{},{} A{},{} 0 1 0 {},{} A{},{} 0 1 0 {},{} Z",
        f.x(cx + r),
        f.y(cy),
        f.len(r),
        f.len(r),
        f.x(cx - r),
        f.y(cy),
        f.len(r),
        f.len(r),
        f.x(cx + r),
        f.y(cy)
    )
}

fn ring_d(f: &Frame, pts: &[[f64; 2]]) -> String {
    let body: Vec<String> = pts.iter().map(|v| format!("{},{}", f.x(v[0]), f.y(v[1]))).collect();
    format!("M{} Z", body.join(" L"))
}

/// Path data of plot paths (polylines and arcs, region frame) on the page.
fn plot_d(paths: &[crate::model::Path], f: &Frame) -> String {
    use crate::model::Path as P2;
    let mut parts = Vec::new();
    for p in paths {
        match p {
            P2::Polyline { points, closed } => {
                let body: Vec<String> = points.iter().map(|v| format!("{},{}", f.x(v[0]), f.y(v[1]))).collect();
                if !body.is_empty() {
                    parts.push(format!("M{}{}", body.join(" L"), if *closed { " Z" } else { "" }));
                }
            }
            P2::Arc { center, radius, sweep, .. } if sweep.abs() >= std::f64::consts::TAU => {
                parts.push(circle_d(f, center[0], center[1], *radius))
            }
            P2::Arc { radius, sweep, .. } => {
                let (a, b) = (p.start_point(), p.end_point());
                // y is flipped on the page: a counter-clockwise arc has sweep-flag 0.
                let large = u8::from(sweep.abs() > std::f64::consts::PI);
                let flag = u8::from(*sweep < 0.0);
                parts.push(format!(
                    "M{},{} A{},{} 0 {large} {flag} {},{}",
                    f.x(a[0]),
                    f.y(a[1]),
                    f.len(*radius),
                    f.len(*radius),
                    f.x(b[0]),
                    f.y(b[1])
                ));
            }
        }
    }
    parts.join(" ")
}

/// A periodic image cut exactly to the tile (for plotter tools that ignore `clip-path`):
/// `None` when the image lies inside the tile and is drawn as it is.
fn clipped_node(
    sh: &ShapeDoc,
    dx: f64,
    dy: f64,
    w: f64,
    h: f64,
    f: &Frame,
    min_feature: f64,
) -> Option<Option<svg::node::element::Element>> {
    use crate::model::{clip_path, Bounds, Path as P2};
    let tile = Bounds {
        x0: 0.0,
        y0: 0.0,
        x1: w,
        y1: h,
    };
    let b = crate::model::shape_bounds(sh);
    if (Bounds {
        x0: b.x0 + dx,
        y0: b.y0 + dy,
        x1: b.x1 + dx,
        y1: b.y1 + dy,
    })
    .inside(&tile, 0.0)
    {
        return None;
    }
    let c = [sh.center[0] + dx, sh.center[1] + dy];
    let outlines: Vec<P2> = match (sh.radius, sh.inner_radius) {
        (Some(r), inner) => std::iter::once(r)
            .chain(hole(inner, min_feature))
            .map(|r| P2::circle(c, r))
            .collect(),
        _ => vec![P2::polyline(
            sh.vertices
                .as_deref()
                .unwrap_or(&[])
                .iter()
                .map(|v| [v[0] + dx, v[1] + dy])
                .collect(),
            true,
        )],
    };
    let pieces: Vec<P2> = outlines.iter().flat_map(|p| clip_path(p, &tile)).collect();
    let d = plot_d(&pieces, f);
    Some((!d.is_empty()).then(|| Path::new().set("d", d).into()))
}

/// A ring's hole, unless it is narrower than `min_feature` (then the ring is drawn as a disc,
/// as the G-code does).
fn hole(inner: Option<f64>, min_feature: f64) -> Option<f64> {
    inner.filter(|&ri| ri > 0.0 && 2.0 * ri >= min_feature)
}

/// The hatch lines of one image of a shape as one path (cut to the `w` x `h` tile when
/// `tile`), or none when no line crosses it.
fn hatch_node(
    sh: &ShapeDoc,
    off: (f64, f64),
    opt: &SvgOptions,
    tile: Option<(f64, f64)>,
    f: &Frame,
) -> Option<svg::node::element::Element> {
    use crate::model::{clip_path, Bounds, Path as P2};
    let h = opt.build.hatch?;
    let lines = h
        .shape(sh, off, opt.build.min_feature)
        .into_iter()
        .map(|[a, b]| P2::polyline(vec![a, b], false));
    let paths: Vec<P2> = match tile {
        Some((w, h)) => {
            let t = Bounds {
                x0: 0.0,
                y0: 0.0,
                x1: w,
                y1: h,
            };
            lines.flat_map(|p| clip_path(&p, &t)).collect()
        }
        None => lines.collect(),
    };
    let d = plot_d(&paths, f);
    (!d.is_empty()).then(|| Path::new().set("class", "hatch").set("d", d).into())
}

fn shape_node(sh: &ShapeDoc, dx: f64, dy: f64, f: &Frame, min_feature: f64) -> Option<svg::node::element::Element> {
    let (cx, cy) = (sh.center[0] + dx, sh.center[1] + dy);
    match (sh.radius, hole(sh.inner_radius, min_feature)) {
        (Some(r), Some(inner)) => {
            let d = format!("{} {}", circle_d(f, cx, cy, r), circle_d(f, cx, cy, inner));
            return Some(Path::new().set("d", d).set("fill-rule", "evenodd").into());
        }
        (Some(r), None) => {
            return Some(Circle::new().set("cx", f.x(cx)).set("cy", f.y(cy)).set("r", f.len(r)).into());
        }
        _ => {}
    }
    let vs = sh.vertices.as_ref()?;
    let pts: Vec<String> = vs.iter().map(|v| format!("{},{}", f.x(v[0] + dx), f.y(v[1] + dy))).collect();
    Some(Polygon::new().set("points", pts.join(" ")).into())
}

/// The region's outline as one path (even-odd for holes).
fn region_node(doc: &FillDoc, f: &Frame) -> Path {
    let d = match &doc.region {
        RegionDoc::Rect { width, height, .. } => ring_d(f, &[[0.0, 0.0], [*width, 0.0], [*width, *height], [0.0, *height]]),
        RegionDoc::Circle { center, radius } => circle_d(f, center[0], center[1], *radius),
        RegionDoc::Annulus {
            center,
            radius_outer,
            radius_inner,
        } => {
            format!(
                "{} {}",
                circle_d(f, center[0], center[1], *radius_outer),
                circle_d(f, center[0], center[1], *radius_inner)
            )
        }
        RegionDoc::Polygon { vertices, holes, outers } => {
            let all: Vec<String> = std::iter::once(vertices).chain(outers).chain(holes).map(|r| ring_d(f, r)).collect();
            all.join(" ")
        }
    };
    Path::new().set("id", "boundary").set("d", d).set("fill-rule", "evenodd")
}

/// The `zetafill fill` command line that reproduces the document.
pub fn command_line(doc: &FillDoc) -> String {
    let p = &doc.params;
    let region = doc.region.arg();
    let mut s = format!(
        "zetafill fill --shape {}{} --rotate {} --region {}{} --c {} --n-offset {} --gap {} --max-trials {} --seed {} --sampler {}{}",
        p.shape,
        p.mix_order.map_or_else(String::new, |m| format!(" --mix-order {m}")),
        p.rotate,
        region,
        if doc.periodic() { " --periodic" } else { "" },
        p.c,
        p.n_offset,
        p.gap,
        p.max_trials,
        p.seed,
        p.sampler,
        if p.scalar == "f64" { "" } else { " --scalar fixed" }
    );
    if let Some(k) = p.count {
        s.push_str(&format!(" --count {k}"));
    }
    if let Some(f) = p.fill {
        s.push_str(&format!(" --fill {f}"));
    }
    if let Some(m) = p.min_size {
        s.push_str(&format!(" --min-size {m}"));
    }
    s
}

/// The size band (0 = largest) of each shape when the shapes are split into `k` bands of
/// equal width in log(area), and each band's (largest, smallest) shape width in mm.
pub fn size_bands(doc: &FillDoc, k: u32) -> (Vec<usize>, Vec<Option<(f64, f64)>>) {
    let k = k.max(1) as usize;
    let areas: Vec<f64> = doc.shapes.iter().map(|s| s.area).collect();
    let bands = crate::output::palette::log_bands(&areas, k);
    let mut widths: Vec<Option<(f64, f64)>> = vec![None; k];
    for (s, &b) in doc.shapes.iter().zip(&bands) {
        let w = crate::model::shape_width(s);
        if let Some(slot) = widths.get_mut(b) {
            *slot = Some(match *slot {
                Some((hi, lo)) => (hi.max(w), lo.min(w)),
                None => (w, w),
            });
        }
    }
    (bands, widths)
}

/// Renders a fill as SVG.
pub fn render(doc: &FillDoc, opt: &SvgOptions) -> Vec<u8> {
    let (w, h) = doc.extent();
    let (x0, _, _, y1) = doc.bbox();
    let (frame, page_w, page_h) = match opt.page {
        None => (
            Frame {
                x0,
                y1,
                s: 1.0,
                ox: 0.0,
                oy: 0.0,
            },
            w,
            h,
        ),
        Some(pg) => {
            let ox = pg.scale * x0 + pg.dx;
            let oy = pg.height - pg.scale * y1 - pg.dy;
            (
                Frame {
                    x0,
                    y1,
                    s: pg.scale,
                    ox,
                    oy,
                },
                pg.width,
                pg.height,
            )
        }
    };
    let style = |g: Group| match opt.style {
        Style::Outline => g
            .set("fill", "none")
            .set("stroke", "black")
            .set("stroke-width", num(opt.pen_width, P)),
        Style::Filled => g.set("fill", "black").set("stroke", "none"),
    };
    // One group, one Inkscape layer per size band (largest shapes first), or one per colour.
    let layer = |i: usize, label: String| {
        style(
            Group::new()
                .set("id", format!("layer{}", i + 1))
                .set("inkscape:groupmode", "layer")
                .set("inkscape:label", label),
        )
    };
    let (bands, mut groups): (Vec<usize>, Vec<Group>) = match (&opt.colour_layers, opt.layers) {
        (Some(palette), _) => {
            let of = |k: usize| crate::output::palette::layer_of(palette, opt.colours.as_ref().and_then(|cs| cs.get(k)));
            let groups = crate::output::palette::colour_layers(&style(Group::new()), palette);
            ((0..doc.shapes.len()).map(of).collect(), groups)
        }
        (None, Some(k)) => {
            let (bands, widths) = size_bands(doc, k);
            let groups = widths
                .iter()
                .enumerate()
                .map(|(i, wd)| {
                    let label = match wd {
                        Some((hi, lo)) => format!("{} widths {}-{} mm", i + 1, num(*hi, 3), num(*lo, 3)),
                        None => format!("{} (empty)", i + 1),
                    };
                    layer(i, label)
                })
                .collect();
            (bands, groups)
        }
        (None, None) => (vec![0; doc.shapes.len()], vec![style(Group::new().set("id", "shapes"))]),
    };
    let periodic = doc.periodic();
    // Plotter output (a page or layers) of a periodic outline fill: images cut exactly to the
    // tile, since vpype and plotter drivers ignore clip-path. Otherwise a clip-path.
    let layered = opt.layers.is_some() || opt.colour_layers.is_some();
    let geometric_clip = periodic && opt.style == Style::Outline && (opt.page.is_some() || layered);
    let min_feature = opt.build.min_feature;
    let paint = if opt.style == Style::Filled { "fill" } else { "stroke" };
    for (k, (sh, &band)) in doc.shapes.iter().zip(&bands).enumerate() {
        if min_feature > 0.0 && crate::model::shape_width(sh) < min_feature {
            continue;
        }
        let colour = opt.colours.as_ref().and_then(|c| c.get(k));
        let offs = if periodic {
            crate::model::shape_images(sh, w, h)
        } else {
            vec![(0.0, 0.0)]
        };
        for (dx, dy) in offs {
            let outline = if opt.build.no_outline {
                None
            } else {
                match geometric_clip
                    .then(|| clipped_node(sh, dx, dy, w, h, &frame, min_feature))
                    .flatten()
                {
                    Some(clipped) => clipped,
                    None => shape_node(sh, dx, dy, &frame, min_feature),
                }
            };
            let hatch = hatch_node(sh, (dx, dy), opt, geometric_clip.then_some((w, h)), &frame);
            for mut n in outline.into_iter().chain(hatch) {
                if let Some(c) = colour {
                    n.assign(paint, c.as_str());
                }
                let g = std::mem::take(&mut groups[band]);
                groups[band] = g.add(n);
            }
        }
    }
    let p = &doc.params;
    let mut d = Document::new()
        .set("xmlns:inkscape", "http://www.inkscape.org/namespaces/inkscape")
        .set("width", format!("{}mm", num(page_w, P)))
        .set("height", format!("{}mm", num(page_h, P)))
        .set("viewBox", format!("0 0 {} {}", num(page_w, P), num(page_h, P)))
        .add(Title::new("").add(Text::new(format!(
            "zetafill: {} {}, c = {}, N = {}, seed {}",
            doc.shapes.len(),
            p.shape,
            p.c,
            p.n_offset,
            p.seed
        ))))
        .add(Description::new().add(Text::new(format!("{}{}", command_line(doc), opt.flags))));
    if let Some(bg) = &opt.background {
        d = d.add(crate::output::palette::background(bg.as_str(), page_w, page_h));
    }
    if periodic && !geometric_clip {
        // Images of edge-crossing shapes tile seamlessly; the clip keeps the tile's bounds.
        let mut rect = Rectangle::new();
        if opt.page.is_some() {
            rect = rect.set("x", frame.x(x0)).set("y", frame.y(y1));
        }
        let clip = ClipPath::new()
            .set("id", "region")
            .add(rect.set("width", frame.len(w)).set("height", frame.len(h)));
        d = d.add(Definitions::new().add(clip));
        groups = groups.into_iter().map(|g| g.set("clip-path", "url(#region)")).collect();
    }
    for g in groups {
        d = d.add(g);
    }
    if opt.boundary {
        let b = region_node(doc, &frame)
            .set("fill", "none")
            .set("stroke", "black")
            .set("stroke-width", num(opt.pen_width, P));
        d = d.add(b);
    }
    let mut s = d.to_string();
    s.push('\n');
    s.into_bytes()
}
