//! PNG preview: the SVG of the same run rendered by resvg (so the preview shows exactly the
//! drawing), on a white background, at `dpi` pixels per inch or with its longer side
//! `pixels` long.

/// Why a PNG cannot be made.
#[derive(Debug, Clone, PartialEq)]
pub enum PngError {
    /// The image would be `w` x `h` pixels, too large to render; `pixels` says its size was
    /// asked as the longer side in pixels, not as a resolution.
    TooLarge {
        /// Width in pixels.
        w: u32,
        /// Height in pixels.
        h: u32,
        /// The size was given in pixels (else in pixels per inch).
        pixels: bool,
    },
    /// The SVG to render could not be read (a fault of this program).
    Svg(String),
    /// The pixels could not be encoded as PNG.
    Encode(String),
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
    pub fn render(&self, svg: &[u8]) -> Result<Vec<u8>, PngError> {
        render(svg, self.dpi, self.pixels)
    }

    /// The flag as written on a command line.
    pub fn flag(&self) -> String {
        self.pixels
            .map_or_else(|| format!(" --dpi {}", self.dpi), |n| format!(" --pixels {n}"))
    }
}

/// Renders SVG bytes to PNG bytes at `dpi`, or with the longer side `pixels` long.
pub fn render(svg: &[u8], dpi: f64, pixels: Option<u32>) -> Result<Vec<u8>, PngError> {
    let opt = resvg::usvg::Options::default();
    let tree = resvg::usvg::Tree::from_data(svg, &opt).map_err(|e| PngError::Svg(e.to_string()))?;
    // usvg sizes mm at 96 px per inch.
    let size = tree.size();
    let (scale, w, h) = match pixels {
        Some(n) => {
            let scale = n as f32 / size.width().max(size.height());
            let side = |v: f32| (v * scale).round().max(1.0) as u32;
            (scale, side(size.width()), side(size.height()))
        }
        None => {
            let scale = (dpi / 96.0) as f32;
            (scale, (size.width() * scale).ceil() as u32, (size.height() * scale).ceil() as u32)
        }
    };
    let too_big = || PngError::TooLarge {
        w,
        h,
        pixels: pixels.is_some(),
    };
    if u64::from(w) * u64::from(h) > 400_000_000 {
        return Err(too_big());
    }
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w.max(1), h.max(1)).ok_or_else(too_big)?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(&tree, resvg::tiny_skia::Transform::from_scale(scale, scale), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| PngError::Encode(e.to_string()))
}
