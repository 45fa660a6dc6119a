//! `zetafill space`: the 3D fractal fill. Runs the core's 3D engine on the plan's scalar,
//! builds the document, and writes it in the plan's format.

use crate::cmd::stopping;
use crate::error::CliError;
use crate::model::doc::{RunParamsDoc, StatsDoc};
use crate::model::slices;
use crate::model::space::{scene, SolidDoc, SpaceDoc};
use crate::output;
use crate::output::mesh::MeshOptions;
use crate::output::stream::{Output, Size};
use crate::plan::format::SpaceFormat;
use crate::plan::space::{first_halt_error, first_solid_error, halt_advice, SpaceDraw, SpacePlan, SpaceRun, SOLIDS};
use zetafill::digest::space_digest;
use zetafill::space::{
    cells_for as space_cells_for, index_words as space_index_words, Cell as SpaceCell, CellSampler as SpaceCells, Engine as SpaceEngine,
    Placed as PlacedSolid, Solid, Storage as SpaceStorage,
};
use zetafill::{Scalar, StepError, StopReason};

/// What a run of the engine produced, in f64 whatever the scalar.
struct EngineRun {
    solids: Vec<SolidDoc>,
    stats: zetafill::Stats,
    reason: StopReason,
    zeta: f64,
    digest: (u64, u64),
}

/// The document's name of a solid.
fn kind_name(s: &Solid) -> &'static str {
    match s {
        Solid::Sphere => "sphere",
        Solid::Cube => "cube",
        Solid::Tetrahedron => "tetrahedron",
        Solid::Octahedron => "octahedron",
        Solid::Shell { .. } => "shell",
        Solid::Torus { .. } => "torus",
    }
}

/// Runs the engine on scalar `S`.
fn run_engine<S: Scalar>(a: &SpaceRun) -> Result<EngineRun, CliError> {
    let cap = a.slots;
    let mut placed = vec![PlacedSolid::<S>::default(); cap];
    let mut index = vec![0u32; space_index_words(cap)];
    let storage = SpaceStorage {
        solids: &mut placed,
        index: &mut index,
    };
    let mut engine = SpaceEngine::<S>::new(a.params.clone(), a.region, storage).map_err(crate::plan::fill_errors::param_error)?;
    let mut rng = zetafill::rng_from_seed(a.seed);
    let bar = stopping::progress_bar(a.quiet, a.stop.count, SOLIDS);
    let mut trials = Vec::with_capacity(cap);
    let on_place = |p: &zetafill::space::Placement<S>| {
        trials.push(p.trials);
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let reason = if a.reference_sampler {
        engine.run(&mut rng, &a.stop, on_place)
    } else {
        let mut pool = vec![SpaceCell::default(); space_cells_for(cap)];
        let mut cells = SpaceCells::new(&mut pool).map_err(|e| CliError::Io(format!("internal: {e}")))?;
        engine.run_fast(&mut cells, &mut rng, &a.stop, on_place)
    };
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let solids = engine
        .placed()
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let i = i as u64;
            let kind = engine.kind_of(i);
            let size = p.scale.to_f64();
            let (inner_radius, tube_radius, beads) = match kind {
                Solid::Shell { inner } => (Some(size * inner), None, None),
                Solid::Torus { ratio } => (None, Some(size * ratio), Some(kind.beads() as u32)),
                _ => (None, None, None),
            };
            SolidDoc {
                index: i,
                kind: kind_name(&kind),
                center: [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()],
                size,
                inner_radius,
                tube_radius,
                beads,
                quaternion: p.rotation.map(|v| v.to_f64()),
                volume: engine.volume_of(i),
                trials: trials.get(i as usize).copied().unwrap_or(0),
            }
        })
        .collect();
    Ok(EngineRun {
        solids,
        stats: engine.stats(),
        reason,
        zeta: engine.sequence().zeta(),
        digest: space_digest(&engine),
    })
}

