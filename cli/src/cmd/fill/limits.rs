//! The limits a fill refuses up front: parameters whose first two shapes certainly cannot
//! both fit an inclusive rectangle, with the largest c (or gap) that works named in the
//! message.

use crate::args::spec;
use crate::error::CliError;
use zetafill::{Params, Region, ShapeKind};

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
pub(crate) fn check_known_limit(params: &Params, region: &Region<'_>) -> Result<(), CliError> {
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
