//! Unit tests of [`super`].

use super::*;
use std::f64::consts::PI;

#[test]
fn arcs_end_exactly_on_the_edges_they_cross() {
    let (w, h) = (100.0, 80.0);
    let mut out = Vec::new();
    // A disc over the top-left corner, one over the bottom edge, one inside.
    disc_pieces([3.0, 78.0], 6.0, w, h, Style::Outline, &mut out);
    disc_pieces([50.0, 1.0], 4.0, w, h, Style::Outline, &mut out);
    disc_pieces([50.0, 40.0], 4.0, w, h, Style::Outline, &mut out);
    assert_eq!(out.iter().filter(|p| matches!(p, Path::Arc { .. })).count(), 1);
    let e = ends(&out, w, h);
    assert_eq!((e.bottom.len(), e.top.len(), e.left.len(), e.right.len()), (2, 1, 1, 0));
    assert!((e.bottom[0] - (50.0 - 15f64.sqrt())).abs() < 1e-12);
    assert!((e.top[0] - (3.0 + 32f64.sqrt())).abs() < 1e-12);
    assert!((e.left[0] - (78.0 - 27f64.sqrt())).abs() < 1e-12);
}

#[test]
fn filled_discs_are_cut_to_the_tile() {
    let (w, h) = (100.0, 80.0);
    let mut out = Vec::new();
    disc_pieces([50.0, 0.0], 4.0, w, h, Style::Filled, &mut out);
    let Some(Path::Polyline {
        points: poly,
        closed: true,
    }) = out.first()
    else {
        panic!("{out:?}")
    };
    assert!(poly.iter().all(|p| p[1] >= 0.0 && libm::hypot(p[0] - 50.0, p[1]) <= 4.0 + 1e-12));
    // Half a disc: its area within the chords' error.
    let area: f64 = 0.5
        * (0..poly.len())
            .map(|i| {
                let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f64>();
    assert!((area - 8.0 * PI).abs() < 0.02, "{area}");
    // A disc that misses the tile near a corner draws nothing; one that holds it, all.
    out.clear();
    disc_pieces([-3.0, -3.0], 4.0, w, h, Style::Filled, &mut out);
    assert!(out.is_empty(), "{out:?}");
    disc_pieces([50.0, 40.0], 70.0, w, h, Style::Filled, &mut out);
    assert_eq!(out, [Path::polyline(vec![[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]], true)]);
}

#[test]
fn seam_gaps_compare_the_top_halves_with_the_bottom_at_half_scale() {
    let good = Ends {
        bottom: vec![20.0, 60.0],
        top: vec![10.0, 30.0, 60.0, 80.0],
        left: vec![5.0],
        right: vec![5.0],
    };
    assert_eq!(seam_gaps(&good, 100.0), 0.0);
    let shifted = Ends {
        top: vec![10.0, 30.0, 60.0, 80.5],
        ..good.clone()
    };
    assert_eq!(seam_gaps(&shifted, 100.0), 0.5);
    let missing = Ends { right: vec![], ..good };
    assert_eq!(seam_gaps(&missing, 100.0), f64::INFINITY);
}
