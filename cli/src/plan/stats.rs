//! `zetafill stats` resolved: each subcommand's flags checked against each other in the order
//! the command has always reported them, and turned into plain options (the scene of the
//! runs, the values of c, where the chart goes). Also the messages of the outcomes that name
//! an argument: a value the core refuses, an input that is not a fill, a box range that
//! leaves nothing to fit.
//!
//! `stats dimension` reads its FILE before it checks `--min-box` against `--max-box` (a bad
//! file is reported first): that check is a plan method the run calls after the read.

use crate::args::stats::{ChartArgs, DimensionArgs, GasketArgs, HaltingArgs, Rotate, SceneArgs, StatsCommand};
use crate::args::stats::{TrialsArgs, TrialsFrom, ZetaArgs};
use crate::error::CliError;
use crate::io::write::Dest;
use crate::plan::format::ChartFormat;
use std::fmt::Display;
use std::path::PathBuf;
use zetafill::ShapeKind;

/// A checked `zetafill stats` subcommand.
#[derive(Debug, Clone)]
pub enum StatsPlan {
    /// `stats zeta`.
    Zeta(ZetaPlan),
    /// `stats gasket`.
    Gasket(GasketPlan),
    /// `stats trials`.
    Trials(TrialsPlan),
    /// `stats halting`.
    Halting(HaltingPlan),
    /// `stats dimension`.
    Dimension(DimensionPlan),
}

/// `stats zeta`: zeta(c, N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZetaPlan {
    /// Exponent c.
    pub c: f64,
    /// Offset N.
    pub n_offset: f64,
    /// Print one JSON object.
    pub json: bool,
}

/// `stats gasket`: b(c, N, n).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GasketPlan {
    /// Exponent c.
    pub c: f64,
    /// Offset N.
    pub n_offset: f64,
    /// Placements done.
    pub n: u64,
    /// Print one JSON object.
    pub json: bool,
}

/// The scene of the statistics runs: shape, rotation and region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scene {
    /// Shape.
    pub shape: ShapeKind,
    /// Random rotation of non-circles.
    pub rotate: bool,
    /// Region width and height (mm).
    pub size: (f64, f64),
    /// Periodic boundary.
    pub periodic: bool,
}

/// Where a chart goes and as what.
pub type ChartOutput = Option<(Dest, ChartFormat)>;

/// `stats trials`: cumulative trials against placements.
#[derive(Debug, Clone)]
pub struct TrialsPlan {
    /// The scene.
    pub scene: Scene,
    /// The values of c, one curve each.
    pub c: Vec<f64>,
    /// Offset N.
    pub n_offset: f64,
    /// Shapes per run.
    pub count: u64,
    /// Estimate the paper's trials with the cell sampler instead of counting them.
    pub estimate: bool,
    /// Runs per value of c.
    pub runs: u64,
    /// Base seed.
    pub seed: u64,
    /// Trial limit per placement.
    pub max_trials: u64,
    /// The fit uses placements n >= this (below `count`).
    pub fit_from: u64,
    /// The chart, if any.
    pub output: ChartOutput,
    /// Print one JSON object.
    pub json: bool,
}

/// `stats halting`: the fraction of runs that halt at each c.
#[derive(Debug, Clone)]
pub struct HaltingPlan {
    /// The scene.
    pub scene: Scene,
    /// The values of c scanned.
    pub c: Vec<f64>,
    /// Offset N.
    pub n_offset: f64,
    /// Runs per value of c.
    pub runs: u64,
    /// Shapes per run.
    pub count: u64,
    /// Trial limit per placement.
    pub max_trials: u64,
    /// Base seed.
    pub seed: u64,
    /// Worker threads (0: one per core).
    pub threads: usize,
    /// The chart, if any.
    pub output: ChartOutput,
    /// Print one JSON object.
    pub json: bool,
    /// No progress bar.
    pub quiet: bool,
}

/// `stats dimension`: a box count of a fill's JSON.
#[derive(Debug, Clone, PartialEq)]
pub struct DimensionPlan {
    /// The fill's JSON.
    pub input: PathBuf,
    /// The box sizes of the fit, as given.
    pub boxes: BoxRange,
    /// Print one JSON object.
    pub json: bool,
}

/// The box sizes of a box-counting fit (mm); `None`: the default of the estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxRange {
    /// Largest box size.
    pub max: Option<f64>,
    /// Smallest box size.
    pub min: Option<f64>,
}

/// Most values of c one `stats halting` may scan.
pub const MAX_POINTS: u64 = 1000;

/// Checks the flags of a `zetafill stats` subcommand and resolves them into a plan. Nothing
/// runs and nothing is read.
pub fn resolve(cmd: &StatsCommand) -> Result<StatsPlan, CliError> {
    Ok(match cmd {
        StatsCommand::Zeta(a) => StatsPlan::Zeta(zeta(a)),
        StatsCommand::Gasket(a) => StatsPlan::Gasket(gasket(a)),
        StatsCommand::Trials(a) => StatsPlan::Trials(trials(a)?),
        StatsCommand::Halting(a) => StatsPlan::Halting(halting(a)?),
        StatsCommand::Dimension(a) => StatsPlan::Dimension(dimension(a)),
    })
}

