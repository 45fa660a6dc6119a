//! An independent checker of finished fills, in plain `f64` on `[f64; 2]` points: nothing of
//! the core but the outlines it reads ([`Mat::from_geo`]). No sampling: every distance is
//! computed from the exact outlines (true circles, the polygons' edges).
//!
//! [`clearance`] is the signed distance between two shapes' material: their distance when
//! they are apart, and minus a penetration depth when they overlap (two edges that cross, or
//! one shape's vertex inside the other). A shape in a ring's hole is apart from the ring.
//! [`region_clearance`] is the same between a shape and the outside of the region.
//! [`check`] asks every pair (and, on a torus, every periodic image) and every shape to keep
//! the gap, up to a rounding tolerance given by the caller.

/// A point.
pub type P = [f64; 2];

/// A shape's material.
#[derive(Clone, Debug, PartialEq)]
pub enum Mat {
    /// A disc.
    Disc { c: P, r: f64 },
    /// An annulus; its hole is free space.
    Ring { c: P, r: f64, inner: f64 },
    /// A simple polygon (either orientation).
    Poly(Vec<P>),
}

/// A region, in the frame the engine places shapes in.
#[derive(Clone, Debug, PartialEq)]
pub enum Area {
    /// `[0, w] x [0, h]`.
    Rect { w: f64, h: f64 },
    /// `[0, w) x [0, h)` with opposite edges glued.
    Torus { w: f64, h: f64 },
    /// The disc of radius `r` centred at (r, r).
    Disc { r: f64 },
    /// The ring between `outer` and `inner` centred at (outer, outer).
    Annulus { outer: f64, inner: f64 },
    /// Rings of a polygon, filled by the even-odd rule.
    Polygon(Vec<Vec<P>>),
}

fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1]]
}

fn cross(a: P, b: P) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn norm(a: P) -> f64 {
    a[0].hypot(a[1])
}

fn edges(vs: &[P]) -> impl Iterator<Item = (P, P)> + '_ {
    (0..vs.len()).map(move |i| (vs[i], vs[(i + 1) % vs.len()]))
}

/// Twice the signed area of a polygon, about its first vertex (so that a small polygon far
/// from the origin loses no digits).
fn area2(vs: &[P]) -> f64 {
    let o = vs.first().copied().unwrap_or([0.0, 0.0]);
    edges(vs).map(|(a, b)| cross(sub(a, o), sub(b, o))).sum()
}

/// Distance from `p` to the segment `ab`.
pub fn seg_dist(p: P, a: P, b: P) -> f64 {
    let e = sub(b, a);
    let len2 = e[0] * e[0] + e[1] * e[1];
    let t = if len2 > 0.0 {
        ((p[0] - a[0]) * e[0] + (p[1] - a[1]) * e[1]) / len2
    } else {
        0.0
    };
    let t = t.clamp(0.0, 1.0);
    norm(sub(p, [a[0] + t * e[0], a[1] + t * e[1]]))
}

/// Whether the segments `a` and `b` meet (cross or touch), and if so how deep: the smaller
/// of the two segments' reach across the other's line (0 when they only touch).
fn crossing_depth(a1: P, a2: P, b1: P, b2: P) -> Option<f64> {
    let (ea, eb) = (sub(a2, a1), sub(b2, b1));
    let (s1, s2) = (cross(ea, sub(b1, a1)), cross(ea, sub(b2, a1)));
    let (s3, s4) = (cross(eb, sub(a1, b1)), cross(eb, sub(a2, b1)));
    let apart = |u: f64, v: f64| (u > 0.0 && v > 0.0) || (u < 0.0 && v < 0.0);
    if apart(s1, s2) || apart(s3, s4) {
        return None;
    }
    if s1 == 0.0 && s2 == 0.0 {
        // Collinear: they meet if their projections on the line overlap.
        let t = |p: P| (p[0] - a1[0]) * ea[0] + (p[1] - a1[1]) * ea[1];
        let len2 = ea[0] * ea[0] + ea[1] * ea[1];
        let (lo, hi) = (t(b1).min(t(b2)), t(b1).max(t(b2)));
        return (hi >= 0.0 && lo <= len2).then_some(0.0);
    }
    let (la, lb) = (norm(ea), norm(eb));
    let reach = |u: f64, v: f64, len: f64| if len > 0.0 { u.abs().min(v.abs()) / len } else { 0.0 };
    Some(reach(s1, s2, la).min(reach(s3, s4, lb)))
}

