//! The fractal tile as plain data: its parameters and the self-similar plane they make
//! ([`TileSpec`], [`Map`]), what its picture shows ([`Render`], [`Style`]), and how copies of
//! that picture are laid out on a sheet ([`layout`]). The plan holds these; `cmd::tile` grows
//! the tile and draws its pieces with them.
//!
//! Nothing here names a flag: a spec or an arrangement that cannot be drawn is reported as a
//! plain value ([`SpecError`], [`layout::LayoutError`]) that the plan words. Deterministic: the
//! same values give the same results.

pub mod layout;

pub use layout::{Arrangement, Layout, LayoutError, Sheet};

use crate::model::Pt;

/// Largest distance between a circle and the polygon or chords that stand for it (mm, in
/// the tile's frame).
pub const TOLERANCE: f64 = 0.002;

/// The most discs a tile may be sized for (each costs up to a dozen copies in the tries).
pub const MAX_DISCS: u64 = 4_000_000;

/// What the tile shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Render {
    /// The discs.
    Discs,
    /// Voronoi "cobblestones" of the disc centres.
    Voronoi,
}

/// How pieces are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// Outlines, for plotters (Voronoi: the cell edges).
    Outline,
    /// Filled shapes, for screens (Voronoi: the cells, inset by half the local spacing).
    Filled,
}

/// The parameters of a tile.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct TileSpec {
    /// Tile width (mm).
    pub width: f64,
    /// Tile height (mm).
    pub height: f64,
    /// Disc radius at the bottom edge (half of it at the top).
    pub radius: f64,
    /// Gap between discs at the bottom edge (half of it at the top).
    pub spacing: f64,
    /// Tries in all.
    pub tries: u64,
    /// RNG seed.
    pub seed: u64,
    /// Centres above `height * (1 - band)` get a twin whatever their disc does (0 for discs).
    pub band: f64,
}

/// Why a [`TileSpec`] cannot make a tile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpecError {
    /// The radius plus the spacing is more than `quarter`, a quarter of the tile's smaller
    /// side: a disc could reach two rows away.
    Reach {
        /// A quarter of the tile's smaller side (mm).
        quarter: f64,
    },
    /// The tile could hold about `most` discs, more than [`MAX_DISCS`] (or the estimate is
    /// not a number).
    TooManyDiscs {
        /// The estimate: the tile's area over the smallest disc's.
        most: f64,
    },
}

/// A similarity of the plane: `p -> (s x + dx, s y + dy)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Map {
    /// Scale.
    pub s: f64,
    /// Shift in x.
    pub dx: f64,
    /// Shift in y.
    pub dy: f64,
}

impl Map {
    /// The image of a point.
    pub fn at(&self, p: Pt) -> Pt {
        [self.s * p[0] + self.dx, self.s * p[1] + self.dy]
    }
}

impl TileSpec {
    /// `f(y) = 1 - y / 2H`: the factor on radius and spacing at height y of the plane.
    pub fn factor(&self, y: f64) -> f64 {
        1.0 - y / (2.0 * self.height)
    }

    /// The radius of a disc centred at height y.
    pub fn radius_at(&self, y: f64) -> f64 {
        self.radius * self.factor(y)
    }

    /// The gap two discs centred at heights `ya` and `yb` keep.
    pub fn gap_between(&self, ya: f64, yb: f64) -> f64 {
        self.spacing * self.factor(0.5 * (ya + yb))
    }

