//! `fill --density`: shapes gather where a noise field is high, with either sampler; the JSON
//! and the `<desc>` command name the field in full; bad fields are refused before any work.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{jpeg_picture, png_picture, tmp, zf, zf_json};
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
    // A picture dark in a small square only, white elsewhere with no floor: the advice names
    // the picture's floor, not the noise's contrast.
    png_picture(&d.join("spot.png"), 40, 40, |x, y| (16..24).contains(&x) && (16..24).contains(&y));
    let o = zf(
        d,
        &[
            "fill",
            "--count",
            "3000",
            "--n-offset",
            "3",
            "--max-trials",
            "100000",
            "--density",
            "image:spot.png",
            "-o",
            "spot.json",
        ],
    );
    assert_eq!(o.code, 3, "{}", o.stderr);
    assert!(o.stderr.contains("floor=F") && !o.stderr.contains("CONTRAST"), "{}", o.stderr);
    assert!(d.join("spot.json").exists());
}

/// Dark means dense: a picture dark on its left half puts every centre there (in a 200 mm
/// square the picture's middle is x = 100; the blend between pixel centres reaches 1.25 mm
/// past it at 80 pixels), `invert` on the right half, in PNG and in JPEG.
#[test]
fn a_picture_draws_where_it_is_dark() {
    let dir = tmp();
    let d = dir.path();
    png_picture(&d.join("left.png"), 80, 60, |x, _| x < 40);
    jpeg_picture(&d.join("left.jpg"), 80, 60, |x, _| x < 40);
    let base = [
        "fill",
        "--count",
        "150",
        "--c",
        "1.3",
        "--n-offset",
        "100",
        "--seed",
        "4",
        "--format",
        "json",
        "-o",
        "-",
    ];
    for (file, invert, left) in [("left.png", false, true), ("left.png", true, false), ("left.jpg", false, true)] {
        let spec = format!("image:{}{}", d.join(file).display(), if invert { ",invert" } else { "" });
        for sampler in ["fast", "reference"] {
            let doc = zf_json(d, &[&base[..], &["--density", &spec, "--sampler", sampler]].concat());
            let c = centres(&doc);
            assert_eq!(c.len(), 150, "{file} {sampler}");
            // JPEG blurs the edge a little: allow a few pixels.
            let edge = if file.ends_with("jpg") { 10.0 } else { 1.25 };
            let wrong = c
                .iter()
                .filter(|&&(x, _)| if left { x > 100.0 + edge } else { x < 100.0 - edge })
                .count();
            assert_eq!(wrong, 0, "{file} invert {invert} {sampler}: {wrong} centres on the light side");
        }
    }
    // The check can fail: without the picture, centres are on both sides.
    let c = centres(&zf_json(d, &base));
    assert!(c.iter().any(|&(x, _)| x > 110.0) && c.iter().any(|&(x, _)| x < 90.0));
}

/// The JSON and the `<desc>` command name the picture and its SHA-256; the command makes the
/// same file again, and refuses once the picture has changed.
#[test]
fn the_picture_is_named_by_its_hash() {
    let dir = tmp();
    let d = dir.path();
    let pic = d.join("p.png");
    png_picture(&pic, 40, 40, |x, y| x + y < 40);
    let spec = format!("image:{},gamma=2,floor=0.05", pic.display());
    let args = ["fill", "--count", "200", "--n-offset", "20", "--density", &spec];
    let doc = zf_json(d, &[&args[..], &["--format", "json", "-o", "-"]].concat());
    let sha = {
        use sha2::{Digest, Sha256};
        Sha256::digest(std::fs::read(&pic).unwrap_or_default())
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect::<String>()
    };
    assert_eq!(doc["params"]["density"], format!("image:{},gamma=2,floor=0.05", pic.display()));
    assert_eq!(doc["params"]["density_sha256"], sha.as_str());
    common::zf_ok(d, &[&args[..], &["-o", "a.svg"]].concat());
    let svg = std::fs::read_to_string(d.join("a.svg")).unwrap_or_default();
    let desc = svg
        .split("<desc>")
        .nth(1)
        .and_then(|s| s.split("</desc>").next())
        .unwrap_or_default()
        .to_string();
    assert!(desc.contains(&format!("--density-sha256 {sha}")), "{desc}");
    let again: Vec<&str> = desc.split_whitespace().skip(1).chain(["-o", "b.svg"]).collect();
    common::zf_ok(d, &again);
    assert_eq!(std::fs::read(d.join("b.svg")).unwrap_or_default(), svg.as_bytes());
    // Change one pixel: the command refuses, naming the flag, and writes nothing.
    png_picture(&pic, 40, 40, |x, y| x + y < 40 || (x, y) == (39, 39));
    let again: Vec<&str> = desc.split_whitespace().skip(1).chain(["-o", "c.svg"]).collect();
    let o = zf(d, &again);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(
        o.stderr.contains("--density-sha256") && o.stderr.contains("changed"),
        "{}",
        o.stderr
    );
    assert!(!d.join("c.svg").exists());
}

