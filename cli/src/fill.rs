//! `zetafill fill`: the 2D fractal fill.

use crate::doc::{FillDoc, ParamsDoc, RegionDoc, ShapeDoc, StatsDoc};
use crate::error::CliError;
use crate::output::svg::Style;
use crate::output::{self, Format};
use crate::spec::{self, RegionSpec};
use crate::stopping::{self, Unit};
use crate::write::Dest;
use clap::{Args, ValueEnum};
use std::path::PathBuf;
use zetafill::{
    index_words, CellSampler, Engine, Geo, MixOrder, Params, Placed, PolygonRegion, Region, ShapeKind, Stop, StopReason, Storage,
};
use zetafill::{ParamError, StepError};

/// Largest number of shapes one run may hold (52 bytes each in the core).
pub const MAX_SHAPES: u64 = 20_000_000;

/// What a 2D run places.
const SHAPES: Unit = Unit {
    plural: "shapes",
    max: MAX_SHAPES,
};

/// Words of the coverage bitmap (2 MiB): a 4096 x 4096 grid.
const COVERAGE_WORDS: usize = 1 << 18;

/// Rotation of non-circular shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Rotate {
    /// Axis-aligned.
    None,
    /// A uniformly random angle per trial.
    Random,
}

/// How the shapes of a mix are taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MixArg {
    /// In turn: placement i gets shape i mod count (the paper's Figure 7).
    Cycle,
    /// A random choice per placement (fixed by the seed).
    Random,
}

/// The candidate sampler.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Sampler {
    /// Candidates only where the next shape could fit (cells with clearance bounds): the same
    /// distribution of placements as `reference`, far fewer trials.
    Fast,
    /// The paper's: uniform candidates over the region, retried until one fits.
    Reference,
}

impl MixArg {
    /// The name written to JSON and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            MixArg::Cycle => "cycle",
            MixArg::Random => "random",
        }
    }
}

impl Sampler {
    /// The name written to JSON.
    pub fn name(self) -> &'static str {
        match self {
            Sampler::Fast => "fast",
            Sampler::Reference => "reference",
        }
    }
}

