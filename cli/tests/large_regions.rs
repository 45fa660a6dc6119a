//! Regression tests for "region checks are quadratic": a polygon region was checked by testing
//! every pair of edges and each ring against every other, and each trial of a fill visited
//! every edge, so an SVG of 3,600 small squares took over 150 s to check and an outline of
//! 10^5 vertices 92 s, before any fill. Both are now checked and filled in well under a
//! second each (the figures are in docs/performance.md; a test asserts no time, but a
//! quadratic check would hold these up for minutes).
//!
//! The outline of 10^5 vertices comes as an SVG `<polygon>`: as `--region polygon:X,Y,...` it
//! would exceed the longest single argument the operating system passes (128 KiB on Linux).
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;
use common::*;
use serde_json::Value;

/// A point of the JSON.
fn pts(v: &Value) -> Vec<[f64; 2]> {
    v.as_array().map(|a| a.iter().map(pt).collect()).unwrap_or_default()
}

/// Whether `p` is inside the ring (even-odd) and its distance to the ring's edges.
fn inside_and_dist(p: [f64; 2], ring: &[[f64; 2]]) -> (bool, f64) {
    let (mut inside, mut d) = (false, f64::INFINITY);
    for (k, &a) in ring.iter().enumerate() {
        let b = ring[(k + 1) % ring.len()];
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) {
            inside = !inside;
        }
        d = d.min(seg_dist(p, a, b));
    }
    (inside, d)
}

/// No two circles come nearer than `gap` (the shared checker reads a rectangle's size).
fn assert_apart(cs: &[([f64; 2], f64)], gap: f64) {
    for (i, &(a, ra)) in cs.iter().enumerate() {
        for (j, &(b, rb)) in cs.iter().enumerate().skip(i + 1) {
            let d = (a[0] - b[0]).hypot(a[1] - b[1]) - ra - rb;
            assert!(d >= gap - 1e-9, "circles {i} and {j} are {d} mm apart");
        }
    }
}

/// The fill's circles: centre and radius.
fn circles(doc: &Value) -> Vec<([f64; 2], f64)> {
    shapes(doc)
        .iter()
        .map(|sh| {
            assert_eq!(s(sh, "kind"), "circle");
            (pt(&sh["center"]), f(sh, "radius"))
        })
        .collect()
}

#[test]
fn an_svg_of_3600_small_squares_is_checked_and_filled() {
    let dir = tmp();
    // 60 x 60 squares of 2 mm at a pitch of 3 mm: 3,600 islands.
    let mut svg = String::from(r#"<svg xmlns="http://www.w3.org/2000/svg" width="180mm" height="180mm" viewBox="0 0 180 180">"#);
    for i in 0..3600 {
        svg.push_str(&format!(
            r#"<rect x="{}" y="{}" width="2" height="2"/>"#,
            3 * (i % 60),
            3 * (i / 60)
        ));
    }
    svg.push_str("</svg>");
    std::fs::write(dir.path().join("squares.svg"), svg).unwrap_or_else(|e| panic!("{e}"));
    // The first circle must fit a 2 mm square: N large enough for an area of at most pi.
    let doc = fill_json(
        dir.path(),
        &[
            "--region",
            "svg:squares.svg",
            "--n-offset",
            "6000",
            "--count",
            "50",
            "--gap",
            "0.05",
        ],
    );
    let region = &doc["region"];
    assert_eq!(s(region, "kind"), "polygon");
    assert_eq!(region["outers"].as_array().map(Vec::len), Some(3599), "3,600 islands");
    assert_eq!(region["holes"].as_array().map(Vec::len), Some(0));
    assert!((f(&doc, "area") - 3600.0 * 4.0).abs() < 1e-6, "area {}", f(&doc, "area"));
    let cs = circles(&doc);
    assert_eq!(cs.len(), 50);
    // Each circle lies in one square, the gap from its edges. The SVG's y runs down: the
    // squares span x in [3i, 3i + 2] and y in [3j + 1, 3j + 3].
    for (i, &(c, r)) in cs.iter().enumerate() {
        let (x0, y0) = (3.0 * (c[0] / 3.0).floor(), 3.0 * ((c[1] - 1.0) / 3.0).floor() + 1.0);
        let room = (c[0] - x0).min(x0 + 2.0 - c[0]).min(c[1] - y0).min(y0 + 2.0 - c[1]);
        assert!(room >= r + 0.05 - 1e-9, "circle {i} at {c:?} (r {r}) leaves its square");
    }
    assert_apart(&cs, 0.05);
}

#[test]
fn an_outline_of_100000_vertices_is_checked_and_filled() {
    let dir = tmp();
    // A wavy star-shaped outline about (100, 100), radius 60 to 100 mm.
    let n = 100_000;
    let points: Vec<String> = (0..n)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / n as f64;
            let r = 80.0 + 20.0 * (7.0 * t).sin();
            format!("{:.4},{:.4}", 100.0 + r * t.cos(), 100.0 + r * t.sin())
        })
        .collect();
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="200mm" viewBox="0 0 200 200"><polygon points="{}"/></svg>"#,
        points.join(" ")
    );
    std::fs::write(dir.path().join("outline.svg"), svg).unwrap_or_else(|e| panic!("{e}"));
    for sampler in ["fast", "reference"] {
        let args = [
            "--region",
            "svg:outline.svg",
            "--c",
            "1.25",
            "--n-offset",
            "3",
            "--count",
            "50",
            "--gap",
            "0.2",
            "--sampler",
            sampler,
        ];
        let doc = fill_json(dir.path(), &args);
        let ring = pts(&doc["region"]["vertices"]);
        assert_eq!(ring.len(), n, "{sampler}: every vertex kept");
        let cs = circles(&doc);
        assert_eq!(cs.len(), 50, "{sampler}");
        // Each circle inside the outline, the gap from every edge (checked against all 10^5).
        for (i, &(c, r)) in cs.iter().enumerate() {
            let (inside, d) = inside_and_dist(c, &ring);
            assert!(
                inside && d >= r + 0.2 - 1e-9,
                "{sampler}: circle {i} at {c:?} (r {r}) is {d} mm from the outline"
            );
        }
        assert_apart(&cs, 0.2);
    }
}
