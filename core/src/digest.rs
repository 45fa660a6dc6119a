//! The determinism digest: FNV-1a 64 over, for every placed shape in order, the little-endian
//! bytes of the bits of its centre x, centre y, nominal area and rotation angle (0 when
//! unrotated), with `-0.0` written as `0.0` (a fixed-point scalar contributes its raw bits).
//! Two runs agree bit for bit exactly when their digests and counts agree (up to FNV
//! collisions). The host, the CLI (`--format digest`) and the firmware compute the same value.
//!
//! # Examples
//!
//! The digest of a run, twice the same: here the canonical `circles` scene (500 circles at
//! c = 1.3, N = 1 in a 200 x 200 rectangle, seed 1), whose digest the golden test and the
//! firmware check too. Another seed gives another fill.
//!
//! ```
//! use zetafill::digest::engine_digest;
//! use zetafill::{index_words, rng_from_seed, Engine, Params, Placed, Region, Stop, Storage};
//!
//! fn digest(seed: u64) -> (u64, u64) {
//!     let mut shapes = vec![Placed::<f64>::default(); 500];
//!     let mut index = vec![0u32; index_words(500)];
//!     let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
//!     let region = Region::Rect { width: 200.0, height: 200.0, periodic: false };
//!     let mut engine = Engine::new(Params::circles(1.3, 1.0), region, storage).expect("valid");
//!     engine.run(&mut rng_from_seed(seed), &Stop { count: Some(500), ..Stop::default() }, |_| {});
//!     engine_digest(&engine)
//! }
//! assert_eq!(digest(1), (500, 0x1406_6bbd_95f2_73d6));
//! assert_eq!(digest(1), digest(1));
//! assert_ne!(digest(2).1, digest(1).1);
//! ```

use crate::engine::Engine;
use crate::scalar::Scalar;

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

/// An FNV-1a 64 hasher.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fnv1a(u64);

impl Default for Fnv1a {
    fn default() -> Self {
        Fnv1a(FNV_OFFSET)
    }
}

impl Fnv1a {
    /// Adds bytes.
    pub fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(FNV_PRIME);
        }
    }

    /// Adds a `u64` as little-endian bytes.
    pub fn write_u64(&mut self, v: u64) {
        self.write(&v.to_le_bytes());
    }

    /// The hash so far.
    pub fn finish(&self) -> u64 {
        self.0
    }
}

/// Adds one shape (centre, nominal area, angle) to a digest.
pub fn add_shape<S: Scalar>(h: &mut Fnv1a, x: S, y: S, area: f64, angle: S) {
    h.write_u64(x.digest_bits());
    h.write_u64(y.digest_bits());
    h.write_u64(area.digest_bits());
    h.write_u64(angle.digest_bits());
}

/// The digest of every shape an engine has placed: `(count, hash)` (see the module's example).
pub fn engine_digest<S: Scalar>(e: &Engine<'_, S>) -> (u64, u64) {
    let mut h = Fnv1a::default();
    for (i, p) in e.placed().iter().enumerate() {
        add_shape(&mut h, p.x, p.y, e.area_of(i as u64), p.angle);
    }
    (e.placed().len() as u64, h.finish())
}

/// The digest of a 3D fill: FNV-1a 64 over, for every placed solid in order, the bits of its
/// centre x, y, z, its nominal volume V_i and its rotation `[w, x, y, z]`, `-0.0` written as
/// `0.0`. Returns `(count, hash)`.
///
/// # Examples
///
/// ```
/// use zetafill::digest::space_digest;
/// use zetafill::{rng_from_seed, Stop};
/// use zetafill::space::{index_words, Engine, Params, Placed, Region, Storage};
///
/// fn digest(seed: u64) -> (u64, u64) {
///     let mut solids = vec![Placed::<f64>::default(); 50];
///     let mut index = vec![0u32; index_words(50)];
///     let storage = Storage { solids: &mut solids, index: &mut index };
///     let region = Region::Box { width: 10.0, height: 10.0, depth: 10.0, periodic: false };
///     let mut engine = Engine::new(Params::spheres(1.15, 1.0), region, storage).expect("valid");
///     engine.run(&mut rng_from_seed(seed), &Stop { count: Some(50), ..Stop::default() }, |_| {});
///     space_digest(&engine)
/// }
/// assert_eq!(digest(1), digest(1));
/// assert_ne!(digest(1).1, digest(2).1);
/// ```
pub fn space_digest<S: Scalar>(e: &crate::space3d::SpaceEngine<'_, S>) -> (u64, u64) {
    let mut h = Fnv1a::default();
    for (i, p) in e.placed().iter().enumerate() {
        for v in [p.x, p.y, p.z] {
            h.write_u64(v.digest_bits());
        }
        h.write_u64(e.volume_of(i as u64).digest_bits());
        for v in p.rotation {
            h.write_u64(v.digest_bits());
        }
    }
    (e.placed().len() as u64, h.finish())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_matches_published_vectors() {
        let mut h = Fnv1a::default();
        assert_eq!(h.finish(), 0xcbf29ce484222325);
        h.write(b"a");
        assert_eq!(h.finish(), 0xaf63dc4c8601ec8c);
        let mut h = Fnv1a::default();
        h.write(b"foobar");
        assert_eq!(h.finish(), 0x85944171f73967e8);
    }
}
