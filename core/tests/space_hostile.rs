//! The 3D engine under hostile parameters: NaN, infinities, 0, negative, huge and tiny values
//! of c, N, sizes and gaps, and bad proportions, through both scalars, never panic; storage
//! too small is refused; a first solid wider than the region is `CannotFit`.

use zetafill::internals::space::V3;
use zetafill::space::{
    index_words as space_index_words, Engine as SpaceEngine, Params as SpaceParams, Placed as PlacedSolid, Region as SpaceRegion, Solid,
    Storage as SpaceStorage,
};
use zetafill::{rng_from_seed, Fixed, StepError, Stop};

fn kinds() -> Vec<Solid> {
    vec![
        Solid::Sphere,
        Solid::Cube,
        Solid::Tetrahedron,
        Solid::Octahedron,
        Solid::Shell { inner: 0.7 },
        Solid::Torus { ratio: 0.3 },
    ]
}

fn regions() -> Vec<SpaceRegion> {
    vec![SpaceRegion::Box {
        width: 40.0,
        height: 30.0,
        depth: 35.0,
        periodic: false,
    }]
}

#[test]
fn hostile_parameters_never_panic() {
    let wild = [
        f64::NAN,
        f64::INFINITY,
        -f64::INFINITY,
        0.0,
        -1.0,
        1e-300,
        1e300,
        1.0,
        1.3,
        2.0,
        5e-324,
    ];
    let mut n = 0;
    for &c in &wild {
        for &nn in &wild {
            for &side in &wild {
                for &gap in &[0.0, f64::NAN, 1e300, 0.1] {
                    for kind in kinds()
                        .into_iter()
                        .chain([Solid::Shell { inner: f64::NAN }, Solid::Torus { ratio: 0.01 }])
                    {
                        let params = SpaceParams {
                            solids: kind.into(),
                            rotate: true,
                            gap,
                            max_trials: 50,
                            ..SpaceParams::spheres(c, nn)
                        };
                        for region in [
                            SpaceRegion::Box {
                                width: side,
                                height: 10.0,
                                depth: 10.0,
                                periodic: n % 2 == 0,
                            },
                            SpaceRegion::Ball { radius: side },
                            SpaceRegion::BoxMinusBall {
                                width: 10.0,
                                height: 10.0,
                                depth: 10.0,
                                centre: [5.0, 5.0, side],
                                radius: 1.0,
                            },
                        ] {
                            n += 1;
                            let mut solids = vec![PlacedSolid::<f64>::default(); 4];
                            let mut index = vec![0u32; space_index_words(4)];
                            let storage = SpaceStorage {
                                solids: &mut solids,
                                index: &mut index,
                            };
                            if let Ok(mut e) = SpaceEngine::<f64>::new(params.clone(), region, storage) {
                                let r = e.run(
                                    &mut rng_from_seed(n),
                                    &Stop {
                                        count: Some(4),
                                        ..Stop::default()
                                    },
                                    |_| {},
                                );
                                let _ = r;
                            }
                            let mut solids = vec![PlacedSolid::<Fixed>::default(); 3];
                            let mut index = vec![0u32; space_index_words(3)];
                            let storage = SpaceStorage {
                                solids: &mut solids,
                                index: &mut index,
                            };
                            if let Ok(mut e) = SpaceEngine::<Fixed>::new(params.clone(), region, storage) {
                                let _ = e.run(
                                    &mut rng_from_seed(n),
                                    &Stop {
                                        count: Some(3),
                                        ..Stop::default()
                                    },
                                    |_| {},
                                );
                            }
                        }
                    }
                }
            }
        }
    }
    // Storage too small, a first solid too large.
    let mut solids = [PlacedSolid::<f64>::default(); 2];
    let mut index = [0u32; 2];
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    assert!(SpaceEngine::<f64>::new(SpaceParams::spheres(1.3, 1.0), regions()[0], storage).is_err());
    let mut solids = [PlacedSolid::<f64>::default(); 2];
    let mut index = [0u32; 8];
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    let flat = SpaceRegion::Box {
        width: 100.0,
        height: 100.0,
        depth: 0.5,
        periodic: false,
    };
    let mut e = SpaceEngine::<f64>::new(SpaceParams::spheres(1.3, 1.0), flat, storage).expect("valid");
    assert_eq!(e.step(&mut rng_from_seed(1)).err(), Some(StepError::CannotFit { index: 0 }));
    let _ = V3::<f64>::default();
}
