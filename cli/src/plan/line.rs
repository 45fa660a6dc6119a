//! `zetafill line` resolved: the flags checked against each other in the order the command
//! has always reported them, and turned into the run (the core's parameters, the interval
//! and the stops) and the drawing (the writers' plain options). Also the messages of the
//! run's own outcomes that name a flag: a parameter the core refuses, a first segment that
//! does not fit, a halt.

use crate::args::line::{LineArgs, RenderArg, MAX_SEGMENTS};
use crate::args::plot::{Layers, PlotArgs};
use crate::error::CliError;
use crate::output::png::Raster;
use crate::output::svg::Style;
use crate::plan::colour::Colours;
use crate::plan::format::Format;
use crate::plan::plot::GcodePlan;
use crate::plan::plot::FOR_GCODE;
use crate::plan::raster;
use crate::plan::Unit;
use zetafill::line::{Interval, Params as LineParams};
use zetafill::{ParamError, Stop};

/// What a 1D run places, and the most one run may hold.
pub const SEGMENTS: Unit = Unit {
    plural: "segments",
    max: MAX_SEGMENTS,
};

/// A checked `zetafill line`: where it writes, what it runs and how it draws.
pub type LinePlan = super::Planned<Format, LineRun, LineDraw>;

/// What the 1D engine runs.
#[derive(Debug, Clone, Copy)]
pub struct LineRun {
    /// The core's parameters.
    pub params: LineParams,
    /// The interval.
    pub interval: Interval,
    /// The stop conditions.
    pub stop: Stop,
    /// RNG seed.
    pub seed: u64,
    /// The paper's sampler instead of the exact gap sampler.
    pub reference_sampler: bool,
    /// No progress bar.
    pub quiet: bool,
}

/// How the segments are drawn: the part of the drawing plan the SVG, PNG and G-code
/// pictures read.
#[derive(Debug, Clone, Copy)]
pub struct LineLook {
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
    /// The point the rows zoom into (mm; the middle unless given).
    pub zoom_center: f64,
    /// Mark the interval's ends.
    pub boundary: bool,
}

/// How the document is drawn.
#[derive(Debug, Clone)]
pub struct LineDraw {
    /// How the segments are drawn.
    pub look: LineLook,
    /// PNG size.
    pub raster: Raster,
    /// The colours, as the colour flags set them.
    pub colours: Colours,
    /// G-code: the machine, its placement and whether its figures go to stderr.
    pub gcode: Option<GcodePlan>,
}

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

impl From<RenderArg> for Render {
    fn from(r: RenderArg) -> Render {
        match r {
            RenderArg::Dashes => Render::Dashes,
            RenderArg::Circles => Render::Circles,
            RenderArg::Bars => Render::Bars,
            RenderArg::Zoom => Render::Zoom,
        }
    }
}

/// Checks the flags of `zetafill line` and resolves them into a plan. Nothing runs and
/// nothing is read but the machine profile.
pub fn resolve(a: &LineArgs) -> Result<LinePlan, CliError> {
    check_zoom(a)?;
    LinePlan::resolve(
        &a.output.output,
        a.output.max_output_size,
        || Format::resolve(a.output.format, &a.output.output),
        |format| resolve_format(a, format),
    )
}

/// The run and the drawing of `a` written as `format`: every rule between the flags, but
/// none about the output path (a library caller, such as a test, picks the format).
pub fn resolve_as(a: &LineArgs, format: Format) -> Result<(LineRun, LineDraw), CliError> {
    check_zoom(a)?;
    resolve_format(a, format)
}

/// Refuses a `--zoom-center` outside the interval.
fn check_zoom(a: &LineArgs) -> Result<(), CliError> {
    if a.zoom_center.is_some_and(|x| x > a.length) {
        return Err(CliError::arg(
            "--zoom-center",
            format!("must lie in the interval [0, {}]", a.length),
        ));
    }
    Ok(())
}

