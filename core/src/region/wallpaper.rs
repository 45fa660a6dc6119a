//! The 17 wallpaper groups: a lattice, and the operations that map a shape to its images in
//! one cell (the point group with its glides and screw-free translations, as the
//! International Tables for Crystallography list the general positions of the plane groups).
//!
//! A fill with the symmetry of a group places orbits: a shape and all its images. The fill
//! runs on the group's torus: the plane modulo the lattice, spanned by `a = (ax, 0)` and
//! `b = (bx, by)` with `by > 0` and `|bx| <= ax / 2`, whose fundamental domain is the
//! rectangle `[0, ax) x [0, by)` (a point that leaves it at the top comes back at the bottom
//! moved by `-bx`). Candidate centres are uniform over that rectangle, which is uniform over
//! the cell. The lattices:
//!
//! | lattice | groups | `--lattice` | `a`, `b` |
//! |---|---|---|---|
//! | oblique | p1, p2 | `A:B:ANGLE` | `(A, 0)`, `B (cos ANGLE, sin ANGLE)` |
//! | rectangular | pm, pg, pmm, pmg, pgg | `A:B` | `(A, 0)`, `(0, B)` |
//! | centred rectangular | cm, cmm | `A:B` | `(A, 0)`, `(A/2, B/2)` (the cell drawn is `A x B`) |
//! | square | p4, p4m, p4g | `A` | `(A, 0)`, `(0, A)` |
//! | hexagonal | p3, p3m1, p31m, p6, p6m | `A` | `(A, 0)`, `(A/2, A sqrt(3)/2)` |
//!
//! Each operation is written in the fractional coordinates of the conventional cell (integer
//! matrix, translation in halves), and turned once into a Cartesian isometry `x -> M x + t`
//! whose entries are snapped to `{0, +-1/2, +-sqrt(3)/2, +-1}`: rotations by multiples of 60 or
//! 90 degrees and mirrors at multiples of 30 degrees are then exact where they can be, and the
//! same bits on every target.
//!
//! The image of a shape whose centre is `c` under operation `k` is centred at
//! `wrap(M c + t)`, and its outline is that centre plus `M (v - c)` for each vertex `v` of the
//! shape's own outline (listed in reverse under a mirror or glide, so it stays
//! counter-clockwise): a rotated shape's image is rotated, a mirrored one mirrored (a chiral
//! blob becomes its mirror image). This is the outline the engine tests and the writers draw.

use crate::geom::{Geo, Point};
use crate::scalar::Scalar;

/// sqrt(3)/2, rounded to the nearest f64.
const SQRT3_2: f64 = 0.866_025_403_784_438_6;

/// Most images a shape has in one cell (p6m's 12).
pub const MAX_IMAGES: usize = 12;

/// One of the 17 wallpaper groups (plane symmetry groups), by its short international name.
///
/// # Examples
///
/// ```
/// use zetafill::{Group, LatticeKind};
///
/// assert_eq!(Group::ALL.len(), 17);
/// assert_eq!(Group::from_name("p4m"), Some(Group::P4m));
/// assert_eq!(Group::P4m.name(), "p4m");
/// assert_eq!(Group::P6m.order(), 12);
/// assert_eq!(Group::Cm.lattice(), LatticeKind::Centred);
/// assert_eq!(Group::from_name("p5"), None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Group {
    /// Translations only.
    P1,
    /// Half turns.
    P2,
    /// Parallel mirrors.
    Pm,
    /// Parallel glides.
    Pg,
    /// Mirrors and glides, centred cell.
    Cm,
    /// Mirrors both ways.
    Pmm,
    /// Mirrors one way, glides the other.
    Pmg,
    /// Glides both ways.
    Pgg,
    /// Mirrors both ways, centred cell.
    Cmm,
    /// Quarter turns.
    P4,
    /// Quarter turns and mirrors through the centres.
    P4m,
    /// Quarter turns, mirrors off the centres.
    P4g,
    /// Third turns.
    P3,
    /// Third turns, mirrors through every centre.
    P3m1,
    /// Third turns, mirrors off some centres.
    P31m,
    /// Sixth turns.
    P6,
    /// Sixth turns and mirrors.
    P6m,
}

