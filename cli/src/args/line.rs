//! The flags of `zetafill line`: the interval, the power law and stops of a fill reworded for
//! segments, the drawing, and the plotter, colour and raster groups flattened in.

use crate::args::colour::ColourArgs;
use crate::args::common::{OutputArgs, RunArgs};
use crate::args::fill::Sampler;
use crate::args::format::FormatArg;
use crate::args::plot::PlotArgs;
use crate::args::raster::RasterArgs;
use crate::args::spec;
use crate::args::style::StyleArg;
use clap::Args;

/// `--render`: how segments are drawn in SVG and PNG.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum RenderArg {
    /// Each segment a stroke along one line: one pen-down per segment.
    Dashes,
    /// Each segment a circle of diameter L_i centred on the line (the paper's Figure 3).
    Circles,
    /// Each segment a filled bar `--bar-height` tall (for engraving).
    Bars,
    /// Rows of circles, each zooming into the central `--zoom-fraction` of the row above.
    Zoom,
}

/// Largest number of segments one run may hold (28 bytes each in the core).
pub const MAX_SEGMENTS: u64 = 10_000_000;

/// Arguments of `zetafill line`. Only its G-code reads the plotter flags, and it has no pages
/// or layers: their help says so, and `--page` and `--layers` are left out of it. The power
/// law and the stops are a fill's, worded for segments (and in 1D, c = 1/D).
#[derive(Debug, Args)]
#[command(
    mut_arg("c", |a| a.help("Power-law exponent c > 1 (default 1.4; about 2.7 is the 1D maximum with N = 1)")),
    mut_arg("dimension", |a| a.help("Fractal dimension D in (0, 1) instead of c (c = 1/D)").value_parser(dimension_1d)),
    mut_arg("n_offset", |a| a.help("The paper's N > 0: larger N makes the first segments shorter")),
    mut_arg("count", |a| a
        .help("Stop after K segments (default 2000 when no stop condition is given)")
        .value_parser(clap::value_parser!(u64).range(1..=MAX_SEGMENTS))),
    mut_arg("fill", |a| a.help("Stop once this fraction of the interval is filled, 0 < F < 1")),
    mut_arg("min_size", |a| a.help("Stop before the first segment shorter than MM")),
    mut_arg("gap", |a| a.help("Minimum clearance between segments and to the ends, in mm")),
    mut_arg("page", |a| a.hide(true)),
    mut_arg("layers", |a| a.hide(true)),
    mut_arg("fit", |a| a.help("G-code: scale the drawing to fill the bed less --margin, centred")),
    mut_arg("center", |a| a.help("G-code: centre the drawing on the bed")),
    mut_arg("margin", |a| a.help("G-code: keep-out border of the bed in mm [default: 0]")),
    mut_arg("hatch", |a| a.help("G-code: hatch bars and circles, SPACING[:ANGLE] in mm and degrees (default angle 45)")),
    mut_arg("min_feature", |a| a.help("G-code: leave out segments shorter than MM (the pen's or beam's width)")),
)]
pub struct LineArgs {
    /// Length L of the interval in mm.
    #[arg(long, default_value_t = 200.0, value_parser = spec::length, allow_hyphen_values = true)]
    pub length: f64,
    /// Periodic boundary: the interval is a circle, a segment running past L continues at 0.
    #[arg(long)]
    pub periodic: bool,
    /// The power law (c = 1/D), stops, clearance, trial limit and seed.
    #[command(flatten)]
    pub run: RunArgs,
    /// Candidate sampler: fast (starts drawn over the free gaps where the next segment fits,
    /// about one trial a placement) or reference (the paper's uniform search); both give the
    /// same distribution of placements.
    #[arg(long, value_enum, default_value = "fast")]
    pub sampler: Sampler,
    /// Where the output goes.
    #[command(flatten)]
    pub output: OutputArgs<FormatArg>,
    /// SVG: how segments are drawn.
    #[arg(long, value_enum, default_value = "circles")]
    pub render: RenderArg,
    /// SVG: circles as outlines (plotters) or filled (dashes are strokes, bars always filled).
    #[arg(long, value_enum, default_value = "outline")]
    pub style: StyleArg,
    /// SVG: stroke width in mm (dashes and outlines).
    #[arg(long = "pen-width", default_value_t = 0.3, value_parser = spec::length, allow_hyphen_values = true)]
    pub pen_width: f64,
    /// SVG `bars`: bar height in mm.
    #[arg(long = "bar-height", default_value_t = 10.0, value_parser = spec::length, allow_hyphen_values = true)]
    pub bar_height: f64,
    /// SVG `zoom`: number of rows (the first shows the whole interval).
    #[arg(long = "zoom-rows", default_value_t = 4, value_parser = clap::value_parser!(u32).range(1..=12), allow_hyphen_values = true)]
    pub zoom_rows: u32,
    /// SVG `zoom`: each row shows this central fraction of the row above (Figure 3: 0.05).
    #[arg(long = "zoom-fraction", default_value_t = 0.05, value_parser = spec::fraction, allow_hyphen_values = true)]
    pub zoom_fraction: f64,
    /// SVG `zoom`: the point (mm from the left end) the rows zoom into (default: the middle).
    #[arg(long = "zoom-center", value_parser = spec::length_or_zero, allow_hyphen_values = true)]
    pub zoom_center: Option<f64>,
    /// SVG: also mark the ends of the interval.
    #[arg(long)]
    pub boundary: bool,
    /// Colours (SVG/PNG).
    #[command(flatten)]
    pub colour: ColourArgs,
    /// PNG size.
    #[command(flatten)]
    pub raster: RasterArgs,
    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
    /// Plotter and laser flags (G-code output).
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The fractal dimension D in 1D: 0 < D < 1 (so that c = 1/D > 1).
pub fn dimension_1d(s: &str) -> Result<f64, String> {
    let v = spec::finite(s)?;
    if v > 0.0 && v < 1.0 {
        Ok(v)
    } else {
        Err(format!(
            "the dimension of a 1D fill must be between 0 and 1, exclusive (got {s}); c = 1/D"
        ))
    }
}
