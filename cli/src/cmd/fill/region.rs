//! `--region` resolved: the outline read from its file, the rings ordered as the JSON lists
//! them, the core region it lends (polygons validated over an edge grid in a scratch buffer
//! the caller owns, so outlines of 10^5 vertices or 10^4 rings take milliseconds), and the
//! region as written in JSON.

use crate::error::CliError;
use crate::model::doc::RegionDoc;
use crate::model::region::{polygon_region as polygon, RegionSpec};
use crate::plan::region::{area_too_small, not_periodic, outline_error, polygon_error};
use zetafill::{Point, Region};

/// A region resolved from its flag: owns the outline vertices the core borrows.
#[derive(Debug, Clone)]
pub struct RegionData {
    spec: RegionSpec,
}

impl RegionData {
    /// Resolves `--region` (reading an SVG outline from its file).
    pub fn load(spec: &RegionSpec) -> Result<Self, CliError> {
        let spec = match spec {
            RegionSpec::Svg(path) => {
                let (points, ends) = crate::io::svgin::read_outline(path).map_err(|e| outline_error(path, e))?;
                outers_first(&points, &ends)
            }
            RegionSpec::Polygon { points, ends } => outers_first(points, ends),
            other => other.clone(),
        };
        Ok(RegionData { spec })
    }

    /// The core region (validating polygons, whose edge grid lives in `scratch`).
    pub fn region<'s>(&'s self, periodic: bool, scratch: &'s mut Vec<u32>) -> Result<Region<'s>, CliError> {
        if periodic && !matches!(self.spec, RegionSpec::Rect { .. }) {
            return Err(not_periodic());
        }
        let region = match &self.spec {
            RegionSpec::Rect { width, height } => Region::Rect {
                width: *width,
                height: *height,
                periodic,
            },
            RegionSpec::Circle { radius } => Region::Circle { radius: *radius },
            RegionSpec::Annulus { outer, inner } => Region::Annulus {
                outer: *outer,
                inner: *inner,
            },
            RegionSpec::Polygon { points, ends } => Region::Polygon(polygon(points, ends, scratch).map_err(polygon_error)?),
            RegionSpec::Svg(_) | RegionSpec::Mask { .. } | RegionSpec::Text { .. } => {
                return Err(CliError::Io("internal: the region's input was not read".into()))
            }
        };
        // Sizes of 1e-160 mm and less give an area that rounds to nothing (or to a number
        // without full precision), from which no shape's size can be computed.
        if !region.area().is_normal() {
            return Err(area_too_small(region.area()));
        }
        Ok(region)
    }

    /// The region as written in JSON.
    pub fn doc(&self, region: &Region<'_>) -> RegionDoc {
        match *region {
            Region::Rect { width, height, periodic } => RegionDoc::Rect { width, height, periodic },
            Region::Circle { radius } => RegionDoc::Circle {
                center: [radius, radius],
                radius,
            },
            Region::Annulus { outer, inner } => RegionDoc::Annulus {
                center: [outer, outer],
                radius_outer: outer,
                radius_inner: inner,
            },
            Region::Polygon(p) => {
                let as_vec = |r: &[Point<f64>]| r.iter().map(|q| [q.x, q.y]).collect::<Vec<_>>();
                let (mut vertices, mut holes, mut outers) = (Vec::new(), Vec::new(), Vec::new());
                for (i, r) in p.rings().enumerate() {
                    if p.is_hole(i) {
                        holes.push(as_vec(r));
                    } else if vertices.is_empty() {
                        vertices = as_vec(r);
                    } else {
                        outers.push(as_vec(r));
                    }
                }
                RegionDoc::Polygon { vertices, holes, outers }
            }
            Region::Wallpaper(w) => wallpaper_doc(&w, (3, 3), None),
        }
    }
}

