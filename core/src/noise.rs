//! Value noise and Perlin gradient noise, summed over octaves: smooth random fields over the
//! plane (and a line) in `[0, 1]`, to modulate where shapes go and how outlines wander.
//!
//! Both are built on a square lattice of spacing `scale` (the first octave's feature size):
//! - **value noise** takes a random value in `[0, 1)` at every lattice point and blends the
//!   four around a point;
//! - **gradient noise** (Perlin's) takes a random unit gradient at every lattice point, the
//!   value of each corner's plane at the point (the dot product of the offset from the corner
//!   with its gradient, zero at the corner itself), and blends those. In two dimensions the
//!   sum lies in `[-sqrt(2) / 2, sqrt(2) / 2]` and is mapped onto `[0, 1]`.
//!
//! Both blend with the quintic fade `6 t^5 - 15 t^4 + 10 t^3` (as in the "Procedural
//! Generation" course notes; its first and second derivatives vanish at the lattice, so the
//! field shows no grid). Octave `k` has half the spacing of octave `k - 1` and `gain` times
//! its weight; the sum is divided by the weights' sum, so it stays in `[0, 1]`.
//!
//! **Determinism.** A lattice point's value or gradient comes from a 64-bit mix of the seed,
//! the octave and its integer coordinates (no generator state), and a gradient is one of 16
//! directions given as constants: the field is made of additions and multiplications of `f64`
//! only, bit for bit the same on every target.
//!
//! **Periodic fields.** With a period `(w, h)`, every octave's lattice wraps: its spacing is
//! made the nearest to the asked one that fits a whole number of cells in `w` (and in `h`),
//! and lattice coordinates are taken modulo that count, so the field is continuous across the
//! seams of a periodic fill and a tileable texture stays tileable.

/// Which noise.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum NoiseKind {
    /// Random values at the lattice points, blended.
    Value,
    /// Perlin's gradient noise: random gradients at the lattice points.
    Gradient,
}

/// The most octaves a [`Noise`] sums.
pub const MAX_OCTAVES: u32 = 16;

/// Why a [`Noise`] cannot be made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum NoiseError {
    /// `scale` is not a positive finite length.
    Scale,
    /// `octaves` is not in `1..=MAX_OCTAVES`.
    Octaves,
    /// `gain` is not in `(0, 1]`.
    Gain,
    /// A period is not a positive finite length, or holds more than 2^40 cells of the finest
    /// octave.
    Period,
}

impl core::fmt::Display for NoiseError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            NoiseError::Scale => "the noise scale must be a positive length",
            NoiseError::Octaves => "the noise needs 1 to 16 octaves",
            NoiseError::Gain => "the noise gain must be above 0 and at most 1",
            NoiseError::Period => "the noise period must be a positive length of at most 2^40 finest cells",
        })
    }
}

/// A noise field: kind, seed, first-octave spacing, octaves, gain, and an optional period.
///
/// # Examples
///
/// ```
/// use zetafill::{Noise, NoiseKind};
///
/// let n = Noise::new(NoiseKind::Gradient, 7, 20.0, 4, 0.5, None).unwrap();
/// let v = n.at(12.5, 40.25);
/// assert!((0.0..=1.0).contains(&v));
/// assert_eq!(v.to_bits(), n.at(12.5, 40.25).to_bits());
/// // Gradient noise is 0.5 at the lattice points of every octave.
/// assert_eq!(Noise::new(NoiseKind::Gradient, 7, 20.0, 4, 0.5, None).unwrap().at(40.0, 60.0), 0.5);
/// // A periodic field meets itself across the seams.
/// let p = Noise::new(NoiseKind::Value, 3, 30.0, 3, 0.6, Some((100.0, 80.0))).unwrap();
/// assert!((p.at(0.0, 10.0) - p.at(100.0, 10.0)).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Noise {
    kind: NoiseKind,
    seed: u64,
    octaves: u32,
    gain: f64,
    /// Lattice cells per unit length, x and y, of the first octave.
    freq: (f64, f64),
    /// Lattice cells across the period, x and y, of the first octave (0: not periodic).
    cells: (u64, u64),
}

