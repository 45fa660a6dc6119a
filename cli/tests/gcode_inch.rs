//! G-code in inches, read back with an independent parser (the `gcode` crate) and replayed by
//! the interpreter of `common/safety.rs`: every built-in profile as `zetafill machines show`
//! prints it, switched to `units = "inch"` (with rapid travel as shipped, and with G1 travel
//! so that the travel feed is written too), run with feeds from 1 to 1,000,000 mm/min. Each
//! program must pass the safety invariants; every feed read back and converted to mm/min must
//! be within 0.1 % of what was asked, on the declared fixed precision; every arc's centre and
//! radius must read back, in mm, within the declared precision of the circle it draws (from
//! the JSON of the same fill).
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::safety::*;
use common::*;
use std::path::Path;

const BUILTINS: [&str; 3] = ["grbl-laser", "grbl-servo-pen", "z-lift-pen"];
const SCENE: [&str; 8] = ["--region", "rect:120:100", "--count", "40", "--seed", "21", "--n-offset", "2"];

/// (drawing feed, travel feed) in mm/min: `None` keeps the profile's. The limits of a feed
/// (1 and 1,000,000 mm/min), the feeds that used to round to 1 in/min or lose a third, and
/// some between.
const FEEDS: [(Option<f64>, Option<f64>); 10] = [
    (None, None),
    (Some(1.0), Some(1_000_000.0)),
    (Some(13.0), Some(37.0)),
    (Some(30.0), Some(1.0)),
    (Some(37.0), Some(13.0)),
    (Some(1000.0), Some(30.0)),
    (Some(1.27), Some(25.4)),
    (Some(25.4), Some(1.27)),
    (Some(999_999.9), Some(1000.0)),
    (Some(1_000_000.0), Some(3.3)),
];

/// A feed asked in mm/min as a flag's text.
fn flag_text(v: f64) -> String {
    format!("{v}")
}

/// The declared precision of a program: the decimals in its header's `units inch (N decimals)`.
fn declared_decimals(text: &str) -> usize {
    let at = text.find("units inch (").unwrap_or_else(|| panic!("no inch units in the header"));
    let rest = &text[at + "units inch (".len()..];
    rest.split(' ')
        .next()
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{rest}"))
}

/// The words of a line as (letter, number text), comments left out.
fn line_words(line: &str) -> Vec<(char, &str)> {
    let code = line.split(';').next().unwrap_or("");
    code.split_whitespace()
        .filter_map(|w| w.chars().next().map(|c| (c, &w[1..])))
        .collect()
}

/// Runs one inch program and checks it; returns the number of F words checked.
fn check_program(d: &Path, profile: &str, feeds: (Option<f64>, Option<f64>), circles: &[([f64; 2], f64)]) -> usize {
    let prof = profile_from_toml(profile);
    let v: toml::Value = toml::from_str(profile).unwrap_or_else(|e| panic!("{e}"));
    let num = |t: &str, k: &str| v[t][k].as_float().unwrap_or_else(|| panic!("{t}.{k}"));
    let (draw, travel) = (feeds.0.unwrap_or(num("feed", "draw")), feeds.1.unwrap_or(num("feed", "travel")));
    std::fs::write(d.join("inch.toml"), profile).unwrap_or_else(|e| panic!("{e}"));
    let mut args: Vec<String> = ["fill", "-q", "--machine", "inch.toml", "-o", "inch.gcode"]
        .map(String::from)
        .to_vec();
    args.extend(SCENE.map(String::from));
    if let Some(f) = feeds.0 {
        args.extend(["--feed".into(), flag_text(f)]);
    }
    if let Some(f) = feeds.1 {
        args.extend(["--travel-feed".into(), flag_text(f)]);
    }
    zf_ok(d, &args.iter().map(String::as_str).collect::<Vec<_>>());
    let text = String::from_utf8_lossy(&read(&d.join("inch.gcode"))).into_owned();
    let what = format!("{} with feeds {draw}/{travel} mm/min", v["name"]);
    assert!(text.contains("\nG20\n"), "{what}: inches");
    let dec = declared_decimals(&text);
    assert_eq!(dec, prof.decimals, "{what}: the header declares the checker's precision");
    let r = assert_safe(&text, &prof, &what);
    let faults = feed_faults(&r, 1.0 / 25.4, draw, &[travel], 1e-3, 0.0);
    assert!(
        faults.is_empty(),
        "{what}: {} feeds off by more than 0.1 %: {:?}",
        faults.len(),
        &faults[..faults.len().min(4)]
    );
    assert!(r.feeds.iter().any(|f| f.1), "{what}: a drawing feed");
    if v["travel"].as_str() == Some("feed") {
        assert!(r.feeds.iter().any(|f| !f.1), "{what}: a travel feed");
    }
    // Every F word on a move: fixed precision, positive.
    let mut checked = 0;
    for line in text.lines().filter(|l| l.starts_with('G') && l.contains(" X")) {
        for (letter, num) in line_words(line) {
            if letter == 'F' {
                let frac = num.split_once('.').map_or(0, |(_, f)| f.len());
                assert!(frac == dec && num.parse::<f64>().is_ok_and(|x| x > 0.0), "{what}: '{line}'");
                checked += 1;
            }
        }
    }
    // Every arc is a whole circle of the fill (start and end on the line, centre at I, J from
    // it): its centre within half a step of the precision, its radius within 1.5 steps.
    let step = 10f64.powi(-(dec as i32)) * 25.4;
    let mut arcs = 0;
    for line in text.lines().filter(|l| l.starts_with("G2 ") || l.starts_with("G3 ")) {
        let w = line_words(line);
        let get = |l: char| {
            w.iter()
                .find(|x| x.0 == l)
                .and_then(|x| x.1.parse::<f64>().ok())
                .unwrap_or(f64::NAN)
        };
        let (x, y, i, j) = (get('X'), get('Y'), get('I'), get('J'));
        let c = [(x + i) * 25.4, (y + j) * 25.4];
        let rad = i.hypot(j) * 25.4;
        let near = circles.iter().any(|(cc, rr)| {
            (c[0] - cc[0]).abs() <= 0.5 * step + 1e-9 && (c[1] - cc[1]).abs() <= 0.5 * step + 1e-9 && (rad - rr).abs() <= 1.5 * step
        });
        assert!(near, "{what}: '{line}' is no circle of the fill to within {step} mm");
        arcs += 1;
    }
    assert!(arcs + 3 >= circles.len(), "{what}: {arcs} arcs for {} circles", circles.len());
    checked
}

