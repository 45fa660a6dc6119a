//! The flags of `zetafill stats` and its subcommands; `stats trials` and `stats halting`
//! share the scene of their runs ([`SceneArgs`]) and their output ([`ChartArgs`]).

use crate::args::spec;
use clap::{Args, Subcommand, ValueEnum};
use std::path::PathBuf;
use zetafill::ShapeKind;

/// The stats subcommands.
#[derive(Debug, Subcommand)]
pub enum StatsCommand {
    /// The Hurwitz zeta function zeta(c, N) = sum_{i>=0} (i+N)^-c.
    Zeta(ZetaArgs),
    /// The dimensionless average gasket width b(c, N, n) for circles (paper section 4, Table 1).
    Gasket(GasketArgs),
    /// Cumulative trials against placements for a fill, with the fitted power-law exponent.
    Trials(TrialsArgs),
    /// The fraction of runs that halt at each c (paper Figure 6), runs spread over all cores.
    Halting(HaltingArgs),
    /// Box-counting estimate of the fractal dimension of a fill's JSON (1D, 2D or 3D), beside the exact value.
    Dimension(DimensionArgs),
}

/// Arguments of `stats zeta`.
#[derive(Debug, Args)]
pub struct ZetaArgs {
    /// Exponent c (> 1).
    #[arg(long, value_parser = spec::exponent, allow_hyphen_values = true)]
    pub c: f64,
    /// Offset N (> 0).
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::n_offset, allow_hyphen_values = true)]
    pub n_offset: f64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `stats gasket`.
#[derive(Debug, Args)]
pub struct GasketArgs {
    /// Exponent c (> 1).
    #[arg(long, value_parser = spec::exponent, allow_hyphen_values = true)]
    pub c: f64,
    /// Offset N (> 0).
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::n_offset, allow_hyphen_values = true)]
    pub n_offset: f64,
    /// Number of placements done, n >= 1 (the next circle is number n, counted from 0).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..), allow_hyphen_values = true)]
    pub n: u64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// What `stats trials` and `stats halting` write.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ChartFormatArg {
    /// The numbers, one row per point.
    Csv,
    /// A chart.
    Svg,
}

/// `--shape`, `--rotate`, `--region`, `--periodic`: the scene of the statistics runs (the
/// paper's Figures 5 and 6), shared by `stats trials` and `stats halting`.
#[derive(Debug, Clone, Args)]
pub struct SceneArgs {
    /// circle | square | rect:ASPECT.
    #[arg(long, default_value = "circle", value_parser = shape_2d)]
    pub shape: ShapeKind,
    /// Rotation of non-circles: none (the paper's squares) or random.
    #[arg(long, value_enum, default_value = "none")]
    pub rotate: Rotate,
    /// rect:W:H, sizes in mm.
    #[arg(long, default_value = "rect:200:200", value_parser = rect_2d, allow_hyphen_values = true)]
    pub region: (f64, f64),
    /// Periodic (toroidal) boundary.
    #[arg(long)]
    pub periodic: bool,
}

/// `-o` and `--format` of `stats trials` and `stats halting`: the numbers as CSV or a chart
/// as SVG. Each command says in its help what its CSV and chart hold.
#[derive(Debug, Clone, Args)]
pub struct ChartArgs {
    /// Output: .csv or .svg; '-' is stdout.
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Output format (overrides the extension): csv or svg.
    #[arg(long, value_enum)]
    pub format: Option<ChartFormatArg>,
}

