//! `zetafill tile` end to end: the tile's discs never overlap anywhere in the plane of rows
//! (checked on the JSON by an independent construction of the plane), their size follows the
//! linear law of the post, every disc crossing the top edge has its doppelganger, the pictures
//! read back with usvg meet their copies at every edge (left and right, and the top's halves
//! against the bottom at half scale), the layouts have the sizes and tile counts they claim,
//! reruns are byte-identical, and bad input is refused. Each checker is shown to fail on a
//! broken input.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use serde_json::Value;

const PX_PER_MM: f64 = 96.0 / 25.4;

/// A cobblestone tile.
const COBBLES: [&str; 10] = [
    "--seed",
    "3",
    "--render",
    "voronoi",
    "--radius",
    "2",
    "--spacing",
    "0.5",
    "--tries",
    "5000",
];

/// A disc of the JSON: centre, radius, twin.
#[derive(Debug, Clone, Copy)]
struct D {
    c: [f64; 2],
    r: f64,
    twin: Option<usize>,
}

fn discs(doc: &Value) -> Vec<D> {
    doc.get("discs")
        .and_then(Value::as_array)
        .unwrap_or_else(|| panic!("no discs"))
        .iter()
        .map(|d| D {
            c: pt(d.get("center").unwrap_or(&Value::Null)),
            r: f(d, "radius"),
            twin: d.get("twin").and_then(Value::as_u64).map(|t| t as usize),
        })
        .collect()
}

/// The tile's parameters from its JSON: (W, H, R, S).
fn spec(doc: &Value) -> (f64, f64, f64, f64) {
    let p = doc.get("params").unwrap_or(&Value::Null);
    (f(p, "width"), f(p, "height"), f(p, "radius"), f(p, "spacing"))
}

fn tile_json(dir: &std::path::Path, args: &[&str]) -> Value {
    zf_ok(dir, &[&["tile"], args, &["-o", "t.json"]].concat());
    parse_json(&read(&dir.join("t.json")))
}

/// The plane of rows built from the tile, independently of the tool: row r (-1 to 2) is the
/// tile scaled by 2^-r, repeated with period W 2^-r, starting at height 2H (1 - 2^-r); the
/// discs of the window `[-W, 2W] x [-2H, 2H]`, each with its row.
fn plane(ds: &[D], w: f64, h: f64) -> Vec<([f64; 2], f64)> {
    plane_rows(ds, w, h, -1..=2, [-w, 2.0 * w, -2.0 * h, 2.0 * h])
}

/// The discs of rows `rows` of the plane whose centres lie in the window `[x0, x1, y0, y1]`.
fn plane_rows(ds: &[D], w: f64, h: f64, rows: std::ops::RangeInclusive<i32>, window: [f64; 4]) -> Vec<([f64; 2], f64)> {
    plane_indexed(ds, w, h, rows, window).into_iter().map(|(c, r, _)| (c, r)).collect()
}

/// [`plane_rows`], each disc with the index of the tile disc it copies.
fn plane_indexed(ds: &[D], w: f64, h: f64, rows: std::ops::RangeInclusive<i32>, window: [f64; 4]) -> Vec<([f64; 2], f64, usize)> {
    let [wx0, wx1, wy0, wy1] = window;
    let mut out = Vec::new();
    for row in rows {
        let s = 0.5f64.powi(row);
        let y0 = 2.0 * h * (1.0 - s);
        let (first, last) = ((wx0 / (w * s)).floor() as i64 - 1, (wx1 / (w * s)).ceil() as i64 + 1);
        for i in first..=last {
            for (k, d) in ds.iter().enumerate() {
                let c = [i as f64 * w * s + s * d.c[0], y0 + s * d.c[1]];
                if c[0] > wx0 && c[0] < wx1 && c[1] > wy0 && c[1] < wy1 {
                    out.push((c, s * d.r, k));
                }
            }
        }
    }
    out
}

/// Pairs of discs of the plane closer than the post's spacing allows (gap `S (1 - ym / 2H)`,
/// ym the mean height of the two centres), among those near the tile `[0, W] x [0, H]`.
fn overlaps(ds: &[D], w: f64, h: f64, sp: f64) -> Vec<String> {
    let all = plane(ds, w, h);
    let near = |c: [f64; 2], r: f64| c[0] + r > -0.25 * w && c[0] - r < 1.25 * w && c[1] + r > -0.25 * h && c[1] - r < 1.25 * h;
    let mut bad = Vec::new();
    for (i, &(a, ra)) in all.iter().enumerate() {
        if !near(a, ra) {
            continue;
        }
        for &(b, rb) in &all[i + 1..] {
            let gap = sp * (1.0 - 0.5 * (a[1] + b[1]) / (2.0 * h));
            let d = (a[0] - b[0]).hypot(a[1] - b[1]);
            if d < ra + rb + gap - 1e-9 {
                bad.push(format!("{a:?} r {ra} and {b:?} r {rb}: {d} < {}", ra + rb + gap));
            }
        }
    }
    bad
}

