//! Machine profiles as data: TOML files (`render/machines/*.toml`, embedded in the binary as the
//! built-ins) read with serde into [`Machine`] and checked once by [`Machine::validate`], so
//! the writer can trust every field. Unknown or missing fields are errors that name the field.
//!
//! TOML is read behind the `toml` feature (on by default). Without it, as in the browser page,
//! there are no profile files and the built-ins are read from JSON the build script writes
//! from the same TOML files, through the same `Deserialize`; a test holds the two readings
//! equal.
//!
//! All lengths are mm and all feeds mm/min in the profile, whatever `units` says: `units`
//! only chooses what the G-code is written in (G21 mm with 3 decimals and whole mm/min
//! feeds; G20 inch with 5 decimals, feeds too).
//! The bed frame has (0, 0) at the bed's front-left corner, x right, y away from the user;
//! `origin` says where the machine's (0, 0) is and which way its y points.

mod blocks;
mod lists;

use crate::model::{Bounds, Pt};
pub use blocks::{printable, MAX_FEED, MIN_FEED};
use blocks::{Kind, Tool};
use serde::{Deserialize, Serialize};

/// Smallest bed side (mm).
pub const MIN_BED: f64 = 1.0;

/// Largest machine profile file (bytes).
pub const MAX_PROFILE_BYTES: u64 = 1 << 20;

// `BUILTIN_NAMES`, `BUILTINS` (name and TOML text) and `BUILTIN_JSON`, one entry per file of
// `render/machines/`, written by the build script.
include!(concat!(env!("OUT_DIR"), "/machines.rs"));

/// Units the G-code is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Millimetres (G21), 3 decimals, feeds in whole mm/min.
    Mm,
    /// Inches (G20), 5 decimals (0.254 µm, finer than the mm grid), feeds in in/min with 5
    /// decimals too (within 0.013 % of any feed from 1 mm/min up).
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
            Units::Inch => 5,
        }
    }

    /// Decimals of every feed (`F` word).
    pub fn feed_decimals(self) -> u32 {
        match self {
            Units::Mm => 0,
            Units::Inch => 5,
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
    /// Machine position to rapid to at the end, if any: exactly `[x, y]`.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "lists::park")]
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
    #[serde(deserialize_with = "lists::table")]
    pub bed: Bed,
    /// Feeds.
    #[serde(deserialize_with = "lists::table")]
    pub feed: Feeds,
    /// Laser power range (lasers only).
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "lists::optional_table")]
    pub power: Option<Power>,
}

fn default_pen_change() -> String {
    "M0\n".to_string()
}

impl Machine {
    /// A built-in profile by name.
    pub fn builtin(name: &str) -> Option<Machine> {
        Machine::read_builtin(name)?.ok()
    }

    /// A built-in read from its TOML text and checked, or `None` if no built-in has that name.
    #[cfg(feature = "toml")]
    fn read_builtin(name: &str) -> Option<Result<Machine, String>> {
        Machine::builtin_text(name).map(Machine::parse)
    }

