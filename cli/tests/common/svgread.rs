//! What a plotter draws from an SVG, read back independently of the writer: the XML through
//! usvg's own parser (`usvg::roxmltree`), the path data in f64 by hand (usvg turns arcs into
//! curves in f32, too coarse to check a cut to the micrometre), arcs rebuilt from their end
//! points as the SVG specification says (F.6.5). Only what zetafill writes is understood:
//! `circle`, `polygon`, `line`, `rect` and `path` with `M`, `L`, `A` and `Z`, no transforms.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

type P = [f64; 2];

/// One straight or circular piece of a subpath, in mm on the page (y down).
#[derive(Debug, Clone, Copy)]
enum Seg {
    Line(P, P),
    /// Centre, radius, start angle and signed sweep (angles as `atan2(y - cy, x - cx)`).
    Arc(P, f64, f64, f64),
}

impl Seg {
    fn length(&self) -> f64 {
        match *self {
            Seg::Line(a, b) => (b[0] - a[0]).hypot(b[1] - a[1]),
            Seg::Arc(_, r, _, da) => r * da.abs(),
        }
    }

    /// ½∮ x dy − y dx along the piece (Green's theorem).
    fn area(&self) -> f64 {
        match *self {
            Seg::Line(a, b) => 0.5 * (a[0] * b[1] - b[0] * a[1]),
            Seg::Arc(c, r, a0, da) => {
                let a1 = a0 + da;
                0.5 * (r * c[0] * (a1.sin() - a0.sin()) - r * c[1] * (a1.cos() - a0.cos()) + r * r * da)
            }
        }
    }
}

/// A subpath: its pieces and the points it reaches (written points, and arc extremes).
#[derive(Debug, Default)]
struct Sub {
    segs: Vec<Seg>,
    /// Points written in the file.
    written: Vec<P>,
    /// Extreme points of arcs, rebuilt from rounded numbers.
    extremes: Vec<P>,
}

/// An SVG read back.
#[derive(Debug, Default)]
pub struct SvgRead {
    /// Everything drawn outside every box, and every clip path or transform met.
    pub problems: Vec<String>,
    /// Pen-down length in mm: every subpath's pieces (a filled shape's outline too).
    pub pen: f64,
    /// Area covered in mm² (each element by its fill rule; nested loops of an even-odd
    /// element as outer minus holes).
    pub area: f64,
    /// Subpaths drawn.
    pub subpaths: usize,
}

fn num(s: &str) -> Result<f64, String> {
    s.trim().parse::<f64>().map_err(|e| format!("{s:?}: {e}"))
}

fn attr(n: &usvg::roxmltree::Node, name: &str) -> Result<f64, String> {
    num(n
        .attribute(name)
        .ok_or_else(|| format!("<{}> without {name}", n.tag_name().name()))?)
}

/// The arc from `a` to `b` of radius `r` with the SVG flags, as centre, radius, start and
/// sweep (a radius too small for the chord is scaled up, as the specification says). A chord
/// within the numbers' rounding of the diameter is read as a half circle: there the centre
/// moves by the square root of the rounding (a whole circle is written as two halves).
fn arc(a: P, b: P, r: f64, large: bool, sweep: bool) -> Seg {
    let (hx, hy) = ((a[0] - b[0]) / 2.0, (a[1] - b[1]) / 2.0);
    let h2 = hx * hx + hy * hy;
    let r = if (r - h2.sqrt()).abs() < 2e-4 {
        h2.sqrt()
    } else {
        r.max(h2.sqrt())
    };
    let k = ((r * r - h2) / h2).max(0.0).sqrt() * if large != sweep { 1.0 } else { -1.0 };
    let c = [k * hy + (a[0] + b[0]) / 2.0, -k * hx + (a[1] + b[1]) / 2.0];
    let a0 = (a[1] - c[1]).atan2(a[0] - c[0]);
    let a1 = (b[1] - c[1]).atan2(b[0] - c[0]);
    let mut da = a1 - a0;
    if sweep && da < 0.0 {
        da += TAU;
    } else if !sweep && da > 0.0 {
        da -= TAU;
    }
    Seg::Arc(c, r, a0, da)
}

/// The points at multiples of π/2 strictly inside an arc.
fn extremes(c: P, r: f64, a0: f64, da: f64) -> Vec<P> {
    let (lo, hi) = if da >= 0.0 { (a0, a0 + da) } else { (a0 + da, a0) };
    let k0 = (lo / FRAC_PI_2).floor() as i64 + 1;
    let k1 = (hi / FRAC_PI_2).ceil() as i64 - 1;
    (k0..=k1)
        .map(|k| k as f64 * FRAC_PI_2)
        .map(|t| [c[0] + r * t.cos(), c[1] + r * t.sin()])
        .collect()
}

