//! `zetafill fill` with every shape in every region, end to end, and the bad inputs of the
//! shapes and regions (exit 2, the flag named, nothing written).
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use serde_json::Value;

const SHAPES: [&str; 10] = [
    "circle",
    "square",
    "rect:2",
    "triangle",
    "polygon:7",
    "star:5:0.45",
    "ring:0.6",
    "blob:0.2",
    "noisy:0.35:5:2",
    "mix:circle,star:4:0.5,ring:0.5",
];
const REGIONS: [&str; 5] = [
    "rect:120:90",
    "circle:60",
    "annulus:60:20",
    "polygon:0,0,120,0,120,120,60,50,0,120",
    "SVG",
];

const OUTLINE: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="120mm" height="120mm" viewBox="0 0 120 120">
<path d="M 0 0 L 120 0 L 120 120 L 0 120 Z M 40 40 C 50 30 70 30 80 40 L 80 80 L 40 80 Z"/></svg>"#;

/// Every polygon in the JSON matches its declared kind: vertex count and area.
fn check_kinds(doc: &Value) {
    for sh in shapes(doc) {
        let kind = s(sh, "kind");
        let area = f(sh, "area");
        match kind {
            "circle" => assert!(rel(std::f64::consts::PI * f(sh, "radius").powi(2), area) < 1e-9),
            "ring" => {
                let (r, ri) = (f(sh, "radius"), f(sh, "inner_radius"));
                assert!(ri > 0.0 && ri < r, "ring radii {r} {ri}");
                assert!(rel(std::f64::consts::PI * (r * r - ri * ri), area) < 1e-9);
            }
            _ => {
                let vs: Vec<[f64; 2]> = sh["vertices"]
                    .as_array()
                    .unwrap_or_else(|| panic!("{kind} has no vertices"))
                    .iter()
                    .map(pt)
                    .collect();
                let want = match kind {
                    "square" | "rect" => 4,
                    "triangle" => 3,
                    "polygon" => 7,
                    "star" => {
                        if vs.len() == 8 {
                            8
                        } else {
                            10
                        }
                    }
                    "blob" | "noisy" => 32,
                    other => panic!("unknown kind {other}"),
                };
                assert_eq!(vs.len(), want, "{kind}");
                assert!(rel(shoelace(&vs), area) < 1e-9, "{kind}: polygon area {} vs {area}", shoelace(&vs));
            }
        }
    }
}

#[test]
fn every_shape_in_every_region_end_to_end() {
    let dir = tmp();
    std::fs::write(dir.path().join("outline.svg"), OUTLINE).unwrap_or_else(|e| panic!("{e}"));
    for region in REGIONS {
        let region_arg = if region == "SVG" { "svg:outline.svg" } else { region };
        for shape in SHAPES {
            let args = [
                "--shape",
                shape,
                "--region",
                region_arg,
                "--c",
                "1.2",
                "--n-offset",
                "5",
                "--count",
                "60",
                "--seed",
                "3",
                "--gap",
                "0.3",
            ];
            let doc = fill_json(dir.path(), &args);
            assert_eq!(shapes(&doc).len(), 60, "{shape} in {region}");
            check_kinds(&doc);
            // The JSON region describes the region given.
            let kind = s(&doc["region"], "kind");
            let want = match region.split(':').next() {
                Some("SVG") => "polygon",
                Some(k) => k,
                None => "",
            };
            assert_eq!(kind, want);
            if region == "SVG" {
                assert_eq!(
                    doc["region"]["holes"].as_array().map(Vec::len),
                    Some(1),
                    "the SVG's inner outline is a hole"
                );
                // 120 x 120 minus the hole: a 40 x 40 square plus the bulge of its curved top
                // (a cubic 10 mm high at its control points: about 210 mm²).
                let a = f(&doc, "area");
                assert!(a > 14400.0 - 1900.0 && a < 14400.0 - 1700.0, "area {a}");
            }
            // SVG and PNG of the same run are written too.
            fill_to(dir.path(), "out.svg", &args);
            let svg = read(&dir.path().join("out.svg"));
            let tree = usvg::Tree::from_data(&svg, &usvg::Options::default()).unwrap_or_else(|e| panic!("{shape} {region}: {e}"));
            assert!(!tree.root().children().is_empty());
        }
    }
}

#[test]
fn mixes_cycle_in_order_and_random_mixes_are_reproducible() {
    let dir = tmp();
    let doc = fill_json(dir.path(), &["--shape", "mix:circle,square,triangle", "--count", "30"]);
    let kinds: Vec<&str> = shapes(&doc).iter().map(|sh| s(sh, "kind")).collect();
    for (i, k) in kinds.iter().enumerate() {
        assert_eq!(*k, ["circle", "square", "triangle"][i % 3]);
    }
    let a = fill_to(
        dir.path(),
        "a.json",
        &["--shape", "mix:circle,square", "--mix-order", "random", "--count", "40"],
    );
    let b = fill_to(
        dir.path(),
        "b.json",
        &["--shape", "mix:circle,square", "--mix-order", "random", "--count", "40"],
    );
    assert_eq!(a, b);
    let doc = parse_json(&a);
    let circles = shapes(&doc).iter().filter(|sh| s(sh, "kind") == "circle").count();
    assert!((8..=32).contains(&circles), "{circles} circles of 40");
}

