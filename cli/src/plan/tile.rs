//! `zetafill tile` resolved: the flags checked against each other in the order the command
//! has always reported them, and turned into the tile to grow (its spec and picture) and the
//! drawing (the arrangement of copies and the writers' plain options). Also the messages of
//! the run's own outcomes that name a flag: cobblestones that never meet their copies, a
//! drawing of too many pieces.

use crate::args::plot::{Layers, PlotArgs, GCODE_FLAGS};
use crate::args::tile::{LayoutArg, RenderArg, StyleArg, TileArgs};
use crate::error::CliError;
use crate::model::tile::{Arrangement, Layout, LayoutError, Render, SpecError, Style, TileSpec, MAX_DISCS};
use crate::output::height::Relief;
use crate::output::num;
use crate::output::png::Raster;
use crate::plan::colour::Colours;
use crate::plan::format::TileFormat;
use crate::plan::plot::GcodePlan;
use crate::plan::plot::FOR_GCODE;
use crate::plan::raster::{self, only_png};

/// A checked `zetafill tile`: where it writes, the tile it grows and how it draws it.
pub type TilePlan = super::Planned<TileFormat, TileRun, TileDraw>;

/// The tile to grow and the picture made of it.
#[derive(Debug, Clone, Copy)]
pub struct TileRun {
    /// The tile's parameters, checked (the band of twins is the one cobblestones start from).
    pub spec: TileSpec,
    /// Discs or cobblestones.
    pub render: Render,
    /// Outlines or filled shapes.
    pub style: Style,
    /// No progress bar, no figures on stderr.
    pub quiet: bool,
}

/// How the tile is drawn.
#[derive(Debug, Clone)]
pub struct TileDraw {
    /// The tile alone, a mosaic or a planet, with its rows and columns.
    pub arrangement: Arrangement,
    /// PNG: a height map of this profile instead of a picture.
    pub relief: Option<Relief>,
    /// PNG size.
    pub raster: Raster,
    /// Stroke width of outlines (mm).
    pub pen_width: f64,
    /// The colours, as the colour flags set them.
    pub colours: Colours,
    /// The plot flags as command-line text.
    pub plot_flags: String,
    /// G-code: the machine, its placement and whether its figures go to stderr.
    pub gcode: Option<GcodePlan>,
}

impl From<RenderArg> for Render {
    fn from(r: RenderArg) -> Render {
        match r {
            RenderArg::Discs => Render::Discs,
            RenderArg::Voronoi => Render::Voronoi,
        }
    }
}

impl From<StyleArg> for Style {
    fn from(s: StyleArg) -> Style {
        match s {
            StyleArg::Outline => Style::Outline,
            StyleArg::Filled => Style::Filled,
        }
    }
}

impl From<LayoutArg> for Layout {
    fn from(l: LayoutArg) -> Layout {
        match l {
            LayoutArg::Tile => Layout::Tile,
            LayoutArg::Mosaic => Layout::Mosaic,
            LayoutArg::Planet => Layout::Planet,
        }
    }
}

/// The band of twins Voronoi cobblestones start from (the "Fractal Tiles" post uses the top quarter).
const VORONOI_BAND: f64 = 0.25;

/// Checks the flags of `zetafill tile` and resolves them into a plan. Nothing runs and
/// nothing is read but the machine profile.
pub fn resolve(a: &TileArgs) -> Result<TilePlan, CliError> {
    TilePlan::resolve(
        &a.output.output,
        a.output.max_output_size,
        || TileFormat::resolve(a.output.format, &a.output.output),
        |format| resolve_as(a, format),
    )
}

