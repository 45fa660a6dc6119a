//! Exit codes and bad input (docs/cli.md, What every subcommand shares): exit 2 with a message naming the
//! argument and no file written or touched; exit 3 when the fill halts, with every shape
//! placed so far in the output.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

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

/// Bad input: a negative number given as a separate word must also be reported as a
/// bad value of its flag (not as an unknown argument '-1').
#[test]
fn negative_values_as_separate_words_name_their_flag() {
    bad(&["--n-offset", "-1"], &["--n-offset"]);
    bad(&["--gap", "-1"], &["--gap"]);
    bad(&["--c", "-2"], &["--c"]);
}

/// Bad input: out-of-range numbers get a clear message naming the problem. Extreme
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
    bad(&["--region", "polygon:0,0,100,0,100,100/10,10,20"], &["--region"]);
    bad(&["--region", "polygon:0,0,100,0,100,100,0,100/"], &["--region"]);
    // Two rings that cross each other.
    bad(
        &["--region", "polygon:0,0,100,0,100,100,0,100/50,50,150,50,150,150,50,150"],
        &["--region"],
    );
    // Only rect regions can be periodic.
    bad(&["--region", "circle:50", "--periodic"], &["--periodic"]);
}

/// What `--scalar fixed` cannot compute exactly is refused, naming the flag (the issue
/// "Hardening": 2,000 squares in a 500 m square came out overlapping by tens of metres, exit
/// 3): a region beyond 10,000 mm a side, and stop conditions that reach shapes narrower than
/// 10 µm (circles in the default 200 mm square do from shape 1,738,916 on).
#[test]
fn fixed_point_refuses_what_it_cannot_compute() {
    let issue = [
        "--shape",
        "square",
        "--region",
        "rect:500000:500000",
        "--scalar",
        "fixed",
        "--c",
        "1.3",
        "--n-offset",
        "2",
        "--count",
        "2000",
        "--seed",
        "67",
    ];
    let o = bad(&issue, &["--region"]);
    assert!(o.stderr.contains("10000 mm"), "{}", o.stderr);
    bad(&["--scalar", "fixed", "--region", "rect:10000.5:100"], &["--region"]);
    bad(&["--scalar", "fixed", "--region", "circle:5001"], &["--region"]);
    let o = bad(&["--scalar", "fixed", "--count", "2000000"], &["--count"]);
    assert!(o.stderr.contains("shape 1738916") && o.stderr.contains("0.01 mm"), "{}", o.stderr);
    bad(&["--scalar", "fixed", "--min-size", "0.005"], &["--min-size"]);
    bad(&["--scalar", "fixed", "--count", "2000000", "--fill", "0.99"], &["--count"]);
    bad(&["--scalar", "fixed", "--fill", "0.99"], &["--fill"]);
    // Within the limits the same flags run.
    let dir = tmp();
    zf_ok(
        dir.path(),
        &[
            "fill",
            "--scalar",
            "fixed",
            "--region",
            "rect:10000:10000",
            "--count",
            "50",
            "-o",
            "a.json",
        ],
    );
    zf_ok(
        dir.path(),
        &["fill", "--region", "rect:500000:500000", "--count", "50", "-o", "b.json"],
    );
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

// ---------------------------------------------------------------------------------------------
// Regressions found by the audit of bad input

/// A copy of a built-in machine profile written to `dir/name`.
fn profile(dir: &Path, name: &str) -> Vec<u8> {
    let o = zf_ok(dir, &["machines", "show", "grbl-servo-pen"]);
    std::fs::write(dir.join(name), &o.stdout).unwrap_or_else(|e| panic!("write: {e}"));
    o.stdout
}

/// Bug: the `--machine FILE.toml` profile was not an input, so `-o` could overwrite it
/// (exit 0) in every mode that writes G-code. It is refused like any input, also through a
/// symbolic link, and the profile is left byte for byte.
#[test]
fn output_equal_to_the_machine_profile_is_refused() {
    let dir = tmp();
    let d = dir.path();
    let text = profile(d, "pen.toml");
    #[cfg(unix)]
    std::os::unix::fs::symlink("pen.toml", d.join("link.toml")).unwrap_or_else(|e| panic!("symlink: {e}"));
    let runs: &[&[&str]] = &[
        &[
            "fill",
            "--count",
            "20",
            "--machine",
            "pen.toml",
            "--format",
            "gcode",
            "-o",
            "pen.toml",
        ],
        &[
            "fill",
            "--count",
            "20",
            "--machine",
            "./pen.toml",
            "--format",
            "gcode",
            "-o",
            "pen.toml",
        ],
        #[cfg(unix)]
        &[
            "fill",
            "--count",
            "20",
            "--machine",
            "pen.toml",
            "--format",
            "gcode",
            "-o",
            "link.toml",
        ],
        &[
            "line",
            "--count",
            "20",
            "--machine",
            "pen.toml",
            "--format",
            "gcode",
            "-o",
            "pen.toml",
        ],
        &[
            "territory",
            "--points",
            "200",
            "--machine",
            "pen.toml",
            "--format",
            "gcode",
            "-o",
            "pen.toml",
        ],
        &["tile", "--machine", "pen.toml", "--format", "gcode", "-o", "pen.toml"],
    ];
    for args in runs {
        let o = zf(d, args);
        assert_eq!(o.code, 2, "zetafill {args:?}: exit {} ({})", o.code, o.stderr);
        assert!(names_flag(&o.stderr, "--output"), "zetafill {args:?}: {}", o.stderr);
        assert!(
            o.stderr.contains("never replaces an input") && o.stderr.contains("--machine"),
            "zetafill {args:?}: {}",
            o.stderr
        );
        assert_eq!(read(&d.join("pen.toml")), text, "zetafill {args:?} changed the profile");
    }
    // A built-in name is no file: an output of that name is fine.
    zf_ok(
        d,
        &[
            "fill",
            "--count",
            "5",
            "--machine",
            "grbl-laser",
            "--format",
            "gcode",
            "-o",
            "grbl-laser",
        ],
    );
}

/// Whether this process can create a file in `dir` (root can in a folder without write
/// permission).
fn can_create_in(dir: &Path) -> bool {
    tempfile::tempfile_in(dir).is_ok()
}

/// Bug: an output in a folder that takes no new files was found only after the work (exit 1,
/// "cannot create a temporary file"). It is refused before, with exit 2 naming --output.
#[test]
fn unwritable_output_folder_is_found_before_the_work() {
    let dir = tmp();
    let d = dir.path();
    let mut folders = Vec::new();
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let locked = d.join("locked");
        std::fs::create_dir(&locked).unwrap_or_else(|e| panic!("mkdir: {e}"));
        std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o555)).unwrap_or_else(|e| panic!("chmod: {e}"));
        folders.push(locked);
    }
    // sysfs takes no new files, not even from root.
    folders.push(std::path::PathBuf::from("/sys"));
    let mut tried = 0;
    for folder in folders.iter().filter(|f| f.is_dir() && !can_create_in(f)) {
        let out = folder.join("x.svg");
        let out = out.to_string_lossy();
        let o = zf(d, &["fill", "--count", "20000", "-o", &out]);
        assert_eq!(o.code, 2, "-o {out}: exit {} ({})", o.code, o.stderr);
        assert!(names_flag(&o.stderr, "--output"), "{}", o.stderr);
        assert!(o.stderr.contains("cannot write in the folder"), "{}", o.stderr);
        assert!(!folder.join("x.svg").exists());
        tried += 1;
    }
    assert!(tried > 0 || !cfg!(target_os = "linux"), "no unwritable folder to try");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let _ = std::fs::set_permissions(d.join("locked"), std::fs::Permissions::from_mode(0o755));
    }
}

