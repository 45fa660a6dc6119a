//! `fill --region mask:FILE` and `--region text:STRING`: a picture's dark areas and a text's
//! letters as regions. The traced rings keep the picture's holes and stay within half a pixel
//! of the marching-squares contour; shapes stay in the dark (checked against the rings with an
//! even-odd test written here); every output format works; the `<desc>` command reproduces
//! the file byte for byte and refuses a changed input; bad inputs exit 2 naming their flag.
//! The tests draw their own pictures.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{jpeg_picture, png_picture, tmp, zf, zf_json, zf_ok};
use serde_json::Value;
use std::path::{Path, PathBuf};
use zetafill::Point;
use zetafill_cli::geometry::{simplify, trace};

/// Whether pixel `(x, y)` (its centre) is in the annulus of radii 40 and 90 about (100, 100).
fn in_annulus(x: f64, y: f64) -> bool {
    let r = (x + 0.5 - 100.0).hypot(y + 0.5 - 100.0);
    r > 40.0 && r < 90.0
}

/// An annulus of radii 40 and 90 pixels about the centre of a 200 x 200 picture.
fn annulus(dir: &Path) -> PathBuf {
    let p = dir.join("annulus.png");
    png_picture(&p, 200, 200, |x, y| in_annulus(f64::from(x), f64::from(y)));
    p
}

/// A fill of `--region REGION` (a picture in `d`) with `args`, as JSON.
fn mask_fill(d: &Path, region: &str, args: &[&str]) -> Value {
    let base = ["fill", "--region", region, "--n-offset", "5", "--format", "json", "-o", "-"];
    zf_json(d, &[&base[..], args].concat())
}

/// The shipped font file.
fn shipped_font() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/fonts/DejaVuSans-Bold.ttf")
}

fn rings_of(doc: &Value, key: &str) -> Vec<Vec<[f64; 2]>> {
    let ring = |r: &Value| r.as_array().map(|a| a.iter().map(common::pt).collect()).unwrap_or_default();
    match key {
        "vertices" => vec![ring(&doc["region"]["vertices"])],
        k => doc["region"][k]
            .as_array()
            .map(|a| a.iter().map(ring).collect())
            .unwrap_or_default(),
    }
}

/// Every ring of the region: the outlines, then the holes.
fn all_rings(doc: &Value) -> Vec<Vec<[f64; 2]>> {
    ["vertices", "outers", "holes"].iter().flat_map(|k| rings_of(doc, k)).collect()
}

/// Whether `p` is inside the rings by the even-odd rule (a ray to the right, counting edges
/// it crosses).
fn inside(rings: &[Vec<[f64; 2]>], p: [f64; 2]) -> bool {
    let mut odd = false;
    for r in rings {
        for k in 0..r.len() {
            let (a, b) = (r[k], r[(k + 1) % r.len()]);
            if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
                odd = !odd;
            }
        }
    }
    odd
}

/// The circles of a fill that stray outside the rings (64 points of each rim tested) or
/// overlap another: one message each.
fn strays(doc: &Value, rings: &[Vec<[f64; 2]>]) -> Vec<String> {
    let circles: Vec<([f64; 2], f64)> = common::shapes(doc)
        .iter()
        .map(|s| (common::pt(&s["center"]), common::f(s, "radius")))
        .collect();
    let mut bad = Vec::new();
    for (i, &(c, r)) in circles.iter().enumerate() {
        let rim = (0..64).map(|k| {
            let t = f64::from(k) / 64.0 * std::f64::consts::TAU;
            [c[0] + r * t.cos(), c[1] + r * t.sin()]
        });
        if !inside(rings, c) || rim.into_iter().any(|p| !inside(rings, p)) {
            bad.push(format!("circle {i} at {c:?} (r {r}) leaves the region"));
        }
        for (j, &(d, s)) in circles.iter().enumerate().skip(i + 1) {
            if (c[0] - d[0]).hypot(c[1] - d[1]) < r + s - 1e-9 {
                bad.push(format!("circles {i} and {j} overlap"));
            }
        }
    }
    bad
}

