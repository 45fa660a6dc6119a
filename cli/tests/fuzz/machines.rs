//! Machine profiles (`output::machine`): arbitrary text and mutations of the built-ins,
//! each accepted profile replayed through the safety checker.

use crate::common::safety::feed_faults;
use crate::*;
use zetafill_cli::output::machine::{Machine, Units};

/// G-code words and lines a profile block might hold: allowed, refused, and malformed.
fn gcode_line() -> impl Strategy<Value = String> {
    let letter = select(vec![
        'G', 'M', 'X', 'Y', 'Z', 'F', 'S', 'P', 'T', 'I', 'J', 'R', 'E', 'N', 'g', 'm', 'z', 's', 'f', 'p',
    ]);
    let value = prop_oneof![
        4 => (0u32..100).prop_map(|v| v.to_string()),
        2 => (-2000.0f64..2000.0).prop_map(|v| format!("{v:.3}")),
        1 => select(vec!["59.1", "38.2", "28.1", "92.1", "0.0", "-0", "+5", ".5", "5.", "1e3", "1E3", "nan", "inf", "1000000", "1000001", "600", "600.001", "-1000", "1000.0001", "", "{power}", "{feed}", "{travel_feed}", "{x}", "99999999999999999999"])
            .prop_map(str::to_string),
    ];
    let word = (letter, value, select(vec!["", "", " ", "\t"])).prop_map(|(l, v, s)| format!("{l}{s}{v}"));
    let valid = (
        select(vec!["G0 Z", "G1 F600 Z", "M3 S", "M4 S", "S", "G4 P", "F"]),
        (0.0f64..100.0).prop_map(|v| format!("{v:.2}")),
        select(vec!["", "", " ; note", " (note)"]),
    )
        .prop_map(|(w, v, c)| format!("{w}{v}{c}"));
    prop_oneof![
        4 => valid,
        5 => (prop::collection::vec(word, 1..4), select(vec!["", "", " ; note", " (note)", ";", "(", " ; {power}"])).prop_map(|(w, c)| format!("{}{c}", w.join(" "))),
        3 => select(vec![
            "M3 S30", "M3 S90", "M5", "M5 S0", "M4 S{power}", "M3 S{power}", "G0 Z3.000", "G1 Z0.000 F600", "G0 Z5", "G1 Z-1", "G4 P0.15", "G4 P0",
            "G4", "M0", "M1", "M2", "M30", "M6 T1", "M7", "M8", "M9", "G17", "G90", "G91", "G20", "G21", "G28", "G53 G0 Z0", "G92 X0", "G54",
            "G0 X10 Y10", "G2 X1 Y1 I1", "S0", "S1000", "F1000", "$H", "%", "#1=5", "M3 S30\r", "M3\u{1b}[31m", "é", "",
        ])
        .prop_map(str::to_string),
    ]
}

/// A TOML value for a numeric field: plain, extreme, of the wrong type.
fn toml_number() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (0.0f64..2000.0).prop_map(|v| format!("{v:.1}")),
        2 => (1u32..200_000).prop_map(|v| v.to_string()),
        1 => any::<u64>().prop_map(|b| format!("{:e}", f64::from_bits(b))).prop_filter("TOML floats", |s| !s.contains("NaN") && !s.contains("inf")),
        1 => select(vec!["0", "-0.0", "-1", "1e-300", "1e300", "1e6", "100000", "100000.0001", "nan", "inf", "-inf", "0.001", "\"300\"", "true", "[1, 2]", "{}", ""])
            .prop_map(str::to_string),
    ]
}

