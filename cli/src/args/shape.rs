//! Parsers for the value of `--shape`: the built-in kinds with their parameters, and the
//! motifs (`svg:FILE`, `glyph:TEXT`) and mixes of them all.

use super::spec::{finite, positive};
use crate::model::doc::shape_name;
use zetafill::{MixOrder, ShapeKind, ShapeList, MAX_MIX};

/// A ratio in (0, 1).
fn ratio(what: &str, s: &str) -> Result<f64, String> {
    let v = finite(s).map_err(|e| format!("{what}: {e}"))?;
    if v > 0.0 && v < 1.0 {
        Ok(v)
    } else {
        Err(format!("{what} must be between 0 and 1, exclusive (got {s})"))
    }
}

/// A count in a range.
fn count(what: &str, s: &str, lo: u8, hi: u8) -> Result<u8, String> {
    match s.trim().parse::<u8>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!("{what} must be a whole number from {lo} to {hi} (got {s})")),
    }
}

const SHAPES: &str =
    "circle, square, rect:ASPECT, triangle, polygon:SIDES, star:POINTS:INNER_RATIO, ring:INNER_RATIO, blob:DELTA, noisy:AMPLITUDE[:FEATURES[:OCTAVES]] or mix:SHAPE,SHAPE,...";

/// One shape: `circle | square | rect:ASPECT | triangle | polygon:SIDES |
/// star:POINTS:INNER_RATIO | ring:INNER_RATIO | blob:DELTA | noisy:AMPLITUDE[:FEATURES[:OCTAVES]]`.
pub fn one_shape(s: &str) -> Result<ShapeKind, String> {
    let mut parts = s.split(':');
    let name = parts.next().unwrap_or("");
    let rest: Vec<&str> = parts.collect();
    let k = match (name, rest.as_slice()) {
        ("circle", []) => ShapeKind::Circle,
        ("square", []) => ShapeKind::Square,
        ("triangle", []) => ShapeKind::Triangle,
        ("rect", [a]) => {
            let aspect = positive(a).map_err(|e| format!("rect:ASPECT: the aspect ratio {e}"))?;
            if !(1e-3..=1e3).contains(&aspect) {
                return Err(format!("rect:ASPECT: the aspect ratio must lie between 0.001 and 1000 (got {a})"));
            }
            ShapeKind::Rect { aspect }
        }
        ("polygon", [n]) => ShapeKind::Polygon {
            sides: count("polygon:SIDES: SIDES", n, 3, 32)?,
        },
        ("star", [p, r]) => ShapeKind::Star {
            points: count("star:POINTS:INNER_RATIO: POINTS", p, 2, 16)?,
            inner: ratio("star:POINTS:INNER_RATIO: INNER_RATIO", r)?,
        },
        ("ring", [r]) => ShapeKind::Ring {
            inner: ratio("ring:INNER_RATIO: INNER_RATIO", r)?,
        },
        ("blob", [d]) => {
            let delta = finite(d).map_err(|e| format!("blob:DELTA: {e}"))?;
            if !(0.0..1.0 / 3.0).contains(&delta) {
                return Err(format!(
                    "blob:DELTA: DELTA must be at least 0 and below 1/3 so that r(θ) stays positive (got {d})"
                ));
            }
            ShapeKind::Blob { delta }
        }
        ("noisy", [a, more @ ..]) if more.len() <= 2 => noisy(a, more.first().copied(), more.get(1).copied())?,
        ("rect", _) => return Err("write rect:ASPECT, for example rect:2 (width twice the height)".into()),
        ("polygon", _) => return Err("write polygon:SIDES, for example polygon:6".into()),
        ("star", _) => return Err("write star:POINTS:INNER_RATIO, for example star:5:0.4".into()),
        ("ring", _) => return Err("write ring:INNER_RATIO, for example ring:0.6".into()),
        ("blob", _) => return Err("write blob:DELTA, for example blob:0.15".into()),
        ("noisy", _) => return Err("write noisy:AMPLITUDE[:FEATURES[:OCTAVES]], for example noisy:0.3:5:2".into()),
        _ => return Err(format!("unknown shape '{s}'; use {SHAPES}")),
    };
    Ok(k)
}

/// `noisy:AMPLITUDE[:FEATURES[:OCTAVES]]`: the amplitude, and the features (default 5) and
/// octaves (default 2) of the noise around the outline.
fn noisy(a: &str, features: Option<&str>, octaves: Option<&str>) -> Result<ShapeKind, String> {
    const FORM: &str = "noisy:AMPLITUDE:FEATURES:OCTAVES";
    let amplitude = finite(a).map_err(|e| format!("{FORM}: AMPLITUDE {e}"))?;
    if !(0.0..=0.9).contains(&amplitude) {
        return Err(format!(
            "{FORM}: AMPLITUDE must be from 0 to 0.9 so that the radius stays positive (got {a})"
        ));
    }
    let features = features.map_or(Ok(5), |f| count(&format!("{FORM}: FEATURES"), f, 2, 16))?;
    let octaves = octaves.map_or(Ok(2), |o| count(&format!("{FORM}: OCTAVES"), o, 1, 4))?;
    if u32::from(features) << (octaves - 1) > 16 {
        return Err(format!(
            "{FORM}: FEATURES x 2^(OCTAVES - 1) must be at most 16, two of the outline's 32 vertices to a cell of the finest octave (got {features} features and {octaves} octaves); give fewer of either"
        ));
    }
    Ok(ShapeKind::Noisy {
        amplitude,
        features,
        octaves,
    })
}

