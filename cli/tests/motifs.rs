//! `--shape svg:FILE` and `--shape glyph:TEXT`: motifs filled end to end, their outlines
//! checked for overlaps with an independent polygon library (geo), their areas against the
//! power law, their decorations drawn, and bad motifs refused with exit 2 and nothing written.

// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{zf, zf_json, zf_ok};
use geo::{Area, Contains, Intersects};
use serde_json::Value;
use std::path::Path;

/// A heart of four cubic curves, 90 mm across.
const HEART: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">
  <path fill="black" d="M50,88 C20,65 5,45 5,28 C5,14 16,5 28,5 C38,5 46,11 50,20 C54,11 62,5 72,5 C84,5 95,14 95,28 C95,45 80,65 50,88 Z"/>
</svg>"#;

/// A heart with a heart-shaped hole, drawn as one path by the nonzero rule (the inner ring
/// runs the other way round, so it is a hole under either rule).
const RING_HEART: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">
  <path fill="black" d="M50,88 C20,65 5,45 5,28 C5,14 16,5 28,5 C38,5 46,11 50,20 C54,11 62,5 72,5 C84,5 95,14 95,28 C95,45 80,65 50,88 Z M50,70 C70,55 78,42 78,32 C78,25 73,21 68,21 C61,21 55,27 50,36 C45,27 39,21 32,21 C27,21 22,25 22,32 C22,42 30,55 50,70 Z"/>
</svg>"#;

/// A butterfly: two wings as the motif, and antennas in an Inkscape layer named
/// `Decoration` (drawn, never tested).
const BUTTERFLY: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" width="60mm" height="50mm" viewBox="0 0 60 50">
  <g id="wings"><path fill="black" d="M30,15 C10,0 0,10 5,25 C0,40 10,50 30,35 C50,50 60,40 55,25 C60,10 50,0 30,15 Z"/></g>
  <g id="layer2" inkscape:label="Decoration"><path fill="none" stroke="black" d="M30,15 C28,8 24,4 20,2 M30,15 C32,8 36,4 40,2"/></g>
</svg>"#;

fn write(dir: &Path, name: &str, text: &str) -> String {
    std::fs::write(dir.join(name), text).unwrap_or_else(|e| panic!("{e}"));
    name.to_string()
}

fn tmp() -> tempfile::TempDir {
    tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"))
}

/// A placed motif as read from the JSON: its rings.
type Rings = Vec<Vec<[f64; 2]>>;

fn rings_of(sh: &Value) -> Rings {
    let rings = sh["outlines"]
        .as_array()
        .unwrap_or_else(|| panic!("a motif without outlines: {sh}"));
    rings
        .iter()
        .map(|r| {
            r.as_array()
                .into_iter()
                .flatten()
                .map(|p| [p[0].as_f64().unwrap_or(f64::NAN), p[1].as_f64().unwrap_or(f64::NAN)])
                .collect()
        })
        .collect()
}

fn ring_poly(r: &[[f64; 2]]) -> geo::Polygon<f64> {
    geo::Polygon::new(
        r.iter().map(|p| geo::coord! { x: p[0], y: p[1] }).collect::<Vec<_>>().into(),
        vec![],
    )
}

/// The even-odd area of a motif's rings.
fn area(rings: &Rings) -> f64 {
    let polys: Vec<_> = rings.iter().map(|r| ring_poly(r)).collect();
    polys
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let depth = polys
                .iter()
                .enumerate()
                .filter(|&(j, q)| j != i && q.contains(&p.exterior().0[0]))
                .count();
            if depth % 2 == 0 {
                p.unsigned_area()
            } else {
                -p.unsigned_area()
            }
        })
        .sum()
}

/// Whether a point lies in a motif's material (inside an odd number of its rings).
fn in_material(rings: &Rings, q: geo::Coord<f64>) -> bool {
    rings.iter().filter(|r| ring_poly(r).contains(&q)).count() % 2 == 1
}

fn bbox(rings: &Rings) -> [f64; 4] {
    rings.iter().flatten().fold([f64::MAX, f64::MAX, f64::MIN, f64::MIN], |b, p| {
        [b[0].min(p[0]), b[1].min(p[1]), b[2].max(p[0]), b[3].max(p[1])]
    })
}

