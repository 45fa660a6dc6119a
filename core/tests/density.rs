//! Density maps: both samplers draw each centre with probability proportional to the density
//! over the valid centres.
//!
//! - The first circle of a fill (tiny, so every centre of the box is valid) lands by a ramp
//!   density: a chi-square test of its x over ten bins against `rho = x / 100` integrated
//!   over each bin, for the paper's sampler and the cell sampler; the same test rejects the
//!   fills made without the density (the check can fail).
//! - Later placements, where the fill shapes the valid set: a Kolmogorov-Smirnov test of the
//!   two samplers against each other on noise density, and a mask that nothing crosses.
//! - No density is the paper's rule, bit for bit: the digest with `set_density(None)` is the
//!   digest of an engine never given one.
//! - A density that bounds itself over boxes ([`Density::max_over`]) lets the cell sampler draw
//!   its cells by area times that bound: the same tests pass with bounds (and fail with a bound
//!   that lies), cells where the bound is 0 are never live, and low-density cells cost fewer
//!   trials.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{ks, Buffers};
use zetafill::{cells_for, digest, rng_from_seed, CellSampler, Density, Engine, Noise, NoiseKind, Params, Region, Stop};

const SIDE: f64 = 100.0;

fn square() -> Region<'static> {
    Region::Rect {
        width: SIDE,
        height: SIDE,
        periodic: false,
    }
}

/// `rho = x / 100`.
struct Ramp;

impl Density for Ramp {
    fn at(&self, x: f64, _y: f64) -> f64 {
        x / SIDE
    }
}

/// Zero left of x = 20.
struct Mask;

impl Density for Mask {
    fn at(&self, x: f64, _y: f64) -> f64 {
        if x < 20.0 {
            0.0
        } else {
            1.0
        }
    }
}

/// The ramp, with its exact bound over a box: its right edge's value.
struct BoundedRamp;

impl Density for BoundedRamp {
    fn at(&self, x: f64, _y: f64) -> f64 {
        x / SIDE
    }
    fn max_over(&self, _x0: f64, _y0: f64, x1: f64, _y1: f64) -> f64 {
        (x1 / SIDE).clamp(0.0, 1.0)
    }
}

/// The ramp with a bound four times too low: a broken density that the tests must catch.
struct LyingRamp;

impl Density for LyingRamp {
    fn at(&self, x: f64, _y: f64) -> f64 {
        x / SIDE
    }
    fn max_over(&self, _x0: f64, _y0: f64, x1: f64, _y1: f64) -> f64 {
        (x1 / SIDE).clamp(0.0, 1.0) / 4.0
    }
}

/// Blocks of 10 by 10 mm at six levels from 0 to 1, with the exact bound: the largest level
/// among the blocks a box touches.
struct Blocks;

impl Blocks {
    const LEVELS: [f64; 6] = [0.0, 0.02, 0.1, 0.3, 0.6, 1.0];

    fn block(i: i64, j: i64) -> f64 {
        let (i, j) = (i.clamp(0, 9), j.clamp(0, 9));
        Self::LEVELS[((i * 7 + j * 3 + i * j) % 6) as usize]
    }
}

impl Density for Blocks {
    fn at(&self, x: f64, y: f64) -> f64 {
        Self::block((x / 10.0).floor() as i64, (y / 10.0).floor() as i64)
    }
    fn max_over(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let (i0, i1) = ((x0 / 10.0).floor() as i64, (x1 / 10.0).floor() as i64);
        let (j0, j1) = ((y0 / 10.0).floor() as i64, (y1 / 10.0).floor() as i64);
        let mut m = 0f64;
        for i in i0.max(0)..=i1.min(9) {
            for j in j0.max(0)..=j1.min(9) {
                m = m.max(Self::block(i, j));
            }
        }
        m
    }
}

/// Zero left of x = 20, with the exact bound.
struct BoundedMask;

impl Density for BoundedMask {
    fn at(&self, x: f64, y: f64) -> f64 {
        Mask.at(x, y)
    }
    fn max_over(&self, _x0: f64, _y0: f64, x1: f64, _y1: f64) -> f64 {
        if x1 < 20.0 {
            0.0
        } else {
            1.0
        }
    }
}

/// 0.01 left of x = 90, 1 right of it: with `bounded`, its exact bound over boxes.
struct Sparse {
    bounded: bool,
}

impl Density for Sparse {
    fn at(&self, x: f64, _y: f64) -> f64 {
        if x < 90.0 {
            0.01
        } else {
            1.0
        }
    }
    fn max_over(&self, _x0: f64, _y0: f64, x1: f64, _y1: f64) -> f64 {
        if !self.bounded || x1 >= 90.0 {
            1.0
        } else {
            0.01
        }
    }
}

/// Noise with its contrast raised: `rho = 0.5 + 4 (noise - 0.5)`, clamped to `[0, 1]`.
struct Sharp(Noise);

