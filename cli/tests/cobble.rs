//! Tests of the Voronoi cobblestones (`zetafill fill --voronoi`): the drawn edges are exactly
//! the Voronoi edges of the centres clipped to the region (against a brute-force half-plane
//! construction), a periodic tile's edges meet themselves across opposite sides, a disc region
//! clips exactly, reruns are byte-identical, and formats other than SVG/PNG are refused. Each
//! checker is shown to fail on a broken input.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use clap::Parser;
use common::voronoi::{same_segment, segment_mismatch, segments, voronoi_cell, ON_BOX};
use common::{zf, Out};
use zetafill_cli::cmd::{cobble, fill};
use zetafill_cli::geometry::voronoi::Pt;
use zetafill_cli::model::doc::FillDoc;
use zetafill_cli::Cli;

fn fill_doc(args: &[&str]) -> FillDoc {
    let mut a = vec!["zetafill", "fill"];
    a.extend_from_slice(args);
    a.extend_from_slice(&["-o", "unused.svg"]);
    let cli = Cli::try_parse_from(a).unwrap_or_else(|e| panic!("{e}"));
    let zetafill_cli::Command::Fill(f) = cli.command else {
        panic!("not fill")
    };
    let (doc, halt) = fill::compute(
        &zetafill_cli::plan::fill::resolve_as(&f, zetafill_cli::plan::format::Format::Json)
            .unwrap_or_else(|e| panic!("{e}"))
            .0,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert!(halt.is_none());
    doc
}

/// Every Voronoi edge inside the box, once (each appears in two cells; deduplicated).
fn brute_edges(pts: &[Pt], bbox: (f64, f64, f64, f64)) -> Vec<(Pt, Pt)> {
    let mut all: Vec<(Pt, Pt)> = Vec::new();
    for i in 0..pts.len() {
        let cell = voronoi_cell(i, pts, bbox);
        for k in 0..cell.len() {
            let (a, j) = cell[k];
            let (b, _) = cell[(k + 1) % cell.len()];
            if j != ON_BOX && (a[0] - b[0]).hypot(a[1] - b[1]) > 1e-9 {
                all.push((a, b));
            }
        }
    }
    let mut out: Vec<(Pt, Pt)> = Vec::new();
    for e in all {
        if !out.iter().any(|o| same_segment(o, &e, 1e-7)) {
            out.push(e);
        }
    }
    out
}

#[test]
fn cobblestones_are_the_voronoi_edges_of_the_centres() {
    for (region, count) in [("rect:100:100", "60"), ("rect:120:50", "150")] {
        let doc = fill_doc(&["--count", count, "--region", region, "--seed", "3"]);
        let lines = cobble::polylines(&doc).unwrap_or_else(|e| panic!("{e}"));
        let got = segments(&lines);
        let centres: Vec<Pt> = doc.shapes.iter().map(|s| s.center).collect();
        let want = brute_edges(&centres, doc.bbox());
        assert_eq!(segment_mismatch(&got, &want, 1e-7).len(), 0, "{region}");
        assert!(lines.len() < got.len(), "edges not merged");
        // The checker fails on a missing and on a doubled edge.
        assert!(!segment_mismatch(&got[1..], &want, 1e-7).is_empty());
        let mut doubled = got.clone();
        doubled.push(got[0]);
        assert!(!segment_mismatch(&doubled, &want, 1e-7).is_empty());
    }
}

/// The crossings of the drawing with the line x = v (or y = v): the other coordinate of every
/// polyline end that lies on it, sorted.
fn ends_on(lines: &[Vec<Pt>], axis: usize, v: f64) -> Vec<f64> {
    let mut out: Vec<f64> = lines
        .iter()
        .flat_map(|l| [l[0], l[l.len() - 1]])
        .filter(|p| (p[axis] - v).abs() < 1e-9)
        .map(|p| p[1 - axis])
        .collect();
    out.sort_by(f64::total_cmp);
    out
}

fn seam_errors(lines: &[Vec<Pt>], w: f64, h: f64) -> usize {
    let mut bad = 0;
    for (axis, size) in [(0, w), (1, h)] {
        let (a, b) = (ends_on(lines, axis, 0.0), ends_on(lines, axis, size));
        if a.len() != b.len() || a.is_empty() {
            bad += 1 + a.len().abs_diff(b.len());
            continue;
        }
        bad += a.iter().zip(&b).filter(|(x, y)| (*x - *y).abs() > 1e-6).count();
    }
    bad
}

#[test]
fn periodic_cobblestones_tile_seamlessly() {
    let doc = fill_doc(&["--count", "300", "--region", "rect:100:80", "--periodic", "--seed", "5"]);
    let lines = cobble::polylines(&doc).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(seam_errors(&lines, 100.0, 80.0), 0);
    assert!(lines
        .iter()
        .flatten()
        .all(|p| (0.0..=100.0).contains(&p[0]) && (0.0..=80.0).contains(&p[1])));
    // The same centres without their periodic copies do not tile: the checker sees it.
    let mut flat = doc.clone();
    flat.region = zetafill_cli::model::doc::RegionDoc::Rect {
        width: 100.0,
        height: 80.0,
        periodic: false,
    };
    let plain = cobble::polylines(&flat).unwrap_or_else(|e| panic!("{e}"));
    assert!(seam_errors(&plain, 100.0, 80.0) > 0);
}

#[test]
fn disc_region_clips_exactly() {
    let doc = fill_doc(&["--count", "200", "--region", "circle:50", "--seed", "2", "--sampler", "reference"]);
    let lines = cobble::polylines(&doc).unwrap_or_else(|e| panic!("{e}"));
    let r = |p: &Pt| (p[0] - 50.0).hypot(p[1] - 50.0);
    assert!(lines.iter().flatten().all(|p| r(p) <= 50.0 + 1e-9));
    assert!(lines
        .iter()
        .flat_map(|l| [l[0], l[l.len() - 1]])
        .filter(|p| r(p) > 49.99)
        .all(|p| (r(&p) - 50.0).abs() < 1e-9));
}

#[test]
fn cli_writes_svg_and_png_identically_on_rerun_and_refuses_other_formats() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    for name in ["a.svg", "b.svg", "a.png", "b.png"] {
        let Out { code, stderr: err, .. } = zf(
            dir.path(),
            &["fill", "--count", "500", "--periodic", "--voronoi", "--boundary", "-o", name],
        );
        assert_eq!(code, 0, "{err}");
    }
    let read = |n: &str| std::fs::read(dir.path().join(n)).unwrap_or_default();
    assert_eq!(read("a.svg"), read("b.svg"));
    assert_eq!(read("a.png"), read("b.png"));
    let text = String::from_utf8(read("a.svg")).unwrap_or_default();
    assert!(text.contains("id=\"cobblestones\"") && text.contains("--voronoi"));
    usvg::Tree::from_str(&text, &usvg::Options::default()).unwrap_or_else(|e| panic!("{e}"));
    let Out { code, stderr: err, .. } = zf(dir.path(), &["fill", "--count", "50", "--voronoi", "-o", "c.json"]);
    assert_eq!(code, 2);
    assert!(err.contains("--voronoi"), "{err}");
    assert!(!dir.path().join("c.json").exists());
}
