//! `zetafill fill` resolved: the flags checked against each other in the order the command
//! has always reported them, and turned into the run (the core's parameters and stops) and
//! the drawing (the writers' plain options). The messages of the run's own outcomes are in
//! `plan::fill_errors`.

use crate::args::fill::{FillArgs, MixArg, Rotate, Sampler, ScalarArg, MAX_SHAPES};
use crate::args::plot::{Layers, PlotArgs, SVG_FLAGS};
use crate::args::style::StyleArg;
use crate::error::CliError;
use crate::model::fill::BuildOptions;
use crate::model::region::RegionSpec;
use crate::output::height::Relief;
use crate::output::png::Raster;
use crate::output::svg::Style;
use crate::plan::colour::Colours;
use crate::plan::format::Format;
use crate::plan::plot::FOR_GCODE;
use crate::plan::plot::{GcodePlan, PagePlan};
use crate::plan::raster::{self, only_png};
use crate::plan::Unit;
use zetafill::{MixOrder, Params, ShapeList, Stop};

/// What a 2D run places, and the most one run may hold.
pub const SHAPES: Unit = Unit {
    plural: "shapes",
    max: MAX_SHAPES,
};

/// A checked `zetafill fill`: where it writes, what it runs and how it draws.
pub type FillPlan = super::Planned<Format, FillRun, FillDraw>;

/// The refusal of `--scalar fixed` by a build without the `fixed-point` feature.
pub fn no_fixed_point() -> CliError {
    CliError::arg(
        "--scalar",
        "this build computes in f64 only (the browser page has no fixed point); use --scalar f64, or the command-line tool",
    )
}

/// What the engine runs.
#[derive(Debug, Clone, PartialEq)]
pub struct FillRun {
    /// The region (an SVG region is read when the run starts; a mask or a text is already
    /// rings).
    pub region: RegionSpec,
    /// Periodic boundary.
    pub periodic: bool,
    /// The symmetry of a wallpaper group, which takes the place of the region.
    pub symmetry: Option<super::symmetry::SymmetryPlan>,
    /// The core's parameters.
    pub params: Params,
    /// The motifs the shape kinds number (`--shape svg:FILE`, `glyph:TEXT`).
    pub motifs: std::sync::Arc<Vec<super::motif::MotifSource>>,
    /// The stop conditions.
    pub stop: Stop,
    /// RNG seed.
    pub seed: u64,
    /// The paper's sampler (and the coverage bitmap it asks) instead of the cell sampler.
    pub reference_sampler: bool,
    /// The batched cell sampler: the threads that screen, and the largest batch.
    pub batched: Option<(usize, usize)>,
    /// Where centres are wanted (`--density`).
    pub density: Option<crate::model::density::DensitySpec>,
    /// The picture of `--density image:FILE`, read when the run was planned.
    pub picture: Option<std::sync::Arc<crate::io::image::Grey>>,
    /// The engine computes in 32.32 fixed point instead of f64.
    pub fixed_point: bool,
    /// No progress bar.
    pub quiet: bool,
    /// The names the JSON document records: shape, rotation, mix order (mixes only),
    /// sampler and scalar.
    pub names: FillNames,
}

/// The names of a run's settings as its JSON document writes them.
#[derive(Debug, Clone, PartialEq)]
pub struct FillNames {
    /// `--shape` as written back.
    pub shape: String,
    /// `random` or `none`.
    pub rotate: &'static str,
    /// `cycle` or `random`, for a mix.
    pub mix_order: Option<&'static str>,
    /// `fast` or `reference`.
    pub sampler: &'static str,
    /// `f64` or `fixed`.
    pub scalar: &'static str,
    /// `--cells`, when given.
    pub cells: Option<u64>,
    /// The largest batch, with the batched sampler.
    pub batch: Option<u64>,
    /// `--density`, written in full, when given.
    pub density: Option<String>,
    /// The SHA-256 of the `--density` picture.
    pub density_sha256: Option<String>,
    /// The SHA-256 of each SVG motif's file, in the order `--shape` names them.
    pub motif_sha256: Option<Vec<String>>,
    /// A region made from a picture or a text: the flags that make it again.
    pub source: Option<crate::model::region::RegionSource>,
}

