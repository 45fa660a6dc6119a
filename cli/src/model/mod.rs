//! The drawing model: the fill's document ([`doc`]), and one plain data model of what a pen or beam draws, built from a
//! fill, and everything that turns it into machine-ready output.
//!
//! # Layers
//!
//! - [`Drawing`] (this file): paths in mm, in the *bed frame* (x right, y up, (0, 0) at the
//!   bed's front-left corner). A [`Path`] is an open or closed polyline, or a circular arc (a
//!   full circle when its sweep is ±2π). [`from_fill`] builds one from a
//!   [`crate::model::doc::FillDoc`]: circles as full circles, rings as two circles, polygons
//!   as closed polylines (their tested vertices); in a periodic fill every image that shows
//!   in the tile is clipped exactly to the tile rectangle (circles into arcs, polygons into
//!   open polylines). [`Placement`] scales and moves a drawing onto a bed or a page.
//! - [`hatch`]: hatch lines clipped exactly to each shape (rings only in the annulus).
//! - [`order`](crate::output::order): pen-up travel reduction (nearest neighbour through a k-d tree, then 2-opt).
//! - [`machine`]: machine profiles as TOML data; the built-ins are embedded.
//! - [`gcode`]: the writer, with its safety invariants.
//!
//! # Reuse from other modes
//!
//! Any mode that produces lines can write G-code the same way `zetafill fill` does:
//!
//! ```no_run
//! use zetafill_cli::model::{Drawing, Path};
//! use zetafill_cli::output::{gcode, machine::Machine};
//! let drawing = Drawing { paths: vec![Path::polyline(vec![[10.0, 10.0], [50.0, 10.0]], false)] };
//! let machine = Machine::builtin("grbl-servo-pen").expect("built-in");
//! let opts = gcode::GcodeOptions::new(&machine);
//! let out = gcode::write(&drawing, &machine, &opts).expect("fits the bed");
//! std::fs::write("out.gcode", &out.bytes).expect("written");
//! eprintln!("{}", out.figures);
//! ```
//!
//! A mode with clap arguments can `#[command(flatten)]` [`PlotArgs`] and call
//! [`drawing_gcode`], which adds placement on the bed (`--fit`, `--center`, `--margin`) and
//! every other flag, exactly as `zetafill fill` does.
//!
//! [`gcode::write`] checks that the drawing lies inside the bed, orders the paths (unless told
//! not to), and writes text whose every coordinate is inside the bed, with the tool off for
//! every rapid move and at the end, a feed before the first cutting move, and plain
//! fixed-precision numbers. Nothing here prints or touches files except through the caller.
//!
//! Everything is deterministic: the same drawing and options give the same bytes.

pub mod doc;

use crate::error::CliError;
use crate::model::doc::{FillDoc, RegionDoc, ShapeDoc};
use crate::output::svg::{Style, SvgOptions};
use crate::output::{gcode, hatch, machine};
use clap::{Args, ValueEnum};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// A point in mm.
pub type Pt = [f64; 2];

/// One stroke of the pen or beam, in mm.
#[derive(Debug, Clone, PartialEq)]
pub enum Path {
    /// Straight segments through `points`; `closed` adds the segment back to the first point.
    Polyline {
        /// The vertices.
        points: Vec<Pt>,
        /// Whether the last point joins the first.
        closed: bool,
    },
    /// A circular arc from angle `start` (radians, counter-clockwise from +x) over `sweep`
    /// (positive counter-clockwise, negative clockwise); `|sweep| >= 2π` is a full circle.
    Arc {
        /// Centre.
        center: Pt,
        /// Radius (> 0).
        radius: f64,
        /// Start angle.
        start: f64,
        /// Signed sweep.
        sweep: f64,
    },
}

/// An axis-aligned box (min x, min y, max x, max y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Minimum x.
    pub x0: f64,
    /// Minimum y.
    pub y0: f64,
    /// Maximum x.
    pub x1: f64,
    /// Maximum y.
    pub y1: f64,
}

impl Bounds {
    /// The empty box (adding any point makes it that point).
    pub const EMPTY: Bounds = Bounds {
        x0: f64::INFINITY,
        y0: f64::INFINITY,
        x1: f64::NEG_INFINITY,
        y1: f64::NEG_INFINITY,
    };

    /// Grows the box to hold `p`.
    pub fn add(&mut self, p: Pt) {
        self.x0 = self.x0.min(p[0]);
        self.y0 = self.y0.min(p[1]);
        self.x1 = self.x1.max(p[0]);
        self.y1 = self.y1.max(p[1]);
    }

    /// Whether nothing was added.
    pub fn is_empty(&self) -> bool {
        self.x0 > self.x1
    }

    /// Width.
    pub fn width(&self) -> f64 {
        self.x1 - self.x0
    }

    /// Height.
    pub fn height(&self) -> f64 {
        self.y1 - self.y0
    }

    /// Whether this box lies inside `outer`, allowing `eps` mm of rounding.
    pub fn inside(&self, outer: &Bounds, eps: f64) -> bool {
        self.is_empty()
            || (self.x0 >= outer.x0 - eps && self.y0 >= outer.y0 - eps && self.x1 <= outer.x1 + eps && self.y1 <= outer.y1 + eps)
    }
}

fn dist(a: Pt, b: Pt) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

impl Path {
    /// A polyline.
    pub fn polyline(points: Vec<Pt>, closed: bool) -> Path {
        Path::Polyline { points, closed }
    }

    /// A full circle drawn counter-clockwise from angle 0.
    pub fn circle(center: Pt, radius: f64) -> Path {
        Path::Arc {
            center,
            radius,
            start: 0.0,
            sweep: TAU,
        }
    }

