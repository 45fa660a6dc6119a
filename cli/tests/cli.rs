//! End-to-end tests of `zetafill fill` and `zetafill stats`: every output format, checked
//! against docs/cli.md and against each other, with the geometry verified independently.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use serde_json::Value;

const REGION: &str = "rect:100:80";
const W: f64 = 100.0;
const H: f64 = 80.0;

/// One configuration of a fill.
#[derive(Debug, Clone, Copy)]
struct Case<'a> {
    shape: &'a str,
    rotate: Option<&'a str>,
    periodic: bool,
    count: u64,
    seed: u64,
}

impl Case<'_> {
    fn args(&self) -> Vec<String> {
        let mut a = vec!["--shape".to_string(), self.shape.into(), "--region".into(), REGION.into()];
        if let Some(r) = self.rotate {
            a.extend(["--rotate".to_string(), r.into()]);
        }
        if self.periodic {
            a.push("--periodic".into());
        }
        a.extend([
            "--count".to_string(),
            self.count.to_string(),
            "--seed".into(),
            self.seed.to_string(),
        ]);
        a
    }

    fn expect(&self) -> Expect<'_> {
        let rotate = match (self.shape, self.rotate) {
            ("circle", _) => "none",
            (_, Some(r)) => r,
            (_, None) => "random",
        };
        Expect {
            shape: self.shape,
            rotate,
            seed: self.seed,
            w: W,
            h: H,
            periodic: self.periodic,
            count: Some(self.count),
            ..Expect::default()
        }
    }
}

fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

fn with<'a>(base: &'a [String], more: &[&'a str]) -> Vec<&'a str> {
    let mut v = strs(base);
    v.extend_from_slice(more);
    v
}

// ---------------------------------------------------------------------------------------------
// SVG

fn path_boxes(g: &usvg::Group, out: &mut Vec<usvg::Rect>) {
    for n in g.children() {
        match n {
            usvg::Node::Group(g) => path_boxes(g, out),
            usvg::Node::Path(p) => out.push(p.abs_bounding_box()),
            _ => {}
        }
    }
}

/// The value of attribute `name` in an element's text.
fn attr(elem: &str, name: &str) -> f64 {
    let key = format!(" {name}=\"");
    let i = elem.find(&key).unwrap_or_else(|| panic!("no {name} in {elem}")) + key.len();
    let rest = &elem[i..];
    let j = rest.find('"').unwrap_or_else(|| panic!("unterminated {name} in {elem}"));
    rest[..j].parse().unwrap_or_else(|_| panic!("bad {name} in {elem}"))
}

fn attr_str<'a>(elem: &'a str, name: &str) -> &'a str {
    let key = format!(" {name}=\"");
    let i = elem.find(&key).unwrap_or_else(|| panic!("no {name} in {elem}")) + key.len();
    let rest = &elem[i..];
    &rest[..rest.find('"').unwrap_or(rest.len())]
}

/// `v` rounded to four decimals, as the SVG writes it.
fn r4(v: f64) -> f64 {
    format!("{v:.4}").parse().unwrap_or(f64::NAN)
}

/// Shifts (by multiples of W and H) that bring a shape's box into the periodic tile.
fn visible_shifts(g: &G, w: f64, h: f64) -> Vec<(f64, f64)> {
    let (x0, y0, x1, y1) = g.bounds();
    let ks = [-2.0, -1.0, 0.0, 1.0, 2.0];
    let xs: Vec<f64> = ks.iter().map(|k| k * w).filter(|&d| x1 + d > 0.0 && x0 + d < w).collect();
    let ys: Vec<f64> = ks.iter().map(|k| k * h).filter(|&d| y1 + d > 0.0 && y0 + d < h).collect();
    ys.iter().flat_map(|&dy| xs.iter().map(move |&dx| (dx, dy))).collect()
}

