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

use crate::model::doc::FillDoc;
use crate::model::fill::{FillLook, LayerSpec};
use crate::model::picture::{Frame, Item, Paint, Picture, Shape};
use crate::model::{Path, Pt};
use crate::output::num;
use svg::node::element::{Circle, ClipPath, Definitions, Description, Element, Group, Line, Path as SvgPath, Polygon, Rectangle, Title};
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
    pub build: crate::model::fill::BuildOptions,
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

pub use crate::model::picture::PageLayout;

const P: usize = 4;

/// A number on the page (four decimals).
fn n(v: f64) -> String {
    num(v, P)
}

/// A closed circle as path data (two half arcs), for rings drawn as one even-odd path.
fn circle_d(f: &Frame, c: Pt, r: f64) -> String {
    let (x, y, rr) = (n(f.x(c[0] + r)), n(f.y(c[1])), n(f.len(r)));
    format!("M{x},{y} A{rr},{rr} 0 1 0 {},{y} A{rr},{rr} 0 1 0 {x},{y} Z", n(f.x(c[0] - r)))
}

/// `x,y` pairs on the page, separated by `sep`.
fn points(f: &Frame, pts: &[Pt], sep: &str) -> String {
    let body: Vec<String> = pts.iter().map(|v| format!("{},{}", n(f.x(v[0])), n(f.y(v[1])))).collect();
    body.join(sep)
}

/// Path data of path pieces (polylines and arcs) on the page.
fn path_d(paths: &[Path], f: &Frame) -> String {
    let mut parts = Vec::with_capacity(paths.len());
    for p in paths {
        match p {
            Path::Polyline { points: pts, closed } => {
                if !pts.is_empty() {
                    parts.push(format!("M{}{}", points(f, pts, " L"), if *closed { " Z" } else { "" }));
                }
            }
            Path::Arc { center, radius, sweep, .. } if sweep.abs() >= std::f64::consts::TAU => parts.push(circle_d(f, *center, *radius)),
            Path::Arc { radius, sweep, .. } => {
                let a = p.start_point();
                parts.push(format!(
                    "M{},{} {}",
                    n(f.x(a[0])),
                    n(f.y(a[1])),
                    arc_to(f, *radius, *sweep, p.end_point())
                ));
            }
        }
    }
    parts.join(" ")
}

/// An arc's path command from where the pen is to `end`.
fn arc_to(f: &Frame, radius: f64, sweep: f64, end: Pt) -> String {
    // When y is flipped on the page, a counter-clockwise arc has sweep-flag 0.
    let large = u8::from(sweep.abs() > std::f64::consts::PI);
    let flag = u8::from((sweep < 0.0) == f.flips());
    let rr = n(f.len(radius));
    format!("A{rr},{rr} 0 {large} {flag} {},{}", n(f.x(end[0])), n(f.y(end[1])))
}

/// Path data of closed loops, each a chain of pieces written as one closed subpath.
fn loops_d(loops: &[Vec<Path>], f: &Frame) -> String {
    let mut parts = Vec::with_capacity(loops.len());
    for lp in loops {
        match lp.as_slice() {
            [] => {}
            [one] if one.is_closed() => parts.push(path_d(lp, f)),
            [first, ..] => {
                let a = first.start_point();
                let mut d = format!("M{},{}", n(f.x(a[0])), n(f.y(a[1])));
                for p in lp {
                    match p {
                        Path::Polyline { points: pts, .. } => {
                            for v in pts.iter().skip(1) {
                                d.push_str(&format!(" L{},{}", n(f.x(v[0])), n(f.y(v[1]))));
                            }
                        }
                        Path::Arc { radius, sweep, .. } => {
                            d.push(' ');
                            d.push_str(&arc_to(f, *radius, *sweep, p.end_point()));
                        }
                    }
                }
                d.push_str(" Z");
                parts.push(d);
            }
        }
    }
    parts.join(" ")
}

/// Sets the paint's attributes on `e`.
fn paint<N: Node>(e: &mut N, p: &Paint) {
    if let Some(v) = &p.fill {
        e.assign("fill", v.as_str());
    }
    if let Some(v) = &p.stroke {
        e.assign("stroke", v.as_str());
    }
    if let Some(v) = p.width {
        e.assign("stroke-width", n(v));
    }
    if let Some(v) = p.cap {
        e.assign("stroke-linecap", v);
    }
    if let Some(v) = p.join {
        e.assign("stroke-linejoin", v);
    }
}