    /// Whether the path ends where it starts (and may start anywhere on it).
    pub fn is_closed(&self) -> bool {
        match self {
            Path::Polyline { closed, .. } => *closed,
            Path::Arc { sweep, .. } => sweep.abs() >= TAU,
        }
    }

    /// Where the pen goes down.
    pub fn start_point(&self) -> Pt {
        match self {
            Path::Polyline { points, .. } => points.first().copied().unwrap_or([0.0, 0.0]),
            Path::Arc { center, radius, start, .. } => polar(*center, *radius, *start),
        }
    }

    /// Where the pen comes up.
    pub fn end_point(&self) -> Pt {
        match self {
            Path::Polyline { points, closed } => {
                if *closed {
                    points.first().copied().unwrap_or([0.0, 0.0])
                } else {
                    points.last().copied().unwrap_or([0.0, 0.0])
                }
            }
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                if sweep.abs() >= TAU {
                    polar(*center, *radius, *start)
                } else {
                    polar(*center, *radius, start + sweep)
                }
            }
        }
    }

    /// Pen-down length in mm.
    pub fn length(&self) -> f64 {
        match self {
            Path::Polyline { points, closed } => {
                let open: f64 = points.windows(2).map(|w| dist(w[0], w[1])).sum();
                match (closed, points.first(), points.last()) {
                    (true, Some(a), Some(b)) if points.len() > 2 => open + dist(*a, *b),
                    _ => open,
                }
            }
            Path::Arc { radius, sweep, .. } => radius * sweep.abs().min(TAU),
        }
    }

    /// The exact bounding box (arcs: their end points and every axis extreme they pass).
    pub fn bounds(&self) -> Bounds {
        let mut b = Bounds::EMPTY;
        match self {
            Path::Polyline { points, .. } => points.iter().for_each(|p| b.add(*p)),
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                b.add(self.start_point());
                b.add(self.end_point());
                for a in arc_extremes(*start, *sweep) {
                    b.add(polar(*center, *radius, a));
                }
            }
        }
        b
    }

    /// The same stroke drawn the other way.
    pub fn reversed(&self) -> Path {
        match self {
            Path::Polyline { points, closed } => {
                let mut p = points.clone();
                if *closed && p.len() > 1 {
                    // Keep the start point: reverse the cycle after it.
                    p[1..].reverse();
                } else {
                    p.reverse();
                }
                Path::Polyline {
                    points: p,
                    closed: *closed,
                }
            }
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                if sweep.abs() >= TAU {
                    Path::Arc {
                        center: *center,
                        radius: *radius,
                        start: *start,
                        sweep: -sweep,
                    }
                } else {
                    Path::Arc {
                        center: *center,
                        radius: *radius,
                        start: start + sweep,
                        sweep: -sweep,
                    }
                }
            }
        }
    }

    /// Applies `p -> (s x + dx, sy y + dy)` where `sy = ±s` (a negative `sy` mirrors y and
    /// turns arcs the other way).
    pub fn transformed(&self, s: f64, sy: f64, dx: f64, dy: f64) -> Path {
        let f = |p: &Pt| [s * p[0] + dx, sy * p[1] + dy];
        match self {
            Path::Polyline { points, closed } => Path::Polyline {
                points: points.iter().map(f).collect(),
                closed: *closed,
            },
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => {
                let (start, sweep) = if sy < 0.0 { (-start, -sweep) } else { (*start, *sweep) };
                Path::Arc {
                    center: f(center),
                    radius: radius * s,
                    start,
                    sweep,
                }
            }
        }
    }
}

/// The point at angle `a` on the circle.
pub fn polar(c: Pt, r: f64, a: f64) -> Pt {
    [c[0] + r * a.cos(), c[1] + r * a.sin()]
}

/// The multiples of π/2 strictly inside an arc's sweep (where x or y is extreme).
pub fn arc_extremes(start: f64, sweep: f64) -> Vec<f64> {
    if sweep.abs() >= TAU {
        return vec![0.0, FRAC_PI_2, PI, 3.0 * FRAC_PI_2];
    }
    let (lo, hi) = if sweep >= 0.0 {
        (start, start + sweep)
    } else {
        (start + sweep, start)
    };
    let k0 = (lo / FRAC_PI_2).ceil() as i64;
    let k1 = (hi / FRAC_PI_2).floor() as i64;
    (k0..=k1).map(|k| k as f64 * FRAC_PI_2).collect()
}

/// Everything a pen or beam draws, in mm in the bed frame.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Drawing {
    /// The strokes, in drawing order.
    pub paths: Vec<Path>,
}

impl Drawing {
    /// The bounding box of every path.
    pub fn bounds(&self) -> Bounds {
        let mut b = Bounds::EMPTY;
        for p in &self.paths {
            let q = p.bounds();
            if !q.is_empty() {
                b.add([q.x0, q.y0]);
                b.add([q.x1, q.y1]);
            }
        }
        b
    }

    /// Total pen-down length in mm.
    pub fn pen_down_length(&self) -> f64 {
        self.paths.iter().map(Path::length).sum()
    }

    /// Pen-up travel in mm from `home` through every path in order (not back home).
    pub fn travel_from(&self, home: Pt) -> f64 {
        let mut at = home;
        let mut t = 0.0;
        for p in &self.paths {
            t += dist(at, p.start_point());
            at = p.end_point();
        }
        t
    }

    /// The drawing under `p -> placement.apply(p)`.
    pub fn placed(&self, pl: &Placement) -> Drawing {
        Drawing {
            paths: self.paths.iter().map(|p| p.transformed(pl.scale, pl.scale, pl.dx, pl.dy)).collect(),
        }
    }
}

