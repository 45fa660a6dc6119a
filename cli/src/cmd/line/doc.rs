//! The document of a 1D fill: Shier and Bourke's JSON with `"mode": "line"`, also read by the
//! CSV and digest writers.

use serde::Serialize;

/// A finished (or halted) 1D fill: the JSON of docs/cli.md with `"mode": "line"`.
#[derive(Debug, Clone, Serialize)]
pub struct LineDoc {
    /// Format version (1).
    pub version: u32,
    /// `"line"`.
    pub mode: &'static str,
    /// Everything needed to reproduce the run.
    pub params: LineParamsDoc,
    /// `{ "kind": "interval", "length": L, "periodic": bool }`.
    pub region: IntervalDoc,
    /// zeta(c, N).
    pub zeta: f64,
    /// Segments in placement order.
    pub shapes: Vec<SegmentDoc>,
    /// Run statistics.
    pub stats: LineStatsDoc,
    /// The determinism digest (count, FNV-1a) of the engine's own bits.
    #[serde(skip)]
    pub digest: (u64, u64),
}

/// Run statistics of a 1D fill.
#[derive(Debug, Clone, Serialize)]
pub struct LineStatsDoc {
    /// Segments placed.
    pub placed: u64,
    /// Trials in all.
    pub trials: u64,
    /// Placed length over L.
    pub fill_fraction: f64,
    /// Whether the run halted at the trial limit.
    pub halted: bool,
    /// Why the run stopped: `count`, `fill`, `min-size` or `halted`.
    pub stop: &'static str,
}

/// The parameters of a 1D fill: the power law, the seed, the sampler, the gap and the stops.
pub type LineParamsDoc = crate::model::doc::RunParamsDoc<LineOwnDoc>;

/// What only a 1D fill has: its sampler.
#[derive(Debug, Clone, Serialize)]
pub struct LineOwnDoc {
    /// `fast` (the exact gap sampler) or `reference` (the paper's).
    pub sampler: &'static str,
}

/// The interval.
#[derive(Debug, Clone, Serialize)]
pub struct IntervalDoc {
    /// `"interval"`.
    pub kind: &'static str,
    /// Length L (mm).
    pub length: f64,
    /// Periodic boundary.
    pub periodic: bool,
}

/// One placed segment `[start, start + length]`.
#[derive(Debug, Clone, Serialize)]
pub struct SegmentDoc {
    /// Placement index.
    pub index: u64,
    /// `"segment"`.
    pub kind: &'static str,
    /// Left end (mm), in `[0, L)` when periodic (the segment may run past L and wrap).
    pub start: f64,
    /// Length L_i (mm).
    pub length: f64,
    /// Trials this placement took.
    pub trials: u64,
}
