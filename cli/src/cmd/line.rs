//! `zetafill line`: the 1D fill, segments of length `L_i = L / (zeta(c, N) (i + N)^c)` in an
//! interval of length `L` (Shier and Bourke, *An Algorithm for Random Fractal Filling of Space*, Figure 3), run by the core's [`zetafill::LineEngine`], and
//! its outputs: SVG (dashes, circles, bars or zoom rows), PNG, JSON, CSV and the digest.

use crate::args::format::Format;
use crate::cmd::stopping::{self, Unit};
use crate::error::CliError;
use crate::model::picture::ClipDef;
use crate::model::{Item, Layer, Paint, Picture, Shape};
use crate::output::svg::Style;
use crate::plan::line::{first_segment_error, halt_advice, param_error, LineDraw, LinePlan, LineRun};
use crate::plan::plot::GcodePlan;
use serde::Serialize;
use std::fmt::Write as _;
use zetafill::StepError;
use zetafill::{line_index_words, LineEngine, LineStorage, Segment, StopReason};

pub use crate::args::line::MAX_SEGMENTS;

/// What a 1D run places.
const SEGMENTS: Unit = Unit {
    plural: "segments",
    max: MAX_SEGMENTS,
};

/// How segments are drawn in SVG and PNG.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Render {
    /// Each segment a stroke along one line: one pen-down per segment.
    Dashes,
    /// Each segment a circle of diameter L_i centred on the line (the paper's Figure 3).
    Circles,
    /// Each segment a filled bar `--bar-height` tall (for engraving).
    Bars,
    /// Rows of circles, each zooming into the central `--zoom-fraction` of the row above.
    Zoom,
}

impl Render {
    /// The name `--render` takes.
    pub fn name(self) -> &'static str {
        match self {
            Render::Dashes => "dashes",
            Render::Circles => "circles",
            Render::Bars => "bars",
            Render::Zoom => "zoom",
        }
    }
}

/// A finished (or halted) 1D fill: DESIGN section 3's JSON with `"mode": "line"`.
#[derive(Debug, Clone, Serialize)]
pub struct LineDoc {
    /// Format version (1).
    pub version: u32,
    /// `"line"`.
    pub mode: &'static str,
    /// Everything needed to reproduce the run.
    pub params: LineParamsDoc,
    /// `{ "kind": "interval", "length": L, "periodic": bool }`.
    pub region: IntervalDoc,
    /// zeta(c, N).
    pub zeta: f64,
    /// Segments in placement order.
    pub shapes: Vec<SegmentDoc>,
    /// Run statistics.
    pub stats: LineStatsDoc,
    /// The determinism digest (count, FNV-1a) of the engine's own bits.
    #[serde(skip)]
    pub digest: (u64, u64),
}

/// Run statistics of a 1D fill.
#[derive(Debug, Clone, Serialize)]
pub struct LineStatsDoc {
    /// Segments placed.
    pub placed: u64,
    /// Trials in all.
    pub trials: u64,
    /// Placed length over L.
    pub fill_fraction: f64,
    /// Whether the run halted at the trial limit.
    pub halted: bool,
    /// Why the run stopped: `count`, `fill`, `min-size` or `halted`.
    pub stop: &'static str,
}

/// The parameters of a 1D run.
#[derive(Debug, Clone, Serialize)]
pub struct LineParamsDoc {
    /// Exponent c.
    pub c: f64,
    /// The paper's N.
    pub n_offset: f64,
    /// RNG seed.
    pub seed: u64,
    /// Clearance in mm.
    pub gap: f64,
    /// Stop after this many segments.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count: Option<u64>,
    /// Stop at this fill fraction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill: Option<f64>,
    /// Stop before the first segment shorter than this (mm).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_size: Option<f64>,
    /// Trial limit per placement.
    pub max_trials: u64,
    /// The fractal dimension D = 1/c.
    pub dimension: f64,
}

/// The interval.
#[derive(Debug, Clone, Serialize)]
pub struct IntervalDoc {
    /// `"interval"`.
    pub kind: &'static str,
    /// Length L (mm).
    pub length: f64,
    /// Periodic boundary.
    pub periodic: bool,
}

/// One placed segment `[start, start + length]`.
#[derive(Debug, Clone, Serialize)]
pub struct SegmentDoc {
    /// Placement index.
    pub index: u64,
    /// `"segment"`.
    pub kind: &'static str,
    /// Left end (mm), in `[0, L)` when periodic (the segment may run past L and wrap).
    pub start: f64,
    /// Length L_i (mm).
    pub length: f64,
    /// Trials this placement took.
    pub trials: u64,
}

