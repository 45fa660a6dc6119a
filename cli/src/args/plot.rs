//! The plotter and laser flags (`--machine`, feeds, power, hatch, order, pages, layers), one
//! group flattened into every command that draws lines. The plan turns them into the plain
//! options of the writers ([`crate::output::gcode::GcodeOptions`],
//! [`crate::model::fill::BuildOptions`]).

use crate::args::spec;
use crate::model::Fit;
use crate::output::machine;
use crate::output::order::PathOrder;
use clap::{Args, ValueEnum};

/// `--order`: path order before writing G-code.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OrderArg {
    /// Placement order, as the shapes were placed.
    None,
    /// Greedy nearest neighbour (with reversal and closed-path start choice).
    Greedy,
    /// Greedy, then 2-opt improvement.
    Improved,
}

impl OrderArg {
    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            OrderArg::None => "none",
            OrderArg::Greedy => "greedy",
            OrderArg::Improved => "improved",
        }
    }
}

impl From<OrderArg> for PathOrder {
    fn from(o: OrderArg) -> PathOrder {
        match o {
            OrderArg::None => PathOrder::None,
            OrderArg::Greedy => PathOrder::Greedy,
            OrderArg::Improved => PathOrder::Improved,
        }
    }
}

/// A page for plotter SVG.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Page {
    /// Width in mm.
    pub width: f64,
    /// Height in mm.
    pub height: f64,
}

/// Parses `--page`: `a4`, `a3`, `letter` (portrait; add `-landscape`), or `WxH` in mm.
pub fn parse_page(s: &str) -> Result<Page, String> {
    let lower = s.to_ascii_lowercase();
    let (name, landscape) = match lower.strip_suffix("-landscape") {
        Some(n) => (n, true),
        None => (lower.as_str(), false),
    };
    let (w, h) = match name {
        "a4" => (210.0, 297.0),
        "a3" => (297.0, 420.0),
        "a5" => (148.0, 210.0),
        "letter" => (215.9, 279.4),
        other => {
            let (a, b) = other
                .split_once('x')
                .ok_or_else(|| format!("'{s}' is not a4, a3, a5, letter or WxH in mm (for example 300x200)"))?;
            let num = |t: &str| {
                t.trim_end_matches("mm")
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite() && *v > 0.0 && *v <= 100_000.0)
            };
            match (num(a), num(b)) {
                (Some(w), Some(h)) => (w, h),
                _ => {
                    return Err(format!(
                        "'{s}': page width and height must be positive numbers of mm, as in 300x200"
                    ))
                }
            }
        }
    };
    Ok(if landscape {
        Page { width: h, height: w }
    } else {
        Page { width: w, height: h }
    })
}

/// `--layers`: none, `size-bands:K` or `colours`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layers {
    /// One group.
    None,
    /// K Inkscape layers by shape size, largest first.
    SizeBands(u32),
    /// One Inkscape layer per `--palette` colour (one pen each), in the palette's order.
    Colours,
}

/// Parses `--layers`.
pub fn parse_layers(s: &str) -> Result<Layers, String> {
    if s == "none" {
        return Ok(Layers::None);
    }
    if s == "colours" || s == "colors" {
        return Ok(Layers::Colours);
    }
    match s.strip_prefix("size-bands:").map(str::parse::<u32>) {
        Some(Ok(k)) if (1..=64).contains(&k) => Ok(Layers::SizeBands(k)),
        _ => Err(format!("'{s}' is not none, size-bands:K with K from 1 to 64, or colours")),
    }
}

/// A positive number (`--chord-tolerance`).
pub fn positive(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("'{s}' must be a positive number")),
    }
}

/// A finite number (feeds and power).
pub fn finite(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("'{s}' must be a finite number")),
    }
}