/// The lattice a group needs, and so the lattice sizes it takes (see the module's table).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LatticeKind {
    /// Any two sides and the angle between them (p1, p2).
    Oblique,
    /// Two sides at a right angle (pm, pg, pmm, pmg, pgg).
    Rectangular,
    /// A rectangle with a lattice point at its centre too (cm, cmm).
    Centred,
    /// One side (p4, p4m, p4g).
    Square,
    /// One side, at 60 degrees (p3, p3m1, p31m, p6, p6m).
    Hexagonal,
}

impl LatticeKind {
    /// How many sizes the lattice takes: 1 (a side), 2 (two sides) or 3 (two sides and an
    /// angle).
    pub fn arity(self) -> usize {
        match self {
            LatticeKind::Square | LatticeKind::Hexagonal => 1,
            LatticeKind::Rectangular | LatticeKind::Centred => 2,
            LatticeKind::Oblique => 3,
        }
    }
}

/// An operation in the fractional coordinates of the conventional cell: `f -> R f + t / 2`.
#[derive(Clone, Copy)]
struct FracOp {
    r: [i8; 4],
    t: [i8; 2],
}

const fn op(r: [i8; 4], t: [i8; 2]) -> FracOp {
    FracOp { r, t }
}

const ID: FracOp = op([1, 0, 0, 1], [0, 0]);
const HALF_TURN: FracOp = op([-1, 0, 0, -1], [0, 0]);
// The square lattice's quarter turns and mirrors.
const Q1: FracOp = op([0, -1, 1, 0], [0, 0]);
const Q3: FracOp = op([0, 1, -1, 0], [0, 0]);
// The hexagonal lattice (a at 0 degrees, the conventional b at 120 degrees).
const H3: FracOp = op([0, -1, 1, -1], [0, 0]);
const H3B: FracOp = op([-1, 1, -1, 0], [0, 0]);
const H6: FracOp = op([1, -1, 1, 0], [0, 0]);
const H6B: FracOp = op([0, 1, -1, 1], [0, 0]);
// Mirrors through the 3-fold centres (p3m1) and between them (p31m).
const M1: [FracOp; 3] = [op([0, -1, -1, 0], [0, 0]), op([-1, 1, 0, 1], [0, 0]), op([1, 0, 1, -1], [0, 0])];
const M31: [FracOp; 3] = [op([0, 1, 1, 0], [0, 0]), op([1, -1, 0, -1], [0, 0]), op([-1, 0, -1, 1], [0, 0])];

const P1_OPS: [FracOp; 1] = [ID];
const P2_OPS: [FracOp; 2] = [ID, HALF_TURN];
const PM_OPS: [FracOp; 2] = [ID, op([-1, 0, 0, 1], [0, 0])];
const PG_OPS: [FracOp; 2] = [ID, op([-1, 0, 0, 1], [0, 1])];
const PMM_OPS: [FracOp; 4] = [ID, HALF_TURN, op([-1, 0, 0, 1], [0, 0]), op([1, 0, 0, -1], [0, 0])];
const PMG_OPS: [FracOp; 4] = [ID, HALF_TURN, op([-1, 0, 0, 1], [1, 0]), op([1, 0, 0, -1], [1, 0])];
const PGG_OPS: [FracOp; 4] = [ID, HALF_TURN, op([-1, 0, 0, 1], [1, 1]), op([1, 0, 0, -1], [1, 1])];
const P4_OPS: [FracOp; 4] = [ID, HALF_TURN, Q1, Q3];
const P4M_OPS: [FracOp; 8] = [
    ID,
    HALF_TURN,
    Q1,
    Q3,
    op([-1, 0, 0, 1], [0, 0]),
    op([1, 0, 0, -1], [0, 0]),
    op([0, 1, 1, 0], [0, 0]),
    op([0, -1, -1, 0], [0, 0]),
];
const P4G_OPS: [FracOp; 8] = [
    ID,
    HALF_TURN,
    Q1,
    Q3,
    op([-1, 0, 0, 1], [1, 1]),
    op([1, 0, 0, -1], [1, 1]),
    op([0, 1, 1, 0], [1, 1]),
    op([0, -1, -1, 0], [1, 1]),
];
const P3_OPS: [FracOp; 3] = [ID, H3, H3B];
const P3M1_OPS: [FracOp; 6] = [ID, H3, H3B, M1[0], M1[1], M1[2]];
const P31M_OPS: [FracOp; 6] = [ID, H3, H3B, M31[0], M31[1], M31[2]];
const P6_OPS: [FracOp; 6] = [ID, H3, H3B, HALF_TURN, H6B, H6];
const P6M_OPS: [FracOp; 12] = [ID, H3, H3B, HALF_TURN, H6B, H6, M1[0], M1[1], M1[2], M31[0], M31[1], M31[2]];

