//! The checker can fail: overlapping shapes, shapes closer than the gap, shapes outside each
//! kind of region, periodic images that meet, and malformed shapes are all reported.

use super::checker::{check, clearance, Area, Fill, Mat, Tolerance};

const EXACT: Tolerance = Tolerance { rel: 1e-12, abs: 0.0 };

/// A shape as the checker takes it: its stored centre and its material.
type Shape = ([f64; 2], Mat);

fn disc(x: f64, y: f64, r: f64) -> Shape {
    ([x, y], Mat::Disc { c: [x, y], r })
}

fn ring(x: f64, y: f64, r: f64, inner: f64) -> Shape {
    ([x, y], Mat::Ring { c: [x, y], r, inner })
}

/// A rectangle centred at (x, y), counter-clockwise.
fn rect(x: f64, y: f64, hw: f64, hh: f64) -> Shape {
    (
        [x, y],
        Mat::Poly(vec![[x - hw, y - hh], [x + hw, y - hh], [x + hw, y + hh], [x - hw, y + hh]]),
    )
}

/// A five-pointed star centred at (x, y) (outer radius r, inner r / 2.5).
fn star(x: f64, y: f64, r: f64) -> Shape {
    let v = (0..10)
        .map(|k| {
            let t = std::f64::consts::FRAC_PI_2 + k as f64 * std::f64::consts::PI / 5.0;
            let rr = if k % 2 == 0 { r } else { r / 2.5 };
            [x + rr * t.cos(), y + rr * t.sin()]
        })
        .collect();
    ([x, y], Mat::Poly(v))
}

fn fill(area: Area, gap: f64, shapes: Vec<Shape>) -> Fill {
    Fill { shapes, area, gap }
}

fn square_room() -> Area {
    Area::Rect { w: 100.0, h: 100.0 }
}

#[test]
fn checker_accepts_valid_fills() {
    let shapes = vec![
        disc(10.0, 10.0, 5.0),
        rect(30.0, 10.0, 4.0, 3.0),
        star(60.0, 60.0, 20.0),
        ring(20.0, 70.0, 15.0, 10.0),
        // In the ring's hole, clear of it.
        disc(20.0, 70.0, 9.0),
    ];
    assert_eq!(check(&fill(square_room(), 0.0, shapes.clone()), EXACT), Ok(()));
    assert_eq!(check(&fill(square_room(), 0.9, shapes), EXACT), Ok(()));
}

#[test]
fn checker_finds_overlaps() {
    let cases = [
        ("two discs", vec![disc(10.0, 10.0, 5.0), disc(19.0, 10.0, 5.0)]),
        ("two discs that touch", vec![disc(10.0, 10.0, 5.0), disc(20.0, 10.0, 5.0 + 1e-9)]),
        // A cross: the rectangles' edges cross, neither has a vertex inside the other.
        ("a cross", vec![rect(50.0, 50.0, 20.0, 2.0), rect(50.0, 50.0, 2.0, 20.0)]),
        (
            "a square inside a square",
            vec![rect(50.0, 50.0, 20.0, 20.0), rect(52.0, 50.0, 2.0, 2.0)],
        ),
        ("a disc inside a star", vec![star(50.0, 50.0, 30.0), disc(50.0, 50.0, 1.0)]),
        (
            "a disc in a star's notch",
            vec![star(50.0, 50.0, 30.0), disc(50.0, 50.0 + 12.5, 1.0)],
        ),
        ("a disc on a ring's band", vec![ring(50.0, 50.0, 20.0, 10.0), disc(65.0, 50.0, 2.0)]),
        (
            "a disc too large for a ring's hole",
            vec![ring(50.0, 50.0, 20.0, 10.0), disc(50.0, 50.0, 10.5)],
        ),
        (
            "a square across a ring's band",
            vec![ring(50.0, 50.0, 20.0, 10.0), rect(50.0, 50.0, 12.0, 1.0)],
        ),
        ("a disc covering a ring", vec![ring(50.0, 50.0, 5.0, 2.0), disc(50.0, 51.0, 8.0)]),
        (
            "rings on each other",
            vec![ring(40.0, 50.0, 10.0, 5.0), ring(55.0, 50.0, 10.0, 5.0)],
        ),
        ("stars point into each other", vec![star(30.0, 50.0, 20.0), star(30.0, 73.0, 10.0)]),
    ];
    for (what, shapes) in cases {
        assert!(
            check(&fill(square_room(), 0.0, shapes), EXACT).is_err(),
            "{what}: overlap not found"
        );
    }
    // Apart, then closer than a gap.
    let apart = vec![disc(10.0, 10.0, 5.0), rect(20.0, 10.0, 4.0, 4.0)];
    assert_eq!(check(&fill(square_room(), 0.9, apart.clone()), EXACT), Ok(()));
    assert!(check(&fill(square_room(), 1.1, apart), EXACT).is_err(), "gap not enforced");
    let stars = vec![star(30.0, 50.0, 10.0), star(52.0, 50.0, 10.0)];
    let d = clearance(&stars[0].1, &stars[1].1);
    assert!(d > 0.0 && d < 3.0, "{d}");
    assert_eq!(check(&fill(square_room(), d * 0.99, stars.clone()), EXACT), Ok(()));
    assert!(
        check(&fill(square_room(), d * 1.01, stars), EXACT).is_err(),
        "gap between stars not enforced"
    );
    let nested = vec![ring(50.0, 50.0, 20.0, 10.0), disc(51.0, 50.0, 8.0)];
    assert_eq!(check(&fill(square_room(), 0.9, nested.clone()), EXACT), Ok(()));
    assert!(
        check(&fill(square_room(), 1.1, nested), EXACT).is_err(),
        "gap in a ring's hole not enforced"
    );
}

