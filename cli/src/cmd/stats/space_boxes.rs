//! The 3D box count of `zetafill stats dimension`: a `space` JSON read into solids, and the
//! boxes of side `e` over the region's bounding box that meet the gasket (the part of the
//! region no solid covers).
//!
//! The boxes are `[i e, (i+1) e] x [j e, (j+1) e] x [k e, (k+1) e]` from the origin, the last
//! one along each axis clipped to the bounding box. `total` counts the boxes that meet the
//! region (every box of a box region; for a ball, the boxes that meet the open ball; for a box
//! without a ball, the boxes not inside the closed ball). A box meets the gasket unless it
//! lies inside a single placed solid; solids are disjoint, so the count is `total` minus the
//! boxes inside some solid (a periodic fill's solids count with their copies moved by whole
//! periods).
//!
//! "Inside" is decided conservatively: a box counts as covered only when it lies inside the
//! solid shrunk by [`MARGIN`] times the region's largest side, a margin far above the rounding
//! of the tests (the smallest solid that can hold a counted box is at least `2^-10` of that
//! side), so rounding never counts a box as covered that is not. Apart from that margin the
//! test is exact for every kind but the torus:
//! - a sphere, cube, tetrahedron or octahedron is convex: a box is inside when its eight
//!   corners are;
//! - a shell: its eight corners inside the outer sphere, and its nearest point to the centre
//!   no nearer than the hole's radius;
//! - a torus is the union of balls (beads) the fill tested: a box counts as covered when it
//!   lies inside one bead. A box inside the union but in no single bead counts as gasket, so
//!   for tori the count of gasket boxes is an upper bound.
//!
//! The boxes are counted a row at a time (fixed `j`, `k`): the boxes of a row inside a convex
//! solid are a run of consecutive `i`, found from where the row's four corner lines cross the
//! solid, so a solid costs one step per row its bounding box spans, not one per box.

use crate::error::CliError;
use crate::model::solid::{mul, Mat3, Region3, SolidKind, V3};
use crate::model::space::rotation;
use crate::plan::stats::input_error;
use serde_json::Value;

/// The margin by which every solid is shrunk before a box is tested against it, as a fraction
/// of the region's largest side.
pub const MARGIN: f64 = 1e-9;

/// A solid as the count tests it, in world coordinates.
#[derive(Debug, Clone)]
enum Body {
    /// A ball: centre and radius.
    Ball(V3, f64),
    /// A hollow ball: centre, outer radius and the hole's radius.
    Shell(V3, f64, f64),
    /// A convex polyhedron: its centre and faces `n . (p - centre) <= d`, `n` a unit vector.
    Poly(V3, Vec<(V3, f64)>),
    /// A union of balls of one radius (a torus's beads).
    Beads(Vec<V3>, f64),
}

/// A 3D fill as the count reads it.
#[derive(Debug, Clone)]
pub struct Space3 {
    /// The region.
    pub region: Region3,
    /// Periodic in x, y and z (box regions only).
    pub periodic: bool,
    bodies: Vec<Body>,
    /// Each solid's diameter (that of its bounding ball about its centre).
    sizes: Vec<f64>,
}

fn num(v: &Value, key: &str, what: &str) -> Result<f64, CliError> {
    v.get(key)
        .and_then(Value::as_f64)
        .filter(|x| x.is_finite())
        .ok_or_else(|| input_error(format!("{what}: '{key}' is missing or not a finite number")))
}

fn positive(v: &Value, key: &str, what: &str) -> Result<f64, CliError> {
    let x = num(v, key, what)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(input_error(format!("{what}: '{key}' is {x}; it must be above 0")))
    }
}