impl Group {
    /// All 17, in the order of the International Tables.
    pub const ALL: [Group; 17] = [
        Group::P1,
        Group::P2,
        Group::Pm,
        Group::Pg,
        Group::Cm,
        Group::Pmm,
        Group::Pmg,
        Group::Pgg,
        Group::Cmm,
        Group::P4,
        Group::P4m,
        Group::P4g,
        Group::P3,
        Group::P3m1,
        Group::P31m,
        Group::P6,
        Group::P6m,
    ];

    /// The short international name (`p1`, `p4m`, `p31m`, ...).
    pub fn name(self) -> &'static str {
        match self {
            Group::P1 => "p1",
            Group::P2 => "p2",
            Group::Pm => "pm",
            Group::Pg => "pg",
            Group::Cm => "cm",
            Group::Pmm => "pmm",
            Group::Pmg => "pmg",
            Group::Pgg => "pgg",
            Group::Cmm => "cmm",
            Group::P4 => "p4",
            Group::P4m => "p4m",
            Group::P4g => "p4g",
            Group::P3 => "p3",
            Group::P3m1 => "p3m1",
            Group::P31m => "p31m",
            Group::P6 => "p6",
            Group::P6m => "p6m",
        }
    }

    /// The group of a short name, `None` for any other text.
    pub fn from_name(name: &str) -> Option<Group> {
        Group::ALL.iter().copied().find(|g| g.name() == name)
    }

    /// The lattice the group needs.
    pub fn lattice(self) -> LatticeKind {
        match self {
            Group::P1 | Group::P2 => LatticeKind::Oblique,
            Group::Pm | Group::Pg | Group::Pmm | Group::Pmg | Group::Pgg => LatticeKind::Rectangular,
            Group::Cm | Group::Cmm => LatticeKind::Centred,
            Group::P4 | Group::P4m | Group::P4g => LatticeKind::Square,
            Group::P3 | Group::P3m1 | Group::P31m | Group::P6 | Group::P6m => LatticeKind::Hexagonal,
        }
    }

    /// The images of a shape in one primitive cell, the shape itself included.
    pub const fn order(self) -> usize {
        self.ops().len()
    }

    const fn ops(self) -> &'static [FracOp] {
        match self {
            Group::P1 => &P1_OPS,
            Group::P2 => &P2_OPS,
            Group::Pm | Group::Cm => &PM_OPS,
            Group::Pg => &PG_OPS,
            Group::Pmm | Group::Cmm => &PMM_OPS,
            Group::Pmg => &PMG_OPS,
            Group::Pgg => &PGG_OPS,
            Group::P4 => &P4_OPS,
            Group::P4m => &P4M_OPS,
            Group::P4g => &P4G_OPS,
            Group::P3 => &P3_OPS,
            Group::P3m1 => &P3M1_OPS,
            Group::P31m => &P31M_OPS,
            Group::P6 => &P6_OPS,
            Group::P6m => &P6M_OPS,
        }
    }
}

