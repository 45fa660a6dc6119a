//! The resolve step: each command's parsed flags ([`crate::args`]) become a checked plan in
//! plain Rust, with no clap type inside. Every rule that ties one flag to another, and every
//! message that names a flag, lives here; the commands of [`crate::cmd`] then compute and
//! write what the plan says, and never look at a flag again.

pub mod fill;
pub mod line;
pub mod plot;
pub mod stats;
pub mod territory;
pub mod tile;

use crate::args::common::{PowerLawArgs, StopArgs};
use zetafill::Stop;

/// The exponent c: `--c`, or else `--dimension` through `from_dimension` (c = 2/D in 2D,
/// 1/D in 1D), or else `default`.
pub fn exponent(p: &PowerLawArgs, default: f64, from_dimension: fn(f64) -> f64) -> f64 {
    match (p.c, p.dimension) {
        (Some(c), _) => c,
        (None, Some(d)) => from_dimension(d),
        (None, None) => default,
    }
}

/// The stop conditions: 2000 pieces when none is given.
pub fn stop(s: &StopArgs) -> Stop {
    crate::cmd::stopping::stop(s.count, s.fill, s.min_size)
}