/// A built-in profile with a few changes: G-code lines inserted into a block, a block
/// replaced, a number changed, an enum or a key changed, a line dropped or repeated.
fn mutated_profile() -> impl Strategy<Value = String> {
    let names = Machine::builtin_names();
    let edit = prop_oneof![
        4 => (select(vec!["start", "tool_on", "tool_off", "pen_change", "end"]), prop::collection::vec(gcode_line(), 1..4), any::<bool>())
            .prop_map(|(k, lines, replace)| Edit::Block(k, lines.join("\n"), replace)),
        3 => (select(vec!["width", "height", "draw", "travel", "min", "max", "default"]), prop_oneof![3 => (1.0f64..1000.0).prop_map(|v| format!("{v:.1}")), 1 => toml_number()]).prop_map(|(k, v)| Edit::Number(k, v)),
        1 => prop_oneof![
            3 => (0.0f64..300.0, 0.0f64..300.0).prop_map(|(a, b)| vec![format!("{a:.1}"), format!("{b:.1}")]),
            1 => prop::collection::vec(toml_number(), 2),
            2 => prop::collection::vec((0.0f64..300.0).prop_map(|v| format!("{v:.1}")), 0..6),
        ]
        .prop_map(Edit::Park),
        1 => (select(vec!["bed", "feed", "power"]), prop::collection::vec((1.0f64..2000.0).prop_map(|v| format!("{v:.1}")), 0..5))
            .prop_map(|(k, v)| Edit::TableArray(k, v)),
        2 => prop_oneof![
            4 => select(vec![("units", "\"mm\""), ("units", "\"inch\""), ("origin", "\"center\""), ("origin", "\"top-left\""), ("origin", "\"bottom-left\""), ("travel", "\"feed\""), ("travel", "\"rapid\""), ("arcs", "true"), ("arcs", "false")]),
            1 => (select(vec!["units", "origin", "arcs", "travel"]), select(vec!["\"left\"", "1", "\"MM\"", "\"\""])),
        ]
            .prop_map(|(k, v)| Edit::Value(k, v.to_string())),
        1 => Just(Edit::Power),
        1 => (any::<prop::sample::Index>(), 0u8..3).prop_map(|(i, how)| Edit::Line(i, how)),
    ];
    (select(names), prop::collection::vec(edit, 1..4)).prop_map(|(name, edits)| {
        let mut text = Machine::builtin_text(name).unwrap_or("").to_string();
        for e in edits {
            text = e.apply(&text);
        }
        text
    })
}