/// The tile and the drawing of `a` written as `format`: every rule between the flags, but
/// none about the output path (a library caller, such as a test, picks the format).
pub fn resolve_as(a: &TileArgs, format: TileFormat) -> Result<(TileRun, TileDraw), CliError> {
    raster::check(&a.raster, format == TileFormat::Png)?;
    if a.relief.is_some() && format != TileFormat::Png {
        return Err(only_png("--relief"));
    }
    let layout = Layout::from(a.layout);
    if a.relief.is_some() && layout != Layout::Tile {
        return Err(CliError::arg(
            "--layout",
            "a height map is of the tile itself (it repeats seamlessly); drop --layout or --relief",
        ));
    }
    let arrangement = arrangement(a)?;
    check_plot(a, format)?;
    if format == TileFormat::Json && layout != Layout::Tile {
        return Err(CliError::arg(
            "--layout",
            "the JSON holds the tile's discs; draw a mosaic or a planet as SVG, PNG or G-code",
        ));
    }
    check_colours(a, format)?;
    let render = Render::from(a.render);
    let spec = TileSpec {
        width: a.width,
        height: a.height,
        radius: a.radius,
        spacing: a.spacing,
        tries: a.tries,
        seed: a.seed.seed,
        band: if render == Render::Voronoi { VORONOI_BAND } else { 0.0 },
    };
    spec.check().map_err(|e| spec_error(&spec, e))?;
    let run = TileRun {
        spec,
        render,
        style: a.style.into(),
        quiet: a.quiet,
    };
    let draw = TileDraw {
        arrangement,
        relief: a.relief.map(Relief::from),
        raster: a.raster.raster(),
        pen_width: a.pen_width,
        colours: a.colour.colours(a.plot.layers == Layers::Colours && a.colour.palette.is_some()),
        plot_flags: a.plot.flags(),
        gcode: if format == TileFormat::Gcode {
            Some(GcodePlan::resolve(&a.plot, a.quiet)?)
        } else {
            None
        },
    };
    Ok((run, draw))
}

/// The name `--layout` takes.
pub fn layout_name(l: Layout) -> &'static str {
    match l {
        Layout::Tile => "tile",
        Layout::Mosaic => "mosaic",
        Layout::Planet => "planet",
    }
}

/// The arrangement the flags ask for, with each layout's defaults; refuses layout flags the
/// layout does not read.
fn arrangement(a: &TileArgs) -> Result<Arrangement, CliError> {
    let layout = Layout::from(a.layout);
    let unread = |flag: &str, why: &str| {
        Err(CliError::arg(
            flag,
            format!("is not read by --layout {}: {why}", layout_name(layout)),
        ))
    };
    if layout == Layout::Tile {
        if a.rows.is_some() {
            return unread("--rows", "the tile is drawn alone; use --layout mosaic or planet");
        }
        if a.columns.is_some() {
            return unread("--columns", "the tile is drawn alone; use --layout mosaic or planet");
        }
    }
    if layout != Layout::Planet && a.planet_radius.is_some() {
        return unread("--planet-radius", "it sizes --layout planet");
    }
    let arr = Arrangement {
        layout,
        rows: a.rows.unwrap_or(4),
        columns: a.columns.unwrap_or(if layout == Layout::Planet { 16 } else { 2 }),
        radius: a.planet_radius.unwrap_or(100.0),
    };
    arr.check(a.width, a.height)
        .map_err(|e| layout_error(a.width, a.height, arr.columns, e))?;
    Ok(arr)
}

/// A tile spec that cannot make a tile, naming the flag to change.
fn spec_error(spec: &TileSpec, e: SpecError) -> CliError {
    match e {
        SpecError::Reach { quarter } => CliError::arg(
            "--radius",
            format!(
                "radius {} plus spacing {} is more than a quarter of the tile's smaller side ({}): a disc could reach two rows away; use a smaller --radius or --spacing, or a larger tile",
                spec.radius, spec.spacing, quarter
            ),
        ),
        SpecError::TooManyDiscs { most } => CliError::arg(
            "--radius",
            format!(
                "a {} x {} mm tile could hold about {:.3e} discs of radius {:?} to {:?}, more than {MAX_DISCS}; use a larger --radius or a smaller tile",
                spec.width,
                spec.height,
                most,
                0.5 * spec.radius,
                spec.radius
            ),
        ),
    }
}

/// An arrangement of `w` x `h` mm tiles, `columns` in the first row or ring, that cannot be
/// drawn, naming the flag to change.
fn layout_error(w: f64, h: f64, columns: u32, e: LayoutError) -> CliError {
    match e {
        LayoutError::InnerRing { need } => CliError::arg(
            "--columns",
            format!(
                "a planet of {w} x {h} mm tiles needs at least {need} tiles in its inner ring (got {columns}): with fewer the rings would cross the centre"
            ),
        ),
    }
}

