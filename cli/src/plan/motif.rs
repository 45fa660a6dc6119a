//! `--shape svg:FILE` and `--shape glyph:TEXT` resolved: each motif read (the SVG's filled
//! outline, or a font's glyph), checked by the core as it will be placed, and given its
//! number in the run's table of motifs. A file or glyph the core refuses stops the command
//! here, before any work, with a message that names `--shape`.

use crate::args::fill::RegionInputArgs;
use crate::args::spec::{ShapeArg, ShapeSpec};
use crate::error::CliError;
use crate::io::font::{FontError, Setting};
use crate::output::machine::printable;
use std::path::Path;
use zetafill::{Motif, Point, ShapeKind, MAX_MOTIF_VERTICES};

/// The flattening of an SVG motif's curves when `--chord-tolerance` is not given: no chord
/// strays more than this from its curve, in mm of the drawing as the file sizes it.
pub const DEFAULT_MOTIF_TOLERANCE: f64 = 0.05;

/// The em of a glyph motif as it is laid out (in mm; a motif's size is its area's, so this
/// only sets the units the outline is read in).
const GLYPH_EM: f64 = 100.0;

/// One motif of a run: its outline as read (the core moves a copy to unit area when the run
/// starts) and what is drawn with it.
#[derive(Debug, Clone, PartialEq)]
pub struct MotifSource {
    /// `svg:FILE` or `glyph:C`, as the messages name it.
    pub name: String,
    /// Vertices, ring after ring, in mm as read.
    pub points: Vec<Point<f64>>,
    /// The exclusive end of each ring.
    pub ends: Vec<usize>,
    /// Polylines drawn with the motif and never tested, in the same frame as `points`.
    pub decoration: Vec<Vec<Point<f64>>>,
    /// The SHA-256 of an SVG motif's file, as read.
    pub sha256: Option<String>,
}

impl MotifSource {
    /// The core's motif of this outline, over copies of its vertices in `points` and its
    /// edge tree in `scratch` (both sized here).
    pub fn motif<'a>(&'a self, points: &'a mut Vec<Point<f64>>, scratch: &'a mut Vec<u32>) -> Result<Motif<'a>, zetafill::MotifError> {
        points.clone_from(&self.points);
        scratch.clear();
        scratch.resize(Motif::scratch_words(points.len()), 0);
        Motif::new_in(points, &self.ends, scratch)
    }
}

/// The run's shapes: the kinds in mix order, and the table of motifs the motif kinds number.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Shapes {
    /// One kind per entry of the mix (a glyph's characters in turn).
    pub kinds: Vec<ShapeKind>,
    /// The motifs, numbered as the kinds name them.
    pub motifs: Vec<MotifSource>,
}

/// Reads and checks every motif of `--shape`. `tolerance` flattens SVG curves; `input` holds
/// `--font` and `--font-sha256`.
pub fn resolve(shape: &ShapeArg, input: &RegionInputArgs, tolerance: f64) -> Result<Shapes, CliError> {
    let mut out = Shapes::default();
    let mut font: Option<crate::io::font::FontFile> = None;
    for spec in &shape.0 {
        match spec {
            ShapeSpec::Kind(k) => out.kinds.push(*k),
            ShapeSpec::Svg(path) => {
                let source = read_svg(path, tolerance)?;
                let kind = check(&source, out.motifs.len())?;
                out.motifs.push(source);
                out.kinds.push(kind);
            }
            ShapeSpec::Glyph(text) => {
                if font.is_none() {
                    if let Some(path) = &input.font {
                        let f = crate::io::font::read_font(path).map_err(|e| glyph_error(e, Some(path)))?;
                        crate::plan::region_input::check_digest("--font-sha256", path, &f.sha256, input.font_sha256.as_ref(), "font")?;
                        font = Some(f);
                    }
                }
                let bytes = match &font {
                    Some(f) => f.bytes.as_slice(),
                    None => crate::io::font::builtin().ok_or_else(|| glyph_error(FontError::NoBuiltin, None))?,
                };
                for ch in text.chars().filter(|c| !c.is_whitespace()) {
                    let name = format!("glyph:{ch}");
                    // A character met before is the same motif again.
                    if let Some(k) = out.motifs.iter().position(|m| m.name == name) {
                        let again = out
                            .kinds
                            .iter()
                            .copied()
                            .find(|kind| matches!(kind, ShapeKind::Motif { id, .. } if usize::from(*id) == k));
                        out.kinds.extend(again);
                        continue;
                    }
                    let source = glyph(bytes, ch, input.font.as_deref())?;
                    let kind = check(&source, out.motifs.len())?;
                    out.motifs.push(source);
                    out.kinds.push(kind);
                }
            }
        }
    }
    Ok(out)
}

/// Motif files handed over by a caller without a file system (the browser page): a path
/// named here is read from these bytes instead of from disk.
static PROVIDED: std::sync::Mutex<Vec<(std::path::PathBuf, Vec<u8>)>> = std::sync::Mutex::new(Vec::new());

/// Makes `--shape svg:PATH` read `bytes` (the file's content) instead of the file, with the
/// same limits and messages; replaces what an earlier call gave for the same path.
pub fn provide_file(path: &Path, bytes: Vec<u8>) {
    let mut files = PROVIDED.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    files.retain(|(p, _)| p != path);
    files.push((path.to_path_buf(), bytes));
}

