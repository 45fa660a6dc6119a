//! How a 1D fill is drawn: its [`Picture`] for SVG and PNG (dashes, circles, bars or zoom
//! rows), the plotter variant the G-code is written from (y up, one whole circle per
//! wrapping segment, hatching, `--min-feature`), and the command line that reproduces them.

use super::doc::{LineDoc, SegmentDoc};
use crate::error::CliError;
use crate::model::{Bounds, Item, Layer, Paint, Picture, Shape};
use crate::output::svg::Style;
use crate::plan::line::{no_zoom_gcode, LineLook, Render};
use std::fmt::Write as _;

/// Drawn sizes below this (mm) round to zero at four decimals and are left out of the SVG.
const INVISIBLE: f64 = 0.5e-4;

/// SVG options of the 1D renders.
#[derive(Debug, Clone)]
pub struct LineSvgOptions {
    /// How the segments are drawn.
    pub look: LineLook,
    /// Each segment's colour (its stroke, or its fill for bars and filled circles); black
    /// without.
    pub colours: Option<Vec<crate::output::palette::Colour>>,
    /// A colour behind the drawing.
    pub background: Option<crate::output::palette::Colour>,
    /// The colour flags, as a command that reproduces the drawing writes them.
    pub colour_flags: String,
    /// `Some(palette)`: the segments in one Inkscape layer per palette colour, in its order
    /// (`--layers colours`).
    pub colour_layers: Option<Vec<crate::output::palette::Colour>>,
}

/// The pieces `[a, b]` of a segment inside `[0, L]`: itself, or, when it wraps past L in a
/// periodic interval, its two parts.
fn pieces(s: &SegmentDoc, l: f64, periodic: bool) -> Vec<(f64, f64)> {
    let end = s.start + s.length;
    if periodic && end > l {
        vec![(s.start, l), (0.0, end - l)]
    } else {
        vec![(s.start, end)]
    }
}

/// The drawing flags of `opt` as command-line text (each with a leading space): with
/// [`command_line`], the command that reproduces a drawing.
pub(crate) fn drawing_flags(opt: &LineSvgOptions) -> String {
    let mut s = format!(" --render {} --style {}", opt.look.render.name(), opt.look.style.name());
    if opt.look.pen_width != 0.3 {
        let _ = write!(s, " --pen-width {}", opt.look.pen_width);
    }
    match opt.look.render {
        Render::Bars => {
            let _ = write!(s, " --bar-height {}", opt.look.bar_height);
        }
        Render::Zoom => {
            let _ = write!(
                s,
                " --zoom-rows {} --zoom-fraction {} --zoom-center {}",
                opt.look.zoom_rows, opt.look.zoom_fraction, opt.look.zoom_center
            );
        }
        _ => {}
    }
    if opt.look.boundary {
        s.push_str(" --boundary");
    }
    s.push_str(&opt.colour_flags);
    s
}

/// The `zetafill line` command line that reproduces the document.
pub fn command_line(doc: &LineDoc) -> String {
    let p = &doc.params;
    let mut s = format!(
        "zetafill line --length {}{} --c {} --n-offset {} --gap {} --max-trials {} --seed {} --sampler {}",
        doc.region.length,
        if doc.region.periodic { " --periodic" } else { "" },
        p.c,
        p.n_offset,
        p.gap,
        p.max_trials,
        p.seed,
        p.of.sampler
    );
    if let Some(k) = p.count {
        let _ = write!(s, " --count {k}");
    }
    if let Some(f) = p.fill {
        let _ = write!(s, " --fill {f}");
    }
    if let Some(m) = p.min_size {
        let _ = write!(s, " --min-size {m}");
    }
    s
}

/// A group of black strokes with butt caps.
fn stroke_layer(id: &str, pen: f64, items: Vec<Item>) -> Layer {
    Layer {
        id: Some(id.into()),
        paint: Paint {
            cap: Some("butt"),
            ..Paint::outline(pen)
        },
        items,
        ..Layer::default()
    }
}

/// The group of circles in the drawing's style.
fn circle_layer(id: &str, opt: &LineSvgOptions) -> Layer {
    Layer {
        id: Some(id.into()),
        paint: match opt.look.style {
            Style::Outline => Paint::outline(opt.look.pen_width),
            Style::Filled => Paint::filled(),
        },
        ..Layer::default()
    }
}

/// `item` in segment `k`'s colour, if the drawing has colours: its fill, or its stroke.
fn painted(mut item: Item, opt: &LineSvgOptions, k: usize, fill: bool) -> Item {
    if let Some(c) = opt.colours.as_ref().and_then(|cs| cs.get(k)) {
        if fill {
            item.paint.fill = Some(c.clone());
        } else {
            item.paint.stroke = Some(c.clone());
        }
    }
    item
}

/// The segments' layer `base`, or one Inkscape layer per palette colour (copies of `base`),
/// with each segment's layer.
fn layered(base: Layer, opt: &LineSvgOptions, n: usize) -> (Vec<Layer>, Vec<usize>) {
    match (&opt.colour_layers, &opt.colours) {
        (Some(palette), Some(colours)) => base.per_colour(palette, colours),
        _ => (vec![base], vec![0; n]),
    }
}