/// Why a lattice was refused ([`Wallpaper::new`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum WallpaperError {
    /// A side is not finite and positive.
    Side,
    /// The angle of an oblique lattice is not in (0, 180) degrees.
    Angle,
}

impl core::fmt::Display for WallpaperError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            WallpaperError::Side => "a lattice side must be finite and positive",
            WallpaperError::Angle => "a lattice angle must be between 0 and 180 degrees",
        })
    }
}

/// A Cartesian isometry `x -> M x + t` (`m` row-major).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iso {
    /// The linear part, row-major: `[m00, m01, m10, m11]`.
    pub m: [f64; 4],
    /// The translation.
    pub t: [f64; 2],
}

impl Iso {
    /// Whether the isometry reverses orientation (a mirror or a glide).
    pub fn mirrors(&self) -> bool {
        let [a, b, c, d] = self.m;
        a * d - b * c < 0.0
    }
}

/// A wallpaper group on a lattice: the region of a symmetric fill ([`crate::Region::Wallpaper`]).
///
/// # Examples
///
/// ```
/// use zetafill::{Group, Point, Wallpaper};
///
/// // p4m on a 60 mm square: 8 images a cell, a fundamental region of 450 mm^2.
/// let w = Wallpaper::new(Group::P4m, 60.0, 60.0, 90.0)?;
/// assert_eq!(w.order(), 8);
/// assert_eq!(w.cell_area(), 3600.0);
/// assert_eq!(w.fundamental_area(), 450.0);
/// // The images of a point: a quarter turn about the origin, wrapped into the cell.
/// let c = Point::new(10.0, 5.0);
/// assert_eq!(w.image_centre(2, c), Point::new(55.0, 10.0));
/// // The points of the plane come back into [0, 60) x [0, 60).
/// assert_eq!(w.wrap(Point::new(-1.0, 125.0)), Point::new(59.0, 5.0));
/// # Ok::<(), zetafill::WallpaperError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wallpaper {
    group: Group,
    /// The sides and angle (degrees) as given.
    sides: (f64, f64, f64),
    /// The primitive lattice: `a = (ax, 0)`, `b = (bx, by)`.
    ax: f64,
    bx: f64,
    by: f64,
    /// The conventional cell's basis (columns): `e1 = (e[0], e[2])`, `e2 = (e[1], e[3])`.
    e: [f64; 4],
}

impl Wallpaper {
    /// The group on a lattice of sides `a` and `b` at `angle` degrees. A square or hexagonal
    /// lattice uses `a` alone, a rectangular or centred one `a` and `b` (at 90 degrees);
    /// only an oblique lattice (p1, p2) uses all three.
    pub fn new(group: Group, a: f64, b: f64, angle: f64) -> Result<Self, WallpaperError> {
        let side = |v: f64| v.is_finite() && v > 0.0;
        let kind = group.lattice();
        let (b, angle) = match kind {
            LatticeKind::Square | LatticeKind::Hexagonal => (a, if kind == LatticeKind::Square { 90.0 } else { 60.0 }),
            LatticeKind::Rectangular | LatticeKind::Centred => (b, 90.0),
            LatticeKind::Oblique => (b, angle),
        };
        if !(side(a) && side(b)) {
            return Err(WallpaperError::Side);
        }
        if !(angle > 0.0 && angle < 180.0) {
            return Err(WallpaperError::Angle);
        }
        let (e, (ax, bx, by)) = match kind {
            LatticeKind::Rectangular | LatticeKind::Square => ([a, 0.0, 0.0, b], (a, 0.0, b)),
            LatticeKind::Centred => ([a, 0.0, 0.0, b], (a, a / 2.0, b / 2.0)),
            LatticeKind::Hexagonal => ([a, -a / 2.0, 0.0, a * SQRT3_2], (a, a / 2.0, a * SQRT3_2)),
            LatticeKind::Oblique => {
                let (s, c) = if angle == 90.0 {
                    (1.0, 0.0)
                } else {
                    let t = angle.to_radians();
                    (libm::sin(t), libm::cos(t))
                };
                let (ex, ey) = (b * c, b * s);
                // The same lattice with b moved by whole a's to |bx| <= ax / 2.
                let bx = ex - libm::round(ex / a) * a;
                ([a, ex, 0.0, ey], (a, bx, ey))
            }
        };
        if !(side(by) && ax.is_finite() && bx.is_finite() && side(ax * by)) {
            return Err(WallpaperError::Side);
        }
        Ok(Wallpaper {
            group,
            sides: (a, b, angle),
            ax,
            bx,
            by,
            e,
        })
    }

