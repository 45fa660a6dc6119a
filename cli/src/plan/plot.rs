//! The plotter flags resolved: a G-code plan (the machine with every override checked, the
//! placement on its bed) and an SVG page plan, with the messages of the placements that can
//! only be checked once the drawing exists.

use crate::args::plot::PlotArgs;
use crate::error::CliError;
use crate::model::fill::BuildOptions;
use crate::model::{place, Bounds, Fit, Placement};
use crate::output::gcode::GcodeOptions;
use crate::output::machine::Machine;
use crate::output::svg::PageLayout;

/// How a drawing goes to G-code: the machine, its checked options, the placement on its bed
/// and the text of the plot flags for the file's header.
#[derive(Debug, Clone)]
pub struct GcodePlan {
    /// The machine profile.
    pub machine: Machine,
    /// Feeds, power, passes, arcs, order and margin, checked against the machine.
    pub options: GcodeOptions,
    /// How the drawing is placed on the bed (as it is unless `--fit` or `--center`).
    pub fit: Fit,
    /// Outlines, hatching and the smallest feature drawn.
    pub build: BuildOptions,
    /// The plot flags as command-line text (each with a leading space).
    pub flags: String,
    /// The hatch as the header says it (`none`, `SPEC` or `SPEC crossed`).
    pub hatch: String,
    /// Shapes narrower than this (mm) are left out.
    pub min_feature: f64,
}

/// A placed drawing the machine's G-code writer refuses (`why`, in the profile's terms), as a
/// fault of `--machine`.
pub fn gcode_error(why: String) -> CliError {
    CliError::arg("--machine", why)
}

impl GcodePlan {
    /// The machine and options the plot flags ask for, every override checked against the
    /// profile (exit 2 naming the flag).
    pub fn resolve(a: &PlotArgs) -> Result<GcodePlan, CliError> {
        let machine = a.machine()?;
        let options = a.gcode_options(&machine)?;
        Ok(GcodePlan {
            options,
            fit: a.fit(Fit::AsIs),
            build: a.build_options()?,
            flags: a.flags(),
            hatch: match (a.hatch.as_deref(), a.cross_hatch) {
                (Some(h), true) => format!("{h} crossed"),
                (h, _) => h.unwrap_or("none").to_string(),
            },
            min_feature: a.min_feature,
            machine,
        })
    }

    /// Where `frame` (the box of the drawing) goes on the bed; exit 2 naming `--machine`
    /// when it does not fit.
    pub fn place(&self, frame: &Bounds) -> Result<Placement, CliError> {
        let m = &self.machine;
        let margin = self.options.margin;
        place(frame, &m.usable_area(margin), self.fit).map_err(|e| {
            CliError::arg(
                "--machine",
                format!(
                    "{e} of the bed of '{}' ({} x {} mm, margin {} mm); use --fit to scale it or --center to move it",
                    m.name, m.bed.width, m.bed.height, margin
                ),
            )
        })
    }
}

/// An SVG page: its size, the margin and how the drawing is placed on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PagePlan {
    /// Width in mm.
    pub width: f64,
    /// Height in mm.
    pub height: f64,
    /// Margin in mm.
    pub margin: f64,
    /// Top left unless `--fit` or `--center`.
    pub fit: Fit,
}

impl PagePlan {
    /// The page `--page` asks for, if any, with `--margin` (default 10 mm) checked against it.
    pub fn resolve(a: &PlotArgs) -> Result<Option<PagePlan>, CliError> {
        let Some(page) = a.page else { return Ok(None) };
        let margin = a.margin.unwrap_or(10.0);
        if 2.0 * margin >= page.width.min(page.height) {
            return Err(CliError::arg(
                "--margin",
                format!("{margin} mm leaves no room on a {} x {} mm page", page.width, page.height),
            ));
        }
        Ok(Some(PagePlan {
            width: page.width,
            height: page.height,
            margin,
            fit: a.fit(Fit::TopLeft),
        }))
    }

    /// The layout of a drawing whose box is `(x0, y0, x1, y1)` on this page; exit 2 naming
    /// `--page` when it does not fit.
    pub fn layout(&self, (x0, y0, x1, y1): (f64, f64, f64, f64)) -> Result<PageLayout, CliError> {
        let m = self.margin;
        // The page frame here has y up from the page's bottom edge.
        let area = Bounds {
            x0: m,
            y0: m,
            x1: self.width - m,
            y1: self.height - m,
        };
        let pl = place(&Bounds { x0, y0, x1, y1 }, &area, self.fit).map_err(|e| {
            CliError::arg(
                "--page",
                format!("{e}; use --fit to scale it, or a larger --page or smaller --margin"),
            )
        })?;
        Ok(PageLayout {
            width: self.width,
            height: self.height,
            scale: pl.scale,
            dx: pl.dx,
            dy: pl.dy,
        })
    }
}