#[test]
fn discs_never_overlap_anywhere_in_the_plane() {
    let dir = tmp();
    let d = dir.path();
    for args in [
        vec!["--seed", "1"],
        vec!["--seed", "2", "--width", "80", "--height", "120", "--radius", "6", "--spacing", "2"],
        COBBLES.to_vec(),
    ] {
        let doc = tile_json(d, &args);
        let (w, h, _, sp) = spec(&doc);
        let ds = discs(&doc);
        assert!(ds.len() > 50, "{args:?}: only {} discs", ds.len());
        let bad = overlaps(&ds, w, h, sp);
        assert!(bad.is_empty(), "{args:?}: {} overlaps, first {}", bad.len(), bad[0]);
    }
    // The checker sees overlaps across rows: a disc just under the top edge, and a disc at the
    // bottom where the double-scale copy of the first lands.
    let (w, h, r, sp) = (100.0, 100.0, 5.0, 1.0);
    let f = |y: f64| 1.0 - y / (2.0 * h);
    let top = D {
        c: [20.0, 97.0],
        r: r * f(97.0),
        twin: None,
    };
    // Its copy in row -1 sits at (40, -6), radius about 5.2: a disc at (40, 1) overlaps it.
    let low = D {
        c: [40.0, 1.0],
        r: r * f(1.0),
        twin: None,
    };
    assert!(!overlaps(&[top, low], w, h, sp).is_empty(), "a cross-row overlap is missed");
    let apart = D { c: [70.0, 30.0], ..low };
    assert!(overlaps(&[top, apart], w, h, sp).is_empty(), "a false overlap");
}

#[test]
fn size_follows_height_and_top_crossings_have_twins() {
    let dir = tmp();
    let d = dir.path();
    let doc = tile_json(d, &["--seed", "5"]);
    let (w, h, r, _) = spec(&doc);
    let ds = discs(&doc);
    let check = |ds: &[D]| -> Vec<String> {
        let mut bad = Vec::new();
        for (i, a) in ds.iter().enumerate() {
            if !(0.0..w).contains(&a.c[0]) || !(0.0..h).contains(&a.c[1]) {
                bad.push(format!("{i}: centre {:?} outside the tile", a.c));
            }
            if rel(a.r, r * (1.0 - a.c[1] / (2.0 * h))) > 1e-12 {
                bad.push(format!("{i}: radius {} at height {}", a.r, a.c[1]));
            }
            if a.c[1] + a.r > h {
                let ok = a.twin.is_some_and(|t| {
                    let b = ds[t];
                    b.twin == Some(i) && b.c[1] == a.c[1] && b.r == a.r && rel((a.c[0] - b.c[0]).abs(), 0.5 * w) < 1e-12
                });
                if !ok {
                    bad.push(format!("{i}: crosses the top edge without a twin half a tile away"));
                }
            }
        }
        bad
    };
    assert!(check(&ds).is_empty(), "{:?}", check(&ds));
    assert!(
        ds.iter().any(|a| a.twin.is_some()),
        "no doppelgangers in this tile: pick a seed with some"
    );
    assert_eq!(u(doc.get("stats").unwrap_or(&Value::Null), "discs") as usize, ds.len());
    // The checker fails on a missing twin, a wrong radius, and a twin at the wrong place.
    let i = ds.iter().position(|a| a.twin.is_some()).unwrap_or_default();
    let mut broken = ds.clone();
    broken[i].twin = None;
    assert!(!check(&broken).is_empty());
    let mut broken = ds.clone();
    broken[0].r *= 1.01;
    assert!(!check(&broken).is_empty());
    let mut broken = ds.clone();
    let t = broken[i].twin.unwrap_or_default();
    broken[t].c[0] = (broken[t].c[0] + 1.0) % w;
    assert!(!check(&broken).is_empty());
    // Voronoi tiles twin every centre in the top band (a quarter at least).
    let doc = tile_json(
        d,
        &[
            "--seed",
            "5",
            "--render",
            "voronoi",
            "--radius",
            "2",
            "--spacing",
            "0.5",
            "--tries",
            "5000",
        ],
    );
    let band = f(doc.get("params").unwrap_or(&Value::Null), "band");
    assert!(band >= 0.25);
    let ds = discs(&doc);
    for a in &ds {
        assert_eq!(a.twin.is_some(), a.c[1] > h * (1.0 - band) || a.c[1] + a.r > h, "{a:?}");
    }
}

/// The ends of the drawn open paths that lie on the edges of a `w` x `h` drawing (mm, y up),
/// read back with usvg: (bottom x, top x, left y, right y), each sorted.
type Ends = (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>);

