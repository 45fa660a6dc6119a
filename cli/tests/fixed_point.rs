//! Fills on the fixed-point scalar at its largest supported size (the issue "Hardening"): the
//! cell sampler halted, as if certain, at placement 9 of 2,000 triangles in a 5,000 mm square
//! (and at 27 of 2,000 squares in a 10,000 mm one) where the reference sampler places all
//! 2,000. Every sampler must place them all, none overlapping and all inside.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;

fn fill(dir: &std::path::Path, shape: &str, side: &str, sampler: &str) -> serde_json::Value {
    let region = format!("rect:{side}:{side}");
    let args = [
        "fill",
        "--shape",
        shape,
        "--region",
        &region,
        "--scalar",
        "fixed",
        "--c",
        "1.3",
        "--n-offset",
        "2",
        "--count",
        "2000",
        "--seed",
        "67",
        "--sampler",
        sampler,
        "-o",
        "out.json",
    ];
    zf_ok(dir, &args);
    parse_json(&read(&dir.join("out.json")))
}

#[test]
fn fixed_point_fills_place_every_shape_the_reference_places() {
    let dir = tmp();
    for (shape, side) in [("triangle", "5000"), ("square", "10000")] {
        for sampler in ["fast", "reference"] {
            let doc = fill(dir.path(), shape, side, sampler);
            let what = format!("{shape}s in {side} mm, {sampler} sampler");
            assert_eq!(shapes(&doc).len(), 2000, "{what}");
            assert_eq!(doc["stats"]["halted"], false, "{what}");
            let errs: Vec<String> = check_overlaps(&doc).into_iter().chain(check_inside(&doc)).collect();
            assert!(errs.is_empty(), "{what}: {errs:?}");
        }
    }
}
