//! `--sites-from`: the sites of a territory run read from a fill's JSON output (its region,
//! and its shapes' centres in fill order with the shapes themselves).

use super::geom::Pt;
use super::render::FillShape;
use crate::error::CliError;
use crate::model::doc::RegionDoc;
use crate::plan::territory::{not_a_fill, sites_from_error};
use serde_json::Value;
use std::path::Path;

/// Where the sites come from.
pub struct Source {
    /// The fill's region.
    pub region: RegionDoc,
    /// Centres in fill order, and their shapes.
    pub centres: Vec<(Pt, u64, FillShape)>,
    /// The file's name as given.
    pub name: String,
}

fn num_pair(v: &Value) -> Option<Pt> {
    let a = v.as_array()?;
    match a.as_slice() {
        [x, y] => Some([x.as_f64()?, y.as_f64()?]),
        _ => None,
    }
}

/// Reads a fill's JSON: its region and its shapes' centres, in fill order.
pub fn load_source(path: &Path) -> Result<Source, CliError> {
    let bytes = crate::io::read::read_limited(path, crate::io::read::MAX_JSON_BYTES, "a fill's JSON")
        .map_err(|e| sites_from_error(path, format!("cannot read it ({e})")))?;
    let v: Value =
        serde_json::from_slice(&bytes).map_err(|e| sites_from_error(path, format!("not JSON ({e}); give a fill's JSON output")))?;
    if v.get("mode").and_then(Value::as_str) != Some("fill") {
        return Err(not_a_fill(path));
    }
    let r = v.get("region").ok_or_else(|| sites_from_error(path, "no region"))?;
    let f = |k: &str| r.get(k).and_then(Value::as_f64).filter(|x| x.is_finite());
    let ring = |x: &Value| -> Option<Vec<Pt>> { x.as_array()?.iter().map(num_pair).collect() };
    let region = match r.get("kind").and_then(Value::as_str) {
        Some("rect") => f("width").zip(f("height")).map(|(width, height)| RegionDoc::Rect {
            width,
            height,
            periodic: false,
        }),
        Some("circle") => r
            .get("center")
            .and_then(num_pair)
            .zip(f("radius"))
            .map(|(center, radius)| RegionDoc::Circle { center, radius }),
        Some("annulus") => match (r.get("center").and_then(num_pair), f("radius_outer"), f("radius_inner")) {
            (Some(center), Some(radius_outer), Some(radius_inner)) => Some(RegionDoc::Annulus {
                center,
                radius_outer,
                radius_inner,
            }),
            _ => None,
        },
        Some("polygon") => {
            let list =
                |k: &str| -> Option<Vec<Vec<Pt>>> { r.get(k).map_or(Some(Vec::new()), |x| x.as_array()?.iter().map(ring).collect()) };
            match (r.get("vertices").and_then(ring), list("holes"), list("outers")) {
                (Some(vertices), Some(holes), Some(outers)) if vertices.len() >= 3 => Some(RegionDoc::Polygon { vertices, holes, outers }),
                _ => None,
            }
        }
        _ => None,
    }
    .ok_or_else(|| sites_from_error(path, "its region is malformed"))?;
    let shapes = v
        .get("shapes")
        .and_then(Value::as_array)
        .ok_or_else(|| sites_from_error(path, "no shapes"))?;
    let mut centres = Vec::with_capacity(shapes.len());
    for (i, s) in shapes.iter().enumerate() {
        let c = s
            .get("center")
            .and_then(num_pair)
            .filter(|c| c[0].is_finite() && c[1].is_finite())
            .ok_or_else(|| sites_from_error(path, format!("shape {i} has no centre")))?;
        let index = s.get("index").and_then(Value::as_u64).unwrap_or(i as u64);
        let radius = s.get("radius").and_then(Value::as_f64);
        let shape = match (
            radius,
            s.get("inner_radius").and_then(Value::as_f64),
            s.get("vertices").and_then(ring),
        ) {
            (Some(r), Some(inner), _) => FillShape::Ring { c, r, inner },
            (Some(r), None, _) => FillShape::Circle { c, r },
            (None, _, Some(vs)) => FillShape::Poly(vs),
            _ => FillShape::Circle { c, r: 0.0 },
        };
        centres.push((c, index, shape));
    }
    Ok(Source {
        region,
        centres,
        name: path.display().to_string(),
    })
}
