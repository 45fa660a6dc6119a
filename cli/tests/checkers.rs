//! The geometry checkers used by the end-to-end tests can fail: edited documents with an
//! overlap or a shape outside the region are reported, and hand-made cases give the expected
//! clearances.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use serde_json::{json, Value};

fn run(args: &[&str]) -> Value {
    let dir = tmp();
    let doc = fill_json(dir.path(), args);
    assert_geometry(&doc);
    doc
}

fn shape_mut(doc: &mut Value, i: usize) -> &mut Value {
    doc.get_mut("shapes")
        .and_then(|s| s.get_mut(i))
        .unwrap_or_else(|| panic!("no shape {i}"))
}

/// Moves shape `i` (centre and vertices) by (dx, dy).
fn move_shape(doc: &mut Value, i: usize, dx: f64, dy: f64) {
    let sh = shape_mut(doc, i);
    let c = pt(&sh["center"]);
    sh["center"] = json!([c[0] + dx, c[1] + dy]);
    if let Some(vs) = sh.get_mut("vertices").and_then(Value::as_array_mut) {
        for v in vs.iter_mut() {
            let p = pt(v);
            *v = json!([p[0] + dx, p[1] + dy]);
        }
    }
}

fn center(doc: &Value, i: usize) -> [f64; 2] {
    pt(&shapes(doc)[i]["center"])
}

#[test]
fn overlap_checker_catches_a_shape_moved_onto_another() {
    for args in [
        &["--region", "rect:100:80", "--count", "100"][..],
        &["--region", "rect:100:80", "--count", "100", "--shape", "square"][..],
        &["--region", "rect:100:80", "--count", "100", "--shape", "rect:2.5", "--periodic"][..],
    ] {
        let doc = run(args);
        let mut bad = doc.clone();
        let (a, b) = (center(&doc, 3), center(&doc, 40));
        move_shape(&mut bad, 40, a[0] - b[0], a[1] - b[1]);
        let errs = check_overlaps(&bad);
        assert!(errs.iter().any(|e| e.contains("shapes 3 and 40")), "{args:?}: not caught: {errs:?}");

        // A tiny nudge is caught too: push circle 1 towards circle 0 until they overlap by
        // 0.01 mm.
        let mut bad = doc.clone();
        let (a, b) = (center(&doc, 0), center(&doc, 1));
        let (gx, gy) = (a[0] - b[0], a[1] - b[1]);
        let d = gx.hypot(gy);
        let gs: Vec<G> = shapes(&doc).iter().map(G::from_json).collect();
        let cl = clearance(&gs[0], &gs[1]);
        if matches!(gs[0], G::Circle { .. }) && !bad["region"]["periodic"].as_bool().unwrap_or(false) {
            let step = cl + 0.01;
            move_shape(&mut bad, 1, gx / d * step, gy / d * step);
            let errs = check_overlaps(&bad);
            assert!(
                errs.iter().any(|e| e.contains("shapes 0 and 1")),
                "{args:?}: nudge not caught (clearance {cl}): {errs:?}"
            );
        }
    }
}

#[test]
fn inside_checker_catches_a_shape_pushed_out() {
    for args in [
        &["--region", "rect:100:80", "--count", "60"][..],
        &["--region", "rect:100:80", "--count", "60", "--shape", "square"][..],
    ] {
        let doc = run(args);
        let mut bad = doc.clone();
        let c = center(&doc, 10);
        move_shape(&mut bad, 10, 100.0 - c[0], 0.0); // centre on the right edge
        let errs = check_inside(&bad);
        assert_eq!(errs.len(), 1, "{args:?}: {errs:?}");
        assert!(errs[0].starts_with("shape 10:"), "{errs:?}");
        let mut bad = doc.clone();
        move_shape(&mut bad, 20, 0.0, -(center(&doc, 20)[1]) - 1.0); // below y = 0
        assert!(!check_inside(&bad).is_empty());
        assert!(check_inside(&doc).is_empty() && check_overlaps(&doc).is_empty());
    }
    // Periodic: a centre at x = W (outside [0, W)) is caught.
    let doc = run(&["--region", "rect:100:80", "--count", "30", "--periodic"]);
    let mut bad = doc.clone();
    let c = center(&doc, 5);
    shape_mut(&mut bad, 5)["center"] = json!([100.0, c[1]]);
    let errs = check_inside(&bad);
    assert_eq!(errs.len(), 1, "{errs:?}");
}

fn doc_of(w: f64, h: f64, periodic: bool, gap: f64, list: Vec<Value>) -> Value {
    json!({ "params": { "gap": gap }, "region": { "kind": "rect", "width": w, "height": h, "periodic": periodic }, "shapes": list })
}