    /// The group.
    pub fn group(&self) -> Group {
        self.group
    }

    /// The sides and the angle in degrees (as used: a square lattice's `b` is its `a`).
    pub fn sides(&self) -> (f64, f64, f64) {
        self.sides
    }

    /// The primitive lattice `(ax, bx, by)`: `a = (ax, 0)`, `b = (bx, by)`; the fundamental
    /// domain of the torus is `[0, ax) x [0, by)`.
    pub fn lattice(&self) -> (f64, f64, f64) {
        (self.ax, self.bx, self.by)
    }

    /// The conventional cell's sides as drawn (`--repeat` counts these): the primitive
    /// rectangle, except a centred lattice's `a x b`.
    pub fn cell(&self) -> (f64, f64) {
        match self.group.lattice() {
            LatticeKind::Centred => (self.sides.0, self.sides.1),
            _ => (self.ax, self.by),
        }
    }

    /// Images a shape has in one primitive cell (the shape itself included).
    pub fn order(&self) -> usize {
        self.group.order()
    }

    /// The area of a primitive cell.
    pub fn cell_area(&self) -> f64 {
        self.ax * self.by
    }

    /// The area of the group's fundamental region: the cell's over [`Wallpaper::order`]. The
    /// power law of a symmetric fill divides this area.
    pub fn fundamental_area(&self) -> f64 {
        self.cell_area() / self.order() as f64
    }

    /// Operation `k` (0 is the identity) as a Cartesian isometry, `None` past the last.
    pub fn iso(&self, k: usize) -> Option<Iso> {
        let f = self.group.ops().get(k)?;
        let [e00, e01, e10, e11] = self.e;
        let det = e00 * e11 - e01 * e10;
        // E R E^-1, snapped to the entries a lattice-preserving isometry can have here.
        let inv = [e11 / det, -e01 / det, -e10 / det, e00 / det];
        let r = f.r.map(f64::from);
        let er = [
            e00 * r[0] + e01 * r[2],
            e00 * r[1] + e01 * r[3],
            e10 * r[0] + e11 * r[2],
            e10 * r[1] + e11 * r[3],
        ];
        let m = [
            er[0] * inv[0] + er[1] * inv[2],
            er[0] * inv[1] + er[1] * inv[3],
            er[2] * inv[0] + er[3] * inv[2],
            er[2] * inv[1] + er[3] * inv[3],
        ]
        .map(snap);
        let (t1, t2) = (f64::from(f.t[0]) / 2.0, f64::from(f.t[1]) / 2.0);
        let t = [e00 * t1 + e01 * t2, e10 * t1 + e11 * t2];
        Some(Iso { m, t })
    }