/// A uniform scale then a shift: `p -> scale * p + (dx, dy)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Scale factor (1 unless fitted).
    pub scale: f64,
    /// Shift in x.
    pub dx: f64,
    /// Shift in y.
    pub dy: f64,
}

impl Placement {
    /// No change.
    pub const IDENTITY: Placement = Placement {
        scale: 1.0,
        dx: 0.0,
        dy: 0.0,
    };

    /// Applies the placement to a point.
    pub fn apply(&self, p: Pt) -> Pt {
        [self.scale * p[0] + self.dx, self.scale * p[1] + self.dy]
    }
}

/// How a drawing is put into an area (a bed or a page, less its margins).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fit {
    /// Where it is (a bed: the region's own coordinates).
    AsIs,
    /// Its bounding box's top-left corner at the area's top-left corner (pages).
    TopLeft,
    /// Centred, unscaled.
    Center,
    /// Scaled (up or down) to the largest size that fits, centred.
    Scale,
}

/// Places `drawing` (its bounding box `b`) into `area`, or says why it does not fit.
pub fn place(b: &Bounds, area: &Bounds, fit: Fit) -> Result<Placement, String> {
    if b.is_empty() {
        return Ok(Placement::IDENTITY);
    }
    let pl = match fit {
        Fit::AsIs => Placement::IDENTITY,
        Fit::TopLeft => Placement {
            scale: 1.0,
            dx: area.x0 - b.x0,
            dy: area.y1 - b.y1,
        },
        Fit::Center => Placement {
            scale: 1.0,
            dx: (area.x0 + area.x1 - b.x0 - b.x1) / 2.0,
            dy: (area.y0 + area.y1 - b.y0 - b.y1) / 2.0,
        },
        Fit::Scale => {
            let sx = if b.width() > 0.0 { area.width() / b.width() } else { f64::INFINITY };
            let sy = if b.height() > 0.0 {
                area.height() / b.height()
            } else {
                f64::INFINITY
            };
            let s = sx.min(sy);
            if !(s.is_finite() && s > 0.0) {
                return Err("the drawing has no extent to scale".into());
            }
            Placement {
                scale: s,
                dx: (area.x0 + area.x1) / 2.0 - s * (b.x0 + b.x1) / 2.0,
                dy: (area.y0 + area.y1) / 2.0 - s * (b.y0 + b.y1) / 2.0,
            }
        }
    };
    let placed = Bounds {
        x0: pl.apply([b.x0, b.y0])[0],
        y0: pl.apply([b.x0, b.y0])[1],
        x1: pl.apply([b.x1, b.y1])[0],
        y1: pl.apply([b.x1, b.y1])[1],
    };
    if !placed.inside(area, 1e-6) {
        return Err(format!(
            "the drawing ({:.3} x {:.3} mm at {:.3}, {:.3}) does not fit the usable area ({:.3} x {:.3} mm at {:.3}, {:.3})",
            placed.width(),
            placed.height(),
            placed.x0,
            placed.y0,
            area.width(),
            area.height(),
            area.x0,
            area.y0
        ));
    }
    Ok(pl)
}

// -------------------------------------------------------------------------------------------
// From a fill

/// What goes into a drawing besides the outlines.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct BuildOptions {
    /// Leave out shapes (and ring holes) narrower than this (mm).
    pub min_feature: f64,
    /// Hatch every shape.
    pub hatch: Option<hatch::Hatch>,
    /// Draw the outlines (false: hatch only).
    pub no_outline: bool,
}

/// The width of a shape: diameter for circles and rings, the smallest caliper width of the
/// convex hull of a polygon's vertices.
pub fn shape_width(sh: &ShapeDoc) -> f64 {
    if let Some(r) = sh.radius {
        return 2.0 * r;
    }
    let vs = sh.vertices.as_deref().unwrap_or(&[]);
    polygon_width(vs)
}

/// Smallest caliper width of a polygon (over the directions of its edges; exact for convex
/// polygons, the hull's width otherwise up to the edge directions).
pub fn polygon_width(vs: &[Pt]) -> f64 {
    let n = vs.len();
    if n < 3 {
        return 0.0;
    }
    let mut best = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (vs[i], vs[(i + 1) % n]);
        let len = dist(a, b);
        if len == 0.0 {
            continue;
        }
        let (nx, ny) = ((b[1] - a[1]) / len, (a[0] - b[0]) / len);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in vs {
            let d = (v[0] - a[0]) * nx + (v[1] - a[1]) * ny;
            lo = lo.min(d);
            hi = hi.max(d);
        }
        best = best.min(hi - lo);
    }
    best
}

/// The (dx, dy) shifts of a shape's images whose bounding boxes meet the `w` x `h` tile:
/// the shape itself first.
pub fn periodic_images(b: &Bounds, w: f64, h: f64) -> Vec<(f64, f64)> {
    let shifts = |lo: f64, hi: f64, p: f64| -> Vec<f64> {
        let k0 = (-hi / p).floor() as i64;
        let k1 = ((p - lo) / p).ceil() as i64;
        let mut ks: Vec<i64> = (k0..=k1).collect();
        ks.sort_by_key(|k| (k.abs(), -k));
        ks.into_iter()
            .map(|k| k as f64 * p)
            .filter(|&d| hi + d > 0.0 && lo + d < p)
            .collect()
    };
    let (xs, ys) = (shifts(b.x0, b.x1, w), shifts(b.y0, b.y1, h));
    ys.iter().flat_map(|&dy| xs.iter().map(move |&dx| (dx, dy))).collect()
}

