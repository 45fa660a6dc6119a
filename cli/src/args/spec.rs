//! Parsers for the value of `--region` and the number checks every flag shares (`--shape` is
//! parsed in `args::shape`, re-exported here). Each returns a message that says what is wrong and what to write instead; clap adds the
//! flag's name and exits with code 2.

pub use super::shape::{one_shape, shape, ShapeArg, ShapeSpec};
use crate::model::density::DensitySpec;
use crate::model::region::RegionSpec;
use zetafill::{NoiseKind, Point, MAX_OCTAVES};

/// A number that must be finite.
pub fn finite(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|_| format!("'{s}' is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("'{s}' is not a finite number"))
    }
}

/// A finite number > 0.
pub fn positive(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!("must be greater than 0 (got {s})"))
    }
}

/// The largest length in mm any flag takes: a kilometre, larger than any sheet, bed or
/// region a tool draws, and small enough that areas and coordinates stay exact.
pub const MAX_MM: f64 = 1_000_000.0;

/// A length in mm: finite, > 0, at most [`MAX_MM`].
pub fn length(s: &str) -> Result<f64, String> {
    let v = positive(s)?;
    if v <= MAX_MM {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_MM} mm, a kilometre (got {s})"))
    }
}

/// A length in mm that may be 0: finite, >= 0, at most [`MAX_MM`].
pub fn length_or_zero(s: &str) -> Result<f64, String> {
    let v = non_negative(s)?;
    if v <= MAX_MM {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_MM} mm, a kilometre (got {s})"))
    }
}

/// The largest N: the core computes zeta(c, N) to full precision up to there.
pub const MAX_N_OFFSET: f64 = 1_000_000.0;

/// The paper's N: finite, > 0, at most [`MAX_N_OFFSET`].
pub fn n_offset(s: &str) -> Result<f64, String> {
    let v = positive(s)?;
    if v <= MAX_N_OFFSET {
        Ok(v)
    } else {
        Err(format!(
            "N must be at most {MAX_N_OFFSET}, where zeta(c, N) is computed to full precision (got {s})"
        ))
    }
}

/// A finite number >= 0.
pub fn non_negative(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err(format!("must be 0 or more (got {s})"))
    }
}

/// The exponent c: finite, > 1.
pub fn exponent(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v > 1.0 {
        Ok(v)
    } else {
        Err(format!("c must be greater than 1 (got {s}); typical values are 1.1 to 1.5"))
    }
}

/// The fractal dimension D in 2D: 0 < D < 2 (so that c = 2/D > 1).
pub fn dimension(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v > 0.0 && v < 2.0 {
        Ok(v)
    } else {
        Err(format!("the dimension must be between 0 and 2, exclusive (got {s}); c = 2/D"))
    }
}

/// A fill fraction in (0, 1).
pub fn fraction(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v > 0.0 && v < 1.0 {
        Ok(v)
    } else {
        Err(format!("the fill fraction must be between 0 and 1, exclusive (got {s})"))
    }
}

/// `polygon:X1,Y1,X2,Y2,...[/X1,Y1,...]...`: one ring of vertices, or several separated by
/// `/`, filled by the even-odd rule (a ring inside another is a hole).
fn polygon(list: &str) -> Result<RegionSpec, String> {
    const FORM: &str = "polygon:X1,Y1,X2,Y2,...[/X1,Y1,...]";
    let several = list.contains('/');
    let mut points = Vec::new();
    let mut ends = Vec::new();
    for (k, ring) in list.split('/').enumerate() {
        let which = if several { format!(" (ring {})", k + 1) } else { String::new() };
        let nums = ring
            .split(',')
            .map(|v| {
                let x = finite(v)?;
                if x.abs() <= MAX_MM {
                    Ok(x)
                } else {
                    Err(format!("the coordinate {v} is beyond {MAX_MM} mm, a kilometre"))
                }
            })
            .collect::<Result<Vec<f64>, _>>()
            .map_err(|e| format!("{FORM}{which}: {e}"))?;
        if nums.len() % 2 != 0 {
            return Err(format!("{FORM}{which}: give an even count of numbers (x,y pairs)"));
        }
        let mut ring: Vec<Point<f64>> = nums.chunks(2).map(|c| Point::new(c[0], c.get(1).copied().unwrap_or(0.0))).collect();
        // A closed ring may repeat its first vertex at the end, as SVG paths and most
        // exports do: the repeat is dropped (it was refused as an outline that crosses itself).
        if ring.len() > 3 && ring.first() == ring.last() {
            ring.pop();
        }
        if ring.len() < 3 {
            return Err(format!("{FORM}{which}: a ring needs at least 3 vertices"));
        }
        points.extend(ring);
        ends.push(points.len());
    }
    Ok(RegionSpec::Polygon { points, ends })
}

