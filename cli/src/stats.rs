//! `zetafill stats`: the numbers behind the fills.

use crate::error::CliError;
use crate::spec;
use clap::{Args, Subcommand};

/// The stats subcommands.
#[derive(Debug, Subcommand)]
pub enum StatsCommand {
    /// The Hurwitz zeta function zeta(c, N) = sum_{i>=0} (i+N)^-c.
    Zeta(ZetaArgs),
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

/// Runs a stats subcommand.
pub fn run(cmd: &StatsCommand) -> Result<(), CliError> {
    match cmd {
        StatsCommand::Zeta(a) => {
            let z = zetafill::zeta::zeta(a.c, a.n_offset).map_err(|e| CliError::arg("--n-offset", e))?;
            if a.json {
                println!("{}", serde_json::json!({ "zeta": z, "c": a.c, "n_offset": a.n_offset }));
            } else {
                println!("{z}");
            }
            Ok(())
        }
    }
}
