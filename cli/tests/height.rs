//! Height maps (`fill --relief`): the 16-bit PNG is decoded with the `png` crate and compared
//! pixel by pixel with a map built here from the JSON of the same run, by brute force (every
//! sample point against every shape and every periodic image, with geometry written for this
//! test); plus the physical meaning (a circle's dome is a hemisphere, nothing outside the
//! region), the text chunks, reproduction from the embedded command, and bad input.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use serde_json::Value;
use std::path::Path;

/// Samples per pixel along each axis (the format's documented 4 x 4).
const SUB: usize = 4;

/// A decoded 16-bit greyscale PNG and its text chunks.
struct Map {
    w: usize,
    h: usize,
    px: Vec<u16>,
    text: Vec<(String, String)>,
}

fn decode(bytes: &[u8]) -> Map {
    let mut reader = png::Decoder::new(bytes).read_info().unwrap_or_else(|e| panic!("not a PNG: {e}"));
    let mut buf = vec![0u8; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).unwrap_or_else(|e| panic!("bad PNG data: {e}"));
    assert_eq!(frame.color_type, png::ColorType::Grayscale, "a height map is greyscale");
    assert_eq!(frame.bit_depth, png::BitDepth::Sixteen, "a height map has 16-bit samples");
    let px = buf[..frame.buffer_size()]
        .chunks(2)
        .map(|c| u16::from_be_bytes([c[0], c[1]]))
        .collect();
    let text = reader
        .info()
        .uncompressed_latin1_text
        .iter()
        .map(|t| (t.keyword.clone(), t.text.clone()))
        .collect();
    Map {
        w: frame.width as usize,
        h: frame.height as usize,
        px,
        text,
    }
}

impl Map {
    fn text(&self, key: &str) -> &str {
        self.text
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
            .unwrap_or_else(|| panic!("no {key} text chunk"))
    }
}

/// A shape of the JSON, with the depth of a point inside it (its distance to the outline).
enum Solid {
    Disc { c: [f64; 2], r: f64 },
    Ring { c: [f64; 2], r: f64, inner: f64 },
    Poly { vs: Vec<[f64; 2]> },
}

/// Winding number of the closed polygon `vs` around `p`.
fn winding(p: [f64; 2], vs: &[[f64; 2]]) -> i32 {
    let mut wn = 0;
    for (i, a) in vs.iter().enumerate() {
        let b = vs[(i + 1) % vs.len()];
        let cross = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
        if a[1] <= p[1] && b[1] > p[1] && cross > 0.0 {
            wn += 1;
        } else if a[1] > p[1] && b[1] <= p[1] && cross < 0.0 {
            wn -= 1;
        }
    }
    wn
}

impl Solid {
    fn of(s: &Value) -> Solid {
        let c = pt(&s["center"]);
        match (s["radius"].as_f64(), s["inner_radius"].as_f64()) {
            (Some(r), None) => Solid::Disc { c, r },
            (Some(r), Some(inner)) => Solid::Ring { c, r, inner },
            _ => Solid::Poly {
                vs: s["vertices"]
                    .as_array()
                    .unwrap_or_else(|| panic!("no vertices"))
                    .iter()
                    .map(pt)
                    .collect(),
            },
        }
    }

    fn depth(&self, p: [f64; 2]) -> Option<f64> {
        let d = match self {
            Solid::Disc { c, r } => r - (p[0] - c[0]).hypot(p[1] - c[1]),
            Solid::Ring { c, r, inner } => {
                let e = (p[0] - c[0]).hypot(p[1] - c[1]);
                (r - e).min(e - inner)
            }
            Solid::Poly { vs } => {
                if winding(p, vs) == 0 {
                    return None;
                }
                (0..vs.len())
                    .map(|i| seg_dist(p, vs[i], vs[(i + 1) % vs.len()]))
                    .fold(f64::INFINITY, f64::min)
            }
        };
        (d > 0.0).then_some(d)
    }

    /// The depth of the deepest point: the radius, half the band, the polygon's centre.
    fn deepest(&self, centre: [f64; 2]) -> f64 {
        match self {
            Solid::Disc { r, .. } => *r,
            Solid::Ring { r, inner, .. } => 0.5 * (r - inner),
            Solid::Poly { .. } => self.depth(centre).unwrap_or(0.0),
        }
    }
}

fn profile(relief: &str, d: f64, rho: f64) -> f64 {
    let s = d.min(rho);
    match relief {
        "dome" => (s * (2.0 * rho - s)).sqrt(),
        "cone" => s,
        "flat" => rho,
        other => panic!("unknown relief {other}"),
    }
}

/// The region's bounding box from the JSON.
fn bbox(doc: &Value) -> (f64, f64, f64, f64) {
    let r = &doc["region"];
    match s(r, "kind") {
        "rect" => (0.0, 0.0, f(r, "width"), f(r, "height")),
        "circle" => {
            let rad = f(r, "radius");
            (0.0, 0.0, 2.0 * rad, 2.0 * rad)
        }
        "annulus" => {
            let rad = f(r, "radius_outer");
            (0.0, 0.0, 2.0 * rad, 2.0 * rad)
        }
        other => panic!("region {other} not used here"),
    }
}