/// The largest `--density noise` contrast: beyond it the density is a hard two-level mask.
pub const MAX_CONTRAST: f64 = 100.0;

/// `noise:value|gradient:SCALE[:OCTAVES[:GAIN[:CONTRAST]]]` (defaults 4 octaves, gain 0.5,
/// contrast 2).
pub fn density(s: &str) -> Result<DensitySpec, String> {
    if let Some(rest) = s.strip_prefix("image:") {
        return image_density(rest);
    }
    const FORM: &str = "noise:value|gradient:SCALE[:OCTAVES[:GAIN[:CONTRAST]]], for example noise:gradient:30:4:0.5:2";
    let parts: Vec<&str> = s.split(':').collect();
    let (kind, rest) = match parts.as_slice() {
        ["noise", "value", rest @ ..] => (NoiseKind::Value, rest),
        ["noise", "gradient", rest @ ..] => (NoiseKind::Gradient, rest),
        _ => {
            return Err(format!(
                "unknown density '{s}'; write {FORM}, or image:FILE[,invert][,gamma=G][,floor=F]"
            ))
        }
    };
    let (scale, octaves, gain, contrast) = match rest {
        [scale, more @ ..] if more.len() <= 3 => (scale, more.first(), more.get(1), more.get(2)),
        _ => return Err(format!("'{s}' has {} values after the kind; write {FORM}", rest.len())),
    };
    let scale = length(scale).map_err(|e| format!("{s}: the noise SCALE {e}"))?;
    let octaves = match octaves {
        None => 4,
        Some(o) => match o.trim().parse::<u32>() {
            Ok(v) if (1..=MAX_OCTAVES).contains(&v) => v,
            _ => return Err(format!("{s}: OCTAVES must be a whole number from 1 to {MAX_OCTAVES} (got {o})")),
        },
    };
    let gain = match gain {
        None => 0.5,
        Some(g) => match finite(g) {
            Ok(v) if v > 0.0 && v <= 1.0 => v,
            _ => return Err(format!("{s}: GAIN must be above 0 and at most 1 (got {g})")),
        },
    };
    let contrast = match contrast {
        None => 2.0,
        Some(k) => match finite(k) {
            Ok(v) if v > 0.0 && v <= MAX_CONTRAST => v,
            _ => return Err(format!("{s}: CONTRAST must be above 0 and at most {MAX_CONTRAST} (got {k})")),
        },
    };
    Ok(DensitySpec::Noise {
        kind,
        scale,
        octaves,
        gain,
        contrast,
    })
}

/// `image:FILE[,invert][,gamma=G][,floor=F]` (after `image:`): defaults gamma 1, floor 0.
fn image_density(rest: &str) -> Result<DensitySpec, String> {
    let mut parts = rest.split(',');
    let file = parts.next().unwrap_or("");
    if file.is_empty() {
        return Err("image: needs a file, for example image:portrait.png,gamma=1.5".into());
    }
    let (mut invert, mut gamma, mut floor) = (false, 1.0, 0.0);
    for opt in parts {
        match opt.split_once('=') {
            None if opt == "invert" => invert = true,
            Some(("gamma", g)) => {
                gamma = match finite(g) {
                    Ok(v) if v > 0.0 && v <= 100.0 => v,
                    _ => return Err(format!("image:{rest}: gamma must be above 0 and at most 100 (got {g})")),
                }
            }
            Some(("floor", f)) => {
                floor = match finite(f) {
                    Ok(v) if (0.0..1.0).contains(&v) => v,
                    _ => return Err(format!("image:{rest}: floor must be at least 0 and below 1 (got {f})")),
                }
            }
            _ => {
                return Err(format!(
                    "image:{rest}: unknown option '{opt}'; use invert, gamma=G or floor=F, separated by commas"
                ))
            }
        }
    }
    Ok(DensitySpec::Image {
        path: file.into(),
        invert,
        gamma,
        floor,
    })
}

