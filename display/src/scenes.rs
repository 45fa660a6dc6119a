//! The scenes the firmware runs and the host re-runs, and the one function that runs them.
//!
//! Each [`Scene`] is a complete fill: scalar, shape, rotation, region, c, N, gap, seed and
//! count. [`SCENES`] starts with the canonical runs of docs/firmware.md, What it runs (`circles`, `squares`,
//! `rects`, whose golden digests `tests/tests/golden.rs` pins, and `circles-fixed`) and then
//! covers every shape kind, region and scalar the core has. Adding a scene is one line here:
//! the firmware prints its digest and frame, and the host test checks both.
//!
//! Storage: every scene runs in an engine of [`CAPACITY`] = 1,024 shape slots with
//! [`INDEX_WORDS`] of spatial hash and no coverage bitmap (it only speeds up rejections and
//! never changes a result), the configuration whose memory the firmware measures. A scene
//! with [`Scene::fast`] runs through [`run_fast`] with the cell sampler and [`FAST_CELLS`] cells (its storage runs out
//! and then it stops refining, still exact) and at most [`FAST_CAPACITY`] shapes, so that it
//! needs no more RAM than the others; with [`Scene::batched`] too, through the batched sampler
//! in batches of at most [`SCENE_BATCH`], its lanes on the stack.

use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use zetafill::{
    digest, Batches, CellSampler, CellWords, Engine, Lane, ParamError, Params, Point, Region, Scalar, ShapeKind, StepError, Stop,
    StopReason, Storage,
};
use zetafill::{Group, PolygonRegion, RegionError, Wallpaper};
use zetafill::{MixOrder, ShapeList};

use crate::draw::View;

/// The engine's shape capacity on the board.
pub const CAPACITY: usize = 1024;
/// Hash buckets: an eighth of the host's `2 * capacity` to save RAM (collisions only cost
/// time, never change a result; 128 buckets would save 512 B and cost 48% more instructions
/// per placement for `circles`).
pub const BUCKETS: usize = 128;
/// Index words: one link per shape slot plus the buckets.
pub const INDEX_WORDS: usize = CAPACITY + BUCKETS;
/// Shape slots of a scene that uses the cell sampler.
pub const FAST_CAPACITY: usize = 256;
/// Index words of such a scene.
pub const FAST_INDEX_WORDS: usize = FAST_CAPACITY + BUCKETS;
/// Cells lent to the cell sampler on the board (16 KiB: 32 bytes a cell).
pub const FAST_CELLS: usize = 512;
/// The largest batch of a batched scene, and the lanes it lends (about 0.9 KiB each).
pub const SCENE_BATCH: usize = 4;

/// The number type a scene's geometry runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScalarKind {
    /// IEEE-754 double precision (soft-float on a Cortex-M3).
    F64,
    /// [`zetafill::Fixed`], 32.32 fixed point.
    Fixed,
}

impl ScalarKind {
    /// The name printed by the firmware.
    pub const fn name(self) -> &'static str {
        match self {
            ScalarKind::F64 => "f64",
            ScalarKind::Fixed => "fixed",
        }
    }
}

/// A scene's region: the core's [`Region`], with a polygon given by static vertices (a
/// [`PolygonRegion`] is validated when built, at run time).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SceneRegion {
    /// `Region::Rect`, inclusive (`false`) or periodic (`true`).
    Rect(f64, f64, bool),
    /// `Region::Circle` of this radius.
    Circle(f64),
    /// `Region::Annulus` (outer, inner).
    Annulus(f64, f64),
    /// `Region::Polygon`: rings of vertices split at the exclusive indices given.
    Polygon(&'static [Point<f64>], &'static [usize]),
    /// `Region::Wallpaper`: a group on a lattice of sides a and b at an angle in degrees.
    Wallpaper(Group, f64, f64, f64),
}