#[test]
fn checker_finds_shapes_outside_the_region() {
    let cases: Vec<(&str, Area, Shape)> = vec![
        ("rect: a disc over the right edge", square_room(), disc(96.0, 50.0, 4.0 + 1e-9)),
        ("rect: a star over the top", square_room(), star(50.0, 95.0, 6.0)),
        ("rect: wholly outside", square_room(), rect(150.0, 50.0, 5.0, 5.0)),
        (
            "disc: a square's corner out",
            Area::Disc { r: 50.0 },
            rect(50.0 + 33.0, 50.0 + 33.0, 3.0, 3.0),
        ),
        (
            "annulus: a disc in the hole",
            Area::Annulus { outer: 50.0, inner: 20.0 },
            disc(50.0, 50.0, 5.0),
        ),
        (
            "annulus: a square over the hole",
            Area::Annulus { outer: 50.0, inner: 20.0 },
            rect(50.0, 50.0, 25.0, 25.0),
        ),
        (
            "annulus: a ring around the hole, too tight",
            Area::Annulus { outer: 50.0, inner: 20.0 },
            ring(50.0, 50.0, 30.0, 19.0),
        ),
        ("polygon: in the hole", with_hole(), disc(50.0, 50.0, 2.0)),
        ("polygon: over the hole's edge", with_hole(), rect(40.0, 50.0, 2.0, 2.0)),
        ("polygon: a square holding the hole", with_hole(), rect(50.0, 50.0, 20.0, 20.0)),
        ("polygon: outside it all", with_hole(), disc(150.0, 50.0, 2.0)),
        ("polygon: across the outline", with_hole(), star(98.0, 50.0, 5.0)),
    ];
    for (what, area, shape) in cases {
        assert!(check(&fill(area, 0.0, vec![shape]), EXACT).is_err(), "{what}: not reported");
    }
    // Inside, and inside with the gap; then the gap is too large.
    let ok: Vec<(Area, Shape)> = vec![
        (square_room(), disc(95.0, 50.0, 4.0)),
        (Area::Disc { r: 50.0 }, rect(50.0, 50.0, 30.0, 30.0)),
        (Area::Annulus { outer: 50.0, inner: 20.0 }, disc(50.0, 50.0 + 35.0, 10.0)),
        (Area::Annulus { outer: 50.0, inner: 20.0 }, ring(50.0, 50.0, 45.0, 25.0)),
        (with_hole(), star(30.0, 30.0, 10.0)),
        (with_hole(), ring(50.0, 50.0, 45.0, 16.0)),
    ];
    for (area, shape) in ok {
        assert_eq!(
            check(&fill(area.clone(), 0.5, vec![shape.clone()]), EXACT),
            Ok(()),
            "{area:?} {shape:?}"
        );
        assert!(
            check(&fill(area.clone(), 8.0, vec![shape.clone()]), EXACT).is_err(),
            "{area:?} {shape:?}: gap"
        );
    }
}

/// A 100 x 100 square with a 20 x 20 hole in its middle.
fn with_hole() -> Area {
    Area::Polygon(vec![
        vec![[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]],
        vec![[40.0, 40.0], [40.0, 60.0], [60.0, 60.0], [60.0, 40.0]],
    ])
}

#[test]
fn checker_finds_periodic_violations() {
    let torus = || Area::Torus { w: 100.0, h: 100.0 };
    assert_eq!(
        check(&fill(torus(), 0.0, vec![disc(2.0, 50.0, 3.0), disc(50.0, 50.0, 3.0)]), EXACT),
        Ok(())
    );
    let cases = [
        ("across the x edge", vec![disc(2.0, 50.0, 3.0), disc(97.0, 50.0, 3.0)]),
        ("across a corner", vec![rect(1.0, 1.0, 2.0, 2.0), disc(98.5, 98.5, 2.0)]),
        ("its own image", vec![disc(50.0, 50.0, 50.5)]),
        ("a long bar and its own image", vec![rect(50.0, 50.0, 50.5, 1.0)]),
        ("a centre outside the period", vec![disc(100.0, 50.0, 1.0)]),
        ("a negative centre", vec![disc(-1e-9, 50.0, 1.0)]),
    ];
    for (what, shapes) in cases {
        assert!(check(&fill(torus(), 0.0, shapes), EXACT).is_err(), "{what}: not reported");
    }
    // A gap broken only across the edge.
    let near = vec![disc(3.0, 50.0, 3.0), disc(99.5, 50.0, 0.4)];
    assert_eq!(check(&fill(torus(), 0.05, near.clone()), EXACT), Ok(()));
    assert!(check(&fill(torus(), 0.2, near), EXACT).is_err());
}

#[test]
fn checker_finds_malformed_shapes() {
    let cases = [
        disc(10.0, 10.0, f64::NAN),
        disc(10.0, 10.0, 0.0),
        ring(10.0, 10.0, 5.0, 5.0),
        ring(10.0, 10.0, 5.0, -1.0),
        ([10.0, 10.0], Mat::Poly(vec![[9.0, 9.0], [11.0, 9.0]])),
        // Clockwise.
        ([10.0, 10.0], Mat::Poly(vec![[9.0, 9.0], [9.0, 11.0], [11.0, 11.0], [11.0, 9.0]])),
    ];
    for shape in cases {
        assert!(check(&fill(square_room(), 0.0, vec![shape.clone()]), EXACT).is_err(), "{shape:?}");
    }
}
