//! The outlines of blobs at scale 1 about the origin: the blob of eq. 9 of Shier and Bourke's
//! "An Algorithm for Random Fractal Filling of Space", whose phases come from the trial's
//! angle, and the noisy blob, whose radius follows periodic 1D noise drawn anew from the
//! angle. Both are polygons of [`BLOB_VERTICES`] vertices at equal angles, tested and drawn
//! alike, and come with twice their area, so that a scale can be chosen that gives exactly
//! the area asked for.

use super::{mix64, rot, BLOB_VERTICES};
use crate::geom::Point;
#[cfg(feature = "noisy-blob")]
use crate::noise::{Noise, NoiseKind};
use crate::scalar::Scalar;

/// The blob of eq. 9 at scale 1 about the origin for `angle` (which selects the phases), and
/// twice its area.
pub(super) fn blob_unit<S: Scalar>(delta: f64, angle: S) -> ([Point<S>; BLOB_VERTICES], S) {
    let tau = S::from_f64(core::f64::consts::TAU);
    let d = S::from_f64(delta);
    let key = angle.digest_bits();
    // Phases φ_2..φ_4 from the angle's bits (angle is uniform per trial, so the phases are new
    // random values at every trial), and e^{i(jθ_k + φ_j)} advanced by e^{ijΔ} per vertex.
    let mut z = [Point::default(); 4];
    let mut step = [Point::default(); 4];
    let dtheta = tau / S::from_f64(BLOB_VERTICES as f64);
    for (j, (zj, sj)) in z.iter_mut().zip(step.iter_mut()).enumerate() {
        let phase = if j == 0 {
            S::ZERO
        } else {
            S::unit(mix64(key ^ (j as u64).wrapping_mul(0xA076_1D64_78BD_642F))) * tau
        };
        let (s, c) = phase.sin_cos();
        *zj = Point::new(c, s);
        let (s, c) = (dtheta * S::from_f64((j + 1) as f64)).sin_cos();
        *sj = Point::new(c, s);
    }
    let mut out = [Point::default(); BLOB_VERTICES];
    for o in out.iter_mut() {
        let (z1, z2, z3, z4) = (z[0], z[1], z[2], z[3]);
        let r = S::ONE + d * (z2.x + z3.x + z4.x);
        *o = Point::new(z1.x * r, z1.y * r);
        for (zj, sj) in z.iter_mut().zip(step.iter()) {
            *zj = rot(*zj, sj.y, sj.x);
        }
    }
    let a2 = crate::geom::edges(&out).fold(S::ZERO, |s, (a, b)| s + a.cross(b));
    (out, a2)
}

/// The noisy blob at scale 1 about the origin for `angle`, and twice its area: vertex `k` at
/// angle `2 pi k / n` and radius `1 + amplitude (2 g(k features / n) - 1)`, where `g` is Perlin
/// gradient noise in `[0, 1]` with `octaves` octaves (each of half the spacing and half the
/// weight of the one before), periodic over `features` lattice cells, so the outline closes
/// smoothly. The angle's bits choose the noise's seed and the row of the plane it is read
/// along (away from the lattice rows, where gradient noise is 0), so every trial draws a new
/// outline; the radii stay within `1 +- amplitude`.
#[cfg(feature = "noisy-blob")]
pub(super) fn noisy_unit<S: Scalar>(amplitude: f64, features: u8, octaves: u8, angle: S) -> ([Point<S>; BLOB_VERTICES], S) {
    let key = angle.digest_bits();
    let seed = mix64(key ^ 0x6E6F_6973_7962_6C6F);
    let row = 0.25 + 0.5 * ((mix64(key ^ 0x726F_7773_6F66_6E6F) >> 11) as f64 / (1u64 << 53) as f64);
    let cells = f64::from(features.max(1));
    let noise = Noise::new(NoiseKind::Gradient, seed, 1.0, u32::from(octaves), 0.5, Some((cells, 1.0))).ok();
    let n = BLOB_VERTICES as f64;
    let (s, c) = (S::from_f64(core::f64::consts::TAU) / S::from_f64(n)).sin_cos();
    let mut dir = Point::new(S::ONE, S::ZERO);
    let mut out = [Point::default(); BLOB_VERTICES];
    for (k, o) in out.iter_mut().enumerate() {
        let g = noise.as_ref().map_or(0.5, |noise| noise.at(cells * k as f64 / n, row));
        let r = S::from_f64(1.0 + amplitude * (2.0 * g - 1.0));
        *o = Point::new(dir.x * r, dir.y * r);
        dir = rot(dir, s, c);
    }
    let a2 = crate::geom::edges(&out).fold(S::ZERO, |s, (a, b)| s + a.cross(b));
    (out, a2)
}

