//! Letters as outlines (`--region text:STRING`): a TrueType or OpenType font read through
//! `ttf-parser`, a text laid out on it, its glyphs' curves cut into chords.
//!
//! Layout: each line starts at x = 0 and goes right by the glyphs' advance widths, plus the
//! kerning of each pair from the font's `kern` table when it has one (horizontal subtables;
//! the `GPOS` table is not read), plus the letter spacing after every character. Lines go
//! down by the font's line height (ascender - descender + line gap, from `hhea`). The em is
//! `size` mm. The text's box is then moved so that its lower left corner is the origin.
//!
//! Curves: a quadratic or cubic segment becomes as many equal steps in its parameter as keep
//! every chord within 1/1000 of the em of the curve (the interpolation bound on the curve's
//! second derivative), at most 100 per segment, so the number of vertices does not depend on
//! the size. Rings inside an odd number of others are holes (the inside of an "O").
//!
//! The built-in font is DejaVu Sans Bold (Bitstream Vera licence, DejaVu changes in the
//! public domain: `cli/assets/fonts/DejaVu-LICENSE.txt`).

use std::path::Path;
use ttf_parser::{Face, GlyphId, OutlineBuilder};
use zetafill::Point;

/// The font used without `--font`: DejaVu Sans Bold, embedded by the `builtin-font` feature (on
/// by default). The browser page builds without it and fetches the file only when a text asks
/// for it ([`provide_builtin`]).
#[cfg(feature = "builtin-font")]
pub const BUILTIN: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-Bold.ttf");

/// The built-in font handed over by a build that does not embed it.
#[cfg(not(feature = "builtin-font"))]
static PROVIDED: std::sync::OnceLock<&'static [u8]> = std::sync::OnceLock::new();

/// The built-in font's bytes: the embedded file.
#[cfg(feature = "builtin-font")]
pub fn builtin() -> Option<&'static [u8]> {
    Some(BUILTIN)
}

/// The built-in font's bytes: the file handed over by [`provide_builtin`], `None` before that.
#[cfg(not(feature = "builtin-font"))]
pub fn builtin() -> Option<&'static [u8]> {
    PROVIDED.get().copied()
}

/// Hands the built-in font's file (`cli/assets/fonts/DejaVuSans-Bold.ttf`) to a build that
/// does not embed it; the first call wins, as the file is always the same. A build that embeds
/// it keeps its own copy.
pub fn provide_builtin(bytes: Vec<u8>) {
    #[cfg(not(feature = "builtin-font"))]
    let _ = PROVIDED.set(Vec::leak(bytes));
    #[cfg(feature = "builtin-font")]
    drop(bytes);
}

/// The largest font file read.
pub const MAX_FONT_BYTES: u64 = 32 << 20;

/// The largest distance of a chord from its curve, as a fraction of the em.
const CURVE_TOLERANCE_EM: f64 = 1e-3;

/// Most chords per curve segment.
const MAX_CHORDS: usize = 100;

/// A font file's bytes and digest.
#[derive(Debug, Clone)]
pub struct FontFile {
    /// The file's bytes.
    pub bytes: Vec<u8>,
    /// The SHA-256 of the file, in hex.
    pub sha256: String,
}

/// Why no outline came out of a font and a text. The caller says which flag to change.
#[derive(Debug)]
pub enum FontError {
    /// The file cannot be read.
    Read(std::io::Error),
    /// The file is empty.
    Empty,
    /// No `--font` is given and this build holds no built-in font (the page has not fetched it).
    NoBuiltin,
    /// The bytes are not a font `ttf-parser` reads (its reason).
    NotAFont(String),
    /// The font has no glyph for this character.
    Missing(char),
    /// Not one character of the text has an outline (spaces only).
    NoOutline,
    /// The letters need more than this many vertices.
    TooManyVertices(usize),
    /// The letters need more than this many rings.
    TooManyRings(usize),
}

/// Reads a font file (checking only its size: [`lay_out`] parses it).
pub fn read_font(path: &Path) -> Result<FontFile, FontError> {
    let bytes = crate::io::read::read_limited(path, MAX_FONT_BYTES, "a font").map_err(FontError::Read)?;
    if bytes.is_empty() {
        return Err(FontError::Empty);
    }
    let sha256 = crate::io::read::sha256_hex(&bytes);
    Ok(FontFile { bytes, sha256 })
}

/// Limits and sizes of a layout.
#[derive(Debug, Clone, Copy)]
pub struct Setting {
    /// The em in mm.
    pub size: f64,
    /// Added after every character, in mm.
    pub spacing: f64,
    /// Most vertices in all.
    pub max_vertices: usize,
    /// Most rings in all.
    pub max_rings: usize,
}

/// A text laid out: its rings in mm, and for each character with an outline the character
/// and the exclusive end of its rings (in `ends`).
#[derive(Debug, Clone, Default)]
pub struct Letters {
    /// Vertices, ring after ring.
    pub points: Vec<Point<f64>>,
    /// The exclusive end of each ring.
    pub ends: Vec<usize>,
    /// Each drawn character and the end of its rings in `ends`.
    pub glyphs: Vec<(char, usize)>,
}