fn push_arc(sub: &mut Sub, seg: Seg) {
    if let Seg::Arc(c, r, a0, da) = seg {
        sub.extremes.extend(extremes(c, r, a0, da));
    }
    sub.segs.push(seg);
}

/// The subpaths of path data (absolute `M`, `L`, `A`, `Z`).
fn path_data(d: &str) -> Result<Vec<Sub>, String> {
    let mut spaced = String::with_capacity(d.len() + 16);
    for ch in d.chars() {
        if ch.is_ascii_alphabetic() {
            spaced.push(' ');
            spaced.push(ch);
            spaced.push(' ');
        } else if ch == ',' {
            spaced.push(' ');
        } else {
            spaced.push(ch);
        }
    }
    let tokens: Vec<&str> = spaced.split_whitespace().collect();
    let mut subs: Vec<Sub> = Vec::new();
    let (mut at, mut start) = ([0.0; 2], [0.0; 2]);
    let mut i = 0;
    let mut cmd = "";
    while i < tokens.len() {
        if tokens[i].chars().all(|c| c.is_ascii_alphabetic()) {
            cmd = tokens[i];
            i += 1;
            if cmd == "Z" {
                let sub = subs.last_mut().ok_or("Z before M")?;
                if at != start {
                    sub.segs.push(Seg::Line(at, start));
                }
                at = start;
            }
            continue;
        }
        let mut take = |n: usize| -> Result<Vec<f64>, String> {
            let v = tokens.get(i..i + n).ok_or("path data ends early")?.iter().map(|t| num(t)).collect();
            i += n;
            v
        };
        match cmd {
            "M" => {
                let v = take(2)?;
                at = [v[0], v[1]];
                start = at;
                subs.push(Sub {
                    written: vec![at],
                    ..Sub::default()
                });
                cmd = "L";
            }
            "L" => {
                let v = take(2)?;
                let b = [v[0], v[1]];
                let sub = subs.last_mut().ok_or("L before M")?;
                sub.segs.push(Seg::Line(at, b));
                sub.written.push(b);
                at = b;
            }
            "A" => {
                let v = take(7)?;
                if v[0] != v[1] || v[2] != 0.0 {
                    return Err(format!("not a circular arc: {v:?}"));
                }
                let b = [v[5], v[6]];
                let sub = subs.last_mut().ok_or("A before M")?;
                push_arc(sub, arc(at, b, v[0], v[3] != 0.0, v[4] != 0.0));
                sub.written.push(b);
                at = b;
            }
            other => return Err(format!("path command {other:?}")),
        }
    }
    Ok(subs)
}

/// A closed polygon through `x,y x,y ...`.
fn polygon(points: &str) -> Result<Sub, String> {
    let v: Vec<f64> = points
        .split([' ', ','])
        .filter(|s| !s.is_empty())
        .map(num)
        .collect::<Result<_, _>>()?;
    let pts: Vec<P> = v.chunks(2).map(|c| [c[0], c.get(1).copied().unwrap_or(f64::NAN)]).collect();
    let n = pts.len();
    Ok(Sub {
        segs: (0..n).map(|i| Seg::Line(pts[i], pts[(i + 1) % n])).collect(),
        written: pts,
        extremes: vec![],
    })
}

/// The subpaths one element draws.
fn element(n: &usvg::roxmltree::Node) -> Result<Vec<Sub>, String> {
    Ok(match n.tag_name().name() {
        "circle" => {
            let (c, r) = ([attr(n, "cx")?, attr(n, "cy")?], attr(n, "r")?);
            let mut sub = Sub::default();
            push_arc(&mut sub, Seg::Arc(c, r, -PI, TAU));
            sub.extremes.push([c[0] - r, c[1]]);
            vec![sub]
        }
        "polygon" => vec![polygon(n.attribute("points").unwrap_or(""))?],
        "line" => {
            let (a, b) = ([attr(n, "x1")?, attr(n, "y1")?], [attr(n, "x2")?, attr(n, "y2")?]);
            vec![Sub {
                segs: vec![Seg::Line(a, b)],
                written: vec![a, b],
                extremes: vec![],
            }]
        }
        "rect" => {
            let (x, y) = (n.attribute("x").map_or(Ok(0.0), num)?, n.attribute("y").map_or(Ok(0.0), num)?);
            let (w, h) = (attr(n, "width")?, attr(n, "height")?);
            vec![polygon(&format!("{x},{y} {},{y} {},{} {x},{}", x + w, x + w, y + h, y + h))?]
        }
        "path" => path_data(n.attribute("d").unwrap_or(""))?,
        _ => vec![],
    })
}