fn edge_ends(svg: &[u8], w: f64, h: f64) -> Ends {
    use usvg::tiny_skia_path::PathSegment;
    let tree = usvg::Tree::from_data(svg, &usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"));
    let mut ends: Vec<[f64; 2]> = Vec::new();
    fn walk(g: &usvg::Group, h: f64, ends: &mut Vec<[f64; 2]>) {
        for n in g.children() {
            match n {
                usvg::Node::Group(g) => walk(g, h, ends),
                usvg::Node::Path(p) => {
                    let ts = p.abs_transform();
                    let mm = |mut q: usvg::tiny_skia_path::Point| {
                        ts.map_point(&mut q);
                        [q.x as f64 / PX_PER_MM, h - q.y as f64 / PX_PER_MM]
                    };
                    let (mut first, mut last, mut closed) = (None, None, false);
                    let mut flush = |first: Option<[f64; 2]>, last: Option<[f64; 2]>, closed: bool| {
                        if let (Some(a), Some(b), false) = (first, last, closed) {
                            ends.push(a);
                            ends.push(b);
                        }
                    };
                    for seg in p.data().segments() {
                        match seg {
                            PathSegment::MoveTo(q) => {
                                flush(first, last, closed);
                                (first, last, closed) = (Some(mm(q)), None, false);
                            }
                            PathSegment::LineTo(q) | PathSegment::QuadTo(_, q) | PathSegment::CubicTo(_, _, q) => last = Some(mm(q)),
                            PathSegment::Close => closed = true,
                        }
                    }
                    flush(first, last, closed);
                }
                _ => {}
            }
        }
    }
    walk(tree.root(), h, &mut ends);
    let tol = 2e-3;
    let mut e: Ends = Default::default();
    for p in ends {
        if p[1].abs() < tol {
            e.0.push(p[0]);
        } else if (p[1] - h).abs() < tol {
            e.1.push(p[0]);
        } else if p[0].abs() < tol {
            e.2.push(p[1]);
        } else if (p[0] - w).abs() < tol {
            e.3.push(p[1]);
        }
    }
    for v in [&mut e.0, &mut e.1, &mut e.2, &mut e.3] {
        v.sort_by(f64::total_cmp);
    }
    e
}

/// What keeps copies of the picture from meeting: left ends against right ends, and each half
/// of the top edge against the bottom edge at half scale (the copies above are half size).
fn seam_faults(e: &Ends, w: f64) -> Vec<String> {
    let mut bad = Vec::new();
    let mut same = |what: &str, a: &[f64], b: &[f64]| {
        if a.len() != b.len() {
            bad.push(format!("{what}: {} ends against {}", a.len(), b.len()));
        } else if let Some((x, y)) = a.iter().zip(b).find(|(x, y)| (*x - *y).abs() > 2e-4) {
            bad.push(format!("{what}: {x} against {y}"));
        }
    };
    same("left/right", &e.2, &e.3);
    let half: Vec<f64> = e.0.iter().map(|x| 0.5 * x).collect();
    let lo: Vec<f64> = e.1.iter().copied().filter(|&x| x < 0.5 * w).collect();
    let hi: Vec<f64> = e.1.iter().filter(|&&x| x >= 0.5 * w).map(|x| x - 0.5 * w).collect();
    same("top left half/bottom", &half, &lo);
    same("top right half/bottom", &half, &hi);
    bad
}

#[test]
fn pictures_meet_their_copies_at_every_edge() {
    let dir = tmp();
    let d = dir.path();
    for args in [
        vec!["--seed", "1"],
        vec!["--seed", "7", "--width", "120", "--height", "80", "--radius", "4"],
        COBBLES.to_vec(),
    ] {
        zf_ok(d, &[&["tile"], &args[..], &["-o", "t.svg"]].concat());
        let svg = read(&d.join("t.svg"));
        let w: f64 = args
            .iter()
            .position(|a| *a == "--width")
            .map_or(100.0, |i| args[i + 1].parse().unwrap_or(0.0));
        let h: f64 = args
            .iter()
            .position(|a| *a == "--height")
            .map_or(100.0, |i| args[i + 1].parse().unwrap_or(0.0));
        let e = edge_ends(&svg, w, h);
        assert!(
            !e.0.is_empty() && !e.1.is_empty() && !e.2.is_empty(),
            "{args:?}: nothing crosses the edges"
        );
        let bad = seam_faults(&e, w);
        assert!(bad.is_empty(), "{args:?}: {bad:?}");
        // The checker fails when one path that ends on the top edge is taken out.
        let text = String::from_utf8_lossy(&svg).into_owned();
        let cut = text
            .lines()
            .position(|l| {
                l.contains("<path") && {
                    let d = l.split("d=\"").nth(1).unwrap_or("");
                    d.split(['M', 'L', ' ', '"']).any(|p| p.ends_with(",0"))
                }
            })
            .unwrap_or_else(|| panic!("no path ends on the top edge"));
        let broken: String = text
            .lines()
            .enumerate()
            .filter(|&(i, _)| i != cut)
            .map(|(_, l)| format!("{l}\n"))
            .collect();
        assert!(
            !seam_faults(&edge_ends(broken.as_bytes(), w, h), w).is_empty(),
            "{args:?}: a missing path is missed"
        );
    }
}

fn size_mm(svg: &[u8]) -> (f64, f64) {
    let t = usvg::Tree::from_data(svg, &usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"));
    (t.size().width() as f64 / PX_PER_MM, t.size().height() as f64 / PX_PER_MM)
}

/// Every vertex of every drawn path (mm, y up), usvg's reading of the SVG.
fn vertices(svg: &[u8], h: f64) -> Vec<Vec<[f64; 2]>> {
    let tree = usvg::Tree::from_data(svg, &usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"));
    let mut out = Vec::new();
    fn walk(g: &usvg::Group, h: f64, out: &mut Vec<Vec<[f64; 2]>>) {
        for n in g.children() {
            match n {
                usvg::Node::Group(g) => walk(g, h, out),
                usvg::Node::Path(p) => {
                    let ts = p.abs_transform();
                    let pts = p
                        .data()
                        .points()
                        .iter()
                        .map(|&q| {
                            let mut q = q;
                            ts.map_point(&mut q);
                            [q.x as f64 / PX_PER_MM, h - q.y as f64 / PX_PER_MM]
                        })
                        .collect();
                    out.push(pts);
                }
                _ => {}
            }
        }
    }
    walk(tree.root(), h, &mut out);
    out
}

#[test]
fn mosaic_and_planet_hold_the_copies_they_claim() {
    let dir = tmp();
    let d = dir.path();
    let base = ["tile", "--seed", "4", "--tries", "3000"];
    zf_ok(d, &[&base[..], &["-o", "t.svg"]].concat());
    let tile = read(&d.join("t.svg"));
    let per_tile = vertices(&tile, 100.0).len();
    assert!(per_tile > 20);
    // Mosaic: 3 rows over 2 tiles, then 4, then 8: 14 copies in 200 x 175 mm.
    zf_ok(d, &[&base[..], &["--layout", "mosaic", "--rows", "3", "-o", "m.svg"]].concat());
    let m = read(&d.join("m.svg"));
    let (w, h) = size_mm(&m);
    assert!((w - 200.0).abs() < 1e-3 && (h - 175.0).abs() < 1e-3, "{w} x {h}");
    let paths = vertices(&m, h);
    assert_eq!(paths.len(), 14 * per_tile);
    assert!(paths
        .iter()
        .flatten()
        .all(|p| p[0] > -0.01 && p[0] < 200.01 && p[1] > -0.01 && p[1] < 175.01));
    // Planet: rings of 16, 32, 64 around a 2 x 90 mm sheet; every vertex lies between the
    // inner ring's inner edge and the surface, and each ring holds its copies' centres.
    zf_ok(
        d,
        &[
            &base[..],
            &[
                "--layout",
                "planet",
                "--rows",
                "3",
                "--planet-radius",
                "90",
                "--style",
                "filled",
                "-o",
                "p.svg",
            ],
        ]
        .concat(),
    );
    let p = read(&d.join("p.svg"));
    let (w, h) = size_mm(&p);
    assert!((w - 180.0).abs() < 1e-3 && (h - 180.0).abs() < 1e-3);
    let paths = vertices(&p, h);
    // Filled copies draw each of the tile's own discs whole, once per copy.
    zf_ok(d, &[&base[..], &["-o", "t.json"]].concat());
    let per_filled = discs(&parse_json(&read(&d.join("t.json")))).len();
    assert_eq!(paths.len(), (16 + 32 + 64) * per_filled);
    let ring0 = std::f64::consts::TAU * 90.0 / 16.0;
    // Ring 0's inner edge, less the largest disc's radius there (whole discs reach across).
    let inner = 90.0 - 2.0 * ring0 - 5.0 * ring0 / 100.0;
    for v in paths.iter().flatten() {
        let rho = (v[0] - 90.0).hypot(v[1] - 90.0);
        assert!(rho > inner - 1e-3 && rho < 90.0 + 1e-3, "vertex at radius {rho}");
    }
    // The outermost ring (64 copies) sits between 90 - ring0 / 2 and 90 - ring0 / 4.
    let mut radii: Vec<f64> = paths
        .iter()
        .map(|l| {
            let n = l.len() as f64;
            let c = l.iter().fold([0.0, 0.0], |s, q| [s[0] + q[0] / n, s[1] + q[1] / n]);
            (c[0] - 90.0).hypot(c[1] - 90.0)
        })
        .collect();
    radii.sort_by(f64::total_cmp);
    let outer = radii.iter().filter(|&&r| r > 90.0 - 0.5 * ring0).count();
    assert!(outer > 64 * per_filled / 2, "{outer} pieces in the outer ring");
}

#[test]
fn reruns_are_byte_identical_and_seeds_differ() {
    let dir = tmp();
    let d = dir.path();
    for fmt in ["svg", "json", "png"] {
        let args = |seed: &str, name: &str| -> Vec<String> {
            ["tile", "--seed", seed, "--tries", "2000", "-o", name]
                .iter()
                .map(|s| s.to_string())
                .collect()
        };
        let run = |seed: &str, name: &str| {
            let a = args(seed, name);
            zf_ok(d, &a.iter().map(String::as_str).collect::<Vec<_>>());
            read(&d.join(name))
        };
        let a = run("9", &format!("a.{fmt}"));
        let b = run("9", &format!("b.{fmt}"));
        let c = run("10", &format!("c.{fmt}"));
        assert_eq!(a, b, "{fmt}");
        assert_ne!(a, c, "{fmt}");
    }
    let png = read(&d.join("a.png"));
    assert_eq!(&png[1..4], b"PNG");
}

#[test]
fn bad_input_is_refused_naming_the_flag() {
    let dir = tmp();
    let d = dir.path();
    std::fs::write(d.join("keep.svg"), b"precious").unwrap_or_else(|e| panic!("{e}"));
    for (args, flag) in [
        (vec!["--radius", "30"], "--radius"),
        (vec!["--rows", "3"], "--rows"),
        (vec!["--columns", "3"], "--columns"),
        (vec!["--layout", "mosaic", "--planet-radius", "50"], "--planet-radius"),
        (vec!["--layout", "planet", "--columns", "8"], "--columns"),
        (vec!["--width", "-5"], "--width"),
        (vec!["--spacing", "nan"], "--spacing"),
        (vec!["--tries", "0"], "--tries"),
        (vec!["--layout", "planet", "--format", "json"], "--layout"),
        (vec!["--layout", "planet", "--rows", "10", "--columns", "4096"], "--rows"),
        (vec!["--palette", "000,fff", "--format", "json"], "--palette"),
        (vec!["--background", "fff", "--format", "gcode"], "--background"),
        (vec!["--palette", "000,fff", "--render", "voronoi"], "--palette"),
        (vec!["--palette", "000,fff", "--color-by", "kind"], "--color-by"),
        (vec!["--palette", "000,ggg"], "--palette"),
        (vec!["--color-by", "size"], "--palette"),
        (vec!["--relief", "dome", "--palette", "000,fff", "--format", "png"], "--palette"),
    ] {
        let o = zf(d, &[&["tile"], &args[..], &["-o", "keep.svg"]].concat());
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        assert!(names_flag(&o.stderr, flag), "{args:?}: {}", o.stderr);
        assert_eq!(read(&d.join("keep.svg")), b"precious", "{args:?} touched the file");
    }
    let o = zf(d, &["tile", "-o", "t.txt"]);
    assert_eq!(o.code, 2);
    assert!(names_flag(&o.stderr, "--output"), "{}", o.stderr);
    assert_eq!(listing(d).len(), 1, "a file was left behind");
}

/// Pixels of a filled picture (rendered by resvg at `ppmm` pixels per mm) that disagree with
/// the discs `ds` of the plane: black where no disc is, or white inside one. Pixels within a
/// pixel and a half of a disc's edge are not judged.
fn filled_mismatches(svg: &[u8], w: f64, h: f64, ds: &[([f64; 2], f64)], ppmm: f64) -> usize {
    use resvg::tiny_skia::{Pixmap, Transform};
    let tree = resvg::usvg::Tree::from_data(svg, &resvg::usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"));
    let (nx, ny) = ((w * ppmm).round() as u32, (h * ppmm).round() as u32);
    let mut pm = Pixmap::new(nx, ny).unwrap_or_else(|| panic!("pixmap"));
    let s = (ppmm / PX_PER_MM) as f32;
    resvg::render(&tree, Transform::from_scale(s, s), &mut pm.as_mut());
    let margin = 1.5 / ppmm;
    let mut bad = 0;
    for j in 0..ny {
        for i in 0..nx {
            let p = [(f64::from(i) + 0.5) / ppmm, h - (f64::from(j) + 0.5) / ppmm];
            let d = ds
                .iter()
                .map(|(c, r)| (p[0] - c[0]).hypot(p[1] - c[1]) - r)
                .fold(f64::INFINITY, f64::min);
            if d.abs() < margin {
                continue;
            }
            let black = pm.pixel(i, j).is_some_and(|px| px.alpha() > 127);
            if black != (d < 0.0) {
                bad += 1;
            }
        }
    }
    bad
}

/// A filled picture is exactly the plane's discs inside the tile, copies from the rows above
/// and below and from the neighbours included (rendered, and compared pixel by pixel with the
/// plane built from the JSON).
#[test]
fn filled_picture_is_the_plane_seen_through_the_tile() {
    let dir = tmp();
    let d = dir.path();
    for seed in ["1", "2"] {
        let args = ["tile", "--seed", seed, "--radius", "8", "--spacing", "2", "--tries", "3000"];
        zf_ok(d, &[&args[..], &["--style", "filled", "-o", "f.svg"]].concat());
        zf_ok(d, &[&args[..], &["-o", "f.json"]].concat());
        let doc = parse_json(&read(&d.join("f.json")));
        let (w, h, _, _) = spec(&doc);
        let ds = discs(&doc);
        let all = plane(&ds, w, h);
        let svg = read(&d.join("f.svg"));
        assert_eq!(filled_mismatches(&svg, w, h, &all, 4.0), 0, "seed {seed}");
        // Without the copies from the row below, the picture disagrees with it.
        let own_rows: Vec<([f64; 2], f64)> = all.iter().copied().filter(|(c, _)| c[1] >= 0.0).collect();
        assert!(
            filled_mismatches(&svg, w, h, &own_rows, 4.0) > 0,
            "seed {seed}: the check misses the row below"
        );
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 48,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x711e),
        ..proptest::prelude::ProptestConfig::default()
    })]

    /// Any tile the flags allow is grown without a panic, refused with exit 2 or written; a
    /// written one has no overlap anywhere in the plane and the size law on every disc.
    #[test]
    fn any_tile_is_refused_cleanly_or_valid(
        w in 20.0f64..200.0,
        h in 20.0f64..200.0,
        r in 0.5f64..10.0,
        sp in 0.0f64..5.0,
        tries in 1u64..800,
        seed in 0u64..1000,
        voronoi in proptest::bool::ANY,
    ) {
        use clap::Parser;
        let args: Vec<String> = [
            "zetafill", "tile", "--width", &w.to_string(), "--height", &h.to_string(), "--radius", &r.to_string(),
            "--spacing", &sp.to_string(), "--tries", &tries.to_string(), "--seed", &seed.to_string(),
            "--render", if voronoi { "voronoi" } else { "discs" }, "-o", "t.json",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        let Ok(zetafill_cli::Cli { command: zetafill_cli::Command::Tile(a) }) = zetafill_cli::Cli::try_parse_from(&args) else {
            panic!("{args:?} does not parse")
        };
        let json = zetafill_cli::plan::format::TileFormat::Json;
        match zetafill_cli::plan::tile::resolve_as(&a, json).and_then(|(run, draw)| zetafill_cli::cmd::tile::output(&run, &draw, json)) {
            Err(e) => proptest::prop_assert_eq!(e.exit_code(), 2, "{:?}: {}", args, e),
            Ok((_, bytes)) => {
                let doc = parse_json(&bytes);
                let ds = discs(&doc);
                let bad = overlaps(&ds, w, h, sp);
                proptest::prop_assert!(bad.is_empty(), "{:?}: {:?}", args, bad.first());
                for d in &ds {
                    proptest::prop_assert!(rel(d.r, r * (1.0 - d.c[1] / (2.0 * h))) < 1e-12);
                }
            }
        }
    }
}

/// A long run piped (as here) prints its one summary line and no progress bar; `-q` prints
/// nothing.
#[test]
fn long_runs_are_quiet_when_piped() {
    let dir = tmp();
    let d = dir.path();
    let o = zf_ok(d, &["tile", "--tries", "2500000", "-o", "t.json"]);
    assert_eq!(o.stderr.lines().count(), 1, "{:?}", o.stderr);
    assert!(o.stderr.contains("in 2500000 tries") && !o.stderr.contains('\r'), "{:?}", o.stderr);
    let o = zf_ok(d, &["tile", "--tries", "2500000", "-q", "-o", "t.json"]);
    assert!(o.stderr.is_empty(), "{:?}", o.stderr);
}

/// The 16-bit samples of a greyscale PNG, with its width and height.
fn grey16(bytes: &[u8]) -> (usize, usize, Vec<u16>) {
    let mut reader = png::Decoder::new(bytes).read_info().unwrap_or_else(|e| panic!("not a PNG: {e}"));
    let mut buf = vec![0u8; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).unwrap_or_else(|e| panic!("bad PNG: {e}"));
    assert_eq!(
        (frame.color_type, frame.bit_depth),
        (png::ColorType::Grayscale, png::BitDepth::Sixteen)
    );
    let px = buf[..frame.buffer_size()]
        .chunks(2)
        .map(|c| u16::from_be_bytes([c[0], c[1]]))
        .collect();
    (frame.width as usize, frame.height as usize, px)
}

/// The dome height map of the discs `plane` seen through the `w` x `h` tile, `n` x `n`
/// pixels of 4 x 4 samples, white the tallest disc reaching the tile: by brute force.
fn dome_map(plane: &[([f64; 2], f64)], w: f64, h: f64, n: usize) -> Vec<u16> {
    let reaches = |c: [f64; 2], r: f64| c[0] + r > 0.0 && c[0] - r < w && c[1] + r > 0.0 && c[1] - r < h;
    let top = plane.iter().filter(|(c, r)| reaches(*c, *r)).map(|(_, r)| *r).fold(0.0, f64::max);
    let (sw, sh) = (w / (4 * n) as f64, h / (4 * n) as f64);
    let mut out = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            let mut sum = 0.0;
            for b in 0..4 {
                for a in 0..4 {
                    let (x, y) = (((4 * i + a) as f64 + 0.5) * sw, h - ((4 * j + b) as f64 + 0.5) * sh);
                    sum += plane
                        .iter()
                        .find_map(|(c, r)| {
                            let d = r - (x - c[0]).hypot(y - c[1]);
                            (d > 0.0).then(|| (d * (2.0 * r - d)).sqrt())
                        })
                        .unwrap_or(0.0);
                }
            }
            out.push((sum / 16.0 / top * 65535.0).round() as u16);
        }
    }
    out
}

