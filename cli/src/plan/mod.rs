//! The resolve step: each command's parsed flags ([`crate::args`]) become a checked plan in
//! plain Rust, with no clap type inside. Every rule that ties one flag to another, and every
//! message that names a flag, lives here; the commands of [`crate::cmd`] then compute and
//! write what the plan says, and never look at a flag again.

pub mod colour;
pub mod files;
pub mod fill;
pub mod fill_errors;
pub mod format;
pub mod line;
pub mod machines;
pub mod motif;
pub mod plot;
pub mod raster;
pub mod region;
pub mod region_input;
pub mod space;
pub mod stats;
pub mod symmetry;
pub mod territory;
pub mod tile;

use crate::args::common::{PowerLawArgs, StopArgs};
use crate::error::CliError;
use crate::io::write::Dest;
use zetafill::{AreaSequence, CapacityError, Stop};

/// A checked command that writes a file: where it writes, in which format, what it runs and
/// how it draws. Each command names its own (`fill::FillPlan`, `space::SpacePlan`, ...).
#[derive(Debug, Clone)]
pub struct Planned<F, R, D> {
    /// Where the output goes.
    pub dest: Dest,
    /// `--max-output-size`: the largest output written, in bytes.
    pub max_output_size: u64,
    /// The output format.
    pub format: F,
    /// The run.
    pub run: R,
    /// The drawing.
    pub draw: D,
}

impl<F: Copy, R, D> Planned<F, R, D> {
    /// The output path checked (`--output`), then its format told by `format`, then the run
    /// and the drawing resolved for that format by `resolve_as`, in that order, so that the
    /// first refusal is always the same one.
    pub fn resolve(
        output: &std::path::Path,
        max_output_size: u64,
        format: impl FnOnce() -> Result<F, CliError>,
        resolve_as: impl FnOnce(F) -> Result<(R, D), CliError>,
    ) -> Result<Self, CliError> {
        let dest = Dest::parse(output);
        dest.check("--output")?;
        let format = format()?;
        let (run, draw) = resolve_as(format)?;
        Ok(Planned {
            dest,
            max_output_size,
            format,
            run,
            draw,
        })
    }
}

/// The exponent c: `--c`, or else `--dimension` through `from_dimension` (c = 2/D in 2D,
/// 1/D in 1D), or else `default`.
pub fn exponent(p: &PowerLawArgs, default: f64, from_dimension: fn(f64) -> f64) -> f64 {
    match (p.c, p.dimension) {
        (Some(c), _) => c,
        (None, Some(d)) => from_dimension(d),
        (None, None) => default,
    }
}

/// The stop conditions: 2000 pieces when none is given.
pub fn stops(s: &StopArgs) -> Stop {
    stop(s.count, s.fill, s.min_size)
}

/// What a run places: `"shapes"` (2D) or `"segments"` (1D), with its limit per run.
#[derive(Debug, Clone, Copy)]
pub struct Unit {
    /// The plural noun used in messages.
    pub plural: &'static str,
    /// The most one run may hold.
    pub max: u64,
}

/// The stop conditions from `--count`, `--fill` and `--min-size`: 2000 pieces when none is
/// given.
pub fn stop(count: Option<u64>, fill: Option<f64>, min_size: Option<f64>) -> Stop {
    let count = match (count, fill, min_size) {
        (None, None, None) => Some(2000),
        (c, _, _) => c,
    };
    Stop { count, fill, min_size }
}

/// The power-law sequence of a run over `total` (area or length), from the core; a bad
/// offset is named as `--n-offset`.
pub fn sequence(total: f64, c: f64, n: f64) -> Result<AreaSequence, CliError> {
    let seq = AreaSequence::new(total, c, n).map_err(|e| CliError::arg("--n-offset", e))?;
    // A huge c (or N) sends the second size below the smallest number there is: the run
    // would place one shape and then pieces of size 0.
    let second = seq.area(1);
    if !(seq.area(0).is_finite() && second.is_finite() && second >= f64::MIN_POSITIVE) {
        return Err(CliError::arg(
            "--c",
            format!(
                "with c = {} and N = {}, the second size ({}) is not a usable number; lower --c",
                crate::error::num(c),
                crate::error::num(n),
                crate::error::num(second)
            ),
        ));
    }
    Ok(seq)
}

/// Refuses a `--min-size` above the first piece's size (`first`, its narrowest width or its
/// length): the run would place nothing.
pub fn check_min_size(stop: &Stop, first: f64, unit: Unit) -> Result<(), CliError> {
    match stop.min_size {
        Some(m) if m > first => Err(CliError::arg(
            "--min-size",
            format!(
                "{} mm is above the size of the first of the {} ({first:.4} mm), so none would be placed; give a smaller --min-size",
                crate::error::num(m),
                unit.plural
            ),
        )),
        _ => Ok(()),
    }
}

/// The slots the stop conditions need, as the core found them ([`zetafill::shape_capacity`], [`zetafill::line::capacity`]); a
/// stop condition no run of the unit's size can meet is refused naming its flag.
pub fn slots(found: Result<u64, CapacityError>, unit: Unit) -> Result<u64, CliError> {
    found.map_err(|e| match e {
        CapacityError::Fill { fill, max } => CliError::arg(
            "--fill",
            format!("{fill} needs more than {max} {} at this c; lower it or raise --c", unit.plural),
        ),
        CapacityError::MinSize { min_size, max } => CliError::arg(
            "--min-size",
            format!("{min_size} mm needs more than {max} {}; raise it", unit.plural),
        ),
    })
}