/// Without the `noisy-blob` feature a noisy blob is never valid, so no engine draws one, and
/// the noise is left out of the build: a point stands in.
#[cfg(not(feature = "noisy-blob"))]
pub(super) fn noisy_unit<S: Scalar>(_: f64, _: u8, _: u8, _: S) -> ([Point<S>; BLOB_VERTICES], S) {
    ([Point::default(); BLOB_VERTICES], S::ZERO)
}

#[cfg(all(test, feature = "noisy-blob"))]
mod tests {
    use super::*;
    use crate::shape::ShapeKind;

    /// Whether every vertex of `v` lies within `1 +- a` of the origin, and every point of every
    /// edge at least `inner` from it.
    fn within(v: &[Point<f64>], a: f64, inner: f64) -> bool {
        let radii = v.iter().all(|p| {
            let r = libm::sqrt(p.x * p.x + p.y * p.y);
            r >= 1.0 - a - 1e-12 && r <= 1.0 + a + 1e-12
        });
        let edges = crate::geom::edges(v).all(|(p, q)| {
            // The nearest point of the edge to the origin.
            let (dx, dy) = (q.x - p.x, q.y - p.y);
            let t = (-(p.x * dx + p.y * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
            let (x, y) = (p.x + t * dx, p.y + t * dy);
            libm::sqrt(x * x + y * y) >= inner
        });
        radii && edges
    }

    #[test]
    fn noisy_outlines_keep_their_bounds_and_their_area() {
        let n = BLOB_VERTICES as f64;
        for (a, features, octaves) in [(0.0, 5, 2), (0.35, 5, 2), (0.9, 2, 1), (0.6, 8, 2), (0.2, 4, 3), (0.5, 16, 1)] {
            let kind = ShapeKind::Noisy {
                amplitude: a,
                features,
                octaves,
            };
            assert!(kind.is_valid(), "{kind:?}");
            // Outlines that differ from the one before.
            let (mut changes, mut last) = (0, None);
            for k in 0..400u32 {
                let angle = f64::from(k) * 0.015_707_963 + 0.001;
                let (v, a2) = noisy_unit::<f64>(a, features, octaves, angle);
                assert!(within(&v, a, kind.inradius(1.0)), "{kind:?} at {angle}");
                // The engine's bound of the area over every outline.
                assert!(a2 <= n * libm::sin(core::f64::consts::TAU / n) * (1.0 + a) * (1.0 + a), "{kind:?}");
                // Drawn anew from the angle, and the same again for the same angle.
                assert_eq!(noisy_unit::<f64>(a, features, octaves, angle).0, v);
                changes += usize::from(last.is_some_and(|l| l != v));
                last = Some(v);
                // The scale for an area gives that area exactly, as drawn.
                let area = 12.5 + f64::from(k);
                let s = kind.scale_for(area, angle);
                let g = kind.geo(Point::new(3.0, -2.0), s, angle);
                assert!((g.poly_area2() / 2.0 - area).abs() < 1e-12 * area, "{kind:?}");
            }
            // Amplitude 0 is the regular polygon, whatever the noise.
            assert_eq!(changes, if a == 0.0 { 0 } else { 399 }, "{kind:?}");
        }
        // The check can fail: radii that vary, held to 1; the disc of radius 1 taken as
        // inscribed; a vertex pushed out past 1 + a.
        let (mut v, _) = noisy_unit::<f64>(0.3, 5, 2, 0.7);
        let kind = ShapeKind::Noisy {
            amplitude: 0.3,
            features: 5,
            octaves: 2,
        };
        assert!(within(&v, 0.3, kind.inradius(1.0)));
        assert!(!within(&v, 0.0, 0.0) && !within(&v, 0.3, 1.0));
        v[3] = Point::new(
            v[3].x * 1.4 / libm::sqrt(v[3].x * v[3].x + v[3].y * v[3].y),
            v[3].y * 1.4 / libm::sqrt(v[3].x * v[3].x + v[3].y * v[3].y),
        );
        assert!(!within(&v, 0.3, kind.inradius(1.0)));
    }

    #[test]
    fn noisy_shapes_are_checked() {
        let ok = |a: f64, features: u8, octaves: u8| {
            ShapeKind::Noisy {
                amplitude: a,
                features,
                octaves,
            }
            .is_valid()
        };
        assert!(ok(0.9, 16, 1) && ok(0.0, 2, 4) && ok(0.3, 4, 3));
        assert!(!ok(0.91, 5, 2) && !ok(-0.1, 5, 2) && !ok(f64::NAN, 5, 2));
        assert!(!ok(0.3, 1, 1) && !ok(0.3, 17, 1) && !ok(0.3, 5, 0) && !ok(0.3, 5, 5) && !ok(0.3, 9, 2));
    }
}