/// `--shape`: one shape, or `mix:SHAPE,SHAPE,...` (up to [`MAX_MIX`] once each `glyph:`
/// is counted as its characters). A shape is a built-in kind, `svg:FILE` (the filled outline
/// of an SVG) or `glyph:TEXT` (each character of TEXT); in a mix, neither FILE nor TEXT can
/// hold a comma.
pub fn shape(s: &str) -> Result<ShapeArg, String> {
    let specs = match s.strip_prefix("mix:") {
        Some(list) => list.split(',').map(shape_spec).collect::<Result<Vec<_>, _>>()?,
        None => vec![shape_spec(s)?],
    };
    let count: usize = specs.iter().map(ShapeSpec::count).sum();
    if specs.is_empty() || count > MAX_MIX {
        return Err(format!(
            "mix: needs 1 to {MAX_MIX} shapes separated by commas (each character of a glyph: counts as one; this has {count})"
        ));
    }
    Ok(ShapeArg(specs))
}

/// One entry of `--shape`.
fn shape_spec(s: &str) -> Result<ShapeSpec, String> {
    if let Some(file) = s.strip_prefix("svg:") {
        if file.is_empty() {
            return Err("svg:FILE: give the SVG file whose filled outline is the shape, for example svg:heart.svg".into());
        }
        return Ok(ShapeSpec::Svg(file.into()));
    }
    if let Some(text) = s.strip_prefix("glyph:") {
        if text.chars().all(char::is_whitespace) {
            return Err("glyph:TEXT: give at least one visible character, for example glyph:0123456789".into());
        }
        return Ok(ShapeSpec::Glyph(text.to_string()));
    }
    one_shape(s).map(ShapeSpec::Kind)
}

/// An entry of `--shape`: a built-in kind, or a motif from a file or a font.
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeSpec {
    /// A built-in kind.
    Kind(ShapeKind),
    /// `svg:FILE`: the filled outline of an SVG file.
    Svg(std::path::PathBuf),
    /// `glyph:TEXT`: each visible character of TEXT, in turn.
    Glyph(String),
}

impl ShapeSpec {
    /// The entries this one adds to the mix.
    pub fn count(&self) -> usize {
        match self {
            ShapeSpec::Glyph(t) => t.chars().filter(|c| !c.is_whitespace()).count(),
            _ => 1,
        }
    }

    /// The text form, as on the command line.
    pub fn name(&self) -> String {
        match self {
            ShapeSpec::Kind(k) => shape_name(k),
            ShapeSpec::Svg(p) => format!("svg:{}", p.display()),
            ShapeSpec::Glyph(t) => format!("glyph:{t}"),
        }
    }
}

/// The parsed `--shape`: one entry, or the entries of a mix.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeArg(pub Vec<ShapeSpec>);

impl ShapeArg {
    /// The built-in kinds, or `None` if an entry is a motif (whose kind is known once its
    /// outline is read: see `plan::motif`).
    pub fn kinds(&self) -> Option<Vec<ShapeKind>> {
        self.0
            .iter()
            .map(|s| match s {
                ShapeSpec::Kind(k) => Some(*k),
                _ => None,
            })
            .collect()
    }

    /// The core's shape list of built-in kinds (a circle for a list with motifs).
    pub fn list(&self, order: MixOrder, salt: u64) -> ShapeList {
        let kinds = self.kinds().unwrap_or_default();
        ShapeList::mix(&kinds, order, salt).unwrap_or_else(|| ShapeKind::Circle.into())
    }

    /// Whether any entry rotates (every motif does).
    pub fn rotates(&self) -> bool {
        self.0.iter().any(|s| match s {
            ShapeSpec::Kind(k) => k.rotates(),
            _ => true,
        })
    }

    /// Whether the entries are more than one shape (a mix).
    pub fn is_mix(&self) -> bool {
        self.0.iter().map(ShapeSpec::count).sum::<usize>() > 1
    }

    /// Whether an entry is an SVG motif.
    pub fn has_svg(&self) -> bool {
        self.0.iter().any(|s| matches!(s, ShapeSpec::Svg(_)))
    }

    /// Whether an entry is a glyph motif (which reads `--font`).
    pub fn has_glyph(&self) -> bool {
        self.0.iter().any(|s| matches!(s, ShapeSpec::Glyph(_)))
    }

    /// The text form, as on the command line.
    pub fn name(&self) -> String {
        match self.0.as_slice() {
            [one] => one.name(),
            many => format!("mix:{}", many.iter().map(ShapeSpec::name).collect::<Vec<_>>().join(",")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_parse_and_name_round_trip() {
        for s in [
            "circle",
            "square",
            "rect:2",
            "rect:0.5",
            "triangle",
            "polygon:6",
            "star:5:0.4",
            "ring:0.6",
            "blob:0.2",
            "mix:circle,square",
        ] {
            let k = shape(s).map(|k| k.name()).unwrap_or_default();
            assert_eq!(k, s);
        }
        assert!(shape("ring:1").is_err());
        assert!(shape("blob:0.34").is_err());
        assert!(shape("star:1:0.5").is_err());
        assert!(shape("polygon:2").is_err());
        assert!(shape("mix:circle,hexagon").is_err());
        assert!(shape("hexagon").is_err());
        assert!(shape("rect").is_err());
        assert!(shape("rect:0").is_err());
        assert!(shape("rect:nan").is_err());
    }
}
