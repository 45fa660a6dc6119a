//! SVG outlines (`--region svg:FILE`, `io::svgin`).

use super::specs::places_shapes;
use crate::*;

/// Numbers for SVG attributes: plain, extreme, negative, with units.
fn svg_number() -> impl Strategy<Value = String> {
    prop_oneof![
        16 => (-500.0f64..500.0).prop_map(|v| format!("{v:.2}")),
        2 => (0u32..200).prop_map(|v| v.to_string()),
        1 => select(vec!["0", "-0", "1e30", "-1e30", "1e-30", "3.4e38", "1e39", "NaN", "inf", ".5", "1e", "--1", "5e-324", "1e308"])
            .prop_map(str::to_string),
    ]
}

fn svg_length() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => ((1.0f64..600.0), select(vec!["", "mm", "mm", "cm", "in", "px", "pt"])).prop_map(|(n, u)| format!("{n:.1}{u}")),
        1 => (svg_number(), select(vec!["", "mm", "pc", "%", "em", "q", "furlong"])).prop_map(|(n, u)| format!("{n}{u}")),
    ]
}

fn transform() -> impl Strategy<Value = String> {
    let n = || svg_number();
    let one = prop_oneof![
        (n(), n()).prop_map(|(a, b)| format!("translate({a},{b})")),
        n().prop_map(|a| format!("scale({a})")),
        (n(), n()).prop_map(|(a, b)| format!("scale({a} {b})")),
        n().prop_map(|a| format!("rotate({a})")),
        (n(), n(), n()).prop_map(|(a, b, c)| format!("rotate({a},{b},{c})")),
        n().prop_map(|a| format!("skewX({a})")),
        n().prop_map(|a| format!("skewY({a})")),
        prop::collection::vec(n(), 6).prop_map(|v| format!("matrix({})", v.join(","))),
        Just("matrix(0,0,0,0,0,0)".to_string()),
        Just("scale(0)".to_string()),
    ];
    prop::collection::vec(one, 1..3).prop_map(|v| v.join(" "))
}

/// Path data: subpaths of every command, absolute and relative, closed or open.
fn path_data() -> impl Strategy<Value = String> {
    let n = || svg_number();
    let cmd = prop_oneof![
        4 => (select(vec!["L", "l", "M", "m", "T", "t"]), n(), n()).prop_map(|(c, x, y)| format!("{c}{x},{y}")),
        1 => (select(vec!["H", "h", "V", "v"]), n()).prop_map(|(c, x)| format!("{c}{x}")),
        1 => (select(vec!["C", "c"]), prop::collection::vec(n(), 6)).prop_map(|(c, v)| format!("{c}{}", v.join(" "))),
        1 => (select(vec!["Q", "q", "S", "s"]), prop::collection::vec(n(), 4)).prop_map(|(c, v)| format!("{c}{}", v.join(" "))),
        1 => (select(vec!["A", "a"]), n(), n(), n(), any::<bool>(), any::<bool>(), n(), n())
            .prop_map(|(c, rx, ry, t, l, s, x, y)| format!("{c}{rx} {ry} {t} {} {} {x} {y}", u8::from(l), u8::from(s))),
        2 => Just("Z".to_string()),
    ];
    let sub = (n(), n(), prop::collection::vec(cmd, 0..12), 0u8..4).prop_map(|(x, y, cmds, close)| {
        let end = match close {
            0 => "",
            1 => " z",
            _ => " Z",
        };
        format!("M{x},{y} {}{end}", cmds.join(" "))
    });
    prop_oneof![
        6 => prop::collection::vec(sub, 1..4).prop_map(|v| v.join(" ")),
        1 => any_text(),
    ]
}

/// A star (with a hole, as a second subpath) as path data: a closed outline that is simple.
fn star_path() -> impl Strategy<Value = String> {
    (3usize..12, 5.0f64..90.0, 0.2f64..0.9, any::<bool>()).prop_map(|(n, r, inner, hole)| {
        let pt = |k: usize, rr: f64| {
            let t = k as f64 / (2 * n) as f64 * std::f64::consts::TAU;
            format!("{:.3},{:.3}", 100.0 + rr * t.cos(), 100.0 + rr * t.sin())
        };
        let mut d = format!("M{}", pt(0, r));
        for k in 1..2 * n {
            d.push_str(&format!(" L{}", pt(k, if k % 2 == 0 { r } else { r * inner })));
        }
        d.push_str(" Z");
        if hole {
            let h = r * inner * 0.5;
            d.push_str(&format!(" M{} L{} L{} Z", pt(0, h), pt(n * 2 / 3, h), pt(n * 4 / 3, h)));
        }
        d
    })
}

