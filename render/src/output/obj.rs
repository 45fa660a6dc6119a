//! Wavefront OBJ of solids: one object (`o solid_K`, K from 1) per solid, its vertices and
//! faces (1-based, counter-clockwise seen from outside). Coordinates are the same 32-bit floats
//! the STL holds, written in their shortest round-trip form, so both files carry the same
//! points and every mesh stays inside its solid ([`MeshOptions::for_scene`]). Deterministic.

use super::mesh::{MeshOptions, ScenePlan};
use super::stl::{to_f32, StlError};
use super::stream::{digits, MAX_F32_DISPLAY};
use crate::model::solid::Solid;
use std::io::Write;

/// The comment line every file starts with.
const HEADER: &[u8] = b"# zetafill: solids of a 3D fractal fill, mm\n";

/// An upper bound on the size of the solids' OBJ, from the triangle count alone (no solid is
/// meshed): every coordinate at the longest an `f32` is written, every index as long as the
/// last one. A closed mesh of `T` triangles whose every vertex is used has `T / 2 + 2 - 2g`
/// vertices per connected piece (Euler; `g` its genus), so a solid of at most two pieces (a
/// shell) has at most `T / 2 + 4`.
pub fn max_size(solids: &[Solid], opt: &MeshOptions) -> Result<u64, StlError> {
    let plan = ScenePlan::new(solids, opt).map_err(StlError::Mesh)?;
    let n = solids.len() as u64;
    let vertices = plan.triangles / 2 + 4 * n;
    let objects = n * ("o solid_\n".len() as u64 + digits(n));
    let vertex_lines = vertices * (5 + 3 * MAX_F32_DISPLAY);
    let face_lines = plan.triangles * (5 + 3 * digits(vertices));
    Ok(HEADER.len() as u64 + objects + vertex_lines + face_lines)
}

/// Writes the solids as OBJ text to `out`, one solid at a time. Every solid is checked before
/// the first byte is written; a failing sink may leave part of the file.
pub fn write(solids: &[Solid], opt: &MeshOptions, out: &mut impl Write) -> Result<(), StlError> {
    use std::fmt::Write as _;
    let plan = ScenePlan::new(solids, opt).map_err(StlError::Mesh)?;
    let io = |e: std::io::Error| StlError::Io(e.to_string());
    out.write_all(HEADER).map_err(io)?;
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
