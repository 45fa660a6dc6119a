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

use crate::model::doc::{FillDoc, RegionDoc};
use crate::model::fill::{FillLook, LayerSpec};
use crate::model::picture::{Frame, Item, Layer, Paint, Picture, Shape};
use crate::model::{Path, Pt};
use crate::output::{num, number};
use ::svg::node::element::{ClipPath, Definitions, Description, Element, Group, Rectangle, Title};
use ::svg::node::Text;
use ::svg::{Document, Node};

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

/// Decimals of every number on the page (0.1 µm).
pub const PLACES: usize = 4;

/// Appends a number on the page.
pub type Num = fn(&mut String, f64);

/// A number on the page: at most [`PLACES`] decimals, no trailing zeros, never `-0`.
fn n(out: &mut String, v: f64) {
    number::push_fixed(out, v, PLACES);
}

/// `x,y` on the page.
fn xy(out: &mut String, f: &Frame, v: Pt, n: Num) {
    n(out, f.x(v[0]));
    out.push(',');
    n(out, f.y(v[1]));
}

/// A closed circle as path data (two half arcs), for rings drawn as one even-odd path.
fn circle_d(out: &mut String, f: &Frame, c: Pt, r: f64, n: Num) {
    out.push('M');
    let start = out.len();
    xy(out, f, [c[0] + r, c[1]], n);
    let first = out.get(start..).unwrap_or("").to_string();
    let mut arc = String::with_capacity(32);
    arc.push_str(" A");
    n(&mut arc, f.len(r));
    arc.push(',');
    n(&mut arc, f.len(r));
    arc.push_str(" 0 1 0 ");
    out.push_str(&arc);
    n(out, f.x(c[0] - r));
    out.push(',');
    n(out, f.y(c[1]));
    out.push_str(&arc);
    out.push_str(&first);
    out.push_str(" Z");
}

/// `x,y` pairs on the page, separated by `sep`.
fn points(out: &mut String, f: &Frame, pts: &[Pt], sep: &str, n: Num) {
    for (i, v) in pts.iter().enumerate() {
        if i > 0 {
            out.push_str(sep);
        }
        xy(out, f, *v, n);
    }
}

/// Path data of path pieces (polylines and arcs) on the page.
fn path_d(out: &mut String, paths: &[Path], f: &Frame, n: Num) {
    let mut first = true;
    for p in paths {
        let sep = |out: &mut String, first: &mut bool| {
            if !std::mem::take(first) {
                out.push(' ');
            }
        };
        match p {
            Path::Polyline { points: pts, closed } => {
                if !pts.is_empty() {
                    sep(out, &mut first);
                    out.push('M');
                    points(out, f, pts, " L", n);
                    if *closed {
                        out.push_str(" Z");
                    }
                }
            }
            Path::Arc { center, radius, sweep, .. } if sweep.abs() >= std::f64::consts::TAU => {
                sep(out, &mut first);
                circle_d(out, f, *center, *radius, n);
            }
            Path::Arc { radius, sweep, .. } => {
                sep(out, &mut first);
                out.push('M');
                xy(out, f, p.start_point(), n);
                out.push(' ');
                arc_to(out, f, *radius, *sweep, p.end_point(), n);
            }
        }
    }
}

/// An arc's path command from where the pen is to `end`.
fn arc_to(out: &mut String, f: &Frame, radius: f64, sweep: f64, end: Pt, n: Num) {
    // When y is flipped on the page, a counter-clockwise arc has sweep-flag 0.
    let large = sweep.abs() > std::f64::consts::PI;
    let flag = (sweep < 0.0) == f.flips();
    out.push('A');
    n(out, f.len(radius));
    out.push(',');
    n(out, f.len(radius));
    out.push_str(if large { " 0 1 " } else { " 0 0 " });
    out.push_str(if flag { "1 " } else { "0 " });
    xy(out, f, end, n);
}

/// Path data of closed loops, each a chain of pieces written as one closed subpath.
fn loops_d(out: &mut String, loops: &[Vec<Path>], f: &Frame, n: Num) {
    let mut first = true;
    for lp in loops {
        if lp.is_empty() {
            continue;
        }
        if !std::mem::take(&mut first) {
            out.push(' ');
        }
        match lp.as_slice() {
            [one] if one.is_closed() => path_d(out, lp, f, n),
            _ => {
                if let Some(head) = lp.first() {
                    out.push('M');
                    xy(out, f, head.start_point(), n);
                }
                for p in lp {
                    match p {
                        Path::Polyline { points: pts, .. } => {
                            for v in pts.iter().skip(1) {
                                out.push_str(" L");
                                xy(out, f, *v, n);
                            }
                        }
                        Path::Arc { radius, sweep, .. } => {
                            out.push(' ');
                            arc_to(out, f, *radius, *sweep, p.end_point(), n);
                        }
                    }
                }
                out.push_str(" Z");
            }
        }
    }
}

