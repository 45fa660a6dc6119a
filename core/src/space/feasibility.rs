//! Up-front checks of a 3D fill: the slots a stop condition needs, and a first solid too
//! large for the region.

use super::engine::SpaceParams;
use super::region::SpaceRegion;
use super::solid::{Solid, SolidList};
use crate::feasibility::{bisect, capacity, AreaSequence, CapacityError};
use crate::params::Stop;

/// A refusal of the first solids, with the largest c that would work: the struct, its
/// message (`WHAT: lower c to at most C`, or `WHAT at any c: raise N or lower the gap`) and its
/// `Error` impl.
macro_rules! max_c_error {
    ($(#[$doc:meta])* $name:ident, $what:literal) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq)]
        #[cfg_attr(feature = "defmt", derive(defmt::Format))]
        pub struct $name {
            /// The largest c that works at this N, or `None` when none does (raise N, lower the gap).
            pub max_c: Option<f64>,
        }

        impl core::fmt::Display for $name {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                match self.max_c {
                    Some(c) => write!(f, concat!($what, ": lower c to at most {}"), c),
                    None => f.write_str(concat!($what, " at any c: raise N or lower the gap")),
                }
            }
        }

        impl core::error::Error for $name {}
    };
}

/// [`crate::internals::feasibility::capacity`] for solids: the width of solid `k` is its
/// narrowest width at volume `seq.area(k)`.
///
/// # Examples
///
/// ```
/// use zetafill::{AreaSequence, Stop};
/// use zetafill::space::{capacity, Solid};
///
/// let seq = AreaSequence::new(1000.0, 1.2, 1.0)?;
/// let stop = Stop { min_size: Some(0.5), ..Stop::default() };
/// let slots = capacity(&seq, &Solid::Sphere.into(), &stop, 10_000_000)?;
/// assert!(Solid::Sphere.min_width(Solid::Sphere.scale_for_volume(seq.area(slots - 1))) < 0.5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn space_capacity(seq: &AreaSequence, solids: &SolidList, stop: &Stop, max: u64) -> Result<u64, CapacityError> {
    capacity(seq, stop, max, |k| {
        let kind = solids.kind_of(k);
        kind.min_width(kind.scale_for_volume(seq.area(k)))
    })
}

max_c_error!(
    /// The first solid cannot fit in the region's box with its gap (it is wider, in every
    /// orientation, than the box's smallest side; in a periodic box, so wide that it meets its own
    /// image one period away): `max_c` is the largest c (60 halvings of
    /// `[1 + 1e-9, c]`) at which it fits, if any.
    FirstSolidError,
    "the first solid is larger than the region"
);

/// Whether the first solid fits in the region's box with its gap (a necessary condition,
/// what [`crate::space::Engine::step`] reports as [`crate::StepError::CannotFit`]), or, in a
/// periodic box, clears its own image one period away by the gap (else every trial would be
/// refused); the parameters are assumed valid ([`crate::space::Engine::new`] checks them).
///
/// # Examples
///
/// ```
/// use zetafill::space::{check_first, Params, Region};
///
/// let region = Region::Box { width: 10.0, height: 10.0, depth: 1.0, periodic: false };
/// let e = check_first(&Params::spheres(1.5, 1.0), &region).unwrap_err();
/// let c = e.max_c.expect("a smaller c works");
/// assert!(c > 1.0 && c < 1.5);
/// assert!(check_first(&Params::spheres(c, 1.0), &region).is_ok());
/// ```
pub fn check_first_solid(params: &SpaceParams, region: &SpaceRegion) -> Result<(), FirstSolidError> {
    let side = region.extent().iter().fold(f64::MAX, |m, &e| m.min(e));
    let kind = params.solids.kind_of(0);
    let periodic = region.periodic();
    let fits = |c: f64| {
        let v = AreaSequence::new(region.volume(), c, params.n_offset).map_or(0.0, |s| s.area(0));
        let scale = kind.scale_for_volume(v);
        if periodic {
            // Its image one period away must clear it by the gap too.
            self_width(&kind, scale) + params.gap <= side
        } else {
            2.0 * (kind.support(scale) + params.gap) <= side
        }
    };
    if fits(params.c) {
        return Ok(());
    }
    let lowest = 1.0 + 1e-9;
    if !fits(lowest) {
        return Err(FirstSolidError { max_c: None });
    }
    Err(FirstSolidError {
        max_c: Some(bisect(lowest, params.c, fits)),
    })
}

/// A width below which a solid meets every copy of itself shifted by less, in any direction
/// and orientation: then a periodic box with a shorter side holds it nowhere, as it meets its
/// own image. For a convex solid that is its narrowest width (the copy shifted by `t` meets it
/// exactly when `t` lies in the solid's difference body, which holds the ball of that
/// radius); for a torus of beads, twice the beads' radius (each bead meets its own copy). A
/// shell meets its copy while the outer spheres cross: twice its outer radius.
fn self_width(kind: &Solid, scale: f64) -> f64 {
    match *kind {
        Solid::Shell { .. } => 2.0 * scale,
        _ => kind.min_width(scale),
    }
}

max_c_error!(
    /// The first two solids certainly cannot both be placed (every run would halt at placement
    /// 1): `max_c` is the largest c (60 halvings of `[1 + 1e-9, c]`) at which they can, if any.
    /// See [`check_first_two_solids`].
    FirstTwoSolidsError,
    "the first two solids cannot both fit"
);

