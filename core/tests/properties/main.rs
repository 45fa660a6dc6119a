//! Properties of whole fills, checked by brute force independently of the engine's spatial
//! hash, coverage bitmap and containment test.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
// Negated comparisons are deliberate: they treat NaN as a failure.
#![allow(
    clippy::neg_cmp_op_on_partial_ord,
    clippy::nonminimal_bool,
    clippy::collapsible_match,
    clippy::collapsible_if
)]

use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use rand_core::RngCore;
use std::panic::{catch_unwind, AssertUnwindSafe};
use zetafill::internals::geom::separated;
use zetafill::Stats;
use zetafill::{
    index_words, rng_from_seed, CellSampler, Engine, Fixed, Geo, ParamError, Params, Placed, Placement, Point, Region, Scalar, ShapeKind,
    StepError, Stop, StopReason, Storage, ZetaRng,
};

mod checker_can_fail;
mod fills;
mod no_panics;
mod replay;
mod stops;
mod strategies;

use replay::engine_area_of;
use strategies::{base_case, case_strategy, varied_cases};

// ---------------------------------------------------------------------------------------------
// The brute-force checker.
// ---------------------------------------------------------------------------------------------

/// O(n^2) checks of a fill that use nothing of the engine but `geom::separated`.
mod checker {
    use super::*;

    /// A placed shape as the checker sees it: its stored centre and its concrete geometry.
    #[derive(Clone, Debug)]
    pub struct Item {
        pub centre: Point<f64>,
        pub geo: Geo<'static, f64>,
    }

    /// (min x, min y, max x, max y), computed here rather than by `Geo::bounds`.
    fn bbox(g: &Geo<f64>) -> (f64, f64, f64, f64) {
        match *g {
            Geo::Circle { c, r } | Geo::Ring { c, r, .. } => (c.x - r, c.y - r, c.x + r, c.y + r),
            Geo::Poly { ref v, .. } => {
                let vs = &v[..];
                let mut b = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
                for p in vs {
                    b = (b.0.min(p.x), b.1.min(p.y), b.2.max(p.x), b.3.max(p.y));
                }
                b
            }
            Geo::Motif { .. } => panic!("the property tests place the built-in kinds"),
        }
    }

    /// The shape is well formed: finite, positive size, polygons counter-clockwise (strictly
    /// convex when flagged convex; convex ones centred on `centre`), discs and rings centred on
    /// `centre`.
    fn well_formed(it: &Item) -> Result<(), String> {
        match it.geo {
            Geo::Motif { .. } => return Err("a motif: the property tests place the built-in kinds".into()),
            Geo::Circle { c, r } | Geo::Ring { c, r, .. } => {
                if !(r > 0.0 && r.is_finite() && c.x.is_finite() && c.y.is_finite()) {
                    return Err(format!("bad circle {:?}", it.geo));
                }
                if let Geo::Ring { inner, .. } = it.geo {
                    if !(inner > 0.0 && inner < r) {
                        return Err(format!("bad ring {:?}", it.geo));
                    }
                }
                if c != it.centre {
                    return Err(format!("circle centre {c:?} is not the stored centre {:?}", it.centre));
                }
            }
            Geo::Poly { ref v, convex } => {
                let n = v.len();
                if n < 3 {
                    return Err(format!("polygon with {n} vertices"));
                }
                let vs = &v[..n];
                if vs.iter().any(|a| !(a.x.is_finite() && a.y.is_finite())) {
                    return Err(format!("non-finite vertex in {:?}", it.geo));
                }
                let mut area2 = 0.0;
                for i in 0..n {
                    let (a, b) = (vs[i], vs[(i + 1) % n]);
                    area2 += a.x * b.y - a.y * b.x;
                }
                if !(area2 > 0.0) {
                    return Err(format!("polygon not counter-clockwise: {:?}", it.geo));
                }
                if convex {
                    let (mut sx, mut sy) = (0.0, 0.0);
                    for i in 0..n {
                        let (a, b, c) = (vs[i], vs[(i + 1) % n], vs[(i + 2) % n]);
                        let cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
                        if !(cross > 0.0) {
                            return Err(format!("polygon flagged convex is not strictly convex at vertex {i}: {:?}", it.geo));
                        }
                        sx += a.x;
                        sy += a.y;
                    }
                    // Rectangles and regular polygons: the vertex mean is the centre.
                    let (mx, my) = (sx / n as f64, sy / n as f64);
                    let (x0, y0, x1, y1) = bbox(&it.geo);
                    let tol = 1e-9 * (1.0 + (x1 - x0).max(y1 - y0) + it.centre.x.abs().max(it.centre.y.abs()));
                    if (mx - it.centre.x).abs() > tol || (my - it.centre.y).abs() > tol {
                        return Err(format!("polygon centroid ({mx}, {my}) is not the stored centre {:?}", it.centre));
                    }
                }
            }
        }
        Ok(())
    }

