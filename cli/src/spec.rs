//! Parsers for the values of `--shape` and `--region` and the number checks every flag shares.
//! Each returns a message that says what is wrong and what to write instead; clap adds the
//! flag's name and exits with code 2.

use zetafill::{Region, ShapeKind};

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

/// `circle | square | rect:ASPECT`.
pub fn shape(s: &str) -> Result<ShapeKind, String> {
    let mut parts = s.split(':');
    let name = parts.next().unwrap_or("");
    let rest: Vec<&str> = parts.collect();
    let k = match (name, rest.as_slice()) {
        ("circle", []) => ShapeKind::Circle,
        ("square", []) => ShapeKind::Square,
        ("rect", [a]) => {
            let aspect = positive(a).map_err(|e| format!("rect:ASPECT: the aspect ratio {e}"))?;
            ShapeKind::Rect { aspect }
        }
        ("rect", _) => return Err("write rect:ASPECT, for example rect:2 (width twice the height)".into()),
        _ => return Err(format!("unknown shape '{s}'; use circle, square or rect:ASPECT")),
    };
    Ok(k)
}

/// The name of a shape as written in JSON and on the command line.
pub fn shape_name(k: &ShapeKind) -> String {
    match k {
        ShapeKind::Circle => "circle".into(),
        ShapeKind::Square => "square".into(),
        ShapeKind::Rect { aspect } => format!("rect:{aspect}"),
    }
}

/// The region kinds accepted by `--region` (periodicity comes from `--periodic`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RegionSpec {
    /// `rect:W:H`.
    Rect {
        /// Width in mm.
        width: f64,
        /// Height in mm.
        height: f64,
    },
}

impl RegionSpec {
    /// The core region.
    pub fn region(&self, periodic: bool) -> Region {
        match *self {
            RegionSpec::Rect { width, height } => Region::Rect { width, height, periodic },
        }
    }
}

/// `rect:W:H` (sizes in mm).
pub fn region(s: &str) -> Result<RegionSpec, String> {
    let parts: Vec<&str> = s.split(':').collect();
    match parts.as_slice() {
        ["rect", w, h] => {
            let width = positive(w).map_err(|e| format!("rect:W:H: the width {e}"))?;
            let height = positive(h).map_err(|e| format!("rect:W:H: the height {e}"))?;
            Ok(RegionSpec::Rect { width, height })
        }
        ["rect", ..] => Err("write rect:W:H with sizes in mm, for example rect:200:150".into()),
        _ => Err(format!("unknown region '{s}'; use rect:W:H (sizes in mm)")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_parse_and_name_round_trip() {
        for s in ["circle", "square", "rect:2", "rect:0.5"] {
            let k = shape(s).unwrap_or(ShapeKind::Circle);
            assert_eq!(shape_name(&k), s);
        }
        assert!(shape("hexagon").is_err());
        assert!(shape("rect").is_err());
        assert!(shape("rect:0").is_err());
        assert!(shape("rect:nan").is_err());
    }

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
    }
}
