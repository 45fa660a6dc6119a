//! Shared helpers of the `zetafill` end-to-end tests: running the binary in a temporary
//! folder, reading its JSON, and geometry checkers written independently of the core
//! ([`geometry`] for fills, [`voronoi`] for cobblestones and territories, [`svgread`] for
//! what a plotter draws from an SVG).

#![allow(dead_code)]

pub mod geometry;
pub mod safety;
pub mod schema;
pub mod svgread;
pub mod voronoi;

// Each test uses a few of the checkers.
#[allow(unused_imports)]
pub use geometry::*;

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The result of one run of the binary.
#[derive(Debug)]
pub struct Out {
    /// Exit code (-1 if killed by a signal).
    pub code: i32,
    /// Raw standard output.
    pub stdout: Vec<u8>,
    /// Standard error as text.
    pub stderr: String,
}

/// Runs `zetafill ARGS` with `dir` as the working folder.
pub fn zf(dir: &Path, args: &[&str]) -> Out {
    let out = Command::new(env!("CARGO_BIN_EXE_zetafill"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("cannot run zetafill: {e}"));
    Out {
        code: out.status.code().unwrap_or(-1),
        stdout: out.stdout,
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Runs `zetafill ARGS` and asserts exit code 0.
pub fn zf_ok(dir: &Path, args: &[&str]) -> Out {
    let o = zf(dir, args);
    assert_eq!(o.code, 0, "zetafill {args:?} failed: {}", o.stderr);
    o
}

/// Runs `zetafill ARGS` (exit 0 required) and parses its standard output as one JSON value.
pub fn zf_json(dir: &Path, args: &[&str]) -> Value {
    let o = zf_ok(dir, args);
    let v = serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{args:?}: not one JSON object ({e}): {}", String::from_utf8_lossy(&o.stdout)));
    schema::check_document(&v);
    v
}

/// A `w x h` greyscale PNG, black where `dark(x, y)` (pixel centres, y down) and white
/// elsewhere.
pub fn png_picture(path: &Path, w: u32, h: u32, dark: impl Fn(u32, u32) -> bool) {
    let data: Vec<u8> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| if dark(x, y) { 0 } else { 255 })
        .collect();
    let file = std::fs::File::create(path).unwrap_or_else(|e| panic!("{e}"));
    let mut enc = png::Encoder::new(file, w, h);
    enc.set_color(png::ColorType::Grayscale);
    enc.set_depth(png::BitDepth::Eight);
    enc.write_header()
        .and_then(|mut wr| wr.write_image_data(&data))
        .unwrap_or_else(|e| panic!("{e}"));
}

/// The same picture as [`png_picture`] draws, as a JPEG (quality 95).
pub fn jpeg_picture(path: &Path, w: u16, h: u16, dark: impl Fn(u16, u16) -> bool) {
    let data: Vec<u8> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| if dark(x, y) { 0 } else { 255 })
        .collect();
    let enc = jpeg_encoder::Encoder::new_file(path, 95).unwrap_or_else(|e| panic!("{e}"));
    enc.encode(&data, w, h, jpeg_encoder::ColorType::Luma)
        .unwrap_or_else(|e| panic!("{e}"));
}

/// A fresh temporary folder.
pub fn tmp() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("zetafill-cli-test-")
        .tempdir()
        .unwrap_or_else(|e| panic!("tempdir: {e}"))
}

/// Reads a file (panics with the path on failure).
pub fn read(p: &Path) -> Vec<u8> {
    std::fs::read(p).unwrap_or_else(|e| panic!("cannot read {}: {e}", p.display()))
}

/// Parses JSON bytes; a document of the tool's must follow its schema
/// ([`schema::check_document`]).
pub fn parse_json(bytes: &[u8]) -> Value {
    let v = serde_json::from_slice(bytes).unwrap_or_else(|e| panic!("bad JSON ({e}): {}", String::from_utf8_lossy(bytes)));
    schema::check_document(&v);
    v
}

/// Runs `COMMAND ARGS -o NAME` in `dir` (exit 0 required) and returns the file's bytes.
pub fn write_to(dir: &Path, command: &str, name: &str, args: &[&str]) -> Vec<u8> {
    let mut a: Vec<&str> = vec![command];
    a.extend_from_slice(args);
    a.extend_from_slice(&["-o", name]);
    zf_ok(dir, &a);
    read(&dir.join(name))
}

/// Runs `fill ARGS -o NAME` in `dir` (exit 0 required) and returns the file's bytes.
pub fn fill_to(dir: &Path, name: &str, args: &[&str]) -> Vec<u8> {
    write_to(dir, "fill", name, args)
}

