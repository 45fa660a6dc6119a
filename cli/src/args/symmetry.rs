//! The flags of a fill with the symmetry of a wallpaper group: the group, its lattice and the
//! cells drawn.

use super::spec;
use clap::{Args, ValueEnum};
use zetafill::Group;

/// A wallpaper group, by its short international name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SymmetryArg {
    /// Translations only (oblique lattice A:B:ANGLE).
    P1,
    /// Half turns (oblique lattice A:B:ANGLE).
    P2,
    /// Parallel mirrors (rectangular lattice A:B).
    Pm,
    /// Parallel glides (rectangular lattice A:B).
    Pg,
    /// Mirrors and glides (centred rectangular lattice A:B).
    Cm,
    /// Mirrors both ways (rectangular lattice A:B).
    Pmm,
    /// Mirrors one way, glides the other (rectangular lattice A:B).
    Pmg,
    /// Glides both ways (rectangular lattice A:B).
    Pgg,
    /// Mirrors both ways, centred (centred rectangular lattice A:B).
    Cmm,
    /// Quarter turns (square lattice A).
    P4,
    /// Quarter turns and mirrors through their centres (square lattice A).
    P4m,
    /// Quarter turns, mirrors off their centres (square lattice A).
    P4g,
    /// Third turns (hexagonal lattice A).
    P3,
    /// Third turns, mirrors through every centre (hexagonal lattice A).
    P3m1,
    /// Third turns, mirrors off some centres (hexagonal lattice A).
    P31m,
    /// Sixth turns (hexagonal lattice A).
    P6,
    /// Sixth turns and mirrors (hexagonal lattice A).
    P6m,
}

impl SymmetryArg {
    /// The core's group.
    pub fn group(self) -> Group {
        match self {
            SymmetryArg::P1 => Group::P1,
            SymmetryArg::P2 => Group::P2,
            SymmetryArg::Pm => Group::Pm,
            SymmetryArg::Pg => Group::Pg,
            SymmetryArg::Cm => Group::Cm,
            SymmetryArg::Pmm => Group::Pmm,
            SymmetryArg::Pmg => Group::Pmg,
            SymmetryArg::Pgg => Group::Pgg,
            SymmetryArg::Cmm => Group::Cmm,
            SymmetryArg::P4 => Group::P4,
            SymmetryArg::P4m => Group::P4m,
            SymmetryArg::P4g => Group::P4g,
            SymmetryArg::P3 => Group::P3,
            SymmetryArg::P3m1 => Group::P3m1,
            SymmetryArg::P31m => Group::P31m,
            SymmetryArg::P6 => Group::P6,
            SymmetryArg::P6m => Group::P6m,
        }
    }
}

/// `--lattice`: one, two or three numbers (sides in mm, then an angle in degrees).
#[derive(Debug, Clone, PartialEq)]
pub struct LatticeArg(pub Vec<f64>);

/// `--repeat`: cells across and up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RepeatArg(pub u32, pub u32);

/// The most cells `--repeat` draws each way.
pub const MAX_REPEAT: u32 = 100;

/// Parses `--lattice A`, `A:B` or `A:B:ANGLE`.
pub fn lattice(s: &str) -> Result<LatticeArg, String> {
    let parts: Vec<&str> = s.split(':').collect();
    if parts.len() > 3 {
        return Err(format!(
            "'{s}' has {} numbers; write A, A:B or A:B:ANGLE (sides in mm, angle in degrees)",
            parts.len()
        ));
    }
    let mut v = Vec::with_capacity(3);
    for (i, p) in parts.iter().enumerate() {
        if i == 2 {
            let a = spec::finite(p)?;
            if !(a > 0.0 && a < 180.0) {
                return Err(format!("the angle must be between 0 and 180 degrees, not inclusive (got {p})"));
            }
            v.push(a);
        } else {
            v.push(spec::length(p)?);
        }
    }
    Ok(LatticeArg(v))
}

/// Parses `--repeat C:R`.
pub fn repeat(s: &str) -> Result<RepeatArg, String> {
    let cells = |p: &str| p.trim().parse::<u32>().ok().filter(|n| (1..=MAX_REPEAT).contains(n));
    match s.split_once(':').map(|(c, r)| (cells(c), cells(r))) {
        Some((Some(c), Some(r))) => Ok(RepeatArg(c, r)),
        _ => Err(format!(
            "'{s}' is not C:R, two whole numbers of cells from 1 to {MAX_REPEAT}, such as 3:3"
        )),
    }
}

/// The symmetry flags of `zetafill fill`.
#[derive(Debug, Args, Default)]
pub struct SymmetryArgs {
    /// Fill the plane with the symmetry of a wallpaper group: each shape comes with all its
    /// images under the group (needs --lattice; drawn over --repeat cells, or cut to --region).
    #[arg(long, value_enum, requires = "lattice", conflicts_with_all = ["periodic", "voronoi"], help_heading = "Symmetry")]
    pub symmetry: Option<SymmetryArg>,
    /// The group's lattice in mm: A for square and hexagonal groups (p4.., p3.., p6..), A:B
    /// for rectangular and centred ones (pm, pg, cm, pmm, pmg, pgg, cmm), A:B:ANGLE for the
    /// oblique p1 and p2 (ANGLE in degrees).
    #[arg(long, value_parser = lattice, requires = "symmetry", allow_hyphen_values = true, help_heading = "Symmetry")]
    pub lattice: Option<LatticeArg>,
    /// The cells drawn, across and up: C:R (default 3:3, unless --region gives the outline or
    /// --page the sheet).
    #[arg(long, value_parser = repeat, requires = "symmetry", conflicts_with = "region", help_heading = "Symmetry")]
    pub repeat: Option<RepeatArg>,
}
