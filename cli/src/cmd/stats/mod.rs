//! `zetafill stats`: the numbers behind the fills. Every subcommand takes `--json` and then
//! prints one JSON object on stdout.

pub mod chart;
pub mod dimension;
pub mod halting;
pub mod space_boxes;
pub mod trials;

use crate::error::CliError;
use crate::plan::stats::{n_offset_error, StatsPlan};

/// Runs a stats subcommand.
pub fn run(plan: &StatsPlan) -> Result<(), CliError> {
    match plan {
        StatsPlan::Zeta(a) => {
            let z = zetafill::AreaSequence::new(1.0, a.c, a.n_offset).map_err(n_offset_error)?.zeta();
            if a.json {
                println!("{}", serde_json::json!({ "zeta": z, "c": a.c, "n_offset": a.n_offset }));
            } else {
                println!("{z}");
            }
            Ok(())
        }
        StatsPlan::Gasket(a) => {
            let b = zetafill::internals::stats::gasket_width(a.c, a.n_offset, a.n).map_err(n_offset_error)?;
            if a.json {
                println!("{}", serde_json::json!({ "b": b, "c": a.c, "n_offset": a.n_offset, "n": a.n }));
            } else {
                println!("{b}");
            }
            Ok(())
        }
        StatsPlan::Trials(a) => trials::run(a),
        StatsPlan::Halting(a) => halting::run(a),
        StatsPlan::Dimension(a) => dimension::run(a),
    }
}