/// The outline paths of one shape (shifted by `off`).
fn shape_outlines(sh: &ShapeDoc, off: (f64, f64), min_feature: f64) -> Vec<Path> {
    let c = [sh.center[0] + off.0, sh.center[1] + off.1];
    match (sh.radius, sh.inner_radius) {
        (Some(r), inner) => {
            let mut v = vec![Path::circle(c, r)];
            if let Some(ri) = inner {
                if ri > 0.0 && 2.0 * ri >= min_feature {
                    v.push(Path::circle(c, ri));
                }
            }
            v
        }
        _ => {
            let vs = sh.vertices.as_deref().unwrap_or(&[]);
            if vs.len() < 2 {
                return vec![];
            }
            vec![Path::polyline(vs.iter().map(|v| [v[0] + off.0, v[1] + off.1]).collect(), true)]
        }
    }
}

/// The bounding box of a shape (its outer outline).
pub fn shape_bounds(sh: &ShapeDoc) -> Bounds {
    let mut b = Bounds::EMPTY;
    if let Some(r) = sh.radius {
        b.add([sh.center[0] - r, sh.center[1] - r]);
        b.add([sh.center[0] + r, sh.center[1] + r]);
    } else {
        for v in sh.vertices.as_deref().unwrap_or(&[]) {
            b.add(*v);
        }
    }
    b
}

/// The drawing of a fill in the region's frame: outlines (and hatching), shapes narrower
/// than `min_feature` left out; periodic fills clipped exactly to the tile.
pub fn from_fill(doc: &FillDoc, opt: &BuildOptions) -> Drawing {
    let tile = match doc.region {
        RegionDoc::Rect {
            width,
            height,
            periodic: true,
        } => Some(Bounds {
            x0: 0.0,
            y0: 0.0,
            x1: width,
            y1: height,
        }),
        _ => None,
    };
    let mut paths = Vec::new();
    for sh in &doc.shapes {
        if shape_width(sh) < opt.min_feature {
            continue;
        }
        let sb = shape_bounds(sh);
        let offs = match &tile {
            Some(t) => periodic_images(&sb, t.x1, t.y1),
            None => vec![(0.0, 0.0)],
        };
        for off in offs {
            let mut here = Vec::new();
            if !opt.no_outline {
                here.extend(shape_outlines(sh, off, opt.min_feature));
            }
            if let Some(h) = &opt.hatch {
                here.extend(
                    h.shape(sh, off, opt.min_feature)
                        .into_iter()
                        .map(|[a, b]| Path::polyline(vec![a, b], false)),
                );
            }
            match &tile {
                Some(t) => {
                    let inside = Bounds {
                        x0: sb.x0 + off.0,
                        y0: sb.y0 + off.1,
                        x1: sb.x1 + off.0,
                        y1: sb.y1 + off.1,
                    }
                    .inside(t, 0.0);
                    if inside {
                        paths.extend(here);
                    } else {
                        paths.extend(here.iter().flat_map(|p| clip_path(p, t)));
                    }
                }
                None => paths.extend(here),
            }
        }
    }
    Drawing { paths }
}

// -------------------------------------------------------------------------------------------
// Exact clipping to a rectangle

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

// -------------------------------------------------------------------------------------------
// Command-line flags

/// Path order before writing G-code.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OrderArg {
    /// Placement order, as the shapes were placed.
    None,
    /// Greedy nearest neighbour (with reversal and closed-path start choice).
    Greedy,
    /// Greedy, then 2-opt improvement.
    Improved,
}

/// A page for plotter SVG.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Page {
    /// Width in mm.
    pub width: f64,
    /// Height in mm.
    pub height: f64,
}

/// Parses `--page`: `a4`, `a3`, `letter` (portrait; add `-landscape`), or `WxH` in mm.
pub fn parse_page(s: &str) -> Result<Page, String> {
    let lower = s.to_ascii_lowercase();
    let (name, landscape) = match lower.strip_suffix("-landscape") {
        Some(n) => (n, true),
        None => (lower.as_str(), false),
    };
    let (w, h) = match name {
        "a4" => (210.0, 297.0),
        "a3" => (297.0, 420.0),
        "a5" => (148.0, 210.0),
        "letter" => (215.9, 279.4),
        other => {
            let (a, b) = other
                .split_once('x')
                .ok_or_else(|| format!("'{s}' is not a4, a3, a5, letter or WxH in mm (for example 300x200)"))?;
            let num = |t: &str| {
                t.trim_end_matches("mm")
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite() && *v > 0.0 && *v <= 100_000.0)
            };
            match (num(a), num(b)) {
                (Some(w), Some(h)) => (w, h),
                _ => {
                    return Err(format!(
                        "'{s}': page width and height must be positive numbers of mm, as in 300x200"
                    ))
                }
            }
        }
    };
    Ok(if landscape {
        Page { width: h, height: w }
    } else {
        Page { width: w, height: h }
    })
}

/// `--layers`: none, `size-bands:K` or `colours`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layers {
    /// One group.
    None,
    /// K Inkscape layers by shape size, largest first.
    SizeBands(u32),
    /// One Inkscape layer per `--palette` colour (one pen each), in the palette's order.
    Colours,
}

/// Parses `--layers`.
pub fn parse_layers(s: &str) -> Result<Layers, String> {
    if s == "none" {
        return Ok(Layers::None);
    }
    if s == "colours" || s == "colors" {
        return Ok(Layers::Colours);
    }
    match s.strip_prefix("size-bands:").map(str::parse::<u32>) {
        Some(Ok(k)) if (1..=64).contains(&k) => Ok(Layers::SizeBands(k)),
        _ => Err(format!("'{s}' is not none, size-bands:K with K from 1 to 64, or colours")),
    }
}

fn positive(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("'{s}' must be a positive number")),
    }
}

