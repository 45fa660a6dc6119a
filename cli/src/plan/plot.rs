//! The plotter flags resolved: a G-code plan (the machine with every override checked, the
//! placement on its bed) and an SVG page plan, with the messages of the placements that can
//! only be checked once the drawing exists.

use crate::args::plot::{Layers, PlotArgs, DEFAULT_MACHINE};
use crate::error::CliError;
use crate::model::fill::BuildOptions;
use crate::model::hatch;
use crate::model::{place, Bounds, Fit, Placement};
use crate::output::gcode;
use crate::output::gcode::GcodeOptions;
use crate::output::machine::Machine;
use crate::output::machine::{self, MAX_FEED, MIN_FEED};
use crate::output::order::PathOrder;
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
    /// No figures (length, time) on stderr.
    pub quiet: bool,
}

/// A placed drawing the machine's G-code writer refuses (`why`, in the profile's terms), as a
/// fault of `--machine`.
pub fn gcode_error(why: String) -> CliError {
    CliError::arg("--machine", why)
}

impl GcodePlan {
    /// The machine and options the plot flags ask for, every override checked against the
    /// profile (exit 2 naming the flag); `quiet` keeps the plot's figures off stderr.
    pub fn resolve(a: &PlotArgs, quiet: bool) -> Result<GcodePlan, CliError> {
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
            quiet,
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

/// The margin of an SVG page without `--margin` (mm).
pub const DEFAULT_PAGE_MARGIN: f64 = 10.0;

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
        let margin = a.margin.unwrap_or(DEFAULT_PAGE_MARGIN);
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

/// What to write instead, for a flag that only G-code output reads.
pub const FOR_GCODE: &str = "is for G-code output (write .gcode or .nc, or give --format gcode)";

/// The checks and conversions of the plotter flags, with every message that names one of them
/// (the flags themselves are clap's, in [`crate::args::plot`]).
impl PlotArgs {
    /// Refuses the first plot flag given that is not in `allowed` (exit 2), with the flag
    /// named and `why` (given the flag) as the reason.
    pub fn refuse_except(&self, allowed: &[&str], why: impl Fn(&str) -> String) -> Result<(), CliError> {
        match self.given().into_iter().find(|f| !allowed.contains(f)) {
            Some(f) => Err(CliError::arg(f, why(f))),
            None => Ok(()),
        }
    }

    /// The checks of G-code output common to every command that writes it: the profile
    /// loads and every override fits it; pages and layers are refused (they are for SVG).
    pub fn check_gcode(&self) -> Result<(), CliError> {
        let m = self.machine()?;
        self.gcode_options(&m)?;
        if self.page.is_some() {
            return Err(CliError::arg("--page", "pages are for SVG; G-code uses the machine's bed"));
        }
        if let Layers::SizeBands(_) = self.layers {
            return Err(CliError::arg(
                "--layers",
                "size bands are SVG layers (one pen per layer); in G-code, --layers colours draws one pen after another",
            ));
        }
        Ok(())
    }

    /// The hatch, if asked for (exit 2 naming --hatch when malformed).
    pub fn hatch(&self) -> Result<Option<hatch::Hatch>, CliError> {
        self.hatch
            .as_deref()
            .map(hatch::Hatch::parse)
            .transpose()
            .map(|h| {
                h.map(|h| hatch::Hatch {
                    cross: self.cross_hatch,
                    ..h
                })
            })
            .map_err(|e| CliError::arg("--hatch", e))
    }

    /// The drawing options.
    pub fn build_options(&self) -> Result<BuildOptions, CliError> {
        Ok(BuildOptions {
            min_feature: self.min_feature,
            hatch: self.hatch()?,
            no_outline: self.hatch_only,
        })
    }

    /// The machine with every command-line override applied and checked.
    pub fn machine(&self) -> Result<machine::Machine, CliError> {
        // A profile file is an input, noted by `profile_text` as it is read: no output may
        // replace it.
        machine::Machine::load(self.machine.as_deref().unwrap_or(DEFAULT_MACHINE), profile_text).map_err(|e| CliError::arg("--machine", e))
    }

    /// The G-code options for `m`, every override checked against the profile.
    pub fn gcode_options(&self, m: &machine::Machine) -> Result<gcode::GcodeOptions, CliError> {
        let mut o = gcode::GcodeOptions::new(m);
        if let Some(f) = self.feed {
            if !(MIN_FEED..=MAX_FEED).contains(&f) {
                return Err(CliError::arg(
                    "--feed",
                    format!(
                        "{} mm/min: a feed must be positive, from {MIN_FEED} to {MAX_FEED} mm/min",
                        crate::error::num(f)
                    ),
                ));
            }
            o.feed = f;
        }
        if let Some(f) = self.travel_feed {
            if !(MIN_FEED..=MAX_FEED).contains(&f) {
                return Err(CliError::arg(
                    "--travel-feed",
                    format!(
                        "{} mm/min: a feed must be positive, from {MIN_FEED} to {MAX_FEED} mm/min",
                        crate::error::num(f)
                    ),
                ));
            }
            o.travel_feed = f;
        }
        if let Some(p) = self.power {
            let Some(range) = &m.power else {
                return Err(CliError::arg(
                    "--power",
                    format!("the profile '{}' has no power range (it is not a laser); drop --power", m.name),
                ));
            };
            if p < range.min || p > range.max {
                return Err(CliError::arg(
                    "--power",
                    format!(
                        "{} is outside the profile's range {} to {}",
                        crate::error::num(p),
                        range.min,
                        range.max
                    ),
                ));
            }
            o.power = Some(p);
        }
        o.passes = self.passes.unwrap_or(1);
        o.arcs = if self.arcs {
            if !m.arcs {
                return Err(CliError::arg(
                    "--arcs",
                    format!("the profile '{}' does not allow arcs (arcs = false)", m.name),
                ));
            }
            true
        } else if self.no_arcs {
            false
        } else {
            m.arcs
        };
        if let Some(t) = self.chord_tolerance {
            // Below the G-code's resolution (3 decimals of mm) finer chords only add lines: a
            // tolerance of 1e-300 mm asked for gigabytes.
            if t < gcode::MIN_CHORD_TOLERANCE {
                return Err(CliError::arg(
                    "--chord-tolerance",
                    format!(
                        "{} mm is below {} mm, the G-code's resolution; give at least {}",
                        crate::error::num(t),
                        gcode::MIN_CHORD_TOLERANCE,
                        gcode::MIN_CHORD_TOLERANCE
                    ),
                ));
            }
            o.chord_tolerance = t;
        }
        o.order = self.order.map_or(o.order, PathOrder::from);
        o.margin = self.margin.unwrap_or(0.0);
        let short = m.bed.width.min(m.bed.height);
        if 2.0 * o.margin >= short {
            return Err(CliError::arg(
                "--margin",
                format!(
                    "{} mm leaves no usable area on the {} x {} mm bed of '{}'; it must be under {} mm (half the bed's shorter side)",
                    o.margin,
                    m.bed.width,
                    m.bed.height,
                    m.name,
                    short / 2.0
                ),
            ));
        }
        Ok(o)
    }
}

/// The text of a machine profile file (`--machine FILE.toml`), for `Machine::load`: at most
/// 1 MiB of UTF-8, noted as an input of the run.
pub fn profile_text(path: &std::path::Path) -> Result<String, String> {
    let bytes = crate::io::read::read_limited(path, machine::MAX_PROFILE_BYTES, "a machine profile").map_err(|e| e.to_string())?;
    String::from_utf8(bytes).map_err(|_| "it is not UTF-8 text".to_string())
}
