//! Slices for stacked laser cuts: the region cut into sheets of one thickness, and on each
//! sheet the cross-section of every solid at the sheet's mid-plane, as a [`Picture`] that the
//! SVG, PNG and G-code writers write like any other.
//!
//! Sheet `k` (from 0) spans `z0 + k t .. z0 + (k + 1) t` over the region's depth (`z0` its
//! lowest z, `t` the thickness); there are `ceil(depth / t)` sheets, the last one possibly
//! sticking out. Its mid-plane `z = z0 + (k + 1/2) t` cuts:
//!
//! - a sphere into a circle, a shell into two (one path, holes by the even-odd rule);
//! - a cube, tetrahedron or octahedron into its exact convex polygon: a square around the
//!   solid clipped by each face's half-plane in the cutting plane;
//! - a bead torus into the outline of the union of its beads' discs: the arcs of each circle
//!   that no other disc covers, chained into closed loops ([`disc_union`]);
//! - a smooth torus likewise, through a union of balls of its tube's radius centred on its
//!   central circle: each lies inside the torus, so the outline lies inside the exact section,
//!   short of it by at most [`SliceOptions::torus_tolerance`] (enough balls are taken).
//!
//! Each sheet's picture has three plotter layers: `outline` (the region's own section: the
//! sheet's outer cut), `parts` (the solids' sections) and `marks` (registration marks: a
//! circle and a cross at each corner, outside the region's box, the same on every sheet, so
//! the sheets stack true). [`stacked`] puts every sheet in one picture, one layer per sheet.
//! Deterministic: the same solids give the same pictures.

use super::path::dist;
use super::picture::{Item, Layer, Shape};
use super::solid::{bead_torus_tube, dot, mul, Region3, Solid, SolidKind};
use super::{Bounds, Path, Picture, Pt};
use std::f64::consts::TAU;

/// How the sheets are cut.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliceOptions {
    /// Sheet thickness (mm).
    pub thickness: f64,
    /// Pen or beam width of the strokes (mm).
    pub pen: f64,
    /// How far inside a smooth torus's section its outline may fall (mm).
    pub torus_tolerance: f64,
}

impl SliceOptions {
    /// Sheets `thickness` mm thick, a 0.1 mm pen, tori within 0.01 mm.
    pub fn new(thickness: f64) -> SliceOptions {
        SliceOptions {
            thickness,
            pen: 0.1,
            torus_tolerance: 0.01,
        }
    }
}

/// One sheet of the stack.
#[derive(Debug, Clone, PartialEq)]
pub struct Sheet {
    /// Its index from the bottom (0).
    pub index: usize,
    /// The height of its mid-plane (mm).
    pub z: f64,
    /// What is cut from it.
    pub picture: Picture,
}

/// Why the region cannot be sliced.
#[derive(Debug, Clone, PartialEq)]
pub enum SliceError {
    /// The thickness is not positive, or thicker than the region is deep.
    Thickness {
        /// The thickness asked (mm).
        thickness: f64,
        /// The region's depth (mm).
        depth: f64,
    },
    /// More sheets than [`MAX_SHEETS`].
    TooMany(f64),
}

impl std::fmt::Display for SliceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SliceError::Thickness { thickness, depth } => {
                write!(
                    f,
                    "sheets {thickness} mm thick: give a thickness above 0 and at most the region's depth, {depth} mm"
                )
            }
            SliceError::TooMany(n) => write!(f, "{n} sheets: at most {MAX_SHEETS}, give thicker sheets"),
        }
    }
}

/// The most sheets a stack may have.
pub const MAX_SHEETS: usize = 10_000;

/// How far the registration marks sit outside the region's box (mm).
pub const MARK_OFFSET: f64 = 6.0;

