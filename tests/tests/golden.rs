//! Golden digests of the canonical scenes: the exact bits every target must produce.
//!
//! Each digest is FNV-1a 64 over every placed shape's centre, area and angle bits
//! (`zetafill::digest`). A change here means every output of zetafill changed: the RNG, its
//! mapping, libm, the zeta function or the placement rule. That is a version-level event.
//! To re-mint after an intended change, run
//! `cargo test -p zetafill-tests --release --test golden -- --nocapture` and copy the printed
//! values into `GOLDEN`, and say why in the commit. The `circles` digest is pinned in the
//! example of `zetafill::digest` too (`core/src/digest.rs`).
//! What it guards: the coverage bitmap and the spatial hash must never change a result
//! (checked below by running with and without them).

use zetafill_tests::{run_scene, CANONICAL};

const GOLDEN: [(&str, u64, u64); 3] = [
    ("circles", 500, 0x14066bbd95f273d6),
    ("squares", 300, 0x2824ce14c6414935),
    ("rects", 300, 0x17f2482347cc23a3),
];

#[test]
fn canonical_scenes_match_golden_digests() {
    let mut bad = Vec::new();
    for (scene, (name, count, digest)) in CANONICAL.iter().zip(GOLDEN) {
        assert_eq!(scene.name, name);
        let (n, h, _) = run_scene(scene, 1 << 14);
        println!("(\"{}\", {}, 0x{:016x}),", scene.name, n, h);
        if (n, h) != (count, digest) {
            bad.push(format!("{name}: got {n} {h:016x}, golden {count} {digest:016x}"));
        }
    }
    assert!(bad.is_empty(), "digests changed:\n{}", bad.join("\n"));
}

#[test]
fn coverage_bitmap_never_changes_a_result() {
    for scene in &CANONICAL {
        let with = run_scene(scene, 1 << 14);
        let without = run_scene(scene, 0);
        assert_eq!(with.0, without.0, "{}", scene.name);
        assert_eq!(with.1, without.1, "{}", scene.name);
    }
}

/// The digest of `shapes` recomputed here from the scene's area sequence, with bit 0 of shape
/// `flip`'s x flipped when given.
fn recomputed(scene: &zetafill_tests::Scene, shapes: &[zetafill::Placed<f64>], flip: Option<usize>) -> u64 {
    let total = scene.size.0 * scene.size.1;
    let zeta = zetafill::internals::zeta::zeta(scene.c, scene.n).unwrap_or(f64::NAN);
    let mut d = zetafill::digest::Fnv1a::default();
    for (i, p) in shapes.iter().enumerate() {
        let x = if flip == Some(i) { f64::from_bits(p.x.to_bits() ^ 1) } else { p.x };
        let area = total / (zeta * zetafill::internals::scalar::powf(i as f64 + scene.n, scene.c));
        zetafill::digest::add_shape(&mut d, x, p.y, area, p.angle);
    }
    d.finish()
}

/// A flipped bit changes the digest. Its control comes first: the digest recomputed from the
/// same shapes without the flip equals the engine's, so the inequality after the flip is the
/// flip's doing (a recomputation that differed for any other reason would pass blindly).
#[test]
fn digest_detects_a_one_bit_change() {
    for scene in &CANONICAL {
        let (_, h, shapes) = run_scene(scene, 0);
        assert!(shapes.len() > 7, "{}: too few shapes", scene.name);
        assert_eq!(recomputed(scene, &shapes, None), h, "{}: the control", scene.name);
        assert_ne!(recomputed(scene, &shapes, Some(7)), h, "{}", scene.name);
    }
}