/// Arguments of `zetafill fill`.
#[derive(Debug, Args)]
pub struct FillArgs {
    /// circle | square | rect:ASPECT | triangle | polygon:SIDES | star:POINTS:INNER_RATIO |
    /// ring:INNER_RATIO | blob:DELTA | mix:SHAPE,SHAPE,...
    #[arg(long, default_value = "circle", value_parser = spec::shape)]
    pub shape: spec::ShapeArg,
    /// Mixes: take the shapes in turn (cycle) or at random per placement.
    #[arg(long = "mix-order", value_enum, default_value = "cycle")]
    pub mix_order: MixArg,
    /// Rotation: none or random (default: random for non-circles).
    #[arg(long, value_enum)]
    pub rotate: Option<Rotate>,
    /// rect:W:H | circle:R | annulus:R_OUTER:R_INNER | polygon:X1,Y1,X2,Y2,...[/X1,Y1,...] (rings,
    /// even-odd) | svg:FILE (mm).
    #[arg(long, default_value = "rect:200:200", value_parser = spec::region)]
    pub region: RegionSpec,
    /// Periodic (toroidal) boundary: the fill tiles seamlessly (rect regions only).
    #[arg(long)]
    pub periodic: bool,
    /// Power-law exponent c > 1 (default 1.3).
    #[arg(long, value_parser = spec::exponent, conflicts_with = "dimension", allow_negative_numbers = true)]
    pub c: Option<f64>,
    /// Fractal dimension D in (0, 2) instead of c (c = 2/D).
    #[arg(long, value_parser = spec::dimension, allow_negative_numbers = true)]
    pub dimension: Option<f64>,
    /// The paper's N > 0: larger N makes the first shapes smaller.
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::positive, allow_negative_numbers = true)]
    pub n_offset: f64,
    /// Stop after K shapes (default 2000 when no stop condition is given).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=MAX_SHAPES))]
    pub count: Option<u64>,
    /// Stop once this fraction of the region is filled, 0 < F < 1.
    #[arg(long, value_parser = spec::fraction, allow_negative_numbers = true)]
    pub fill: Option<f64>,
    /// Stop before the first shape narrower than MM.
    #[arg(long = "min-size", value_parser = spec::positive, allow_negative_numbers = true)]
    pub min_size: Option<f64>,
    /// Minimum clearance between shapes and to the boundary, in mm.
    #[arg(long, default_value_t = 0.0, value_parser = spec::non_negative, allow_negative_numbers = true)]
    pub gap: f64,
    /// Trial limit per placement; reaching it halts the fill (exit 3).
    #[arg(long = "max-trials", default_value_t = DEFAULT_MAX_TRIALS, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_trials: u64,
    /// RNG seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Candidate sampler: fast (cells where the next shape could fit) or reference (the
    /// paper's uniform search); both give the same distribution of placements.
    #[arg(long, value_enum, default_value = "fast")]
    pub sampler: Sampler,
    /// Number type of the engine: f64 or fixed (32.32 fixed point).
    #[arg(long, value_enum, default_value = "f64")]
    pub scalar: ScalarArg,
    /// Output path; the format comes from the extension (.svg .png .json .csv .gcode/.nc);
    /// '-' is stdout.
    #[arg(short = 'o', long)]
    pub output: PathBuf,
    /// Output format (overrides the extension).
    #[arg(long, value_enum)]
    pub format: Option<Format>,
    /// SVG: outline (plotters) or filled.
    #[arg(long, value_enum, default_value = "outline")]
    pub style: Style,
    /// SVG: stroke width in mm.
    #[arg(long = "pen-width", default_value_t = 0.3, value_parser = spec::positive)]
    pub pen_width: f64,
    /// SVG: also draw the region's outline.
    #[arg(long)]
    pub boundary: bool,
    /// PNG size.
    #[command(flatten)]
    pub raster: crate::output::png::Raster,
    /// PNG: write a 16-bit height map (each shape a raised stone of this profile) instead
    /// of a picture.
    #[arg(long, value_enum)]
    pub relief: Option<output::height::Relief>,
    /// Colours (SVG/PNG).
    #[command(flatten)]
    pub colour: output::palette::ColourArgs,
    /// SVG/PNG: draw the Voronoi cells of the shapes' centres ("cobblestones") instead of the
    /// shapes; with --periodic the cells tile seamlessly.
    #[arg(long)]
    pub voronoi: bool,
    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
    /// Plotter and laser output: G-code machine, path order, hatch, pages, layers.
    #[command(flatten)]
    pub plot: crate::plot::PlotArgs,
}

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

/// The default of `--max-trials`.
pub const DEFAULT_MAX_TRIALS: u64 = 10_000_000;

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

/// A region resolved from its flag: owns the outline vertices the core borrows.
#[derive(Debug, Clone)]
pub struct RegionData {
    spec: RegionSpec,
}

impl RegionData {
    /// Resolves `--region` (reading an SVG outline from its file).
    pub fn load(spec: &RegionSpec) -> Result<Self, CliError> {
        let spec = match spec {
            RegionSpec::Svg(path) => {
                let (points, ends) = crate::svgin::read_outline(path)?;
                outers_first(&points, &ends)
            }
            RegionSpec::Polygon { points, ends } => outers_first(points, ends),
            other => other.clone(),
        };
        Ok(RegionData { spec })
    }