/// The plotter and laser flags of `zetafill fill` (and of any mode that draws lines).
#[derive(Debug, Clone, Args)]
pub struct PlotArgs {
    /// G-code: machine profile, a built-in name (see `zetafill machines`) or a FILE.toml
    /// [default: grbl-servo-pen].
    #[arg(long, help_heading = "Plotters and lasers")]
    pub machine: Option<String>,
    /// G-code: drawing feed in mm/min (default: the profile's).
    #[arg(long, value_parser = finite, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub feed: Option<f64>,
    /// G-code: travel feed in mm/min (G1 travel, and the time estimate of G0 travel).
    #[arg(long = "travel-feed", value_parser = finite, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub travel_feed: Option<f64>,
    /// G-code: laser power (S value) within the profile's range.
    #[arg(long, value_parser = finite, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub power: Option<f64>,
    /// G-code: draw everything this many times (laser cutting) [default: 1].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100), help_heading = "Plotters and lasers", allow_hyphen_values = true)]
    pub passes: Option<u32>,
    /// G-code: circles as G2/G3 arcs (default: if the profile allows them).
    #[arg(long, conflicts_with = "no_arcs", help_heading = "Plotters and lasers")]
    pub arcs: bool,
    /// G-code: circles as polylines within --chord-tolerance.
    #[arg(long = "no-arcs", help_heading = "Plotters and lasers")]
    pub no_arcs: bool,
    /// G-code: largest distance between a circle and the chords that replace it (mm)
    /// [default: 0.01].
    #[arg(long = "chord-tolerance", value_parser = positive, help_heading = "Plotters and lasers", allow_hyphen_values = true)]
    pub chord_tolerance: Option<f64>,
    /// Hatch every shape: SPACING or SPACING:ANGLE, in mm and degrees (default angle 45).
    #[arg(long, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub hatch: Option<String>,
    /// With --hatch: hatch lines only, no outlines.
    #[arg(long = "hatch-only", requires = "hatch", help_heading = "Plotters and lasers")]
    pub hatch_only: bool,
    /// With --hatch: cross-hatch, a second family of lines at right angles to the first.
    #[arg(long = "cross-hatch", requires = "hatch", help_heading = "Plotters and lasers")]
    pub cross_hatch: bool,
    /// G-code: path order [default: improved].
    #[arg(long, value_enum, help_heading = "Plotters and lasers")]
    pub order: Option<OrderArg>,
    /// Leave out shapes (and ring holes) narrower than MM: the pen's or beam's width.
    #[arg(long = "min-feature", default_value_t = 0.0, value_parser = spec::length_or_zero, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub min_feature: f64,
    /// Scale the drawing to fill the bed (G-code) or the page (SVG) less margins, centred.
    #[arg(long, help_heading = "Plotters and lasers")]
    pub fit: bool,
    /// Centre the drawing on the bed (G-code) or the page (SVG).
    #[arg(long, help_heading = "Plotters and lasers")]
    pub center: bool,
    /// SVG: page a4 | a3 | a5 | letter (portrait; add -landscape) | WxH in mm.
    #[arg(long, value_parser = parse_page, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub page: Option<Page>,
    /// Margin in mm: SVG pages (default 10), G-code bed (default 0).
    #[arg(long, value_parser = spec::length_or_zero, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub margin: Option<f64>,
    /// SVG: none | size-bands:K (K Inkscape layers by shape size, largest first) | colours
    /// (one layer per --palette colour, a pen each).
    #[arg(long, default_value = "none", value_parser = parse_layers, help_heading = "Plotters and lasers")]
    pub layers: Layers,
}

/// The machine profile used when `--machine` is not given.
pub const DEFAULT_MACHINE: &str = "grbl-servo-pen";

/// The plot flags that only G-code output reads.
pub const GCODE_FLAGS: [&str; 9] = [
    "--machine",
    "--feed",
    "--travel-feed",
    "--power",
    "--passes",
    "--arcs",
    "--no-arcs",
    "--chord-tolerance",
    "--order",
];

/// The plot flags that a fill's SVG (and PNG) reads.
pub const SVG_FLAGS: [&str; 9] = [
    "--hatch",
    "--hatch-only",
    "--cross-hatch",
    "--min-feature",
    "--page",
    "--margin",
    "--layers",
    "--fit",
    "--center",
];