/// One item as an element (`in_clip`: inside a clip path, where the fill rule is the clip
/// rule).
fn element(item: &Item, f: &Frame, in_clip: bool) -> Element {
    let mut e: Element = match &item.shape {
        Shape::Circle { c, r } => Circle::new()
            .set("cx", n(f.x(c[0])))
            .set("cy", n(f.y(c[1])))
            .set("r", n(f.len(*r)))
            .into(),
        Shape::Polygon(vs) => Polygon::new().set("points", points(f, vs, " ")).into(),
        Shape::Path(pieces) => SvgPath::new().set("d", path_d(pieces, f)).into(),
        Shape::Loops(loops) => SvgPath::new().set("d", loops_d(loops, f)).into(),
        Shape::Line(a, b) => Line::new()
            .set("x1", n(f.x(a[0])))
            .set("y1", n(f.y(a[1])))
            .set("x2", n(f.x(b[0])))
            .set("y2", n(f.y(b[1])))
            .into(),
        Shape::Rect { corner, w, h } => {
            let mut r = Rectangle::new();
            if let Some(c) = corner {
                r = r.set("x", n(f.x(c[0]))).set("y", n(f.y(c[1])));
            }
            r.set("width", n(f.len(*w))).set("height", n(f.len(*h))).into()
        }
    };
    if item.evenodd {
        e.assign(if in_clip { "clip-rule" } else { "fill-rule" }, "evenodd");
    }
    if let Some(id) = item.id {
        e.assign("id", id);
    }
    if let Some(class) = item.class {
        e.assign("class", class);
    }
    paint(&mut e, &item.paint);
    e
}

/// Writes any picture as SVG.
pub fn write(pic: &Picture) -> Vec<u8> {
    let f = pic.to_page();
    let (page_w, page_h) = pic.page_size();
    let mut d = Document::new()
        .set("xmlns:inkscape", "http://www.inkscape.org/namespaces/inkscape")
        .set("width", format!("{}mm", n(page_w)))
        .set("height", format!("{}mm", n(page_h)))
        .set("viewBox", format!("0 0 {} {}", n(page_w), n(page_h)))
        .add(Title::new("").add(Text::new(pic.title.as_str())))
        .add(Description::new().add(Text::new(pic.desc.as_str())));
    if let Some(bg) = &pic.background {
        d = d.add(crate::output::palette::background(bg.as_str(), page_w, page_h));
    }
    if !pic.clips.is_empty() {
        let mut defs = Definitions::new();
        for c in &pic.clips {
            defs = defs.add(ClipPath::new().set("id", c.id.as_str()).add(element(&c.item, &f, true)));
        }
        d = d.add(defs);
    }
    for layer in &pic.layers {
        if layer.bare {
            for item in &layer.items {
                d.append(element(item, &f, false));
            }
            continue;
        }
        let mut g = Group::new();
        if let Some(id) = &layer.id {
            g.assign("id", id.as_str());
        }
        if let Some(label) = &layer.label {
            g.assign("inkscape:groupmode", "layer");
            g.assign("inkscape:label", label.as_str());
        }
        paint(&mut g, &layer.paint);
        if let Some(clip) = &layer.clip {
            g.assign("clip-path", format!("url(#{clip})"));
        }
        for item in &layer.items {
            g.append(element(item, &f, false));
        }
        d = d.add(g);
    }
    let mut s = d.to_string();
    s.push('\n');
    s.into_bytes()
}

/// The `zetafill fill` command line that reproduces the document.
pub fn command_line(doc: &FillDoc) -> String {
    let p = &doc.params;
    let region = doc.region.arg();
    let mut s = format!(
        "zetafill fill --shape {}{} --rotate {} --region {}{} --c {} --n-offset {} --gap {} --max-trials {} --seed {} --sampler {}{}",
        p.of.shape,
        p.of.mix_order.map_or_else(String::new, |m| format!(" --mix-order {m}")),
        p.of.rotate,
        region,
        if doc.periodic() { " --periodic" } else { "" },
        p.c,
        p.n_offset,
        p.gap,
        p.max_trials,
        p.seed,
        p.of.sampler,
        if p.of.scalar == "f64" { "" } else { " --scalar fixed" }
    );
    if let Some(n) = p.of.cells {
        s.push_str(&format!(" --cells {n}"));
    }
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

/// The fill's picture for these options: layers by size band or by colour, and the periodic
/// images cut exactly to the tile.
pub fn picture(doc: &FillDoc, opt: &SvgOptions) -> Picture {
    let (layers, layer_of) = match (&opt.colour_layers, opt.layers) {
        (Some(palette), _) => LayerSpec::colours(palette, opt.colours.as_deref().unwrap_or(&[])),
        (None, Some(k)) => {
            let (bands, widths) = size_bands(doc, k);
            let labels = widths.iter().enumerate().map(|(i, wd)| LayerSpec {
                label: match wd {
                    Some((hi, lo)) => format!("{} widths {}-{} mm", i + 1, num(*hi, 3), num(*lo, 3)),
                    None => format!("{} (empty)", i + 1),
                },
                pen: None,
            });
            (labels.collect(), bands)
        }
        (None, None) => (Vec::new(), Vec::new()),
    };
    let look = FillLook {
        filled: opt.style == Style::Filled,
        pen_width: opt.pen_width,
        boundary: opt.boundary,
        page: opt.page,
        build: opt.build,
        colours: opt.colours.clone(),
        background: opt.background.clone(),
        layers,
        layer_of,
    };
    let mut pic = crate::model::fill::picture(doc, &look);
    let p = &doc.params;
    pic.title = format!(
        "zetafill: {} {}, c = {}, N = {}, seed {}",
        doc.shapes.len(),
        p.of.shape,
        p.c,
        p.n_offset,
        p.seed
    );
    pic.desc = format!("{}{}", command_line(doc), opt.flags);
    pic
}

/// Renders a fill as SVG.
pub fn render(doc: &FillDoc, opt: &SvgOptions) -> Vec<u8> {
    write(&picture(doc, opt))
}
