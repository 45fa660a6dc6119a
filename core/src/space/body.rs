//! Concrete solids ([`Body`]) and the exact clearance test between two of them.
//!
//! [`apart`] answers "is the distance between the two solids' material greater than `gap`?"
//! in the scalar's arithmetic, on the vertices and bead centres exactly as computed (the
//! tested solid is the drawn solid); with `gap = 0` touching counts as overlapping. A solid in a
//! shell's hole keeps `gap` from the inner sphere. The test is symmetric.
//! - Two balls: centre distance against the sum of radii.
//! - A ball and a polyhedron: the point-to-polyhedron distance of the ball's centre (inside:
//!   overlap; else the nearest of the faces it sees, each face a union of triangles).
//! - Two polyhedra: separating axes (face normals of both, cross products of edge directions:
//!   exact for convex polyhedra) say whether they meet; with a gap, their distance is the
//!   least of vertex-to-polyhedron and edge-to-edge distances (a closest pair of two disjoint
//!   convex polyhedra always includes a vertex of one, or a point inside an edge of each).
//! - A torus is the union of its beads: every bead apart. Only the beads that can reach the
//!   other solid are tested ([`near_beads`]): the rest are farther than the test's threshold
//!   by a margin far above rounding, so the answer is the one every bead would give.

use super::solid::{Solid, Table, MAX_BEADS};
use super::vec3::{apply, columns, Quat, V3};
use crate::scalar::Scalar;
use core::f64::consts::{PI, TAU};

/// The sines and cosines of a torus's bead angles `2 pi k / n`, in the scalar's arithmetic:
/// what [`Body::new`] computes for every torus, kept by an engine that builds many.
#[derive(Clone, Copy, Debug)]
pub struct BeadTrig<S> {
    n: usize,
    sin_cos: [(S, S); MAX_BEADS],
}

impl<S: Scalar> BeadTrig<S> {
    /// The table for `kind`'s beads (empty for a solid that is not a torus).
    pub fn new(kind: &Solid) -> Self {
        let n = kind.beads();
        let mut sin_cos = [(S::ZERO, S::ZERO); MAX_BEADS];
        for (k, sc) in sin_cos.iter_mut().take(n).enumerate() {
            *sc = S::from_f64(TAU * k as f64 / n as f64).sin_cos();
        }
        BeadTrig { n, sin_cos }
    }
}

/// A polyhedron in place.
#[derive(Clone, Copy, Debug)]
pub struct Poly<S> {
    /// Centre.
    pub c: V3<S>,
    /// Scale.
    pub s: S,
    /// Vertices (the first `table.verts.len()`).
    pub v: [V3<S>; 8],
    /// Outward unit face normals (the first `table.normals.len()`).
    pub n: [V3<S>; 8],
    pub(crate) table: &'static Table,
}

/// A solid in place, with the geometry its tests need.
#[derive(Clone, Copy, Debug)]
pub enum Body<S> {
    /// A ball.
    Ball {
        /// Centre.
        c: V3<S>,
        /// Radius.
        r: S,
    },
    /// A hollow ball.
    Shell {
        /// Centre.
        c: V3<S>,
        /// Outer radius.
        r: S,
        /// Hole radius.
        hole: S,
    },
    /// A convex polyhedron.
    Poly(Poly<S>),
    /// A torus as the union of `n` balls of radius `tube` centred at `beads`.
    Torus {
        /// Centre.
        c: V3<S>,
        /// The unit vectors of its plane: bead `k` is at
        /// `c + axes[0] (R cos(2 pi k / n)) + axes[1] (R sin(2 pi k / n))`.
        axes: [V3<S>; 2],
        /// The major radius `R`.
        major: S,
        /// The tube's radius.
        tube: S,
        /// Bounding radius.
        bound: S,
        /// Number of beads.
        n: usize,
        /// Bead centres (the first `n`).
        beads: [V3<S>; MAX_BEADS],
    },
}

fn v3<S: Scalar>(a: &[f64; 3]) -> V3<S> {
    V3::from_f64(a[0], a[1], a[2])
}

impl<S: Scalar> Body<S> {
    /// The solid `kind` with centre `c`, scale `s` and rotation `q`.
    pub fn new(kind: &Solid, c: V3<S>, s: S, q: &Quat<S>) -> Self {
        Self::with_trig(kind, c, s, q, None)
    }

