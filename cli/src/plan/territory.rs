//! `zetafill territory` resolved: the flags checked against each other in the order the
//! command has always reported them, and turned into the run (where the sites come from,
//! the seeds, the growth and the colour rules) and the drawing (the writers' plain options).
//!
//! Some rules need the region or the fill's JSON (a seed outside the region, more seeds than
//! the fill has shapes) or have always been reported after the growth (more `--color` rules
//! than territories): their messages live here too, and the run checks them where it always
//! has, so the first error reported stays the same.

use crate::args::plot::{Layers, PlotArgs};
use crate::args::territory::{RenderArg, TerritoryArgs};
use crate::error::CliError;
use crate::geometry::site::SiteError;
use crate::geometry::voronoi::Pt;
use crate::model::region::RegionSpec;
use crate::output::palette::ColorBy;
use crate::output::png::Raster;
use crate::plan::colour::Colours;
use crate::plan::format::TerritoryFormat;
use crate::plan::plot::GcodePlan;
use crate::plan::plot::FOR_GCODE;
use crate::plan::raster;
use std::path::{Path, PathBuf};

/// A checked `zetafill territory`: where it writes, what it grows and how it draws.
pub type TerritoryPlan = super::Planned<TerritoryFormat, TerritoryRun, TerritoryDraw>;

/// What the territory competition grows.
#[derive(Debug, Clone)]
pub struct TerritoryRun {
    /// A fill's JSON whose centres are the sites (and whose region is the region).
    pub sites_from: Option<PathBuf>,
    /// The region, without `sites_from`.
    pub region: RegionSpec,
    /// The number of seeds k (territories).
    pub seeds: usize,
    /// The seed points given; none: k drawn at random.
    pub site: Vec<Pt>,
    /// Total number of sites, seeds included, without `sites_from`.
    pub points: usize,
    /// No density control.
    pub uniform: bool,
    /// The paper's n0.
    pub n0: u64,
    /// The paper's s.
    pub s: f64,
    /// Weight of a boundary bucket.
    pub boost: f64,
    /// RNG seed.
    pub seed: u64,
    /// Colour rules of territory 0, 1, ...: c^k, and d^k if given.
    pub colors: Vec<([f64; 3], Option<[f64; 3]>)>,
    /// What the drawing shows (the JSON records it).
    pub render: Render,
    /// No progress bar.
    pub quiet: bool,
}

/// How the pattern is drawn.
#[derive(Debug, Clone)]
pub struct TerritoryDraw {
    /// What to draw.
    pub render: Render,
    /// Stroke width of the boundaries (mm).
    pub pen_width: f64,
    /// Stroke width of the thin cell edges (mm).
    pub thin_width: f64,
    /// Also draw the region's outline.
    pub boundary: bool,
    /// PNG size.
    pub raster: Raster,
    /// The colours, as the colour flags set them.
    pub colours: Colours,
    /// The plot flags as command-line text.
    pub plot_flags: String,
    /// G-code: the machine, its placement and whether its figures go to stderr.
    pub gcode: Option<GcodePlan>,
}

/// What to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Render {
    /// Territory boundaries as merged polylines (plotters).
    Boundaries,
    /// All Voronoi edges: cells thin, boundaries at pen width (two layers).
    Cells,
    /// Cells filled with their HSB colours (screens, prints).
    Filled,
    /// The fill's own shapes filled with their site's colour (only with --sites-from).
    Shapes,
}

impl Render {
    /// The name as on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Render::Boundaries => "boundaries",
            Render::Cells => "cells",
            Render::Filled => "filled",
            Render::Shapes => "shapes",
        }
    }
}

impl From<RenderArg> for Render {
    fn from(r: RenderArg) -> Render {
        match r {
            RenderArg::Boundaries => Render::Boundaries,
            RenderArg::Cells => Render::Cells,
            RenderArg::Filled => Render::Filled,
            RenderArg::Shapes => Render::Shapes,
        }
    }
}

/// How territories take a palette's colours unless `--color-by` says: in turn.
const COLOUR_BY: ColorBy = ColorBy::Cycle;

