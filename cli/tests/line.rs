//! End-to-end tests of `zetafill line`: every format written and read back, the segments
//! checked independently of the core (inside, no overlap, periodic wrap), reruns
//! byte-identical, prefixes stable, bad input refused with exit 2 and no file, halting exit 3
//! with a valid partial file. The checker is shown to fail on broken fills.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
// The checks are written `!(a < b)` on purpose: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod common;

use common::{line_to, parse_json, read, tmp, zf, zf_ok};
use serde_json::Value;

/// `(start, length)` of every segment of a line document.
fn segments(doc: &Value) -> Vec<(f64, f64)> {
    doc["shapes"].as_array().map_or(vec![], |v| {
        v.iter()
            .map(|s| (s["start"].as_f64().unwrap_or(f64::NAN), s["length"].as_f64().unwrap_or(f64::NAN)))
            .collect()
    })
}

/// Independent checker: every segment inside `[gap, L - gap]` (periodic: starts in `[0, L)`),
/// sorted neighbours more than `gap` apart, the last clear of the first + L when periodic,
/// lengths the power law `L / (zeta (i+N)^c)` with the document's own zeta.
fn check_line(doc: &Value) -> Result<(), String> {
    let l = doc["region"]["length"].as_f64().ok_or("no length")?;
    let periodic = doc["region"]["periodic"].as_bool().ok_or("no periodic")?;
    let gap = doc["params"]["gap"].as_f64().ok_or("no gap")?;
    let (c, n, z) = (
        doc["params"]["c"].as_f64().ok_or("c")?,
        doc["params"]["n_offset"].as_f64().ok_or("N")?,
        doc["zeta"].as_f64().ok_or("zeta")?,
    );
    let segs = segments(doc);
    for (i, &(s, len)) in segs.iter().enumerate() {
        let want = l / (z * (i as f64 + n).powf(c));
        if !(((len - want) / want).abs() < 1e-12) {
            return Err(format!("segment {i}: length {len}, expected {want}"));
        }
        let inside = if periodic {
            s >= 0.0 && s < l && len + gap < l
        } else {
            s >= gap && s + len <= l - gap
        };
        if !inside {
            return Err(format!("segment {i} [{s}, {}] is outside", s + len));
        }
    }
    let mut v = segs.clone();
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    for w in v.windows(2) {
        if !(w[0].0 + w[0].1 + gap < w[1].0) {
            return Err(format!("{:?} and {:?} overlap or come within {gap}", w[0], w[1]));
        }
    }
    if periodic && v.len() > 1 {
        let (first, last) = (v[0], v[v.len() - 1]);
        if !(last.0 + last.1 + gap < first.0 + l) {
            return Err(format!("{last:?} wraps onto {first:?}"));
        }
    }
    Ok(())
}

#[test]
fn json_follows_the_design_and_passes_the_checker() {
    let d = tmp();
    for (periodic, gap, count) in [(false, "0", 1500), (true, "0", 1500), (false, "0.002", 400), (true, "0.002", 400)] {
        let k = count.to_string();
        let mut args = vec!["--c", "1.3", "--count", &k, "--seed", "5", "--length", "150", "--gap", gap];
        if periodic {
            args.push("--periodic");
        }
        let doc = parse_json(&line_to(d.path(), "a.json", &args));
        assert_eq!(doc["version"], 1);
        assert_eq!(doc["mode"], "line");
        assert_eq!(doc["region"]["kind"], "interval");
        assert_eq!(doc["region"]["length"], 150.0);
        assert_eq!(doc["region"]["periodic"], periodic);
        assert_eq!(doc["params"]["seed"], 5);
        assert_eq!(doc["params"]["dimension"], 1.0 / 1.3);
        assert_eq!(doc["stats"]["placed"], count);
        assert_eq!(doc["stats"]["halted"], false);
        let shapes = doc["shapes"].as_array().cloned().unwrap_or_default();
        assert_eq!(shapes.len(), count);
        for (i, s) in shapes.iter().enumerate() {
            assert_eq!(s["index"], i);
            assert_eq!(s["kind"], "segment");
            assert!(s["trials"].as_u64().is_some_and(|t| t >= 1));
        }
        let trials: u64 = shapes.iter().filter_map(|s| s["trials"].as_u64()).sum();
        assert_eq!(doc["stats"]["trials"], trials);
        let placed: f64 = shapes.iter().filter_map(|s| s["length"].as_f64()).sum();
        assert!((doc["stats"]["fill_fraction"].as_f64().unwrap_or(0.0) - placed / 150.0).abs() < 1e-12);
        check_line(&doc).unwrap_or_else(|e| panic!("periodic={periodic} gap={gap}: {e}"));
    }
}