    /// [`Body::new`], taking a torus's bead angles from `trig` when it was made for as many
    /// beads (the same bits as computing them).
    pub fn with_trig(kind: &Solid, c: V3<S>, s: S, q: &Quat<S>, trig: Option<&BeadTrig<S>>) -> Self {
        match *kind {
            Solid::Sphere => Body::Ball { c, r: s },
            Solid::Shell { inner } => Body::Shell {
                c,
                r: s,
                hole: s * S::from_f64(inner),
            },
            Solid::Torus { ratio } => {
                let m = columns(q);
                let n = kind.beads();
                let own;
                let trig = match trig {
                    Some(t) if t.n == n => t,
                    _ => {
                        own = BeadTrig::new(kind);
                        &own
                    }
                };
                let mut beads = [c; MAX_BEADS];
                for (b, &(sin, cos)) in beads.iter_mut().zip(trig.sin_cos.iter()).take(n) {
                    *b = c.add(m[0].scale(s * cos).add(m[1].scale(s * sin)));
                }
                Body::Torus {
                    c,
                    axes: [m[0], m[1]],
                    major: s,
                    tube: s * S::from_f64(ratio),
                    bound: super::solid::bounding(kind, s),
                    n,
                    beads,
                }
            }
            Solid::Cube | Solid::Tetrahedron | Solid::Octahedron => {
                let Some(table) = kind.table() else { return Body::Ball { c, r: s } };
                let m = columns(q);
                let mut v = [c; 8];
                for (out, p) in v.iter_mut().zip(table.verts) {
                    *out = c.add(apply(&m, v3::<S>(p).scale(s)));
                }
                let mut n = [V3::default(); 8];
                for (out, p) in n.iter_mut().zip(table.normals) {
                    *out = apply(&m, v3(p));
                }
                Body::Poly(Poly { c, s, v, n, table })
            }
        }
    }

    /// Centre.
    pub fn centre(&self) -> V3<S> {
        match self {
            Body::Ball { c, .. } | Body::Shell { c, .. } | Body::Torus { c, .. } => *c,
            Body::Poly(p) => p.c,
        }
    }

    /// The same body moved by `d`.
    pub fn shifted(&self, d: V3<S>) -> Self {
        let mut b = *self;
        match &mut b {
            Body::Ball { c, .. } | Body::Shell { c, .. } => *c = c.add(d),
            Body::Torus { c, beads, .. } => {
                *c = c.add(d);
                beads.iter_mut().for_each(|p| *p = p.add(d));
            }
            Body::Poly(p) => {
                p.c = p.c.add(d);
                p.v.iter_mut().for_each(|v| *v = v.add(d));
            }
        }
        b
    }

    /// The vertices of a polyhedron (empty for other bodies).
    pub fn vertices(&self) -> &[V3<S>] {
        match self {
            Body::Poly(p) => p.v.get(..p.table.verts.len()).unwrap_or(&[]),
            _ => &[],
        }
    }

    /// The bead centres of a torus (empty for other bodies).
    pub fn beads(&self) -> &[V3<S>] {
        match self {
            Body::Torus { n, beads, .. } => beads.get(..*n).unwrap_or(&[]),
            _ => &[],
        }
    }

    /// Whether every point of the body is within `room` of `p` (strictly), its convex hull
    /// too.
    pub fn within(&self, p: V3<S>, room: S) -> bool {
        let ball = |c: V3<S>, r: S| {
            let d = room - r;
            d > S::ZERO && c.sub(p).norm2() < d * d
        };
        match self {
            Body::Ball { c, r } | Body::Shell { c, r, .. } => ball(*c, *r),
            Body::Torus { tube, .. } => self.beads().iter().all(|b| ball(*b, *tube)),
            Body::Poly(_) => room > S::ZERO && self.vertices().iter().all(|v| v.sub(p).norm2() < room * room),
        }
    }

    /// The signed distance from `p` to the body's material (negative inside), an upper bound
    /// of it for a torus (the least over its beads), in the scalar's arithmetic.
    pub fn signed_dist(&self, p: V3<S>) -> S {
        match self {
            Body::Ball { c, r } => c.sub(p).norm2_up().sqrt() - *r,
            Body::Shell { c, r, hole } => {
                let d = c.sub(p).norm2_up().sqrt();
                if d >= *r {
                    d - *r
                } else if d <= *hole {
                    *hole - d
                } else {
                    -(d - *hole).min(*r - d)
                }
            }
            Body::Torus { tube, .. } => self
                .beads()
                .iter()
                .map(|b| b.sub(p).norm2_up().sqrt() - *tube)
                .fold(None, |m: Option<S>, d| Some(m.map_or(d, |m| m.min(d))))
                .unwrap_or(S::ZERO),
            Body::Poly(poly) => match poly_dist2(poly, p) {
                Err(depth) => depth,
                Ok(d2) => d2.sqrt(),
            },
        }
    }
}

