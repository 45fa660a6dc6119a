//! The flags of `zetafill tile`: the tile, its layout and drawing, with the plotter, colour
//! and raster groups flattened in.

use crate::args::colour::ColourArgs;
use crate::args::common::{OutputArgs, SeedArgs};
use crate::args::plot::PlotArgs;
use crate::args::raster::{RasterArgs, ReliefArg};
use crate::args::spec;
use clap::{Args, ValueEnum};

/// `--render`: what the tile shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RenderArg {
    /// The discs.
    Discs,
    /// Voronoi "cobblestones" of the disc centres.
    Voronoi,
}

/// `--style`: how pieces are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StyleArg {
    /// Outlines, for plotters (Voronoi: the cell edges).
    Outline,
    /// Filled shapes, for screens (Voronoi: the cells, inset by half the local spacing).
    Filled,
}

/// `--layout`: what is laid out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LayoutArg {
    /// The tile alone (the texture).
    Tile,
    /// Rows of tiles, each row half the scale of the one below, showing how the tile meets its
    /// copies.
    Mosaic,
    /// Rings of tiles around a disc, each ring with twice as many tiles as the one inside it.
    Planet,
}

/// Output formats of `zetafill tile`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TileFormatArg {
    /// SVG drawing in mm.
    Svg,
    /// PNG preview (the SVG rendered).
    Png,
    /// JSON document (version 1, mode "tile"): the tile's discs.
    Json,
    /// G-code for a plotter or laser (the drawing's outlines).
    Gcode,
}

/// Arguments of `zetafill tile`. The tile draws its own outlines: pages and hatching are
/// refused, and left out of the help; of the layers, only `--layers colours`.
#[derive(Debug, Args)]
#[command(
    mut_arg("output", |a| a.help("Output path; the format comes from the extension (.svg .png .json); '-' is stdout")),
    mut_arg("page", |a| a.hide(true)),
    mut_arg("hatch", |a| a.hide(true)),
    mut_arg("hatch_only", |a| a.hide(true)),
    mut_arg("cross_hatch", |a| a.hide(true)),
    mut_arg("min_feature", |a| a.hide(true)),
)]
pub struct TileArgs {
    /// Tile width in mm.
    #[arg(long, default_value_t = 100.0, value_parser = spec::length, allow_hyphen_values = true)]
    pub width: f64,
    /// Tile height in mm.
    #[arg(long, default_value_t = 100.0, value_parser = spec::length, allow_hyphen_values = true)]
    pub height: f64,
    /// Disc radius at the tile's bottom edge in mm (half of it at the top edge).
    #[arg(long, default_value_t = 5.0, value_parser = spec::length, allow_hyphen_values = true)]
    pub radius: f64,
    /// Gap between discs at the bottom edge in mm (half of it at the top edge).
    #[arg(long, default_value_t = 1.0, value_parser = spec::length_or_zero, allow_hyphen_values = true)]
    pub spacing: f64,
    /// Random tries in all (each places a disc where it fits).
    #[arg(long, default_value_t = 20_000, value_parser = clap::value_parser!(u64).range(1..=100_000_000), allow_hyphen_values = true)]
    pub tries: u64,
    /// The seed.
    #[command(flatten)]
    pub seed: SeedArgs,
    /// discs | voronoi (cobblestones of the disc centres).
    #[arg(long, value_enum, default_value = "discs")]
    pub render: RenderArg,
    /// outline (plotters) | filled (screens).
    #[arg(long, value_enum, default_value = "outline")]
    pub style: StyleArg,
    /// tile (the texture) | mosaic (rows of copies, each half the scale of the one below) |
    /// planet (rings of copies, each holding twice as many as the one inside it).
    #[arg(long, value_enum, default_value = "tile")]
    pub layout: LayoutArg,
    /// Mosaic and planet: rows (rings) of tiles.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=10), allow_hyphen_values = true)]
    pub rows: Option<u32>,
    /// Mosaic: tiles in the bottom row (default 2); planet: tiles in the inner ring (default
    /// 16).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096), allow_hyphen_values = true)]
    pub columns: Option<u32>,
    /// Planet: its outer radius in mm, where the rings pile up.
    #[arg(long = "planet-radius", value_parser = spec::length, allow_hyphen_values = true)]
    pub planet_radius: Option<f64>,
    /// Where the output goes.
    #[command(flatten)]
    pub output: OutputArgs<TileFormatArg>,
    /// SVG: stroke width of the outlines in mm.
    #[arg(long = "pen-width", default_value_t = 0.3, value_parser = spec::length, allow_hyphen_values = true)]
    pub pen_width: f64,
    /// Colours (SVG/PNG).
    #[command(flatten)]
    pub colour: ColourArgs,
    /// PNG size.
    #[command(flatten)]
    pub raster: RasterArgs,
    /// PNG: write a 16-bit height map of the tile (each disc or cobblestone a raised stone of
    /// this profile) instead of a picture.
    #[arg(long, value_enum)]
    pub relief: Option<ReliefArg>,
    /// No figures on stderr.
    #[arg(short, long)]
    pub quiet: bool,
    /// Plotter and laser output (G-code): machine, feeds, passes, order, --fit/--center.
    #[command(flatten)]
    pub plot: PlotArgs,
}
