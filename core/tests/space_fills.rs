//! The 3D engine checked by geometry written here (not the engine's): every solid inside its
//! region and no two closer than the gap, for every solid and region kind, on `f64` and fixed
//! point; a checker twin that must fail on broken fills; determinism, prefix stability, a
//! golden digest, hostile parameters, and fill fractions.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

use zetafill::digest::space_digest;
use zetafill::space::{
    index_words as space_index_words, Engine as SpaceEngine, Params as SpaceParams, Placed as PlacedSolid, Region as SpaceRegion, Solid,
    SolidList, Storage as SpaceStorage,
};
use zetafill::{rng_from_seed, Fixed, MixOrder, Scalar, Stop, StopReason};

type P = [f64; 3];
/// A placed solid as the checker reads it: kind, centre, scale, quaternion.
type Rec = (Solid, P, f64, [f64; 4]);

fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A solid sampled densely as points of its surface and interior, computed here from its
/// centre, scale and quaternion (independent of the engine's tables): the checker measures
/// distances between point clouds and subtracts a bound on the sampling error.
struct Cloud {
    pts: Vec<P>,
    /// Every point of the solid is within this of a sample.
    err: f64,
    centre: P,
    radius: f64,
}

fn rot(q: [f64; 4], v: P) -> P {
    let [w, x, y, z] = q;
    // v' = q v q*, written out.
    let t = [
        2.0 * (y * v[2] - z * v[1]),
        2.0 * (z * v[0] - x * v[2]),
        2.0 * (x * v[1] - y * v[0]),
    ];
    [
        v[0] + w * t[0] + (y * t[2] - z * t[1]),
        v[1] + w * t[1] + (z * t[0] - x * t[2]),
        v[2] + w * t[2] + (x * t[1] - y * t[0]),
    ]
}

/// The surface of a solid (material boundary) sampled with spacing about `h` of its scale.
fn cloud(kind: Solid, c: P, s: f64, q: [f64; 4]) -> Cloud {
    let n = 12usize;
    let mut pts = Vec::new();
    let mut push = |v: P| {
        let r = rot(q, v);
        pts.push([c[0] + r[0], c[1] + r[1], c[2] + r[2]]);
    };
    let sphere = |r: f64, push: &mut dyn FnMut(P)| {
        for i in 0..=n {
            let th = std::f64::consts::PI * i as f64 / n as f64;
            for j in 0..2 * n {
                let ph = std::f64::consts::PI * j as f64 / n as f64;
                push([r * th.sin() * ph.cos(), r * th.sin() * ph.sin(), r * th.cos()]);
            }
        }
    };
    let step = std::f64::consts::PI / n as f64;
    let (err, radius, _hole) = match kind {
        Solid::Sphere => {
            sphere(s, &mut push);
            (s * step, s, 0.0)
        }
        Solid::Shell { inner } => {
            sphere(s, &mut push);
            sphere(s * inner, &mut push);
            (s * step, s, s * inner)
        }
        Solid::Torus { ratio } => {
            // The ideal torus whose tube is the beads' tube less their bumps (2 R sin(pi / 2n)):
            // it lies inside the union of beads the engine tests.
            let beads = Solid::Torus { ratio }.beads() as f64;
            let (big, a) = (s, s * ratio - 2.0 * s * (std::f64::consts::PI / (2.0 * beads)).sin());
            for i in 0..4 * n {
                let u = std::f64::consts::PI * i as f64 / (2 * n) as f64;
                for j in 0..2 * n {
                    let v = std::f64::consts::PI * j as f64 / n as f64;
                    let rr = big + a * v.cos();
                    push([rr * u.cos(), rr * u.sin(), a * v.sin()]);
                }
            }
            (big * step, big + a, 0.0)
        }
        _ => {
            let (verts, faces): (Vec<P>, Vec<Vec<usize>>) = polyhedron(kind, s);
            for f in &faces {
                // Sample each triangle of a fan.
                for k in 1..f.len() - 1 {
                    let (a, b, cc) = (verts[f[0]], verts[f[k]], verts[f[k + 1]]);
                    for i in 0..=n {
                        for j in 0..=n - i {
                            let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                            push([
                                a[0] + u * (b[0] - a[0]) + v * (cc[0] - a[0]),
                                a[1] + u * (b[1] - a[1]) + v * (cc[1] - a[1]),
                                a[2] + u * (b[2] - a[2]) + v * (cc[2] - a[2]),
                            ]);
                        }
                    }
                }
            }
            let r = verts.iter().map(|v| dot(*v, *v).sqrt()).fold(0.0, f64::max);
            (3.0 * r / n as f64, r, 0.0)
        }
    };
    Cloud {
        pts,
        err,
        centre: c,
        radius,
    }
}