fn zeta(a: &ZetaArgs) -> ZetaPlan {
    ZetaPlan {
        c: a.c,
        n_offset: a.n_offset,
        json: a.json,
    }
}

fn gasket(a: &GasketArgs) -> GasketPlan {
    GasketPlan {
        c: a.c,
        n_offset: a.n_offset,
        n: a.n,
        json: a.json,
    }
}

fn scene(a: &SceneArgs) -> Scene {
    Scene {
        shape: a.shape,
        rotate: a.rotate == Rotate::Random,
        size: a.region,
        periodic: a.periodic,
    }
}

fn trials(a: &TrialsArgs) -> Result<TrialsPlan, CliError> {
    let output = chart_output(&a.chart, "stats trials")?;
    let fit_from = a.fit_from.unwrap_or((a.count / 10).max(1));
    if fit_from >= a.count {
        return Err(CliError::arg(
            "--fit-from",
            format!("{fit_from} leaves nothing to fit; it must be below --count {}", a.count),
        ));
    }
    Ok(TrialsPlan {
        scene: scene(&a.scene),
        c: a.c.0.clone(),
        n_offset: a.n_offset,
        count: a.count,
        estimate: a.sampler == TrialsFrom::Fast,
        runs: a.runs,
        seed: a.seed,
        max_trials: a.max_trials,
        fit_from,
        output,
        json: a.json,
    })
}

fn halting(a: &HaltingArgs) -> Result<HaltingPlan, CliError> {
    let output = chart_output(&a.chart, "stats halting")?;
    Ok(HaltingPlan {
        scene: scene(&a.scene),
        c: c_values(a.c_from, a.c_to, a.c_step)?,
        n_offset: a.n_offset,
        runs: a.runs,
        count: a.count,
        max_trials: a.max_trials,
        seed: a.seed,
        threads: a.threads,
        output,
        json: a.json,
        quiet: a.quiet,
    })
}

fn dimension(a: &DimensionArgs) -> DimensionPlan {
    DimensionPlan {
        input: a.input.clone(),
        boxes: BoxRange {
            max: a.max_box,
            min: a.min_box,
        },
        json: a.json,
    }
}

/// Where a chart-writing subcommand (`name`, e.g. `"stats trials"`) writes: the checked
/// destination of `--output` and its format, `--format` or else the extension (SVG for `-`);
/// `None` without `--output`.
pub fn chart_output(a: &ChartArgs, name: &str) -> Result<ChartOutput, CliError> {
    let Some(p) = &a.output else { return Ok(None) };
    let format = a.format.map(ChartFormat::from);
    let dest = Dest::parse(p);
    let ext = p.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let f = match (format, ext.as_deref()) {
        (Some(f), _) => f,
        _ if dest == Dest::Stdout => ChartFormat::Svg,
        (None, Some("csv")) => ChartFormat::Csv,
        (None, Some("svg")) => ChartFormat::Svg,
        (None, _) => {
            return Err(CliError::arg(
                "--output",
                format!("{name} writes .csv or .svg; end the file name in one of them, or give --format"),
            ))
        }
    };
    dest.check("--output")?;
    Ok(Some((dest, f)))
}

/// The values of c `stats halting` scans: `from + k * step` up to `to` (inclusive, to within
/// 1e-9 of a step), at most [`MAX_POINTS`] of them.
pub fn c_values(from: f64, to: f64, step: f64) -> Result<Vec<f64>, CliError> {
    if to < from {
        return Err(CliError::arg("--c-to", format!("{to} is below --c-from {from}")));
    }
    let k = ((to - from) / step + 1e-9).floor();
    if !(k.is_finite() && k < MAX_POINTS as f64) {
        return Err(CliError::arg(
            "--c-step",
            format!("{step} gives more than {MAX_POINTS} values of c; raise it"),
        ));
    }
    Ok((0..=k as u64).map(|i| from + i as f64 * step).collect())
}

/// The core refuses zeta(c, N) or b(c, N, n) at this offset.
pub fn n_offset_error(e: impl Display) -> CliError {
    CliError::arg("--n-offset", e)
}

/// The core refuses the parameters of a statistics run.
pub fn exponent_error(e: impl Display) -> CliError {
    CliError::arg("--c", e)
}

/// The FILE of `stats dimension` cannot be read, or is not a fill's JSON.
pub fn input_error(e: impl Display) -> CliError {
    CliError::arg("FILE", e)
}

impl BoxRange {
    /// Refuses a smallest box size that is not below the largest.
    pub fn check(&self) -> Result<(), CliError> {
        if let (Some(hi), Some(lo)) = (self.max, self.min) {
            if lo >= hi {
                return Err(CliError::arg("--min-box", format!("{lo} must be below --max-box {hi}")));
            }
        }
        Ok(())
    }

    /// The refusal of a fit whose box sizes, from `hi` down to `lo` mm, give fewer than two
    /// levels.
    pub fn too_few_levels(hi: f64, lo: f64) -> CliError {
        CliError::arg(
            "--min-box",
            format!("box sizes from {hi} down to {lo} mm give fewer than two levels; place more shapes or widen the range"),
        )
    }
}
