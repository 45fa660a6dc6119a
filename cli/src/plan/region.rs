//! `--region` and `--periodic`: the refusals of a region that cannot be filled, which the
//! runs of fill and territory meet once they have read the region's outline.

use crate::error::CliError;
use crate::io::svgin::OutlineError;
use std::path::Path;
use zetafill::RegionError;

/// An SVG outline (`--region svg:FILE`, the file `path`) that cannot be read.
pub fn outline_error(path: &Path, e: OutlineError) -> CliError {
    let path = path.display();
    CliError::arg(
        "--region",
        match e {
            OutlineError::Read(e) => format!("cannot read '{path}': {e}"),
            OutlineError::Svg(e) => format!("'{path}' is not a readable SVG file: {e}"),
            OutlineError::NoClosedPath => {
                format!("'{path}' has no closed path; draw the outline as a closed path (ending in Z)")
            }
        },
    )
}

/// The refusal of `--periodic` with a region that is not a rectangle.
pub fn not_periodic() -> CliError {
    CliError::arg(
        "--periodic",
        "only rect:W:H regions can be periodic; remove --periodic or use a rect region",
    )
}

/// A polygon region (given, or read from SVG) that the core refuses.
pub fn polygon_error(e: RegionError) -> CliError {
    CliError::arg("--region", format!("{e}; give a simple outline"))
}