#[test]
fn periodic_fills_wrap_and_thirty_thousand_segments_are_routine() {
    let d = tmp();
    let doc = parse_json(&line_to(d.path(), "p.json", &["--c", "1.4", "--count", "30000", "--periodic"]));
    check_line(&doc).unwrap_or_else(|e| panic!("{e}"));
    let l = 200.0;
    let mut wrapped = segments(&doc).iter().filter(|s| s.0 + s.1 > l).count();
    for seed in 2..30 {
        let s = seed.to_string();
        let doc = parse_json(&line_to(
            d.path(),
            "q.json",
            &["--c", "1.2", "--count", "200", "--periodic", "--seed", &s],
        ));
        check_line(&doc).unwrap_or_else(|e| panic!("{e}"));
        wrapped += segments(&doc).iter().filter(|s| s.0 + s.1 > l).count();
    }
    assert!(wrapped > 0, "no segment crossed the periodic boundary");
}

#[test]
fn reruns_are_byte_identical_and_prefixes_stable() {
    let d = tmp();
    for name in ["a.svg", "a.json", "a.csv"] {
        let one = line_to(d.path(), name, &["--count", "800", "--seed", "9", "--periodic"]);
        let two = line_to(d.path(), name, &["--count", "800", "--seed", "9", "--periodic"]);
        assert_eq!(one, two, "{name} differs between runs");
    }
    let short = segments(&parse_json(&line_to(d.path(), "s.json", &["--count", "300", "--seed", "4"])));
    let long = segments(&parse_json(&line_to(d.path(), "l.json", &["--count", "900", "--seed", "4"])));
    assert_eq!(&long[..300], &short[..]);
    let other = segments(&parse_json(&line_to(d.path(), "o.json", &["--count", "300", "--seed", "5"])));
    assert_ne!(other, short);
}

#[test]
fn csv_and_digest_agree_with_json_and_the_core() {
    let d = tmp();
    let args = ["--c", "1.5", "--count", "400", "--seed", "3", "--periodic"];
    let doc = parse_json(&line_to(d.path(), "a.json", &args));
    let csv = String::from_utf8(line_to(d.path(), "a.csv", &args)).unwrap_or_default();
    let mut rows = csv.lines();
    assert_eq!(rows.next(), Some("index,kind,start,end,length,trials"));
    for (row, s) in rows.zip(doc["shapes"].as_array().cloned().unwrap_or_default()) {
        let f: Vec<&str> = row.split(',').collect();
        assert_eq!(f[0].parse::<u64>().ok(), s["index"].as_u64());
        assert_eq!(f[1], "segment");
        assert_eq!(f[2].parse::<f64>().ok(), s["start"].as_f64());
        assert_eq!(f[4].parse::<f64>().ok(), s["length"].as_f64());
        assert_eq!(f[5].parse::<u64>().ok(), s["trials"].as_u64());
    }
    // The digest equals the core's own digest of the same run, with either sampler.
    for sampler in ["fast", "reference"] {
        let mut a = vec!["line", "--format", "digest", "-o", "-", "--sampler", sampler];
        a.extend_from_slice(&args);
        let out = String::from_utf8(zf_ok(d.path(), &a).stdout).unwrap_or_default();
        let mut segs = vec![zetafill::line::Segment::<f64>::default(); 401];
        let mut index = vec![0u32; zetafill::line::index_words(401)];
        let mut words = vec![zetafill::line::Gap::default(); zetafill::line::gaps_for(401)];
        let storage = zetafill::line::Storage {
            segments: &mut segs,
            index: &mut index,
        };
        let interval = zetafill::line::Interval {
            length: 200.0,
            periodic: true,
        };
        let mut e = zetafill::line::Engine::new(zetafill::line::Params::new(1.5, 1.0), interval, storage).unwrap_or_else(|e| panic!("{e}"));
        let mut rng = zetafill::rng_from_seed(3);
        let stop = zetafill::Stop {
            count: Some(400),
            ..zetafill::Stop::default()
        };
        if sampler == "fast" {
            let mut gaps = zetafill::line::Gaps::new(&mut words).unwrap_or_else(|e| panic!("{e}"));
            e.run_fast(&mut gaps, &mut rng, &stop, |_| {});
        } else {
            e.run(&mut rng, &stop, |_| {});
        }
        let (n, h) = zetafill::internals::line::line_digest(&e);
        assert_eq!(out.trim(), format!("{n} {h:016x}"), "{sampler}");
    }
    // The default is the exact gap sampler, and the document says which ran.
    assert_eq!(doc["params"]["sampler"], "fast");
}

