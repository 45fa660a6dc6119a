//! `zetafill fill --symmetry`: every wallpaper group drawn without overlaps (its SVG read
//! back and checked with the `geo` polygon library), the power law over the fundamental
//! region, prefix stability, byte-identical reruns and reproducing commands, `--periodic` as
//! p1, and the refusals of bad input.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use geo::{Distance, Euclidean};
use serde_json::Value;

/// The drawn shapes of an outline SVG, in the page's frame (y down): discs and polygons.
/// Pieces of shapes cut at the window's edge (paths) are left out.
#[derive(Debug, Clone)]
enum Drawn {
    Disc([f64; 2], f64),
    Poly(geo::Polygon<f64>),
}

fn drawn(svg: &[u8]) -> (Vec<Drawn>, usize) {
    let text = std::str::from_utf8(svg).expect("UTF-8");
    let doc = usvg::roxmltree::Document::parse(text).expect("an SVG");
    let num = |n: &usvg::roxmltree::Node, a: &str| -> f64 { n.attribute(a).and_then(|v| v.parse().ok()).expect("a number") };
    let (mut out, mut cut) = (Vec::new(), 0);
    for n in doc.descendants().filter(|n| n.is_element()) {
        match n.tag_name().name() {
            "circle" => out.push(Drawn::Disc([num(&n, "cx"), num(&n, "cy")], num(&n, "r"))),
            "polygon" => {
                let pts: Vec<f64> = n
                    .attribute("points")
                    .expect("points")
                    .split([' ', ','])
                    .filter(|s| !s.is_empty())
                    .map(|s| s.parse().expect("a number"))
                    .collect();
                let ring: Vec<(f64, f64)> = pts.chunks(2).map(|c| (c[0], c[1])).collect();
                out.push(Drawn::Poly(geo::Polygon::new(ring.into(), vec![])));
            }
            "path" => cut += 1,
            _ => {}
        }
    }
    (out, cut)
}

fn bbox(d: &Drawn) -> [f64; 4] {
    match d {
        Drawn::Disc(c, r) => [c[0] - r, c[1] - r, c[0] + r, c[1] + r],
        Drawn::Poly(p) => {
            let mut b = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
            for c in p.exterior().coords() {
                b = [b[0].min(c.x), b[1].min(c.y), b[2].max(c.x), b[3].max(c.y)];
            }
            b
        }
    }
}

/// The distance between two drawn shapes' material, by `geo` (0 where they meet).
fn distance(a: &Drawn, b: &Drawn) -> f64 {
    match (a, b) {
        (Drawn::Disc(p, r), Drawn::Disc(q, s)) => ((p[0] - q[0]).hypot(p[1] - q[1]) - r - s).max(0.0),
        (Drawn::Disc(c, r), Drawn::Poly(p)) | (Drawn::Poly(p), Drawn::Disc(c, r)) => {
            (Euclidean.distance(&geo::Point::new(c[0], c[1]), p) - r).max(0.0)
        }
        (Drawn::Poly(p), Drawn::Poly(q)) => Euclidean.distance(p, q),
    }
}

/// The pairs of drawn shapes closer than `gap` (less `slack`).
fn crowded(shapes: &[Drawn], gap: f64, slack: f64) -> Vec<(usize, usize, f64)> {
    let boxes: Vec<[f64; 4]> = shapes.iter().map(bbox).collect();
    let mut order: Vec<usize> = (0..shapes.len()).collect();
    order.sort_by(|&i, &j| boxes[i][0].total_cmp(&boxes[j][0]));
    let mut bad = Vec::new();
    for (n, &i) in order.iter().enumerate() {
        for &j in &order[n + 1..] {
            if boxes[j][0] > boxes[i][2] + gap {
                break;
            }
            if boxes[j][1] > boxes[i][3] + gap || boxes[i][1] > boxes[j][3] + gap {
                continue;
            }
            let d = distance(&shapes[i], &shapes[j]);
            if d < gap - slack {
                bad.push((i, j, d));
            }
        }
    }
    bad
}

