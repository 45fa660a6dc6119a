//! The replay oracle: every trial the engine made, re-derived from the RNG and decided by brute force.

use super::*;

/// Whether candidate `g` (centre `c`) would be accepted after `placed`: inside the region (or
/// free of its own images), and clear of every placed shape and image. Brute force.
pub(super) fn brute_accepts(case: &Case, placed: &[Item], g: &Geo<f64>) -> bool {
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
            Geo::Poly { ref v, .. } => v.iter().all(|p| inside(p.x, p.y)),
            Geo::Motif { .. } => false,
        };
        if !ok {
            return false;
        }
    }
    let offs: &[f64] = if case.periodic { &[0.0, 1.0, -1.0] } else { &[0.0] };
    for p in placed {
        for &ky in offs {
            for &kx in offs {
                let gi = if kx == 0.0 && ky == 0.0 {
                    g.clone()
                } else {
                    g.shift(kx * w, ky * h)
                };
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
pub(super) fn replay(case: &Case, r: &Run, e_area_of: impl Fn(u64) -> f64) -> Result<(), String> {
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

pub(super) fn engine_area_of(case: &Case) -> impl Fn(u64) -> f64 {
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