/// How the document is drawn.
#[derive(Debug, Clone)]
pub struct FillDraw {
    /// Cobblestones (the Voronoi cells of the centres) instead of the shapes.
    pub voronoi: bool,
    /// PNG: a height map of this profile instead of a picture.
    pub relief: Option<Relief>,
    /// PNG size.
    pub raster: Raster,
    /// Outline or filled.
    pub style: Style,
    /// Stroke width (mm).
    pub pen_width: f64,
    /// Also draw the region's outline.
    pub boundary: bool,
    /// SVG: outlines, hatching and the smallest feature drawn.
    pub build: BuildOptions,
    /// SVG: the page, if any.
    pub page: Option<PagePlan>,
    /// SVG: K layers by size.
    pub size_layers: Option<u32>,
    /// The plot flags as command-line text.
    pub plot_flags: String,
    /// The colours, as the colour flags set them.
    pub colours: Colours,
    /// The shapes of the run, to tell each shape's entry in a mix.
    pub shapes: ShapeList,
    /// G-code: the machine, its placement and whether its figures go to stderr.
    pub gcode: Option<GcodePlan>,
}

/// The message of `--layers colours` without a palette.
fn colours_need_palette() -> CliError {
    CliError::arg(
        "--layers",
        "colours makes one layer (one pen) per --palette colour: give --palette, or use size-bands:K",
    )
}

/// The core's mix order.
fn mix_order(m: MixArg) -> MixOrder {
    match m {
        MixArg::Cycle => MixOrder::Cycle,
        MixArg::Random => MixOrder::Random,
    }
}

/// Checks that every plot flag given is one `format` reads (before the fill runs).
/// `--chord-tolerance` is also read by every format when an SVG motif's curves are flattened
/// (`motif_svg`).
fn check_plot(p: &PlotArgs, format: Format, motif_svg: bool) -> Result<(), CliError> {
    p.build_options()?;
    let tolerance: &[&str] = if motif_svg { &["--chord-tolerance"] } else { &[] };
    match format {
        Format::Gcode => p.check_gcode()?,
        Format::Svg | Format::Png => {
            let allowed: Vec<&str> = SVG_FLAGS.iter().chain(tolerance).copied().collect();
            p.refuse_except(&allowed, |_| FOR_GCODE.to_string())?;
            if (p.fit || p.center || p.margin.is_some()) && p.page.is_none() {
                let flag = if p.fit {
                    "--fit"
                } else if p.center {
                    "--center"
                } else {
                    "--margin"
                };
                return Err(CliError::arg(
                    flag,
                    "for SVG it needs --page (without a page the drawing is the region itself)",
                ));
            }
        }
        other => p.refuse_except(tolerance, |_| {
            format!("is for drawings (svg, png, gcode), not {} output", other.name())
        })?,
    }
    Ok(())
}

/// Checks the flags of `zetafill fill` and resolves them into a plan. Nothing runs and
/// nothing is read but the machine profile.
pub fn resolve(a: &FillArgs) -> Result<FillPlan, CliError> {
    FillPlan::resolve(
        &a.output.output,
        a.output.max_output_size,
        || Format::resolve(a.output.format, &a.output.output),
        |format| resolve_as(a, format),
    )
}

