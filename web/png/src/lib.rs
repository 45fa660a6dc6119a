//! The browser page's PNG renderer, a WebAssembly module of its own. The page's main module
//! (`zetafill-web`) builds every file but a PNG's pixels: for a PNG it makes the SVG, checks
//! the size as the CLI does, and hands the SVG with its scale and size to this module, which
//! the page loads the first time a PNG is asked for. Rendering (resvg and tiny-skia) is the
//! largest part of the writers and most pages never need it; kept apart, the main module
//! loads about a third lighter. The pixels come from the same function as the CLI's, so the
//! PNG is the CLI's byte for byte.

#![deny(missing_docs)]

use wasm_bindgen::prelude::*;

/// The PNG of `svg` scaled by `scale` (from SVG pixels) into `w` x `h` pixels on white, as
/// `zetafill_render::output::png::render` makes it.
#[wasm_bindgen]
pub fn rasterise(svg: &[u8], scale: f32, w: u32, h: u32) -> Result<Vec<u8>, String> {
    zetafill_render::output::png::raster::from_svg(svg, scale, w, h)
}
