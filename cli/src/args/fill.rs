//! The flags of `zetafill fill`: the shape, region, power law, stops, sampler and output, with
//! the plotter, colour and raster groups flattened in.

use crate::args::colour::ColourArgs;
use crate::args::common::{OutputArgs, RunArgs};
use crate::args::format::FormatArg;
use crate::args::plot::PlotArgs;
use crate::args::raster::{RasterArgs, ReliefArg};
use crate::args::spec;
use crate::args::style::StyleArg;
use crate::model::region::RegionSpec;
use clap::{Args, ValueEnum};

pub use crate::args::common::{DEFAULT_MAX_TRIALS, MAX_SHAPES};

/// Rotation of non-circular shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Rotate {
    /// Axis-aligned.
    None,
    /// A uniformly random angle per trial.
    Random,
}

/// How the shapes of a mix are taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MixArg {
    /// In turn: placement i gets shape i mod count (the paper's Figure 7).
    Cycle,
    /// A random choice per placement (fixed by the seed).
    Random,
}

/// The candidate sampler.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Sampler {
    /// Candidates only where the next shape could fit (cells with clearance bounds): the same
    /// distribution of placements as `reference`, far fewer trials.
    Fast,
    /// The paper's: uniform candidates over the region, retried until one fits.
    Reference,
    /// The cells' candidates screened in batches, many in flight and on every thread: the
    /// same distribution of placements, the same fill for any number of threads (2D only).
    Batched,
}

impl MixArg {
    /// The name written to JSON and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            MixArg::Cycle => "cycle",
            MixArg::Random => "random",
        }
    }
}

impl Sampler {
    /// The name written to JSON.
    pub fn name(self) -> &'static str {
        match self {
            Sampler::Fast => "fast",
            Sampler::Reference => "reference",
            Sampler::Batched => "batched",
        }
    }
}

/// The number type the engine computes in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ScalarArg {
    /// IEEE double precision through libm (the default).
    F64,
    /// 32.32 fixed point, as on a microcontroller without an FPU (different shapes, equally
    /// deterministic; `--format digest` then matches the firmware's fixed-point runs).
    Fixed,
}

impl ScalarArg {
    /// The name in JSON.
    pub fn name(self) -> &'static str {
        match self {
            ScalarArg::F64 => "f64",
            ScalarArg::Fixed => "fixed",
        }
    }
}

/// The flags that only `--region mask:` and `--region text:` read.
#[derive(Debug, Args, Default)]
pub struct RegionInputArgs {
    /// mask: the width in mm the picture's width becomes (square pixels; default 200).
    #[arg(long = "region-width", value_parser = spec::length, allow_hyphen_values = true)]
    pub region_width: Option<f64>,
    /// mask: the SHA-256 the picture must have (the command a file carries gives it, so a
    /// changed picture is refused instead of filling differently).
    #[arg(long = "region-sha256")]
    pub region_sha256: Option<String>,
    /// text: a TrueType or OpenType font file (default: the built-in DejaVu Sans Bold).
    #[arg(long)]
    pub font: Option<std::path::PathBuf>,
    /// text: the SHA-256 the --font file must have.
    #[arg(long = "font-sha256")]
    pub font_sha256: Option<String>,
    /// text: the size of the font's em in mm (default 50: capitals about 36 mm tall).
    #[arg(long = "text-size", value_parser = spec::length, allow_hyphen_values = true)]
    pub text_size: Option<f64>,
    /// text: space added after every character, in mm (default 0), to part letters that
    /// touch.
    #[arg(long = "letter-spacing", value_parser = spec::length_or_zero, allow_hyphen_values = true)]
    pub letter_spacing: Option<f64>,
}