#[test]
fn bad_pictures_are_refused_before_any_work() {
    let dir = tmp();
    let d = dir.path();
    std::fs::write(d.join("empty.png"), b"").unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(d.join("notes.txt"), b"not a picture").unwrap_or_else(|e| panic!("{e}"));
    png_picture(&d.join("ok.png"), 4, 4, |_, _| true);
    let p = |f: &str| d.join(f).display().to_string();
    for (spec, flag, says) in [
        (format!("image:{}", p("missing.png")), "--density", "cannot read"),
        (format!("image:{}", p("empty.png")), "--density", "empty"),
        (format!("image:{}", p("notes.txt")), "--density", "not a PNG or JPEG"),
        ("image:/dev/zero".to_string(), "--density", "64 MiB"),
        (format!("image:{},gamma=0", p("ok.png")), "--density", "gamma"),
        (format!("image:{},floor=1", p("ok.png")), "--density", "floor"),
        (format!("image:{},sharp", p("ok.png")), "--density", "unknown option"),
        ("image:".to_string(), "--density", "needs a file"),
    ] {
        let o = zf(d, &["fill", "--count", "20", "--density", &spec, "-o", "bad.svg"]);
        assert_eq!(o.code, 2, "{spec}: {}", o.stderr);
        assert!(o.stderr.contains(flag) && o.stderr.contains(says), "{spec}: {}", o.stderr);
        assert!(!d.join("bad.svg").exists(), "{spec}");
    }
    let o = zf(d, &["fill", "--count", "20", "--density-sha256", "00", "-o", "bad.svg"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(o.stderr.contains("--density-sha256") && !d.join("bad.svg").exists(), "{}", o.stderr);
}

/// Bug pinned here: a density that is zero everywhere (an all-white picture, or a noise that
/// never rises above 0.5 - 0.5/CONTRAST over the region) was blamed on `--c`: "the first
/// circle ... does not fit; lower --c or raise --n-offset". The density is named now: at once
/// for a picture, and after the fill placed nothing for noise. The controls: the same picture
/// with a floor, and the same noise at another seed, fill.
#[test]
fn a_density_zero_everywhere_is_named_not_c() {
    let dir = tmp();
    let d = dir.path();
    png_picture(&d.join("white.png"), 8, 8, |_, _| false);
    png_picture(&d.join("black.png"), 8, 8, |_, _| true);
    let refused = [
        vec!["--c", "1.05", "--n-offset", "1000", "--density", "image:white.png"],
        vec!["--density", "image:black.png,invert"],
        vec![
            "--region",
            "rect:1:1",
            "--density",
            "noise:value:1000:1:0.5:50",
            "--seed",
            "4",
            "--max-trials",
            "20000",
        ],
    ];
    for args in &refused {
        let mut a = vec!["fill", "-q", "--count", "10"];
        a.extend(args);
        a.extend(["-o", "w.svg"]);
        let o = zf(d, &a);
        assert_eq!(o.code, 2, "{a:?}: {}", o.stderr);
        assert!(
            o.stderr.starts_with("error: --density: ") && !o.stderr.contains("--c"),
            "{a:?}: {}",
            o.stderr
        );
        assert!(!d.join("w.svg").exists(), "{a:?} wrote a file");
    }
    for args in [
        vec!["--density", "image:white.png,floor=0.2"],
        vec!["--region", "rect:1:1", "--density", "noise:value:1000:1:0.5:50", "--seed", "1"],
    ] {
        let mut a = vec!["fill", "-q", "--count", "10"];
        a.extend(args);
        a.extend(["-o", "ok.svg"]);
        let o = zf(d, &a);
        assert_eq!(o.code, 0, "{a:?}: {}", o.stderr);
    }
}