/// Vertices and faces by coordinates (written independently of the engine's tables).
fn polyhedron(kind: Solid, s: f64) -> (Vec<P>, Vec<Vec<usize>>) {
    match kind {
        Solid::Cube => {
            let v = (0..8)
                .map(|b| {
                    [
                        if b & 1 > 0 { s } else { -s },
                        if b & 2 > 0 { s } else { -s },
                        if b & 4 > 0 { s } else { -s },
                    ]
                })
                .collect();
            let f = vec![
                vec![0, 2, 6, 4],
                vec![1, 3, 7, 5],
                vec![0, 1, 5, 4],
                vec![2, 3, 7, 6],
                vec![0, 1, 3, 2],
                vec![4, 5, 7, 6],
            ];
            (v, f)
        }
        Solid::Tetrahedron => {
            let k = s / 3f64.sqrt();
            let v = vec![[k, k, k], [k, -k, -k], [-k, k, -k], [-k, -k, k]];
            (v, vec![vec![1, 2, 3], vec![0, 2, 3], vec![0, 1, 3], vec![0, 1, 2]])
        }
        _ => {
            let v = vec![
                [s, 0.0, 0.0],
                [-s, 0.0, 0.0],
                [0.0, s, 0.0],
                [0.0, -s, 0.0],
                [0.0, 0.0, s],
                [0.0, 0.0, -s],
            ];
            let mut f = vec![];
            for a in [0, 1] {
                for b in [2, 3] {
                    for c in [4, 5] {
                        f.push(vec![a, b, c]);
                    }
                }
            }
            (v, f)
        }
    }
}

/// Whether `d` (relative to the centre) is strictly inside the solid, by geometry written
/// here: a torus by the ideal torus of 3/4 of its tube (which the beads hold).
fn inside(kind: Solid, d: P, s: f64, q: [f64; 4]) -> bool {
    let [w, x, y, z] = q;
    let l = rot([w, -x, -y, -z], d);
    let r = dot(l, l).sqrt();
    match kind {
        Solid::Sphere => r < s * (1.0 - 1e-9),
        Solid::Shell { inner } => r < s * (1.0 - 1e-9) && r > s * inner * (1.0 + 1e-9),
        Solid::Torus { ratio } => {
            let rho = (l[0] * l[0] + l[1] * l[1]).sqrt() - s;
            (rho * rho + l[2] * l[2]).sqrt() < 0.7 * ratio * s
        }
        _ => {
            let (verts, faces) = polyhedron(kind, s);
            faces.iter().all(|f| {
                let (a, b, c) = (verts[f[0]], verts[f[1]], verts[f[2]]);
                let (u, v) = (sub(b, a), sub(c, a));
                let mut n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
                if dot(n, a) < 0.0 {
                    n = [-n[0], -n[1], -n[2]];
                }
                let k = dot(n, n).sqrt();
                dot(n, sub(l, a)) / k < -1e-9 * s
            })
        }
    }
}

/// The checker: `Err` names the first violation. Distances between clouds, less both
/// sampling errors, must exceed the gap (a cloud inside a shell's hole counts as apart when it
/// keeps the gap from the hole's sphere); every sample inside the region with the gap.
fn check(region: &SpaceRegion, gap: f64, solids: &[(Solid, P, f64, [f64; 4])]) -> Result<(), String> {
    let clouds: Vec<Cloud> = solids.iter().map(|&(k, c, s, q)| cloud(k, c, s, q)).collect();
    let ext = region.extent();
    let periodic = region.periodic();
    for (i, a) in clouds.iter().enumerate() {
        if !periodic {
            for p in &a.pts {
                let inside = match *region {
                    SpaceRegion::Ball { radius } => {
                        let d = sub(*p, [radius; 3]);
                        dot(d, d).sqrt() <= radius - gap + 1e-9
                    }
                    SpaceRegion::BoxMinusBall { centre, radius, .. } => {
                        let d = sub(*p, centre);
                        (0..3).all(|k| p[k] >= gap - 1e-9 && p[k] <= ext[k] - gap + 1e-9) && dot(d, d).sqrt() >= radius + gap - a.err - 1e-9
                    }
                    _ => (0..3).all(|k| p[k] >= gap - 1e-9 && p[k] <= ext[k] - gap + 1e-9),
                };
                if !inside {
                    return Err(format!("solid {i} pokes out of the region at {p:?}"));
                }
            }
        }
        for (j, b) in clouds.iter().enumerate().skip(i + 1) {
            let shifts: Vec<P> = if periodic {
                let mut v = vec![];
                for x in -1..=1 {
                    for y in -1..=1 {
                        for z in -1..=1 {
                            v.push([x as f64 * ext[0], y as f64 * ext[1], z as f64 * ext[2]]);
                        }
                    }
                }
                v
            } else {
                vec![[0.0; 3]]
            };
            for sh in shifts {
                let bc = [b.centre[0] + sh[0], b.centre[1] + sh[1], b.centre[2] + sh[2]];
                let d = sub(a.centre, bc);
                let dc = dot(d, d).sqrt();
                if dc > a.radius + b.radius + gap + 1e-9 {
                    continue;
                }
                let shifted: Vec<P> = b.pts.iter().map(|q| [q[0] + sh[0], q[1] + sh[1], q[2] + sh[2]]).collect();
                let bi = &solids[j];
                let b_in = |p: &P| inside(bi.0, sub(*p, bc), bi.2, bi.3);
                let ai = &solids[i];
                let a_in = |p: &P| inside(ai.0, sub(*p, a.centre), ai.2, ai.3);
                if a.pts.iter().any(b_in) || shifted.iter().any(a_in) {
                    return Err(format!("solids {i} and {j} overlap"));
                }
                if gap > 0.0 {
                    let g2 = gap * gap;
                    if a.pts
                        .iter()
                        .any(|p| shifted.iter().any(|q| dot(sub(*p, *q), sub(*p, *q)) < g2 * (1.0 - 1e-9)))
                    {
                        return Err(format!("solids {i} and {j} are closer than the gap"));
                    }
                }
            }
        }
    }
    Ok(())
}