/// Checks the flags of `zetafill territory` and resolves them into a plan. Nothing runs and
/// nothing is read but the machine profile.
pub fn resolve(a: &TerritoryArgs) -> Result<TerritoryPlan, CliError> {
    TerritoryPlan::resolve(
        &a.output.output,
        a.output.max_output_size,
        || TerritoryFormat::resolve(a.output.format, &a.output.output),
        |format| resolve_as(a, format),
    )
}

/// The run and the drawing of `a` written as `format`: every rule between the flags, but
/// none about the output path (a library caller, such as a test, picks the format).
pub fn resolve_as(a: &TerritoryArgs, format: TerritoryFormat) -> Result<(TerritoryRun, TerritoryDraw), CliError> {
    raster::check(&a.raster, format == TerritoryFormat::Png)?;
    check_plot(a, format)?;
    check_colours(a, format)?;
    if a.site.len() == 1 {
        return Err(CliError::arg(
            "--site",
            "territory competing needs at least 2 seeds; give --site twice or more, or --sites K",
        ));
    }
    if a.render == RenderArg::Shapes && a.sites_from.is_none() {
        return Err(CliError::arg(
            "--render",
            "shapes draws a fill's shapes: it needs --sites-from FILE.json; use boundaries, cells or filled",
        ));
    }
    let render = Render::from(a.render);
    let run = TerritoryRun {
        sites_from: a.sites_from.clone(),
        region: a.region.clone(),
        seeds: if a.site.is_empty() { a.sites.unwrap_or(3) } else { a.site.len() },
        site: a.site.clone(),
        points: a.points.map_or(7000, |p| p as usize),
        uniform: a.uniform,
        n0: a.n0,
        s: a.s,
        boost: a.boost,
        seed: a.seed.seed,
        colors: a.colors.clone(),
        render,
        quiet: a.quiet,
    };
    let draw = TerritoryDraw {
        render,
        pen_width: a.pen_width,
        thin_width: a.thin_width,
        boundary: a.boundary,
        raster: a.raster.raster(),
        colours: Colours {
            palette: a.colours.palette.clone(),
            by: a.colours.by_or(COLOUR_BY),
            layers: false,
            background: a.colours.background.clone(),
            flags: a.colours.flags_or(COLOUR_BY),
        },
        plot_flags: a.plot.flags(),
        gcode: if format == TerritoryFormat::Gcode {
            Some(GcodePlan::resolve(&a.plot, a.quiet)?)
        } else {
            None
        },
    };
    Ok((run, draw))
}

/// Refuses the plot flags that have no meaning for territories, before any work.
fn check_plot(a: &TerritoryArgs, format: TerritoryFormat) -> Result<(), CliError> {
    let p: &PlotArgs = &a.plot;
    let not_here = |flag: &str, why: &str| Err(CliError::arg(flag, format!("is not available for territory: {why}")));
    if p.hatch.is_some() || p.hatch_only {
        return not_here("--hatch", "territories are drawn as lines");
    }
    if p.min_feature > 0.0 {
        return not_here("--min-feature", "every boundary edge is drawn");
    }
    if p.layers != Layers::None {
        return not_here("--layers", "the SVG has its own layers (cells, boundaries, outline)");
    }
    if p.page.is_some() {
        return not_here("--page", "the SVG is drawn at the region's size");
    }
    if format == TerritoryFormat::Gcode {
        if !matches!(a.render, RenderArg::Boundaries | RenderArg::Cells) {
            return Err(CliError::arg("--render", "G-code draws lines: use --render boundaries or cells"));
        }
        let m = p.machine()?;
        p.gcode_options(&m)?;
    } else if p.fit || p.center {
        return Err(CliError::arg(
            if p.fit { "--fit" } else { "--center" },
            "places the drawing on a machine's bed: it is for G-code output",
        ));
    } else {
        p.refuse_except(&[], |_| FOR_GCODE.to_string())?;
    }
    Ok(())
}