/// What receives an element's attributes: an element of the `svg` crate, or the list of them
/// gathered before their element exists.
pub trait Attributes {
    /// Sets attribute `name` to the text `value` appends.
    fn set(&mut self, name: &'static str, value: impl FnOnce(&mut String));

    /// Sets attribute `name` to `value`.
    fn text(&mut self, name: &'static str, value: &str) {
        self.set(name, |s| s.push_str(value));
    }
}

/// Sets the paint's attributes.
pub fn paint(e: &mut impl Attributes, p: &Paint, n: Num) {
    if let Some(v) = &p.fill {
        e.text("fill", v);
    }
    if let Some(v) = &p.stroke {
        e.text("stroke", v);
    }
    if let Some(v) = p.width {
        e.set("stroke-width", |s| n(s, v));
    }
    if let Some(v) = p.cap {
        e.text("stroke-linecap", v);
    }
    if let Some(v) = p.join {
        e.text("stroke-linejoin", v);
    }
}

/// One item's tag and attributes (`in_clip`: inside a clip path, where the fill rule is the
/// clip rule).
pub fn item(e: &mut impl Attributes, item: &Item, f: &Frame, in_clip: bool, n: Num) -> &'static str {
    let tag = match &item.shape {
        Shape::Circle { c, r } => {
            e.set("cx", |s| n(s, f.x(c[0])));
            e.set("cy", |s| n(s, f.y(c[1])));
            e.set("r", |s| n(s, f.len(*r)));
            "circle"
        }
        Shape::Polygon(vs) => {
            e.set("points", |s| points(s, f, vs, " ", n));
            "polygon"
        }
        Shape::Path(pieces) => {
            e.set("d", |s| path_d(s, pieces, f, n));
            "path"
        }
        Shape::Loops(loops) => {
            e.set("d", |s| loops_d(s, loops, f, n));
            "path"
        }
        Shape::Line(a, b) => {
            e.set("x1", |s| n(s, f.x(a[0])));
            e.set("y1", |s| n(s, f.y(a[1])));
            e.set("x2", |s| n(s, f.x(b[0])));
            e.set("y2", |s| n(s, f.y(b[1])));
            "line"
        }
        Shape::Rect { corner, w, h } => {
            if let Some(c) = corner {
                e.set("x", |s| n(s, f.x(c[0])));
                e.set("y", |s| n(s, f.y(c[1])));
            }
            e.set("width", |s| n(s, f.len(*w)));
            e.set("height", |s| n(s, f.len(*h)));
            "rect"
        }
    };
    if item.evenodd {
        e.text(if in_clip { "clip-rule" } else { "fill-rule" }, "evenodd");
    }
    if let Some(id) = item.id {
        e.text("id", id);
    }
    if let Some(class) = item.class {
        e.text("class", class);
    }
    paint(e, &item.paint, n);
    tag
}

/// The page's size and `viewBox` (the document's own attributes).
pub fn page(e: &mut impl Attributes, page_w: f64, page_h: f64, n: Num) {
    e.text("xmlns", "http://www.w3.org/2000/svg");
    e.text("xmlns:inkscape", "http://www.inkscape.org/namespaces/inkscape");
    e.set("width", |s| {
        n(s, page_w);
        s.push_str("mm");
    });
    e.set("height", |s| {
        n(s, page_h);
        s.push_str("mm");
    });
    e.set("viewBox", |s| {
        s.push_str("0 0 ");
        n(s, page_w);
        s.push(' ');
        n(s, page_h);
    });
}

/// A background rectangle of `colour` over the page, before the shapes.
pub fn background(e: &mut impl Attributes, colour: &str, page_w: f64, page_h: f64, n: Num) {
    e.text("id", "background");
    e.set("width", |s| n(s, page_w));
    e.set("height", |s| n(s, page_h));
    e.text("fill", colour);
}

/// A layer's group attributes.
pub fn group(e: &mut impl Attributes, layer: &Layer, n: Num) {
    if let Some(id) = &layer.id {
        e.text("id", id);
    }
    if let Some(label) = &layer.label {
        e.text("inkscape:groupmode", "layer");
        e.text("inkscape:label", label);
    }
    paint(e, &layer.paint, n);
    if let Some(clip) = &layer.clip {
        e.set("clip-path", |s| {
            s.push_str("url(#");
            s.push_str(clip);
            s.push(')');
        });
    }
}

/// An `svg` crate node receiving attributes.
struct Crate<'a, N: Node>(&'a mut N);

