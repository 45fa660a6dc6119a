//! Densities: where a fill wants its centres, and the thinning of candidates by them.

/// The engine's density (a reference that shows in `Debug` by name only).
#[derive(Clone, Copy)]
pub(super) struct Thinning<'a>(pub(super) &'a dyn Density);

impl core::fmt::Debug for Thinning<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("Density")
    }
}

/// A density `rho` over the plane, in `[0, 1]`: the placement of every shape is drawn with
/// probability proportional to `rho` over the centres where it fits, instead of uniformly
/// (the paper's rule is `rho = 1`). A zero density is a mask: no centre is drawn there, while
/// the areas still follow the power law, so a fill fraction counts the masked area too and a
/// fill halts sooner where the open part fills up.
///
/// Both samplers thin their candidates: a candidate at `x` is kept with probability `rho(x)`
/// (a unit value `u` from the generator, kept when `u < rho(x)`), independently of everything
/// else, and then tested as before. The candidates the paper's sampler draws are uniform over
/// the box of centres, those of the cell sampler uniform over its live cells, which hold every
/// valid centre; a kept, valid candidate is therefore drawn with density proportional to
/// `rho(x)` over the valid centres in both, the same distribution.
///
/// # Examples
///
/// ```
/// use zetafill::{rng_from_seed, index_words, Density, Engine, Params, Placed, Region, Stop, Storage};
///
/// /// Only the right half.
/// struct Right;
/// impl Density for Right {
///     fn at(&self, x: f64, _y: f64) -> f64 {
///         if x > 50.0 { 1.0 } else { 0.0 }
///     }
/// }
/// let mut shapes = [Placed::<f64>::default(); 40];
/// let mut index = [0u32; index_words(40)];
/// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
/// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
/// let mut e = Engine::new(Params::circles(1.3, 8.0), region, storage).unwrap();
/// e.set_density(Some(&Right));
/// e.run(&mut rng_from_seed(1), &Stop { count: Some(40), ..Stop::default() }, |_| {});
/// assert!(e.placed().iter().all(|p| p.x > 50.0));
/// ```
pub trait Density: Sync {
    /// `rho` at `(x, y)`, in `[0, 1]` (a value above 1 counts as 1; below 0, or NaN, as 0).
    fn at(&self, x: f64, y: f64) -> f64;

    /// An upper bound of `rho` over the box `[x0, x1] x [y0, y1]` (by default 1, no bound).
    ///
    /// The cell sampler draws its cells by area times this bound (rounded up to a power of
    /// two) and thins by `rho` over it, so that low-density cells cost few trials; where it
    /// is 0 no candidate is drawn at all. It must never be below `at` anywhere in the box, or
    /// the cell sampler no longer draws from the density; a loose bound only costs trials.
    fn max_over(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let _ = (x0, y0, x1, y1);
        1.0
    }
}

impl Density for crate::Noise {
    fn at(&self, x: f64, y: f64) -> f64 {
        crate::Noise::at(self, x, y)
    }
}

/// Whether a candidate at `(x, y)` drawn where the density is at most `2^-class` is kept, for
/// the unit value `u`: with probability `rho 2^class` (exact: a power of two scales without
/// rounding). One copy for every scalar.
#[inline(never)]
pub(super) fn kept_at(d: &dyn Density, x: f64, y: f64, class: u32, u: f64) -> bool {
    u < d.at(x, y) * f64::from(1u32 << class.min(31))
}
