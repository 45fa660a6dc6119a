//! PNG preview: the SVG of the same run rendered by resvg (so the preview shows exactly the
//! drawing), on a white background, at `dpi` pixels per inch or with its longer side
//! `pixels` long.

use crate::error::CliError;

/// The refusal of a flag that only a PNG output reads.
pub fn only_png(flag: &str) -> CliError {
    CliError::arg(flag, "is for PNG output: write .png (or --format png), or drop it")
}

/// The size of a PNG: pixels per inch, or the longer side in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Raster {
    /// Resolution in pixels per inch.
    pub dpi: f64,
    /// The image's longer side in pixels (instead of `dpi`).
    pub pixels: Option<u32>,
}

impl Raster {
    /// Renders SVG bytes to PNG at this size.
    pub fn render(&self, svg: &[u8]) -> Result<Vec<u8>, CliError> {
        render(svg, self.dpi, self.pixels)
    }

    /// The flag as written on a command line.
    pub fn flag(&self) -> String {
        self.pixels
            .map_or_else(|| format!(" --dpi {}", self.dpi), |n| format!(" --pixels {n}"))
    }
}

/// Renders SVG bytes to PNG bytes at `dpi`, or with the longer side `pixels` long.
pub fn render(svg: &[u8], dpi: f64, pixels: Option<u32>) -> Result<Vec<u8>, CliError> {
    let opt = resvg::usvg::Options::default();
    let tree = resvg::usvg::Tree::from_data(svg, &opt).map_err(|e| CliError::Io(format!("internal: cannot read own SVG: {e}")))?;
    // usvg sizes mm at 96 px per inch.
    let size = tree.size();
    let (scale, w, h, flag) = match pixels {
        Some(n) => {
            let scale = n as f32 / size.width().max(size.height());
            let side = |v: f32| (v * scale).round().max(1.0) as u32;
            (scale, side(size.width()), side(size.height()), "--pixels")
        }
        None => {
            let scale = (dpi / 96.0) as f32;
            (
                scale,
                (size.width() * scale).ceil() as u32,
                (size.height() * scale).ceil() as u32,
                "--dpi",
            )
        }
    };
    let too_big = || CliError::arg(flag, format!("a {w} x {h} pixel image is too large; lower {flag}"));
    if u64::from(w) * u64::from(h) > 400_000_000 {
        return Err(too_big());
    }
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w.max(1), h.max(1)).ok_or_else(too_big)?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(&tree, resvg::tiny_skia::Transform::from_scale(scale, scale), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| CliError::Io(format!("cannot encode PNG: {e}")))
}
