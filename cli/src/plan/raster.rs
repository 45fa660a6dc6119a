//! The PNG flags (`--dpi`, `--pixels`, `--relief`): the refusal of one where the output is
//! not a PNG, and the wording of a raster too large to make, which the writers of
//! [`crate::output`] report as plain values once the run knows the drawing's size.

use crate::args::raster::RasterArgs;
use crate::error::CliError;
use crate::output::height::{self, MAX_PIXELS};
use crate::output::png::PngError;

/// The refusal of a flag that only a PNG output reads.
pub fn only_png(flag: &str) -> CliError {
    CliError::arg(flag, "is for PNG output: write .png (or --format png), or drop it")
}

/// Refuses `--pixels` when the output is not a PNG (`png` false).
pub fn check(r: &RasterArgs, png: bool) -> Result<(), CliError> {
    match r.pixels {
        Some(_) if !png => Err(only_png("--pixels")),
        _ => Ok(()),
    }
}

/// The flag that sized a raster: `--pixels` when given, else `--dpi`.
fn size_flag(pixels: bool) -> &'static str {
    if pixels {
        "--pixels"
    } else {
        "--dpi"
    }
}

/// A PNG that could not be made: too large (naming the flag that sized it), or a failure of
/// the renderer or the encoder.
pub fn png_error(e: PngError) -> CliError {
    match e {
        PngError::TooLarge { w, h, pixels } => {
            let flag = size_flag(pixels);
            CliError::arg(flag, format!("a {w} x {h} pixel image is too large; lower {flag}"))
        }
        PngError::Svg(e) => CliError::Io(format!("internal: cannot read own SVG: {e}")),
        PngError::Encode(e) => CliError::Io(format!("cannot encode PNG: {e}")),
    }
}

/// A height map too large to make, naming the flag that sized it.
pub fn height_map_error(e: height::TooLarge) -> CliError {
    let (nx, ny, flag) = (e.nx, e.ny, size_flag(e.pixels));
    CliError::arg(
        flag,
        format!("a {nx} x {ny} pixel height map is too large (at most {MAX_PIXELS} pixels); lower {flag}"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_raster_too_large_names_the_flag_that_sized_it() {
        let e = png_error(PngError::TooLarge { w: 3, h: 4, pixels: true });
        assert_eq!(e.to_string(), "--pixels: a 3 x 4 pixel image is too large; lower --pixels");
        assert_eq!(e.exit_code(), 2);
        let e = height_map_error(height::TooLarge {
            nx: 1e5,
            ny: 2e5,
            pixels: false,
        });
        assert_eq!(
            e.to_string(),
            "--dpi: a 100000 x 200000 pixel height map is too large (at most 64000000 pixels); lower --dpi"
        );
        assert_eq!(png_error(PngError::Encode("x".into())).exit_code(), 1);
    }
}
