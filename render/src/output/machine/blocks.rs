//! What a profile's G-code blocks may say, and what state they leave the tool in.
//!
//! The writer keeps every X/Y move inside the bed and the tool off for every travel, but only
//! if the blocks it copies in cannot undo that. So each block kind has an allow-list of words
//! (anything else is refused, with the word and the reason), and the blocks are run on a
//! small model of the tool: `tool_on` must put the pen down or the laser on, `tool_off` must
//! undo it, and `pen_change` and `end` must leave the tool off.
//!
//! Allowed everywhere: `G0`/`G1` with `Z` and `F` (a pen lift), `G4 P` (a dwell of at most
//! [`MAX_DWELL`] s), `G17`, `G90`, `G94` (the modes the writer already sets), `M3`/`M4`/`M5`
//! with `S`, `M7`/`M8`/`M9` (air assist or coolant), and a bare `F` or `S`. Also `M0`/`M1`
//! (a pause) in `start`, `pen_change` and `end`; `M6` and `T` in `pen_change`; `M2`/`M30` in
//! `end`. Refused because they move the head off the bed or change what every coordinate
//! means: `G91`, `G20`/`G21` (the profile's `units` decide), `G28`, `G30`, `G53`, `G54`..`G59`,
//! `G92`, `G18`, `G19`, `G93`, `G95`, arcs; and any other letter or character (a GRBL `$`
//! command, a `%` tape mark, `#` parameters).

use std::fmt::Write as _;

/// Longest dwell a block may hold (seconds).
pub const MAX_DWELL: f64 = 600.0;
/// Largest |Z| a block may move to (output units).
pub const MAX_Z: f64 = 1_000.0;
/// Feeds (mm/min, in the profile and in an `F` word) lie in `[MIN_FEED, MAX_FEED]`.
pub const MIN_FEED: f64 = 1.0;
/// See [`MIN_FEED`].
pub const MAX_FEED: f64 = 1_000_000.0;
/// Largest `S` word.
pub const MAX_S: f64 = 1_000_000.0;

/// The five kinds of block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// `start`, once before drawing.
    Start,
    /// `tool_on`: pen down or laser on.
    ToolOn,
    /// `tool_off`: pen up or laser off.
    ToolOff,
    /// `pen_change`, between two pens, tool off and parked.
    PenChange,
    /// `end`, once at the end.
    End,
}

impl Kind {
    /// The profile key.
    pub fn key(self) -> &'static str {
        match self {
            Kind::Start => "start",
            Kind::ToolOn => "tool_on",
            Kind::ToolOff => "tool_off",
            Kind::PenChange => "pen_change",
            Kind::End => "end",
        }
    }
}

/// The spindle output: a laser's power or a servo pen's position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spindle {
    /// `M5`.
    Off,
    /// `M3` or `M4`.
    On,
}

/// What a block leaves behind, as far as the tool is concerned: `None` for what no block
/// has said yet.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Tool {
    /// The spindle, after `M3`, `M4` or `M5`.
    pub spindle: Option<Spindle>,
    /// The last `S` (the placeholder `{power}` counts as a positive power).
    pub s: Option<f64>,
    /// The last `Z`.
    pub z: Option<f64>,
}

impl Tool {
    /// A laser fires when its spindle is on with a power above 0.
    pub fn laser_fires(&self) -> bool {
        self.spindle == Some(Spindle::On) && self.s.is_some_and(|s| s > 0.0)
    }

    /// Whether this state is the pen-down state `on`: equal in everything `on` sets.
    pub fn pen_down(&self, on: &Tool) -> bool {
        (on.spindle.is_none() || self.spindle == on.spindle) && (on.s.is_none() || self.s == on.s) && (on.z.is_none() || self.z == on.z)
    }