/// Arguments of `zetafill fill`.
#[derive(Debug, Args)]
pub struct FillArgs {
    /// circle | square | rect:ASPECT | triangle | polygon:SIDES | star:POINTS:INNER_RATIO |
    /// ring:INNER_RATIO | blob:DELTA | noisy:AMPLITUDE (then optionally :FEATURES and :OCTAVES)
    /// | svg:FILE (the filled outline of an SVG) | glyph:TEXT (each character of TEXT, from
    /// --font or the built-in font) | mix:SHAPE,SHAPE,...
    #[arg(long, default_value = "circle", value_parser = spec::shape)]
    pub shape: spec::ShapeArg,
    /// Mixes: take the shapes in turn (cycle) or at random per placement.
    #[arg(long = "mix-order", value_enum, default_value = "cycle")]
    pub mix_order: MixArg,
    /// Rotation: none or random (default: random for non-circles).
    #[arg(long, value_enum)]
    pub rotate: Option<Rotate>,
    /// rect:W:H | circle:R | annulus:R_OUTER:R_INNER | polygon:X1,Y1,X2,Y2,...[/X1,Y1,...] (rings,
    /// even-odd) | svg:FILE (mm) | mask:FILE or mask:FILE:THRESHOLD (the dark areas of a PNG
    /// or JPEG, luminance below THRESHOLD, default 0.5) | text:STRING (letters; \n starts a line)
    /// [default: rect:200:200]. With --symmetry: the region the pattern is cut to.
    #[arg(long, value_parser = spec::fill_region)]
    pub region: Option<RegionSpec>,
    /// The flags of mask: and text: regions.
    #[command(flatten)]
    pub input: RegionInputArgs,
    /// Periodic (toroidal) boundary: the fill tiles seamlessly (rect regions only).
    #[arg(long)]
    pub periodic: bool,
    /// The symmetry of a wallpaper group.
    #[command(flatten)]
    pub symmetry: super::symmetry::SymmetryArgs,
    /// The power law, stops, clearance, trial limit and seed.
    #[command(flatten)]
    pub run: RunArgs,
    /// Candidate sampler: fast (cells where the next shape could fit) or reference (the
    /// paper's uniform search); both give the same distribution of placements.
    #[arg(long, value_enum, default_value = "fast")]
    pub sampler: Sampler,
    /// Cell sampler: the cells lent to it (at least 64). By default as many as it can ever use,
    /// so the fill depends on nothing but the parameters; fewer, as on a board (the firmware
    /// lends 512), and the sampler stops refining when they run out: still exact, but another
    /// fill. Give the board's number to place its shapes.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    pub cells: Option<u64>,
    /// Batched sampler: the threads that screen each batch's candidates (default: one per
    /// core). The fill is the same for any number.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=1024))]
    pub threads: Option<u64>,
    /// Batched sampler: the most placements a batch holds (1 to 4096, default 64). The fill
    /// depends on it; the firmware's batched scene uses 4.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=4096))]
    pub batch: Option<u64>,
    /// Where centres are wanted: noise:KIND:SCALE, optionally then :OCTAVES:GAIN:CONTRAST
    /// (KIND value or gradient; a noise field of lattice spacing SCALE mm seeded by --seed,
    /// tileable with --periodic; density 0.5 + CONTRAST (noise - 0.5), clamped to 0..1;
    /// defaults 4 octaves, gain 0.5, contrast 2), or image:FILE, optionally followed by any of
    /// ,invert ,gamma=G ,floor=F (a PNG or JPEG over the region's bounding box, dark means
    /// dense: F + (1 - F) t^G with t the darkness). Each shape is placed with probability proportional to the density over
    /// the centres where it fits.
    #[arg(long, value_parser = spec::density)]
    pub density: Option<crate::model::density::DensitySpec>,
    /// The SHA-256 the --density picture must have (the command a file carries gives it, so
    /// a changed picture is refused instead of filling differently).
    #[arg(long = "density-sha256")]
    pub density_sha256: Option<String>,
    /// Number type of the engine: f64 or fixed (32.32 fixed point).
    #[arg(long, value_enum, default_value = "f64")]
    pub scalar: ScalarArg,
    /// Where the output goes.
    #[command(flatten)]
    pub output: OutputArgs<FormatArg>,
    /// SVG: outline (plotters) or filled.
    #[arg(long, value_enum, default_value = "outline")]
    pub style: StyleArg,
    /// SVG: stroke width in mm.
    #[arg(long = "pen-width", default_value_t = 0.3, value_parser = spec::length, allow_hyphen_values = true)]
    pub pen_width: f64,
    /// SVG: also draw the region's outline.
    #[arg(long)]
    pub boundary: bool,
    /// PNG size.
    #[command(flatten)]
    pub raster: RasterArgs,
    /// PNG: write a 16-bit height map (each shape a raised stone of this profile) instead
    /// of a picture.
    #[arg(long, value_enum)]
    pub relief: Option<ReliefArg>,
    /// Colours (SVG/PNG).
    #[command(flatten)]
    pub colour: ColourArgs,
    /// SVG/PNG: draw the Voronoi cells of the shapes' centres ("cobblestones") instead of the
    /// shapes; with --periodic the cells tile seamlessly.
    #[arg(long)]
    pub voronoi: bool,
    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
    /// Plotter and laser output: G-code machine, path order, hatch, pages, layers.
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The region of a fill without `--region`: the 200 mm square.
pub const DEFAULT_REGION: RegionSpec = RegionSpec::Rect {
    width: 200.0,
    height: 200.0,
};

impl FillArgs {
    /// The region to fill: `--region`, or the 200 mm square.
    pub fn region(&self) -> RegionSpec {
        self.region.clone().unwrap_or(DEFAULT_REGION)
    }
}
