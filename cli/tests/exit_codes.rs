//! Exit codes and bad input (DESIGN sections 3 and 6): exit 2 with a message naming the
//! argument and no file written or touched; exit 3 when the fill halts, with every shape
//! placed so far in the output.

mod common;

use common::*;
use serde_json::Value;
use std::path::Path;

const KEEP: &[u8] = b"existing content, must survive\n";

/// Runs `fill ARGS -o OUT` in `dir` and checks exit 2, that stderr names every flag in
/// `flags`, and that nothing is printed on stdout.
fn expect_usage(dir: &Path, args: &[&str], out: &str, flags: &[&str]) -> Out {
    let mut a = vec!["fill"];
    a.extend_from_slice(args);
    a.extend_from_slice(&["-o", out]);
    let o = zf(dir, &a);
    assert_eq!(o.code, 2, "zetafill {a:?}: exit {} (stderr: {})", o.code, o.stderr);
    for fl in flags {
        assert!(names_flag(&o.stderr, fl), "zetafill {a:?}: stderr does not name {fl}: {}", o.stderr);
    }
    assert!(o.stdout.is_empty(), "zetafill {a:?}: stdout not empty");
    o
}

/// A bad input, tried with no output file and with an existing one.
fn bad(args: &[&str], flags: &[&str]) -> Out {
    bad_to(args, "out.json", flags)
}

fn bad_to(args: &[&str], out: &str, flags: &[&str]) -> Out {
    // No file beforehand: none afterwards.
    let dir = tmp();
    let o = expect_usage(dir.path(), args, out, flags);
    assert!(listing(dir.path()).is_empty(), "zetafill {args:?}: left {:?}", listing(dir.path()));

    // An existing file is left byte for byte, and nothing else appears.
    let dir = tmp();
    let p = dir.path().join(out);
    std::fs::write(&p, KEEP).unwrap_or_else(|e| panic!("write: {e}"));
    expect_usage(dir.path(), args, out, flags);
    assert_eq!(read(&p), KEEP, "zetafill {args:?}: the existing output was changed");
    assert_eq!(listing(dir.path()), vec![p], "zetafill {args:?}: extra files");
    o
}

#[test]
fn bad_exponent() {
    bad(&["--c", "1"], &["--c"]);
    bad(&["--c", "0.5"], &["--c"]);
    bad(&["--c", "nan"], &["--c"]);
    bad(&["--c", "NaN"], &["--c"]);
    bad(&["--c", "inf"], &["--c"]);
    bad(&["--c", "abc"], &["--c"]);
    bad(&["--c=-2"], &["--c"]);
}

#[test]
fn bad_offset() {
    bad(&["--n-offset", "0"], &["--n-offset"]);
    bad(&["--n-offset=-1"], &["--n-offset"]);
    bad(&["--n-offset", "inf"], &["--n-offset"]);
}

#[test]
fn bad_stop_conditions() {
    bad(&["--count", "0"], &["--count"]);
    bad(&["--fill", "0"], &["--fill"]);
    bad(&["--fill", "1"], &["--fill"]);
    bad(&["--fill", "1.5"], &["--fill"]);
    bad(&["--fill", "nan"], &["--fill"]);
    bad(&["--min-size", "0"], &["--min-size"]);
    bad(&["--max-trials", "0"], &["--max-trials"]);
}

#[test]
fn bad_gap() {
    bad(&["--gap=-1"], &["--gap"]);
    bad(&["--gap", "nan"], &["--gap"]);
    bad(&["--gap", "150", "--region", "rect:200:200"], &["--gap"]);
    bad(&["--gap", "100", "--region", "rect:200:200"], &["--gap"]);
}

/// DESIGN section 6: a negative number given as a separate word must also be reported as a
/// bad value of its flag (not as an unknown argument '-1').
#[test]
fn negative_values_as_separate_words_name_their_flag() {
    bad(&["--n-offset", "-1"], &["--n-offset"]);
    bad(&["--gap", "-1"], &["--gap"]);
    bad(&["--c", "-2"], &["--c"]);
}

/// DESIGN section 6: out-of-range numbers get a clear message naming the problem. Extreme
/// but finite values must not end in "area NaN" / "area inf" blamed on --c.
#[test]
fn extreme_values_get_clear_messages() {
    for (args, flag) in [
        (&["--n-offset", "1e300"][..], "--n-offset"),
        (&["--region", "rect:1e300:1e300"][..], "--region"),
    ] {
        let o = bad(args, &[flag]);
        assert!(
            !o.stderr.contains("NaN") && !o.stderr.contains("inf mm"),
            "zetafill {args:?}: {}",
            o.stderr
        );
    }
}

