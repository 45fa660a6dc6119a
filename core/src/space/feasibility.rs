//! Up-front checks of a 3D fill: the slots a stop condition needs, and a first solid too
//! large for the region.

use super::engine::SpaceParams;
use super::region::SpaceRegion;
use super::solid::SolidList;
use crate::feasibility::{capacity, AreaSequence, CapacityError};
use crate::params::Stop;
use crate::zeta;

/// [`crate::internals::feasibility::capacity`] for solids: the width of solid `k` is its
/// narrowest width at volume `seq.area(k)`.
///
/// # Examples
///
/// ```
/// use zetafill::{space_capacity, AreaSequence, Solid, Stop};
///
/// let seq = AreaSequence::new(1000.0, 1.2, 1.0)?;
/// let stop = Stop { min_size: Some(0.5), ..Stop::default() };
/// let slots = space_capacity(&seq, &Solid::Sphere.into(), &stop, 10_000_000)?;
/// assert!(Solid::Sphere.min_width(Solid::Sphere.scale_for_volume(seq.area(slots - 1))) < 0.5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn space_capacity(seq: &AreaSequence, solids: &SolidList, stop: &Stop, max: u64) -> Result<u64, CapacityError> {
    capacity(seq, stop, max, |k| {
        let kind = solids.kind_of(k);
        kind.min_width(kind.scale_for_volume(seq.area(k)))
    })
}

/// The first solid cannot fit in the region's box with its gap (it is wider, in every
/// orientation, than the box's smallest side): `max_c` is the largest c (60 halvings of
/// `[1 + 1e-9, c]`) at which it fits, if any.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FirstSolidError {
    /// The largest c that works at this N, or `None` when none does (raise N, lower the gap).
    pub max_c: Option<f64>,
}

impl core::fmt::Display for FirstSolidError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.max_c {
            Some(c) => write!(f, "the first solid is larger than the region: lower c to at most {c}"),
            None => f.write_str("the first solid is larger than the region at any c: raise N or lower the gap"),
        }
    }
}

impl core::error::Error for FirstSolidError {}

/// Whether the first solid fits in the region's box with its gap (a necessary condition,
/// what [`crate::SpaceEngine::step`] reports as [`crate::StepError::CannotFit`]); the
/// parameters are assumed valid ([`crate::SpaceEngine::new`] checks them).
///
/// # Examples
///
/// ```
/// use zetafill::{check_first_solid, SpaceParams, SpaceRegion};
///
/// let region = SpaceRegion::Box { width: 10.0, height: 10.0, depth: 1.0, periodic: false };
/// let e = check_first_solid(&SpaceParams::spheres(1.5, 1.0), &region).unwrap_err();
/// let c = e.max_c.expect("a smaller c works");
/// assert!(c > 1.0 && c < 1.5);
/// assert!(check_first_solid(&SpaceParams::spheres(c, 1.0), &region).is_ok());
/// ```
pub fn check_first_solid(params: &SpaceParams, region: &SpaceRegion) -> Result<(), FirstSolidError> {
    if region.periodic() {
        return Ok(());
    }
    let side = region.extent().iter().fold(f64::MAX, |m, &e| m.min(e));
    let kind = params.solids.kind_of(0);
    let fits = |c: f64| {
        let v = region.volume() / (zeta::zeta(c, params.n_offset).unwrap_or(f64::MAX) * libm::pow(params.n_offset, c));
        2.0 * (kind.support(kind.scale_for_volume(v)) + params.gap) <= side
    };
    if fits(params.c) {
        return Ok(());
    }
    let mut lo = 1.0 + 1e-9;
    if !fits(lo) {
        return Err(FirstSolidError { max_c: None });
    }
    let mut hi = params.c;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if fits(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Err(FirstSolidError { max_c: Some(lo) })
}
