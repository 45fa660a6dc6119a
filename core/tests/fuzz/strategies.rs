//! Generators of fuzz cases: well-formed parameters spread over their whole valid ranges
//! (and their edges), every shape kind and mixes of them, every region kind with polygons of
//! many forms (stars, holes, islands, combs, slivers, crossing outlines), every stop
//! condition, small trial limits and storage, both scalars and both samplers.

use proptest::prelude::*;
use proptest::sample::select;
use zetafill::{cells_for, MixOrder, Params, Point, ShapeKind, ShapeList, Stop, MAX_MIX};

/// The number type the engine computes in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scal {
    F64,
    Fixed,
}

/// How the shapes are placed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sampler {
    /// `Engine::step`.
    Reference,
    /// `Engine::step_fast` over a pool of this many cells (`None`: `cells_for` the capacity).
    Cells(Option<usize>),
}

/// How the engine is driven.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Drive {
    /// `run` / `run_fast` with the case's stop conditions.
    Run,
    /// `step` / `step_fast` up to the count, stepping once more after a halt.
    Step,
}

/// A region as generated (a polygon owns its points; the engine borrows them).
#[derive(Clone, Debug)]
pub enum RegionGen {
    Rect { w: f64, h: f64, periodic: bool },
    Circle { r: f64 },
    Annulus { outer: f64, inner: f64 },
    Polygon { points: Vec<Point<f64>>, ends: Vec<usize> },
}

impl RegionGen {
    /// A length that measures the region.
    pub fn size(&self) -> f64 {
        match self {
            RegionGen::Rect { w, h, .. } => w.min(*h),
            RegionGen::Circle { r } => *r,
            RegionGen::Annulus { outer, inner } => outer - inner,
            RegionGen::Polygon { points, .. } => {
                let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
                for p in points {
                    x0 = x0.min(p.x);
                    x1 = x1.max(p.x);
                }
                (x1 - x0).max(0.0)
            }
        }
    }
}

/// One fuzz case.
#[derive(Clone, Debug)]
pub struct Case {
    pub scalar: Scal,
    pub sampler: Sampler,
    pub drive: Drive,
    pub params: Params,
    pub region: RegionGen,
    pub stop: Stop,
    /// Shape slots lent to the engine.
    pub capacity: usize,
    /// Words of the coverage bitmap.
    pub coverage: usize,
    pub seed: u64,
}

/// 10^e for e uniform in `lo..hi`.
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi).prop_map(|e: f64| 10f64.powf(e))
}

/// A ratio in (0, 1), with its edges.
fn unit_open() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => 0.02f64..0.98,
        1 => select(vec![1e-9, 1e-4, 0.01, 0.5, 0.99, 0.9999, 1.0 - 1e-9]),
    ]
}

/// Every kind of shape over its valid proportions.
pub fn kind() -> impl Strategy<Value = ShapeKind> {
    prop_oneof![
        3 => Just(ShapeKind::Circle),
        2 => Just(ShapeKind::Square),
        2 => prop_oneof![4 => log_uniform(-3.0, 3.0), 1 => select(vec![1e-6, 1e-4, 1.0, 1e4, 1e6])]
            .prop_map(|aspect| ShapeKind::Rect { aspect }),
        1 => Just(ShapeKind::Triangle),
        1 => (3u8..=32).prop_map(|sides| ShapeKind::Polygon { sides }),
        2 => (2u8..=16, unit_open()).prop_map(|(points, inner)| ShapeKind::Star { points, inner }),
        2 => unit_open().prop_map(|inner| ShapeKind::Ring { inner }),
        2 => prop_oneof![3 => 0.0f64..(1.0 / 3.0), 1 => select(vec![0.0, 1e-9, 0.3, 1.0 / 3.0 - 1e-9])]
            .prop_map(|delta| ShapeKind::Blob { delta }),
        1 => (prop_oneof![3 => 0.0f64..=0.9, 1 => select(vec![0.0, 0.9])], 2u8..=8, 1u8..=2).prop_map(|(amplitude, features, octaves)| {
            ShapeKind::Noisy { amplitude, features, octaves }
        }),
    ]
}