/// The 16 gradient directions, `(cos, sin)` of `k pi / 8`.
const R: f64 = core::f64::consts::FRAC_1_SQRT_2;
const DIRS: [(f64, f64); 16] = [
    (1.0, 0.0),
    (0.923_879_532_511_286_7, 0.382_683_432_365_089_8),
    (R, R),
    (0.382_683_432_365_089_8, 0.923_879_532_511_286_7),
    (0.0, 1.0),
    (-0.382_683_432_365_089_8, 0.923_879_532_511_286_7),
    (-R, R),
    (-0.923_879_532_511_286_7, 0.382_683_432_365_089_8),
    (-1.0, 0.0),
    (-0.923_879_532_511_286_7, -0.382_683_432_365_089_8),
    (-R, -R),
    (-0.382_683_432_365_089_8, -0.923_879_532_511_286_7),
    (0.0, -1.0),
    (0.382_683_432_365_089_8, -0.923_879_532_511_286_7),
    (R, -R),
    (0.923_879_532_511_286_7, -0.382_683_432_365_089_8),
];

/// The largest finest-octave cell count a period may hold (lattice coordinates stay exact).
const MAX_CELLS: f64 = (1u64 << 40) as f64;

/// A 64-bit mix (the finaliser of SplitMix64).
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The quintic fade.
fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// The lattice coordinate `i` wrapped into `0..n` (`n = 0`: unwrapped).
fn wrap(i: i64, n: u64) -> u64 {
    if n == 0 {
        i as u64
    } else if i >= 0 {
        i as u64 % n
    } else {
        // `!i = -1 - i` is not negative: no overflow for any `i` and `n`.
        n - 1 - (!i as u64) % n
    }
}

impl Noise {
    /// A field of `kind` with `seed`, first-octave lattice spacing `scale` (mm), `octaves`
    /// octaves each `gain` times the weight of the last, periodic over `period` when given.
    pub fn new(kind: NoiseKind, seed: u64, scale: f64, octaves: u32, gain: f64, period: Option<(f64, f64)>) -> Result<Self, NoiseError> {
        if !(scale.is_finite() && scale > 0.0) {
            return Err(NoiseError::Scale);
        }
        if !(1..=MAX_OCTAVES).contains(&octaves) {
            return Err(NoiseError::Octaves);
        }
        if !(gain > 0.0 && gain <= 1.0) {
            return Err(NoiseError::Gain);
        }
        let finest = (1u64 << (octaves - 1)) as f64;
        let (freq, cells) = match period {
            None => ((1.0 / scale, 1.0 / scale), (0, 0)),
            Some((w, h)) => {
                let fit = |len: f64| -> Result<(f64, u64), NoiseError> {
                    if !(len.is_finite() && len > 0.0) {
                        return Err(NoiseError::Period);
                    }
                    let n = libm::round(len / scale).max(1.0);
                    if n * finest > MAX_CELLS {
                        return Err(NoiseError::Period);
                    }
                    Ok((n / len, n as u64))
                };
                let ((fx, nx), (fy, ny)) = (fit(w)?, fit(h)?);
                ((fx, fy), (nx, ny))
            }
        };
        Ok(Noise {
            kind,
            seed,
            octaves,
            gain,
            freq,
            cells,
        })
    }

    /// The kind.
    pub fn kind(&self) -> NoiseKind {
        self.kind
    }

    /// The field at `(x, y)` (mm), in `[0, 1]`; 0.5 for a point too far out to place on the
    /// lattice (beyond 2^52 cells).
    pub fn at(&self, x: f64, y: f64) -> f64 {
        let mut sum = 0.0;
        let mut total = 0.0;
        let mut w = 1.0;
        for k in 0..self.octaves {
            let m = (1u64 << k) as f64;
            let cells = (self.cells.0 << k, self.cells.1 << k);
            sum += w * self.octave(k, x * self.freq.0 * m, y * self.freq.1 * m, cells);
            total += w;
            w *= self.gain;
        }
        (sum / total).clamp(0.0, 1.0)
    }