/// The pairs of motifs that overlap: an edge of one meets an edge of the other, or a ring of
/// one starts in the other's material. Written with geo's segment and polygon tests, apart
/// from the core's.
fn overlaps(all: &[Rings]) -> Vec<(usize, usize)> {
    let boxes: Vec<[f64; 4]> = all.iter().map(bbox).collect();
    let lines = |rings: &Rings| -> Vec<geo::Line<f64>> {
        rings
            .iter()
            .flat_map(|r| {
                (0..r.len()).map(move |k| {
                    geo::Line::new(
                        geo::coord! { x: r[k][0], y: r[k][1] },
                        geo::coord! { x: r[(k + 1) % r.len()][0], y: r[(k + 1) % r.len()][1] },
                    )
                })
            })
            .collect()
    };
    let mut bad = Vec::new();
    for i in 0..all.len() {
        for j in i + 1..all.len() {
            let (a, b) = (boxes[i], boxes[j]);
            if a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1] {
                continue;
            }
            let (la, lb) = (lines(&all[i]), lines(&all[j]));
            let cross = la.iter().any(|e| lb.iter().any(|f| e.intersects(f)));
            let start = |x: &Rings, y: &Rings| x.iter().any(|r| in_material(y, geo::coord! { x: r[0][0], y: r[0][1] }));
            if cross || start(&all[i], &all[j]) || start(&all[j], &all[i]) {
                bad.push((i, j));
            }
        }
    }
    bad
}

fn shapes(doc: &Value) -> Vec<Value> {
    doc["shapes"].as_array().cloned().unwrap_or_default()
}

/// `zetafill fill --shape SHAPE EXTRA... -o - --format FORMAT -q`, run in `dir`.
fn fill_args<'a>(shape: &'a str, extra: &[&'a str], format: &'a str) -> Vec<&'a str> {
    let mut args = vec!["fill", "--shape", shape];
    args.extend_from_slice(extra);
    args.extend(["-o", "-", "--format", format, "-q"]);
    args
}

/// The JSON document of a fill of SHAPE.
fn fill_json(dir: &Path, shape: &str, extra: &[&str]) -> Value {
    zf_json(dir, &fill_args(shape, extra, "json"))
}

/// The SVG bytes of a fill of SHAPE.
fn fill_svg(dir: &Path, shape: &str, extra: &[&str]) -> Vec<u8> {
    zf_ok(dir, &fill_args(shape, extra, "svg")).stdout
}

#[test]
fn svg_motifs_fill_without_overlap_at_their_areas_and_inside_the_region() {
    let dir = tmp();
    let heart = write(dir.path(), "heart.svg", HEART);
    let doc = fill_json(
        dir.path(),
        &format!("svg:{heart}"),
        &["--region", "rect:120:100", "--count", "300", "--seed", "5"],
    );
    let placed = shapes(&doc);
    assert_eq!(placed.len(), 300);
    assert_eq!(doc["params"]["shape"], "svg:heart.svg");
    // The file's SHA-256, computed here independently of the tool.
    let digest = {
        use sha2::Digest;
        let d = sha2::Sha256::digest(HEART.as_bytes());
        d.iter().map(|b| format!("{b:02x}")).collect::<String>()
    };
    assert_eq!(doc["params"]["motif_sha256"], serde_json::json!([digest]));
    let all: Vec<Rings> = placed.iter().map(rings_of).collect();
    for (sh, rings) in placed.iter().zip(&all) {
        assert_eq!(sh["kind"], "motif");
        let want = sh["area"].as_f64().unwrap_or(0.0);
        assert!((area(rings) - want).abs() <= 1e-9 * want, "area {} against A_i {want}", area(rings));
        let b = bbox(rings);
        assert!(
            b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= 120.0 && b[3] <= 100.0,
            "outside the region: {b:?}"
        );
    }
    assert_eq!(overlaps(&all), vec![], "motifs overlap");
    // The checker catches an overlap: the second heart moved onto the first.
    let mut broken = all.clone();
    let (c0, c1) = (&placed[0]["center"], &placed[1]["center"]);
    let (dx, dy) = (
        c0[0].as_f64().unwrap_or(0.0) - c1[0].as_f64().unwrap_or(0.0),
        c0[1].as_f64().unwrap_or(0.0) - c1[1].as_f64().unwrap_or(0.0),
    );
    for p in broken[1].iter_mut().flatten() {
        *p = [p[0] + dx, p[1] + dy];
    }
    assert!(overlaps(&broken).contains(&(0, 1)));
    // The same command gives the same bytes.
    let run = || fill_svg(dir.path(), "svg:heart.svg", &["--count", "200"]);
    assert_eq!(run(), run());
}

