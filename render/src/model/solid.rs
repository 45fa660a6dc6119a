//! Solids in space: the plain data a 3D fill hands to the writers (meshes, slices, the render),
//! with the exact geometry they share: which points a solid holds, its faces, its bounding
//! sphere. A [`Solid`] is a centre in mm, a rotation and a [`SolidKind`] in geometric terms;
//! a [`Region3`] is the box or ball it was placed in.
//!
//! Frames: a solid's *local* frame has its centre at the origin; a point `q` of it is the world
//! point `centre + rotation * q` (the rotation is a row-major, orthonormal 3x3 matrix with
//! determinant +1). A torus's central circle lies in the local xy plane, around the local z
//! axis. Regions follow `circle:R` of the 2D fill: every region's bounding box starts at the
//! origin, so a ball of radius R is centred at (R, R, R).
//!
//! Nothing here allocates more than its answer, prints or panics; everything is deterministic.

use std::f64::consts::PI;

/// A point or vector in mm.
pub type V3 = [f64; 3];

/// A 3x3 matrix, row-major: `m[row][col]`.
pub type Mat3 = [[f64; 3]; 3];

/// The identity rotation.
pub const IDENTITY: Mat3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// What a solid is, in its local frame (sizes in mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SolidKind {
    /// A ball.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// A hollow ball: the points between the two spheres.
    Shell {
        /// Outer radius.
        outer: f64,
        /// Radius of the hole (`0 < inner < outer`).
        inner: f64,
    },
    /// A cube with faces perpendicular to the local axes.
    Cube {
        /// Half the side.
        half_side: f64,
    },
    /// A regular tetrahedron with vertices `circumradius / sqrt 3 * (±1, ±1, ±1)` (an even number
    /// of minus signs).
    Tetrahedron {
        /// Distance from the centre to a vertex.
        circumradius: f64,
    },
    /// A regular octahedron with vertices on the local axes.
    Octahedron {
        /// Distance from the centre to a vertex.
        circumradius: f64,
    },
    /// A solid torus: the points within `minor` of the circle of radius `major` in the local xy
    /// plane (`minor < major`).
    Torus {
        /// Radius of the tube's central circle.
        major: f64,
        /// Radius of the tube.
        minor: f64,
    },
    /// A torus as a union of `beads` balls of radius `minor`, centred evenly on the circle of
    /// radius `major` in the local xy plane, the first on the local +x axis.
    BeadTorus {
        /// Radius of the circle of bead centres.
        major: f64,
        /// Radius of each bead.
        minor: f64,
        /// Number of beads (at least 3).
        beads: u32,
    },
}

/// A convex polyhedron of a [`SolidKind`], in the local frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyhedron {
    /// The vertices.
    pub vertices: Vec<V3>,
    /// Triangles of the boundary, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// The faces as half-spaces `n . q <= d` (`n` a unit outward normal, `d` > 0).
    pub planes: Vec<(V3, f64)>,
}

/// One placed solid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solid {
    /// Centre in mm (world frame).
    pub centre: V3,
    /// Local to world rotation.
    pub rotation: Mat3,
    /// What it is.
    pub kind: SolidKind,
}

/// The region a fill took place in (mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Region3 {
    /// The box `[0, w] x [0, h] x [0, d]`.
    Box {
        /// Width (x).
        w: f64,
        /// Height (y).
        h: f64,
        /// Depth (z).
        d: f64,
    },
    /// The ball of radius `r` centred at `(r, r, r)`.
    Ball {
        /// Radius.
        r: f64,
    },
    /// The box `[0, w] x [0, h] x [0, d]` without the ball of radius `r` centred at the box's
    /// centre.
    BoxMinusBall {
        /// Width (x).
        w: f64,
        /// Height (y).
        h: f64,
        /// Depth (z).
        d: f64,
        /// Radius of the ball removed.
        r: f64,
    },
}

