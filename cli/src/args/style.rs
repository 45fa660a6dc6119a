//! `--style`: how the shapes of an SVG are painted.

use crate::output::svg::Style;

/// `--style`: outlines or filled shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum StyleArg {
    /// Stroke-only outlines (pen plotters, laser cutting).
    Outline,
    /// Filled shapes without stroke (screens, prints).
    Filled,
}

impl From<StyleArg> for Style {
    fn from(s: StyleArg) -> Style {
        match s {
            StyleArg::Outline => Style::Outline,
            StyleArg::Filled => Style::Filled,
        }
    }
}