    /// A built-in read from its JSON and checked, or `None` if no built-in has that name.
    #[cfg(not(feature = "toml"))]
    fn read_builtin(name: &str) -> Option<Result<Machine, String>> {
        BUILTIN_JSON
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, json)| Machine::from_json(json))
    }

    /// The TOML text of a built-in (with or without the `toml` feature: it is only text).
    pub fn builtin_text(name: &str) -> Option<&'static str> {
        BUILTINS.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
    }

    /// Names of the built-ins, sorted.
    pub fn builtin_names() -> Vec<&'static str> {
        BUILTIN_NAMES.to_vec()
    }

    /// Parses and checks a profile.
    #[cfg(feature = "toml")]
    pub fn parse(text: &str) -> Result<Machine, String> {
        // A parse error quotes the file: control bytes in it are shown as escapes.
        let m: Machine = toml::from_str(text).map_err(|e| printable(&e.to_string().trim_end().replace('\n', " ")))?;
        m.validate()?;
        Ok(m)
    }

    /// Reads and checks a built-in's JSON, the build script's copy of its TOML.
    #[cfg(any(test, not(feature = "toml")))]
    fn from_json(text: &str) -> Result<Machine, String> {
        let m: Machine = serde_json::from_str(text).map_err(|e| printable(&e.to_string()))?;
        m.validate()?;
        Ok(m)
    }

    /// `--machine`: a built-in name, or a profile file whose text `read` gives (the caller owns
    /// the file system; its error is the message's end, such as "it is not UTF-8 text").
    /// Without the `toml` feature a file is refused, with the names of the built-ins, and
    /// `read` is not called.
    pub fn load(spec: &str, read: impl FnOnce(&std::path::Path) -> Result<String, String>) -> Result<Machine, String> {
        if let Some(m) = Machine::read_builtin(spec) {
            return m.map_err(|e| format!("built-in '{spec}': {e}"));
        }
        let looks_like_file = spec.ends_with(".toml") || spec.contains('/') || spec.contains('\\');
        let names = || Machine::builtin_names().join(", ");
        #[cfg(feature = "toml")]
        {
            if !looks_like_file {
                return Err(format!(
                    "unknown machine '{spec}'; built-ins are {}, or give a profile FILE.toml (see `zetafill machines`)",
                    names()
                ));
            }
            let text = read(std::path::Path::new(spec)).map_err(|e| format!("cannot read '{spec}': {e}"))?;
            Machine::parse(&text).map_err(|e| format!("'{spec}': {e}"))
        }
        #[cfg(not(feature = "toml"))]
        {
            let _ = read;
            Err(if looks_like_file {
                format!(
                    "'{spec}': machine profile files need the `toml` feature, which this build leaves out; use a built-in: {}",
                    names()
                )
            } else {
                format!("unknown machine '{spec}'; built-ins are {}", names())
            })
        }
    }

    /// Checks every field; the message names the field.
    pub fn validate(&self) -> Result<(), String> {
        if self.name.trim().is_empty() {
            return Err("name: must not be empty".into());
        }
        // At least 1 mm: on a smaller bed a drawing fitted to it collapses onto a few points
        // of the G-code's 0.001 mm grid.
        let pos = |what: &str, v: f64, max: f64| -> Result<(), String> {
            if v.is_finite() && (MIN_BED..=max).contains(&v) {
                Ok(())
            } else {
                Err(format!(
                    "{what} = {}: must be positive, from {MIN_BED} to {max} mm",
                    crate::error::num(v)
                ))
            }
        };
        pos("bed.width", self.bed.width, 100_000.0)?;
        pos("bed.height", self.bed.height, 100_000.0)?;
        let feed = |what: &str, v: f64| -> Result<(), String> {
            if (blocks::MIN_FEED..=blocks::MAX_FEED).contains(&v) {
                Ok(())
            } else {
                Err(format!(
                    "{what} = {}: must lie between {} and {} mm/min",
                    crate::error::num(v),
                    blocks::MIN_FEED,
                    blocks::MAX_FEED
                ))
            }
        };
        feed("feed.draw", self.feed.draw)?;
        feed("feed.travel", self.feed.travel)?;
        if let Some(p) = &self.power {
            if !(p.min.is_finite() && p.max.is_finite() && p.min >= 0.0 && p.min < p.max && p.max <= 1e6) {
                return Err(format!(
                    "power: min {} and max {} must be finite with 0 <= min < max (at most 1000000)",
                    crate::error::num(p.min),
                    crate::error::num(p.max)
                ));
            }
            if !(p.default >= p.min && p.default <= p.max) {
                return Err(format!(
                    "power.default = {}: must be within min {} and max {}",
                    crate::error::num(p.default),
                    crate::error::num(p.min),
                    crate::error::num(p.max)
                ));
            }
        }
        if let Some(park) = self.park {
            let b = self.machine_bounds_mm();
            if !(park[0] >= b.x0 && park[0] <= b.x1 && park[1] >= b.y0 && park[1] <= b.y1) {
                return Err(format!(
                    "park = [{}, {}]: must be inside the bed (machine x {}..{}, y {}..{})",
                    crate::error::num(park[0]),
                    crate::error::num(park[1]),
                    b.x0,
                    b.x1,
                    b.y0,
                    b.y1
                ));
            }
        }
        self.check_blocks()
    }

    /// Checks every block's words, then runs the blocks in the writer's order on a model of
    /// the tool: `tool_on` must put the pen down or fire the laser, `tool_off` must undo it
    /// (a pen lifted higher than it was put down), and `pen_change` and `end` must leave the
    /// tool off: a laser off, a pen up as [`Tool::pen_up`] says.
    fn check_blocks(&self) -> Result<(), String> {
        let power = self.power.as_ref().map(|p| (p.min, p.max));
        let laser = power.is_some();
        let all = [
            (Kind::Start, &self.start),
            (Kind::ToolOn, &self.tool_on),
            (Kind::ToolOff, &self.tool_off),
            (Kind::PenChange, &self.pen_change),
            (Kind::End, &self.end),
        ];
        for (kind, text) in all {
            blocks::run(kind, text, power, &mut Tool::default())?;
        }
        if self.tool_on.trim().is_empty() || self.tool_off.trim().is_empty() {
            return Err("tool_on and tool_off: must not be empty".into());
        }
        // What tool_off alone sets: the pen is up there, or farther from where tool_on puts it.
        let mut lift = Tool::default();
        blocks::run(Kind::ToolOff, &self.tool_off, power, &mut lift)?;
        let mut t = Tool::default();
        blocks::run(Kind::Start, &self.start, power, &mut t)?;
        blocks::run(Kind::ToolOff, &self.tool_off, power, &mut t)?;
        let off = t;
        blocks::run(Kind::ToolOn, &self.tool_on, power, &mut t)?;
        let on = t;
        blocks::run(Kind::ToolOff, &self.tool_off, power, &mut t)?;
        let lifted = t;
        if laser && !on.laser_fires() {
            return Err(format!(
                "tool_on: must fire the laser (M3 or M4 with S above 0, or S{{power}}); it leaves {}",
                on.describe()
            ));
        }
        if !laser && off.pen_down(&on) {
            return Err(format!(
                "tool_on and tool_off: leave the tool the same ({}); tool_on must put the pen down (a Z or servo position) and tool_off lift it",
                off.describe()
            ));
        }
        if let (false, Some(down), Some(up)) = (laser, on.z, lifted.z) {
            if up <= down {
                return Err(format!("tool_off: lifts the pen to Z{up}, which is not above tool_on's Z{down}"));
            }
        }
        let fires = |s: &Tool| if laser { s.laser_fires() } else { !s.pen_up(&on, &lift) };
        if fires(&lifted) {
            return Err(format!(
                "tool_off: must {} ; after it the tool is still on ({})",
                if laser { "turn the laser off (M5, or S0)" } else { "lift the pen" },
                lifted.describe()
            ));
        }
        if fires(&off) {
            return Err(format!(
                "start and tool_off: leave the tool on for the first travel ({})",
                off.describe()
            ));
        }
        // A pause with the pen down where its position is known (the fields tool_off sets).
        let known_down = |s: &Tool| !laser && (lift.z.is_none() || s.z.is_some()) && (lift.s.is_none() || s.s.is_some()) && fires(s);
        blocks::run_with(Kind::Start, &self.start, power, &mut Tool::default(), Some(&known_down))?;
        for (kind, text) in [(Kind::PenChange, &self.pen_change), (Kind::End, &self.end)] {
            let mut s = lifted;
            blocks::run_with(kind, text, power, &mut s, Some(&known_down))?;
            if fires(&s) {
                return Err(format!(
                    "{}: must leave the tool off; it turns it on ({})",
                    kind.key(),
                    s.describe()
                ));
            }
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

    /// Seconds of `G4 P` dwell in a block (of a checked profile).
    pub fn dwell_seconds(block: &str) -> f64 {
        blocks::dwell_seconds(block)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtins_parse_and_validate() {
        let names = Machine::builtin_names();
        assert!(names.len() >= 3 && names.is_sorted(), "{names:?}");
        assert_eq!(BUILTINS.iter().map(|(n, _)| *n).collect::<Vec<_>>(), names);
        for name in names {
            let m = Machine::builtin(name).unwrap_or_else(|| panic!("{name} does not read: {:?}", Machine::read_builtin(name)));
            assert_eq!(m.name, name);
            let loaded = Machine::load(name, |_| Err("a built-in is not read from a file".into()));
            assert_eq!(loaded.as_ref().ok(), Some(&m), "{loaded:?}");
            assert!(Machine::builtin_text(name).is_some_and(|t| t.contains(&format!("name = \"{name}\""))));
        }
        let laser = Machine::builtin("grbl-laser").map(|m| m.power.is_some());
        assert_eq!(laser, Some(true));
        assert_eq!(Machine::dwell_seconds("M3 S90\nG4 P0.15 ; wait"), 0.15);
    }

    /// The JSON a build without the `toml` feature reads its built-ins from is the same
    /// profile as the TOML: every field, to the bit (the debug text tells -0.0 from 0.0).
    #[cfg(feature = "toml")]
    #[test]
    fn builtin_json_reads_as_its_toml() {
        assert_eq!(BUILTIN_JSON.len(), BUILTINS.len());
        for ((name, json), (toml_name, text)) in BUILTIN_JSON.iter().zip(BUILTINS) {
            assert_eq!(name, toml_name);
            let from_json = Machine::from_json(json).unwrap_or_else(|e| panic!("{name}: {e}\n{json}"));
            let from_toml = Machine::parse(text).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(from_json, from_toml, "{name}: {json}");
            assert_eq!(format!("{from_json:?}"), format!("{from_toml:?}"), "{name}: {json}");
        }
    }

    #[cfg(feature = "toml")]
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

    /// Bug: `tool_off = "M3 S1000"` in a laser profile was accepted (every rapid with the laser
    /// on, and the program ended with it on); so were `G91`, `G28` and a feed of 1e-300.
    #[cfg(feature = "toml")]
    #[test]
    fn profiles_that_leave_the_tool_on_or_leave_the_bed_are_refused() {
        let laser = Machine::builtin_text("grbl-laser").unwrap_or("");
        let servo = Machine::builtin_text("grbl-servo-pen").unwrap_or("");
        let z = Machine::builtin_text("z-lift-pen").unwrap_or("");
        let cases = [
            (
                laser.replace("tool_off = \"\"\"\nM5 S0", "tool_off = \"\"\"\nM3 S1000"),
                "tool_off: must turn the laser off",
            ),
            (laser.replace("M4 S{power}", "M5"), "tool_on: must fire the laser"),
            (
                laser.replace("end = \"\"\"\nM5 S0", "end = \"\"\"\nM4 S500"),
                "end: must leave the tool off",
            ),
            (
                laser.replace("start = \"\"\"\nM5 S0", "start = \"\"\"\nG91"),
                "start, line 1: 'G91'",
            ),
            (laser.replace("draw = 1000.0", "draw = 1e-300"), "feed.draw"),
            (laser.replace("travel = 3000.0", "travel = 1e300"), "feed.travel"),
            (
                servo.replace("M3 S30\nG4 P0.15", "M3 S90\nG4 P0.15"),
                "tool_on and tool_off: leave the tool the same",
            ),
            (
                servo.replace("pen_change = \"\"\"\nM0", "pen_change = \"\"\"\nM3 S90"),
                "pen_change: must leave the tool off",
            ),
            (servo.replace("M2\n", "G28\nM2\n"), "end, line 1: 'G28'"),
            (
                z.replace("tool_off = \"\"\"\nG0 Z3.000", "tool_off = \"\"\"\nG0 Z-1.000"),
                "not above tool_on's Z0",
            ),
            (
                z.replace("tool_on = \"\"\"\nG1 Z0.000 F600", "tool_on = \"\"\"\nG4 P0.1"),
                "tool_on and tool_off: leave the tool the same",
            ),
            (z.replace("G0 Z3.000\nM2", "G1 Z0.000 F600\nM2"), "end: must leave the tool off"),
            // Found by the fuzz targets: a servo moved between its angles (the pen touching)
            // and then a pause, in start, before tool_off lifts it.
            (
                servo.replace("start = \"\"\"\nM3 S30\nG4 P0.3", "start = \"\"\"\nM3 S30\nG4 P0.3\nM3 S44.16\nM0"),
                "start, line 4: 'M0': a pause with the pen down",
            ),
            (
                z.replace("pen_change = \"\"\"\nM0", "pen_change = \"\"\"\nG1 Z0.000 F600\nM0"),
                "pen_change, line 2: 'M0': a pause with the pen down",
            ),
        ];
        for (text, want) in cases {
            assert_ne!(text, laser);
            assert_ne!(text, servo);
            assert_ne!(text, z);
            let e = Machine::parse(&text).err().unwrap_or_default();
            assert!(e.contains(want), "expected '{want}', got '{e}'");
        }
    }

    #[cfg(feature = "toml")]
    #[test]
    fn toml_errors_show_control_bytes_as_escapes() {
        let e = Machine::parse("name = \"a\u{1b}[31m\nunits = ").err().unwrap_or_default();
        assert!(!e.chars().any(|c| c.is_control()), "{e:?}");
    }

    #[test]
    fn unknown_machine_lists_the_builtins() {
        let e = Machine::load("grbl-lazer", |_| Err("not read".into())).err().unwrap_or_default();
        assert!(e.contains("unknown machine") && e.contains("grbl-laser"), "{e}");
    }

    /// Without the `toml` feature a profile file is refused, naming the built-ins, unread.
    #[cfg(not(feature = "toml"))]
    #[test]
    fn without_toml_files_are_refused_naming_the_builtins() {
        for spec in ["my-plotter.toml", "profiles/plotter", "C:\\profiles\\plotter"] {
            let e = Machine::load(spec, |_| panic!("{spec} is read")).err().unwrap_or_default();
            assert!(
                e.contains(spec) && e.contains("`toml` feature") && e.contains("grbl-laser, grbl-servo-pen, z-lift-pen"),
                "{e}"
            );
        }
        let e = Machine::load("grbl-lazer", |_| panic!("read")).err().unwrap_or_default();
        assert!(!e.contains("FILE.toml"), "{e}");
    }
}
