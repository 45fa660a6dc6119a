//! `zetafill fill`: the 2D fractal fill.

pub mod limits;
pub mod region;

use crate::args::fill::{FillArgs, MixArg, Rotate, Sampler, ScalarArg, DEFAULT_MAX_TRIALS, MAX_SHAPES};
use crate::args::format::Format;
use crate::args::spec::{self, RegionSpec};
use crate::args::style::StyleArg;
use crate::cmd::stopping::{self, Unit};
use crate::error::CliError;
use crate::io::write::Dest;
use crate::model::doc::{FillDoc, ParamsDoc, ShapeDoc, StatsDoc};
use crate::output;
use limits::check_known_limit;
use region::RegionData;
use zetafill::{index_words, CellSampler, Engine, Geo, MixOrder, Params, Placed, Region, ShapeKind, Stop, StopReason, Storage};
use zetafill::{ParamError, StepError};

/// What a 2D run places.
const SHAPES: Unit = Unit {
    plural: "shapes",
    max: MAX_SHAPES,
};

/// Words of the coverage bitmap (2 MiB): a 4096 x 4096 grid.
const COVERAGE_WORDS: usize = 1 << 18;

impl FillArgs {
    /// The exponent c, from `--c`, `--dimension` or the default 1.3.
    pub fn c(&self) -> f64 {
        match (self.c, self.dimension) {
            (Some(c), _) => c,
            (None, Some(d)) => Params::c_from_dimension(d),
            (None, None) => 1.3,
        }
    }

    fn rotate(&self) -> bool {
        match self.rotate {
            Some(r) => r == Rotate::Random,
            None => self.shape.rotates(),
        }
    }

    fn stop(&self) -> Stop {
        stopping::stop(self.count, self.fill, self.min_size)
    }
}

/// Names the flag behind a core parameter error.
fn param_error(e: ParamError) -> CliError {
    let flag = match e {
        ParamError::Exponent => "--c",
        ParamError::Offset | ParamError::Zeta => "--n-offset",
        ParamError::Shape => "--shape",
        ParamError::Region => "--region",
        ParamError::Gap => "--gap",
        ParamError::MaxTrials => "--max-trials",
        ParamError::Storage => "--count",
    };
    CliError::arg(flag, e)
}

/// How many shape slots the stop conditions can need (see [`stopping::capacity`]).
fn capacity(params: &Params, area: f64, stop: &Stop) -> Result<u64, CliError> {
    let (c, n) = (params.c, params.n_offset);
    let zeta = zetafill::internals::zeta::zeta(c, n).map_err(|e| CliError::arg("--n-offset", e))?;
    // Shape k's width decreases with k.
    let width = |k: u64| {
        let kind = params.shape.kind_of(k);
        kind.min_width(kind.scale_for_area(area / (zeta * zetafill::internals::scalar::powf(k as f64 + n, c))))
    };
    stopping::capacity(c, n, stop, SHAPES, width)
}

/// Advice for a halt at placement `index` (at least 1: a halt at the first placement is
/// [`first_shape_error`]).
fn halt_advice(index: u64) -> &'static str {
    if index < 100 {
        "the first shapes left no room for this one: lower --c, raise --n-offset, or try another --seed"
    } else {
        "raise --max-trials, lower --c, or ask for fewer shapes"
    }
}

/// The usage error of a fill that cannot place its first shape: `halt` is `None` when the
/// core knows the shape is too large for the region, or the trials spent before giving up.
/// Nothing is written: an output with no shape is no drawing.
fn first_shape_error(params: &Params, area: f64, zeta: f64, halt: Option<u64>) -> CliError {
    let kind = params.shape.kind_of(0);
    let a0 = area / (zeta * zetafill::internals::scalar::powf(params.n_offset, params.c));
    let width = kind.min_width(kind.scale_for_area(a0));
    let what = match halt {
        None => "does not fit the region".to_string(),
        Some(t) if t < params.max_trials => "does not fit anywhere in the region".to_string(),
        Some(t) => format!("never fit in the region ({t} trials found no place for it)"),
    };
    let mut advice = String::from("lower --c or raise --n-offset (a smaller first shape)");
    if params.gap > 0.0 {
        advice.push_str(", lower --gap");
    }
    advice.push_str(" or use a larger --region");
    if halt.is_some_and(|t| t >= params.max_trials && params.max_trials < DEFAULT_MAX_TRIALS) {
        advice.push_str("; if it does fit, raise --max-trials");
    }
    CliError::arg(
        "--c",
        format!(
            "the first {} ({width:.4} mm wide, area {a0:.4} mm²) {what}; {advice}",
            spec::kind_name(&kind)
        ),
    )
}