fn fill<S: Scalar>(params: SpaceParams, region: SpaceRegion, count: u64, seed: u64) -> (Vec<Rec>, (u64, u64), StopReason) {
    let cap = count as usize;
    let mut solids = vec![PlacedSolid::<S>::default(); cap];
    let mut index = vec![0u32; space_index_words(cap)];
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    let mut e = SpaceEngine::<S>::new(params, region, storage).expect("valid");
    let reason = e.run(
        &mut rng_from_seed(seed),
        &Stop {
            count: Some(count),
            ..Stop::default()
        },
        |_| {},
    );
    let out = e
        .placed()
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let q = p.rotation.map(|v| v.to_f64());
            (e.kind_of(i as u64), [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()], p.scale.to_f64(), q)
        })
        .collect();
    (out, space_digest(&e), reason)
}

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
    vec![
        SpaceRegion::Box {
            width: 40.0,
            height: 30.0,
            depth: 35.0,
            periodic: false,
        },
        SpaceRegion::Box {
            width: 40.0,
            height: 40.0,
            depth: 40.0,
            periodic: true,
        },
        SpaceRegion::Ball { radius: 20.0 },
        SpaceRegion::BoxMinusBall {
            width: 40.0,
            height: 40.0,
            depth: 40.0,
            centre: [20.0, 20.0, 20.0],
            radius: 8.0,
        },
    ]
}

#[test]
fn every_solid_in_every_region_is_clear_and_inside() {
    for (ki, kind) in kinds().into_iter().enumerate() {
        for (ri, region) in regions().into_iter().enumerate() {
            for gap in [0.0, 0.3] {
                let params = SpaceParams {
                    solids: kind.into(),
                    rotate: true,
                    gap,
                    max_trials: 200_000,
                    ..SpaceParams::spheres(1.15, 10.0)
                };
                let (solids, _, reason) = fill::<f64>(params.clone(), region, 20, 7 + ki as u64 + 10 * ri as u64);
                assert_eq!(reason, StopReason::Count, "{kind:?} in {region:?}");
                check(&region, gap, &solids).unwrap_or_else(|e| panic!("{kind:?} in {region:?} gap {gap}: {e}"));
                let (solids, _, _) = fill::<Fixed>(params, region, 8, 3);
                check(&region, gap, &solids).unwrap_or_else(|e| panic!("fixed {kind:?} in {region:?} gap {gap}: {e}"));
            }
        }
    }
}

#[test]
fn mixtures_are_clear_and_keep_the_volume_sequence() {
    let mix = SolidList::mix(&kinds(), MixOrder::Random, 9).expect("mix");
    let region = regions()[0];
    let params = SpaceParams {
        solids: mix,
        rotate: true,
        max_trials: 200_000,
        ..SpaceParams::spheres(1.15, 10.0)
    };
    let (solids, _, reason) = fill::<f64>(params, region, 25, 1);
    assert_eq!(reason, StopReason::Count);
    check(&region, 0.0, &solids).expect("clear");
    let vol = |k: Solid, s: f64| k.volume(s);
    let seq = zetafill::AreaSequence::new(region.volume(), 1.15, 10.0).expect("seq");
    for (i, &(k, _, s, _)) in solids.iter().enumerate() {
        assert!((vol(k, s) / seq.area(i as u64) - 1.0).abs() < 1e-9);
    }
}

