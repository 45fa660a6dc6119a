//! No panics on any input.

use super::*;

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
        1 => (any_f64(0.0..1.0), any::<u8>(), any::<u8>()).prop_map(|(amplitude, features, octaves)| ShapeKind::Noisy {
            amplitude,
            features,
            octaves
        }),
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
        w.params.clone(),
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
