//! The plain formats of a 3D fill: its JSON document (version 1, mode `"space"`, numbers in
//! shortest round-trip form, one line and a newline), its CSV rows and its digest line. The
//! meshes, the render and the slices are written by [`super::stl`], [`super::obj`],
//! [`super::glb`], [`super::render3d`] and [`crate::model::slices`].

use crate::error::CliError;
use crate::model::space::SpaceDoc;
use std::fmt::Write;

/// The JSON document.
pub fn json(doc: &SpaceDoc) -> Result<Vec<u8>, CliError> {
    let mut v = serde_json::to_vec(doc).map_err(|e| CliError::Io(format!("cannot encode JSON: {e}")))?;
    v.push(b'\n');
    Ok(v)
}

/// One row per solid after a header: index, kind, x, y, z, size, inner_radius, tube_radius,
/// beads, qw, qx, qy, qz, volume, trials (a shell's and a torus's own columns empty for the
/// others). Full f64 precision.
pub fn csv(doc: &SpaceDoc) -> Vec<u8> {
    let mut s = String::from("index,kind,x,y,z,size,inner_radius,tube_radius,beads,qw,qx,qy,qz,volume,trials\n");
    let opt = |v: Option<f64>| v.map_or_else(String::new, |v| v.to_string());
    for d in &doc.solids {
        let [x, y, z] = d.center;
        let [qw, qx, qy, qz] = d.quaternion;
        let _ = writeln!(
            s,
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
    }
    s.into_bytes()
}

/// The digest line `COUNT HEX16`: the core's `space_digest` of the run.
pub fn digest(doc: &SpaceDoc) -> Vec<u8> {
    let (n, h) = doc.digest;
    format!("{n} {h:016x}\n").into_bytes()
}
