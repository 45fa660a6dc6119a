//! One cell of the sampler and its storage in four 64-bit words ([`CellWords`]): all-zero
//! words are an empty cell, so a pool can be zeroed memory.

use super::{CellWords, NEAR, NONE, X_BITS};
use crate::scalar::Scalar;

/// One cell: its level and grid position, the shapes it knows of, and the bound on the
/// clearance anywhere in it (stored as [`CellWords`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cell<S> {
    /// The x index in the low [`X_BITS`] bits, the level above.
    pub(super) xl: u32,
    /// The y index in the low [`X_BITS`] bits, the candidates rejected above.
    pub(super) yr: u32,
    pub(super) near: [u32; NEAR],
    /// The bound on the clearance anywhere in the cell, from the outside of the region and
    /// the known shapes.
    pub(super) u: S,
}

impl<S: Scalar> Default for Cell<S> {
    fn default() -> Self {
        Cell {
            xl: 0,
            yr: 0,
            near: [NONE; NEAR],
            u: S::ZERO,
        }
    }
}

impl<S: Scalar> Cell<S> {
    /// The cell stored in `w` (shape indices are kept plus one, so that zero is none).
    #[inline]
    pub(super) fn load(w: &CellWords) -> Self {
        let [a, b, c, d] = *w;
        let dec = |x: u64| (x as u32).wrapping_sub(1);
        Cell {
            xl: a as u32,
            yr: (a >> 32) as u32,
            near: [dec(b), dec(b >> 32), dec(c), dec(c >> 32)],
            u: S::from_word(d),
        }
    }

    /// The words that store the cell.
    #[inline]
    pub(super) fn store(&self) -> CellWords {
        let enc = |j: u32| u64::from(j.wrapping_add(1));
        let [n0, n1, n2, n3] = self.near;
        [
            u64::from(self.xl) | (u64::from(self.yr) << 32),
            enc(n0) | (enc(n1) << 32),
            enc(n2) | (enc(n3) << 32),
            self.u.to_word(),
        ]
    }
}

impl<S> Cell<S> {
    #[inline]
    pub(super) fn level(&self) -> u32 {
        self.xl >> X_BITS
    }

    #[inline]
    pub(super) fn ix(&self) -> u32 {
        self.xl & ((1 << X_BITS) - 1)
    }

    #[inline]
    pub(super) fn iy(&self) -> u32 {
        self.yr & ((1 << X_BITS) - 1)
    }

    #[inline]
    pub(super) fn rejects(&self) -> u32 {
        self.yr >> X_BITS
    }

    /// The shapes the cell knows of.
    pub(crate) fn near(&self) -> [u32; NEAR] {
        self.near
    }

    /// Whether two cells are the same cell (level and position), whatever their bounds.
    #[inline]
    pub(super) fn same(&self, o: &Self) -> bool {
        self.xl == o.xl && self.iy() == o.iy()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Fixed;

    fn round_trip<S: Scalar>(u: S) {
        for (xl, yr, near) in [
            (0, 0, [NONE; NEAR]),
            ((5 << X_BITS) | 12345, (3 << X_BITS) | CHECK_Y, [0, 1, NONE, u32::MAX - 1]),
            (u32::MAX, u32::MAX, [7, NONE, 0, 99]),
        ] {
            let c = Cell { xl, yr, near, u };
            assert_eq!(Cell::<S>::load(&c.store()), c);
        }
    }

    const CHECK_Y: u32 = (1 << X_BITS) - 1;

    #[test]
    fn cells_read_back_what_was_stored() {
        for u in [0.0, -0.0, 1.5e-300, -3.25, f64::MAX] {
            round_trip(u);
        }
        for u in [0.0, -7.5, 1e-9, 2e9] {
            round_trip(Fixed::from_f64(u));
        }
    }

    #[test]
    fn zero_words_are_an_empty_cell() {
        let c = Cell::<f64>::load(&[0; 4]);
        assert_eq!(c, Cell::default());
        assert_eq!(c.near, [NONE; NEAR]);
        assert_eq!(Cell::<Fixed>::load(&[0; 4]), Cell::default());
    }
}
