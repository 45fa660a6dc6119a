//! The G-code writer: a [`Drawing`] in the bed frame, a [`Machine`] and [`GcodeOptions`] in,
//! bytes and [`Figures`] out.
//!
//! Safety invariants, by construction (and checked by `cli/tests/gcode.rs`, which replays the
//! output through an independent interpreter):
//! - every X/Y coordinate is inside the bed: the drawing is refused unless it lies inside the
//!   usable area; every number is rounded on a fixed grid and clamped to the bed's grid; an
//!   arc whose rounded circle would pass outside the bed is written as chords instead;
//! - the tool is off for every travel move and at the end: travel happens only between the
//!   profile's `tool_off` and `tool_on` blocks, and `tool_off` runs after `start` and before
//!   `end`;
//! - a feed is stated on the first cutting move after every profile block (so before the
//!   first cutting move, and again if a block changed it);
//! - numbers are plain fixed-precision decimals (integers in units of 10^-decimals formatted
//!   by hand): never exponent notation, NaN or `-0`;
//! - every feed is written within 0.013 % of what was asked in inches, and to the whole mm/min
//!   in mm (see `words.rs`);
//! - the same input gives the same bytes (no clock, no hashing, no environment).

use crate::model::{arc_extremes, Bounds, Drawing, Path, Pt};
use crate::output::machine::{Machine, Travel};
use crate::output::order::order;
use crate::output::order::PathOrder;
use crate::output::stream::TextSink;
use std::f64::consts::TAU;
use std::fmt::{self, Write as _};

mod words;

use words::{feed, int};
pub use words::{feed_error_bound, fixed};

/// The smallest chord tolerance (mm): the resolution of G-code written in mm (3 decimals;
/// inches, with 5, are finer).
/// Finer chords would only add lines, up to gigabytes of them.
pub const MIN_CHORD_TOLERANCE: f64 = 0.001;

/// What to write besides the drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct GcodeOptions {
    /// Drawing feed, mm/min.
    pub feed: f64,
    /// Travel feed, mm/min.
    pub travel_feed: f64,
    /// Laser power (S), for profiles with a power range.
    pub power: Option<f64>,
    /// Times to draw everything.
    pub passes: u32,
    /// Circles and arcs as G2/G3.
    pub arcs: bool,
    /// Largest distance between an arc and the chords that replace it (mm).
    pub chord_tolerance: f64,
    /// Path order.
    pub order: PathOrder,
    /// Margin kept free on every side of the bed (mm).
    pub margin: f64,
    /// Comment lines for the header (parameters, seed, command line).
    pub header: Vec<String>,
}

impl GcodeOptions {
    /// The profile's defaults.
    pub fn new(m: &Machine) -> GcodeOptions {
        GcodeOptions {
            feed: m.feed.draw,
            travel_feed: m.feed.travel,
            power: m.power.map(|p| p.default),
            passes: 1,
            arcs: m.arcs,
            chord_tolerance: 0.01,
            order: PathOrder::Improved,
            margin: 0.0,
            header: Vec::new(),
        }
    }
}

/// What a program does, for the header and stderr.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Figures {
    /// Paths drawn (each pass counts).
    pub paths: usize,
    /// Times the tool goes on.
    pub tool_ons: usize,
    /// Pen-down (cutting) length, mm.
    pub pen_down_mm: f64,
    /// Pen-up travel, mm (from the machine's origin, and to `park`).
    pub travel_mm: f64,
    /// Estimated run time, seconds: lengths over feeds plus the profile's dwells.
    pub seconds: f64,
}

impl fmt::Display for Figures {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = self.seconds.round() as u64;
        write!(
            f,
            "{} paths, pen-down {:.1} mm, pen-up travel {:.1} mm, {} pen-downs, estimated time {}:{:02}:{:02}",
            self.paths,
            self.pen_down_mm,
            self.travel_mm,
            self.tool_ons,
            s / 3600,
            (s / 60) % 60,
            s % 60
        )
    }
}