/// The sheets of the stack, each with the sections of the solids it cuts.
pub fn slices(solids: &[Solid], region: &Region3, opt: &SliceOptions) -> Result<Vec<Sheet>, SliceError> {
    let (lo, hi) = region.bounds();
    let (t, depth) = (opt.thickness, hi[2] - lo[2]);
    if !(t.is_finite() && t > 0.0 && t <= depth) {
        return Err(SliceError::Thickness { thickness: t, depth });
    }
    let n = (depth / t - 1e-9).ceil().max(1.0);
    if n > MAX_SHEETS as f64 {
        return Err(SliceError::TooMany(n));
    }
    let n = n as usize;
    // The solids each sheet's plane may cut, found from their bounding spheres.
    let mut cut: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, s) in solids.iter().enumerate() {
        let r = s.kind.bounding_radius();
        let first = ((s.centre[2] - r - lo[2]) / t - 0.5).ceil().max(0.0);
        let last = ((s.centre[2] + r - lo[2]) / t - 0.5).floor().min(n as f64 - 1.0);
        let mut k = first;
        while k <= last {
            cut[k as usize].push(i);
            k += 1.0;
        }
    }
    let frame = Bounds {
        x0: lo[0] - 2.0 * MARK_OFFSET,
        y0: lo[1] - 2.0 * MARK_OFFSET,
        x1: hi[0] + 2.0 * MARK_OFFSET,
        y1: hi[1] + 2.0 * MARK_OFFSET,
    };
    Ok(cut
        .iter()
        .enumerate()
        .map(|(index, ids)| {
            let z = lo[2] + (index as f64 + 0.5) * t;
            let parts: Vec<Item> = ids.iter().filter_map(|i| section(&solids[*i], z, opt.torus_tolerance)).collect();
            let mut picture = Picture::new(frame);
            picture.title = format!("zetafill sheet {} of {n}, mid-plane z = {z} mm", index + 1);
            picture.desc = format!("sheet {} of {n}, {t} mm thick, cut at z = {z} mm", index + 1);
            picture.layers = vec![
                Layer::strokes("outline", opt.pen, region_section(region, z)),
                Layer::strokes("parts", opt.pen, parts),
                Layer::strokes("marks", opt.pen, marks(lo, hi)),
            ];
            Sheet { index, z, picture }
        })
        .collect())
}

/// Every sheet in one picture: one layer per sheet (labelled `sheet K z=Z`), holding its
/// outline, parts and marks, so a laser's software can show and cut one sheet at a time.
pub fn stacked(sheets: &[Sheet]) -> Option<Picture> {
    let first = sheets.first()?;
    let mut picture = Picture::new(first.picture.frame);
    picture.title = format!("zetafill: {} sheets", sheets.len());
    picture.desc = first.picture.desc.clone();
    picture.layers = sheets
        .iter()
        .map(|s| {
            let mut layer = s.picture.layers.first().cloned().unwrap_or_default();
            let id = format!("sheet{}", s.index + 1);
            layer.label = Some(format!("sheet {} z={}", s.index + 1, s.z));
            layer.items = s.picture.layers.iter().flat_map(|l| l.items.iter().cloned()).collect();
            layer.id = Some(id);
            layer
        })
        .collect();
    Some(picture)
}

/// The region's own section at height `z`: the sheet's outer cut.
pub fn region_section(region: &Region3, z: f64) -> Vec<Item> {
    let (lo, hi) = region.bounds();
    let c = region.centre();
    let rect = Item::new(Shape::Polygon(vec![[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]]));
    let circle = |r: f64| {
        let dz = z - c[2];
        (dz.abs() < r).then(|| {
            Item::new(Shape::Circle {
                c: [c[0], c[1]],
                r: (r * r - dz * dz).sqrt(),
            })
        })
    };
    match *region {
        Region3::Box { .. } => vec![rect],
        Region3::Ball { r } => circle(r).into_iter().collect(),
        Region3::BoxMinusBall { r, .. } => std::iter::once(rect).chain(circle(r)).collect(),
    }
}

/// Registration marks: a circle of 2 mm radius and a cross 8 mm wide at each corner of the
/// region's box, [`MARK_OFFSET`] mm out along both axes.
fn marks(lo: [f64; 3], hi: [f64; 3]) -> Vec<Item> {
    let o = MARK_OFFSET;
    [
        [lo[0] - o, lo[1] - o],
        [hi[0] + o, lo[1] - o],
        [hi[0] + o, hi[1] + o],
        [lo[0] - o, hi[1] + o],
    ]
    .iter()
    .flat_map(|&[x, y]| {
        [
            Item::new(Shape::Circle { c: [x, y], r: 2.0 }),
            Item::new(Shape::Line([x - 4.0, y], [x + 4.0, y])),
            Item::new(Shape::Line([x, y - 4.0], [x, y + 4.0])),
        ]
    })
    .collect()
}