/// Bug: a read-only output file was replaced (the rename needs only the folder's
/// permission). It is refused with exit 2 and left as it was.
#[test]
fn read_only_output_is_refused() {
    let dir = tmp();
    let d = dir.path();
    let p = d.join("out.svg");
    std::fs::write(&p, KEEP).unwrap_or_else(|e| panic!("write: {e}"));
    let mut perm = std::fs::metadata(&p).unwrap_or_else(|e| panic!("stat: {e}")).permissions();
    perm.set_readonly(true);
    std::fs::set_permissions(&p, perm).unwrap_or_else(|e| panic!("chmod: {e}"));
    let o = expect_usage(d, &["--count", "20"], "out.svg", &["--output"]);
    assert!(o.stderr.contains("read-only"), "{}", o.stderr);
    assert_eq!(read(&p), KEEP);
    assert_eq!(listing(d), vec![p]);
}

/// Bug: a fill whose first shape never found a place exited 3 ("halted at placement 0") and
/// replaced the output with an empty drawing. It is bad input: exit 2, the first shape's
/// size and the flags to change in the message, nothing written.
#[test]
fn first_shape_that_never_fits_is_bad_input() {
    let frame = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><path d="M 0 0 L 100 0 L 100 100 L 0 100 Z M 5 5 L 95 5 L 95 95 L 5 95 Z"/></svg>"#;
    let plus = "polygon:40,0,60,0,60,40,100,40,100,60,60,60,60,100,40,100,40,60,0,60,0,40,40,40";
    let cases: &[&[&str]] = &[
        // Rotated triangles: the core cannot prove it, the trial limit ends the search.
        &["--shape", "triangle", "--c", "3"],
        &["--region", plus],
        &["--region", plus, "--sampler", "reference", "--max-trials", "100000"],
        &["--region", "svg:frame.svg"],
        &["--region", "svg:frame.svg", "--sampler", "reference", "--max-trials", "100000"],
    ];
    for args in cases {
        for out in ["out.json", "out.svg"] {
            let dir = tmp();
            let d = dir.path();
            std::fs::write(d.join("frame.svg"), frame).unwrap_or_else(|e| panic!("write: {e}"));
            let mut a = vec!["fill"];
            a.extend_from_slice(args);
            a.extend_from_slice(&["-o", out]);
            let o = zf(d, &a);
            assert_eq!(o.code, 2, "zetafill {a:?}: exit {} ({})", o.code, o.stderr);
            assert!(o.stderr.contains("the first ") && o.stderr.contains(" mm wide"), "{}", o.stderr);
            for flag in ["--c", "--n-offset", "--region"] {
                assert!(names_flag(&o.stderr, flag), "zetafill {a:?}: does not name {flag}: {}", o.stderr);
            }
            assert!(!o.stderr.contains("halted"), "{}", o.stderr);
            assert_eq!(listing(d), vec![d.join("frame.svg")], "zetafill {a:?} wrote a file");
            // An existing output is left as it was.
            std::fs::write(d.join(out), KEEP).unwrap_or_else(|e| panic!("write: {e}"));
            assert_eq!(zf(d, &a).code, 2);
            assert_eq!(read(&d.join(out)), KEEP, "zetafill {a:?} changed the output");
        }
    }
}

