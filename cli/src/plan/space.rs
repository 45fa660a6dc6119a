//! `zetafill space` resolved: the flags of a 3D fill checked against each other and turned
//! into the run (the core's parameters, region and stops) and the drawing (the mesh
//! resolution, the render, the sheets). Also the messages of the run's own outcomes that name
//! a flag: a first solid that does not fit, a halt.

use crate::args::fill::{Rotate, Sampler, ScalarArg, DEFAULT_MAX_TRIALS};
use crate::args::space::{solid_name, CutArg, SpaceArgs};
use crate::error::{num, CliError};
use crate::model::slices::{SliceOptions, MAX_SHEETS};
use crate::model::solid::{Region3, SolidKind};
use crate::model::space::{SolidParamsDoc, SpaceRegionDoc};
use crate::output::mesh::{MeshOptions, Mesher, SEGMENTS};
use crate::output::render3d::{Cut, RenderOptions, MAX_SIDE};
use crate::plan::format::SpaceFormat;
use crate::plan::Unit;
use zetafill::space::{
    capacity as space_capacity, check_first as check_first_solid, check_first_two as check_first_two_solids, Params as SpaceParams,
    Region as SpaceRegion, Solid,
};
use zetafill::{AreaSequence, Scalar, Stop};

/// The most solids one 3D run may hold (64 bytes a solid in the core, in f64).
pub const MAX_SOLIDS: u64 = 5_000_000;

/// What a 3D run places, and the most one run may hold.
pub const SOLIDS: Unit = Unit {
    plural: "solids",
    max: MAX_SOLIDS,
};

/// The default exponent of a 3D fill.
pub const DEFAULT_C: f64 = 1.15;

/// A checked `zetafill space`.
pub type SpacePlan = super::Planned<SpaceFormat, SpaceRun, SpaceDraw>;

/// What the engine runs.
#[derive(Debug, Clone)]
pub struct SpaceRun {
    /// The core's region.
    pub region: SpaceRegion,
    /// The region as the document records it.
    pub region_doc: SpaceRegionDoc,
    /// The core's parameters.
    pub params: SpaceParams,
    /// The stop conditions.
    pub stop: Stop,
    /// The volume sequence.
    pub sequence: AreaSequence,
    /// The solid slots the stop conditions need.
    pub slots: usize,
    /// RNG seed.
    pub seed: u64,
    /// The engine computes in 32.32 fixed point instead of f64.
    pub fixed_point: bool,
    /// The paper's sampler instead of the octree cell sampler.
    pub reference_sampler: bool,
    /// No progress bar.
    pub quiet: bool,
    /// The names the document records.
    pub names: SolidParamsDoc,
    /// The command line that makes the same solids again (without the output's own flags).
    pub command: String,
}

/// How the solids are written.
#[derive(Debug, Clone)]
pub struct SpaceDraw {
    /// STL, OBJ, GLB: segments around round solids.
    pub segments: u32,
    /// PNG: the render's size and cut-away.
    pub render: RenderOptions,
    /// SVG: the sheets.
    pub slices: Option<SliceOptions>,
    /// The output's own flags as command-line text.
    pub flags: String,
}

/// The core's region of `r`.
fn core_region(r: Region3, periodic: bool) -> (SpaceRegion, SpaceRegionDoc) {
    match r {
        Region3::Box { w, h, d } => (
            SpaceRegion::Box {
                width: w,
                height: h,
                depth: d,
                periodic,
            },
            SpaceRegionDoc::Box {
                width: w,
                height: h,
                depth: d,
                periodic,
            },
        ),
        Region3::Ball { r } => (SpaceRegion::Ball { radius: r }, SpaceRegionDoc::Ball { center: [r; 3], radius: r }),
        Region3::BoxMinusBall { w, h, d, r } => {
            let centre = [w / 2.0, h / 2.0, d / 2.0];
            (
                SpaceRegion::BoxMinusBall {
                    width: w,
                    height: h,
                    depth: d,
                    centre,
                    radius: r,
                },
                SpaceRegionDoc::Boxball {
                    width: w,
                    height: h,
                    depth: d,
                    center: centre,
                    radius: r,
                },
            )
        }
    }
}

