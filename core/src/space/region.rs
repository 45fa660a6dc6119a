//! The regions of a 3D fill and their exact containment tests.

use super::body::{apart, Body};
use super::vec3::V3;
use crate::params::ParamError;
use crate::scalar::Scalar;
use core::f64::consts::PI;

/// The region a 3D fill fills, in mm. A box spans `[0, W] x [0, H] x [0, D]`; a ball of
/// radius `R` is centred at `(R, R, R)` (so it lies in `[0, 2R]^3`).
///
/// # Examples
///
/// ```
/// use zetafill::space::Region;
///
/// let cube = Region::Box { width: 10.0, height: 10.0, depth: 10.0, periodic: false };
/// assert_eq!(cube.volume(), 1000.0);
/// let ball = Region::Ball { radius: 3.0 };
/// assert!((ball.volume() - 36.0 * std::f64::consts::PI).abs() < 1e-12);
/// // A box with a ball removed: the ball must lie inside the box.
/// let holed = Region::BoxMinusBall { width: 10.0, height: 10.0, depth: 10.0, centre: [5.0, 5.0, 5.0], radius: 2.0 };
/// assert!(holed.check().is_ok());
/// let poking = Region::BoxMinusBall { width: 10.0, height: 10.0, depth: 10.0, centre: [1.0, 5.0, 5.0], radius: 2.0 };
/// assert!(poking.check().is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SpaceRegion {
    /// A box, inclusive (solids may touch its faces when the gap is 0) or periodic in x, y
    /// and z (a solid crossing a face exists again on the other side).
    Box {
        /// Side along x.
        width: f64,
        /// Side along y.
        height: f64,
        /// Side along z.
        depth: f64,
        /// Periodic boundary.
        periodic: bool,
    },
    /// A ball centred at `(R, R, R)`.
    Ball {
        /// Radius R.
        radius: f64,
    },
    /// An inclusive box with a ball removed; the ball lies inside the box (it may touch its
    /// faces). Solids keep more than the gap from the ball's surface (touching it counts as
    /// overlapping); a shell may hold the ball in its hole.
    BoxMinusBall {
        /// Side along x.
        width: f64,
        /// Side along y.
        height: f64,
        /// Side along z.
        depth: f64,
        /// The removed ball's centre.
        centre: [f64; 3],
        /// The removed ball's radius.
        radius: f64,
    },
}

impl SpaceRegion {
    /// The region's volume.
    pub fn volume(&self) -> f64 {
        match *self {
            SpaceRegion::Box { width, height, depth, .. } => width * height * depth,
            SpaceRegion::Ball { radius } => 4.0 / 3.0 * PI * radius * radius * radius,
            SpaceRegion::BoxMinusBall {
                width,
                height,
                depth,
                radius,
                ..
            } => width * height * depth - 4.0 / 3.0 * PI * radius * radius * radius,
        }
    }

    /// The box that holds the region: its sides along x, y and z (it starts at the origin).
    pub fn extent(&self) -> [f64; 3] {
        match *self {
            SpaceRegion::Box { width, height, depth, .. } | SpaceRegion::BoxMinusBall { width, height, depth, .. } => {
                [width, height, depth]
            }
            SpaceRegion::Ball { radius } => [2.0 * radius; 3],
        }
    }

    /// Whether the boundary is periodic.
    pub fn periodic(&self) -> bool {
        matches!(self, SpaceRegion::Box { periodic: true, .. })
    }

    /// Checks the sizes: finite and positive ([`ParamError::Region`]), a removed ball inside
    /// its box with some volume left ([`ParamError::Region`]).
    pub fn check(&self) -> Result<(), ParamError> {
        let pos = |v: f64| v.is_finite() && v > 0.0;
        let ok = match *self {
            SpaceRegion::Box { width, height, depth, .. } => pos(width) && pos(height) && pos(depth),
            SpaceRegion::Ball { radius } => pos(radius),
            SpaceRegion::BoxMinusBall {
                width,
                height,
                depth,
                centre,
                radius,
            } => {
                let inside = centre
                    .iter()
                    .zip([width, height, depth])
                    .all(|(&c, side)| c.is_finite() && c - radius >= 0.0 && c + radius <= side);
                pos(width) && pos(height) && pos(depth) && pos(radius) && inside && pos(self.volume())
            }
        };
        if ok && pos(self.volume()) {
            Ok(())
        } else {
            Err(ParamError::Region)
        }
    }

