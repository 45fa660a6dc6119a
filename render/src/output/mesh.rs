//! Triangle meshes of solids that lie *inside* the solids, so that printed parts never touch
//! where the fill kept them apart. Every mesh is closed and oriented (each edge is shared by
//! exactly two triangles, in opposite directions; triangles are counter-clockwise seen from
//! outside the material).
//!
//! Why each mesh lies inside its solid:
//!
//! - **Sphere**: a UV sphere whose vertices lie on the sphere. Each triangle is the convex hull
//!   of three points of the ball, and the ball is convex, so the triangle lies in the ball.
//! - **Cube, tetrahedron, octahedron**: the boundary itself (exact).
//! - **Shell**: the outer surface is the inscribed UV sphere above. The inner surface must
//!   stay *outside* the hole: it is a UV sphere of radius `inner / m`, where `m` is the least
//!   distance from the centre to any triangle of the unit UV sphere (computed exactly for each
//!   resolution, [`uv_sphere_gap`]); every point of it is then at least `inner` from the centre.
//!   Its triangles face the hole.
//! - **Torus** (the points within `r` of the circle C of radius `R`): vertices on the surface
//!   are *not* enough, because on the inner, concave side a chord between two vertices passes
//!   closer to the axis than the tube allows. Take the quad between the meridians at angles
//!   `u0` and `u1 = u0 + 2δ` (`δ = π / n`, `n` meridians), and the chord `S` from `C(u0)` to
//!   `C(u1)`. Every point of `S` lies within `R (1 - cos δ)` of C (the chord's middle is
//!   `R cos δ` from the axis). A vertex at `u0` is `C(u0) + ρ w` with `w` a unit vector of the
//!   meridian plane; along `S` its offset projects to `-ρ cos v sin δ`, so its nearest point of
//!   `S` is `C(u0)` (distance `ρ`) when `cos v >= 0`, and an inner point of `S` at distance
//!   `ρ sqrt(1 - cos² v sin² δ) <= ρ` otherwise (likewise at `u1`). So every vertex of the quad
//!   lies in the capsule of radius `ρ` around `S`, which is convex, hence holds the quad's
//!   triangles; and every point of that capsule is within `ρ + R (1 - cos δ)` of C. With the
//!   tube of the mesh `ρ = r - R (1 - cos δ)` ([`torus_mesh_tube`]), the mesh lies in the torus.
//! - **Bead torus** (balls of radius `r` centred at `beads` points evenly on C): a point at
//!   distance `d` from C, whose nearest point of C is at angle `Δ <= β = π / beads` from a bead
//!   centre, is at squared distance `d² + 2R (1 - cos Δ)(R + d cos v) <= d² + 2R (1 - cos β)(R + d)`
//!   from that bead's centre. So the smooth torus of tube `t` with
//!   `t² + 2R (1 - cos β)(R + t) = r²` lies in the union, and it is the largest such torus
//!   about C (equality holds midway between two beads, on the outer side). It is meshed as a
//!   torus, shrunk as above ([`bead_torus_tube`]).
//!
//! A mesh built with [`MeshOptions::margin`] lies inside the solid shrunk by that many mm
//! (spheres and tori lose it from their radius, polyhedra are scaled so every face moves in by
//! it), which absorbs the rounding of writing coordinates as 32-bit floats
//! ([`MeshOptions::for_scene`]). Deterministic: the same solids give the same numbers.

pub use crate::model::solid::bead_torus_tube;
use crate::model::solid::{add, cross, dot, is_rotation, norm, scale, sub, Solid, SolidKind, V3};
use std::f64::consts::PI;

/// The fewest and most segments a round solid may be meshed with.
pub const SEGMENTS: std::ops::RangeInclusive<u32> = 3..=1024;

/// A triangle mesh: vertices in mm and triangles as indices, counter-clockwise seen from outside.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// The vertices.
    pub vertices: Vec<V3>,
    /// The triangles.
    pub triangles: Vec<[u32; 3]>,
}

/// How round solids are meshed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshOptions {
    /// Segments around a sphere's equator and around a torus's ring (the tube gets half as
    /// many, at least 3); a sphere has `segments / 2` (at least 2) bands from pole to pole.
    pub segments: u32,
    /// How far inside the solid the mesh stays (mm, at least 0).
    pub margin: f64,
}