/// [`resolve_as`] after the zoom centre.
fn resolve_format(a: &LineArgs, format: Format) -> Result<(LineRun, LineDraw), CliError> {
    if a.sampler == crate::args::fill::Sampler::Batched {
        return Err(CliError::arg(
            "--sampler",
            "batched is a sampler of fill: use fast (the exact gap sampler) or reference for a line",
        ));
    }
    raster::check(&a.raster, format == Format::Png)?;
    check_plot(a, format)?;
    let colour_layers = a.plot.layers == Layers::Colours;
    let pens = format == Format::Gcode && colour_layers && a.colour.background.is_none();
    a.colour.check(
        matches!(format, Format::Svg | Format::Png) || pens,
        "write .svg or .png (or G-code with --layers colours, without --background)",
        true,
    )?;
    if 2.0 * a.run.gap >= a.length {
        return Err(CliError::arg(
            "--gap",
            format!(
                "{} mm leaves no room in a {} mm interval; it must be under half the length",
                a.run.gap, a.length
            ),
        ));
    }
    let run = LineRun {
        params: LineParams {
            c: crate::plan::exponent(&a.run.power, 1.4, LineParams::c_from_dimension),
            n_offset: a.run.power.n_offset,
            gap: a.run.gap,
            max_trials: a.run.max_trials,
        },
        interval: Interval {
            length: a.length,
            periodic: a.periodic,
        },
        stop: crate::plan::stops(&a.run.stop),
        seed: a.run.seed.seed,
        reference_sampler: a.sampler == crate::args::fill::Sampler::Reference,
        quiet: a.quiet,
    };
    let draw = LineDraw {
        look: LineLook {
            render: a.render.into(),
            style: a.style.into(),
            pen_width: a.pen_width,
            bar_height: a.bar_height,
            zoom_rows: a.zoom_rows,
            zoom_fraction: a.zoom_fraction,
            zoom_center: a.zoom_center.unwrap_or(a.length / 2.0),
            boundary: a.boundary,
        },
        raster: a.raster.raster(),
        colours: a.colour.colours(colour_layers && a.colour.palette.is_some()),
        gcode: if format == Format::Gcode {
            Some(GcodePlan::resolve(&a.plot, a.quiet)?)
        } else {
            None
        },
    };
    Ok((run, draw))
}

/// Refuses, before any work, a plot flag that `format` does not read: no output has pages or
/// layers, only the G-code reads the other plot flags (the SVG is the paper's figure), and it
/// has no zoom or hatched dashes.
fn check_plot(a: &LineArgs, format: Format) -> Result<(), CliError> {
    let p: &PlotArgs = &a.plot;
    p.build_options()?;
    if p.page.is_some() || matches!(p.layers, Layers::SizeBands(_)) {
        return Err(CliError::arg(
            if p.page.is_some() { "--page" } else { "--layers" },
            "is not available for line in any format: its SVG is the interval at full size, with no page or size layers, and its G-code goes on the machine's bed (--fit, --center, --margin); drop it (--layers colours splits a coloured drawing by pen)",
        ));
    }
    if p.layers == Layers::Colours {
        if a.colour.palette.is_none() {
            return Err(CliError::arg(
                "--layers",
                "colours makes one layer (one pen) per --palette colour: give --palette",
            ));
        }
        if a.render == RenderArg::Zoom || !matches!(format, Format::Svg | Format::Gcode) {
            return Err(CliError::arg(
                "--layers",
                "colours splits a plotter drawing by pen: write .svg or .gcode, with --render dashes, circles or bars",
            ));
        }
    }
    if format != Format::Gcode {
        return p.refuse_except(&["--layers"], |_| FOR_GCODE.to_string());
    }
    p.check_gcode()?;
    match a.render {
        RenderArg::Zoom => Err(zoom_has_no_gcode()),
        RenderArg::Dashes if p.hatch.is_some() => Err(CliError::arg(
            "--hatch",
            "dashes are single strokes with nothing to hatch: use --render bars or circles",
        )),
        _ => Ok(()),
    }
}

/// The refusal of `--render zoom` for G-code.
pub fn zoom_has_no_gcode() -> CliError {
    CliError::arg("--render", "zoom has no G-code form; use dashes, circles or bars")
}

/// Names the flag behind a core parameter error.
pub fn param_error(e: ParamError) -> CliError {
    let flag = match e {
        ParamError::Exponent => "--c",
        ParamError::Offset | ParamError::Zeta => "--n-offset",
        ParamError::Region | ParamError::Extent => "--length",
        ParamError::Gap => "--gap",
        ParamError::MaxTrials => "--max-trials",
        _ => "--count",
    };
    CliError::arg(flag, e)
}

/// The usage error of a fill whose first segment, `length` mm long, does not fit.
pub fn first_segment_error(run: &LineRun, length: f64) -> CliError {
    let gap = run.params.gap;
    CliError::arg(
        if gap > 0.0 { "--gap" } else { "--c" },
        format!(
            "the first segment ({length:.4} mm) with a gap of {gap} mm does not fit the {} mm interval; lower --c, raise --n-offset or lower --gap",
            run.interval.length
        ),
    )
}

/// Advice for a halt at placement `index`; a `proven` halt came before the trial limit (no
/// gap is left that can hold the segment), so more trials cannot help.
pub fn halt_advice(index: u64, proven: bool) -> &'static str {
    match (index < 100, proven) {
        (true, false) => "the first segments left no room for this one: lower --c, raise --n-offset, or try another --seed",
        (true, true) => {
            "the first segments left no room for this one, so more trials cannot help: lower --c, raise --n-offset, or try another --seed"
        }
        (false, false) => "raise --max-trials, lower --c, or ask for fewer segments",
        (false, true) => "no gap is left for a segment of this length, so more trials cannot help: lower --c, or ask for fewer segments",
    }
}

/// The refusal of `--render zoom` as G-code, met once the plotter drawing is made.
pub fn no_zoom_gcode() -> CliError {
    CliError::arg("--render", "zoom has no G-code form; use dashes, circles or bars")
}