/// Runs `line ARGS -o NAME` in `dir` (exit 0 required) and returns the file's bytes.
pub fn line_to(dir: &Path, name: &str, args: &[&str]) -> Vec<u8> {
    write_to(dir, "line", name, args)
}

/// Runs a fill to JSON and returns the document.
pub fn fill_json(dir: &Path, args: &[&str]) -> Value {
    parse_json(&fill_to(dir, "out.json", args))
}

/// The names of the entries of a folder, sorted.
pub fn listing(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("read_dir {}: {e}", dir.display()))
        .map(|e| e.map(|e| e.path()).unwrap_or_default())
        .collect();
    v.sort();
    v
}

// ---------------------------------------------------------------------------------------------
// JSON access

/// `v[key]` as f64.
pub fn f(v: &Value, key: &str) -> f64 {
    v.get(key)
        .and_then(Value::as_f64)
        .unwrap_or_else(|| panic!("'{key}' is not a number in {v}"))
}

/// `v[key]` as u64.
pub fn u(v: &Value, key: &str) -> u64 {
    v.get(key)
        .and_then(Value::as_u64)
        .unwrap_or_else(|| panic!("'{key}' is not an unsigned integer in {v}"))
}

/// `v[key]` as str.
pub fn s<'a>(v: &'a Value, key: &str) -> &'a str {
    v.get(key)
        .and_then(Value::as_str)
        .unwrap_or_else(|| panic!("'{key}' is not a string in {v}"))
}

/// `v[key]` as bool.
pub fn b(v: &Value, key: &str) -> bool {
    v.get(key)
        .and_then(Value::as_bool)
        .unwrap_or_else(|| panic!("'{key}' is not a bool in {v}"))
}

/// `v` as a point `[x, y]`.
pub fn pt(v: &Value) -> [f64; 2] {
    let a = v.as_array().unwrap_or_else(|| panic!("not a point: {v}"));
    assert_eq!(a.len(), 2, "a point has two coordinates: {v}");
    let c = |i: usize| a.get(i).and_then(Value::as_f64).unwrap_or_else(|| panic!("bad coordinate in {v}"));
    [c(0), c(1)]
}

/// The shapes array of a fill document.
pub fn shapes(doc: &Value) -> &Vec<Value> {
    doc.get("shapes")
        .and_then(Value::as_array)
        .unwrap_or_else(|| panic!("no shapes array"))
}

/// The sorted keys of an object.
pub fn keys(v: &Value) -> Vec<String> {
    let mut k: Vec<String> = v
        .as_object()
        .unwrap_or_else(|| panic!("not an object: {v}"))
        .keys()
        .cloned()
        .collect();
    k.sort();
    k
}

fn sorted(k: &[&str]) -> Vec<String> {
    let mut v: Vec<String> = k.iter().map(|s| s.to_string()).collect();
    v.sort();
    v
}

/// Region (width, height, periodic) of a document.
pub fn region(doc: &Value) -> (f64, f64, bool) {
    let r = doc.get("region").unwrap_or_else(|| panic!("no region"));
    (f(r, "width"), f(r, "height"), b(r, "periodic"))
}

/// Relative difference.
pub fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

/// Shoelace area (absolute).
pub fn shoelace(vs: &[[f64; 2]]) -> f64 {
    let n = vs.len();
    let mut a2 = 0.0;
    for i in 0..n {
        let (p, q) = (vs[i], vs[(i + 1) % n]);
        a2 += p[0] * q[1] - q[0] * p[1];
    }
    (a2 / 2.0).abs()
}

// ---------------------------------------------------------------------------------------------
// The document contract (docs/cli.md, Outputs)

/// What a run was asked for.
#[derive(Debug, Clone, Copy)]
pub struct Expect<'a> {
    /// `--shape` as written ("circle", "square", "rect:2.5").
    pub shape: &'a str,
    /// Expected `params.rotate`.
    pub rotate: &'a str,
    /// c.
    pub c: f64,
    /// N.
    pub n_offset: f64,
    /// Seed.
    pub seed: u64,
    /// Region width and height.
    pub w: f64,
    /// Region height.
    pub h: f64,
    /// Periodic region.
    pub periodic: bool,
    /// `--count`, if the run used one (then exactly this many shapes unless halted).
    pub count: Option<u64>,
    /// Gap.
    pub gap: f64,
    /// Trial limit.
    pub max_trials: u64,
    /// `params.sampler` (the default is "fast").
    pub sampler: &'a str,
}

