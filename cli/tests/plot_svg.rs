//! Plotter SVG: pages with margins, `--center`, `--fit`, Inkscape layers by size band, read
//! back with usvg (element count, bounds and units must match the page), and reruns
//! byte-identical. The default SVG (no page, no layers) is pinned by the gallery test.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;

const PX_PER_MM: f64 = 96.0 / 25.4;

fn tree(bytes: &[u8]) -> usvg::Tree {
    usvg::Tree::from_data(bytes, &usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"))
}

/// Bounding boxes (px) of every drawn path, and how many there are per top-level group id.
/// The Inkscape layers of a drawing: the groups whose id starts with `layer`, in order.
fn layer_groups<'a>(g: &'a usvg::Group, out: &mut Vec<&'a usvg::Group>) {
    for node in g.children() {
        if let usvg::Node::Group(g) = node {
            if g.id().starts_with("layer") {
                out.push(g);
            } else {
                layer_groups(g, out);
            }
        }
    }
}

fn paths(g: &usvg::Group, out: &mut Vec<usvg::Rect>) {
    for n in g.children() {
        match n {
            usvg::Node::Group(g) => paths(g, out),
            usvg::Node::Path(p) => out.push(p.abs_bounding_box()),
            _ => {}
        }
    }
}

fn union(boxes: &[usvg::Rect]) -> [f64; 4] {
    boxes
        .iter()
        .fold([f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY], |b, r| {
            [
                b[0].min(r.left() as f64),
                b[1].min(r.top() as f64),
                b[2].max(r.right() as f64),
                b[3].max(r.bottom() as f64),
            ]
        })
}

/// The region's box on the page in mm (x0, y0 from the top-left, x1, y1), from the shapes
/// of the same run: circles' extreme points.
fn drawn_mm(tree: &usvg::Tree) -> [f64; 4] {
    let mut boxes = Vec::new();
    paths(tree.root(), &mut boxes);
    let b = union(&boxes);
    [b[0] / PX_PER_MM, b[1] / PX_PER_MM, b[2] / PX_PER_MM, b[3] / PX_PER_MM]
}

/// Asserts that a drawing's box (mm from the page's top-left) lies in the 100 x 80 mm tile
/// centred on A4 (x 55 to 155, y 108.5 to 188.5), up to half the pen's width.
fn assert_in_a4_tile(b: [f64; 4]) {
    let pen = 0.3 / 2.0 + 1e-3;
    assert!(
        b[0] >= 55.0 - pen && b[2] <= 155.0 + pen && b[1] >= 108.5 - pen && b[3] <= 188.5 + pen,
        "{b:?} leaves the tile"
    );
}

fn size_mm(t: &usvg::Tree) -> (f64, f64) {
    (t.size().width() as f64 / PX_PER_MM, t.size().height() as f64 / PX_PER_MM)
}

#[test]
fn page_presets_place_the_drawing_inside_the_margins() {
    let dir = tmp();
    let d = dir.path();
    let base = ["--region", "rect:150:100", "--count", "300", "--seed", "21"];
    let doc = fill_json(d, &base);
    let n = shapes(&doc).len();
    for (page, w, h) in [
        ("a4", 210.0, 297.0),
        ("a3", 297.0, 420.0),
        ("letter", 215.9, 279.4),
        ("a4-landscape", 297.0, 210.0),
        ("180x130", 180.0, 130.0),
    ] {
        let svg = fill_to(d, "p.svg", &[&base[..], &["--page", page, "--margin", "12"]].concat());
        let text = String::from_utf8_lossy(&svg).into_owned();
        assert!(
            text.contains(&format!("width=\"{w}mm\"")) && text.contains(&format!("height=\"{h}mm\"")),
            "{page}: size in mm"
        );
        assert!(text.contains(&format!("viewBox=\"0 0 {w} {h}\"")), "{page}: a viewBox in mm");
        let t = tree(&svg);
        let (pw, ph) = size_mm(&t);
        assert!((pw - w).abs() < 1e-3 && (ph - h).abs() < 1e-3, "{page}: usvg reads {pw} x {ph} mm");
        let mut boxes = Vec::new();
        paths(t.root(), &mut boxes);
        assert_eq!(boxes.len(), n, "{page}: one element per shape");
        // Top-left placement: the region's box starts at the margin; every shape inside it.
        let b = drawn_mm(&t);
        let pen = 0.3 / 2.0 + 1e-3;
        assert!(b[0] >= 12.0 - pen && b[1] >= 12.0 - pen, "{page}: {b:?}");
        assert!(b[2] <= 12.0 + 150.0 + pen && b[3] <= 12.0 + 100.0 + pen, "{page}: {b:?}");
        assert_eq!(
            svg,
            fill_to(d, "q.svg", &[&base[..], &["--page", page, "--margin", "12"]].concat()),
            "{page}: byte-identical rerun"
        );
    }
}