/// The writers' kind of a solid at unit size (for the mesh checks before a run).
fn unit_kind(s: &Solid) -> SolidKind {
    match *s {
        Solid::Sphere => SolidKind::Sphere { radius: 1.0 },
        Solid::Cube => SolidKind::Cube { half_side: 1.0 },
        Solid::Tetrahedron => SolidKind::Tetrahedron { circumradius: 1.0 },
        Solid::Octahedron => SolidKind::Octahedron { circumradius: 1.0 },
        Solid::Shell { inner } => SolidKind::Shell { outer: 1.0, inner },
        Solid::Torus { ratio } => SolidKind::BeadTorus {
            major: 1.0,
            minor: ratio,
            beads: s.beads() as u32,
        },
    }
}

/// Checks the flags of `zetafill space` and resolves them into a plan. Nothing runs.
pub fn resolve(a: &SpaceArgs) -> Result<SpacePlan, CliError> {
    SpacePlan::resolve(
        &a.output.output,
        a.output.max_output_size,
        || SpaceFormat::resolve(a.output.format, &a.output.output),
        |format| resolve_as(a, format),
    )
}

/// The run and the drawing of `a` written as `format`: every rule between the flags, but none
/// about the output path.
pub fn resolve_as(a: &SpaceArgs, format: SpaceFormat) -> Result<(SpaceRun, SpaceDraw), CliError> {
    if a.sampler == Sampler::Batched {
        return Err(CliError::arg(
            "--sampler",
            "batched is a sampler of fill: use fast (the octree cells) or reference in 3D",
        ));
    }
    if a.periodic && !matches!(a.region, Region3::Box { .. }) {
        return Err(CliError::arg(
            "--periodic",
            "only box:W:H:D regions can be periodic; remove --periodic or use a box region",
        ));
    }
    if a.slices.is_some() && format != SpaceFormat::Svg {
        return Err(CliError::arg(
            "--slices",
            format!("writes the sheets as SVG, not {}: end -o in .svg", format.name()),
        ));
    }
    if a.slices.is_none() && format == SpaceFormat::Svg {
        return Err(CliError::arg(
            "--output",
            "the SVG of a 3D fill is its sheets for stacked laser cuts: give --slices THICKNESS",
        ));
    }
    let (lo, hi) = a.region.bounds();
    let depth = hi[2] - lo[2];
    let slices = match a.slices {
        Some(t) => {
            if t > depth {
                return Err(CliError::arg(
                    "--slices",
                    format!(
                        "sheets {} mm thick are thicker than the region is deep ({} mm); give at most its depth",
                        num(t),
                        num(depth)
                    ),
                ));
            }
            let n = (depth / t - 1e-9).ceil();
            if n > MAX_SHEETS as f64 {
                return Err(CliError::arg(
                    "--slices",
                    format!(
                        "{} mm makes {} sheets, more than {MAX_SHEETS}; give sheets at least {} mm thick",
                        num(t),
                        num(n),
                        num(depth / MAX_SHEETS as f64)
                    ),
                ));
            }
            Some(SliceOptions::new(t))
        }
        None => None,
    };
    if a.cut != CutArg::None && format != SpaceFormat::Png {
        return Err(CliError::arg("--cut", "is for the render: end -o in .png, or drop --cut"));
    }
    if !(1..=MAX_SIDE).contains(&a.pixels) {
        return Err(CliError::arg(
            "--pixels",
            format!("{} pixels: the render's side must be from 1 to {MAX_SIDE}", a.pixels),
        ));
    }
    if !SEGMENTS.contains(&a.segments) {
        return Err(CliError::arg(
            "--segments",
            format!("{}: a mesh needs {} to {} segments", a.segments, SEGMENTS.start(), SEGMENTS.end()),
        ));
    }
    let stop = crate::plan::stops(&a.run.stop);
    if matches!(format, SpaceFormat::Stl | SpaceFormat::Obj | SpaceFormat::Glb) {
        let mesher = Mesher::new(&MeshOptions::new(a.segments)).map_err(|e| CliError::arg("--segments", e))?;
        let mut fewest = u64::MAX;
        for s in &a.shape.0 {
            let plan = mesher.plan(&unit_kind(s)).map_err(|e| {
                CliError::arg(
                    "--segments",
                    format!(
                        "{} at {} segments: {e}; raise --segments or change the --shape proportions",
                        solid_name(s),
                        a.segments
                    ),
                )
            })?;
            fewest = fewest.min(mesher.triangles(&plan) as u64);
        }
        check_mesh_size(a, format, &stop, fewest)?;
    }
    if stop.count.is_some_and(|k| k > SOLIDS.max) {
        return Err(CliError::arg(
            "--count",
            format!("at most {} solids a run; ask for fewer", SOLIDS.max),
        ));
    }
    let seed = a.run.seed.seed;
    let order = match a.mix_order {
        crate::args::fill::MixArg::Cycle => zetafill::MixOrder::Cycle,
        crate::args::fill::MixArg::Random => zetafill::MixOrder::Random,
    };
    let solids = a.shape.list(order, seed);
    let rotate = a.rotate.map_or(a.shape.rotates(), |r| r == Rotate::Random);
    let params = SpaceParams {
        c: crate::plan::exponent(&a.run.power, DEFAULT_C, SpaceParams::c_from_dimension),
        n_offset: a.run.power.n_offset,
        solids,
        rotate,
        gap: a.run.gap,
        max_trials: a.run.max_trials,
    };
    let (region, region_doc) = core_region(a.region, a.periodic);
    let fixed_point = a.scalar == ScalarArg::Fixed;
    if fixed_point {
        let max = <zetafill::Fixed as Scalar>::MAX_EXTENT;
        if hi.iter().any(|&v| v > max) {
            return Err(crate::plan::fill_errors::param_error(zetafill::ParamError::Extent));
        }
    }
    region.check().map_err(crate::plan::fill_errors::param_error)?;
    if a.run.gap >= 0.5 * hi.iter().fold(f64::MAX, |m, &v| m.min(v)) {
        return Err(CliError::arg(
            "--gap",
            format!("{} mm leaves no room in this region; lower it", num(a.run.gap)),
        ));
    }
    let sequence = crate::plan::sequence(region.volume(), params.c, params.n_offset)?;
    let first = params.solids.kind_of(0);
    crate::plan::check_min_size(&stop, first.min_width(first.scale_for_volume(sequence.area(0))), SOLIDS)?;
    check_first_solid(&params, &region).map_err(|e| first_solid_error(e.max_c, &params, &region))?;
    check_first_two_solids(&params, &region).map_err(|e| first_two_error(e.max_c, &params))?;
    let slots = crate::plan::slots(space_capacity(&sequence, &params.solids, &stop, SOLIDS.max), SOLIDS)? as usize;
    let names = SolidParamsDoc {
        shape: a.shape.name(),
        rotate: if rotate && a.shape.rotates() { "random" } else { "none" },
        mix_order: (a.shape.0.len() > 1).then(|| a.mix_order.name()),
        scalar: a.scalar.name(),
        sampler: a.sampler.name(),
    };
    let mut command = format!(
        "zetafill space --shape {}{} --rotate {} --region {} --c {} --n-offset {} --gap {} --max-trials {} --seed {} --sampler {}{}",
        names.shape,
        names.mix_order.map_or_else(String::new, |m| format!(" --mix-order {m}")),
        names.rotate,
        region_doc.arg(),
        params.c,
        params.n_offset,
        params.gap,
        params.max_trials,
        seed,
        names.sampler,
        if fixed_point { " --scalar fixed" } else { "" }
    );
    if let Some(k) = stop.count {
        command.push_str(&format!(" --count {k}"));
    }
    if let Some(f) = stop.fill {
        command.push_str(&format!(" --fill {f}"));
    }
    if let Some(m) = stop.min_size {
        command.push_str(&format!(" --min-size {m}"));
    }
    let cut = match a.cut {
        CutArg::None => Cut::None,
        CutArg::Octant => Cut::Octant,
        CutArg::Half => Cut::Half,
    };
    let flags = match format {
        SpaceFormat::Stl | SpaceFormat::Obj | SpaceFormat::Glb => format!(" --segments {}", a.segments),
        SpaceFormat::Png => format!(" --pixels {} --cut {}", a.pixels, cut_name(a.cut)),
        SpaceFormat::Svg => a.slices.map_or_else(String::new, |t| format!(" --slices {t}")),
        _ => String::new(),
    };
    let run = SpaceRun {
        region,
        region_doc,
        params,
        stop,
        sequence,
        slots,
        seed,
        fixed_point,
        reference_sampler: a.sampler == Sampler::Reference,
        quiet: a.quiet,
        names,
        command,
    };
    let draw = SpaceDraw {
        segments: a.segments,
        render: RenderOptions {
            width: a.pixels,
            height: a.pixels,
            samples: 2,
            cut,
        },
        slices,
        flags,
    };
    Ok((run, draw))
}

