//! The arguments of the commands the page runs (`fill`, `line`, `territory`, `tile`), built
//! from a command line with [`Words`]: each flag with the binary's parser of its value, its
//! default and its rules. The tests check every flag, default, rule and name against clap's
//! definitions in `zetafill_cli::args`.

use crate::words::{choice, ranged, Words, MISSING};
use std::path::PathBuf;
use zetafill_cli::args::colour::{ColorByArg, ColourArgs};
use zetafill_cli::args::common::{byte_size, OutputArgs, PowerLawArgs, RunArgs, SeedArgs, StopArgs, MAX_SHAPES};
use zetafill_cli::args::fill::{FillArgs, MixArg, RegionInputArgs, Rotate, Sampler, ScalarArg};
use zetafill_cli::args::format::FormatArg;
use zetafill_cli::args::line::{self, LineArgs, RenderArg as LineRender, MAX_SEGMENTS};
use zetafill_cli::args::plot::{self, OrderArg, PlotArgs};
use zetafill_cli::args::raster::{RasterArgs, ReliefArg};
use zetafill_cli::args::spec;
use zetafill_cli::args::style::StyleArg;
use zetafill_cli::args::symmetry::{self, SymmetryArg, SymmetryArgs};
use zetafill_cli::args::territory::{self, RenderArg as TerritoryRender, TerritoryArgs, TerritoryFormatArg, MAX_POINTS};
use zetafill_cli::args::tile::{self, LayoutArg, RenderArg as TileRender, TileArgs, TileFormatArg};
use zetafill_render::output::palette;

/// The one-letter flags of every command here.
pub const SHORTS: [(char, &str); 2] = [('o', "output"), ('q', "quiet")];

/// The flags whose value may not start with `-`: clap takes such a word for another flag.
pub const PLAIN: &[&str] = &[
    "region-sha256",
    "font",
    "font-sha256",
    "shape",
    "mix-order",
    "rotate",
    "region",
    "symmetry",
    "repeat",
    "sampler",
    "cells",
    "threads",
    "batch",
    "density",
    "density-sha256",
    "scalar",
    "style",
    "relief",
    "output",
    "format",
    "render",
    "sites-from",
    "layout",
    "machine",
    "order",
    "layers",
    "palette",
    "color-by",
    "background",
];

/// The names of each choice flag's values, in clap's order.
pub mod names {
    use super::*;