/// A 1D fill as a picture, y down (the line runs left to right at x = 0 ... L).
pub fn picture(doc: &LineDoc, opt: &LineSvgOptions) -> Picture {
    let filled_circles = opt.look.style == Style::Filled;
    let l = doc.region.length;
    let periodic = doc.region.periodic;
    let d0 = doc.shapes.first().map_or(l / 10.0, |s| s.length);
    let mut layers: Vec<Layer> = Vec::new();
    let n = doc.shapes.len();
    let mut add = |(mut ls, of): (Vec<Layer>, Vec<usize>), items: Vec<(usize, Item)>| {
        for (k, item) in items {
            if let Some(layer) = ls.get_mut(of.get(k).copied().unwrap_or(0)) {
                layer.items.push(item);
            }
        }
        layers.append(&mut ls);
    };
    let height;
    match opt.look.render {
        Render::Dashes => {
            height = (4.0 * opt.look.pen_width).max(2.0);
            let y = height / 2.0;
            let mut items = Vec::new();
            for (k, s) in doc.shapes.iter().enumerate() {
                for (a, b) in pieces(s, l, periodic) {
                    if b - a >= INVISIBLE {
                        items.push((k, painted(Item::new(Shape::Line([a, y], [b, y])), opt, k, false)));
                    }
                }
            }
            add(layered(stroke_layer("segments", opt.look.pen_width, Vec::new()), opt, n), items);
        }
        Render::Bars => {
            height = opt.look.bar_height;
            let base = Layer {
                id: Some("segments".into()),
                paint: Paint::filled(),
                ..Layer::default()
            };
            let mut items = Vec::new();
            for (k, s) in doc.shapes.iter().enumerate() {
                for (a, b) in pieces(s, l, periodic) {
                    if b - a >= INVISIBLE {
                        let bar = Shape::Rect {
                            corner: Some([a, 0.0]),
                            w: b - a,
                            h: opt.look.bar_height,
                        };
                        items.push((k, painted(Item::new(bar), opt, k, true)));
                    }
                }
            }
            add(layered(base, opt, n), items);
        }
        Render::Circles => {
            height = d0;
            let base = circle_layer("segments", opt);
            // A wrapping segment's circle shows at both ends, each image cut exactly to the
            // interval's box (its arcs, or its area when filled), never by a clip path.
            let interval = Bounds {
                x0: 0.0,
                y0: 0.0,
                x1: l,
                y1: height,
            };
            let mut items = Vec::new();
            for (k, s) in doc.shapes.iter().enumerate() {
                let r = s.length / 2.0;
                if r < INVISIBLE {
                    continue;
                }
                let mid = s.start + r;
                let wraps = periodic && s.start + s.length > l;
                for x in if wraps { vec![mid, mid - l] } else { vec![mid] } {
                    let circle = Item::new(Shape::Circle { c: [x, height / 2.0], r });
                    let drawn = if periodic {
                        circle.cut(&interval, filled_circles)
                    } else {
                        Some(circle)
                    };
                    items.extend(drawn.map(|item| (k, painted(item, opt, k, filled_circles))));
                }
            }
            add(layered(base, opt, n), items);
        }
        Render::Zoom => {
            let row_h = d0;
            let spacing = row_h / 4.0;
            let rows = opt.look.zoom_rows.max(1);
            height = rows as f64 * row_h + (rows - 1) as f64 * spacing;
            let mut marks = stroke_layer("zoom-marks", opt.look.pen_width / 2.0, Vec::new());
            let shifts: &[f64] = if periodic { &[0.0, -l, l] } else { &[0.0] };
            for k in 0..rows {
                let w = l * opt.look.zoom_fraction.powi(k as i32);
                let mid = opt.look.zoom_center;
                let (a, b) = (mid - w / 2.0, mid + w / 2.0);
                let scale = l / w;
                let y0 = k as f64 * (row_h + spacing);
                let cy = y0 + row_h / 2.0;
                let id = format!("row{k}");
                // The row's circles cut exactly to its box, never by a clip path.
                let bounds = Bounds {
                    x0: 0.0,
                    y0,
                    x1: l,
                    y1: y0 + row_h,
                };
                let mut row = circle_layer(&id, opt);
                for (n, s) in doc.shapes.iter().enumerate() {
                    let r = s.length / 2.0 * scale;
                    if r < INVISIBLE {
                        continue;
                    }
                    for &d in shifts {
                        let (s0, s1) = (s.start + d, s.start + s.length + d);
                        if s1 < a || s0 > b {
                            continue;
                        }
                        let c = [((s0 + s1) / 2.0 - a) * scale, cy];
                        if let Some(item) = Item::new(Shape::Circle { c, r }).cut(&bounds, filled_circles) {
                            row.items.push(painted(item, opt, n, filled_circles));
                        }
                    }
                }
                layers.push(row);
                if k + 1 < rows {
                    // Ticks at the part of this row that the next row shows.
                    let half = l * opt.look.zoom_fraction / 2.0;
                    let at = (mid - a) * scale;
                    for x in [at - half, at + half] {
                        marks.items.push(Item::new(Shape::Line([x, y0 + row_h], [x, y0 + row_h + spacing])));
                    }
                }
            }
            layers.push(marks);
        }
    }
    if opt.look.boundary {
        let ends = [0.0, l].map(|x| Item::new(Shape::Line([x, 0.0], [x, height])));
        layers.push(stroke_layer("boundary", opt.look.pen_width, ends.to_vec()));
    }
    let mut pic = Picture::new(Bounds {
        x0: 0.0,
        y0: 0.0,
        x1: l,
        y1: height,
    });
    pic.flip = false;
    let p = &doc.params;
    pic.title = format!(
        "zetafill line: {} segments, c = {}, N = {}, seed {}",
        doc.shapes.len(),
        p.c,
        p.n_offset,
        p.seed
    );
    pic.desc = format!(
        "{}{}{}",
        command_line(doc),
        drawing_flags(opt),
        // The G-code's header has it among the plot flags.
        if opt.colour_layers.is_some() { " --layers colours" } else { "" }
    );
    pic.background.clone_from(&opt.background);
    pic.layers = layers;
    pic
}