impl<N: Node> Attributes for Crate<'_, N> {
    fn set(&mut self, name: &'static str, value: impl FnOnce(&mut String)) {
        let mut s = String::new();
        value(&mut s);
        self.0.assign(name, s);
    }
}

/// Attributes gathered before their element exists.
struct Pairs(Vec<(&'static str, String)>);

impl Attributes for Pairs {
    fn set(&mut self, name: &'static str, value: impl FnOnce(&mut String)) {
        let mut s = String::new();
        value(&mut s);
        self.0.push((name, s));
    }
}

/// Writes any picture as SVG: a tree of `svg` crate elements, printed by it.
pub fn write(pic: &Picture) -> Vec<u8> {
    write_with(pic, n)
}

/// [`write`], with the numbers on the page written by `n`.
#[doc(hidden)]
pub fn write_with(pic: &Picture, n: Num) -> Vec<u8> {
    let mut s = document(pic, n).to_string();
    s.push('\n');
    s.into_bytes()
}

/// Any picture as SVG, ready to be streamed: the tree of elements is built once and printed
/// straight into the destination (its size is counted by printing it into a
/// [`Counter`](super::stream::Counter) first, which costs little beside building it).
pub fn output(pic: &Picture) -> Result<super::stream::Output<'static>, crate::error::CliError> {
    use super::stream::{io_error, Counter, Output, Size};
    use std::io::Write as _;
    let d = document(pic, n);
    let mut c = Counter(0);
    writeln!(c, "{d}").map_err(io_error)?;
    Ok(Output::stream(Size::Exact(c.0), move |w| writeln!(w, "{d}").map_err(io_error)))
}

/// The tree of `svg` crate elements of a picture.
fn document(pic: &Picture, n: Num) -> Document {
    let f = pic.to_page();
    let (page_w, page_h) = pic.page_size();
    let element = |it, in_clip| {
        let mut pairs = Pairs(Vec::new());
        let mut e = Element::new(item(&mut pairs, it, &f, in_clip, n));
        for (k, v) in pairs.0 {
            e.assign(k, v);
        }
        e
    };
    let mut d = Document::new();
    page(&mut Crate(&mut d), page_w, page_h, n);
    d = d
        .add(Title::new("").add(Text::new(pic.title.as_str())))
        .add(Description::new().add(Text::new(pic.desc.as_str())));
    if let Some(bg) = &pic.background {
        let mut r = Rectangle::new();
        background(&mut Crate(&mut r), bg, page_w, page_h, n);
        d = d.add(r);
    }
    if !pic.clips.is_empty() {
        let mut defs = Definitions::new();
        for c in &pic.clips {
            defs = defs.add(ClipPath::new().set("id", c.id.as_str()).add(element(&c.item, true)));
        }
        d = d.add(defs);
    }
    for layer in &pic.layers {
        if layer.bare {
            for it in &layer.items {
                d.append(element(it, false));
            }
            continue;
        }
        let mut g = Group::new();
        group(&mut Crate(&mut g), layer, n);
        for it in &layer.items {
            g.append(element(it, false));
        }
        d = d.add(g);
    }
    d
}

/// The `zetafill fill` command line that reproduces the document.
pub fn command_line(doc: &FillDoc) -> String {
    let p = &doc.params;
    // A region made from a picture or a text is named by its input (and that input's digest);
    // any other travels as its rings.
    // A symmetric fill names its group and lattice, then its cells or the region it is cut to.
    let symmetry = match &doc.region {
        RegionDoc::Wallpaper { group, repeat, .. } => {
            let lattice = doc
                .wallpaper()
                .map(|w| crate::model::wallpaper::lattice_arg(&w))
                .unwrap_or_default();
            let cells = repeat.map_or_else(String::new, |r| format!(" --repeat {}:{}", r[0], r[1]));
            format!(" --symmetry {group} --lattice {lattice}{cells}")
        }
        _ => String::new(),
    };
    let region = match (&p.of.source, &doc.region) {
        (Some(src), _) => format!(" --region {}{}", crate::model::region::shell_word(&src.region), src.flags()),
        (None, RegionDoc::Wallpaper { window: None, .. }) => String::new(),
        (None, r) => format!(" --region {}", r.arg()),
    };
    let region = symmetry + &region;
    let mut s = format!(
        "zetafill fill --shape {}{} --rotate {}{}{} --c {} --n-offset {} --gap {} --max-trials {} --seed {} --sampler {}{}",
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
    if let Some(n) = p.of.batch {
        s.push_str(&format!(" --batch {n}"));
    }
    if let Some(d) = &p.of.density {
        s.push_str(&format!(" --density {d}"));
    }
    if let Some(h) = &p.of.density_sha256 {
        s.push_str(&format!(" --density-sha256 {h}"));
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
