//! Flag groups several commands share, each written once and flattened where it is used:
//! the power law (`--c`, `--dimension`, `--n-offset`), the stop conditions (`--count`,
//! `--fill`, `--min-size`), both inside the run of a fill with `--gap`, `--max-trials` and
//! `--seed`; `--seed` alone; and the output (`-o`, `--format`).
//!
//! The help texts are the 2D fill's; a command whose pieces are other (the segments of
//! `line`) or whose numbers differ rewords them with `mut_arg` where it flattens the group.

use crate::args::spec;
use std::path::PathBuf;

/// The largest `--count` of a 2D fill (52 bytes a shape in the core).
pub const MAX_SHAPES: u64 = 20_000_000;

/// The default of `--max-trials`.
pub const DEFAULT_MAX_TRIALS: u64 = 10_000_000;

/// `--c`, `--dimension`, `--n-offset`: the power law of the pieces' sizes.
#[derive(Debug, Clone, clap::Args)]
pub struct PowerLawArgs {
    /// Power-law exponent c > 1 (default 1.3).
    #[arg(long, value_parser = spec::exponent, conflicts_with = "dimension", allow_hyphen_values = true)]
    pub c: Option<f64>,
    /// Fractal dimension D in (0, 2) instead of c (c = 2/D).
    #[arg(long, value_parser = spec::dimension, allow_hyphen_values = true)]
    pub dimension: Option<f64>,
    /// The paper's N > 0: larger N makes the first shapes smaller.
    #[arg(long = "n-offset", default_value_t = 1.0, value_parser = spec::n_offset, allow_hyphen_values = true)]
    pub n_offset: f64,
}

/// `--count`, `--fill`, `--min-size`: when a fill stops.
#[derive(Debug, Clone, clap::Args)]
pub struct StopArgs {
    /// Stop after K shapes (default 2000 when no stop condition is given).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=MAX_SHAPES), allow_hyphen_values = true)]
    pub count: Option<u64>,
    /// Stop once this fraction of the region is filled, 0 < F < 1.
    #[arg(long, value_parser = spec::fraction, allow_hyphen_values = true)]
    pub fill: Option<f64>,
    /// Stop before the first shape narrower than MM.
    #[arg(long = "min-size", value_parser = spec::length, allow_hyphen_values = true)]
    pub min_size: Option<f64>,
}

/// The power law, the stops, `--gap`, `--max-trials` and `--seed`: how a fill runs, the
/// same for shapes in 2D and segments in 1D.
#[derive(Debug, Clone, clap::Args)]
pub struct RunArgs {
    /// The power law.
    #[command(flatten)]
    pub power: PowerLawArgs,
    /// The stop conditions.
    #[command(flatten)]
    pub stop: StopArgs,
    /// Minimum clearance between shapes and to the boundary, in mm.
    #[arg(long, default_value_t = 0.0, value_parser = spec::length_or_zero, allow_hyphen_values = true)]
    pub gap: f64,
    /// Trial limit per placement; reaching it halts the fill (exit 3).
    #[arg(long = "max-trials", default_value_t = DEFAULT_MAX_TRIALS, value_parser = clap::value_parser!(u64).range(1..), allow_hyphen_values = true)]
    pub max_trials: u64,
    /// The seed.
    #[command(flatten)]
    pub seed: SeedArgs,
}

/// `--seed`: the seed of the run's random numbers.
#[derive(Debug, Clone, clap::Args)]
pub struct SeedArgs {
    /// RNG seed.
    #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
    pub seed: u64,
}

/// `-o` and `--format`: where the output goes and in which of the command's formats `F`.
#[derive(Debug, Clone, clap::Args)]
pub struct OutputArgs<F: clap::ValueEnum + Clone + Send + Sync + 'static> {
    /// Output path; the format comes from the extension (.svg .png .json .csv .gcode/.nc);
    /// '-' is stdout.
    #[arg(short = 'o', long)]
    pub output: PathBuf,
    /// Output format (overrides the extension).
    #[arg(long, value_enum)]
    pub format: Option<F>,
    /// The largest output written, in bytes (or with K, M, G, T: KiB, MiB, GiB, TiB); a
    /// larger one is refused before anything is written (exit 2).
    #[arg(long = "max-output-size", value_name = "BYTES", default_value = "4G", value_parser = byte_size, allow_hyphen_values = true)]
    pub max_output_size: u64,
}

/// Parses `--max-output-size`: a whole number of bytes, at least 1, optionally followed by
/// K, M, G or T (powers of 1024, also written KiB, MiB, GiB, TiB).
pub fn byte_size(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let split = t.find(|c: char| !c.is_ascii_digit()).unwrap_or(t.len());
    let (digits, unit) = t.split_at(split);
    let shift = match unit.strip_suffix("iB").unwrap_or(unit) {
        "" if unit.is_empty() => 0,
        "K" | "k" => 10,
        "M" => 20,
        "G" => 30,
        "T" => 40,
        _ => {
            return Err(format!(
                "'{s}': give a number of bytes, optionally followed by K, M, G or T (KiB, MiB, GiB, TiB)"
            ))
        }
    };
    let n: u64 = digits.parse().map_err(|_| format!("'{s}' is not a number of bytes"))?;
    match n.checked_mul(1u64 << shift) {
        Some(0) => Err("the output limit must be at least 1 byte".into()),
        Some(v) => Ok(v),
        None => Err(format!("'{s}' is more bytes than can be counted")),
    }
}

#[cfg(test)]
mod tests {
    use super::byte_size;

    #[test]
    fn byte_sizes_parse_in_binary_units() {
        assert_eq!(byte_size("4G"), Ok(4 << 30));
        assert_eq!(byte_size("4GiB"), Ok(4 << 30));
        assert_eq!(byte_size("1000"), Ok(1000));
        assert_eq!(byte_size("3k"), Ok(3072));
        assert_eq!(byte_size("2T"), Ok(2 << 40));
        for bad in ["", "0", "G", "1.5G", "-1", "4GB", "4 G", "99999999999T"] {
            assert!(byte_size(bad).is_err(), "{bad}");
        }
    }
}
