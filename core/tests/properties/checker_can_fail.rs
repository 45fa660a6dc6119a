//! The brute-force checker can fail.

use super::*;

fn circle(x: f64, y: f64, r: f64) -> Item {
    Item {
        centre: Point::new(x, y),
        geo: Geo::Circle { c: Point::new(x, y), r },
    }
}

fn square(x: f64, y: f64, half: f64) -> Item {
    let g = ShapeKind::Square.geo(Point::new(x, y), half, 0.0);
    Item {
        centre: Point::new(x, y),
        geo: g,
    }
}

#[test]
fn checker_accepts_valid_sets() {
    let items = [
        circle(10.0, 10.0, 5.0),
        circle(30.0, 10.0, 5.0),
        square(50.0, 50.0, 10.0),
        square(80.0, 20.0, 9.0),
    ];
    assert_eq!(check_fill(&items, 100.0, 100.0, 0.0, false), Ok(()));
    assert_eq!(check_fill(&items, 100.0, 100.0, 0.9, false), Ok(()));
    assert_eq!(check_fill(&items, 100.0, 100.0, 0.0, true), Ok(()));
    // Across the periodic edge but clear of each other's images.
    let wrap = [circle(1.0, 50.0, 3.0), circle(50.0, 50.0, 3.0), circle(50.0, 98.0, 3.0)];
    assert_eq!(check_fill(&wrap, 100.0, 100.0, 0.5, true), Ok(()));
}

#[test]
fn checker_detects_overlapping_circles() {
    let items = [circle(10.0, 10.0, 5.0), circle(19.0, 10.0, 5.0)];
    assert!(check_fill(&items, 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&items, 100.0, 100.0, 0.0, true).is_err());
    // Touching counts as overlapping; a gap too small is detected too.
    assert!(check_fill(&[circle(10.0, 10.0, 5.0), circle(20.0, 10.0, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&[circle(10.0, 10.0, 5.0), circle(20.5, 10.0, 5.0)], 100.0, 100.0, 0.6, false).is_err());
    // A circle inside a square.
    assert!(check_fill(&[square(50.0, 50.0, 10.0), circle(50.0, 50.0, 1.0)], 100.0, 100.0, 0.0, false).is_err());
}

#[test]
fn checker_detects_shape_outside_region() {
    // A square poking out of the right edge by 1e-9.
    let s = square(100.0 - 5.0 + 1e-9, 50.0, 5.0);
    assert!(check_fill(&[s], 100.0, 100.0, 0.0, false).is_err());
    // Just inside is accepted; poking through the gap by 1e-9 is not.
    assert_eq!(check_fill(&[square(95.0, 50.0, 5.0)], 100.0, 100.0, 0.0, false), Ok(()));
    assert!(check_fill(&[square(94.0 + 1e-9, 50.0, 5.0)], 100.0, 100.0, 1.0, false).is_err());
    // Poking out at the bottom and left, and a circle.
    assert!(check_fill(&[square(5.0 - 1e-9, 50.0, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&[square(50.0, 5.0 - 1e-9, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    assert!(check_fill(&[circle(50.0, 100.0 - 5.0 + 1e-9, 5.0)], 100.0, 100.0, 0.0, false).is_err());
    // A rotated square whose corner pokes out.
    let g = ShapeKind::Square.geo(Point::new(94.5, 50.0), 5.0, 0.3);
    assert!(check_fill(
        &[Item {
            centre: Point::new(94.5, 50.0),
            geo: g
        }],
        100.0,
        100.0,
        0.0,
        false
    )
    .is_err());
}

#[test]
fn checker_detects_periodic_violations() {
    // Two circles overlapping only across the x edge (image at +W), and across the corner.
    let across = [circle(2.0, 50.0, 3.0), circle(97.0, 50.0, 3.0)];
    assert!(check_fill(&across, 100.0, 100.0, 0.0, true).is_err());
    let corner = [circle(1.0, 1.0, 2.0), circle(98.5, 98.5, 2.0)];
    assert!(check_fill(&corner, 100.0, 100.0, 0.0, true).is_err());
    let y_edge = [square(50.0, 1.0, 2.0), square(50.5, 98.5, 2.0)];
    assert!(check_fill(&y_edge, 100.0, 100.0, 0.0, true).is_err());
    // A gap violated only across the edge.
    let gap = [circle(3.0, 50.0, 3.0), circle(99.5, 50.0, 0.4)];
    assert_eq!(check_fill(&gap, 100.0, 100.0, 0.05, true), Ok(()));
    assert!(check_fill(&gap, 100.0, 100.0, 0.2, true).is_err());
    // A shape overlapping its own image.
    assert!(check_fill(&[circle(50.0, 50.0, 50.0)], 100.0, 100.0, 0.0, true).is_err());
    assert!(check_fill(&[square(50.0, 50.0, 30.0)], 100.0, 60.0, 0.0, true).is_err());
    // A centre outside the period.
    assert!(check_fill(&[circle(100.0, 50.0, 1.0)], 100.0, 100.0, 0.0, true).is_err());
    assert!(check_fill(&[circle(-1e-12, 50.0, 1.0)], 100.0, 100.0, 0.0, true).is_err());
    // An overlap only with an image two periods away (a long thin diagonal rectangle).
    let r = ShapeKind::Rect { aspect: 40.0 };
    let g = r.geo(Point::new(10.0, 10.0), 0.6, libm::atan2(20.0, 40.0));
    let long = Item {
        centre: Point::new(10.0, 10.0),
        geo: g,
    };
    assert!(check_fill(&[long], 20.0, 20.0, 0.0, true).is_err());
    // A centre that does not match its geometry.
    let mut bad = circle(10.0, 10.0, 1.0);
    bad.centre.x = 11.0;
    assert!(check_fill(&[bad], 100.0, 100.0, 0.0, false).is_err());
}

// ---------------------------------------------------------------------------------------------