    /// Whether this state has the pen up, for a pen that `tool_off` alone leaves as `lift`
    /// and `tool_on` as `on`: in everything `lift` sets, a Z above `on`'s (or at least
    /// `lift`'s, when `on` sets none), a servo angle at `lift`'s or farther from `on`'s
    /// (or the spindle off once an angle is set), the spindle off if `lift` turns it off.
    /// A pen below its down position, or a servo between its two angles, is down.
    pub fn pen_up(&self, on: &Tool, lift: &Tool) -> bool {
        let z_up = match (lift.z, on.z) {
            (None, _) => true,
            (Some(_), Some(down)) => self.z.is_some_and(|z| z > down),
            (Some(up), None) => self.z.is_some_and(|z| z >= up),
        };
        let s_up = match lift.s {
            None => true,
            Some(up) => {
                let off = self.spindle == Some(Spindle::Off) && self.s.is_some();
                let past = |s: f64| match on.s {
                    Some(down) if down != up => (s - down) * (up - down) >= (up - down) * (up - down),
                    _ => s == up,
                };
                off || self.s.is_some_and(past)
            }
        };
        let spindle_up = lift.spindle != Some(Spindle::Off) || self.spindle == Some(Spindle::Off);
        let lifts = lift.z.is_some() || lift.s.is_some() || lift.spindle == Some(Spindle::Off);
        lifts && z_up && s_up && spindle_up
    }

    /// The words of the tool's state, for messages.
    pub fn describe(&self) -> String {
        let mut s = String::new();
        match self.spindle {
            Some(Spindle::On) => s.push_str("spindle on"),
            Some(Spindle::Off) => s.push_str("spindle off"),
            None => s.push_str("spindle unset"),
        }
        if let Some(v) = self.s {
            let _ = write!(s, ", S{v}");
        }
        if let Some(z) = self.z {
            let _ = write!(s, ", Z{z}");
        }
        s
    }
}

/// A line shown in a message: trimmed, control characters written as escapes.
pub fn shown(line: &str) -> String {
    printable(line.trim())
}

/// `text` with every control character written as `\u{..}`, so that a message never
/// carries bytes that move a terminal's cursor.
pub fn printable(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() && c != ' ' {
            let _ = write!(out, "\\u{{{:x}}}", c as u32);
        } else {
            out.push(c);
        }
    }
    out
}

/// The line without its comments, as a controller reads it: `(` to the next `)` is left out
/// and reading goes on after it; `;` ends the line. A `(` left open is refused (controllers
/// differ on what follows it).
fn strip_comment(line: &str) -> Result<String, String> {
    let mut out = String::with_capacity(line.len());
    let mut open = false;
    for c in line.chars() {
        match (open, c) {
            (true, ')') => open = false,
            (true, _) => {}
            (false, ';') => break,
            (false, '(') => open = true,
            (false, c) => out.push(c),
        }
    }
    if open {
        return Err("a comment opened with '(' is not closed on its line".into());
    }
    Ok(out)
}

/// Placeholders a block may hold, and the value a check stands in for each.
const PLACEHOLDERS: &[(&str, &str)] = &[("{power}", "1"), ("{feed}", "1000"), ("{travel_feed}", "1000")];

/// Checks `text` as a block of `kind` and runs it on `tool`. `power` is the laser's S range,
/// if the profile is a laser's.
pub fn run(kind: Kind, text: &str, power: Option<(f64, f64)>, tool: &mut Tool) -> Result<(), String> {
    run_with(kind, text, power, tool, None)
}

