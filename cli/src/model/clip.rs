//! Exact clipping of paths to a rectangle: segments by Liang–Barsky, circles and arcs cut at
//! their crossings into arcs, so that a periodic tile's images end exactly at its edges.

use super::{polar, Bounds, Path, Pt};
use std::f64::consts::{PI, TAU};

/// The parameter range `[t0, t1]` of segment `a -> b` inside `r` (Liang–Barsky), if any.
pub fn clip_segment(a: Pt, b: Pt, r: &Bounds) -> Option<(f64, f64)> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-dx, a[0] - r.x0), (dx, r.x1 - a[0]), (-dy, a[1] - r.y0), (dy, r.y1 - a[1])] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 < t1).then_some((t0, t1))
}

fn lerp(a: Pt, b: Pt, t: f64) -> Pt {
    if t == 0.0 {
        a
    } else if t == 1.0 {
        b
    } else {
        [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]
    }
}

/// A path cut to the parts inside `r` (edges on the boundary count as inside).
pub fn clip_path(p: &Path, r: &Bounds) -> Vec<Path> {
    if p.bounds().inside(r, 0.0) {
        return vec![p.clone()];
    }
    match p {
        Path::Polyline { points, closed } => clip_polyline(points, *closed, r),
        Path::Arc {
            center,
            radius,
            start,
            sweep,
        } => clip_arc(*center, *radius, *start, *sweep, r),
    }
}

fn clip_polyline(points: &[Pt], closed: bool, r: &Bounds) -> Vec<Path> {
    let n = points.len();
    if n < 2 {
        return vec![];
    }
    let inside = |p: &Pt| p[0] >= r.x0 && p[0] <= r.x1 && p[1] >= r.y0 && p[1] <= r.y1;
    // A closed polyline is walked from a vertex outside, so no piece is split at the seam.
    let (first, edges) = if closed {
        (points.iter().position(|p| !inside(p)).unwrap_or(0), n)
    } else {
        (0, n - 1)
    };
    let mut out = Vec::new();
    let mut cur: Vec<Pt> = Vec::new();
    for k in 0..edges {
        let (a, b) = (points[(first + k) % n], points[(first + k + 1) % n]);
        match clip_segment(a, b, r) {
            Some((t0, t1)) => {
                if t0 > 0.0 || cur.is_empty() {
                    if cur.len() >= 2 {
                        out.push(Path::polyline(std::mem::take(&mut cur), false));
                    }
                    cur.clear();
                    cur.push(lerp(a, b, t0));
                }
                cur.push(lerp(a, b, t1));
                if t1 < 1.0 {
                    out.push(Path::polyline(std::mem::take(&mut cur), false));
                }
            }
            None => {
                if cur.len() >= 2 {
                    out.push(Path::polyline(std::mem::take(&mut cur), false));
                }
                cur.clear();
            }
        }
    }
    if cur.len() >= 2 {
        out.push(Path::polyline(cur, false));
    }
    out
}

/// Normalises an angle into [0, 2π).
fn norm_angle(a: f64) -> f64 {
    let t = a.rem_euclid(TAU);
    if t >= TAU {
        0.0
    } else {
        t
    }
}

fn clip_arc(c: Pt, rad: f64, start: f64, sweep: f64, r: &Bounds) -> Vec<Path> {
    // Work counter-clockwise; a clockwise arc is clipped reversed and turned back.
    if sweep < 0.0 && sweep.abs() < TAU {
        return clip_arc(c, rad, start + sweep, -sweep, r)
            .into_iter()
            .rev()
            .map(|p| p.reversed())
            .collect();
    }
    let full = sweep >= TAU;
    let (s0, span) = if full { (0.0, TAU) } else { (norm_angle(start), sweep) };
    // Angles where the circle crosses the rectangle's edge lines, relative to s0.
    let mut cuts: Vec<f64> = vec![0.0, span];
    let mut add = |a: f64| {
        let rel = norm_angle(a - s0);
        if rel > 0.0 && rel < span {
            cuts.push(rel);
        }
    };
    for (x, vertical) in [(r.x0, true), (r.x1, true), (r.y0, false), (r.y1, false)] {
        let d = if vertical { x - c[0] } else { x - c[1] };
        if d.abs() < rad {
            let base = if vertical { (d / rad).acos() } else { (d / rad).asin() };
            if vertical {
                add(base);
                add(-base);
            } else {
                add(base);
                add(PI - base);
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let inside = |a: f64| {
        let p = polar(c, rad, s0 + a);
        p[0] >= r.x0 && p[0] <= r.x1 && p[1] >= r.y0 && p[1] <= r.y1
    };
    let mut pieces: Vec<(f64, f64)> = Vec::new();
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b - a <= 0.0 || !inside(0.5 * (a + b)) {
            continue;
        }
        match pieces.last_mut() {
            Some(last) if last.1 == a => last.1 = b,
            _ => pieces.push((a, b)),
        }
    }
    if full && pieces.len() > 1 {
        // The piece through angle 0 continues across the seam.
        let (first, last) = (pieces[0], pieces[pieces.len() - 1]);
        if first.0 == 0.0 && last.1 == TAU {
            pieces.pop();
            pieces[0] = (last.0 - TAU, first.1);
        }
    }
    if full && pieces.len() == 1 && pieces[0].1 - pieces[0].0 >= TAU {
        return vec![Path::circle(c, rad)];
    }
    pieces
        .into_iter()
        .map(|(a, b)| Path::Arc {
            center: c,
            radius: rad,
            start: s0 + a,
            sweep: b - a,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Bounds {
        Bounds {
            x0: 0.0,
            y0: 0.0,
            x1: 10.0,
            y1: 10.0,
        }
    }

    #[test]
    fn circle_crossing_a_corner_is_cut_into_arcs_inside() {
        let c = Path::circle([0.0, 5.0], 2.0);
        let parts = clip_path(&c, &unit());
        assert_eq!(parts.len(), 1, "{parts:?}");
        let b = parts[0].bounds();
        assert!(b.inside(&unit(), 1e-12), "{b:?}");
        assert!((parts[0].length() - PI * 2.0).abs() < 1e-9, "half the circle");
        // Through the corner: a quarter.
        let q = clip_path(&Path::circle([0.0, 0.0], 3.0), &unit());
        assert_eq!(q.len(), 1);
        assert!((q[0].length() - 0.5 * PI * 3.0).abs() < 1e-9);
        // Inside: unchanged; outside: nothing.
        assert_eq!(clip_path(&Path::circle([5.0, 5.0], 1.0), &unit()).len(), 1);
        assert!(clip_path(&Path::circle([20.0, 5.0], 1.0), &unit()).is_empty());
    }

    #[test]
    fn polygon_crossing_an_edge_is_cut_into_one_open_piece() {
        let sq = Path::polyline(vec![[-1.0, 4.0], [1.0, 4.0], [1.0, 6.0], [-1.0, 6.0]], true);
        let parts = clip_path(&sq, &unit());
        assert_eq!(parts.len(), 1, "{parts:?}");
        assert!((parts[0].length() - 4.0).abs() < 1e-12, "1 + 2 + 1 mm inside");
        assert!(parts[0].bounds().inside(&unit(), 0.0));
    }
}