/// The bytes [`provide_file`] gave for `path`, if any.
fn provided(path: &Path) -> Option<Vec<u8>> {
    let files = PROVIDED.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    files.iter().find(|(p, _)| p == path).map(|(_, b)| b.clone())
}

/// The motif of an SVG file.
fn read_svg(path: &Path, tolerance: f64) -> Result<MotifSource, CliError> {
    let chords = format!("within {} mm", crate::error::num(tolerance));
    let fail = |e| crate::plan::region::svg_error("--shape", &chords, path, e);
    let limit = crate::io::read::MAX_SVG_BYTES;
    let data = match provided(path) {
        Some(bytes) if bytes.len() as u64 > limit => {
            return Err(fail(crate::io::svgin::OutlineError::Read(crate::io::read::too_large(
                limit,
                "an SVG motif",
            ))));
        }
        Some(bytes) => bytes,
        None => crate::io::read::read_limited(path, limit, "an SVG motif").map_err(|e| fail(crate::io::svgin::OutlineError::Read(e)))?,
    };
    let sha256 = crate::io::read::sha256_hex(&data);
    let m = crate::io::svgin::motif_of(data, tolerance).map_err(fail)?;
    Ok(MotifSource {
        name: format!("svg:{}", path.display()),
        points: m.points,
        ends: m.ends,
        decoration: m.decoration,
        sha256: Some(sha256),
    })
}

/// The motif of one character of the font `bytes`.
fn glyph(bytes: &[u8], ch: char, font: Option<&Path>) -> Result<MotifSource, CliError> {
    let set = Setting {
        size: GLYPH_EM,
        spacing: 0.0,
        max_vertices: MAX_MOTIF_VERTICES,
        max_rings: crate::io::svgin::MAX_RINGS,
    };
    let letters = crate::io::font::lay_out(bytes, &[ch.to_string()], set).map_err(|e| match e {
        FontError::NoOutline => CliError::arg(
            "--shape",
            printable(&format!(
                "the font draws nothing for '{}' (U+{:04X}); leave it out of glyph:TEXT",
                ch.escape_debug(),
                u32::from(ch)
            )),
        ),
        e => glyph_error(e, font),
    })?;
    Ok(MotifSource {
        name: format!("glyph:{ch}"),
        points: letters.points,
        ends: letters.ends,
        decoration: Vec::new(),
        sha256: None,
    })
}

/// A font that gives no glyph motif, worded for the flag to change.
fn glyph_error(e: FontError, path: Option<&Path>) -> CliError {
    let name = path.map_or_else(|| "the built-in font".to_string(), |p| format!("'{}'", p.display()));
    match e {
        FontError::Missing(c) => CliError::arg(
            if path.is_some() { "--font" } else { "--shape" },
            printable(&format!(
                "{name} has no glyph for '{}' (U+{:04X}); leave it out of glyph:TEXT or give a --font that has it",
                c.escape_debug(),
                u32::from(c)
            )),
        ),
        FontError::TooManyVertices(n) => CliError::arg(
            "--shape",
            format!("a glyph of {name} needs more than {n} vertices, the most a motif has; use a simpler --font"),
        ),
        e => crate::plan::region_input::font_error(e, path),
    }
}

/// The kind of motif `source`, numbered `id`, or the refusal naming its source.
fn check(source: &MotifSource, id: usize) -> Result<ShapeKind, CliError> {
    let Ok(id8) = u8::try_from(id) else {
        return Err(CliError::arg("--shape", "a fill takes at most 256 motifs"));
    };
    let (mut points, mut scratch) = (Vec::new(), Vec::new());
    let m = source
        .motif(&mut points, &mut scratch)
        .map_err(|e| CliError::arg("--shape", printable(&format!("{} is not a motif: {e}; {}", source.name, fix(e)))))?;
    Ok(m.kind(id8))
}

/// What to change in a motif the core refuses.
fn fix(e: zetafill::MotifError) -> String {
    match e {
        zetafill::MotifError::TooManyVertices => {
            format!("a motif has at most {MAX_MOTIF_VERTICES} vertices: simplify it, or give a larger --chord-tolerance")
        }
        zetafill::MotifError::NoInterior => "give it an outline with room inside".to_string(),
        zetafill::MotifError::Outline(_) => {
            "draw it as outlines that neither cross themselves nor each other (a hole inside its outline), with an area".to_string()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_provided_file_is_read_in_place_of_the_disk_with_the_same_limit() {
        let path = Path::new("/nonexistent/zetafill-provided-heart.svg");
        let heart =
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm" viewBox="0 0 10 10"><path d="M1 1H9V9H1Z"/></svg>"#;
        // Not there: the disk's error.
        assert!(read_svg(path, 0.05).is_err());
        provide_file(path, heart.as_bytes().to_vec());
        let m = read_svg(path, 0.05).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.ends, vec![4]);
        assert_eq!(m.sha256.as_deref(), Some(crate::io::read::sha256_hex(heart.as_bytes()).as_str()));
        // Too large, as a file of that size would be.
        provide_file(path, vec![b' '; crate::io::read::MAX_SVG_BYTES as usize + 1]);
        let e = read_svg(path, 0.05).err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.contains("more than 64 MiB"), "{e}");
    }
}