    /// The point `p` brought into the fundamental domain `[0, ax) x [0, by)` by a lattice
    /// translation.
    pub fn wrap<S: Scalar>(&self, p: Point<S>) -> Point<S> {
        let (ax, bx, by) = (S::from_f64(self.ax), S::from_f64(self.bx), S::from_f64(self.by));
        let (mut x, mut y) = (p.x, p.y);
        let l = (y / by).floor_i64();
        if l != 0 {
            let l = S::from_f64(l as f64);
            y = y - by * l;
            x = x - bx * l;
        }
        // Rounding may leave y a hair outside.
        if y < S::ZERO {
            y = y + by;
            x = x + bx;
        } else if y >= by {
            y = y - by;
            x = x - bx;
        }
        let k = (x / ax).floor_i64();
        if k != 0 {
            x = x - ax * S::from_f64(k as f64);
        }
        if x < S::ZERO {
            x = x + ax;
        } else if x >= ax {
            x = x - ax;
        }
        // Never outside, whatever the rounding did.
        Point::new(x.max(S::ZERO).min(ax), y.max(S::ZERO).min(by))
    }

    /// The centre of image `k` of a shape centred at `c`, wrapped into the domain (`c` itself
    /// for `k = 0` or past the last operation).
    pub fn image_centre<S: Scalar>(&self, k: usize, c: Point<S>) -> Point<S> {
        if k == 0 {
            return c;
        }
        let Some(iso) = self.iso(k) else { return c };
        let [m00, m01, m10, m11] = iso.m.map(S::from_f64);
        let q = Point::new(
            m00 * c.x + m01 * c.y + S::from_f64(iso.t[0]),
            m10 * c.x + m11 * c.y + S::from_f64(iso.t[1]),
        );
        self.wrap(q)
    }

    /// Image `k` of `shape` (centred at `c`) written into `out`, centred at `centre` (its
    /// [`Wallpaper::image_centre`], or that moved by a lattice vector): `centre + M (v - c)`
    /// for every point `v` of the outline, listed in reverse under a mirror.
    pub fn image_into<'m, S: Scalar>(&self, k: usize, shape: &Geo<'m, S>, c: Point<S>, centre: Point<S>, out: &mut Geo<'m, S>) {
        out.clone_from(shape);
        self.image_in_place(k, out, c, centre);
    }

    /// [`Wallpaper::image_into`] in place: `g` (centred at `c`) becomes its image `k`,
    /// centred at `centre` (no second outline is held, which a board's stack would feel).
    pub fn image_in_place<S: Scalar>(&self, k: usize, g: &mut Geo<S>, c: Point<S>, centre: Point<S>) {
        let iso = self.iso(k).unwrap_or(Iso {
            m: [1.0, 0.0, 0.0, 1.0],
            t: [0.0, 0.0],
        });
        let [m00, m01, m10, m11] = iso.m.map(S::from_f64);
        match g {
            Geo::Circle { c: gc, .. } | Geo::Ring { c: gc, .. } => *gc = centre,
            Geo::Poly { v, .. } => {
                for p in v.iter_mut() {
                    let d = p.diff(c);
                    *p = Point::new(centre.x + (m00 * d.x + m01 * d.y), centre.y + (m10 * d.x + m11 * d.y));
                }
                if iso.mirrors() {
                    v.reverse();
                }
            }
            Geo::Motif { f, .. } => *f = f.then([m00, m01, m10, m11], centre),
        }
    }

    /// Image `k` of `shape` (centred at `c`), at its wrapped centre.
    pub fn image<'m, S: Scalar>(&self, k: usize, shape: &Geo<'m, S>, c: Point<S>) -> Geo<'m, S> {
        let mut out = Geo::Circle { c, r: S::ZERO };
        self.image_into(k, shape, c, self.image_centre(k, c), &mut out);
        out
    }
}

/// The nearest of `0, +-1/2, +-sqrt(3)/2, +-1` to `v` (every entry of the groups' matrices is
/// one of them; rounding only moved it).
fn snap(v: f64) -> f64 {
    let mag = [0.0, 0.5, SQRT3_2, 1.0].iter().copied().fold(
        0.0f64,
        |best, m| if (v.abs() - m).abs() < (v.abs() - best).abs() { m } else { best },
    );
    if v < 0.0 {
        -mag
    } else {
        mag
    }
}

mod room;
#[cfg(test)]
mod tests;