/// [`run`], refusing as well a pause (`M0`, `M1`) while `pen_down` says the pen is down: an
/// operator who changes the paper or the pen there meets a pen on the paper.
pub fn run_with(
    kind: Kind,
    text: &str,
    power: Option<(f64, f64)>,
    tool: &mut Tool,
    pen_down: Option<&dyn Fn(&Tool) -> bool>,
) -> Result<(), String> {
    let field = kind.key();
    for (n, raw) in text.lines().enumerate() {
        let at = |why: String| format!("{field}, line {}: '{}': {why}", n + 1, shown(raw));
        let mut line = strip_comment(raw).map_err(&at)?;
        for (p, stand_in) in PLACEHOLDERS {
            if *p == "{power}" && line.contains(p) && power.is_none() {
                return Err(format!("{field}, line {}: {{power}} needs a [power] range in the profile", n + 1));
            }
            line = line.replace(p, stand_in);
        }
        let b = line.as_bytes();
        if b.windows(2).any(|w| w[0].is_ascii_digit() && (w[1] == b'e' || w[1] == b'E')) {
            return Err(at("numbers must be plain decimals, not exponent notation".into()));
        }
        if line.contains('{') || line.contains('}') {
            let names: Vec<&str> = PLACEHOLDERS.iter().map(|(p, _)| *p).collect();
            return Err(at(format!("the only placeholders are {}", names.join(", "))));
        }
        if let Some(c) = line
            .chars()
            .find(|c| !(c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '+' | ' ' | '\t')))
        {
            return Err(at(format!(
                "'{}' is not part of a G-code word (no GRBL $ commands, % marks or # parameters in a profile)",
                printable(&c.to_string())
            )));
        }
        let words = words(&line).map_err(&at)?;
        check_line(kind, &words, power).map_err(&at)?;
        let pause = words.iter().any(|w| w.letter == 'M' && matches!(tenths(w.value), 0 | 10));
        if pause && power.is_some() && tool.laser_fires() {
            return Err(at("a pause with the laser on; turn it off first (M5)".into()));
        }
        if pause && pen_down.is_some_and(|down| down(tool)) {
            return Err(at(format!("a pause with the pen down ({}); lift it first", tool.describe())));
        }
        for w in &words {
            match (w.letter, tenths(w.value)) {
                ('M', 30 | 40) => tool.spindle = Some(Spindle::On),
                ('M', 50) => tool.spindle = Some(Spindle::Off),
                ('S', _) => tool.s = Some(w.value),
                ('Z', _) => tool.z = Some(w.value),
                _ => {}
            }
        }
    }
    Ok(())
}

/// A word: its letter and value.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Word {
    letter: char,
    value: f64,
}

impl Word {
    fn code(&self) -> String {
        format!("{}{}", self.letter, self.value)
    }
}

/// Whether `v` is a plain decimal as the writer writes its own numbers: an optional `-`,
/// digits, and optionally a `.` and digits; not a negative zero.
fn plain(v: &str) -> bool {
    let body = v.strip_prefix('-').unwrap_or(v);
    let (int, frac) = body.split_once('.').unwrap_or((body, "0"));
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    digits(int) && digits(frac) && !(v.starts_with('-') && body.bytes().all(|b| b == b'0' || b == b'.'))
}

/// The words of a line (letters upper-cased); a letter not followed at once by a plain
/// decimal ([`plain`]) is refused.
fn words(line: &str) -> Result<Vec<Word>, String> {
    let mut out = Vec::new();
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        if c == ' ' || c == '\t' {
            continue;
        }
        if !c.is_ascii_alphabetic() {
            return Err(format!("'{c}' does not follow a letter; a word is a letter and a plain decimal"));
        }
        let mut v = String::new();
        while let Some(&d) = chars.peek() {
            if d.is_ascii_digit() || matches!(d, '.' | '-' | '+') {
                v.push(d);
                chars.next();
            } else {
                break;
            }
        }
        let value = v.parse::<f64>().ok().filter(|x| plain(&v) && x.is_finite());
        let Some(value) = value else {
            return Err(format!(
                "'{c}{v}' is not a letter followed at once by a plain decimal (as Z3 or S0.5: no space, no + and no -0)"
            ));
        };
        out.push(Word {
            letter: c.to_ascii_uppercase(),
            value,
        });
    }
    Ok(out)
}

/// A G or M number in tenths (`G59.1` is 591), so that codes match as integers.
fn tenths(v: f64) -> i64 {
    (v * 10.0).round() as i64
}