fn array<const K: usize>(v: &Value, key: &str, what: &str) -> Result<[f64; K], CliError> {
    let bad = || input_error(format!("{what}: '{key}' is missing or not {K} finite numbers"));
    let a = v.get(key).and_then(Value::as_array).ok_or_else(bad)?;
    if a.len() != K {
        return Err(bad());
    }
    let mut out = [0.0; K];
    for (o, x) in out.iter_mut().zip(a) {
        *o = x.as_f64().filter(|x| x.is_finite()).ok_or_else(bad)?;
    }
    Ok(out)
}

/// Reads the region and solids of a `"mode": "space"` document.
pub fn read(doc: &Value) -> Result<Space3, CliError> {
    let region = doc.get("region").ok_or_else(|| input_error("no 'region'"))?;
    let (region, periodic) = match region.get("kind").and_then(Value::as_str) {
        Some("box") => (
            Region3::Box {
                w: positive(region, "width", "the region")?,
                h: positive(region, "height", "the region")?,
                d: positive(region, "depth", "the region")?,
            },
            region.get("periodic").and_then(Value::as_bool).unwrap_or(false),
        ),
        Some("ball") => (
            Region3::Ball {
                r: positive(region, "radius", "the region")?,
            },
            false,
        ),
        Some("boxball") => {
            let (w, h, d) = (
                positive(region, "width", "the region")?,
                positive(region, "height", "the region")?,
                positive(region, "depth", "the region")?,
            );
            let r = positive(region, "radius", "the region")?;
            if 2.0 * r > w.min(h).min(d) {
                return Err(input_error(format!("the region's ball (radius {r}) does not fit its box")));
            }
            (Region3::BoxMinusBall { w, h, d, r }, false)
        }
        other => return Err(input_error(format!("the region's kind {other:?} is not box, ball or boxball"))),
    };
    let solids = doc
        .get("solids")
        .and_then(Value::as_array)
        .ok_or_else(|| input_error("no 'solids' list"))?;
    let side = region.bounds().1.iter().fold(0.0f64, |m, &v| m.max(v));
    let margin = MARGIN * side;
    let mut bodies = Vec::with_capacity(solids.len());
    let mut sizes = Vec::with_capacity(solids.len());
    for (n, s) in solids.iter().enumerate() {
        let what = format!("solid {n}");
        let what = what.as_str();
        let centre: V3 = array(s, "center", what)?;
        let size = positive(s, "size", what)?;
        let q: [f64; 4] = array(s, "quaternion", what)?;
        if q.iter().all(|&v| v == 0.0) {
            return Err(input_error(format!("{what}: 'quaternion' is zero, not a rotation")));
        }
        let m = rotation(q);
        let kind = match s.get("kind").and_then(Value::as_str) {
            Some("sphere") => SolidKind::Sphere { radius: size },
            Some("cube") => SolidKind::Cube { half_side: size },
            Some("tetrahedron") => SolidKind::Tetrahedron { circumradius: size },
            Some("octahedron") => SolidKind::Octahedron { circumradius: size },
            Some("shell") => {
                let inner = positive(s, "inner_radius", what)?;
                if inner >= size {
                    return Err(input_error(format!("{what}: 'inner_radius' {inner} is not below its size {size}")));
                }
                SolidKind::Shell { outer: size, inner }
            }
            Some("torus") => {
                let minor = positive(s, "tube_radius", what)?;
                let beads = s
                    .get("beads")
                    .and_then(Value::as_u64)
                    .filter(|b| (3..=zetafill::internals::space::MAX_BEADS as u64).contains(b))
                    .ok_or_else(|| {
                        input_error(format!(
                            "{what}: 'beads' is missing or not a whole number from 3 to {}",
                            zetafill::internals::space::MAX_BEADS
                        ))
                    })?;
                SolidKind::BeadTorus {
                    major: size,
                    minor,
                    beads: beads as u32,
                }
            }
            other => {
                return Err(input_error(format!(
                    "{what}: kind {other:?} is not sphere, cube, tetrahedron, octahedron, shell or torus"
                )))
            }
        };
        sizes.push(2.0 * kind.bounding_radius());
        bodies.push(body(&kind, centre, &m, margin));
    }
    Ok(Space3 {
        region,
        periodic,
        bodies,
        sizes,
    })
}

