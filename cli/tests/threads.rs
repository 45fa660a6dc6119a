//! `fill --sampler batched --threads N`: every file the same for 1, 2, 3 and 8 threads, and
//! the fill valid by the document checker (no overlaps, inside the region, the power law).
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;

/// Fills with `args` (plus the batched sampler) on 1, 2, 3 and 8 threads, into `name`: the
/// bytes, which must be the same for all four.
fn same_for_any_threads(args: &[&str], name: &str) -> Vec<u8> {
    let dir = tmp();
    let mut first: Option<Vec<u8>> = None;
    for threads in ["1", "2", "3", "8"] {
        let mut a = args.to_vec();
        a.extend_from_slice(&["--sampler", "batched", "--threads", threads, "-q"]);
        let bytes = fill_to(dir.path(), &format!("{threads}-{name}"), &a);
        match &first {
            None => first = Some(bytes),
            Some(f) => assert!(f == &bytes, "{name} with {args:?}: {threads} threads wrote other bytes than one"),
        }
    }
    first.unwrap_or_default()
}

/// The first two circles that overlap or touch, by brute force.
fn first_overlap(circles: &[([f64; 2], f64)]) -> Option<(usize, usize)> {
    for (i, (a, ra)) in circles.iter().enumerate() {
        for (j, (b, rb)) in circles.iter().enumerate().skip(i + 1) {
            if (a[0] - b[0]).hypot(a[1] - b[1]) <= ra + rb {
                return Some((i, j));
            }
        }
    }
    None
}

#[test]
fn every_format_is_the_same_for_any_number_of_threads() {
    let base = ["--region", "rect:100:80", "--count", "1500", "--seed", "4"];
    let mut seen = Vec::new();
    for name in ["out.svg", "out.json", "out.gcode", "out.png", "out.csv", "out.txt"] {
        let mut a = base.to_vec();
        if name == "out.txt" {
            a.extend_from_slice(&["--format", "digest"]);
        }
        seen.push(same_for_any_threads(&a, name));
    }
    let doc = parse_json(&seen[1]);
    // The document checker's own checks (the power law, the trials); it returns whether the
    // fill halted.
    assert!(!check_doc(
        &doc,
        &Expect {
            count: Some(1500),
            seed: 4,
            sampler: "batched",
            ..Expect::default()
        }
    ));
    // No two circles meet, and every one lies in the region.
    let circles: Vec<([f64; 2], f64)> = shapes(&doc).iter().map(|c| (pt(&c["center"]), f(c, "radius"))).collect();
    assert_eq!(first_overlap(&circles), None);
    let mut broken = circles.clone();
    broken[9].0 = broken[10].0;
    assert!(
        first_overlap(&broken).is_some(),
        "the overlap check missed a circle moved onto another"
    );
    assert!(circles
        .iter()
        .all(|&([x, y], r)| x >= r && y >= r && x + r <= 100.0 && y + r <= 80.0));
    // The control: another seed gives another file, so the comparison can fail.
    let mut other = base.to_vec();
    other[5] = "5";
    assert_ne!(same_for_any_threads(&other, "out.svg"), seen[0], "seeds 4 and 5 wrote the same SVG");
}

#[test]
fn rotated_shapes_densities_tori_and_fixed_point_are_the_same_for_any_threads() {
    let cases: [&[&str]; 3] = [
        &[
            "--shape",
            "square",
            "--periodic",
            "--region",
            "rect:100:80",
            "--count",
            "800",
            "--density",
            "noise:value:30",
        ],
        &[
            "--shape",
            "mix:star:5:0.5,circle,blob:0.2",
            "--region",
            "circle:60",
            "--c",
            "1.25",
            "--n-offset",
            "3",
            "--gap",
            "0.3",
            "--count",
            "300",
        ],
        &[
            "--shape",
            "triangle",
            "--scalar",
            "fixed",
            "--region",
            "rect:100:80",
            "--count",
            "800",
        ],
    ];
    for args in cases {
        let doc = parse_json(&same_for_any_threads(args, "out.json"));
        let placed = doc["stats"]["placed"].as_u64().unwrap_or(0);
        assert!(placed >= 300, "{args:?}: {placed} placed");
    }
}

#[test]
fn threads_need_the_batched_sampler_and_batched_is_2d_only() {
    let dir = tmp();
    let out = zf(dir.path(), &["fill", "--threads", "2", "-o", "a.svg"]);
    assert_eq!(out.code, 2);
    assert!(names_flag(&out.stderr, "--threads"), "{}", out.stderr);
    for command in ["line", "space"] {
        let out = zf(dir.path(), &[command, "--sampler", "batched", "-o", "a.json"]);
        assert_eq!(out.code, 2, "{command}");
        assert!(names_flag(&out.stderr, "--sampler"), "{command}: {}", out.stderr);
    }
    let out = zf(dir.path(), &["fill", "--batch", "4", "-o", "a.svg"]);
    assert_eq!(out.code, 2);
    assert!(names_flag(&out.stderr, "--batch"), "{}", out.stderr);
    let out = zf(dir.path(), &["fill", "--sampler", "batched", "--threads", "0", "-o", "a.svg"]);
    assert_eq!(out.code, 2);
    assert!(
        listing(dir.path()).is_empty(),
        "a refused run left files: {:?}",
        listing(dir.path())
    );
}

/// The largest batch decides the fill, and the document records it, so that its command
/// remakes it.
#[test]
fn the_batch_size_is_part_of_the_fill() {
    let dir = tmp();
    let args = ["--count", "900", "--sampler", "batched", "-q"];
    let default = parse_json(&fill_to(dir.path(), "a.json", &args));
    let mut four = args.to_vec();
    four.extend_from_slice(&["--batch", "4"]);
    let small = parse_json(&fill_to(dir.path(), "b.json", &four));
    assert_eq!(default["params"]["batch"].as_u64(), Some(64));
    assert_eq!(small["params"]["batch"].as_u64(), Some(4));
    assert_ne!(default["shapes"], small["shapes"], "batches of 4 and 64 gave the same fill");
    let svg = String::from_utf8(fill_to(dir.path(), "b.svg", &four)).unwrap_or_default();
    assert!(
        svg.contains("--sampler batched") && svg.contains("--batch 4"),
        "the SVG's command lacks the batch"
    );
    let fast = parse_json(&fill_to(dir.path(), "c.json", &["--count", "50", "-q"]));
    assert!(fast["params"].get("batch").is_none(), "a fill of the cell sampler records a batch");
}
