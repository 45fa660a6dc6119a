//! `zetafill line`: the 1D fill, segments of length `L_i = L / (zeta(c, N) (i + N)^c)` in an
//! interval of length `L` (Shier and Bourke, *An Algorithm for Random Fractal Filling of Space*, Figure 3), run by the core's [`zetafill::line::Engine`], and
//! its outputs: SVG (dashes, circles, bars or zoom rows), PNG, JSON, CSV and the digest.

use crate::cmd::stopping;
use crate::error::CliError;
use crate::output::stream::{io_error, Output, Size, TextSink, MAX_F64_DISPLAY, MAX_JSON_NUMBER, MAX_U64};
use crate::plan::format::Format;
use crate::plan::line::{first_segment_error, halt_advice, param_error, LineDraw, LinePlan, LineRun, SEGMENTS};
use crate::plan::plot::GcodePlan;
use crate::plan::raster::png_error;
use std::fmt::Write as _;
use zetafill::line::{
    gaps_for as line_gaps_for, index_words as line_index_words, Engine as LineEngine, Gap as LineGap, Gaps as LineGaps, Segment,
    Storage as LineStorage,
};
use zetafill::StepError;
use zetafill::StopReason;

pub mod doc;
pub mod picture;

pub use doc::{IntervalDoc, LineDoc, LineOwnDoc, LineParamsDoc, LineStatsDoc, SegmentDoc};
use picture::drawing_flags;
pub use picture::{command_line, picture, plotter_picture, LineSvgOptions};