    /// `--rotate`.
    pub const ROTATE: [(&str, Rotate); 2] = [("none", Rotate::None), ("random", Rotate::Random)];
    /// `--mix-order`.
    pub const MIX: [(&str, MixArg); 2] = [("cycle", MixArg::Cycle), ("random", MixArg::Random)];
    /// `--sampler`.
    pub const SAMPLER: [(&str, Sampler); 3] = [
        ("fast", Sampler::Fast),
        ("reference", Sampler::Reference),
        ("batched", Sampler::Batched),
    ];
    /// `--scalar`.
    pub const SCALAR: [(&str, ScalarArg); 2] = [("f64", ScalarArg::F64), ("fixed", ScalarArg::Fixed)];
    /// `--symmetry`.
    pub const SYMMETRY: [(&str, SymmetryArg); 17] = [
        ("p1", SymmetryArg::P1),
        ("p2", SymmetryArg::P2),
        ("pm", SymmetryArg::Pm),
        ("pg", SymmetryArg::Pg),
        ("cm", SymmetryArg::Cm),
        ("pmm", SymmetryArg::Pmm),
        ("pmg", SymmetryArg::Pmg),
        ("pgg", SymmetryArg::Pgg),
        ("cmm", SymmetryArg::Cmm),
        ("p4", SymmetryArg::P4),
        ("p4m", SymmetryArg::P4m),
        ("p4g", SymmetryArg::P4g),
        ("p3", SymmetryArg::P3),
        ("p3m1", SymmetryArg::P3m1),
        ("p31m", SymmetryArg::P31m),
        ("p6", SymmetryArg::P6),
        ("p6m", SymmetryArg::P6m),
    ];
    /// `--format` of `fill` and `line`.
    pub const FORMAT: [(&str, FormatArg); 6] = [
        ("svg", FormatArg::Svg),
        ("json", FormatArg::Json),
        ("csv", FormatArg::Csv),
        ("png", FormatArg::Png),
        ("digest", FormatArg::Digest),
        ("gcode", FormatArg::Gcode),
    ];
    /// `--style` of `fill` and `line`.
    pub const STYLE: [(&str, StyleArg); 2] = [("outline", StyleArg::Outline), ("filled", StyleArg::Filled)];
    /// `--relief`.
    pub const RELIEF: [(&str, ReliefArg); 3] = [("dome", ReliefArg::Dome), ("cone", ReliefArg::Cone), ("flat", ReliefArg::Flat)];
    /// `--color-by`.
    pub const COLOR_BY: [(&str, ColorByArg); 4] = [
        ("size", ColorByArg::Size),
        ("random", ColorByArg::Random),
        ("cycle", ColorByArg::Cycle),
        ("kind", ColorByArg::Kind),
    ];
    /// `--order`.
    pub const ORDER: [(&str, OrderArg); 3] = [
        ("none", OrderArg::None),
        ("greedy", OrderArg::Greedy),
        ("improved", OrderArg::Improved),
    ];
    /// `--render` of `line`.
    pub const LINE_RENDER: [(&str, LineRender); 4] = [
        ("dashes", LineRender::Dashes),
        ("circles", LineRender::Circles),
        ("bars", LineRender::Bars),
        ("zoom", LineRender::Zoom),
    ];
    /// `--render` of `territory`.
    pub const TERRITORY_RENDER: [(&str, TerritoryRender); 4] = [
        ("boundaries", TerritoryRender::Boundaries),
        ("cells", TerritoryRender::Cells),
        ("filled", TerritoryRender::Filled),
        ("shapes", TerritoryRender::Shapes),
    ];
    /// `--format` of `territory`.
    pub const TERRITORY_FORMAT: [(&str, TerritoryFormatArg); 4] = [
        ("svg", TerritoryFormatArg::Svg),
        ("png", TerritoryFormatArg::Png),
        ("json", TerritoryFormatArg::Json),
        ("gcode", TerritoryFormatArg::Gcode),
    ];
    /// `--render` of `tile`.
    pub const TILE_RENDER: [(&str, TileRender); 2] = [("discs", TileRender::Discs), ("voronoi", TileRender::Voronoi)];
    /// `--style` of `tile`.
    pub const TILE_STYLE: [(&str, tile::StyleArg); 2] = [("outline", tile::StyleArg::Outline), ("filled", tile::StyleArg::Filled)];
    /// `--layout` of `tile`.
    pub const LAYOUT: [(&str, LayoutArg); 3] = [
        ("tile", LayoutArg::Tile),
        ("mosaic", LayoutArg::Mosaic),
        ("planet", LayoutArg::Planet),
    ];
    /// `--format` of `tile`.
    pub const TILE_FORMAT: [(&str, TileFormatArg); 4] = [
        ("svg", TileFormatArg::Svg),
        ("png", TileFormatArg::Png),
        ("json", TileFormatArg::Json),
        ("gcode", TileFormatArg::Gcode),
    ];
}

use names::*;

/// Any text.
fn text(s: &str) -> Result<String, String> {
    Ok(s.to_string())
}

/// A path.
fn path(s: &str) -> Result<PathBuf, String> {
    match s {
        "" => Err(MISSING.to_string()),
        _ => Ok(PathBuf::from(s)),
    }
}

/// A 32-bit whole number in `lo..=hi`.
fn small(lo: u64, hi: u64) -> impl Fn(&str) -> Result<u32, String> {
    move |s| ranged(s, lo, Some(hi), true).map(|v| v as u32)
}

/// A 64-bit whole number from `lo`, up to `hi` if given.
fn whole(lo: u64, hi: Option<u64>) -> impl Fn(&str) -> Result<u64, String> {
    move |s| ranged(s, lo, hi, false)
}

/// Which command's wording of the power law and the stops.
#[derive(Clone, Copy, PartialEq)]
enum Pieces {
    Shapes,
    Segments,
}

fn power_law(w: &mut Words, pieces: Pieces) -> Result<PowerLawArgs, String> {
    let dimension = match pieces {
        Pieces::Shapes => w.opt("dimension", spec::dimension)?,
        Pieces::Segments => w.opt("dimension", line::dimension_1d)?,
    };
    let a = PowerLawArgs {
        c: w.opt("c", spec::exponent)?,
        dimension,
        n_offset: w.or("n-offset", "1", spec::n_offset)?,
    };
    w.conflict("c", "dimension")?;
    Ok(a)
}

fn stop(w: &mut Words, pieces: Pieces) -> Result<StopArgs, String> {
    let most = if pieces == Pieces::Shapes { MAX_SHAPES } else { MAX_SEGMENTS };
    Ok(StopArgs {
        count: w.opt("count", whole(1, Some(most)))?,
        fill: w.opt("fill", spec::fraction)?,
        min_size: w.opt("min-size", spec::length)?,
    })
}

fn seed(w: &mut Words) -> Result<SeedArgs, String> {
    Ok(SeedArgs {
        seed: w.or("seed", "1", whole(0, None))?,
    })
}

