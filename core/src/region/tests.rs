use super::*;

fn pts(v: &[(f64, f64)]) -> [Point<f64>; 8] {
    let mut out = [Point::default(); 8];
    for (o, &(x, y)) in out.iter_mut().zip(v) {
        *o = Point::new(x, y);
    }
    out
}

#[test]
fn square_with_square_hole_has_the_right_area_and_inside() {
    let p = pts(&[
        (0.0, 0.0),
        (10.0, 0.0),
        (10.0, 10.0),
        (0.0, 10.0),
        (4.0, 4.0),
        (4.0, 6.0),
        (6.0, 6.0),
        (6.0, 4.0),
    ]);
    let ends = [4, 8];
    let r = PolygonRegion::new(&p, &ends).map(Region::Polygon);
    let Ok(r) = r else { panic!("valid region rejected") };
    assert_eq!(r.area(), 96.0);
    assert!(r.point_inside(Point::new(1.0, 1.0)));
    assert!(!r.point_inside(Point::new(5.0, 5.0)));
    let small = Geo::Circle {
        c: Point::new(2.0, 2.0),
        r: 1.0,
    };
    assert!(r.contains(&small, 0.5));
    assert!(!r.contains(&small, 1.0));
    assert!(!r.contains(
        &Geo::Circle {
            c: Point::new(5.0, 5.0),
            r: 0.5
        },
        0.0
    ));
    // A circle around the hole is not inside.
    assert!(!r.contains(
        &Geo::Circle {
            c: Point::new(5.0, 5.0),
            r: 2.0
        },
        0.0
    ));
}

#[test]
fn bad_polygons_are_rejected() {
    let bow = pts(&[(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
    assert_eq!(PolygonRegion::new(&bow[..4], &[4]).err(), Some(RegionError::SelfIntersecting));
    assert_eq!(PolygonRegion::new(&bow[..2], &[2]).err(), Some(RegionError::TooFewVertices));
    let line = pts(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]);
    assert!(PolygonRegion::new(&line[..3], &[3]).is_err());
    let nan = pts(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)]);
    assert_eq!(PolygonRegion::new(&nan[..3], &[3]).err(), Some(RegionError::NotFinite));
}

#[test]
fn circle_and_annulus_contain_exactly() {
    let c = Region::Circle { radius: 10.0 };
    assert!(c.contains(
        &Geo::Circle {
            c: Point::new(10.0, 15.0),
            r: 5.0
        },
        0.0
    ));
    assert!(!c.contains(
        &Geo::Circle {
            c: Point::new(10.0, 15.0),
            r: 5.0
        },
        0.1
    ));
    let a = Region::Annulus { outer: 10.0, inner: 4.0 };
    assert!(!a.contains(
        &Geo::Circle {
            c: Point::new(10.0, 10.0),
            r: 1.0
        },
        0.0
    ));
    assert!(a.contains(
        &Geo::Circle {
            c: Point::new(10.0, 17.0),
            r: 2.0
        },
        0.0
    ));
    assert!(a.contains(
        &Geo::Ring {
            c: Point::new(10.0, 10.0),
            r: 9.0,
            inner: 5.0
        },
        0.5
    ));
}
