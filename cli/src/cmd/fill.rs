//! `zetafill fill`: the 2D fractal fill.

mod density;
pub mod region;

use crate::cmd::stopping;
use crate::error::CliError;
use crate::model::doc::{kind_name, FillDoc, ParamsDoc, ShapeDoc, ShapeParamsDoc, StatsDoc};
use crate::output;
use crate::output::stream::{Output, Size};
use crate::plan::fill::{fixed_outline_error, FillDraw, FillPlan, FillRun, FIXED_MAX_VERTICES, SHAPES};
use crate::plan::fill_errors::{first_shape_error, first_two_error, halt_advice, param_error, too_large_error, too_small_error};
use crate::plan::format::Format;
use crate::plan::raster::{height_map_error, png_error};
use crate::plan::symmetry::first_orbit_error;
use region::RegionData;
use zetafill::StepError;
use zetafill::{index_words, AreaSequence, CellSampler, Engine, Geo, Params, Placed, Region, ShapeKind, Stop, StopReason, Storage};

/// Words of the coverage bitmap (2 MiB): a 4096 x 4096 grid.
const COVERAGE_WORDS: usize = 1 << 18;

/// The concrete geometry of a placed shape as a [`ShapeDoc`], each point computed in the
/// scalar that tested it and then written as `f64`.
/// A motif's decorations (`sources`, by the kind's number) go by the frame it was placed by.
fn shape_doc<S: zetafill::Scalar>(
    kind: &ShapeKind,
    geo: &Geo<'_, S>,
    p: &Placed<f64>,
    (index, area, trials): (u64, f64, u64),
    sources: &[crate::plan::motif::MotifSource],
) -> ShapeDoc {
    let pt = |p: zetafill::Point<S>| [p.x.to_f64(), p.y.to_f64()];
    let decorations = match (kind, geo) {
        (ShapeKind::Motif { id, .. }, Geo::Motif { m, f }) => sources.get(usize::from(*id)).filter(|s| !s.decoration.is_empty()).map(|s| {
            s.decoration
                .iter()
                .map(|line| line.iter().map(|&q| pt(f.apply(m.to_unit(q)))).collect())
                .collect()
        }),
        _ => None,
    };
    let (radius, inner_radius, angle, vertices, outlines) = match geo {
        Geo::Circle { r, .. } => (Some(r.to_f64()), None, None, None, None),
        Geo::Ring { r, inner, .. } => (Some(r.to_f64()), Some(inner.to_f64()), None, None, None),
        Geo::Poly { .. } => (
            None,
            None,
            Some(p.angle),
            Some(geo.vertices().iter().map(|v| pt(*v)).collect()),
            None,
        ),
        Geo::Motif { m, f } => (
            None,
            None,
            Some(p.angle),
            None,
            Some(m.rings_at(f).map(|r| r.map(pt).collect()).collect()),
        ),
    };
    ShapeDoc {
        index,
        kind: kind_name(kind),
        center: [p.x, p.y],
        radius,
        inner_radius,
        angle,
        area,
        trials,
        vertices,
        outlines,
        decorations,
    }
}

/// What a run of the engine produced, in f64 whatever the scalar.
struct EngineRun {
    shapes: Vec<ShapeDoc>,
    stats: zetafill::Stats,
    reason: StopReason,
    zeta: f64,
    area: f64,
    digest: (u64, u64),
}

