//! The JSON document of a territory run (docs/territory.md, `"mode": "territory"`): its sites,
//! colour rules, parameters and statistics.

use crate::model::doc::RegionDoc;
use serde::Serialize;

/// One site in the JSON output.
#[derive(Debug, Clone, Serialize)]
pub struct SiteDoc {
    /// Insertion order (the first k are the seeds).
    pub index: usize,
    /// Position (mm).
    pub point: [f64; 2],
    /// Territory 0..k-1.
    pub territory: u32,
    /// Graph distance from the territory's seed (Procedure 2).
    pub distance: u32,
    /// HSB colour, each in [0, 1].
    pub color: [f64; 3],
    /// With --sites-from: the index of the fill's shape this site is the centre of.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<u64>,
}

/// A territory's colour rule in the JSON output.
#[derive(Debug, Clone, Serialize)]
pub struct RuleDoc {
    /// c^k.
    pub c: [f64; 3],
    /// d^k.
    pub d: [f64; 3],
}

/// The parameters of a territory run.
#[derive(Debug, Clone, Serialize)]
pub struct TerritoryParamsDoc {
    /// RNG seed.
    pub seed: u64,
    /// Total number of sites asked for.
    pub points: usize,
    /// Density control on or off.
    pub uniform: bool,
    /// The paper's n0.
    pub n0: u64,
    /// The paper's s.
    pub s: f64,
    /// Weight of a boundary bucket.
    pub boost: f64,
    /// What the SVG draws.
    pub render: &'static str,
    /// The fill the sites came from.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sites_from: Option<String>,
    /// Per-territory colour rules.
    pub colors: Vec<RuleDoc>,
}

/// Per-territory figures.
#[derive(Debug, Clone, Serialize)]
pub struct TerritoryStatsDoc {
    /// Sites in the territory.
    pub sites: usize,
    /// Largest distance from the seed.
    pub max_distance: u32,
}

/// Run statistics.
#[derive(Debug, Clone, Serialize)]
pub struct StatsDoc {
    /// Sites in all.
    pub sites: usize,
    /// Per territory.
    pub territories: Vec<TerritoryStatsDoc>,
    /// Sites handed over by connectivity repairs.
    pub reassigned: u64,
    /// Insertions after which a component was handed over.
    pub repairs: u64,
    /// Sites visited by repair searches, in all.
    pub repair_visits: u64,
    /// The most sites one insertion's repair visited.
    pub max_repair_visits: u64,
    /// Random draws rejected (outside the region or on a site).
    pub rejected: u64,
    /// Boundary polylines after merging and clipping.
    pub boundary_polylines: usize,
    /// Total boundary length (mm).
    pub boundary_length: f64,
}

/// The JSON document of a territory run (docs/territory.md).
#[derive(Debug, Clone, Serialize)]
pub struct TerritoryDoc {
    /// Format version (1).
    pub version: u32,
    /// `"territory"`.
    pub mode: &'static str,
    /// Number of seeds k (= territories).
    pub seeds: usize,
    /// Parameters.
    pub params: TerritoryParamsDoc,
    /// The region in its own frame.
    pub region: RegionDoc,
    /// Sites in insertion order.
    pub sites: Vec<SiteDoc>,
    /// Statistics.
    pub stats: StatsDoc,
}