/// Why a solid cannot be meshed.
#[derive(Debug, Clone, PartialEq)]
pub enum MeshError {
    /// `segments` is outside [`SEGMENTS`].
    Segments(u32),
    /// A solid's size is not a positive finite number, or a shell's or torus's radii are out of
    /// order.
    BadSize,
    /// A shell's wall is too thin for this resolution: its inner mesh would cross its outer one.
    ShellTooThin,
    /// A torus's tube is too thin for this many segments around its ring (or, for a bead torus,
    /// the beads do not overlap enough to hold a smooth torus).
    TubeTooThin,
    /// A solid's centre is not finite, or its rotation matrix is not a rotation (orthonormal,
    /// determinant +1, within 1e-9).
    Placement,
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MeshError::Segments(n) => {
                write!(f, "{n} segments: a mesh needs {} to {}", SEGMENTS.start(), SEGMENTS.end())
            }
            MeshError::BadSize => write!(f, "a solid has a size that is not a positive number, or radii out of order"),
            MeshError::ShellTooThin => write!(f, "a shell's wall is too thin to mesh at this resolution: use more segments"),
            MeshError::TubeTooThin => write!(f, "a torus's tube is too thin to mesh at this resolution: use more segments"),
            MeshError::Placement => write!(f, "its centre is not a finite point or its rotation is not a rotation matrix"),
        }
    }
}

/// A mesh error and the index of the solid it concerns.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The solid's index in the list.
    pub index: usize,
    /// What is wrong.
    pub error: MeshError,
}

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "solid {}: {}", self.index, self.error)
    }
}

impl MeshOptions {
    /// `segments` and no margin.
    pub fn new(segments: u32) -> MeshOptions {
        MeshOptions { segments, margin: 0.0 }
    }

    /// `segments`, with a margin that covers rounding every coordinate of these solids to a
    /// 32-bit float: a coordinate `x` moves by at most `|x| 2^-24`, a point by less than
    /// `2 max|x| 2^-24`; the margin is twice that.
    pub fn for_scene(solids: &[Solid], segments: u32) -> MeshOptions {
        let extent = solids
            .iter()
            .map(|s| s.centre.iter().fold(0.0f64, |m, c| m.max(c.abs())) + s.kind.bounding_radius())
            .fold(0.0f64, f64::max);
        MeshOptions {
            segments,
            margin: 2.0 * extent * f64::from(f32::EPSILON),
        }
    }
}

impl Mesh {
    /// Appends `other`, its indices shifted.
    pub fn append(&mut self, other: &Mesh) {
        let base = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.triangles.extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }

    /// This mesh with every vertex mapped by `f`.
    pub fn mapped(&self, f: impl Fn(V3) -> V3) -> Mesh {
        Mesh {
            vertices: self.vertices.iter().map(|v| f(*v)).collect(),
            triangles: self.triangles.clone(),
        }
    }

    /// The corners of triangle `i`.
    pub fn corners(&self, i: usize) -> [V3; 3] {
        self.triangles[i].map(|k| self.vertices[k as usize])
    }
}

