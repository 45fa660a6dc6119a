//! The clearance tests of two bodies, and the bead window against every bead.

use super::super::vec3::identity;
use super::*;

fn body(kind: Solid, x: f64, y: f64, z: f64, s: f64) -> Body<f64> {
    Body::new(&kind, V3::new(x, y, z), s, &identity())
}

#[test]
fn touching_counts_as_overlap() {
    let (a, b) = (body(Solid::Cube, 0.0, 0.0, 0.0, 1.0), body(Solid::Cube, 2.0, 0.0, 0.0, 1.0));
    assert!(!apart(&a, &b, 0.0));
    let c = body(Solid::Cube, 2.5, 0.0, 0.0, 1.0);
    assert!(apart(&a, &c, 0.0) && apart(&a, &c, 0.49) && !apart(&a, &c, 0.5));
    // Corner to corner along the diagonal: distance sqrt(3) * 0.5.
    let d = body(Solid::Cube, 2.5, 2.5, 2.5, 1.0);
    let g = 0.5 * 3f64.sqrt();
    assert!(apart(&a, &d, g - 1e-9) && !apart(&a, &d, g + 1e-9));
    let s = body(Solid::Sphere, 2.0, 0.0, 0.0, 1.0);
    assert!(!apart(&a, &s, 0.0) && apart(&a, &s, -0.0) == apart(&s, &a, 0.0));
}

#[test]
fn shells_hold_solids() {
    let shell = body(Solid::Shell { inner: 0.6 }, 0.0, 0.0, 0.0, 10.0);
    let inside = body(Solid::Cube, 0.0, 0.0, 0.0, 3.0);
    assert!(apart(&shell, &inside, 0.0) && apart(&inside, &shell, 0.5));
    assert!(!apart(&shell, &inside, 0.9));
    let big = body(Solid::Cube, 0.0, 0.0, 0.0, 4.0);
    assert!(!apart(&shell, &big, 0.0));
}

/// Pairs of tori (and a torus with a ball) around contact, at random rotations, sizes and
/// tube ratios, some centred near each other's axis, in either scalar.
fn disagreements<S: Scalar, W: Fn(&Body<S>, V3<S>, S) -> (usize, usize)>(window: &W, pairs: usize) -> usize {
    use crate::space3d::vec3::random_rotation;
    let mut rng = crate::rng_from_seed(11);
    let mut unit = || crate::rng::unit::<f64, _>(&mut rng);
    let mut bad = 0;
    for i in 0..pairs {
        let ratio = [0.2, 0.25, 0.3, 0.5, 0.9][i % 5];
        let kind = Solid::Torus { ratio };
        let (s1, s2) = (1.0 + 9.0 * unit(), 0.2 + 9.0 * unit());
        let mut r2 = crate::rng_from_seed(i as u64);
        let (q1, q2): (Quat<S>, Quat<S>) = (random_rotation(&mut r2), random_rotation(&mut r2));
        let a = Body::new(&kind, V3::from_f64(50.0, 50.0, 50.0), S::from_f64(s1), &q1);
        // Along a random direction, or along a's axis (where every bead is as near).
        let axis = i % 7 == 0;
        let dir = if axis {
            columns(&q1)[2]
        } else {
            let (x, y, z) = (unit() - 0.5, unit() - 0.5, unit() - 0.5);
            let l = libm::sqrt(x * x + y * y + z * z).max(1e-9);
            V3::from_f64(x / l, y / l, z / l)
        };
        let d = (s1 + s2) * (1.0 + ratio) * unit() * 1.2;
        let c2 = V3::from_f64(50.0, 50.0, 50.0).add(dir.scale(S::from_f64(d)));
        let other = if i % 3 == 0 {
            Solid::Sphere
        } else {
            Solid::Torus { ratio: [0.25, 0.6][i % 2] }
        };
        let b = Body::new(&other, c2, S::from_f64(s2), &q2);
        let gap = S::from_f64([0.0, 0.05, 0.5][i % 3]);
        let every = |t: &Body<S>, _: V3<S>, _: S| (0, t.beads().len());
        let want = apart_by(&a, &b, gap, &every);
        if apart_by(&a, &b, gap, window) != want || apart_by(&b, &a, gap, window) != want {
            bad += 1;
        }
    }
    bad
}

#[test]
fn nearest_beads_answer_as_every_bead_does() {
    assert_eq!(disagreements(&near_beads::<f64>, 20_000), 0);
    assert_eq!(disagreements(&near_beads::<crate::Fixed>, 5_000), 0);
    // The comparison can fail: without its bead of margin at either end, the run misses
    // the only contacts of a few pairs (5 of these 20,000); one bead misses many.
    let short = |t: &Body<f64>, p: V3<f64>, r: f64| {
        let (first, count) = near_beads(t, p, r);
        (first + 1, count.saturating_sub(2))
    };
    assert!(disagreements(&short, 20_000) > 0);
    let one = |t: &Body<f64>, p: V3<f64>, r: f64| (near_beads(t, p, r).0, 1);
    assert!(disagreements(&one, 20_000) > 1_000);
}

#[test]
fn beads_chain_link() {
    // Two tori linked like a chain: one in the xy plane, the other in the xz plane
    // through its hole.
    let q = [0.5f64.sqrt(), 0.5f64.sqrt(), 0.0, 0.0]; // 90 degrees about x
    let a = Body::new(&Solid::Torus { ratio: 0.25 }, V3::new(0.0, 0.0, 0.0), 4.0, &identity());
    let b = Body::new(&Solid::Torus { ratio: 0.25 }, V3::new(4.0, 0.0, 0.0), 4.0, &q);
    assert!(apart(&a, &b, 0.0));
    let c = Body::new(&Solid::Torus { ratio: 0.25 }, V3::new(3.0, 0.0, 0.0), 4.0, &identity());
    assert!(!apart(&a, &c, 0.0));
}