/// One change to a profile's text.
#[derive(Clone, Debug)]
enum Edit {
    /// Lines for a block: added to its end, or in place of it (the block is added if absent).
    Block(&'static str, String, bool),
    /// A new value for every `KEY = number` line.
    Number(&'static str, String),
    /// A park position, of any length.
    Park(Vec<String>),
    /// A table (`[bed]`, `[feed]`, `[power]`) replaced by an array of numbers of any length.
    TableArray(&'static str, Vec<String>),
    /// A new value for a `KEY = ...` line.
    Value(&'static str, String),
    /// A power range added (or removed, when there is one).
    Power,
    /// A line removed, repeated or emptied.
    Line(prop::sample::Index, u8),
}

impl Edit {
    fn apply(&self, text: &str) -> String {
        let set = |key: &str, value: &str| -> String {
            text.lines()
                .map(|l| {
                    if l.split('=').next().map(str::trim) == Some(key) && l.contains('=') && !l.contains("\"\"\"") {
                        format!("{key} = {value}")
                    } else {
                        l.to_string()
                    }
                })
                .collect::<Vec<_>>()
                .join("\n")
                + "\n"
        };
        match self {
            Edit::Block(key, lines, replace) => {
                let open = format!("{key} = \"\"\"\n");
                match text.find(&open) {
                    Some(at) => {
                        let body = at + open.len();
                        let end = text[body..].find("\"\"\"").map_or(text.len(), |e| body + e);
                        if *replace {
                            format!("{}{lines}\n{}", &text[..body], &text[end..])
                        } else {
                            format!("{}{lines}\n{}", &text[..end], &text[end..])
                        }
                    }
                    // Before the first table, where top-level keys belong.
                    None => match text.find("\n[") {
                        Some(at) => format!("{}\n{key} = \"\"\"\n{lines}\n\"\"\"{}", &text[..at], &text[at..]),
                        None => format!("{text}\n{key} = \"\"\"\n{lines}\n\"\"\"\n"),
                    },
                }
            }
            Edit::Number(key, v) => set(key, v),
            Edit::Value(key, v) => set(key, v),
            Edit::Park(v) => match text.lines().any(|l| l.starts_with("park")) {
                true => set("park", &format!("[{}]", v.join(", "))),
                false => format!("park = [{}]\n{text}", v.join(", ")),
            },
            Edit::TableArray(key, v) => {
                let head = format!("\n[{key}]\n");
                let text = match text.find(&head) {
                    Some(at) => {
                        let body = at + head.len();
                        let end = text[body..].find("\n[").map_or(text.len(), |e| body + e);
                        format!("{}{}", &text[..at + 1], &text[end..])
                    }
                    None => text.to_string(),
                };
                format!("{key} = [{}]\n{text}", v.join(", "))
            }
            Edit::Power => match text.find("\n[power]") {
                Some(at) => text[..at].to_string() + "\n",
                None => format!("{text}\n[power]\nmin = 0.0\nmax = 1000.0\ndefault = 800.0\n"),
            },
            Edit::Line(i, how) => {
                let mut lines: Vec<&str> = text.lines().collect();
                if lines.is_empty() {
                    return text.to_string();
                }
                let k = i.index(lines.len());
                match how {
                    0 => {
                        lines.remove(k);
                    }
                    1 => lines.insert(k, lines[k]),
                    _ => lines[k] = "",
                }
                lines.join("\n") + "\n"
            }
        }
    }
}

/// Profile texts: mutated built-ins mostly, TOML-like soup and arbitrary text.
fn profile_text() -> impl Strategy<Value = String> {
    let key = select(vec![
        "name",
        "description",
        "units",
        "origin",
        "arcs",
        "travel",
        "park",
        "start",
        "tool_on",
        "tool_off",
        "pen_change",
        "end",
        "width",
        "speed",
        "[bed]",
        "[feed]",
        "[power]",
    ]);
    let soup = prop::collection::vec((key, toml_number()), 0..12).prop_map(|kv| {
        kv.iter()
            .map(|(k, v)| {
                if k.starts_with('[') {
                    format!("{k}\n")
                } else {
                    format!("{k} = {v}\n")
                }
            })
            .collect::<String>()
    });
    prop_oneof![
        8 => mutated_profile(),
        1 => soup,
        1 => any_text(),
    ]
}

/// A small fill written as G-code for `machine` (a profile file) with random plot flags;
/// `Ok(None)` when the flags are refused (naming one).
pub(crate) fn small_fill_gcode(machine: &Path, flags: &PlotFlags) -> Result<Option<Vec<u8>>, String> {
    let mut args: Vec<String> = ["zetafill", "fill", "-q", "--machine"].iter().map(|s| s.to_string()).collect();
    args.push(machine.display().to_string());
    args.extend(flags.args());
    args.extend(["-o".to_string(), "fuzz.gcode".to_string()]);
    let cli = match <zetafill_cli::Cli as clap::Parser>::try_parse_from(&args) {
        Ok(c) => c,
        Err(e) => return Err(format!("{args:?}: the command line is refused: {e}")),
    };
    let zetafill_cli::Command::Fill(a) = cli.command else {
        return Err("not a fill".into());
    };
    let refused = |e: zetafill_cli::error::CliError| -> Result<Option<Vec<u8>>, String> {
        let msg = e.to_string();
        readable(&msg)?;
        if !msg.starts_with("--") {
            return Err(format!("{args:?}: refused without naming a flag: {msg}"));
        }
        Ok(None)
    };
    let (run, draw) = match zetafill_cli::plan::fill::resolve_as(&a, zetafill_cli::plan::format::Format::Gcode) {
        Ok(p) => p,
        Err(e) => return refused(e),
    };
    let (doc, _) = match zetafill_cli::cmd::fill::compute(&run) {
        Ok(d) => d,
        Err(e) => return refused(e),
    };
    match zetafill_cli::cmd::fill::render(&doc, zetafill_cli::plan::format::Format::Gcode, &draw) {
        Ok(bytes) => Ok(Some(bytes)),
        Err(e) => refused(e),
    }
}

/// The plot flags of a small fill.
#[derive(Clone, Debug)]
pub(crate) struct PlotFlags {
    pub region: String,
    pub shape: &'static str,
    pub count: u32,
    pub seed: u64,
    pub place: &'static str,
    pub extra: Vec<String>,
}

impl PlotFlags {
    /// The value of `flag`, if given.
    fn value(&self, flag: &str) -> Option<f64> {
        let at = self.extra.iter().position(|a| a == flag)?;
        self.extra.get(at + 1)?.parse().ok()
    }

    /// The `--margin` (0 when not given).
    fn margin(&self) -> f64 {
        self.value("--margin").unwrap_or(0.0)
    }

    fn args(&self) -> Vec<String> {
        let mut a: Vec<String> = vec![
            "--region".into(),
            self.region.clone(),
            "--shape".into(),
            self.shape.into(),
            "--count".into(),
            self.count.to_string(),
            "--seed".into(),
            self.seed.to_string(),
            "--n-offset".into(),
            "3".into(),
            "--max-trials".into(),
            "20000".into(),
        ];
        if !self.place.is_empty() {
            a.push(self.place.into());
        }
        a.extend(self.extra.iter().cloned());
        a
    }
}

pub(crate) fn plot_flags() -> impl Strategy<Value = PlotFlags> {
    // Each flag at most once, each given one time in five.
    let maybe = |s: BoxedStrategy<Vec<String>>| prop_oneof![4 => Just(vec![]), 1 => s];
    let extra = (
        maybe(Just(vec!["--no-arcs".to_string()]).boxed()),
        maybe((1u32..4).prop_map(|p| vec!["--passes".to_string(), p.to_string()]).boxed()),
        maybe(
            (0.5f64..5.0, 0u32..180)
                .prop_map(|(s, a)| vec!["--hatch".to_string(), format!("{s:.2}:{a}")])
                .boxed(),
        ),
        maybe(
            select(vec!["none", "greedy", "improved"])
                .prop_map(|o| vec!["--order".to_string(), o.to_string()])
                .boxed(),
        ),
        maybe((0.0f64..5.0).prop_map(|m| vec!["--margin".to_string(), format!("{m:.2}")]).boxed()),
        maybe(
            Just(
                ["--layers", "colours", "--palette", "000000,ff0000,00ff00", "--color-by", "random"]
                    .map(str::to_string)
                    .to_vec(),
            )
            .boxed(),
        ),
        maybe(
            (0.0f64..1000.0)
                .prop_map(|p| vec!["--power".to_string(), format!("{p:.0}")])
                .boxed(),
        ),
        maybe(
            (100.0f64..5000.0)
                .prop_map(|f| vec!["--feed".to_string(), format!("{f:.0}")])
                .boxed(),
        ),
    )
        .prop_map(|(a, b, c, d, e, f, g, h)| [a, b, c, d, e, f, g, h].concat());
    (
        prop_oneof![
            3 => (5.0f64..400.0, 5.0f64..400.0).prop_map(|(w, h)| format!("rect:{w:.1}:{h:.1}")),
            1 => (5.0f64..200.0).prop_map(|r| format!("circle:{r:.1}")),
            1 => Just("polygon:0,0,100,0,100,100,0,100/30,30,30,70,70,70,70,30".to_string()),
        ],
        select(vec!["circle", "square", "ring:0.5", "star:5:0.4", "mix:circle,triangle"]),
        5u32..40,
        any::<u64>(),
        select(vec!["--fit", "--fit", "--fit", "--center", ""]),
        extra,
    )
        .prop_map(|(region, shape, count, seed, place, extra)| PlotFlags {
            region,
            shape,
            count,
            seed,
            place,
            extra,
        })
}

fn check_profile(dir: &Scratch, text: &str, flags: &PlotFlags, tally: &Tally) -> Result<(), String> {
    let m = match Machine::parse(text) {
        Ok(m) => m,
        Err(msg) => {
            tally.add("refused");
            if msg.trim().is_empty() || msg.chars().any(|c| c.is_control()) {
                return Err(format!("refused with an unreadable message: {msg:?}"));
            }
            return Ok(());
        }
    };
    tally.add("accepted");
    let _ = m.validate();
    let v: toml::Value = toml::from_str(text).map_err(|e| e.to_string())?;
    for (key, n) in [("park", 2), ("bed", 2), ("feed", 2), ("power", 3)] {
        if let Some(a) = v.get(key).and_then(toml::Value::as_array) {
            if a.len() != n {
                return Err(format!("{key} = {a:?} ({} numbers, not {n}) accepted in\n{text}", a.len()));
            }
        }
    }
    let path = dir.write("machine.toml", text.as_bytes());
    let Some(bytes) = small_fill_gcode(&path, flags)? else {
        tally.add("flags refused");
        return Ok(());
    };
    let program = String::from_utf8(bytes).map_err(|_| "the G-code is not UTF-8".to_string())?;
    let r = replay(&program, &profile_from_toml(text));
    let draw = flags.value("--feed").unwrap_or(m.feed.draw);
    let faults = match m.units {
        Units::Inch => feed_faults(&r, m.units.per_mm(), draw, &[m.feed.travel, draw], 1e-3, 0.0),
        Units::Mm => feed_faults(&r, 1.0, draw, &[m.feed.travel, draw], 0.0, 0.5 + 1e-9),
    };
    if let Some(f) = faults.first() {
        return Err(format!("{} feeds not as asked, first {f}, from profile\n{text}", faults.len()));
    }
    if !r.errors.is_empty() {
        let show: String = program.lines().take(60).collect::<Vec<_>>().join("\n");
        return Err(format!(
            "unsafe G-code ({} faults, first {:?}) from profile\n{text}\nprogram:\n{show}",
            r.errors.len(),
            &r.errors[..r.errors.len().min(3)]
        ));
    }
    // A bed (less the margin) under 1 mm has the drawing fitted to a few grid points.
    let room = m.bed.width.min(m.bed.height) - 2.0 * flags.margin();
    let draws = program.lines().any(|l| ["G1 X", "G2 X", "G3 X"].iter().any(|m| l.starts_with(m)));
    if !draws && room >= 1.0 {
        return Err(format!("nothing drawn for profile\n{text}"));
    }
    tally.add("programs");
    Ok(())
}

#[test]
fn fuzz_machine_profiles() {
    let dir = Scratch::new();
    let tally = Tally::new(&["accepted", "refused", "flags refused", "programs"]);
    fuzz("machine_profiles", 1000, (profile_text(), plot_flags()), |(text, flags)| {
        check_profile(&dir, &text, &flags, &tally)
    });
    tally.report("machine profiles");
    assert!(
        tally.get("programs") * 10 >= cases(1000) as u64,
        "fewer than one profile in ten wrote G-code"
    );
}

/// An array for `key` of a built-in profile, of any length, written on one line or several,
/// with a trailing comma or a comment: (profile text, key, count, the count it must have).
fn array_profile() -> impl Strategy<Value = (String, &'static str, usize, usize)> {
    let key = select(vec![("park", 2), ("bed", 2), ("feed", 2), ("power", 3)]);
    (
        key,
        select(Machine::builtin_names()),
        prop::collection::vec(0.0f64..1.0, 0..7),
        0u8..4,
    )
        .prop_map(|((key, n), name, units, style)| {
            let name = if key == "power" { "grbl-laser" } else { name };
            // Values a valid profile may hold: park at the bed's corner, sides of 200 to 300 mm,
            // feeds of 100 to 10,000 mm/min, a power range 0..1000 with its default inside.
            let value = |i: usize, u: f64| match key {
                "park" => 0.0,
                "bed" => 200.0 + 100.0 * u,
                "feed" => 100.0 + 9900.0 * u,
                _ => [0.0, 1000.0, 500.0][i.min(2)],
            };
            let nums: Vec<String> = units.iter().enumerate().map(|(i, &u)| format!("{:.1}", value(i, u))).collect();
            let array = match style {
                0 => format!("[{}]", nums.join(", ")),
                1 => format!("[\n  {}\n]", nums.join(",\n  ")),
                2 => format!("[{}{}]", nums.join(", "), if nums.is_empty() { "" } else { "," }),
                _ => format!("[{}]  # {} numbers", nums.join(", "), nums.len()),
            };
            let text = Machine::builtin_text(name).unwrap_or("");
            let text = match key {
                "park" => Edit::Park(vec![]).apply(text).replacen("park = []", &format!("park = {array}"), 1),
                _ => Edit::TableArray(key, vec![])
                    .apply(text)
                    .replacen(&format!("{key} = []"), &format!("{key} = {array}"), 1),
            };
            (text, key, units.len(), n)
        })
}

/// Bug pinned here: arrays with more numbers than their fields (`park = [0.0, 0.0, 5.0]`)
/// were read with the rest dropped. An array of the right length reads, number for number;
/// any other is refused with the line of its key named.
#[test]
fn fuzz_profile_arrays() {
    let tally = Tally::new(&["accepted", "refused"]);
    fuzz("profile_arrays", 500, array_profile(), |(text, key, count, want)| {
        let line = text.lines().position(|l| l.starts_with(&format!("{key} ="))).map_or(0, |i| i + 1);
        match Machine::parse(&text) {
            Ok(m) if count == want => {
                tally.add("accepted");
                let v: toml::Value = toml::from_str(&text).map_err(|e| e.to_string())?;
                let asked: Vec<f64> = v[key]
                    .as_array()
                    .map(|a| a.iter().filter_map(toml::Value::as_float).collect())
                    .unwrap_or_default();
                let read = match key {
                    "park" => m.park.map(Vec::from).unwrap_or_default(),
                    "bed" => vec![m.bed.width, m.bed.height],
                    "feed" => vec![m.feed.draw, m.feed.travel],
                    _ => m.power.map(|p| vec![p.min, p.max, p.default]).unwrap_or_default(),
                };
                if read != asked {
                    return Err(format!("{key}: {asked:?} read as {read:?}"));
                }
                Ok(())
            }
            Ok(_) => Err(format!("{key} with {count} numbers (not {want}) accepted:\n{text}")),
            Err(e) if count == want => Err(format!("{key} with {count} numbers refused: {e}\n{text}")),
            Err(e) => {
                tally.add("refused");
                readable(&e)?;
                let (what, at) = (format!("{key}: {count} number"), format!("line {line},"));
                if e.contains(&what) && e.contains(&at) {
                    Ok(())
                } else {
                    Err(format!("expected '{what}' at {at}, got: {e}\n{text}"))
                }
            }
        }
    });
    tally.report("profile arrays");
    assert!(tally.get("accepted") > 0 && tally.get("refused") > 0);
}