/// Runs the fill and returns the document (and the halt, if any). Nothing is written.
pub fn compute(a: &LineRun) -> Result<(LineDoc, Option<StepError>), CliError> {
    let (params, interval, stop) = (a.params, a.interval, a.stop);
    let sequence = stopping::sequence(interval.length, params.c, params.n_offset)?;
    let cap = stopping::slots(zetafill::segment_capacity(&sequence, &stop, SEGMENTS.max), SEGMENTS)? as usize;
    let mut segs = vec![Segment::<f64>::default(); cap];
    let mut index = vec![0u32; line_index_words(cap)];
    let mut engine = LineEngine::<f64>::new(
        params,
        interval,
        LineStorage {
            segments: &mut segs,
            index: &mut index,
        },
    )
    .map_err(param_error)?;
    let mut rng = zetafill::rng_from_seed(a.seed);
    let bar = stopping::progress_bar(a.quiet, stop.count, SEGMENTS);
    let mut trials = Vec::with_capacity(cap);
    let reason = engine.run(&mut rng, &stop, |p| {
        trials.push(p.trials);
        if let Some(b) = &bar {
            b.inc(1);
        }
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let (stop_name, halt) = match reason {
        StopReason::Count => ("count", None),
        StopReason::Fill => ("fill", None),
        StopReason::MinSize => ("min-size", None),
        StopReason::Step(StepError::CannotFit { index: 0 }) => return Err(first_segment_error(a, engine.length_of(0))),
        StopReason::Step(e @ (StepError::Halted { .. } | StepError::CannotFit { .. })) => ("halted", Some(e)),
        #[allow(unreachable_patterns)]
        r => return Err(CliError::Io(format!("internal: the fill stopped unexpectedly ({r:?})"))),
    };
    let shapes = engine
        .placed()
        .iter()
        .enumerate()
        .map(|(i, s)| SegmentDoc {
            index: i as u64,
            kind: "segment",
            start: s.start,
            length: s.length,
            trials: trials.get(i).copied().unwrap_or(0),
        })
        .collect();
    let st = engine.stats();
    let doc = LineDoc {
        version: 1,
        mode: "line",
        params: LineParamsDoc {
            c: params.c,
            n_offset: params.n_offset,
            seed: a.seed,
            gap: params.gap,
            count: stop.count,
            fill: stop.fill,
            min_size: stop.min_size,
            max_trials: params.max_trials,
            dimension: 1.0 / params.c,
        },
        region: IntervalDoc {
            kind: "interval",
            length: interval.length,
            periodic: interval.periodic,
        },
        zeta: engine.zeta(),
        shapes,
        stats: LineStatsDoc {
            placed: st.placed,
            trials: st.trials,
            fill_fraction: st.fill_fraction,
            halted: halt.is_some(),
            stop: stop_name,
        },
        digest: zetafill::internals::line::line_digest(&engine),
    };
    Ok((doc, halt))
}

// ---------------------------------------------------------------------------------------------
// Outputs
// ---------------------------------------------------------------------------------------------

/// Drawn sizes below this (mm) round to zero at four decimals and are left out of the SVG.
const INVISIBLE: f64 = 0.5e-4;

/// SVG options of the 1D renders.
#[derive(Debug, Clone)]
pub struct LineSvgOptions {
    /// How segments are drawn.
    pub render: Render,
    /// Outline or filled circles.
    pub style: Style,
    /// Stroke width (mm).
    pub pen_width: f64,
    /// Bar height (mm).
    pub bar_height: f64,
    /// Zoom rows.
    pub zoom_rows: u32,
    /// Zoom fraction per row.
    pub zoom_fraction: f64,
    /// The point the rows zoom into (mm).
    pub zoom_center: f64,
    /// Mark the interval's ends.
    pub boundary: bool,
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
fn drawing_flags(opt: &LineSvgOptions) -> String {
    let mut s = format!(" --render {} --style {}", opt.render.name(), opt.style.name());
    if opt.pen_width != 0.3 {
        let _ = write!(s, " --pen-width {}", opt.pen_width);
    }
    match opt.render {
        Render::Bars => {
            let _ = write!(s, " --bar-height {}", opt.bar_height);
        }
        Render::Zoom => {
            let _ = write!(
                s,
                " --zoom-rows {} --zoom-fraction {} --zoom-center {}",
                opt.zoom_rows, opt.zoom_fraction, opt.zoom_center
            );
        }
        _ => {}
    }
    if opt.boundary {
        s.push_str(" --boundary");
    }
    s.push_str(&opt.colour_flags);
    s
}

/// The `zetafill line` command line that reproduces the document.
pub fn command_line(doc: &LineDoc) -> String {
    let p = &doc.params;
    let mut s = format!(
        "zetafill line --length {}{} --c {} --n-offset {} --gap {} --max-trials {} --seed {}",
        doc.region.length,
        if doc.region.periodic { " --periodic" } else { "" },
        p.c,
        p.n_offset,
        p.gap,
        p.max_trials,
        p.seed
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
        paint: match opt.style {
            Style::Outline => Paint::outline(opt.pen_width),
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
    let filled_circles = opt.style == Style::Filled;
    let l = doc.region.length;
    let periodic = doc.region.periodic;
    let d0 = doc.shapes.first().map_or(l / 10.0, |s| s.length);
    let mut clips = Vec::new();
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
    match opt.render {
        Render::Dashes => {
            height = (4.0 * opt.pen_width).max(2.0);
            let y = height / 2.0;
            let mut items = Vec::new();
            for (k, s) in doc.shapes.iter().enumerate() {
                for (a, b) in pieces(s, l, periodic) {
                    if b - a >= INVISIBLE {
                        items.push((k, painted(Item::new(Shape::Line([a, y], [b, y])), opt, k, false)));
                    }
                }
            }
            add(layered(stroke_layer("segments", opt.pen_width, Vec::new()), opt, n), items);
        }
        Render::Bars => {
            height = opt.bar_height;
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
                            h: opt.bar_height,
                        };
                        items.push((k, painted(Item::new(bar), opt, k, true)));
                    }
                }
            }
            add(layered(base, opt, n), items);
        }
        Render::Circles => {
            height = d0;
            let mut base = circle_layer("segments", opt);
            if periodic {
                clips.push(ClipDef {
                    id: "interval".into(),
                    item: Item::new(Shape::Rect {
                        corner: None,
                        w: l,
                        h: height,
                    }),
                });
                base.clip = Some("interval".into());
            }
            let mut items = Vec::new();
            for (k, s) in doc.shapes.iter().enumerate() {
                let r = s.length / 2.0;
                if r < INVISIBLE {
                    continue;
                }
                let mid = s.start + r;
                let c = [mid, height / 2.0];
                items.push((k, painted(Item::new(Shape::Circle { c, r }), opt, k, filled_circles)));
                if periodic && s.start + s.length > l {
                    let c = [mid - l, height / 2.0];
                    items.push((k, painted(Item::new(Shape::Circle { c, r }), opt, k, filled_circles)));
                }
            }
            add(layered(base, opt, n), items);
        }
        Render::Zoom => {
            let row_h = d0;
            let spacing = row_h / 4.0;
            let rows = opt.zoom_rows.max(1);
            height = rows as f64 * row_h + (rows - 1) as f64 * spacing;
            let mut marks = stroke_layer("zoom-marks", opt.pen_width / 2.0, Vec::new());
            let shifts: &[f64] = if periodic { &[0.0, -l, l] } else { &[0.0] };
            for k in 0..rows {
                let w = l * opt.zoom_fraction.powi(k as i32);
                let mid = opt.zoom_center;
                let (a, b) = (mid - w / 2.0, mid + w / 2.0);
                let scale = l / w;
                let y0 = k as f64 * (row_h + spacing);
                let cy = y0 + row_h / 2.0;
                let id = format!("row{k}");
                clips.push(ClipDef {
                    id: format!("clip-{id}"),
                    item: Item::new(Shape::Rect {
                        corner: Some([0.0, y0]),
                        w: l,
                        h: row_h,
                    }),
                });
                let mut row = circle_layer(&id, opt);
                row.clip = Some(format!("clip-{id}"));
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
                        row.items.push(painted(Item::new(Shape::Circle { c, r }), opt, n, filled_circles));
                    }
                }
                layers.push(row);
                if k + 1 < rows {
                    // Ticks at the part of this row that the next row shows.
                    let half = l * opt.zoom_fraction / 2.0;
                    let at = (mid - a) * scale;
                    for x in [at - half, at + half] {
                        marks.items.push(Item::new(Shape::Line([x, y0 + row_h], [x, y0 + row_h + spacing])));
                    }
                }
            }
            layers.push(marks);
        }
    }
    if opt.boundary {
        let ends = [0.0, l].map(|x| Item::new(Shape::Line([x, 0.0], [x, height])));
        layers.push(stroke_layer("boundary", opt.pen_width, ends.to_vec()));
    }
    let mut pic = Picture::new(crate::model::Bounds {
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
    pic.clips = clips;
    pic.layers = layers;
    pic
}

/// Renders a 1D fill as SVG.
pub fn render_svg(doc: &LineDoc, opt: &LineSvgOptions) -> Vec<u8> {
    crate::output::svg::write(&picture(doc, opt))
}

/// JSON (version 1), numbers in shortest round-trip form, one line.
pub fn render_json(doc: &LineDoc) -> Result<Vec<u8>, CliError> {
    let mut v = serde_json::to_vec(doc).map_err(|e| CliError::Io(format!("cannot encode JSON: {e}")))?;
    v.push(b'\n');
    Ok(v)
}

/// CSV: `index,kind,start,end,length,trials`, full f64 precision (`end` = start + length, past
/// L for a periodic segment that wraps).
pub fn render_csv(doc: &LineDoc) -> Vec<u8> {
    let mut s = String::from("index,kind,start,end,length,trials\n");
    for sh in &doc.shapes {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{}",
            sh.index,
            sh.kind,
            sh.start,
            sh.start + sh.length,
            sh.length,
            sh.trials
        );
    }
    s.into_bytes()
}

