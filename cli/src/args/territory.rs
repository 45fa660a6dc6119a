//! The flags of `zetafill territory`: the sites, the region, the growth, the colours and the
//! drawing, with the plotter, colour and raster groups flattened in.

use crate::args::colour::ColourArgs;
use crate::args::common::{OutputArgs, SeedArgs};
use crate::args::plot::PlotArgs;
use crate::args::raster::RasterArgs;
use crate::args::spec;
use crate::geometry::voronoi::Pt;
use crate::model::region::RegionSpec;
use clap::{Args, ValueEnum};
use std::path::PathBuf;

/// Largest number of sites one run may hold.
pub const MAX_POINTS: usize = 10_000_000;

/// `--render`: what to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RenderArg {
    /// Territory boundaries as merged polylines (plotters).
    Boundaries,
    /// All Voronoi edges: cells thin, boundaries at pen width (two layers).
    Cells,
    /// Cells filled with their HSB colours (screens, prints).
    Filled,
    /// The fill's own shapes filled with their site's colour (only with --sites-from).
    Shapes,
}

/// Output formats of `zetafill territory`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TerritoryFormatArg {
    /// SVG drawing in mm.
    Svg,
    /// PNG preview (the SVG rendered).
    Png,
    /// JSON document (version 1, mode "territory").
    Json,
    /// G-code for a plotter or laser (the boundaries, or every edge with --render cells).
    Gcode,
}

/// Arguments of `zetafill territory`. Territory drawings have no pages, size layers or
/// hatching: those flags are refused, and left out of the help.
#[derive(Debug, Args)]
#[command(
    mut_arg("output", |a| a.help("Output path; the format comes from the extension (.svg .png .json); '-' is stdout")),
    mut_arg("page", |a| a.hide(true)),
    mut_arg("layers", |a| a.hide(true)),
    mut_arg("hatch", |a| a.hide(true)),
    mut_arg("hatch_only", |a| a.hide(true)),
    mut_arg("cross_hatch", |a| a.hide(true)),
    mut_arg("min_feature", |a| a.hide(true)),
)]
pub struct TerritoryArgs {
    /// K random seed sites (territories 0..K-1), K >= 2 (default 3); with --sites-from, K of
    /// the fill's centres chosen at random.
    #[arg(long, value_parser = seed_count, conflicts_with = "site", allow_hyphen_values = true)]
    pub sites: Option<usize>,
    /// A seed site X,Y in mm (repeat for each; at least two). With --sites-from, the fill's
    /// centre nearest to X,Y.
    #[arg(long = "site", value_parser = point, allow_hyphen_values = true)]
    pub site: Vec<Pt>,
    /// Take the sites from a fill's JSON (`zetafill fill -o fill.json`): its shapes' centres,
    /// inserted in fill order after the seeds; the region is the fill's.
    #[arg(long = "sites-from", conflicts_with_all = ["points", "region"])]
    pub sites_from: Option<PathBuf>,
    /// Total number of sites, seeds included (the paper's pictures use about 7,000).
    #[arg(long, value_parser = clap::value_parser!(u64).range(2..=MAX_POINTS as u64), allow_hyphen_values = true)]
    pub points: Option<u64>,
    /// rect:W:H | circle:R | annulus:R_OUTER:R_INNER | polygon:X1,Y1,X2,Y2,...[/X1,Y1,...] (rings,
    /// even-odd) | svg:FILE (mm).
    #[arg(long, default_value = "rect:200:200", value_parser = spec::region)]
    pub region: RegionSpec,
    /// The seed.
    #[command(flatten)]
    pub seed: SeedArgs,
    /// boundaries (plotters) | cells | filled | shapes (with --sites-from).
    #[arg(long, value_enum, default_value = "boundaries")]
    pub render: RenderArg,
    /// No density control: every new point uniform over the region.
    #[arg(long)]
    pub uniform: bool,
    /// Density control starts at the n0-th point (the paper's n0).
    #[arg(long, default_value_t = 1000, value_parser = clap::value_parser!(u64).range(1..), allow_hyphen_values = true)]
    pub n0: u64,
    /// The paper's s: floor(log2(s i)) x floor(log2(s i)) buckets for the i-th point.
    #[arg(long, default_value_t = 0.1, value_parser = bucket_scale, allow_hyphen_values = true)]
    pub s: f64,
    /// How much more likely a new point lands in a boundary bucket than in another (>= 1).
    #[arg(long, default_value_t = 8.0, value_parser = boost, allow_hyphen_values = true)]
    pub boost: f64,
    /// Colour of territory 0, 1, ... in turn: H,S,B (the seed's colour c^k, each in [0, 1])
    /// or H,S,B:DH,DS,DB (with the step d^k per unit of distance). Territories without one
    /// get random colours from the seed.
    #[arg(long = "color", value_parser = colour_rule, allow_hyphen_values = true)]
    pub colors: Vec<([f64; 3], Option<[f64; 3]>)>,
    /// Where the output goes.
    #[command(flatten)]
    pub output: OutputArgs<TerritoryFormatArg>,
    /// SVG: stroke width of the boundaries in mm.
    #[arg(long = "pen-width", default_value_t = 0.3, value_parser = spec::length, allow_hyphen_values = true)]
    pub pen_width: f64,
    /// SVG: stroke width of the thin cell edges in mm.
    #[arg(long = "thin-width", default_value_t = 0.1, value_parser = spec::length, allow_hyphen_values = true)]
    pub thin_width: f64,
    /// SVG: also draw the region's outline.
    #[arg(long)]
    pub boundary: bool,
    /// PNG size.
    #[command(flatten)]
    pub raster: RasterArgs,
    /// No progress bar (and no G-code figures on stderr).
    #[arg(short, long)]
    pub quiet: bool,
    /// Palette colours instead of the --color rules (filled cells or shapes; default
    /// --color-by cycle: territory k takes colour k).
    #[command(flatten)]
    pub colours: ColourArgs,
    /// Plotter and laser output (G-code): machine, feeds, passes, order, --fit/--center.
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// `--sites`: a whole number of seeds from 2 to [`MAX_POINTS`].
pub fn seed_count(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(k) if (2..=MAX_POINTS).contains(&k) => Ok(k),
        Ok(k) if k < 2 => Err(format!("territory competing needs at least 2 seeds (got {k})")),
        _ => Err(format!("'{s}' is not a whole number from 2 to {MAX_POINTS}")),
    }
}

