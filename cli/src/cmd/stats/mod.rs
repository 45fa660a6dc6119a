//! `zetafill stats`: the numbers behind the fills. Every subcommand takes `--json` and then
//! prints one JSON object on stdout.

pub mod chart;
pub mod dimension;
pub mod halting;
pub mod trials;

use crate::args::stats::{ChartFormat, StatsCommand};
use crate::error::CliError;
use crate::io::write::Dest;
use std::path::PathBuf;

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
            let z = zetafill::AreaSequence::new(1.0, a.c, a.n_offset)
                .map_err(|e| CliError::arg("--n-offset", e))?
                .zeta();
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