/// Refuses, before the fill, a mesh that `--count` solids of at least `fewest` triangles each
/// make larger than `--max-output-size` (when the count is the only stop, the run places that
/// many solids unless it halts). The fill's own check after the run covers the rest.
fn check_mesh_size(a: &SpaceArgs, format: SpaceFormat, stop: &Stop, fewest: u64) -> Result<(), CliError> {
    let (Some(k), None, None) = (stop.count, stop.fill, stop.min_size) else {
        return Ok(());
    };
    let least = match format {
        SpaceFormat::Stl => crate::output::stl::file_size(k.saturating_mul(fewest)),
        // A line "f A B C" of at least 8 bytes a triangle.
        SpaceFormat::Obj => k.saturating_mul(8 * fewest),
        _ => return Ok(()),
    };
    let limit = a.output.max_output_size;
    if least <= limit {
        return Ok(());
    }
    let bytes = crate::output::stream::bytes_text;
    Err(CliError::arg(
        "--max-output-size",
        format!(
            "{k} solids at {} segments make an {} file of {}{}, more than the limit of {}: ask for fewer solids (--count) or use fewer --segments, or raise --max-output-size",
            a.segments,
            format.name().to_ascii_uppercase(),
            if format == SpaceFormat::Stl { "" } else { "at least " },
            bytes(least),
            bytes(limit)
        ),
    ))
}