impl SceneRegion {
    /// The core's region.
    pub fn region(&self) -> Result<Region<'static>, RegionError> {
        Ok(match *self {
            SceneRegion::Rect(width, height, periodic) => Region::Rect { width, height, periodic },
            SceneRegion::Circle(radius) => Region::Circle { radius },
            SceneRegion::Annulus(outer, inner) => Region::Annulus { outer, inner },
            SceneRegion::Polygon(points, ends) => Region::Polygon(PolygonRegion::new(points, ends)?),
            // The scenes' lattices are finite and positive: a refusal could only be of
            // numbers that are not.
            SceneRegion::Wallpaper(g, a, b, angle) => {
                Region::Wallpaper(Wallpaper::new(g, a, b, angle).map_err(|_| RegionError::NotFinite)?)
            }
        })
    }

    /// The entries a placement stores: a wallpaper group's images, otherwise 1.
    pub const fn images(&self) -> usize {
        match *self {
            SceneRegion::Wallpaper(g, ..) => g.order(),
            _ => 1,
        }
    }
}

/// A complete fill.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scene {
    /// Name in the firmware's output (`digest NAME COUNT HEX16`).
    pub name: &'static str,
    /// Scalar.
    pub scalar: ScalarKind,
    /// The shape, or the shapes of a mix taken in turn.
    pub shapes: &'static [ShapeKind],
    /// Random rotation.
    pub rotate: bool,
    /// Region.
    pub region: SceneRegion,
    /// Exponent c.
    pub c: f64,
    /// Offset N.
    pub n_offset: f64,
    /// Gap (mm).
    pub gap: f64,
    /// Seed.
    pub seed: u64,
    /// Shapes to place.
    pub count: u64,
    /// Placed with the cell sampler (`Engine::step_fast`) rather than the paper's.
    pub fast: bool,
    /// With [`Scene::fast`]: placed by the batched sampler (`Engine::run_batched`, batches of
    /// at most [`SCENE_BATCH`]) on the cells.
    pub batched: bool,
    /// Drawn filled ([`View::fill`]) rather than as outlines ([`View::draw`]).
    pub filled: bool,
}

impl Scene {
    /// The engine parameters (default trial limit); a mix cycles through [`Scene::shapes`].
    pub fn params(&self) -> Result<Params, ParamError> {
        let shape = ShapeList::mix(self.shapes, MixOrder::Cycle, 0).ok_or(ParamError::Shape)?;
        Ok(Params {
            shape,
            rotate: self.rotate,
            gap: self.gap,
            ..Params::circles(self.c, self.n_offset)
        })
    }
}

const fn rect(w: f64, h: f64) -> SceneRegion {
    SceneRegion::Rect(w, h, false)
}

const fn torus(w: f64, h: f64) -> SceneRegion {
    SceneRegion::Rect(w, h, true)
}

#[allow(clippy::too_many_arguments)]
const fn scene(
    name: &'static str,
    scalar: ScalarKind,
    shapes: &'static [ShapeKind],
    rotate: bool,
    region: SceneRegion,
    c: f64,
    n_offset: f64,
    gap: f64,
    seed: u64,
    count: u64,
) -> Scene {
    Scene {
        name,
        scalar,
        shapes,
        rotate,
        region,
        c,
        n_offset,
        gap,
        seed,
        count,
        fast: false,
        batched: false,
        filled: false,
    }
}

/// The same scene placed with the cell sampler.
const fn fast(s: Scene) -> Scene {
    Scene { fast: true, ..s }
}

/// The same scene placed by the batched sampler on the cells.
const fn batched(s: Scene) -> Scene {
    Scene {
        fast: true,
        batched: true,
        ..s
    }
}

/// The same scene drawn filled.
const fn filled(s: Scene) -> Scene {
    Scene { filled: true, ..s }
}

const fn pt(x: f64, y: f64) -> Point<f64> {
    Point { x, y }
}

/// An L-shaped room 120 x 100 mm with a square pillar (a hole): the polygon region.
const ROOM: [Point<f64>; 10] = [
    pt(0.0, 0.0),
    pt(120.0, 0.0),
    pt(120.0, 40.0),
    pt(60.0, 40.0),
    pt(60.0, 100.0),
    pt(0.0, 100.0),
    pt(20.0, 20.0),
    pt(20.0, 35.0),
    pt(35.0, 35.0),
    pt(35.0, 20.0),
];
const ROOM_RINGS: [usize; 2] = [6, 10];

