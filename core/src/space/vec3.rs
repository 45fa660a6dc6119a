//! Points in space, rotations, and the fixed mapping from random bits to a uniform rotation.
//!
//! A rotation is a unit quaternion `(w, x, y, z)` drawn with Shoemake's method ("Uniform random
//! rotations", Graphics Gems III): three unit values `u1, u2, u3` (each one `next_u64()`, mapped
//! as every unit value of the crate, see [`crate::internals::rng`]) give
//! `w = sqrt(1 - u1) sin(2 pi u2)`, `x = sqrt(1 - u1) cos(2 pi u2)`, `y = sqrt(u1) sin(2 pi u3)`,
//! `z = sqrt(u1) cos(2 pi u3)`, a quaternion uniform on the unit 3-sphere and so a rotation
//! uniform (Haar) in SO(3). The identity is `(1, 0, 0, 0)`.

use crate::rng;
use crate::scalar::Scalar;
use rand_core::RngCore;

/// A point (or vector) in space, in the region's frame.
///
/// # Examples
///
/// ```
/// use zetafill::internals::space::V3;
///
/// let (a, b) = (V3::new(1.0, 2.0, 2.0), V3::new(0.0, 0.0, 0.0));
/// assert_eq!(a.sub(b).norm2(), 9.0);
/// assert_eq!(V3::new(1.0, 0.0, 0.0).cross(V3::new(0.0, 1.0, 0.0)), V3::new(0.0, 0.0, 1.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct V3<S> {
    /// x coordinate.
    pub x: S,
    /// y coordinate.
    pub y: S,
    /// z coordinate.
    pub z: S,
}

#[allow(clippy::should_implement_trait)]
impl<S: Scalar> V3<S> {
    /// A point from its coordinates.
    #[inline]
    pub fn new(x: S, y: S, z: S) -> Self {
        V3 { x, y, z }
    }
    /// A point from `f64` coordinates.
    #[inline]
    pub fn from_f64(x: f64, y: f64, z: f64) -> Self {
        V3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z))
    }
    /// `self + o`.
    #[inline]
    pub fn add(self, o: Self) -> Self {
        V3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
    /// `self - o`.
    #[inline]
    pub fn sub(self, o: Self) -> Self {
        V3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
    /// `self * k`.
    #[inline]
    pub fn scale(self, k: S) -> Self {
        V3::new(self.x * k, self.y * k, self.z * k)
    }
    /// Dot product.
    #[inline]
    pub fn dot(self, o: Self) -> S {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    /// Cross product.
    #[inline]
    pub fn cross(self, o: Self) -> Self {
        V3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
    /// Squared length.
    #[inline]
    pub fn norm2(self) -> S {
        self.dot(self)
    }
    /// Squared length rounded up (never below the exact value; see [`Scalar::dist2_up`]).
    #[inline]
    pub fn norm2_up(self) -> S {
        S::dist2_up(self.x, self.y) + S::dist2_up(self.z, S::ZERO)
    }
}

/// A unit quaternion `[w, x, y, z]`: the rotation of a placed solid.
pub type Quat<S> = [S; 4];

/// The identity rotation.
pub fn identity<S: Scalar>() -> Quat<S> {
    [S::ONE, S::ZERO, S::ZERO, S::ZERO]
}

/// A uniformly random rotation from the next three unit values (Shoemake; see the module).
pub fn random_rotation<S: Scalar, R: RngCore + ?Sized>(rng: &mut R) -> Quat<S> {
    let u1: S = rng::unit(rng);
    let a2: S = rng::angle(rng);
    let a3: S = rng::angle(rng);
    let (s1, s2) = ((S::ONE - u1).sqrt(), u1.sqrt());
    let (sin2, cos2) = a2.sin_cos();
    let (sin3, cos3) = a3.sin_cos();
    [s1 * sin2, s1 * cos2, s2 * sin3, s2 * cos3]
}

/// The rotation matrix of a unit quaternion, as its three columns (the images of the x, y and
/// z axes).
pub fn columns<S: Scalar>(q: &Quat<S>) -> [V3<S>; 3] {
    let [w, x, y, z] = *q;
    let two = S::ONE + S::ONE;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let (xy, xz, yz, wx, wy, wz) = (x * y, x * z, y * z, w * x, w * y, w * z);
    [
        V3::new(S::ONE - two * (yy + zz), two * (xy + wz), two * (xz - wy)),
        V3::new(two * (xy - wz), S::ONE - two * (xx + zz), two * (yz + wx)),
        V3::new(two * (xz + wy), two * (yz - wx), S::ONE - two * (xx + yy)),
    ]
}

/// `m v` for a matrix given by its columns.
#[inline]
pub fn apply<S: Scalar>(m: &[V3<S>; 3], v: V3<S>) -> V3<S> {
    m[0].scale(v.x).add(m[1].scale(v.y)).add(m[2].scale(v.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn random_rotations_are_orthonormal() {
        let mut r = crate::rng_from_seed(5);
        for _ in 0..100 {
            let q: Quat<f64> = random_rotation(&mut r);
            let n: f64 = q.iter().map(|v| v * v).sum();
            assert!((n - 1.0).abs() < 1e-12);
            let m = columns(&q);
            for i in 0..3 {
                for j in 0..3 {
                    let d = m[i].dot(m[j]);
                    assert!((d - if i == j { 1.0 } else { 0.0 }).abs() < 1e-12);
                }
            }
            // Right-handed.
            assert!((m[0].cross(m[1]).dot(m[2]) - 1.0).abs() < 1e-12);
        }
    }
}
