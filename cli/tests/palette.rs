//! Colours (`fill --palette`, `--color-by`, `--background`): the SVG is read back with usvg
//! and every drawn shape's paint is compared with the colour its rule gives, worked out here
//! from the JSON of the same run (size bands of equal width in log(area), SplitMix64 of the
//! seed and index, or the index in turn); the PNG preview shows the colours; bad colours and
//! colours where no picture is drawn are refused. Territories take colours by territory (in
//! turn or at random) or by the size of their cells.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use serde_json::Value;

const PALETTE: [&str; 4] = ["#264653", "#2a9d8f", "#e9c46a", "#e76f51"];

/// The palette index rule `by` gives item `i` of size `size`, the sizes ranging over
/// `[min, max]` (as the README states the rules).
fn pick(by: &str, seed: u64, i: u64, size: f64, (max, min): (f64, f64)) -> usize {
    let k = PALETTE.len();
    match by {
        "size" => {
            let t = (max / size).ln() / (max / min).ln();
            ((t * k as f64).floor() as usize).min(k - 1)
        }
        "random" => (splitmix64(seed ^ splitmix64(i)) % k as u64) as usize,
        "cycle" => i as usize % k,
        other => panic!("rule {other}"),
    }
}

/// The colour each item of `doc` should have under rule `by`, its size being `key` (a
/// fill's shapes by area, a line's segments by length).
fn expected_by(doc: &Value, by: &str, key: &str) -> Vec<&'static str> {
    let list = shapes(doc);
    let sizes: Vec<f64> = list.iter().map(|s| f(s, key)).collect();
    let range = sizes.iter().fold((0.0f64, f64::MAX), |(a, b), &x| (a.max(x), b.min(x)));
    let seed = u(&doc["params"], "seed");
    list.iter()
        .zip(&sizes)
        .map(|(s, &a)| PALETTE[pick(by, seed, u(s, "index"), a, range)])
        .collect()
}

/// The colour each shape of a fill should have under rule `by`.
fn expected(doc: &Value, by: &str) -> Vec<&'static str> {
    expected_by(doc, by, "area")
}

/// Whether every path has its shape's colour: path k is shape k (one path per shape).
fn check(paths: &[Painted], want: &[&str]) -> Result<(), String> {
    if paths.len() != want.len() {
        return Err(format!("{} paths for {} shapes", paths.len(), want.len()));
    }
    for (k, (p, w)) in paths.iter().zip(want).enumerate() {
        let got = &p.colour;
        if got != w {
            return Err(format!("shape {k} is painted {got}, expected {w}"));
        }
    }
    Ok(())
}

#[test]
fn shapes_take_the_colour_of_their_rule() {
    let dir = tmp();
    let list = PALETTE.join(",");
    for (by, style, shape) in [
        ("size", "filled", "circle"),
        ("random", "filled", "star:5:0.45"),
        ("cycle", "outline", "square"),
        ("random", "outline", "ring:0.5"),
    ] {
        let args = [
            "--shape",
            shape,
            "--c",
            "1.25",
            "--n-offset",
            "2",
            "--count",
            "150",
            "--seed",
            "9",
            "-q",
        ];
        let mut a = args.to_vec();
        a.extend_from_slice(&["--style", style, "--palette", &list, "--color-by", by]);
        let svg = fill_to(dir.path(), "c.svg", &a);
        let doc = fill_json(dir.path(), &args);
        let want = expected(&doc, by);
        check(&painted(&svg, style == "outline"), &want).unwrap_or_else(|e| panic!("{by} {style} {shape}: {e}"));
        // Every colour is used, and the checker sees a wrong assignment.
        for c in PALETTE {
            assert!(want.contains(&c), "{by}: {c} unused among {} shapes", want.len());
        }
        let mut rotated = want.clone();
        rotated.rotate_left(1);
        assert!(
            check(&painted(&svg, style == "outline"), &rotated).is_err(),
            "{by}: a wrong colouring must be caught"
        );
    }
}