/// A lattice for each group: oblique 50:40:70, rectangular and centred 50:36, square and
/// hexagonal 40.
fn lattice(group: &str) -> &'static str {
    match group {
        "p1" | "p2" => "50:40:70",
        "pm" | "pg" | "cm" | "pmm" | "pmg" | "pgg" | "cmm" => "50:36",
        _ => "40",
    }
}

const GROUPS: [&str; 17] = [
    "p1", "p2", "pm", "pg", "cm", "pmm", "pmg", "pgg", "cmm", "p4", "p4m", "p4g", "p3", "p3m1", "p31m", "p6", "p6m",
];

const MIX: &str = "mix:circle,square,triangle,star:5:0.45,blob:0.25";

#[test]
fn no_two_drawn_images_meet_in_any_group() {
    let dir = tmp();
    let mut all = 0;
    for g in GROUPS {
        let args = [
            "--symmetry",
            g,
            "--lattice",
            lattice(g),
            "--shape",
            MIX,
            "--c",
            "1.25",
            "--n-offset",
            "3",
            "--count",
            "40",
            "--gap",
            "0.05",
            "--seed",
            "4",
            "-q",
        ];
        let svg = fill_to(dir.path(), "s.svg", &args);
        let (seen, cut) = drawn(&svg);
        // (Where mirrors bound the cell, as in pmm, no shape crosses the window's edge.)
        assert!(seen.len() + cut > 40 * 9 / 2, "{g}: {} shapes, {cut} cut", seen.len());
        // Coordinates are written to 1e-4 mm: the gap holds to within that.
        let bad = crowded(&seen, 0.05, 3e-4);
        assert!(
            bad.is_empty(),
            "{g}: {} pairs closer than the gap, first {:?}",
            bad.len(),
            bad.first()
        );
        // Every image of the representative that lies whole in the window is drawn once.
        let doc = fill_json(dir.path(), &args);
        let r = &doc["region"];
        let order = u(r, "order") as f64;
        let v = r["vectors"].as_array().expect("vectors");
        let cells = f(r, "width") * f(r, "height") / (v[0].as_f64().expect("ax") * v[2].as_f64().expect("by"));
        assert_eq!(shapes(&doc).len(), 40, "{g}");
        assert!((seen.len() as f64) <= 40.0 * order * (cells + 8.0), "{g}: {} drawn", seen.len());
        all += seen.len();
    }
    assert!(all > 20_000, "{all} shapes checked");
    // The checker finds a meeting: one shape moved onto its neighbour.
    let svg = fill_to(
        dir.path(),
        "t.svg",
        &[
            "--symmetry",
            "p4m",
            "--lattice",
            "40",
            "--n-offset",
            "3",
            "--count",
            "30",
            "--gap",
            "0.05",
            "-q",
        ],
    );
    let (mut shapes, _) = drawn(&svg);
    assert!(crowded(&shapes, 0.05, 3e-4).is_empty());
    let Drawn::Disc(c, _) = shapes[1].clone() else { panic!("circles") };
    if let Drawn::Disc(p, _) = &mut shapes[0] {
        *p = [c[0] + 0.01, c[1]];
    }
    assert!(!crowded(&shapes, 0.05, 3e-4).is_empty(), "the moved circle went unseen");
}

