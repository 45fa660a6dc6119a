//! The writers as they were before the fast number formatting: numbers through the standard
//! formatter (SVG elements built with the `svg` crate, as the tool builds them), CSV through
//! `Display`, JSON through `serde_json`'s derive. Never used by the tool; kept as the control that
//! `cli/tests/writers.rs` compares the fast writers with, byte for byte, and that
//! `cargo bench --bench writing` times them against.

use crate::model::doc::FillDoc;
use crate::model::picture::Picture;
use crate::output::number::fixed_std;
use crate::output::svg::{self, PLACES};
use std::fmt::Write as _;

/// A number on the page through the standard formatter.
fn n(out: &mut String, v: f64) {
    out.push_str(&fixed_std(v, PLACES));
}

/// Any picture as SVG, the numbers through the standard formatter.
pub fn svg(pic: &Picture) -> Vec<u8> {
    svg::write_with(pic, n)
}

/// A fill as CSV, each number through `Display`.
pub fn csv(doc: &FillDoc) -> Vec<u8> {
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

/// A fill as JSON through `serde_json`'s derive.
pub fn json(doc: &FillDoc) -> Vec<u8> {
    let mut v = serde_json::to_vec(doc).unwrap_or_default();
    v.push(b'\n');
    v
}
