//! The G-code safety invariants (docs/plotting.md, Safety invariants), checked by reading a
//! program back with an independent parser (the `gcode` crate) and replaying it in a small
//! interpreter written here, not shared with the writer. It tracks position, modal motion
//! (G0/G1/G2/G3), feed, and the tool's state as the profile's own `tool_off` block defines
//! "off" (a Z height, a servo angle or the spindle for pens; the spindle and its power for a
//! laser), and reports every breach:
//! - every coordinate inside the bed, arcs included (their extreme points);
//! - the tool off for every G0, at every pause and at the end of the program;
//! - a feed set before the first cutting move;
//! - plain decimals with fixed precision (no exponent, NaN or -0): 3 decimals in mm, 5 in
//!   inches.
//!
//! It also records the feed in force at every G1/G2/G3 move ([`Replay::feeds`]), which
//! [`feed_faults`] compares with the feeds that were asked for.
//!
//! `cli/tests/gcode.rs` (`checkers_fail_on_broken_programs`) shows that each check can fail.

use std::f64::consts::{FRAC_PI_2, TAU};

// ---------------------------------------------------------------------------------------------
// The profile as the checker sees it (read with `toml`, not with the writer's types)

/// What "the tool is off" means for a machine.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ToolModel {
    /// A laser (the profile has a power range): on while M3/M4 is active with S > 0.
    Laser,
    /// A pen: up while every output the profile's `tool_off` block sets is where it leaves
    /// it: a Z above `tool_on`'s (at least `tool_off`'s when `tool_on` sets none); a servo
    /// angle (S) at `tool_off`'s or farther from `tool_on`'s (M5 also counts as up once an
    /// angle was set); the spindle off if `tool_off` turns it off. Down otherwise (a pen
    /// pressed below its down position, a servo between its two angles), and down while
    /// unknown (at the start, before any block set it).
    Pen {
        /// `tool_off`'s last Z.
        z: Option<f64>,
        /// `tool_off`'s last S.
        s: Option<f64>,
        /// `tool_off` leaves the spindle off (M5).
        spindle_off: bool,
        /// `tool_on`'s last Z.
        z_down: Option<f64>,
        /// `tool_on`'s last S.
        s_down: Option<f64>,
    },
}

impl ToolModel {
    /// A servo pen, up at the angle `up` (`M3 S<up>`).
    pub fn servo(up: f64) -> ToolModel {
        ToolModel::Pen {
            z: None,
            s: Some(up),
            spindle_off: false,
            z_down: None,
            s_down: None,
        }
    }

    /// A Z-lift pen, up at or above `up`.
    pub fn z_lift(up: f64) -> ToolModel {
        ToolModel::Pen {
            z: Some(up),
            s: None,
            spindle_off: false,
            z_down: None,
            s_down: None,
        }
    }
}

/// A machine as the checker sees it.
#[derive(Debug, Clone)]
pub struct Profile {
    /// Decimals of every X, Y, I and J.
    pub decimals: usize,
    /// Bed in output units: x0, y0, x1, y1.
    pub bed: [f64; 4],
    /// When the tool is off.
    pub tool: ToolModel,
}

/// A number of the profile at `path`; a table's field may also be written as an array of its
/// fields in order, `[bed]` as `bed = [width, height]`.
fn toml_f(v: &toml::Value, path: &[&str]) -> f64 {
    let mut cur = v;
    for k in path {
        cur = match (cur.as_array(), *k) {
            (Some(a), "width") => &a[0],
            (Some(a), "height") => &a[1],
            _ => cur.get(k).unwrap_or_else(|| panic!("profile lacks {path:?}")),
        };
    }
    cur.as_float()
        .or_else(|| cur.as_integer().map(|i| i as f64))
        .unwrap_or_else(|| panic!("{path:?} is not a number"))
}

