//! Hatch fill: parallel lines `SPACING` mm apart at `ANGLE` degrees, clipped exactly to each
//! shape. Circles are cut analytically (half chords), rings only in the annulus (the chord of
//! the outer circle less the chord of the hole), polygons by scanline intersection with the
//! even-odd rule (so stars and blobs hatch correctly). The lines lie on one global family
//! `p · n = k · SPACING` (n the lines' normal), so neighbouring shapes hatch in register.
//! Deterministic; never panics.

use crate::model::doc::ShapeDoc;
use crate::model::Pt;

/// A hatch pattern.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hatch {
    /// Distance between lines (mm, > 0).
    pub spacing: f64,
    /// Direction of the lines in degrees counter-clockwise from +x.
    pub angle: f64,
    /// Cross-hatching: a second family of lines at right angles to the first.
    pub cross: bool,
}

impl Hatch {
    /// Parses `SPACING[:ANGLE]` (angle in degrees, default 45).
    pub fn parse(s: &str) -> Result<Hatch, String> {
        let (sp, an) = match s.split_once(':') {
            Some((a, b)) => (a, Some(b)),
            None => (s, None),
        };
        let spacing = sp
            .trim()
            .parse::<f64>()
            .map_err(|_| format!("'{sp}' is not a number of mm (SPACING[:ANGLE])"))?;
        if !spacing.is_finite() {
            return Err(format!("'{}' is not a finite number of mm (SPACING[:ANGLE])", sp.trim()));
        }
        if spacing <= 0.0 {
            return Err(format!("spacing {spacing} mm must be positive"));
        }
        if spacing < 1e-3 {
            return Err(format!("spacing {} mm is below 0.001 mm", crate::error::num(spacing)));
        }
        let angle = match an {
            Some(a) => a
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("'{a}' is not an angle in degrees"))?,
            None => 45.0,
        };
        Ok(Hatch {
            spacing,
            angle,
            cross: false,
        })
    }

    /// The families of parallel lines: the angle, and with `cross` the angle plus 90 degrees.
    fn families(&self) -> impl Iterator<Item = Hatch> {
        let one = Hatch { cross: false, ..*self };
        let two = self.cross.then_some(Hatch {
            angle: self.angle + 90.0,
            ..one
        });
        std::iter::once(one).chain(two)
    }

    /// Unit direction of the lines and their normal.
    fn frame(&self) -> (Pt, Pt) {
        let (s, c) = libm::sincos(self.angle.to_radians());
        ([c, s], [-s, c])
    }

    /// The line indices `k` whose line `p · n = k s` meets `[lo, hi]` (in normal coordinate).
    fn lines(&self, lo: f64, hi: f64) -> std::ops::RangeInclusive<i64> {
        let k0 = (lo / self.spacing).ceil() as i64;
        let k1 = (hi / self.spacing).floor() as i64;
        k0..=k1
    }

    /// The hatch segments of one shape shifted by `off`. A ring's hole narrower than
    /// `min_feature` is not drawn, so it is hatched over too.
    pub fn shape(&self, sh: &ShapeDoc, off: (f64, f64), min_feature: f64) -> Vec<[Pt; 2]> {
        let c = [sh.center[0] + off.0, sh.center[1] + off.1];
        match (sh.radius, sh.inner_radius) {
            (Some(r), inner) => {
                let hole = inner.filter(|ri| *ri > 0.0 && 2.0 * ri >= min_feature).unwrap_or(0.0);
                self.annulus(c, r, hole)
            }
            _ => {
                let vs: Vec<Pt> = sh
                    .vertices
                    .as_deref()
                    .unwrap_or(&[])
                    .iter()
                    .map(|v| [v[0] + off.0, v[1] + off.1])
                    .collect();
                self.polygon(&vs)
            }
        }
    }

    /// Hatch of a disc (`inner = 0`) or an annulus.
    pub fn annulus(&self, c: Pt, r: f64, inner: f64) -> Vec<[Pt; 2]> {
        self.families().flat_map(|h| h.annulus_one(c, r, inner)).collect()
    }

    /// Hatch of a simple polygon (either orientation; even-odd rule).
    pub fn polygon(&self, vs: &[Pt]) -> Vec<[Pt; 2]> {
        self.families().flat_map(|h| h.polygon_one(vs)).collect()
    }

    /// One family's lines across a disc or an annulus.
    fn annulus_one(&self, c: Pt, r: f64, inner: f64) -> Vec<[Pt; 2]> {
        let (u, n) = self.frame();
        let vc = c[0] * n[0] + c[1] * n[1];
        let mut out = Vec::new();
        for k in self.lines(vc - r, vc + r) {
            let o = k as f64 * self.spacing - vc;
            let h = (r * r - o * o).max(0.0).sqrt();
            if h <= 0.0 {
                continue;
            }
            let foot = [c[0] + o * n[0], c[1] + o * n[1]];
            let at = |t: f64| [foot[0] + t * u[0], foot[1] + t * u[1]];
            if o.abs() < inner {
                let hi = (inner * inner - o * o).max(0.0).sqrt();
                if hi > 0.0 {
                    out.push([at(-h), at(-hi)]);
                    out.push([at(hi), at(h)]);
                    continue;
                }
            }
            out.push([at(-h), at(h)]);
        }
        out
    }

    /// One family's lines across a simple polygon.
    fn polygon_one(&self, vs: &[Pt]) -> Vec<[Pt; 2]> {
        let m = vs.len();
        if m < 3 {
            return vec![];
        }
        let (u, n) = self.frame();
        let proj_n: Vec<f64> = vs.iter().map(|p| p[0] * n[0] + p[1] * n[1]).collect();
        let (lo, hi) = proj_n
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        let mut out = Vec::new();
        let mut xs: Vec<(f64, Pt)> = Vec::new();
        for k in self.lines(lo, hi) {
            let level = k as f64 * self.spacing;
            xs.clear();
            for i in 0..m {
                let j = (i + 1) % m;
                let (va, vb) = (proj_n[i], proj_n[j]);
                // Half-open rule: a vertex on the line counts for one of its edges only.
                if (va <= level) != (vb <= level) {
                    let t = (level - va) / (vb - va);
                    let (a, b) = (vs[i], vs[j]);
                    let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                    xs.push((p[0] * u[0] + p[1] * u[1], p));
                }
            }
            xs.sort_by(|a, b| a.0.total_cmp(&b.0));
            for pair in xs.chunks_exact(2) {
                if pair[1].0 > pair[0].0 {
                    out.push([pair[0].1, pair[1].1]);
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn len(s: &[Pt; 2]) -> f64 {
        libm::hypot(s[1][0] - s[0][0], s[1][1] - s[0][1])
    }

    #[test]
    fn parse_and_refuse() {
        let h = |spacing, angle| Hatch {
            spacing,
            angle,
            cross: false,
        };
        assert_eq!(Hatch::parse("0.5"), Ok(h(0.5, 45.0)));
        assert_eq!(Hatch::parse("1:0"), Ok(h(1.0, 0.0)));
        for bad in ["0", "-1", "nan", "x", "1:y", "inf"] {
            assert!(Hatch::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn disc_hatch_endpoints_lie_on_the_circle() {
        let h = Hatch {
            spacing: 0.25,
            angle: 30.0,
            cross: false,
        };
        let (c, r) = ([3.0, 4.0], 2.0);
        let segs = h.annulus(c, r, 0.0);
        assert_eq!(segs.len(), 16, "lines at k s within 4 mm of width");
        for s in &segs {
            for p in s {
                assert!((libm::hypot(p[0] - c[0], p[1] - c[1]) - r).abs() < 1e-12);
            }
        }
        // Area by the midpoint rule approximates the disc.
        let area: f64 = segs.iter().map(len).sum::<f64>() * h.spacing;
        assert!((area - std::f64::consts::PI * 4.0).abs() < 0.1, "{area}");
    }

    #[test]
    fn ring_hatch_stays_out_of_the_hole() {
        let h = Hatch {
            spacing: 0.1,
            angle: 0.0,
            cross: false,
        };
        for s in h.annulus([0.0, 0.0], 2.0, 1.0) {
            let mid = [(s[0][0] + s[1][0]) / 2.0, (s[0][1] + s[1][1]) / 2.0];
            let d = libm::hypot(mid[0], mid[1]);
            assert!((1.0 - 1e-12..=2.0 + 1e-12).contains(&d), "{s:?}");
            for p in s {
                let d = libm::hypot(p[0], p[1]);
                assert!((d - 1.0).abs() < 1e-12 || (d - 2.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn cross_hatch_adds_the_perpendicular_family() {
        let one = Hatch {
            spacing: 0.2,
            angle: 15.0,
            cross: false,
        };
        let both = Hatch { cross: true, ..one };
        let vs = [[0.0, 0.0], [3.0, 0.0], [3.0, 2.0], [0.0, 2.0]];
        let (a, b) = (one.polygon(&vs), both.polygon(&vs));
        assert_eq!(&b[..a.len()], &a[..], "the first family is unchanged");
        let dir = |s: &[Pt; 2]| libm::atan2(s[1][1] - s[0][1], s[1][0] - s[0][0]).to_degrees().rem_euclid(180.0);
        assert!(
            b[a.len()..].iter().all(|s| (dir(s) - 105.0).abs() < 1e-9),
            "the second at 105 degrees"
        );
        let area = |segs: &[[Pt; 2]]| segs.iter().map(len).sum::<f64>() * 0.2;
        assert!((area(&b[a.len()..]) - 6.0).abs() < 0.3 && (area(&a) - 6.0).abs() < 0.3);
        let disc = both.annulus([0.0, 0.0], 3.0, 0.0);
        let hatched = disc.iter().map(len).sum::<f64>() * 0.2;
        assert!((hatched - 2.0 * 9.0 * std::f64::consts::PI).abs() < 0.5, "{hatched}");
    }

    #[test]
    fn star_hatch_is_inside_by_even_odd() {
        // A concave arrow: hatch lines split where the notch cuts them.
        let vs = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [2.0, 1.0], [0.0, 4.0]];
        let h = Hatch {
            spacing: 0.5,
            angle: 0.0,
            cross: false,
        };
        let segs = h.polygon(&vs);
        let at = |y: f64| segs.iter().filter(|s| s[0][1] == y).count();
        assert_eq!(at(0.5), 1, "below the notch: one span");
        assert_eq!(at(2.0), 2, "across the notch: two spans");
        assert_eq!(at(4.0), 0, "the tips touch y = 4 only at vertices");
        let area: f64 = segs.iter().map(len).sum::<f64>() * h.spacing;
        assert!((area - 10.0).abs() < 1.0, "{area}");
    }
}
