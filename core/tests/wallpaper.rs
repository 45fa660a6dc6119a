//! Fills with the symmetry of each wallpaper group: no two images meet, on the torus or
//! across a 3 x 3 block of cells, the pattern maps onto itself under the group's generators
//! (given here from their geometry, not taken from the engine), and the cell sampler and the
//! batched one place orbits with the reference's distribution (two-sample Kolmogorov-Smirnov
//! tests over 400 fills a side, the family held at 0.01; a lattice 10% narrower must fail).
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::{ks, Buffers};
use zetafill::{
    rng_from_seed, Batches, CellSampler, Engine, Geo, Group, Lane, MixOrder, Params, Placed, Point, Region, ShapeKind, ShapeList, Stop,
    StopReason, Wallpaper,
};

/// An isometry of the plane, given by the images of the origin and of the two unit vectors.
#[derive(Clone, Copy, Debug)]
struct Op {
    m: [f64; 4],
    t: [f64; 2],
}

impl Op {
    fn rotation(deg: f64) -> Op {
        let (s, c) = (libm::sin(deg.to_radians()), libm::cos(deg.to_radians()));
        Op {
            m: [c, -s, s, c],
            t: [0.0, 0.0],
        }
    }
    /// The reflection in the line through `p` at `deg` degrees, then a slide of `slide` along it.
    fn reflection(deg: f64, p: [f64; 2], slide: f64) -> Op {
        let (s, c) = (libm::sin((2.0 * deg).to_radians()), libm::cos((2.0 * deg).to_radians()));
        let m = [c, s, s, -c];
        // x -> p + m (x - p) + slide (cos deg, sin deg)
        let (d0, d1) = (libm::cos(deg.to_radians()) * slide, libm::sin(deg.to_radians()) * slide);
        let t = [p[0] - (m[0] * p[0] + m[1] * p[1]) + d0, p[1] - (m[2] * p[0] + m[3] * p[1]) + d1];
        Op { m, t }
    }
    fn apply(&self, q: Point<f64>) -> Point<f64> {
        let [a, b, c, d] = self.m;
        Point::new(a * q.x + b * q.y + self.t[0], c * q.x + d * q.y + self.t[1])
    }
}

/// The generators of each group beyond its translations, from the groups' geometry: the
/// rotation about the origin and the mirrors or glides, for a conventional cell `a x b`.
fn generators(g: Group, a: f64, b: f64) -> Vec<Op> {
    let o = [0.0, 0.0];
    match g {
        Group::P1 => vec![],
        Group::P2 => vec![Op::rotation(180.0)],
        Group::Pm | Group::Cm => vec![Op::reflection(90.0, o, 0.0)],
        Group::Pg => vec![Op::reflection(90.0, o, b / 2.0)],
        Group::Pmm | Group::Cmm => vec![Op::reflection(90.0, o, 0.0), Op::reflection(0.0, o, 0.0)],
        Group::Pmg => vec![Op::rotation(180.0), Op::reflection(90.0, [a / 4.0, 0.0], 0.0)],
        Group::Pgg => vec![Op::rotation(180.0), Op::reflection(90.0, [a / 4.0, 0.0], b / 2.0)],
        Group::P4 => vec![Op::rotation(90.0)],
        Group::P4m => vec![Op::rotation(90.0), Op::reflection(90.0, o, 0.0)],
        Group::P4g => vec![Op::rotation(90.0), Op::reflection(135.0, [a / 2.0, 0.0], 0.0)],
        Group::P3 => vec![Op::rotation(120.0)],
        Group::P3m1 => vec![Op::rotation(120.0), Op::reflection(90.0, o, 0.0)],
        Group::P31m => vec![Op::rotation(120.0), Op::reflection(0.0, o, 0.0)],
        Group::P6 => vec![Op::rotation(60.0)],
        Group::P6m => vec![Op::rotation(60.0), Op::reflection(90.0, o, 0.0)],
    }
}