/// The first pixel that differs by more than one unit.
fn map_fault(want: &[u16], got: &[u16], n: usize) -> Option<String> {
    want.iter()
        .zip(got)
        .position(|(a, b)| a.abs_diff(*b) > 1)
        .map(|k| format!("pixel ({}, {}) is {}, expected {}", k % n, k / n, got[k], want[k]))
}

/// The tile's height map is the plane of rows seen through the tile, with the discs of the
/// rows above and below and of the neighbours (so it repeats left and right and meets its
/// half-scale copies along the top), compared pixel by pixel with a brute-force rendering of
/// the plane built from the JSON.
#[test]
fn the_height_map_is_the_plane_seen_through_the_tile() {
    let dir = tmp();
    let args = ["--radius", "4", "--spacing", "1", "--tries", "3000", "--seed", "3"];
    let doc = tile_json(dir.path(), &args);
    let (w, h, _, _) = spec(&doc);
    zf_ok(
        dir.path(),
        &[&["tile"], &args[..], &["--relief", "dome", "--pixels", "90", "-q", "-o", "h.png"]].concat(),
    );
    let (nx, ny, px) = grey16(&read(&dir.path().join("h.png")));
    assert_eq!((nx, ny), (90, 90));
    let ds = discs(&doc);
    let all = plane(&ds, w, h);
    if let Some(fault) = map_fault(&dome_map(&all, w, h, 90), &px, 90) {
        panic!("{fault}");
    }
    // The check fails for a plane without the rows above and below.
    let own_row = plane_rows(&ds, w, h, 0..=0, [-w, 2.0 * w, -2.0 * h, 2.0 * h]);
    assert!(
        map_fault(&dome_map(&own_row, w, h, 90), &px, 90).is_some(),
        "the other rows must show"
    );
    // Tile refusals: a height map is a PNG of the tile itself.
    for (extra, flag) in [
        (&["-o", "x.svg"][..], "--relief"),
        (&["--layout", "mosaic", "-o", "x.png"][..], "--layout"),
    ] {
        let o = zf(dir.path(), &[&["tile", "--relief", "dome"], extra].concat());
        assert_eq!(o.code, 2, "{extra:?}: {}", o.stderr);
        assert!(o.stderr.contains(flag), "{extra:?}: {}", o.stderr);
        assert!(!dir.path().join("x.svg").exists() && !dir.path().join("x.png").exists());
    }
}

