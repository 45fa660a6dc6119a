//! Periodic fills in SVG are cut to the tile geometrically, as the G-code is, so that a
//! plotter (vpype and plotter drivers ignore `clip-path`) draws only the tile. Read back
//! with an independent reader (`common::svgread`): every drawn coordinate, arc extremes
//! included, lies inside the tile; no clip path is left; an outline SVG draws the same
//! pen-down length as the G-code of the same fill; filled shapes cover exactly the area of
//! the shapes (on a torus the images of a shape add up to it). The same holds for the other
//! drawings that used to lean on a clip path (1D circles and zoom rows, filled tile
//! layouts), and a twin shows that the reader reports an uncut image and a clip path.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::svgread::{gcode_pen_length, read_svg, usvg_clip_paths};
use common::*;

/// The tile without a page, and on A4 with `--center` (mm on the page, y down).
const TILE: [f64; 4] = [0.0, 0.0, 100.0, 80.0];
const A4_TILE: [f64; 4] = [55.0, 108.5, 155.0, 188.5];

/// Written points on the tile's edges are exact; arc extremes are rebuilt from centres and
/// radii rounded to the SVG's four decimals.
const TOL: f64 = 1e-6;
const TOL_ARC: f64 = 2e-4;

/// (name, the fill's flags): circles, hatched squares, rings and stars on a 100 x 80 torus.
const FILLS: [(&str, &[&str]); 4] = [
    ("circles", &["--count", "200", "--seed", "24"]),
    (
        "squares",
        &[
            "--shape",
            "square",
            "--c",
            "1.25",
            "--n-offset",
            "2",
            "--count",
            "150",
            "--seed",
            "5",
        ],
    ),
    (
        "rings",
        &[
            "--shape",
            "ring:0.5",
            "--c",
            "1.25",
            "--n-offset",
            "2",
            "--count",
            "150",
            "--seed",
            "5",
        ],
    ),
    (
        "stars",
        &[
            "--shape",
            "star:5:0.45",
            "--c",
            "1.2",
            "--n-offset",
            "3",
            "--count",
            "150",
            "--seed",
            "2",
        ],
    ),
];

fn assert_clean(what: &str, svg: &[u8], boxes: &[[f64; 4]], tol: f64) -> common::svgread::SvgRead {
    let r = read_svg(svg, boxes, tol, TOL_ARC.max(tol));
    assert!(
        r.problems.is_empty(),
        "{what}: {} problems, first: {:?}",
        r.problems.len(),
        &r.problems[..r.problems.len().min(5)]
    );
    assert!(!String::from_utf8_lossy(svg).contains("clip-path"), "{what}: a clip-path");
    assert_eq!(usvg_clip_paths(svg), 0, "{what}: usvg applies a clip path");
    assert!(r.subpaths > 0, "{what}: nothing drawn");
    r
}

#[test]
fn periodic_fills_are_cut_to_the_tile_in_every_svg() {
    let dir = tmp();
    let d = dir.path();
    for (name, flags) in FILLS {
        let base = [&["--region", "rect:100:80", "--periodic"][..], flags].concat();
        let doc = fill_json(d, &base);
        let area: f64 = shapes(&doc).iter().map(|s| f(s, "area")).sum();
        // Outlines (hatched for the squares): what the pen draws is what the G-code draws.
        let hatch: &[&str] = if name == "squares" { &["--hatch", "2"] } else { &[] };
        let plotted = [&base[..], hatch].concat();
        let gcode = fill_to(d, "p.gcode", &plotted);
        let want = gcode_pen_length(&String::from_utf8_lossy(&gcode));
        for (page, tile) in [
            (&[][..], TILE),
            (&["--page", "a4", "--center"][..], A4_TILE),
            (&["--layers", "size-bands:2"][..], TILE),
        ] {
            let what = format!("{name} outline {page:?}");
            let svg = fill_to(d, "o.svg", &[&plotted[..], page].concat());
            let r = assert_clean(&what, &svg, &[tile], TOL);
            assert!(rel(r.pen, want) < 1e-3, "{what}: pen-down {} mm, G-code {want} mm", r.pen);
        }
        // Filled: the images' areas, cut to the tile, add up to the shapes' areas.
        for (page, tile) in [(&[][..], TILE), (&["--page", "a4", "--center"][..], A4_TILE)] {
            let what = format!("{name} filled {page:?}");
            let svg = fill_to(d, "f.svg", &[&base[..], &["--style", "filled"], page].concat());
            let r = assert_clean(&what, &svg, &[tile], TOL);
            assert!(rel(r.area, area) < 1e-4, "{what}: covers {} mm², the shapes {area} mm²", r.area);
        }
    }
}