/// Checks an SVG against the JSON document of the same run.
fn check_svg(doc: &Value, bytes: &[u8]) {
    let (w, h, periodic) = region(doc);
    let text = std::str::from_utf8(bytes).unwrap_or_else(|e| panic!("SVG is not UTF-8: {e}"));
    let tree = usvg::Tree::from_data(bytes, &usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"));

    // Size: mm converted by usvg at 96 dpi.
    let (pw, ph) = (w * 96.0 / 25.4, h * 96.0 / 25.4);
    let size = tree.size();
    assert!((size.width() as f64 - pw).abs() < 1e-3, "SVG width {} px, want {pw}", size.width());
    assert!(
        (size.height() as f64 - ph).abs() < 1e-3,
        "SVG height {} px, want {ph}",
        size.height()
    );

    // One path per shape (per visible image in a periodic region), inside the view.
    let list = shapes(doc);
    let mut boxes = Vec::new();
    path_boxes(tree.root(), &mut boxes);
    if periodic {
        assert!(boxes.len() >= list.len(), "{} paths for {} shapes", boxes.len(), list.len());
        let want: usize = list.iter().map(|s| visible_shifts(&G::from_json(s), w, h).len()).sum();
        assert_eq!(boxes.len(), want, "one path per visible image");
    } else {
        assert_eq!(boxes.len(), list.len(), "one path per shape");
    }
    let tol = 0.01; // px: four-decimal rounding and f32
    for (i, bb) in boxes.iter().enumerate() {
        let (l, t, r, btm) = (bb.left() as f64, bb.top() as f64, bb.right() as f64, bb.bottom() as f64);
        if periodic {
            assert!(
                r > -tol && l < pw + tol && btm > -tol && t < ph + tol,
                "path {i} {bb:?} does not show in the view"
            );
        } else {
            assert!(
                l >= -tol && t >= -tol && r <= pw + tol && btm <= ph + tol,
                "path {i} {bb:?} leaves the view {pw}x{ph}"
            );
        }
    }

    // Metadata: seed and c in <desc>.
    let d0 = text.find("<desc>").unwrap_or_else(|| panic!("no <desc>")) + "<desc>".len();
    let d1 = text[d0..].find("</desc>").unwrap_or_else(|| panic!("no </desc>")) + d0;
    let desc: Vec<&str> = text[d0..d1].split_whitespace().collect();
    let p = doc.get("params").unwrap_or(&Value::Null);
    let seed = u(p, "seed").to_string();
    let c = f(p, "c");
    assert!(
        desc.windows(2).any(|x| x[0] == "--seed" && x[1] == seed),
        "desc {desc:?} lacks the seed {seed}"
    );
    assert!(
        desc.windows(2).any(|x| x[0] == "--c" && x[1].parse::<f64>().ok() == Some(c)),
        "desc {desc:?} lacks c = {c}"
    );

    // The first shape, drawn with y flipped and four decimals: its elements come first (one
    // per visible image in a periodic region, the unshifted one among them). An image that
    // crosses the tile's edge is cut to it, a path (tests/periodic_svg.rs checks those); the
    // others are whole circles and polygons.
    let Some(first) = list.first() else { return };
    let g = G::from_json(first);
    let shifts = if periodic { visible_shifts(&g, w, h) } else { vec![(0.0, 0.0)] };
    assert!(shifts.contains(&(0.0, 0.0)), "a shape centred in the tile shows unshifted");
    let (x0, y0, x1, y1) = g.bounds();
    let whole: Vec<(f64, f64)> = shifts
        .into_iter()
        .filter(|(dx, dy)| !periodic || (x0 + dx >= 0.0 && x1 + dx <= w && y0 + dy >= 0.0 && y1 + dy <= h))
        .collect();
    let elems = shape_elems(text);
    let mine = &elems[..whole.len()];
    for (dx, dy) in whole {
        let want: Vec<f64> = match &g {
            G::Circle { c, r } => vec![r4(c[0] + dx), r4(h - (c[1] + dy)), r4(*r)],
            G::Poly(vs) => vs.iter().flat_map(|v| [r4(v[0] + dx), r4(h - (v[1] + dy))]).collect(),
        };
        assert!(
            mine.contains(&want),
            "shape 0 shifted by ({dx}, {dy}): {want:?} not among the first elements {mine:?}"
        );
    }
}

/// The numbers of every `<circle>` (cx, cy, r) and `<polygon>` (x1, y1, x2, y2, ...) in
/// document order.
fn shape_elems(svg: &str) -> Vec<Vec<f64>> {
    let mut out = Vec::new();
    let mut rest = svg;
    loop {
        let c = rest.find("<circle ");
        let p = rest.find("<polygon ");
        let i = match (c, p) {
            (Some(a), Some(b)) => a.min(b),
            (Some(a), None) | (None, Some(a)) => a,
            (None, None) => break,
        };
        let j = rest[i..].find('>').unwrap_or_else(|| panic!("unterminated element")) + i;
        let e = &rest[i..=j];
        if e.starts_with("<circle ") {
            out.push(vec![attr(e, "cx"), attr(e, "cy"), attr(e, "r")]);
        } else {
            out.push(
                attr_str(e, "points")
                    .split(|ch: char| ch == ',' || ch.is_whitespace())
                    .filter(|t| !t.is_empty())
                    .map(|t| t.parse().unwrap_or(f64::NAN))
                    .collect(),
            );
        }
        rest = &rest[j..];
    }
    out
}

// ---------------------------------------------------------------------------------------------
// CSV

fn check_csv(doc: &Value, bytes: &[u8]) {
    let text = std::str::from_utf8(bytes).unwrap_or_else(|e| panic!("CSV is not UTF-8: {e}"));
    assert!(text.ends_with('\n'), "CSV ends with a newline");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("index,kind,x,y,radius,angle,area,trials"), "CSV header");
    let rows: Vec<&str> = lines.collect();
    let list = shapes(doc);
    assert_eq!(rows.len(), list.len(), "one CSV row per shape");
    let num = |s: &str| s.parse::<f64>().unwrap_or_else(|_| panic!("bad number '{s}'"));
    for (i, (row, sh)) in rows.iter().zip(list).enumerate() {
        let c: Vec<&str> = row.split(',').collect();
        assert_eq!(c.len(), 8, "row {i}: {row}");
        assert_eq!(c[0].parse::<u64>().ok(), Some(u(sh, "index")), "row {i} index");
        assert_eq!(c[1], s(sh, "kind"), "row {i} kind");
        let cen = pt(sh.get("center").unwrap_or(&Value::Null));
        assert_eq!(num(c[2]), cen[0], "row {i} x");
        assert_eq!(num(c[3]), cen[1], "row {i} y");
        match sh.get("radius").and_then(Value::as_f64) {
            Some(r) => {
                assert_eq!(num(c[4]), r, "row {i} radius");
                assert_eq!(c[5], "", "row {i}: circles have no angle");
            }
            None => {
                assert_eq!(c[4], "", "row {i}: polygons have no radius");
                assert_eq!(num(c[5]), f(sh, "angle"), "row {i} angle");
            }
        }
        assert_eq!(num(c[6]), f(sh, "area"), "row {i} area");
        assert_eq!(c[7].parse::<u64>().ok(), Some(u(sh, "trials")), "row {i} trials");
    }
}

