//! Arcs as cubic Bézier curves, computed here, for the SVG a PNG is rendered from.
//!
//! usvg turns every arc (an `A` command, a `<circle>`) into curves with the platform's
//! trigonometry, whose last bits differ between the host's C library and the browser's
//! (Rust's `compiler-builtins`): the same SVG then gives a few other pixels in the page than
//! on the command line. So before a PNG is rendered, the arcs of the SVG this crate wrote
//! become `C` commands computed with the pinned `libm`, the same bits on every target, and
//! usvg has no trigonometry left to do. The SVG files themselves keep their arcs.
//!
//! Each arc is split into pieces of at most 45 degrees; a piece's curve strays from the
//! circle by at most 4.2e-6 of its radius (0.004 px for a radius of 1,000 px).

use std::borrow::Cow;
use std::f64::consts::{FRAC_PI_4, PI, TAU};
use std::fmt::Write;

/// `svg` with its arcs and circles as cubic curves; itself when it has none.
pub fn arcs_as_curves(svg: &str) -> Cow<'_, str> {
    if !svg.contains("<circle") && !svg.contains('A') {
        return Cow::Borrowed(svg);
    }
    let mut out = String::with_capacity(svg.len() + svg.len() / 4);
    let mut rest = svg;
    loop {
        let circle = rest.find("<circle ");
        let path = rest.find(" d=\"");
        match (circle, path) {
            (Some(c), p) if p.is_none_or(|p| c < p) => {
                let Some(end) = rest[c..].find("/>").map(|e| c + e) else { break };
                out.push_str(&rest[..c]);
                match circle_path(&rest[c..end]) {
                    Some(elem) => out.push_str(&elem),
                    None => out.push_str(&rest[c..end]),
                }
                rest = &rest[end..];
            }
            (_, Some(p)) => {
                let start = p + 4;
                let Some(end) = rest[start..].find('"').map(|e| start + e) else {
                    break;
                };
                out.push_str(&rest[..start]);
                match path_curves(&rest[start..end]) {
                    Some(d) => out.push_str(&d),
                    None => out.push_str(&rest[start..end]),
                }
                rest = &rest[end..];
            }
            _ => break,
        }
    }
    out.push_str(rest);
    Cow::Owned(out)
}

/// The value of attribute `name` in an element's text.
fn attribute<'a>(elem: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let at = elem.find(&key)? + key.len();
    elem[at..].split('"').next()
}

/// A `<circle .../>` (without its `/>`) as a `<path>` of eight curves, its other attributes
/// kept.
fn circle_path(elem: &str) -> Option<String> {
    let num = |name: &str| attribute(elem, name)?.parse::<f64>().ok();
    let (cx, cy, r) = (num("cx")?, num("cy")?, num("r")?);
    let mut d = String::new();
    let _ = write!(d, "M{},{}", cx + r, cy);
    curves(&mut d, [cx, cy], r, 0.0, TAU, [cx + r, cy]);
    d.push_str(" Z");
    let mut rest = elem.trim_start_matches("<circle").to_string();
    for name in ["cx", "cy", "r"] {
        let v = attribute(&rest, name)?.to_string();
        rest = rest.replacen(&format!(" {name}=\"{v}\""), "", 1);
    }
    Some(format!("<path d=\"{d}\"{rest}"))
}

/// Appends the curves of the arc of centre `c` and radius `r` from angle `a0` over `sweep`
/// (y down, as in SVG), ending exactly at `end`.
fn curves(d: &mut String, c: [f64; 2], r: f64, a0: f64, sweep: f64, end: [f64; 2]) {
    let n = (sweep.abs() / FRAC_PI_4).ceil().max(1.0) as usize;
    let step = sweep / n as f64;
    let k = 4.0 / 3.0 * libm::tan(step / 4.0) * r;
    let at = |a: f64| ([c[0] + r * libm::cos(a), c[1] + r * libm::sin(a)], [-libm::sin(a), libm::cos(a)]);
    for i in 0..n {
        let (a, b) = (a0 + step * i as f64, a0 + step * (i + 1) as f64);
        let (p, tp) = at(a);
        let (q, tq) = at(b);
        let q = if i + 1 == n { end } else { q };
        let _ = write!(
            d,
            " C{},{} {},{} {},{}",
            p[0] + k * tp[0],
            p[1] + k * tp[1],
            q[0] - k * tq[0],
            q[1] - k * tq[1],
            q[0],
            q[1]
        );
    }
}

/// Path data with every `A` (circular, unrotated, as this crate writes them) turned into
/// curves; `None` when it holds a command this crate does not write, or no arc.
fn path_curves(d: &str) -> Option<String> {
    if !d.contains('A') {
        return None;
    }
    let mut out = String::with_capacity(2 * d.len());
    let (mut cur, mut start) = ([0.0f64; 2], [0.0f64; 2]);
    let mut words = d.split([' ', ',']).filter(|w| !w.is_empty()).peekable();
    let num = |w: Option<&str>| w.and_then(|w| w.parse::<f64>().ok());
    while let Some(w) = words.next() {
        let (cmd, first) = w.split_at(1);
        let first = (!first.is_empty()).then_some(first);
        if !out.is_empty() {
            out.push(' ');
        }
        match cmd {
            "M" | "L" => {
                let p = [num(first.or_else(|| words.next()))?, num(words.next())?];
                let _ = write!(out, "{cmd}{},{}", p[0], p[1]);
                cur = p;
                if cmd == "M" {
                    start = p;
                }
            }
            "Z" => {
                out.push('Z');
                cur = start;
            }
            "A" => {
                let rx = num(first.or_else(|| words.next()))?;
                let ry = num(words.next())?;
                let rot = num(words.next())?;
                let large = num(words.next())? != 0.0;
                let sweep = num(words.next())? != 0.0;
                let p = [num(words.next())?, num(words.next())?];
                if rx != ry || rot != 0.0 {
                    return None;
                }
                arc(&mut out, cur, p, rx, large, sweep);
                cur = p;
            }
            _ => return None,
        }
    }
    Some(out)
}

