//! The messages of a 2D fill's own outcomes that name a flag: a parameter the core refuses, a
//! fill that cannot be held or reached, a first shape or first pair that does not fit, a halt.

use crate::args::fill::DEFAULT_MAX_TRIALS;
use crate::error::CliError;
use crate::model::doc::kind_name;
use zetafill::{FirstShape, FirstTwoError, ParamError, Params, ShapeList, Stop, TooLarge, TooSmall};

/// Names the flag behind a core parameter error.
pub fn param_error(e: ParamError) -> CliError {
    let flag = match e {
        ParamError::Exponent => "--c",
        ParamError::Offset | ParamError::Zeta => "--n-offset",
        ParamError::Shape => "--shape",
        ParamError::Region => "--region",
        // Only the fixed-point scalar has a limit.
        ParamError::Extent => {
            let max = <zetafill::Fixed as zetafill::Scalar>::MAX_EXTENT;
            return CliError::arg(
                "--region",
                format!(
                    "--scalar fixed computes regions of at most {max} mm a side, lying within {max} mm of the origin, exactly; use a smaller region or --scalar f64"
                ),
            );
        }
        ParamError::Gap => "--gap",
        ParamError::MaxTrials => "--max-trials",
        ParamError::Storage => "--count",
    };
    CliError::arg(flag, e)
}

/// The usage error of a run whose stop conditions reach a shape narrower than the scalar
/// resolves (the core's [`zetafill::check_smallest`]: 10 µm on `--scalar fixed`, 2^-40 of
/// the region's largest coordinate on `--scalar f64`), naming the stop condition that lets
/// it through. `is_f64`: the scalar is `f64`.
pub fn too_small_error(e: TooSmall, stop: &Stop, is_f64: bool) -> CliError {
    let TooSmall { index, width, limit } = e;
    // f64's limits are far below a micrometre: in exponent form.
    let (width, limit) = if is_f64 {
        (format!("{width:e}"), format!("{limit:e}"))
    } else {
        (width.to_string(), limit.to_string())
    };
    let scalar = if is_f64 {
        "--scalar f64 resolves at this region's coordinates (its outline would round to zero area)"
    } else {
        "--scalar fixed resolves"
    };
    let shape = format!("shape {index} ({width} mm wide) is narrower than the {limit} mm that {scalar}");
    let (flag, advice) = match (stop.count, stop.fill, stop.min_size) {
        (Some(count), _, _) => (
            "--count",
            format!("of the {count} shapes asked for, {shape}; ask for at most {index}, add --min-size {limit}"),
        ),
        (None, Some(fill), _) => (
            "--fill",
            format!("covering {fill} of the region, {shape}; lower it, add --min-size {limit}"),
        ),
        (None, None, Some(m)) => ("--min-size", format!("stopping at {m} mm, {shape}; raise it to {limit}")),
        (None, None, None) => ("--count", format!("{shape}; give --count or --min-size {limit}")),
    };
    let last = if is_f64 {
        "or use less slender --shape proportions"
    } else {
        "or use --scalar f64"
    };
    CliError::arg(
        flag,
        format!("{advice}, lower --c or raise --n-offset (larger small shapes), {last}"),
    )
}

/// The usage error of a run whose stop conditions reach a shape wider than `--scalar fixed`
/// computes exactly (the core's [`zetafill::check_largest`]: only a torus lets one in,
/// wrapped around it). Names `--shape` for a slender kind, `--n-offset` otherwise.
pub fn too_large_error(e: TooLarge, shape: &ShapeList, periodic: bool) -> CliError {
    let TooLarge { index, width, limit } = e;
    let kind = shape.kind_of(index);
    let flag = if kind.min_width(1.0) < 0.5 * kind.bounding_radius(1.0) {
        "--shape"
    } else {
        "--n-offset"
    };
    CliError::arg(
        flag,
        format!(
            "shape {index} would be {width} mm across, wider than the {limit} mm that --scalar fixed computes exactly{}; use less slender --shape proportions, raise --n-offset or lower --c (smaller first shapes), or use --scalar f64",
            if periodic { " (it would wrap around the torus)" } else { "" }
        ),
    )
}