#[test]
fn center_and_fit() {
    let dir = tmp();
    let d = dir.path();
    let base = ["--region", "rect:150:100", "--count", "300", "--seed", "22", "--boundary"];
    // With --boundary the region's outline is drawn, so its box is the drawing's box.
    let c = tree(&fill_to(d, "c.svg", &[&base[..], &["--page", "a4", "--center"]].concat()));
    let b = drawn_mm(&c);
    let pen = 0.3 / 2.0 + 1e-3;
    assert!(
        (b[0] - (210.0 - 150.0) / 2.0).abs() <= pen && (b[2] - (210.0 + 150.0) / 2.0).abs() <= pen,
        "{b:?}"
    );
    assert!(
        (b[1] - (297.0 - 100.0) / 2.0).abs() <= pen && (b[3] - (297.0 + 100.0) / 2.0).abs() <= pen,
        "{b:?}"
    );
    // --fit scales to the page less margins: 150 mm wide becomes 190 mm on A4 with 10 mm margins.
    let f = tree(&fill_to(d, "f.svg", &[&base[..], &["--page", "a4", "--fit"]].concat()));
    let b = drawn_mm(&f);
    assert!((b[0] - 10.0).abs() <= pen && (b[2] - 200.0).abs() <= pen, "{b:?}");
    assert!(((b[3] - b[1]) - 190.0 * 100.0 / 150.0).abs() <= 2.0 * pen, "{b:?}");
    // Too big for the page: refused, naming --page, nothing written.
    std::fs::write(d.join("big.svg"), b"keep").unwrap_or_else(|e| panic!("{e}"));
    let o = zf(
        d,
        &["fill", "--region", "rect:300:100", "--count", "20", "--page", "a4", "-o", "big.svg"],
    );
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(names_flag(&o.stderr, "--page") && o.stderr.contains("--fit"), "{}", o.stderr);
    assert_eq!(read(&d.join("big.svg")), b"keep");
    // --fit without a page is a mistake for SVG.
    let o = zf(d, &["fill", "--count", "20", "--fit", "-o", "x.svg"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--fit"), "{}", o.stderr);
    let o = zf(d, &["fill", "--count", "20", "--page", "a4", "--margin", "200", "-o", "x.svg"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--margin"), "{}", o.stderr);
}

#[test]
fn layers_split_shapes_by_size() {
    let dir = tmp();
    let d = dir.path();
    let base = ["--region", "rect:150:150", "--count", "400", "--seed", "23"];
    let doc = fill_json(d, &base);
    let n = shapes(&doc).len();
    let svg = fill_to(d, "l.svg", &[&base[..], &["--layers", "size-bands:3", "--page", "a4"]].concat());
    let text = String::from_utf8_lossy(&svg).into_owned();
    assert_eq!(text.matches("inkscape:groupmode=\"layer\"").count(), 3, "three Inkscape layers");
    for k in 1..=3 {
        assert!(
            text.contains(&format!("id=\"layer{k}\"")) && text.contains(&format!("inkscape:label=\"{k} ")),
            "layer {k}"
        );
    }
    let t = tree(&svg);
    // Each layer is a top-level group (usvg keeps groups with an id).
    let mut groups = Vec::new();
    layer_groups(t.root(), &mut groups);
    let per_layer: Vec<(String, Vec<usvg::Rect>)> = groups
        .iter()
        .map(|g| {
            let mut v = Vec::new();
            paths(g, &mut v);
            (g.id().to_string(), v)
        })
        .collect();
    let ids: Vec<&str> = per_layer.iter().map(|(i, _)| i.as_str()).collect();
    assert_eq!(ids, ["layer1", "layer2", "layer3"]);
    assert_eq!(
        per_layer.iter().map(|(_, v)| v.len()).sum::<usize>(),
        n,
        "every shape in exactly one layer"
    );
    assert!(per_layer.iter().all(|(_, v)| !v.is_empty()));
    // Largest first: every shape of a layer is at least as large as every shape of the next.
    let size = |r: &usvg::Rect| r.width().max(r.height()) as f64;
    for w in per_layer.windows(2) {
        let smallest = w[0].1.iter().map(size).fold(f64::INFINITY, f64::min);
        let largest_next = w[1].1.iter().map(size).fold(0.0, f64::max);
        assert!(
            smallest >= largest_next - 1e-3,
            "{} then {}: {smallest} < {largest_next}",
            w[0].0,
            w[1].0
        );
    }
    assert!(per_layer[0].1.len() < per_layer[2].1.len(), "few large shapes, many small ones");
    // Layers without a page work too, and keep the region's size.
    let plain = tree(&fill_to(d, "m.svg", &[&base[..], &["--layers", "size-bands:2"]].concat()));
    let (w, h) = size_mm(&plain);
    assert!((w - 150.0).abs() < 1e-3 && (h - 150.0).abs() < 1e-3);
    let o = zf(d, &["fill", "--count", "20", "--layers", "size-bands:0", "-o", "x.svg"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--layers"), "{}", o.stderr);
}

#[test]
fn periodic_on_a_page_clips_to_the_tile() {
    let dir = tmp();
    let d = dir.path();
    let svg = fill_to(
        d,
        "t.svg",
        &[
            "--region",
            "rect:100:80",
            "--periodic",
            "--count",
            "200",
            "--seed",
            "24",
            "--page",
            "a4",
            "--center",
        ],
    );
    let t = tree(&svg);
    let b = drawn_mm(&t);
    // Images of edge-crossing shapes are cut exactly to the tile (plotter tools ignore
    // clip-path), so nothing is drawn outside.
    assert_in_a4_tile(b);
    let pen = 0.3 / 2.0 + 1e-3;
    assert!(b[0] < 55.5 && b[2] > 154.5, "cut shapes reach the tile's edges: {b:?}");
    let text = String::from_utf8_lossy(&svg).into_owned();
    assert!(!text.contains("clip-path"), "no clip-path for plotters");
    // The same with layers and no page: the tile is the page.
    let l = tree(&fill_to(
        d,
        "tl.svg",
        &[
            "--region",
            "rect:100:80",
            "--periodic",
            "--count",
            "200",
            "--seed",
            "24",
            "--layers",
            "size-bands:2",
        ],
    ));
    let b = drawn_mm(&l);
    assert!(b[0] >= -pen && b[2] <= 100.0 + pen && b[1] >= -pen && b[3] <= 80.0 + pen, "{b:?}");
    // Without page and layers too (tests/periodic_svg.rs checks every coordinate).
    let plain = fill_to(
        d,
        "tp.svg",
        &["--region", "rect:100:80", "--periodic", "--count", "200", "--seed", "24"],
    );
    assert!(!String::from_utf8_lossy(&plain).contains("clip-path"), "no clip-path");
    let b = drawn_mm(&tree(&plain));
    assert!(b[0] >= -pen && b[2] <= 100.0 + pen && b[1] >= -pen && b[3] <= 80.0 + pen, "{b:?}");
    // PNG previews follow the page.
    let png = fill_to(d, "t.png", &["--region", "rect:100:80", "--count", "50", "--page", "a5"]);
    assert_eq!(&png[12..16], b"IHDR");
    let be = |i: usize| u32::from_be_bytes([png[i], png[i + 1], png[i + 2], png[i + 3]]);
    assert_eq!((be(16), be(20)), (560, 794), "A5 at 96 dpi");
}

/// Every straight piece `[a, b]` of every drawn path, in the region's frame (mm, y up) of a
/// drawing `height` mm tall: SVG y points down, usvg works in px.
fn line_pieces(g: &usvg::Group, height: f64, out: &mut Vec<[[f64; 2]; 2]>) {
    use usvg::tiny_skia_path::PathSegment;
    for n in g.children() {
        match n {
            usvg::Node::Group(g) => line_pieces(g, height, out),
            usvg::Node::Path(p) => {
                let ts = p.abs_transform();
                let mm = |mut q: usvg::tiny_skia_path::Point| {
                    ts.map_point(&mut q);
                    [q.x as f64 / PX_PER_MM, height - q.y as f64 / PX_PER_MM]
                };
                let mut last = None;
                for seg in p.data().segments() {
                    match seg {
                        PathSegment::MoveTo(q) => last = Some(mm(q)),
                        PathSegment::LineTo(q) => {
                            let b = mm(q);
                            if let Some(a) = last {
                                out.push([a, b]);
                            }
                            last = Some(b);
                        }
                        _ => last = None,
                    }
                }
            }
            _ => {}
        }
    }
}

/// `--hatch` in SVG, read back with usvg: each line lies in one ring's material (both ends on
/// its circles), a ring whose hole is narrower than `--min-feature` is hatched as a disc, rings
/// narrower than it are left out, and the lines' total length times the spacing is the area
/// of what is kept. The lines run at the angle asked for.
#[test]
fn svg_hatch_fills_each_shape_it_keeps() {
    let dir = tmp();
    let d = dir.path();
    let base = RINGS;
    let doc = fill_json(d, &base);
    let min_feature = 4.0;
    // Kept rings as (centre, outer, hole drawn).
    let rings: Vec<([f64; 2], f64, f64)> = rings(&doc)
        .into_iter()
        .filter(|r| 2.0 * r.1 >= min_feature)
        .map(|(c, ro, ri)| (c, ro, if 2.0 * ri >= min_feature { ri } else { 0.0 }))
        .collect();
    assert!(rings.len() < shapes(&doc).len(), "some rings are narrower than 4 mm");
    assert!(rings.iter().any(|r| r.2 == 0.0), "some holes are narrower than 4 mm");
    let spacing = 0.4;
    let svg = fill_to(
        d,
        "h.svg",
        &[&base[..], &["--hatch", "0.4:20", "--hatch-only", "--min-feature", "4"]].concat(),
    );
    let mut segs = Vec::new();
    line_pieces(tree(&svg).root(), 120.0, &mut segs);
    let tol = 2e-3;
    let mut length = 0.0;
    for s in &segs {
        let mid = [(s[0][0] + s[1][0]) / 2.0, (s[0][1] + s[1][1]) / 2.0];
        let ok = rings.iter().any(|(c, ro, ri)| {
            let dist = |q: [f64; 2]| (q[0] - c[0]).hypot(q[1] - c[1]);
            let on = |q| (dist(q) - ro).abs() < tol || (*ri > 0.0 && (dist(q) - ri).abs() < tol);
            dist(mid) >= ri - tol && dist(mid) <= ro + tol && on(s[0]) && on(s[1])
        });
        assert!(ok, "hatch line {s:?} is not inside one kept ring");
        let (dx, dy) = (s[1][0] - s[0][0], s[1][1] - s[0][1]);
        let sin = (dx * 20f64.to_radians().sin() - dy * 20f64.to_radians().cos()).abs() / dx.hypot(dy);
        assert!(sin < 1e-3, "line {s:?} is not at 20 degrees");
        length += dx.hypot(dy);
    }
    let area: f64 = rings.iter().map(|(_, ro, ri)| std::f64::consts::PI * (ro * ro - ri * ri)).sum();
    assert!(rel(length * spacing, area) < 0.02, "hatched {} mm^2 of {area}", length * spacing);
    // Cross-hatching: the same lines, and as much again at right angles (110 degrees).
    let crossed = fill_to(
        d,
        "x.svg",
        &[
            &base[..],
            &["--hatch", "0.4:20", "--cross-hatch", "--hatch-only", "--min-feature", "4"],
        ]
        .concat(),
    );
    let mut both = Vec::new();
    line_pieces(tree(&crossed).root(), 120.0, &mut both);
    let family = |deg: f64| -> (usize, f64) {
        let (sin, cos) = deg.to_radians().sin_cos();
        let on: Vec<f64> = both
            .iter()
            .map(|s| (s[1][0] - s[0][0], s[1][1] - s[0][1]))
            .filter(|(dx, dy)| (dx * sin - dy * cos).abs() < 1e-3 * dx.hypot(*dy))
            .map(|(dx, dy)| dx.hypot(dy))
            .collect();
        (on.len(), on.iter().sum())
    };
    let ((n20, l20), (n110, l110)) = (family(20.0), family(110.0));
    assert_eq!((n20, n20 + n110), (segs.len(), both.len()), "two families, the first unchanged");
    assert!(rel(l110 * spacing, area) < 0.02 && rel(l20, length) < 1e-6, "{l20} {l110}");
    // With outlines: one circle element per ring (and per drawn hole) besides the hatch.
    let text = String::from_utf8_lossy(&fill_to(
        d,
        "o.svg",
        &[&base[..], &["--hatch", "0.4:20", "--min-feature", "4"]].concat(),
    ))
    .into_owned();
    assert_eq!(text.matches("class=\"hatch\"").count(), rings.len(), "one hatch path per ring");
    assert_eq!(
        text.matches("fill-rule=\"evenodd\"").count(),
        rings.iter().filter(|r| r.2 > 0.0).count()
    );
    assert_eq!(text.matches("<circle").count(), rings.iter().filter(|r| r.2 == 0.0).count());
    assert_eq!(
        svg,
        fill_to(
            d,
            "h2.svg",
            &[&base[..], &["--hatch", "0.4:20", "--hatch-only", "--min-feature", "4"]].concat()
        ),
        "byte-identical rerun"
    );
}

/// A periodic fill hatched on a page with layers (the plotter case): outlines and hatch cut
/// exactly to the tile, nothing outside it, each layer holding its shapes' hatch too.
#[test]
fn svg_hatch_of_a_periodic_fill_stays_in_the_tile() {
    let dir = tmp();
    let d = dir.path();
    let base = [
        "--region",
        "rect:100:80",
        "--periodic",
        "--shape",
        "star:5:0.5",
        "--count",
        "150",
        "--seed",
        "3",
        "--hatch",
        "0.5",
    ];
    let svg = fill_to(
        d,
        "p.svg",
        &[&base[..], &["--page", "a4", "--center", "--layers", "size-bands:2"]].concat(),
    );
    let t = tree(&svg);
    assert_in_a4_tile(drawn_mm(&t));
    let text = String::from_utf8_lossy(&svg).into_owned();
    assert!(!text.contains("clip-path"), "no clip-path for plotters");
    for k in 1..=2 {
        let layer = text
            .split(&format!("id=\"layer{k}\""))
            .nth(1)
            .and_then(|t| t.split("</g>").next())
            .unwrap_or("");
        assert!(layer.contains("class=\"hatch\""), "layer {k} holds hatch lines");
    }
    // In the tile frame every hatch line is inside [0, 100] x [0, 80].
    let mut segs = Vec::new();
    line_pieces(t.root(), 297.0, &mut segs);
    let (x0, y0) = (55.0, 297.0 - 188.5);
    for s in &segs {
        for q in s {
            let (x, y) = (q[0] - x0, q[1] - y0);
            assert!(
                (-1e-3..=100.001).contains(&x) && (-1e-3..=80.001).contains(&y),
                "{s:?} leaves the tile"
            );
        }
    }
}

/// Each plot flag is read only by the outputs it applies to; given anywhere else it is
/// refused before any work (exit 2, the flag named, an existing file left as it was).
#[test]
fn plot_flags_are_refused_where_nothing_reads_them() {
    let dir = tmp();
    let d = dir.path();
    let cases: &[(&[&str], &str)] = &[
        (&["fill", "--power", "300", "-o", "x.svg"], "--power"),
        (&["fill", "--machine", "grbl-laser", "-o", "x.png"], "--machine"),
        (&["fill", "--order", "greedy", "-o", "x.svg"], "--order"),
        (&["fill", "--hatch", "1", "-o", "x.json"], "--hatch"),
        (&["fill", "--page", "a4", "-o", "x.csv"], "--page"),
        (&["fill", "--hatch", "1", "--style", "filled", "-o", "x.svg"], "--hatch"),
        (&["fill", "--voronoi", "--min-feature", "1", "-o", "x.svg"], "--min-feature"),
        (&["fill", "--layers", "size-bands:2", "-o", "x.gcode"], "--layers"),
        (&["fill", "--margin", "5", "-o", "x.svg"], "--margin"),
        (&["line", "--hatch", "1", "-o", "x.svg"], "--hatch"),
        (&["line", "--page", "a4", "-o", "x.png"], "--page"),
        (&["line", "--passes", "2", "-o", "x.json"], "--passes"),
        (&["line", "--page", "a4", "-o", "x.gcode"], "--page"),
        (&["line", "--render", "dashes", "--hatch", "1", "-o", "x.gcode"], "--hatch"),
        (&["territory", "--points", "300", "--feed", "900", "-o", "x.svg"], "--feed"),
    ];
    for (args, flag) in cases {
        let out = args.last().copied().unwrap_or_default();
        std::fs::write(d.join(out), b"keep").unwrap_or_else(|e| panic!("{e}"));
        let mut a = args.to_vec();
        a.extend_from_slice(&["--count", "20"][..if args[0] == "territory" { 0 } else { 2 }]);
        let o = zf(d, &a);
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        assert!(names_flag(&o.stderr, flag), "{args:?}: {}", o.stderr);
        assert_eq!(read(&d.join(out)), b"keep", "{args:?} touched the file");
    }
    // The same flags where they apply.
    zf_ok(
        d,
        &["fill", "--count", "20", "--hatch", "1", "--min-feature", "0.5", "-o", "ok.svg"],
    );
    zf_ok(d, &["fill", "--count", "20", "--hatch", "1", "-o", "ok.png"]);
    zf_ok(
        d,
        &[
            "line",
            "--count",
            "20",
            "--hatch",
            "1",
            "--power",
            "300",
            "--machine",
            "grbl-laser",
            "-o",
            "ok.gcode",
        ],
    );
}

/// `--layers colours` puts each shape in the Inkscape layer of its palette colour (one pen
/// each), in the palette's order: every path of a layer is stroked in the colour its label
/// names, every layer has shapes, and each shape is in exactly one layer.
#[test]
fn layers_split_shapes_by_colour() {
    let dir = tmp();
    let d = dir.path();
    let palette = ["#264653", "#e9c46a", "#e76f51"];
    for (extra, page) in [
        (&["--region", "rect:150:150"][..], &[][..]),
        (&["--periodic", "--region", "rect:150:150"][..], &["--page", "a4"][..]),
    ] {
        let base = [&["--count", "300", "--seed", "29"][..], extra].concat();
        let doc = fill_json(d, &base);
        let list = palette.join(",");
        let colour = ["--palette", &list, "--color-by", "random", "--layers", "colours"];
        let svg = fill_to(d, "c.svg", &[&base[..], page, &colour].concat());
        let text = String::from_utf8_lossy(&svg).into_owned();
        for (k, c) in palette.iter().enumerate() {
            assert!(
                text.contains(&format!(
                    "id=\"layer{}\" inkscape:groupmode=\"layer\" inkscape:label=\"{} {c}\"",
                    k + 1,
                    k + 1
                )),
                "{extra:?}: layer {c}"
            );
        }
        fn strokes(g: &usvg::Group, out: &mut Vec<String>) {
            for node in g.children() {
                match node {
                    usvg::Node::Group(g) => strokes(g, out),
                    usvg::Node::Path(p) => out.push(match p.stroke().map(|s| s.paint()) {
                        Some(usvg::Paint::Color(c)) => format!("#{:02x}{:02x}{:02x}", c.red, c.green, c.blue),
                        other => format!("{other:?}"),
                    }),
                    _ => {}
                }
            }
        }
        let t = tree(&svg);
        let mut groups = Vec::new();
        layer_groups(t.root(), &mut groups);
        // (layer id, stroke colours of its paths)
        let per_layer: Vec<(String, Vec<String>)> = groups
            .iter()
            .map(|g| {
                let mut v = Vec::new();
                strokes(g, &mut v);
                (g.id().to_string(), v)
            })
            .collect();
        assert_eq!(per_layer.len(), 3, "{extra:?}");
        for (k, (id, colours)) in per_layer.iter().enumerate() {
            assert!(!colours.is_empty(), "{extra:?}: {id} is empty");
            assert!(
                colours.iter().all(|c| c == palette[k]),
                "{extra:?}: {id} holds another pen's shapes"
            );
        }
        let drawn: usize = per_layer.iter().map(|(_, v)| v.len()).sum();
        if extra.contains(&"--periodic") {
            // Edge-crossing shapes are cut into pieces at the tile's edges.
            assert!(drawn > shapes(&doc).len(), "{extra:?}: {drawn} paths");
        } else {
            assert_eq!(drawn, shapes(&doc).len(), "every shape in exactly one layer");
        }
    }
    // Without a palette there is nothing to split by.
    let o = zf(d, &["fill", "--count", "20", "--layers", "colours", "-o", "x.svg"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--layers"), "{}", o.stderr);
    assert!(!d.join("x.svg").exists());
}