#[test]
fn the_checker_fails_on_broken_fills() {
    let region = regions()[0];
    let id = [1.0, 0.0, 0.0, 0.0];
    let ok = vec![
        (Solid::Cube, [10.0, 10.0, 10.0], 2.0, id),
        (Solid::Sphere, [20.0, 10.0, 10.0], 2.0, id),
    ];
    assert!(check(&region, 0.0, &ok).is_ok());
    // Overlapping pair: a cube's corner into a sphere.
    let overlap = vec![
        (Solid::Cube, [10.0, 10.0, 10.0], 2.0, id),
        (Solid::Sphere, [13.0, 13.0, 13.0], 2.0, id),
    ];
    assert!(check(&region, 0.0, &overlap).is_err());
    // Closer than the gap.
    assert!(check(&region, 6.5, &ok).is_err());
    // Poking out of the box, and out of a ball.
    let out = vec![(Solid::Tetrahedron, [1.0, 10.0, 10.0], 2.0, id)];
    assert!(check(&region, 0.0, &out).is_err());
    let ball = SpaceRegion::Ball { radius: 20.0 };
    assert!(check(&ball, 0.0, &[(Solid::Octahedron, [2.0, 20.0, 20.0], 3.0, id)]).is_err());
    // Linked tori pass; a torus through a sphere does not.
    let q = [0.5f64.sqrt(), 0.5f64.sqrt(), 0.0, 0.0];
    let linked = vec![
        (Solid::Torus { ratio: 0.25 }, [15.0, 15.0, 15.0], 4.0, id),
        (Solid::Torus { ratio: 0.25 }, [19.0, 15.0, 15.0], 4.0, q),
    ];
    assert!(check(&region, 0.0, &linked).is_ok());
    let through = vec![
        (Solid::Torus { ratio: 0.25 }, [15.0, 15.0, 15.0], 4.0, id),
        (Solid::Sphere, [19.0, 15.0, 15.0], 1.5, id),
    ];
    assert!(check(&region, 0.0, &through).is_err());
}

#[test]
fn reruns_are_identical_and_prefixes_stable() {
    let params = SpaceParams {
        solids: Solid::Cube.into(),
        rotate: true,
        ..SpaceParams::spheres(1.2, 4.0)
    };
    let region = regions()[1];
    let (a, da, _) = fill::<f64>(params.clone(), region, 200, 5);
    let (b, db, _) = fill::<f64>(params.clone(), region, 200, 5);
    assert_eq!(da, db);
    let (p, _, _) = fill::<f64>(params, region, 60, 5);
    assert_eq!(a[..60], p[..]);
    assert_eq!(a, b);
}

/// The golden digest: 300 randomly rotated cubes, c = 1.1, N = 4, in a 50 mm inclusive cube,
/// seed 1. It pins the volume sequence, the rotation and centre mapping, the exact tests and
/// the digest's layout: any change to an output changes it. To re-mint after a deliberate,
/// version-level change, run this test and copy the value it prints.
#[test]
fn golden_digest() {
    let params = SpaceParams {
        solids: Solid::Cube.into(),
        rotate: true,
        ..SpaceParams::spheres(1.1, 4.0)
    };
    let region = SpaceRegion::Box {
        width: 50.0,
        height: 50.0,
        depth: 50.0,
        periodic: false,
    };
    let (_, d, _) = fill::<f64>(params, region, 300, 1);
    assert_eq!(d, (300, GOLDEN), "digest {:#x}", d.1);
}
const GOLDEN: u64 = 0xe31f_b5a2_c4ba_1b3d;

#[test]
fn fill_fractions_of_spheres_and_cubes() {
    let region = SpaceRegion::Box {
        width: 100.0,
        height: 100.0,
        depth: 100.0,
        periodic: false,
    };
    for (params, n) in [
        (SpaceParams::spheres(1.15, 1.0), 3000u64),
        (
            SpaceParams {
                solids: Solid::Cube.into(),
                ..SpaceParams::spheres(1.2, 4.0)
            },
            2000,
        ),
    ] {
        let seq = zetafill::AreaSequence::new(region.volume(), params.c, params.n_offset).expect("seq");
        let mut solids = vec![PlacedSolid::<f64>::default(); n as usize];
        let mut index = vec![0u32; space_index_words(n as usize)];
        let storage = SpaceStorage {
            solids: &mut solids,
            index: &mut index,
        };
        let mut e = SpaceEngine::<f64>::new(params, region, storage).expect("valid");
        assert_eq!(
            e.run(
                &mut rng_from_seed(3),
                &Stop {
                    count: Some(n),
                    ..Stop::default()
                },
                |_| {}
            ),
            StopReason::Count
        );
        let f = e.stats().fill_fraction;
        assert!((f - seq.covered(n)).abs() < 1e-9, "{f}");
        assert!(f > 0.3 && f < 1.0);
    }
}