/// Arguments of `stats trials`.
#[derive(Debug, Args)]
#[command(mut_arg("output", |a| a.help("Output: .csv (every placement of every run) or .svg (log-log chart); '-' is stdout")))]
pub struct TrialsArgs {
    /// The shape, rotation and region of the runs.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Exponent c > 1, or several separated by commas (one curve each).
    #[arg(long, default_value = "1.3", value_parser = exponents, allow_hyphen_values = true)]
    pub c: Exponents,
    /// The paper's N > 0.
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::n_offset, allow_hyphen_values = true)]
    pub n_offset: f64,
    /// Shapes per run.
    #[arg(long, default_value_t = 10_000, value_parser = clap::value_parser!(u64).range(10..=10_000_000), allow_hyphen_values = true)]
    pub count: u64,
    /// reference: run the paper's sampler and count its trials; fast: place with the cell
    /// sampler and estimate the paper's trials (unbiased; seconds where the paper's sampler
    /// takes hours).
    #[arg(long, value_enum, default_value = "reference")]
    pub sampler: TrialsFrom,
    /// Runs per value of c (seeds seed + k * runs + r).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=100), allow_hyphen_values = true)]
    pub runs: u64,
    /// Base seed.
    #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
    pub seed: u64,
    /// Trial limit per placement.
    #[arg(long = "max-trials", default_value_t = 10_000_000, value_parser = clap::value_parser!(u64).range(1..), allow_hyphen_values = true)]
    pub max_trials: u64,
    /// The fit uses placements n >= this (default: a tenth of --count).
    #[arg(long = "fit-from", value_parser = clap::value_parser!(u64).range(1..), allow_hyphen_values = true)]
    pub fit_from: Option<u64>,
    /// Where the numbers or the chart go.
    #[command(flatten)]
    pub chart: ChartArgs,
    /// Print one JSON object: {"exponent", "placed", "trials", ...} of the first run, and
    /// every run under "series".
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `stats halting`.
#[derive(Debug, Args)]
#[command(mut_arg("output", |a| a.help("Output: .csv (c,runs,halted,fraction) or .svg (chart); '-' is stdout")))]
pub struct HaltingArgs {
    /// The shape, rotation and region of the runs.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// First c (> 1).
    #[arg(long = "c-from", value_parser = spec::exponent, allow_hyphen_values = true)]
    pub c_from: f64,
    /// Last c (>= --c-from).
    #[arg(long = "c-to", value_parser = spec::exponent, allow_hyphen_values = true)]
    pub c_to: f64,
    /// Step between values of c (> 0).
    #[arg(long = "c-step", value_parser = spec::positive, allow_hyphen_values = true)]
    pub c_step: f64,
    /// The paper's N > 0.
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::n_offset, allow_hyphen_values = true)]
    pub n_offset: f64,
    /// Runs per value of c.
    #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u64).range(1..=1_000_000), allow_hyphen_values = true)]
    pub runs: u64,
    /// Shapes per run: a run that places them all did not halt.
    #[arg(long, default_value_t = 100, value_parser = clap::value_parser!(u64).range(1..=1_000_000), allow_hyphen_values = true)]
    pub count: u64,
    /// Trial limit per placement: reaching it is a halt.
    #[arg(long = "max-trials", default_value_t = 1_000_000, value_parser = clap::value_parser!(u64).range(1..), allow_hyphen_values = true)]
    pub max_trials: u64,
    /// Base seed.
    #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
    pub seed: u64,
    /// Worker threads (0: one per core).
    #[arg(long, default_value_t = 0, allow_hyphen_values = true)]
    pub threads: usize,
    /// Where the numbers or the chart go.
    #[command(flatten)]
    pub chart: ChartArgs,
    /// Print one JSON object: {"points": [{"c", "runs", "halted", "fraction"}, ...]}.
    #[arg(long)]
    pub json: bool,
    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

/// Arguments of `stats dimension`.
#[derive(Debug, Args)]
pub struct DimensionArgs {
    /// A JSON file written by `zetafill fill`, `zetafill line` or `zetafill space` (boxes in 3D).
    pub input: PathBuf,
    /// Largest box size in mm for the fit (default: see the module docs).
    #[arg(long = "max-box", value_parser = spec::length, allow_hyphen_values = true)]
    pub max_box: Option<f64>,
    /// Smallest box size in mm for the fit (default: twice the smallest shape's size).
    #[arg(long = "min-box", value_parser = spec::length, allow_hyphen_values = true)]
    pub min_box: Option<f64>,
    /// Print one JSON object: {"box_counting": ..., "exact": ..., ...}.
    #[arg(long)]
    pub json: bool,
}

/// Rotation of non-circular shapes in the statistics runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Rotate {
    /// Axis-aligned (the paper's squares).
    None,
    /// A uniformly random angle per trial.
    Random,
}

/// Where the trials of `stats trials` come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TrialsFrom {
    /// The paper's sampler is run and its trials counted.
    Reference,
    /// The cell sampler places the shapes and estimates the paper's trials (unbiased, far
    /// faster at large counts).
    Fast,
}

/// `circle | square | rect:ASPECT`: the shapes of the paper's Figures 5 and 6.
pub fn shape_2d(s: &str) -> Result<ShapeKind, String> {
    match s.split(':').collect::<Vec<_>>().as_slice() {
        ["circle"] => Ok(ShapeKind::Circle),
        ["square"] => Ok(ShapeKind::Square),
        ["rect", a] => Ok(ShapeKind::Rect {
            aspect: spec::positive(a).map_err(|e| format!("rect:ASPECT: the aspect ratio {e}"))?,
        }),
        _ => Err(format!(
            "unknown shape '{s}'; the statistics runs take circle, square or rect:ASPECT"
        )),
    }
}

/// `rect:W:H` in mm.
pub fn rect_2d(s: &str) -> Result<(f64, f64), String> {
    match s.split(':').collect::<Vec<_>>().as_slice() {
        ["rect", w, h] => Ok((
            spec::positive(w).map_err(|e| format!("rect:W:H: the width {e}"))?,
            spec::positive(h).map_err(|e| format!("rect:W:H: the height {e}"))?,
        )),
        _ => Err(format!("unknown region '{s}'; use rect:W:H (sizes in mm)")),
    }
}

/// A list of exponents given as `C1,C2,...`.
#[derive(Debug, Clone, PartialEq)]
pub struct Exponents(pub Vec<f64>);

/// A comma-separated list of 1 to 32 exponents, each > 1.
pub fn exponents(s: &str) -> Result<Exponents, String> {
    let v = s.split(',').map(spec::exponent).collect::<Result<Vec<_>, _>>()?;
    if v.is_empty() || v.len() > 32 {
        return Err("give 1 to 32 values of c separated by commas".into());
    }
    Ok(Exponents(v))
}