/// `a + b`.
pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a - b`.
pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `s * a`.
pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// The dot product.
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The cross product.
pub fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The length.
pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// `a / |a|` (the zero vector stays zero).
pub fn unit(a: V3) -> V3 {
    let n = norm(a);
    if n > 0.0 {
        scale(a, 1.0 / n)
    } else {
        a
    }
}

/// `m * v`.
pub fn mul(m: &Mat3, v: V3) -> V3 {
    [dot(m[0], v), dot(m[1], v), dot(m[2], v)]
}

/// `m^T * v` (the inverse rotation).
pub fn mul_t(m: &Mat3, v: V3) -> V3 {
    [
        m[0][0] * v[0] + m[1][0] * v[1] + m[2][0] * v[2],
        m[0][1] * v[0] + m[1][1] * v[1] + m[2][1] * v[2],
        m[0][2] * v[0] + m[1][2] * v[1] + m[2][2] * v[2],
    ]
}

/// The rotation by `angle` (radians) about the axis `a`, which need not be a unit vector
/// (Rodrigues' formula; the zero axis gives no rotation).
pub fn axis_angle(a: V3, angle: f64) -> Mat3 {
    let n = norm(a);
    if n == 0.0 {
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    }
    let [x, y, z] = a.map(|v| v / n);
    let (s, c) = libm::sincos(angle);
    let t = 1.0 - c;
    [
        [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
        [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
    ]
}

/// Whether `m` is a rotation (orthonormal rows, determinant +1) within `eps`.
pub fn is_rotation(m: &Mat3, eps: f64) -> bool {
    let orthonormal = (0..3).all(|i| (0..3).all(|j| (dot(m[i], m[j]) - f64::from(u8::from(i == j))).abs() <= eps));
    orthonormal && (dot(m[0], cross(m[1], m[2])) - 1.0).abs() <= eps
}

/// The distance from `q` (local frame) to the circle of radius `major` in the xy plane.
pub fn circle_distance(q: V3, major: f64) -> f64 {
    libm::hypot(libm::hypot(q[0], q[1]) - major, q[2])
}

/// The tube of the largest smooth torus about the bead circle that a bead torus holds (the argument is in
/// `output::mesh`); `None` when the beads are too far apart to hold one.
pub fn bead_torus_tube(major: f64, minor: f64, beads: u32) -> Option<f64> {
    // t² + 2k t + (2 R k - r²) = 0 with k = R (1 - cos β).
    let k = major * (1.0 - libm::cos(PI / f64::from(beads)));
    let disc = k * k - 2.0 * major * k + minor * minor;
    let t = disc.sqrt() - k;
    (disc > 0.0 && t > 0.0).then_some(t)
}

impl SolidKind {
    /// The radius of a ball about the centre that holds the solid.
    pub fn bounding_radius(&self) -> f64 {
        match *self {
            SolidKind::Sphere { radius } => radius,
            SolidKind::Shell { outer, .. } => outer,
            SolidKind::Cube { half_side } => half_side * 3f64.sqrt(),
            SolidKind::Tetrahedron { circumradius } | SolidKind::Octahedron { circumradius } => circumradius,
            SolidKind::Torus { major, minor } | SolidKind::BeadTorus { major, minor, .. } => major + minor,
        }
    }

    /// The polyhedron of a cube, tetrahedron or octahedron; `None` for the round solids.
    pub fn polyhedron(&self) -> Option<Polyhedron> {
        let s3 = 3f64.sqrt();
        match *self {
            SolidKind::Cube { half_side: h } => {
                let vertices = (0..8).map(|i| [sign(i & 1) * h, sign(i & 2) * h, sign(i & 4) * h]).collect();
                // Vertex i has x = +h when bit 0 is set, y with bit 1, z with bit 2.
                let quads = [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1], [4, 5, 7, 6]];
                let triangles = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
                let planes = (0..3).flat_map(|a| [-1.0, 1.0].map(|s| (axis(a, s), h))).collect();
                Some(Polyhedron {
                    vertices,
                    triangles,
                    planes,
                })
            }
            SolidKind::Tetrahedron { circumradius: r } => {
                let dirs = [[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
                let vertices = dirs.iter().map(|d| scale(*d, r / s3)).collect();
                // The face opposite vertex i, wound so that it faces away from vertex i.
                let triangles = vec![[1, 3, 2], [0, 2, 3], [0, 3, 1], [0, 1, 2]];
                let planes = dirs.iter().map(|d| (scale(*d, -1.0 / s3), r / 3.0)).collect();
                Some(Polyhedron {
                    vertices,
                    triangles,
                    planes,
                })
            }
            SolidKind::Octahedron { circumradius: r } => {
                let vertices = (0..3).flat_map(|a| [1.0, -1.0].map(|s| scale(axis(a, s), r))).collect();
                // Vertices: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z; one face per octant.
                let mut triangles = Vec::new();
                let mut planes = Vec::new();
                for oct in 0..8u32 {
                    let (x, y, z) = (oct & 1, (oct >> 1) & 1, (oct >> 2) & 1);
                    let (vx, vy, vz) = (x, 2 + y, 4 + z);
                    // Counter-clockwise seen from outside when the octant has an even number of
                    // negative axes.
                    let even = (x + y + z) % 2 == 0;
                    triangles.push(if even { [vx, vy, vz] } else { [vx, vz, vy] });
                    let n = [sign(x ^ 1), sign(y ^ 1), sign(z ^ 1)];
                    planes.push((scale(n, 1.0 / s3), r / s3));
                }
                Some(Polyhedron {
                    vertices,
                    triangles,
                    planes,
                })
            }
            _ => None,
        }
    }

    /// The bead centres of a bead torus (local frame); empty for every other kind.
    pub fn bead_centres(&self) -> Vec<V3> {
        match *self {
            SolidKind::BeadTorus { major, beads, .. } => (0..beads)
                .map(|k| {
                    let a = 2.0 * PI * f64::from(k) / f64::from(beads);
                    [major * libm::cos(a), major * libm::sin(a), 0.0]
                })
                .collect(),
            _ => Vec::new(),
        }
    }

    /// Whether the local point `q` lies in the solid, allowing `eps` mm.
    pub fn contains_local(&self, q: V3, eps: f64) -> bool {
        match *self {
            SolidKind::Sphere { radius } => norm(q) <= radius + eps,
            SolidKind::Shell { outer, inner } => {
                let r = norm(q);
                r <= outer + eps && r >= inner - eps
            }
            SolidKind::Torus { major, minor } => circle_distance(q, major) <= minor + eps,
            SolidKind::BeadTorus { minor, .. } => self.bead_centres().iter().any(|c| norm(sub(q, *c)) <= minor + eps),
            _ => self
                .polyhedron()
                .is_some_and(|p| p.planes.iter().all(|(n, d)| dot(*n, q) <= d + eps)),
        }
    }
}

/// -1 for 0, +1 otherwise.
fn sign(bit: u32) -> f64 {
    if bit == 0 {
        -1.0
    } else {
        1.0
    }
}

/// `s` times the unit vector of axis `a`.
fn axis(a: usize, s: f64) -> V3 {
    let mut v = [0.0; 3];
    v[a] = s;
    v
}

impl Solid {
    /// A solid with its local axes along the world's.
    pub fn new(centre: V3, kind: SolidKind) -> Solid {
        Solid {
            centre,
            rotation: IDENTITY,
            kind,
        }
    }

    /// The world point of the local point `q`.
    pub fn to_world(&self, q: V3) -> V3 {
        add(self.centre, mul(&self.rotation, q))
    }

    /// The local point of the world point `p`.
    pub fn to_local(&self, p: V3) -> V3 {
        mul_t(&self.rotation, sub(p, self.centre))
    }

    /// Whether the world point `p` lies in the solid, allowing `eps` mm.
    pub fn contains(&self, p: V3, eps: f64) -> bool {
        self.kind.contains_local(self.to_local(p), eps)
    }
}

impl Region3 {
    /// The region's bounding box: its lowest and highest corners.
    pub fn bounds(&self) -> (V3, V3) {
        match *self {
            Region3::Box { w, h, d } | Region3::BoxMinusBall { w, h, d, .. } => ([0.0; 3], [w, h, d]),
            Region3::Ball { r } => ([0.0; 3], [2.0 * r; 3]),
        }
    }

    /// The centre of the bounding box (and of the ball, when there is one).
    pub fn centre(&self) -> V3 {
        scale(self.bounds().1, 0.5)
    }

    /// Whether `p` lies in the region, allowing `eps` mm.
    pub fn contains(&self, p: V3, eps: f64) -> bool {
        let (lo, hi) = self.bounds();
        let in_box = (0..3).all(|i| p[i] >= lo[i] - eps && p[i] <= hi[i] + eps);
        let from_centre = norm(sub(p, self.centre()));
        match *self {
            Region3::Box { .. } => in_box,
            Region3::Ball { r } => from_centre <= r + eps,
            Region3::BoxMinusBall { r, .. } => in_box && from_centre >= r - eps,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_angle_turns_about_its_axis() {
        let m = axis_angle([0.0, 0.0, 2.0], std::f64::consts::FRAC_PI_2);
        let v = mul(&m, [1.0, 0.0, 0.0]);
        assert!(norm(sub(v, [0.0, 1.0, 0.0])) < 1e-15, "{v:?}");
        assert!(is_rotation(&axis_angle([1.0, -2.0, 0.5], 2.3), 1e-12));
        assert_eq!(axis_angle([0.0; 3], 1.0), axis_angle([1.0, 0.0, 0.0], 0.0));
    }

    fn kinds() -> Vec<SolidKind> {
        vec![
            SolidKind::Cube { half_side: 1.5 },
            SolidKind::Tetrahedron { circumradius: 2.0 },
            SolidKind::Octahedron { circumradius: 2.0 },
        ]
    }

    #[test]
    fn polyhedra_are_outward_and_their_planes_hold_their_vertices() {
        for k in kinds() {
            let p = k.polyhedron().expect("a polyhedron");
            for t in &p.triangles {
                let [a, b, c] = t.map(|i| p.vertices[i as usize]);
                let n = cross(sub(b, a), sub(c, a));
                let centroid = scale(add(add(a, b), c), 1.0 / 3.0);
                assert!(dot(n, centroid) > 0.0, "{k:?}: triangle {t:?} faces inwards");
            }
            for v in &p.vertices {
                assert!(p.planes.iter().all(|(n, d)| dot(*n, *v) <= d + 1e-12), "{k:?}");
                assert!(p.planes.iter().filter(|(n, d)| (dot(*n, *v) - d).abs() < 1e-12).count() >= 3);
                assert!(
                    (norm(*v) - k.bounding_radius()).abs() < 1e-12,
                    "{k:?}: a vertex at the bounding radius"
                );
            }
            assert!(!k.contains_local([k.bounding_radius() * 1.001, 0.0, 0.0], 0.0));
        }
    }

    #[test]
    fn points_in_solids() {
        let s = Solid::new([10.0, 0.0, 0.0], SolidKind::Shell { outer: 2.0, inner: 1.0 });
        assert!(s.contains([11.5, 0.0, 0.0], 0.0));
        assert!(!s.contains([10.5, 0.0, 0.0], 0.0));
        let t = SolidKind::Torus { major: 3.0, minor: 1.0 };
        assert!(t.contains_local([3.9, 0.0, 0.0], 0.0) && !t.contains_local([0.0, 0.0, 0.0], 0.0));
        let b = SolidKind::BeadTorus {
            major: 3.0,
            minor: 1.0,
            beads: 12,
        };
        assert!(b.contains_local([0.0, 3.9, 0.0], 0.0) && !b.contains_local([0.0, 1.9, 0.0], 0.0));
        assert!(is_rotation(&IDENTITY, 0.0));
        assert!(!is_rotation(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]], 1e-9));
    }

    #[test]
    fn regions() {
        let b = Region3::Ball { r: 5.0 };
        assert!(b.contains([5.0, 5.0, 9.9], 0.0) && !b.contains([0.5, 0.5, 0.5], 0.0));
        let m = Region3::BoxMinusBall {
            w: 10.0,
            h: 10.0,
            d: 10.0,
            r: 3.0,
        };
        assert!(m.contains([0.5, 0.5, 0.5], 0.0) && !m.contains([5.0, 5.0, 5.0], 0.0));
    }
}
