//! The shape, or mix of shapes, of a fill: which kind each placement index gets.

use super::{ShapeKind, MAX_MIX};

/// How a mix of shapes is taken.
///
/// # Examples
///
/// ```
/// use zetafill::{MixOrder, ShapeKind, ShapeList};
///
/// let kinds = [ShapeKind::Circle, ShapeKind::Square, ShapeKind::Triangle];
/// let cycle = ShapeList::mix(&kinds, MixOrder::Cycle, 0).expect("three kinds");
/// assert_eq!(cycle.kind_of(4), ShapeKind::Square);
/// // A random choice is fixed by the salt and the index, and takes every kind.
/// let random = ShapeList::mix(&kinds, MixOrder::Random, 42).expect("three kinds");
/// let again = random.clone();
/// assert!((0..100).all(|i| random.kind_of(i) == again.kind_of(i)));
/// assert!(kinds.iter().all(|k| (0..100).any(|i| random.kind_of(i) == *k)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum MixOrder {
    /// In turn: placement i gets kind i mod len (the paper's Figure 7).
    Cycle,
    /// A fixed pseudo-random choice per placement index (from `salt`), so nothing is stored.
    Random,
}

/// The shape, or mix of shapes, of a fill. The area sequence is the same whatever the mix.
///
/// It holds 1..=[`MAX_MIX`] kinds in a fixed-capacity vector, so it is `Clone` but not `Copy`:
/// the engine keeps one and lends it. A single kind converts into a list.
///
/// # Examples
///
/// ```
/// use zetafill::{MixOrder, ShapeKind, ShapeList};
///
/// let one: ShapeList = ShapeKind::Triangle.into();
/// assert_eq!(one.kinds(), &[ShapeKind::Triangle]);
/// assert_eq!(one.kind_of(1234), ShapeKind::Triangle);
///
/// // The paper's Figure 7: circles and squares in turn.
/// let mix = ShapeList::mix(&[ShapeKind::Circle, ShapeKind::Square], MixOrder::Cycle, 0).expect("two kinds");
/// assert_eq!([mix.kind_of(0), mix.kind_of(1), mix.kind_of(2)], [ShapeKind::Circle, ShapeKind::Square, ShapeKind::Circle]);
/// assert!(mix.is_valid());
/// // An empty list is no mix; neither is one with a bad proportion.
/// assert!(ShapeList::mix(&[], MixOrder::Cycle, 0).is_none());
/// assert!(!ShapeList::from(ShapeKind::Ring { inner: 1.0 }).is_valid());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeList {
    kinds: heapless::Vec<ShapeKind, MAX_MIX>,
    /// How kinds are chosen per placement.
    pub order: MixOrder,
    /// Salt for [`MixOrder::Random`].
    pub salt: u64,
}

#[cfg(feature = "defmt")]
impl defmt::Format for ShapeList {
    fn format(&self, f: defmt::Formatter<'_>) {
        defmt::write!(
            f,
            "ShapeList {{ kinds: {=[?]}, order: {}, salt: {=u64} }}",
            self.kinds(),
            self.order,
            self.salt
        );
    }
}

impl From<ShapeKind> for ShapeList {
    fn from(k: ShapeKind) -> Self {
        let mut kinds = heapless::Vec::new();
        // Cannot fail: MAX_MIX >= 1 (checked at compile time).
        let _ = kinds.push(k);
        ShapeList {
            kinds,
            order: MixOrder::Cycle,
            salt: 0,
        }
    }
}
const _: () = assert!(MAX_MIX >= 1, "a list holds at least one kind");

impl ShapeList {
    /// A mix of 1..=MAX_MIX kinds, or `None` for an empty or too long list.
    pub fn mix(kinds: &[ShapeKind], order: MixOrder, salt: u64) -> Option<Self> {
        if kinds.is_empty() {
            return None;
        }
        let kinds = heapless::Vec::from_slice(kinds).ok()?;
        Some(ShapeList { kinds, order, salt })
    }

    /// The kinds in the mix.
    pub fn kinds(&self) -> &[ShapeKind] {
        &self.kinds
    }

    /// The kind of placement `i`.
    #[inline]
    pub fn kind_of(&self, i: u64) -> ShapeKind {
        // Asked for every neighbour a candidate is tested against: one kind returns at once,
        // and a mix divides by a length known to be at least 2.
        let kinds = self.kinds.as_slice();
        let k = match (kinds, self.order) {
            ([only], _) => return *only,
            ([], _) => return ShapeKind::Circle,
            (_, MixOrder::Cycle) => i % kinds.len() as u64,
            (_, MixOrder::Random) => mix64(i ^ self.salt) % kinds.len() as u64,
        };
        kinds.get(k as usize).copied().unwrap_or(ShapeKind::Circle)
    }

    /// Whether every kind is valid and the list is not empty.
    pub fn is_valid(&self) -> bool {
        !self.kinds.is_empty() && self.kinds.iter().all(ShapeKind::is_valid)
    }
}

/// SplitMix64's output function: a fixed bijective mix of 64 bits.
pub fn mix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
