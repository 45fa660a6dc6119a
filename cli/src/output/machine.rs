//! Machine profiles as data: TOML files (`cli/machines/*.toml`, embedded in the binary as the
//! built-ins) read with serde into [`Machine`] and checked once by [`Machine::validate`], so
//! the writer can trust every field. Unknown or missing fields are errors that name the field.
//!
//! All lengths are mm and all feeds mm/min in the profile, whatever `units` says: `units`
//! only chooses what the G-code is written in (G21 mm with 3 decimals, G20 inch with 4).
//! The bed frame has (0, 0) at the bed's front-left corner, x right, y away from the user;
//! `origin` says where the machine's (0, 0) is and which way its y points.

use crate::model::{Bounds, Pt};
use serde::{Deserialize, Serialize};

/// The built-in profiles: name and TOML text.
pub const BUILTINS: &[(&str, &str)] = &[
    ("grbl-laser", include_str!("../../machines/grbl-laser.toml")),
    ("grbl-servo-pen", include_str!("../../machines/grbl-servo-pen.toml")),
    ("z-lift-pen", include_str!("../../machines/z-lift-pen.toml")),
];

/// Units the G-code is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Millimetres (G21), 3 decimals.
    Mm,
    /// Inches (G20), 4 decimals.
    Inch,
}

impl Units {
    /// Output units per mm.
    pub fn per_mm(self) -> f64 {
        match self {
            Units::Mm => 1.0,
            Units::Inch => 1.0 / 25.4,
        }
    }

    /// Decimals of every coordinate.
    pub fn decimals(self) -> u32 {
        match self {
            Units::Mm => 3,
            Units::Inch => 4,
        }
    }
}

/// Where the machine's (0, 0) is on the bed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Origin {
    /// Front-left corner, y away from the user: machine = bed frame.
    BottomLeft,
    /// Back-left corner, y towards the user (y mirrored, so drawings stay upright).
    TopLeft,
    /// Centre of the bed, y away from the user.
    Center,
}

/// How the pen travels between paths (always with the tool off).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Travel {
    /// `G0` rapids.
    #[default]
    Rapid,
    /// `G1` at the travel feed.
    Feed,
}

/// The bed in mm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Bed {
    /// Width (x) in mm.
    pub width: f64,
    /// Depth (y) in mm.
    pub height: f64,
}

/// Feeds in mm/min.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Feeds {
    /// While drawing or cutting.
    pub draw: f64,
    /// Between paths (G1 travel, and the time estimate of rapids).
    pub travel: f64,
}

/// A laser's power range (the S word).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Power {
    /// Lowest S.
    pub min: f64,
    /// Highest S.
    pub max: f64,
    /// S used without `--power`.
    pub default: f64,
}

/// A machine profile.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Machine {
    /// Short name.
    pub name: String,
    /// One line about the machine.
    pub description: String,
    /// Output units.
    pub units: Units,
    /// Where the machine's (0, 0) is.
    pub origin: Origin,
    /// Whether G2/G3 arcs may be used.
    pub arcs: bool,
    /// Travel moves.
    #[serde(default)]
    pub travel: Travel,
    /// Machine position to rapid to at the end, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub park: Option<[f64; 2]>,
    /// Lines written once before drawing.
    pub start: String,
    /// Lines that put the pen down or the laser on.
    pub tool_on: String,
    /// Lines that lift the pen or turn the laser off.
    pub tool_off: String,
    /// Lines written where one pen is swapped for the next (`--layers colours`), with the
    /// tool off and the head parked: by default `M0`, a pause until the operator resumes.
    #[serde(default = "default_pen_change")]
    pub pen_change: String,
    /// Lines written once at the end.
    pub end: String,
    /// The bed.
    pub bed: Bed,
    /// Feeds.
    pub feed: Feeds,
    /// Laser power range (lasers only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power: Option<Power>,
}

fn default_pen_change() -> String {
    "M0\n".to_string()
}

/// Placeholders a block may hold.
const PLACEHOLDERS: &[&str] = &["{power}", "{feed}", "{travel_feed}"];

impl Machine {
    /// A built-in profile by name.
    pub fn builtin(name: &str) -> Option<Machine> {
        BUILTINS
            .iter()
            .find(|(n, _)| *n == name)
            .and_then(|(_, text)| Machine::parse(text).ok())
    }