fn circle(x: f64, y: f64, r: f64) -> Value {
    json!({ "center": [x, y], "radius": r })
}

fn poly(vs: &[[f64; 2]]) -> Value {
    let c = vs
        .iter()
        .fold([0.0, 0.0], |a, v| [a[0] + v[0] / vs.len() as f64, a[1] + v[1] / vs.len() as f64]);
    json!({ "center": c, "vertices": vs })
}

#[test]
fn periodic_images_are_checked() {
    // 9.2 apart directly, but 0.8 apart across the left/right edge: overlap only if periodic.
    let list = vec![circle(0.5, 5.0, 1.0), circle(9.7, 5.0, 1.0)];
    let periodic = doc_of(10.0, 10.0, true, 0.0, list.clone());
    let errs = check_overlaps(&periodic);
    assert_eq!(errs.len(), 1, "{errs:?}");
    assert!(errs[0].contains("shapes 0 and 1") && errs[0].contains("-10"), "{errs:?}");
    assert!(check_inside(&periodic).is_empty(), "centres are inside [0,10)");
    let inclusive = doc_of(10.0, 10.0, false, 0.0, list);
    assert!(check_overlaps(&inclusive).is_empty());
    assert_eq!(check_inside(&inclusive).len(), 2, "both cross the boundary");
    // Across the top/bottom edge and a corner, for polygons.
    let sq = |x: f64, y: f64, hs: f64| poly(&[[x - hs, y - hs], [x + hs, y - hs], [x + hs, y + hs], [x - hs, y + hs]]);
    let corner = doc_of(10.0, 10.0, true, 0.0, vec![sq(0.3, 0.3, 0.5), sq(9.7, 9.7, 0.5)]);
    assert_eq!(check_overlaps(&corner).len(), 1);
    // A shape too big for the torus overlaps its own image.
    let own = doc_of(10.0, 10.0, true, 0.0, vec![circle(5.0, 5.0, 5.5)]);
    let errs = check_overlaps(&own);
    assert!(!errs.is_empty() && errs[0].contains("shapes 0 and 0"), "{errs:?}");
}

#[test]
fn polygon_clearance_is_exact() {
    // Diamonds |x|+|y| <= 1 and |x-1.2|+|y-1.2| <= 1: bounding boxes overlap, the shapes do
    // not; their distance is 0.4/sqrt(2).
    let a = G::Poly(vec![[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]);
    let b = a.shift(1.2, 1.2);
    let d = clearance(&a, &b);
    assert!((d - 0.4 / 2f64.sqrt()).abs() < 1e-12, "{d}");
    let doc = doc_of(10.0, 10.0, false, 0.0, vec![]);
    assert!(check_overlaps(&doc).is_empty());
    // Touching squares are not an overlap; a 1e-6 penetration is.
    let s1 = G::Poly(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    assert!(clearance(&s1, &s1.shift(1.0, 0.0)).abs() < 1e-15);
    assert!(clearance(&s1, &s1.shift(1.0 - 1e-6, 0.3)) < -EPS);
    // Corner-to-corner distance (vertex-vertex, not along an edge normal).
    let d = clearance(&s1, &s1.shift(1.5, 1.5));
    assert!((d - 0.5 * 2f64.sqrt()).abs() < 1e-12, "{d}");
    // A rotated square poking into an axis-aligned one, and a circle against a polygon.
    let rot = G::Poly(vec![[1.5, 0.5], [2.0, 1.0], [1.5, 1.5], [1.0, 1.0]]);
    assert!(clearance(&s1, &rot.shift(-0.1, 0.0)) < 0.0);
    assert!((clearance(&s1, &rot.shift(0.1, 0.0)) - 0.1).abs() < 1e-12);
    let c = G::Circle { c: [2.0, 2.0], r: 0.5 };
    assert!((clearance(&s1, &c) - (2f64.sqrt() - 0.5)).abs() < 1e-12);
    assert!(clearance(&s1, &G::Circle { c: [0.5, 0.5], r: 0.1 }) < 0.0);
    // The gap: 0.28 mm apart passes a 0.2 gap and fails a 0.3 gap.
    let two = vec![
        poly(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]),
        poly(&[[2.2, 1.2], [1.2, 2.2], [0.2, 1.2], [1.2, 0.2]]),
    ];
    assert!(check_overlaps(&doc_of(10.0, 10.0, false, 0.2, two.clone())).is_empty());
    assert_eq!(check_overlaps(&doc_of(10.0, 10.0, false, 0.3, two)).len(), 1);
}