/// `Ok(squared distance)` from `p` to the polyhedron when `p` is outside it, else
/// `Err(signed depth)` (at most 0: minus the distance to the nearest face's plane).
pub(crate) fn poly_dist2<S: Scalar>(poly: &Poly<S>, p: V3<S>) -> Result<S, S> {
    let h = poly.s * S::from_f64(poly.table.h);
    let rel = p.sub(poly.c);
    let mut depth: Option<S> = None;
    let mut outside = false;
    for n in poly.n.iter().take(poly.table.normals.len()) {
        let s = n.dot(rel) - h;
        outside |= s > S::ZERO;
        depth = Some(depth.map_or(s, |d| d.max(s)));
    }
    if !outside {
        return Err(depth.unwrap_or(S::ZERO));
    }
    let mut best: Option<S> = None;
    for t in poly.table.tris {
        let n = poly.n.get(usize::from(t[3])).copied().unwrap_or_default();
        // Only the faces `p` sees hold its nearest point.
        if n.dot(rel) - h <= S::ZERO {
            continue;
        }
        let vert = |i: u8| poly.v.get(usize::from(i)).copied().unwrap_or_default();
        let d = tri_dist2(p, vert(t[0]), vert(t[1]), vert(t[2]), n);
        best = Some(best.map_or(d, |b| b.min(d)));
    }
    Ok(best.unwrap_or(S::ZERO))
}

/// Squared distance from `p` to the closed segment `a`-`b`.
pub(crate) fn seg_dist2<S: Scalar>(p: V3<S>, a: V3<S>, b: V3<S>) -> S {
    let ab = b.sub(a);
    let ap = p.sub(a);
    let t = ap.dot(ab);
    let l2 = ab.norm2();
    if t <= S::ZERO || l2 <= S::ZERO {
        return ap.norm2();
    }
    if t >= l2 {
        return p.sub(b).norm2();
    }
    ap.sub(ab.scale(t / l2)).norm2()
}

/// Squared distance from `p` to the triangle `a b c` of unit normal `n`.
fn tri_dist2<S: Scalar>(p: V3<S>, a: V3<S>, b: V3<S>, c: V3<S>, n: V3<S>) -> S {
    // Inside the prism over the triangle: the plane's distance.
    let side = |u: V3<S>, v: V3<S>| p.sub(u).dot(n.cross(v.sub(u)));
    let (s0, s1, s2) = (side(a, b), side(b, c), side(c, a));
    let z = S::ZERO;
    if (s0 >= z && s1 >= z && s2 >= z) || (s0 <= z && s1 <= z && s2 <= z) {
        let d = p.sub(a).dot(n);
        return d * d;
    }
    seg_dist2(p, a, b).min(seg_dist2(p, b, c)).min(seg_dist2(p, c, a))
}

/// Squared distance between two segments given by their starts, unit directions and lengths.
fn segs_dist2<S: Scalar>(p1: V3<S>, u1: V3<S>, l1: S, p2: V3<S>, u2: V3<S>, l2: S) -> S {
    let r = p1.sub(p2);
    let (b, c, f) = (u1.dot(u2), u1.dot(r), u2.dot(r));
    let clamp = |v: S, hi: S| v.max(S::ZERO).min(hi);
    let denom = S::ONE - b * b;
    let mut s = if denom > S::ZERO { clamp((b * f - c) / denom, l1) } else { S::ZERO };
    let mut t = b * s + f;
    if t < S::ZERO {
        t = S::ZERO;
        s = clamp(-c, l1);
    } else if t > l2 {
        t = l2;
        s = clamp(b * l2 - c, l1);
    }
    r.add(u1.scale(s)).sub(u2.scale(t)).norm2()
}

/// The projection interval of the vertices on `axis`.
fn interval<S: Scalar>(vs: &[V3<S>], axis: V3<S>) -> (S, S) {
    let first = vs.first().map_or(S::ZERO, |v| v.dot(axis));
    vs.iter().fold((first, first), |(lo, hi), v| {
        let d = v.dot(axis);
        (lo.min(d), hi.max(d))
    })
}