/// Runs the engine on scalar `S` with the CLI's storage, progress bar and known-limit checks
/// (the region and the smallest shape the scalar computes exactly, the first two shapes).
fn run_engine<S: zetafill::Scalar>(
    a: &FillRun,
    params: &Params,
    region: Region<'_>,
    sequence: &AreaSequence,
    stop: &Stop,
    cap: usize,
    watch: &mut dyn FnMut(&zetafill::Placement<f64>),
) -> Result<EngineRun, CliError> {
    if let Region::Polygon(p) = &region {
        if !S::IS_F64 && p.points().len() > FIXED_MAX_VERTICES {
            return Err(fixed_outline_error(p.points().len()));
        }
    }
    // The region first: the shapes' limits below are measured against what it allows.
    if !region.within(S::MAX_EXTENT) {
        return Err(param_error(zetafill::ParamError::Extent));
    }
    // Before the storage is allocated: a run that reaches shapes the scalar cannot resolve
    // may ask for millions.
    zetafill::check_smallest::<S>(sequence, &params.shape, stop, cap as u64, &region).map_err(|e| too_small_error(e, stop, S::IS_F64))?;
    zetafill::check_largest::<S>(sequence, &params.shape, stop, cap as u64)
        .map_err(|e| too_large_error(e, &params.shape, region.periodic()))?;
    // The density, made before the engine that borrows it.
    let density = density::field(a, &region)?;
    if let Some(d) = &density {
        density::refuse_zero(d, &region, false)?;
    }
    // A symmetric fill stores each orbit's images.
    let images = region.wallpaper().map_or(1, |w| w.order());
    let mut shapes = vec![Placed::<S>::default(); cap * images];
    let mut index = vec![0u32; index_words(cap * images)];
    // Only the paper's sampler asks the coverage bitmap (the cell sampler never does).
    let mut coverage = vec![0u64; if a.reference_sampler { COVERAGE_WORDS } else { 0 }];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    // The motifs, each over its own copy of the outline and edge tree (checked when planned).
    let mut buffers: Vec<(Vec<zetafill::Point<f64>>, Vec<u32>)> = a.motifs.iter().map(|_| Default::default()).collect();
    let motifs = a
        .motifs
        .iter()
        .zip(buffers.iter_mut())
        .map(|(m, (points, scratch))| m.motif(points, scratch))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| CliError::Io(format!("internal: a motif checked when planned is refused: {e}")))?;
    let mut engine = Engine::<S>::with_motifs(params.clone(), region, storage, &motifs).map_err(param_error)?;
    zetafill::check_first_two(params, &region).map_err(|e| first_two_error(e, params))?;
    engine.set_density(density.as_ref().map(|d| d as &dyn zetafill::Density));
    let mut rng = zetafill::rng_from_seed(a.seed);
    let bar = stopping::progress_bar(a.quiet, stop.count, SHAPES);
    let mut trials = Vec::with_capacity(cap);
    let on_place = |p: &zetafill::Placement<S>| {
        trials.push(p.trials);
        if let Some(b) = &bar {
            b.inc(1);
        }
        watch(&zetafill::Placement {
            index: p.index,
            shape: Placed {
                x: p.shape.x.to_f64(),
                y: p.shape.y.to_f64(),
                scale: p.shape.scale.to_f64(),
                angle: p.shape.angle.to_f64(),
            },
            area: p.area,
            trials: p.trials,
        });
    };
    let reason = if a.reference_sampler {
        engine.run(&mut rng, stop, on_place)
    } else {
        // Enough cells that only the sampler's own budget limits it: the shapes of a seed
        // then do not depend on the count asked for. Zeroed memory: the system maps only
        // the pages the sampler writes.
        // `--cells` lends fewer, as a board does (see `--help`).
        let lent = a.names.cells.map_or(usize::MAX, |n| usize::try_from(n).unwrap_or(usize::MAX));
        let mut pool = vec![[0u64; 4]; zetafill::cells_for(cap).min(lent)];
        let mut cells = CellSampler::new(&mut pool).map_err(|_| CliError::Io("internal: no cells for the fast sampler".into()))?;
        match a.batched {
            Some((threads, size)) => {
                let mut lanes = vec![zetafill::Lane::default(); size];
                let mut batches = zetafill::Batches::new(&mut lanes, a.seed, size)
                    .map_err(|_| CliError::Io("internal: no lanes for the batched sampler".into()))?;
                engine.run_batched_with(&mut cells, &mut batches, stop, on_place, |e, c, plan, lanes| {
                    screen_on(threads, e, c, plan, lanes);
                })
            }
            None => engine.run_fast(&mut cells, &mut rng, stop, on_place),
        }
    };
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    // (Of a symmetric fill, the representatives: each orbit's first entry.)
    let shapes_doc = engine
        .placed()
        .iter()
        .enumerate()
        .step_by(images)
        .filter_map(|(e, p)| {
            let g = engine.geo(e)?;
            let pf = Placed {
                x: p.x.to_f64(),
                y: p.y.to_f64(),
                scale: p.scale.to_f64(),
                angle: p.angle.to_f64(),
            };
            let i = (e / images) as u64;
            let t = trials.get(i as usize).copied().unwrap_or(0);
            Some(shape_doc(&engine.kind_of(i), &g, &pf, (i, engine.area_of(i), t), &a.motifs))
        })
        .collect();
    Ok(EngineRun {
        shapes: shapes_doc,
        stats: engine.stats(),
        reason,
        zeta: engine.zeta(),
        area: engine.total_area(),
        digest: zetafill::digest::engine_digest(&engine),
    })
}

