//! The solids: their kinds ([`Solid`], mixes in a [`SolidList`]), sizes from volumes, and the
//! polyhedra's tables.
//!
//! Sizes (`scale`): a sphere's and a shell's outer radius, half a cube's side, the
//! circumradius of a tetrahedron and of an octahedron, a torus's major radius `R` (the radius
//! of its tube's centre line; the tube's radius is `ratio R`). A torus's volume is the ideal
//! torus's `2 pi^2 ratio^2 R^3`; what is tested and drawn is the union of its beads (see
//! [`crate::internals::space`]).

use crate::scalar::Scalar;
use crate::shape::{mix64, MixOrder};
use core::f64::consts::PI;

/// How many kinds a [`SolidList`] holds at most.
pub const MAX_SOLIDS: usize = 8;

/// The most beads a torus is made of.
pub const MAX_BEADS: usize = 64;

/// A kind of solid.
///
/// # Examples
///
/// ```
/// use zetafill::space::Solid;
///
/// // A unit cube has volume 8 (its scale is half its side).
/// assert_eq!(Solid::Cube.volume(1.0), 8.0);
/// assert!((Solid::Sphere.scale_for_volume(Solid::Sphere.volume(2.5)) - 2.5).abs() < 1e-12);
/// assert!(Solid::Shell { inner: 0.5 }.is_valid() && !Solid::Torus { ratio: 1.5 }.is_valid());
/// // A torus of tube ratio 0.25 is drawn and tested as 51 spheres.
/// assert_eq!(Solid::Torus { ratio: 0.25 }.beads(), 51);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Solid {
    /// A ball.
    Sphere,
    /// A cube (rotated at random when the fill asks for rotation).
    Cube,
    /// A regular tetrahedron.
    Tetrahedron,
    /// A regular octahedron.
    Octahedron,
    /// A hollow sphere whose hole has `inner` times its radius (0 < inner < 1): smaller
    /// solids may be placed in the hole.
    Shell {
        /// Hole radius over outer radius.
        inner: f64,
    },
    /// A ring torus whose tube has `ratio` times its major radius (0.2 <= ratio <= 0.9),
    /// made of [`Solid::beads`] spheres.
    Torus {
        /// Tube radius over major radius.
        ratio: f64,
    },
}

impl Solid {
    /// Whether the proportions are in range.
    pub fn is_valid(&self) -> bool {
        match *self {
            Solid::Shell { inner } => inner.is_finite() && inner > 0.0 && inner < 1.0,
            Solid::Torus { ratio } => ratio.is_finite() && (0.2..=0.9).contains(&ratio),
            _ => true,
        }
    }

    /// Volume at `scale`.
    pub fn volume(&self, scale: f64) -> f64 {
        scale * scale * scale * self.unit_volume()
    }

    /// The scale of a solid of volume `v`.
    pub fn scale_for_volume(&self, v: f64) -> f64 {
        libm::cbrt(v / self.unit_volume())
    }

    fn unit_volume(&self) -> f64 {
        match *self {
            Solid::Sphere => 4.0 / 3.0 * PI,
            Solid::Cube => 8.0,
            // Edge sqrt(8/3): edge^3 / (6 sqrt 2).
            Solid::Tetrahedron => 8.0 * libm::sqrt(3.0) / 27.0,
            Solid::Octahedron => 4.0 / 3.0,
            Solid::Shell { inner } => 4.0 / 3.0 * PI * (1.0 - inner * inner * inner),
            Solid::Torus { ratio } => 2.0 * PI * PI * ratio * ratio,
        }
    }

    /// The radius of a ball about the centre that holds the solid, at `scale` (exact, before
    /// the scalar's rounding slack).
    pub fn circumradius(&self, scale: f64) -> f64 {
        match *self {
            Solid::Cube => scale * libm::sqrt(3.0),
            Solid::Torus { ratio } => scale * (1.0 + ratio),
            _ => scale,
        }
    }

    /// The least distance from the centre to a supporting plane (in any orientation): a ball
    /// of this radius about the centre lies in the solid's convex hull, so a centre closer to
    /// a face of a box than this (plus the gap) never fits.
    pub fn support(&self, scale: f64) -> f64 {
        match *self {
            Solid::Sphere | Solid::Shell { .. } | Solid::Cube => scale,
            Solid::Tetrahedron => scale / 3.0,
            Solid::Octahedron => scale / libm::sqrt(3.0),
            Solid::Torus { ratio } => scale * ratio,
        }
    }

    /// The narrowest width of the solid at `scale` (for `Stop::min_size`).
    pub fn min_width(&self, scale: f64) -> f64 {
        match *self {
            Solid::Tetrahedron => scale * 2.0 / libm::sqrt(3.0),
            Solid::Octahedron => scale * 2.0 / libm::sqrt(3.0),
            Solid::Shell { inner } => scale * (1.0 - inner),
            _ => 2.0 * self.support(scale),
        }
    }