    /// The core region (validating polygons).
    pub fn region(&self, periodic: bool) -> Result<Region<'_>, CliError> {
        if periodic && !matches!(self.spec, RegionSpec::Rect { .. }) {
            return Err(CliError::arg(
                "--periodic",
                "only rect:W:H regions can be periodic; remove --periodic or use a rect region",
            ));
        }
        Ok(match &self.spec {
            RegionSpec::Rect { width, height } => Region::Rect {
                width: *width,
                height: *height,
                periodic,
            },
            RegionSpec::Circle { radius } => Region::Circle { radius: *radius },
            RegionSpec::Annulus { outer, inner } => Region::Annulus {
                outer: *outer,
                inner: *inner,
            },
            RegionSpec::Polygon { points, ends } => Region::Polygon(
                PolygonRegion::new(points, ends).map_err(|e| CliError::arg("--region", format!("{e}; give a simple outline")))?,
            ),
            RegionSpec::Svg(_) => return Err(CliError::Io("internal: SVG region not loaded".into())),
        })
    }

    /// The region as written in JSON.
    pub fn doc(&self, region: &Region<'_>) -> RegionDoc {
        match *region {
            Region::Rect { width, height, periodic } => RegionDoc::Rect { width, height, periodic },
            Region::Circle { radius } => RegionDoc::Circle {
                center: [radius, radius],
                radius,
            },
            Region::Annulus { outer, inner } => RegionDoc::Annulus {
                center: [outer, outer],
                radius_outer: outer,
                radius_inner: inner,
            },
            Region::Polygon(p) => {
                let rings: Vec<&[zetafill::Point<f64>]> = p.rings().collect();
                let as_vec = |r: &[zetafill::Point<f64>]| r.iter().map(|q| [q.x, q.y]).collect::<Vec<_>>();
                let (mut vertices, mut holes, mut outers) = (Vec::new(), Vec::new(), Vec::new());
                for (r, hole) in rings.iter().zip(holes_of(&rings)) {
                    if hole {
                        holes.push(as_vec(r));
                    } else if vertices.is_empty() {
                        vertices = as_vec(r);
                    } else {
                        outers.push(as_vec(r));
                    }
                }
                RegionDoc::Polygon { vertices, holes, outers }
            }
        }
    }
}

/// Whether each ring is a hole: inside an odd number of the others (the even-odd rule), judged
/// by its first vertex.
fn holes_of(rings: &[&[zetafill::Point<f64>]]) -> Vec<bool> {
    (0..rings.len())
        .map(|i| {
            let probe = rings.get(i).and_then(|r| r.first()).copied().unwrap_or_default();
            let depth = rings
                .iter()
                .enumerate()
                .filter(|(j, o)| *j != i && zetafill::internals::geom::point_in_poly(probe, o))
                .count();
            depth % 2 == 1
        })
        .collect()
}

/// The rings reordered as the JSON lists them (the outer outlines, then the holes, each in
/// their own order), so that the `--region polygon:` written from the JSON gives the core the
/// same rings in the same order, and so the same bits.
fn outers_first(points: &[zetafill::Point<f64>], ends: &[usize]) -> RegionSpec {
    let starts = std::iter::once(0).chain(ends.iter().copied());
    let rings: Vec<&[zetafill::Point<f64>]> = starts.zip(ends).filter_map(|(a, &b)| points.get(a..b)).collect();
    let holes = holes_of(&rings);
    let (mut out, mut out_ends) = (Vec::with_capacity(points.len()), Vec::with_capacity(ends.len()));
    for want_hole in [false, true] {
        for (r, _) in rings.iter().zip(&holes).filter(|(_, h)| **h == want_hole) {
            out.extend_from_slice(r);
            out_ends.push(out.len());
        }
    }
    RegionSpec::Polygon {
        points: out,
        ends: out_ends,
    }
}