/// The concrete geometry of a placed shape as a [`ShapeDoc`].
fn shape_doc(kind: &ShapeKind, geo: &Geo<f64>, p: &Placed<f64>, index: u64, area: f64, trials: u64) -> ShapeDoc {
    let name = spec::kind_name(kind);
    let (radius, inner_radius, angle, vertices) = match geo {
        Geo::Circle { r, .. } => (Some(*r), None, None, None),
        Geo::Ring { r, inner, .. } => (Some(*r), Some(*inner), None, None),
        Geo::Poly { .. } => (None, None, Some(p.angle), Some(geo.vertices().iter().map(|v| [v.x, v.y]).collect())),
    };
    ShapeDoc {
        index,
        kind: name,
        center: [p.x, p.y],
        radius,
        inner_radius,
        angle,
        area,
        trials,
        vertices,
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

fn geo_f64<S: zetafill::Scalar>(g: &Geo<S>) -> Geo<f64> {
    let pt = |p: zetafill::Point<S>| zetafill::Point::new(p.x.to_f64(), p.y.to_f64());
    match *g {
        Geo::Circle { c, r } => Geo::Circle { c: pt(c), r: r.to_f64() },
        Geo::Ring { c, r, inner } => Geo::Ring {
            c: pt(c),
            r: r.to_f64(),
            inner: inner.to_f64(),
        },
        Geo::Poly { v, n, convex } => {
            let mut out = [zetafill::Point::new(0.0, 0.0); zetafill::internals::geom::MAX_VERTS];
            for (o, p) in out.iter_mut().zip(v.iter()) {
                *o = pt(*p);
            }
            Geo::Poly { v: out, n, convex }
        }
    }
}

/// Runs the engine on scalar `S` with the CLI's storage, progress bar and known-limit check.
fn run_engine<S: zetafill::Scalar>(
    a: &FillArgs,
    params: Params,
    region: Region<'_>,
    stop: &Stop,
    cap: usize,
) -> Result<EngineRun, CliError> {
    let mut shapes = vec![Placed::<S>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    // Only the paper's sampler asks the coverage bitmap (the cell sampler never does).
    let mut coverage = vec![0u64; if a.sampler == Sampler::Reference { COVERAGE_WORDS } else { 0 }];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    let mut engine = Engine::<S>::new(params, region, storage).map_err(param_error)?;
    check_known_limit(&params, &region)?;
    let mut rng = zetafill::rng_from_seed(a.seed);
    let bar = stopping::progress_bar(a.quiet, stop.count, SHAPES);
    let mut trials = Vec::with_capacity(cap);
    let on_place = |p: &zetafill::Placement<S>| {
        trials.push(p.trials);
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let reason = match a.sampler {
        Sampler::Reference => engine.run(&mut rng, stop, on_place),
        Sampler::Fast => {
            // Enough cells that only the sampler's own budget limits it: the shapes of a seed
            // then do not depend on the count asked for. Zeroed memory: the system maps only
            // the pages the sampler writes.
            let mut pool = vec![[0u64; 4]; zetafill::cells_for(cap)];
            let mut cells = CellSampler::new(&mut pool).map_err(|_| CliError::Io("internal: no cells for the fast sampler".into()))?;
            engine.run_fast(&mut cells, &mut rng, stop, on_place)
        }
    };
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let shapes_doc = engine
        .placed()
        .iter()
        .enumerate()
        .filter_map(|(i, p)| {
            let g = geo_f64(&engine.geo(i)?);
            let pf = Placed {
                x: p.x.to_f64(),
                y: p.y.to_f64(),
                scale: p.scale.to_f64(),
                angle: p.angle.to_f64(),
            };
            let i = i as u64;
            let t = trials.get(i as usize).copied().unwrap_or(0);
            Some(shape_doc(&engine.kind_of(i), &g, &pf, i, engine.area_of(i), t))
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

/// Runs the fill and returns the document (and the halt, if any, after at least one
/// placement: a first shape that finds no place is a usage error). Nothing is written.
pub fn compute(a: &FillArgs) -> Result<(FillDoc, Option<StepError>), CliError> {
    let data = RegionData::load(&a.region)?;
    let region = data.region(a.periodic)?;
    let order = mix_order(a.mix_order);
    let params = Params {
        c: a.c(),
        n_offset: a.n_offset,
        shape: a.shape.list(order, a.seed),
        rotate: a.rotate(),
        gap: a.gap,
        max_trials: a.max_trials,
    };
    let stop = a.stop();
    let cap = capacity(&params, region.area(), &stop)? as usize;
    let run = match a.scalar {
        ScalarArg::F64 => run_engine::<f64>(a, params, region, &stop, cap)?,
        ScalarArg::Fixed => run_engine::<zetafill::Fixed>(a, params, region, &stop, cap)?,
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
        StopReason::Step(StepError::CannotFit { index: 0 }) => return Err(first_shape_error(&params, area, zeta, None)),
        StopReason::Step(StepError::Halted { index: 0, trials }) => return Err(first_shape_error(&params, area, zeta, Some(trials))),
        StopReason::Step(e @ StepError::Halted { .. }) => ("halted", Some(e)),
        StopReason::Step(e @ StepError::CannotFit { .. }) => ("halted", Some(e)),
        StopReason::Step(e @ StepError::Capacity { .. }) => return Err(CliError::Io(format!("internal: {e}"))),
    };
    let doc = FillDoc {
        version: 1,
        mode: "fill",
        params: ParamsDoc {
            c: params.c,
            n_offset: params.n_offset,
            seed: a.seed,
            shape: a.shape.name(),
            rotate: if params.rotate && a.shape.rotates() { "random" } else { "none" },
            mix_order: (a.shape.0.len() > 1).then(|| a.mix_order.name()),
            sampler: a.sampler.name(),
            scalar: a.scalar.name(),
            gap: params.gap,
            count: stop.count,
            fill: stop.fill,
            min_size: stop.min_size,
            max_trials: params.max_trials,
            dimension: 2.0 / params.c,
        },
        region: data.doc(&region),
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

/// The core's mix order.
fn mix_order(m: MixArg) -> MixOrder {
    match m {
        MixArg::Cycle => MixOrder::Cycle,
        MixArg::Random => MixOrder::Random,
    }
}

/// The SVG options of the drawing flags, colours included.
fn svg_options(doc: &FillDoc, a: &FillArgs) -> Result<output::svg::SvgOptions, CliError> {
    let mut o = a.plot.svg_options(doc, a.style.into(), a.pen_width, a.boundary)?;
    if let Some(p) = &a.colour.palette {
        o.colours = Some(shape_colours(doc, a, &p.0));
        if a.plot.layers == crate::args::plot::Layers::Colours {
            o.colour_layers = Some(p.0.clone());
        }
    } else if a.plot.layers == crate::args::plot::Layers::Colours {
        return Err(colours_need_palette());
    }
    o.flags.push_str(&a.colour.flags());
    o.background.clone_from(&a.colour.background);
    Ok(o)
}

fn colours_need_palette() -> CliError {
    CliError::arg(
        "--layers",
        "colours makes one layer (one pen) per --palette colour: give --palette, or use size-bands:K",
    )
}

/// Each shape's colour from `palette` by the `--color-by` rule.
fn shape_colours(doc: &FillDoc, a: &FillArgs, palette: &[output::palette::Colour]) -> Vec<output::palette::Colour> {
    // The mix entry of each shape, as the engine chose it.
    let list = a.shape.list(mix_order(a.mix_order), a.seed);
    let entry = |i: u64| {
        let kind = list.kind_of(i);
        list.kinds().iter().position(|k| *k == kind).unwrap_or(0)
    };
    output::palette::assign(doc, palette, a.colour.by(), entry)
}

/// How `--voronoi` draws the cobblestones: edges, or cells filled in their shapes' colours.
fn cobble_look(doc: &FillDoc, a: &FillArgs) -> crate::cmd::cobble::Look {
    let filled = a.style == StyleArg::Filled;
    let mut flags = format!(" --pen-width {}", output::num(a.pen_width, 4));
    if filled {
        flags.push_str(" --style filled");
    }
    if a.boundary {
        flags.push_str(" --boundary");
    }
    flags.push_str(&a.colour.flags());
    crate::cmd::cobble::Look {
        filled,
        pen_width: a.pen_width,
        outline: a.boundary,
        colours: a.colour.palette.as_ref().map(|p| shape_colours(doc, a, &p.0)),
        background: a.colour.background.clone(),
        flags,
    }
}

/// Renders a document in a format.
pub fn render(doc: &FillDoc, format: Format, a: &FillArgs) -> Result<Vec<u8>, CliError> {
    if a.voronoi {
        let look = cobble_look(doc, a);
        return match format {
            Format::Svg => crate::cmd::cobble::svg(doc, &look),
            Format::Png => a.raster.raster().render(&crate::cmd::cobble::svg(doc, &look)?),
            _ => Err(CliError::arg(
                "--voronoi",
                "cobblestones are drawn as SVG or PNG; write .svg or .png, or drop --voronoi",
            )),
        };
    }
    Ok(match format {
        Format::Svg => output::svg::render(doc, &svg_options(doc, a)?),
        Format::Gcode => match (&a.colour.palette, a.plot.layers) {
            (Some(p), crate::args::plot::Layers::Colours) => {
                let colours = shape_colours(doc, a, &p.0);
                crate::cmd::plot::render_gcode_pens(doc, &a.plot, Some((&colours, &p.0, a.colour.flags())), a.quiet)?
            }
            (None, crate::args::plot::Layers::Colours) => return Err(colours_need_palette()),
            _ => crate::cmd::plot::render_gcode(doc, &a.plot, a.quiet)?,
        },
        Format::Json => output::json::render(doc)?,
        Format::Csv => output::csv::render(doc),
        Format::Digest => output::digest::render(doc),
        Format::Png => match a.relief {
            Some(relief) => {
                let relief: output::height::Relief = relief.into();
                let command = format!(
                    "{} --relief {}{}",
                    output::svg::command_line(doc),
                    relief.name(),
                    a.raster.raster().flag()
                );
                output::height::render(doc, relief, output::height::grid(doc.extent(), &a.raster.raster())?, &command)?
            }
            None => {
                let svg = output::svg::render(doc, &svg_options(doc, a)?);
                a.raster.raster().render(&svg)?
            }
        },
    })
}

/// `zetafill fill`.
pub fn run(a: &FillArgs) -> Result<(), CliError> {
    let dest = Dest::parse(&a.output);
    let mut inputs: Vec<&std::path::Path> = a.plot.machine_file().into_iter().collect();
    if let RegionSpec::Svg(p) = &a.region {
        inputs.push(p.as_path());
    }
    dest.check("--output", &inputs)?;
    let format = Format::resolve(a.format, &a.output)?;
    // Plotter flags (machine profile, feeds, power, hatch, page) are checked before the fill
    // runs; the bed check needs the drawing and happens in render().
    if a.voronoi {
        a.plot.refuse_except(&[], |_| {
            "is not available with --voronoi (cobblestones are drawn at the region's size)".to_string()
        })?;
    }
    if format != Format::Png && a.relief.is_some() {
        return Err(crate::output::png::only_png("--relief"));
    }
    a.raster.check(format == Format::Png)?;
    // A palette also picks the pens of a G-code plot with --layers colours.
    let pens = format == Format::Gcode && a.plot.layers == crate::args::plot::Layers::Colours && a.colour.background.is_none();
    a.colour.check(
        (matches!(format, Format::Svg | Format::Png) && a.relief.is_none()) || pens,
        "write .svg or .png, without --relief (or G-code with --layers colours, without --background)",
        false,
    )?;
    if a.plot.layers == crate::args::plot::Layers::Colours && a.colour.palette.is_none() {
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
    a.plot.check(format)?;
    if a.plot.hatch.is_some() && a.style == StyleArg::Filled && matches!(format, Format::Svg | Format::Png) {
        return Err(CliError::arg(
            "--hatch",
            "draws lines, which filled shapes would hide: use --style outline",
        ));
    }
    let (doc, halt) = compute(a)?;
    let bytes = render(&doc, format, a)?;
    dest.write(&bytes)?;
    stopping::outcome(halt, SHAPES, halt_advice)
}