    /// Whether the solid may be rotated (spheres and shells look the same in every
    /// orientation and take no rotation).
    pub fn rotates(&self) -> bool {
        !matches!(self, Solid::Sphere | Solid::Shell { .. })
    }

    /// How many beads a torus is made of: the fewest, at least 8, that are at most half the
    /// tube's radius apart along the centre line, `ceil(4 pi / ratio)` (0 for other kinds).
    pub fn beads(&self) -> usize {
        match *self {
            Solid::Torus { ratio } if self.is_valid() => {
                let n = libm::ceil(4.0 * PI / ratio);
                (n as usize).clamp(8, MAX_BEADS)
            }
            _ => 0,
        }
    }

    /// The polyhedron's table, if the solid is one.
    pub(crate) fn table(&self) -> Option<&'static Table> {
        match self {
            Solid::Cube => Some(&CUBE),
            Solid::Tetrahedron => Some(&TETRA),
            Solid::Octahedron => Some(&OCTA),
            _ => None,
        }
    }
}

/// A bounding radius in scalar `S`: the exact one grown by the scalar's outline slack, so that
/// a test skipped because bounding balls are apart never skips a contact.
pub(crate) fn bounding<S: Scalar>(kind: &Solid, scale: S) -> S {
    let r = kind.circumradius(scale.to_f64());
    let [rel, abs] = S::OUTLINE_SLACK;
    S::from_f64(r * (1.0 + rel) + abs)
}

/// The solid, or mix of solids, of a 3D fill: placement `i` has the kind
/// [`SolidList::kind_of`]`(i)`; the volume sequence is the same whatever the mix.
///
/// # Examples
///
/// ```
/// use zetafill::MixOrder;
/// use zetafill::space::{Solid, SolidList};
///
/// let mix = SolidList::mix(&[Solid::Cube, Solid::Sphere], MixOrder::Cycle, 0).expect("two kinds");
/// assert_eq!((mix.kind_of(0), mix.kind_of(1), mix.kind_of(2)), (Solid::Cube, Solid::Sphere, Solid::Cube));
/// let one: SolidList = Solid::Octahedron.into();
/// assert_eq!(one.kinds(), &[Solid::Octahedron]);
/// assert!(SolidList::mix(&[], MixOrder::Random, 0).is_none());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SolidList {
    kinds: heapless::Vec<Solid, MAX_SOLIDS>,
    /// How kinds are chosen per placement.
    pub order: MixOrder,
    /// Salt for [`MixOrder::Random`].
    pub salt: u64,
}

#[cfg(feature = "defmt")]
impl defmt::Format for SolidList {
    fn format(&self, f: defmt::Formatter<'_>) {
        defmt::write!(
            f,
            "SolidList {{ kinds: {=[?]}, order: {}, salt: {=u64} }}",
            self.kinds(),
            self.order,
            self.salt
        );
    }
}

impl From<Solid> for SolidList {
    fn from(k: Solid) -> Self {
        let mut kinds = heapless::Vec::new();
        let _ = kinds.push(k);
        SolidList {
            kinds,
            order: MixOrder::Cycle,
            salt: 0,
        }
    }
}

impl SolidList {
    /// A mix of 1..=[`MAX_SOLIDS`] kinds, or `None` for an empty or too long list.
    pub fn mix(kinds: &[Solid], order: MixOrder, salt: u64) -> Option<Self> {
        if kinds.is_empty() {
            return None;
        }
        let kinds = heapless::Vec::from_slice(kinds).ok()?;
        Some(SolidList { kinds, order, salt })
    }

    /// The kinds in the mix.
    pub fn kinds(&self) -> &[Solid] {
        &self.kinds
    }

    /// The kind of placement `i` (in turn, or a fixed pseudo-random choice per index as in
    /// 2D's [`crate::ShapeList`]).
    pub fn kind_of(&self, i: u64) -> Solid {
        let kinds = self.kinds.as_slice();
        let k = match (kinds, self.order) {
            ([only], _) => return *only,
            ([], _) => return Solid::Sphere,
            (_, MixOrder::Cycle) => i % kinds.len() as u64,
            (_, MixOrder::Random) => mix64(i ^ self.salt) % kinds.len() as u64,
        };
        kinds.get(k as usize).copied().unwrap_or(Solid::Sphere)
    }

    /// Whether every kind is valid and the list is not empty.
    pub fn is_valid(&self) -> bool {
        !self.kinds.is_empty() && self.kinds.iter().all(Solid::is_valid)
    }
}

/// A polyhedron at unit scale: vertices, triangles (three vertices and the face they lie
/// in), outward face normals and the faces' distance from the centre, edges and their
/// length, and the face normals and edges whose directions differ (for separating axes).
#[derive(Debug)]
pub(crate) struct Table {
    pub verts: &'static [[f64; 3]],
    pub tris: &'static [[u8; 4]],
    pub normals: &'static [[f64; 3]],
    pub h: f64,
    pub edges: &'static [[u8; 2]],
    pub edge_len: f64,
    pub axes: &'static [u8],
    pub dir_edges: &'static [[u8; 2]],
}

