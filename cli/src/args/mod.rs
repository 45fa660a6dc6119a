//! The command line as clap parses it, and nothing else: the top-level parser, one module
//! of flags per subcommand, the flag groups several share ([`common`]), and the parsers of
//! flag values ([`spec`]).

pub mod colour;
pub mod common;
pub mod fill;
pub mod format;
pub mod line;
pub mod machines;
pub mod plot;
pub mod raster;
pub mod shape;
pub mod shell;
pub mod space;
pub mod spec;
pub mod stats;
pub mod style;
pub mod symmetry;
pub mod territory;
pub mod tile;

use clap::{Parser, Subcommand};

/// The command line (its help text is the crate's description in Cargo.toml).
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
    /// Fill a 3D region (box, ball, box without a ball) with solids whose volumes follow a
    /// power law: JSON, CSV, STL, OBJ, GLB, a PNG render, or SVG sheets for stacked laser cuts.
    Space(space::SpaceArgs),
    /// Sugihara's Voronoi territory competing: boundaries, cells or coloured cells.
    Territory(territory::TerritoryArgs),
    /// The scale-periodic fractal tile of the "Fractal Tiles" post: a texture that meets
    /// half- and double-scale copies of itself; drawn alone, as a mosaic or as a planet of rings.
    Tile(tile::TileArgs),
    /// Numbers behind the fills: zeta, gasket width, trials, halting, dimension.
    #[command(subcommand)]
    Stats(stats::StatsCommand),
    /// Machine profiles for G-code: list the built-ins, or show one as TOML.
    Machines(machines::MachinesArgs),
    /// Shell completions (bash, zsh, fish, elvish, powershell), on standard output.
    Completions(shell::CompletionsArgs),
    /// The manual page (roff) of zetafill or of one subcommand, on standard output.
    Man(shell::ManArgs),
}