/// The first shape (by position in `middle`) whose image under some generator matches no
/// shape of `all` within 1e-9 mm (centre, radius, every vertex), if any.
fn asymmetric(g: Group, a: f64, b: f64, middle: &[Geo<f64>], all: &[Geo<f64>]) -> Option<usize> {
    let close = |p: Point<f64>, q: Point<f64>| (p.x - q.x).abs() < 1e-9 && (p.y - q.y).abs() < 1e-9;
    for op in generators(g, a, b) {
        for (i, s) in middle.iter().enumerate() {
            let found = match s {
                Geo::Circle { c, r } => {
                    let q = op.apply(*c);
                    all.iter()
                        .any(|t| matches!(t, Geo::Circle { c: c2, r: r2 } if close(q, *c2) && (r - r2).abs() < 1e-9))
                }
                Geo::Ring { .. } | Geo::Motif { .. } => panic!("no rings or motifs here"),
                Geo::Poly { v, .. } => {
                    let img: Vec<Point<f64>> = v.iter().map(|p| op.apply(*p)).collect();
                    all.iter().any(|t| {
                        let tv = t.vertices();
                        tv.len() == img.len() && img.iter().all(|p| tv.iter().any(|q| close(*p, *q)))
                    })
                }
            };
            if !found {
                return Some(i);
            }
        }
    }
    None
}

