//! The 3D engine: the paper's loop over caller-owned storage ([`SpaceEngine::step`]).

use super::body::{apart, bound_of, BeadTrig, Body};
use super::hash::{Hash3, NIL};
use super::region::SpaceRegion;
use super::solid::{bounding, Solid, SolidList};
use super::vec3::{identity, random_rotation, Quat, V3};
use crate::engine::Stats;
use crate::feasibility::AreaSequence;
use crate::params::{ParamError, StepError, Stop, StopReason};
use crate::rng;
use crate::scalar::Scalar;
use rand_core::RngCore;

/// The parameters of a 3D fill: volumes `V_i = V / (zeta(c, N) (i + N)^c)`, fractal dimension
/// `D = 3 / c`.
///
/// # Examples
///
/// ```
/// use zetafill::space::{Params, Solid};
///
/// let spheres = Params::spheres(1.15, 1.0);
/// assert_eq!(spheres.solids.kinds(), &[Solid::Sphere]);
/// let cubes = Params { solids: Solid::Cube.into(), rotate: true, gap: 0.2, ..Params::spheres(Params::c_from_dimension(2.5), 1.0) };
/// assert_eq!(cubes.c, 1.2);
/// ```
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct SpaceParams {
    /// The power-law exponent c (> 1).
    pub c: f64,
    /// The offset N (> 0).
    pub n_offset: f64,
    /// The solid placed, or a mix.
    pub solids: SolidList,
    /// Uniformly random rotation (for solids that rotate; see [`Solid::rotates`]).
    pub rotate: bool,
    /// Minimum clearance between solids and to the boundary (>= 0).
    pub gap: f64,
    /// Trial limit per placement (>= 1).
    pub max_trials: u64,
}

impl SpaceParams {
    /// Spheres with the given exponent and offset, no gap, the default trial limit (10^7).
    pub fn spheres(c: f64, n_offset: f64) -> Self {
        SpaceParams {
            c,
            n_offset,
            solids: Solid::Sphere.into(),
            rotate: false,
            gap: 0.0,
            max_trials: 10_000_000,
        }
    }

    /// c for a fractal dimension D in 3D (c = 3 / D).
    pub fn c_from_dimension(d: f64) -> f64 {
        3.0 / d
    }
}

/// A placed solid: centre, scale (see [`Solid`]) and rotation as a unit quaternion
/// `[w, x, y, z]` (the identity when unrotated). `PlacedSolid::default()` is an empty slot.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PlacedSolid<S> {
    /// Centre x.
    pub x: S,
    /// Centre y.
    pub y: S,
    /// Centre z.
    pub z: S,
    /// Scale.
    pub scale: S,
    /// Rotation `[w, x, y, z]`.
    pub rotation: Quat<S>,
}

/// One placement ([`SpaceEngine::step`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpacePlacement<S> {
    /// Placement index i.
    pub index: u64,
    /// The solid as stored.
    pub solid: PlacedSolid<S>,
    /// Its kind.
    pub kind: Solid,
    /// V_i.
    pub volume: f64,
    /// Trials spent (>= 1).
    pub trials: u64,
}

/// Index words for `capacity` solids: one link each and two buckets.
pub const fn space_index_words(capacity: usize) -> usize {
    capacity * 3 + 1
}

/// The caller-owned storage of a [`SpaceEngine`].
#[derive(Debug)]
pub struct SpaceStorage<'a, S> {
    /// One slot per solid: its length is the capacity.
    pub solids: &'a mut [PlacedSolid<S>],
    /// The index, longer than `solids` ([`space_index_words`]).
    pub index: &'a mut [u32],
}

/// The 3D fill engine. See the crate's "3D" example.
#[derive(Debug)]
pub struct SpaceEngine<'a, S: Scalar> {
    pub(crate) params: SpaceParams,
    pub(crate) region: SpaceRegion,
    pub(crate) solids: &'a mut [PlacedSolid<S>],
    pub(crate) len: usize,
    pub(crate) hash: Hash3<'a, S>,
    seq: AreaSequence,
    placed_volume: f64,
    pub(crate) trials: u64,
    pub(crate) gap: S,
    pub(crate) period: [S; 3],
    /// The bead angles of the fill's first torus kind, computed once.
    pub(crate) trig: BeadTrig<S>,
}