/// Runs the fill and returns the document (and the halt, if any). Nothing is written.
pub fn compute(a: &LineRun) -> Result<(LineDoc, Option<StepError>), CliError> {
    let (params, interval, stop) = (a.params, a.interval, a.stop);
    let sequence = stopping::sequence(interval.length, params.c, params.n_offset)?;
    stopping::check_min_size(&stop, sequence.area(0), SEGMENTS)?;
    let cap = stopping::slots(zetafill::line::capacity(&sequence, &stop, SEGMENTS.max), SEGMENTS)? as usize;
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
    let on_place = |p: &zetafill::line::Placement<f64>| {
        trials.push(p.trials);
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let reason = if a.reference_sampler {
        engine.run(&mut rng, &stop, on_place)
    } else {
        // Words for every gap the fill can make: the fill never depends on them.
        let mut words = vec![LineGap::default(); line_gaps_for(cap)];
        let mut gaps = LineGaps::new(&mut words).map_err(|_| CliError::Io("internal: no storage for the gap sampler".into()))?;
        engine.run_fast(&mut gaps, &mut rng, &stop, on_place)
    };
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
            of: doc::LineOwnDoc {
                sampler: if a.reference_sampler { "reference" } else { "fast" },
            },
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

/// Renders a 1D fill as SVG.
pub fn render_svg(doc: &LineDoc, opt: &LineSvgOptions) -> Vec<u8> {
    crate::output::svg::write(&picture(doc, opt))
}

/// JSON (version 1), numbers in shortest round-trip form, one line.
pub fn render_json(doc: &LineDoc) -> Result<Vec<u8>, CliError> {
    let mut v = Vec::new();
    json_to(doc, &mut v)?;
    Ok(v)
}

/// [`render_json`] written into `out` as it is encoded.
fn json_to(doc: &LineDoc, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    serde_json::to_writer(&mut *out, doc).map_err(crate::output::space::json_error)?;
    out.write_all(b"\n").map_err(io_error)
}

/// An upper bound on [`render_json`]'s size: all but the segments exactly (encoded without
/// them), each segment with its keys, a comma, two `u64` and two numbers at their longest.
fn json_max_size(doc: &LineDoc) -> Result<u64, CliError> {
    let bare = LineDoc {
        params: doc.params.clone(),
        region: doc.region.clone(),
        shapes: Vec::new(),
        stats: doc.stats.clone(),
        ..*doc
    };
    let base = serde_json::to_vec(&bare).map_err(crate::output::space::json_error)?.len() as u64 + 1;
    let keys = "{\"index\":,\"kind\":\"\",\"start\":,\"length\":,\"trials\":},".len() as u64;
    let segments: u64 = doc
        .shapes
        .iter()
        .map(|s| keys + 6 * s.kind.len() as u64 + 2 * MAX_U64 + 2 * MAX_JSON_NUMBER)
        .sum();
    Ok(base + segments)
}

/// The CSV's first line.
const CSV_HEADER: &str = "index,kind,start,end,length,trials\n";

/// CSV: `index,kind,start,end,length,trials`, full f64 precision (`end` = start + length, past
/// L for a periodic segment that wraps).
pub fn render_csv(doc: &LineDoc) -> Vec<u8> {
    let mut v = Vec::new();
    // A Vec takes every byte.
    let _ = csv_to(doc, &mut v);
    v
}

/// [`render_csv`] written into `out`, a few rows at a time.
fn csv_to(doc: &LineDoc, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    let mut sink = TextSink::new(out);
    sink.buf.push_str(CSV_HEADER);
    for sh in &doc.shapes {
        let _ = writeln!(
            sink.buf,
            "{},{},{},{},{},{}",
            sh.index,
            sh.kind,
            sh.start,
            sh.start + sh.length,
            sh.length,
            sh.trials
        );
        sink.maybe_flush()?;
    }
    sink.flush()
}

/// An upper bound on [`render_csv`]'s size: every row at its longest.
fn csv_max_size(doc: &LineDoc) -> u64 {
    let rows: u64 = doc
        .shapes
        .iter()
        .map(|s| 2 * MAX_U64 + s.kind.len() as u64 + 3 * MAX_F64_DISPLAY + 6)
        .sum();
    CSV_HEADER.len() as u64 + rows
}

/// The digest line `COUNT HEX16`: the engine's own digest of every segment's bits.
pub fn render_digest(doc: &LineDoc) -> Vec<u8> {
    let (count, hash) = doc.digest;
    format!("{count} {hash:016x}\n").into_bytes()
}

fn gcode_output(doc: &LineDoc, opt: &LineSvgOptions, gcode: &GcodePlan) -> Result<Output<'static>, CliError> {
    let pic = plotter_picture(doc, opt, &gcode.build)?;
    let header = vec![format!("{}{}{}", command_line(doc), drawing_flags(opt), gcode.flags)];
    // With --layers colours, one pen per palette colour, each drawing its segments, placed as
    // the whole.
    crate::cmd::plot::pens_output(&pic.pens(), &pic.frame, gcode, header)
}

/// Renders a document in a format.
pub fn render(doc: &LineDoc, format: Format, d: &LineDraw) -> Result<Vec<u8>, CliError> {
    output(doc, format, d)?.into_bytes()
}

/// A document in a format, ready to be streamed (see [`crate::cmd::fill::output`]).
pub fn output<'a>(doc: &'a LineDoc, format: Format, d: &LineDraw) -> Result<Output<'a>, CliError> {
    let opt = LineSvgOptions {
        look: d.look,
        colours: d.colours.palette.as_ref().map(|p| {
            let items: Vec<(u64, f64)> = doc.shapes.iter().map(|s| (s.index, s.length)).collect();
            crate::output::palette::assign_items(&p.0, d.colours.by, doc.params.seed, &items, |_| 0)
        }),
        background: d.colours.background.clone(),
        colour_flags: d.colours.flags.clone(),
        colour_layers: d.colours.palette.as_ref().filter(|_| d.colours.layers).map(|p| p.0.clone()),
    };
    Ok(match format {
        Format::Svg => crate::output::svg::output(&picture(doc, &opt))?,
        Format::Json => Output::stream(Size::AtMost(json_max_size(doc)?), move |w| json_to(doc, w)),
        Format::Csv => Output::stream(Size::AtMost(csv_max_size(doc)), move |w| csv_to(doc, w)),
        Format::Digest => Output::bytes(render_digest(doc)),
        Format::Png => Output::bytes(d.raster.render(&render_svg(doc, &opt)).map_err(png_error)?),
        Format::Gcode => gcode_output(doc, &opt, d.gcode.as_ref().ok_or_else(no_gcode)?)?,
    })
}

/// The G-code plan of a drawing that has none (it was resolved for another format).
fn no_gcode() -> CliError {
    CliError::Io("internal: G-code asked of a plan resolved for another format".into())
}

/// `zetafill line`: runs the plan and writes its output.
pub fn run(plan: &LinePlan) -> Result<(), CliError> {
    let (doc, halt) = compute(&plan.run)?;
    let out = output(&doc, plan.format, &plan.draw)?;
    let what = crate::output::stream::file_of(plan.format.name());
    crate::cmd::write_output(
        &plan.dest,
        &out,
        plan.max_output_size,
        &what,
        "ask for fewer segments (--count, --fill, --min-size)",
    )?;
    let max_trials = plan.run.params.max_trials;
    stopping::outcome(halt, SEGMENTS, |index, trials| halt_advice(index, trials < max_trials))
}