fn run(w: &mut Words, pieces: Pieces) -> Result<RunArgs, String> {
    Ok(RunArgs {
        power: power_law(w, pieces)?,
        stop: stop(w, pieces)?,
        gap: w.or("gap", "0", spec::length_or_zero)?,
        max_trials: w.or("max-trials", "10000000", whole(1, None))?,
        seed: seed(w)?,
    })
}

/// `-o`, `--format` (one of `formats`) and `--max-output-size`. A macro, as the type of
/// the formats carries clap's bound.
macro_rules! output {
    ($w:expr, $formats:expr) => {
        OutputArgs {
            output: $w.required("output", path)?,
            format: $w.opt("format", |s| choice(s, &$formats))?,
            max_output_size: $w.or("max-output-size", "4G", byte_size)?,
        }
    };
}

fn raster(w: &mut Words) -> Result<RasterArgs, String> {
    let a = RasterArgs {
        dpi: w.or("dpi", "96", spec::positive)?,
        pixels: w.opt("pixels", small(1, 100_000))?,
    };
    w.conflict("pixels", "dpi")?;
    Ok(a)
}

fn colour(w: &mut Words) -> Result<ColourArgs, String> {
    let a = ColourArgs {
        palette: w.opt("palette", palette::palette)?,
        color_by: w.opt("color-by", |s| choice(s, &COLOR_BY))?,
        background: w.opt("background", palette::colour)?,
    };
    w.requires("color-by", "palette")?;
    Ok(a)
}

fn plot(w: &mut Words) -> Result<PlotArgs, String> {
    let a = PlotArgs {
        machine: w.opt("machine", text)?,
        feed: w.opt("feed", plot::finite)?,
        travel_feed: w.opt("travel-feed", plot::finite)?,
        power: w.opt("power", plot::finite)?,
        passes: w.opt("passes", small(1, 100))?,
        arcs: w.flag("arcs")?,
        no_arcs: w.flag("no-arcs")?,
        chord_tolerance: w.opt("chord-tolerance", plot::positive)?,
        hatch: w.opt("hatch", text)?,
        hatch_only: w.flag("hatch-only")?,
        cross_hatch: w.flag("cross-hatch")?,
        order: w.opt("order", |s| choice(s, &ORDER))?,
        min_feature: w.or("min-feature", "0", spec::length_or_zero)?,
        fit: w.flag("fit")?,
        center: w.flag("center")?,
        page: w.opt("page", plot::parse_page)?,
        margin: w.opt("margin", spec::length_or_zero)?,
        layers: w.or("layers", "none", plot::parse_layers)?,
    };
    w.conflict("arcs", "no-arcs")?;
    w.requires("hatch-only", "hatch")?;
    w.requires("cross-hatch", "hatch")?;
    Ok(a)
}

fn region_input(w: &mut Words) -> Result<RegionInputArgs, String> {
    Ok(RegionInputArgs {
        region_width: w.opt("region-width", spec::length)?,
        region_sha256: w.opt("region-sha256", text)?,
        font: w.opt("font", path)?,
        font_sha256: w.opt("font-sha256", text)?,
        text_size: w.opt("text-size", spec::length)?,
        letter_spacing: w.opt("letter-spacing", spec::length_or_zero)?,
    })
}

/// `zetafill fill ARGV`.
pub fn fill(w: &mut Words) -> Result<FillArgs, String> {
    Ok(FillArgs {
        shape: w.or("shape", "circle", spec::shape)?,
        mix_order: w.or("mix-order", "cycle", |s| choice(s, &MIX))?,
        rotate: w.opt("rotate", |s| choice(s, &ROTATE))?,
        region: w.opt("region", spec::fill_region)?,
        input: region_input(w)?,
        periodic: w.flag("periodic")?,
        symmetry: symmetry(w)?,
        run: run(w, Pieces::Shapes)?,
        sampler: w.or("sampler", "fast", |s| choice(s, &SAMPLER))?,
        cells: w.opt("cells", whole(1, None))?,
        threads: w.opt("threads", whole(1, Some(1024)))?,
        batch: w.opt("batch", whole(1, Some(4096)))?,
        density: w.opt("density", spec::density)?,
        density_sha256: w.opt("density-sha256", text)?,
        scalar: w.or("scalar", "f64", |s| choice(s, &SCALAR))?,
        output: output!(w, FORMAT),
        style: w.or("style", "outline", |s| choice(s, &STYLE))?,
        pen_width: w.or("pen-width", "0.3", spec::length)?,
        boundary: w.flag("boundary")?,
        raster: raster(w)?,
        relief: w.opt("relief", |s| choice(s, &RELIEF))?,
        colour: colour(w)?,
        voronoi: w.flag("voronoi")?,
        quiet: w.flag("quiet")?,
        plot: plot(w)?,
    })
}