impl Density for Sharp {
    fn at(&self, x: f64, y: f64) -> f64 {
        (0.5 + 4.0 * (self.0.at(x, y) - 0.5)).clamp(0.0, 1.0)
    }
}

/// The centres (x, y) of a fill of `count` circles, with the paper's sampler or the cells.
fn fill(params: &Params, density: Option<&dyn Density>, fast: bool, seed: u64, count: u64) -> Vec<(f64, f64)> {
    let mut b = Buffers::<f64>::new(count as usize);
    let mut e = Engine::new(params.clone(), square(), b.storage(&mut [])).expect("valid");
    e.set_density(density);
    let mut rng = rng_from_seed(seed);
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    if fast {
        let mut pool = vec![[0u64; 4]; cells_for(count as usize)];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        e.run_fast(&mut cells, &mut rng, &stop, |_| {});
    } else {
        e.run(&mut rng, &stop, |_| {});
    }
    e.placed().iter().map(|p| (p.x, p.y)).collect()
}

/// Pearson's chi-square of the first circle's x over ten bins against the ramp, over `runs`
/// fills.
fn ramp_chi2(density: Option<&dyn Density>, fast: bool, runs: u64) -> f64 {
    // N = 400: the first circle's radius is about 0.2 mm.
    let params = Params::circles(1.3, 400.0);
    let r = (SIDE * SIDE
        / (zetafill::AreaSequence::new(SIDE * SIDE, 1.3, 400.0).expect("zeta").zeta() * 400f64.powf(1.3))
        / std::f64::consts::PI)
        .sqrt();
    let (lo, hi) = (r, SIDE - r);
    let mut counts = [0f64; 10];
    for seed in 0..runs {
        let x = fill(&params, density, fast, 1000 + seed, 1)[0].0;
        let k = (((x - lo) / (hi - lo)) * 10.0).floor().clamp(0.0, 9.0) as usize;
        counts[k] += 1.0;
    }
    let total = (hi * hi - lo * lo) / 2.0;
    (0..10)
        .map(|k| {
            let (a, b) = (lo + (hi - lo) * k as f64 / 10.0, lo + (hi - lo) * (k + 1) as f64 / 10.0);
            let want = runs as f64 * (b * b - a * a) / 2.0 / total;
            (counts[k] - want).powi(2) / want
        })
        .sum()
}

/// The chi-square value with 9 degrees of freedom exceeded with probability 0.001.
const CHI2_9_0001: f64 = 27.877;

#[test]
fn first_centres_follow_the_density_in_both_samplers() {
    for fast in [false, true] {
        let chi2 = ramp_chi2(Some(&Ramp), fast, 3000);
        assert!(chi2 < CHI2_9_0001, "fast {fast}: chi-square {chi2:.1}");
        // The test can fail: uniform centres are far from the ramp.
        let uniform = ramp_chi2(None, fast, 3000);
        assert!(uniform > 10.0 * CHI2_9_0001, "fast {fast}: uniform chi-square {uniform:.1}");
    }
}

#[test]
fn both_samplers_place_the_same_distribution_under_noise() {
    let noise = Sharp(Noise::new(NoiseKind::Gradient, 5, 30.0, 3, 0.5, None).expect("noise"));
    let params = Params::circles(1.3, 2.0);
    // Placement 12's x and y, and its density, over 300 fills a side.
    let pick = |fast: bool| {
        let (mut xs, mut ys, mut rho) = (Vec::new(), Vec::new(), Vec::new());
        for seed in 0..300 {
            let c = fill(&params, Some(&noise), fast, 7000 + seed, 13);
            let (x, y) = c[12];
            xs.push(x);
            ys.push(y);
            rho.push(noise.at(x, y));
        }
        (xs, ys, rho)
    };
    let (a, b) = (pick(false), pick(true));
    for (name, p, q) in [("x", &a.0, &b.0), ("y", &a.1, &b.1), ("rho", &a.2, &b.2)] {
        let (d, pv) = ks(p, q);
        assert!(pv > 0.01 / 3.0, "{name}: D {d:.3}, p {pv:.4}");
    }
    // Placed where the noise is high: the mean density at the centres is above the field's
    // mean over the square (the check can fail: uniform centres sit at the mean).
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let field = mean(
        &(0..10_000)
            .map(|k| noise.at((k % 100) as f64 + 0.5, (k / 100) as f64 + 0.5))
            .collect::<Vec<_>>(),
    );
    let uniform = (0..300)
        .map(|s| fill(&params, None, true, 7000 + s, 13)[12])
        .map(|(x, y)| noise.at(x, y))
        .collect::<Vec<_>>();
    assert!(
        mean(&a.2) > field + 0.05 && mean(&b.2) > field + 0.05,
        "{} {} against {field}",
        mean(&a.2),
        mean(&b.2)
    );
    assert!((mean(&uniform) - field).abs() < 0.05, "{} against {field}", mean(&uniform));
}