/// A_f / (zeta(c, N) (i + N)^c), A_f the cell's area over the group's order, from the
/// document's own numbers and the lattice worked out here.
#[test]
fn areas_follow_the_power_law_of_the_fundamental_region() {
    let dir = tmp();
    let cases = [
        ("p6m", "40", 40.0 * 40.0 * 3f64.sqrt() / 2.0, 12.0),
        ("cmm", "50:36", 50.0 * 36.0 / 2.0, 4.0),
        ("p2", "50:40:70", 50.0 * 40.0 * 70f64.to_radians().sin(), 2.0),
        ("p4g", "40", 1600.0, 8.0),
    ];
    for (g, l, cell, order) in cases {
        let doc = fill_json(
            dir.path(),
            &[
                "--symmetry",
                g,
                "--lattice",
                l,
                "--shape",
                "mix:circle,triangle",
                "--n-offset",
                "3",
                "--count",
                "60",
                "-q",
            ],
        );
        let fundamental = cell / order;
        assert!(
            (f(&doc, "area") - fundamental).abs() < 1e-9 * fundamental,
            "{g}: area {}",
            f(&doc, "area")
        );
        let (zeta, c, n) = (f(&doc, "zeta"), f(&doc["params"], "c"), f(&doc["params"], "n_offset"));
        let mut sum = 0.0;
        for (i, sh) in shapes(&doc).iter().enumerate() {
            let want = fundamental / (zeta * (i as f64 + n).powf(c));
            assert!((f(sh, "area") - want).abs() < 1e-12 * want, "{g} shape {i}");
            // The shape as drawn has that area.
            let drawn = match sh.get("radius") {
                Some(r) => std::f64::consts::PI * r.as_f64().expect("r").powi(2),
                None => {
                    let v: Vec<[f64; 2]> = sh["vertices"].as_array().expect("vertices").iter().map(pt).collect();
                    (0..v.len())
                        .map(|k| v[k][0] * v[(k + 1) % v.len()][1] - v[(k + 1) % v.len()][0] * v[k][1])
                        .sum::<f64>()
                        / 2.0
                }
            };
            assert!((drawn - want).abs() < 1e-9 * want, "{g} shape {i}: drawn {drawn}, law {want}");
            sum += want;
        }
        let fraction = f(&doc["stats"], "fill_fraction");
        assert!((fraction - sum / fundamental).abs() < 1e-12, "{g}: {fraction}");
        assert_eq!(u(&doc["region"], "order") as f64, order, "{g}");
    }
}

#[test]
fn prefixes_reruns_and_the_reproducing_command() {
    let dir = tmp();
    let base = [
        "--symmetry",
        "p31m",
        "--lattice",
        "40",
        "--shape",
        "mix:circle,blob:0.3",
        "--n-offset",
        "3",
        "-q",
    ];
    let with = |count: &str, sampler: &str| {
        let mut a = base.to_vec();
        a.extend(["--count", count, "--sampler", sampler]);
        fill_json(dir.path(), &a)
    };
    for sampler in ["fast", "reference", "batched"] {
        let (short, long) = (with("25", sampler), with("60", sampler));
        assert_eq!(
            shapes(&short)[..],
            shapes(&long)[..25],
            "{sampler}: the first 25 depend on the count"
        );
    }
    // The same bytes again, and from the command the SVG carries.
    let mut a = base.to_vec();
    a.extend(["--count", "80", "--style", "filled", "--palette", "264653,2a9d8f,e9c46a"]);
    let first = fill_to(dir.path(), "a.svg", &a);
    assert_eq!(fill_to(dir.path(), "b.svg", &a), first);
    let text = String::from_utf8(first.clone()).expect("UTF-8");
    let desc = text
        .split("<desc>")
        .nth(1)
        .and_then(|t| t.split("</desc>").next())
        .expect("a <desc>");
    let words: Vec<&str> = desc.split_whitespace().skip(2).collect();
    assert!(words.contains(&"--symmetry") && words.contains(&"--repeat"), "{desc}");
    let mut again = vec!["fill"];
    again.extend(words);
    again.extend(["-q", "-o", "c.svg"]);
    zf_ok(dir.path(), &again);
    assert_eq!(read(&dir.path().join("c.svg")), first, "the <desc> command gives the same file");
    // Every format draws the pattern.
    for name in ["p.png", "p.gcode", "p.csv"] {
        let mut a = base.to_vec();
        a.extend(["--count", "40"]);
        assert!(!fill_to(dir.path(), name, &a).is_empty(), "{name}");
    }
    let mut a = base.to_vec();
    a.extend(["--count", "40", "--relief", "dome", "--pixels", "200"]);
    assert!(!fill_to(dir.path(), "h.png", &a).is_empty());
}