/// `--cut` as written.
fn cut_name(c: CutArg) -> &'static str {
    match c {
        CutArg::None => "none",
        CutArg::Octant => "octant",
        CutArg::Half => "half",
    }
}

/// The usage error of a first solid that cannot fit the region: `max_c` is the largest c at
/// which it does, when one does. In a periodic box the solid is too wide for the period: it
/// would meet its own image.
pub fn first_solid_error(max_c: Option<f64>, params: &SpaceParams, region: &SpaceRegion) -> CliError {
    let what = if region.periodic() {
        "wider than the period (it would meet its own image)"
    } else {
        "larger than the region"
    };
    match max_c {
        Some(c) => CliError::arg(
            "--c",
            format!(
                "the first solid is {what} at c = {}; lower --c to at most {c:.4}, raise --n-offset or use a larger --region",
                params.c
            ),
        ),
        None => CliError::arg(
            "--n-offset",
            format!(
                "the first solid is {what} at any c; raise --n-offset{} or use a larger --region",
                if params.gap > 0.0 { ", lower --gap" } else { "" }
            ),
        ),
    }
}

/// The usage error of a first solid that found no place in `trials` trials (nothing is
/// written: an output with no solid is no fill), in the words of the 2D fill's
/// ([`crate::plan::fill_errors::first_shape_error`]): the solid, what happened, and what to change,
/// `--max-trials` included when the limit was lowered and reached.
pub fn first_halt_error(run: &SpaceRun, trials: u64) -> CliError {
    let params = &run.params;
    let kind = params.solids.kind_of(0);
    let volume = run.sequence.area(0);
    let width = kind.min_width(kind.scale_for_volume(volume));
    let what = if trials < params.max_trials {
        "does not fit anywhere in the region".to_string()
    } else {
        format!("never fit in the region ({trials} trials found no place for it)")
    };
    let mut advice = String::from("lower --c or raise --n-offset (a smaller first solid)");
    if params.gap > 0.0 {
        advice.push_str(", lower --gap");
    }
    advice.push_str(" or use a larger --region");
    if trials >= params.max_trials && params.max_trials < DEFAULT_MAX_TRIALS {
        advice.push_str("; if it does fit, raise --max-trials");
    }
    CliError::arg(
        "--c",
        format!(
            "the first {} ({width:.4} mm wide, volume {volume:.4} mm³) {what}; {advice}",
            solid_name(&kind)
        ),
    )
}

/// Advice for a halt at placement `index` (at least 1).
pub fn halt_advice(index: u64) -> &'static str {
    if index < 100 {
        "the first solids left no room for this one: lower --c, raise --n-offset, or try another --seed"
    } else {
        "raise --max-trials, lower --c, or ask for fewer solids"
    }
}

/// The usage error of a first two solids that cannot both fit the region (the hard limit on c
/// for spheres, and for unrotated cubes in a box): `max_c` is the largest c at which they do,
/// when one does.
pub fn first_two_error(max_c: Option<f64>, params: &SpaceParams) -> CliError {
    match max_c {
        Some(c) => CliError::arg(
            "--c",
            format!(
                "with N = {} the first two solids cannot both fit in this region when c > {c:.4} (the hard limit, Shier and Bourke's section 3); lower --c to at most {c:.4} or raise --n-offset",
                params.n_offset
            ),
        ),
        None => CliError::arg(
            "--n-offset",
            format!(
                "the first two solids cannot both fit in this region at any c; raise --n-offset{} or use a larger --region",
                if params.gap > 0.0 { ", lower --gap" } else { "" }
            ),
        ),
    }
}
