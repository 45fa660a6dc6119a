//! The engine's side of the cell sampler: distance bounds to placed solids, the need of the
//! next solid, and the placement loop.

use super::*;

impl<S: Scalar> SpaceEngine<'_, S> {
    /// An upper bound of the signed distance from `p` to placed solid `j`'s material, in
    /// `f64` (the nearest periodic image for a periodic box); see [`SpaceCells`].
    pub(crate) fn dist_up(&self, j: u32, p: [f64; 3]) -> f64 {
        let Some(s) = self.placed().get(j as usize) else {
            return f64::INFINITY;
        };
        let kind = self.kind_of(u64::from(j));
        let d = self.offset(s, p);
        let r = libm::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        let scale = s.scale.to_f64();
        match kind {
            Solid::Sphere => r - scale,
            Solid::Shell { inner } => {
                let hole = scale * inner;
                if r >= scale {
                    r - scale
                } else if r <= hole {
                    hole - r
                } else {
                    -(r - hole).min(scale - r)
                }
            }
            Solid::Torus { ratio } => torus_dist(s, ratio, kind.beads(), d, r),
            _ => r - kind.support(scale),
        }
    }

    /// An upper bound of [`Self::dist_up`] over the cube of centre `m` and half side `half`
    /// (half diagonal `h`): for a sphere, and the inscribed ball of a polyhedron, the largest
    /// over the cube's corners (the distance to a ball is convex, so no point of the cube is
    /// farther than its farthest corner); for the others the centre's plus `h` (1-Lipschitz).
    pub(crate) fn dist_over(&self, j: u32, m: [f64; 3], half: f64, h: f64) -> f64 {
        let Some(s) = self.placed().get(j as usize) else {
            return f64::INFINITY;
        };
        let kind = self.kind_of(u64::from(j));
        let ball = match kind {
            Solid::Sphere | Solid::Cube | Solid::Tetrahedron | Solid::Octahedron => kind.support(s.scale.to_f64()),
            _ => return self.dist_up(j, m) + h,
        };
        let d = self.offset(s, m);
        let far = |v: f64| {
            let a = libm::fabs(v) + half;
            a * a
        };
        libm::sqrt(far(d[0]) + far(d[1]) + far(d[2])) - ball
    }

    /// `p` less the solid's centre (the nearest periodic image's, for a periodic box).
    fn offset(&self, s: &PlacedSolid<S>, p: [f64; 3]) -> [f64; 3] {
        let mut d = [p[0] - s.x.to_f64(), p[1] - s.y.to_f64(), p[2] - s.z.to_f64()];
        if self.region.periodic() {
            for (v, &period) in d.iter_mut().zip(self.region.extent().iter()) {
                *v -= period * libm::round(*v / period);
            }
        }
        d
    }

    /// Calls `f` with every placed solid that may come within `reach` of `p` (each periodic
    /// image of `p` that can reach into the box, for a periodic box).
    pub(crate) fn near(&self, p: [f64; 3], reach: f64, mut f: impl FnMut(u32)) {
        let total = self.len as u32;
        let r = S::from_f64(reach);
        let at = |q: [f64; 3], f: &mut dyn FnMut(u32)| {
            self.hash.query(q.map(S::from_f64), r, total, |j| {
                f(j);
                true
            });
        };
        if !self.region.periodic() {
            at(p, &mut f);
            return;
        }
        let ext = self.region.extent();
        let m = reach + self.hash.max_r().to_f64();
        let shifts = |a: usize| {
            let (v, w) = (p.get(a).copied().unwrap_or(0.0), ext.get(a).copied().unwrap_or(0.0));
            [(-w, v + m >= w), (0.0, true), (w, v - m < 0.0)]
        };
        for (dx, ox) in shifts(0) {
            for (dy, oy) in shifts(1) {
                for (dz, oz) in shifts(2) {
                    if ox && oy && oz {
                        at([p[0] + dx, p[1] + dy, p[2] + dz], &mut f);
                    }
                }
            }
        }
    }

    /// The clearance every valid centre of the next solid has, or `None` when it has no
    /// usable one (see [`SpaceCells`]).
    pub(super) fn need(&self, next: &Next<S>) -> Option<f64> {
        let scale = next.scale.to_f64();
        let r = match next.kind {
            Solid::Torus { .. } => return None,
            Solid::Shell { inner } => {
                let hole = scale * inner;
                let ball_fits = self.region.ball_radius().is_some_and(|b| b < hole);
                if 2.0 * inner * inner * inner > 1.0 || ball_fits {
                    return None;
                }
                scale
            }
            k => k.support(scale),
        };
        Some(r + self.params.gap)
    }

    /// Places the next solid with the cell sampler: the same distribution of placements as
    /// [`SpaceEngine::step`], drawn only where it could fit (see [`SpaceCells`]). A halt
    /// with fewer trials than the limit is proven: no valid centre is left. On error nothing is
    /// placed and the engine may be stepped again.
    pub fn step_fast<R: RngCore + ?Sized>(&mut self, cells: &mut SpaceCells<'_>, rng: &mut R) -> Result<SpacePlacement<S>, StepError> {
        let next = self.next()?;
        let Some(need) = self.need(&next) else {
            return self.step(rng);
        };
        let need = cells.prepare(self, need);
        let mut trials = 0u64;
        loop {
            if trials >= self.params.max_trials || cells.weight == 0 {
                return Err(StepError::Halted { index: next.index, trials });
            }
            trials += 1;
            self.trials = self.trials.saturating_add(1);
            let Some((slot, units)) = cells.draw(rng) else { continue };
            let cell = cells.get(slot);
            let side = cells.side(cell.level);
            let point: [f64; 3] =
                core::array::from_fn(|a| (f64::from(cell.at.get(a).copied().unwrap_or(0)) + units.get(a).copied().unwrap_or(0.0)) * side);
            let slot = match cells.restructure(self, slot, units, need) {
                Drawn::Reject => continue,
                Drawn::Test(s) => s,
            };
            let c = V3::<S>::from_f64(point[0], point[1], point[2]);
            let inside = |v: S, a: usize| next.lo.get(a).is_some_and(|&l| v >= l) && next.hi.get(a).is_some_and(|&h| v <= h);
            if !(inside(c.x, 0) && inside(c.y, 1) && inside(c.z, 2)) {
                cells.note_reject(slot);
                continue;
            }
            // A point nearer than the need to a solid the cell knows cannot be valid (the
            // distance used is an upper bound): rejected without the index.
            let known = cells.get(slot).known;
            if known.iter().any(|&j| j != NIL && self.dist_up(j, point) + cells.slack < need) {
                cells.note_reject(slot);
                continue;
            }
            let q = if next.rotated {
                crate::space3d::vec3::random_rotation(rng)
            } else {
                crate::space3d::vec3::identity()
            };
            let body = self.body_of(&next.kind, c, next.scale, &q);
            match self.fits_hit(&body, next.bound, true) {
                Ok(()) => {
                    let placed = self.place(&next, &body, q, trials);
                    cells.learn(self, slot, next.index as u32);
                    if cells.get(slot).u < need {
                        cells.retire(slot);
                    }
                    return Ok(placed);
                }
                Err(Some(j)) => {
                    cells.learn(self, slot, j);
                    cells.note_reject(slot);
                    if cells.get(slot).u < need {
                        cells.retire(slot);
                    }
                }
                Err(None) => cells.note_reject(slot),
            }
        }
    }

    /// [`SpaceEngine::run`] with the cell sampler ([`SpaceEngine::step_fast`]).
    pub fn run_fast<R: RngCore + ?Sized>(
        &mut self,
        cells: &mut SpaceCells<'_>,
        rng: &mut R,
        stop: &Stop,
        on_place: impl FnMut(&SpacePlacement<S>),
    ) -> StopReason {
        self.run_with(stop, on_place, |e| e.step_fast(cells, rng))
    }
}

/// The distance from `d` (the point less the torus's centre, `r = |d|`) to the smooth torus
/// held by the beads of a torus of major radius `s.scale`.
fn torus_dist<S: Scalar>(s: &PlacedSolid<S>, ratio: f64, beads: usize, d: [f64; 3], r: f64) -> f64 {
    let big = s.scale.to_f64();
    let q = s.rotation.map(|v| v.to_f64());
    let axis = columns::<f64>(&q)[2];
    let n2 = axis.norm2();
    let z = if n2 > 0.0 {
        (axis.x * d[0] + axis.y * d[1] + axis.z * d[2]) / libm::sqrt(n2)
    } else {
        0.0
    };
    let rho = libm::sqrt((r * r - z * z).max(0.0));
    let n = beads.max(1) as f64;
    let tube = ratio * big - 2.0 * big * libm::sin(core::f64::consts::PI / (2.0 * n));
    let dr = rho - big;
    libm::sqrt(dr * dr + z * z) - tube
}