/// A UV sphere of `radius` with `n` segments around and `max(n / 2, 2)` bands.
pub fn uv_sphere(radius: f64, n: u32) -> Mesh {
    let bands = (n / 2).max(2);
    let mut vertices = vec![[0.0, 0.0, radius]];
    for i in 1..bands {
        let theta = PI * f64::from(i) / f64::from(bands);
        for j in 0..n {
            let phi = 2.0 * PI * f64::from(j) / f64::from(n);
            let (st, sp) = (libm::sin(theta), libm::sin(phi));
            vertices.push(scale([st * libm::cos(phi), st * sp, libm::cos(theta)], radius));
        }
    }
    vertices.push([0.0, 0.0, -radius]);
    let south = vertices.len() as u32 - 1;
    let at = |i: u32, j: u32| 1 + (i - 1) * n + j % n;
    let mut triangles = Vec::new();
    for j in 0..n {
        triangles.push([0, at(1, j), at(1, j + 1)]);
        for i in 1..bands - 1 {
            let (a, b, c, d) = (at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
        triangles.push([south, at(bands - 1, j + 1), at(bands - 1, j)]);
    }
    Mesh { vertices, triangles }
}

/// The least distance from the centre to a triangle of the unit UV sphere of `n` segments
/// (every band has the same triangles up to a turn about z, so one column of them is enough).
pub fn uv_sphere_gap(n: u32) -> f64 {
    let m = uv_sphere(1.0, n);
    let bands = (n / 2).max(2) as usize;
    // The first 2 bands - 2 + 2 triangles are the column at j = 0.
    (0..2 * bands - 2)
        .map(|i| triangle_distance(m.corners(i), [0.0; 3]))
        .fold(f64::INFINITY, f64::min)
}

/// The least distance from `p` to the triangle `t`.
pub fn triangle_distance(t: [V3; 3], p: V3) -> f64 {
    let [a, b, c] = t;
    let n = cross(sub(b, a), sub(c, a));
    let nn = dot(n, n);
    if nn > 0.0 {
        // The foot of the perpendicular, if it falls inside the triangle.
        let h = dot(sub(p, a), n) / nn;
        let foot = sub(p, scale(n, h));
        let inside = [(a, b), (b, c), (c, a)]
            .iter()
            .all(|(u, v)| dot(cross(sub(*v, *u), sub(foot, *u)), n) >= 0.0);
        if inside {
            return h.abs() * nn.sqrt();
        }
    }
    [(a, b), (b, c), (c, a)]
        .iter()
        .map(|(u, v)| {
            let e = sub(*v, *u);
            let s = (dot(sub(p, *u), e) / dot(e, e).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            norm(sub(p, add(*u, scale(e, s))))
        })
        .fold(f64::INFINITY, f64::min)
}

/// The tube radius of the mesh of a torus of tube `minor` about a circle of radius `major`
/// with `n` segments around its ring: `minor - major (1 - cos(π / n))` (see the module's
/// argument); `None` when nothing is left.
pub fn torus_mesh_tube(major: f64, minor: f64, n: u32) -> Option<f64> {
    let t = minor - major * (1.0 - libm::cos(PI / f64::from(n)));
    (t > 0.0).then_some(t)
}

/// A polygonal torus with `n` segments around the ring, `max(n / 2, 3)` around the tube, its
/// vertices `tube` from the circle of radius `major`.
pub fn torus_mesh(major: f64, tube: f64, n: u32) -> Mesh {
    let m = (n / 2).max(3);
    let mut vertices = Vec::new();
    for i in 0..n {
        let u = 2.0 * PI * f64::from(i) / f64::from(n);
        for j in 0..m {
            let v = 2.0 * PI * f64::from(j) / f64::from(m);
            let rho = major + tube * libm::cos(v);
            vertices.push([rho * libm::cos(u), rho * libm::sin(u), tube * libm::sin(v)]);
        }
    }
    let at = |i: u32, j: u32| (i % n) * m + j % m;
    let mut triangles = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    Mesh { vertices, triangles }
}

fn positive(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite() && *x > 0.0)
}

/// A solid's mesh once its sizes are checked: the radii its surfaces are built at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MeshPlan {
    /// A UV sphere of this vertex radius.
    Sphere(f64),
    /// A UV sphere of vertex radius `outer`, and one of vertex radius `hole` facing inwards.
    Shell {
        /// The outer surface's vertex radius.
        outer: f64,
        /// The inner surface's vertex radius.
        hole: f64,
    },
    /// A polygonal torus with its vertices `tube` from the circle of radius `major`.
    Torus {
        /// Radius of the central circle.
        major: f64,
        /// The vertices' distance from it.
        tube: f64,
    },
    /// A polyhedron scaled about its centre by this factor.
    Polyhedron(SolidKind, f64),
}

/// Checks and plans meshes at one resolution (the least distance of the unit UV sphere's
/// triangles from its centre is computed once).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mesher {
    opt: MeshOptions,
    gap: f64,
}

impl Mesher {
    /// A mesher for `opt`, if its segments are in [`SEGMENTS`].
    pub fn new(opt: &MeshOptions) -> Result<Mesher, MeshError> {
        if !SEGMENTS.contains(&opt.segments) {
            return Err(MeshError::Segments(opt.segments));
        }
        Ok(Mesher {
            opt: MeshOptions {
                margin: opt.margin.max(0.0),
                ..*opt
            },
            gap: uv_sphere_gap(opt.segments),
        })
    }

