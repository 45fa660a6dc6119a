//! Unit tests of [`super`].

use super::*;
use crate::model::Drawing;

/// A deterministic scatter of circles and segments.
fn scene(n: usize) -> Vec<Path> {
    let mut s = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|k| {
            let (x, y) = (next() * 200.0, next() * 200.0);
            match k % 3 {
                0 => Path::circle([x, y], 0.1 + next() * 3.0),
                1 => Path::polyline(vec![[x, y], [x + next() * 5.0, y + next() * 5.0]], false),
                _ => Path::polyline(vec![[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]], true),
            }
        })
        .collect()
}

fn brute_nearest(items: &[(Pt, f64, u32, u32)], alive: &[bool], q: Pt) -> f64 {
    items
        .iter()
        .zip(alive)
        .filter(|(_, a)| **a)
        .map(|(it, _)| if it.1 > 0.0 { (dist(q, it.0) - it.1).abs() } else { dist(q, it.0) })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn index_agrees_with_brute_force_under_deletion() {
    let paths = scene(600);
    let items: Vec<(Pt, f64, u32, u32)> = paths
        .iter()
        .enumerate()
        .map(|(i, p)| match full_circle(p) {
            Some((c, r)) => (c, r, i as u32, 0),
            None => (p.start_point(), 0.0, i as u32, 0),
        })
        .collect();
    let mut idx = PointIndex::new(&items);
    let mut alive = vec![true; items.len()];
    let mut q = [13.0, 170.0];
    let mut found = Vec::new();
    for step in 0..items.len() {
        let (pos, d) = idx.nearest(q).unwrap_or((usize::MAX, f64::NAN));
        assert_eq!(d, brute_nearest(&items, &alive, q), "step {step}");
        idx.k_nearest(q, 5, &mut found);
        assert_eq!(found.first().map(|f| f.0), Some(d));
        assert!(found.windows(2).all(|w| w[0].0 <= w[1].0));
        let (id, _) = idx.item(pos);
        alive[id as usize] = false;
        idx.remove(pos);
        q = [(q[0] * 1.7 + 31.0) % 200.0, (q[1] * 1.3 + 17.0) % 200.0];
    }
    assert!(idx.is_empty());
    assert!(idx.nearest(q).is_none());
}

#[test]
fn orders_are_permutations_of_the_same_strokes() {
    let paths = scene(900);
    let before = Drawing { paths: paths.clone() }.pen_down_length();
    for mode in [PathOrder::None, PathOrder::Greedy, PathOrder::Improved] {
        let out = order(&paths, [0.0, 0.0], mode);
        assert_eq!(out.len(), paths.len());
        let after = Drawing { paths: out.clone() }.pen_down_length();
        assert!((after - before).abs() < 1e-6 * before, "{mode:?}: pen-down length kept");
        // Every output path is an input path, rotated or reversed.
        for p in &out {
            let b = p.bounds();
            assert!(paths.iter().any(|q| {
                let c = q.bounds();
                (b.x0 - c.x0).abs() < 1e-9 && (b.y1 - c.y1).abs() < 1e-9 && (p.length() - q.length()).abs() < 1e-9
            }));
        }
    }
}

#[test]
fn improved_beats_greedy_beats_none_and_is_deterministic() {
    let paths = scene(3000);
    let home = [0.0, 0.0];
    let t = |m| {
        Drawing {
            paths: order(&paths, home, m),
        }
        .travel_from(home)
    };
    let (none, greedy, improved) = (t(PathOrder::None), t(PathOrder::Greedy), t(PathOrder::Improved));
    assert!(greedy < none / 5.0, "greedy {greedy} vs none {none}");
    assert!(improved < greedy * 0.97, "improved {improved} vs greedy {greedy}");
    assert_eq!(order(&paths, home, PathOrder::Improved), order(&paths, home, PathOrder::Improved));
}

#[test]
fn circle_is_entered_at_its_nearest_point() {
    let paths = vec![Path::circle([10.0, 0.0], 2.0)];
    let out = order(&paths, [0.0, 0.0], PathOrder::Greedy);
    let s = out[0].start_point();
    assert!((s[0] - 8.0).abs() < 1e-12 && s[1].abs() < 1e-12, "{s:?}");
}
