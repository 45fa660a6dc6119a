//! Properties of whole fills, checked by brute force independently of the engine's spatial
//! hash, coverage bitmap and containment test.

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

// ---------------------------------------------------------------------------------------------
// The brute-force checker.
// ---------------------------------------------------------------------------------------------

/// O(n^2) checks of a fill that use nothing of the engine but `geom::separated`.
mod checker {
    use super::*;

    /// A placed shape as the checker sees it: its stored centre and its concrete geometry.
    #[derive(Clone, Copy, Debug)]
    pub struct Item {
        pub centre: Point<f64>,
        pub geo: Geo<f64>,
    }

    /// (min x, min y, max x, max y), computed here rather than by `Geo::bounds`.
    fn bbox(g: &Geo<f64>) -> (f64, f64, f64, f64) {
        match *g {
            Geo::Circle { c, r } | Geo::Ring { c, r, .. } => (c.x - r, c.y - r, c.x + r, c.y + r),
            Geo::Poly { v, n, .. } => {
                let vs = &v[..n.min(v.len())];
                let mut b = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
                for p in vs {
                    b = (b.0.min(p.x), b.1.min(p.y), b.2.max(p.x), b.3.max(p.y));
                }
                b
            }
        }
    }

    /// The shape is well formed: finite, positive size, polygons counter-clockwise (strictly
    /// convex when flagged convex; convex ones centred on `centre`), discs and rings centred on
    /// `centre`.
    fn well_formed(it: &Item) -> Result<(), String> {
        match it.geo {
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
            Geo::Poly { v, n, convex } => {
                if !(3..=v.len()).contains(&n) {
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
                    Geo::Poly { v, n, .. } => v[..n].iter().all(|p| inside(p.x, p.y)),
                };
                if !ok {
                    return Err(format!("shape {i} is not inside the region with gap {gap}: {:?}", it.geo));
                }
            }
        }
        for j in 0..items.len() {
            let gj = items[j].geo;
            let bj = bbox(&gj);
            for (i, it) in items.iter().enumerate().take(j) {
                // The later shape is the moving one, as it was when it was placed.
                let gi = it.geo;
                if !separated(&gj, &gi, gap) {
                    return Err(format!("shapes {i} and {j} are not separated by {gap}: {gi:?} / {gj:?}"));
                }
                if !periodic {
                    continue;
                }
                let bi = bbox(&gi);
                for kx in k_range(bi.0, bi.2, bj.0, bj.2, gap, w) {
                    for ky in k_range(bi.1, bi.3, bj.1, bj.3, gap, h) {
                        if (kx, ky) == (0, 0) {
                            continue;
                        }
                        let img = gj.shift(kx as f64 * w, ky as f64 * h);
                        if !separated(&img, &gi, gap) {
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
            let geo = e.geo(i).unwrap_or_else(|| panic!("no geometry for placed shape {i}"));
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

// ---------------------------------------------------------------------------------------------
// Replay oracle: every trial the engine made, re-derived from the RNG and decided by brute force.
// ---------------------------------------------------------------------------------------------

/// Whether candidate `g` (centre `c`) would be accepted after `placed`: inside the region (or
/// free of its own images), and clear of every placed shape and image. Brute force.
fn brute_accepts(case: &Case, placed: &[Item], g: &Geo<f64>) -> bool {
    let (w, h, gap) = (case.w, case.h, case.gap);
    if case.periodic {
        for (ox, oy) in [(w, 0.0), (0.0, h), (w, h), (w, -h)] {
            if !separated(g, &g.shift(ox, oy), gap) {
                return false;
            }
        }
    } else {
        let inside = |x: f64, y: f64| x >= gap && x <= w - gap && y >= gap && y <= h - gap;
        let ok = match *g {
            Geo::Circle { c, r } | Geo::Ring { c, r, .. } => inside(c.x - r, c.y - r) && inside(c.x + r, c.y + r),
            Geo::Poly { v, n, .. } => v[..n].iter().all(|p| inside(p.x, p.y)),
        };
        if !ok {
            return false;
        }
    }
    let offs: &[f64] = if case.periodic { &[0.0, 1.0, -1.0] } else { &[0.0] };
    for p in placed {
        for &ky in offs {
            for &kx in offs {
                let gi = if kx == 0.0 && ky == 0.0 { *g } else { g.shift(kx * w, ky * h) };
                if !separated(&gi, &p.geo, gap) {
                    return false;
                }
            }
        }
    }
    true
}

/// Replays every trial of `r` from the seed: each rejected candidate must be rejected by brute
/// force, each accepted one accepted and equal to the stored shape. This tests the spatial hash
/// (and the coverage bitmap) for false rejections as well as false acceptances.
fn replay(case: &Case, r: &Run, e_area_of: impl Fn(u64) -> f64) -> Result<(), String> {
    let mut rng = rng_from_seed(case.seed);
    let kind = case.shape;
    let region = case.region();
    let rotated = case.rotate && kind.rotates();
    let unit = |rng: &mut ZetaRng| ((rng.next_u64() >> 11) as f64) * (1.0 / 9_007_199_254_740_992.0);
    for (i, pl) in r.placements.iter().enumerate() {
        let scale = kind.scale_for_area(e_area_of(i as u64));
        if scale.to_bits() != pl.shape.scale.to_bits() {
            return Err(format!("placement {i}: scale {} vs {scale}", pl.shape.scale));
        }
        // The documented mapping (`rng` module): centres uniform over the positions where the
        // inscribed circle (rotated) or the bounding box (unrotated) lies inside the region
        // shrunk by the gap.
        let (ex, ey) = if rotated {
            let inr = kind.inradius(scale);
            (inr, inr)
        } else {
            let (x0, y0, x1, y1) = kind.geo(Point::new(0.0, 0.0), scale, 0.0).bounds();
            ((-x0).max(x1), (-y0).max(y1))
        };
        let (x0, x1, y0, y1) = region.centre_range(ex, ey, case.gap).unwrap_or((0.0, 0.0, 0.0, 0.0));
        for t in 1..=pl.trials {
            let angle = if rotated { unit(&mut rng) * std::f64::consts::TAU } else { 0.0 };
            let (ux, uy) = (unit(&mut rng), unit(&mut rng));
            let (sin, cos) = if rotated { ShapeKind::sin_cos(angle) } else { (0.0, 1.0) };
            let c = region.wrap(Point::new(x0 + ux * (x1 - x0), y0 + uy * (y1 - y0)));
            let g = kind.geo_sc(c, scale, sin, cos);
            let accepted = brute_accepts(case, &r.items[..i], &g);
            if accepted && t == pl.trials {
                let s = Placed {
                    x: c.x,
                    y: c.y,
                    scale,
                    angle,
                };
                if placed_bits(&s) != placed_bits(&pl.shape) {
                    return Err(format!("placement {i}: replayed {s:?}, engine placed {:?}", pl.shape));
                }
            }
            if accepted != (t == pl.trials) {
                return Err(format!(
                    "placement {i}, trial {t} of {}: brute force {} the candidate, the engine did the opposite",
                    pl.trials,
                    if accepted { "accepts" } else { "rejects" }
                ));
            }
        }
    }
    Ok(())
}

fn engine_area_of(case: &Case) -> impl Fn(u64) -> f64 {
    let mut shapes = [Placed::<f64>::default(); 1];
    let mut idx = [0u32; 4];
    let e = Engine::<f64>::new(
        case.params(),
        case.region(),
        Storage {
            shapes: &mut shapes,
            index: &mut idx,
            coverage: &mut [],
        },
    )
    .unwrap_or_else(|e| panic!("{case:?}: {e:?}"));
    let (a, z, n, c) = (e.total_area(), e.zeta(), case.n, case.c);
    // Same expression as the engine's `area_of` (checked against it below).
    let f = move |i: u64| a / (z * libm::pow(i as f64 + n, c));
    for i in [0u64, 1, 17, 1000] {
        assert_eq!(f(i).to_bits(), e.area_of(i).to_bits());
    }
    f
}

// ---------------------------------------------------------------------------------------------
// Strategies.
// ---------------------------------------------------------------------------------------------

fn shape_strategy() -> impl Strategy<Value = ShapeKind> {
    prop_oneof![
        Just(ShapeKind::Circle),
        Just(ShapeKind::Square),
        (0.2f64..5.0).prop_map(|aspect| ShapeKind::Rect { aspect }),
    ]
}

fn case_strategy() -> impl Strategy<Value = Case> {
    (
        any::<u64>(),
        1.1f64..1.45,
        0.5f64..5.0,
        shape_strategy(),
        any::<bool>(),
        prop_oneof![Just(0.0), 0.001f64..0.5],
        20.0f64..300.0,
        20.0f64..300.0,
        any::<bool>(),
    )
        .prop_map(|(seed, c, n, shape, rotate, gap, w, h, periodic)| Case {
            seed,
            c,
            n,
            shape,
            rotate,
            gap,
            w,
            h,
            periodic,
            max_trials: 200_000,
        })
}

fn base_case() -> Case {
    Case {
        seed: 7,
        c: 1.3,
        n: 1.0,
        shape: ShapeKind::Circle,
        rotate: false,
        gap: 0.0,
        w: 100.0,
        h: 100.0,
        periodic: false,
        max_trials: 1_000_000,
    }
}

/// A spread of configurations for the fixed-case tests.
fn varied_cases() -> Vec<Case> {
    let b = base_case();
    vec![
        b,
        Case {
            seed: 11,
            shape: ShapeKind::Square,
            rotate: true,
            gap: 0.1,
            ..b
        },
        Case {
            seed: 12,
            shape: ShapeKind::Rect { aspect: 3.0 },
            rotate: true,
            periodic: true,
            w: 80.0,
            h: 50.0,
            ..b
        },
        Case {
            seed: 13,
            c: 1.2,
            n: 2.0,
            periodic: true,
            gap: 0.05,
            w: 60.0,
            h: 120.0,
            ..b
        },
        Case {
            seed: 14,
            shape: ShapeKind::Rect { aspect: 0.4 },
            c: 1.4,
            n: 1.5,
            w: 40.0,
            h: 150.0,
            ..b
        },
        Case {
            seed: 15,
            shape: ShapeKind::Square,
            periodic: true,
            c: 1.35,
            n: 0.6,
            ..b
        },
    ]
}

// ---------------------------------------------------------------------------------------------
// Property tests.
// ---------------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, failure_persistence: None, rng_seed: RngSeed::Fixed(0x2f11), ..ProptestConfig::default() })]

    /// Random fills are valid, and the coverage bitmap never changes a result.
    #[test]
    fn random_fills_are_valid(case in case_strategy(), k in 50u64..400) {
        let with_cov = run(&case, k, 1 << 12);
        let without = run(&case, k, 0);
        prop_assert!(
            matches!(
                with_cov.reason,
                StopReason::Count | StopReason::Step(StepError::Halted { .. }) | StopReason::Step(StepError::CannotFit { .. })
            ),
            "unexpected stop {:?}", with_cov.reason
        );
        if with_cov.reason == StopReason::Count {
            prop_assert_eq!(with_cov.placed.len() as u64, k);
        }
        if let Err(e) = same_run(&with_cov, &without) {
            return Err(TestCaseError::fail(format!("coverage changed the result: {e}")));
        }
        if let Err(e) = check_run(&case, &with_cov) {
            return Err(TestCaseError::fail(format!("{case:?} k={k}: {e}")));
        }
    }
}

#[test]
fn coverage_sizes_never_change_results() {
    for case in varied_cases() {
        let reference = run(&case, 300, 0);
        check_run(&case, &reference).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        for words in [1usize, 3, 64, 1 << 12, 1 << 14] {
            let r = run(&case, 300, words);
            same_run(&reference, &r).unwrap_or_else(|e| panic!("{case:?} coverage {words} words: {e}"));
        }
    }
}

#[test]
fn prefix_stability() {
    for (j, base) in varied_cases().into_iter().enumerate() {
        for k in [1u64, 37, 150] {
            let case = Case {
                seed: base.seed + 100 * j as u64 + k,
                ..base
            };
            let short = run(&case, k, 1 << 12);
            let long = run(&case, 2 * k, 1 << 12);
            assert_eq!(short.reason, StopReason::Count, "{case:?}");
            assert_eq!(short.placed.len() as u64, k);
            assert!(long.placed.len() as u64 >= k);
            for i in 0..k as usize {
                assert_eq!(placed_bits(&short.placed[i]), placed_bits(&long.placed[i]), "{case:?}: shape {i}");
                assert_eq!(
                    placement_bits(&short.placements[i]),
                    placement_bits(&long.placements[i]),
                    "{case:?}: placement {i}"
                );
            }
            let t: u64 = long.placements[..k as usize].iter().map(|p| p.trials).sum();
            assert_eq!(short.stats.trials, t);
        }
    }
}

#[test]
fn determinism() {
    for case in varied_cases() {
        let a = run(&case, 200, 1 << 12);
        let b = run(&case, 200, 1 << 12);
        same_run(&a, &b).unwrap_or_else(|e| panic!("{case:?}: same seed, different runs: {e}"));
        let other = run(
            &Case {
                seed: case.seed ^ 0x5555,
                ..case
            },
            200,
            1 << 12,
        );
        assert!(same_run(&a, &other).is_err(), "{case:?}: different seeds gave the same run");
        assert_ne!(placed_bits(&a.placed[0]), placed_bits(&other.placed[0]), "{case:?}");
    }
}

#[test]
fn spatial_hash_parity_with_single_bucket() {
    for case in varied_cases() {
        let k = 300u64;
        let stop = case.stop(k);
        let full = run_with(&case, k as usize, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        let one = run_with(&case, k as usize, &stop, 1 << 12, IndexSize::OneBucket).unwrap_or_else(|e| panic!("{e:?}"));
        same_run(&full, &one).unwrap_or_else(|e| panic!("{case:?}: hash size changed the result: {e}"));
        // A bigger capacity (more buckets) must not change the result either.
        let big = run_with(&case, 4 * k as usize, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        same_run(&full, &big).unwrap_or_else(|e| panic!("{case:?}: capacity changed the result: {e}"));
        check_run(&case, &full).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    }
}

#[test]
fn every_trial_matches_brute_force() {
    for case in varied_cases() {
        let r = run(&case, 250, 1 << 12);
        assert_eq!(r.reason, StopReason::Count, "{case:?}");
        replay(&case, &r, engine_area_of(&case)).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, failure_persistence: None, rng_seed: RngSeed::Fixed(0x2f12), ..ProptestConfig::default() })]

    /// The replay oracle on random configurations: no false rejections or acceptances.
    #[test]
    fn random_trials_match_brute_force(case in case_strategy(), k in 20u64..150) {
        let case = Case { max_trials: 20_000, ..case };
        let r = run(&case, k, 1 << 10);
        if let Err(e) = replay(&case, &r, engine_area_of(&case)) {
            return Err(TestCaseError::fail(format!("{case:?} k={k}: {e}")));
        }
    }
}

#[test]
fn capacity_stops_with_all_shapes_valid() {
    for case in varied_cases() {
        let r = run_with(&case, 10, &case.stop(20), 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.reason, StopReason::Step(StepError::Capacity { capacity: 10 }), "{case:?}");
        assert_eq!(r.placed.len(), 10);
        check_run(&case, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        // Same shapes as a run that was asked for exactly 10.
        let exact = run(&case, 10, 1 << 12);
        for (p, q) in r.placed.iter().zip(&exact.placed) {
            assert_eq!(placed_bits(p), placed_bits(q));
        }
    }
    // Stepping a full engine keeps failing the same way and changes nothing.
    let case = base_case();
    let mut shapes = vec![Placed::<f64>::default(); 3];
    let mut idx = vec![0u32; index_words(3)];
    let mut e = Engine::<f64>::new(
        case.params(),
        case.region(),
        Storage {
            shapes: &mut shapes,
            index: &mut idx,
            coverage: &mut [],
        },
    )
    .unwrap_or_else(|e| panic!("{e:?}"));
    let mut rng = rng_from_seed(1);
    for _ in 0..3 {
        assert!(e.step(&mut rng).is_ok());
    }
    let before: Vec<_> = e.placed().iter().map(placed_bits).collect();
    let stats = e.stats();
    for _ in 0..3 {
        assert_eq!(e.step(&mut rng), Err(StepError::Capacity { capacity: 3 }));
    }
    assert_eq!(e.placed().iter().map(placed_bits).collect::<Vec<_>>(), before);
    assert_eq!(stats_bits(&e.stats()), stats_bits(&stats));
}

#[test]
fn fill_fraction_stop() {
    for case in varied_cases() {
        let stop = Stop {
            fill: Some(0.5),
            ..Stop::default()
        };
        let r = run_with(&case, 5000, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.reason, StopReason::Fill, "{case:?}");
        check_run(&case, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        let n = r.placed.len();
        assert!(n >= 1);
        assert!(r.stats.fill_fraction >= 0.5, "{:?}", r.stats);
        // The area before the last placement was below half (accumulated as the engine does).
        let mut sum = 0.0f64;
        for p in &r.placements[..n - 1] {
            sum += p.area;
        }
        assert!(
            sum < 0.5 * r.area,
            "{case:?}: already {} filled before the last shape",
            sum / r.area
        );
        assert!(sum + r.placements[n - 1].area >= 0.5 * r.area);
        // One fewer shape: the fill stop does not hold yet.
        let fewer = run_with(
            &case,
            5000,
            &Stop {
                count: Some(n as u64 - 1),
                ..stop
            },
            1 << 12,
            IndexSize::Full,
        )
        .unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(fewer.reason, StopReason::Count, "{case:?}");
        assert!(fewer.stats.fill_fraction < 0.5, "{:?}", fewer.stats);
        // count and fill together: whichever holds first.
        let both = run_with(
            &case,
            5000,
            &Stop {
                count: Some(n as u64 + 5),
                ..stop
            },
            1 << 12,
            IndexSize::Full,
        )
        .unwrap_or_else(|e| panic!("{e:?}"));
        same_run(&r, &both).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    }
}

#[test]
fn min_size_stop() {
    for case in varied_cases() {
        // A minimum width that the 40th shape is just above and the 41st below (roughly).
        let kind = case.shape;
        let width_of = |i: u64| {
            let a = case.w * case.h
                / (zetafill::internals::zeta::hurwitz_zeta(case.c, case.n).unwrap_or(f64::NAN) * (i as f64 + case.n).powf(case.c));
            kind.min_width(kind.scale_for_area(a))
        };
        let m = 0.5 * (width_of(40) + width_of(41));
        let stop = Stop {
            min_size: Some(m),
            ..Stop::default()
        };
        let r = run_with(&case, 5000, &stop, 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.reason, StopReason::MinSize, "{case:?}");
        check_run(&case, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        assert_eq!(r.placed.len(), 41, "{case:?}");
        for p in &r.placed {
            assert!(kind.min_width(p.scale) >= m);
        }
        let area_of = engine_area_of(&case);
        let next = kind.min_width(kind.scale_for_area(area_of(r.placed.len() as u64)));
        assert!(next < m, "{case:?}: next shape width {next} >= {m}");
        // A minimum exactly at a shape's width keeps that shape (stop is strictly below).
        let exact = kind.min_width(kind.scale_for_area(area_of(10)));
        let r = run_with(
            &case,
            5000,
            &Stop {
                min_size: Some(exact),
                ..stop
            },
            1 << 12,
            IndexSize::Full,
        )
        .unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(r.placed.len(), 11, "{case:?}");
    }
}

#[test]
fn stop_conditions_checked_before_the_first_step() {
    let case = base_case();
    for stop in [
        Stop {
            count: Some(0),
            ..Stop::default()
        },
        Stop {
            min_size: Some(f64::INFINITY),
            ..Stop::default()
        },
        Stop {
            fill: Some(0.0),
            ..Stop::default()
        },
    ] {
        let r = run_with(&case, 10, &stop, 0, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        assert!(r.placed.is_empty(), "{stop:?}");
        assert_eq!(r.stats.trials, 0);
        assert_ne!(r.reason, StopReason::Step(StepError::Capacity { capacity: 10 }));
    }
}

#[test]
fn halting_at_one_trial_keeps_everything_before() {
    for case in varied_cases() {
        let halting = Case { max_trials: 1, ..case };
        let r = run_with(&halting, 5000, &halting.stop(5000), 1 << 12, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
        let StopReason::Step(StepError::Halted { index, trials }) = r.reason else {
            panic!("{case:?}: expected a halt, got {:?}", r.reason);
        };
        assert_eq!(trials, 1);
        assert_eq!(index, r.placed.len() as u64);
        assert!(r.placements.iter().all(|p| p.trials == 1));
        assert_eq!(r.stats.trials, index + 1);
        check_run(&halting, &r).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        // The same shapes as an unlimited run: each of them took one trial there too.
        let full = run(&case, index + 1, 1 << 12);
        for i in 0..index as usize {
            assert_eq!(placed_bits(&r.placed[i]), placed_bits(&full.placed[i]));
        }
        assert!(full.placements[index as usize].trials > 1);
    }
}

#[test]
fn step_after_halt_continues() {
    // A halted step places nothing; stepping again draws new candidates.
    let case = Case {
        max_trials: 1,
        ..base_case()
    };
    let mut shapes = vec![Placed::<f64>::default(); 100];
    let mut idx = vec![0u32; index_words(100)];
    let mut e = Engine::<f64>::new(
        case.params(),
        case.region(),
        Storage {
            shapes: &mut shapes,
            index: &mut idx,
            coverage: &mut [],
        },
    )
    .unwrap_or_else(|e| panic!("{e:?}"));
    let mut rng = rng_from_seed(3);
    let mut halts = 0;
    let mut trials = 0;
    while e.placed().len() < 30 && halts < 100_000 {
        trials += 1;
        match e.step(&mut rng) {
            Ok(p) => assert_eq!(p.index + 1, e.placed().len() as u64),
            Err(StepError::Halted { index, trials: 1 }) => {
                assert_eq!(index, e.placed().len() as u64);
                halts += 1;
            }
            Err(other) => panic!("{other:?}"),
        }
    }
    assert_eq!(e.placed().len(), 30);
    assert!(halts > 0);
    assert_eq!(e.stats().trials, trials);
    let items = items_of(&e);
    check_fill(&items, case.w, case.h, case.gap, case.periodic).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn first_shape_too_large_cannot_fit() {
    // A square of almost the whole area cannot fit in a thin region.
    let case = Case {
        c: 1.9,
        n: 0.05,
        shape: ShapeKind::Square,
        w: 100.0,
        h: 10.0,
        ..base_case()
    };
    let r = run_with(&case, 10, &case.stop(10), 0, IndexSize::Full).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(r.reason, StopReason::Step(StepError::CannotFit { index: 0 }));
    assert!(r.placed.is_empty());
    assert_eq!(r.stats.trials, 0);
}

// ---------------------------------------------------------------------------------------------
// The checker can fail.
// ---------------------------------------------------------------------------------------------

fn circle(x: f64, y: f64, r: f64) -> Item {
    Item {
        centre: Point::new(x, y),
        geo: Geo::Circle { c: Point::new(x, y), r },
    }
}

fn square(x: f64, y: f64, half: f64) -> Item {
    let g = ShapeKind::Square.geo(Point::new(x, y), half, 0.0);
    Item {
        centre: Point::new(x, y),
        geo: g,
    }
}

#[test]
fn checker_accepts_valid_sets() {
    let items = [
        circle(10.0, 10.0, 5.0),
        circle(30.0, 10.0, 5.0),
        square(50.0, 50.0, 10.0),
        square(80.0, 20.0, 9.0),
    ];
    assert_eq!(check_fill(&items, 100.0, 100.0, 0.0, false), Ok(()));
    assert_eq!(check_fill(&items, 100.0, 100.0, 0.9, false), Ok(()));
    assert_eq!(check_fill(&items, 100.0, 100.0, 0.0, true), Ok(()));
    // Across the periodic edge but clear of each other's images.
    let wrap = [circle(1.0, 50.0, 3.0), circle(50.0, 50.0, 3.0), circle(50.0, 98.0, 3.0)];
    assert_eq!(check_fill(&wrap, 100.0, 100.0, 0.5, true), Ok(()));
}

#[test]
fn checker_detects_overlapping_circles() {
    let items = [circle(10.0, 10.0, 5.0), circle(19.0, 10.0, 5.0)];
    assert!(check_fill(&items, 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&items, 100.0, 100.0, 0.0, true).is_err());
    // Touching counts as overlapping; a gap too small is detected too.
    assert!(check_fill(&[circle(10.0, 10.0, 5.0), circle(20.0, 10.0, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&[circle(10.0, 10.0, 5.0), circle(20.5, 10.0, 5.0)], 100.0, 100.0, 0.6, false).is_err());
    // A circle inside a square.
    assert!(check_fill(&[square(50.0, 50.0, 10.0), circle(50.0, 50.0, 1.0)], 100.0, 100.0, 0.0, false).is_err());
}

#[test]
fn checker_detects_shape_outside_region() {
    // A square poking out of the right edge by 1e-9.
    let s = square(100.0 - 5.0 + 1e-9, 50.0, 5.0);
    assert!(check_fill(&[s], 100.0, 100.0, 0.0, false).is_err());
    // Just inside is accepted; poking through the gap by 1e-9 is not.
    assert_eq!(check_fill(&[square(95.0, 50.0, 5.0)], 100.0, 100.0, 0.0, false), Ok(()));
    assert!(check_fill(&[square(94.0 + 1e-9, 50.0, 5.0)], 100.0, 100.0, 1.0, false).is_err());
    // Poking out at the bottom and left, and a circle.
    assert!(check_fill(&[square(5.0 - 1e-9, 50.0, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&[square(50.0, 5.0 - 1e-9, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&[circle(50.0, 100.0 - 5.0 + 1e-9, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    // A rotated square whose corner pokes out.
    let g = ShapeKind::Square.geo(Point::new(94.5, 50.0), 5.0, 0.3);
    assert!(check_fill(
        &[Item {
            centre: Point::new(94.5, 50.0),
            geo: g
        }],
        100.0,
        100.0,
        0.0,
        false
    )
    .is_err());
}

#[test]
fn checker_detects_periodic_violations() {
    // Two circles overlapping only across the x edge (image at +W), and across the corner.
    let across = [circle(2.0, 50.0, 3.0), circle(97.0, 50.0, 3.0)];
    assert!(check_fill(&across, 100.0, 100.0, 0.0, true).is_err());
    let corner = [circle(1.0, 1.0, 2.0), circle(98.5, 98.5, 2.0)];
    assert!(check_fill(&corner, 100.0, 100.0, 0.0, true).is_err());
    let y_edge = [square(50.0, 1.0, 2.0), square(50.5, 98.5, 2.0)];
    assert!(check_fill(&y_edge, 100.0, 100.0, 0.0, true).is_err());
    // A gap violated only across the edge.
    let gap = [circle(3.0, 50.0, 3.0), circle(99.5, 50.0, 0.4)];
    assert_eq!(check_fill(&gap, 100.0, 100.0, 0.05, true), Ok(()));
    assert!(check_fill(&gap, 100.0, 100.0, 0.2, true).is_err());
    // A shape overlapping its own image.
    assert!(check_fill(&[circle(50.0, 50.0, 50.0)], 100.0, 100.0, 0.0, true).is_err());
    assert!(check_fill(&[square(50.0, 50.0, 30.0)], 100.0, 60.0, 0.0, true).is_err());
    // A centre outside the period.
    assert!(check_fill(&[circle(100.0, 50.0, 1.0)], 100.0, 100.0, 0.0, true).is_err());
    assert!(check_fill(&[circle(-1e-12, 50.0, 1.0)], 100.0, 100.0, 0.0, true).is_err());
    // An overlap only with an image two periods away (a long thin diagonal rectangle).
    let r = ShapeKind::Rect { aspect: 40.0 };
    let g = r.geo(Point::new(10.0, 10.0), 0.6, libm::atan2(20.0, 40.0));
    let long = Item {
        centre: Point::new(10.0, 10.0),
        geo: g,
    };
    assert!(check_fill(&[long], 20.0, 20.0, 0.0, true).is_err());
    // A centre that does not match its geometry.
    let mut bad = circle(10.0, 10.0, 1.0);
    bad.centre.x = 11.0;
    assert!(check_fill(&[bad], 100.0, 100.0, 0.0, false).is_err());
}

// ---------------------------------------------------------------------------------------------
// No panics on any input.
// ---------------------------------------------------------------------------------------------

/// The payload of the budget panic (a harness device, not an engine failure): a valid run with
/// an astronomically large trial limit may legitimately take forever.
struct OutOfBudget;

struct BudgetRng {
    inner: ZetaRng,
    left: u64,
}

impl RngCore for BudgetRng {
    fn next_u32(&mut self) -> u32 {
        self.next_u64() as u32
    }
    fn next_u64(&mut self) -> u64 {
        if self.left == 0 {
            std::panic::panic_any(OutOfBudget);
        }
        self.left -= 1;
        self.inner.next_u64()
    }
    fn fill_bytes(&mut self, dst: &mut [u8]) {
        for chunk in dst.chunks_mut(8) {
            let b = self.next_u64().to_le_bytes();
            chunk.copy_from_slice(&b[..chunk.len()]);
        }
    }
}

fn quiet_budget_panics() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if info.payload().downcast_ref::<OutOfBudget>().is_none() {
                default(info);
            }
        }));
    });
}

fn special_f64() -> impl Strategy<Value = f64> {
    prop::sample::select(vec![
        f64::NAN,
        -f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        f64::MIN_POSITIVE,
        5e-324,
        -5e-324,
        f64::MAX,
        f64::MIN,
        1.0,
        -1.0,
        1.0 + f64::EPSILON,
        1.0 - f64::EPSILON / 2.0,
        2.0,
        1e-300,
        1e300,
        1e-10,
        1e10,
        1e154,
        1.5e-154,
        0.5,
    ])
}

/// Any f64 bit pattern, special values, and plausible values.
fn any_f64(plausible: std::ops::Range<f64>) -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => any::<u64>().prop_map(f64::from_bits),
        2 => special_f64(),
        3 => plausible,
    ]
}

fn any_shape() -> impl Strategy<Value = ShapeKind> {
    prop_oneof![
        2 => Just(ShapeKind::Circle),
        2 => Just(ShapeKind::Square),
        4 => any_f64(0.01..100.0).prop_map(|aspect| ShapeKind::Rect { aspect }),
        // The other kinds, for the no-panic guarantee only.
        1 => Just(ShapeKind::Triangle),
        1 => prop_oneof![any::<u8>(), 3u8..49].prop_map(|sides| ShapeKind::Polygon { sides }),
        1 => (prop_oneof![any::<u8>(), 2u8..25], any_f64(0.0..1.0)).prop_map(|(points, inner)| ShapeKind::Star { points, inner }),
        1 => any_f64(0.0..1.0).prop_map(|inner| ShapeKind::Ring { inner }),
        1 => any_f64(0.0..0.34).prop_map(|delta| ShapeKind::Blob { delta }),
    ]
}

/// Rectangles mostly; discs and annuli for the no-panic guarantee.
fn any_region(width: f64, height: f64, periodic: bool, pick: u8) -> Region<'static> {
    match pick % 8 {
        6 => Region::Circle { radius: width },
        7 => Region::Annulus {
            outer: width,
            inner: height,
        },
        _ => Region::Rect { width, height, periodic },
    }
}

#[derive(Debug, Clone)]
struct Wild {
    params: Params,
    region: Region<'static>,
    shapes: usize,
    index: usize,
    coverage: usize,
    /// Cells lent to the cell sampler (none: the engine's error path).
    cells: usize,
    seed: u64,
}

/// Cell pools for the cell sampler: none, a few, or plenty.
fn any_cells() -> impl Strategy<Value = usize> {
    prop_oneof![0usize..8, Just(64), Just(4096)]
}

fn wild_strategy() -> impl Strategy<Value = Wild> {
    (
        (any_f64(1.0..3.0), any_f64(0.0..10.0), any_shape(), any::<bool>(), any_f64(0.0..2.0)),
        prop_oneof![any::<u64>(), 0u64..4, Just(u64::MAX)],
        (any_f64(0.0..200.0), any_f64(0.0..200.0), any::<bool>(), any::<u8>()),
        (0usize..5, 0usize..20, 0usize..4, any_cells(), any::<u64>()),
    )
        .prop_map(
            |((c, n_offset, shape, rotate, gap), max_trials, (width, height, periodic, pick), (shapes, index, coverage, cells, seed))| {
                Wild {
                    params: Params {
                        c,
                        n_offset,
                        shape: shape.into(),
                        rotate,
                        gap,
                        max_trials,
                    },
                    region: any_region(width, height, periodic, pick),
                    shapes,
                    index,
                    coverage,
                    cells,
                    seed,
                }
            },
        )
}

/// Mostly valid values, with edge values that are still valid and an occasional wild one.
fn near_valid(plausible: std::ops::Range<f64>, edges: &[f64]) -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => any::<u64>().prop_map(f64::from_bits),
        1 => special_f64(),
        3 => prop::sample::select(edges.to_vec()),
        6 => plausible,
    ]
}

/// Inputs that mostly pass `Engine::new`, so the run itself meets the extremes.
fn near_valid_strategy() -> impl Strategy<Value = Wild> {
    const SIZES: [f64; 9] = [5e-324, 1e-300, 1e-10, 0.5, 1e10, 1e154, 1e300, f64::MAX, 3.0];
    let shape = prop_oneof![
        Just(ShapeKind::Circle),
        Just(ShapeKind::Square),
        near_valid(0.01..100.0, &[5e-324, 1e-300, 1e-8, 1e8, 1e300, f64::MAX]).prop_map(|aspect| ShapeKind::Rect { aspect }),
    ];
    (
        (
            near_valid(1.0..3.0, &[1.0 + f64::EPSILON, 1.0000001, 1.001, 10.0, 1e3, 1e300]),
            near_valid(0.0..10.0, &[5e-324, 1e-300, 1e-10, 1e10, 1e300, f64::MAX]),
            shape,
            any::<bool>(),
            prop_oneof![3 => Just(0.0), 2 => 0.0f64..1.0, 1 => near_valid(0.0..1.0, &[5e-324, 1e-300, 1e300])],
        ),
        prop_oneof![1u64..1000, Just(u64::MAX), any::<u64>()],
        (
            near_valid(0.0..200.0, &SIZES),
            near_valid(0.0..200.0, &SIZES),
            any::<bool>(),
            0.0f64..0.5,
            any::<bool>(),
            any::<u8>(),
        ),
        (1usize..8, 0usize..16, 0usize..4, any_cells(), any::<u64>()),
    )
        .prop_map(
            |(
                (c, n_offset, shape, rotate, gap),
                max_trials,
                (width, height, periodic, g, gap_rel, pick),
                (shapes, extra, coverage, cells, seed),
            )| {
                // Half the time the gap is a fraction of the region (up to just under half).
                let gap = if gap_rel { g * width.min(height) } else { gap };
                Wild {
                    params: Params {
                        c,
                        n_offset,
                        shape: shape.into(),
                        rotate,
                        gap,
                        max_trials,
                    },
                    region: any_region(width, height, periodic, pick),
                    shapes,
                    index: shapes + 1 + extra,
                    coverage,
                    cells,
                    seed,
                }
            },
        )
}

/// Which sampler a wild run uses.
#[derive(Clone, Copy, Debug)]
enum Sampler {
    Reference,
    /// The cell sampler over the wild run's cell pool.
    Cells,
}

/// Builds and runs an engine on arbitrary inputs. `Ok(None)`: rejected by `Engine::new` (or,
/// for the cell sampler, an empty pool refused by `CellSampler::new`).
fn wild_run<S: Scalar>(w: &Wild, sampler: Sampler) -> Result<Option<(StopReason, Stats)>, ParamError> {
    let mut shapes = vec![Placed::<S>::default(); w.shapes];
    let mut idx = vec![0u32; w.index];
    let mut cov = vec![0u64; w.coverage];
    let mut pool = vec![[0u64; 4]; w.cells];
    let mut e = Engine::<S>::new(
        w.params,
        w.region,
        Storage {
            shapes: &mut shapes,
            index: &mut idx,
            coverage: &mut cov,
        },
    )?;
    let mut rng = BudgetRng {
        inner: rng_from_seed(w.seed),
        left: 30_000,
    };
    let stop = Stop {
        count: Some(5),
        ..Stop::default()
    };
    let on_place = |p: &Placement<S>| {
        let _ = p.area;
    };
    let reason = match sampler {
        Sampler::Reference => e.run(&mut rng, &stop, on_place),
        Sampler::Cells => {
            let Ok(mut cells) = CellSampler::new(&mut pool) else {
                return Ok(None);
            };
            let _ = e.prepare_fast(&mut cells);
            let reason = e.run_fast(&mut cells, &mut rng, &stop, on_place);
            let _ = (cells.stats(), cells.live_area(), cells.live_boxes().count());
            reason
        }
    };
    for i in 0..e.placed().len() + 2 {
        let _ = e.geo(i);
    }
    let _ = (
        e.coverage_fraction(),
        e.area_of(u64::MAX),
        e.capacity(),
        e.zeta(),
        format!("{reason:?}"),
    );
    if let StopReason::Step(s) = reason {
        let _ = s.to_string();
    }
    Ok(Some((reason, e.stats())))
}

/// Runs `w` with both samplers, on `f64` and on fixed point: none may panic (other than
/// running out of the random-number budget), place more than asked or more than fits.
fn check_no_panic(w: &Wild) -> Result<(), TestCaseError> {
    quiet_budget_panics();
    for (scalar, sampler) in [
        ("f64", Sampler::Reference),
        ("f64", Sampler::Cells),
        ("fixed", Sampler::Reference),
        ("fixed", Sampler::Cells),
    ] {
        let run = || {
            if scalar == "f64" {
                wild_run::<f64>(w, sampler)
            } else {
                wild_run::<Fixed>(w, sampler)
            }
        };
        match catch_unwind(AssertUnwindSafe(run)) {
            Ok(Ok(Some((reason, stats)))) => {
                prop_assert!(stats.placed <= 5, "{scalar} {sampler:?}: {:?}", stats);
                prop_assert!(stats.placed <= w.shapes as u64, "{scalar} {sampler:?}: {:?}", stats);
                if reason == StopReason::Count {
                    prop_assert_eq!(stats.placed, 5, "{} {:?}", scalar, sampler);
                }
            }
            Ok(Ok(None)) => {}
            Ok(Err(e)) => {
                let _ = e.to_string();
            }
            Err(payload) => {
                if payload.downcast_ref::<OutOfBudget>().is_none() {
                    let msg = payload
                        .downcast_ref::<String>()
                        .cloned()
                        .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                        .unwrap_or_default();
                    return Err(TestCaseError::fail(format!("{scalar} {sampler:?}: panic {msg:?} for {w:?}")));
                }
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 5000, failure_persistence: None, rng_seed: RngSeed::Fixed(0x2f13), ..ProptestConfig::default() })]

    #[test]
    fn engine_never_panics(w in wild_strategy()) {
        check_no_panic(&w)?;
    }

    #[test]
    fn engine_never_panics_near_valid(w in near_valid_strategy()) {
        check_no_panic(&w)?;
    }

    #[test]
    fn zeta_never_panics(s in any_f64(0.0..5.0), a in any_f64(0.0..100.0), n in prop_oneof![any::<u64>(), 0u64..200, Just(u64::MAX)]) {
        let res = catch_unwind(|| {
            (
                zetafill::internals::zeta::hurwitz_zeta(s, a),
                zetafill::internals::zeta::zeta(s, a),
                zetafill::internals::zeta::partial_sum(s, a, n),
                zetafill::internals::zeta::tail_sum(s, a, n),
                zetafill::internals::zeta::table_lookup(s, a),
            )
        });
        let Ok((h, z, p, t, _)) = res else {
            return Err(TestCaseError::fail(format!("panic for s={s:e} a={a:e} n={n}")));
        };
        prop_assert_eq!(h.map(f64::to_bits), z.map(f64::to_bits), "zeta and hurwitz_zeta differ at s={:e} a={:e}", s, a);
        // Finite whenever Ok. (Not checked here: the sign. partial_sum can return negative
        // values by cancellation; see zeta_reference.rs, partial_sum_near_s_1_is_accurate.)
        for v in [h, p, t].into_iter().flatten() {
            prop_assert!(v.is_finite(), "bad value {:e} at s={:e} a={:e} n={}", v, s, a, n);
        }
        for v in [h, t].into_iter().flatten() {
            prop_assert!(v >= 0.0, "negative value {:e} at s={:e} a={:e} n={}", v, s, a, n);
        }
        let valid_a = a.is_finite() && a > 0.0;
        if !(s.is_finite() && s > 1.0) || !valid_a {
            prop_assert!(h.is_err());
        }
        if !(s.is_finite() && s > 0.0) || !valid_a {
            prop_assert!(p.is_err());
        }
        if !valid_a {
            prop_assert!(t.is_err());
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Regression: images more than one period away.
// ---------------------------------------------------------------------------------------------

/// A rotated elongated shape in a narrow torus can reach more than one period. `Engine::clear`
/// once tested only the images one period away, so shape 1's image two periods to the right,
/// (x + 2W, y), overlapped shape 0 and was accepted. Now every image within reach is tested.
#[test]
fn periodic_images_beyond_one_period_are_tested() {
    let case = Case {
        seed: 19,
        c: 1.3,
        n: 2.0,
        shape: ShapeKind::Rect { aspect: 4.0 },
        rotate: true,
        gap: 0.0,
        w: 30.0,
        h: 200.0,
        periodic: true,
        max_trials: 100_000,
    };
    let r = run(&case, 2, 0);
    assert_eq!(r.reason, StopReason::Count);
    check_fill(&r.items, case.w, case.h, case.gap, case.periodic).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    // More of the same: narrow tori, rotated rectangles within the proptest's ranges.
    for (aspect, w) in [(4.0, 25.0), (5.0, 25.0), (3.0, 25.0)] {
        for seed in 0..100u64 {
            let case = Case {
                seed,
                shape: ShapeKind::Rect { aspect },
                w,
                ..case
            };
            let r = run(&case, 100, 0);
            check_fill(&r.items, case.w, case.h, case.gap, case.periodic).unwrap_or_else(|e| panic!("{case:?}: {e}"));
        }
    }
}