/// Lays `lines` out in the font `bytes`.
pub fn lay_out(bytes: &[u8], lines: &[String], set: Setting) -> Result<Letters, FontError> {
    let face = Face::parse(bytes, 0).map_err(|e| FontError::NotAFont(e.to_string()))?;
    let em = f64::from(face.units_per_em());
    let line_height = f64::from(face.ascender()) - f64::from(face.descender()) + f64::from(face.line_gap());
    let spacing = set.spacing / set.size * em;
    let mut pen = Pen {
        tolerance: CURVE_TOLERANCE_EM * em,
        origin: (0.0, 0.0),
        rings: Vec::new(),
        current: Vec::new(),
        last: Point::new(0.0, 0.0),
        left: set.max_vertices,
        over: false,
    };
    let mut glyphs = Vec::new();
    for (row, line) in lines.iter().enumerate() {
        let mut x = 0.0;
        let mut before: Option<GlyphId> = None;
        for ch in line.chars() {
            let id = face.glyph_index(ch).ok_or(FontError::Missing(ch))?;
            if let Some(b) = before {
                x += f64::from(kerning(&face, b, id));
            }
            pen.origin = (x, -(row as f64) * line_height);
            let had = pen.rings.len();
            face.outline_glyph(id, &mut pen);
            pen.end_ring();
            if pen.over {
                return Err(FontError::TooManyVertices(set.max_vertices));
            }
            if pen.rings.len() > set.max_rings {
                return Err(FontError::TooManyRings(set.max_rings));
            }
            if pen.rings.len() > had {
                glyphs.push((ch, pen.rings.len()));
            }
            x += f64::from(face.glyph_hor_advance(id).unwrap_or(0)) + spacing;
            before = Some(id);
        }
    }
    if pen.rings.is_empty() {
        return Err(FontError::NoOutline);
    }
    // Font units to mm, the box's lower left corner at the origin.
    let scale = set.size / em;
    let all = || pen.rings.iter().flatten();
    let x0 = all().map(|p| p.x).fold(f64::MAX, f64::min);
    let y0 = all().map(|p| p.y).fold(f64::MAX, f64::min);
    let mut out = Letters {
        glyphs,
        ..Letters::default()
    };
    for r in &pen.rings {
        out.points
            .extend(r.iter().map(|p| Point::new((p.x - x0) * scale, (p.y - y0) * scale)));
        out.ends.push(out.points.len());
    }
    Ok(out)
}

/// The kerning of the pair `(left, right)` in font units, from the first horizontal `kern`
/// subtable that has it.
fn kerning(face: &Face<'_>, left: GlyphId, right: GlyphId) -> i16 {
    let Some(kern) = face.tables().kern else { return 0 };
    kern.subtables
        .into_iter()
        .filter(|s| s.horizontal && !s.variable && !s.has_cross_stream)
        .find_map(|s| s.glyphs_kerning(left, right))
        .unwrap_or(0)
}

/// Collects a glyph's contours as rings, in font units, its curves cut into chords.
struct Pen {
    tolerance: f64,
    origin: (f64, f64),
    rings: Vec<Vec<Point<f64>>>,
    current: Vec<Point<f64>>,
    last: Point<f64>,
    /// Vertices still allowed.
    left: usize,
    /// The vertex budget ran out.
    over: bool,
}

impl Pen {
    fn at(&self, x: f32, y: f32) -> Point<f64> {
        Point::new(self.origin.0 + f64::from(x), self.origin.1 + f64::from(y))
    }

    fn add(&mut self, p: Point<f64>) {
        if self.current.last() != Some(&p) {
            match self.left.checked_sub(1) {
                Some(l) => self.left = l,
                None => self.over = true,
            }
            if !self.over {
                self.current.push(p);
            }
        }
        self.last = p;
    }

    /// Closes the contour being drawn: the closing vertex dropped, kept if 3 vertices remain.
    fn end_ring(&mut self) {
        let mut r = std::mem::take(&mut self.current);
        if r.len() >= 2 && r.first() == r.last() {
            r.pop();
        }
        if r.len() >= 3 {
            self.rings.push(r);
        }
    }

    /// Steps `n` so that the chords of a curve with second-derivative bound `m` stay within
    /// the tolerance: the error of a chord over a parameter step h is at most h² m / 8.
    fn steps(&self, m: f64) -> usize {
        ((m / (8.0 * self.tolerance)).sqrt().ceil() as usize).clamp(1, MAX_CHORDS)
    }
}

fn norm(x: f64, y: f64) -> f64 {
    (x * x + y * y).sqrt()
}