#[test]
fn size_is_the_default_rule_and_the_largest_band_takes_the_first_colour() {
    let dir = tmp();
    let args = ["--count", "300", "-q"];
    let mut a = args.to_vec();
    a.extend_from_slice(&["--style", "filled", "--palette", "264653,2A9D8F,e9c46a,#e76f51"]);
    let svg = fill_to(dir.path(), "d.svg", &a);
    let doc = fill_json(dir.path(), &args);
    let want = expected(&doc, "size");
    check(&painted(&svg, false), &want).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(want[0], PALETTE[0]);
    assert_eq!(*want.last().unwrap_or(&""), PALETTE[3], "the smallest shapes take the last colour");
}

#[test]
fn periodic_images_share_their_shape_colour_and_the_background_is_behind() {
    let dir = tmp();
    let args = ["--count", "200", "--periodic", "--seed", "5", "-q"];
    let mut a = args.to_vec();
    let list = PALETTE.join(",");
    a.extend_from_slice(&[
        "--style",
        "filled",
        "--palette",
        &list,
        "--color-by",
        "cycle",
        "--background",
        "fefae0",
    ]);
    let svg = fill_to(dir.path(), "p.svg", &a);
    let doc = fill_json(dir.path(), &args);
    let want = expected(&doc, "cycle");
    let paths = painted(&svg, false);
    // The background first, the size of the tile.
    let Painted { centre, colour, .. } = &paths[0];
    assert_eq!(colour, "#fefae0");
    assert!((centre[0] - 100.0).abs() < 1e-3 && (centre[1] - 100.0).abs() < 1e-3, "{centre:?}");
    // Every other path is a shape or one of its images, cut to the tile: it is found by a
    // point inside it (its box's centre: a disc, or a disc cut by the tile's edges), modulo
    // the period, and has the shape's colour.
    let discs: Vec<([f64; 2], f64)> = shapes(&doc).iter().map(|s| (pt(&s["center"]), f(s, "radius"))).collect();
    assert!(paths.len() > discs.len() + 1, "edge-crossing shapes have images");
    for Painted { centre: c, colour, .. } in &paths[1..] {
        // SVG y runs down from the top.
        let (x, y) = (c[0].rem_euclid(200.0), (200.0 - c[1]).rem_euclid(200.0));
        let k = discs
            .iter()
            .position(|(s, r)| {
                let dx = (s[0] - x).abs();
                let dy = (s[1] - y).abs();
                dx.min(200.0 - dx).hypot(dy.min(200.0 - dy)) < *r
            })
            .unwrap_or_else(|| panic!("a path at {c:?} is no shape's"));
        assert_eq!(colour, want[k], "shape {k} or its image");
    }
}