fn non_negative(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        _ => Err(format!("'{s}' must be a number >= 0")),
    }
}

fn finite(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("'{s}' must be a finite number")),
    }
}

/// The plotter and laser flags of `zetafill fill` (and of any mode that draws lines).
#[derive(Debug, Clone, Args)]
pub struct PlotArgs {
    /// G-code: machine profile, a built-in name (see `zetafill machines`) or a FILE.toml
    /// [default: grbl-servo-pen].
    #[arg(long, help_heading = "Plotters and lasers")]
    pub machine: Option<String>,
    /// G-code: drawing feed in mm/min (default: the profile's).
    #[arg(long, value_parser = finite, allow_negative_numbers = true, help_heading = "Plotters and lasers")]
    pub feed: Option<f64>,
    /// G-code: travel feed in mm/min (G1 travel, and the time estimate of G0 travel).
    #[arg(long = "travel-feed", value_parser = finite, allow_negative_numbers = true, help_heading = "Plotters and lasers")]
    pub travel_feed: Option<f64>,
    /// G-code: laser power (S value) within the profile's range.
    #[arg(long, value_parser = finite, allow_negative_numbers = true, help_heading = "Plotters and lasers")]
    pub power: Option<f64>,
    /// G-code: draw everything this many times (laser cutting) [default: 1].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100), help_heading = "Plotters and lasers")]
    pub passes: Option<u32>,
    /// G-code: circles as G2/G3 arcs (default: if the profile allows them).
    #[arg(long, conflicts_with = "no_arcs", help_heading = "Plotters and lasers")]
    pub arcs: bool,
    /// G-code: circles as polylines within --chord-tolerance.
    #[arg(long = "no-arcs", help_heading = "Plotters and lasers")]
    pub no_arcs: bool,
    /// G-code: largest distance between a circle and the chords that replace it (mm)
    /// [default: 0.01].
    #[arg(long = "chord-tolerance", value_parser = positive, help_heading = "Plotters and lasers")]
    pub chord_tolerance: Option<f64>,
    /// Hatch every shape: SPACING or SPACING:ANGLE, in mm and degrees (default angle 45).
    #[arg(long, allow_hyphen_values = true, help_heading = "Plotters and lasers")]
    pub hatch: Option<String>,
    /// With --hatch: hatch lines only, no outlines.
    #[arg(long = "hatch-only", requires = "hatch", help_heading = "Plotters and lasers")]
    pub hatch_only: bool,
    /// With --hatch: cross-hatch, a second family of lines at right angles to the first.
    #[arg(long = "cross-hatch", requires = "hatch", help_heading = "Plotters and lasers")]
    pub cross_hatch: bool,
    /// G-code: path order [default: improved].
    #[arg(long, value_enum, help_heading = "Plotters and lasers")]
    pub order: Option<OrderArg>,
    /// Leave out shapes (and ring holes) narrower than MM: the pen's or beam's width.
    #[arg(long = "min-feature", default_value_t = 0.0, value_parser = non_negative, allow_negative_numbers = true, help_heading = "Plotters and lasers")]
    pub min_feature: f64,
    /// Scale the drawing to fill the bed (G-code) or the page (SVG) less margins, centred.
    #[arg(long, help_heading = "Plotters and lasers")]
    pub fit: bool,
    /// Centre the drawing on the bed (G-code) or the page (SVG).
    #[arg(long, help_heading = "Plotters and lasers")]
    pub center: bool,
    /// SVG: page a4 | a3 | a5 | letter (portrait; add -landscape) | WxH in mm.
    #[arg(long, value_parser = parse_page, help_heading = "Plotters and lasers")]
    pub page: Option<Page>,
    /// Margin in mm: SVG pages (default 10), G-code bed (default 0).
    #[arg(long, value_parser = non_negative, allow_negative_numbers = true, help_heading = "Plotters and lasers")]
    pub margin: Option<f64>,
    /// SVG: none | size-bands:K (K Inkscape layers by shape size, largest first) | colours
    /// (one layer per --palette colour, a pen each).
    #[arg(long, default_value = "none", value_parser = parse_layers, help_heading = "Plotters and lasers")]
    pub layers: Layers,
}

/// The machine profile used when `--machine` is not given.
pub const DEFAULT_MACHINE: &str = "grbl-servo-pen";

/// The plot flags that only G-code output reads.
pub const GCODE_FLAGS: [&str; 9] = [
    "--machine",
    "--feed",
    "--travel-feed",
    "--power",
    "--passes",
    "--arcs",
    "--no-arcs",
    "--chord-tolerance",
    "--order",
];

/// The plot flags that a fill's SVG (and PNG) reads.
pub const SVG_FLAGS: [&str; 9] = [
    "--hatch",
    "--hatch-only",
    "--cross-hatch",
    "--min-feature",
    "--page",
    "--margin",
    "--layers",
    "--fit",
    "--center",
];

/// What to write instead, for a flag that only G-code output reads.
pub const FOR_GCODE: &str = "is for G-code output (write .gcode or .nc, or give --format gcode)";