/// The reader fails on the old behaviour: an image uncut under a clip path (a circle across
/// the right edge), and an arc whose ends are inside but which bulges out of the tile.
#[test]
fn the_reader_reports_uncut_images_and_clip_paths() {
    let old = br#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="80mm" viewBox="0 0 100 80">
<defs><clipPath id="region"><rect width="100" height="80"/></clipPath></defs>
<g id="shapes" fill="none" stroke="black" clip-path="url(#region)">
<circle cx="98" cy="40" r="5"/><path d="M2,10 A5,5 0 0 0 2,20"/><circle cx="50" cy="40" r="5"/>
</g></svg>
"#;
    let r = read_svg(old, &[TILE], TOL, TOL_ARC);
    let has = |s: &str| r.problems.iter().any(|p| p.contains(s));
    assert!(has("a <clipPath>") && has("clip-path=\"url(#region)\""), "{:?}", r.problems);
    assert!(has("<circle> draws outside"), "{:?}", r.problems);
    assert!(has("<path> draws outside: arc extreme"), "{:?}", r.problems);
    assert_eq!(r.problems.len(), 4, "the circle inside is fine: {:?}", r.problems);
    assert_eq!(usvg_clip_paths(old), 1);
    // Uncut, the images are longer than what the tile shows: 2 whole circles and a half.
    let full = std::f64::consts::PI * 5.0;
    assert!(rel(r.pen, 5.0 * full) < 1e-9, "{}", r.pen);
    // The same drawing cut to the tile passes.
    let cut = br#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="80mm" viewBox="0 0 100 80">
<g id="shapes" fill="none" stroke="black">
<path d="M100,35.4174 A5,5 0 1 0 100,44.5826"/><path d="M2,10 A5,5 0 0 1 2,20"/>
</g></svg>
"#;
    assert!(read_svg(cut, &[TILE], TOL, TOL_ARC).problems.is_empty());
}

/// The viewBox's width and height.
fn view_box(svg: &[u8]) -> (f64, f64) {
    let text = String::from_utf8_lossy(svg);
    let v: Vec<f64> = text
        .split("viewBox=\"")
        .nth(1)
        .and_then(|t| t.split('"').next())
        .unwrap_or("")
        .split_whitespace()
        .filter_map(|n| n.parse().ok())
        .collect();
    assert_eq!(v.len(), 4, "a viewBox");
    (v[2], v[3])
}

/// `zetafill line`: a wrapping segment's circles, and the zoom rows' magnified circles, are
/// cut to the interval's box or their row (outlines and filled), with no clip path.
#[test]
fn line_circles_and_zoom_rows_are_cut_to_their_boxes() {
    let dir = tmp();
    let d = dir.path();
    let base = ["--periodic", "--count", "300", "--seed", "3"];
    for style in ["outline", "filled"] {
        let svg = line_to(d, "c.svg", &[&base[..], &["--render", "circles", "--style", style]].concat());
        let (w, h) = view_box(&svg);
        // Numbers have four decimals, and these edges are not on that grid.
        assert_clean(&format!("circles {style}"), &svg, &[[0.0, 0.0, w, h]], 1e-4);
    }
    let doc = parse_json(&line_to(d, "l.json", &base));
    let d0 = f(&shapes(&doc)[0], "length");
    let rows = 3;
    let svg = line_to(d, "z.svg", &[&base[..], &["--render", "zoom", "--zoom-rows", "3"]].concat());
    let (w, _) = view_box(&svg);
    // Each row's box, and the gap below it (where the marks are).
    let boxes: Vec<[f64; 4]> = (0..rows)
        .flat_map(|k| {
            let y0 = f64::from(k) * 1.25 * d0;
            [[0.0, y0, w, y0 + d0], [0.0, y0 + d0, w, y0 + 1.25 * d0]]
        })
        .collect();
    assert_clean("zoom", &svg, &boxes, 1e-4);
}

/// `zetafill tile` filled mosaics and planets draw each copy's shapes whole, cut exactly to
/// the sheet (no clip path).
#[test]
fn filled_tile_layouts_are_cut_to_the_sheet() {
    let dir = tmp();
    let d = dir.path();
    for layout in ["mosaic", "planet"] {
        let svg = write_to(
            d,
            "tile",
            "t.svg",
            &["-q", "--tries", "1500", "--style", "filled", "--layout", layout, "--rows", "2"],
        );
        let (w, h) = view_box(&svg);
        assert_clean(layout, &svg, &[[0.0, 0.0, w, h]], 1e-4);
    }
}