#[test]
fn the_png_preview_shows_the_colours() {
    let dir = tmp();
    let args = ["--count", "100", "-q"];
    let mut a = args.to_vec();
    a.extend_from_slice(&[
        "--style",
        "filled",
        "--palette",
        "ff0000,00ff00",
        "--color-by",
        "cycle",
        "--background",
        "0000ff",
        "--pixels",
        "200",
    ]);
    let png = fill_to(dir.path(), "c.png", &a);
    let doc = fill_json(dir.path(), &args);
    let mut reader = png::Decoder::new(&png[..]).read_info().unwrap_or_else(|e| panic!("{e}"));
    let mut buf = vec![0u8; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(frame.color_type, png::ColorType::Rgba);
    let rgb = |x: f64, y: f64| {
        let (i, j) = (x as usize, (200.0 - y) as usize);
        let at = 4 * (j * frame.width as usize + i);
        [buf[at], buf[at + 1], buf[at + 2]]
    };
    // 1 pixel per mm: the centres of the first two circles, then a corner of the gasket.
    let c0 = pt(&shapes(&doc)[0]["center"]);
    let c1 = pt(&shapes(&doc)[1]["center"]);
    assert_eq!(rgb(c0[0], c0[1]), [255, 0, 0], "shape 0 takes the first colour");
    assert_eq!(rgb(c1[0], c1[1]), [0, 255, 0], "shape 1 the second");
    let corner = (0..200)
        .flat_map(|j| (0..200).map(move |i| (i, j)))
        .find(|&(i, j)| {
            let p = [f64::from(i) + 0.5, 199.5 - f64::from(j)];
            shapes(&doc).iter().all(|s| {
                let c = pt(&s["center"]);
                (c[0] - p[0]).hypot(c[1] - p[1]) > f(s, "radius") + 1.5
            })
        })
        .unwrap_or_else(|| panic!("no pixel of gasket"));
    assert_eq!(
        rgb(f64::from(corner.0) + 0.5, 199.5 - f64::from(corner.1)),
        [0, 0, 255],
        "the gasket shows the background"
    );
}

#[test]
fn bad_colours_and_colours_without_a_picture_are_refused() {
    let many = vec!["000"; 65].join(",");
    let cases: [(&[&str], &str); 9] = [
        (&["--palette", "red", "-o", "keep.svg"], "--palette"),
        (&["--palette", "12", "-o", "keep.svg"], "--palette"),
        (&["--palette", "000,,fff", "-o", "keep.svg"], "--palette"),
        (&["--palette", &many, "-o", "keep.svg"], "--palette"),
        (&["--background", "#12345g", "-o", "keep.svg"], "--background"),
        (&["--color-by", "random", "-o", "keep.svg"], "--palette"),
        (&["--palette", "000", "--format", "json", "-o", "keep.svg"], "--palette"),
        (&["--palette", "000", "--voronoi", "-o", "keep.svg"], "--palette"),
        (
            &["--background", "000", "--relief", "dome", "--format", "png", "-o", "keep.svg"],
            "--background",
        ),
    ];
    assert_fill_refuses("keep.svg", &cases);
}

#[test]
fn kind_colours_each_entry_of_a_mix() {
    let dir = tmp();
    let kinds = ["circle", "triangle", "ring"];
    let args = [
        "--shape",
        "mix:circle,triangle,ring:0.5",
        "--mix-order",
        "random",
        "--c",
        "1.25",
        "--n-offset",
        "2",
        "--count",
        "200",
        "-q",
    ];
    let mut a = args.to_vec();
    let list = PALETTE.join(",");
    a.extend_from_slice(&["--style", "filled", "--palette", &list, "--color-by", "kind"]);
    let svg = fill_to(dir.path(), "k.svg", &a);
    let doc = fill_json(dir.path(), &args);
    // Each shape's kind, as the JSON names it, picks its entry's colour.
    let want: Vec<&str> = shapes(&doc)
        .iter()
        .map(|sh| {
            let k = s(sh, "kind");
            PALETTE[kinds.iter().position(|n| *n == k).unwrap_or_else(|| panic!("kind {k}"))]
        })
        .collect();
    check(&painted(&svg, false), &want).unwrap_or_else(|e| panic!("{e}"));
    assert!(want.iter().any(|c| *c == PALETTE[2]) && want.iter().any(|c| *c == PALETTE[1]));
    // Cycling the colours instead would not match a random mix.
    assert!(check(&painted(&svg, false), &expected(&doc, "cycle")).is_err());
}

/// A 1D fill's segments take the colours of their rule: each drawn piece (a bar, a dash, a
/// circle, a periodic segment's two pieces or its circle's image) is found by its middle
/// among the segments of the JSON.
#[test]
fn line_segments_take_the_colour_of_their_rule() {
    let dir = tmp();
    let d = dir.path();
    let list = PALETTE.join(",");
    for (render, style, by, periodic) in [
        ("bars", "outline", "size", false),
        ("dashes", "outline", "cycle", true),
        ("circles", "outline", "random", true),
        ("circles", "filled", "size", false),
    ] {
        let mut args = vec!["line", "--count", "200", "--seed", "4", "--length", "150"];
        if periodic {
            args.push("--periodic");
        }
        zf_ok(d, &[&args[..], &["-o", "l.json"]].concat());
        let doc = parse_json(&read(&d.join("l.json")));
        let colour = format!("--render {render} --style {style} --palette {list} --color-by {by} --background fefae0");
        zf_ok(d, &[&args[..], &words(&colour), &["-o", "l.svg"]].concat());
        let svg = read(&d.join("l.svg"));
        assert_eq!(painted(&svg, false)[0].colour, "#fefae0", "{render}: the background comes first");
        let stroke = render == "dashes" || style == "outline" && render == "circles";
        let pieces = painted(&svg, stroke).split_off(1);
        let want = expected_by(&doc, by, "length");
        let segs: Vec<(f64, f64)> = shapes(&doc).iter().map(|s| (f(s, "start"), f(s, "length"))).collect();
        let faults = |shift: usize| {
            let mut bad = Vec::new();
            for p in &pieces {
                let x = p.centre[0].rem_euclid(150.0);
                let k = segs.iter().position(|&(a, len)| (x - a).rem_euclid(150.0) < len);
                match k {
                    Some(k) if p.colour == PALETTE[(PALETTE.iter().position(|c| *c == want[k]).unwrap_or(0) + shift) % PALETTE.len()] => {}
                    Some(k) => bad.push(format!("segment {k} at {x}: {}", p.colour)),
                    None => bad.push(format!("a piece at {x} lies on no segment")),
                }
            }
            bad
        };
        assert!(pieces.len() >= 150, "{render}: {} pieces", pieces.len());
        let bad = faults(0);
        assert!(bad.is_empty(), "{render} {by}: {} wrong, first {:?}", bad.len(), bad.first());
        assert_eq!(faults(1).len(), pieces.len(), "{render}: the check misses colours shifted by one");
    }
}

#[test]
fn line_colours_are_refused_where_nothing_shows_them() {
    let dir = tmp();
    let d = dir.path();
    std::fs::write(d.join("keep.json"), b"precious").unwrap_or_else(|e| panic!("{e}"));
    for (args, flag) in [
        (&["--palette", "000,fff"][..], "--palette"),
        (&["--background", "fff"][..], "--background"),
        (&["--palette", "000", "--color-by", "kind", "--format", "svg"][..], "--color-by"),
    ] {
        let o = zf(d, &[&["line", "--count", "20"][..], args, &["-o", "keep.json"]].concat());
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        assert!(names_flag(&o.stderr, flag), "{args:?}: {}", o.stderr);
        assert_eq!(read(&d.join("keep.json")), b"precious", "{args:?} touched the file");
    }
}

/// Filled cobblestones (`--voronoi --style filled`) take their shapes' colours: every cell,
/// those of the periodic copies that fill in what wraps around included, is found as the
/// cell of the nearest centre (or copy) to a point inside it.
#[test]
fn cobblestone_cells_take_their_shapes_colour() {
    let dir = tmp();
    let d = dir.path();
    let list = PALETTE.join(",");
    for (region, periodic, by) in [("rect:120:120", true, "random"), ("circle:60", false, "size")] {
        let mut args = vec![
            "--count",
            "300",
            "--c",
            "1.2",
            "--n-offset",
            "2",
            "--seed",
            "4",
            "--region",
            region,
            "-q",
        ];
        if periodic {
            args.push("--periodic");
        }
        let doc = fill_json(d, &args);
        let colour = format!("--voronoi --style filled --palette {list} --color-by {by} --background fefae0");
        let svg = fill_to(d, "v.svg", &[&args[..], &words(&colour)].concat());
        let paths = painted(&svg, false);
        assert_eq!(paths[0].colour, "#fefae0", "{region}: the background first");
        let cells: Vec<&Painted> = paths[1..].iter().filter(|p| p.colour.starts_with('#')).collect();
        let want = expected(&doc, by);
        let centres: Vec<[f64; 2]> = shapes(&doc).iter().map(|s| pt(&s["center"])).collect();
        let shifts = period_shifts(periodic, 120.0, 120.0);
        let owner = |q: [f64; 2]| {
            let dist = |c: &[f64; 2]| {
                shifts
                    .iter()
                    .map(|(dx, dy)| (q[0] - c[0] - dx).hypot(q[1] - c[1] - dy))
                    .fold(f64::INFINITY, f64::min)
            };
            (0..centres.len())
                .min_by(|&a, &b| dist(&centres[a]).total_cmp(&dist(&centres[b])))
                .unwrap_or(0)
        };
        let faults = |shift: usize| {
            cells
                .iter()
                .filter(|p| {
                    let k = owner([p.inside[0], 120.0 - p.inside[1]]);
                    let i = PALETTE.iter().position(|c| *c == want[k]).unwrap_or(0);
                    p.colour != PALETTE[(i + shift) % PALETTE.len()]
                })
                .count()
        };
        assert!(
            cells.len() >= centres.len(),
            "{region}: {} cells for {} shapes",
            cells.len(),
            centres.len()
        );
        assert_eq!(faults(0), 0, "{region} {by}: cells in the wrong colour");
        assert_eq!(faults(1), cells.len(), "{region}: the check misses colours shifted by one");
    }
    // Outlines are shared edges: they cannot take a cell's colour.
    let o = zf(d, &["fill", "--count", "50", "--voronoi", "--palette", "000,fff", "-o", "o.svg"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--palette"), "{}", o.stderr);
}

/// `line --layers colours`: the segments in one Inkscape layer per palette colour, in its
/// order: read back in document order, the colours never go back to an earlier pen.
#[test]
fn line_layers_hold_one_colour_each() {
    let dir = tmp();
    let d = dir.path();
    let list = PALETTE.join(",");
    let args = [
        "line",
        "--count",
        "200",
        "--render",
        "circles",
        "--palette",
        &list,
        "--color-by",
        "random",
        "--layers",
        "colours",
    ];
    zf_ok(d, &[&args[..], &["-o", "l.svg"]].concat());
    let pens = assert_pens_in_layers(&read(&d.join("l.svg")), &PALETTE);
    assert!(pens.len() >= 190, "{} circles", pens.len());
}

/// A territory run's seed and sites (point, territory), from its JSON.
fn territory_sites(dir: &std::path::Path, args: &str) -> (u64, Vec<([f64; 2], u64)>) {
    zf_ok(dir, &words(&format!("{args} -o t.json")));
    let doc = parse_json(&read(&dir.join("t.json")));
    let sites = doc["sites"].as_array().cloned().unwrap_or_default();
    let list = sites.iter().map(|s| (pt(&s["point"]), u(s, "territory"))).collect();
    (u(&doc["params"], "seed"), list)
}

/// The pixels of a 400 x 400 PNG of the 200 x 200 mm region: the colour at a point in mm.
fn png_sampler(png: &[u8]) -> impl Fn([f64; 2]) -> String {
    let mut reader = png::Decoder::new(png).read_info().unwrap_or_else(|e| panic!("{e}"));
    let mut buf = vec![0u8; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((frame.width, frame.height), (400, 400));
    move |p: [f64; 2]| {
        let (i, j) = ((p[0] * 2.0) as usize, ((200.0 - p[1]) * 2.0) as usize);
        let at = 4 * (j * 400 + i);
        format!("#{:02x}{:02x}{:02x}", buf[at], buf[at + 1], buf[at + 2])
    }
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The sites whose pixel lies well inside their cell: a millimetre from the nearest
/// bisector and from the region's edge.
fn clear_sites(sites: &[([f64; 2], u64)]) -> Vec<usize> {
    (0..sites.len())
        .filter(|&i| {
            let p = sites[i].0;
            let near = sites
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != i)
                .map(|(_, s)| dist(s.0, p))
                .fold(f64::MAX, f64::min);
            near / 2.0 > 1.0 && p.iter().all(|&v| (1.0..199.0).contains(&v))
        })
        .collect()
}

/// The area of site `i`'s Voronoi cell in the 200 x 200 square, by brute force: the square
/// cut by the bisector with every other site.
fn cell_area(sites: &[([f64; 2], u64)], i: usize) -> f64 {
    let s = sites[i].0;
    let mut poly = vec![[0.0, 0.0], [200.0, 0.0], [200.0, 200.0], [0.0, 200.0]];
    for o in sites.iter().enumerate().filter(|&(j, _)| j != i).map(|(_, o)| o.0) {
        // Keep the side nearer s: (x - m) . (o - s) <= 0.
        let m = [(s[0] + o[0]) / 2.0, (s[1] + o[1]) / 2.0];
        let side = |p: [f64; 2]| (p[0] - m[0]) * (o[0] - s[0]) + (p[1] - m[1]) * (o[1] - s[1]);
        let mut out = Vec::new();
        for k in 0..poly.len() {
            let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
            let (fa, fb) = (side(a), side(b));
            if fa <= 0.0 {
                out.push(a);
            }
            if (fa < 0.0) != (fb < 0.0) && fa != fb {
                let t = fa / (fa - fb);
                out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
            }
        }
        poly = out;
    }
    shoelace(&poly)
}

#[test]
fn territory_cells_and_shapes_take_their_territorys_colour() {
    let dir = tmp();
    let d = dir.path();
    let palette = PALETTE.map(|c| c.trim_start_matches('#')).join(",");
    let base = "territory --sites 6 --points 900 --seed 4 --render filled";
    let (seed, sites) = territory_sites(d, base);
    let clear = clear_sites(&sites);
    assert!(clear.len() > 600, "only {} sites to look at", clear.len());
    for by in ["cycle", "random"] {
        let args = format!("{base} --palette {palette} --color-by {by} --background 000");
        zf_ok(d, &words(&format!("{args} --pixels 400 -o t.png")));
        let at = png_sampler(&read(&d.join("t.png")));
        for &i in &clear {
            let want = PALETTE[pick(by, seed, sites[i].1, 1.0, (1.0, 1.0))];
            assert_eq!(at(sites[i].0), want, "--color-by {by}: site {i} of territory {}", sites[i].1);
        }
        // The SVG: the background, then one path per colour used.
        zf_ok(d, &words(&format!("{args} -o t.svg")));
        let svg = read(&d.join("t.svg"));
        let paths = painted(&svg, false);
        assert_eq!(
            paths.first().map(|p| p.colour.as_str()),
            Some("#000000"),
            "{by}: no background first"
        );
        let colours: std::collections::BTreeSet<&str> = paths[1..].iter().map(|p| p.colour.as_str()).collect();
        assert_eq!(colours.len(), paths.len() - 1, "{by}: a colour drawn twice");
        assert!(colours.iter().all(|c| PALETTE.contains(c)), "{by}: {colours:?}");
        if by == "cycle" {
            // Cycle is the default for territories: the same picture without the flag.
            zf_ok(d, &words(&format!("{base} --palette {palette} --background 000 -o u.svg")));
            assert_eq!(read(&d.join("u.svg")), svg, "cycle is not the default");
        }
    }
    // By size: of two cells, the larger never takes a later colour (cells within 1% of each
    // other may fall either side of a band's edge).
    zf_ok(
        d,
        &words(&format!("{base} --palette {palette} --color-by size --pixels 400 -o s.png")),
    );
    let at = png_sampler(&read(&d.join("s.png")));
    let band = |i: usize| PALETTE.iter().position(|c| *c == at(sites[i].0)).unwrap_or(usize::MAX);
    let cells: Vec<(f64, usize)> = clear.iter().map(|&i| (cell_area(&sites, i), band(i))).collect();
    for a in &cells {
        for b in cells.iter().filter(|b| b.0 * 1.01 < a.0) {
            assert!(a.1 <= b.1, "a cell of {} mm² after one of {} mm²", a.0, b.0);
        }
    }
    let used: std::collections::BTreeSet<usize> = cells.iter().map(|c| c.1).collect();
    assert!(used.contains(&0) && used.len() >= 2, "bands used: {used:?}");
    // A fill's own shapes, each in its site's territory colour.
    zf_ok(d, &words("fill --count 300 --seed 2 -o f.json"));
    let from = "territory --sites-from f.json --sites 3 --seed 5 --render shapes";
    let (seed, sites) = territory_sites(d, from);
    zf_ok(d, &words(&format!("{from} --palette {palette} --color-by random -o f.svg")));
    let want: Vec<&str> = sites
        .iter()
        .map(|&(_, t)| PALETTE[pick("random", seed, t, 1.0, (1.0, 1.0))])
        .collect();
    if let Err(e) = check(&painted(&read(&d.join("f.svg")), false), &want) {
        panic!("shapes: {e}");
    }
}

#[test]
fn territory_colours_are_refused_where_nothing_shows_them() {
    let dir = tmp();
    let d = dir.path();
    let cases = [
        ("territory --render boundaries --palette 000 -o k.svg", "--palette"),
        ("territory --render filled --palette 000 -o k.json", "--palette"),
        ("territory --render cells --background fff -o k.svg", "--background"),
        ("territory --render filled --palette 000 --color 0.5,0.5,0.5 -o k.svg", "--palette"),
        ("territory --render filled --palette 000 --color-by kind -o k.svg", "--color-by"),
    ];
    for (args, flag) in cases {
        let o = zf(d, &words(args));
        assert_eq!(o.code, 2, "{args}: exit {}", o.code);
        assert!(names_flag(&o.stderr, flag), "{args}: {}", o.stderr);
        assert!(listing(d).is_empty(), "{args} wrote {:?}", listing(d));
    }
}

/// A territory in flat palette colours shows no seams: rendered, the pixel on the edge
/// between two cells of one territory is that territory's colour exactly, not mixed with the
/// background (each colour is drawn as one path, so anti-aliasing leaves no gap between its
/// cells).
#[test]
fn flat_territories_have_no_seams_between_their_cells() {
    let dir = tmp();
    let d = dir.path();
    let base = "territory --sites 4 --points 600 --seed 7 --render filled";
    let (_, sites) = territory_sites(d, base);
    let palette = ["#ff0000", "#00ff00", "#0000ff", "#ffff00"];
    zf_ok(
        d,
        &words(&format!("{base} --palette f00,0f0,00f,ff0 --background 000 --pixels 400 -o t.png")),
    );
    let at = png_sampler(&read(&d.join("t.png")));
    let mut edges = 0;
    for (i, &(a, ta)) in sites.iter().enumerate() {
        for &(b, tb) in &sites[i + 1..] {
            let m = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
            let r = dist(a, m);
            // On the edge of the two cells, a millimetre from any other cell and the border.
            let clear =
                sites.iter().all(|&(c, _)| c == a || c == b || dist(c, m) > r + 1.0) && m.iter().all(|&v| (1.0..199.0).contains(&v));
            if ta != tb || !clear {
                continue;
            }
            edges += 1;
            assert_eq!(at(m), palette[ta as usize % 4], "a seam between the cells at {a:?} and {b:?}");
        }
    }
    assert!(edges > 100, "only {edges} edges checked");
}
