//! Regions and buffers shared by the core's tests.

// Not every test crate that includes this module uses every helper.
#![allow(dead_code)]

use zetafill::{index_words, Params, Placed, Point, PolygonRegion, Region, ShapeKind, Storage};

/// The outline of a ten-pointed star (radii 100 and 55 about (100, 100)) with a 20 mm square
/// hole at its centre, as points and ring ends for [`PolygonRegion::new`].
pub fn star_with_hole() -> (Vec<Point<f64>>, Vec<usize>) {
    let mut pts: Vec<Point<f64>> = (0..10)
        .map(|k| {
            let t = std::f64::consts::FRAC_PI_2 + k as f64 * std::f64::consts::PI / 5.0;
            let r = if k % 2 == 0 { 100.0 } else { 55.0 };
            Point::new(100.0 + r * t.cos(), 100.0 + r * t.sin())
        })
        .collect();
    pts.extend([
        Point::new(90.0, 90.0),
        Point::new(90.0, 110.0),
        Point::new(110.0, 110.0),
        Point::new(110.0, 90.0),
    ]);
    (pts, vec![10, 14])
}

/// One region of each kind: a 160 x 120 rectangle, inclusive and periodic, a disc, an
/// annulus, and `poly`.
pub fn every_kind(poly: PolygonRegion<'_>) -> [Region<'_>; 5] {
    [
        Region::Rect {
            width: 160.0,
            height: 120.0,
            periodic: false,
        },
        Region::Rect {
            width: 160.0,
            height: 120.0,
            periodic: true,
        },
        Region::Circle { radius: 80.0 },
        Region::Annulus { outer: 90.0, inner: 35.0 },
        Region::Polygon(poly),
    ]
}

/// The shape and index buffers of an engine for `cap` shapes.
pub struct Buffers<S> {
    pub shapes: Vec<Placed<S>>,
    pub index: Vec<u32>,
}

impl<S: zetafill::Scalar> Buffers<S> {
    pub fn new(cap: usize) -> Self {
        Buffers {
            shapes: vec![Placed::<S>::default(); cap],
            index: vec![0u32; index_words(cap)],
        }
    }

    /// The storage, with a coverage bitmap or none.
    pub fn storage<'a>(&'a mut self, coverage: &'a mut [u64]) -> Storage<'a, S> {
        Storage {
            shapes: &mut self.shapes,
            index: &mut self.index,
            coverage,
        }
    }
}

/// The parameters of the sampler tests: c = 1.3, N = 2, rotated where the kind rotates.
pub fn params(kind: ShapeKind) -> Params {
    let mut p = Params::circles(1.3, 2.0);
    p.shape = kind.into();
    p.rotate = kind.rotates();
    p.max_trials = 10_000_000;
    p
}

/// The two-sample Kolmogorov–Smirnov statistic D and its asymptotic p-value.
pub fn ks(a: &[f64], b: &[f64]) -> (f64, f64) {
    let mut a = a.to_vec();
    let mut b = b.to_vec();
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (n, m) = (a.len() as f64, b.len() as f64);
    let (mut i, mut j, mut d) = (0usize, 0usize, 0f64);
    while i < a.len() && j < b.len() {
        let v = a[i].min(b[j]);
        while i < a.len() && a[i] <= v {
            i += 1;
        }
        while j < b.len() && b[j] <= v {
            j += 1;
        }
        d = d.max((i as f64 / n - j as f64 / m).abs());
    }
    let ne = n * m / (n + m);
    let lambda = (ne.sqrt() + 0.12 + 0.11 / ne.sqrt()) * d;
    // Q_KS(lambda) = 2 sum_{k>=1} (-1)^(k-1) exp(-2 k^2 lambda^2).
    let mut p = 0.0;
    for k in 1..=100 {
        let term = (-2.0 * (k * k) as f64 * lambda * lambda).exp();
        p += if k % 2 == 1 { 2.0 * term } else { -2.0 * term };
        if term < 1e-12 {
            break;
        }
    }
    (d, p.clamp(0.0, 1.0))
}

// 1D fills: segments as (start, length).

/// O(n^2): every segment well formed and inside; every pair (and, periodic, every pair of
/// images at ±L) separated by more than `gap`.
// The checks are written `!(a < b)` on purpose: a NaN must fail them.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
pub fn check_pairs(segs: &[(f64, f64)], l: f64, gap: f64, periodic: bool) -> Result<(), String> {
    for (i, &(s, len)) in segs.iter().enumerate() {
        if !(s.is_finite() && len.is_finite() && len > 0.0) {
            return Err(format!("segment {i} malformed: start {s}, length {len}"));
        }
        if periodic {
            if !(s >= 0.0 && s < l) {
                return Err(format!("segment {i} starts at {s}, outside [0, {l})"));
            }
            if !(len + gap < l) {
                return Err(format!("segment {i} (length {len}) meets its own image"));
            }
        } else if !(s >= gap && s + len <= l - gap) {
            return Err(format!("segment {i} [{s}, {}] is not inside [{gap}, {}]", s + len, l - gap));
        }
    }
    let sep = |a: f64, alen: f64, b: f64, blen: f64| a > b + blen + gap || a + alen + gap < b;
    for j in 0..segs.len() {
        let (b, blen) = segs[j];
        for (i, &(a, alen)) in segs.iter().enumerate().take(j) {
            let shifts: &[f64] = if periodic { &[0.0, l, -l] } else { &[0.0] };
            for &d in shifts {
                if !sep(b + d, blen, a, alen) {
                    return Err(format!(
                        "segments {i} [{a}, {}] and {j} [{b}, {}] (shift {d}) are not {gap} apart",
                        a + alen,
                        b + blen
                    ));
                }
            }
        }
    }
    Ok(())
}

/// O(n log n): sorted by start, each segment ends more than `gap` before the next starts (and,
/// periodic, the last one before the first + L).
#[allow(clippy::neg_cmp_op_on_partial_ord)]
pub fn check_sorted(segs: &[(f64, f64)], l: f64, gap: f64, periodic: bool) -> Result<(), String> {
    let mut v: Vec<(f64, f64)> = segs.to_vec();
    if v.iter().any(|s| !(s.0.is_finite() && s.1 > 0.0)) {
        return Err("malformed segment".into());
    }
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    for w in v.windows(2) {
        if !(w[0].0 + w[0].1 + gap < w[1].0) {
            return Err(format!(
                "[{}, {}] and [{}, {}] are not {gap} apart",
                w[0].0,
                w[0].0 + w[0].1,
                w[1].0,
                w[1].0 + w[1].1
            ));
        }
    }
    if let (Some(first), Some(last)) = (v.first(), v.last()) {
        if periodic {
            if !(first.0 >= 0.0 && last.0 < l) {
                return Err("a start is outside [0, L)".into());
            }
            if v.len() > 1 && !(last.0 + last.1 + gap < first.0 + l) {
                return Err(format!("the last segment wraps onto the first: {last:?} / {first:?}"));
            }
        } else if !(first.0 >= gap && last.0 + last.1 <= l - gap) {
            return Err("a segment is outside the interval".into());
        }
    }
    Ok(())
}