/// A written program.
#[derive(Debug, Clone, PartialEq)]
pub struct GcodeOutput {
    /// The G-code text.
    pub bytes: Vec<u8>,
    /// Its figures.
    pub figures: Figures,
}

/// A point on the output grid (units of 10^-decimals of the output unit).
type Q = [i64; 2];

struct Writer<'a, 'w> {
    m: &'a Machine,
    o: &'a GcodeOptions,
    out: TextSink<'w>,
    dec: u32,
    /// Grid units per mm of the bed frame.
    k: f64,
    lo: Q,
    hi: Q,
    pos: Option<Q>,
    tool_on: bool,
    feed_stated: bool,
    fig: Figures,
}

impl Writer<'_, '_> {
    fn line(&mut self, s: &str) {
        self.out.buf.push_str(s);
        self.out.buf.push('\n');
    }

    fn block(&mut self, text: &str) {
        let power = self.o.power.map(|p| int(p, 0)).unwrap_or_else(|| "0".into());
        let (draw, travel) = (feed(self.o.feed, self.m.units), feed(self.o.travel_feed, self.m.units));
        for l in text.lines() {
            let l = l.trim();
            if l.is_empty() {
                continue;
            }
            let l = l
                .replace("{power}", &power)
                .replace("{feed}", &draw)
                .replace("{travel_feed}", &travel);
            self.line(&l);
        }
        // A block may change the feed: state it again on the next cutting move.
        self.feed_stated = false;
    }

    /// Bed frame (mm) to the output grid, clamped to the bed.
    fn q(&self, p: Pt) -> Q {
        let r = self.q_raw(p);
        [r[0].clamp(self.lo[0], self.hi[0]), r[1].clamp(self.lo[1], self.hi[1])]
    }

    /// Bed frame (mm) to the output grid, not clamped (arc centres may lie off the bed).
    fn q_raw(&self, p: Pt) -> Q {
        let (sy, dx, dy) = self.m.bed_to_machine();
        let mx = (p[0] + dx) * self.k;
        let my = (sy * p[1] + dy) * self.k;
        [mx.round() as i64, my.round() as i64]
    }

    fn xy(&self, q: Q) -> String {
        format!("X{} Y{}", fixed(q[0], self.dec), fixed(q[1], self.dec))
    }

    fn grid_mm(&self, a: Q, b: Q) -> f64 {
        libm::hypot((a[0] - b[0]) as f64, (a[1] - b[1]) as f64) / self.k
    }

    /// Rapid to the profile's park position, if it has one and the head is elsewhere.
    fn park(&mut self) {
        if let Some(park) = self.m.park {
            let q = [
                ((park[0] * self.k).round() as i64).clamp(self.lo[0], self.hi[0]),
                ((park[1] * self.k).round() as i64).clamp(self.lo[1], self.hi[1]),
            ];
            if self.pos != Some(q) {
                let from = self.pos.unwrap_or([0, 0]);
                self.fig.travel_mm += self.grid_mm(from, q);
                let s = format!("G0 {}", self.xy(q));
                self.line(&s);
                self.pos = Some(q);
            }
        }
    }

    fn tool(&mut self, on: bool) {
        if on == self.tool_on {
            return;
        }
        let text = if on { self.m.tool_on.clone() } else { self.m.tool_off.clone() };
        self.block(&text);
        self.tool_on = on;
        if on {
            self.fig.tool_ons += 1;
        }
    }

    fn travel_to(&mut self, q: Q) {
        if self.pos == Some(q) {
            return;
        }
        self.tool(false);
        let from = self.pos.unwrap_or(self.home_q());
        self.fig.travel_mm += self.grid_mm(from, q);
        match self.m.travel {
            Travel::Rapid => {
                let s = format!("G0 {}", self.xy(q));
                self.line(&s);
            }
            Travel::Feed => {
                let s = format!("G1 {} F{}", self.xy(q), feed(self.o.travel_feed, self.m.units));
                self.line(&s);
                self.feed_stated = false;
            }
        }
        self.pos = Some(q);
    }

    fn home_q(&self) -> Q {
        [0, 0]
    }

