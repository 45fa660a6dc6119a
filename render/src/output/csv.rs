//! CSV output: one row per shape, a header first. Columns: index, kind, x, y, radius, angle,
//! area, trials (radius empty for polygons, angle empty for circles). Full f64 precision:
//! each number as Rust's `Display` writes it (shortest round-trip, never an exponent).

use crate::error::CliError;
use crate::model::doc::FillDoc;
use crate::output::number::{push_int, push_shortest};
use crate::output::stream::{TextSink, MAX_F64_DISPLAY, MAX_U64};

/// The first line.
const HEADER: &str = "index,kind,x,y,radius,angle,area,trials\n";

/// Renders a fill as CSV.
pub fn render(doc: &FillDoc) -> Vec<u8> {
    let mut v = Vec::new();
    // A Vec takes every byte.
    let _ = write(doc, &mut v);
    v
}

/// Writes a fill as CSV into `out`, a few rows at a time.
pub fn write(doc: &FillDoc, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    let mut sink = TextSink::new(out);
    let s = &mut sink.buf;
    s.push_str(HEADER);
    for sh in &doc.shapes {
        let s = &mut sink.buf;
        push_int(s, sh.index);
        s.push(',');
        s.push_str(sh.kind);
        for v in [Some(sh.center[0]), Some(sh.center[1]), sh.radius, sh.angle, Some(sh.area)] {
            s.push(',');
            if let Some(v) = v {
                push_shortest(s, v);
            }
        }
        s.push(',');
        push_int(s, sh.trials);
        s.push('\n');
        sink.maybe_flush()?;
    }
    sink.flush()
}

/// An upper bound on the CSV's size: every row with two `u64`, its kind, five numbers at
/// [`MAX_F64_DISPLAY`], seven commas and a newline.
pub fn max_size(doc: &FillDoc) -> u64 {
    let rows: u64 = doc
        .shapes
        .iter()
        .map(|sh| 2 * MAX_U64 + sh.kind.len() as u64 + 5 * MAX_F64_DISPLAY + 8)
        .sum();
    HEADER.len() as u64 + rows
}