#[test]
fn a_zero_density_is_a_mask() {
    let params = Params::circles(1.3, 20.0);
    for fast in [false, true] {
        let c = fill(&params, Some(&Mask), fast, 3, 100);
        assert_eq!(c.len(), 100);
        assert!(c.iter().all(|&(x, _)| x >= 20.0), "fast {fast}: a centre in the mask");
        // Without the mask the left part is used.
        assert!(fill(&params, None, fast, 3, 100).iter().any(|&(x, _)| x < 20.0));
    }
}

#[test]
fn no_density_is_the_papers_rule_bit_for_bit() {
    let params = Params::circles(1.3, 1.0);
    for fast in [false, true] {
        let digest_of = |set: bool| {
            let mut b = Buffers::<f64>::new(300);
            let mut e = Engine::new(params.clone(), square(), b.storage(&mut [])).expect("valid");
            if set {
                e.set_density(None);
            }
            let stop = Stop {
                count: Some(300),
                ..Stop::default()
            };
            let mut rng = rng_from_seed(9);
            if fast {
                let mut pool = vec![[0u64; 4]; cells_for(300)];
                let mut cells = CellSampler::new(&mut pool).expect("cells");
                e.run_fast(&mut cells, &mut rng, &stop, |_| {});
            } else {
                e.run(&mut rng, &stop, |_| {});
            }
            digest::engine_digest(&e)
        };
        assert_eq!(digest_of(false), digest_of(true));
    }
}

#[test]
fn cells_drawn_by_their_density_bound_keep_the_distribution() {
    let chi2 = ramp_chi2(Some(&BoundedRamp), true, 3000);
    assert!(chi2 < CHI2_9_0001, "bounded ramp: chi-square {chi2:.1}");
    // A bound below the density breaks it, and the test sees it.
    let liar = ramp_chi2(Some(&LyingRamp), true, 3000);
    assert!(liar > 5.0 * CHI2_9_0001, "lying bound: chi-square {liar:.1}");
}

#[test]
fn both_samplers_place_the_same_distribution_with_bounded_blocks() {
    let params = Params::circles(1.3, 2.0);
    // Placement 12's x and y, and its density, over 300 fills a side.
    let pick = |fast: bool| {
        let (mut xs, mut ys, mut rho) = (Vec::new(), Vec::new(), Vec::new());
        for seed in 0..300 {
            let c = fill(&params, Some(&Blocks), fast, 9000 + seed, 13);
            let (x, y) = c[12];
            xs.push(x);
            ys.push(y);
            rho.push(Blocks.at(x, y));
        }
        (xs, ys, rho)
    };
    let (a, b) = (pick(false), pick(true));
    for (name, p, q) in [("x", &a.0, &b.0), ("y", &a.1, &b.1), ("rho", &a.2, &b.2)] {
        let (d, pv) = ks(p, q);
        assert!(pv > 0.01 / 3.0, "{name}: D {d:.3}, p {pv:.4}");
    }
    assert!(b.2.iter().all(|&r| r > 0.0), "a centre where the density is 0");
}

#[test]
fn cells_where_the_bound_is_zero_are_never_live() {
    let live_area = |density: &dyn Density| {
        let mut b = common::Buffers::<f64>::new(10);
        let mut e = Engine::new(Params::circles(1.3, 20.0), square(), b.storage(&mut [])).expect("valid");
        e.set_density(Some(density));
        let mut pool = vec![[0u64; 4]; cells_for(10)];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        assert!(e.prepare_fast(&mut cells));
        cells.live_area()
    };
    // The level-0 cells are 6.25 mm wide: three columns lie left of x = 20.
    assert!(live_area(&BoundedMask) <= 8125.0 + 1e-9, "{}", live_area(&BoundedMask));
    // Without the bound every cell is live (the check can fail).
    assert!(live_area(&Mask) > 9999.0, "{}", live_area(&Mask));
}

#[test]
fn low_density_cells_cost_fewer_trials() {
    let trials = |bounded: bool| {
        let mut b = common::Buffers::<f64>::new(200);
        let mut e = Engine::new(Params::circles(1.3, 20.0), square(), b.storage(&mut [])).expect("valid");
        let density = Sparse { bounded };
        e.set_density(Some(&density));
        let mut pool = vec![[0u64; 4]; cells_for(200)];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        let stop = Stop {
            count: Some(200),
            ..Stop::default()
        };
        e.run_fast(&mut cells, &mut rng_from_seed(4), &stop, |_| {});
        e.stats().trials
    };
    // Expected about 10000 / 1090 = 9.2 trials a placement at first without the bound, and
    // (9000 / 8 + 1000) / 1090 = 1.9 with it.
    let (with, without) = (trials(true), trials(false));
    assert!(2 * with < without, "{with} trials with the bound, {without} without");
}