    /// The range of lattice multiples k for which `b` shifted by k * period can come within
    /// `gap` of `a` along one axis (always including -1..=1).
    fn k_range(a_lo: f64, a_hi: f64, b_lo: f64, b_hi: f64, gap: f64, period: f64) -> std::ops::RangeInclusive<i64> {
        let lo = ((a_lo - gap - b_hi) / period).floor();
        let hi = ((a_hi + gap - b_lo) / period).ceil();
        let lo = if lo.is_finite() { (lo as i64).clamp(-16, -1) } else { -1 };
        let hi = if hi.is_finite() { (hi as i64).clamp(1, 16) } else { 1 };
        lo..=hi
    }

    /// Checks a fill: `items` in placement order, region `[0, w] x [0, h]`.
    ///
    /// (a) every pair is `separated` by more than `gap`; in a periodic region also against the
    ///     other's images (the 8 neighbours, and any farther image whose box comes within
    ///     `gap`);
    /// (b) inclusive: every shape lies in `[gap, w - gap] x [gap, h - gap]`; periodic: every
    ///     centre lies in `[0, w) x [0, h)` and no shape comes within `gap` of its own images.
    pub fn check_fill(items: &[Item], w: f64, h: f64, gap: f64, periodic: bool) -> Result<(), String> {
        for (i, it) in items.iter().enumerate() {
            well_formed(it).map_err(|e| format!("shape {i}: {e}"))?;
            if periodic {
                let c = it.centre;
                if !(c.x >= 0.0 && c.x < w && c.y >= 0.0 && c.y < h) {
                    return Err(format!("shape {i}: centre {c:?} outside the period [0,{w})x[0,{h})"));
                }
                let b = bbox(&it.geo);
                for kx in k_range(b.0, b.2, b.0, b.2, gap, w) {
                    for ky in k_range(b.1, b.3, b.1, b.3, gap, h) {
                        if (kx, ky) == (0, 0) {
                            continue;
                        }
                        let img = it.geo.shift(kx as f64 * w, ky as f64 * h);
                        if !separated(&img, &it.geo, gap) {
                            return Err(format!("shape {i} overlaps its own image ({kx}, {ky}): {:?}", it.geo));
                        }
                    }
                }
            } else {
                let inside = |x: f64, y: f64| x >= gap && x <= w - gap && y >= gap && y <= h - gap;
                let ok = match it.geo {
                    Geo::Circle { c, r } | Geo::Ring { c, r, .. } => inside(c.x - r, c.y - r) && inside(c.x + r, c.y + r),
                    Geo::Poly { ref v, .. } => v.iter().all(|p| inside(p.x, p.y)),
                    Geo::Motif { .. } => false,
                };
                if !ok {
                    return Err(format!("shape {i} is not inside the region with gap {gap}: {:?}", it.geo));
                }
            }
        }
        for j in 0..items.len() {
            let gj = &items[j].geo;
            let bj = bbox(gj);
            for (i, it) in items.iter().enumerate().take(j) {
                // The later shape is the moving one, as it was when it was placed.
                let gi = &it.geo;
                if !separated(gj, gi, gap) {
                    return Err(format!("shapes {i} and {j} are not separated by {gap}: {gi:?} / {gj:?}"));
                }
                if !periodic {
                    continue;
                }
                let bi = bbox(gi);
                for kx in k_range(bi.0, bi.2, bj.0, bj.2, gap, w) {
                    for ky in k_range(bi.1, bi.3, bj.1, bj.3, gap, h) {
                        if (kx, ky) == (0, 0) {
                            continue;
                        }
                        let img = gj.shift(kx as f64 * w, ky as f64 * h);
                        if !separated(&img, gi, gap) {
                            return Err(format!(
                                "shape {i} and image ({kx}, {ky}) of shape {j} are not separated by {gap}: {gi:?} / {gj:?}"
                            ));
                        }
                    }
                }
            }
        }
        Ok(())
    }
}

