//! No input is ever overwritten: an output that is the same file as any input of its command
//! (the same path, a symbolic link to it, a hard link, another spelling of the path) is
//! refused before any work with exit 2, naming `--output` and the input's flag, and nothing
//! is written.
//!
//! Bug pinned here: `fill --density image:g.png -o g.png` exited 0 and replaced the picture
//! with the fill's PNG, so the file's own reproducing command could never run again; the same
//! through `-o link.png` (a link to the picture), and `--region mask:A.png --density
//! image:OUT.png -o OUT.png` replaced the picture too (exit 3). The mask, SVG, font, sites and
//! machine inputs were each checked by their own command; now one list per command is
//! checked in one place.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
#![cfg(unix)]

mod common;

use common::*;
use std::path::Path;

/// The inputs of one case: file name, how to make it, and the command that reads it (with
/// `OUT` for the output path) and the flag that names the input.
struct Case {
    input: &'static str,
    flag: &'static str,
    args: &'static [&'static str],
}

const CASES: &[Case] = &[
    Case {
        input: "g.png",
        flag: "--density",
        args: &["fill", "-q", "--count", "100", "--density", "image:g.png", "-o", "OUT"],
    },
    Case {
        input: "g.png",
        flag: "--density",
        args: &[
            "fill",
            "-q",
            "--count",
            "60",
            "--region",
            "mask:m.png",
            "--density",
            "image:g.png",
            "-o",
            "OUT",
        ],
    },
    Case {
        input: "m.png",
        flag: "--region",
        args: &["fill", "-q", "--count", "30", "--region", "mask:m.png", "-o", "OUT"],
    },
    Case {
        input: "o.svg",
        flag: "--region",
        args: &["fill", "-q", "--count", "30", "--region", "svg:o.svg", "-o", "OUT"],
    },
    Case {
        input: "f.ttf",
        flag: "--font",
        args: &[
            "fill",
            "-q",
            "--count",
            "30",
            "--region",
            "text:ab",
            "--n-offset",
            "20",
            "--font",
            "f.ttf",
            "--format",
            "svg",
            "-o",
            "OUT",
        ],
    },
    Case {
        input: "pen.toml",
        flag: "--machine",
        args: &[
            "fill",
            "-q",
            "--count",
            "20",
            "--machine",
            "pen.toml",
            "--format",
            "gcode",
            "-o",
            "OUT",
        ],
    },
    Case {
        input: "pen.toml",
        flag: "--machine",
        args: &[
            "line",
            "-q",
            "--count",
            "20",
            "--machine",
            "pen.toml",
            "--format",
            "gcode",
            "-o",
            "OUT",
        ],
    },
    Case {
        input: "pen.toml",
        flag: "--machine",
        args: &["tile", "-q", "--machine", "pen.toml", "--format", "gcode", "-o", "OUT"],
    },
    Case {
        input: "sites.json",
        flag: "--sites-from",
        args: &["territory", "-q", "--sites-from", "sites.json", "-o", "OUT"],
    },
    Case {
        input: "o.svg",
        flag: "--region",
        args: &["territory", "-q", "--points", "300", "--region", "svg:o.svg", "-o", "OUT"],
    },
];

/// The input files every case may read, made once in `d`.
fn inputs(d: &Path) {
    png_picture(&d.join("g.png"), 32, 32, |x, _| x < 20);
    png_picture(&d.join("m.png"), 40, 40, |x, y| {
        (x as i32 - 20).pow(2) + (y as i32 - 20).pow(2) < 300
    });
    std::fs::write(
        d.join("o.svg"),
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><path d="M 0 0 L 100 0 L 100 100 L 0 100 Z"/></svg>"#,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let font = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/fonts/DejaVuSans-Bold.ttf");
    std::fs::copy(font, d.join("f.ttf")).unwrap_or_else(|e| panic!("{e}"));
    let pen = zf_ok(d, &["machines", "show", "grbl-servo-pen"]).stdout;
    std::fs::write(d.join("pen.toml"), pen).unwrap_or_else(|e| panic!("{e}"));
    zf_ok(d, &["fill", "-q", "--count", "20", "-o", "sites.json"]);
}

/// Every entry of the folder `d` with its bytes.
fn contents(d: &Path) -> Vec<(std::path::PathBuf, Vec<u8>)> {
    listing(d).into_iter().map(|p| (p.clone(), read(&p))).collect()
}

fn with_output<'a>(args: &[&'a str], out: &'a str) -> Vec<&'a str> {
    args.iter().map(|&a| if a == "OUT" { out } else { a }).collect()
}

/// Every case, with the output named directly, by another spelling, through a symbolic link
/// and through a hard link: exit 2 naming both flags, every file as it was, nothing new.
#[test]
fn an_output_that_is_an_input_is_refused_and_nothing_changes() {
    let dir = tmp();
    let d = dir.path();
    inputs(d);
    for case in CASES {
        // The control: the same command with a fresh output runs (exit 0, or 3 for a halt).
        let control = format!("control-{}", case.input);
        let o = zf(d, &with_output(case.args, &control));
        assert!(o.code == 0 || o.code == 3, "{:?}: exit {} ({})", case.args, o.code, o.stderr);
        std::fs::remove_file(d.join(&control)).unwrap_or_else(|e| panic!("{:?}: {e}", case.args));

        let link = "link.out";
        let hard = "hard.out";
        std::os::unix::fs::symlink(case.input, d.join(link)).unwrap_or_else(|e| panic!("{e}"));
        std::fs::hard_link(d.join(case.input), d.join(hard)).unwrap_or_else(|e| panic!("{e}"));
        let spelled = format!("./{}", case.input);
        for out in [case.input, spelled.as_str(), link, hard] {
            let before = contents(d);
            let o = zf(d, &with_output(case.args, out));
            assert_eq!(o.code, 2, "{:?} -o {out}: exit {} ({})", case.args, o.code, o.stderr);
            assert!(
                o.stderr.starts_with("error: --output: ") && o.stderr.contains(case.flag),
                "{:?} -o {out}: the message names --output and {}: {}",
                case.args,
                case.flag,
                o.stderr
            );
            assert!(before == contents(d), "{:?} -o {out}: a file changed or appeared", case.args);
        }
        std::fs::remove_file(d.join(link)).unwrap_or_else(|e| panic!("{e}"));
        std::fs::remove_file(d.join(hard)).unwrap_or_else(|e| panic!("{e}"));
    }
}