/// The cobblestone height map raises exactly the cells the filled picture draws: a stone at
/// every centre in the tile; floor wherever resvg's picture is wholly white, a stone wherever
/// it is wholly black (pixels the two rasterisers share an edge in are not judged), so no copy
/// from a neighbour or another row is missing or extra.
#[test]
fn the_cobblestone_height_map_covers_the_drawn_cells() {
    let dir = tmp();
    let doc = tile_json(dir.path(), &COBBLES);
    let (w, h, _, _) = spec(&doc);
    // Pixels of an eighth of a millimetre: the gaps between cells are several pixels wide.
    let n = 800;
    let pixels = n.to_string();
    zf_ok(
        dir.path(),
        &[
            &["tile"],
            &COBBLES[..],
            &["--relief", "cone", "--pixels", &pixels, "-q", "-o", "h.png"],
        ]
        .concat(),
    );
    let (_, _, px) = grey16(&read(&dir.path().join("h.png")));
    for d in discs(&doc) {
        let (i, j) = ((d.c[0] / w * n as f64) as usize, ((h - d.c[1]) / h * n as f64) as usize);
        assert!(px[j.min(n - 1) * n + i.min(n - 1)] > 0, "no stone at the centre {:?}", d.c);
    }
    zf_ok(
        dir.path(),
        &[
            &["tile"],
            &COBBLES[..],
            &["--style", "filled", "--pixels", &pixels, "-q", "-o", "f.png"],
        ]
        .concat(),
    );
    let bytes = read(&dir.path().join("f.png"));
    let mut reader = png::Decoder::new(&bytes[..]).read_info().unwrap_or_else(|e| panic!("{e}"));
    let mut buf = vec![0u8; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        (frame.width, frame.height, frame.color_type),
        (n as u32, n as u32, png::ColorType::Rgba)
    );
    let faults = |px: &[u16]| {
        buf.chunks(4)
            .zip(px)
            .filter(|(p, &v)| (p[0] == 255 && v > 0) || (p[0] == 0 && v == 0))
            .count()
    };
    let bad = faults(&px);
    assert!(bad * 1000 <= n * n, "{bad} pixels disagree with the drawn cells");
    // The check fails for a map shifted by two pixels.
    let shifted: Vec<u16> = (0..n * n).map(|k| if k % n >= 2 { px[k - 2] } else { 0 }).collect();
    assert!(faults(&shifted) * 1000 > n * n, "a shifted map must be caught");
}