// ---------------------------------------------------------------------------------------------
// Every format, end to end

fn full_case(case: Case) {
    let dir = tmp();
    let d = dir.path();
    let args = case.args();
    let json = fill_to(d, "out.json", &strs(&args));
    let doc = parse_json(&json);
    let halted = check_doc(&doc, &case.expect());
    assert!(!halted, "{case:?} halted");
    assert_eq!(shapes(&doc).len() as u64, case.count);
    assert_geometry(&doc);

    // Standard output with --format json: the same bytes as the file. (Polygon runs cost
    // more in the core, so only rotated squares repeat this.)
    if case.shape == "circle" || (case.shape == "square" && case.rotate != Some("none")) {
        let mut a = vec!["fill"];
        a.extend(with(&args, &["-o", "-", "--format", "json"]));
        let o = zf_ok(d, &a);
        assert_eq!(o.stdout, json, "stdout JSON differs from the file");
    }

    let svg = fill_to(d, "out.svg", &strs(&args));
    check_svg(&doc, &svg);
    let csv = fill_to(d, "out.csv", &strs(&args));
    check_csv(&doc, &csv);

    // Nothing else left behind (no temporary files).
    let names: Vec<String> = listing(d)
        .iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    assert_eq!(names, ["out.csv", "out.json", "out.svg"]);
}

#[test]
fn circles_inclusive_all_formats() {
    full_case(Case {
        shape: "circle",
        rotate: None,
        periodic: false,
        count: 300,
        seed: 7,
    });
}

#[test]
fn circles_periodic_all_formats() {
    full_case(Case {
        shape: "circle",
        rotate: None,
        periodic: true,
        count: 300,
        seed: 7,
    });
}

#[test]
fn squares_rotated_inclusive_all_formats() {
    full_case(Case {
        shape: "square",
        rotate: None,
        periodic: false,
        count: 250,
        seed: 3,
    });
}

