//! The `zetafill` command-line tool: argument parsing (clap), one module per subcommand, one
//! per output format, and the single place where outcomes become exit codes ([`run_main`]).

#![deny(missing_docs)]

pub mod cobble;
pub mod doc;
pub mod error;
pub mod fill;
pub mod line;
pub mod machines_cmd;
pub mod output;
pub mod plot;
pub mod spec;
pub mod stats;
pub mod stopping;
pub mod svgin;
pub mod territory;
pub mod tile;
pub mod write;

use clap::{Parser, Subcommand};
use error::CliError;
use std::ffi::OsString;

/// Random fractal space filling (Shier & Bourke's statistical geometry).
#[derive(Debug, Parser)]
#[command(name = "zetafill", version, about, long_about = None)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
// Parsed once per run: the size of the largest variant does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Fill a 2D region with shapes whose areas follow a power law.
    Fill(fill::FillArgs),
    /// Fill an interval with segments whose lengths follow a power law (1D).
    Line(line::LineArgs),
    /// Sugihara's Voronoi territory competing: boundaries, cells or coloured cells.
    Territory(territory::TerritoryArgs),
    /// The scale-periodic fractal tile (seed 002): a texture that meets half- and
    /// double-scale copies of itself; drawn alone, as a mosaic or as a planet of rings.
    Tile(tile::TileArgs),
    /// Numbers behind the fills: zeta, gasket width, trials, halting, dimension.
    #[command(subcommand)]
    Stats(stats::StatsCommand),
    /// Machine profiles for G-code: list the built-ins, or show one as TOML.
    Machines(machines_cmd::MachinesArgs),
}

/// Runs the tool on `args` (including the program name); returns the exit code after
/// printing any message on stderr.
pub fn run_main<I, T>(args: I) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(c) => c,
        Err(e) => {
            // clap prints help and version to stdout (exit 0), usage errors to stderr (exit 2).
            let _ = e.print();
            return if e.use_stderr() { 2 } else { 0 };
        }
    };
    match run(cli) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}

/// Runs a parsed command.
pub fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        Command::Fill(a) => fill::run(&a),
        Command::Line(a) => line::run(&a),
        Command::Territory(a) => territory::run(&a),
        Command::Tile(a) => tile::run(&a),
        Command::Stats(s) => stats::run(&s),
        Command::Machines(m) => machines_cmd::run(&m),
    }
}