/// An element: a path, a basic shape, or a group (with a transform) of elements.
fn element() -> impl Strategy<Value = String> {
    let n = || svg_number();
    let attrs = || {
        (
            prop::option::of(transform()),
            select(vec![
                "",
                "fill=\"none\"",
                "fill=\"black\"",
                "stroke=\"red\"",
                "fill-rule=\"evenodd\"",
                "visibility=\"hidden\"",
                "display=\"none\"",
            ]),
        )
            .prop_map(|(t, a)| format!("{} {a}", t.map(|t| format!("transform=\"{t}\"")).unwrap_or_default()))
    };
    let leaf = prop_oneof![
        4 => (path_data(), attrs()).prop_map(|(d, a)| format!("<path d=\"{d}\" {a}/>")),
        6 => (star_path(), attrs()).prop_map(|(d, a)| format!("<path d=\"{d}\" {a}/>")),
        1 => (n(), n(), n(), n(), n(), attrs()).prop_map(|(x, y, w, h, rx, a)| format!("<rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" rx=\"{rx}\" {a}/>")),
        1 => (n(), n(), n(), attrs()).prop_map(|(x, y, r, a)| format!("<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\" {a}/>")),
        1 => (n(), n(), n(), n(), attrs()).prop_map(|(x, y, rx, ry, a)| format!("<ellipse cx=\"{x}\" cy=\"{y}\" rx=\"{rx}\" ry=\"{ry}\" {a}/>")),
        1 => (prop::collection::vec(n(), 0..12), any::<bool>(), attrs()).prop_map(|(v, poly, a)| {
            let tag = if poly { "polygon" } else { "polyline" };
            format!("<{tag} points=\"{}\" {a}/>", v.join(" "))
        }),
        1 => (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!("<line x1=\"{a}\" y1=\"{b}\" x2=\"{c}\" y2=\"{d}\"/>")),
        1 => Just("<use href=\"#p\"/>".to_string()),
        1 => Just("<text x=\"1\" y=\"1\">A</text>".to_string()),
    ];
    leaf.prop_recursive(3, 12, 4, move |inner| {
        (prop::collection::vec(inner, 0..4), prop::option::of(transform())).prop_map(|(kids, t)| {
            format!(
                "<g {}>{}</g>",
                t.map(|t| format!("transform=\"{t}\"")).unwrap_or_default(),
                kids.concat()
            )
        })
    })
}

/// A document: a root with random size and view box, and elements.
fn svg_document() -> impl Strategy<Value = String> {
    (
        prop::option::of(svg_length()),
        prop::option::of(svg_length()),
        prop::option::of(prop_oneof![
            3 => (0.0f64..50.0, 0.0f64..50.0, 10.0f64..500.0, 10.0f64..500.0).prop_map(|(x, y, w, h)| [x, y, w, h].iter().map(|v| format!("{v:.1}")).collect::<Vec<_>>()),
            1 => prop::collection::vec(svg_number(), 4),
        ]),
        prop::collection::vec(element(), 0..5),
        any::<bool>(),
    )
        .prop_map(|(w, h, vb, kids, defs)| {
            let mut root = String::from("<svg xmlns=\"http://www.w3.org/2000/svg\"");
            if let Some(w) = w {
                root.push_str(&format!(" width=\"{w}\""));
            }
            if let Some(h) = h {
                root.push_str(&format!(" height=\"{h}\""));
            }
            if let Some(vb) = vb {
                root.push_str(&format!(" viewBox=\"{}\"", vb.join(" ")));
            }
            let defs = if defs {
                "<defs><path id=\"p\" d=\"M10,10 L90,10 L50,80 Z\"/></defs>"
            } else {
                ""
            };
            format!("{root}>{defs}{}</svg>", kids.concat())
        })
}

/// Bytes of a file given as `svg:FILE`: arbitrary bytes, documents, and documents with a
/// few bytes changed.
fn svg_bytes() -> impl Strategy<Value = Vec<u8>> {
    prop_oneof![
        1 => prop::collection::vec(any::<u8>(), 0..600),
        8 => svg_document().prop_map(String::into_bytes),
        1 => (svg_document(), prop::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6)).prop_map(|(doc, edits)| {
            let mut b = doc.into_bytes();
            for (at, byte, how) in edits {
                if b.is_empty() {
                    break;
                }
                let i = at.index(b.len());
                match how {
                    0 => b[i] = byte,
                    1 => b.insert(i, byte),
                    _ => {
                        b.remove(i);
                    }
                }
            }
            b
        }),
    ]
}

/// What an outline must be: rings of at least 3 finite points, ends increasing to the
/// number of points; then the core accepts it or refuses it with an error value, and the
/// run resolves it into a region that places shapes or a message naming `--region`.
/// Outline rings: the points, ring after ring, and the end of each ring.
type Rings = (Vec<zetafill::Point<f64>>, Vec<usize>);