#[test]
fn squares_rotated_periodic_all_formats() {
    full_case(Case {
        shape: "square",
        rotate: Some("random"),
        periodic: true,
        count: 250,
        seed: 3,
    });
}

#[test]
fn squares_unrotated_inclusive_all_formats() {
    full_case(Case {
        shape: "square",
        rotate: Some("none"),
        periodic: false,
        count: 250,
        seed: 11,
    });
}

#[test]
fn squares_unrotated_periodic_all_formats() {
    full_case(Case {
        shape: "square",
        rotate: Some("none"),
        periodic: true,
        count: 250,
        seed: 11,
    });
}

#[test]
fn rects_inclusive_all_formats() {
    full_case(Case {
        shape: "rect:2.5",
        rotate: None,
        periodic: false,
        count: 200,
        seed: 5,
    });
}

#[test]
fn rects_periodic_all_formats() {
    full_case(Case {
        shape: "rect:2.5",
        rotate: None,
        periodic: true,
        count: 200,
        seed: 5,
    });
}

#[test]
fn rects_unrotated_inclusive_all_formats() {
    full_case(Case {
        shape: "rect:2.5",
        rotate: Some("none"),
        periodic: false,
        count: 200,
        seed: 2,
    });
}

#[test]
fn rects_unrotated_periodic_all_formats() {
    full_case(Case {
        shape: "rect:2.5",
        rotate: Some("none"),
        periodic: true,
        count: 200,
        seed: 2,
    });
}

#[test]
fn rotated_squares_really_rotate() {
    let dir = tmp();
    let doc = fill_json(dir.path(), &["--shape", "square", "--region", REGION, "--count", "50"]);
    let nonzero = shapes(&doc).iter().filter(|s| f(s, "angle") != 0.0).count();
    assert!(nonzero > 40, "only {nonzero} of 50 squares rotated by default");
}

#[test]
fn stdout_without_format_is_svg() {
    let dir = tmp();
    let d = dir.path();
    let args = ["fill", "--region", REGION, "--count", "40", "-o", "-"];
    let o = zf_ok(d, &args);
    let svg = fill_to(d, "a.svg", &["--region", REGION, "--count", "40"]);
    assert_eq!(o.stdout, svg);
    assert_eq!(listing(d).len(), 1, "only a.svg was written");
}

#[test]
fn format_flag_overrides_extension() {
    let dir = tmp();
    let d = dir.path();
    zf_ok(d, &["fill", "--region", REGION, "--count", "30", "--format", "csv", "-o", "x.json"]);
    let csv = fill_to(d, "x.csv", &["--region", REGION, "--count", "30"]);
    assert_eq!(read(&d.join("x.json")), csv);
}

