//! Geometry checks written independently of the core: shapes from the JSON, their
//! clearances (the separating-axis test for polygons), inside and overlap checks.

use super::{f, pt, region, shapes};
use serde_json::Value;

/// A shape's geometry.
#[derive(Debug, Clone, PartialEq)]
pub enum G {
    /// A disc.
    Circle {
        /// Centre.
        c: [f64; 2],
        /// Radius.
        r: f64,
    },
    /// A convex polygon (either orientation).
    Poly(Vec<[f64; 2]>),
}

impl G {
    /// From a JSON shape.
    pub fn from_json(sh: &Value) -> G {
        if let Some(r) = sh.get("radius").and_then(Value::as_f64) {
            G::Circle {
                c: pt(sh.get("center").unwrap_or(&Value::Null)),
                r,
            }
        } else {
            let vs = sh
                .get("vertices")
                .and_then(Value::as_array)
                .unwrap_or_else(|| panic!("no vertices in {sh}"));
            G::Poly(vs.iter().map(pt).collect())
        }
    }

    /// Shifted copy.
    pub fn shift(&self, dx: f64, dy: f64) -> G {
        match self {
            G::Circle { c, r } => G::Circle {
                c: [c[0] + dx, c[1] + dy],
                r: *r,
            },
            G::Poly(vs) => G::Poly(vs.iter().map(|v| [v[0] + dx, v[1] + dy]).collect()),
        }
    }

    /// Bounding box (x0, y0, x1, y1).
    pub fn bounds(&self) -> (f64, f64, f64, f64) {
        match self {
            G::Circle { c, r } => (c[0] - r, c[1] - r, c[0] + r, c[1] + r),
            G::Poly(vs) => vs
                .iter()
                .fold((f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY), |b, v| {
                    (b.0.min(v[0]), b.1.min(v[1]), b.2.max(v[0]), b.3.max(v[1]))
                }),
        }
    }

    /// A bounding circle (centre of the bounding box, half diagonal).
    fn bcircle(&self) -> ([f64; 2], f64) {
        match self {
            G::Circle { c, r } => (*c, *r),
            G::Poly(_) => {
                let (x0, y0, x1, y1) = self.bounds();
                ([(x0 + x1) / 2.0, (y0 + y1) / 2.0], (x1 - x0).hypot(y1 - y0) / 2.0)
            }
        }
    }
}

/// The distance from `p` to the segment `ab`.
pub fn seg_dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
    let len2 = ex * ex + ey * ey;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - (a[0] + t * ex)).hypot(p[1] - (a[1] + t * ey))
}

fn edges(vs: &[[f64; 2]]) -> impl Iterator<Item = ([f64; 2], [f64; 2])> + '_ {
    (0..vs.len()).map(move |i| (vs[i], vs[(i + 1) % vs.len()]))
}

fn inside_poly(p: [f64; 2], vs: &[[f64; 2]]) -> bool {
    let (mut pos, mut neg) = (false, false);
    for (a, b) in edges(vs) {
        let cr = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        if cr > 0.0 {
            pos = true;
        }
        if cr < 0.0 {
            neg = true;
        }
    }
    !(pos && neg)
}

/// Separating-axis test over the edge normals of both polygons: the largest gap between the
/// projections (negative when every axis overlaps, i.e. the polygons intersect).
pub fn sat_gap(a: &[[f64; 2]], b: &[[f64; 2]]) -> f64 {
    let mut best = f64::NEG_INFINITY;
    for (p, q) in edges(a).chain(edges(b)) {
        let (nx, ny) = (q[1] - p[1], p[0] - q[0]);
        let len = nx.hypot(ny);
        if len == 0.0 {
            continue;
        }
        let proj = |vs: &[[f64; 2]]| {
            vs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |m, v| {
                let d = (v[0] * nx + v[1] * ny) / len;
                (m.0.min(d), m.1.max(d))
            })
        };
        let (a0, a1) = proj(a);
        let (b0, b1) = proj(b);
        best = best.max((b0 - a1).max(a0 - b1));
    }
    best
}