    /// The TOML text of a built-in.
    pub fn builtin_text(name: &str) -> Option<&'static str> {
        BUILTINS.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
    }

    /// Names of the built-ins.
    pub fn builtin_names() -> Vec<&'static str> {
        BUILTINS.iter().map(|(n, _)| *n).collect()
    }

    /// Parses and checks a profile.
    pub fn parse(text: &str) -> Result<Machine, String> {
        let m: Machine = toml::from_str(text).map_err(|e| e.to_string().trim_end().replace('\n', " "))?;
        m.validate()?;
        Ok(m)
    }

    /// `--machine`: a built-in name, or a path to a `.toml` file.
    pub fn load(spec: &str) -> Result<Machine, String> {
        if let Some(m) = Machine::builtin_text(spec) {
            return Machine::parse(m).map_err(|e| format!("built-in '{spec}': {e}"));
        }
        let path = std::path::Path::new(spec);
        let looks_like_file = spec.ends_with(".toml") || spec.contains('/') || spec.contains('\\');
        if !looks_like_file {
            return Err(format!(
                "unknown machine '{spec}'; built-ins are {}, or give a profile FILE.toml (see `zetafill machines`)",
                Machine::builtin_names().join(", ")
            ));
        }
        let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read '{spec}': {e}"))?;
        Machine::parse(&text).map_err(|e| format!("'{spec}': {e}"))
    }

    /// Checks every field; the message names the field.
    pub fn validate(&self) -> Result<(), String> {
        if self.name.trim().is_empty() {
            return Err("name: must not be empty".into());
        }
        let pos = |what: &str, v: f64, max: f64| -> Result<(), String> {
            if v.is_finite() && v > 0.0 && v <= max {
                Ok(())
            } else {
                Err(format!("{what} = {v}: must be positive (at most {max})"))
            }
        };
        pos("bed.width", self.bed.width, 100_000.0)?;
        pos("bed.height", self.bed.height, 100_000.0)?;
        pos("feed.draw", self.feed.draw, 1e6)?;
        pos("feed.travel", self.feed.travel, 1e6)?;
        if let Some(p) = &self.power {
            if !(p.min.is_finite() && p.max.is_finite() && p.min >= 0.0 && p.min < p.max && p.max <= 1e6) {
                return Err(format!("power: min {} and max {} must be finite with 0 <= min < max", p.min, p.max));
            }
            if !(p.default >= p.min && p.default <= p.max) {
                return Err(format!(
                    "power.default = {}: must be within min {} and max {}",
                    p.default, p.min, p.max
                ));
            }
        }
        if let Some(park) = self.park {
            let b = self.machine_bounds_mm();
            if !(park[0] >= b.x0 && park[0] <= b.x1 && park[1] >= b.y0 && park[1] <= b.y1) {
                return Err(format!(
                    "park = [{}, {}]: must be inside the bed (machine x {}..{}, y {}..{})",
                    park[0], park[1], b.x0, b.x1, b.y0, b.y1
                ));
            }
        }
        for (field, text) in [
            ("start", &self.start),
            ("tool_on", &self.tool_on),
            ("tool_off", &self.tool_off),
            ("pen_change", &self.pen_change),
            ("end", &self.end),
        ] {
            check_block(field, text, self.power.is_some())?;
        }
        if self.tool_on.trim().is_empty() || self.tool_off.trim().is_empty() {
            return Err("tool_on and tool_off: must not be empty".into());
        }
        Ok(())
    }

    /// The area a drawing may use in the bed frame: the bed less `margin` on every side.
    pub fn usable_area(&self, margin: f64) -> Bounds {
        Bounds {
            x0: margin,
            y0: margin,
            x1: self.bed.width - margin,
            y1: self.bed.height - margin,
        }
    }

    /// The bed in machine coordinates (mm).
    pub fn machine_bounds_mm(&self) -> Bounds {
        let (w, h) = (self.bed.width, self.bed.height);
        match self.origin {
            Origin::BottomLeft | Origin::TopLeft => Bounds {
                x0: 0.0,
                y0: 0.0,
                x1: w,
                y1: h,
            },
            Origin::Center => Bounds {
                x0: -w / 2.0,
                y0: -h / 2.0,
                x1: w / 2.0,
                y1: h / 2.0,
            },
        }
    }

    /// Bed frame to machine frame (mm): `(x, y) -> (x + dx, sy * y + dy)`.
    pub fn bed_to_machine(&self) -> (f64, f64, f64) {
        let (w, h) = (self.bed.width, self.bed.height);
        match self.origin {
            Origin::BottomLeft => (1.0, 0.0, 0.0),
            Origin::TopLeft => (-1.0, 0.0, h),
            Origin::Center => (1.0, -w / 2.0, -h / 2.0),
        }
    }

    /// Machine (0, 0) in the bed frame: where the pen is when the program starts.
    pub fn home_in_bed(&self) -> Pt {
        let (w, h) = (self.bed.width, self.bed.height);
        match self.origin {
            Origin::BottomLeft => [0.0, 0.0],
            Origin::TopLeft => [0.0, h],
            Origin::Center => [w / 2.0, h / 2.0],
        }
    }

    /// Seconds of `G4 P` dwell in a block.
    pub fn dwell_seconds(block: &str) -> f64 {
        block
            .lines()
            .map(strip_comment)
            .filter(|l| words(l).iter().any(|(c, v)| *c == 'G' && v == "4"))
            .filter_map(|l| {
                words(l)
                    .into_iter()
                    .find(|(c, _)| *c == 'P')
                    .and_then(|(_, v)| v.parse::<f64>().ok())
            })
            .sum()
    }
}