/// Why a G code is refused, or `None` if blocks may use it.
fn refused_g(g: f64) -> Option<&'static str> {
    Some(match tenths(g) {
        0 | 10 | 40 | 170 | 900 | 940 => return None,
        910 | 911 => "relative moves would take the head off the bed",
        200 | 210 => "the profile's `units` sets the units; a block may not change them",
        280 | 281 | 300 | 301 => "it moves to a stored position the writer cannot keep on the bed; use `park` for an end position",
        530 => "it moves in machine coordinates, outside the writer's bed check",
        540..=599 | 920..=929 => "it changes the coordinate offset, which would shift every coordinate off the declared bed",
        180 | 190 => "it changes the arc plane; the writer's arcs are in XY",
        930 | 950 => "it changes the feed mode; the writer's feeds are mm (or inch) per minute",
        20 | 30 => "blocks may not move in X or Y (the writer keeps every X/Y move inside the bed; use `park` for an end position)",
        _ => "it is not among the G codes a profile block may use (G0/G1 Z, G4 P, G17, G90, G94)",
    })
}

fn check_line(kind: Kind, words: &[Word], power: Option<(f64, f64)>) -> Result<(), String> {
    let g = |code: i64| words.iter().any(|w| w.letter == 'G' && tenths(w.value) == code);
    let dwell = g(40);
    for w in words {
        match w.letter {
            'G' => {
                if let Some(why) = refused_g(w.value) {
                    return Err(format!("'{}' is not allowed: {why}", w.code()));
                }
            }
            'M' => {
                let ok = match tenths(w.value) {
                    30 | 40 | 50 | 70 | 80 | 90 => true,
                    0 | 10 => kind != Kind::ToolOn && kind != Kind::ToolOff,
                    60 => kind == Kind::PenChange,
                    20 | 300 => kind == Kind::End,
                    _ => false,
                };
                if !ok {
                    return Err(format!(
                        "'{}' is not allowed in {}; {} blocks may use {}",
                        w.code(),
                        kind.key(),
                        kind.key(),
                        m_codes(kind)
                    ));
                }
            }
            'X' | 'Y' | 'I' | 'J' | 'R' => {
                return Err(
                    "blocks may not move in X or Y (the writer keeps every X/Y move inside the bed; use `park` for an end position)".into(),
                );
            }
            'Z' => {
                if w.value.abs() > MAX_Z {
                    return Err(format!("'{}': Z must lie within ±{MAX_Z}", w.code()));
                }
            }
            'F' => {
                if !(MIN_FEED..=MAX_FEED).contains(&w.value) {
                    return Err(format!("'{}': a feed must lie between {MIN_FEED} and {MAX_FEED}", w.code()));
                }
            }
            'S' => {
                let max = power.map_or(MAX_S, |(_, hi)| hi);
                if !(0.0..=max).contains(&w.value) {
                    return Err(format!("'{}': S must lie between 0 and {max}", w.code()));
                }
            }
            'P' => {
                if !dwell {
                    return Err(format!("'{}': a P word belongs to a G4 dwell", w.code()));
                }
                if !(0.0..=MAX_DWELL).contains(&w.value) {
                    return Err(format!("'{}': a dwell must lie between 0 and {MAX_DWELL} s", w.code()));
                }
            }
            'T' if kind == Kind::PenChange => {}
            c => {
                return Err(format!(
                    "'{}' words are not allowed in {} (a block may use G, M, S, F, Z and P{})",
                    c,
                    kind.key(),
                    if kind == Kind::PenChange { " and T" } else { "" }
                ));
            }
        }
    }
    if dwell && !words.iter().any(|w| w.letter == 'P') {
        return Err("a G4 dwell needs its P word (seconds)".into());
    }
    // A controller refuses a line that repeats a letter, and does nothing of what it says.
    for (i, w) in words.iter().enumerate() {
        if words[..i].iter().any(|o| o.letter == w.letter) {
            return Err(format!(
                "'{}' comes twice on the line, which a controller refuses; give each its own line",
                w.letter
            ));
        }
    }
    // A Z alone moves in whatever mode the line before left: after an arc the controller
    // refuses it (no centre) and the pen stays where it was.
    if let Some(z) = words.iter().find(|w| w.letter == 'Z') {
        if !(g(0) || g(10)) {
            return Err(format!(
                "'{}' needs G0 or G1 on its line (alone it moves in the mode the line before left)",
                z.code()
            ));
        }
    }
    // The first G1 of a block may come before any feed was set: a controller refuses it.
    if g(10) && !words.iter().any(|w| w.letter == 'F') {
        return Err("'G1' needs its F on the same line (no feed may be set yet when the block runs)".into());
    }
    Ok(())
}