/// A fill's `--region`: every form of [`region`], and `mask:FILE[:THRESHOLD]` (default
/// threshold 0.5) and `text:STRING` (`\n` starts a new line, `\\` is a backslash).
pub fn fill_region(s: &str) -> Result<RegionSpec, String> {
    if let Some(rest) = s.strip_prefix("mask:") {
        return mask(rest);
    }
    if let Some(rest) = s.strip_prefix("text:") {
        return text(rest);
    }
    region(s).map_err(|e| {
        if e.starts_with("unknown region") {
            format!(
                "unknown region '{s}'; use rect:W:H, circle:R, annulus:R_OUTER:R_INNER, polygon:X1,Y1,X2,Y2,..., svg:FILE (sizes in mm), mask:FILE[:THRESHOLD] or text:STRING"
            )
        } else {
            e
        }
    })
}

/// `FILE[:THRESHOLD]` after `mask:`: a last part that reads as a number is the threshold.
fn mask(rest: &str) -> Result<RegionSpec, String> {
    let (path, threshold) = match rest.rsplit_once(':') {
        Some((file, t)) if t.trim().parse::<f64>().is_ok() => {
            let v = finite(t).map_err(|e| format!("mask:FILE:THRESHOLD: {e}"))?;
            if !(v > 0.0 && v < 1.0) {
                return Err(format!(
                    "mask:FILE:THRESHOLD: the threshold is a luminance between 0 and 1, exclusive (got {t}); pixels darker than it are inside"
                ));
            }
            (file, v)
        }
        _ => (rest, 0.5),
    };
    if path.is_empty() {
        return Err("mask: needs a PNG or JPEG file, for example mask:logo.png or mask:logo.png:0.4".into());
    }
    Ok(RegionSpec::Mask {
        path: path.into(),
        threshold,
    })
}

/// `STRING` after `text:`: lines split at `\n` (or a line break), `\\` a backslash.
fn text(rest: &str) -> Result<RegionSpec, String> {
    if rest.is_empty() {
        return Err("text: needs a string, for example text:zeta".into());
    }
    let mut lines = vec![String::new()];
    let mut chars = rest.chars();
    while let Some(c) = chars.next() {
        let line = match c {
            '\\' => match chars.clone().next() {
                Some('n') => {
                    chars.next();
                    None
                }
                Some('\\') => {
                    chars.next();
                    Some('\\')
                }
                _ => Some('\\'),
            },
            '\n' => None,
            c => Some(c),
        };
        match (line, lines.last_mut()) {
            (Some(c), Some(l)) => l.push(c),
            _ => lines.push(String::new()),
        }
    }
    Ok(RegionSpec::Text { lines })
}