#[test]
fn smaller_motifs_go_into_the_holes_of_larger_ones() {
    let dir = tmp();
    let ring = write(dir.path(), "ring.svg", RING_HEART);
    let doc = fill_json(
        dir.path(),
        &format!("svg:{ring}"),
        &["--c", "1.2", "--n-offset", "3", "--count", "400"],
    );
    let all: Vec<Rings> = shapes(&doc).iter().map(rings_of).collect();
    assert!(all.iter().all(|r| r.len() == 2), "each motif is a ring and its hole");
    assert_eq!(overlaps(&all), vec![]);
    // Some motif's centre lies inside another's bounding ring but outside its material: in
    // its hole.
    let centres: Vec<geo::Coord<f64>> = shapes(&doc)
        .iter()
        .map(|s| geo::coord! { x: s["center"][0].as_f64().unwrap_or(0.0), y: s["center"][1].as_f64().unwrap_or(0.0) })
        .collect();
    let in_a_hole = centres.iter().enumerate().any(|(i, c)| {
        all.iter()
            .enumerate()
            .any(|(j, r)| j != i && ring_poly(&r[0]).contains(c) && !in_material(r, *c))
    });
    assert!(in_a_hole, "no motif went into a hole");
}

#[test]
fn glyphs_are_ten_mixed_shapes_taken_in_turn_and_mix_with_built_in_kinds() {
    let dir = tmp();
    let doc = fill_json(dir.path(), "glyph:0123456789", &["--n-offset", "4", "--count", "60"]);
    assert_eq!(doc["params"]["mix_order"], "cycle");
    let placed = shapes(&doc);
    let all: Vec<Rings> = placed.iter().map(rings_of).collect();
    assert_eq!(overlaps(&all), vec![]);
    // A cycle of ten: shape i and i + 10 are the same glyph (the same rings, scaled).
    let rings: Vec<usize> = all.iter().map(Vec::len).collect();
    for i in 0..50 {
        assert_eq!(rings[i], rings[i + 10], "glyph {i}");
    }
    // "0" has a hole, "1" none, "8" two.
    assert_eq!((rings[0], rings[1], rings[8]), (2, 1, 3));
    // A mix of an SVG motif, glyphs and a circle, at random.
    let heart = write(dir.path(), "heart.svg", HEART);
    let mix = format!("mix:svg:{heart},glyph:AZ,circle");
    let doc = fill_json(dir.path(), &mix, &["--mix-order", "random", "--n-offset", "4", "--count", "100"]);
    assert_eq!(doc["params"]["shape"], mix.as_str());
    let kinds: std::collections::BTreeSet<String> = shapes(&doc).iter().map(|s| s["kind"].as_str().unwrap_or("").to_string()).collect();
    assert_eq!(kinds.into_iter().collect::<Vec<_>>(), ["circle", "motif"]);
}

#[test]
fn decorations_are_drawn_with_the_motif_and_never_tested() {
    let dir = tmp();
    let fly = write(dir.path(), "fly.svg", BUTTERFLY);
    let doc = fill_json(dir.path(), &format!("svg:{fly}"), &["--count", "150"]);
    let placed = shapes(&doc);
    for sh in &placed {
        let lines = sh["decorations"].as_array().unwrap_or_else(|| panic!("no decorations: {sh}"));
        assert_eq!(lines.len(), 2, "two antennas");
        // Each antenna starts at the wings' top notch, a vertex of the outline.
        let start = [lines[0][0][0].as_f64().unwrap_or(0.0), lines[0][0][1].as_f64().unwrap_or(0.0)];
        let near = rings_of(sh)
            .iter()
            .flatten()
            .map(|p| (p[0] - start[0]).hypot(p[1] - start[1]))
            .fold(f64::MAX, f64::min);
        assert!(
            near < 1e-9 * (1.0 + start[0].abs() + start[1].abs()),
            "antenna off its notch by {near}"
        );
    }
    let all: Vec<Rings> = placed.iter().map(rings_of).collect();
    assert_eq!(overlaps(&all), vec![]);
    // The SVG draws them as open paths of class decoration, in both styles.
    for style in ["outline", "filled"] {
        let svg = fill_svg(dir.path(), "svg:fly.svg", &["--count", "150", "--style", style]);
        let text = String::from_utf8_lossy(&svg);
        assert_eq!(text.matches("class=\"decoration\"").count(), 150, "{style}");
        let tree = usvg::Tree::from_data(&svg, &usvg::Options::default()).unwrap_or_else(|e| panic!("{e}"));
        assert!(tree.root().has_children());
    }
}