/// Clearance between two shapes: the Euclidean distance when they are disjoint, <= 0 when
/// they touch or overlap.
pub fn clearance(a: &G, b: &G) -> f64 {
    match (a, b) {
        (G::Circle { c: c1, r: r1 }, G::Circle { c: c2, r: r2 }) => (c1[0] - c2[0]).hypot(c1[1] - c2[1]) - r1 - r2,
        (G::Circle { c, r }, G::Poly(vs)) | (G::Poly(vs), G::Circle { c, r }) => {
            if inside_poly(*c, vs) {
                return -r;
            }
            edges(vs).map(|(p, q)| seg_dist(*c, p, q)).fold(f64::INFINITY, f64::min) - r
        }
        (G::Poly(pa), G::Poly(pb)) => {
            let g = sat_gap(pa, pb);
            if g <= 0.0 {
                return g;
            }
            // Disjoint convex polygons: the distance is reached between a vertex and an edge.
            let mut d = f64::INFINITY;
            for (x, y) in [(pa, pb), (pb, pa)] {
                for v in x.iter() {
                    for (p, q) in edges(y) {
                        d = d.min(seg_dist(*v, p, q));
                    }
                }
            }
            d
        }
    }
}

/// Tolerance of the geometry checks (mm).
pub const EPS: f64 = 1e-9;

/// Every pair of shapes (and, for a periodic region, every shape against the images of all
/// shapes, itself included, shifted by ±W, ±H) keeps at least `gap` clearance. Returns one
/// message per violation.
pub fn check_overlaps(doc: &Value) -> Vec<String> {
    let (w, h, periodic) = region(doc);
    let gap = doc.get("params").map(|p| f(p, "gap")).unwrap_or(0.0);
    let gs: Vec<G> = shapes(doc).iter().map(G::from_json).collect();
    let bc: Vec<([f64; 2], f64)> = gs.iter().map(G::bcircle).collect();
    let shifts = period_shifts(periodic, w, h);
    let mut errs = Vec::new();
    for i in 0..gs.len() {
        for j in i..gs.len() {
            for &(dx, dy) in &shifts {
                if i == j && dx == 0.0 && dy == 0.0 {
                    continue;
                }
                let (ci, ri) = bc[i];
                let (cj, rj) = bc[j];
                if (ci[0] - cj[0] - dx).hypot(ci[1] - cj[1] - dy) > ri + rj + gap + 1e-6 {
                    continue;
                }
                let d = clearance(&gs[i], &gs[j].shift(dx, dy));
                if d < gap - EPS {
                    errs.push(format!(
                        "shapes {i} and {j} (shifted by {dx}, {dy}) are {d} mm apart, less than the gap {gap}"
                    ));
                }
            }
        }
    }
    errs
}

/// Inclusive regions: every shape inside [gap, W-gap] x [gap, H-gap]. Periodic regions: every
/// centre in [0, W) x [0, H).
pub fn check_inside(doc: &Value) -> Vec<String> {
    let (w, h, periodic) = region(doc);
    let gap = doc.get("params").map(|p| f(p, "gap")).unwrap_or(0.0);
    let mut errs = Vec::new();
    for (i, sh) in shapes(doc).iter().enumerate() {
        if periodic {
            let c = pt(sh.get("center").unwrap_or(&Value::Null));
            if !(c[0] >= 0.0 && c[0] < w && c[1] >= 0.0 && c[1] < h) {
                errs.push(format!("shape {i}: centre {c:?} outside [0,{w})x[0,{h})"));
            }
        } else {
            let (x0, y0, x1, y1) = G::from_json(sh).bounds();
            if x0 < gap - EPS || y0 < gap - EPS || x1 > w - gap + EPS || y1 > h - gap + EPS {
                errs.push(format!(
                    "shape {i}: bounds ({x0}, {y0}, {x1}, {y1}) outside the region {w}x{h} less gap {gap}"
                ));
            }
        }
    }
    errs
}

/// Both geometry checks; panics listing the first violations.
pub fn assert_geometry(doc: &Value) {
    let mut errs = check_inside(doc);
    errs.extend(check_overlaps(doc));
    assert!(
        errs.is_empty(),
        "{} geometry errors, first: {:?}",
        errs.len(),
        &errs[..errs.len().min(5)]
    );
}

/// The shifts that bring a shape's images next to the `w` x `h` tile: the nine of a period
/// each way when `periodic`, only none otherwise.
pub fn period_shifts(periodic: bool, w: f64, h: f64) -> Vec<(f64, f64)> {
    if !periodic {
        return vec![(0.0, 0.0)];
    }
    [-1.0, 0.0, 1.0]
        .iter()
        .flat_map(|&i| [-1.0, 0.0, 1.0].iter().map(move |&j| (i * w, j * h)))
        .collect()
}