/// Screens a batch's lanes on `threads` threads (this one among them). The lanes are handed
/// out a few at a time to whichever thread is free, so that one placement that takes many
/// trials does not hold the others up.
fn screen_on<S: zetafill::Scalar>(
    threads: usize,
    e: &Engine<'_, S>,
    cells: &CellSampler<'_, S>,
    plan: &zetafill::Plan<S>,
    lanes: &mut [zetafill::Lane<S>],
) {
    const LANES_AT_ONCE: usize = 4;
    let threads = threads.min(lanes.len().div_ceil(LANES_AT_ONCE)).max(1);
    // Without the `parallel` feature (the browser page, which has no threads) every lane is
    // screened here: the same fill, as for any number of threads.
    if threads == 1 || !cfg!(feature = "parallel") {
        e.screen(cells, plan, lanes);
        return;
    }
    let parts = std::sync::Mutex::new(lanes.chunks_mut(LANES_AT_ONCE));
    let work = || loop {
        let part = match parts.lock() {
            Ok(mut p) => p.next(),
            Err(_) => None,
        };
        match part {
            Some(part) => e.screen(cells, plan, part),
            None => break,
        }
    };
    std::thread::scope(|s| {
        for _ in 1..threads {
            s.spawn(work);
        }
        work();
    });
}

/// Runs the fill and returns the document (and the halt, if any, after at least one
/// placement: a first shape that finds no place is a usage error). Nothing is written.
pub fn compute(a: &FillRun) -> Result<(FillDoc, Option<StepError>), CliError> {
    compute_watched(a, &mut |_| {})
}

/// [`compute`], handing each placement to `watch` as it is made (in f64 whatever the
/// scalar), for a caller that draws the fill as it grows (the browser page).
pub fn compute_watched(a: &FillRun, watch: &mut dyn FnMut(&zetafill::Placement<f64>)) -> Result<(FillDoc, Option<StepError>), CliError> {
    let data = RegionData::load(&a.region)?;
    let mut scratch = Vec::new();
    let region = match &a.symmetry {
        Some(s) => Region::Wallpaper(s.wallpaper),
        None => data.region(a.periodic, &mut scratch)?,
    };
    // The region a symmetric pattern is cut to, checked as a region to fill is.
    let mut window_scratch = Vec::new();
    let window = match &a.symmetry {
        Some(s) if s.cut => Some(data.doc(&data.region(false, &mut window_scratch)?)),
        _ => None,
    };
    let params = &a.params;
    if let Some(s) = &a.symmetry {
        zetafill::check_first_orbit(params, &s.wallpaper).map_err(|e| first_orbit_error(e, params, &s.wallpaper))?;
    }
    let stop = a.stop;
    let sequence = stopping::sequence(region.area(), params.c, params.n_offset)?;
    stopping::check_min_size(&stop, zetafill::first_shape(&sequence, &params.shape).width, SHAPES)?;
    let cap = stopping::slots(zetafill::shape_capacity(&sequence, &params.shape, &stop, SHAPES.max), SHAPES)? as usize;
    let run = match a.fixed_point {
        #[cfg(feature = "fixed-point")]
        true => run_engine::<zetafill::Fixed>(a, params, region, &sequence, &stop, cap, watch)?,
        #[cfg(not(feature = "fixed-point"))]
        true => return Err(crate::plan::fill::no_fixed_point()),
        false => run_engine::<f64>(a, params, region, &sequence, &stop, cap, watch)?,
    };
    let EngineRun {
        shapes: shapes_doc,
        stats: st,
        reason,
        zeta,
        area,
        digest,
    } = run;
    let (stop_name, halt) = match reason {
        StopReason::Count => ("count", None),
        StopReason::Fill => ("fill", None),
        StopReason::MinSize => ("min-size", None),
        StopReason::Step(StepError::CannotFit { index: 0 }) => {
            return Err(first_shape_error(
                params,
                &zetafill::first_shape(&sequence, &params.shape),
                None,
                a.symmetry.is_some(),
            ))
        }
        StopReason::Step(StepError::Halted { index: 0, trials }) => {
            // Nothing placed: a density of zero everywhere is the reason, not the size.
            if let Some(d) = density::field(a, &region)? {
                density::refuse_zero(&d, &region, true)?;
            }
            return Err(first_shape_error(
                params,
                &zetafill::first_shape(&sequence, &params.shape),
                Some(trials),
                a.symmetry.is_some(),
            ));
        }
        StopReason::Step(e @ StepError::Halted { .. }) => ("halted", Some(e)),
        StopReason::Step(e @ (StepError::CannotFit { .. } | StepError::TooSmall { .. } | StepError::TooLarge { .. })) => {
            ("halted", Some(e))
        }
        StopReason::Step(e @ StepError::Capacity { .. }) => return Err(CliError::Io(format!("internal: {e}"))),
    };
    let doc = FillDoc {
        version: 1,
        mode: "fill",
        params: ParamsDoc {
            c: params.c,
            n_offset: params.n_offset,
            seed: a.seed,
            of: ShapeParamsDoc {
                shape: a.names.shape.clone(),
                rotate: a.names.rotate,
                mix_order: a.names.mix_order,
                sampler: a.names.sampler,
                scalar: a.names.scalar,
                cells: a.names.cells,
                batch: a.names.batch,
                density: a.names.density.clone(),
                density_sha256: a.names.density_sha256.clone(),
                motif_sha256: a.names.motif_sha256.clone(),
                source: a.names.source.clone(),
            },
            gap: params.gap,
            count: stop.count,
            fill: stop.fill,
            min_size: stop.min_size,
            max_trials: params.max_trials,
            dimension: 2.0 / params.c,
        },
        region: match &a.symmetry {
            Some(s) => region::wallpaper_doc(&s.wallpaper, s.repeat, window),
            None => data.doc(&region),
        },
        area,
        zeta,
        shapes: shapes_doc,
        stats: StatsDoc {
            placed: st.placed,
            trials: st.trials,
            fill_fraction: st.fill_fraction,
            halted: halt.is_some(),
            stop: stop_name,
        },
        digest: Some(digest),
    };
    Ok((doc, halt))
}