/// One kind, or a mix of up to [`MAX_MIX`] kinds taken in turn or at random.
pub fn shape_list() -> impl Strategy<Value = ShapeList> {
    prop_oneof![
        3 => kind().prop_map(ShapeList::from),
        2 => (prop::collection::vec(kind(), 1..=MAX_MIX), any::<bool>(), any::<u64>()).prop_map(|(kinds, random, salt)| {
            let order = if random { MixOrder::Random } else { MixOrder::Cycle };
            ShapeList::mix(&kinds, order, salt).unwrap_or_else(|| ShapeKind::Circle.into())
        }),
    ]
}

/// SplitMix64, for the polygon outlines drawn from one seed.
pub struct Mix(pub u64);

impl Mix {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// A ring star-shaped about (cx, cy): `n` vertices at increasing angles, radii in
/// `[rmin, rmax]`; clockwise when `cw`.
fn star_ring(m: &mut Mix, c: (f64, f64), rmin: f64, rmax: f64, n: usize, cw: bool) -> Vec<Point<f64>> {
    let step = std::f64::consts::TAU / n as f64;
    let turn = m.unit() * std::f64::consts::TAU;
    let mut ring: Vec<Point<f64>> = (0..n)
        .map(|k| {
            let t = turn + (k as f64 + 0.8 * m.unit()) * step;
            let r = rmin + (rmax - rmin) * m.unit();
            Point::new(c.0 + r * t.cos(), c.1 + r * t.sin())
        })
        .collect();
    if cw {
        ring.reverse();
    }
    ring
}

/// A comb: a spine along the bottom with `teeth` teeth of width `tooth` (of a unit pitch)
/// and random heights, in a box `s` wide.
fn comb(m: &mut Mix, s: f64, teeth: usize, tooth: f64) -> Vec<Point<f64>> {
    let pitch = s / teeth as f64;
    let spine = 0.1 * s;
    let mut ring = vec![Point::new(0.0, 0.0), Point::new(s, 0.0)];
    for k in (0..teeth).rev() {
        let (x0, x1) = (k as f64 * pitch, k as f64 * pitch + tooth * pitch);
        let top = spine + (0.2 + 0.8 * m.unit()) * s;
        if k + 1 == teeth {
            ring.push(Point::new(s, top));
        } else {
            ring.push(Point::new(x1, spine));
            ring.push(Point::new(x1, top));
        }
        ring.push(Point::new(x0, top));
        if k > 0 {
            ring.push(Point::new(x0, spine));
        }
    }
    ring
}

/// A polygon region of size about `s` from a seed: one of many forms.
fn polygon(form: u8, s: f64, seed: u64, offset: (f64, f64)) -> RegionGen {
    let mut m = Mix(seed);
    let mut rings: Vec<Vec<Point<f64>>> = Vec::new();
    let cw = |m: &mut Mix| m.below(4) == 0;
    let half = s / 2.0;
    match form % 8 {
        // A star-shaped outline.
        0 => {
            let n = 3 + m.below(40);
            let w = cw(&mut m);
            rings.push(star_ring(&mut m, (half, half), 0.3 * half, half, n, w));
        }
        // A star-shaped outline with up to three holes, and a hole at the centre.
        1 => {
            let n = 3 + m.below(30);
            let w = cw(&mut m);
            rings.push(star_ring(&mut m, (half, half), 0.62 * half, half, n + 3, w));
            let holes = 1 + m.below(3);
            let turn = m.unit() * std::f64::consts::TAU;
            for k in 0..holes {
                let t = turn + k as f64 * std::f64::consts::TAU / 3.0;
                let c = (half + 0.35 * half * t.cos(), half + 0.35 * half * t.sin());
                let n = 3 + m.below(8);
                let w = cw(&mut m);
                rings.push(star_ring(&mut m, c, 0.03 * half, 0.12 * half, n, w));
            }
            if m.below(2) == 0 {
                let w = cw(&mut m);
                let n = 3 + m.below(6);
                rings.push(star_ring(&mut m, (half, half), 0.05 * half, 0.2 * half, n, w));
            }
        }
        // Islands: two outlines side by side, the second with a hole holding a third.
        2 => {
            let w = cw(&mut m);
            let n = 3 + m.below(12);
            rings.push(star_ring(&mut m, (0.25 * s, half), 0.1 * s, 0.24 * s, n, w));
            let w = cw(&mut m);
            let n = 3 + m.below(12);
            rings.push(star_ring(&mut m, (0.75 * s, half), 0.2 * s, 0.24 * s, n, w));
            let w = cw(&mut m);
            let n = 3 + m.below(12);
            rings.push(star_ring(&mut m, (0.75 * s, half), 0.1 * s, 0.18 * s, n, w));
            let w = cw(&mut m);
            let n = 3 + m.below(12);
            rings.push(star_ring(&mut m, (0.75 * s, half), 0.02 * s, 0.08 * s, n, w));
        }
        // A comb with narrow teeth.
        3 => {
            let teeth = 1 + m.below(8);
            let tooth = [0.5, 0.1, 0.01, 1e-4][m.below(4)];
            rings.push(comb(&mut m, s, teeth, tooth));
        }
        // Random points: mostly crossing outlines, which the core refuses.
        4 => {
            let n = 3 + m.below(12);
            rings.push((0..n).map(|_| Point::new(s * m.unit(), s * m.unit())).collect());
        }
        // Slivers and spikes: a triangle of tiny height, a star with a needle.
        5 => {
            let thin = [1e-3, 1e-6, 1e-9][m.below(3)];
            if m.below(2) == 0 {
                rings.push(vec![Point::new(0.0, 0.0), Point::new(s, 0.0), Point::new(half, thin * s)]);
            } else {
                let mut r = star_ring(&mut m, (half, half), 0.3 * half, 0.5 * half, 12, false);
                let (a, b) = (r[3], r[4]);
                let mid = Point::new((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
                let out = Point::new(half + (mid.x - half) * 2.0, half + (mid.y - half) * 2.0);
                r.insert(4, out);
                rings.push(r);
            }
        }
        // Repeated and collinear vertices: a square with extra points on its edges.
        6 => {
            let mut r = vec![
                Point::new(0.0, 0.0),
                Point::new(half, 0.0),
                Point::new(s, 0.0),
                Point::new(s, s),
                Point::new(0.0, s),
            ];
            match m.below(3) {
                0 => r.insert(1, Point::new(0.0, 0.0)),
                1 => r.push(Point::new(0.0, 0.0)),
                _ => r.insert(3, Point::new(s, half)),
            }
            rings.push(r);
        }
        // Two outlines that overlap (refused), or a hole that crosses its outline.
        _ => {
            rings.push(star_ring(&mut m, (half, half), 0.5 * half, half, 6, false));
            let c = if m.below(2) == 0 { (half * 1.5, half) } else { (half, half) };
            rings.push(star_ring(&mut m, c, 0.2 * half, 0.9 * half, 5, false));
        }
    }
    let mut points = Vec::new();
    let mut ends = Vec::new();
    for r in rings {
        points.extend(r.into_iter().map(|p| Point::new(p.x + offset.0, p.y + offset.1)));
        ends.push(points.len());
    }
    RegionGen::Polygon { points, ends }
}

/// Region sizes: mostly 1 to 1000, over 10^-3..10^7 in all (10^-3..10^6 on fixed point).
fn region_size() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => log_uniform(0.0, 3.0),
        3 => log_uniform(-3.0, 6.0),
        1 => select(vec![1e-3, 0.01, 1e4, 1e5, 1e6, 1e7]),
    ]
}

/// Regions of every kind, sized in `sizes` (and every coordinate within ±`sizes.1`).
pub fn region(sizes: (f64, f64)) -> impl Strategy<Value = RegionGen> {
    (
        0u8..10,
        region_size().prop_map(move |s| s.clamp(sizes.0, sizes.1)),
        prop_oneof![4 => log_uniform(-0.5, 0.5), 1 => log_uniform(-2.0, 2.0)],
        0u8..8,
        any::<u64>(),
        prop_oneof![3 => Just(0.0), 1 => log_uniform(-3.0, 3.0), 1 => log_uniform(-3.0, 3.0).prop_map(|v| -v)],
    )
        .prop_map(move |(kind, s, ar, form, seed, shift)| {
            let max_size = sizes.1;
            match kind {
                0..=2 => RegionGen::Rect {
                    w: s,
                    h: (s * ar).min(max_size),
                    periodic: false,
                },
                3..=4 => RegionGen::Rect {
                    w: s,
                    h: (s * ar).min(max_size),
                    periodic: true,
                },
                5 => RegionGen::Circle { r: s / 2.0 },
                6 => RegionGen::Annulus {
                    outer: s / 2.0,
                    inner: s / 2.0 * (0.001 + 0.95 * Mix(seed).unit()),
                },
                _ => {
                    let off = (shift * s).clamp(-max_size, max_size - s);
                    polygon(form, s, seed, (off, -off / 2.0))
                }
            }
        })
}

/// The stop conditions and the storage: a count up to 200, sometimes with a fill fraction
/// or a minimum size, sometimes none (the storage then ends the fill).
fn stop_and_capacity() -> impl Strategy<Value = (Stop, usize)> {
    (
        0u8..20,
        prop_oneof![3 => 1u64..=40, 2 => 40u64..=200],
        prop_oneof![4 => 0.01f64..0.9, 1 => select(vec![1e-9, 0.5, 0.99, 1.0 - 1e-12])],
        log_uniform(-6.0, 0.0),
        0u8..10,
    )
        .prop_map(|(which, count, fill, min_rel, cap)| {
            let (count, fill, min_size) = match which {
                0..=11 => (Some(count), None, None),
                12..=14 => (Some(count), Some(fill), None),
                15..=17 => (Some(count), None, Some(min_rel)),
                18 => (None, Some(fill), None),
                _ => (None, None, Some(min_rel)),
            };
            let want = count.unwrap_or(200) as usize;
            // Mostly enough slots; sometimes too few (the capacity error), or none.
            let capacity = match cap {
                0 if want == 1 => 0,
                1 => want / 2,
                _ => want,
            };
            (Stop { count, fill, min_size }, capacity)
        })
}

/// Every case, on the scalar `scal`, with regions sized in `sizes` and shapes no narrower
/// than `min_shape` (the fill stops before the first that would be).
pub fn case(scal: Scal, sizes: (f64, f64), min_shape: f64) -> impl Strategy<Value = Case> {
    // Mostly a first shape that fits (a few percent of the region, down to fractions of a
    // percent); sometimes one that takes nearly all of it.
    let c = prop_oneof![
        7 => 1.05f64..1.5,
        2 => 1.5f64..3.0,
        1 => select(vec![1.0 + 1e-9, 1.001, 4.0, 10.0, 50.0]),
    ];
    let n = prop_oneof![
        6 => 2.0f64..30.0,
        2 => log_uniform(-3.0, 4.0),
        1 => select(vec![1e-6, 1e-3, 1e5, 1e6]),
    ];
    let gap_rel = prop_oneof![8 => Just(0.0), 6 => log_uniform(-6.0, -1.5), 1 => select(vec![5e-324, 1e-12, 0.1, 0.45])];
    let max_trials = prop_oneof![1 => 1u64..=60, 6 => 200u64..=2000, 1 => select(vec![1, 2, 3000])];
    let sampler = prop_oneof![
        1 => Just(Sampler::Reference),
        1 => prop_oneof![3 => Just(None), 1 => select(vec![0usize, 1, 2, 6, 64]).prop_map(Some)].prop_map(Sampler::Cells),
    ];
    (
        (c, n, shape_list(), any::<bool>(), gap_rel, max_trials),
        region(sizes),
        stop_and_capacity(),
        (sampler, any::<bool>(), select(vec![0usize, 0, 8, 256, 4096]), any::<u64>()),
    )
        .prop_map(
            move |((c, n_offset, shape, rotate, gap_rel, max_trials), region, (mut stop, capacity), (sampler, step, coverage, seed))| {
                let size = region.size();
                if let Some(m) = stop.min_size.as_mut() {
                    *m *= size;
                }
                if min_shape > 0.0 {
                    stop.min_size = Some(stop.min_size.unwrap_or(0.0).max(min_shape));
                }
                let sampler = match sampler {
                    Sampler::Cells(None) => Sampler::Cells(Some(cells_for(capacity))),
                    s => s,
                };
                Case {
                    scalar: scal,
                    sampler,
                    drive: if step { Drive::Step } else { Drive::Run },
                    params: Params {
                        c,
                        n_offset,
                        shape,
                        rotate,
                        gap: gap_rel * size,
                        max_trials,
                    },
                    region,
                    stop,
                    capacity,
                    coverage,
                    seed,
                }
            },
        )
}