/// `--site`: a point X,Y in mm.
pub fn point(s: &str) -> Result<Pt, String> {
    let v: Vec<&str> = s.split(',').collect();
    if v.len() != 2 {
        return Err(format!("write X,Y in mm, for example 50,120 (got '{s}')"));
    }
    Ok([spec::finite(v[0])?, spec::finite(v[1])?])
}

/// `--s`: the bucket scale, > 0 and at most a million (beyond, every point has its own
/// bucket row long before the run ends).
pub fn bucket_scale(s: &str) -> Result<f64, String> {
    let v = spec::positive(s)?;
    if v <= 1e6 {
        Ok(v)
    } else {
        Err(format!("must be at most 1000000 (got {s}); the paper uses 0.1"))
    }
}

/// `--boost`: a weight of 1 or more (at most a million).
pub fn boost(s: &str) -> Result<f64, String> {
    let v = spec::finite(s)?;
    if (1.0..=1e6).contains(&v) {
        Ok(v)
    } else if v > 1e6 {
        Err(format!("must be at most 1000000 (got {s})"))
    } else {
        Err(format!(
            "must be 1 or more (got {s}); 1 means no preference, like --uniform after n0"
        ))
    }
}

/// `--color`: a colour rule `H,S,B` or `H,S,B:DH,DS,DB`; without the step, `None` for d
/// (drawn at random).
pub fn colour_rule(s: &str) -> Result<(/* c */ [f64; 3], Option<[f64; 3]>), String> {
    let triple = |part: &str, what: &str| -> Result<[f64; 3], String> {
        let v: Vec<&str> = part.split(',').collect();
        if v.len() != 3 {
            return Err(format!(
                "{what} needs three comma-separated numbers (got '{part}'); write H,S,B or H,S,B:DH,DS,DB"
            ));
        }
        let mut out = [0.0; 3];
        for (o, x) in out.iter_mut().zip(&v) {
            let n: f64 = x.trim().parse().map_err(|_| format!("{what}: '{x}' is not a number"))?;
            if !n.is_finite() {
                return Err(format!("{what}: '{x}' is not a finite number"));
            }
            *o = n;
        }
        Ok(out)
    };
    let mut parts = s.split(':');
    let c = triple(parts.next().unwrap_or(""), "the seed colour H,S,B")?;
    if let Some(bad) = c.iter().find(|v| !(0.0..=1.0).contains(*v)) {
        return Err(format!("the seed colour H,S,B must lie in [0, 1] each (got {bad})"));
    }
    let d = match parts.next() {
        Some(p) => Some(triple(p, "the step DH,DS,DB")?),
        None => None,
    };
    if parts.next().is_some() {
        return Err(format!("'{s}' has more than one ':'; write H,S,B or H,S,B:DH,DS,DB"));
    }
    Ok((c, d))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_parse_or_say_why() {
        assert_eq!(colour_rule("0.1,0.2,0.3"), Ok(([0.1, 0.2, 0.3], None)));
        assert_eq!(colour_rule("0,1,1:-0.01,0,0.02"), Ok(([0.0, 1.0, 1.0], Some([-0.01, 0.0, 0.02]))));
        assert!(colour_rule("0.1,0.2").is_err());
        assert!(colour_rule("0.1,0.2,1.5").is_err());
        assert!(colour_rule("0.1,x,0.3").is_err());
        assert!(colour_rule("0.1,0.2,0.3:1,2").is_err());
        assert!(colour_rule("0.1,0.2,0.3:1,2,nan").is_err());
        assert!(colour_rule("0.1,0.2,0.3:1,2,3:4").is_err());
    }
}