/// The run and the drawing of `a` written as `format`: every rule between the flags, but
/// none about the output path (a library caller, such as a test, picks the format).
pub fn resolve_as(a: &FillArgs, format: Format) -> Result<(FillRun, FillDraw), CliError> {
    if a.voronoi {
        a.plot.refuse_except(&[], |_| {
            "is not available with --voronoi (cobblestones are drawn at the region's size)".to_string()
        })?;
    }
    if format != Format::Png && a.relief.is_some() {
        return Err(only_png("--relief"));
    }
    raster::check(&a.raster, format == Format::Png)?;
    // A palette also picks the pens of a G-code plot with --layers colours.
    let colour_layers = a.plot.layers == Layers::Colours;
    let pens = format == Format::Gcode && colour_layers && a.colour.background.is_none();
    a.colour.check(
        (matches!(format, Format::Svg | Format::Png) && a.relief.is_none()) || pens,
        "write .svg or .png, without --relief (or G-code with --layers colours, without --background)",
        false,
    )?;
    if colour_layers && a.colour.palette.is_none() {
        return Err(colours_need_palette());
    }
    if a.voronoi && a.colour.palette.is_some() && a.style != StyleArg::Filled {
        return Err(CliError::arg(
            "--palette",
            "cobblestone outlines are edges, each shared by two cells; add --style filled to colour the cells",
        ));
    }
    if a.relief.is_some() {
        if a.voronoi {
            return Err(CliError::arg(
                "--relief",
                "a height map is made of the shapes, not of cobblestones: drop --voronoi",
            ));
        }
        a.plot.refuse_except(&[], |_| {
            "is not available with --relief (a height map has no page or layers)".to_string()
        })?;
    }
    check_plot(&a.plot, format, a.shape.has_svg())?;
    check_cells(a)?;
    for (given, flag, what) in [
        (a.threads.is_some(), "--threads", "screens on threads"),
        (a.batch.is_some(), "--batch", "takes placements in batches"),
    ] {
        if given && a.sampler != Sampler::Batched {
            return Err(CliError::arg(
                flag,
                format!("only the batched sampler {what}: add --sampler batched, or drop {flag}"),
            ));
        }
    }
    if a.plot.hatch.is_some() && a.style == StyleArg::Filled && matches!(format, Format::Svg | Format::Png) {
        return Err(CliError::arg(
            "--hatch",
            "draws lines, which filled shapes would hide: use --style outline",
        ));
    }
    if a.voronoi && !matches!(format, Format::Svg | Format::Png) {
        return Err(CliError::arg(
            "--voronoi",
            "cobblestones are drawn as SVG or PNG; write .svg or .png, or drop --voronoi",
        ));
    }
    let seed = a.run.seed.seed;
    let tolerance = a.plot.chord_tolerance.unwrap_or(super::motif::DEFAULT_MOTIF_TOLERANCE);
    let resolved = super::motif::resolve(&a.shape, &a.input, tolerance)?;
    let shapes =
        ShapeList::mix(&resolved.kinds, mix_order(a.mix_order), seed).unwrap_or_else(|| a.shape.list(mix_order(a.mix_order), seed));
    let params = Params {
        c: crate::plan::exponent(&a.run.power, 1.3, Params::c_from_dimension),
        n_offset: a.run.power.n_offset,
        shape: shapes.clone(),
        rotate: a.rotate.map_or(a.shape.rotates(), |r| r == Rotate::Random),
        gap: a.run.gap,
        max_trials: a.run.max_trials,
    };
    let picture = density_picture(a)?;
    // A symmetric pattern on a page, with neither --region nor --repeat, is cut to the page's
    // drawing area (the page less its margins), which it then fills.
    let page_window = match (&a.symmetry.symmetry, &a.region, &a.symmetry.repeat, &a.plot.page) {
        (Some(_), None, None, Some(page)) => {
            let margin = a.plot.margin.unwrap_or(super::plot::DEFAULT_PAGE_MARGIN);
            (2.0 * margin < page.width.min(page.height)).then_some(RegionSpec::Rect {
                width: page.width - 2.0 * margin,
                height: page.height - 2.0 * margin,
            })
        }
        _ => None,
    };
    let cut = a.region.is_some() || page_window.is_some();
    let (region, source) = crate::plan::region_input::resolve(&page_window.unwrap_or_else(|| a.region()), &a.input, a.shape.has_glyph())?;
    let names = FillNames {
        shape: a.shape.name(),
        rotate: if params.rotate && a.shape.rotates() { "random" } else { "none" },
        mix_order: a.shape.is_mix().then(|| a.mix_order.name()),
        sampler: a.sampler.name(),
        scalar: a.scalar.name(),
        cells: a.cells,
        batch: (a.sampler == Sampler::Batched).then(|| batch_size(a.batch) as u64),
        density: a.density.as_ref().map(|d| d.name()),
        density_sha256: picture.as_ref().map(|p| p.sha256.clone()),
        motif_sha256: Some(resolved.motifs.iter().filter_map(|m| m.sha256.clone()).collect::<Vec<_>>()).filter(|v| !v.is_empty()),
        source,
    };
    if a.scalar == ScalarArg::Fixed && !cfg!(feature = "fixed-point") {
        return Err(no_fixed_point());
    }
    let symmetry = super::symmetry::resolve(&a.symmetry, cut)?;
    let run = FillRun {
        region,
        periodic: a.periodic,
        symmetry,
        params,
        motifs: std::sync::Arc::new(resolved.motifs),
        stop: crate::plan::stops(&a.run.stop),
        seed,
        reference_sampler: a.sampler == Sampler::Reference,
        batched: (a.sampler == Sampler::Batched).then(|| (threads(a.threads), batch_size(a.batch))),
        density: a.density.clone(),
        picture,
        fixed_point: a.scalar == ScalarArg::Fixed,
        quiet: a.quiet,
        names,
    };
    let picture = matches!(format, Format::Svg | Format::Png) && a.relief.is_none() && !a.voronoi;
    let draw = FillDraw {
        voronoi: a.voronoi,
        relief: a.relief.map(Relief::from),
        raster: a.raster.raster(),
        style: a.style.into(),
        pen_width: a.pen_width,
        boundary: a.boundary,
        build: a.plot.build_options()?,
        page: if picture { PagePlan::resolve(&a.plot)? } else { None },
        size_layers: match a.plot.layers {
            Layers::SizeBands(k) => Some(k),
            _ => None,
        },
        plot_flags: a.plot.flags(),
        colours: a.colour.colours(colour_layers),
        shapes,
        gcode: if format == Format::Gcode {
            Some(GcodePlan::resolve(&a.plot, a.quiet)?)
        } else {
            None
        },
    };
    Ok((run, draw))
}