    /// The plan of `kind`'s mesh, inside it by the margin (see the module's argument).
    pub fn plan(&self, kind: &SolidKind) -> Result<MeshPlan, MeshError> {
        let (n, e, gap) = (self.opt.segments, self.opt.margin, self.gap);
        match *kind {
            SolidKind::Sphere { radius } => {
                if !positive(&[radius, radius - e]) {
                    return Err(MeshError::BadSize);
                }
                Ok(MeshPlan::Sphere(radius - e))
            }
            SolidKind::Shell { outer, inner } => {
                if !positive(&[outer, inner, outer - inner, outer - e]) {
                    return Err(MeshError::BadSize);
                }
                // The outer mesh's nearest point to the centre is gap * (outer - e); the inner
                // mesh's farthest is its vertex radius. Slightly more than the least radius, so
                // rounding cannot bring a triangle into the hole.
                let hole = (inner + e) / gap * (1.0 + 1e-12);
                if hole >= (outer - e) * gap {
                    return Err(MeshError::ShellTooThin);
                }
                Ok(MeshPlan::Shell { outer: outer - e, hole })
            }
            SolidKind::Torus { major, minor } => {
                if !positive(&[major, minor, major - minor]) {
                    return Err(MeshError::BadSize);
                }
                let tube = torus_mesh_tube(major, minor - e, n).ok_or(MeshError::TubeTooThin)?;
                Ok(MeshPlan::Torus { major, tube })
            }
            SolidKind::BeadTorus { major, minor, beads } => {
                if !positive(&[major, minor]) || beads < 3 {
                    return Err(MeshError::BadSize);
                }
                let smooth = bead_torus_tube(major, minor, beads).ok_or(MeshError::TubeTooThin)?;
                if smooth >= major {
                    return Err(MeshError::BadSize);
                }
                let tube = torus_mesh_tube(major, smooth - e, n).ok_or(MeshError::TubeTooThin)?;
                Ok(MeshPlan::Torus { major, tube })
            }
            SolidKind::Cube { .. } | SolidKind::Tetrahedron { .. } | SolidKind::Octahedron { .. } => {
                // Every face is at the inradius; scaling by (in - e) / in moves each in by e.
                let inradius = kind.polyhedron().and_then(|p| p.planes.first().map(|pl| pl.1)).unwrap_or(0.0);
                if !positive(&[inradius, inradius - e]) {
                    return Err(MeshError::BadSize);
                }
                Ok(MeshPlan::Polyhedron(*kind, (inradius - e) / inradius))
            }
        }
    }

    /// The number of triangles of a planned mesh.
    pub fn triangles(&self, plan: &MeshPlan) -> usize {
        let n = self.opt.segments as usize;
        let sphere = 2 * n * ((n / 2).max(2) - 1);
        match plan {
            MeshPlan::Sphere(_) => sphere,
            MeshPlan::Shell { .. } => 2 * sphere,
            MeshPlan::Torus { .. } => 2 * n * (n / 2).max(3),
            MeshPlan::Polyhedron(kind, _) => kind.polyhedron().map_or(0, |p| p.triangles.len()),
        }
    }

    /// The planned mesh in the solid's local frame.
    pub fn build(&self, plan: &MeshPlan) -> Mesh {
        let n = self.opt.segments;
        match *plan {
            MeshPlan::Sphere(r) => uv_sphere(r, n),
            MeshPlan::Shell { outer, hole } => {
                let mut mesh = uv_sphere(outer, n);
                let mut inside = uv_sphere(hole, n);
                for t in &mut inside.triangles {
                    t.swap(1, 2);
                }
                mesh.append(&inside);
                mesh
            }
            MeshPlan::Torus { major, tube } => torus_mesh(major, tube, n),
            MeshPlan::Polyhedron(kind, s) => kind.polyhedron().map_or_else(Mesh::default, |p| Mesh {
                vertices: p.vertices.iter().map(|v| scale(*v, s)).collect(),
                triangles: p.triangles,
            }),
        }
    }
}

/// The mesh of `kind` in its local frame, inside it (by `opt.margin`).
pub fn local_mesh(kind: &SolidKind, opt: &MeshOptions) -> Result<Mesh, MeshError> {
    let m = Mesher::new(opt)?;
    Ok(m.build(&m.plan(kind)?))
}

/// The mesh of a placed solid in the world frame.
pub fn solid_mesh(solid: &Solid, opt: &MeshOptions) -> Result<Mesh, MeshError> {
    Ok(local_mesh(&solid.kind, opt)?.mapped(|q| solid.to_world(q)))
}