impl Default for Expect<'_> {
    fn default() -> Self {
        Expect {
            shape: "circle",
            rotate: "none",
            c: 1.3,
            n_offset: 1.0,
            seed: 1,
            w: 100.0,
            h: 80.0,
            periodic: false,
            count: None,
            gap: 0.0,
            max_trials: 10_000_000,
            sampler: "fast",
        }
    }
}

/// The kind name a `--shape` value gives in the shapes list.
pub fn kind_of(shape: &str) -> &'static str {
    if shape == "circle" {
        "circle"
    } else if shape == "square" {
        "square"
    } else if shape.starts_with("rect:") {
        "rect"
    } else {
        panic!("unknown shape {shape}")
    }
}

/// Aspect ratio (width over height) of a `--shape` value (1 for circle and square).
pub fn aspect_of(shape: &str) -> f64 {
    shape
        .strip_prefix("rect:")
        .map(|a| a.parse::<f64>().unwrap_or_else(|_| panic!("bad aspect {a}")))
        .unwrap_or(1.0)
}

/// Checks keys, types and every number of a fill document that follows from the others.
/// Returns whether the run was halted.
pub fn check_doc(doc: &Value, e: &Expect) -> bool {
    assert_eq!(
        keys(doc),
        sorted(&["version", "mode", "params", "region", "area", "zeta", "shapes", "stats"]),
        "top-level keys"
    );
    assert_eq!(doc.get("version").and_then(Value::as_u64), Some(1), "version");
    assert_eq!(s(doc, "mode"), "fill");

    // params
    let p = doc.get("params").unwrap_or_else(|| panic!("no params"));
    let pk = keys(p);
    for k in ["c", "n_offset", "seed", "shape", "rotate", "sampler", "gap", "max_trials"] {
        assert!(pk.contains(&k.to_string()), "params lacks {k}: {p}");
    }
    let allowed = [
        "c",
        "n_offset",
        "seed",
        "shape",
        "rotate",
        "sampler",
        "scalar",
        "batch",
        "gap",
        "count",
        "fill",
        "min_size",
        "max_trials",
        "dimension",
    ];
    for k in &pk {
        assert!(allowed.contains(&k.as_str()), "unexpected params key {k}");
    }
    assert!(p.get("c").is_some_and(Value::is_f64), "c is a float");
    assert!(p.get("n_offset").is_some_and(Value::is_f64), "n_offset is a float");
    assert!(p.get("gap").is_some_and(Value::is_f64), "gap is a float");
    assert_eq!(f(p, "c"), e.c, "params.c");
    assert_eq!(f(p, "n_offset"), e.n_offset, "params.n_offset");
    assert_eq!(u(p, "seed"), e.seed, "params.seed");
    assert_eq!(s(p, "shape"), e.shape, "params.shape");
    assert_eq!(s(p, "rotate"), e.rotate, "params.rotate");
    assert_eq!(s(p, "sampler"), e.sampler, "params.sampler");
    assert_eq!(f(p, "gap"), e.gap, "params.gap");
    assert_eq!(u(p, "max_trials"), e.max_trials, "params.max_trials");
    if let Some(k) = e.count {
        assert_eq!(u(p, "count"), k, "params.count");
    }

    // region
    let r = doc.get("region").unwrap_or_else(|| panic!("no region"));
    assert_eq!(keys(r), sorted(&["kind", "width", "height", "periodic"]), "region keys");
    assert_eq!(s(r, "kind"), "rect");
    assert!(r.get("width").is_some_and(Value::is_f64) && r.get("height").is_some_and(Value::is_f64));
    assert_eq!(f(r, "width"), e.w);
    assert_eq!(f(r, "height"), e.h);
    assert_eq!(b(r, "periodic"), e.periodic);
    let area = f(doc, "area");
    assert_eq!(area, e.w * e.h, "area == width * height");
    let zeta = f(doc, "zeta");
    assert!(zeta.is_finite() && zeta > 0.0);

    // shapes
    let kind = kind_of(e.shape);
    let aspect = aspect_of(e.shape);
    let list = shapes(doc);
    let mut trial_sum = 0u64;
    let mut area_sum = 0.0;
    for (i, sh) in list.iter().enumerate() {
        let want_keys: &[&str] = if kind == "circle" {
            &["index", "kind", "center", "radius", "area", "trials"]
        } else {
            &["index", "kind", "center", "angle", "area", "trials", "vertices"]
        };
        assert_eq!(keys(sh), sorted(want_keys), "keys of shape {i}");
        assert_eq!(u(sh, "index"), i as u64, "shapes in index order");
        assert_eq!(s(sh, "kind"), kind);
        let c = pt(sh.get("center").unwrap_or(&Value::Null));
        let a = f(sh, "area");
        let t = u(sh, "trials");
        assert!(t >= 1, "shape {i} took {t} trials");
        assert!(t <= e.max_trials);
        trial_sum += t;
        area_sum += a;
        let want = area / (zeta * (i as f64 + e.n_offset).powf(e.c));
        assert!(rel(a, want) <= 1e-12, "shape {i}: area {a} != A/(zeta (i+N)^c) = {want}");
        if kind == "circle" {
            let r = f(sh, "radius");
            assert!(
                rel(std::f64::consts::PI * r * r, a) <= 1e-9,
                "shape {i}: radius {r} does not give area {a}"
            );
        } else {
            let angle = f(sh, "angle");
            let vs: Vec<[f64; 2]> = sh
                .get("vertices")
                .and_then(Value::as_array)
                .unwrap_or_else(|| panic!("vertices"))
                .iter()
                .map(pt)
                .collect();
            assert_eq!(vs.len(), 4, "shape {i} has 4 vertices");
            assert!(rel(shoelace(&vs), a) <= 1e-9, "shape {i}: polygon area {} != {a}", shoelace(&vs));
            if e.rotate == "none" {
                assert_eq!(angle, 0.0, "shape {i} rotated with --rotate none");
            }
            // The vertices are the rectangle of that area, aspect and angle about the centre.
            let hh = (a / (4.0 * aspect)).sqrt();
            let hw = aspect * hh;
            let (sn, cs) = angle.sin_cos();
            let size = hw.max(hh);
            let mut found = 0;
            for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                let (dx, dy) = (sx * hw, sy * hh);
                let q = [c[0] + dx * cs - dy * sn, c[1] + dx * sn + dy * cs];
                if vs.iter().any(|v| (v[0] - q[0]).hypot(v[1] - q[1]) <= 1e-9 * size.max(1.0)) {
                    found += 1;
                }
            }
            assert_eq!(
                found, 4,
                "shape {i}: vertices {vs:?} are not the {e:?} rectangle at {c:?}, angle {angle}"
            );
        }
    }

    // stats
    let st = doc.get("stats").unwrap_or_else(|| panic!("no stats"));
    let sk = keys(st);
    for k in ["placed", "trials", "fill_fraction", "halted"] {
        assert!(sk.contains(&k.to_string()), "stats lacks {k}");
    }
    assert_eq!(u(st, "placed"), list.len() as u64, "stats.placed");
    let halted = b(st, "halted");
    if halted {
        // The halted placement's trials count too (core Stats).
        assert_eq!(u(st, "trials"), trial_sum + e.max_trials, "stats.trials of a halted run");
    } else {
        assert_eq!(u(st, "trials"), trial_sum, "stats.trials == sum of shape trials");
        if let Some(k) = e.count {
            if sk.contains(&"stop".to_string()) && s(st, "stop") == "count" {
                assert_eq!(list.len() as u64, k, "count");
            }
        }
    }
    let ff = f(st, "fill_fraction");
    assert!((ff - area_sum / area).abs() <= 1e-12, "fill_fraction {ff} != {}", area_sum / area);
    halted
}