/// Distance between two segments (0 when they meet).
fn seg_seg_dist(a1: P, a2: P, b1: P, b2: P) -> f64 {
    if crossing_depth(a1, a2, b1, b2).is_some() {
        return 0.0;
    }
    seg_dist(a1, b1, b2)
        .min(seg_dist(a2, b1, b2))
        .min(seg_dist(b1, a1, a2))
        .min(seg_dist(b2, a1, a2))
}

/// The even-odd rule over `rings` (points on an edge may go either way).
pub fn inside_rings<'a>(p: P, rings: impl IntoIterator<Item = &'a [P]>) -> bool {
    let mut inside = false;
    for vs in rings {
        for (a, b) in edges(vs) {
            if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
                inside = !inside;
            }
        }
    }
    inside
}

fn in_poly(p: P, vs: &[P]) -> bool {
    inside_rings(p, [vs])
}

fn boundary_dist(p: P, vs: &[P]) -> f64 {
    edges(vs).map(|(a, b)| seg_dist(p, a, b)).fold(f64::INFINITY, f64::min)
}

/// Signed distance from `p` to a polygon's material: negative inside.
fn point_poly(p: P, vs: &[P]) -> f64 {
    let d = boundary_dist(p, vs);
    if in_poly(p, vs) {
        -d
    } else {
        d
    }
}