#[test]
fn periodic_is_p1_on_a_rectangular_cell() {
    let dir = tmp();
    for sampler in ["fast", "reference"] {
        let common = [
            "--shape",
            "mix:circle,square",
            "--n-offset",
            "2",
            "--count",
            "150",
            "--seed",
            "3",
            "--sampler",
            sampler,
            "-q",
        ];
        let mut a = vec!["--periodic", "--region", "rect:80:50"];
        a.extend(common);
        let torus = fill_json(dir.path(), &a);
        let mut b = vec!["--symmetry", "p1", "--lattice", "80:50:90"];
        b.extend(common);
        let p1 = fill_json(dir.path(), &b);
        let strip = |doc: &Value| -> Vec<Value> { shapes(doc).to_vec() };
        assert_eq!(strip(&torus), strip(&p1), "{sampler}");
        assert_eq!(torus["stats"], p1["stats"], "{sampler}");
    }
}

#[test]
fn bad_symmetry_input_is_refused_naming_the_flag() {
    let dir = tmp();
    let cases: [(&[&str], &str, &str); 12] = [
        (&["--symmetry", "p5", "--lattice", "40"], "--symmetry", "p31m"),
        (&["--symmetry", "p4m", "--lattice", "40:30"], "--lattice", "square lattice"),
        (&["--symmetry", "pmg", "--lattice", "40"], "--lattice", "rectangular lattice"),
        (&["--symmetry", "p2", "--lattice", "40:30"], "--lattice", "oblique lattice"),
        (&["--symmetry", "p6m", "--lattice", "0"], "--lattice", "greater than 0"),
        (&["--symmetry", "p6m", "--lattice", "-40"], "--lattice", ""),
        (&["--symmetry", "p6m", "--lattice", "nan"], "--lattice", "number"),
        (&["--symmetry", "p6m", "--lattice", "1e9"], "--lattice", "kilometre"),
        (&["--symmetry", "p1", "--lattice", "40:30:0"], "--lattice", "between 0 and 180"),
        (&["--symmetry", "p1", "--lattice", "40:30:180"], "--lattice", "between 0 and 180"),
        (
            &["--symmetry", "p4m", "--lattice", "40", "--n-offset", "0.3"],
            "--c",
            "lower --c to",
        ),
        (&["--symmetry", "p4m", "--lattice", "40", "--gap", "20"], "--gap", "lower it below"),
    ];
    for (args, flag, says) in cases {
        let mut a = vec!["fill", "-o", "x.svg"];
        a.extend(args);
        let o = zf(dir.path(), &a);
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        assert!(o.stderr.contains(flag) && o.stderr.contains(says), "{args:?}: {}", o.stderr);
        assert!(listing(dir.path()).is_empty(), "{args:?} wrote a file");
    }
    // An unknown group lists all 17.
    let o = zf(dir.path(), &["fill", "-o", "x.svg", "--symmetry", "p5", "--lattice", "40"]);
    assert!(GROUPS.iter().all(|g| o.stderr.contains(g)), "{}", o.stderr);
    // The largest c named is the limit: a little above it is refused up front, a little
    // below it fills (at the limit itself the first circle fits at one point only).
    let o = zf(
        dir.path(),
        &["fill", "-o", "x.svg", "--symmetry", "p4m", "--lattice", "40", "--n-offset", "0.3"],
    );
    let c: f64 = o
        .stderr
        .split("lower --c to ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|c| c.parse().ok())
        .expect("a c");
    let run = |c: f64| {
        zf(
            dir.path(),
            &[
                "fill",
                "-o",
                "x.svg",
                "--symmetry",
                "p4m",
                "--lattice",
                "40",
                "--n-offset",
                "0.3",
                "--c",
                &c.to_string(),
                "--count",
                "5",
                "-q",
            ],
        )
    };
    let above = run(c + 2e-4);
    assert!(
        above.code == 2 && above.stderr.contains("cannot clear its own images"),
        "{}",
        above.stderr
    );
    assert_eq!(run(c - 0.01).code, 0);
}