/// The words of a profile block, letters upper-cased, placeholders standing for 1, comments
/// (`;` to the end of the line, `(` ... `)`) left out; words that are not a letter and a
/// number are skipped.
fn block_words(block: &str) -> Vec<(char, f64)> {
    let mut out = Vec::new();
    for raw in block.lines() {
        let line = raw.split(';').next().unwrap_or("");
        let line = line.split('(').next().unwrap_or("");
        let line = line.replace("{power}", "1").replace("{feed}", "1").replace("{travel_feed}", "1");
        let mut chars = line.chars().peekable();
        while let Some(c) = chars.next() {
            if !c.is_ascii_alphabetic() {
                continue;
            }
            let mut num = String::new();
            while let Some(&d) = chars.peek() {
                if d.is_ascii_digit() || matches!(d, '.' | '-' | '+' | ' ' | '\t') {
                    if !d.is_whitespace() {
                        num.push(d);
                    }
                    chars.next();
                } else {
                    break;
                }
            }
            if let Ok(v) = num.parse::<f64>() {
                out.push((c.to_ascii_uppercase(), v));
            }
        }
    }
    out
}

/// The checker's view of a machine profile (its TOML text): a laser if it has a power
/// range, else a pen lifted as its `tool_off` block says.
pub fn profile_from_toml(text: &str) -> Profile {
    let v: toml::Value = toml::from_str(text).unwrap_or_else(|e| panic!("profile TOML: {e}"));
    let inch = v.get("units").and_then(|u| u.as_str()) == Some("inch");
    let f = if inch { 1.0 / 25.4 } else { 1.0 };
    let (w, h) = (toml_f(&v, &["bed", "width"]) * f, toml_f(&v, &["bed", "height"]) * f);
    let bed = match v.get("origin").and_then(|o| o.as_str()) {
        Some("center") => [-w / 2.0, -h / 2.0, w / 2.0, h / 2.0],
        _ => [0.0, 0.0, w, h],
    };
    let tool = if v.get("power").is_some() {
        ToolModel::Laser
    } else {
        let off = v.get("tool_off").and_then(|t| t.as_str()).unwrap_or("");
        let (mut z, mut s, mut spindle_off) = (None, None, false);
        for (letter, val) in block_words(off) {
            match letter {
                'Z' => z = Some(val),
                'S' => s = Some(val),
                'M' if val == 5.0 => spindle_off = true,
                'M' if val == 3.0 || val == 4.0 => spindle_off = false,
                _ => {}
            }
        }
        let on = v.get("tool_on").and_then(|t| t.as_str()).unwrap_or("");
        let last = |l: char| block_words(on).iter().rev().find(|w| w.0 == l).map(|w| w.1);
        ToolModel::Pen {
            z,
            s,
            spindle_off,
            z_down: last('Z'),
            s_down: last('S'),
        }
    };
    Profile {
        decimals: if inch { 5 } else { 3 },
        bed,
        tool,
    }
}

/// A code's letter, major number and arguments.
pub fn code_parts(c: &gcode::Code) -> (char, u32, &[gcode::Argument]) {
    match c {
        gcode::Code::General(g) => ('G', g.number.major(), &g.args),
        gcode::Code::Miscellaneous(m) => ('M', m.number.major(), &m.args),
        gcode::Code::ToolChange(t) => ('T', t.number.major(), &t.args),
        _ => ('?', 0, &[]),
    }
}

// ---------------------------------------------------------------------------------------------
// The interpreter

/// What a replay found and measured.
#[derive(Debug, Default, Clone)]
pub struct Replay {
    /// One message per violation.
    pub errors: Vec<String>,
    /// Cutting length (output units).
    pub down: f64,
    /// Rapid / tool-off travel (output units).
    pub up: f64,
    pub g0: usize,
    pub arcs: usize,
    pub cuts: usize,
    /// Cutting moves as segments (arcs as their chord) for geometry checks.
    pub segments: Vec<[[f64; 2]; 2]>,
    /// Every position reached (x0, y0, x1, y1).
    pub bounds: [f64; 4],
    /// Every position reached with the tool on, arc extremes included.
    pub drawn: [f64; 4],
    /// At each program pause (`M0`, `M1`: a pen change), the number of cutting segments so far.
    pub pauses: Vec<usize>,
    /// Every G1/G2/G3 move in X or Y: its line, whether the tool was on, and the feed in force
    /// (output units per minute).
    pub feeds: Vec<(usize, bool, f64)>,
}

