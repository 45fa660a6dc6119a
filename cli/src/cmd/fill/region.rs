//! `--region` resolved: the outline read from its file, the rings ordered as the JSON lists
//! them, the core region it lends, and the region as written in JSON.

use crate::error::CliError;
use crate::model::doc::RegionDoc;
use crate::model::region::RegionSpec;
use crate::plan::region::{area_too_small, not_periodic, outline_error, polygon_error};
use zetafill::{PolygonRegion, Region};

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

    /// The core region (validating polygons).
    pub fn region(&self, periodic: bool) -> Result<Region<'_>, CliError> {
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
            RegionSpec::Polygon { points, ends } => Region::Polygon(PolygonRegion::new(points, ends).map_err(polygon_error)?),
            RegionSpec::Svg(_) => return Err(CliError::Io("internal: SVG region not loaded".into())),
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
                let rings: Vec<&[zetafill::Point<f64>]> = p.rings().collect();
                let as_vec = |r: &[zetafill::Point<f64>]| r.iter().map(|q| [q.x, q.y]).collect::<Vec<_>>();
                let (mut vertices, mut holes, mut outers) = (Vec::new(), Vec::new(), Vec::new());
                for (r, hole) in rings.iter().zip(holes_of(&rings)) {
                    if hole {
                        holes.push(as_vec(r));
                    } else if vertices.is_empty() {
                        vertices = as_vec(r);
                    } else {
                        outers.push(as_vec(r));
                    }
                }
                RegionDoc::Polygon { vertices, holes, outers }
            }
        }
    }
}

/// Whether each ring is a hole: inside an odd number of the others (the even-odd rule), judged
/// by its first vertex.
fn holes_of(rings: &[&[zetafill::Point<f64>]]) -> Vec<bool> {
    (0..rings.len())
        .map(|i| {
            let probe = rings.get(i).and_then(|r| r.first()).copied().unwrap_or_default();
            let depth = rings
                .iter()
                .enumerate()
                .filter(|(j, o)| *j != i && zetafill::internals::geom::point_in_poly(probe, o))
                .count();
            depth % 2 == 1
        })
        .collect()
}

/// The rings reordered as the JSON lists them (the outer outlines, then the holes, each in
/// their own order), so that the `--region polygon:` written from the JSON gives the core the
/// same rings in the same order, and so the same bits.
fn outers_first(points: &[zetafill::Point<f64>], ends: &[usize]) -> RegionSpec {
    let starts = std::iter::once(0).chain(ends.iter().copied());
    let rings: Vec<&[zetafill::Point<f64>]> = starts.zip(ends).filter_map(|(a, &b)| points.get(a..b)).collect();
    let holes = holes_of(&rings);
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
}