const R3: f64 = 0.577_350_269_189_625_8; // 1 / sqrt(3)

/// Vertex `b` at (bit 0 ? 1 : -1, bit 1 ? 1 : -1, bit 2 ? 1 : -1); scale is half the side.
static CUBE: Table = Table {
    verts: &[
        [-1.0, -1.0, -1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
        [1.0, -1.0, 1.0],
        [-1.0, 1.0, 1.0],
        [1.0, 1.0, 1.0],
    ],
    tris: &[
        [0, 4, 6, 0],
        [0, 6, 2, 0],
        [1, 3, 7, 1],
        [1, 7, 5, 1],
        [0, 1, 5, 2],
        [0, 5, 4, 2],
        [2, 6, 7, 3],
        [2, 7, 3, 3],
        [0, 2, 3, 4],
        [0, 3, 1, 4],
        [4, 5, 7, 5],
        [4, 7, 6, 5],
    ],
    normals: &[
        [-1.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, -1.0],
        [0.0, 0.0, 1.0],
    ],
    h: 1.0,
    edges: &[
        [0, 1],
        [2, 3],
        [4, 5],
        [6, 7],
        [0, 2],
        [1, 3],
        [4, 6],
        [5, 7],
        [0, 4],
        [1, 5],
        [2, 6],
        [3, 7],
    ],
    edge_len: 2.0,
    axes: &[1, 3, 5],
    dir_edges: &[[0, 1], [0, 2], [0, 4]],
};

/// Circumradius 1; the face opposite vertex `i` has outward normal `-v_i`.
static TETRA: Table = Table {
    verts: &[[R3, R3, R3], [R3, -R3, -R3], [-R3, R3, -R3], [-R3, -R3, R3]],
    tris: &[[1, 2, 3, 0], [0, 2, 3, 1], [0, 1, 3, 2], [0, 1, 2, 3]],
    normals: &[[-R3, -R3, -R3], [-R3, R3, R3], [R3, -R3, R3], [R3, R3, -R3]],
    h: 1.0 / 3.0,
    edges: &[[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]],
    edge_len: 1.632_993_161_855_452, // sqrt(8/3)
    axes: &[0, 1, 2, 3],
    dir_edges: &[[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]],
};

/// Vertices +x, -x, +y, -y, +z, -z at distance 1.
static OCTA: Table = Table {
    verts: &[
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ],
    tris: &[
        [0, 2, 4, 0],
        [0, 2, 5, 1],
        [0, 3, 4, 2],
        [0, 3, 5, 3],
        [1, 2, 4, 4],
        [1, 2, 5, 5],
        [1, 3, 4, 6],
        [1, 3, 5, 7],
    ],
    normals: &[
        [R3, R3, R3],
        [R3, R3, -R3],
        [R3, -R3, R3],
        [R3, -R3, -R3],
        [-R3, R3, R3],
        [-R3, R3, -R3],
        [-R3, -R3, R3],
        [-R3, -R3, -R3],
    ],
    h: R3,
    edges: &[
        [0, 2],
        [0, 3],
        [1, 2],
        [1, 3],
        [0, 4],
        [0, 5],
        [1, 4],
        [1, 5],
        [2, 4],
        [2, 5],
        [3, 4],
        [3, 5],
    ],
    edge_len: core::f64::consts::SQRT_2,
    axes: &[0, 1, 2, 3],
    dir_edges: &[[0, 2], [0, 3], [0, 4], [0, 5], [2, 4], [2, 5]],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_are_consistent() {
        for (kind, t) in [(Solid::Cube, &CUBE), (Solid::Tetrahedron, &TETRA), (Solid::Octahedron, &OCTA)] {
            let v = |i: u8| t.verts[i as usize];
            for e in t.edges {
                let (a, b) = (v(e[0]), v(e[1]));
                let l = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
                assert!((l - t.edge_len).abs() < 1e-12, "{kind:?}");
            }
            for tri in t.tris {
                let n = t.normals[tri[3] as usize];
                for &i in &tri[..3] {
                    let p = v(i);
                    assert!((p[0] * n[0] + p[1] * n[1] + p[2] * n[2] - t.h).abs() < 1e-12, "{kind:?}");
                }
            }
            // Every vertex within every face's half-space, and the support is the inradius.
            for p in t.verts {
                for n in t.normals {
                    assert!(p[0] * n[0] + p[1] * n[1] + p[2] * n[2] <= t.h + 1e-12);
                }
            }
            assert!((kind.support(1.0) - t.h).abs() < 1e-12);
        }
    }

    #[test]
    fn volumes_invert() {
        for k in [
            Solid::Sphere,
            Solid::Cube,
            Solid::Tetrahedron,
            Solid::Octahedron,
            Solid::Shell { inner: 0.4 },
            Solid::Torus { ratio: 0.3 },
        ] {
            assert!((k.scale_for_volume(k.volume(3.0)) - 3.0).abs() < 1e-12);
        }
        assert_eq!(Solid::Torus { ratio: 0.2 }.beads(), 63);
    }
}
