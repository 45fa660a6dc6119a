//! A region as the command line gives it, before any file is read or the core checks it: a
//! plain value that the flag parser produces, the plan holds and the run turns into the
//! core's region.

use zetafill::Point;

/// A region as given (periodicity is given apart): its kind and sizes, polygon rings, or an
/// SVG file whose outline is not read yet.
#[derive(Debug, Clone, PartialEq)]
pub enum RegionSpec {
    /// `rect:W:H`.
    Rect {
        /// Width in mm.
        width: f64,
        /// Height in mm.
        height: f64,
    },
    /// `circle:R`: the disc centred at (R, R).
    Circle {
        /// Radius in mm.
        radius: f64,
    },
    /// `annulus:R_OUTER:R_INNER`, centred at (R_OUTER, R_OUTER).
    Annulus {
        /// Outer radius.
        outer: f64,
        /// Inner radius.
        inner: f64,
    },
    /// `polygon:X1,Y1,X2,Y2,...` or the outlines of `svg:FILE`: rings of vertices.
    Polygon {
        /// Vertices, ring after ring.
        points: Vec<Point<f64>>,
        /// Exclusive end of each ring.
        ends: Vec<usize>,
    },
    /// `svg:FILE`, read by the run ([`crate::io::svgin`]).
    Svg(std::path::PathBuf),
}