    fn feed_word(&mut self) -> String {
        if self.feed_stated {
            String::new()
        } else {
            self.feed_stated = true;
            format!(" F{}", feed(self.o.feed, self.m.units))
        }
    }

    fn cut_to(&mut self, q: Q) {
        let Some(from) = self.pos else { return };
        if from == q {
            return;
        }
        let f = self.feed_word();
        let s = format!("G1 {}{f}", self.xy(q));
        self.line(&s);
        self.fig.pen_down_mm += self.grid_mm(from, q);
        self.pos = Some(q);
    }

    /// Starts a path at `q`: travels unless already there with the tool on (consecutive
    /// paths that meet are drawn without lifting).
    fn begin(&mut self, q: Q) {
        if !(self.tool_on && self.pos == Some(q)) {
            self.travel_to(q);
            self.tool(true);
        }
        self.fig.paths += 1;
    }

    fn polyline(&mut self, pts: &[Pt], closed: bool) {
        let Some(first) = pts.first() else { return };
        let q0 = self.q(*first);
        self.begin(q0);
        for p in &pts[1..] {
            let q = self.q(*p);
            self.cut_to(q);
        }
        if closed {
            self.cut_to(q0);
        }
    }

    fn chords(&mut self, c: Pt, r: f64, start: f64, sweep: f64) {
        let sweep = sweep.clamp(-TAU, TAU);
        let tol = self.o.chord_tolerance.min(r);
        let step = 2.0 * libm::acos((1.0 - tol / r).clamp(-1.0, 1.0));
        let min_n = if sweep.abs() >= TAU { 8 } else { 1 };
        let n = ((sweep.abs() / step.max(1e-9)).ceil() as usize).clamp(min_n, 100_000);
        let pts: Vec<Pt> = (0..=n)
            .map(|i| crate::model::polar(c, r, start + sweep * i as f64 / n as f64))
            .collect();
        self.polyline(&pts, false);
    }

    /// An arc as G2/G3 when the rounded arc is well defined and inside the bed, else chords.
    fn arc(&mut self, c: Pt, r: f64, start: f64, sweep: f64) {
        let full = sweep.abs() >= TAU;
        let s = crate::model::polar(c, r, start);
        let e = if full { s } else { crate::model::polar(c, r, start + sweep) };
        let (qs, qe, qc) = (self.q(s), self.q(e), self.q_raw(c));
        let (sy, _, _) = self.m.bed_to_machine();
        // Direction on the machine: a mirrored y turns the arc the other way.
        let ccw = (sweep > 0.0) == (sy > 0.0);
        let rq = libm::hypot((qs[0] - qc[0]) as f64, (qs[1] - qc[1]) as f64);
        let ok = self.o.arcs && rq >= 10.0 && {
            let a_s = libm::atan2((qs[1] - qc[1]) as f64, (qs[0] - qc[0]) as f64);
            let (a_from, span) = if full {
                (a_s, TAU)
            } else {
                let a_e = libm::atan2((qe[1] - qc[1]) as f64, (qe[0] - qc[0]) as f64);
                let span = if ccw {
                    (a_e - a_s).rem_euclid(TAU)
                } else {
                    (a_s - a_e).rem_euclid(TAU)
                };
                (if ccw { a_s } else { a_e }, span)
            };
            // The rounded arc must still be the intended one (no end point on the start, which
            // a controller reads as a full circle) and stay inside the bed.
            let sane = full || (qs != qe && (span - sweep.abs()).abs() < 1e-3 && span > 1e-3);
            let extremes_in = arc_extremes(a_from, span).into_iter().all(|a| {
                let x = qc[0] as f64 + rq * libm::cos(a);
                let y = qc[1] as f64 + rq * libm::sin(a);
                x >= self.lo[0] as f64 && x <= self.hi[0] as f64 && y >= self.lo[1] as f64 && y <= self.hi[1] as f64
            });
            sane && extremes_in
        };
        if !ok {
            self.chords(c, r, start, sweep);
            return;
        }
        self.begin(qs);
        let f = self.feed_word();
        let line = format!(
            "{} {} I{} J{}{f}",
            if ccw { "G3" } else { "G2" },
            self.xy(qe),
            fixed(qc[0] - qs[0], self.dec),
            fixed(qc[1] - qs[1], self.dec)
        );
        self.line(&line);
        self.fig.pen_down_mm += rq / self.k * if full { TAU } else { sweep.abs() };
        self.pos = Some(qe);
    }

