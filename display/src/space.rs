//! The 3D scenes the firmware runs and the host re-runs, and the one function that runs them.
//!
//! Each [`SpaceScene`] is a complete 3D fill (Shier and Bourke, "An Algorithm for Random
//! Fractal Filling of Space", in three dimensions): scalar, solids, rotation, region, c, N,
//! gap, seed and count. The firmware prints the digest of every placed solid's bits
//! ([`zetafill::digest::space_digest`], the line `zetafill space ... --format digest` writes)
//! and the host recomputes it through the same core. A 3D scene draws nothing: the board's
//! display is the 2D scenes' business.
//!
//! Storage: every 3D scene runs in a [`zetafill::space::Engine`] of [`SPACE_CAPACITY`] solid
//! slots (64 bytes each, whatever the scalar) and [`SPACE_INDEX_WORDS`] of 3D spatial hash,
//! the configuration whose memory the firmware measures on its own stack frame.

use zetafill::space::{Engine as SpaceEngine, Params as SpaceParams, Region as SpaceRegion, Solid, SolidList, Storage as SpaceStorage};
use zetafill::{digest, MixOrder, ParamError, Scalar, StepError};

use crate::scenes::{Outcome, ScalarKind};

/// Solid slots of a 3D scene on the board.
pub const SPACE_CAPACITY: usize = 256;
/// Index words of a 3D scene: the core's [`zetafill::space::index_words`] for the capacity.
pub const SPACE_INDEX_WORDS: usize = zetafill::space::index_words(SPACE_CAPACITY);

/// A complete 3D fill.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceScene {
    /// Name in the firmware's output (`digest NAME COUNT HEX16`).
    pub name: &'static str,
    /// Scalar.
    pub scalar: ScalarKind,
    /// The solid, or the solids of a mix taken in turn.
    pub solids: &'static [Solid],
    /// Uniform random rotation (for the solids that take one).
    pub rotate: bool,
    /// Region.
    pub region: SpaceRegion,
    /// Exponent c.
    pub c: f64,
    /// Offset N.
    pub n_offset: f64,
    /// Gap (mm).
    pub gap: f64,
    /// Seed.
    pub seed: u64,
    /// Solids to place.
    pub count: u64,
}

impl SpaceScene {
    /// The engine parameters (default trial limit); a mix cycles through
    /// [`SpaceScene::solids`].
    pub fn params(&self) -> Result<SpaceParams, ParamError> {
        let solids = SolidList::mix(self.solids, MixOrder::Cycle, 0).ok_or(ParamError::Shape)?;
        Ok(SpaceParams {
            solids,
            rotate: self.rotate,
            gap: self.gap,
            ..SpaceParams::spheres(self.c, self.n_offset)
        })
    }
}

const fn cube_box(side: f64) -> SpaceRegion {
    SpaceRegion::Box {
        width: side,
        height: side,
        depth: side,
        periodic: false,
    }
}

const fn periodic_box(side: f64) -> SpaceRegion {
    SpaceRegion::Box {
        width: side,
        height: side,
        depth: side,
        periodic: true,
    }
}

const fn ball(radius: f64) -> SpaceRegion {
    SpaceRegion::Ball { radius }
}

use ScalarKind::{Fixed as FX, F64};
use Solid::{Cube, Sphere};
const RING: Solid = Solid::Torus { ratio: 0.4 };

/// Every 3D scene, in the order the firmware runs them. One line each.
#[rustfmt::skip]
pub const SPACE_SCENES: &[SpaceScene] = &[
    // Spheres in a box, on both scalars.
    SpaceScene { name: "spheres-box",       scalar: F64, solids: &[Sphere], rotate: false, region: cube_box(60.0), c: 1.15, n_offset: 2.0, gap: 0.0, seed: 31, count: 200 },
    SpaceScene { name: "spheres-box-fixed", scalar: FX,  solids: &[Sphere], rotate: false, region: cube_box(60.0), c: 1.15, n_offset: 2.0, gap: 0.0, seed: 31, count: 200 },
    // Rotated cubes in a ball: Shier and Bourke's Figure 12 in small.
    SpaceScene { name: "cubes-ball",        scalar: F64, solids: &[Cube],   rotate: true,  region: ball(50.0),     c: 1.1,  n_offset: 1.0, gap: 0.0, seed: 32, count: 60 },
    // Rings and spheres in a periodic box, with a gap, on fixed point (the paper's Figure 1's
    // rings, beads and periodic images).
    SpaceScene { name: "rings-torus-fixed", scalar: FX,  solids: &[RING, Sphere], rotate: true, region: periodic_box(60.0), c: 1.15, n_offset: 2.0, gap: 0.2, seed: 34, count: 30 },
];