/// A wallpaper group's region as written in JSON: drawn over `repeat` cells, or cut to
/// `window`.
pub fn wallpaper_doc(w: &zetafill::Wallpaper, repeat: (u32, u32), window: Option<RegionDoc>) -> RegionDoc {
    let (a, b, angle) = w.sides();
    let (ax, bx, by) = w.lattice();
    let (cw, ch) = w.cell();
    let (width, height) = match &window {
        Some(r) => {
            let (x0, y0, x1, y1) = r.bbox();
            (x1 - x0, y1 - y0)
        }
        None => (f64::from(repeat.0) * cw, f64::from(repeat.1) * ch),
    };
    RegionDoc::Wallpaper {
        group: w.group().name().to_string(),
        lattice: [a, b, angle],
        vectors: [ax, bx, by],
        order: w.order(),
        repeat: window.is_none().then_some([repeat.0, repeat.1]),
        width,
        height,
        window: window.map(Box::new),
    }
}

/// The rings reordered as the JSON lists them (the outer outlines, then the holes, each in
/// their own order), so that the `--region polygon:` written from the JSON gives the core the
/// same rings in the same order, and so the same bits.
///
/// Rings that do not make a valid region are left in their order (validating them again
/// gives the same error).
fn outers_first(points: &[Point<f64>], ends: &[usize]) -> RegionSpec {
    let starts = std::iter::once(0).chain(ends.iter().copied());
    let rings: Vec<&[Point<f64>]> = starts.zip(ends).filter_map(|(a, &b)| points.get(a..b)).collect();
    let mut scratch = Vec::new();
    let Ok(region) = polygon(points, ends, &mut scratch) else {
        return RegionSpec::Polygon {
            points: points.to_vec(),
            ends: ends.to_vec(),
        };
    };
    let holes: Vec<bool> = (0..rings.len()).map(|i| region.is_hole(i)).collect();
    let (mut out, mut out_ends) = (Vec::with_capacity(points.len()), Vec::with_capacity(ends.len()));
    for want_hole in [false, true] {
        for (r, _) in rings.iter().zip(&holes).filter(|(_, h)| **h == want_hole) {
            out.extend_from_slice(r);
            out_ends.push(out.len());
        }
    }
    RegionSpec::Polygon {
        points: out,
        ends: out_ends,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use zetafill::Point;

    #[test]
    fn outlines_come_before_holes() {
        // A hole, the outline around it, and an island beside them.
        let xy = [4, 4, 6, 4, 6, 6, 0, 0, 10, 0, 10, 10, 0, 10, 20, 0, 30, 0, 30, 9];
        let points: Vec<Point<f64>> = xy.chunks(2).map(|c| Point::new(f64::from(c[0]), f64::from(c[1]))).collect();
        let ends = [3, 7, 10];
        let RegionSpec::Polygon { points: p, ends: e } = outers_first(&points, &ends) else {
            panic!("not a polygon");
        };
        assert_eq!(e, [4, 7, 10]);
        let xs: Vec<f64> = p.iter().map(|q| q.x).collect();
        assert_eq!(xs, [0.0, 10.0, 10.0, 0.0, 20.0, 30.0, 30.0, 4.0, 6.0, 6.0]);
        // Already in order: unchanged.
        let RegionSpec::Polygon { points: again, ends: e2 } = outers_first(&p, &e) else {
            panic!("not a polygon");
        };
        assert_eq!((again, e2), (p, e));
    }

    #[test]
    fn rings_that_make_no_region_keep_their_order() {
        // A hole listed first, crossing its outline: left as given, so that validating them
        // reports the crossing.
        let xy = [
            (8.0, 2.0),
            (12.0, 2.0),
            (12.0, 6.0),
            (8.0, 6.0),
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 10.0),
            (0.0, 10.0),
        ];
        let points: Vec<Point<f64>> = xy.iter().map(|&(x, y)| Point::new(x, y)).collect();
        let ends = vec![4, 8];
        let RegionSpec::Polygon { points: p, ends: e } = outers_first(&points, &ends) else {
            panic!("not a polygon");
        };
        assert_eq!((&p, &e), (&points, &ends));
        let mut scratch = Vec::new();
        assert_eq!(polygon(&p, &e, &mut scratch).err(), Some(zetafill::RegionError::SelfIntersecting));
    }
}