    /// Copies of the tile around it, the tile itself first: row 0 (shifted by -W, 0, W), row
    /// 1 (half scale: the two above and those beyond each side), row -1 (double scale).
    ///
    /// For the tries (`picture` false), row -1 is shifted by every multiple of W that brings
    /// it under the tile: the tile is the left half of one double-scale copy and the right
    /// half of the next, and must fit both. For the picture (`picture` true), only the copies
    /// of the plane around the tile at `[0, W]` (double-scale copies at `[-2W, 0]` and
    /// `[0, 2W]`): with the doppelgangers, both halves see the same there.
    pub fn maps(&self, picture: bool) -> Vec<Map> {
        let (w, h) = (self.width, self.height);
        let mut out = vec![
            Map { s: 1.0, dx: 0.0, dy: 0.0 },
            Map { s: 1.0, dx: -w, dy: 0.0 },
            Map { s: 1.0, dx: w, dy: 0.0 },
        ];
        let above = if picture { -2..=3 } else { -1..=2 };
        for a in above {
            out.push(Map {
                s: 0.5,
                dx: f64::from(a) * 0.5 * w,
                dy: h,
            });
        }
        let below: &[i32] = if picture { &[-2, 0] } else { &[-3, -2, -1, 0, 1] };
        for &j in below {
            out.push(Map {
                s: 2.0,
                dx: f64::from(j) * w,
                dy: -2.0 * h,
            });
        }
        out
    }

    /// Why the parameters cannot make a tile: a disc that could reach two rows away, or more
    /// discs than [`MAX_DISCS`].
    pub fn check(&self) -> Result<(), SpecError> {
        let quarter = 0.25 * self.width.min(self.height);
        if self.radius + self.spacing > quarter {
            return Err(SpecError::Reach { quarter });
        }
        // Discs are at least R/2 in radius, so at most W H / (pi R^2 / 4) fit.
        let most = (self.width / self.radius) * (self.height / self.radius) * 4.0 / core::f64::consts::PI;
        if most.is_nan() || most > MAX_DISCS as f64 {
            return Err(SpecError::TooManyDiscs { most });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec() -> TileSpec {
        TileSpec {
            width: 100.0,
            height: 80.0,
            radius: 5.0,
            spacing: 1.0,
            tries: 3000,
            seed: 3,
            band: 0.0,
        }
    }

    #[test]
    fn the_size_law_matches_the_copies_above_and_below() {
        let s = spec();
        for y in [0.0, 10.0, 40.0, 79.9] {
            // Half scale above: y -> H + y/2; double scale below: y -> 2y - 2H.
            assert!((s.factor(s.height + 0.5 * y) - 0.5 * s.factor(y)).abs() < 1e-15);
            assert!((s.factor(2.0 * y - 2.0 * s.height) - 2.0 * s.factor(y)).abs() < 1e-15);
        }
        assert_eq!(s.radius_at(0.0), 5.0);
        assert_eq!(s.radius_at(s.height), 2.5);
    }

    #[test]
    fn the_tries_see_both_configurations_below_and_the_picture_one() {
        let s = spec();
        let count = |maps: &[Map], scale: f64| maps.iter().filter(|m| m.s == scale).count();
        let tries = s.maps(false);
        let picture = s.maps(true);
        assert_eq!(tries[0], Map { s: 1.0, dx: 0.0, dy: 0.0 }, "the tile itself first");
        assert_eq!((count(&tries, 1.0), count(&tries, 0.5), count(&tries, 2.0)), (3, 4, 5));
        // Row -1 under the tile as a left half (even multiples of W) and a right half (odd).
        let shifts: Vec<f64> = tries.iter().filter(|m| m.s == 2.0).map(|m| m.dx / s.width).collect();
        assert!(shifts.contains(&0.0) && shifts.contains(&-1.0));
        let shifts: Vec<f64> = picture.iter().filter(|m| m.s == 2.0).map(|m| m.dx / s.width).collect();
        assert_eq!(shifts, [-2.0, 0.0]);
    }

    #[test]
    fn oversized_and_tiny_discs_are_refused() {
        let s = TileSpec { radius: 19.5, ..spec() };
        assert_eq!(s.check(), Err(SpecError::Reach { quarter: 20.0 }));
        assert!(TileSpec { radius: 19.0, ..spec() }.check().is_ok());
        // Discs so small that millions would fit.
        assert!(matches!(
            TileSpec { radius: 0.04, ..spec() }.check(),
            Err(SpecError::TooManyDiscs { .. })
        ));
        assert!(TileSpec { radius: 0.06, ..spec() }.check().is_ok());
    }
}