/// Bug: a gap that leaves no room for two shapes of any size was blamed on --n-offset
/// ("raise --n-offset"); it names --gap and its largest workable value.
#[test]
fn gap_too_large_for_two_shapes_names_gap() {
    for shape in ["circle", "square"] {
        let o = bad(
            &[
                "--count",
                "50",
                "--gap",
                "80",
                "--n-offset",
                "200",
                "--shape",
                shape,
                "--rotate",
                "none",
            ],
            &["--gap"],
        );
        assert!(o.stderr.starts_with("error: --gap:"), "{}", o.stderr);
        assert!(!o.stderr.contains("raise --n-offset"), "{}", o.stderr);
    }
}

/// Bug: a G-code margin that leaves no bed was reported as "--machine: the drawing has no
/// extent" (with --fit) or as a negative usable area. It names --margin.
#[test]
fn margin_that_leaves_no_bed_names_margin() {
    for args in [
        &["--margin", "200", "--fit"][..],
        &["--margin", "200"][..],
        &["--margin", "150", "--center"][..],
    ] {
        let o = bad_to(args, "out.gcode", &["--margin"]);
        assert!(o.stderr.starts_with("error: --margin:"), "{args:?}: {}", o.stderr);
        assert!(
            !o.stderr.contains("no extent") && !o.stderr.contains("-100"),
            "{args:?}: {}",
            o.stderr
        );
    }
}

/// `--arcs` with `--no-arcs` is a contradiction, not "the last one wins".
#[test]
fn arcs_and_no_arcs_conflict() {
    bad_to(&["--count", "5", "--arcs", "--no-arcs"], "out.gcode", &["--arcs", "--no-arcs"]);
    bad_to(&["--count", "5", "--no-arcs", "--arcs"], "out.gcode", &["--arcs", "--no-arcs"]);
}

/// The help of `-o` lists every extension that works, G-code included.
#[test]
fn output_help_lists_gcode() {
    let dir = tmp();
    for cmd in ["fill", "line"] {
        let o = zf_ok(dir.path(), &[cmd, "--help"]);
        let help = String::from_utf8_lossy(&o.stdout).into_owned();
        let line = help
            .lines()
            .skip_while(|l| !l.trim_start().starts_with("-o, --output"))
            .nth(1)
            .unwrap_or_else(|| panic!("{cmd}: no --output in the help"));
        assert!(line.contains(".gcode") && line.contains(".nc"), "{cmd}: {line}");
    }
}

/// A subcommand's help lists only the drawing flags it reads: `territory` and `tile` refuse
/// pages and hatching (and `territory` layers), so their help leaves them out; `tile` lists
/// `--layers` for its colours; `fill` lists them all.
#[test]
fn help_leaves_out_flags_that_are_refused() {
    let dir = tmp();
    let help = |cmd: &str| String::from_utf8_lossy(&zf_ok(dir.path(), &[cmd, "--help"]).stdout).into_owned();
    // Whether the help has an entry (a line starting with the flag) for `flag`.
    let lists = |h: &str, flag: &str| {
        h.lines().any(|l| {
            let t = l.trim_start();
            t == flag || t.starts_with(&format!("{flag} "))
        })
    };
    let refused = ["--page", "--layers", "--hatch", "--hatch-only", "--cross-hatch", "--min-feature"];
    for cmd in ["territory", "tile"] {
        let h = help(cmd);
        for flag in refused.iter().filter(|f| !(cmd == "tile" && **f == "--layers")) {
            assert!(!lists(&h, flag), "{cmd} --help lists {flag}");
        }
        assert!(lists(&h, "--machine"), "{cmd} --help keeps the G-code flags");
    }
    assert!(lists(&help("tile"), "--layers"), "tile --help lists --layers (colours)");
    let h = help("fill");
    assert!(refused.iter().all(|f| lists(&h, f)), "fill --help lists them all");
}