const PALETTE: [&str; 5] = ["#264653", "#2a9d8f", "#e9c46a", "#f4a261", "#e76f51"];

/// The palette index a rule gives tile disc `i` (`cycle` or `random`, as the README states them).
fn rule(by: &str, seed: u64, i: usize) -> usize {
    let k = PALETTE.len();
    match by {
        "cycle" => i % k,
        "random" => (splitmix64(seed ^ splitmix64(i as u64)) % k as u64) as usize,
        other => panic!("rule {other}"),
    }
}

/// The pieces of a tile picture whose colour is not `want` of the disc they show: a disc (or
/// part of one) is found as the disc of the plane holding a point inside it, a cobblestone as
/// the nearest centre to a point inside it. Pieces of the same disc on opposite edges must so
/// agree.
fn colour_faults(paths: &[Painted], plane: &[([f64; 2], f64, usize)], h: f64, cells: bool, want: impl Fn(usize) -> usize) -> Vec<String> {
    let mut bad = Vec::new();
    for p in paths {
        let q = [p.inside[0], h - p.inside[1]];
        // Distance to a disc's edge (negative inside), or to a cobblestone's centre.
        let key = |(c, r, _): &([f64; 2], f64, usize)| (q[0] - c[0]).hypot(q[1] - c[1]) - if cells { 0.0 } else { *r };
        let Some(best) = plane.iter().min_by(|a, b| key(a).total_cmp(&key(b))) else {
            bad.push("no disc".to_string());
            continue;
        };
        let i = best.2;
        if !cells && key(best) >= 0.0 {
            bad.push(format!("the piece at {q:?} lies in no disc"));
        } else if p.colour != PALETTE[want(i)] {
            bad.push(format!(
                "the piece at {q:?} of disc {i} is {}, expected {}",
                p.colour,
                PALETTE[want(i)]
            ));
        }
    }
    bad
}