/// The body of a solid shrunk by `margin`.
fn body(kind: &SolidKind, c: V3, m: &Mat3, margin: f64) -> Body {
    match *kind {
        SolidKind::Sphere { radius } => Body::Ball(c, radius - margin),
        SolidKind::Shell { outer, inner } => Body::Shell(c, outer - margin, inner + margin),
        SolidKind::BeadTorus { minor, .. } => {
            let centres = kind
                .bead_centres()
                .iter()
                .map(|q| {
                    let w = mul(m, *q);
                    [c[0] + w[0], c[1] + w[1], c[2] + w[2]]
                })
                .collect();
            Body::Beads(centres, minor - margin)
        }
        _ => {
            // A cube, tetrahedron or octahedron (every other kind is matched above).
            let planes = kind
                .polyhedron()
                .map(|p| p.planes)
                .unwrap_or_default()
                .iter()
                .map(|(n, d)| (mul(m, *n), d - margin))
                .collect();
            Body::Poly(c, planes)
        }
    }
}

impl Body {
    fn shifted(&self, d: V3) -> Body {
        let mv = |c: &V3| [c[0] + d[0], c[1] + d[1], c[2] + d[2]];
        match self {
            Body::Ball(c, r) => Body::Ball(mv(c), *r),
            Body::Shell(c, r, ri) => Body::Shell(mv(c), *r, *ri),
            Body::Poly(c, p) => Body::Poly(mv(c), p.clone()),
            Body::Beads(cs, r) => Body::Beads(cs.iter().map(mv).collect(), *r),
        }
    }

    /// The world bounding box (of the shrunk body; empty bodies give an empty box).
    fn bounds(&self) -> (V3, V3) {
        match self {
            Body::Ball(c, r) | Body::Shell(c, r, _) => (c.map(|v| v - r), c.map(|v| v + r)),
            Body::Beads(cs, r) => {
                let mut lo = [f64::INFINITY; 3];
                let mut hi = [f64::NEG_INFINITY; 3];
                for p in cs {
                    for a in 0..3 {
                        lo[a] = lo[a].min(p[a] - r);
                        hi[a] = hi[a].max(p[a] + r);
                    }
                }
                (lo, hi)
            }
            Body::Poly(c, planes) => {
                // Bounded by the circumsphere: the largest plane offset times sqrt 3 holds a
                // cube, tetrahedron (3 d) or octahedron (sqrt 3 d) alike.
                let r = planes.iter().fold(0.0f64, |m, p| m.max(p.1)) * 3.0;
                (c.map(|v| v - r), c.map(|v| v + r))
            }
        }
    }

    /// Pushes the index ranges `[a, b)` of the boxes of the row `y in [y0, y1]`,
    /// `z in [z0, z1]` that lie inside the body.
    fn row(&self, grid: &Axis, y: (f64, f64), z: (f64, f64), out: &mut Vec<(i64, i64)>) {
        match self {
            Body::Ball(c, r) => {
                if let Some((lo, hi)) = ball_chord(*c, *r, y, z) {
                    out.push(grid.inside(lo, hi));
                }
            }
            Body::Beads(cs, r) => {
                for c in cs {
                    if let Some((lo, hi)) = ball_chord(*c, *r, y, z) {
                        out.push(grid.inside(lo, hi));
                    }
                }
            }
            Body::Shell(c, r, ri) => {
                let Some((lo, hi)) = ball_chord(*c, *r, y, z) else { return };
                // The nearest point of the row's cross-section to the centre.
                let near = |v: f64, (a, b): (f64, f64)| {
                    if v < a {
                        a - v
                    } else if v > b {
                        v - b
                    } else {
                        0.0
                    }
                };
                let (dy, dz) = (near(c[1], y), near(c[2], z));
                let rest = ri * ri - dy * dy - dz * dz;
                if rest <= 0.0 {
                    out.push(grid.inside(lo, hi));
                } else {
                    let h = rest.sqrt();
                    out.push(grid.inside(lo, hi.min(c[0] - h)));
                    out.push(grid.inside(lo.max(c[0] + h), hi));
                }
            }
            Body::Poly(c, planes) => {
                let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
                for yy in [y.0, y.1] {
                    for zz in [z.0, z.1] {
                        for (n, d) in planes {
                            // n . (p - c) <= d along the line p = (t, yy, zz).
                            let rest = d - n[1] * (yy - c[1]) - n[2] * (zz - c[2]);
                            if n[0] > 0.0 {
                                hi = hi.min(c[0] + rest / n[0]);
                            } else if n[0] < 0.0 {
                                lo = lo.max(c[0] + rest / n[0]);
                            } else if rest < 0.0 {
                                return;
                            }
                        }
                    }
                }
                if lo <= hi {
                    out.push(grid.inside(lo, hi));
                }
            }
        }
    }
}