/// Seconds of `G4 P` dwell in a block that [`run`] accepted.
pub fn dwell_seconds(block: &str) -> f64 {
    let mut total = 0.0;
    for raw in block.lines() {
        let Ok(mut line) = strip_comment(raw) else { continue };
        for (p, stand_in) in PLACEHOLDERS {
            line = line.replace(p, stand_in);
        }
        let Ok(words) = words(&line) else { continue };
        if words.iter().any(|w| w.letter == 'G' && tenths(w.value) == 40) {
            total += words.iter().filter(|w| w.letter == 'P').map(|w| w.value).sum::<f64>();
        }
    }
    total
}

fn m_codes(kind: Kind) -> &'static str {
    match kind {
        Kind::Start => "M0, M1, M3, M4, M5, M7, M8, M9",
        Kind::ToolOn | Kind::ToolOff => "M3, M4, M5, M7, M8, M9",
        Kind::PenChange => "M0, M1, M3, M4, M5, M6, M7, M8, M9",
        Kind::End => "M0, M1, M2, M3, M4, M5, M7, M8, M9, M30",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(kind: Kind, text: &str) -> Result<Tool, String> {
        let mut t = Tool::default();
        run(kind, text, Some((0.0, 1000.0)), &mut t).map(|()| t)
    }

    #[test]
    fn the_built_in_words_pass_and_set_the_tool() {
        let t = check(Kind::ToolOn, "M4 S{power}\nG4 P0.15 ; wait\nG1 Z0.000 F600").unwrap_or_else(|e| panic!("{e}"));
        assert!(t.laser_fires());
        assert_eq!(t.z, Some(0.0));
        let t = check(Kind::ToolOff, "M5 S0").unwrap_or_else(|e| panic!("{e}"));
        assert!(!t.laser_fires());
        assert!(check(Kind::End, "M5 S0\nM9\nM2").is_ok());
        assert!(check(Kind::PenChange, "M0\nM6 T2").is_ok());
    }

    #[test]
    fn every_refused_word_is_named() {
        for (kind, text, want) in [
            (Kind::Start, "G91", "'G91'"),
            (Kind::Start, "G20", "'G20'"),
            (Kind::Start, "G21", "units"),
            (Kind::End, "G28", "'G28'"),
            (Kind::End, "G30", "'G30'"),
            (Kind::Start, "G53 Z0", "'G53'"),
            (Kind::Start, "G54", "'G54'"),
            (Kind::Start, "G59.1", "offset"),
            (Kind::Start, "G92 Z0", "'G92'"),
            (Kind::Start, "G18", "'G18'"),
            (Kind::Start, "G93", "'G93'"),
            (Kind::ToolOn, "G2", "X or Y"),
            (Kind::ToolOn, "G0 X1", "X or Y"),
            (Kind::Start, "M2", "'M2'"),
            (Kind::ToolOn, "M0", "'M0'"),
            (Kind::Start, "M6 T1", "'M6'"),
            (Kind::Start, "M62 P1", "'M62'"),
            (Kind::Start, "$H", "'$'"),
            (Kind::Start, "%", "'%'"),
            (Kind::Start, "#1=2", "'#'"),
            (Kind::Start, "N10 G90", "'N'"),
            (Kind::Start, "H1", "'H'"),
            (Kind::ToolOn, "G1 Z0 F0", "'F0'"),
            (Kind::ToolOn, "G1 Z0 F2000000", "feed"),
            (Kind::ToolOn, "G0 Z5000", "Z must"),
            (Kind::ToolOn, "M3 S2000", "S must"),
            (Kind::ToolOn, "M3 S-1", "S must"),
            (Kind::ToolOn, "G4 P1000", "dwell"),
            (Kind::ToolOn, "G4", "P word"),
            (Kind::ToolOn, "M3 P2", "G4"),
            (Kind::ToolOn, "M3 S1e3", "exponent"),
            (Kind::ToolOn, "M3 S9-0", "plain decimal"),
            (Kind::ToolOn, "M3 S", "plain decimal"),
            (Kind::ToolOn, "M3 S{speed}", "placeholders"),
            // Found by the fuzz targets (cli/tests/fuzz.rs): lines a controller reads
            // otherwise than this check did.
            (Kind::ToolOff, "Z3.000", "needs G0 or G1"),
            (Kind::ToolOff, "G0 Z3 Z5", "comes twice"),
            (Kind::ToolOff, "M5 M3", "comes twice"),
            (Kind::ToolOn, "G1 Z0", "needs its F"),
            (Kind::ToolOff, "M5 S0 (off) X500", "X or Y"),
            (Kind::ToolOff, "M5 S0 (off", "not closed"),
            (Kind::ToolOff, "G0 Z 3", "at once"),
            (Kind::ToolOn, "M3 S+5", "at once"),
            (Kind::ToolOn, "M3 S.5", "at once"),
            (Kind::ToolOn, "M3 S5.", "at once"),
            (Kind::ToolOff, "M3 S-0", "at once"),
            (Kind::Start, "M3 S500\nM0", "pause with the laser on"),
        ] {
            let e = check(kind, text).err().unwrap_or_default();
            assert!(e.contains(want), "{text:?}: expected '{want}' in '{e}'");
            assert!(e.starts_with(kind.key()), "{e}");
        }
    }

    #[test]
    fn closed_comments_are_read_past() {
        let t = check(Kind::ToolOff, "M5 (laser off) S0 ; done").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((t.spindle, t.s), (Some(Spindle::Off), Some(0.0)));
        assert!(check(Kind::ToolOn, "G1 Z-0.5 F600 (down)\nG4 P0.1").is_ok());
        assert_eq!(dwell_seconds("G4 P0.5 (wait)\nG4 P1 (\nM5"), 0.5);
    }

    #[test]
    fn messages_escape_control_characters() {
        let e = check(Kind::Start, "M3\u{1b}[2J").err().unwrap_or_default();
        assert!(!e.contains('\u{1b}') && e.contains("\\u{1b}"), "{e}");
        assert_eq!(printable("a\tb\u{7}"), "a\\u{9}b\\u{7}");
    }

    #[test]
    fn pen_down_compares_what_tool_on_sets() {
        let on = Tool {
            spindle: None,
            s: None,
            z: Some(0.0),
        };
        let up = Tool { z: Some(3.0), ..on };
        assert!(on.pen_down(&on) && !up.pen_down(&on));
    }

    /// Found by the fuzz targets (cli/tests/fuzz.rs): an `end` or `pen_change` that moved the
    /// pen below its down position (`G1 Z-1 F100`), or a servo to an angle between up and
    /// down, passed as "not the down state".
    #[test]
    fn pen_up_is_at_or_past_the_lift() {
        let z = |v: f64| Tool {
            z: Some(v),
            ..Tool::default()
        };
        let (on, lift) = (z(0.0), z(3.0));
        assert!(z(3.0).pen_up(&on, &lift) && z(0.5).pen_up(&on, &lift));
        assert!(!z(0.0).pen_up(&on, &lift) && !z(-1.0).pen_up(&on, &lift) && !Tool::default().pen_up(&on, &lift));
        let servo = |s: f64, spindle: Spindle| Tool {
            spindle: Some(spindle),
            s: Some(s),
            z: None,
        };
        let (on, lift) = (servo(90.0, Spindle::On), servo(30.0, Spindle::On));
        assert!(servo(30.0, Spindle::On).pen_up(&on, &lift) && servo(10.0, Spindle::On).pen_up(&on, &lift));
        assert!(servo(90.0, Spindle::Off).pen_up(&on, &lift));
        for down in [37.0, 90.0, 97.0] {
            assert!(!servo(down, Spindle::On).pen_up(&on, &lift), "S{down}");
        }
    }
}