use ScalarKind::{Fixed as FX, F64};
use ShapeKind::{Circle, Square, Triangle};
const RECT2: ShapeKind = ShapeKind::Rect { aspect: 2.0 };

/// Every scene, in the order the firmware runs them. One line each.
#[rustfmt::skip]
pub const SCENES: &[Scene] = &[
    // The canonical runs (docs/firmware.md, tests/src/lib.rs CANONICAL), then on fixed point.
    scene("circles",         F64, &[Circle], false, rect(200.0, 200.0),  1.3,  1.0, 0.0, 1, 500),
    scene("squares",         F64, &[Square], true,  torus(100.0, 100.0), 1.25, 2.0, 0.0, 2, 300),
    scene("rects",           F64, &[RECT2],  false, rect(150.0, 100.0),  1.2,  3.0, 0.0, 3, 300),
    scene("circles-fixed",   FX,  &[Circle], false, rect(200.0, 200.0),  1.3,  1.0, 0.0, 1, 500),
    // Every shape kind, region and scalar the core has: rotation, periodic images, gaps,
    // nesting in rings, non-convex shapes and regions, mixes; fixed-point sin/cos and sqrt.
    scene("squares-fixed",   FX,  &[Square], true,  torus(100.0, 100.0), 1.25, 2.0, 0.0, 2, 300),
    scene("rects-rotated",   F64, &[RECT2],  true,  rect(150.0, 100.0),  1.25, 2.0, 0.0, 4, 200),
    scene("circles-torus",   F64, &[Circle], false, torus(120.0, 80.0),  1.3,  1.0, 0.2, 5, 150),
    scene("rects-gap-fixed", FX,  &[RECT2],  true,  rect(100.0, 100.0),  1.25, 2.0, 0.3, 6, 60),
    scene("squares-gap",     F64, &[Square], false, rect(100.0, 100.0),  1.25, 2.0, 0.2, 7, 80),
    scene("triangles",       F64, &[Triangle], true, rect(100.0, 100.0), 1.25, 3.0, 0.0, 9, 80),
    scene("hexagons-disc",   F64, &[ShapeKind::Polygon { sides: 6 }], true, SceneRegion::Circle(60.0), 1.3, 2.0, 0.0, 10, 100),
    scene("stars-annulus",   F64, &[ShapeKind::Star { points: 5, inner: 0.5 }], true, SceneRegion::Annulus(60.0, 20.0), 1.3, 10.0, 0.0, 11, 60),
    scene("rings-fixed",     FX,  &[ShapeKind::Ring { inner: 0.6 }], false, rect(100.0, 100.0), 1.3, 3.0, 0.0, 12, 60),
    scene("blobs",           F64, &[ShapeKind::Blob { delta: 0.2 }], true, rect(100.0, 100.0), 1.3, 2.0, 0.0, 13, 12),
    scene("mix-room",        F64, &[Circle, Square, Triangle], true, SceneRegion::Polygon(&ROOM, &ROOM_RINGS), 1.3, 2.0, 0.0, 14, 60),
    scene("triangles-disc-fixed", FX, &[Triangle], true, SceneRegion::Circle(60.0), 1.25, 3.0, 0.0, 15, 60),
    // The cell sampler on the board, against the host's bits.
    fast(scene("circles-cells",  F64, &[Circle], false, rect(200.0, 200.0),  1.3,  1.0, 0.0, 16, 250)),
    fast(scene("squares-cells-fixed", FX, &[Square], true, torus(100.0, 100.0), 1.25, 2.0, 0.0, 17, 200)),
    // The batched sampler on one core, against the host's bits for any number of threads.
    batched(scene("circles-batched", F64, &[Circle], false, rect(200.0, 200.0), 1.3, 1.0, 0.0, 22, 250)),
    // Filled shapes: the pixels whose centres are inside (non-convex stars on a torus, rings
    // with their holes, rotated squares through the cell sampler).
    filled(scene("stars-filled", F64, &[ShapeKind::Star { points: 5, inner: 0.45 }], true, torus(100.0, 100.0), 1.25, 4.0, 0.0, 18, 50)),
    filled(scene("rings-filled-fixed", FX, &[ShapeKind::Ring { inner: 0.5 }], false, SceneRegion::Circle(60.0), 1.3, 3.0, 0.0, 19, 60)),
    filled(fast(scene("squares-cells-filled", F64, &[Square], true, rect(200.0, 100.0), 1.25, 2.0, 0.0, 20, 150))),
    // The symmetry of a wallpaper group: each placement an orbit of eight images.
    scene("p4m-mix", F64, &[Circle, Square], true, SceneRegion::Wallpaper(Group::P4m, 60.0, 60.0, 90.0), 1.3, 3.0, 0.0, 23, 40),
    // The whole capacity: 1,024 rectangles.
    scene("capacity",        F64, &[RECT2],  false, rect(150.0, 100.0),  1.2,  3.0, 0.0, 8, CAPACITY as u64),
];

