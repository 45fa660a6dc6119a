//! `fill --density`: shapes gather where a noise field is high, with either sampler; the JSON
//! and the `<desc>` command name the field in full; bad fields are refused before any work.

mod common;

use common::{tmp, zf, zf_json};
use serde_json::Value;
use zetafill::{Noise, NoiseKind};

/// `rho` as the CLI computes it for `noise:gradient:40:3:0.5:3` with seed 2 in a 200 mm square.
fn rho(x: f64, y: f64) -> f64 {
    let n = Noise::new(NoiseKind::Gradient, 2, 40.0, 3, 0.5, None).expect("noise");
    (0.5 + 3.0 * (n.at(x, y) - 0.5)).clamp(0.0, 1.0)
}

fn centres(doc: &Value) -> Vec<(f64, f64)> {
    doc["shapes"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|s| {
                    (
                        s["center"][0].as_f64().unwrap_or(f64::NAN),
                        s["center"][1].as_f64().unwrap_or(f64::NAN),
                    )
                })
                .collect()
        })
        .unwrap_or_default()
}

#[test]
fn shapes_gather_where_the_density_is_high() {
    let dir = tmp();
    let d = dir.path();
    let grid: Vec<f64> = (0..40_000).map(|k| rho((k % 200) as f64 + 0.5, (k / 200) as f64 + 0.5)).collect();
    let field = grid.iter().sum::<f64>() / grid.len() as f64;
    for sampler in ["fast", "reference"] {
        let base = [
            "fill",
            "--count",
            "1000",
            "--c",
            "1.3",
            "--n-offset",
            "100",
            "--seed",
            "2",
            "--sampler",
            sampler,
        ];
        let doc = zf_json(
            d,
            &[
                &base[..],
                &["--density", "noise:gradient:40:3:0.5:3", "--format", "json", "-o", "-"],
            ]
            .concat(),
        );
        assert_eq!(doc["params"]["density"], "noise:gradient:40:3:0.5:3");
        let c = centres(&doc);
        assert_eq!(c.len(), 1000);
        // The first hundred: later shapes go where room is left, dense or not.
        let at = c.iter().take(100).map(|&(x, y)| rho(x, y)).sum::<f64>() / 100.0;
        assert!(at > field + 0.1, "{sampler}: mean density at the centres {at} against {field}");
        // The check can fail: without the density the centres sit where the field averages.
        let plain = zf_json(d, &[&base[..], &["--format", "json", "-o", "-"]].concat());
        assert!(plain["params"].get("density").is_none());
        let c = centres(&plain);
        let at = c.iter().take(100).map(|&(x, y)| rho(x, y)).sum::<f64>() / 100.0;
        assert!((at - field).abs() < 0.05, "{sampler}: uniform centres {at} against {field}");
    }
}

#[test]
fn defaults_are_written_out() {
    let dir = tmp();
    let doc = zf_json(
        dir.path(),
        &[
            "fill",
            "--count",
            "50",
            "--density",
            "noise:value:30",
            "--format",
            "json",
            "-o",
            "-",
        ],
    );
    assert_eq!(doc["params"]["density"], "noise:value:30:4:0.5:2");
}

#[test]
fn bad_fields_are_refused_before_any_work() {
    let dir = tmp();
    let d = dir.path();
    for (spec, says) in [
        ("noise:pink:30", "noise:value|gradient"),
        ("noise:gradient", "noise:value|gradient"),
        ("noise:gradient:0", "SCALE"),
        ("noise:gradient:30:0", "OCTAVES"),
        ("noise:gradient:30:17", "OCTAVES"),
        ("noise:gradient:30:4:1.5", "GAIN"),
        ("noise:gradient:30:4:0.5:0", "CONTRAST"),
        ("noise:gradient:30:4:0.5:2:9", "noise:value|gradient"),
        ("image:face.png", "noise:value|gradient"),
    ] {
        let o = zf(d, &["fill", "--count", "50", "--density", spec, "-o", "bad.svg"]);
        assert_eq!(o.code, 2, "{spec}: {}", o.stderr);
        assert!(o.stderr.contains("--density") && o.stderr.contains(says), "{spec}: {}", o.stderr);
        assert!(!d.join("bad.svg").exists(), "{spec}");
    }
    // A periodic field whose finest octave would hold too many cells.
    let o = zf(
        d,
        &[
            "fill",
            "--count",
            "50",
            "--periodic",
            "--density",
            "noise:value:0.000001:16",
            "-o",
            "bad.svg",
        ],
    );
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(o.stderr.contains("--density") && !d.join("bad.svg").exists(), "{}", o.stderr);
}

#[test]
fn a_density_that_empties_the_region_halts_with_advice() {
    let dir = tmp();
    let d = dir.path();
    let o = zf(
        d,
        &[
            "fill",
            "--count",
            "3000",
            "--c",
            "1.3",
            "--n-offset",
            "3",
            "--seed",
            "2",
            "--max-trials",
            "100000",
            "--density",
            "noise:gradient:40:3:0.5:4",
            "-o",
            "h.json",
        ],
    );
    assert_eq!(o.code, 3, "{}", o.stderr);
    assert!(o.stderr.contains("CONTRAST"), "{}", o.stderr);
    assert!(d.join("h.json").exists());
}