/// A plain decimal: `-?\d+(\.\d+)?` with exactly `decimals` decimals when given.
pub fn plain(num: &str, decimals: Option<usize>) -> bool {
    let body = num.strip_prefix('-').unwrap_or(num);
    let (int, frac) = match body.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (body, None),
    };
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    if !digits(int) || frac.is_some_and(|f| !digits(f)) {
        return false;
    }
    if num.starts_with('-') && body.bytes().all(|b| b == b'0' || b == b'.') {
        return false; // -0
    }
    match decimals {
        Some(d) => frac.map_or(0, str::len) == d,
        None => true,
    }
}

/// Checks the raw text of every line, independently of the parser: words are a letter and a
/// plain number; coordinates have exactly `decimals` decimals; no letter comes twice on a
/// line (a controller refuses such a line, and what it was to do is not done).
pub fn check_numbers(text: &str, decimals: usize, errors: &mut Vec<String>) {
    for (n, raw) in text.lines().enumerate() {
        // Comments as a controller reads them: `;` to the end of the line, `(` to `)`.
        let mut line = String::new();
        let mut open = false;
        for c in raw.chars() {
            match (open, c) {
                (true, ')') => open = false,
                (true, _) => {}
                (false, ';') => break,
                (false, '(') => open = true,
                (false, c) => line.push(c),
            }
        }
        if open {
            errors.push(format!("line {}: a comment left open in '{raw}'", n + 1));
        }
        let line = line.as_str();
        let mut seen = String::new();
        let mut chars = line.char_indices().peekable();
        while let Some((i, c)) = chars.next() {
            if c.is_whitespace() {
                continue;
            }
            if !c.is_ascii_alphabetic() {
                errors.push(format!("line {}: unexpected '{c}' in '{raw}'", n + 1));
                break;
            }
            let start = i + c.len_utf8();
            let mut end = start;
            while let Some(&(j, d)) = chars.peek() {
                if d.is_ascii_digit() || d == '.' || d == '-' || d == '+' {
                    end = j + d.len_utf8();
                    chars.next();
                } else {
                    break;
                }
            }
            let num = &line[start..end];
            let letter = c.to_ascii_uppercase();
            if seen.contains(letter) {
                errors.push(format!("line {}: '{letter}' comes twice in '{raw}'", n + 1));
            }
            seen.push(letter);
            let want = if matches!(letter, 'X' | 'Y' | 'I' | 'J') {
                Some(decimals)
            } else {
                None
            };
            if !plain(num, want) {
                errors.push(format!(
                    "line {}: '{letter}{num}' is not a plain number with the fixed precision ({raw})",
                    n + 1
                ));
            }
        }
    }
}

fn arc_extreme_angles(from: f64, span: f64) -> Vec<f64> {
    let k0 = (from / FRAC_PI_2).ceil() as i64;
    let k1 = ((from + span) / FRAC_PI_2).floor() as i64;
    (k0..=k1).map(|k| k as f64 * FRAC_PI_2).collect()
}