/// Bug pinned here: in inches every feed was written as whole inches per minute: `--feed 30`
/// (mm/min) became `F1` (25.4 mm/min, -15 %), 1 to 13 mm/min all `F1` (up to 25 times too
/// fast), 37 became `F1` (-31 %) and 1000 became `F39`.
#[test]
fn inch_feeds_and_coordinates_read_back_as_asked() {
    let dir = tmp();
    let d = dir.path();
    let doc = fill_json(d, &SCENE);
    let circles: Vec<([f64; 2], f64)> = shapes(&doc).iter().map(|s| (pt(&s["center"]), f(s, "radius"))).collect();
    assert_eq!(circles.len(), 40);
    let mut words = 0;
    for name in BUILTINS {
        let shown = String::from_utf8_lossy(&zf_ok(d, &["machines", "show", name]).stdout).into_owned();
        let inch = shown.replacen("units = \"mm\"", "units = \"inch\"", 1);
        assert_ne!(inch, shown, "{name}: switched to inches");
        let fed = inch.replacen("travel = \"rapid\"", "travel = \"feed\"", 1);
        assert_ne!(fed, inch, "{name}: switched to G1 travel");
        for profile in [&inch, &fed] {
            for feeds in FEEDS {
                words += check_program(d, profile, feeds, &circles);
            }
        }
    }
    assert!(words > 1000, "{words} F words checked");
}

/// The check fails on the old whole-inch feeds and on a feed a tenth of a percent off.
#[test]
fn the_feed_check_can_fail() {
    let laser = Profile {
        decimals: 5,
        bed: [0.0, 0.0, 10.0, 10.0],
        tool: ToolModel::Laser,
    };
    let program = |f: &str| format!("G90\nG20\nM5 S0\nG0 X1.00000 Y1.00000\nM4 S800\nG1 X2.00000 Y1.00000 F{f}\nM5 S0\nM2\n");
    let per_mm = 1.0 / 25.4;
    let r = replay(&program("1.18110"), &laser);
    assert!(
        r.errors.is_empty() && feed_faults(&r, per_mm, 30.0, &[3000.0], 1e-3, 0.0).is_empty(),
        "{:?}",
        r.errors
    );
    let r = replay(&program("1"), &laser);
    assert_eq!(feed_faults(&r, per_mm, 30.0, &[3000.0], 1e-3, 0.0).len(), 1, "whole inches");
    let r = replay(&program("1.18240"), &laser);
    assert_eq!(feed_faults(&r, per_mm, 30.0, &[3000.0], 1e-3, 0.0).len(), 1, "0.11 % fast");
    // The travel feed of a G1 with the tool off.
    let travel = program("1.18110").replace("G0 X1.00000 Y1.00000", "G1 X1.00000 Y1.00000 F118.11024");
    let r = replay(&travel, &laser);
    assert!(feed_faults(&r, per_mm, 30.0, &[3000.0], 1e-3, 0.0).is_empty());
    assert_eq!(feed_faults(&r, per_mm, 30.0, &[2000.0], 1e-3, 0.0).len(), 1);
}
