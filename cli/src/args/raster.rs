//! The PNG flags: the size of a raster (`--dpi`, `--pixels`) and the height-map profile
//! (`--relief`).

use crate::output::height::Relief;
use crate::output::png::Raster;

/// `--dpi` / `--pixels`: the size of a PNG.
#[derive(Debug, Clone, clap::Args)]
pub struct RasterArgs {
    /// PNG: resolution in pixels per inch.
    #[arg(long, default_value_t = 96.0, value_parser = crate::args::spec::positive, allow_hyphen_values = true)]
    pub dpi: f64,
    /// PNG: the image's longer side in pixels (instead of --dpi).
    #[arg(long, conflicts_with = "dpi", value_parser = clap::value_parser!(u32).range(1..=100_000), allow_hyphen_values = true)]
    pub pixels: Option<u32>,
}

impl RasterArgs {
    /// The raster size these flags ask for.
    pub fn raster(&self) -> Raster {
        Raster {
            dpi: self.dpi,
            pixels: self.pixels,
        }
    }
}

/// `--relief`: the profile of every stone of a height map.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ReliefArg {
    /// A round top: a circle becomes a hemisphere.
    Dome,
    /// The height is the distance to the outline: a circle becomes a cone, a polygon a
    /// hipped roof.
    Cone,
    /// A flat top as high as the stone's deepest point is deep, with sheer sides.
    Flat,
}

impl From<ReliefArg> for Relief {
    fn from(r: ReliefArg) -> Relief {
        match r {
            ReliefArg::Dome => Relief::Dome,
            ReliefArg::Cone => Relief::Cone,
            ReliefArg::Flat => Relief::Flat,
        }
    }
}
