//! `--symmetry`, `--lattice` and `--repeat` (or `--region`) resolved into the group on its lattice, and the
//! message of a first shape that can never clear its own images.

use crate::args::symmetry::SymmetryArgs;
use crate::error::CliError;
use crate::model::doc::kind_name;
use zetafill::{FirstOrbitError, LatticeKind, Params};

/// A fill with the symmetry of a wallpaper group: the group on its lattice, and the cells
/// drawn across and up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SymmetryPlan {
    /// The group and its lattice.
    pub wallpaper: zetafill::Wallpaper,
    /// `--repeat`.
    pub repeat: (u32, u32),
    /// Whether the pattern is cut to `--region` (instead of drawn over `repeat` cells).
    pub cut: bool,
}

/// The lattice a group needs, as its message names it.
fn lattice_form(kind: LatticeKind) -> &'static str {
    match kind {
        LatticeKind::Oblique => "an oblique lattice: give A:B:ANGLE (sides in mm, angle in degrees)",
        LatticeKind::Rectangular => "a rectangular lattice: give A:B (sides in mm)",
        LatticeKind::Centred => "a centred rectangular lattice: give A:B (sides in mm)",
        LatticeKind::Square => "a square lattice: give A (side in mm)",
        LatticeKind::Hexagonal => "a hexagonal lattice: give A (side in mm)",
    }
}

/// `--symmetry`, `--lattice` and `--repeat` checked against each other.
pub fn resolve(a: &SymmetryArgs, cut: bool) -> Result<Option<SymmetryPlan>, CliError> {
    let (Some(s), Some(l)) = (a.symmetry, &a.lattice) else {
        return Ok(None);
    };
    let group = s.group();
    let kind = group.lattice();
    let v = &l.0;
    if v.len() != kind.arity() {
        return Err(CliError::arg(
            "--lattice",
            format!(
                "{} has {}, not {} number{}",
                group.name(),
                lattice_form(kind),
                v.len(),
                if v.len() == 1 { "" } else { "s" }
            ),
        ));
    }
    let side = v.first().copied().unwrap_or(0.0);
    let other = v.get(1).copied().unwrap_or(side);
    let angle = v.get(2).copied().unwrap_or(90.0);
    let wallpaper = zetafill::Wallpaper::new(group, side, other, angle).map_err(|e| CliError::arg("--lattice", e.to_string()))?;
    let repeat = a.repeat.map_or((3, 3), |r| (r.0, r.1));
    Ok(Some(SymmetryPlan { wallpaper, repeat, cut }))
}

/// The usage error of a symmetric fill whose first shape can never clear its own images
/// (the core's [`zetafill::check_first_orbit`]).
pub fn first_orbit_error(e: FirstOrbitError, params: &Params, w: &zetafill::Wallpaper) -> CliError {
    let lattice = crate::model::wallpaper::lattice_arg(w);
    match e {
        FirstOrbitError::Gap { gap, max_gap, .. } => CliError::arg(
            "--gap",
            format!(
                "{gap} mm leaves no shape room to clear its own images on this lattice, whatever --c and --n-offset; lower it below {max_gap:.4} mm or use a larger --lattice"
            ),
        ),
        FirstOrbitError::Exponent { kind, max_c, room, .. } => CliError::arg(
            "--c",
            format!(
                "the first {} cannot clear its own images in {} on the lattice {lattice} (the most room anywhere is a disc of radius {room:.4} mm); lower --c to {} or less, raise --n-offset{}, or use a larger --lattice",
                kind_name(&kind),
                w.group().name(),
                // Rounded down, so that the value named works.
                (max_c * 1e4).floor() / 1e4,
                if params.gap > 0.0 { ", lower --gap" } else { "" }
            ),
        ),
    }
}