/// The symmetry flags of `zetafill fill`, with clap's rules between them and the flags
/// the pattern replaces.
fn symmetry(w: &mut Words) -> Result<SymmetryArgs, String> {
    let a = SymmetryArgs {
        symmetry: w.opt("symmetry", |s| choice(s, &SYMMETRY))?,
        lattice: w.opt("lattice", symmetry::lattice)?,
        repeat: w.opt("repeat", symmetry::repeat)?,
    };
    for other in ["periodic", "voronoi"] {
        w.conflict("symmetry", other)?;
    }
    w.conflict("repeat", "region")?;
    w.requires("symmetry", "lattice")?;
    w.requires("lattice", "symmetry")?;
    w.requires("repeat", "symmetry")?;
    Ok(a)
}

/// `zetafill line ARGV`.
pub fn line(w: &mut Words) -> Result<LineArgs, String> {
    Ok(LineArgs {
        length: w.or("length", "200", spec::length)?,
        periodic: w.flag("periodic")?,
        run: run(w, Pieces::Segments)?,
        sampler: w.or("sampler", "fast", |s| choice(s, &SAMPLER))?,
        output: output!(w, FORMAT),
        render: w.or("render", "circles", |s| choice(s, &LINE_RENDER))?,
        style: w.or("style", "outline", |s| choice(s, &STYLE))?,
        pen_width: w.or("pen-width", "0.3", spec::length)?,
        bar_height: w.or("bar-height", "10", spec::length)?,
        zoom_rows: w.or("zoom-rows", "4", small(1, 12))?,
        zoom_fraction: w.or("zoom-fraction", "0.05", spec::fraction)?,
        zoom_center: w.opt("zoom-center", spec::length_or_zero)?,
        boundary: w.flag("boundary")?,
        colour: colour(w)?,
        raster: raster(w)?,
        quiet: w.flag("quiet")?,
        plot: plot(w)?,
    })
}

/// `zetafill territory ARGV`.
pub fn territory(w: &mut Words) -> Result<TerritoryArgs, String> {
    let a = TerritoryArgs {
        sites: w.opt("sites", territory::seed_count)?,
        site: w.all("site", territory::point)?,
        sites_from: w.opt("sites-from", path)?,
        points: w.opt("points", whole(2, Some(MAX_POINTS as u64)))?,
        region: w.or("region", "rect:200:200", spec::region)?,
        seed: seed(w)?,
        render: w.or("render", "boundaries", |s| choice(s, &TERRITORY_RENDER))?,
        uniform: w.flag("uniform")?,
        n0: w.or("n0", "1000", whole(1, None))?,
        s: w.or("s", "0.1", territory::bucket_scale)?,
        boost: w.or("boost", "8", territory::boost)?,
        colors: w.all("color", territory::colour_rule)?,
        output: output!(w, TERRITORY_FORMAT),
        pen_width: w.or("pen-width", "0.3", spec::length)?,
        thin_width: w.or("thin-width", "0.1", spec::length)?,
        boundary: w.flag("boundary")?,
        raster: raster(w)?,
        quiet: w.flag("quiet")?,
        colours: colour(w)?,
        plot: plot(w)?,
    };
    w.conflict("sites", "site")?;
    w.conflict("sites-from", "points")?;
    w.conflict("sites-from", "region")?;
    Ok(a)
}

/// `zetafill tile ARGV`.
pub fn tile(w: &mut Words) -> Result<TileArgs, String> {
    Ok(TileArgs {
        width: w.or("width", "100", spec::length)?,
        height: w.or("height", "100", spec::length)?,
        radius: w.or("radius", "5", spec::length)?,
        spacing: w.or("spacing", "1", spec::length_or_zero)?,
        tries: w.or("tries", "20000", whole(1, Some(100_000_000)))?,
        seed: seed(w)?,
        render: w.or("render", "discs", |s| choice(s, &TILE_RENDER))?,
        style: w.or("style", "outline", |s| choice(s, &TILE_STYLE))?,
        layout: w.or("layout", "tile", |s| choice(s, &LAYOUT))?,
        rows: w.opt("rows", small(1, 10))?,
        columns: w.opt("columns", small(1, 4096))?,
        planet_radius: w.opt("planet-radius", spec::length)?,
        output: output!(w, TILE_FORMAT),
        pen_width: w.or("pen-width", "0.3", spec::length)?,
        colour: colour(w)?,
        raster: raster(w)?,
        relief: w.opt("relief", |s| choice(s, &RELIEF))?,
        quiet: w.flag("quiet")?,
        plot: plot(w)?,
    })
}
