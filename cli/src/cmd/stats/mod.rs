//! `zetafill stats`: the numbers behind the fills. Every subcommand takes `--json` and then
//! prints one JSON object on stdout.

pub mod chart;
pub mod dimension;
pub mod halting;
pub mod trials;

use crate::args::spec;
use crate::error::CliError;
use crate::io::write::Dest;
use clap::{Args, Subcommand};
use std::path::PathBuf;

/// The stats subcommands.
#[derive(Debug, Subcommand)]
pub enum StatsCommand {
    /// The Hurwitz zeta function zeta(c, N) = sum_{i>=0} (i+N)^-c.
    Zeta(ZetaArgs),
    /// The dimensionless average gasket width b(c, N, n) for circles (paper section 4, Table 1).
    Gasket(GasketArgs),
    /// Cumulative trials against placements for a fill, with the fitted power-law exponent.
    Trials(trials::TrialsArgs),
    /// The fraction of runs that halt at each c (paper Figure 6), runs spread over all cores.
    Halting(halting::HaltingArgs),
    /// Box-counting estimate of the fractal dimension of a fill's JSON, beside the exact value.
    Dimension(dimension::DimensionArgs),
}

/// Arguments of `stats zeta`.
#[derive(Debug, Args)]
pub struct ZetaArgs {
    /// Exponent c (> 1).
    #[arg(long, value_parser = spec::exponent, allow_negative_numbers = true)]
    pub c: f64,
    /// Offset N (> 0).
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::positive, allow_negative_numbers = true)]
    pub n_offset: f64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `stats gasket`.
#[derive(Debug, Args)]
pub struct GasketArgs {
    /// Exponent c (> 1).
    #[arg(long, value_parser = spec::exponent, allow_negative_numbers = true)]
    pub c: f64,
    /// Offset N (> 0).
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::positive, allow_negative_numbers = true)]
    pub n_offset: f64,
    /// Number of placements done, n >= 1 (the next circle is number n, counted from 0).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    pub n: u64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// What `stats trials` and `stats halting` write.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ChartFormat {
    /// The numbers, one row per point.
    Csv,
    /// A chart.
    Svg,
}

/// Where a chart-writing subcommand (`name`, e.g. `"stats trials"`) writes: the checked
/// destination of `--output` and its format, `--format` or else the extension (SVG for `-`);
/// `None` without `--output`.
pub fn chart_output(output: Option<&PathBuf>, format: Option<ChartFormat>, name: &str) -> Result<Option<(Dest, ChartFormat)>, CliError> {
    let Some(p) = output else { return Ok(None) };
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
    dest.check("--output", &[])?;
    Ok(Some((dest, f)))
}

/// Runs a stats subcommand.
pub fn run(cmd: &StatsCommand) -> Result<(), CliError> {
    match cmd {
        StatsCommand::Zeta(a) => {
            let z = zetafill::internals::zeta::zeta(a.c, a.n_offset).map_err(|e| CliError::arg("--n-offset", e))?;
            if a.json {
                println!("{}", serde_json::json!({ "zeta": z, "c": a.c, "n_offset": a.n_offset }));
            } else {
                println!("{z}");
            }
            Ok(())
        }
        StatsCommand::Gasket(a) => {
            let b = zetafill::internals::stats::gasket_width(a.c, a.n_offset, a.n).map_err(|e| CliError::arg("--n-offset", e))?;
            if a.json {
                println!("{}", serde_json::json!({ "b": b, "c": a.c, "n_offset": a.n_offset, "n": a.n }));
            } else {
                println!("{b}");
            }
            Ok(())
        }
        StatsCommand::Trials(a) => trials::run(a),
        StatsCommand::Halting(a) => halting::run(a),
        StatsCommand::Dimension(a) => dimension::run(a),
    }
}
