//! CSV output: one row per shape, a header first. Columns: index, kind, x, y, radius, angle,
//! area, trials (radius empty for polygons, angle empty for circles). Full f64 precision:
//! each number as Rust's `Display` writes it (shortest round-trip, never an exponent).

use crate::model::doc::FillDoc;
use crate::output::number::{push_int, push_shortest};

/// Renders a fill as CSV.
pub fn render(doc: &FillDoc) -> Vec<u8> {
    let mut s = String::with_capacity(64 + 96 * doc.shapes.len());
    s.push_str("index,kind,x,y,radius,angle,area,trials\n");
    for sh in &doc.shapes {
        push_int(&mut s, sh.index);
        s.push(',');
        s.push_str(sh.kind);
        for v in [Some(sh.center[0]), Some(sh.center[1]), sh.radius, sh.angle, Some(sh.area)] {
            s.push(',');
            if let Some(v) = v {
                push_shortest(&mut s, v);
            }
        }
        s.push(',');
        push_int(&mut s, sh.trials);
        s.push('\n');
    }
    s.into_bytes()
}