/// Checked at compile time: every scene fits the storage, and the index is valid (indexing
/// here can only fail the build, never panic at run time).
#[allow(clippy::indexing_slicing)]
const _: () = {
    let mut i = 0;
    while i < SCENES.len() {
        assert!(
            SCENES[i].count as usize * SCENES[i].region.images() <= CAPACITY,
            "a scene needs more shapes than CAPACITY"
        );
        assert!(
            !SCENES[i].fast || SCENES[i].count as usize <= FAST_CAPACITY,
            "a cell-sampler scene needs more shapes than FAST_CAPACITY"
        );
        assert!(SCENES[i].count > 0, "a scene must place at least one shape");
        assert!(!SCENES[i].shapes.is_empty(), "a scene needs a shape");
        i += 1;
    }
    assert!(INDEX_WORDS > CAPACITY, "the index needs at least one bucket");
};

/// What a run produced.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Outcome {
    /// Entries the digest covers: the shapes placed (a wallpaper scene's every image).
    pub count: u64,
    /// Placements made (a wallpaper scene's orbits).
    pub placed: u64,
    /// The determinism digest (`zetafill::digest`).
    pub digest: u64,
    /// Trials made.
    pub trials: u64,
    /// Clock ticks spent in [`Engine::step`] only (not drawing), by the caller's clock.
    pub ticks: u64,
}

/// Why a run failed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RunError<E> {
    /// The region was refused.
    Region(RegionError),
    /// The parameters or storage were refused.
    Param(ParamError),
    /// A placement failed (halting, capacity, a shape that cannot fit).
    Step(StepError),
    /// The display refused a drawing.
    Draw(E),
}

impl<E: core::fmt::Debug> core::fmt::Display for RunError<E> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            RunError::Region(e) => write!(f, "invalid region: {e}"),
            RunError::Param(e) => write!(f, "invalid parameters: {e}"),
            RunError::Step(e) => write!(f, "{e}"),
            RunError::Draw(e) => write!(f, "display error: {e:?}"),
        }
    }
}

/// Draws one placed shape as the scene asks: filled or as an outline.
fn paint<S: Scalar, D: DrawTarget<Color = BinaryColor>>(
    scene: &Scene,
    view: &View,
    geo: &zetafill::Geo<S>,
    target: &mut D,
) -> Result<(), D::Error> {
    if scene.filled {
        view.fill(geo, BinaryColor::On, target)
    } else {
        view.draw(geo, target)
    }
}