/// Replays a program on a machine: every breach of the invariants, and the figures.
pub fn replay(text: &str, p: &Profile) -> Replay {
    let empty = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    let mut r = Replay {
        bounds: empty,
        drawn: empty,
        ..Replay::default()
    };
    check_numbers(text, p.decimals, &mut r.errors);
    let prog = match gcode::parse(text) {
        Ok(p) => p,
        Err(e) => {
            r.errors.push(format!("does not parse: {e:?}"));
            return r;
        }
    };
    let eps = 1e-9;
    let [bx0, by0, bx1, by1] = p.bed;
    let mut pos = [0.0f64, 0.0];
    let mut motion: Option<u32> = None;
    let mut feed: Option<f64> = None;
    let mut spindle = false;
    // Unknown at the start: assume the worst (down) for pens, off for a laser (GRBL boots off).
    let mut s_word: Option<f64> = None;
    let mut z = f64::NEG_INFINITY;
    // Whether the tool's state is known: a pen is where the operator left it until a block
    // sets what `tool_off` sets (a pause then cannot be judged; a move counts it as down).
    let known = |s: Option<f64>, z: f64| match p.tool {
        ToolModel::Laser => true,
        ToolModel::Pen { z: z_up, s: s_up, .. } => (z_up.is_none() || z > f64::NEG_INFINITY) && (s_up.is_none() || s.is_some()),
    };
    let past = |v: f64, up: f64, down: Option<f64>| match down {
        Some(d) if d != up => (v - d) * (up - d) >= (up - d) * (up - d),
        _ => v == up,
    };
    let tool_on = |spindle: bool, s: Option<f64>, z: f64| match p.tool {
        ToolModel::Laser => spindle && s.is_some_and(|s| s > 0.0),
        ToolModel::Pen {
            z: z_up,
            s: s_up,
            spindle_off,
            z_down,
            s_down,
        } => {
            let z_ok = z_up.is_none_or(|up| match z_down {
                Some(d) => z > d,
                None => z >= up - 1e-9,
            });
            let s_ok = s_up.is_none_or(|up| s.is_some_and(|v| past(v, up, s_down)) || (!spindle && s.is_some()));
            let spindle_ok = !spindle_off || !spindle;
            let known = z_up.is_some() || s_up.is_some() || spindle_off;
            !(known && z_ok && s_ok && spindle_ok)
        }
    };
    for (n, b) in prog.blocks.iter().enumerate() {
        let line = n + 1;
        let mut words: Vec<(char, f64)> = Vec::new();
        let mut codes: Vec<(char, u32)> = Vec::new();
        for c in &b.codes {
            let (letter, num, args) = code_parts(c);
            codes.push((letter, num));
            for a in args {
                let raw = &text[a.span.start..a.span.start + a.span.length];
                let v = raw[1..].trim().parse::<f64>().unwrap_or(f64::NAN);
                words.push((a.letter.to_ascii_uppercase(), v));
            }
        }
        for w in &b.word_addresses {
            let raw = &text[w.span.start..w.span.start + w.span.length];
            words.push((w.letter.to_ascii_uppercase(), raw[1..].trim().parse::<f64>().unwrap_or(f64::NAN)));
        }
        let word = |l: char| words.iter().find(|w| w.0 == l).map(|w| w.1);
        for &(l, num) in &codes {
            match (l, num) {
                ('G', 0..=3) => motion = Some(num),
                ('M', 3) | ('M', 4) => spindle = true,
                ('M', 5) | ('M', 2) | ('M', 30) => spindle = false,
                ('M', 0) | ('M', 1) => {
                    if tool_on(spindle, s_word, z) && known(s_word, z) {
                        r.errors.push(format!("line {line}: a pause with the tool on"));
                    }
                    r.pauses.push(r.segments.len());
                }
                _ => {}
            }
        }
        if let Some(f) = word('F') {
            feed = Some(f);
        }
        if let Some(s) = word('S') {
            s_word = Some(s);
        }
        let moves_xy = word('X').is_some() || word('Y').is_some();
        let moves_z = word('Z').is_some();
        let dwell = codes.contains(&('G', 4));
        if dwell || !(moves_xy || moves_z) {
            continue;
        }
        let Some(m) = motion else {
            r.errors.push(format!("line {line}: a move without a motion mode"));
            continue;
        };
        let on = tool_on(spindle, s_word, z);
        // In arc mode (left by the previous arc when the line has no G of its own), a move
        // without its centre is refused by the controller: the move is not made.
        if m >= 2 && word('I').is_none() && word('J').is_none() {
            r.errors.push(format!("line {line}: a move in arc mode (G{m}) without I or J"));
        }
        if m >= 1 && feed.is_none() {
            r.errors.push(format!("line {line}: G{m} before any feed was set"));
        }
        if let Some(zz) = word('Z') {
            z = zz;
        }
        if !moves_xy {
            continue;
        }
        let to = [word('X').unwrap_or(pos[0]), word('Y').unwrap_or(pos[1])];
        if !(to[0].is_finite() && to[1].is_finite()) {
            r.errors.push(format!("line {line}: a coordinate is not a number"));
            continue;
        }
        let visit = |q: [f64; 2], what: &str, r: &mut Replay| {
            r.bounds = [
                r.bounds[0].min(q[0]),
                r.bounds[1].min(q[1]),
                r.bounds[2].max(q[0]),
                r.bounds[3].max(q[1]),
            ];
            if on {
                r.drawn = [
                    r.drawn[0].min(q[0]),
                    r.drawn[1].min(q[1]),
                    r.drawn[2].max(q[0]),
                    r.drawn[3].max(q[1]),
                ];
            }
            if q[0] < bx0 - eps || q[0] > bx1 + eps || q[1] < by0 - eps || q[1] > by1 + eps {
                r.errors
                    .push(format!("line {line}: {what} ({}, {}) is outside the bed", q[0], q[1]));
            }
        };
        if on {
            visit(pos, "start point", &mut r);
        }
        visit(to, "end point", &mut r);
        if let (1.., Some(f)) = (m, feed) {
            r.feeds.push((line, on, f));
        }
        let len = (to[0] - pos[0]).hypot(to[1] - pos[1]);
        match m {
            0 => {
                r.g0 += 1;
                if on {
                    r.errors.push(format!("line {line}: G0 with the tool on"));
                }
                r.up += len;
            }
            1 => {
                if on {
                    r.down += len;
                    r.cuts += 1;
                    r.segments.push([pos, to]);
                } else {
                    r.up += len;
                }
            }
            _ => {
                let (i, j) = (word('I').unwrap_or(0.0), word('J').unwrap_or(0.0));
                let c = [pos[0] + i, pos[1] + j];
                let rad = i.hypot(j);
                let rad_end = (to[0] - c[0]).hypot(to[1] - c[1]);
                if (rad - rad_end).abs() > 0.005_f64.max(rad * 1e-3) {
                    r.errors
                        .push(format!("line {line}: arc radius {rad} at the start, {rad_end} at the end"));
                }
                let a0 = (pos[1] - c[1]).atan2(pos[0] - c[0]);
                let a1 = (to[1] - c[1]).atan2(to[0] - c[0]);
                let full = to == pos;
                let ccw = m == 3;
                let span = if full {
                    TAU
                } else if ccw {
                    (a1 - a0).rem_euclid(TAU)
                } else {
                    (a0 - a1).rem_euclid(TAU)
                };
                let from = if ccw || full { a0 } else { a1 };
                for a in arc_extreme_angles(from, span) {
                    visit([c[0] + rad * a.cos(), c[1] + rad * a.sin()], "arc extreme", &mut r);
                }
                r.arcs += 1;
                if on {
                    r.down += rad * span;
                    r.cuts += 1;
                    r.segments.push([pos, to]);
                } else {
                    r.up += rad * span;
                }
            }
        }
        pos = to;
    }
    if tool_on(spindle, s_word, z) {
        r.errors.push("the tool is on at the end of the program".into());
    }
    r
}