#[test]
fn bad_motifs_exit_2_naming_the_flag_and_write_nothing() {
    let dir = tmp();
    let d = dir.path();
    write(d, "empty.svg", "");
    std::fs::write(d.join("binary.svg"), [0u8, 159, 146, 150, 255, 0, 1, 2]).unwrap_or_else(|e| panic!("{e}"));
    let big = std::fs::File::create(d.join("big.svg")).unwrap_or_else(|e| panic!("{e}"));
    big.set_len(65 << 20).unwrap_or_else(|e| panic!("{e}"));
    let svg = |body: &str| {
        format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\">{body}</svg>")
    };
    write(
        d,
        "stroke.svg",
        &svg("<path fill=\"none\" stroke=\"black\" d=\"M10,10 L90,10 L50,80 Z\"/>"),
    );
    write(d, "nan.svg", &svg("<path d=\"M10,10 L90,NaN L50,80 Z\"/>"));
    write(d, "huge.svg", &svg("<path d=\"M10,10 L1e300,10 L50,80 Z\"/>"));
    write(d, "bowtie.svg", &svg("<path d=\"M10,10 L90,90 L90,10 L10,90 Z\"/>"));
    write(d, "flat.svg", &svg("<path d=\"M10,10 L50,10 L90,10 Z\"/>"));
    let many: String = (0..70_000)
        .map(|k| {
            let t = k as f64 / 70_000.0 * std::f64::consts::TAU;
            format!(
                "{}{:.5},{:.5} ",
                if k == 0 { "M" } else { "L" },
                50.0 + 40.0 * t.cos(),
                50.0 + 40.0 * t.sin()
            )
        })
        .collect();
    write(d, "many.svg", &svg(&format!("<path d=\"{many}Z\"/>")));
    for (shape, says) in [
        ("svg:missing.svg", "cannot read"),
        ("svg:empty.svg", "not a readable SVG"),
        ("svg:binary.svg", "not a readable SVG"),
        ("svg:big.svg", "MiB"),
        ("svg:stroke.svg", "no filled path"),
        ("svg:nan.svg", "no filled path"),
        ("svg:huge.svg", "1e300"),
        ("svg:bowtie.svg", "crosses itself"),
        ("svg:flat.svg", "not a motif"),
        ("svg:many.svg", "65536 vertices"),
        ("glyph:\u{e000}", "no glyph for"),
        ("glyph:", "at least one visible character"),
        ("glyph:   ", "at least one visible character"),
        ("mix:circle,glyph:ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789", "1 to 32 shapes"),
    ] {
        let o = zf(d, &["fill", "--shape", shape, "--count", "10", "-o", "out.svg"]);
        assert_eq!(o.code, 2, "{shape}: {}", o.stderr);
        assert!(o.stderr.contains("--shape") && o.stderr.contains(says), "{shape}: {}", o.stderr);
        assert!(!d.join("out.svg").exists(), "{shape} wrote a file");
    }
    // --font is read by glyph motifs, and refused without a text or glyph to read it.
    let o = zf(d, &["fill", "--font", "nofont.ttf", "--count", "10", "-o", "out.svg"]);
    assert_eq!(o.code, 2);
    assert!(o.stderr.contains("--font") && o.stderr.contains("glyph:TEXT"), "{}", o.stderr);
    let o = zf(
        d,
        &[
            "fill",
            "--shape",
            "glyph:A",
            "--font",
            "nofont.ttf",
            "--count",
            "10",
            "-o",
            "out.svg",
        ],
    );
    assert_eq!(o.code, 2);
    assert!(o.stderr.contains("--font") && o.stderr.contains("cannot read"), "{}", o.stderr);
    assert!(!d.join("out.svg").exists());
}