/// Refuses the plot flags that the output does not read, before any work.
fn check_plot(a: &TileArgs, format: TileFormat) -> Result<(), CliError> {
    let p: &PlotArgs = &a.plot;
    if format == TileFormat::Gcode {
        let allowed: Vec<&str> = GCODE_FLAGS
            .iter()
            .copied()
            .chain(["--fit", "--center", "--margin", "--layers"])
            .collect();
        p.refuse_except(&allowed, |f| {
            format!("is not available for tile: {f} is for fills (the tile draws its own outlines, on the machine's bed)")
        })?;
        p.check_gcode()?;
    } else {
        p.refuse_except(&["--layers"], |_| FOR_GCODE.to_string())?;
    }
    match p.layers {
        Layers::None => Ok(()),
        Layers::SizeBands(_) => Err(CliError::arg(
            "--layers",
            "size bands are for fills; a coloured tile splits by pen with --layers colours",
        )),
        Layers::Colours if a.colour.palette.is_none() => Err(CliError::arg(
            "--layers",
            "colours makes one layer (one pen) per --palette colour: give --palette",
        )),
        Layers::Colours if !matches!(format, TileFormat::Svg | TileFormat::Gcode) => Err(CliError::arg(
            "--layers",
            "colours splits a plotter drawing by pen: write .svg or .gcode",
        )),
        Layers::Colours => Ok(()),
    }
}

/// Refuses colour flags the output cannot show.
fn check_colours(a: &TileArgs, format: TileFormat) -> Result<(), CliError> {
    let picture = matches!(format, TileFormat::Svg | TileFormat::Png) && a.relief.is_none();
    let pens = format == TileFormat::Gcode && a.plot.layers == Layers::Colours && a.colour.background.is_none();
    a.colour.check(
        picture || pens,
        "write .svg or .png, without --relief (or G-code with --layers colours, without --background)",
        true,
    )?;
    if a.colour.palette.is_some() && a.render == RenderArg::Voronoi && a.style == StyleArg::Outline {
        return Err(CliError::arg(
            "--palette",
            "cobblestone outlines are edges, each shared by two cells; add --style filled to colour the cells",
        ));
    }
    Ok(())
}

/// The refusal of cobblestones that do not meet their copies even with every centre
/// twinned (their matching ends `gap` mm apart).
pub fn seams_apart(gap: f64) -> CliError {
    CliError::arg(
        "--tries",
        format!(
            "the cobblestones do not meet their copies even with every centre twinned (ends {} mm apart): the fill is too sparse for its cells to stay near their discs; raise --tries",
            num(gap, 6)
        ),
    )
}

/// The refusal of a drawing of `copies` copies of a picture of `pieces` pieces, more than
/// `max` in all.
pub fn too_many_pieces(layout: Layout, copies: u64, pieces: usize, max: u64) -> CliError {
    CliError::arg(
        if layout == Layout::Tile { "--radius" } else { "--rows" },
        format!(
            "{copies} copies of a picture of {pieces} pieces make more than {max} pieces, too many to draw; lower --rows or --columns, or raise --radius"
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(radius: f64) -> TileSpec {
        TileSpec {
            width: 100.0,
            height: 80.0,
            radius,
            spacing: 1.0,
            tries: 3000,
            seed: 3,
            band: 0.0,
        }
    }

    fn message(s: TileSpec) -> String {
        s.check().map_err(|e| spec_error(&s, e).to_string()).err().unwrap_or_default()
    }

    #[test]
    fn oversized_and_tiny_discs_are_refused_naming_the_radius() {
        assert_eq!(
            message(spec(19.5)),
            "--radius: radius 19.5 plus spacing 1 is more than a quarter of the tile's smaller side (20): a disc could reach two rows away; use a smaller --radius or --spacing, or a larger tile"
        );
        assert!(message(spec(0.04)).starts_with("--radius: a 100 x 80 mm tile could hold about 6.366e6 discs of radius 0.02 to 0.04"));
        assert_eq!(message(spec(19.0)), "");
    }

    #[test]
    fn a_planet_with_too_few_inner_tiles_is_refused_naming_the_columns() {
        let arr = Arrangement {
            layout: Layout::Planet,
            rows: 4,
            columns: 2,
            radius: 100.0,
        };
        let e = arr
            .check(100.0, 100.0)
            .map_err(|e| layout_error(100.0, 100.0, arr.columns, e).to_string());
        assert_eq!(
            e,
            Err("--columns: a planet of 100 x 100 mm tiles needs at least 13 tiles in its inner ring (got 2): with fewer the rings would cross the centre".to_string())
        );
        assert!(Arrangement { columns: 13, ..arr }.check(100.0, 100.0).is_ok());
    }
}
