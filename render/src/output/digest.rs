//! Digest output: one line `COUNT HEX16`, the FNV-1a 64 digest of every placed shape's
//! centre, area and angle bits (see `zetafill::digest`), the same value the firmware prints.

use crate::model::doc::FillDoc;
use zetafill::digest::{add_shape, Fnv1a};

/// The digest line of a fill.
pub fn render(doc: &FillDoc) -> Vec<u8> {
    // The engine's own digest (exact for every scalar) when the document carries it.
    if let Some((n, h)) = doc.digest {
        return format!("{n} {h:016x}\n").into_bytes();
    }
    let mut h = Fnv1a::default();
    for s in &doc.shapes {
        add_shape(&mut h, s.center[0], s.center[1], s.area, s.angle.unwrap_or(0.0));
    }
    format!("{} {:016x}\n", doc.shapes.len(), h.finish()).into_bytes()
}