/// Replays a program and asserts it breaks no invariant and draws something.
pub fn assert_safe(text: &str, p: &Profile, what: &str) -> Replay {
    let r = replay(text, p);
    assert!(
        r.errors.is_empty(),
        "{what}: {} violations, first: {:?}",
        r.errors.len(),
        &r.errors[..r.errors.len().min(5)]
    );
    assert!(r.cuts > 0, "{what}: nothing drawn");
    r
}

/// The moves of a replay whose feed is not what was asked: `draw` for every move with the tool
/// on, and one of `off` for every G1 with it off (mm/min: the travel feed; a profile whose
/// blocks the interpreter reads as leaving the pen up while the writer cuts may add `draw`).
/// Each is read back in mm/min (`per_mm` output units per mm: 1, or 1 / 25.4 in inches)
/// within the relative tolerance `rel`, or within `abs` mm/min (for the whole mm/min of mm
/// programs).
pub fn feed_faults(r: &Replay, per_mm: f64, draw: f64, off: &[f64], rel: f64, abs: f64) -> Vec<String> {
    let mut out = Vec::new();
    let ok = |got: f64, want: f64| (got - want).abs() <= rel * want || (got - want).abs() <= abs;
    for &(line, on, f) in &r.feeds {
        let got = f / per_mm;
        let fine = if on { ok(got, draw) } else { off.iter().any(|&w| ok(got, w)) };
        if !fine {
            let what = if on {
                format!("drawing feed, asked {draw}")
            } else {
                format!("travel feed, asked {off:?}")
            };
            out.push(format!("line {line}: {got} mm/min (F{f}) as {what} mm/min"));
        }
    }
    out
}