use checker::{check_fill, Item};

// ---------------------------------------------------------------------------------------------
// Running the engine.
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug)]
struct Case {
    seed: u64,
    c: f64,
    n: f64,
    shape: ShapeKind,
    rotate: bool,
    gap: f64,
    w: f64,
    h: f64,
    periodic: bool,
    max_trials: u64,
}

impl Case {
    fn params(&self) -> Params {
        Params {
            c: self.c,
            n_offset: self.n,
            shape: self.shape.into(),
            rotate: self.rotate,
            gap: self.gap,
            max_trials: self.max_trials,
        }
    }
    fn region(&self) -> Region<'static> {
        Region::Rect {
            width: self.w,
            height: self.h,
            periodic: self.periodic,
        }
    }
    fn stop(&self, k: u64) -> Stop {
        Stop {
            count: Some(k),
            ..Stop::default()
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum IndexSize {
    /// `index_words(cap)`.
    Full,
    /// `cap + 1`: a single bucket, every query walks one list of all shapes.
    OneBucket,
}

#[derive(Clone, Debug)]
struct Run {
    placed: Vec<Placed<f64>>,
    items: Vec<Item>,
    placements: Vec<Placement<f64>>,
    reason: StopReason,
    stats: Stats,
    zeta: f64,
    area: f64,
}

fn run_with(case: &Case, cap: usize, stop: &Stop, cov_words: usize, index: IndexSize) -> Result<Run, ParamError> {
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut idx = vec![0u32; if index == IndexSize::Full { index_words(cap) } else { cap + 1 }];
    let mut cov = vec![0u64; cov_words];
    let mut e = Engine::<f64>::new(
        case.params(),
        case.region(),
        Storage {
            shapes: &mut shapes,
            index: &mut idx,
            coverage: &mut cov,
        },
    )?;
    let mut rng = rng_from_seed(case.seed);
    let mut placements = Vec::new();
    let reason = e.run(&mut rng, stop, |p| placements.push(*p));
    let placed = e.placed().to_vec();
    let items = items_of(&e);
    Ok(Run {
        placed,
        items,
        placements,
        reason,
        stats: e.stats(),
        zeta: e.zeta(),
        area: e.total_area(),
    })
}

/// The placed shapes as the checker sees them, through `Engine::geo`.
fn items_of(e: &Engine<'_, f64>) -> Vec<Item> {
    (0..e.placed().len())
        .map(|i| {
            let p = e.placed()[i];
            let geo = e
                .geo(i)
                .and_then(|g| g.owned())
                .unwrap_or_else(|| panic!("no geometry for placed shape {i}"));
            Item {
                centre: Point::new(p.x, p.y),
                geo,
            }
        })
        .collect()
}

fn run(case: &Case, k: u64, cov_words: usize) -> Run {
    run_with(case, k as usize, &case.stop(k), cov_words, IndexSize::Full).unwrap_or_else(|e| panic!("{case:?}: {e:?}"))
}

fn placed_bits(p: &Placed<f64>) -> (u64, u64, u64, u64) {
    (p.x.to_bits(), p.y.to_bits(), p.scale.to_bits(), p.angle.to_bits())
}

fn placement_bits(p: &Placement<f64>) -> (u64, (u64, u64, u64, u64), u64, u64) {
    (p.index, placed_bits(&p.shape), p.area.to_bits(), p.trials)
}

fn stats_bits(s: &Stats) -> (u64, u64, u64) {
    (s.placed, s.trials, s.fill_fraction.to_bits())
}

/// Bitwise equality of two runs (shapes, placements, stop reason, statistics).
fn same_run(a: &Run, b: &Run) -> Result<(), String> {
    if a.placed.len() != b.placed.len() {
        return Err(format!(
            "{} vs {} shapes ({:?} / {:?})",
            a.placed.len(),
            b.placed.len(),
            a.reason,
            b.reason
        ));
    }
    for (i, (p, q)) in a.placed.iter().zip(&b.placed).enumerate() {
        if placed_bits(p) != placed_bits(q) {
            return Err(format!("shape {i} differs: {p:?} vs {q:?}"));
        }
    }
    let pa: Vec<_> = a.placements.iter().map(placement_bits).collect();
    let pb: Vec<_> = b.placements.iter().map(placement_bits).collect();
    if pa != pb {
        return Err("placements differ".into());
    }
    if a.reason != b.reason {
        return Err(format!("stop reasons differ: {:?} vs {:?}", a.reason, b.reason));
    }
    if stats_bits(&a.stats) != stats_bits(&b.stats) {
        return Err(format!("stats differ: {:?} vs {:?}", a.stats, b.stats));
    }
    Ok(())
}

/// Checks the reported areas, the shapes' actual areas, the stored shapes and the statistics.
fn check_run(case: &Case, r: &Run) -> Result<(), String> {
    check_fill(&r.items, case.w, case.h, case.gap, case.periodic)?;
    let n = r.placed.len();
    if r.placements.len() != n {
        return Err(format!("{} placements reported for {n} shapes", r.placements.len()));
    }
    let z = zetafill::internals::zeta::hurwitz_zeta(case.c, case.n).map_err(|e| format!("zeta: {e:?}"))?;
    if z.to_bits() != r.zeta.to_bits() {
        return Err(format!("engine zeta {} != hurwitz_zeta {z}", r.zeta));
    }
    let a_tot = case.w * case.h;
    if a_tot != r.area {
        return Err(format!("total area {} != {a_tot}", r.area));
    }
    let mut sum = 0.0f64;
    let mut trials = 0u64;
    for (i, (p, s)) in r.placements.iter().zip(&r.placed).enumerate() {
        if p.index != i as u64 || placed_bits(&p.shape) != placed_bits(s) || p.trials == 0 || p.trials > case.max_trials {
            return Err(format!("placement {i} inconsistent: {p:?} / {s:?}"));
        }
        let want = a_tot / (z * (i as f64 + case.n).powf(case.c));
        if !(((p.area - want) / want).abs() < 1e-12) {
            return Err(format!("placement {i}: area {} but A/(zeta (i+N)^c) = {want}", p.area));
        }
        let actual = case.shape.area_for_scale(s.scale);
        if !(((actual - p.area) / p.area).abs() < 1e-9) {
            return Err(format!("placement {i}: shape area {actual} but nominal {}", p.area));
        }
        let rotated = case.rotate && case.shape.rotates();
        if rotated {
            if !(s.angle >= 0.0 && s.angle < std::f64::consts::TAU) {
                return Err(format!("placement {i}: angle {}", s.angle));
            }
        } else if s.angle.to_bits() != 0 {
            return Err(format!("placement {i}: unrotated shape has angle {}", s.angle));
        }
        sum += p.area;
        trials += p.trials;
    }
    match r.reason {
        StopReason::Step(StepError::Halted { index, trials: t }) => {
            if index != n as u64 || t != case.max_trials {
                return Err(format!("bad halt {:?} after {n} shapes", r.reason));
            }
            trials += t;
        }
        StopReason::Step(StepError::CannotFit { index }) | StopReason::Step(StepError::Capacity { capacity: index }) => {
            if index != n as u64 {
                return Err(format!("bad stop {:?} after {n} shapes", r.reason));
            }
        }
        _ => {}
    }
    if r.stats.placed != n as u64 || r.stats.trials != trials || r.stats.fill_fraction.to_bits() != (sum / a_tot).to_bits() {
        return Err(format!(
            "stats {:?}, expected placed {n}, trials {trials}, fill {}",
            r.stats,
            sum / a_tot
        ));
    }
    Ok(())
}