fn check_outline(path: &Path, tally: &Tally) -> Result<Option<Rings>, String> {
    let (points, ends) = match zetafill_cli::io::svgin::read_outline(path) {
        Ok(o) => o,
        Err(e) => {
            let msg = zetafill_cli::plan::region::outline_error(path, e).to_string();
            readable(&msg)?;
            tally.add("no outline");
            return Ok(None);
        }
    };
    let mut start = 0;
    for &e in &ends {
        if e < start + 3 {
            return Err(format!("a ring of {} points: ends {ends:?}", e.saturating_sub(start)));
        }
        start = e;
    }
    if start != points.len() || ends.is_empty() {
        return Err(format!("ends {ends:?} for {} points", points.len()));
    }
    if let Some(p) = points.iter().find(|p| !(p.x.is_finite() && p.y.is_finite())) {
        return Err(format!("a point that is not finite: {p:?}"));
    }
    let mut tree = vec![0u32; PolygonRegion::scratch_words(points.len())];
    match PolygonRegion::new_in(&points, &ends, &mut tree) {
        Ok(_) => tally.add("polygons"),
        Err(e) => {
            let _ = e.to_string();
            tally.add("refused by the core");
        }
    }
    let data = RegionData::load(&RegionSpec::Svg(path.to_path_buf())).map_err(|e| format!("read twice, refused: {e}"))?;
    let mut scratch = Vec::new();
    match data.region(false, &mut scratch) {
        Ok(region) => places_shapes(region)?,
        Err(e) => {
            let msg = e.to_string();
            readable(&msg)?;
            if !msg.starts_with("--region") {
                return Err(format!("refused without naming --region: {msg}"));
            }
        }
    }
    Ok(Some((points, ends)))
}

#[test]
fn fuzz_svg_outlines() {
    let dir = Scratch::new();
    let tally = Tally::new(&["no outline", "polygons", "refused by the core"]);
    fuzz("svg_outlines", 1500, svg_bytes(), |bytes| {
        let path = dir.write("outline.svg", &bytes);
        check_outline(&path, &tally).map(|_| ())
    });
    tally.report("svg outlines");
    assert!(
        tally.get("polygons") * 10 >= cases(1500) as u64,
        "fewer than one file in ten gave a polygon"
    );
}

/// A polygon drawn in a 1:1 mm document (no transform) reads back where it was drawn, in
/// the region frame (y up from the bottom of the page).
#[test]
fn fuzz_svg_polygons_read_back_where_drawn() {
    let dir = Scratch::new();
    let tally = Tally::new(&["polygons"]);
    let ring = (3usize..24, 1.0f64..90.0, 0.2f64..1.0, any::<u64>(), select(vec!["path", "polygon"]));
    fuzz("svg_read_back", 500, ring, |(n, r, inner, seed, tag)| {
        let mut m = seed;
        let mut unit = || {
            m = m.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (m >> 11) as f64 / (1u64 << 53) as f64
        };
        // Star-shaped about (100, 100), vertices on a 0.01 mm grid.
        let pts: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let t = (k as f64 + 0.5 * unit()) / n as f64 * std::f64::consts::TAU;
                let rr = r * (inner + (1.0 - inner) * unit());
                [
                    ((100.0 + rr * t.cos()) * 100.0).round() / 100.0,
                    ((100.0 + rr * t.sin()) * 100.0).round() / 100.0,
                ]
            })
            .collect();
        let list: Vec<String> = pts.iter().map(|p| format!("{},{}", p[0], p[1])).collect();
        let el = if tag == "path" {
            format!("<path d=\"M{} Z\"/>", list.join(" L"))
        } else {
            format!("<polygon points=\"{}\"/>", list.join(" "))
        };
        let doc = format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" height=\"200mm\" viewBox=\"0 0 200 200\">{el}</svg>");
        let path = dir.write("polygon.svg", doc.as_bytes());
        let Some((points, ends)) = check_outline(&path, &tally)? else {
            return Err(format!("no outline in {doc}"));
        };
        // Repeated vertices (after rounding) are dropped.
        let mut want: Vec<[f64; 2]> = pts.iter().map(|p| [p[0], 200.0 - p[1]]).collect();
        want.dedup();
        if want.len() > 1 && want.first() == want.last() {
            want.pop();
        }
        let got: Vec<[f64; 2]> = points.iter().map(|p| [p.x, p.y]).collect();
        let close = got.len() == want.len()
            && got
                .iter()
                .zip(&want)
                .all(|(a, b)| (a[0] - b[0]).abs() < 1e-3 && (a[1] - b[1]).abs() < 1e-3);
        if ends != [got.len()] || !close {
            return Err(format!("drawn {want:?}, read {got:?} (ends {ends:?})"));
        }
        Ok(())
    });
}