fn strip_comment(line: &str) -> &str {
    let line = line.split(';').next().unwrap_or("");
    line.split('(').next().unwrap_or("")
}

/// The words of a G-code line (letter, number text), placeholders kept as numbers.
fn words(line: &str) -> Vec<(char, String)> {
    let mut out: Vec<(char, String)> = Vec::new();
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        if c.is_ascii_alphabetic() {
            let mut v = String::new();
            while let Some(&d) = chars.peek() {
                if d.is_ascii_digit()
                    || d == '.'
                    || d == '-'
                    || d == '+'
                    || d == '{'
                    || d == '}'
                    || d == '_'
                    || d.is_ascii_lowercase() && v.starts_with('{')
                {
                    v.push(d);
                    chars.next();
                } else {
                    break;
                }
            }
            out.push((c.to_ascii_uppercase(), v));
        }
    }
    out
}

fn check_block(field: &str, text: &str, has_power: bool) -> Result<(), String> {
    for (n, raw) in text.lines().enumerate() {
        let line = strip_comment(raw);
        let mut rest = line.to_string();
        for p in PLACEHOLDERS {
            if *p == "{power}" && rest.contains(p) && !has_power {
                return Err(format!("{field}, line {}: {{power}} needs a [power] range in the profile", n + 1));
            }
            rest = rest.replace(p, "0");
        }
        let b = rest.as_bytes();
        if b.windows(2).any(|w| w[0].is_ascii_digit() && (w[1] == b'e' || w[1] == b'E')) {
            return Err(format!(
                "{field}, line {}: '{}': numbers must be plain decimals, not exponent notation",
                n + 1,
                raw.trim()
            ));
        }
        if rest.contains('{') || rest.contains('}') {
            return Err(format!(
                "{field}, line {}: '{}': the only placeholders are {}",
                n + 1,
                raw.trim(),
                PLACEHOLDERS.join(", ")
            ));
        }
        for (c, v) in words(&rest) {
            if matches!(c, 'X' | 'Y' | 'I' | 'J' | 'R') {
                return Err(format!(
                    "{field}, line {}: '{}': blocks may not move in X or Y (the writer keeps every X/Y move inside the bed; use `park` for an end position)",
                    n + 1,
                    raw.trim()
                ));
            }
            let plain = !v.is_empty()
                && v.trim_start_matches(['-', '+']).chars().all(|d| d.is_ascii_digit() || d == '.')
                && v.matches('.').count() <= 1;
            if !plain {
                return Err(format!(
                    "{field}, line {}: '{}': '{c}{v}' is not a plain decimal number",
                    n + 1,
                    raw.trim()
                ));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtins_parse_and_validate() {
        for name in Machine::builtin_names() {
            let m = Machine::builtin(name).unwrap_or_else(|| {
                panic!(
                    "{name} does not parse: {:?}",
                    Machine::parse(Machine::builtin_text(name).unwrap_or(""))
                )
            });
            assert_eq!(m.name, name);
        }
        let laser = Machine::builtin("grbl-laser").map(|m| m.power.is_some());
        assert_eq!(laser, Some(true));
        assert_eq!(Machine::dwell_seconds("M3 S90\nG4 P0.15 ; wait"), 0.15);
    }

    #[test]
    fn bad_profiles_name_the_field() {
        let good = Machine::builtin_text("grbl-servo-pen").unwrap_or("");
        let cases = [
            (good.replace("name = \"grbl-servo-pen\"\n", ""), "name"),
            (good.replace("draw = 3000.0", "draw = -1.0"), "feed.draw"),
            (good.replace("draw = 3000.0", "draw = \"fast\""), "draw"),
            (good.replace("width = 300.0", "width = 0.0"), "bed.width"),
            (good.replace("arcs = true", "arcs = true\nspeed = 3"), "speed"),
            (good.replace("M3 S90", "M3 S9e1"), "plain decimals"),
            (good.replace("M3 S90", "G0 X10 Y10"), "X or Y"),
            (good.replace("M3 S90", "M3 S{power}"), "{power}"),
            (good.replace("park = [0.0, 0.0]", "park = [500.0, 0.0]"), "park"),
            (good.replace("origin = \"bottom-left\"", "origin = \"left\""), "origin"),
        ];
        for (text, want) in cases {
            let e = Machine::parse(&text).err().unwrap_or_default();
            assert!(e.contains(want), "expected an error naming {want}, got '{e}'");
        }
    }

    #[test]
    fn unknown_machine_lists_the_builtins() {
        let e = Machine::load("grbl-lazer").err().unwrap_or_default();
        assert!(e.contains("unknown machine") && e.contains("grbl-laser"), "{e}");
    }
}