/// Refuses colour flags where nothing shows them or where they clash with `--color`.
fn check_colours(a: &TerritoryArgs, format: TerritoryFormat) -> Result<(), CliError> {
    let shown = matches!(format, TerritoryFormat::Svg | TerritoryFormat::Png) && matches!(a.render, RenderArg::Filled | RenderArg::Shapes);
    a.colours
        .check(shown, "use --render filled or shapes with an .svg or .png output", true)?;
    if a.colours.palette.is_some() && !a.colors.is_empty() {
        return Err(CliError::arg("--palette", "replaces the --color rules; give one or the other"));
    }
    Ok(())
}

impl TerritoryRun {
    /// The flag that set the number of seeds.
    fn seeds_flag(&self) -> &'static str {
        if self.site.is_empty() {
            "--sites"
        } else {
            "--site"
        }
    }

    /// Refuses a given seed outside the region (`inside` says what is in it) or given twice,
    /// seed by seed.
    pub fn check_seeds(&self, inside: impl Fn(Pt) -> bool) -> Result<(), CliError> {
        for (i, p) in self.site.iter().enumerate() {
            if !inside(*p) {
                return Err(CliError::arg(
                    "--site",
                    format!("{},{} lies outside the region; give seeds inside it", p[0], p[1]),
                ));
            }
            if self.site[..i].contains(p) {
                return Err(CliError::arg(
                    "--site",
                    format!("{},{} is given twice; seeds must be distinct points", p[0], p[1]),
                ));
            }
        }
        Ok(())
    }

    /// Refuses more seeds than the `n` shapes of the fill the sites come from.
    pub fn check_seeds_in_fill(&self, n: usize) -> Result<(), CliError> {
        let k = self.seeds;
        if k > n {
            return Err(CliError::arg(
                self.seeds_flag(),
                format!("{k} seeds but the fill has only {n} shapes; ask for fewer seeds (more sites than points)"),
            ));
        }
        Ok(())
    }

    /// Refuses more seeds than `--points`.
    pub fn check_seeds_in_points(&self) -> Result<(), CliError> {
        let (k, points) = (self.seeds, self.points);
        if k > points {
            return Err(CliError::arg(
                self.seeds_flag(),
                format!("{k} seeds but only --points {points}: more sites than points; raise --points or give fewer seeds"),
            ));
        }
        Ok(())
    }

    /// Refuses more `--color` rules than territories (reported once the pattern has grown,
    /// where the command has always reported it).
    pub fn check_colour_rules(&self) -> Result<(), CliError> {
        let k = self.seeds;
        if self.colors.len() > k {
            return Err(CliError::arg(
                "--color",
                format!("{} colours for {k} territories; give at most one per territory", self.colors.len()),
            ));
        }
        Ok(())
    }
}

/// The refusal of a `--site` (`p`) that picks the same centre of the fill as an earlier one.
pub fn same_centre(p: Pt) -> CliError {
    CliError::arg(
        "--site",
        format!(
            "{},{} picks the same centre as an earlier --site; give seeds farther apart",
            p[0], p[1]
        ),
    )
}

/// The refusal of a region in which no random seed could be drawn.
pub fn no_seed_drawn() -> CliError {
    CliError::arg("--region", "no seed could be drawn inside the region")
}

/// The seeds given (`--site`) cannot start a pattern.
pub fn seeds_error(e: SiteError) -> CliError {
    CliError::arg("--site", e)
}

/// The seeds taken from the fill (`--sites-from`) cannot start a pattern.
pub fn fill_seeds_error(e: SiteError) -> CliError {
    CliError::arg("--sites-from", e)
}

/// The pattern cannot grow in the region.
pub fn growth_error(e: SiteError) -> CliError {
    CliError::arg("--region", e)
}

/// A `--sites-from` file (`path`) that cannot serve, and why.
pub fn sites_from_error(path: &Path, why: impl std::fmt::Display) -> CliError {
    CliError::arg("--sites-from", format!("'{}': {why}", path.display()))
}

/// The refusal of a `--sites-from` file (`path`) that is JSON but not a fill's.
pub fn not_a_fill(path: &Path) -> CliError {
    sites_from_error(
        path,
        "not a fill's JSON (no \"mode\": \"fill\"); write one with zetafill fill -o FILE.json",
    )
}
