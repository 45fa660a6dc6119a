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

/// The command an SVG's `<desc>` holds, and the bytes it writes.
fn remade(dir: &std::path::Path, svg: &[u8]) -> (String, Vec<u8>) {
    let text = String::from_utf8(svg.to_vec()).expect("UTF-8");
    let desc = text
        .split("<desc>")
        .nth(1)
        .and_then(|t| t.split("</desc>").next())
        .expect("a <desc>")
        .to_string();
    let mut again = vec!["fill"];
    again.extend(desc.split_whitespace().skip(2));
    again.extend(["-q", "-o", "remade.svg"]);
    zf_ok(dir, &again);
    (desc, read(&dir.join("remade.svg")))
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
    let (desc, again) = remade(dir.path(), &first);
    assert!(desc.contains("--symmetry") && desc.contains("--repeat"), "{desc}");
    assert_eq!(again, first, "the <desc> command gives the same file");
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
    let cases: [(&[&str], &str, &str); 15] = [
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
        (
            &["--symmetry", "p4m", "--lattice", "40", "--repeat", "2:2", "--region", "circle:50"],
            "--region",
            "cannot be used",
        ),
        (
            &["--symmetry", "p4m", "--lattice", "40", "--region", "polygon:0,0,10,0"],
            "--region",
            "",
        ),
        (
            &["--symmetry", "p4m", "--lattice", "40", "--periodic"],
            "--periodic",
            "cannot be used",
        ),
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

/// The regions a pattern is cut to, all with the bounding box [0, 140]^2, and each one's
/// distance to its outline, negative outside: a disc, an annulus, and a U (concave).
const WINDOWS: [&str; 3] = [
    "circle:70",
    "annulus:70:25",
    "polygon:0,0,140,0,140,140,90,140,90,40,50,40,50,140,0,140",
];

fn signed_distance(region: &str, p: [f64; 2]) -> f64 {
    let r = (p[0] - 70.0).hypot(p[1] - 70.0);
    match region.split(':').next() {
        Some("circle") => 70.0 - r,
        Some("annulus") => (70.0 - r).min(r - 25.0),
        _ => {
            let u = [
                [0.0, 0.0],
                [140.0, 0.0],
                [140.0, 140.0],
                [90.0, 140.0],
                [90.0, 40.0],
                [50.0, 40.0],
                [50.0, 140.0],
                [0.0, 140.0],
            ];
            let d = (0..u.len())
                .map(|i| seg_dist(p, u[i], u[(i + 1) % u.len()]))
                .fold(f64::MAX, f64::min);
            let inside = (0.0..=140.0).contains(&p[0]) && (0.0..=140.0).contains(&p[1]) && !(p[0] > 50.0 && p[0] < 90.0 && p[1] > 40.0);
            if inside {
                d
            } else {
                -d
            }
        }
    }
}

/// The first channel of a PNG, row by row from the top, and its width.
fn grey(png: &[u8]) -> (Vec<u8>, usize) {
    let mut reader = png::Decoder::new(png).read_info().unwrap_or_else(|e| panic!("{e}"));
    let mut buf = vec![0u8; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).unwrap_or_else(|e| panic!("{e}"));
    let step = frame.color_type.samples();
    (buf.iter().step_by(step).copied().collect(), frame.width as usize)
}

/// The pixels of `cut` (a picture of [0, 140]^2) that differ from `whole` masked by the
/// region: inside, farther than two pixels from the outline, they must be `whole`'s; outside,
/// the background. A cut shape's arcs are other Bézier curves than its whole circle's, which
/// moves the anti-aliasing of its edge pixels by up to three of the renderer's 16 coverage
/// steps (48 grey levels); a piece missing or too many changes pixels by far more.
fn unmasked(region: &str, cut: &[u8], whole: &[u8], width: usize) -> usize {
    let s = width as f64 / 140.0;
    let (c, wc) = grey(cut);
    let (w, ww) = grey(whole);
    assert_eq!((wc, ww), (width, width));
    let mut bad = 0;
    for (k, (&a, &b)) in c.iter().zip(&w).enumerate() {
        let (i, j) = (k % width, k / width);
        let p = [(i as f64 + 0.5) / s, 140.0 - (j as f64 + 0.5) / s];
        let d = signed_distance(region, p) * s;
        if d > 2.0 && a.abs_diff(b) > 64 || d < -2.0 && a != 255 {
            bad += 1;
        }
    }
    bad
}

#[test]
fn a_pattern_cut_to_a_region_is_its_square_masked_by_the_region() {
    let dir = tmp();
    let run = |name: &str, region: &str, seed: &str| {
        let a = [
            "--symmetry",
            "p6m",
            "--lattice",
            "40",
            "--shape",
            "mix:circle,triangle,blob:0.3",
            "--n-offset",
            "3",
            "--count",
            "120",
            "--style",
            "filled",
            "--pixels",
            "560",
            "--seed",
            seed,
            "--region",
            region,
            "-q",
        ];
        fill_to(dir.path(), name, &a)
    };
    let square = run("square.png", "rect:140:140", "5");
    for region in WINDOWS {
        let cut = run("cut.png", region, "5");
        assert_eq!(unmasked(region, &cut, &square, 560), 0, "{region}");
    }
    // The check sees a picture that is not the square's: another seed's pattern.
    let other = run("other.png", "circle:70", "6");
    assert!(unmasked("circle:70", &other, &square, 560) > 1000, "another pattern went unseen");
}

/// The open pieces and the vertices of every path an outline SVG draws, in mm with y up
/// (the SVG read by usvg, arcs as its curves).
fn strokes(svg: &[u8], height: f64) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let tree = usvg::Tree::from_data(svg, &usvg::Options::default()).expect("an SVG");
    let k = height / f64::from(tree.size().height());
    let (mut points, mut ends) = (Vec::new(), Vec::new());
    fn walk(g: &usvg::Group, k: f64, height: f64, points: &mut Vec<[f64; 2]>, ends: &mut Vec<[f64; 2]>) {
        for node in g.children() {
            match node {
                usvg::Node::Group(g) => walk(g, k, height, points, ends),
                usvg::Node::Path(p) => {
                    let ts = p.abs_transform();
                    let mm = |q: usvg::tiny_skia_path::Point| {
                        let mut q = q;
                        ts.map_point(&mut q);
                        [f64::from(q.x) * k, height - f64::from(q.y) * k]
                    };
                    let mut open: Option<([f64; 2], [f64; 2])> = None;
                    let finish = |open: &mut Option<([f64; 2], [f64; 2])>, ends: &mut Vec<[f64; 2]>| {
                        if let Some((a, b)) = open.take() {
                            ends.extend([a, b]);
                        }
                    };
                    use usvg::tiny_skia_path::PathSegment as S;
                    for seg in p.data().segments() {
                        match seg {
                            S::MoveTo(q) => {
                                finish(&mut open, ends);
                                let q = mm(q);
                                points.push(q);
                                open = Some((q, q));
                            }
                            S::LineTo(q) | S::QuadTo(_, q) | S::CubicTo(_, _, q) => {
                                let q = mm(q);
                                points.push(q);
                                if let Some(o) = &mut open {
                                    o.1 = q;
                                }
                            }
                            S::Close => open = None,
                        }
                    }
                    finish(&mut open, ends);
                }
                _ => {}
            }
        }
    }
    walk(tree.root(), k, height, &mut points, &mut ends);
    (points, ends)
}

#[test]
fn strokes_cut_to_a_region_stay_inside_and_end_on_its_outline() {
    let dir = tmp();
    for region in WINDOWS {
        let a = [
            "--symmetry",
            "p4m",
            "--lattice",
            "40",
            "--shape",
            "mix:circle,square,star:5:0.45",
            "--n-offset",
            "3",
            "--count",
            "100",
            "--region",
            region,
            "-q",
        ];
        let svg = fill_to(dir.path(), "cut.svg", &a);
        let (points, ends) = strokes(&svg, 140.0);
        assert!(
            points.len() > 5000 && ends.len() > 100,
            "{region}: {} points, {} ends",
            points.len(),
            ends.len()
        );
        // Coordinates are written to 1e-4 mm, and read back in f32.
        let outside: Vec<_> = points.iter().filter(|p| signed_distance(region, **p) < -1e-3).collect();
        assert!(
            outside.is_empty(),
            "{region}: {} points outside, first {:?}",
            outside.len(),
            outside.first()
        );
        let loose: Vec<_> = ends.iter().filter(|p| signed_distance(region, **p).abs() > 1e-3).collect();
        assert!(
            loose.is_empty(),
            "{region}: {} piece ends off the outline, first {:?}",
            loose.len(),
            loose.first()
        );
        // Its command makes it again, and the JSON says what it was cut to.
        let (desc, again) = remade(dir.path(), &svg);
        assert!(desc.contains(&format!("--region {region}")) && !desc.contains("--repeat"), "{desc}");
        assert_eq!(again, svg, "{region}: the <desc> command");
        let doc = fill_json(dir.path(), &a);
        assert_eq!(s(&doc["region"]["window"], "kind"), region.split(':').next().expect("a kind"));
        assert!(doc["region"].get("repeat").is_none());
    }
    // The check sees a piece that does not end on the outline: the whole pattern's square.
    let square = fill_to(
        dir.path(),
        "square.svg",
        &[
            "--symmetry",
            "p4m",
            "--lattice",
            "40",
            "--n-offset",
            "3",
            "--count",
            "100",
            "--region",
            "rect:140:140",
            "-q",
        ],
    );
    let (points, _) = strokes(&square, 140.0);
    assert!(points.iter().any(|p| signed_distance("circle:70", *p) < -1e-3));
}

/// The representatives whose centre lies outside the left half of the primitive cell, in
/// the lattice's own coordinate `u = (x - y bx / by) mod ax` (with half a pixel of a 64-pixel
/// picture's blend).
fn right_of_half(doc: &Value) -> usize {
    let v: Vec<f64> = doc["region"]["vectors"]
        .as_array()
        .expect("vectors")
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect();
    let (ax, bx, by) = (v[0], v[1], v[2]);
    shapes(doc)
        .iter()
        .filter(|sh| {
            let c = pt(&sh["center"]);
            (c[0] - c[1] * bx / by).rem_euclid(ax) > 32.5 / 64.0 * ax
        })
        .count()
}

#[test]
fn a_density_picture_covers_one_primitive_cell() {
    let dir = tmp();
    let pic = dir.path().join("half.png");
    png_picture(&pic, 64, 64, |i, _| i < 32);
    let density = format!("image:{},floor=0", pic.display());
    for (group, lattice) in [("p6", "50"), ("pmg", "50:36"), ("p2", "50:40:70")] {
        for sampler in ["fast", "reference", "batched"] {
            let a = [
                "--symmetry",
                group,
                "--lattice",
                lattice,
                "--shape",
                "mix:circle,square",
                "--n-offset",
                "3",
                "--count",
                "60",
                "--sampler",
                sampler,
                "--density",
                &density,
                "-q",
            ];
            let doc = fill_json(dir.path(), &a);
            assert_eq!(shapes(&doc).len(), 60, "{group} {sampler}");
            assert_eq!(right_of_half(&doc), 0, "{group} {sampler}: centres where the density is zero");
            assert_eq!(fill_json(dir.path(), &a)["shapes"], doc["shapes"], "{group} {sampler}: a rerun");
        }
        // The check sees centres in the other half: the same fill without the density.
        let doc = fill_json(
            dir.path(),
            &["--symmetry", group, "--lattice", lattice, "--n-offset", "3", "--count", "60", "-q"],
        );
        assert!(right_of_half(&doc) > 10, "{group}: no centre found outside the half");
    }
    // Noise repeats with the lattice: it runs, and its reruns are the same.
    let a = [
        "--symmetry",
        "p31m",
        "--lattice",
        "50",
        "--n-offset",
        "3",
        "--count",
        "80",
        "--density",
        "noise:gradient:12",
        "-q",
    ];
    let doc = fill_json(dir.path(), &a);
    assert_eq!(fill_json(dir.path(), &a)["shapes"], doc["shapes"]);
    assert_eq!(s(&doc["params"], "density"), "noise:gradient:12:4:0.5:2");
}

#[test]
fn a_pattern_on_a_page_fills_its_drawing_area() {
    let dir = tmp();
    let base = [
        "--symmetry",
        "p4m",
        "--lattice",
        "40",
        "--shape",
        "mix:circle,square",
        "--n-offset",
        "3",
        "--count",
        "120",
        "-q",
    ];
    let with = |name: &str, more: &[&str]| {
        let mut a = base.to_vec();
        a.extend(more);
        fill_to(dir.path(), name, &a)
    };
    // A4 less its 10 mm margins is the region rect:190:277, placed at the margins.
    let page = with("page.svg", &["--page", "a4"]);
    assert_eq!(with("region.svg", &["--region", "rect:190:277", "--page", "a4"]), page);
    let (points, _) = strokes(&page, 297.0);
    let span = points.iter().fold([f64::MAX, f64::MIN, f64::MAX, f64::MIN], |b, p| {
        [b[0].min(p[0]), b[1].max(p[0]), b[2].min(p[1]), b[3].max(p[1])]
    });
    assert!(
        span[0] >= 10.0 - 1e-3 && span[1] <= 200.0 + 1e-3 && span[2] >= 10.0 - 1e-3 && span[3] <= 287.0 + 1e-3,
        "{span:?}"
    );
    assert!(
        span[0] < 10.5 && span[1] > 199.5 && span[2] < 10.5 && span[3] > 286.5,
        "the page is covered: {span:?}"
    );
    // Other margins give another area; --repeat draws its cells on the page instead.
    assert_eq!(
        with("m.svg", &["--page", "a4", "--margin", "20"]),
        with("mr.svg", &["--region", "rect:170:257", "--page", "a4", "--margin", "20"])
    );
    assert_ne!(with("r.svg", &["--page", "a4", "--repeat", "3:3"]), page);
}