/// Every piece of a coloured tile has its disc's colour: whole discs, discs cut at the edges
/// (so copies meet in one colour), their outlines and cobblestone cells, by the `cycle` and
/// `random` rules; and the background lies behind.
#[test]
fn pieces_take_the_colour_of_their_disc() {
    let dir = tmp();
    let d = dir.path();
    let list = PALETTE.join(",");
    for (extra, by, cells) in [
        (
            &["--radius", "8", "--spacing", "2", "--tries", "3000", "--style", "filled"][..],
            "cycle",
            false,
        ),
        (&["--radius", "8", "--spacing", "2", "--tries", "3000"][..], "random", false),
        (&COBBLES[2..], "random", true),
    ] {
        let base = [&["--seed", "3"][..], extra].concat();
        let mut coloured = base.clone();
        coloured.extend_from_slice(&["--palette", &list, "--color-by", by, "--background", "fefae0"]);
        if cells {
            coloured.extend_from_slice(&["--style", "filled"]);
        }
        zf_ok(d, &[&["tile"], &coloured[..], &["-o", "c.svg"]].concat());
        let doc = tile_json(d, &base);
        let (w, h, _, _) = spec(&doc);
        let plane = plane_indexed(&discs(&doc), w, h, -1..=2, [-w, 2.0 * w, -2.0 * h, 2.0 * h]);
        let svg = read(&d.join("c.svg"));
        // The background (read by its fill), then the pieces (by their fill, or their stroke
        // for outlines).
        let bg = painted(&svg, false).swap_remove(0);
        assert_eq!(bg.colour, "#fefae0");
        assert!(
            (bg.centre[0] - 0.5 * w).abs() < 1e-3 && (bg.centre[1] - 0.5 * h).abs() < 1e-3,
            "{:?}",
            bg.centre
        );
        let outline = !(extra.contains(&"filled") || cells);
        let pieces = painted(&svg, outline).split_off(1);
        assert!(pieces.len() > 30, "{by}: {} pieces", pieces.len());
        let faults = colour_faults(&pieces, &plane, h, cells, |i| rule(by, 3, i));
        assert!(
            faults.is_empty(),
            "{by} cells {cells}: {} faults, first {:?}",
            faults.len(),
            faults.first()
        );
        // The check can fail: the next colour along is caught.
        let shifted = colour_faults(&pieces, &plane, h, cells, |i| (rule(by, 3, i) + 1) % PALETTE.len());
        assert_eq!(shifted.len(), pieces.len(), "{by}: the check misses a wrong colour");
    }
}