// ---------------------------------------------------------------------------------------------
// Messages

/// Whether `text` mentions `flag` as a whole word (so "--c" is not found in "--count").
pub fn names_flag(text: &str, flag: &str) -> bool {
    text.match_indices(flag).any(|(i, _)| {
        let next = text[i + flag.len()..].chars().next();
        !next.is_some_and(|ch| ch.is_ascii_alphanumeric() || ch == '-' || ch == '_')
    })
}

/// A fill of 120 rings for hatching tests. The drawing, not the sampler, is under test: the
/// paper's sampler with this seed places all 120 (with N = 1 the first ring often leaves no
/// room for the second).
pub const RINGS: [&str; 10] = [
    "--region",
    "rect:120:120",
    "--shape",
    "ring:0.5",
    "--count",
    "120",
    "--seed",
    "13",
    "--sampler",
    "reference",
];

/// The rings of a fill document as (centre, outer radius, inner radius).
pub fn rings(doc: &Value) -> Vec<([f64; 2], f64, f64)> {
    shapes(doc)
        .iter()
        .map(|s| (pt(s.get("center").unwrap_or(&Value::Null)), f(s, "radius"), f(s, "inner_radius")))
        .collect()
}

/// Runs `fill --count 20 ARGS` for each `(ARGS, FLAG)` in a fresh folder holding only
/// `keep` (whose `-o` the cases name): each must exit 2 naming FLAG, leave `keep` as it was
/// and write nothing else.
pub fn assert_fill_refuses(keep: &str, cases: &[(&[&str], &str)]) {
    let dir = tmp();
    let kept = dir.path().join(keep);
    std::fs::write(&kept, b"keep").unwrap_or_else(|e| panic!("write: {e}"));
    for (args, flag) in cases {
        let mut a = vec!["fill", "--count", "20"];
        a.extend_from_slice(args);
        let o = zf(dir.path(), &a);
        assert_eq!(o.code, 2, "{a:?}: {}", o.stderr);
        assert!(o.stderr.contains(flag), "{a:?} should name {flag}: {}", o.stderr);
        assert_eq!(read(&kept), b"keep", "{a:?} touched the output");
    }
    assert_eq!(listing(dir.path()), vec![kept], "nothing else written");
}

