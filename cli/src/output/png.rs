//! PNG preview: the SVG of the same run rendered by resvg (so the preview shows exactly the
//! drawing), on a white background, at `dpi` pixels per inch.

use crate::error::CliError;

/// Renders SVG bytes to PNG bytes at `dpi`.
pub fn render(svg: &[u8], dpi: f64) -> Result<Vec<u8>, CliError> {
    let opt = resvg::usvg::Options::default();
    let tree = resvg::usvg::Tree::from_data(svg, &opt).map_err(|e| CliError::Io(format!("internal: cannot read own SVG: {e}")))?;
    // usvg sizes mm at 96 px per inch.
    let scale = (dpi / 96.0) as f32;
    let size = tree.size();
    let (w, h) = ((size.width() * scale).ceil() as u32, (size.height() * scale).ceil() as u32);
    let too_big = || CliError::arg("--dpi", format!("a {w} x {h} pixel image is too large; lower --dpi"));
    if u64::from(w) * u64::from(h) > 400_000_000 {
        return Err(too_big());
    }
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w.max(1), h.max(1)).ok_or_else(too_big)?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(&tree, resvg::tiny_skia::Transform::from_scale(scale, scale), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| CliError::Io(format!("cannot encode PNG: {e}")))
}