#[test]
fn an_annulus_traces_to_one_outline_and_one_hole_of_its_area() {
    let dir = tmp();
    let d = dir.path();
    annulus(d);
    let doc = mask_fill(d, "mask:annulus.png", &["--count", "200"]);
    assert_eq!((rings_of(&doc, "outers").len(), rings_of(&doc, "holes").len()), (0, 1));
    // One pixel is 1 mm: the traced area is the analytic one within half a pixel along the
    // two rims.
    let area = |rings: &[Vec<[f64; 2]>]| rings[0..1].iter().map(|r| common::shoelace(r)).sum::<f64>() - common::shoelace(&rings[1]);
    let near = |a: f64, outer: f64, inner: f64| {
        let exact = std::f64::consts::PI * (outer * outer - inner * inner);
        (a - exact).abs() <= 0.5 * std::f64::consts::TAU * (outer + inner)
    };
    let traced = area(&all_rings(&doc));
    assert!(near(traced, 90.0, 40.0), "{traced}");
    // The check can fail: a rim a pixel and a half out is too far.
    assert!(!near(traced, 91.5, 40.0));
    let p = &doc["params"];
    assert_eq!(
        (p["region"].as_str(), p["region_width"].as_f64()),
        (Some("mask:annulus.png:0.5"), Some(200.0))
    );
    assert_eq!(p["region_sha256"].as_str().map(str::len), Some(64));
    // The same picture as a JPEG traces to the same two rings, within its compression's blur.
    jpeg_picture(&d.join("annulus.jpg"), 200, 200, |x, y| in_annulus(f64::from(x), f64::from(y)));
    let jpeg = mask_fill(d, "mask:annulus.jpg", &["--count", "50"]);
    assert_eq!((rings_of(&jpeg, "outers").len(), rings_of(&jpeg, "holes").len()), (0, 1));
    assert!(near(area(&all_rings(&jpeg)), 90.0, 40.0));
    // Half the width, half the sizes.
    let small = mask_fill(d, "mask:annulus.png", &["--region-width", "100", "--count", "50"]);
    assert!(near(area(&all_rings(&small)) * 4.0, 90.0, 40.0));
}

#[test]
fn every_traced_vertex_lies_within_half_a_pixel_of_its_simplified_ring() {
    let dir = tmp();
    let grey = zetafill_cli::io::image::read_grey(&annulus(dir.path())).unwrap_or_else(|e| panic!("{e}"));
    let raw = trace::trace(&grey.luma, grey.width, grey.height, 0.5, usize::MAX).unwrap_or_default();
    assert_eq!(raw.ends.len(), 2);
    let far = |simple: &trace::Rings| {
        raw.iter()
            .zip(simple.iter())
            .flat_map(|(r, s)| {
                r.iter().map(move |&p| {
                    (0..s.len())
                        .map(|k| simplify::segment_distance(p, s[k], s[(k + 1) % s.len()]))
                        .fold(f64::MAX, f64::min)
                })
            })
            .fold(0.0, f64::max)
    };
    let simple = simplify::simplify(&raw, 0.5);
    assert!(far(&simple) <= 0.5, "{}", far(&simple));
    assert!(
        simple.points.len() * 2 < raw.points.len(),
        "{} of {}",
        simple.points.len(),
        raw.points.len()
    );
    let rings: Vec<Vec<Point<f64>>> = simple.iter().map(<[_]>::to_vec).collect();
    assert_eq!(simplify::crossing_rings(&rings), [false, false]);
    // The core accepts the rings as one region.
    let mut scratch = Vec::new();
    assert!(zetafill_cli::model::region::polygon_region(&simple.points, &simple.ends, &mut scratch).is_ok());
    // The check can fail: simplified at 3 pixels, vertices stray beyond half a pixel.
    let coarse = simplify::simplify(&raw, 3.0);
    assert!(far(&coarse) > 0.5);
}

#[test]
fn a_fill_on_a_mask_keeps_out_of_the_hole_and_the_light() {
    let dir = tmp();
    let d = dir.path();
    annulus(d);
    let doc = mask_fill(d, "mask:annulus.png", &["--count", "600"]);
    let rings = all_rings(&doc);
    assert_eq!(common::shapes(&doc).len(), 600);
    assert_eq!(strays(&doc, &rings), Vec::<String>::new());
    // Independently of the traced rings: every circle within the analytic annulus, a pixel's
    // tolerance.
    for s in common::shapes(&doc) {
        let (c, r) = (common::pt(&s["center"]), common::f(s, "radius"));
        let dist = (c[0] - 100.0).hypot(c[1] - 100.0);
        assert!(dist - r > 39.0 && dist + r < 91.0, "{c:?} {r}");
    }
    // The check can fail: a circle moved into the hole strays.
    let mut moved = doc.clone();
    moved["shapes"][0]["center"] = serde_json::json!([100.0, 100.0]);
    assert!(!strays(&moved, &rings).is_empty());
}

