//! A digest of noise fields, the same on the host and on the board: value and gradient noise,
//! open and periodic, sampled on a grid, every bit hashed.

use zetafill::digest::Fnv1a;
use zetafill::{Noise, NoiseKind};

/// The FNV-1a hash of the bits of four fields (value and gradient, open and periodic over
/// 100 x 80 mm; seed 11, spacing 17 mm, 5 octaves, gain 0.55) at the 64 x 64 points
/// `(1.7 i - 3, 1.3 j + 0.25)`, or `None` if a field cannot be made.
pub fn noise_digest() -> Option<u64> {
    let mut h = Fnv1a::default();
    for kind in [NoiseKind::Value, NoiseKind::Gradient] {
        for period in [None, Some((100.0, 80.0))] {
            let n = Noise::new(kind, 11, 17.0, 5, 0.55, period).ok()?;
            for i in 0..64u32 {
                for j in 0..64u32 {
                    let (x, y) = (1.7 * f64::from(i) - 3.0, 1.3 * f64::from(j) + 0.25);
                    h.write_u64(n.at(x, y).to_bits());
                }
            }
        }
    }
    Some(h.finish())
}