impl PlotArgs {
    /// The plot flags given on the command line, in the order of `--help`. (`--min-feature 0`
    /// and `--layers none` change nothing and do not count.)
    pub fn given(&self) -> Vec<&'static str> {
        let flags = [
            ("--machine", self.machine.is_some()),
            ("--feed", self.feed.is_some()),
            ("--travel-feed", self.travel_feed.is_some()),
            ("--power", self.power.is_some()),
            ("--passes", self.passes.is_some()),
            ("--arcs", self.arcs),
            ("--no-arcs", self.no_arcs),
            ("--chord-tolerance", self.chord_tolerance.is_some()),
            ("--hatch", self.hatch.is_some()),
            ("--hatch-only", self.hatch_only),
            ("--cross-hatch", self.cross_hatch),
            ("--order", self.order.is_some()),
            ("--min-feature", self.min_feature > 0.0),
            ("--fit", self.fit),
            ("--center", self.center),
            ("--page", self.page.is_some()),
            ("--margin", self.margin.is_some()),
            ("--layers", self.layers != Layers::None),
        ];
        flags.into_iter().filter(|&(_, on)| on).map(|(f, _)| f).collect()
    }

    /// How the drawing is placed: as it is, centred, or scaled (`default` without `--fit` or
    /// `--center`).
    pub fn fit(&self, default: Fit) -> Fit {
        if self.fit {
            Fit::Scale
        } else if self.center {
            Fit::Center
        } else {
            default
        }
    }

    /// The flags of this group that were given, as command-line text (each with a leading
    /// space), so that a file's header can say how to make it again.
    pub fn flags(&self) -> String {
        let text = |v: f64| Some(v.to_string());
        let order = self.order.map(|o| o.name().to_string());
        let layers = match self.layers {
            Layers::SizeBands(k) => Some(format!("size-bands:{k}")),
            Layers::Colours => Some("colours".to_string()),
            Layers::None => None,
        };
        // (flag, given, value)
        let all: [(&str, bool, Option<String>); 18] = [
            ("machine", self.machine.is_some(), self.machine.clone()),
            ("feed", self.feed.is_some(), self.feed.and_then(text)),
            ("travel-feed", self.travel_feed.is_some(), self.travel_feed.and_then(text)),
            ("power", self.power.is_some(), self.power.and_then(text)),
            ("passes", self.passes.is_some(), self.passes.map(|p| p.to_string())),
            ("arcs", self.arcs, None),
            ("no-arcs", self.no_arcs, None),
            (
                "chord-tolerance",
                self.chord_tolerance.is_some(),
                self.chord_tolerance.and_then(text),
            ),
            ("hatch", self.hatch.is_some(), self.hatch.clone()),
            ("hatch-only", self.hatch_only, None),
            ("cross-hatch", self.cross_hatch, None),
            ("order", order.is_some(), order),
            ("min-feature", self.min_feature > 0.0, text(self.min_feature)),
            ("fit", self.fit, None),
            ("center", self.center, None),
            ("page", self.page.is_some(), self.page.map(|p| format!("{}x{}", p.width, p.height))),
            ("margin", self.margin.is_some(), self.margin.and_then(text)),
            ("layers", layers.is_some(), layers),
        ];
        all.into_iter()
            .filter(|(_, given, _)| *given)
            .map(|(flag, _, value)| value.map_or_else(|| format!(" --{flag}"), |v| format!(" --{flag} {v}")))
            .collect()
    }

    /// The profile file `--machine` names, if it names one rather than a built-in: an
    /// input, which no output may overwrite.
    pub fn machine_file(&self) -> Option<&std::path::Path> {
        let m = self.machine.as_deref()?;
        machine::Machine::builtin_text(m).is_none().then(|| std::path::Path::new(m))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pages_and_layers_parse() {
        assert_eq!(
            parse_page("a4"),
            Ok(Page {
                width: 210.0,
                height: 297.0
            })
        );
        assert_eq!(
            parse_page("A4-landscape"),
            Ok(Page {
                width: 297.0,
                height: 210.0
            })
        );
        assert_eq!(
            parse_page("300x200"),
            Ok(Page {
                width: 300.0,
                height: 200.0
            })
        );
        assert!(parse_page("0x5").is_err());
        assert!(parse_page("b5").is_err());
        assert_eq!(parse_layers("size-bands:3"), Ok(Layers::SizeBands(3)));
        assert!(parse_layers("size-bands:0").is_err());
        assert_eq!(parse_layers("colours"), Ok(Layers::Colours));
        assert_eq!(parse_layers("colors"), Ok(Layers::Colours));
    }
}