/// Checked at compile time: every scene fits the storage (indexing here can only fail the
/// build, never panic at run time).
#[allow(clippy::indexing_slicing)]
const _: () = {
    let mut i = 0;
    while i < SPACE_SCENES.len() {
        assert!(
            SPACE_SCENES[i].count as usize <= SPACE_CAPACITY,
            "a 3D scene needs more solids than SPACE_CAPACITY"
        );
        assert!(SPACE_SCENES[i].count > 0, "a 3D scene must place at least one solid");
        assert!(!SPACE_SCENES[i].solids.is_empty(), "a 3D scene needs a solid");
        i += 1;
    }
};

/// Why a 3D run failed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpaceRunError {
    /// The parameters, region or storage were refused.
    Param(ParamError),
    /// A placement failed (halting, capacity, a solid that cannot fit).
    Step(StepError),
}

impl core::fmt::Display for SpaceRunError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            SpaceRunError::Param(e) => write!(f, "invalid parameters: {e}"),
            SpaceRunError::Step(e) => write!(f, "{e}"),
        }
    }
}

/// Runs `scene` on the caller's storage. `clock` is read before and after each step, so
/// [`Outcome::ticks`] counts the engine's time only (pass `|| 0` where there is no clock).
pub fn run_space<S: Scalar>(
    scene: &SpaceScene,
    storage: SpaceStorage<'_, S>,
    mut clock: impl FnMut() -> u64,
) -> Result<Outcome, SpaceRunError> {
    let params = scene.params().map_err(SpaceRunError::Param)?;
    let mut engine = SpaceEngine::<S>::new(params, scene.region, storage).map_err(SpaceRunError::Param)?;
    let mut rng = zetafill::rng_from_seed(scene.seed);
    let mut ticks = 0u64;
    while (engine.placed().len() as u64) < scene.count {
        let t0 = clock();
        let step = engine.step(&mut rng);
        ticks = ticks.wrapping_add(clock().wrapping_sub(t0));
        step.map_err(SpaceRunError::Step)?;
    }
    let (count, digest) = digest::space_digest(&engine);
    Ok(Outcome {
        count,
        placed: count,
        digest,
        trials: engine.stats().trials,
        ticks,
    })
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::indexing_slicing)]
mod tests {
    extern crate std;
    use super::*;
    use crate::scenes::SCENES;
    use std::vec;
    use zetafill::space::Placed as PlacedSolid;

    fn storage_run(s: &SpaceScene, cap: usize) -> Result<Outcome, SpaceRunError> {
        let mut solids = vec![PlacedSolid::<f64>::default(); cap];
        let mut index = vec![0u32; zetafill::space::index_words(cap)];
        let storage = SpaceStorage {
            solids: &mut solids,
            index: &mut index,
        };
        run_space(s, storage, || 0)
    }

    #[test]
    fn names_are_unique_across_2d_and_3d() {
        let names: std::vec::Vec<_> = SCENES.iter().map(|s| s.name).chain(SPACE_SCENES.iter().map(|s| s.name)).collect();
        for (i, n) in names.iter().enumerate() {
            assert!(!names[..i].contains(n), "{n} twice");
            assert!(!n.contains(' '));
        }
    }

    #[test]
    fn a_run_places_the_count() {
        let o = storage_run(&SPACE_SCENES[0], SPACE_CAPACITY).unwrap();
        assert_eq!(o.count, SPACE_SCENES[0].count);
        assert!(o.trials >= o.count);
    }

    #[test]
    fn a_failed_step_is_an_error_not_a_panic() {
        let e = storage_run(&SPACE_SCENES[0], 3).unwrap_err();
        assert_eq!(e, SpaceRunError::Step(StepError::Capacity { capacity: 3 }));
    }
}