/// Where the row's four corner lines all lie inside the ball: `x` in `[lo, hi]`.
fn ball_chord(c: V3, r: f64, y: (f64, f64), z: (f64, f64)) -> Option<(f64, f64)> {
    if r <= 0.0 {
        return None;
    }
    let dy = (y.0 - c[1]).abs().max((y.1 - c[1]).abs());
    let dz = (z.0 - c[2]).abs().max((z.1 - c[2]).abs());
    let rest = r * r - dy * dy - dz * dz;
    if rest < 0.0 {
        return None;
    }
    let h = rest.sqrt();
    Some((c[0] - h, c[0] + h))
}

/// One axis of the grid: `n` boxes of side `e`, the last clipped to `len`.
#[derive(Debug, Clone, Copy)]
struct Axis {
    e: f64,
    n: i64,
    len: f64,
}

impl Axis {
    fn new(len: f64, e: f64) -> Axis {
        Axis {
            e,
            n: (len / e).ceil().max(1.0) as i64,
            len,
        }
    }

    fn lo(&self, i: i64) -> f64 {
        i as f64 * self.e
    }

    fn hi(&self, i: i64) -> f64 {
        ((i + 1) as f64 * self.e).min(self.len)
    }

    /// The boxes `i` in `[a, b)` whose span lies in `[lo, hi]` (decided with the same
    /// arithmetic as the boxes' own ends).
    fn inside(&self, lo: f64, hi: f64) -> (i64, i64) {
        if lo.partial_cmp(&hi).is_none_or(|o| o == std::cmp::Ordering::Greater) {
            return (0, 0);
        }
        let n = self.n;
        let clamp = |x: f64| if x.is_nan() { 0 } else { x.clamp(0.0, n as f64) as i64 };
        let mut a = clamp((lo / self.e).ceil());
        while a > 0 && self.lo(a - 1) >= lo {
            a -= 1;
        }
        while a < n && self.lo(a) < lo {
            a += 1;
        }
        let mut b = clamp((hi / self.e).floor());
        while b < n && self.hi(b) <= hi {
            b += 1;
        }
        while b > 0 && self.hi(b - 1) > hi {
            b -= 1;
        }
        (a, b.max(a))
    }

    /// The boxes `[a, b)` whose span meets `[lo, hi]` (a superset: one box more at each end).
    fn span(&self, lo: f64, hi: f64) -> (i64, i64) {
        let n = self.n;
        let clamp = |x: f64| if x.is_nan() { 0 } else { x.clamp(0.0, n as f64) as i64 };
        (clamp((lo / self.e).floor() - 1.0), clamp((hi / self.e).ceil() + 1.0))
    }
}

/// The size of the union of the index ranges (sorted in place).
fn union_len(r: &mut [(i64, i64)]) -> u64 {
    r.sort_unstable();
    let (mut total, mut end) = (0u64, i64::MIN);
    for &(a, b) in r.iter() {
        let a = a.max(end);
        if b > a {
            total += (b - a) as u64;
            end = b;
        }
    }
    total
}

