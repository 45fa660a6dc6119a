//! Regions shared by the tests that run in every kind of region.

use zetafill::{Point, PolygonRegion, Region};

/// The outline of a ten-pointed star (radii 100 and 55 about (100, 100)) with a 20 mm square
/// hole at its centre, as points and ring ends for [`PolygonRegion::new`].
pub fn star_with_hole() -> (Vec<Point<f64>>, Vec<usize>) {
    let mut pts: Vec<Point<f64>> = (0..10)
        .map(|k| {
            let t = std::f64::consts::FRAC_PI_2 + k as f64 * std::f64::consts::PI / 5.0;
            let r = if k % 2 == 0 { 100.0 } else { 55.0 };
            Point::new(100.0 + r * t.cos(), 100.0 + r * t.sin())
        })
        .collect();
    pts.extend([
        Point::new(90.0, 90.0),
        Point::new(90.0, 110.0),
        Point::new(110.0, 110.0),
        Point::new(110.0, 90.0),
    ]);
    (pts, vec![10, 14])
}

/// One region of each kind: a 160 x 120 rectangle, inclusive and periodic, a disc, an
/// annulus, and `poly`.
pub fn every_kind(poly: PolygonRegion<'_>) -> [Region<'_>; 5] {
    [
        Region::Rect {
            width: 160.0,
            height: 120.0,
            periodic: false,
        },
        Region::Rect {
            width: 160.0,
            height: 120.0,
            periodic: true,
        },
        Region::Circle { radius: 80.0 },
        Region::Annulus { outer: 90.0, inner: 35.0 },
        Region::Polygon(poly),
    ]
}