#[test]
fn letters_keep_their_holes_with_the_built_in_font_and_a_font_file() {
    let dir = tmp();
    let d = dir.path();
    let run = |args: &[&str]| {
        zf_json(
            d,
            &[&["fill", "--count", "100", "--n-offset", "30", "--format", "json", "-o", "-"], args].concat(),
        )
    };
    let o = run(&["--region", "text:O"]);
    assert_eq!((rings_of(&o, "outers").len(), rings_of(&o, "holes").len()), (0, 1));
    assert_eq!(o["params"]["text_size"].as_f64(), Some(50.0));
    assert!(o["params"].get("font").is_none());
    let zeta = run(&["--region", "text:zeta"]);
    // z, e (with its hole), t, a (with its hole).
    assert_eq!((rings_of(&zeta, "outers").len() + 1, rings_of(&zeta, "holes").len()), (4, 2));
    // The shipped file is the built-in font: the same letters, the file named.
    let font = shipped_font();
    let font = font.to_str().unwrap_or_default();
    let named = run(&["--region", "text:zeta", "--font", font]);
    assert_eq!(named["region"], zeta["region"]);
    assert_eq!(named["params"]["font"].as_str(), Some(font));
    assert_eq!(named["params"]["font_sha256"].as_str().map(str::len), Some(64));
    // Another face of the family, when the system has it, makes other letters.
    let other = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    if Path::new(other).exists() {
        let book = run(&["--region", "text:zeta", "--font", other]);
        assert_ne!(book["region"], zeta["region"]);
    }
    // Two lines, spaced letters, a larger size: all inside their letters.
    let two = run(&["--region", "text:ab\\ncd", "--text-size", "80", "--letter-spacing", "2"]);
    assert_eq!(two["params"]["region"].as_str(), Some("text:ab\\ncd"));
    assert_eq!(two["params"]["letter_spacing"].as_f64(), Some(2.0));
    assert_eq!(strays(&two, &all_rings(&two)), Vec::<String>::new());
}

#[test]
fn every_output_format_takes_a_mask_and_a_text() {
    let dir = tmp();
    let d = dir.path();
    annulus(d);
    for region in [
        &["--region", "mask:annulus.png", "--n-offset", "5"][..],
        &["--region", "text:zeta", "--n-offset", "30"],
    ] {
        for ext in ["svg", "png", "json", "csv", "gcode"] {
            let out = format!("out.{ext}");
            zf_ok(d, &[&["fill", "--count", "150", "-q", "-o", out.as_str()], region].concat());
            let bytes = std::fs::read(d.join(&out)).unwrap_or_default();
            assert!(bytes.len() > 100, "{region:?} {ext}: {} bytes", bytes.len());
        }
    }
}

/// The words of a command as a POSIX shell splits them (spaces, single quotes, and a
/// backslash outside them).
fn shell_words(line: &str) -> Vec<String> {
    let (mut words, mut word, mut quoted, mut any) = (Vec::new(), String::new(), false, false);
    let mut chars = line.chars();
    while let Some(c) = chars.next() {
        match c {
            '\\' if !quoted => {
                word.extend(chars.next());
                any = true;
            }
            '\'' => {
                quoted = !quoted;
                any = true;
            }
            ' ' if !quoted => {
                if any {
                    words.push(std::mem::take(&mut word));
                }
                any = false;
            }
            c => {
                word.push(c);
                any = true;
            }
        }
    }
    if any {
        words.push(word);
    }
    words
}