/// Whether a solid's centre is finite and its rotation a rotation (so a mesh moved by them
/// stays inside the solid and keeps its orientation).
pub fn check_placement(s: &Solid) -> Result<(), MeshError> {
    let ok = s.centre.iter().all(|c| c.is_finite()) && is_rotation(&s.rotation, 1e-9);
    ok.then_some(()).ok_or(MeshError::Placement)
}

/// The meshes of a list of solids, checked and counted before any is built, so a writer can
/// write a header with the count and then stream one solid at a time.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenePlan {
    mesher: Mesher,
    plans: Vec<MeshPlan>,
    /// The number of triangles of every mesh together.
    pub triangles: u64,
}

impl ScenePlan {
    /// Checks every solid; the error names the first that cannot be meshed.
    pub fn new(solids: &[Solid], opt: &MeshOptions) -> Result<ScenePlan, SceneError> {
        let mesher = Mesher::new(opt).map_err(|error| SceneError { index: 0, error })?;
        let plans = solids
            .iter()
            .enumerate()
            .map(|(index, s)| {
                check_placement(s)
                    .and_then(|()| mesher.plan(&s.kind))
                    .map_err(|error| SceneError { index, error })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let triangles = plans.iter().map(|p| mesher.triangles(p) as u64).sum();
        Ok(ScenePlan { mesher, plans, triangles })
    }

    /// Solid `index`'s mesh in the world frame (`solid` is that solid).
    pub fn mesh(&self, index: usize, solid: &Solid) -> Mesh {
        self.plans
            .get(index)
            .map_or_else(Mesh::default, |p| self.mesher.build(p).mapped(|q| solid.to_world(q)))
    }
}

/// What makes two solids share one mesh up to a rotation, a uniform scale and a move.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct MeshKey {
    /// The kind: 0 sphere, 1 shell, 2 cube, 3 tetrahedron, 4 octahedron, 5 torus, 6 bead torus.
    pub kind: u8,
    /// The bits of the shape's ratio (inner / outer, minor / major; 0 otherwise) rounded to
    /// 32 bits, the precision of a mesh's coordinates: the ratio of a solid is computed from
    /// its two radii, so solids of one `--shape shell:0.3` give 0.3 and 0.29999999999999993,
    /// whose meshes round to the same vertices and are one mesh.
    pub ratio: u32,
    /// The beads of a bead torus (0 otherwise).
    pub beads: u32,
}

/// The key of `kind`, the unit-size kind it is a scaled copy of, and the scale.
pub fn unit_kind(kind: &SolidKind) -> (MeshKey, SolidKind, f64) {
    let key = |kind: u8, ratio: f64, beads: u32| MeshKey {
        kind,
        ratio: (ratio as f32).to_bits(),
        beads,
    };
    match *kind {
        SolidKind::Sphere { radius } => (key(0, 0.0, 0), SolidKind::Sphere { radius: 1.0 }, radius),
        SolidKind::Shell { outer, inner } => {
            let q = inner / outer;
            (key(1, q, 0), SolidKind::Shell { outer: 1.0, inner: q }, outer)
        }
        SolidKind::Cube { half_side } => (key(2, 0.0, 0), SolidKind::Cube { half_side: 1.0 }, half_side),
        SolidKind::Tetrahedron { circumradius } => (key(3, 0.0, 0), SolidKind::Tetrahedron { circumradius: 1.0 }, circumradius),
        SolidKind::Octahedron { circumradius } => (key(4, 0.0, 0), SolidKind::Octahedron { circumradius: 1.0 }, circumradius),
        SolidKind::Torus { major, minor } => {
            let q = minor / major;
            (key(5, q, 0), SolidKind::Torus { major: 1.0, minor: q }, major)
        }
        SolidKind::BeadTorus { major, minor, beads } => {
            let q = minor / major;
            (
                key(6, q, beads),
                SolidKind::BeadTorus {
                    major: 1.0,
                    minor: q,
                    beads,
                },
                major,
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points spread over a triangle (corners, edges, inside).
    fn samples(t: [V3; 3]) -> Vec<V3> {
        let k = 6;
        let mut out = Vec::new();
        for i in 0..=k {
            for j in 0..=k - i {
                let (a, b) = (f64::from(i) / f64::from(k), f64::from(j) / f64::from(k));
                out.push(add(add(scale(t[0], 1.0 - a - b), scale(t[1], a)), scale(t[2], b)));
            }
        }
        out
    }

    #[test]
    fn triangle_counts_are_those_built() {
        let m = Mesher::new(&MeshOptions::new(7)).expect("7 segments");
        for kind in [
            SolidKind::Sphere { radius: 2.0 },
            SolidKind::Shell { outer: 2.0, inner: 1.0 },
            SolidKind::Cube { half_side: 1.0 },
            SolidKind::Tetrahedron { circumradius: 1.0 },
            SolidKind::Octahedron { circumradius: 1.0 },
            SolidKind::Torus { major: 3.0, minor: 1.0 },
            SolidKind::BeadTorus {
                major: 3.0,
                minor: 1.0,
                beads: 16,
            },
        ] {
            let plan = m.plan(&kind).unwrap_or_else(|e| panic!("{kind:?}: {e:?}"));
            assert_eq!(m.triangles(&plan), m.build(&plan).triangles.len(), "{kind:?}");
        }
    }

    fn inside(kind: SolidKind, n: u32) -> bool {
        let m = local_mesh(&kind, &MeshOptions::new(n)).expect("meshes");
        (0..m.triangles.len()).all(|i| samples(m.corners(i)).iter().all(|p| kind.contains_local(*p, 1e-12)))
    }

    #[test]
    fn tori_shrink_enough_and_surface_vertices_do_not() {
        let kind = SolidKind::Torus { major: 3.0, minor: 1.0 };
        assert!(inside(kind, 12));
        // The twin: a torus meshed with its vertices on the surface leaves the tube on the
        // inner side.
        let naive = torus_mesh(3.0, 1.0, 12);
        let out = (0..naive.triangles.len()).any(|i| samples(naive.corners(i)).iter().any(|p| !kind.contains_local(*p, 1e-9)));
        assert!(out, "surface vertices must leave the tube somewhere");
    }

    #[test]
    fn bead_tori_hold_their_smooth_torus_tightly() {
        let kind = SolidKind::BeadTorus {
            major: 3.0,
            minor: 1.0,
            beads: 16,
        };
        assert!(inside(kind, 24));
        let t = bead_torus_tube(3.0, 1.0, 16).expect("overlapping beads");
        // Midway between two beads on the outer side, the smooth torus touches the union.
        let b = PI / 16.0;
        let p = [(3.0 + t) * libm::cos(b), (3.0 + t) * libm::sin(b), 0.0];
        assert!(kind.contains_local(p, 1e-12) && !kind.contains_local(scale(p, 1.0 + 1e-9), 0.0));
        assert_eq!(bead_torus_tube(3.0, 0.3, 8), None);
    }

    #[test]
    fn shells_keep_out_of_their_hole() {
        let kind = SolidKind::Shell { outer: 2.0, inner: 1.5 };
        assert!(inside(kind, 16));
        assert_eq!(
            local_mesh(&SolidKind::Shell { outer: 2.0, inner: 1.95 }, &MeshOptions::new(8)),
            Err(MeshError::ShellTooThin)
        );
    }

    #[test]
    fn spheres_and_polyhedra_are_inside_with_a_margin() {
        for kind in [
            SolidKind::Sphere { radius: 2.0 },
            SolidKind::Cube { half_side: 1.0 },
            SolidKind::Tetrahedron { circumradius: 1.0 },
            SolidKind::Octahedron { circumradius: 1.0 },
        ] {
            assert!(inside(kind, 5), "{kind:?}");
            let m = local_mesh(&kind, &MeshOptions { segments: 5, margin: 0.01 }).expect("meshes");
            assert!(m.vertices.iter().all(|v| kind.contains_local(*v, -0.0099)), "{kind:?}");
        }
        assert_eq!(
            local_mesh(&SolidKind::Sphere { radius: 1.0 }, &MeshOptions::new(2)),
            Err(MeshError::Segments(2))
        );
    }

    #[test]
    fn triangle_distance_is_exact_on_simple_cases() {
        let t = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
        assert_eq!(triangle_distance(t, [0.2, 0.2, 0.0]), 1.0);
        assert!((triangle_distance(t, [2.0, 0.0, 1.0]) - 1.0).abs() < 1e-15);
    }
}