impl PlotArgs {
    /// The plot flags given on the command line, in the order of `--help`. (`--min-feature 0`
    /// and `--layers none` change nothing and do not count.)
    pub fn given(&self) -> Vec<&'static str> {
        let flags = [
            ("--machine", self.machine.is_some()),
            ("--feed", self.feed.is_some()),
            ("--travel-feed", self.travel_feed.is_some()),
            ("--power", self.power.is_some()),
            ("--passes", self.passes.is_some()),
            ("--arcs", self.arcs),
            ("--no-arcs", self.no_arcs),
            ("--chord-tolerance", self.chord_tolerance.is_some()),
            ("--hatch", self.hatch.is_some()),
            ("--hatch-only", self.hatch_only),
            ("--cross-hatch", self.cross_hatch),
            ("--order", self.order.is_some()),
            ("--min-feature", self.min_feature > 0.0),
            ("--fit", self.fit),
            ("--center", self.center),
            ("--page", self.page.is_some()),
            ("--margin", self.margin.is_some()),
            ("--layers", self.layers != Layers::None),
        ];
        flags.into_iter().filter(|&(_, on)| on).map(|(f, _)| f).collect()
    }

    /// Refuses the first plot flag given that is not in `allowed` (exit 2), with the flag
    /// named and `why` (given the flag) as the reason.
    pub fn refuse_except(&self, allowed: &[&str], why: impl Fn(&str) -> String) -> Result<(), CliError> {
        match self.given().into_iter().find(|f| !allowed.contains(f)) {
            Some(f) => Err(CliError::arg(f, why(f))),
            None => Ok(()),
        }
    }

    /// The checks of G-code output common to every command that writes it: the profile
    /// loads and every override fits it; pages and layers are refused (they are for SVG).
    pub fn check_gcode(&self) -> Result<(), CliError> {
        let m = self.machine()?;
        self.gcode_options(&m)?;
        if self.page.is_some() {
            return Err(CliError::arg("--page", "pages are for SVG; G-code uses the machine's bed"));
        }
        if let Layers::SizeBands(_) = self.layers {
            return Err(CliError::arg(
                "--layers",
                "size bands are SVG layers (one pen per layer); in G-code, --layers colours draws one pen after another",
            ));
        }
        Ok(())
    }

    /// The hatch, if asked for (exit 2 naming --hatch when malformed).
    pub fn hatch(&self) -> Result<Option<hatch::Hatch>, CliError> {
        self.hatch
            .as_deref()
            .map(hatch::Hatch::parse)
            .transpose()
            .map(|h| {
                h.map(|h| hatch::Hatch {
                    cross: self.cross_hatch,
                    ..h
                })
            })
            .map_err(|e| CliError::arg("--hatch", e))
    }

    /// The drawing options.
    pub fn build_options(&self) -> Result<BuildOptions, CliError> {
        Ok(BuildOptions {
            min_feature: self.min_feature,
            hatch: self.hatch()?,
            no_outline: self.hatch_only,
        })
    }

    /// How the drawing is placed: as it is, centred, or scaled.
    fn fit(&self, default: Fit) -> Fit {
        if self.fit {
            Fit::Scale
        } else if self.center {
            Fit::Center
        } else {
            default
        }
    }

    /// The flags of this group that were given, as command-line text (each with a leading
    /// space), so that a file's header can say how to make it again.
    pub fn flags(&self) -> String {
        let text = |v: f64| Some(v.to_string());
        let order = self
            .order
            .and_then(|o| clap::ValueEnum::to_possible_value(&o).map(|v| v.get_name().to_string()));
        let layers = match self.layers {
            Layers::SizeBands(k) => Some(format!("size-bands:{k}")),
            Layers::Colours => Some("colours".to_string()),
            Layers::None => None,
        };
        // (flag, given, value)
        let all: [(&str, bool, Option<String>); 18] = [
            ("machine", self.machine.is_some(), self.machine.clone()),
            ("feed", self.feed.is_some(), self.feed.and_then(text)),
            ("travel-feed", self.travel_feed.is_some(), self.travel_feed.and_then(text)),
            ("power", self.power.is_some(), self.power.and_then(text)),
            ("passes", self.passes.is_some(), self.passes.map(|p| p.to_string())),
            ("arcs", self.arcs, None),
            ("no-arcs", self.no_arcs, None),
            (
                "chord-tolerance",
                self.chord_tolerance.is_some(),
                self.chord_tolerance.and_then(text),
            ),
            ("hatch", self.hatch.is_some(), self.hatch.clone()),
            ("hatch-only", self.hatch_only, None),
            ("cross-hatch", self.cross_hatch, None),
            ("order", order.is_some(), order),
            ("min-feature", self.min_feature > 0.0, text(self.min_feature)),
            ("fit", self.fit, None),
            ("center", self.center, None),
            ("page", self.page.is_some(), self.page.map(|p| format!("{}x{}", p.width, p.height))),
            ("margin", self.margin.is_some(), self.margin.and_then(text)),
            ("layers", layers.is_some(), layers),
        ];
        all.into_iter()
            .filter(|(_, given, _)| *given)
            .map(|(flag, _, value)| value.map_or_else(|| format!(" --{flag}"), |v| format!(" --{flag} {v}")))
            .collect()
    }

    /// The profile file `--machine` names, if it names one rather than a built-in: an
    /// input, which no output may overwrite.
    pub fn machine_file(&self) -> Option<&std::path::Path> {
        let m = self.machine.as_deref()?;
        machine::Machine::builtin_text(m).is_none().then(|| std::path::Path::new(m))
    }

    /// The machine with every command-line override applied and checked.
    pub fn machine(&self) -> Result<machine::Machine, CliError> {
        machine::Machine::load(self.machine.as_deref().unwrap_or(DEFAULT_MACHINE)).map_err(|e| CliError::arg("--machine", e))
    }

    /// The G-code options for `m`, every override checked against the profile.
    pub fn gcode_options(&self, m: &machine::Machine) -> Result<gcode::GcodeOptions, CliError> {
        let mut o = gcode::GcodeOptions::new(m);
        if let Some(f) = self.feed {
            if f <= 0.0 {
                return Err(CliError::arg("--feed", format!("{f} mm/min: a feed must be positive")));
            }
            o.feed = f;
        }
        if let Some(f) = self.travel_feed {
            if f <= 0.0 {
                return Err(CliError::arg("--travel-feed", format!("{f} mm/min: a feed must be positive")));
            }
            o.travel_feed = f;
        }
        if let Some(p) = self.power {
            let Some(range) = &m.power else {
                return Err(CliError::arg(
                    "--power",
                    format!("the profile '{}' has no power range (it is not a laser); drop --power", m.name),
                ));
            };
            if p < range.min || p > range.max {
                return Err(CliError::arg(
                    "--power",
                    format!("{p} is outside the profile's range {} to {}", range.min, range.max),
                ));
            }
            o.power = Some(p);
        }
        o.passes = self.passes.unwrap_or(1);
        o.arcs = if self.arcs {
            if !m.arcs {
                return Err(CliError::arg(
                    "--arcs",
                    format!("the profile '{}' does not allow arcs (arcs = false)", m.name),
                ));
            }
            true
        } else if self.no_arcs {
            false
        } else {
            m.arcs
        };
        o.chord_tolerance = self.chord_tolerance.unwrap_or(o.chord_tolerance);
        o.order = self.order.unwrap_or(o.order);
        o.margin = self.margin.unwrap_or(0.0);
        let short = m.bed.width.min(m.bed.height);
        if 2.0 * o.margin >= short {
            return Err(CliError::arg(
                "--margin",
                format!(
                    "{} mm leaves no usable area on the {} x {} mm bed of '{}'; it must be under {} mm (half the bed's shorter side)",
                    o.margin,
                    m.bed.width,
                    m.bed.height,
                    m.name,
                    short / 2.0
                ),
            ));
        }
        Ok(o)
    }

    /// Checks every flag that can be checked before the fill runs, for `format`: each plot
    /// flag given must be one that `format` reads.
    pub fn check(&self, format: crate::output::Format) -> Result<(), CliError> {
        use crate::output::Format;
        self.build_options()?;
        match format {
            Format::Gcode => self.check_gcode()?,
            Format::Svg | Format::Png => {
                self.refuse_except(&SVG_FLAGS, |_| FOR_GCODE.to_string())?;
                if (self.fit || self.center || self.margin.is_some()) && self.page.is_none() {
                    let flag = if self.fit {
                        "--fit"
                    } else if self.center {
                        "--center"
                    } else {
                        "--margin"
                    };
                    return Err(CliError::arg(
                        flag,
                        "for SVG it needs --page (without a page the drawing is the region itself)",
                    ));
                }
            }
            other => {
                let name = clap::ValueEnum::to_possible_value(&other).map_or_else(String::new, |v| v.get_name().to_string());
                self.refuse_except(&[], |_| format!("is for drawings (svg, png, gcode), not {name} output"))?
            }
        }
        Ok(())
    }

    /// SVG options from the fill's flags and these: page layout and layers.
    pub fn svg_options(&self, doc: &FillDoc, style: Style, pen_width: f64, boundary: bool) -> Result<SvgOptions, CliError> {
        let mut o = SvgOptions {
            style,
            pen_width,
            boundary,
            page: None,
            layers: None,
            build: self.build_options()?,
            flags: format!(
                " --style {}{}{}{}",
                clap::ValueEnum::to_possible_value(&style).map_or_else(String::new, |v| v.get_name().to_string()),
                if pen_width == 0.3 {
                    String::new()
                } else {
                    format!(" --pen-width {pen_width}")
                },
                if boundary { " --boundary" } else { "" },
                self.flags()
            ),
            colours: None,
            background: None,
            colour_layers: None,
        };
        if let Layers::SizeBands(k) = self.layers {
            o.layers = Some(k);
        }
        if let Some(page) = self.page {
            let m = self.margin.unwrap_or(10.0);
            if 2.0 * m >= page.width.min(page.height) {
                return Err(CliError::arg(
                    "--margin",
                    format!("{m} mm leaves no room on a {} x {} mm page", page.width, page.height),
                ));
            }
            let (x0, y0, x1, y1) = doc.bbox();
            // The page frame here has y up from the page's bottom edge.
            let area = Bounds {
                x0: m,
                y0: m,
                x1: page.width - m,
                y1: page.height - m,
            };
            let pl = place(&Bounds { x0, y0, x1, y1 }, &area, self.fit(Fit::TopLeft)).map_err(|e| {
                CliError::arg(
                    "--page",
                    format!("{e}; use --fit to scale it, or a larger --page or smaller --margin"),
                )
            })?;
            o.page = Some(crate::output::svg::PageLayout {
                width: page.width,
                height: page.height,
                scale: pl.scale,
                dx: pl.dx,
                dy: pl.dy,
            });
        }
        Ok(o)
    }
}

