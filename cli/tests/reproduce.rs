//! A file says how to make it again: the command in an SVG's `<desc>` and in a G-code header,
//! run as written, writes the same bytes; the JSON's parameters name every choice that
//! changes the fill.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{tmp, zf_ok};
use std::path::Path;

/// The text of the first `<desc>` element.
fn svg_desc(svg: &str) -> Option<String> {
    let start = svg.find("<desc>")? + "<desc>".len();
    let end = start + svg.get(start..)?.find("</desc>")?;
    svg.get(start..end)
        .map(|t| t.replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"))
}

/// The `zetafill SUBCOMMAND ...` comment line of a G-code header.
fn gcode_command(gcode: &str) -> Option<String> {
    gcode
        .lines()
        .filter_map(|l| l.strip_prefix("; "))
        .find(|l| {
            ["fill", "line", "territory", "tile"]
                .iter()
                .any(|c| l.starts_with(&format!("zetafill {c} ")))
        })
        .map(String::from)
}

/// Runs `command` (starting `zetafill `) with `-o out` in `dir`; the bytes written.
fn rerun(dir: &Path, command: &str, out: &str) -> Vec<u8> {
    let args: Vec<&str> = command.split_whitespace().skip(1).chain(["-o", out]).collect();
    zf_ok(dir, &args);
    std::fs::read(dir.join(out)).unwrap_or_default()
}

/// Runs `args` writing `out`, then the command the file carries; true when both wrote the
/// same bytes.
fn reproduces(dir: &Path, args: &[&str], out: &str, command_of: fn(&str) -> Option<String>) -> bool {
    let full: Vec<&str> = args.iter().copied().chain(["-o", out]).collect();
    zf_ok(dir, &full);
    let first = std::fs::read(dir.join(out)).unwrap_or_default();
    let text = String::from_utf8_lossy(&first).into_owned();
    let Some(command) = command_of(&text) else {
        panic!("{out}: no command in the file");
    };
    let again = format!("again-{out}");
    first == rerun(dir, &command, &again)
}

const RUNS: [&[&str]; 10] = [
    &["fill", "--count", "300", "--density", "noise:value:25", "--periodic", "--seed", "4"],
    &["fill", "--count", "400", "--cells", "512", "--seed", "5"],
    &["fill", "--count", "300", "--sampler", "reference", "--seed", "3"],
    &["fill", "--count", "200", "--scalar", "fixed", "--shape", "square"],
    &["fill", "--count", "200", "--shape", "mix:circle,triangle", "--mix-order", "random"],
    &[
        "fill",
        "--count",
        "300",
        "--page",
        "a4",
        "--fit",
        "--layers",
        "size-bands:3",
        "--style",
        "filled",
        "--pen-width",
        "0.5",
    ],
    &[
        "fill",
        "--count",
        "200",
        "--hatch",
        "0.8:30",
        "--cross-hatch",
        "--min-feature",
        "0.5",
        "--boundary",
    ],
    &[
        "fill",
        "--count",
        "200",
        "--style",
        "filled",
        "--palette",
        "264653,e9c46a,e76f51",
        "--background",
        "fefae0",
    ],
    &[
        "fill",
        "--count",
        "200",
        "--periodic",
        "--voronoi",
        "--style",
        "filled",
        "--boundary",
        "--palette",
        "264653,e9c46a",
        "--color-by",
        "cycle",
        "--background",
        "fefae0",
    ],
    &[
        "fill",
        "--count",
        "200",
        "--periodic",
        "--palette",
        "#000,#f00",
        "--color-by",
        "random",
    ],
];

#[test]
fn the_svg_desc_command_writes_the_same_file() {
    let dir = tmp();
    for args in RUNS {
        assert!(
            reproduces(dir.path(), args, "a.svg", svg_desc),
            "zetafill {args:?}: <desc> does not reproduce the file"
        );
    }
    // The check can fail: a command with the sampler left out makes another fill.
    let dir = tmp();
    zf_ok(dir.path(), &["fill", "--count", "300", "--sampler", "reference", "-o", "r.svg"]);
    let svg = std::fs::read_to_string(dir.path().join("r.svg")).unwrap_or_default();
    let desc = svg_desc(&svg).unwrap_or_default();
    assert!(desc.contains("--sampler reference"), "{desc}");
    let without = desc.replace(" --sampler reference", "");
    assert_ne!(svg.into_bytes(), rerun(dir.path(), &without, "r2.svg"));
}

#[test]
fn the_gcode_header_command_writes_the_same_file() {
    let dir = tmp();
    for args in [
        &[
            "fill",
            "--count",
            "200",
            "--sampler",
            "reference",
            "--machine",
            "grbl-laser",
            "--passes",
            "2",
            "--power",
            "500",
        ][..],
        &[
            "fill",
            "--count",
            "200",
            "--shape",
            "ring:0.5",
            "--n-offset",
            "2",
            "--hatch",
            "0.5:45",
            "--hatch-only",
            "--order",
            "greedy",
        ],
        &[
            "fill",
            "--count",
            "200",
            "--region",
            "rect:300:200",
            "--fit",
            "--margin",
            "5",
            "--no-arcs",
            "--chord-tolerance",
            "0.05",
        ],
        &[
            "fill",
            "--count",
            "200",
            "--palette",
            "1d3557,e63946",
            "--color-by",
            "cycle",
            "--layers",
            "colours",
        ],
    ] {
        assert!(
            reproduces(dir.path(), args, "a.gcode", gcode_command),
            "zetafill {args:?}: the header does not reproduce the file"
        );
    }
}

/// The other subcommands' files carry their commands too.
#[test]
fn line_territory_and_tile_files_carry_their_commands() {
    let dir = tmp();
    let words = |c: &'static str| c.split_whitespace().collect::<Vec<_>>();
    let svg: (&str, fn(&str) -> Option<String>) = ("a.svg", svg_desc);
    let gcode: (&str, fn(&str) -> Option<String>) = ("a.gcode", gcode_command);
    for (c, (out, command_of)) in [
        ("line --count 300 --render bars --bar-height 6 --boundary", svg),
        ("line --count 300 --render zoom --zoom-rows 3 --zoom-fraction 0.1", svg),
        ("line --count 200 --render circles --style filled --pen-width 0.2", svg),
        (
            "line --count 200 --periodic --render dashes --palette 264653,e76f51 --color-by cycle --background fefae0",
            svg,
        ),
        (
            "line --count 200 --render bars --palette 264653,e76f51 --color-by random --layers colours",
            svg,
        ),
        (
            "line --count 200 --render bars --palette 264653,e76f51 --color-by random --layers colours",
            gcode,
        ),
        ("territory --sites 3 --points 1500 --render filled --boundary --pen-width 0.4", svg),
        (
            "territory --sites 4 --points 1500 --render filled --palette 264653,e76f51,e9c46a --background fefae0",
            svg,
        ),
        ("tile --tries 3000 --style filled --layout mosaic --rows 2", svg),
        ("tile --tries 3000 --render voronoi --pen-width 0.2", svg),
        (
            "tile --tries 3000 --style filled --layout planet --rows 2 --palette 264653,e76f51 --color-by random --background fefae0",
            svg,
        ),
        ("line --count 200 --render bars --hatch 0.5 --machine grbl-laser", gcode),
        ("territory --sites 3 --points 1500 --render cells --order greedy", gcode),
        ("tile --tries 3000 --layout mosaic --fit --passes 2 --machine grbl-laser", gcode),
        (
            "tile --tries 3000 --layout planet --rows 2 --fit --palette 1d3557,e63946 --layers colours",
            gcode,
        ),
        (
            "tile --tries 3000 --layout mosaic --palette 1d3557,e63946 --color-by random --layers colours",
            svg,
        ),
    ] {
        assert!(
            reproduces(dir.path(), &words(c), out, command_of),
            "zetafill {c}: the command in {out} does not reproduce it"
        );
    }
}

#[test]
fn json_names_the_mix_order() {
    let dir = tmp();
    let d = dir.path();
    for order in ["cycle", "random"] {
        zf_ok(
            d,
            &[
                "fill",
                "--count",
                "50",
                "--shape",
                "mix:circle,square",
                "--mix-order",
                order,
                "-o",
                "m.json",
            ],
        );
        let v = common::parse_json(&common::read(&d.join("m.json")));
        assert_eq!(v["params"]["mix_order"], order);
    }
    zf_ok(d, &["fill", "--count", "50", "-o", "c.json"]);
    assert!(
        common::parse_json(&common::read(&d.join("c.json")))["params"]
            .get("mix_order")
            .is_none(),
        "only mixes have an order"
    );
}

/// `--cells` is recorded (its fill differs from the default's), refused with the paper's
/// sampler and out of range, and nothing is written then.
#[test]
fn json_names_the_cells_lent() {
    let dir = tmp();
    let d = dir.path();
    zf_ok(d, &["fill", "--count", "400", "--seed", "5", "--cells", "512", "-o", "few.json"]);
    zf_ok(d, &["fill", "--count", "400", "--seed", "5", "-o", "all.json"]);
    let (few, all) = (
        common::parse_json(&common::read(&d.join("few.json"))),
        common::parse_json(&common::read(&d.join("all.json"))),
    );
    assert_eq!(few["params"]["cells"], 512);
    assert!(all["params"].get("cells").is_none());
    assert_ne!(few["shapes"], all["shapes"], "512 cells run out before 400 circles");
    for (args, says) in [
        (&["--cells", "512", "--sampler", "reference"][..], "--sampler fast"),
        (&["--cells", "63"][..], "at least 64"),
        (&["--cells", "999999999999"][..], "drop --cells"),
    ] {
        let mut all = vec!["fill", "--count", "50"];
        all.extend_from_slice(args);
        all.extend(["-o", "bad.json"]);
        let o = common::zf(d, &all);
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        assert!(o.stderr.contains("--cells") && o.stderr.contains(says), "{args:?}: {}", o.stderr);
        assert!(!d.join("bad.json").exists());
    }
}

/// An outline whose hole comes first in the file, with a second, separate outline beside it.
const HOLE_FIRST: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="150mm" height="100mm" viewBox="0 0 150 100">
<path d="M40,30 L80,30 Q95,50 80,70 L40,70 Z"/>
<path d="M0,0 H120 V100 H0 Z"/>
<path d="M125,10 H148 V90 H125 Z"/>
</svg>"#;

/// An `svg:FILE` region is written out as its rings (`polygon:...[/...]`), so the command a
/// file carries makes it again without the SVG it was read from.
#[test]
fn an_svg_region_travels_as_its_rings() {
    let dir = tmp();
    let d = dir.path();
    std::fs::write(d.join("outline.svg"), HOLE_FIRST).unwrap_or_else(|e| panic!("{e}"));
    let fill = ["fill", "--region", "svg:outline.svg", "--count", "300", "--n-offset", "5"];
    assert!(reproduces(d, &fill, "a.svg", svg_desc), "fill SVG");
    assert!(reproduces(d, &fill, "a.gcode", gcode_command), "fill G-code");
    let territory = ["territory", "--region", "svg:outline.svg", "--sites", "3", "--points", "800"];
    assert!(reproduces(d, &territory, "t.svg", svg_desc), "territory SVG");

    let svg = std::fs::read_to_string(d.join("a.svg")).unwrap_or_default();
    let desc = svg_desc(&svg).unwrap_or_default();
    assert!(!desc.contains("svg:"), "the command still names a file: {desc}");
    // The rings as the JSON lists them: the first outline, the other one, then the hole.
    let rings: Vec<&str> = desc
        .split_whitespace()
        .find_map(|w| w.strip_prefix("polygon:"))
        .unwrap_or_default()
        .split('/')
        .collect();
    assert_eq!(rings.len(), 3, "{desc}");
    assert!(rings[0].starts_with("0,100,") && rings[1].starts_with("125,90,") && rings[2].starts_with("40,70,"));

    // The check can fail: without its hole the region makes another fill.
    let without_hole = desc.replace(&format!("/{}", rings[2]), "");
    assert_ne!(svg.into_bytes(), rerun(d, &without_hole, "no-hole.svg"));
}