/// For shapes whose first two placements have a known geometric limit (unrotated squares,
/// rectangles, circles and rings in an inclusive rectangle), whether shapes 0 and 1 can both
/// be placed: side by side, one above the other, or in opposite corners.
fn first_two_fit(kind: &ShapeKind, a0: f64, a1: f64, w: f64, h: f64, gap: f64) -> bool {
    let (w, h) = (w - 2.0 * gap, h - 2.0 * gap);
    match kind {
        ShapeKind::Square | ShapeKind::Rect { .. } => {
            let (s0, s1) = (kind.scale_for_area(a0), kind.scale_for_area(a1));
            let aspect = if let ShapeKind::Rect { aspect } = kind { *aspect } else { 1.0 };
            let (w0, h0, w1, h1) = (2.0 * aspect * s0, 2.0 * s0, 2.0 * aspect * s1, 2.0 * s1);
            w0 <= w && h0 <= h && (w0 + w1 + gap < w || h0 + h1 + gap < h)
        }
        ShapeKind::Circle | ShapeKind::Ring { .. } => {
            let (r0, r1) = (kind.scale_for_area(a0), kind.scale_for_area(a1));
            let (dx, dy) = ((w - r0 - r1).max(0.0), (h - r0 - r1).max(0.0));
            2.0 * r0 <= w.min(h) && dx * dx + dy * dy > (r0 + r1 + gap) * (r0 + r1 + gap)
        }
        _ => true,
    }
}

/// Refuses parameters whose first two shapes certainly cannot both fit, naming the largest c
/// that works for this shape, N and region.
fn check_known_limit(params: &Params, region: &Region<'_>) -> Result<(), CliError> {
    let (
        Region::Rect {
            width,
            height,
            periodic: false,
        },
        [kind],
    ) = (region, params.shape.kinds())
    else {
        return Ok(());
    };
    if params.rotate && kind.rotates() {
        return Ok(());
    }
    let fits = |c: f64| {
        let Ok(z) = zetafill::internals::zeta::zeta(c, params.n_offset) else {
            return false;
        };
        let a = |i: f64| width * height / (z * zetafill::internals::scalar::powf(i + params.n_offset, c));
        first_two_fit(kind, a(0.0), a(1.0), *width, *height, params.gap)
    };
    if fits(params.c) {
        return Ok(());
    }
    // However small the shapes (N large), the gap alone may leave no room for two.
    let room = |gap: f64| first_two_fit(kind, 0.0, 0.0, *width, *height, gap);
    if !room(params.gap) {
        let ok = bisect(0.0, params.gap, room);
        return Err(CliError::arg(
            "--gap",
            format!(
                "{} mm leaves no room for two {}s in this {} x {} mm region, whatever --c and --n-offset; lower it below {:.4} mm or enlarge --region",
                params.gap,
                spec::kind_name(kind),
                width,
                height,
                ok
            ),
        ));
    }
    let lo = 1.0 + 1e-9;
    if !fits(lo) {
        return Err(CliError::arg(
            "--n-offset",
            format!(
                "the first two {}s cannot both fit this region for any c; raise --n-offset{} or enlarge --region",
                spec::kind_name(kind),
                if params.gap > 0.0 { ", lower --gap" } else { "" }
            ),
        ));
    }
    let lo = bisect(lo, params.c, fits);
    Err(CliError::arg(
        "--c",
        format!(
            "with N = {} the first two {}s cannot both fit in this region when c > {:.4} (the paper's hard limit, section 3); lower --c or raise --n-offset",
            params.n_offset,
            spec::kind_name(kind),
            lo
        ),
    ))
}

/// Where `works` turns false between `ok` (where it holds) and `bad` (where it does not):
/// the last value found to work after 60 halvings.
fn bisect(mut ok: f64, mut bad: f64, works: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..60 {
        let mid = 0.5 * (ok + bad);
        if works(mid) {
            ok = mid;
        } else {
            bad = mid;
        }
    }
    ok
}

/// The number type the engine computes in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ScalarArg {
    /// IEEE double precision through libm (the default).
    F64,
    /// 32.32 fixed point, as on a microcontroller without an FPU (different shapes, equally
    /// deterministic; `--format digest` then matches the firmware's fixed-point runs).
    Fixed,
}

