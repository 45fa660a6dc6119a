//! `--region` and `--periodic`: the refusals of a region that cannot be filled, which the
//! runs of fill and territory meet once they have read the region's outline.

use crate::error::CliError;
use crate::io::svgin::OutlineError;
use crate::output::machine::printable;
use std::path::Path;
use zetafill::RegionError;

/// An SVG outline (`--region svg:FILE`, the file `path`) that cannot be read.
pub fn outline_error(path: &Path, e: OutlineError) -> CliError {
    svg_error("--region", "of 0.5 mm", path, e)
}

/// An SVG file that `flag` names (its curves cut into chords `chords`, as the message words
/// it) that cannot be read.
pub fn svg_error(flag: &str, chords: &str, path: &Path, e: OutlineError) -> CliError {
    let path = path.display();
    // usvg's messages quote the byte they stopped at, control bytes too: written as escapes.
    CliError::arg(
        flag,
        printable(&match e {
            OutlineError::Read(e) => format!("cannot read '{path}': {e}"),
            OutlineError::Svg(e) => format!("'{path}' is not a readable SVG file: {e}"),
            OutlineError::NoClosedPath => {
                format!("'{path}' has no closed path; draw the outline as a closed path (ending in Z)")
            }
            OutlineError::NoFilledPath => {
                format!("'{path}' has no filled path outside its decorations; give the motif's outline a fill (fill=\"black\")")
            }
            OutlineError::Number(n) => format!(
                "'{path}' holds the number {n} in its path data, radii or styles, beyond {:e}; scale the drawing down",
                crate::io::svgin::MAX_NUMBER
            ),
            OutlineError::Far(v) => format!(
                "'{path}' puts a vertex {} mm from the origin once its transforms are applied, beyond {} mm; scale the drawing down",
                crate::error::num(v),
                crate::error::num(crate::io::svgin::MAX_COORDINATE_MM)
            ),
            OutlineError::TooManyRings => format!(
                "'{path}' has more than {} closed outlines; join or drop some",
                crate::io::svgin::MAX_RINGS
            ),
            OutlineError::TooManyVertices => format!(
                "'{path}' has more than {} vertices once its curves are cut into chords {chords}; simplify the outline",
                crate::io::svgin::MAX_VERTICES
            ),
        }),
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

/// A region whose area is too small to compute the shapes' sizes from (it rounds to 0 or
/// loses precision).
pub fn area_too_small(area: f64) -> CliError {
    CliError::arg(
        "--region",
        format!(
            "its area, {} mm², is too small to compute the shapes' sizes from; give sizes of at least 1e-150 mm",
            crate::error::num(area)
        ),
    )
}