/// The SVG options of the drawing, colours included.
pub fn svg_options(doc: &FillDoc, d: &FillDraw) -> Result<output::svg::SvgOptions, CliError> {
    let flags = format!(
        " --style {}{}{}{}",
        d.style.name(),
        if d.pen_width == 0.3 {
            String::new()
        } else {
            format!(" --pen-width {}", d.pen_width)
        },
        if d.boundary { " --boundary" } else { "" },
        d.plot_flags
    );
    let page = match &d.page {
        Some(p) => Some(p.layout(doc.bbox())?),
        None => None,
    };
    Ok(output::svg::SvgOptions {
        style: d.style,
        pen_width: d.pen_width,
        boundary: d.boundary,
        page,
        layers: d.size_layers,
        build: d.build,
        flags: flags + &d.colours.flags,
        colours: d.colours.palette.as_ref().map(|p| shape_colours(doc, d, &p.0)),
        background: d.colours.background.clone(),
        colour_layers: d.colours.palette.as_ref().filter(|_| d.colours.layers).map(|p| p.0.clone()),
    })
}

/// Each shape's colour from `palette` by the `--color-by` rule.
fn shape_colours(doc: &FillDoc, d: &FillDraw, palette: &[output::palette::Colour]) -> Vec<output::palette::Colour> {
    // The mix entry of each shape, as the engine chose it.
    let entry = |i: u64| {
        let kind = d.shapes.kind_of(i);
        d.shapes.kinds().iter().position(|k| *k == kind).unwrap_or(0)
    };
    output::palette::assign(doc, palette, d.colours.by, entry)
}

/// How `--voronoi` draws the cobblestones: edges, or cells filled in their shapes' colours.
fn cobble_look(doc: &FillDoc, d: &FillDraw) -> crate::cmd::cobble::Look {
    let filled = d.style == output::svg::Style::Filled;
    let mut flags = format!(" --pen-width {}", output::num(d.pen_width, 4));
    if filled {
        flags.push_str(" --style filled");
    }
    if d.boundary {
        flags.push_str(" --boundary");
    }
    flags.push_str(&d.colours.flags);
    crate::cmd::cobble::Look {
        filled,
        pen_width: d.pen_width,
        outline: d.boundary,
        colours: d.colours.palette.as_ref().map(|p| shape_colours(doc, d, &p.0)),
        background: d.colours.background.clone(),
        flags,
    }
}