/// The plotter variant of the picture, what the G-code draws, in the frame of its SVG (x along
/// the interval, y up, the line at mid height): `dashes` one open stroke per segment (per
/// piece when a periodic segment wraps), `circles` one whole circle of diameter L_i per
/// segment centred on the line (a wrapping segment's circle centred at its middle taken
/// modulo L), `bars` each segment's bar outline. `--hatch` hatches bars and circles
/// (`--hatch-only`: without their outlines), each layer's hatching before its outlines;
/// `--min-feature` leaves out segments shorter than it. The picture's frame is the interval's
/// box grown to hold every circle. `zoom` has no G-code form.
pub fn plotter_picture(doc: &LineDoc, opt: &LineSvgOptions, build: &crate::model::fill::BuildOptions) -> Result<Picture, CliError> {
    use crate::model::Path;
    let l = doc.region.length;
    let periodic = doc.region.periodic;
    let d0 = doc.shapes.first().map_or(l / 10.0, |s| s.length);
    let kept = doc.shapes.iter().enumerate().filter(|(_, s)| s.length >= build.min_feature);
    let outline = !build.no_outline;
    let (mut hatching, mut outlines) = (Vec::new(), Vec::new());
    let mut hatch = |k: usize, lines: Vec<[crate::model::Pt; 2]>| {
        let pieces = lines.into_iter().map(|[a, b]| Path::polyline(vec![a, b], false)).collect();
        hatching.push((k, Item::new(Shape::Path(pieces))));
    };
    let height = match opt.look.render {
        Render::Dashes => {
            let h = (4.0 * opt.look.pen_width).max(2.0);
            for (k, s) in kept {
                for (a, b) in pieces(s, l, periodic) {
                    if b - a >= INVISIBLE {
                        outlines.push((k, Item::polyline(vec![[a, h / 2.0], [b, h / 2.0]])));
                    }
                }
            }
            h
        }
        Render::Circles => {
            for (k, s) in kept {
                let r = s.length / 2.0;
                if r >= INVISIBLE {
                    let mid = s.start + r;
                    let c = [if periodic && mid >= l { mid - l } else { mid }, d0 / 2.0];
                    if outline {
                        outlines.push((k, Item::new(Shape::Circle { c, r })));
                    }
                    if let Some(h) = &build.hatch {
                        hatch(k, h.annulus(c, r, 0.0));
                    }
                }
            }
            d0
        }
        Render::Bars => {
            let h = opt.look.bar_height;
            for (k, s) in kept {
                for (a, b) in pieces(s, l, periodic) {
                    if b - a >= INVISIBLE {
                        let bar = vec![[a, 0.0], [b, 0.0], [b, h], [a, h]];
                        if let Some(hp) = &build.hatch {
                            hatch(k, hp.polygon(&bar));
                        }
                        if outline {
                            outlines.push((k, Item::new(Shape::Polygon(bar))));
                        }
                    }
                }
            }
            h
        }
        Render::Zoom => return Err(no_zoom_gcode()),
    };
    let (mut layers, of) = layered(Layer::default(), opt, doc.shapes.len());
    // Circles may reach past the ends of the interval: the frame holds them all.
    let mut frame = Bounds {
        x0: 0.0,
        y0: 0.0,
        x1: l,
        y1: height,
    };
    for (k, item) in hatching.into_iter().chain(outlines) {
        for p in item.strokes() {
            let b = p.bounds();
            frame = Bounds {
                x0: frame.x0.min(b.x0),
                y0: frame.y0.min(b.y0),
                x1: frame.x1.max(b.x1),
                y1: frame.y1.max(b.y1),
            };
        }
        if let Some(layer) = layers.get_mut(of.get(k).copied().unwrap_or(0)) {
            layer.items.push(item);
        }
    }
    let mut pic = Picture::new(frame);
    pic.layers = layers;
    Ok(pic)
}
