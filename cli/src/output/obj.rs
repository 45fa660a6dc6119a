//! Wavefront OBJ of solids: one object (`o solid_K`, K from 1) per solid, its vertices and
//! faces (1-based, counter-clockwise seen from outside). Coordinates are the same 32-bit floats
//! the STL holds, written in their shortest round-trip form, so both files carry the same
//! points and every mesh stays inside its solid ([`MeshOptions::for_scene`]). Deterministic.

use super::mesh::{MeshOptions, ScenePlan};
use super::stl::{to_f32, StlError};
use crate::model::solid::Solid;
use std::io::Write;

/// Writes the solids as OBJ text to `out`, one solid at a time. Every solid is checked before
/// the first byte is written; a failing sink may leave part of the file.
pub fn write(solids: &[Solid], opt: &MeshOptions, out: &mut impl Write) -> Result<(), StlError> {
    use std::fmt::Write as _;
    let plan = ScenePlan::new(solids, opt).map_err(StlError::Mesh)?;
    let io = |e: std::io::Error| StlError::Io(e.to_string());
    out.write_all(b"# zetafill: solids of a 3D fractal fill, mm\n").map_err(io)?;
    let mut base: u64 = 1;
    let mut text = String::new();
    for (i, s) in solids.iter().enumerate() {
        let m = plan.mesh(i, s);
        text.clear();
        let _ = writeln!(text, "o solid_{}", i + 1);
        for v in &m.vertices {
            let [x, y, z] = to_f32(*v).map(|c| if c == 0.0 { 0.0 } else { c });
            let _ = writeln!(text, "v {x} {y} {z}");
        }
        for t in &m.triangles {
            let [a, b, c] = t.map(|k| base + u64::from(k));
            let _ = writeln!(text, "f {a} {b} {c}");
        }
        base += m.vertices.len() as u64;
        out.write_all(text.as_bytes()).map_err(io)?;
    }
    Ok(())
}

/// The solids as OBJ bytes.
pub fn to_bytes(solids: &[Solid], opt: &MeshOptions) -> Result<Vec<u8>, StlError> {
    let mut v = Vec::new();
    write(solids, opt, &mut v)?;
    Ok(v)
}