/// The G-code plan of a drawing that has none (it was resolved for another format).
fn no_gcode() -> CliError {
    CliError::Io("internal: G-code asked of a plan resolved for another format".into())
}

/// Renders a document in a format.
pub fn render(doc: &FillDoc, format: Format, d: &FillDraw) -> Result<Vec<u8>, CliError> {
    output(doc, format, d)?.into_bytes()
}

/// A document in a format, ready to be streamed: the JSON and the CSV are written a few
/// shapes at a time, the SVG's tree and the G-code's paths are made once and printed straight
/// into the destination; a PNG is made whole.
pub fn output<'a>(doc: &'a FillDoc, format: Format, d: &FillDraw) -> Result<Output<'a>, CliError> {
    if d.voronoi {
        let look = cobble_look(doc, d);
        return match format {
            Format::Png => Ok(Output::bytes(
                d.raster.render(&crate::cmd::cobble::svg(doc, &look)?).map_err(png_error)?,
            )),
            _ => output::svg::output(&crate::cmd::cobble::picture(doc, &look)?),
        };
    }
    Ok(match format {
        Format::Svg => output::svg::output(&output::svg::picture(doc, &svg_options(doc, d)?))?,
        Format::Gcode => {
            let gcode = d.gcode.as_ref().ok_or_else(no_gcode)?;
            match (&d.colours.palette, d.colours.layers) {
                (Some(p), true) => {
                    let colours = shape_colours(doc, d, &p.0);
                    crate::cmd::plot::gcode_pens_output(doc, gcode, Some((&colours, &p.0, d.colours.flags.clone())))?
                }
                _ => crate::cmd::plot::gcode_pens_output(doc, gcode, None)?,
            }
        }
        Format::Json => Output::stream(Size::AtMost(output::json::max_size(doc)?), move |w| output::json::write(doc, w)),
        Format::Csv => Output::stream(Size::AtMost(output::csv::max_size(doc)), move |w| output::csv::write(doc, w)),
        Format::Digest => Output::bytes(output::digest::render(doc)),
        Format::Png => Output::bytes(match d.relief {
            Some(relief) => {
                let command = format!("{} --relief {}{}", output::svg::command_line(doc), relief.name(), d.raster.flag());
                let size = output::height::grid(doc.extent(), &d.raster).map_err(height_map_error)?;
                output::height::render(doc, relief, size, &command)?
            }
            None => {
                let svg = output::svg::render(doc, &svg_options(doc, d)?);
                d.raster.render(&svg).map_err(png_error)?
            }
        }),
    })
}

/// What makes the output of a 2D fill smaller, for the refusal of one above
/// `--max-output-size`.
pub const SMALLER: &str = "ask for fewer shapes (--count, --fill, --min-size)";

/// `zetafill fill`: runs the plan and writes its output.
pub fn run(plan: &FillPlan) -> Result<(), CliError> {
    let (doc, halt) = compute(&plan.run)?;
    let out = output(&doc, plan.format, &plan.draw)?;
    let what = output::stream::file_of(plan.format.name());
    crate::cmd::write_output(&plan.dest, &out, plan.max_output_size, &what, SMALLER)?;
    outcome(&plan.run, halt)
}

/// The outcome of a run whose output was made: a halt becomes [`CliError::Halted`] with the
/// advice that fits the run.
pub fn outcome(run: &FillRun, halt: Option<StepError>) -> Result<(), CliError> {
    let max_trials = run.params.max_trials;
    if let Some(d) = &run.density {
        // Where the density is low the candidates are thinned away; where it is zero nothing
        // goes: the dense parts fill up first.
        let advice = match d {
            crate::model::density::DensitySpec::Noise { .. } => {
                "the --density leaves too little room where it is high: lower its CONTRAST (less empty space), raise --n-offset or lower --c (smaller shapes), or ask for fewer shapes"
            }
            crate::model::density::DensitySpec::Image { .. } => {
                "the --density leaves too little room where the picture is dark: raise its floor=F (the density of white; less empty space), raise --n-offset or lower --c (smaller shapes), or ask for fewer shapes"
            }
        };
        return stopping::outcome(halt, SHAPES, |_, _| advice);
    }
    stopping::outcome(halt, SHAPES, |index, trials| halt_advice(index, trials < max_trials))
}