/// `--format gcode` of a fill: its drawing (outlines, hatching) placed on the bed by the
/// region's box.
pub fn render_gcode(doc: &FillDoc, a: &PlotArgs, quiet: bool) -> Result<Vec<u8>, CliError> {
    render_gcode_pens(doc, a, None, quiet)
}

/// [`render_gcode`], with `pens` (each shape's colour, the palette, and the colour flags for
/// the header): the shapes of each palette colour drawn as one pen, in the palette's order.
pub fn render_gcode_pens(
    doc: &FillDoc,
    a: &PlotArgs,
    pens: Option<(&[crate::output::palette::Colour], &[crate::output::palette::Colour], String)>,
    quiet: bool,
) -> Result<Vec<u8>, CliError> {
    let build = a.build_options()?;
    let (x0, y0, x1, y1) = doc.bbox();
    let mut header = format!("{}{}", crate::output::svg::command_line(doc), a.flags());
    let layers: Vec<(String, Drawing)> = match pens {
        None => vec![(String::new(), from_fill(doc, &build))],
        Some((colours, palette, flags)) => {
            header.push_str(&flags);
            palette
                .iter()
                .map(|c| {
                    let mut part = doc.clone();
                    part.shapes = doc
                        .shapes
                        .iter()
                        .zip(colours)
                        .filter(|(_, k)| *k == c)
                        .map(|(s, _)| s.clone())
                        .collect();
                    (c.clone(), from_fill(&part, &build))
                })
                .collect()
        }
    };
    pens_gcode(&layers, &Bounds { x0, y0, x1, y1 }, a, vec![header], quiet)
}