/// Every entry's outline over a block of `n x n` primitive cells around the domain.
fn tiled(e: &Engine<'_, f64>, w: &Wallpaper, n: i64) -> Vec<Geo<'static, f64>> {
    let (ax, bx, by) = w.lattice();
    let mut out = Vec::new();
    for i in 0..e.placed().len() {
        let g = e.geo(i).and_then(|g| g.owned()).expect("an entry");
        for l in -n..=n {
            for k in -n - 1..=n + 1 {
                out.push(g.shift(k as f64 * ax + l as f64 * bx, l as f64 * by));
            }
        }
    }
    out
}

fn centre(g: &Geo<f64>) -> Point<f64> {
    match g {
        Geo::Circle { c, .. } | Geo::Ring { c, .. } => *c,
        Geo::Motif { f, .. } => f.t,
        Geo::Poly { v, .. } => {
            let n = v.len() as f64;
            Point::new(v.iter().map(|p| p.x).sum::<f64>() / n, v.iter().map(|p| p.y).sum::<f64>() / n)
        }
    }
}

/// Whether two discs (the only kind this test fills) keep apart.
fn discs_clear(a: &Geo<f64>, b: &Geo<f64>) -> bool {
    match (a, b) {
        (Geo::Circle { c: p, r: s }, Geo::Circle { c: q, r: t }) => p.dist2(*q).sqrt() > s + t,
        _ => panic!("discs only"),
    }
}

fn fill(group: Group, sides: (f64, f64, f64), count: u64, fast: bool, seed: u64) -> (Vec<Placed<f64>>, Wallpaper, Vec<Geo<'static, f64>>) {
    fill_with(Params::circles(1.3, 1.0), group, sides, count, fast, seed, 1)
}

fn fill_with(
    params: Params,
    group: Group,
    sides: (f64, f64, f64),
    count: u64,
    fast: bool,
    seed: u64,
    block: i64,
) -> (Vec<Placed<f64>>, Wallpaper, Vec<Geo<'static, f64>>) {
    let w = Wallpaper::new(group, sides.0, sides.1, sides.2).expect("a lattice");
    let cap = count as usize * w.order();
    let mut buffers = Buffers::<f64>::new(cap);
    let storage = buffers.storage(&mut []);
    let mut e = Engine::new(params, Region::Wallpaper(w), storage).expect("an engine");
    let stop = Stop {
        count: Some(count),
        ..Stop::default()
    };
    let mut rng = rng_from_seed(seed);
    let reason = if fast {
        let mut pool = vec![[0u64; 4]; zetafill::cells_for(cap)];
        let mut cells = CellSampler::new(&mut pool).expect("cells");
        e.run_fast(&mut cells, &mut rng, &stop, |_| {})
    } else {
        e.run(&mut rng, &stop, |_| {})
    };
    assert_eq!(e.stats().placed, count, "{group:?} {reason:?}");
    let geos = tiled(&e, &w, block);
    (e.placed().to_vec(), w, geos)
}

fn sides(g: Group) -> (f64, f64, f64) {
    match g.lattice() {
        zetafill::LatticeKind::Oblique => (50.0, 40.0, 70.0),
        _ => (50.0, 36.0, 90.0),
    }
}

#[test]
fn no_two_images_meet_in_any_group() {
    for fast in [false, true] {
        for g in Group::ALL {
            let (_, w, geos) = fill(g, sides(g), 60, fast, 5);
            let (ax, _, by) = w.lattice();
            // The shapes whose centres lie in the middle cell, against all.
            for (i, a) in geos.iter().enumerate() {
                let c = centre(a);
                if !(c.x >= 0.0 && c.x < ax && c.y >= 0.0 && c.y < by) {
                    continue;
                }
                for (j, b) in geos.iter().enumerate() {
                    if i != j {
                        assert!(discs_clear(a, b), "{g:?} fast {fast}: {a:?} meets {b:?}");
                    }
                }
            }
        }
    }
}

/// The shapes of `geos` centred in the domain `[0, ax) x [0, by)`.
fn middle(w: &Wallpaper, geos: &[Geo<'static, f64>]) -> Vec<Geo<'static, f64>> {
    let (ax, _, by) = w.lattice();
    geos.iter()
        .filter(|g| {
            let c = centre(g);
            c.x >= 0.0 && c.x < ax && c.y >= 0.0 && c.y < by
        })
        .cloned()
        .collect()
}

#[test]
fn every_group_maps_its_pattern_onto_itself() {
    let kinds = [
        ShapeKind::Circle,
        ShapeKind::Square,
        ShapeKind::Triangle,
        ShapeKind::Star { points: 5, inner: 0.45 },
        ShapeKind::Blob { delta: 0.25 },
    ];
    let mix = ShapeList::mix(&kinds, MixOrder::Cycle, 0).expect("a mix");
    for (g, fast) in Group::ALL.iter().flat_map(|&g| [(g, false), (g, true)]) {
        let (a, b, angle) = sides(g);
        let params = Params {
            shape: mix.clone(),
            rotate: true,
            ..Params::circles(1.25, 3.0)
        };
        let (_, w, geos) = fill_with(params, g, (a, b, angle), 40, fast, 9, 2);
        let mid = middle(&w, &geos);
        assert!(mid.len() >= 40, "{g:?}");
        let (ca, cb) = w.cell();
        assert_eq!(asymmetric(g, ca, cb, &mid, &geos), None, "{g:?}");
        // The twin: one shape moved by 1e-6 mm is found out (every group but p1 has a
        // generator to find it with).
        if g != Group::P1 {
            let mut moved = geos.clone();
            let at = moved.iter().position(|s| centre(s) == centre(&mid[3])).expect("the shape");
            moved[at] = moved[at].shift(1e-6, 0.0);
            let mid2 = middle(&w, &moved);
            assert!(asymmetric(g, ca, cb, &mid2, &moved).is_some(), "{g:?}: the moved shape went unseen");
        }
    }
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Sampler {
    Reference,
    Fast,
    Batched,
    /// The reference sampler on a lattice 10% narrower: a biased input for the checker.
    Narrow,
}

const RUNS: u64 = 400;
const COUNT: u64 = 24;
const PICKS: [usize; 2] = [5, 20];

/// One symmetric fill's entries, and its lattice.
fn sampled(group: Group, kind: ShapeKind, sampler: Sampler, seed: u64) -> (Vec<Placed<f64>>, Wallpaper) {
    let side = if sampler == Sampler::Narrow { 36.0 } else { 40.0 };
    let w = Wallpaper::new(group, side, 30.0, 90.0).expect("a lattice");
    let cap = COUNT as usize * w.order();
    let mut buffers = Buffers::<f64>::new(cap);
    let storage = buffers.storage(&mut []);
    let params = Params {
        shape: kind.into(),
        rotate: kind.rotates(),
        ..Params::circles(1.3, 3.0)
    };
    let mut e = Engine::new(params, Region::Wallpaper(w), storage).expect("an engine");
    let stop = Stop {
        count: Some(COUNT),
        ..Stop::default()
    };
    let mut rng = rng_from_seed(seed);
    let mut pool = vec![[0u64; 4]; zetafill::cells_for(200 * w.order())];
    let reason = match sampler {
        Sampler::Reference | Sampler::Narrow => e.run(&mut rng, &stop, |_| {}),
        Sampler::Fast => {
            let mut cells = CellSampler::new(&mut pool).expect("cells");
            e.run_fast(&mut cells, &mut rng, &stop, |_| {})
        }
        Sampler::Batched => {
            let mut cells = CellSampler::new(&mut pool).expect("cells");
            let mut lanes = vec![Lane::default(); 16];
            let mut batches = Batches::new(&mut lanes, seed, 16).expect("lanes");
            e.run_batched(&mut cells, &mut batches, &stop, |_| {})
        }
    };
    assert_eq!(reason, StopReason::Count, "{group:?} {kind:?} {sampler:?} seed {seed}");
    (e.placed().to_vec(), w)
}

/// The distance between two points of the torus of `w` (to the nearest translate).
fn torus_dist(w: &Wallpaper, p: &Placed<f64>, q: &Placed<f64>) -> f64 {
    let (ax, bx, by) = w.lattice();
    let mut best = f64::INFINITY;
    for l in -2..=2 {
        for k in -3..=3 {
            let (dx, dy) = (q.x + k as f64 * ax + l as f64 * bx - p.x, q.y + l as f64 * by - p.y);
            best = best.min(dx.hypot(dy));
        }
    }
    best
}

/// For each picked orbit: its representative's x and y in the fundamental domain, the room
/// its bounding circle had among the images placed before it, and the distance from its
/// centre to the nearest other centre of the finished fill.
fn statistics(kind: ShapeKind, (entries, w): &(Vec<Placed<f64>>, Wallpaper)) -> Vec<f64> {
    let m = w.order();
    let mut out = Vec::new();
    for &i in &PICKS {
        let s = &entries[i * m];
        let radius = |p: &Placed<f64>| kind.bounding_radius(p.scale);
        let margin = entries[..i * m]
            .iter()
            .map(|o| torus_dist(w, s, o) - radius(o))
            .fold(f64::INFINITY, f64::min)
            - radius(s);
        let nearest = entries
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i * m)
            .map(|(_, o)| torus_dist(w, s, o))
            .fold(f64::INFINITY, f64::min);
        out.extend([s.x, s.y, margin, nearest]);
    }
    out
}

fn columns(group: Group, kind: ShapeKind, sampler: Sampler, first_seed: u64) -> Vec<Vec<f64>> {
    let mut cols: Vec<Vec<f64>> = Vec::new();
    for seed in first_seed..first_seed + RUNS {
        let st = statistics(kind, &sampled(group, kind, sampler, seed));
        cols.resize(st.len(), Vec::new());
        for (c, v) in cols.iter_mut().zip(st) {
            c.push(v);
        }
    }
    cols
}

/// The smallest p of the comparisons of `sampler` against the reference, with its label.
fn compare(group: Group, kind: ShapeKind, sampler: Sampler) -> Vec<(String, f64)> {
    let a = columns(group, kind, Sampler::Reference, 1);
    let b = columns(group, kind, sampler, 1_000_001);
    a.iter()
        .zip(&b)
        .enumerate()
        .map(|(k, (x, y))| {
            let (d, p) = ks(x, y);
            (format!("{group:?} {kind:?} {sampler:?}: statistic {k} (D = {d:.3})"), p)
        })
        .collect()
}

const CASES: [(Group, ShapeKind); 3] = [
    (Group::P4m, ShapeKind::Circle),
    (Group::P6m, ShapeKind::Circle),
    (Group::Pgg, ShapeKind::Square),
];

#[test]
fn both_samplers_place_orbits_as_the_reference_does() {
    let samplers = [Sampler::Fast, Sampler::Batched];
    let tests = samplers.len() * CASES.len() * PICKS.len() * 4;
    let alpha = 0.01 / tests as f64;
    let mut failures = Vec::new();
    for sampler in samplers {
        for (g, kind) in CASES {
            for (label, p) in compare(g, kind, sampler) {
                if p < alpha {
                    failures.push(format!("{label}: p = {p:.2e} < {alpha:.1e}"));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "a sampler differs from the reference:\n{}",
        failures.join("\n")
    );
    // The same test rejects fills on a narrower lattice.
    let worst = compare(Group::P4m, ShapeKind::Circle, Sampler::Narrow)
        .iter()
        .map(|(_, p)| *p)
        .fold(1.0, f64::min);
    assert!(worst < alpha, "the biased input passed (smallest p = {worst:.2e})");
}