#[test]
fn bad_region() {
    bad(&["--region", "rect:0:10"], &["--region"]);
    bad(&["--region", "rect:10:-1"], &["--region"]);
    bad(&["--region", "rect:10"], &["--region"]);
    bad(&["--region", "rect:10:10:10"], &["--region"]);
    bad(&["--region", "rect:inf:10"], &["--region"]);
    // circle:R is a supported region now; these are not.
    bad(&["--region", "ellipse:5:3"], &["--region"]);
    bad(&["--region", "square"], &["--region"]);
    bad(&["--region", "circle:0"], &["--region"]);
    bad(&["--region", "annulus:5:6"], &["--region"]);
    bad(&["--region", "polygon:0,0,1,1"], &["--region"]);
    // Only rect regions can be periodic.
    bad(&["--region", "circle:50", "--periodic"], &["--periodic"]);
}

#[test]
fn bad_shape() {
    bad(&["--shape", "hexagon"], &["--shape"]);
    bad(&["--shape", "rect:0"], &["--shape"]);
    bad(&["--shape", "rect:nan"], &["--shape"]);
    bad(&["--shape", "rect:-2"], &["--shape"]);
    bad(&["--shape", "rect"], &["--shape"]);
    bad(&["--rotate", "sometimes"], &["--rotate"]);
}

#[test]
fn bad_dimension() {
    bad(&["--dimension", "2"], &["--dimension"]);
    bad(&["--dimension", "0"], &["--dimension"]);
    bad(&["--dimension", "nan"], &["--dimension"]);
    bad(&["--c", "1.3", "--dimension", "1.5"], &["--c", "--dimension"]);
}

#[test]
fn first_shape_that_cannot_fit() {
    let o = bad(&["--c", "2.9", "--region", "rect:10:10"], &["--c", "--n-offset"]);
    assert!(
        o.stderr.contains("lower --c") && o.stderr.contains("raise --n-offset"),
        "advice: {}",
        o.stderr
    );
    // Also for squares and a periodic region.
    bad(
        &["--c", "2.9", "--region", "rect:10:5", "--shape", "square"],
        &["--c", "--n-offset"],
    );
    bad(&["--c", "2.9", "--region", "rect:10:10", "--periodic"], &["--c", "--n-offset"]);
}

#[test]
fn unknown_output_extension() {
    bad_to(&["--count", "5"], "out.txt", &["--output"]);
    bad_to(&["--count", "5"], "noext", &["--output"]);
}

#[test]
fn output_is_a_directory() {
    let dir = tmp();
    let d = dir.path();
    let sub = d.join("sub.svg");
    std::fs::create_dir(&sub).unwrap_or_else(|e| panic!("mkdir: {e}"));
    std::fs::write(sub.join("keep"), KEEP).unwrap_or_else(|e| panic!("write: {e}"));
    expect_usage(d, &["--count", "5"], "sub.svg", &["--output"]);
    assert!(sub.is_dir());
    assert_eq!(listing(&sub), vec![sub.join("keep")]);
    assert_eq!(read(&sub.join("keep")), KEEP);
    assert_eq!(listing(d), vec![sub.clone()]);
    // Also '.' and a path with a trailing slash.
    expect_usage(d, &["--count", "5"], ".", &["--output"]);
    expect_usage(d, &["--count", "5"], "sub.svg/", &["--output"]);
    assert_eq!(listing(d), vec![sub]);
}

#[test]
fn output_in_a_missing_folder() {
    let dir = tmp();
    let d = dir.path();
    expect_usage(d, &["--count", "5"], "missing/out.json", &["--output"]);
    expect_usage(d, &["--count", "5"], "missing/deeper/out.svg", &["--output"]);
    assert!(listing(d).is_empty(), "left {:?}", listing(d));
}