/// Whether solids 0 and 1, of scales `s0` and `s1`, can both lie in `region` at least `gap`
/// from its boundary and from each other, for the cases whose limit is known exactly:
/// spheres in an inclusive box (in opposite corners) or in a ball (on opposite sides), and
/// unrotated cubes in an inclusive box (side by side along some axis). True for every other
/// case (no known limit).
pub fn first_two_solids_fit(kind: Solid, rotate: bool, s0: f64, s1: f64, region: &SpaceRegion, gap: f64) -> bool {
    match (kind, region) {
        (Solid::Sphere, SpaceRegion::Box { periodic: false, .. }) => {
            let room = region.extent().map(|e| e - 2.0 * gap);
            let mut d2 = 0.0;
            for e in room {
                if 2.0 * s0 > e {
                    return false;
                }
                let d = e - s0 - s1;
                d2 += if d > 0.0 { d * d } else { 0.0 };
            }
            d2 > (s0 + s1 + gap) * (s0 + s1 + gap)
        }
        (Solid::Sphere, SpaceRegion::Ball { radius }) => {
            let (a, b) = (radius - gap - s0, radius - gap - s1);
            a >= 0.0 && a + b > s0 + s1 + gap
        }
        (Solid::Cube, SpaceRegion::Box { periodic: false, .. }) if !rotate => {
            let room = region.extent().map(|e| e - 2.0 * gap);
            let (w0, w1) = (2.0 * s0, 2.0 * s1);
            room.iter().all(|&e| w0 <= e) && room.iter().any(|&e| w0 + w1 + gap < e)
        }
        _ => true,
    }
}

/// Refuses parameters whose first two solids certainly cannot both fit, for the cases of
/// [`first_two_solids_fit`] and a single kind (no mix). This is the hard limit on c of Shier
/// and Bourke's section 3 in 3D: about 1.2 for unrotated cubes in a cube at N = 1.
///
/// # Examples
///
/// ```
/// use zetafill::space::{check_first_two, Params, Region, Solid};
///
/// let region = Region::Box { width: 100.0, height: 100.0, depth: 100.0, periodic: false };
/// let mut params = Params::spheres(1.15, 1.0);
/// params.solids = Solid::Cube.into();
/// params.rotate = false;
/// assert!(check_first_two(&params, &region).is_ok());
/// params.c = 1.3;
/// let c = check_first_two(&params, &region).unwrap_err().max_c.expect("a smaller c works");
/// assert!(c > 1.19 && c < 1.21);
/// ```
pub fn check_first_two_solids(params: &SpaceParams, region: &SpaceRegion) -> Result<(), FirstTwoSolidsError> {
    let [kind] = params.solids.kinds() else {
        return Ok(());
    };
    let kind = *kind;
    let n = params.n_offset;
    let fits = |c: f64| {
        let Ok(seq) = AreaSequence::new(region.volume(), c, n) else {
            return false;
        };
        let (s0, s1) = (kind.scale_for_volume(seq.area(0)), kind.scale_for_volume(seq.area(1)));
        first_two_solids_fit(kind, params.rotate, s0, s1, region, params.gap)
    };
    if fits(params.c) {
        return Ok(());
    }
    let lowest = 1.0 + 1e-9;
    if !fits(lowest) {
        return Err(FirstTwoSolidsError { max_c: None });
    }
    Err(FirstTwoSolidsError {
        max_c: Some(bisect(lowest, params.c, fits)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_limit_errors_say_what_to_change() {
        extern crate std;
        use std::string::ToString;
        let cases = [
            (
                FirstSolidError { max_c: Some(1.5) }.to_string(),
                "the first solid is larger than the region: lower c to at most 1.5",
            ),
            (
                FirstSolidError { max_c: None }.to_string(),
                "the first solid is larger than the region at any c: raise N or lower the gap",
            ),
            (
                FirstTwoSolidsError { max_c: Some(1.25) }.to_string(),
                "the first two solids cannot both fit: lower c to at most 1.25",
            ),
            (
                FirstTwoSolidsError { max_c: None }.to_string(),
                "the first two solids cannot both fit at any c: raise N or lower the gap",
            ),
        ];
        for (got, want) in cases {
            assert_eq!(got, want);
        }
    }

    #[test]
    fn a_periodic_first_sphere_must_clear_its_own_image() {
        let region = SpaceRegion::Box {
            width: 100.0,
            height: 100.0,
            depth: 100.0,
            periodic: true,
        };
        // Control: a small first sphere passes.
        assert!(check_first_solid(&SpaceParams::spheres(1.3, 1.0), &region).is_ok());
        let e = check_first_solid(&SpaceParams::spheres(1.8, 1.0), &region);
        let c = e.err().and_then(|e| e.max_c).unwrap_or(0.0);
        assert!(c > 1.3 && c < 1.8, "{c}");
        // At the limit the diameter is the period.
        let v = region.volume() / (crate::zeta::zeta(c, 1.0).unwrap_or(f64::MAX));
        let d = 2.0 * Solid::Sphere.scale_for_volume(v);
        assert!((d - 100.0).abs() < 1e-6 && d <= 100.0, "{d}");
        assert!(check_first_solid(&SpaceParams::spheres(c, 1.0), &region).is_ok());
    }
}