    fn path(&mut self, p: &Path) {
        match p {
            Path::Polyline { points, closed } => self.polyline(points, *closed),
            Path::Arc {
                center,
                radius,
                start,
                sweep,
            } => self.arc(*center, *radius, *start, *sweep),
        }
    }
}

fn check_options(m: &Machine, o: &GcodeOptions) -> Result<(), String> {
    if !(o.feed.is_finite() && o.feed > 0.0) {
        return Err(format!("feed {} mm/min must be positive", o.feed));
    }
    if !(o.travel_feed.is_finite() && o.travel_feed > 0.0) {
        return Err(format!("travel feed {} mm/min must be positive", o.travel_feed));
    }
    match (&m.power, o.power) {
        (Some(r), Some(p)) if !(p >= r.min && p <= r.max) => return Err(format!("power {p} is outside {}..{}", r.min, r.max)),
        (None, Some(_)) => return Err(format!("'{}' has no power range", m.name)),
        _ => {}
    }
    if o.passes == 0 {
        return Err("passes must be at least 1".into());
    }
    if !(o.chord_tolerance.is_finite() && o.chord_tolerance >= MIN_CHORD_TOLERANCE) {
        return Err(format!("the chord tolerance must be at least {MIN_CHORD_TOLERANCE} mm"));
    }
    if !(o.margin.is_finite() && o.margin >= 0.0 && 2.0 * o.margin < m.bed.width.min(m.bed.height)) {
        return Err(format!("margin {} mm leaves no room on the bed", o.margin));
    }
    Ok(())
}

fn comment(out: &mut String, s: &str) {
    for l in s.lines() {
        let clean: String = l
            .chars()
            .map(|c| if c.is_ascii() && !c.is_ascii_control() { c } else { '?' })
            .collect();
        let _ = writeln!(out, "; {clean}");
    }
}

/// Writes `d` (bed frame, mm) for machine `m`. Refuses a drawing that does not lie inside the
/// bed less the margin, and options outside the profile's ranges.
pub fn write(d: &Drawing, m: &Machine, o: &GcodeOptions) -> Result<GcodeOutput, String> {
    write_pens(std::slice::from_ref(&(String::new(), d.clone())), m, o)
}

/// [`write`](fn@write) for a drawing in several pens, drawn one after the other, each named (its
/// colour) in a comment: between two pens the tool goes off, the head parks (if the profile
/// has a park) and the profile's `pen_change` block is written (`M0` by default: the machine
/// waits while the operator swaps the pen). Pens with nothing to draw are left out.
pub fn write_pens(pens: &[(String, Drawing)], m: &Machine, o: &GcodeOptions) -> Result<GcodeOutput, String> {
    let p = program(pens, m, o)?;
    let mut bytes = Vec::new();
    // A Vec takes every byte.
    let _ = p.write_to(&mut bytes);
    Ok(GcodeOutput { bytes, figures: p.figures })
}

fn path_finite(p: &Path) -> bool {
    match p {
        Path::Polyline { points, .. } => points.iter().all(|q| q[0].is_finite() && q[1].is_finite()),
        Path::Arc {
            center,
            radius,
            start,
            sweep,
        } => {
            center[0].is_finite() && center[1].is_finite() && radius.is_finite() && *radius > 0.0 && start.is_finite() && sweep.is_finite()
        }
    }
}

/// The bed in the output units' grid, for checkers: (lo, hi) corners.
pub fn grid_bounds(m: &Machine) -> Bounds {
    let f = m.units.per_mm();
    let b = m.machine_bounds_mm();
    Bounds {
        x0: b.x0 * f,
        y0: b.y0 * f,
        x1: b.x1 * f,
        y1: b.y1 * f,
    }
}

mod program;
#[cfg(test)]
mod tests;

pub use program::{program, Program};
