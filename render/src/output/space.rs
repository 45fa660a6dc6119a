//! The plain formats of a 3D fill: its JSON document (version 1, mode `"space"`, numbers in
//! shortest round-trip form, one line and a newline), its CSV rows and its digest line. The
//! meshes, the render and the slices are written by [`super::stl`], [`super::obj`],
//! [`super::glb`], [`super::render3d`] and [`crate::model::slices`].

use crate::error::CliError;
use crate::model::space::SpaceDoc;
use crate::output::stream::{io_error, TextSink, MAX_F64_DISPLAY, MAX_JSON_NUMBER, MAX_U64};
use std::fmt::Write;

/// The JSON document.
pub fn json(doc: &SpaceDoc) -> Result<Vec<u8>, CliError> {
    let mut v = Vec::new();
    json_to(doc, &mut v)?;
    Ok(v)
}

/// Writes the JSON document into `out` as it is encoded.
pub fn json_to(doc: &SpaceDoc, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    serde_json::to_writer(&mut *out, doc).map_err(json_error)?;
    out.write_all(b"\n").map_err(io_error)
}

/// A `serde_json` failure: the sink's, or an encoding one.
pub fn json_error(e: serde_json::Error) -> CliError {
    if e.is_io() {
        io_error(e.into())
    } else {
        CliError::Io(format!("cannot encode JSON: {e}"))
    }
}

/// The most bytes one solid takes in the JSON document: its keys (132 bytes with the longest
/// kind, a shell's and a torus's fields both counted), two `u64`, a `u32` and eleven numbers
/// of at most [`MAX_JSON_NUMBER`] bytes.
pub const MAX_JSON_SOLID: u64 = 132 + 2 * MAX_U64 + 10 + 11 * MAX_JSON_NUMBER;

/// An upper bound on the JSON document's size: everything but the solids exactly (encoded
/// without them), each solid at [`MAX_JSON_SOLID`] and a comma.
pub fn json_max_size(doc: &SpaceDoc) -> Result<u64, CliError> {
    let bare = SpaceDoc {
        command: doc.command.clone(),
        params: doc.params.clone(),
        solids: Vec::new(),
        stats: doc.stats.clone(),
        ..*doc
    };
    let base = serde_json::to_vec(&bare).map_err(json_error)?.len() as u64 + 1;
    Ok(base + doc.solids.len() as u64 * (MAX_JSON_SOLID + 1))
}

/// The CSV's first line.
const CSV_HEADER: &str = "index,kind,x,y,z,size,inner_radius,tube_radius,beads,qw,qx,qy,qz,volume,trials\n";

/// One row per solid after a header: index, kind, x, y, z, size, inner_radius, tube_radius,
/// beads, qw, qx, qy, qz, volume, trials (a shell's and a torus's own columns empty for the
/// others). Full f64 precision.
pub fn csv(doc: &SpaceDoc) -> Vec<u8> {
    let mut v = Vec::new();
    // A Vec takes every byte.
    let _ = csv_to(doc, &mut v);
    v
}

/// Writes the CSV into `out`, a few rows at a time.
pub fn csv_to(doc: &SpaceDoc, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    let mut sink = TextSink::new(out);
    sink.buf.push_str(CSV_HEADER);
    let opt = |v: Option<f64>| v.map_or_else(String::new, |v| v.to_string());
    for d in &doc.solids {
        let [x, y, z] = d.center;
        let [qw, qx, qy, qz] = d.quaternion;
        let _ = writeln!(
            sink.buf,
            "{},{},{x},{y},{z},{},{},{},{},{qw},{qx},{qy},{qz},{},{}",
            d.index,
            d.kind,
            d.size,
            opt(d.inner_radius),
            opt(d.tube_radius),
            d.beads.map_or_else(String::new, |b| b.to_string()),
            d.volume,
            d.trials
        );
        sink.maybe_flush()?;
    }
    sink.flush()
}

/// An upper bound on the CSV's size: every row at its longest (two `u64`, a `u32`, the longest
/// kind, eleven numbers at [`MAX_F64_DISPLAY`], 14 commas and a newline).
pub fn csv_max_size(doc: &SpaceDoc) -> u64 {
    let row = 2 * MAX_U64 + 10 + "tetrahedron".len() as u64 + 11 * MAX_F64_DISPLAY + 15;
    CSV_HEADER.len() as u64 + doc.solids.len() as u64 * row
}

/// The digest line `COUNT HEX16`: the core's `space_digest` of the run.
pub fn digest(doc: &SpaceDoc) -> Vec<u8> {
    let (n, h) = doc.digest;
    format!("{n} {h:016x}\n").into_bytes()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::space::SolidDoc;

    #[test]
    fn a_solid_at_its_longest_fits_its_bound() {
        let long = -2.2250738585072014e-308;
        let d = SolidDoc {
            index: u64::MAX,
            kind: "tetrahedron",
            center: [long; 3],
            size: long,
            inner_radius: Some(long),
            tube_radius: Some(long),
            beads: Some(u32::MAX),
            quaternion: [long; 4],
            volume: long,
            trials: u64::MAX,
        };
        let json = serde_json::to_vec(&d).unwrap_or_default();
        assert!(!json.is_empty() && json.len() as u64 <= MAX_JSON_SOLID, "{}", json.len());
        assert!(long.to_string().len() as u64 <= MAX_F64_DISPLAY);
    }
}