/// Draws placement `index` of `engine`: its shape, or on a wallpaper torus every image of its
/// orbit with the lattice translates that can show in the cell.
fn paint_placement<S: Scalar, D: DrawTarget<Color = BinaryColor>>(
    scene: &Scene,
    view: &View,
    engine: &Engine<'_, S>,
    index: u64,
    target: &mut D,
) -> Result<(), D::Error> {
    let m = engine.images();
    let first = index as usize * m;
    for e in first..first + m {
        let Some(geo) = engine.geo(e) else { continue };
        match engine.region().wallpaper() {
            Some(w) => {
                let (ax, bx, by) = w.lattice();
                for l in -1i32..=1 {
                    for k in -1i32..=1 {
                        let (dx, dy) = (f64::from(k) * ax + f64::from(l) * bx, f64::from(l) * by);
                        paint(scene, view, &geo.shift(S::from_f64(dx), S::from_f64(dy)), target)?;
                    }
                }
            }
            None => paint(scene, view, &geo, target)?,
        }
    }
    Ok(())
}

/// Runs `scene` on the caller's storage, drawing each shape onto `target` as it is placed.
/// `clock` is read before and after each step, so [`Outcome::ticks`] counts the engine's
/// time only (pass `|| 0` where there is no clock).
pub fn run<S: Scalar, D: DrawTarget<Color = BinaryColor>>(
    scene: &Scene,
    storage: Storage<'_, S>,
    target: &mut D,
    mut clock: impl FnMut() -> u64,
) -> Result<Outcome, RunError<D::Error>> {
    let region = scene.region.region().map_err(RunError::Region)?;
    let params = scene.params().map_err(RunError::Param)?;
    let mut engine = Engine::<S>::new(params, region, storage).map_err(RunError::Param)?;
    let size = target.bounding_box().size;
    let view = View::new(&region, size.width, size.height);
    let mut rng = zetafill::rng_from_seed(scene.seed);
    let mut ticks = 0u64;
    while engine.stats().placed < scene.count {
        let t0 = clock();
        let step = engine.step(&mut rng);
        ticks = ticks.wrapping_add(clock().wrapping_sub(t0));
        let placement = step.map_err(RunError::Step)?;
        paint_placement(scene, &view, &engine, placement.index, target).map_err(RunError::Draw)?;
    }
    let (count, digest) = digest::engine_digest(&engine);
    Ok(Outcome {
        count,
        placed: engine.stats().placed,
        digest,
        trials: engine.stats().trials,
        ticks,
    })
}

/// [`run`] for a [`Scene::fast`] scene: the same, placing with the cell sampler over `cells`
/// (at least one). A separate function, so that the other scenes' stack frames hold no
/// sampler.
pub fn run_fast<S: Scalar, D: DrawTarget<Color = BinaryColor>>(
    scene: &Scene,
    storage: Storage<'_, S>,
    cells: &mut [CellWords],
    target: &mut D,
    mut clock: impl FnMut() -> u64,
) -> Result<Outcome, RunError<D::Error>> {
    let region = scene.region.region().map_err(RunError::Region)?;
    let params = scene.params().map_err(RunError::Param)?;
    let mut engine = Engine::<S>::new(params, region, storage).map_err(RunError::Param)?;
    let mut sampler = CellSampler::new(cells).map_err(|_| RunError::Param(ParamError::Storage))?;
    let size = target.bounding_box().size;
    let view = View::new(&region, size.width, size.height);
    let mut rng = zetafill::rng_from_seed(scene.seed);
    let mut ticks = 0u64;
    if scene.batched {
        ticks = run_batches(scene, &mut engine, &mut sampler, &view, target, &mut clock)?;
    }
    while engine.stats().placed < scene.count {
        let t0 = clock();
        let step = engine.step_fast(&mut sampler, &mut rng);
        ticks = ticks.wrapping_add(clock().wrapping_sub(t0));
        let placement = step.map_err(RunError::Step)?;
        paint_placement(scene, &view, &engine, placement.index, target).map_err(RunError::Draw)?;
    }
    let (count, digest) = digest::engine_digest(&engine);
    Ok(Outcome {
        count,
        placed: engine.stats().placed,
        digest,
        trials: engine.stats().trials,
        ticks,
    })
}