impl Space3 {
    /// The region's bounding box's sides.
    pub fn sides(&self) -> V3 {
        self.region.bounds().1
    }

    /// The smallest solid's diameter, as that of its bounding ball (infinite for no solid).
    pub fn smallest(&self) -> f64 {
        self.sizes.iter().copied().fold(f64::INFINITY, f64::min)
    }

    /// `(boxes that meet the region, boxes that meet the gasket)` at box size `e`.
    pub fn count(&self, e: f64) -> (u64, u64) {
        let s = self.sides();
        let g = [Axis::new(s[0], e), Axis::new(s[1], e), Axis::new(s[2], e)];
        let total = self.region_boxes(&g);
        let mut inside = 0u64;
        let mut ranges = Vec::new();
        let mut count_body = |b: &Body| {
            let (lo, hi) = b.bounds();
            if (0..3).any(|a| hi[a] <= 0.0 || lo[a] >= s[a]) {
                return;
            }
            let (j0, j1) = g[1].span(lo[1], hi[1]);
            let (k0, k1) = g[2].span(lo[2], hi[2]);
            for k in k0..k1 {
                let z = (g[2].lo(k), g[2].hi(k));
                for j in j0..j1 {
                    ranges.clear();
                    b.row(&g[0], (g[1].lo(j), g[1].hi(j)), z, &mut ranges);
                    inside += union_len(&mut ranges);
                }
            }
        };
        for b in &self.bodies {
            count_body(b);
            if self.periodic {
                for dz in [0.0, s[2], -s[2]] {
                    for dy in [0.0, s[1], -s[1]] {
                        for dx in [0.0, s[0], -s[0]] {
                            if dx != 0.0 || dy != 0.0 || dz != 0.0 {
                                count_body(&b.shifted([dx, dy, dz]));
                            }
                        }
                    }
                }
            }
        }
        (total, total.saturating_sub(inside))
    }

    /// The boxes of the grid that meet the region.
    fn region_boxes(&self, g: &[Axis; 3]) -> u64 {
        let all = (g[0].n * g[1].n * g[2].n) as u64;
        match self.region {
            Region3::Box { .. } => all,
            Region3::Ball { r } => {
                // Boxes whose nearest point to the centre is nearer than r.
                let mut n = 0u64;
                for k in 0..g[2].n {
                    for j in 0..g[1].n {
                        let near = |v: f64, a: f64, b: f64| {
                            if v < a {
                                a - v
                            } else if v > b {
                                v - b
                            } else {
                                0.0
                            }
                        };
                        let (dy, dz) = (near(r, g[1].lo(j), g[1].hi(j)), near(r, g[2].lo(k), g[2].hi(k)));
                        let rest = r * r - dy * dy - dz * dz;
                        if rest <= 0.0 {
                            continue;
                        }
                        let h = rest.sqrt();
                        // Boxes with lo(i) < r + h and hi(i) > r - h.
                        let row = (0..g[0].n).filter(|&i| g[0].lo(i) < r + h && g[0].hi(i) > r - h).count();
                        n += row as u64;
                    }
                }
                n
            }
            Region3::BoxMinusBall { w, h, d, r } => {
                let removed = Body::Ball([w / 2.0, h / 2.0, d / 2.0], r);
                let mut inside = 0u64;
                let mut ranges = Vec::new();
                for k in 0..g[2].n {
                    for j in 0..g[1].n {
                        ranges.clear();
                        removed.row(&g[0], (g[1].lo(j), g[1].hi(j)), (g[2].lo(k), g[2].hi(k)), &mut ranges);
                        inside += union_len(&mut ranges);
                    }
                }
                all.saturating_sub(inside)
            }
        }
    }
}

#[cfg(test)]
mod tests;