impl OutlineBuilder for Pen {
    fn move_to(&mut self, x: f32, y: f32) {
        self.end_ring();
        let p = self.at(x, y);
        self.add(p);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.at(x, y);
        self.add(p);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (a, b, c) = (self.last, self.at(x1, y1), self.at(x, y));
        // B'' = 2 (a - 2b + c), constant.
        let n = self.steps(2.0 * norm(a.x - 2.0 * b.x + c.x, a.y - 2.0 * b.y + c.y));
        for k in 1..=n {
            let t = k as f64 / n as f64;
            let u = 1.0 - t;
            let p = Point::new(
                u * u * a.x + 2.0 * u * t * b.x + t * t * c.x,
                u * u * a.y + 2.0 * u * t * b.y + t * t * c.y,
            );
            self.add(if k == n { c } else { p });
        }
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (a, b, c, d) = (self.last, self.at(x1, y1), self.at(x2, y2), self.at(x, y));
        // |B''| <= 6 max(|a - 2b + c|, |b - 2c + d|).
        let m = 6.0 * norm(a.x - 2.0 * b.x + c.x, a.y - 2.0 * b.y + c.y).max(norm(b.x - 2.0 * c.x + d.x, b.y - 2.0 * c.y + d.y));
        let n = self.steps(m);
        for k in 1..=n {
            let t = k as f64 / n as f64;
            let u = 1.0 - t;
            let (w0, w1, w2, w3) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
            let p = Point::new(w0 * a.x + w1 * b.x + w2 * c.x + w3 * d.x, w0 * a.y + w1 * b.y + w2 * c.y + w3 * d.y);
            self.add(if k == n { d } else { p });
        }
    }

    fn close(&mut self) {
        self.end_ring();
    }
}

#[cfg(all(test, feature = "builtin-font"))]
mod tests {
    use super::*;

    fn set() -> Setting {
        Setting {
            size: 50.0,
            spacing: 0.0,
            max_vertices: 250_000,
            max_rings: 25_000,
        }
    }

    fn lines(text: &str) -> Vec<String> {
        text.split('\n').map(String::from).collect()
    }

    #[test]
    fn letters_have_their_holes() {
        // O: an outline and a hole; B: an outline and two holes; l: one ring.
        for (text, rings) in [("O", 2), ("B", 3), ("l", 1), ("O l", 3)] {
            let l = lay_out(BUILTIN, &lines(text), set()).unwrap_or_else(|e| panic!("{text}: {e:?}"));
            assert_eq!(l.ends.len(), rings, "{text}");
        }
        let o = lay_out(BUILTIN, &lines("O"), set()).unwrap_or_default();
        let (x0, y0) = o.points.iter().fold((f64::MAX, f64::MAX), |b, p| (b.0.min(p.x), b.1.min(p.y)));
        assert_eq!((x0, y0), (0.0, 0.0));
        // A capital O of DejaVu Sans Bold is about 0.75 em tall.
        let top = o.points.iter().map(|p| p.y).fold(0.0, f64::max);
        assert!(top > 0.7 * 50.0 && top < 0.8 * 50.0, "{top}");
    }

    #[test]
    fn lines_kerning_and_spacing_move_letters() {
        let width = |text: &str, spacing: f64| {
            let l = lay_out(BUILTIN, &lines(text), Setting { spacing, ..set() }).unwrap_or_default();
            let xs = l.points.iter().map(|p| p.x);
            (
                xs.clone().fold(f64::MIN, f64::max),
                l.points.iter().map(|p| p.y).fold(f64::MIN, f64::max),
            )
        };
        let (one, h1) = width("AV", 0.0);
        let (spaced, _) = width("AV", 5.0);
        assert!((spaced - one - 5.0).abs() < 1e-9, "{one} {spaced}");
        let (_, h2) = width("A\nA", 0.0);
        assert!(h2 > h1 + 40.0, "{h1} {h2}");
        // DejaVu's kern table pulls "AV" together, and holds "AA" as it is.
        let face = Face::parse(BUILTIN, 0).unwrap_or_else(|e| panic!("{e}"));
        let id = |c| face.glyph_index(c).unwrap_or_default();
        assert!(kerning(&face, id('A'), id('V')) < 0);
        assert_eq!(kerning(&face, id('A'), id('A')), 0);
    }

    #[test]
    fn bad_fonts_and_texts_are_refused() {
        assert!(matches!(lay_out(b"not a font", &lines("a"), set()), Err(FontError::NotAFont(_))));
        assert!(matches!(
            lay_out(BUILTIN, &lines("a\u{e000}"), set()),
            Err(FontError::Missing('\u{e000}'))
        ));
        assert!(matches!(lay_out(BUILTIN, &lines("  \n "), set()), Err(FontError::NoOutline)));
        let small = Setting { max_vertices: 50, ..set() };
        assert!(matches!(
            lay_out(BUILTIN, &lines("OOOO"), small),
            Err(FontError::TooManyVertices(50))
        ));
        let few = Setting { max_rings: 3, ..set() };
        assert!(matches!(lay_out(BUILTIN, &lines("OO"), few), Err(FontError::TooManyRings(3))));
    }
}