/// The batched part of [`run_fast`], out of line so that its lanes take stack only while a
/// batched scene runs: the placements with the batched sampler, drawn as they are committed,
/// and the clock ticks they took less the drawing's.
#[inline(never)]
fn run_batches<S: Scalar, D: DrawTarget<Color = BinaryColor>>(
    scene: &Scene,
    engine: &mut Engine<'_, S>,
    sampler: &mut CellSampler<'_, S>,
    view: &View,
    target: &mut D,
    clock: &mut impl FnMut() -> u64,
) -> Result<u64, RunError<D::Error>> {
    let mut lanes: [Lane<S>; SCENE_BATCH] = core::array::from_fn(|_| Lane::default());
    let mut batches = Batches::new(&mut lanes, scene.seed, SCENE_BATCH).map_err(|_| RunError::Param(ParamError::Storage))?;
    let stop = Stop {
        count: Some(scene.count),
        ..Stop::default()
    };
    let shapes = engine.params().shape.clone();
    let mut drawn = Ok(());
    let (t0, mut drawing) = (clock(), 0u64);
    let reason = engine.run_batched(sampler, &mut batches, &stop, |p| {
        let d0 = clock();
        let s = p.shape;
        let geo = shapes.kind_of(p.index).geo(Point::new(s.x, s.y), s.scale, s.angle);
        if drawn.is_ok() {
            drawn = paint(scene, view, &geo, target);
        }
        drawing = drawing.wrapping_add(clock().wrapping_sub(d0));
    });
    let ticks = clock().wrapping_sub(t0).wrapping_sub(drawing);
    drawn.map_err(RunError::Draw)?;
    match reason {
        StopReason::Step(e) => Err(RunError::Step(e)),
        _ => Ok(ticks),
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::indexing_slicing)]
mod tests {
    extern crate std;
    use super::*;
    use crate::draw::Frame;
    use std::vec;
    use zetafill::Placed;

    fn run_f64(s: &Scene) -> (Outcome, Frame) {
        let mut shapes = vec![Placed::<f64>::default(); CAPACITY];
        let mut index = vec![0u32; INDEX_WORDS];
        let mut frame = Frame::new();
        let storage = Storage {
            shapes: &mut shapes,
            index: &mut index,
            coverage: &mut [],
        };
        (run(s, storage, &mut frame, || 0).unwrap(), frame)
    }

    #[test]
    fn names_are_unique_and_the_canonical_runs_come_first() {
        let names: std::vec::Vec<_> = SCENES.iter().map(|s| s.name).collect();
        assert_eq!(&names[..4], ["circles", "squares", "rects", "circles-fixed"]);
        for (i, n) in names.iter().enumerate() {
            assert!(!names[..i].contains(n), "{n} twice");
            assert!(!n.contains(' '));
        }
    }

    #[test]
    fn a_run_places_the_count_and_draws_something() {
        let (o, f) = run_f64(&SCENES[2]);
        assert_eq!(o.count, 300);
        assert!(o.trials >= 300);
        assert!(f.data().iter().any(|&b| b != 0));
    }

    #[test]
    fn a_failed_step_is_an_error_not_a_panic() {
        let mut s = SCENES[0];
        s.count = 5;
        let mut shapes = vec![Placed::<f64>::default(); 3];
        let mut index = vec![0u32; 8];
        let mut frame = Frame::new();
        let storage = Storage {
            shapes: &mut shapes,
            index: &mut index,
            coverage: &mut [],
        };
        let e = run(&s, storage, &mut frame, || 0).unwrap_err();
        assert_eq!(e, RunError::Step(StepError::Capacity { capacity: 3 }));
    }

    #[test]
    fn a_cell_sampler_scene_needs_cells() {
        let s = *SCENES.iter().find(|s| s.fast).unwrap();
        let mut shapes = vec![Placed::<f64>::default(); FAST_CAPACITY];
        let mut index = vec![0u32; FAST_INDEX_WORDS];
        let mut frame = Frame::new();
        let storage = Storage {
            shapes: &mut shapes,
            index: &mut index,
            coverage: &mut [],
        };
        let e = run_fast(&s, storage, &mut [], &mut frame, || 0).unwrap_err();
        assert_eq!(e, RunError::Param(ParamError::Storage));
    }
}