/// The `<desc>` of an SVG, unescaped.
fn desc(svg: &[u8]) -> String {
    let text = String::from_utf8_lossy(svg);
    let start = text.find("<desc>").map_or(0, |i| i + 6);
    let end = text.find("</desc>").unwrap_or(start);
    text[start..end]
        .replace("&apos;", "'")
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// Runs the command of `desc` writing `out`; its exit and the bytes written.
fn rerun(d: &Path, desc: &str, out: &str) -> (common::Out, Vec<u8>) {
    let words = shell_words(desc);
    let mut args: Vec<&str> = words.iter().skip(1).map(String::as_str).collect();
    args.extend(["-o", out]);
    let o = zf(d, &args);
    (o, std::fs::read(d.join(out)).unwrap_or_default())
}

#[test]
fn the_desc_command_reproduces_the_file_and_refuses_a_changed_input() {
    let dir = tmp();
    let d = dir.path();
    annulus(d);
    std::fs::copy(shipped_font(), d.join("my font.ttf")).unwrap_or_else(|e| panic!("{e}"));
    let cases: [(&[&str], &str); 3] = [
        (
            &["--region", "mask:annulus.png:0.4", "--region-width", "150", "--n-offset", "5"],
            "annulus.png",
        ),
        (
            &[
                "--region",
                "text:it's a\\nzeta",
                "--font",
                "my font.ttf",
                "--letter-spacing",
                "1",
                "--n-offset",
                "40",
            ],
            "my font.ttf",
        ),
        (&["--region", "text:Oz", "--text-size", "30", "--n-offset", "40"], ""),
    ];
    for (args, input) in cases {
        zf_ok(
            d,
            &[&["fill", "--count", "150", "--style", "filled", "-q", "-o", "a.svg"], args].concat(),
        );
        let first = std::fs::read(d.join("a.svg")).unwrap_or_default();
        let command = desc(&first);
        let (o, again) = rerun(d, &command, "b.svg");
        assert_eq!(o.code, 0, "{command}: {}", o.stderr);
        assert!(first == again, "{command}: other bytes");
        // The check can fail: another text or threshold makes another file.
        let (_, other) = rerun(
            d,
            &command.replace(":0.4 ", ":0.45 ").replace("zeta", "zeal").replace(":Oz", ":Ox"),
            "c.svg",
        );
        assert!(!other.is_empty() && first != other, "{command}");
        if input.is_empty() {
            assert!(!command.contains("--font"), "{command}");
            continue;
        }
        // A changed input is refused, naming the flag of its digest, and nothing is written.
        let saved = std::fs::read(d.join(input)).unwrap_or_default();
        if input.ends_with(".png") {
            png_picture(&d.join(input), 200, 200, |x, y| x > 20 && y > 20 && x < 180 && y < 180);
        } else {
            std::fs::write(d.join(input), [&saved[..], &[0]].concat()).unwrap_or_else(|e| panic!("{e}"));
        }
        let (o, written) = rerun(d, &command, "changed.svg");
        let flag = if input.ends_with(".png") {
            "--region-sha256"
        } else {
            "--font-sha256"
        };
        assert_eq!(o.code, 2, "{command}");
        assert!(common::names_flag(&o.stderr, flag), "{}", o.stderr);
        assert!(written.is_empty());
        std::fs::write(d.join(input), &saved).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn bad_masks_fonts_and_texts_exit_2_naming_their_flag() {
    let dir = tmp();
    let d = dir.path();
    let keep = d.join("keep");
    std::fs::create_dir(&keep).unwrap_or_else(|e| panic!("{e}"));
    let path = |name: &str| keep.join(name).to_string_lossy().into_owned();
    png_picture(&keep.join("white.png"), 40, 40, |_, _| false);
    png_picture(&keep.join("specks.png"), 40, 40, |x, y| x % 10 == 5 && y % 10 == 5);
    png_picture(&keep.join("dot.png"), 40, 40, |x, y| x > 10 && x < 30 && y > 10 && y < 30);
    std::fs::write(keep.join("empty.png"), b"").unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(keep.join("notes.txt"), b"not a picture, nor a font").unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(keep.join("empty.ttf"), b"").unwrap_or_else(|e| panic!("{e}"));
    let mask = |name: &str| format!("mask:{}", path(name));
    let (white, specks, dot, empty, notes) = (
        mask("white.png"),
        mask("specks.png"),
        mask("dot.png"),
        mask("empty.png"),
        mask("notes.txt"),
    );
    let (missing, no_font, empty_font) = (mask("missing.png"), path("notes.txt"), path("empty.ttf"));
    let (bad_threshold, nowhere) = (format!("{dot}:1.5"), path("nowhere.ttf"));
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--region", missing.as_str(), "-o", "out.json"], "--region"),
        (vec!["--region", empty.as_str(), "-o", "out.json"], "--region"),
        (vec!["--region", notes.as_str(), "-o", "out.json"], "--region"),
        (vec!["--region", "mask:/dev/zero", "-o", "out.json"], "--region"),
        (vec!["--region", white.as_str(), "-o", "out.json"], "--region"),
        (vec!["--region", specks.as_str(), "-o", "out.json"], "--region"),
        (
            vec!["--region", dot.as_str(), "--region-sha256", "00", "-o", "out.json"],
            "--region-sha256",
        ),
        (vec!["--region", bad_threshold.as_str(), "-o", "out.json"], "--region"),
        (vec!["--region", "text:", "-o", "out.json"], "--region"),
        (vec!["--region", "text:   ", "-o", "out.json"], "--region"),
        (vec!["--region", "text:a\u{e000}", "-o", "out.json"], "--region"),
        (vec!["--region", "text:a", "--font", no_font.as_str(), "-o", "out.json"], "--font"),
        (
            vec!["--region", "text:a", "--font", empty_font.as_str(), "-o", "out.json"],
            "--font",
        ),
        (vec!["--region", "text:a", "--font", nowhere.as_str(), "-o", "out.json"], "--font"),
        (vec!["--region", "text:a", "--font-sha256", "00", "-o", "out.json"], "--font-sha256"),
        (
            vec!["--region", "text:a", "--region-width", "100", "-o", "out.json"],
            "--region-width",
        ),
        (
            vec!["--region", "text:a", "--region-sha256", "00", "-o", "out.json"],
            "--region-sha256",
        ),
        (
            vec!["--region", dot.as_str(), "--font", no_font.as_str(), "-o", "out.json"],
            "--font",
        ),
        (vec!["--region", dot.as_str(), "--text-size", "20", "-o", "out.json"], "--text-size"),
        (
            vec!["--region", dot.as_str(), "--letter-spacing", "1", "-o", "out.json"],
            "--letter-spacing",
        ),
        (vec!["--text-size", "20", "-o", "out.json"], "--text-size"),
        (vec!["--region-width", "20", "-o", "out.json"], "--region-width"),
        (
            vec!["--region", "circle:50", "--font", no_font.as_str(), "-o", "out.json"],
            "--font",
        ),
        (vec!["--region", "text:a", "--text-size", "0", "-o", "out.json"], "--text-size"),
        (vec!["--region", dot.as_str(), "--periodic", "-o", "out.json"], "--periodic"),
        (
            vec!["--region", "text:zetafill zetafill", "--text-size", "200000", "-o", "out.json"],
            "--text-size",
        ),
    ];
    // The pictures and fonts live in keep/; the run's folder holds only out.json.
    let run_dir = tmp();
    let out = run_dir.path().join("out.json");
    std::fs::write(&out, b"keep").unwrap_or_else(|e| panic!("{e}"));
    for (args, flag) in &cases {
        let all = [&["fill", "--count", "20"][..], &args[..]].concat();
        let o = zf(run_dir.path(), &all);
        assert_eq!(o.code, 2, "{all:?}: {}", o.stderr);
        assert!(common::names_flag(&o.stderr, flag), "{all:?} should name {flag}: {}", o.stderr);
        assert_eq!(std::fs::read(&out).unwrap_or_default(), b"keep");
    }
    assert_eq!(common::listing(run_dir.path()), vec![out]);
    // The checker can fail: a good mask writes its file.
    let o = zf(run_dir.path(), &["fill", "--count", "20", "--region", &dot, "-o", "good.json"]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(run_dir.path().join("good.json").exists());
}

/// Bug pinned here: a tiny `--text-size` or `--region-width` blamed something else: 1e-300
/// said the font's outline of 'a' was not simple, or that the outline enclosed no area, and
/// 1e-100 spent 10^7 trials and blamed `--c`. Below 1e-6 mm both are refused naming their
/// flag and the smallest size that works; at 1e-6 mm the fill runs (the control).
#[test]
fn tiny_text_and_mask_sizes_name_their_flag() {
    let dir = tmp();
    let d = dir.path();
    png_picture(&d.join("m.png"), 40, 40, |x, y| {
        (x as i32 - 20).pow(2) + (y as i32 - 20).pow(2) < 200
    });
    let fill = ["fill", "-q", "--count", "100", "--c", "1.25", "--n-offset", "30"];
    for (flag, region) in [("--text-size", "text:ab"), ("--region-width", "mask:m.png")] {
        for size in ["1e-300", "1e-100", "9e-7"] {
            let mut a = fill.to_vec();
            a.extend(["--region", region, flag, size, "-o", "t.svg"]);
            let o = zf(d, &a);
            assert_eq!(o.code, 2, "{a:?}: {}", o.stderr);
            assert!(
                o.stderr.starts_with(&format!("error: {flag}: ")) && o.stderr.contains("at least 0.000001 mm"),
                "{a:?}: {}",
                o.stderr
            );
            assert!(!d.join("t.svg").exists());
        }
        let mut a = fill.to_vec();
        a.extend(["--region", region, flag, "1e-6", "-o", "t.json"]);
        let o = zf(d, &a);
        assert_eq!(o.code, 0, "{a:?}: {}", o.stderr);
    }
}