#[test]
fn squares_beyond_the_hard_limit_are_refused_before_running() {
    let dir = tmp();
    let o = zf(
        dir.path(),
        &["fill", "--shape", "square", "--rotate", "none", "--c", "1.53", "-o", "x.json"],
    );
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(o.stderr.contains("1.5224"), "{}", o.stderr);
    assert!(!dir.path().join("x.json").exists());
    // Just below the limit the first two squares can fit (the run may still halt later).
    let o = zf(
        dir.path(),
        &[
            "fill",
            "--shape",
            "square",
            "--rotate",
            "none",
            "--c",
            "1.52",
            "--count",
            "2",
            "--max-trials",
            "100000000",
            "-o",
            "y.json",
        ],
    );
    assert!(o.code == 0 || o.code == 3, "{}", o.stderr);
}

#[test]
fn bad_shapes_and_regions_exit_2_naming_the_flag() {
    let dir = tmp();
    std::fs::write(
        dir.path().join("open.svg"),
        r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 10 10 L 20 0"/></svg>"#,
    )
    .unwrap_or_default();
    std::fs::write(dir.path().join("broken.svg"), "<svg this is not xml").unwrap_or_default();
    std::fs::write(dir.path().join("out.json"), "keep me").unwrap_or_default();
    let cases: &[(&[&str], &str)] = &[
        (&["--region", "polygon:0,0,10,0"], "--region"),
        (&["--region", "polygon:0,0,10,0,20,0"], "--region"),
        (&["--region", "polygon:0,0,10,10,10,0,0,10"], "--region"),
        (&["--region", "polygon:0,0,10,0,nan,5"], "--region"),
        (&["--region", "annulus:10:20"], "--region"),
        (&["--region", "svg:open.svg"], "--region"),
        (&["--region", "svg:broken.svg"], "--region"),
        (&["--region", "svg:missing.svg"], "--region"),
        (&["--region", "circle:50", "--periodic"], "--periodic"),
        (&["--region", "polygon:0,0,10,0,10,10", "--periodic"], "--periodic"),
        (&["--shape", "ring:0"], "--shape"),
        (&["--shape", "ring:1"], "--shape"),
        (&["--shape", "star:5:1.5"], "--shape"),
        (&["--shape", "star:1:0.5"], "--shape"),
        (&["--shape", "polygon:2"], "--shape"),
        (&["--shape", "polygon:100"], "--shape"),
        (&["--shape", "blob:0.4"], "--shape"),
        (&["--shape", "blob:-0.1"], "--shape"),
        (&["--shape", "mix:circle,hexagon"], "--shape"),
        (&["--shape", "mix:"], "--shape"),
        (&["--gap", "60", "--region", "rect:100:100"], "--gap"),
        (&["--region", "circle:10", "--shape", "square", "--c", "2.5"], "--c"),
    ];
    for (args, flag) in cases {
        let mut a = vec!["fill"];
        a.extend_from_slice(args);
        a.extend_from_slice(&["-o", "out.json"]);
        let o = zf(dir.path(), &a);
        assert_eq!(o.code, 2, "{args:?}: exit {} ({})", o.code, o.stderr);
        assert!(names_flag(&o.stderr, flag), "{args:?}: stderr does not name {flag}: {}", o.stderr);
        assert_eq!(read(&dir.path().join("out.json")), b"keep me", "{args:?} touched the output");
    }
    // An output path equal to the SVG region's file.
    std::fs::write(dir.path().join("shape.svg"), OUTLINE).unwrap_or_default();
    let o = zf(dir.path(), &["fill", "--region", "svg:shape.svg", "-o", "shape.svg"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--output"), "{}", o.stderr);
    assert_eq!(read(&dir.path().join("shape.svg")), OUTLINE.as_bytes());
}

/// Bug: an outline that repeats its first vertex at the end (as exports of closed paths do)
/// was refused as "crosses itself". It is the same outline as without the repeat, so it
/// gives the same file; the twin, a repeat in the middle, is still refused.
#[test]
fn a_closed_polygon_repeating_its_first_vertex_is_the_same_outline() {
    let dir = tmp();
    let d = dir.path();
    let open = fill_to(d, "open.json", &["--region", "polygon:0,0,100,0,100,100,0,100", "--count", "40"]);
    let closed = fill_to(
        d,
        "closed.json",
        &["--region", "polygon:0,0,100,0,100,100,0,100,0,0", "--count", "40"],
    );
    assert_eq!(open, closed);
    let holes = fill_to(
        d,
        "holes.json",
        &[
            "--region",
            "polygon:0,0,100,0,100,100,0,100,0,0/70,70,90,70,90,90,70,90,70,70",
            "--n-offset",
            "4",
            "--count",
            "40",
        ],
    );
    assert!(!holes.is_empty());
    let o = zf(d, &["fill", "--region", "polygon:0,0,100,0,0,0,100,100,0,100", "-o", "bad.json"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(names_flag(&o.stderr, "--region"), "{}", o.stderr);
}