/// The section of one solid by the plane at height `z`, `None` when the plane misses it.
pub fn section(s: &Solid, z: f64, torus_tolerance: f64) -> Option<Item> {
    let dz = z - s.centre[2];
    let centre = [s.centre[0], s.centre[1]];
    let disc = |r: f64| (dz.abs() < r).then(|| (r * r - dz * dz).sqrt());
    match s.kind {
        SolidKind::Sphere { radius } => disc(radius).map(|r| Item::new(Shape::Circle { c: centre, r })),
        SolidKind::Shell { outer, inner } => {
            let ro = disc(outer)?;
            let mut paths = vec![Path::circle(centre, ro)];
            paths.extend(disc(inner).map(|ri| Path::circle(centre, ri)));
            Some(Item::new(Shape::Path(paths)).evenodd())
        }
        SolidKind::Cube { .. } | SolidKind::Tetrahedron { .. } | SolidKind::Octahedron { .. } => {
            let poly = polygon_section(s, z);
            (poly.len() >= 3).then(|| Item::new(Shape::Polygon(poly)))
        }
        SolidKind::BeadTorus { minor, .. } => beads_section(s, &s.kind.bead_centres(), minor, z),
        SolidKind::Torus { major, minor } => {
            let beads = balls_for(major, minor, torus_tolerance);
            let kind = SolidKind::BeadTorus { major, minor, beads };
            beads_section(s, &kind.bead_centres(), minor, z)
        }
    }
}

/// The fewest balls of radius `minor` on the circle of radius `major` whose union holds the
/// torus shrunk by `tolerance` (at least 8, at most 2^16).
pub fn balls_for(major: f64, minor: f64, tolerance: f64) -> u32 {
    let mut k = 8u32;
    while k < 1 << 16 && bead_torus_tube(major, minor, k).is_none_or(|t| minor - t > tolerance) {
        k *= 2;
    }
    k
}

/// The outline of the discs the plane at `z` cuts from balls of radius `r` at these local
/// centres of `s`.
fn beads_section(s: &Solid, centres: &[[f64; 3]], r: f64, z: f64) -> Option<Item> {
    let discs: Vec<(Pt, f64)> = centres
        .iter()
        .map(|c| s.to_world(*c))
        .filter(|c| (z - c[2]).abs() < r)
        .map(|c| ([c[0], c[1]], (r * r - (z - c[2]).powi(2)).sqrt()))
        .collect();
    let loops = disc_union(&discs);
    (!loops.is_empty()).then(|| Item::new(Shape::Loops(loops)).evenodd())
}

/// The exact section of a convex polyhedron: a square around it, clipped by each face's
/// half-plane in the cutting plane (Sutherland–Hodgman), counter-clockwise.
pub fn polygon_section(s: &Solid, z: f64) -> Vec<Pt> {
    let Some(p) = s.kind.polyhedron() else {
        return Vec::new();
    };
    let r = 2.0 * s.kind.bounding_radius();
    let [cx, cy, _] = s.centre;
    let mut poly = vec![[cx - r, cy - r], [cx + r, cy - r], [cx + r, cy + r], [cx - r, cy + r]];
    for (n, d) in &p.planes {
        // n_w . (p - c) <= d, with p = (x, y, z).
        let w = mul(&s.rotation, *n);
        let e = d + dot(w, s.centre) - w[2] * z;
        poly = clip_half_plane(&poly, w[0], w[1], e);
        if poly.is_empty() {
            break;
        }
    }
    poly.dedup_by(|a, b| dist(*a, *b) <= 1e-12 * r);
    if poly.len() > 1 && dist(poly[0], poly[poly.len() - 1]) <= 1e-12 * r {
        poly.pop();
    }
    poly
}

/// The part of a convex polygon where `a x + b y <= e`.
fn clip_half_plane(poly: &[Pt], a: f64, b: f64, e: f64) -> Vec<Pt> {
    let f = |p: Pt| a * p[0] + b * p[1] - e;
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (i, &p) in poly.iter().enumerate() {
        let q = poly[(i + 1) % poly.len()];
        let (fp, fq) = (f(p), f(q));
        if fp <= 0.0 {
            out.push(p);
        }
        if (fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0) {
            let t = fp / (fp - fq);
            out.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
        }
    }
    out
}