fn edge_dir<S: Scalar>(p: &Poly<S>, e: &[u8; 2]) -> (V3<S>, V3<S>, S) {
    let get = |i: u8| p.v.get(usize::from(i)).copied().unwrap_or_default();
    let (a, b) = (get(e[0]), get(e[1]));
    let len = p.s * S::from_f64(p.table.edge_len);
    let u = if len > S::ZERO {
        b.sub(a).scale(S::ONE / len)
    } else {
        V3::default()
    };
    (a, u, len)
}

/// Whether two convex polyhedra are more than `gap` apart.
fn poly_poly<S: Scalar>(a: &Poly<S>, b: &Poly<S>, gap: S) -> bool {
    let (va, vb) = (
        a.v.get(..a.table.verts.len()).unwrap_or(&[]),
        b.v.get(..b.table.verts.len()).unwrap_or(&[]),
    );
    let separates = |axis: V3<S>| {
        let (lo_a, hi_a) = interval(va, axis);
        let (lo_b, hi_b) = interval(vb, axis);
        hi_a < lo_b || hi_b < lo_a
    };
    let normal = |p: &Poly<S>, i: u8| p.n.get(usize::from(i)).copied().unwrap_or_default();
    let mut apart = a.table.axes.iter().any(|&i| separates(normal(a, i))) || b.table.axes.iter().any(|&i| separates(normal(b, i)));
    if !apart {
        'outer: for ea in a.table.dir_edges {
            let (_, ua, _) = edge_dir(a, ea);
            for eb in b.table.dir_edges {
                let (_, ub, _) = edge_dir(b, eb);
                if separates(ua.cross(ub)) {
                    apart = true;
                    break 'outer;
                }
            }
        }
    }
    if !apart {
        return false;
    }
    if gap <= S::ZERO {
        return true;
    }
    let g2 = gap * gap;
    let far = |p: &Poly<S>, v: &V3<S>| matches!(poly_dist2(p, *v), Ok(d2) if d2 > g2);
    if !(va.iter().all(|v| far(b, v)) && vb.iter().all(|v| far(a, v))) {
        return false;
    }
    a.table.edges.iter().all(|ea| {
        let (pa, ua, la) = edge_dir(a, ea);
        b.table.edges.iter().all(|eb| {
            let (pb, ub, lb) = edge_dir(b, eb);
            segs_dist2(pa, ua, la, pb, ub, lb) > g2
        })
    })
}

/// The outer body of a shell (its full ball); other bodies unchanged.
fn outer<S: Scalar>(b: &Body<S>) -> Body<S> {
    match *b {
        Body::Shell { c, r, .. } => Body::Ball { c, r },
        other => other,
    }
}

/// Whether `x` lies in the hole of `s` (a shell), keeping `gap` from its inner sphere.
fn in_hole<S: Scalar>(x: &Body<S>, s: &Body<S>, gap: S) -> bool {
    match s {
        Body::Shell { c, hole, .. } => outer(x).within(*c, *hole - gap),
        _ => false,
    }
}

/// Whether the material of `a` and `b` is more than `gap` apart (`gap >= 0`).
pub fn apart<S: Scalar>(a: &Body<S>, b: &Body<S>, gap: S) -> bool {
    apart_by(a, b, gap, &near_beads)
}

/// [`apart`], testing the beads of a torus that `window` names for a point and a reach (see
/// [`near_beads`]).
fn apart_by<S: Scalar, W: Fn(&Body<S>, V3<S>, S) -> (usize, usize)>(a: &Body<S>, b: &Body<S>, gap: S, window: &W) -> bool {
    let apart = |a: &Body<S>, b: &Body<S>, gap: S| apart_by(a, b, gap, window);
    match (a, b) {
        (Body::Shell { .. }, _) | (_, Body::Shell { .. }) => in_hole(a, b, gap) || in_hole(b, a, gap) || apart(&outer(a), &outer(b), gap),
        (Body::Torus { tube, .. }, other) | (other, Body::Torus { tube, .. }) => {
            let t = if matches!(a, Body::Torus { .. }) { a } else { b };
            let (oc, ob) = (other.centre(), bound_of(other));
            let reach = *tube + ob + gap;
            let beads = t.beads();
            let (first, count) = window(t, oc, reach);
            (first..first + count).all(|k| {
                let Some(&bc) = beads.get(k % beads.len().max(1)) else {
                    return true;
                };
                bc.sub(oc).norm2() > reach * reach || apart(&Body::Ball { c: bc, r: *tube }, other, gap)
            })
        }
        (Body::Ball { c: c1, r: r1 }, Body::Ball { c: c2, r: r2 }) => {
            let reach = *r1 + *r2 + gap;
            c1.sub(*c2).norm2() > reach * reach
        }
        (Body::Ball { c, r }, Body::Poly(p)) | (Body::Poly(p), Body::Ball { c, r }) => {
            let reach = *r + gap;
            matches!(poly_dist2(p, *c), Ok(d2) if d2 > reach * reach)
        }
        (Body::Poly(p), Body::Poly(q)) => poly_poly(p, q, gap),
    }
}

