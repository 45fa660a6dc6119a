//! Why a site cannot join a Delaunay triangulation of sites (the territory competition's, or
//! any other): a plain error value whose text names no flag, so each caller can say which
//! flag or input the site came from.

use std::fmt;

/// Why a site could not be added.
#[derive(Debug, Clone, PartialEq)]
pub enum SiteError {
    /// The point lies exactly on site `index`.
    Coincident {
        /// The existing site.
        index: usize,
    },
    /// A coordinate spade cannot hold (not finite, or out of its range).
    Coordinate(String),
    /// Fewer than two seeds.
    TooFewSeeds,
}

impl fmt::Display for SiteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SiteError::Coincident { index } => write!(f, "the point coincides with site {index}"),
            SiteError::Coordinate(e) => write!(f, "a coordinate is out of range ({e})"),
            SiteError::TooFewSeeds => f.write_str("at least 2 seeds are needed"),
        }
    }
}

impl std::error::Error for SiteError {}
