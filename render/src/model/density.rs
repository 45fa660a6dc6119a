//! A fill's density (`--density`): where shape centres are wanted, as the plan and the
//! commands carry it (the flag's parser is in `args::spec`).

use zetafill::NoiseKind;

/// `--density`: where shape centres are wanted.
#[derive(Debug, Clone, PartialEq)]
pub enum DensitySpec {
    /// `image:FILE[,invert][,gamma=G][,floor=F]`: a PNG or JPEG over the region's bounding box,
    /// `rho = F + (1 - F) t^G` with `t` the darkness (one minus the luminance; the luminance
    /// with `invert`), bilinear between pixel centres.
    Image {
        /// The picture.
        path: std::path::PathBuf,
        /// Light means dense instead of dark.
        invert: bool,
        /// The exponent on the darkness (> 0).
        gamma: f64,
        /// The least density, in `[0, 1)`.
        floor: f64,
    },
    /// `noise:KIND:SCALE[:OCTAVES[:GAIN[:CONTRAST]]]`: value or gradient noise of lattice
    /// spacing SCALE mm, seeded by the fill's seed, as `rho = 0.5 + CONTRAST (noise - 0.5)`
    /// clamped to `[0, 1]`.
    Noise {
        /// Value or gradient noise.
        kind: NoiseKind,
        /// The first octave's lattice spacing (mm).
        scale: f64,
        /// Octaves (1 to 16).
        octaves: u32,
        /// Each octave's weight over the last's, in (0, 1].
        gain: f64,
        /// How far the density swings from one half (> 0).
        contrast: f64,
    },
}

impl DensitySpec {
    /// The spec written in full (the form the JSON and the reproducing command carry).
    pub fn name(&self) -> String {
        match *self {
            DensitySpec::Image {
                ref path,
                invert,
                gamma,
                floor,
            } => format!(
                "image:{}{},gamma={gamma},floor={floor}",
                path.display(),
                if invert { ",invert" } else { "" }
            ),
            DensitySpec::Noise {
                kind,
                scale,
                octaves,
                gain,
                contrast,
            } => {
                let kind = match kind {
                    NoiseKind::Value => "value",
                    NoiseKind::Gradient => "gradient",
                };
                format!("noise:{kind}:{scale}:{octaves}:{gain}:{contrast}")
            }
        }
    }
}