impl ScalarArg {
    /// The name in JSON.
    pub fn name(self) -> &'static str {
        match self {
            ScalarArg::F64 => "f64",
            ScalarArg::Fixed => "fixed",
        }
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
    let mut o = a.plot.svg_options(doc, a.style, a.pen_width, a.boundary)?;
    if let Some(p) = &a.colour.palette {
        o.colours = Some(shape_colours(doc, a, &p.0));
        if a.plot.layers == crate::plot::Layers::Colours {
            o.colour_layers = Some(p.0.clone());
        }
    } else if a.plot.layers == crate::plot::Layers::Colours {
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
fn cobble_look(doc: &FillDoc, a: &FillArgs) -> crate::cobble::Look {
    let filled = a.style == output::svg::Style::Filled;
    let mut flags = format!(" --pen-width {}", output::num(a.pen_width, 4));
    if filled {
        flags.push_str(" --style filled");
    }
    if a.boundary {
        flags.push_str(" --boundary");
    }
    flags.push_str(&a.colour.flags());
    crate::cobble::Look {
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
            Format::Svg => crate::cobble::svg(doc, &look),
            Format::Png => a.raster.render(&crate::cobble::svg(doc, &look)?),
            _ => Err(CliError::arg(
                "--voronoi",
                "cobblestones are drawn as SVG or PNG; write .svg or .png, or drop --voronoi",
            )),
        };
    }
    Ok(match format {
        Format::Svg => output::svg::render(doc, &svg_options(doc, a)?),
        Format::Gcode => match (&a.colour.palette, a.plot.layers) {
            (Some(p), crate::plot::Layers::Colours) => {
                let colours = shape_colours(doc, a, &p.0);
                crate::plot::render_gcode_pens(doc, &a.plot, Some((&colours, &p.0, a.colour.flags())), a.quiet)?
            }
            (None, crate::plot::Layers::Colours) => return Err(colours_need_palette()),
            _ => crate::plot::render_gcode(doc, &a.plot, a.quiet)?,
        },
        Format::Json => output::json::render(doc)?,
        Format::Csv => output::csv::render(doc),
        Format::Digest => output::digest::render(doc),
        Format::Png => match a.relief {
            Some(relief) => {
                let command = format!("{} --relief {}{}", output::svg::command_line(doc), relief.name(), a.raster.flag());
                output::height::render(doc, relief, output::height::grid(doc.extent(), &a.raster)?, &command)?
            }
            None => {
                let svg = output::svg::render(doc, &svg_options(doc, a)?);
                a.raster.render(&svg)?
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
    let pens = format == Format::Gcode && a.plot.layers == crate::plot::Layers::Colours && a.colour.background.is_none();
    a.colour.check(
        (matches!(format, Format::Svg | Format::Png) && a.relief.is_none()) || pens,
        "write .svg or .png, without --relief (or G-code with --layers colours, without --background)",
        false,
    )?;
    if a.plot.layers == crate::plot::Layers::Colours && a.colour.palette.is_none() {
        return Err(colours_need_palette());
    }
    if a.voronoi && a.colour.palette.is_some() && a.style != output::svg::Style::Filled {
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
    if a.plot.hatch.is_some() && a.style == output::svg::Style::Filled && matches!(format, Format::Svg | Format::Png) {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outlines_come_before_holes() {
        // A hole, the outline around it, and an island beside them.
        let Ok(RegionSpec::Polygon { points, ends }) = spec::region("polygon:4,4,6,4,6,6/0,0,10,0,10,10,0,10/20,0,30,0,30,9") else {
            panic!("rings refused");
        };
        let RegionSpec::Polygon { points: p, ends: e } = outers_first(&points, &ends) else {
            panic!("not a polygon");
        };
        assert_eq!(e, [4, 7, 10]);
        let xs: Vec<f64> = p.iter().map(|q| q.x).collect();
        assert_eq!(xs, [0.0, 10.0, 10.0, 0.0, 20.0, 30.0, 30.0, 4.0, 6.0, 6.0]);
        // Already in order: unchanged.
        let RegionSpec::Polygon { points: again, ends: e2 } = outers_first(&p, &e) else {
            panic!("not a polygon");
        };
        assert_eq!((again, e2), (p, e));
    }
}