/// The height map of the JSON document `doc`, `w` x `h` pixels, by brute force: each of a
/// pixel's 4 x 4 sample points is tested against every shape and, when periodic, its eight
/// images.
fn expected(doc: &Value, relief: &str, w: usize, h: usize) -> Vec<u16> {
    let (x0, y0, x1, y1) = bbox(doc);
    let periodic = doc["region"]["periodic"].as_bool().unwrap_or(false);
    let stones: Vec<(Solid, f64)> = shapes(doc)
        .iter()
        .map(|sh| {
            let solid = Solid::of(sh);
            let rho = solid.deepest(pt(&sh["center"]));
            (solid, rho)
        })
        .collect();
    let top = stones.iter().map(|(_, rho)| profile(relief, *rho, *rho)).fold(0.0, f64::max);
    let (pw, ph) = (x1 - x0, y1 - y0);
    let shifts = period_shifts(periodic, pw, ph);
    let (sw, sh) = (pw / (SUB * w) as f64, ph / (SUB * h) as f64);
    let mut out = Vec::with_capacity(w * h);
    for j in 0..h {
        for i in 0..w {
            let mut sum = 0.0;
            for b in 0..SUB {
                for a in 0..SUB {
                    let x = x0 + ((i * SUB + a) as f64 + 0.5) * sw;
                    let y = y1 - ((j * SUB + b) as f64 + 0.5) * sh;
                    let hit = stones.iter().find_map(|(solid, rho)| {
                        shifts
                            .iter()
                            .find_map(|(dx, dy)| solid.depth([x - dx, y - dy]).map(|d| profile(relief, d, *rho)))
                    });
                    sum += hit.unwrap_or(0.0);
                }
            }
            out.push((sum / (SUB * SUB) as f64 / top * 65535.0).round() as u16);
        }
    }
    out
}

/// Whether `got` equals `want` pixel for pixel, up to one unit (sums in another order may
/// round the other way at an exact half).
fn compare(want: &[u16], got: &Map) -> Result<(), String> {
    if want.len() != got.px.len() {
        return Err(format!("{} pixels, expected {}", got.px.len(), want.len()));
    }
    for (k, (&a, &b)) in want.iter().zip(got.px.iter()).enumerate() {
        if a.abs_diff(b) > 1 {
            return Err(format!("pixel ({}, {}) is {b}, expected {a}", k % got.w, k / got.w));
        }
    }
    Ok(())
}

/// Runs the fill twice, as a height map and as JSON, and checks the map against the JSON.
fn check_case(dir: &Path, args: &[&str], relief: &str, pixels: &str, size: (usize, usize)) -> (Map, Value) {
    let mut a = args.to_vec();
    a.extend_from_slice(&["--relief", relief, "--pixels", pixels]);
    let map = decode(&fill_to(dir, "h.png", &a));
    let doc = fill_json(dir, args);
    assert_eq!((map.w, map.h), size, "{args:?}: image size");
    compare(&expected(&doc, relief, map.w, map.h), &map).unwrap_or_else(|e| panic!("{args:?} --relief {relief}: {e}"));
    (map, doc)
}

#[test]
fn height_maps_match_a_brute_force_rendering() {
    let dir = tmp();
    // Circles on a torus (the map tiles: shapes across an edge show on both sides).
    check_case(
        dir.path(),
        &["--count", "150", "--periodic", "--seed", "3", "-q"],
        "dome",
        "96",
        (96, 96),
    );
    // Concave stars in a disc, cones.
    check_case(
        dir.path(),
        &[
            "--shape",
            "star:5:0.45",
            "--c",
            "1.2",
            "--n-offset",
            "3",
            "--region",
            "circle:50",
            "--count",
            "120",
            "-q",
        ],
        "cone",
        "80",
        (80, 80),
    );
    // Rings (stones with a hole) and rotated squares in a wide rectangle, flat tops.
    check_case(
        dir.path(),
        &[
            "--shape",
            "mix:ring:0.6,square",
            "--c",
            "1.25",
            "--n-offset",
            "2",
            "--region",
            "rect:200:120",
            "--count",
            "150",
            "-q",
        ],
        "flat",
        "100",
        (100, 60),
    );
}

#[test]
fn the_checker_catches_a_wrong_map() {
    let dir = tmp();
    let args = ["--count", "60", "--seed", "2", "-q"];
    let (map, doc) = check_case(dir.path(), &args, "dome", "64", (64, 64));
    let want = expected(&doc, "dome", map.w, map.h);
    // One pixel off by two units.
    let mut bad = Map {
        w: map.w,
        h: map.h,
        px: map.px.clone(),
        text: Vec::new(),
    };
    bad.px[1000] = bad.px[1000].wrapping_add(2);
    assert!(compare(&want, &bad).is_err(), "a changed pixel must be caught");
    // The map of a run whose first circle sits 1 mm away.
    let mut moved = doc.clone();
    let x = pt(&moved["shapes"][0]["center"])[0];
    moved["shapes"][0]["center"][0] = serde_json::json!(x + 1.0);
    assert!(
        compare(&expected(&moved, "dome", map.w, map.h), &map).is_err(),
        "a moved shape must be caught"
    );
    // The wrong profile.
    assert!(
        compare(&expected(&doc, "cone", map.w, map.h), &map).is_err(),
        "another profile must be caught"
    );
}