/// Advice for a halt at placement `index` (at least 1: a halt at the first placement is
/// [`first_shape_error`]). A `proven` halt came before the trial limit: the cell sampler
/// found no place left, so more trials cannot help.
pub fn halt_advice(index: u64, proven: bool) -> &'static str {
    match (index < 100, proven) {
        (true, false) => "the first shapes left no room for this one: lower --c, raise --n-offset, or try another --seed",
        (true, true) => {
            "the first shapes left no room for this one, so more trials cannot help: lower --c, raise --n-offset, or try another --seed"
        }
        (false, false) => "raise --max-trials, lower --c, or ask for fewer shapes",
        (false, true) => "no place is left for a shape of this size, so more trials cannot help: lower --c, or ask for fewer shapes",
    }
}

/// The usage error of a fill that cannot place its first shape: `halt` is `None` when the
/// core knows the shape is too large for the region, or the trials spent before giving up.
/// `first` is the shape, as the core describes it. Nothing is written: an output with no shape
/// is no drawing.
///
/// `symmetric` names a fill with the symmetry of a wallpaper group, whose shape must clear
/// its own images in the lattice's cell.
pub fn first_shape_error(params: &Params, first: &FirstShape, halt: Option<u64>, symmetric: bool) -> CliError {
    let FirstShape {
        kind,
        area: first_area,
        width,
    } = *first;
    let region = if symmetric {
        "the cell clear of its own images"
    } else {
        "the region"
    };
    let what = match halt {
        None => format!("does not fit {region}"),
        Some(t) if t < params.max_trials => format!("does not fit anywhere in {region}"),
        Some(t) => format!("never fit in {region} ({t} trials found no place for it)"),
    };
    let mut advice = String::from("lower --c or raise --n-offset (a smaller first shape)");
    if params.gap > 0.0 {
        advice.push_str(", lower --gap");
    }
    advice.push_str(if symmetric {
        " or use a larger --lattice"
    } else {
        " or use a larger --region"
    });
    if halt.is_some_and(|t| t >= params.max_trials && params.max_trials < DEFAULT_MAX_TRIALS) {
        advice.push_str("; if it does fit, raise --max-trials");
    }
    CliError::arg(
        "--c",
        format!(
            "the first {} ({width:.4} mm wide, area {first_area:.4} mm²) {what}; {advice}",
            kind_name(&kind)
        ),
    )
}

/// The usage error of parameters whose first two shapes can never both fit an inclusive
/// rectangle (the core's [`zetafill::check_first_two`]), naming the flag to change and the
/// largest value that works; `params` are the run's.
pub fn first_two_error(e: FirstTwoError, params: &Params) -> CliError {
    match e {
        FirstTwoError::Gap {
            kind,
            gap,
            max_gap,
            width,
            height,
        } => CliError::arg(
            "--gap",
            format!(
                "{gap} mm leaves no room for two {}s in this {width} x {height} mm region, whatever --c and --n-offset; lower it below {max_gap:.4} mm or enlarge --region",
                kind_name(&kind),
            ),
        ),
        FirstTwoError::Offset { kind, n_offset: _ } => CliError::arg(
            "--n-offset",
            format!(
                "the first two {}s cannot both fit this region for any c; raise --n-offset{} or enlarge --region",
                kind_name(&kind),
                if params.gap > 0.0 { ", lower --gap" } else { "" }
            ),
        ),
        FirstTwoError::Exponent { kind, n_offset, max_c, .. } => CliError::arg(
            "--c",
            format!(
                "with N = {n_offset} the first two {}s cannot both fit in this region when c > {max_c:.4} (the paper's hard limit, section 3); lower --c or raise --n-offset",
                kind_name(&kind),
            ),
        ),
    }
}