    /// The removed ball as a body (the ball region's own ball for [`SpaceRegion::Ball`]).
    /// The removed ball's radius, if the region has one.
    pub(crate) fn ball_radius(&self) -> Option<f64> {
        match *self {
            SpaceRegion::BoxMinusBall { radius, .. } => Some(radius),
            _ => None,
        }
    }

    fn ball<S: Scalar>(&self) -> Option<Body<S>> {
        match *self {
            SpaceRegion::BoxMinusBall { centre, radius, .. } => Some(Body::Ball {
                c: V3::from_f64(centre[0], centre[1], centre[2]),
                r: S::from_f64(radius),
            }),
            _ => None,
        }
    }

    /// Whether `b` lies in the region, at least `gap` from its boundary (for a periodic box:
    /// always; the images are the engine's business).
    pub fn holds<S: Scalar>(&self, b: &Body<S>, gap: S) -> bool {
        let [w, h, d] = self.extent();
        let in_box = |c: V3<S>, r: S| {
            let lo = r + gap;
            let (hx, hy, hz) = (S::from_f64(w) - lo, S::from_f64(h) - lo, S::from_f64(d) - lo);
            c.x >= lo && c.y >= lo && c.z >= lo && c.x <= hx && c.y <= hy && c.z <= hz
        };
        let inside = match *self {
            SpaceRegion::Box { periodic: true, .. } => return true,
            SpaceRegion::Ball { radius } => {
                let room = S::from_f64(radius) - gap;
                let o = S::from_f64(radius);
                let o = V3::new(o, o, o);
                match b {
                    Body::Ball { c, r } | Body::Shell { c, r, .. } => {
                        let d = room - *r;
                        d >= S::ZERO && c.sub(o).norm2() <= d * d
                    }
                    Body::Torus { tube, .. } => {
                        let d = room - *tube;
                        d >= S::ZERO && b.beads().iter().all(|p| p.sub(o).norm2() <= d * d)
                    }
                    Body::Poly(_) => room >= S::ZERO && b.vertices().iter().all(|v| v.sub(o).norm2() <= room * room),
                }
            }
            _ => match b {
                Body::Ball { c, r } | Body::Shell { c, r, .. } => in_box(*c, *r),
                Body::Torus { tube, .. } => b.beads().iter().all(|p| in_box(*p, *tube)),
                Body::Poly(_) => b.vertices().iter().all(|v| in_box(*v, S::ZERO)),
            },
        };
        // The removed ball is tested like a placed solid: more than `gap` from it, so
        // touching it counts as overlapping (the conservative side of an inclusive boundary).
        inside && self.ball::<S>().is_none_or(|ball| apart(b, &ball, gap))
    }

    /// The signed distance from `p` to the outside of the region (positive inside; a large
    /// value for a periodic box).
    pub fn edge<S: Scalar>(&self, p: V3<S>) -> S {
        let [w, h, d] = self.extent();
        let to_box = || {
            let (w, h, d) = (S::from_f64(w), S::from_f64(h), S::from_f64(d));
            p.x.min(w - p.x).min(p.y).min(h - p.y).min(p.z).min(d - p.z)
        };
        match *self {
            SpaceRegion::Box { periodic: true, .. } => S::from_f64(w.max(h).max(d)),
            SpaceRegion::Box { .. } => to_box(),
            SpaceRegion::Ball { radius } => {
                let r = S::from_f64(radius);
                r - p.sub(V3::new(r, r, r)).norm2().sqrt()
            }
            SpaceRegion::BoxMinusBall { centre, radius, .. } => {
                let c = V3::from_f64(centre[0], centre[1], centre[2]);
                to_box().min(p.sub(c).norm2_up().sqrt() - S::from_f64(radius))
            }
        }
    }
}