    /// One octave at lattice coordinates `(u, v)`, in `[0, 1]`.
    fn octave(&self, k: u32, u: f64, v: f64, cells: (u64, u64)) -> f64 {
        const LIMIT: f64 = 4_503_599_627_370_496.0; // 2^52
        if !(u.abs() < LIMIT && v.abs() < LIMIT) {
            return 0.5;
        }
        let (fu, fv) = (libm::floor(u), libm::floor(v));
        let (tx, ty) = (u - fu, v - fv);
        let (i, j) = (fu as i64, fv as i64);
        let salt = mix(self.seed ^ mix(u64::from(k) + 1));
        let corner = |di: i64, dj: i64| {
            let (a, b) = (wrap(i + di, cells.0), wrap(j + dj, cells.1));
            mix(salt ^ mix(a ^ mix(b)))
        };
        let (sx, sy) = (fade(tx), fade(ty));
        let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
        match self.kind {
            NoiseKind::Value => {
                let val = |h: u64| (h >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
                let top = lerp(val(corner(0, 0)), val(corner(1, 0)), sx);
                let bottom = lerp(val(corner(0, 1)), val(corner(1, 1)), sx);
                lerp(top, bottom, sy)
            }
            NoiseKind::Gradient => {
                let dot = |h: u64, dx: f64, dy: f64| {
                    let (gx, gy) = DIRS.get((h >> 60) as usize).copied().unwrap_or((1.0, 0.0));
                    gx * dx + gy * dy
                };
                let top = lerp(dot(corner(0, 0), tx, ty), dot(corner(1, 0), tx - 1.0, ty), sx);
                let bottom = lerp(dot(corner(0, 1), tx, ty - 1.0), dot(corner(1, 1), tx - 1.0, ty - 1.0), sx);
                lerp(top, bottom, sy) * core::f64::consts::FRAC_1_SQRT_2 + 0.5
            }
        }
    }

    /// The field along a line: at `t` (mm) of the row `y = 0`. With a period `(w, h)`, it
    /// repeats every `w`: a closed outline of perimeter `w` takes it as a function of arc length.
    pub fn at_1d(&self, t: f64) -> f64 {
        self.at(t, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PINNED: u64 = 17_005_825_372_383_369_978;

    #[test]
    fn wrap_is_the_euclidean_remainder_without_overflow() {
        for n in [1u64, 2, 3, 7, 64, 1 << 40] {
            for i in [-130i64, -65, -64, -7, -3, -1, 0, 1, 6, 7, 129, i64::MAX - 1, i64::MIN + 1] {
                assert_eq!(wrap(i, n), i.rem_euclid(n as i64) as u64, "i {i} n {n}");
            }
        }
        // Where `rem_euclid` itself would overflow or misread `n`.
        assert_eq!(wrap(i64::MIN, u64::MAX), (i64::MIN as i128).rem_euclid(u64::MAX as i128) as u64);
        assert_eq!(wrap(-1, u64::MAX), u64::MAX - 1);
        assert_eq!(wrap(-5, 0), (-5i64) as u64);
    }

    fn field(kind: NoiseKind, period: Option<(f64, f64)>) -> Noise {
        Noise::new(kind, 42, 10.0, 5, 0.5, period).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn bad_parameters_are_refused() {
        let g = NoiseKind::Gradient;
        assert_eq!(Noise::new(g, 1, 0.0, 1, 0.5, None), Err(NoiseError::Scale));
        assert_eq!(Noise::new(g, 1, f64::NAN, 1, 0.5, None), Err(NoiseError::Scale));
        assert_eq!(Noise::new(g, 1, 1.0, 0, 0.5, None), Err(NoiseError::Octaves));
        assert_eq!(Noise::new(g, 1, 1.0, 17, 0.5, None), Err(NoiseError::Octaves));
        assert_eq!(Noise::new(g, 1, 1.0, 2, 0.0, None), Err(NoiseError::Gain));
        assert_eq!(Noise::new(g, 1, 1.0, 2, 1.5, None), Err(NoiseError::Gain));
        assert_eq!(Noise::new(g, 1, 1.0, 2, 0.5, Some((0.0, 1.0))), Err(NoiseError::Period));
        assert_eq!(Noise::new(g, 1, 1e-9, 16, 0.5, Some((1e3, 1.0))), Err(NoiseError::Period));
    }

    #[test]
    fn values_stay_in_range_on_any_input() {
        for kind in [NoiseKind::Value, NoiseKind::Gradient] {
            let n = field(kind, None);
            let mut r = crate::rng_from_seed(9);
            for _ in 0..50_000 {
                let (x, y) = (
                    crate::rng::uniform::<f64, _>(&mut r, -1e4, 1e4),
                    crate::rng::uniform::<f64, _>(&mut r, -1e4, 1e4),
                );
                let v = n.at(x, y);
                assert!((0.0..=1.0).contains(&v), "{kind:?} at ({x}, {y}): {v}");
            }
            for (x, y) in [(f64::NAN, 0.0), (f64::INFINITY, 1.0), (1e300, -1e300), (-0.0, 0.0)] {
                assert!((0.0..=1.0).contains(&n.at(x, y)));
            }
        }
    }

    #[test]
    fn gradient_noise_is_half_at_the_lattice_and_value_noise_is_its_values() {
        let n = Noise::new(NoiseKind::Gradient, 5, 8.0, 1, 0.5, None).unwrap_or_else(|e| panic!("{e}"));
        for (i, j) in [(0, 0), (3, -2), (-7, 11)] {
            assert_eq!(n.at(8.0 * f64::from(i), 8.0 * f64::from(j)), 0.5);
        }
        // Value noise varies at the lattice, and between lattice points is within the corners.
        let v = Noise::new(NoiseKind::Value, 5, 8.0, 1, 0.5, None).unwrap_or_else(|e| panic!("{e}"));
        let corners = [v.at(0.0, 0.0), v.at(8.0, 0.0), v.at(0.0, 8.0), v.at(8.0, 8.0)];
        assert!(corners.iter().any(|&c| (c - corners[0]).abs() > 1e-3));
        let (lo, hi) = corners.iter().fold((1.0f64, 0.0f64), |(l, h), &c| (l.min(c), h.max(c)));
        for k in 0..=16 {
            let x = 0.5 * f64::from(k);
            let m = v.at(x, 8.0 - x);
            assert!(m >= lo - 1e-15 && m <= hi + 1e-15);
        }
    }

    #[test]
    fn fields_are_continuous_and_vary() {
        for kind in [NoiseKind::Value, NoiseKind::Gradient] {
            let n = field(kind, None);
            let (mut lo, mut hi, mut jump) = (1.0f64, 0.0f64, 0.0f64);
            let h = 1e-4;
            for k in 0..20_000 {
                let x = 0.0137 * f64::from(k);
                let y = 7.0 + 0.0071 * f64::from(k);
                let v = n.at(x, y);
                lo = lo.min(v);
                hi = hi.max(v);
                jump = jump.max((n.at(x + h, y) - v).abs());
            }
            // A smooth field: a step of 1e-4 mm moves it by far less than its range.
            assert!(hi - lo > 0.3, "{kind:?}: range {lo}..{hi}");
            assert!(jump < 1e-3, "{kind:?}: jump {jump}");
        }
    }

    #[test]
    fn periodic_fields_meet_across_the_seams() {
        for kind in [NoiseKind::Value, NoiseKind::Gradient] {
            let (w, h) = (97.0, 61.5);
            let n = field(kind, Some((w, h)));
            let open = field(kind, None);
            let mut worst = 0.0f64;
            let mut open_worst = 0.0f64;
            for k in 0..500 {
                let t = 0.193 * f64::from(k);
                worst = worst.max((n.at(0.0, t) - n.at(w, t)).abs()).max((n.at(t, 0.0) - n.at(t, h)).abs());
                open_worst = open_worst.max((open.at(0.0, t) - open.at(w, t)).abs());
            }
            assert!(worst < 1e-12, "{kind:?}: {worst}");
            // The check can fail: the same field without the period does not meet itself.
            assert!(open_worst > 0.05, "{kind:?}: {open_worst}");
        }
    }

    #[test]
    fn seeds_and_kinds_give_other_fields_and_reruns_the_same_bits() {
        let a = field(NoiseKind::Gradient, None);
        let b = Noise::new(NoiseKind::Gradient, 43, 10.0, 5, 0.5, None).unwrap_or_else(|e| panic!("{e}"));
        let c = field(NoiseKind::Value, None);
        let pts = [(1.5, 2.25), (33.3, -7.7), (100.1, 0.3)];
        assert!(pts.iter().any(|&(x, y)| a.at(x, y) != b.at(x, y)));
        assert!(pts.iter().any(|&(x, y)| a.at(x, y) != c.at(x, y)));
        // Pinned bits: the field is a pure function of its parameters, so these never change.
        let bits: u64 = pts
            .iter()
            .fold(0, |h, &(x, y)| mix(h ^ a.at(x, y).to_bits() ^ c.at(x, y).to_bits()));
        assert_eq!(bits, PINNED);
    }

    #[test]
    fn octaves_add_detail() {
        // With more octaves the field moves more over a short step (finer features).
        let one = Noise::new(NoiseKind::Gradient, 3, 50.0, 1, 0.5, None).unwrap_or_else(|e| panic!("{e}"));
        let six = Noise::new(NoiseKind::Gradient, 3, 50.0, 6, 0.7, None).unwrap_or_else(|e| panic!("{e}"));
        let rough = |n: &Noise| {
            (0..2000)
                .map(|k| (n.at(0.5 * f64::from(k) + 0.5, 3.0) - n.at(0.5 * f64::from(k), 3.0)).abs())
                .sum::<f64>()
        };
        assert!(rough(&six) > 2.0 * rough(&one));
    }
}