/// G-code of any drawing with the plotter flags of `a` (machine, feeds, power, passes, arcs,
/// order, margin, `--fit`, `--center`): `frame` is the box placed on the bed (the region's,
/// so every seed lands in the same place), `header` the comment lines that say how the
/// drawing was made (command line, parameters, seed). The figures go to stderr unless
/// `quiet`. This is the entry point for other modes (`line`, `territory`, ...).
pub fn drawing_gcode(drawing: &Drawing, frame: &Bounds, a: &PlotArgs, header: Vec<String>, quiet: bool) -> Result<Vec<u8>, CliError> {
    pens_gcode(&[(String::new(), drawing.clone())], frame, a, header, quiet)
}

/// [`drawing_gcode`] for a drawing in several named pens, drawn one after the other with a
/// pen change between them (see [`gcode::write_pens`]), all placed on the bed as one.
pub fn pens_gcode(pens: &[(String, Drawing)], frame: &Bounds, a: &PlotArgs, header: Vec<String>, quiet: bool) -> Result<Vec<u8>, CliError> {
    let m = a.machine()?;
    let mut opts = a.gcode_options(&m)?;
    let area = m.usable_area(opts.margin);
    let pl = place(frame, &area, a.fit(Fit::AsIs)).map_err(|e| {
        CliError::arg(
            "--machine",
            format!(
                "{e} of the bed of '{}' ({} x {} mm, margin {} mm); use --fit to scale it or --center to move it",
                m.name, m.bed.width, m.bed.height, opts.margin
            ),
        )
    })?;
    let pens: Vec<(String, Drawing)> = pens.iter().map(|(n, d)| (n.clone(), d.placed(&pl))).collect();
    opts.header = header;
    opts.header.push(format!(
        "plot: machine {} order {:?} passes {} hatch {} min-feature {} scale {} shift {} {}",
        m.name,
        opts.order,
        opts.passes,
        match (a.hatch.as_deref(), a.cross_hatch) {
            (Some(h), true) => format!("{h} crossed"),
            (h, _) => h.unwrap_or("none").to_string(),
        },
        a.min_feature,
        pl.scale,
        pl.dx,
        pl.dy
    ));
    let out = gcode::write_pens(&pens, &m, &opts).map_err(|e| CliError::arg("--machine", e))?;
    if !quiet {
        eprintln!("{}", out.figures);
    }
    Ok(out.bytes)
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
    fn arc_bounds_see_the_extremes() {
        let p = Path::Arc {
            center: [0.0, 0.0],
            radius: 1.0,
            start: -0.1,
            sweep: 0.2,
        };
        let b = p.bounds();
        assert!((b.x1 - 1.0).abs() < 1e-15, "passes angle 0: {b:?}");
        let q = Path::Arc {
            center: [0.0, 0.0],
            radius: 1.0,
            start: 0.1,
            sweep: 0.2,
        };
        assert!(q.bounds().x1 < 1.0);
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

    #[test]
    fn placement_refuses_what_does_not_fit() {
        let b = Bounds {
            x0: 0.0,
            y0: 0.0,
            x1: 20.0,
            y1: 5.0,
        };
        assert!(place(&b, &unit(), Fit::AsIs).is_err());
        assert!(place(&b, &unit(), Fit::Center).is_err());
        let pl = place(&b, &unit(), Fit::Scale).unwrap_or(Placement::IDENTITY);
        assert_eq!(pl.scale, 0.5);
        assert_eq!(pl.apply([0.0, 0.0]), [0.0, 3.75]);
    }

    #[test]
    fn pages_and_layers_parse() {
        assert_eq!(
            parse_page("a4"),
            Ok(Page {
                width: 210.0,
                height: 297.0
            })
        );
        assert_eq!(
            parse_page("A4-landscape"),
            Ok(Page {
                width: 297.0,
                height: 210.0
            })
        );
        assert_eq!(
            parse_page("300x200"),
            Ok(Page {
                width: 300.0,
                height: 200.0
            })
        );
        assert!(parse_page("0x5").is_err());
        assert!(parse_page("b5").is_err());
        assert_eq!(parse_layers("size-bands:3"), Ok(Layers::SizeBands(3)));
        assert!(parse_layers("size-bands:0").is_err());
        assert_eq!(parse_layers("colours"), Ok(Layers::Colours));
        assert_eq!(parse_layers("colors"), Ok(Layers::Colours));
    }

    #[test]
    fn reversal_keeps_closed_starts_and_flips_arcs() {
        let p = Path::polyline(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], true);
        let r = p.reversed();
        assert_eq!(r.start_point(), [0.0, 0.0]);
        assert_eq!(r, Path::polyline(vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0]], true));
        let a = Path::Arc {
            center: [0.0, 0.0],
            radius: 1.0,
            start: 0.0,
            sweep: 1.0,
        };
        let ra = a.reversed();
        assert!(dist(ra.start_point(), a.end_point()) < 1e-15);
        assert!(dist(ra.end_point(), a.start_point()) < 1e-15);
    }
}