/// Runs the fill and returns the document, and the halt if any (after at least one
/// placement: a first solid that finds no place is a usage error). Nothing is written.
pub fn compute(a: &SpaceRun) -> Result<(SpaceDoc, Option<StepError>), CliError> {
    let run = if a.fixed_point {
        run_engine::<zetafill::Fixed>(a)?
    } else {
        run_engine::<f64>(a)?
    };
    let (stop_name, halt) = match run.reason {
        StopReason::Count => ("count", None),
        StopReason::Fill => ("fill", None),
        StopReason::MinSize => ("min-size", None),
        StopReason::Step(StepError::CannotFit { index: 0 }) => return Err(first_solid_error(None, &a.params, &a.region)),
        StopReason::Step(StepError::Halted { index: 0, trials }) => return Err(first_halt_error(a, trials)),
        StopReason::Step(e @ StepError::Capacity { .. }) => return Err(CliError::Io(format!("internal: {e}"))),
        StopReason::Step(e) => ("halted", Some(e)),
    };
    let (params, stop) = (&a.params, &a.stop);
    let doc = SpaceDoc {
        version: 1,
        mode: "space",
        command: a.command.clone(),
        params: RunParamsDoc {
            c: params.c,
            n_offset: params.n_offset,
            seed: a.seed,
            of: a.names.clone(),
            gap: params.gap,
            count: stop.count,
            fill: stop.fill,
            min_size: stop.min_size,
            max_trials: params.max_trials,
            dimension: 3.0 / params.c,
        },
        region: a.region_doc,
        volume: a.region.volume(),
        zeta: run.zeta,
        solids: run.solids,
        stats: StatsDoc {
            placed: run.stats.placed,
            trials: run.stats.trials,
            fill_fraction: run.stats.fill_fraction,
            halted: halt.is_some(),
            stop: stop_name,
        },
        digest: run.digest,
    };
    Ok((doc, halt))
}

/// A writer's refusal, which the plan's checks should have met first.
fn write_error(e: impl std::fmt::Display) -> CliError {
    CliError::Io(format!("cannot write the solids: {e}"))
}

/// Renders a document in a format.
pub fn render(doc: &SpaceDoc, format: SpaceFormat, d: &SpaceDraw) -> Result<Vec<u8>, CliError> {
    output(doc, format, d)?.into_bytes()
}

/// A document in a format, ready to be streamed: the meshes, the JSON and the CSV are
/// written one solid at a time as they are made; the render, the GLB (one mesh per kind of
/// solid) and the sheets are made whole first.
pub fn output<'a>(doc: &'a SpaceDoc, format: SpaceFormat, d: &SpaceDraw) -> Result<Output<'a>, CliError> {
    let region = doc.region.region3();
    Ok(match format {
        SpaceFormat::Json => Output::stream(Size::AtMost(output::space::json_max_size(doc)?), move |w| {
            output::space::json_to(doc, w)
        }),
        SpaceFormat::Csv => Output::stream(Size::AtMost(output::space::csv_max_size(doc)), move |w| {
            output::space::csv_to(doc, w)
        }),
        SpaceFormat::Digest => Output::bytes(output::space::digest(doc)),
        SpaceFormat::Stl => {
            let solids = scene(doc);
            let opt = MeshOptions::for_scene(&solids, d.segments);
            let size = output::stl::size(&solids, &opt).map_err(write_error)?;
            Output::stream(Size::Exact(size), move |mut w| {
                output::stl::write(&solids, &opt, &mut w).map_err(write_error)
            })
        }
        SpaceFormat::Obj => {
            let solids = scene(doc);
            let opt = MeshOptions::for_scene(&solids, d.segments);
            let size = output::obj::max_size(&solids, &opt).map_err(write_error)?;
            Output::stream(Size::AtMost(size), move |mut w| {
                output::obj::write(&solids, &opt, &mut w).map_err(write_error)
            })
        }
        SpaceFormat::Glb => Output::bytes(output::glb::to_bytes(&scene(doc), d.segments).map_err(write_error)?),
        SpaceFormat::Png => Output::bytes(output::render3d::render(&scene(doc), &region, &d.render).map_err(write_error)?),
        SpaceFormat::Svg => {
            let opt = d.slices.ok_or_else(|| CliError::Io("internal: an SVG without --slices".into()))?;
            let sheets = slices::slices(&scene(doc), &region, &opt).map_err(write_error)?;
            let mut picture = slices::stacked(&sheets).ok_or_else(|| write_error("no sheet"))?;
            picture.desc = format!("{}{}", doc.command, d.flags);
            output::svg::output(&picture)?
        }
    })
}

/// What makes a 3D output smaller, for the refusal of one above `--max-output-size`.
fn smaller(format: SpaceFormat) -> &'static str {
    match format {
        SpaceFormat::Stl | SpaceFormat::Obj | SpaceFormat::Glb => {
            "place fewer solids (--count, --fill, --min-size) or use fewer --segments"
        }
        SpaceFormat::Svg => "place fewer solids or cut thicker --slices",
        _ => "place fewer solids (--count, --fill, --min-size)",
    }
}

/// `zetafill space`: runs the plan and writes its output.
pub fn run(plan: &SpacePlan) -> Result<(), CliError> {
    let (doc, halt) = compute(&plan.run)?;
    let out = output(&doc, plan.format, &plan.draw)?;
    let what = output::stream::file_of(plan.format.name());
    crate::cmd::write_output(&plan.dest, &out, plan.max_output_size, &what, smaller(plan.format))?;
    stopping::outcome(halt, SOLIDS, |index, _| halt_advice(index))
}