/// `rect:W:H | circle:R | annulus:R_OUTER:R_INNER | polygon:X1,Y1,...[/...] | svg:FILE` (mm).
pub fn region(s: &str) -> Result<RegionSpec, String> {
    if let Some(file) = s.strip_prefix("svg:") {
        return Ok(RegionSpec::Svg(file.into()));
    }
    if let Some(list) = s.strip_prefix("polygon:") {
        return polygon(list);
    }
    let parts: Vec<&str> = s.split(':').collect();
    match parts.as_slice() {
        ["rect", w, h] => {
            let width = length(w).map_err(|e| format!("rect:W:H: the width {e}"))?;
            let height = length(h).map_err(|e| format!("rect:W:H: the height {e}"))?;
            Ok(RegionSpec::Rect { width, height })
        }
        ["rect", ..] => Err("write rect:W:H with sizes in mm, for example rect:200:150".into()),
        ["circle", r] => Ok(RegionSpec::Circle {
            radius: length(r).map_err(|e| format!("circle:R: the radius {e}"))?,
        }),
        ["circle", ..] => Err("write circle:R with the radius in mm, for example circle:100".into()),
        ["annulus", ro, ri] => {
            let outer = length(ro).map_err(|e| format!("annulus:R_OUTER:R_INNER: R_OUTER {e}"))?;
            let inner = length(ri).map_err(|e| format!("annulus:R_OUTER:R_INNER: R_INNER {e}"))?;
            if inner >= outer {
                return Err(format!(
                    "annulus:R_OUTER:R_INNER: R_INNER ({ri}) must be smaller than R_OUTER ({ro})"
                ));
            }
            Ok(RegionSpec::Annulus { outer, inner })
        }
        ["annulus", ..] => Err("write annulus:R_OUTER:R_INNER in mm, for example annulus:100:40".into()),
        _ => Err(format!(
            "unknown region '{s}'; use rect:W:H, circle:R, annulus:R_OUTER:R_INNER, polygon:X1,Y1,X2,Y2,... or svg:FILE (sizes in mm)"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_reject_non_finite_and_out_of_range() {
        assert!(exponent("1").is_err());
        assert!(exponent("inf").is_err());
        assert!(exponent("NaN").is_err());
        assert!(fraction("1").is_err());
        assert!(fraction("0").is_err());
        assert!(positive("-2").is_err());
        assert!(region("rect:10:-1").is_err());
        assert!(region("rect:10").is_err());
        assert!(dimension("2").is_err());
        assert!(region("annulus:10:10").is_err());
        assert!(region("polygon:0,0,1,1").is_err());
        assert!(region("polygon:0,0,1,1,2").is_err());
        assert!(region("polygon:0,0,9,0,9,9/1,1,2").is_err());
        assert!(region("polygon:0,0,9,0,9,9/").is_err());
        assert!(region("circle:0").is_err());
    }

    #[test]
    fn masks_and_texts_parse_and_name_round_trip() {
        let mask = |s: &str| fill_region(s).ok().and_then(|r| r.input_name());
        assert_eq!(mask("mask:a.png").as_deref(), Some("mask:a.png:0.5"));
        assert_eq!(mask("mask:dir:x/a.png:0.25").as_deref(), Some("mask:dir:x/a.png:0.25"));
        assert_eq!(mask("mask:a.png:0.25:0.5").as_deref(), Some("mask:a.png:0.25:0.5"));
        for bad in ["mask:", "mask:a.png:1", "mask:a.png:0", "mask:a.png:nan", "mask::0.5", "text:"] {
            assert!(fill_region(bad).is_err(), "{bad}");
        }
        let Ok(RegionSpec::Text { lines }) = fill_region("text:a\\nb\\\\n\\q") else {
            panic!("text refused");
        };
        assert_eq!(lines, ["a", "b\\n\\q"]);
        for t in ["text:zeta", "text:a\\nb", "text:back\\\\slash", "text:x\\y"] {
            let name = mask(t).unwrap_or_default();
            assert_eq!(mask(&name).as_deref(), Some(name.as_str()), "{t}");
        }
        assert_eq!(mask("text:a\nb").as_deref(), Some("text:a\\nb"));
        assert!(fill_region("hexagon").err().unwrap_or_default().contains("text:STRING"));
        assert!(region("text:zeta").is_err());
    }

    #[test]
    fn polygon_rings_are_split_at_slashes() {
        let Ok(RegionSpec::Polygon { points, ends }) = region("polygon:0,0,9,0,9,9,0,9/2,2,4,2,4,4") else {
            panic!("two rings refused");
        };
        assert_eq!(ends, [4, 7]);
        assert_eq!((points[4].x, points[6].y), (2.0, 4.0));
        let e = region("polygon:0,0,9,0,9,9/1,1,2,2").err().unwrap_or_default();
        assert!(e.contains("(ring 2): a ring needs at least 3 vertices"), "{e}");
    }
}