#[test]
fn domes_are_hemispheres_and_the_outside_is_the_floor() {
    let dir = tmp();
    let args = ["--count", "80", "--region", "circle:60", "-q"];
    let (map, doc) = check_case(dir.path(), &args, "dome", "120", (120, 120));
    // White is the largest circle's radius, in mm.
    let r0 = f(&shapes(&doc)[0], "radius");
    let comment = map.text("Comment");
    let white: f64 = comment
        .split("white (65535) is ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("comment without the height of white: {comment}"));
    assert!((white - r0).abs() < 1e-5, "white is {white} mm, the first radius {r0}");
    // Every circle's top: the pixel holding its centre stands at its radius (a hemisphere's
    // height), to within the dome's fall across a pixel.
    let px = 120.0 / 120.0;
    for sh in shapes(&doc) {
        let r = f(sh, "radius");
        if r < 3.0 * px {
            continue;
        }
        let [cx, cy] = pt(&sh["center"]);
        let (i, j) = ((cx / px) as usize, ((120.0 - cy) / px) as usize);
        let got = f64::from(map.px[j * map.w + i]) / 65535.0 * white;
        let fall = r - (r * r - 2.0 * px * px).sqrt();
        assert!(got <= r + 1e-3 && got >= r - fall - 1e-3, "circle of radius {r}: top at {got} mm");
    }
    // Outside the disc region: the floor.
    for (i, j) in [(0, 0), (119, 0), (0, 119), (119, 119)] {
        assert_eq!(map.px[j * map.w + i], 0, "corner ({i}, {j}) lies outside the region");
    }
}

#[test]
fn the_embedded_command_reproduces_the_map() {
    let dir = tmp();
    let bytes = fill_to(
        dir.path(),
        "a.png",
        &["--shape", "triangle", "--count", "100", "--relief", "cone", "--dpi", "40", "-q"],
    );
    let map = decode(&bytes);
    let command = map.text("Description").to_string();
    assert!(command.starts_with("zetafill fill ") && command.contains("--relief cone") && command.contains("--dpi 40"));
    let mut args: Vec<&str> = command.split_whitespace().skip(1).collect();
    args.extend_from_slice(&["-q", "-o", "b.png"]);
    zf_ok(dir.path(), &args);
    assert_eq!(read(&dir.path().join("b.png")), bytes, "{command}");
    // 200 mm at 40 pixels per inch.
    assert_eq!((map.w, map.h), (315, 315));
}

#[test]
fn height_map_flags_are_refused_where_they_mean_nothing() {
    let cases: [(&[&str], &str); 7] = [
        (&["--relief", "dome", "-o", "x.svg"], "--relief"),
        (&["--pixels", "64", "-o", "x.json"], "--pixels"),
        (&["--relief", "dome", "--voronoi", "-o", "keep.png"], "--relief"),
        (&["--relief", "dome", "--page", "a4", "-o", "keep.png"], "--page"),
        (&["--relief", "dome", "--pixels", "100000", "-o", "keep.png"], "--pixels"),
        (&["--relief", "dome", "--pixels", "0", "-o", "keep.png"], "--pixels"),
        (&["--relief", "dome", "--pixels", "64", "--dpi", "50", "-o", "keep.png"], "--pixels"),
    ];
    assert_fill_refuses("keep.png", &cases);
}

#[test]
fn pixels_sizes_every_png_and_is_refused_elsewhere() {
    let dir = tmp();
    let size = |args: &[&str]| {
        let mut a = args.to_vec();
        a.extend_from_slice(&["--pixels", "300", "-q", "-o", "p.png"]);
        zf_ok(dir.path(), &a);
        let bytes = read(&dir.path().join("p.png"));
        let img = png::Decoder::new(&bytes[..]).read_info().unwrap_or_else(|e| panic!("{e}"));
        (img.info().width, img.info().height)
    };
    assert_eq!(size(&["fill", "--region", "rect:200:100", "--count", "50"]), (300, 150));
    assert_eq!(size(&["fill", "--count", "50", "--voronoi"]), (300, 300));
    assert_eq!(size(&["tile"]), (300, 300));
    assert_eq!(size(&["territory", "--points", "300"]), (300, 300));
    assert_eq!(size(&["line", "--count", "50"]).0, 300);
    for cmd in ["line", "territory", "tile"] {
        let o = zf(dir.path(), &[cmd, "--pixels", "64", "-o", "x.svg"]);
        assert_eq!(o.code, 2, "{cmd}: {}", o.stderr);
        assert!(o.stderr.contains("--pixels"), "{cmd}: {}", o.stderr);
        assert!(!dir.path().join("x.svg").exists(), "{cmd} wrote a file");
    }
}
