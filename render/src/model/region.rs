//! A region as the command line gives it, before any file is read or the core checks it: a
//! plain value that the flag parser produces, the plan holds and the run turns into the
//! core's region.

use zetafill::{Point, PolygonRegion, RegionError};

/// A region as given (periodicity is given apart): its kind and sizes, polygon rings, or an
/// SVG file whose outline is not read yet.
#[derive(Debug, Clone, PartialEq)]
pub enum RegionSpec {
    /// `rect:W:H`.
    Rect {
        /// Width in mm.
        width: f64,
        /// Height in mm.
        height: f64,
    },
    /// `circle:R`: the disc centred at (R, R).
    Circle {
        /// Radius in mm.
        radius: f64,
    },
    /// `annulus:R_OUTER:R_INNER`, centred at (R_OUTER, R_OUTER).
    Annulus {
        /// Outer radius.
        outer: f64,
        /// Inner radius.
        inner: f64,
    },
    /// `polygon:X1,Y1,X2,Y2,...` or the outlines of `svg:FILE`: rings of vertices.
    Polygon {
        /// Vertices, ring after ring.
        points: Vec<Point<f64>>,
        /// Exclusive end of each ring.
        ends: Vec<usize>,
    },
    /// `svg:FILE`, read by the command-line tool (its `io::svgin`).
    Svg(std::path::PathBuf),
    /// `mask:FILE[:THRESHOLD]`: the dark areas of a picture, traced when the fill is planned.
    Mask {
        /// The picture.
        path: std::path::PathBuf,
        /// Luminance below which a pixel is dark, in (0, 1).
        threshold: f64,
    },
    /// `text:STRING`: the letters of a text, laid out when the fill is planned.
    Text {
        /// The lines (`\n` in the argument starts a new one).
        lines: Vec<String>,
    },
}

impl RegionSpec {
    /// For a region made from a picture or a text, the `--region` argument written in full:
    /// the threshold always given, a backslash doubled and each line break as `\n`, so it
    /// reads back as the same region.
    pub fn input_name(&self) -> Option<String> {
        match self {
            RegionSpec::Mask { path, threshold } => Some(format!("mask:{}:{threshold}", path.display())),
            RegionSpec::Text { lines } => {
                let escaped: Vec<String> = lines.iter().map(|l| l.replace('\\', "\\\\")).collect();
                Some(format!("text:{}", escaped.join("\\n")))
            }
            _ => None,
        }
    }
}

/// Where a region made from a picture or a text came from: the flags that make it again,
/// as the JSON's parameters and the reproducing command carry them.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RegionSource {
    /// `--region`, written in full (`mask:FILE:THRESHOLD` or `text:STRING`).
    pub region: String,
    /// `--region-width` (mm), for a mask.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub region_width: Option<f64>,
    /// The SHA-256 of the mask picture.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub region_sha256: Option<String>,
    /// `--text-size` (mm), for a text.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub text_size: Option<f64>,
    /// `--letter-spacing` (mm), when not 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub letter_spacing: Option<f64>,
    /// `--font`, when given (the built-in font otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub font: Option<String>,
    /// The SHA-256 of the `--font` file.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub font_sha256: Option<String>,
}

impl RegionSource {
    /// The flags after `--region` as command-line text (each starting with a space).
    pub fn flags(&self) -> String {
        let mut s = String::new();
        let mut add = |flag: &str, value: Option<String>| {
            if let Some(v) = value {
                s.push_str(&format!(" {flag} {v}"));
            }
        };
        add("--region-width", self.region_width.map(|w| w.to_string()));
        add("--region-sha256", self.region_sha256.clone());
        add("--text-size", self.text_size.map(|w| w.to_string()));
        add("--letter-spacing", self.letter_spacing.map(|w| w.to_string()));
        add("--font", self.font.as_deref().map(shell_word));
        add("--font-sha256", self.font_sha256.clone());
        s
    }
}

/// `word` as one word of a POSIX shell command: as it is when it holds only characters no
/// shell treats specially, in single quotes otherwise (a quote written `'\''`).
pub fn shell_word(word: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-+=.,:/@%^".contains(c);
    if !word.is_empty() && word.chars().all(plain) {
        word.to_string()
    } else {
        format!("'{}'", word.replace('\'', "'\\''"))
    }
}

/// The core's polygon region over `points` and its rings' `ends`, its edge grid in `scratch`
/// (resized to fit): validating an outline of 10^5 vertices takes milliseconds.
pub fn polygon_region<'s>(
    points: &'s [Point<f64>],
    ends: &'s [usize],
    scratch: &'s mut Vec<u32>,
) -> Result<PolygonRegion<'s>, RegionError> {
    scratch.clear();
    scratch.resize(PolygonRegion::scratch_words(points.len()), 0);
    PolygonRegion::new_in(points, ends, scratch)
}
