//! PNG preview: the SVG of the same run rendered by resvg (so the preview shows exactly the
//! drawing), on a white background, at `dpi` pixels per inch or with its longer side
//! `pixels` long. Its arcs are turned into curves first ([`super::curves`]), so that the
//! pixels are the same on every target.

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
    // Arcs become curves here, with the pinned libm: usvg would use the platform's.
    let curved = std::str::from_utf8(svg).map(super::curves::arcs_as_curves);
    let svg = match &curved {
        Ok(text) => text.as_bytes(),
        Err(_) => svg,
    };
    let opt = usvg::Options::default();
    let tree = usvg::Tree::from_data(svg, &opt).map_err(|e| PngError::Svg(e.to_string()))?;
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
    let (w, h) = (w.max(1), h.max(1));
    #[cfg(feature = "raster")]
    {
        let _ = svg;
        raster::pixels(&tree, scale, w, h).map_err(|e| e.unwrap_or_else(too_big))
    }
    #[cfg(not(feature = "raster"))]
    {
        let _ = tree;
        match RASTERISER.get() {
            Some(f) => f(svg, scale, w, h).map_err(PngError::Encode),
            None => Err(PngError::Encode("no PNG renderer is linked into this build".into())),
        }
    }
}

/// What renders an SVG to PNG bytes in a build without the `raster` feature: the SVG, its
/// scale from SVG pixels, and the image's width and height in pixels (already checked).
pub type Rasteriser = fn(&[u8], f32, u32, u32) -> Result<Vec<u8>, String>;

static RASTERISER: std::sync::OnceLock<Rasteriser> = std::sync::OnceLock::new();

/// Sets the renderer a build without the `raster` feature hands its PNGs to (the browser
/// page's, which loads it only when a PNG is asked for); the first one set stays. A build
/// with `raster` renders with resvg itself and never calls it.
pub fn set_rasteriser(f: Rasteriser) {
    let _ = RASTERISER.set(f);
}

/// The pixels of an SVG, by resvg (the `raster` feature).
#[cfg(feature = "raster")]
pub mod raster {
    /// Renders `tree` scaled by `scale` into a `w` x `h` image on white, encoded as PNG;
    /// `Err(None)` when so many pixels cannot be had.
    pub fn pixels(tree: &usvg::Tree, scale: f32, w: u32, h: u32) -> Result<Vec<u8>, Option<super::PngError>> {
        let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).ok_or(None)?;
        pixmap.fill(resvg::tiny_skia::Color::WHITE);
        resvg::render(tree, resvg::tiny_skia::Transform::from_scale(scale, scale), &mut pixmap.as_mut());
        pixmap.encode_png().map_err(|e| Some(super::PngError::Encode(e.to_string())))
    }

    /// What [`super::render`] hands a [`super::Rasteriser`]: the SVG read again and rendered
    /// as `render` itself does (the PNG module of the browser page).
    pub fn from_svg(svg: &[u8], scale: f32, w: u32, h: u32) -> Result<Vec<u8>, String> {
        let tree = usvg::Tree::from_data(svg, &usvg::Options::default()).map_err(|e| e.to_string())?;
        pixels(&tree, scale, w, h).map_err(|e| e.map_or_else(|| format!("no room for {w} x {h} pixels"), |e| format!("{e:?}")))
    }
}