/// An output path ending in a slash names a folder, even when it does not exist yet: refused
/// before the work, naming --output.
#[test]
fn output_ending_in_a_slash_is_refused() {
    let dir = tmp();
    let o = zf(dir.path(), &["fill", "--count", "5", "-o", "missing/"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(o.stderr.contains("--output") && o.stderr.contains("slash"), "{}", o.stderr);
}

/// Bug: after a proven halt (the cell sampler found no place left for the shape) the message
/// said "raise --max-trials", which cannot help. The twin, a halt at the trial limit, must
/// still say it, so the check below can tell the two apart.
#[test]
fn a_proven_halt_does_not_ask_for_more_trials() {
    let dir = tmp();
    let d = dir.path();
    let proven = zf(d, &["fill", "--gap", "1", "--count", "5000", "-o", "p.json"]);
    assert_eq!(proven.code, 3, "{}", proven.stderr);
    assert!(halt_index(&proven.stderr) >= 100, "{}", proven.stderr);
    assert!(proven.stderr.contains("more trials cannot help"), "{}", proven.stderr);
    assert!(!proven.stderr.contains("--max-trials"), "{}", proven.stderr);
    let limit = zf(
        d,
        &[
            "fill",
            "--count",
            "3000",
            "--sampler",
            "reference",
            "--max-trials",
            "1000",
            "-o",
            "l.json",
        ],
    );
    assert_eq!(limit.code, 3, "{}", limit.stderr);
    assert!(halt_index(&limit.stderr) >= 100, "{}", limit.stderr);
    assert!(limit.stderr.contains("raise --max-trials"), "{}", limit.stderr);
    assert!(!limit.stderr.contains("cannot help"), "{}", limit.stderr);
}

/// Bug: `--c 1e100` named the limit 1.0000 (a bisection from 1e100 never left 1).
#[test]
fn a_huge_exponent_names_the_true_limit() {
    let o = bad(&["--c", "1e100"], &["--c"]);
    let limit = o.stderr.split("when c > ").nth(1).and_then(|t| t.get(..6)).unwrap_or_default();
    let small = bad(&["--c", "1.7"], &["--c"]);
    assert!(
        small.stderr.contains(&format!("when c > {limit}")),
        "{} / {}",
        o.stderr,
        small.stderr
    );
    assert_ne!(limit, "1.0000", "{}", o.stderr);
}

/// Bug: `--region svg:/dev/zero` read until the memory ran out, and `--chord-tolerance
/// 1e-300` asked for gigabytes of G-code. Every input file is read up to a documented limit,
/// and the tolerance has a floor; each refusal is exit 2, names the flag, and writes nothing.
#[test]
fn unbounded_inputs_are_refused_at_their_limits() {
    let dir = tmp();
    let d = dir.path();
    let cases: &[(&[&str], &str, &str)] = &[
        (&["fill", "--region", "svg:/dev/zero", "-o", "out.svg"], "--region", "64 MiB"),
        (&["fill", "--machine", "/dev/zero", "-o", "out.gcode"], "--machine", "1 MiB"),
        (
            &["fill", "--no-arcs", "--chord-tolerance", "1e-300", "-o", "out.gcode"],
            "--chord-tolerance",
            "1e-300 mm is below 0.001",
        ),
        (
            &["fill", "--no-arcs", "--chord-tolerance", "0.0009", "-o", "out.gcode"],
            "--chord-tolerance",
            "0.001",
        ),
    ];
    for (args, flag, what) in cases {
        let out = d.join(args.last().copied().unwrap_or_default());
        std::fs::write(&out, KEEP).unwrap_or_else(|e| panic!("{e}"));
        let o = zf(d, args);
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        assert!(names_flag(&o.stderr, flag), "{args:?}: {}", o.stderr);
        assert!(o.stderr.contains(what), "{args:?}: {}", o.stderr);
        assert!(o.stderr.len() < 400, "{args:?}: a short message: {}", o.stderr);
        assert_eq!(read(&out), KEEP, "{args:?}: the old output is untouched");
    }
    // The twin: at the floor the tolerance is accepted.
    let o = zf(
        d,
        &["fill", "--count", "20", "--no-arcs", "--chord-tolerance", "0.001", "-o", "ok.gcode"],
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
}
