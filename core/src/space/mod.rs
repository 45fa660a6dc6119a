//! The three-dimensional fill (Shier and Bourke, "An Algorithm for Random Fractal Filling of
//! Space": the algorithm "in 1, 2, or 3 physical dimensions"): solids of volume
//! `V_i = V / (zeta(c, N) (i + N)^c)` in a region of volume `V`, fractal dimension `D = 3 / c`.
//!
//! It shares the volume sequence ([`crate::AreaSequence`]), the zeta code, the generator and
//! its mapping ([`crate::internals::rng`]), the stop conditions and errors ([`crate::Stop`],
//! [`crate::StopReason`], [`crate::StepError`], [`crate::ParamError`]), the statistics
//! ([`crate::Stats`]) and the digest hasher with the 2D and 1D fills.
//!
//! - `solid`: the kinds ([`Solid`]), mixes ([`SolidList`], the 2D [`crate::MixOrder`]),
//!   sizes from volumes, the polyhedra's tables;
//! - `vec3`: points, quaternions, and the uniform random rotation (Shoemake's, from three unit
//!   values; see [`vec3`]);
//! - `body`: a solid in place and the exact clearance test between two ([`apart`]);
//! - `region`: boxes (inclusive or periodic), balls, a box with a ball removed;
//! - `hash`: the 3D multi-level spatial hash in caller storage;
//! - `engine`: the paper's loop ([`SpaceEngine::step`]);
//! - `cells`: the octree cell sampler ([`SpaceCells`], [`SpaceEngine::step_fast`]), the same
//!   distribution of placements with far fewer trials.
//!
//! ## Tori are beads
//! A torus of major radius `R` and tube radius `a = ratio R` is represented, tested and meant
//! to be drawn as the exact union of `n = ceil(4 pi / ratio)` balls of radius `a` centred on
//! its centre line at equal angles (at most `a / 2` apart along the line; 51 beads for ratio
//! 0.25; ratio is kept in `[0.2, 0.9]` so that `n <= 64`). Every test then reduces to sphere
//! tests, which are exact and cheap in both scalars, the tested solid is the drawn solid, and
//! a torus's hole stays open: rings chain-link as in the paper's Figure 1. An exact torus test
//! against polyhedra would need quartic root finding, neither exact nor portable bit for bit.
//! The union holds the ideal torus of tube radius `a - 2 R sin(pi / (2 n))` (at least
//! `0.75 a`), and a mesh of that torus lies inside the tested solid; the volume counted is the
//! ideal torus's `2 pi^2 a^2 R`.
//!
//! ## Rotations
//! A rotated solid draws, before its centre, a unit quaternion by Shoemake's method from three
//! unit values `u1`, then the angles `2 pi u2` and `2 pi u3` (each a `next_u64()` mapped like
//! every unit value and angle of the crate): `q = (sqrt(1 - u1) sin(2 pi u2), sqrt(1 - u1)
//! cos(2 pi u2), sqrt(u1) sin(2 pi u3), sqrt(u1) cos(2 pi u3))` as `[w, x, y, z]`, uniform on
//! the unit 3-sphere, so the rotation is uniform in SO(3). Spheres and shells draw none.
//!
//! ## A trial
//! Draws the rotation (when rotated), then x, y and z uniform over the box of centres whose
//! solid keeps its support distance ([`Solid::support`]) plus the gap from the region's box
//! (the period itself for a periodic box), builds the solid, and accepts it when it lies in
//! the region (at least `gap` from the boundary, touching allowed when the gap is 0) and keeps
//! more than `gap` from every placed solid and periodic image (touching is overlapping).
//!
//! Guarantees as in 2D: caller-owned storage, no panics on any input, the same bits on every
//! target for each scalar, prefix stability, what a scalar cannot compute refused
//! ([`crate::Scalar::MAX_EXTENT`], [`crate::Scalar::MIN_SIZE`]).

mod body;
mod cells;
mod engine;
mod feasibility;
mod hash;
mod region;
mod solid;
pub mod vec3;

pub use body::{apart, Body, Poly};
pub use cells::{
    space_cells_for, NoSpaceCells, SpaceCell, SpaceCells, SPACE_CELLS_BASE, SPACE_CELLS_PER_SOLID, SPACE_CELL_LEVELS, SPACE_NEAR,
};
pub use engine::{space_index_words, PlacedSolid, SpaceEngine, SpaceParams, SpacePlacement, SpaceStorage};
pub use feasibility::{
    check_first_solid, check_first_two_solids, first_two_solids_fit, space_capacity, FirstSolidError, FirstTwoSolidsError,
};
pub use hash::SPACE_LEVELS;
pub use region::SpaceRegion;
pub use solid::{Solid, SolidList, MAX_BEADS, MAX_SOLIDS};
pub use vec3::{Quat, V3};