/// SplitMix64's output for `x` (the published generator: add the constant, then mix).
pub fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A path as usvg reads it: in mm on the page (y down).
#[derive(Debug, Clone)]
pub struct Painted {
    /// The centre of its box.
    pub centre: [f64; 2],
    /// A point inside it when it is convex: the box centre of a curved path (a circle), the
    /// mean of the vertices of a polygon.
    pub inside: [f64; 2],
    /// Its fill (or stroke) colour as `#rrggbb`.
    pub colour: String,
}

/// The paths of an SVG in document order, with their fill or stroke colour.
pub fn painted(bytes: &[u8], stroke: bool) -> Vec<Painted> {
    // usvg works in px at 96 per inch; the drawing is in mm.
    const MM: f64 = 25.4 / 96.0;
    use usvg::tiny_skia_path::PathVerb;
    fn walk(g: &usvg::Group, stroke: bool, out: &mut Vec<Painted>) {
        for n in g.children() {
            match n {
                usvg::Node::Group(g) => walk(g, stroke, out),
                usvg::Node::Path(p) => {
                    let paint = if stroke {
                        p.stroke().map(|s| s.paint())
                    } else {
                        p.fill().map(|f| f.paint())
                    };
                    let colour = match paint {
                        Some(usvg::Paint::Color(c)) => format!("#{:02x}{:02x}{:02x}", c.red, c.green, c.blue),
                        other => format!("{other:?}"),
                    };
                    let b = p.abs_bounding_box();
                    let centre = [f64::from(b.x() + b.width() / 2.0) * MM, f64::from(b.y() + b.height() / 2.0) * MM];
                    let data = p.data();
                    let curved = data.verbs().iter().any(|v| matches!(v, PathVerb::Quad | PathVerb::Cubic));
                    let mut pts = data.points().to_vec();
                    let inside = if curved || pts.is_empty() {
                        centre
                    } else {
                        p.abs_transform().map_points(&mut pts);
                        let n = pts.len() as f64;
                        let (sx, sy) = pts.iter().fold((0.0, 0.0), |(x, y), q| (x + f64::from(q.x), y + f64::from(q.y)));
                        [sx / n * MM, sy / n * MM]
                    };
                    out.push(Painted { centre, inside, colour });
                }
                _ => {}
            }
        }
    }
    let tree = usvg::Tree::from_data(bytes, &usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"));
    let mut out = Vec::new();
    walk(tree.root(), stroke, &mut out);
    out
}

/// For a drawing written with `--layers colours` and `palette`: checks that every colour has
/// its labelled layer and that, read back in document order, the paths' strokes never go
/// back to an earlier pen and use every pen. The pen (palette index) of each path.
pub fn assert_pens_in_layers(svg: &[u8], palette: &[&str]) -> Vec<usize> {
    let text = String::from_utf8_lossy(svg).into_owned();
    for (k, c) in palette.iter().enumerate() {
        assert!(text.contains(&format!("inkscape:label=\"{} {c}\"", k + 1)), "no layer for {c}");
    }
    let pens: Vec<usize> = painted(svg, true)
        .iter()
        .map(|p| {
            palette
                .iter()
                .position(|c| *c == p.colour)
                .unwrap_or_else(|| panic!("colour {}", p.colour))
        })
        .collect();
    assert!(pens.windows(2).all(|w| w[0] <= w[1]), "a pen's shapes outside its layer");
    assert_eq!(pens.iter().copied().max(), Some(palette.len() - 1), "a pen unused");
    pens
}

/// A command line written as one string, split at spaces (no argument holds one).
pub fn words(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}