/// Reads `svg` and checks that every subpath drawn lies inside one of `boxes` (mm on the
/// page, y down: `[x0, y0, x1, y1]`): the points written in the file within `tol`, the
/// extremes of arcs (rebuilt from the file's rounded centres and radii) within `tol_arc`.
/// Clip paths and transforms are problems too: a plotter ignores the first, and this reader
/// the second.
pub fn read_svg(svg: &[u8], boxes: &[[f64; 4]], tol: f64, tol_arc: f64) -> SvgRead {
    let text = String::from_utf8_lossy(svg);
    let doc = usvg::roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("not XML: {e}"));
    let mut out = SvgRead::default();
    let in_box = |b: &[f64; 4], p: &P, t: f64| p[0] >= b[0] - t && p[0] <= b[2] + t && p[1] >= b[1] - t && p[1] <= b[3] + t;
    let inside = |p: &P, t: f64| boxes.iter().any(|b| in_box(b, p, t));
    for n in doc.descendants().filter(|n| n.is_element()) {
        let name = n.tag_name().name();
        if name == "clipPath" {
            out.problems.push("a <clipPath>".into());
        }
        if n.ancestors().any(|a| matches!(a.tag_name().name(), "defs" | "clipPath")) {
            continue;
        }
        for a in ["clip-path", "transform", "mask"] {
            if let Some(v) = n.attribute(a) {
                out.problems.push(format!("<{name}> has {a}=\"{v}\""));
            }
        }
        let subs = match element(&n) {
            Ok(s) => s,
            Err(e) => {
                out.problems.push(format!("<{name}>: {e}"));
                continue;
            }
        };
        let evenodd = n.attribute("fill-rule") == Some("evenodd");
        let areas: Vec<f64> = subs.iter().map(|s| s.segs.iter().map(Seg::area).sum::<f64>().abs()).collect();
        out.area += if evenodd {
            areas.first().copied().unwrap_or(0.0) - areas.iter().skip(1).sum::<f64>()
        } else {
            areas.iter().sum()
        };
        for s in &subs {
            out.subpaths += 1;
            out.pen += s.segs.iter().map(Seg::length).sum::<f64>();
            let fits = |b: &[f64; 4]| s.written.iter().all(|p| in_box(b, p, tol)) && s.extremes.iter().all(|p| in_box(b, p, tol_arc));
            if !boxes.iter().any(fits) {
                let bad = s
                    .written
                    .iter()
                    .find(|p| !inside(p, tol))
                    .map(|p| format!("point {p:?}"))
                    .or_else(|| {
                        s.extremes
                            .iter()
                            .find(|p| !inside(p, tol_arc))
                            .map(|p| format!("arc extreme {p:?}"))
                    })
                    .unwrap_or_else(|| "across two boxes".into());
                out.problems.push(format!("<{name}> draws outside: {bad}"));
            }
        }
    }
    out
}

/// The clip paths a renderer applies (usvg's tree).
pub fn usvg_clip_paths(svg: &[u8]) -> usize {
    fn walk(g: &usvg::Group) -> usize {
        usize::from(g.clip_path().is_some())
            + g.children()
                .iter()
                .map(|n| match n {
                    usvg::Node::Group(g) => walk(g),
                    _ => 0,
                })
                .sum::<usize>()
    }
    let tree = usvg::Tree::from_data(svg, &usvg::Options::default()).unwrap_or_else(|e| panic!("usvg: {e}"));
    walk(tree.root())
}

/// Pen-down length of a G-code program whose travel is rapid (`G0`) and whose every `G1`,
/// `G2` and `G3` with X or Y draws: lines, and arcs by their centre offsets `I`, `J`.
pub fn gcode_pen_length(text: &str) -> f64 {
    let mut at = [0.0f64; 2];
    let mut len = 0.0;
    for line in text.lines() {
        let line = line.split(';').next().unwrap_or("");
        let words: Vec<(char, f64)> = line
            .split_whitespace()
            .filter_map(|w| Some((w.chars().next()?, w[1..].parse::<f64>().ok()?)))
            .collect();
        let word = |l: char| words.iter().find(|w| w.0 == l).map(|w| w.1);
        let (Some(g), true) = (word('G'), word('X').is_some() || word('Y').is_some()) else {
            continue;
        };
        let to = [word('X').unwrap_or(at[0]), word('Y').unwrap_or(at[1])];
        if g == 1.0 {
            len += (to[0] - at[0]).hypot(to[1] - at[1]);
        } else if g == 2.0 || g == 3.0 {
            let (i, j) = (word('I').unwrap_or(0.0), word('J').unwrap_or(0.0));
            let c = [at[0] + i, at[1] + j];
            let (a0, a1) = ((at[1] - c[1]).atan2(at[0] - c[0]), (to[1] - c[1]).atan2(to[0] - c[0]));
            let span = if to == at {
                TAU
            } else if g == 3.0 {
                (a1 - a0).rem_euclid(TAU)
            } else {
                (a0 - a1).rem_euclid(TAU)
            };
            len += i.hypot(j) * span;
        }
        at = to;
    }
    len
}