/// The beads of torus `t` that may lie within `reach` of `p`, as a run `(first, count)` of
/// indices taken modulo the bead count: every bead outside it is farther from `p` than `reach`
/// by a margin far above the rounding of either scalar (all beads for other cases).
///
/// The beads lie on the centre circle at the angles `2 pi k / n`. With `p` at height `h` over
/// the torus's plane and `rho` from its axis, at angle `theta*` in the plane, the squared distance
/// to the circle's point at angle `theta` is `|p - c|^2 + R^2 - 2 R rho cos(theta - theta*)`,
/// growing with `|theta - theta*|`; the beads within reach lie within `phi` of `theta*`, with
/// `cos(phi) = (|p - c|^2 + R^2 - reach^2) / (2 R rho)`. The run covers `phi` widened by one
/// bead's angle on each side and the threshold widened by a millionth of the squares (plus
/// 1e-8 for the fixed-point scalar's products), computed in `f64`. Near the axis
/// (`rho < R / 20`) the distances hardly vary with the angle, and every bead is tested.
pub(crate) fn near_beads<S: Scalar>(t: &Body<S>, p: V3<S>, reach: S) -> (usize, usize) {
    let Body::Torus { c, axes, major, n, .. } = t else { return (0, 0) };
    let n = *n;
    let all = (0, n);
    let w = p.sub(*c);
    let f = |v: V3<S>| [v.x.to_f64(), v.y.to_f64(), v.z.to_f64()];
    let (wf, u, v) = (f(w), f(axes[0]), f(axes[1]));
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let (a, b, w2) = (dot(wf, u), dot(wf, v), dot(wf, wf));
    let (r, l) = (major.to_f64(), reach.to_f64());
    let rho = libm::sqrt(a * a + b * b);
    if n == 0 || !(rho.is_finite() && w2.is_finite() && l.is_finite() && r > 0.0) || rho < 0.05 * r {
        return all;
    }
    let tol = 1e-6 * (w2 + r * r + l * l) + 1e-8;
    // The nearest point of the circle is beyond reach: so is every bead.
    if w2 + r * r - 2.0 * r * rho > l * l + tol {
        return (0, 0);
    }
    let kappa = (w2 + r * r - l * l - tol) / (2.0 * r * rho);
    let step = TAU / n as f64;
    let phi = libm::acos(kappa.clamp(-1.0, 1.0)) + step;
    if phi >= PI {
        return all;
    }
    let theta = libm::atan2(b, a);
    let lo = libm::ceil((theta - phi) / step);
    let hi = libm::floor((theta + phi) / step);
    if !(lo.is_finite() && hi.is_finite()) || hi < lo {
        return all;
    }
    let count = (hi - lo) as usize + 1;
    if count >= n {
        return all;
    }
    let first = (lo as i64).rem_euclid(n as i64) as usize;
    (first, count)
}

/// A radius about the centre that holds the body (the torus's stored bound; a polyhedron's
/// farthest vertex, grown by the scalar's slack).
pub(crate) fn bound_of<S: Scalar>(b: &Body<S>) -> S {
    match b {
        Body::Ball { r, .. } | Body::Shell { r, .. } => *r,
        Body::Torus { bound, .. } => *bound,
        Body::Poly(p) => {
            let r =
                p.v.iter()
                    .take(p.table.verts.len())
                    .map(|v| v.sub(p.c).norm2_up())
                    .fold(S::ZERO, |m, d| m.max(d))
                    .sqrt();
            let [rel, abs] = S::OUTLINE_SLACK;
            r + r * S::from_f64(rel) + S::from_f64(abs + 1e-12 * r.to_f64())
        }
    }
}

#[cfg(test)]
mod tests;