/// What stays fixed over a placement's trials.
pub(crate) struct Next<S> {
    pub index: u64,
    pub kind: Solid,
    pub volume: f64,
    pub scale: S,
    pub rotated: bool,
    pub lo: [S; 3],
    pub hi: [S; 3],
    pub bound: S,
}

impl<'a, S: Scalar> SpaceEngine<'a, S> {
    /// Validates everything and builds an engine over the caller's storage.
    pub fn new(params: SpaceParams, region: SpaceRegion, storage: SpaceStorage<'a, S>) -> Result<Self, ParamError> {
        let SpaceStorage { solids, index } = storage;
        crate::params::check_power_law(params.c, params.n_offset)?;
        if !params.solids.is_valid() {
            return Err(ParamError::Shape);
        }
        region.check()?;
        let ext = region.extent();
        if ext.iter().any(|&e| e > S::MAX_EXTENT) {
            return Err(ParamError::Extent);
        }
        let min_side = ext.iter().fold(f64::MAX, |m, &e| m.min(e));
        if !(params.gap.is_finite() && params.gap >= 0.0 && 2.0 * params.gap < min_side) {
            return Err(ParamError::Gap);
        }
        if params.max_trials == 0 {
            return Err(ParamError::MaxTrials);
        }
        if solids.is_empty() || index.len() <= solids.len() || solids.len() >= NIL as usize {
            return Err(ParamError::Storage);
        }
        let seq = AreaSequence::new(region.volume(), params.c, params.n_offset).map_err(|_| ParamError::Zeta)?;
        let largest = ext.iter().fold(0.0f64, |m, &e| m.max(e));
        let (next, heads) = index.split_at_mut(solids.len());
        let hash = Hash3::new(heads, next, S::from_f64(largest)).map_err(|_| ParamError::Storage)?;
        Ok(SpaceEngine {
            gap: S::from_f64(params.gap),
            region,
            solids,
            len: 0,
            hash,
            seq,
            placed_volume: 0.0,
            trials: 0,
            period: [S::from_f64(ext[0]), S::from_f64(ext[1]), S::from_f64(ext[2])],
            trig: BeadTrig::new(
                params
                    .solids
                    .kinds()
                    .iter()
                    .find(|k| matches!(k, Solid::Torus { .. }))
                    .unwrap_or(&Solid::Sphere),
            ),
            params,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &SpaceParams {
        &self.params
    }

    /// The region.
    pub fn region(&self) -> &SpaceRegion {
        &self.region
    }

    /// The volume sequence.
    pub fn sequence(&self) -> &AreaSequence {
        &self.seq
    }

    /// `V_i`.
    pub fn volume_of(&self, i: u64) -> f64 {
        self.seq.area(i)
    }

    /// The kind of placement `i`.
    pub fn kind_of(&self, i: u64) -> Solid {
        self.params.solids.kind_of(i)
    }

    /// The solids placed so far, in placement order.
    pub fn placed(&self) -> &[PlacedSolid<S>] {
        self.solids.get(..self.len).unwrap_or(&[])
    }

    /// The storage capacity in solids.
    pub fn capacity(&self) -> usize {
        self.solids.len()
    }

    /// Statistics (`fill_fraction` is placed volume over the region's).
    pub fn stats(&self) -> Stats {
        Stats {
            placed: self.len as u64,
            trials: self.trials,
            fill_fraction: self.placed_volume / self.seq.total(),
        }
    }

    /// The geometry of placed solid `i` as tested (vertices, bead centres).
    pub fn body(&self, i: usize) -> Option<Body<S>> {
        let p = self.placed().get(i)?;
        Some(self.body_of(&self.kind_of(i as u64), V3::new(p.x, p.y, p.z), p.scale, &p.rotation))
    }

    /// [`Body::new`] with the engine's bead angles.
    pub(crate) fn body_of(&self, kind: &Solid, c: V3<S>, s: S, q: &Quat<S>) -> Body<S> {
        Body::with_trig(kind, c, s, q, Some(&self.trig))
    }

    pub(crate) fn next(&self) -> Result<Next<S>, StepError> {
        let i = self.len;
        let index = i as u64;
        if i >= self.solids.len() {
            return Err(StepError::Capacity {
                capacity: self.solids.len() as u64,
            });
        }
        let kind = self.kind_of(index);
        let volume = self.volume_of(index);
        let scale = kind.scale_for_volume(volume);
        if S::MIN_SIZE > 0.0 && kind.min_width(scale).partial_cmp(&S::MIN_SIZE).is_none_or(|o| o.is_lt()) {
            return Err(StepError::TooSmall { index });
        }
        let s = S::from_f64(scale);
        if !(scale.is_finite() && s > S::ZERO) {
            return Err(StepError::CannotFit { index });
        }
        let m = S::from_f64(kind.support(scale)) + self.gap;
        let periodic = self.region.periodic();
        let (mut lo, mut hi) = ([S::ZERO; 3], self.period);
        if !periodic {
            for (l, h) in lo.iter_mut().zip(hi.iter_mut()) {
                *l = m;
                *h = *h - m;
                if *h < *l {
                    return Err(StepError::CannotFit { index });
                }
            }
        }
        Ok(Next {
            index,
            kind,
            volume,
            scale: s,
            rotated: self.params.rotate && kind.rotates(),
            lo,
            hi,
            bound: bounding(&kind, s),
        })
    }

    /// Draws one candidate's rotation (first, when rotated) then centre: the fixed mapping.
    pub(crate) fn draw<R: RngCore + ?Sized>(next: &Next<S>, rng: &mut R) -> (Quat<S>, V3<S>) {
        let q = if next.rotated { random_rotation(rng) } else { identity() };
        let [x, y, z]: [S; 3] = core::array::from_fn(|a| {
            let (l, h) = (
                next.lo.get(a).copied().unwrap_or(S::ZERO),
                next.hi.get(a).copied().unwrap_or(S::ZERO),
            );
            rng::uniform(rng, l, h)
        });
        (q, V3::new(x, y, z))
    }

    /// Whether the body fits: inside the region and apart from every placed solid and every
    /// periodic image (its own too).
    pub(crate) fn fits(&self, body: &Body<S>, bound: S) -> bool {
        self.fits_hit(body, bound, false).is_ok()
    }

    /// [`Self::fits`], naming on failure a placed solid the body hits (`None` when it leaves
    /// the region, or meets only its own periodic image). With `least`, every solid is tested
    /// and the hit named is the one placed first, so that it does not depend on the spatial
    /// index's layout (the cell sampler learns it); otherwise the first found.
    pub(crate) fn fits_hit(&self, body: &Body<S>, bound: S, least: bool) -> Result<(), Option<u32>> {
        if !self.region.holds(body, self.gap) {
            return Err(None);
        }
        let gap = self.gap;
        let total = self.len as u32;
        let c = body.centre();
        let mut hit: Option<u32> = None;
        let mut test = |b: &Body<S>| {
            let bc = b.centre();
            self.hash.query([bc.x, bc.y, bc.z], bound + gap, total, |j| {
                if hit.is_some_and(|h| j >= h) {
                    return true;
                }
                let Some(p) = self.solids.get(j as usize) else { return true };
                let kind = self.kind_of(u64::from(j));
                let contact = bound + bounding(&kind, p.scale) + gap;
                let d = V3::new(p.x, p.y, p.z).sub(bc);
                let ok = d.norm2() > contact * contact || apart(b, &self.body_of(&kind, V3::new(p.x, p.y, p.z), p.scale, &p.rotation), gap);
                if !ok {
                    hit = Some(j);
                }
                ok || least
            })
        };
        if !self.region.periodic() {
            test(body);
            return hit.map_or(Ok(()), |j| Err(Some(j)));
        }
        let reach = bound + gap + self.hash.max_r().max(bound);
        let self_reach = bound + bound + gap;
        let [px, py, pz] = self.period;
        let ks = |p: S, r: S| (r / p).floor_i64().saturating_add(1).clamp(1, 3);
        let (kx, ky, kz) = (ks(px, reach), ks(py, reach), ks(pz, reach));
        let mut own_image = false;
        for i in -kx..=kx {
            for j in -ky..=ky {
                for k in -kz..=kz {
                    let f = |n: i64| S::from_f64(n as f64);
                    let d = V3::new(f(i) * px, f(j) * py, f(k) * pz);
                    let q = c.add(d);
                    let near = |v: S, p: S| v >= -reach && v <= p + reach;
                    if !(near(q.x, px) && near(q.y, py) && near(q.z, pz)) {
                        continue;
                    }
                    let image = body.shifted(d);
                    if !test(&image) && !least {
                        return Err(hit);
                    }
                    let own = d.norm2() < self_reach * self_reach;
                    if (i, j, k) != (0, 0, 0) && own && !apart(body, &image, gap) {
                        if !least {
                            return Err(None);
                        }
                        own_image = true;
                    }
                }
            }
        }
        match hit {
            Some(j) => Err(Some(j)),
            None if own_image => Err(None),
            None => Ok(()),
        }
    }

    /// Records the placement.
    pub(crate) fn place(&mut self, next: &Next<S>, body: &Body<S>, q: Quat<S>, trials: u64) -> SpacePlacement<S> {
        let c = body.centre();
        let solid = PlacedSolid {
            x: c.x,
            y: c.y,
            z: c.z,
            scale: next.scale,
            rotation: q,
        };
        let i = self.len;
        if let Some(slot) = self.solids.get_mut(i) {
            *slot = solid;
        }
        self.hash.insert(i as u32, [c.x, c.y, c.z], next.bound.max(bound_of(body)));
        self.len += 1;
        self.placed_volume += next.volume;
        SpacePlacement {
            index: next.index,
            solid,
            kind: next.kind,
            volume: next.volume,
            trials,
        }
    }

    /// Places the next solid with the paper's sampler: a rotation (when rotated), then a centre
    /// uniform over the box of centres whose solid keeps its support distance and the gap from
    /// the region's box, until a candidate fits or the trial limit is reached. On error nothing
    /// is placed and the engine may be stepped again.
    pub fn step<R: RngCore + ?Sized>(&mut self, rng: &mut R) -> Result<SpacePlacement<S>, StepError> {
        let next = self.next()?;
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials {
                return Err(StepError::Halted { index: next.index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let (q, c) = Self::draw(&next, rng);
            let body = self.body_of(&next.kind, c, next.scale, &q);
            if self.fits(&body, next.bound) {
                return Ok(self.place(&next, &body, q, trials));
            }
        }
    }

    /// Steps until a stop condition holds or a step fails (`Stop::min_size` is compared with
    /// the next solid's narrowest width, [`Solid::min_width`]).
    pub fn run<R: RngCore + ?Sized>(&mut self, rng: &mut R, stop: &Stop, on_place: impl FnMut(&SpacePlacement<S>)) -> StopReason {
        self.run_with(stop, on_place, |e| e.step(rng))
    }

    pub(crate) fn run_with(
        &mut self,
        stop: &Stop,
        on_place: impl FnMut(&SpacePlacement<S>),
        step: impl FnMut(&mut Self) -> Result<SpacePlacement<S>, StepError>,
    ) -> StopReason {
        let stops = |e: &Self| {
            let n = e.len as u64;
            stop.holds(n, e.placed_volume, e.seq.total(), || {
                let kind = e.kind_of(n);
                kind.min_width(kind.scale_for_volume(e.volume_of(n)))
            })
        };
        crate::params::run_until(self, stops, on_place, step)
    }
}