/// Points along a chain of edges: the vertices and seven points between each two.
fn along(edges: impl Iterator<Item = (P, P)>) -> impl Iterator<Item = P> {
    edges.flat_map(|(a, b)| {
        (0..8).map(move |k| {
            let t = f64::from(k) / 8.0;
            [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
        })
    })
}

/// How deep the points reach into a polygon: the largest distance to its boundary of those
/// inside it (0 when none is).
fn reach_into(points: impl Iterator<Item = P>, vs: &[P]) -> f64 {
    points.filter(|&p| in_poly(p, vs)).map(|p| boundary_dist(p, vs)).fold(0.0, f64::max)
}

fn poly_poly(a: &[P], b: &[P]) -> f64 {
    let mut met = false;
    let mut depth = 0.0f64;
    for (a1, a2) in edges(a) {
        for (b1, b2) in edges(b) {
            if let Some(d) = crossing_depth(a1, a2, b1, b2) {
                met = true;
                depth = depth.max(d);
            }
        }
    }
    // Without crossing edges, they overlap only if one holds the other's vertices.
    met = met || a.iter().any(|&v| in_poly(v, b)) || b.iter().any(|&v| in_poly(v, a));
    if met {
        // They meet: how deep, also where edges run along each other (points on one
        // outline strictly inside the other).
        return -depth.max(reach_into(along(edges(a)), b)).max(reach_into(along(edges(b)), a));
    }
    let mut d = f64::INFINITY;
    for (a1, a2) in edges(a) {
        for (b1, b2) in edges(b) {
            d = d.min(seg_seg_dist(a1, a2, b1, b2));
        }
    }
    d
}

/// Signed distance between the material of two shapes (see the module docs).
pub fn clearance(a: &Mat, b: &Mat) -> f64 {
    use Mat::*;
    match (a, b) {
        (Disc { c: c1, r: r1 }, Disc { c: c2, r: r2 }) => norm(sub(*c1, *c2)) - r1 - r2,
        (Disc { c: cd, r: rd }, Ring { c, r, inner }) | (Ring { c, r, inner }, Disc { c: cd, r: rd }) => {
            let d = norm(sub(*cd, *c));
            (inner - d - rd).max(d - rd - r)
        }
        (Ring { c: c1, r: r1, inner: i1 }, Ring { c: c2, r: r2, inner: i2 }) => {
            let d = norm(sub(*c1, *c2));
            (d - r1 - r2).max(i1 - d - r2).max(i2 - d - r1)
        }
        (Disc { c, r }, Poly(v)) | (Poly(v), Disc { c, r }) => point_poly(*c, v) - r,
        (Ring { c, r, inner }, Poly(v)) | (Poly(v), Ring { c, r, inner }) => {
            // The polygon is connected: its distances from the centre fill [near, far].
            let near = point_poly(*c, v).max(0.0);
            let far = v.iter().map(|&p| norm(sub(p, *c))).fold(0.0, f64::max);
            (inner - far).max(near - r)
        }
        (Poly(p), Poly(q)) => poly_poly(p, q),
    }
}

/// Signed distance between a shape's material and the segment `ab`.
fn clearance_to_segment(m: &Mat, a: P, b: P) -> f64 {
    match m {
        Mat::Disc { c, r } => seg_dist(*c, a, b) - r,
        Mat::Ring { c, r, inner } => {
            let near = seg_dist(*c, a, b);
            let far = norm(sub(a, *c)).max(norm(sub(b, *c)));
            (inner - far).max(near - r)
        }
        Mat::Poly(v) => {
            let mut met = false;
            let mut depth = 0.0f64;
            for (p, q) in edges(v) {
                if let Some(d) = crossing_depth(p, q, a, b) {
                    met = true;
                    depth = depth.max(d);
                }
            }
            met = met || in_poly(a, v) || in_poly(b, v);
            if met {
                -depth.max(reach_into(along([(a, b)].into_iter()), v))
            } else {
                edges(v).map(|(p, q)| seg_seg_dist(p, q, a, b)).fold(f64::INFINITY, f64::min)
            }
        }
    }
}

impl Mat {
    /// From the core's outline, through `to_f64`.
    pub fn from_geo<S: zetafill::Scalar>(g: &zetafill::Geo<S>) -> Mat {
        let p = |q: &zetafill::Point<S>| [q.x.to_f64(), q.y.to_f64()];
        match g {
            zetafill::Geo::Circle { c, r } => Mat::Disc { c: p(c), r: r.to_f64() },
            zetafill::Geo::Ring { c, r, inner } => Mat::Ring {
                c: p(c),
                r: r.to_f64(),
                inner: inner.to_f64(),
            },
            zetafill::Geo::Poly { v, .. } => Mat::Poly(v.iter().map(p).collect()),
            zetafill::Geo::Motif { .. } => panic!("the fuzz checker takes the built-in kinds (motifs: core/tests/motifs.rs)"),
        }
    }

    /// (min x, min y, max x, max y).
    pub fn bbox(&self) -> [f64; 4] {
        match self {
            Mat::Disc { c, r } | Mat::Ring { c, r, .. } => [c[0] - r, c[1] - r, c[0] + r, c[1] + r],
            Mat::Poly(v) => v
                .iter()
                .fold([f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY], |b, p| {
                    [b[0].min(p[0]), b[1].min(p[1]), b[2].max(p[0]), b[3].max(p[1])]
                }),
        }
    }

    /// The shape moved by (dx, dy).
    pub fn shift(&self, dx: f64, dy: f64) -> Mat {
        match self {
            Mat::Disc { c, r } => Mat::Disc {
                c: [c[0] + dx, c[1] + dy],
                r: *r,
            },
            Mat::Ring { c, r, inner } => Mat::Ring {
                c: [c[0] + dx, c[1] + dy],
                r: *r,
                inner: *inner,
            },
            Mat::Poly(v) => Mat::Poly(v.iter().map(|p| [p[0] + dx, p[1] + dy]).collect()),
        }
    }

    /// The area of the material.
    pub fn area(&self) -> f64 {
        use std::f64::consts::PI;
        match self {
            Mat::Disc { r, .. } => PI * r * r,
            Mat::Ring { r, inner, .. } => PI * (r * r - inner * inner),
            Mat::Poly(v) => (area2(v) / 2.0).abs(),
        }
    }

    /// A point inside the material: a disc's centre, the middle of a ring's band, a
    /// polygon's stored centre when it lies inside (every polygon the engine places is
    /// star-shaped about it), else its first vertex.
    fn probe(&self, centre: P) -> P {
        match self {
            Mat::Disc { c, .. } => *c,
            Mat::Ring { c, r, inner } => [c[0] + (r + inner) / 2.0, c[1]],
            Mat::Poly(v) if in_poly(centre, v) => centre,
            Mat::Poly(v) => v.first().copied().unwrap_or([f64::NAN, f64::NAN]),
        }
    }

    /// Finite, positive sizes, at least 3 vertices, counter-clockwise (as `Geo` promises).
    /// A ring's hole may be empty: on fixed point a hole under 2^-32 mm (a ring of radius
    /// 0.09 mm with `inner: 1e-9`) rounds to 0, and the ring is a disc.
    pub fn well_formed(&self) -> Result<(), String> {
        let ok = match self {
            Mat::Disc { c, r } => c.iter().all(|v| v.is_finite()) && r.is_finite() && *r > 0.0,
            Mat::Ring { c, r, inner } => c.iter().all(|v| v.is_finite()) && r.is_finite() && *inner >= 0.0 && inner < r,
            Mat::Poly(v) => v.len() >= 3 && v.iter().flatten().all(|x| x.is_finite()) && area2(v) > 0.0,
        };
        if ok {
            Ok(())
        } else {
            Err(format!("malformed shape {self:?}"))
        }
    }
}

impl Area {
    /// Signed distance from a shape's material (stored centre `centre`) to the outside of the
    /// region (a torus has no outside).
    pub fn clearance(&self, m: &Mat, centre: P) -> f64 {
        let b = m.bbox();
        match self {
            Area::Torus { .. } => f64::INFINITY,
            Area::Rect { w, h } => match m {
                Mat::Poly(v) => v
                    .iter()
                    .map(|p| p[0].min(w - p[0]).min(p[1]).min(h - p[1]))
                    .fold(f64::INFINITY, f64::min),
                _ => b[0].min(w - b[2]).min(b[1]).min(h - b[3]),
            },
            Area::Disc { r } => Self::in_disc(m, [*r, *r], *r),
            Area::Annulus { outer, inner } => {
                let c = [*outer, *outer];
                Self::in_disc(m, c, *outer).min(clearance(m, &Mat::Disc { c, r: *inner }))
            }
            Area::Polygon(rings) => {
                let all = || rings.iter().map(Vec::as_slice);
                let near = all()
                    .flat_map(edges)
                    .map(|(a, b)| clearance_to_segment(m, a, b))
                    .fold(f64::INFINITY, f64::min);
                // Clear of every edge, the material is wholly inside or wholly outside: a
                // point inside it decides which.
                let probe = m.probe(centre);
                if inside_rings(probe, all()) {
                    near
                } else {
                    near.min(-all().map(|r| boundary_dist(probe, r)).fold(f64::INFINITY, f64::min))
                }
            }
        }
    }

    /// How far the material stays inside the disc (centre `c`, radius `r`): a convex region,
    /// so the farthest point decides.
    fn in_disc(m: &Mat, c: P, r: f64) -> f64 {
        match m {
            Mat::Disc { c: s, r: rs } | Mat::Ring { c: s, r: rs, .. } => r - norm(sub(*s, c)) - rs,
            Mat::Poly(v) => r - v.iter().map(|&p| norm(sub(p, c))).fold(0.0, f64::max),
        }
    }

    /// The size of the numbers involved: a scale for rounding tolerances.
    pub fn magnitude(&self) -> f64 {
        match self {
            Area::Rect { w, h } | Area::Torus { w, h } => w.max(*h),
            Area::Disc { r } => 2.0 * r,
            Area::Annulus { outer, .. } => 2.0 * outer,
            Area::Polygon(rings) => rings.iter().flatten().flatten().fold(0.0, |m, v| m.max(v.abs())),
        }
    }
}

/// A finished fill: each shape's stored centre and material, in placement order.
#[derive(Clone, Debug)]
pub struct Fill {
    pub shapes: Vec<(P, Mat)>,
    pub area: Area,
    pub gap: f64,
}

/// Tolerances: a shape may come `rel * magnitude + abs` closer than the gap, the rounding of
/// the scalar the engine computed in.
#[derive(Clone, Copy, Debug)]
pub struct Tolerance {
    pub rel: f64,
    pub abs: f64,
}

/// The multiples k for which `b` shifted by `k * period` can come within `reach` of `a`
/// along one axis (at least -1..=1, at most -4..=4).
fn shifts(a: (f64, f64), b: (f64, f64), reach: f64, period: f64) -> std::ops::RangeInclusive<i64> {
    let lo = ((a.0 - reach - b.1) / period).floor();
    let hi = ((a.1 + reach - b.0) / period).ceil();
    let lo = if lo.is_finite() { (lo as i64).clamp(-4, -1) } else { -1 };
    let hi = if hi.is_finite() { (hi as i64).clamp(1, 4) } else { 1 };
    lo..=hi
}

/// Checks a fill: every shape well formed and inside the region with its gap (on a torus,
/// its centre in the period), every pair of shapes and periodic images at least `gap` apart.
/// Returns the first violation.
pub fn check(fill: &Fill, tol: Tolerance) -> Result<(), String> {
    let gap = fill.gap;
    let scale = fill.area.magnitude();
    let torus = match fill.area {
        Area::Torus { w, h } => Some((w, h)),
        _ => None,
    };
    let boxes: Vec<[f64; 4]> = fill.shapes.iter().map(|(_, m)| m.bbox()).collect();
    let slack = |b: &[f64; 4], o: &[f64; 4]| {
        let mag = [b[0], b[1], b[2], b[3], o[0], o[1], o[2], o[3]]
            .iter()
            .fold(scale, |m, v| m.max(v.abs()));
        tol.rel * mag + tol.abs
    };
    for (i, (centre, m)) in fill.shapes.iter().enumerate() {
        m.well_formed().map_err(|e| format!("shape {i}: {e}"))?;
        let b = &boxes[i];
        if let Some((w, h)) = torus {
            if !(centre[0] >= 0.0 && centre[0] < w && centre[1] >= 0.0 && centre[1] < h) {
                return Err(format!("shape {i}: centre {centre:?} outside the period [0, {w}) x [0, {h})"));
            }
        } else {
            let d = fill.area.clearance(m, *centre);
            if !(d >= gap - slack(b, b)) {
                return Err(format!(
                    "shape {i} is {d:e} from the outside of the region, less than the gap {gap:e}: {m:?}"
                ));
            }
        }
    }
    for (j, ((_, mj), bj)) in fill.shapes.iter().zip(&boxes).enumerate() {
        for (i, ((_, mi), bi)) in fill.shapes.iter().zip(&boxes).enumerate().take(j + 1) {
            let reach = gap + slack(bi, bj);
            let (kx, ky) = match torus {
                Some((w, h)) => (
                    shifts((bi[0], bi[2]), (bj[0], bj[2]), reach, w),
                    shifts((bi[1], bi[3]), (bj[1], bj[3]), reach, h),
                ),
                None => (0..=0, 0..=0),
            };
            let (w, h) = torus.unwrap_or((0.0, 0.0));
            for x in kx {
                for y in ky.clone() {
                    if i == j && x == 0 && y == 0 {
                        continue;
                    }
                    let (dx, dy) = (x as f64 * w, y as f64 * h);
                    // Boxes farther apart than the gap need no exact test.
                    if bj[0] + dx > bi[2] + reach || bi[0] > bj[2] + dx + reach || bj[1] + dy > bi[3] + reach || bi[1] > bj[3] + dy + reach
                    {
                        continue;
                    }
                    let other = mj.shift(dx, dy);
                    let d = clearance(mi, &other);
                    if !(d >= gap - slack(bi, &other.bbox())) {
                        return Err(format!(
                            "shapes {i} and {j} (image {x}, {y}) are {d:e} apart, less than the gap {gap:e}: {mi:?} / {other:?}"
                        ));
                    }
                }
            }
        }
    }
    Ok(())
}