#[test]
fn missing_output_flag_is_usage() {
    let dir = tmp();
    let o = zf(dir.path(), &["fill", "--count", "5"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--output"), "{}", o.stderr);
    let o = zf(dir.path(), &["frobnicate"]);
    assert_eq!(o.code, 2);
    assert!(listing(dir.path()).is_empty());
}

#[test]
fn help_and_version_exit_zero() {
    let dir = tmp();
    for a in [&["--help"][..], &["--version"][..], &["fill", "--help"][..]] {
        let o = zf(dir.path(), a);
        assert_eq!(o.code, 0, "{a:?}");
        assert!(!o.stdout.is_empty());
    }
}

#[test]
fn stats_bad_input() {
    let dir = tmp();
    for (args, flag) in [
        (&["stats", "zeta", "--c", "1"][..], "--c"),
        (&["stats", "zeta", "--c", "nan"][..], "--c"),
        (&["stats", "zeta", "--c", "1.3", "--n-offset", "0"][..], "--n-offset"),
        (&["stats", "zeta"][..], "--c"),
    ] {
        let o = zf(dir.path(), args);
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        assert!(names_flag(&o.stderr, flag), "{args:?}: {}", o.stderr);
        assert!(o.stdout.is_empty());
    }
}

// ---------------------------------------------------------------------------------------------
// Halting (exit 3)

/// Parses "halted at placement N ... holds the N shapes" and checks both numbers agree.
fn halt_index(stderr: &str) -> usize {
    let after = |pat: &str| -> usize {
        let i = stderr.find(pat).unwrap_or_else(|| panic!("stderr lacks '{pat}': {stderr}")) + pat.len();
        let digits: String = stderr[i..].chars().take_while(char::is_ascii_digit).collect();
        digits.parse().unwrap_or_else(|_| panic!("no number after '{pat}': {stderr}"))
    };
    let k = after("halted at placement ");
    assert_eq!(after("holds the "), k, "the two counts in: {stderr}");
    k
}

fn halting_case(args: &[&str], e: Expect, min_index: usize) {
    let dir = tmp();
    let d = dir.path();
    // The output file exists beforehand: it is replaced by the partial fill.
    std::fs::write(d.join("h.json"), KEEP).unwrap_or_else(|err| panic!("write: {err}"));
    let run = |out: &str| {
        let mut a = vec!["fill"];
        a.extend_from_slice(args);
        a.extend_from_slice(&["-o", out]);
        let o = zf(d, &a);
        assert_eq!(o.code, 3, "zetafill {a:?}: exit {} ({})", o.code, o.stderr);
        assert!(o.stderr.contains("halted at placement"), "{}", o.stderr);
        o
    };
    let o = run("h.json");
    let k = halt_index(&o.stderr);
    assert!(k >= min_index, "halted at {k}");
    let doc = parse_json(&read(&d.join("h.json")));
    assert!(check_doc(&doc, &e), "stats.halted");
    assert_eq!(shapes(&doc).len(), k, "the output holds exactly the {k} shapes placed");
    let st = doc.get("stats").unwrap_or(&Value::Null);
    assert_eq!(u(st, "placed"), k as u64);
    if let Some(stop) = st.get("stop") {
        assert_eq!(stop.as_str(), Some("halted"));
    }
    assert_geometry(&doc);

    // The same run in the other formats, and to standard output.
    let o = run("h.csv");
    assert_eq!(halt_index(&o.stderr), k);
    let csv = String::from_utf8_lossy(&read(&d.join("h.csv"))).into_owned();
    assert_eq!(csv.lines().count(), k + 1, "CSV header + {k} rows");
    let o = run("h.svg");
    assert_eq!(halt_index(&o.stderr), k);
    let svg = read(&d.join("h.svg"));
    assert!(
        usvg::Tree::from_data(&svg, &usvg::Options::default()).is_ok(),
        "the halted SVG parses"
    );
    let text = String::from_utf8_lossy(&svg).into_owned();
    let n = text.matches("<circle ").count() + text.matches("<polygon ").count();
    if !e.periodic {
        assert_eq!(n, k, "SVG elements");
    }
    let mut a = vec!["fill"];
    a.extend_from_slice(args);
    a.extend_from_slice(&["-o", "-", "--format", "json"]);
    let o = zf(d, &a);
    assert_eq!(o.code, 3);
    assert_eq!(o.stdout, read(&d.join("h.json")), "stdout JSON of a halted run");
}

#[test]
fn halting_exits_3_with_the_shapes_placed_so_far() {
    halting_case(
        &["--c", "1.45", "--count", "300", "--max-trials", "50", "--seed", "1"],
        Expect {
            c: 1.45,
            w: 200.0,
            h: 200.0,
            count: Some(300),
            max_trials: 50,
            ..Expect::default()
        },
        1,
    );
}

#[test]
fn halting_late_in_a_long_run() {
    halting_case(
        &[
            "--c",
            "1.3",
            "--count",
            "3000",
            "--max-trials",
            "1000",
            "--region",
            "rect:100:80",
            "--seed",
            "1",
            // The fast sampler needs far fewer trials than this limit.
            "--sampler",
            "reference",
        ],
        Expect {
            count: Some(3000),
            max_trials: 1000,
            sampler: "reference",
            ..Expect::default()
        },
        100,
    );
}

#[test]
fn halting_squares_periodic() {
    halting_case(
        &[
            "--shape",
            "square",
            "--periodic",
            "--c",
            "1.3",
            "--count",
            "5000",
            "--max-trials",
            "300",
            "--region",
            "rect:100:80",
            "--seed",
            "2",
        ],
        Expect {
            shape: "square",
            rotate: "random",
            seed: 2,
            periodic: true,
            count: Some(5000),
            max_trials: 300,
            ..Expect::default()
        },
        1,
    );
}