fn count(svg: &str, tag: &str) -> usize {
    svg.matches(&format!("<{tag} ")).count() + svg.matches(&format!("<{tag}/")).count()
}

#[test]
fn every_render_is_valid_svg_in_mm() {
    let d = tmp();
    let base = ["--count", "300", "--seed", "2", "--c", "1.3"];
    let doc = parse_json(&line_to(d.path(), "a.json", &base));
    let segs = segments(&doc);
    for render in ["dashes", "circles", "bars", "zoom"] {
        for periodic in [false, true] {
            let mut args = base.to_vec();
            args.extend_from_slice(&["--render", render]);
            if periodic {
                args.push("--periodic");
            }
            let bytes = line_to(d.path(), "a.svg", &args);
            let tree = usvg::Tree::from_data(&bytes, &usvg::Options::default()).unwrap_or_else(|e| panic!("{render}: {e}"));
            assert!(
                (tree.size().width() - 200.0 / 25.4 * 96.0).abs() < 0.01,
                "{render}: width is not 200 mm"
            );
            let svg = String::from_utf8(bytes).unwrap_or_default();
            assert!(svg.contains("width=\"200mm\""));
            assert!(svg.contains("zetafill line --length 200"), "no command line in the metadata");
            assert!(!svg.contains("NaN") && !svg.contains("inf"));
            if !periodic {
                let visible = segs.iter().filter(|s| s.1 >= 1e-4).count();
                match render {
                    "dashes" => assert_eq!(count(&svg, "line"), visible, "one pen-down per segment"),
                    "bars" => assert_eq!(count(&svg, "rect"), visible),
                    "circles" => assert_eq!(count(&svg, "circle"), visible),
                    _ => assert!(count(&svg, "circle") > visible, "zoom rows repeat circles"),
                }
            }
        }
    }
    let png = line_to(d.path(), "a.png", &base);
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn bad_input_exits_2_names_the_flag_and_writes_nothing() {
    let d = tmp();
    let cases: &[(&[&str], &str)] = &[
        (&["--c", "1"], "--c"),
        (&["--c", "0.5"], "--c"),
        (&["--c", "-3"], "--c"),
        (&["--c", "nan"], "--c"),
        (&["--c", "inf"], "--c"),
        (&["--n-offset", "0"], "--n-offset"),
        (&["--n-offset", "-1"], "--n-offset"),
        (&["--length", "0"], "--length"),
        (&["--length", "-5"], "--length"),
        (&["--length", "nan"], "--length"),
        (&["--gap", "-1"], "--gap"),
        (&["--gap", "150"], "--gap"),
        (&["--gap", "80", "--c", "1.3"], "--gap"),
        (&["--fill", "1"], "--fill"),
        (&["--fill", "0"], "--fill"),
        (&["--count", "0"], "--count"),
        (&["--dimension", "1"], "--dimension"),
        (&["--dimension", "1.5"], "--dimension"),
        (&["--max-trials", "0"], "--max-trials"),
        (&["--min-size", "0"], "--min-size"),
        (&["--zoom-fraction", "1"], "--zoom-fraction"),
        (&["--zoom-center", "500"], "--zoom-center"),
        (&["--render", "spiral"], "--render"),
    ];
    for (extra, flag) in cases {
        let mut args = vec!["line", "-o", "out.svg"];
        args.extend_from_slice(extra);
        let o = zf(d.path(), &args);
        assert_eq!(o.code, 2, "{extra:?}: exit {} ({})", o.code, o.stderr);
        assert!(o.stderr.contains(flag), "{extra:?}: message does not name {flag}: {}", o.stderr);
        assert!(!d.path().join("out.svg").exists(), "{extra:?} wrote a file");
    }
    let o = zf(d.path(), &["line", "-o", "out.txt"]);
    assert_eq!(o.code, 2);
    assert!(o.stderr.contains("--output"));
    let o = zf(d.path(), &["line", "-o", "no/such/dir/out.svg"]);
    assert_eq!(o.code, 2);
    assert!(d.path().read_dir().map(|r| r.count()).unwrap_or(1) == 0, "a file was left behind");
}

#[test]
fn halting_exits_3_with_a_valid_partial_file() {
    let d = tmp();
    // At c = 3 the first segments leave little room: with 3 trials per placement the paper's
    // sampler halts (the gap sampler needs one trial a placement).
    let o = zf(
        d.path(),
        &[
            "line",
            "--c",
            "3",
            "--count",
            "500",
            "--max-trials",
            "3",
            "--sampler",
            "reference",
            "-o",
            "h.json",
        ],
    );
    assert_eq!(o.code, 3, "{}", o.stderr);
    assert!(o.stderr.contains("halted at placement"), "{}", o.stderr);
    let doc = parse_json(&read(&d.path().join("h.json")));
    assert_eq!(doc["stats"]["halted"], true);
    assert_eq!(doc["stats"]["stop"], "halted");
    let placed = doc["stats"]["placed"].as_u64().unwrap_or(0);
    assert!(placed > 0 && placed < 500);
    assert!(o.stderr.contains(&format!("placement {placed}")));
    check_line(&doc).unwrap_or_else(|e| panic!("{e}"));
}

/// The gap sampler knows at once when no segment can fit: with a 26 mm clearance in 200 mm
/// at c = 2 the second segment fits on neither side of the first, and more trials cannot help.
#[test]
fn a_proven_halt_exits_3_at_once() {
    let d = tmp();
    let o = zf(d.path(), &["line", "--c", "2", "--gap", "26", "--count", "5", "-o", "p.json"]);
    assert_eq!(o.code, 3, "{}", o.stderr);
    assert!(o.stderr.contains("halted at placement 1 after 0 trials"), "{}", o.stderr);
    assert!(o.stderr.contains("more trials cannot help"), "{}", o.stderr);
    let doc = parse_json(&read(&d.path().join("p.json")));
    assert_eq!(doc["stats"]["placed"], 1);
    check_line(&doc).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn stop_conditions_and_dimension() {
    let d = tmp();
    let doc = parse_json(&line_to(d.path(), "f.json", &["--fill", "0.9"]));
    assert_eq!(doc["stats"]["stop"], "fill");
    assert!(doc["stats"]["fill_fraction"].as_f64().is_some_and(|f| f >= 0.9));
    let doc = parse_json(&line_to(d.path(), "m.json", &["--min-size", "0.2"]));
    assert_eq!(doc["stats"]["stop"], "min-size");
    assert!(segments(&doc).iter().all(|s| s.1 >= 0.2));
    let doc = parse_json(&line_to(d.path(), "d.json", &["--dimension", "0.5", "--count", "50"]));
    assert_eq!(doc["params"]["c"], 2.0);
}

/// A line document with c = 2, N = 1 in `[0, l]` and segments starting at `starts`.
fn synthetic(l: f64, periodic: bool, starts: &[f64]) -> Value {
    let z = std::f64::consts::PI * std::f64::consts::PI / 6.0;
    let shapes: Vec<Value> = starts
        .iter()
        .enumerate()
        .map(|(i, &s)| serde_json::json!({ "index": i, "kind": "segment", "start": s, "length": l / (z * ((i + 1) as f64).powi(2)), "trials": 1 }))
        .collect();
    serde_json::json!({ "version": 1, "mode": "line", "params": { "c": 2.0, "n_offset": 1.0, "gap": 0.0 }, "zeta": z,
        "region": { "kind": "interval", "length": l, "periodic": periodic }, "shapes": shapes })
}

#[test]
fn the_checker_fails_on_broken_fills() {
    // Lengths 6.08, 1.52, 0.68 in [0, 10].
    assert!(check_line(&synthetic(10.0, false, &[1.0, 7.5, 9.2])).is_ok());
    assert!(check_line(&synthetic(10.0, true, &[1.0, 7.5, 0.1])).is_ok());
    let broken: [(&str, Value); 6] = [
        ("overlap", synthetic(10.0, false, &[1.0, 6.5, 9.2])),
        (
            "touching",
            synthetic(10.0, false, &[1.0, 10.0 / (std::f64::consts::PI.powi(2) / 6.0) + 1.0, 9.2]),
        ),
        ("outside", synthetic(10.0, false, &[1.0, 7.5, 9.5])),
        ("wraps onto the first", synthetic(10.0, true, &[1.0, 9.6])),
        ("start outside the period", synthetic(10.0, true, &[1.0, 10.0])),
        ("negative start", synthetic(10.0, false, &[-0.5])),
    ];
    for (what, doc) in broken {
        assert!(check_line(&doc).is_err(), "not caught: {what}");
    }
    let mut wrong = synthetic(10.0, false, &[1.0, 7.5, 9.2]);
    wrong["shapes"][1]["length"] = Value::from(1.6);
    assert!(check_line(&wrong).is_err(), "wrong length not caught");
    // And on a real fill with one segment moved onto another.
    let d = tmp();
    let mut doc = parse_json(&line_to(d.path(), "a.json", &["--count", "50", "--periodic"]));
    assert!(check_line(&doc).is_ok());
    doc["shapes"][2]["start"] = doc["shapes"][1]["start"].clone();
    assert!(check_line(&doc).is_err());
}

/// Bug: `--page` with SVG was refused as "for G-code output" and with G-code as "for SVG",
/// while line has pages and layers in no format. One message in every format, and line's
/// help no longer offers them (nor calls the other plot flags SVG options).
#[test]
fn pages_and_layers_are_refused_the_same_way_in_every_format() {
    let d = tmp();
    for (flag, value) in [("--page", "a4"), ("--layers", "size-bands:2")] {
        let mut messages = Vec::new();
        for out in ["o.svg", "o.gcode", "o.png", "o.json"] {
            let o = zf(d.path(), &["line", flag, value, "-o", out]);
            assert_eq!(o.code, 2, "{flag} -o {out}: exit {} ({})", o.code, o.stderr);
            assert!(o.stderr.starts_with(&format!("error: {flag}:")), "{flag} -o {out}: {}", o.stderr);
            assert!(o.stderr.contains("any format"), "{flag} -o {out}: {}", o.stderr);
            messages.push(o.stderr);
        }
        assert!(messages.windows(2).all(|w| w[0] == w[1]), "{flag}: {messages:?}");
    }
    assert_eq!(d.path().read_dir().map(|r| r.count()).unwrap_or(1), 0, "a file was written");
    let help = String::from_utf8_lossy(&zf_ok(d.path(), &["line", "--help"]).stdout).into_owned();
    let plot = help
        .split("Plotters and lasers:")
        .nth(1)
        .unwrap_or_else(|| panic!("no plot flags in: {help}"));
    for word in ["--page", "--layers", "SVG", "page"] {
        assert!(!plot.contains(word), "line's plot help mentions {word}: {plot}");
    }
}