/// Most vertices of a polygon region on `--scalar fixed`: its region tests visit every edge on
/// every trial (the edge tree's pruning is proven for `f64` rounding only), so a fill's time
/// grows with the outline (about 80 s for 2,000 circles at the limit).
pub const FIXED_MAX_VERTICES: usize = 10_000;

/// The refusal of an outline too large for `--scalar fixed`.
pub fn fixed_outline_error(vertices: usize) -> CliError {
    CliError::arg(
        "--scalar",
        format!(
            "--scalar fixed tests every edge of the outline on every trial, and this outline has {vertices} vertices (at most {FIXED_MAX_VERTICES}); simplify the outline or use --scalar f64"
        ),
    )
}

/// The picture of `--density image:FILE`, read now so that a bad file stops the run before any
/// work, checked against `--density-sha256` when given.
fn density_picture(a: &FillArgs) -> Result<Option<std::sync::Arc<crate::io::image::Grey>>, CliError> {
    let Some(crate::model::density::DensitySpec::Image { path, .. }) = &a.density else {
        if a.density_sha256.is_some() {
            return Err(CliError::arg(
                "--density-sha256",
                "names the picture of --density image:FILE: drop it, or give an image density",
            ));
        }
        return Ok(None);
    };
    let grey = crate::io::image::read_grey(path).map_err(|e| CliError::arg("--density", e))?;
    crate::plan::region_input::check_digest("--density-sha256", path, &grey.sha256, a.density_sha256.as_ref(), "picture")?;
    Ok(Some(std::sync::Arc::new(grey)))
}

/// The largest batch `--batch` asks for, or the default.
pub fn batch_size(asked: Option<u64>) -> usize {
    asked.map_or(zetafill::DEFAULT_BATCH, |n| usize::try_from(n).unwrap_or(zetafill::DEFAULT_BATCH))
}

/// The threads `--threads` asks for, or one per core.
pub fn threads(asked: Option<u64>) -> usize {
    asked.map_or_else(
        // (A build without `parallel`, the browser page, has one thread.)
        || {
            if cfg!(feature = "parallel") {
                std::thread::available_parallelism().map_or(1, |n| n.get())
            } else {
                1
            }
        },
        |n| usize::try_from(n).unwrap_or(1),
    )
}

/// The fewest cells `--cells` lends: fewer leave the sampler no room to refine at all.
pub const MIN_CELLS: u64 = 64;

/// `--cells` only with the cell sampler, at least [`MIN_CELLS`], and at most what the fill
/// could use (more would change nothing but the memory taken).
fn check_cells(a: &FillArgs) -> Result<(), CliError> {
    let Some(n) = a.cells else { return Ok(()) };
    if a.sampler == Sampler::Reference {
        return Err(CliError::arg(
            "--cells",
            "only the cell sampler takes cells: drop --cells or use --sampler fast",
        ));
    }
    if n < MIN_CELLS {
        return Err(CliError::arg(
            "--cells",
            format!("{n} cells are too few: lend at least {MIN_CELLS}"),
        ));
    }
    let most = zetafill::cells_for(crate::args::common::MAX_SHAPES as usize) as u64;
    if n > most {
        return Err(CliError::arg(
            "--cells",
            format!("{n} is more cells than any fill uses ({most}): drop --cells to lend what the fill can use"),
        ));
    }
    Ok(())
}