/// The radius of every disc of an SVG in document order: a `<circle>`'s `r`, or the radius
/// of the first arc of a `<path>` (a disc cut by the sheet's edge).
fn disc_radii(svg: &str) -> Vec<f64> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = [rest.find("<circle "), rest.find("<path ")].into_iter().flatten().min() {
        let elem = &rest[i..];
        let end = elem.find('>').unwrap_or(elem.len());
        let e = &elem[..end];
        let r = if e.starts_with("<circle ") {
            e.split(" r=\"").nth(1).and_then(|t| t.split('"').next())
        } else {
            e.split(" A").nth(1).and_then(|t| t.split(',').next())
        };
        out.push(r.and_then(|t| t.parse().ok()).unwrap_or(f64::NAN));
        rest = &elem[end..];
    }
    out
}

/// `--color-by size` (the default) bands the drawn discs by their drawn size: a mosaic's rows,
/// each half the scale of the one below, run through the palette from the bottom up.
#[test]
fn size_bands_follow_the_drawn_size() {
    let dir = tmp();
    let d = dir.path();
    let list = PALETTE.join(",");
    let args = words("tile --radius 8 --spacing 2 --tries 3000 --layout mosaic --rows 3 --style filled");
    zf_ok(d, &[&args[..], &["--palette", &list, "-o", "m.svg"]].concat());
    let svg = read(&d.join("m.svg"));
    let paths = painted(&svg, false);
    // Every piece is a disc: a whole circle, or a disc cut by the sheet's edge (a path of
    // arcs and edges); its radius is the circle's, or its arcs'.
    let drawn = disc_radii(&String::from_utf8_lossy(&svg));
    assert_eq!(drawn.len(), paths.len());
    assert!(drawn.iter().all(|r| r.is_finite() && *r > 0.0), "a piece that is no disc");
    // The bands span every laid-out copy, the rim rows outside the sheet included (a row
    // below at twice the scale, one above at 1/2^3), even those whose discs miss the sheet.
    let json = words("tile --radius 8 --spacing 2 --tries 3000 -o - --format json");
    let tile = parse_json(&zf_ok(d, &json).stdout);
    let radii: Vec<f64> = tile["discs"]
        .as_array()
        .map_or(vec![], |v| v.iter().map(|c| f(c, "radius")).collect());
    let (rmax, rmin) = radii
        .iter()
        .fold((0.0f64, f64::INFINITY), |(a, b), &r| (a.max(2.0 * r), b.min(r / 8.0)));
    let k = PALETTE.len() as f64;
    let check = |shift: usize| {
        let mut bad = 0;
        let mut judged = 0;
        for (p, &r) in paths.iter().zip(&drawn) {
            let t = k * (rmax / r).ln() / (rmax / rmin).ln();
            // Radii are written to 0.1 µm: a disc at a band's edge is not judged.
            if (t - t.round()).abs() < 1e-3 {
                continue;
            }
            judged += 1;
            let band = ((t.floor() as usize).min(PALETTE.len() - 1) + shift) % PALETTE.len();
            if p.colour != PALETTE[band] {
                bad += 1;
            }
        }
        (bad, judged)
    };
    let (bad, judged) = check(0);
    assert!(judged > 100 && bad == 0, "{bad} of {judged} discs out of their size band");
    assert_eq!(check(1).0, judged, "the check misses a wrong band");
    // Every band is used: the rows span a factor of eight in size.
    for c in PALETTE {
        assert!(paths.iter().any(|p| p.colour == c), "{c} unused");
    }
}

/// `--layers colours`: a coloured tile's pieces in one Inkscape layer per palette colour, in
/// its order (read back in document order, the colours never go back to an earlier pen), and
/// refused without a palette or as size bands.
#[test]
fn tile_layers_hold_one_colour_each() {
    let dir = tmp();
    let d = dir.path();
    let list = PALETTE.join(",");
    let args = words("tile --radius 8 --spacing 2 --tries 3000 --layout mosaic --rows 3");
    zf_ok(
        d,
        &[
            &args[..],
            &["--palette", &list, "--color-by", "random", "--layers", "colours", "-o", "l.svg"],
        ]
        .concat(),
    );
    let pens = assert_pens_in_layers(&read(&d.join("l.svg")), &PALETTE);
    // The same pieces as without layers, only regrouped.
    zf_ok(
        d,
        &[&args[..], &["--palette", &list, "--color-by", "random", "-o", "m.svg"]].concat(),
    );
    assert_eq!(painted(&read(&d.join("m.svg")), true).len(), pens.len());
    for (extra, flag) in [
        (&["--layers", "colours"][..], "--layers"),
        (&["--layers", "size-bands:2"][..], "--layers"),
    ] {
        let o = zf(d, &[&args[..], extra, &["-o", "x.svg"]].concat());
        assert_eq!(o.code, 2, "{extra:?}");
        assert!(names_flag(&o.stderr, flag), "{}", o.stderr);
    }
}