/// The SVG arc from `p1` to `p2` of radius `r` (the centre found as the SVG specification's
/// implementation notes say, the radius scaled up when it cannot reach) as curves.
fn arc(out: &mut String, p1: [f64; 2], p2: [f64; 2], r: f64, large: bool, sweep: bool) {
    let (hx, hy) = (0.5 * (p1[0] - p2[0]), 0.5 * (p1[1] - p2[1]));
    let h2 = hx * hx + hy * hy;
    if h2 == 0.0 {
        return;
    }
    let r = r.abs();
    if r == 0.0 {
        let _ = write!(out, "L{},{}", p2[0], p2[1]);
        return;
    }
    let r = if h2 > r * r { h2.sqrt() } else { r };
    let sign = if large != sweep { 1.0 } else { -1.0 };
    let coef = sign * ((r * r - h2).max(0.0) / h2).sqrt();
    let (ox, oy) = (coef * hy, -coef * hx);
    let c = [ox + 0.5 * (p1[0] + p2[0]), oy + 0.5 * (p1[1] + p2[1])];
    let u = [p1[0] - c[0], p1[1] - c[1]];
    let v = [p2[0] - c[0], p2[1] - c[1]];
    let a0 = libm::atan2(u[1], u[0]);
    let mut delta = libm::atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]);
    if sweep && delta < 0.0 {
        delta += TAU;
    } else if !sweep && delta > 0.0 {
        delta -= TAU;
    }
    // A large arc that rounding left short of half a turn is the half turn.
    if large && delta.abs() < PI {
        delta = if sweep { PI } else { -PI };
    }
    // The curves are written without a leading space; drop the one `curves` adds first.
    let mut d = String::new();
    curves(&mut d, c, r, a0, delta, p2);
    out.push_str(d.trim_start());
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The points of a cubic at `t`.
    fn bezier(p: [[f64; 2]; 4], t: f64) -> [f64; 2] {
        let s = 1.0 - t;
        let w = [s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t];
        [0, 1].map(|k| (0..4).map(|i| w[i] * p[i][k]).sum())
    }

    /// Every curve of path data `d` (after its first `M`) sampled, as distances from `c`.
    fn radii(d: &str, c: [f64; 2]) -> Vec<f64> {
        let nums: Vec<Vec<f64>> = d
            .split(' ')
            .map(|w| {
                w.trim_start_matches(['M', 'C', 'L', 'Z'])
                    .split(',')
                    .filter_map(|v| v.parse().ok())
                    .collect()
            })
            .collect();
        let mut pen = [nums[0][0], nums[0][1]];
        let mut out = Vec::new();
        let words: Vec<&str> = d.split(' ').collect();
        let mut i = 1;
        while i + 2 < words.len() && words[i].starts_with('C') {
            let p = [
                pen,
                [nums[i][0], nums[i][1]],
                [nums[i + 1][0], nums[i + 1][1]],
                [nums[i + 2][0], nums[i + 2][1]],
            ];
            for k in 0..=8 {
                let q = bezier(p, f64::from(k) / 8.0);
                out.push(libm::hypot(q[0] - c[0], q[1] - c[1]));
            }
            pen = p[3];
            i += 3;
        }
        out
    }

    #[test]
    fn a_circle_becomes_eight_curves_on_it() {
        let svg = r#"<g><circle cx="10" cy="20" r="5" fill="red"/></g>"#;
        let out = arcs_as_curves(svg);
        assert!(
            out.starts_with("<g><path d=\"M15,20 C") && out.ends_with(" Z\" fill=\"red\"/></g>"),
            "{out}"
        );
        let d = attribute(&out, "d").expect("a d");
        let r = radii(d, [10.0, 20.0]);
        assert_eq!(r.len(), 8 * 9);
        assert!(r.iter().all(|r| (r - 5.0).abs() < 5.0 * 4.3e-6), "{r:?}");
    }

    #[test]
    fn an_arc_keeps_its_ends_centre_and_side() {
        // A quarter from (10, 0) to (0, 10) about the origin: sweep 1 turns through (7.07, 7.07).
        let d = path_curves("M10,0 A10,10 0 0 1 0,10").expect("curves");
        assert!(d.starts_with("M10,0 C") && d.ends_with(" 0,10"), "{d}");
        let r = radii(&d, [0.0, 0.0]);
        assert!(r.iter().all(|r| (r - 10.0).abs() < 1e-4), "{r:?}");
        // The other way round the same circle: sweep 0, three quarters, through (-7, -7).
        let d = path_curves("M10,0 A10,10 0 1 0 0,10").expect("curves");
        assert_eq!(d.matches('C').count(), 6, "{d}");
        assert!(radii(&d, [0.0, 0.0]).iter().all(|r| (r - 10.0).abs() < 1e-4));
        // Other commands pass as they were; a command this crate does not write leaves the
        // data alone.
        assert_eq!(path_curves("M0,0 L1,1 Z").as_deref(), None);
        assert_eq!(path_curves("M0,0 Q1,1 2,2 A1,1 0 0 1 3,3"), None);
        let d = path_curves("M0,0 L2,0 A1,1 0 0 1 2,2 Z").expect("curves");
        assert!(d.starts_with("M0,0 L2,0 C") && d.ends_with(" 2,2 Z"), "{d}");
    }
}