#[test]
fn gap_is_kept_between_shapes_and_to_the_boundary() {
    for shape in ["circle", "square", "rect:2.5"] {
        for periodic in [false, true] {
            let dir = tmp();
            let mut a = vec![
                "--shape",
                shape,
                "--region",
                REGION,
                "--gap",
                "0.3",
                "--n-offset",
                "4",
                "--count",
                "120",
                "--seed",
                "4",
            ];
            if periodic {
                a.push("--periodic");
            }
            let doc = fill_json(dir.path(), &a);
            let rotate = if shape == "circle" { "none" } else { "random" };
            let e = Expect {
                shape,
                rotate,
                seed: 4,
                periodic,
                n_offset: 4.0,
                count: Some(120),
                gap: 0.3,
                ..Expect::default()
            };
            check_doc(&doc, &e);
            assert_geometry(&doc);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Reproducibility

fn reruns(shape: &str, periodic: bool, exts: &[&str]) {
    let dir = tmp();
    let d = dir.path();
    let mut base = vec!["--shape", shape, "--region", REGION, "--count", "200", "--seed", "9"];
    if periodic {
        base.push("--periodic");
    }
    let mut other = base.clone();
    other[7] = "10";
    for ext in exts {
        let a = fill_to(d, &format!("a.{ext}"), &base);
        let b = fill_to(d, &format!("b.{ext}"), &base);
        assert_eq!(a, b, "{shape} {ext}: two runs differ");
        let c = fill_to(d, &format!("c.{ext}"), &other);
        assert_ne!(a, c, "{shape} {ext}: another seed gives the same bytes");
    }
}

#[test]
fn reruns_are_byte_identical_and_seeds_differ_circles() {
    reruns("circle", false, &["svg", "json", "csv"]);
}

#[test]
fn reruns_are_byte_identical_and_seeds_differ_squares_periodic() {
    reruns("square", true, &["svg", "json", "csv"]);
}

#[test]
fn reruns_are_byte_identical_and_seeds_differ_rects() {
    reruns("rect:2.5", false, &["json"]);
}

#[test]
fn svg_desc_reproduces_the_run() {
    let dir = tmp();
    let d = dir.path();
    for extra in [
        &[][..],
        &["--periodic", "--shape", "rect:2.5"][..],
        &["--fill", "0.6", "--shape", "square"][..],
    ] {
        let mut a = vec!["--region", REGION, "--seed", "21"];
        a.extend_from_slice(extra);
        if !extra.contains(&"--fill") {
            a.extend_from_slice(&["--count", "120"]);
        }
        let svg = fill_to(d, "orig.svg", &a);
        let text = String::from_utf8_lossy(&svg).into_owned();
        let d0 = text.find("<desc>").unwrap_or(0) + 6;
        let d1 = text.find("</desc>").unwrap_or(text.len());
        let words: Vec<&str> = text[d0..d1].split_whitespace().collect();
        assert_eq!(words.first(), Some(&"zetafill"), "desc is a command line: {words:?}");
        let mut again: Vec<&str> = words[1..].to_vec();
        again.extend_from_slice(&["-o", "again.svg"]);
        zf_ok(d, &again);
        assert_eq!(
            read(&d.join("again.svg")),
            svg,
            "the desc command line {words:?} does not reproduce the file"
        );
    }
}

#[test]
fn prefix_stability() {
    let dir = tmp();
    let d = dir.path();
    for (shape, periodic) in [("circle", false), ("circle", true), ("square", true), ("rect:2.5", false)] {
        let mut base = vec!["--shape", shape, "--region", REGION, "--seed", "13"];
        if periodic {
            base.push("--periodic");
        }
        let short = fill_json(d, &[&base[..], &["--count", "50"]].concat());
        let long = fill_json(d, &[&base[..], &["--count", "200"]].concat());
        let (s, l) = (shapes(&short), shapes(&long));
        assert_eq!(s.len(), 50);
        assert_eq!(l.len(), 200);
        for i in 0..50 {
            assert_eq!(
                s[i], l[i],
                "{shape} periodic={periodic}: shape {i} differs between --count 50 and 200"
            );
        }
    }
}

#[test]
fn dimension_is_c_two_over_d() {
    let dir = tmp();
    let d = dir.path();
    for ext in ["json", "svg", "csv"] {
        let a = fill_to(
            d,
            &format!("d.{ext}"),
            &["--region", REGION, "--count", "150", "--dimension", "1.6"],
        );
        let b = fill_to(d, &format!("c.{ext}"), &["--region", REGION, "--count", "150", "--c", "1.25"]);
        assert_eq!(a, b, "{ext}: --dimension 1.6 differs from --c 1.25");
    }
    let doc = parse_json(&read(&d.join("d.json")));
    check_doc(
        &doc,
        &Expect {
            c: 1.25,
            count: Some(150),
            ..Expect::default()
        },
    );
}

// ---------------------------------------------------------------------------------------------
// Stop conditions

fn prefix_fraction(doc: &Value, k: usize) -> f64 {
    shapes(doc).iter().take(k).map(|s| f(s, "area")).sum::<f64>() / f(doc, "area")
}

#[test]
fn fill_stops_at_the_first_shape_reaching_the_fraction() {
    let dir = tmp();
    for (shape, fill) in [("circle", 0.5), ("circle", 0.8), ("square", 0.5), ("rect:2.5", 0.7)] {
        let doc = fill_json(
            dir.path(),
            &["--shape", shape, "--region", REGION, "--fill", &fill.to_string(), "--seed", "3"],
        );
        let rotate = if shape == "circle" { "none" } else { "random" };
        assert!(!check_doc(
            &doc,
            &Expect {
                shape,
                rotate,
                seed: 3,
                ..Expect::default()
            }
        ));
        assert_geometry(&doc);
        let p = doc.get("params").unwrap_or(&Value::Null);
        assert_eq!(f(p, "fill"), fill);
        assert!(p.get("count").is_none(), "no count with only --fill: {p}");
        let n = shapes(&doc).len();
        assert!(n >= 1);
        let ff = f(doc.get("stats").unwrap_or(&Value::Null), "fill_fraction");
        assert!(ff >= fill, "{shape}: stopped at {ff} < {fill}");
        assert!(prefix_fraction(&doc, n) >= fill);
        assert!(
            prefix_fraction(&doc, n - 1) < fill,
            "{shape}: {n} shapes, but {} already reached {fill}",
            n - 1
        );
    }
}

#[test]
fn min_size_stops_before_the_first_narrower_shape() {
    let dir = tmp();
    for shape in ["circle", "square", "rect:2.5"] {
        let doc = fill_json(
            dir.path(),
            &["--shape", shape, "--region", REGION, "--min-size", "2", "--seed", "8"],
        );
        let rotate = if shape == "circle" { "none" } else { "random" };
        assert!(!check_doc(
            &doc,
            &Expect {
                shape,
                rotate,
                seed: 8,
                ..Expect::default()
            }
        ));
        assert_geometry(&doc);
        assert_eq!(f(doc.get("params").unwrap_or(&Value::Null), "min_size"), 2.0);
        let aspect = aspect_of(shape);
        // Narrowest width of a shape of area a: diameter, or the shorter side.
        let width = |a: f64| {
            if shape == "circle" {
                2.0 * (a / std::f64::consts::PI).sqrt()
            } else {
                let hh = (a / (4.0 * aspect)).sqrt();
                2.0 * hh.min(aspect * hh)
            }
        };
        let list = shapes(&doc);
        let n = list.len();
        assert!(n > 10, "{shape}: only {n} shapes");
        for sh in list {
            assert!(width(f(sh, "area")) >= 2.0, "{shape}: shape {} narrower than 2 mm", u(sh, "index"));
        }
        let (zeta, area) = (f(&doc, "zeta"), f(&doc, "area"));
        let next = area / (zeta * (n as f64 + 1.0).powf(1.3));
        assert!(
            width(next) < 2.0,
            "{shape}: stopped at {n} although shape {n} is {} mm wide",
            width(next)
        );
    }
}

// ---------------------------------------------------------------------------------------------
// stats

const ZETA_13: f64 = 3.931949211809544;

#[test]
fn stats_zeta_json_and_plain() {
    let dir = tmp();
    let d = dir.path();
    let o = zf_ok(d, &["stats", "zeta", "--c", "1.3", "--n-offset", "1", "--json"]);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    assert_eq!(text.trim_end().lines().count(), 1, "one JSON object on one line: {text}");
    let v = parse_json(text.as_bytes());
    assert!(v.is_object());
    let z = f(&v, "zeta");
    assert!(rel(z, ZETA_13) <= 1e-14, "zeta(1.3, 1) = {z}");

    let o = zf_ok(d, &["stats", "zeta", "--c", "1.3", "--n-offset", "1"]);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let plain: f64 = text.trim().parse().unwrap_or_else(|_| panic!("not a plain number: {text:?}"));
    assert_eq!(plain, z, "plain and JSON agree");

    // The fill uses the same zeta.
    let doc = fill_json(d, &["--region", REGION, "--count", "5"]);
    assert_eq!(f(&doc, "zeta"), z);
    assert!(listing(d).iter().all(|p| p.ends_with("out.json")), "stats wrote no file");
}

#[test]
fn stats_zeta_other_offsets_match_fill() {
    let dir = tmp();
    let d = dir.path();
    let o = zf_ok(d, &["stats", "zeta", "--c", "1.4", "--n-offset", "2.5", "--json"]);
    let z = f(&parse_json(&o.stdout), "zeta");
    // Direct sum with an integral tail bound: zeta(c, N) = sum_{i<K} (i+N)^-c + ~(K+N-1/2)^(1-c)/(c-1).
    let (c, n) = (1.4f64, 2.5f64);
    let k = 200_000u32;
    let head: f64 = (0..k).map(|i| (i as f64 + n).powf(-c)).sum();
    let tail = (k as f64 + n - 0.5).powf(1.0 - c) / (c - 1.0);
    assert!(rel(z, head + tail) < 1e-8, "zeta(1.4, 2.5) = {z}, direct {}", head + tail);
    let doc = fill_json(d, &["--region", REGION, "--count", "5", "--c", "1.4", "--n-offset", "2.5"]);
    assert_eq!(f(&doc, "zeta"), z);
    check_doc(
        &doc,
        &Expect {
            c: 1.4,
            n_offset: 2.5,
            count: Some(5),
            ..Expect::default()
        },
    );
}
