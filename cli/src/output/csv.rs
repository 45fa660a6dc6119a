//! CSV output: one row per shape, a header first. Columns: index, kind, x, y, radius, angle,
//! area, trials (radius empty for polygons, angle empty for circles). Full f64 precision.

use crate::model::doc::FillDoc;
use std::fmt::Write as _;

/// Renders a fill as CSV.
pub fn render(doc: &FillDoc) -> Vec<u8> {
    let mut s = String::from("index,kind,x,y,radius,angle,area,trials\n");
    let opt = |v: Option<f64>| v.map(|x| x.to_string()).unwrap_or_default();
    for sh in &doc.shapes {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{}",
            sh.index,
            sh.kind,
            sh.center[0],
            sh.center[1],
            opt(sh.radius),
            opt(sh.angle),
            sh.area,
            sh.trials
        );
    }
    s.into_bytes()
}