/// The digest line `COUNT HEX16`: the engine's own digest of every segment's bits.
pub fn render_digest(doc: &LineDoc) -> Vec<u8> {
    let (count, hash) = doc.digest;
    format!("{count} {hash:016x}\n").into_bytes()
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
    use crate::model::{Bounds, Path};
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
    let height = match opt.render {
        Render::Dashes => {
            let h = (4.0 * opt.pen_width).max(2.0);
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
            let h = opt.bar_height;
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
        Render::Zoom => return Err(CliError::arg("--render", "zoom has no G-code form; use dashes, circles or bars")),
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

fn render_gcode(doc: &LineDoc, opt: &LineSvgOptions, gcode: &GcodePlan, quiet: bool) -> Result<Vec<u8>, CliError> {
    let pic = plotter_picture(doc, opt, &gcode.build)?;
    let header = vec![format!("{}{}{}", command_line(doc), drawing_flags(opt), gcode.flags)];
    // With --layers colours, one pen per palette colour, each drawing its segments, placed as
    // the whole.
    crate::cmd::plot::pens_gcode(&pic.pens(), &pic.frame, gcode, header, quiet)
}

/// Renders a document in a format.
pub fn render(doc: &LineDoc, format: Format, d: &LineDraw) -> Result<Vec<u8>, CliError> {
    let opt = LineSvgOptions {
        render: d.render,
        style: d.style,
        pen_width: d.pen_width,
        bar_height: d.bar_height,
        zoom_rows: d.zoom_rows,
        zoom_fraction: d.zoom_fraction,
        zoom_center: d.zoom_center,
        boundary: d.boundary,
        colours: d.palette.as_ref().map(|p| {
            let items: Vec<(u64, f64)> = doc.shapes.iter().map(|s| (s.index, s.length)).collect();
            crate::output::palette::assign_items(&p.0, d.color_by, doc.params.seed, &items, |_| 0)
        }),
        background: d.background.clone(),
        colour_flags: d.colour_flags.clone(),
        colour_layers: d.palette.as_ref().filter(|_| d.colour_layers).map(|p| p.0.clone()),
    };
    Ok(match format {
        Format::Svg => render_svg(doc, &opt),
        Format::Json => render_json(doc)?,
        Format::Csv => render_csv(doc),
        Format::Digest => render_digest(doc),
        Format::Png => d.raster.render(&render_svg(doc, &opt))?,
        Format::Gcode => render_gcode(doc, &opt, d.gcode.as_ref().ok_or_else(no_gcode)?, d.quiet)?,
    })
}

/// The G-code plan of a drawing that has none (it was resolved for another format).
fn no_gcode() -> CliError {
    CliError::Io("internal: G-code asked of a plan resolved for another format".into())
}

/// `zetafill line`: runs the plan and writes its output.
pub fn run(plan: &LinePlan) -> Result<(), CliError> {
    let (doc, halt) = compute(&plan.run)?;
    let bytes = render(&doc, plan.format, &plan.draw)?;
    plan.dest.write(&bytes)?;
    stopping::outcome(halt, SEGMENTS, halt_advice)
}