/// The boundary of a union of discs as closed loops of arcs: each circle's arcs that no other
/// disc covers (counter-clockwise about their own centres), chained end to start. A disc inside
/// another adds nothing; of equal discs, the first counts.
///
/// Discs are paired through a sweep along x, and an arc that ends where disc `j` starts to
/// cover its circle goes on with an arc of `j`'s circle, so the work grows with the number of
/// overlapping pairs, not with its square.
pub fn disc_union(discs: &[(Pt, f64)]) -> Vec<Vec<Path>> {
    let rmax = discs.iter().fold(0.0f64, |m, d| m.max(d.1));
    let mut order: Vec<usize> = (0..discs.len()).collect();
    order.sort_by(|a, b| discs[*a].0[0].total_cmp(&discs[*b].0[0]).then(a.cmp(b)));
    // Arcs with the disc they lie on and the disc whose circle the boundary goes on along.
    let mut arcs: Vec<(Path, usize, usize)> = Vec::new();
    let mut loops: Vec<Vec<Path>> = Vec::new();
    for (p, &i) in order.iter().enumerate() {
        let (ci, ri) = discs[i];
        let near = |q: &&usize| (discs[**q].0[0] - ci[0]).abs() < ri + rmax;
        let before = order[..p].iter().rev().take_while(near);
        let after = order[p + 1..].iter().take_while(near);
        // Covered angle ranges of circle i, each with the disc that covers it.
        let mut covered: Vec<(f64, f64, usize)> = Vec::new();
        let mut hidden = false;
        for &j in before.chain(after) {
            let (cj, rj) = discs[j];
            let d = dist(ci, cj);
            let same = d == 0.0 && rj == ri;
            if d >= ri + rj || (d + rj <= ri && !same) {
                continue;
            }
            if d + ri <= rj {
                hidden = !(same && j > i);
                if hidden {
                    break;
                }
                continue;
            }
            let a = libm::atan2(cj[1] - ci[1], cj[0] - ci[0]);
            let h = libm::acos(((ri * ri + d * d - rj * rj) / (2.0 * ri * d)).clamp(-1.0, 1.0));
            let s = (a - h).rem_euclid(TAU);
            if s + 2.0 * h > TAU {
                covered.push((s, TAU, j));
                covered.push((0.0, s + 2.0 * h - TAU, j));
            } else {
                covered.push((s, s + 2.0 * h, j));
            }
        }
        if hidden {
            continue;
        }
        if covered.is_empty() {
            loops.push(vec![Path::circle(ci, ri)]);
            continue;
        }
        covered.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)).then(x.2.cmp(&y.2)));
        // Merged ranges: start, end, the disc covering the start.
        let mut merged: Vec<(f64, f64, usize)> = Vec::new();
        for (s, e, j) in covered {
            match merged.last_mut() {
                Some(last) if s <= last.1 => last.1 = last.1.max(e),
                _ => merged.push((s, e, j)),
            }
        }
        // The gaps between covered ranges, the last one wrapping past 2π.
        for (k, &(_, end, _)) in merged.iter().enumerate() {
            let (next, to) = merged.get(k + 1).map_or((merged[0].0 + TAU, merged[0].2), |m| (m.0, m.2));
            if next - end > 1e-12 {
                let arc = Path::Arc {
                    center: ci,
                    radius: ri,
                    start: end,
                    sweep: next - end,
                };
                arcs.push((arc, i, to));
            }
        }
    }
    let mut on_disc: Vec<Vec<usize>> = vec![Vec::new(); discs.len()];
    for (k, a) in arcs.iter().enumerate() {
        on_disc[a.1].push(k);
    }
    // Chain the arcs: each goes on with the unused arc of the next disc that starts nearest its
    // end (any unused arc, should that disc have none), until the loop's own start is nearer.
    let mut used = vec![false; arcs.len()];
    for first in 0..arcs.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let home = arcs[first].0.start_point();
        let mut chain = vec![arcs[first].0.clone()];
        let (mut end, mut to) = (arcs[first].0.end_point(), arcs[first].2);
        loop {
            let nearest = |ks: &mut dyn Iterator<Item = usize>| {
                ks.filter(|k| !used[*k])
                    .map(|k| (dist(end, arcs[k].0.start_point()), k))
                    .min_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)))
            };
            let next = nearest(&mut on_disc[to].iter().copied()).or_else(|| nearest(&mut (0..arcs.len())));
            match next {
                Some((d, k)) if d < dist(end, home) => {
                    used[k] = true;
                    (end, to) = (arcs[k].0.end_point(), arcs[k].2);
                    chain.push(arcs[k].0.clone());
                }
                _ => break,
            }
        }
        loops.push(chain);
    }
    loops
}
