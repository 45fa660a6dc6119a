//! Binary STL of solids: one closed, oriented mesh per solid ([`super::mesh`]), each inside its
//! solid even after its coordinates are rounded to 32-bit floats (the margin of
//! [`MeshOptions::for_scene`]). The 80-byte header names the program, never a date, so the
//! same solids give the same bytes.

use super::mesh::{MeshOptions, SceneError, ScenePlan};
use crate::model::solid::{cross, sub, Solid};
use std::io::Write;

/// The header every file starts with (80 bytes, space padded).
pub const HEADER: &[u8] = b"zetafill binary STL: solids of a 3D fractal fill, mm";

/// The 32-bit float coordinates of a point as written.
pub fn to_f32(p: [f64; 3]) -> [f32; 3] {
    p.map(|x| x as f32)
}

/// The unit normal of a triangle of rounded corners (zero for a degenerate one).
pub fn normal(t: [[f32; 3]; 3]) -> [f32; 3] {
    let [a, b, c] = t.map(|p| p.map(f64::from));
    let n = cross(sub(b, a), sub(c, a));
    let len = crate::model::solid::norm(n);
    if len > 0.0 {
        n.map(|x| (x / len) as f32)
    } else {
        [0.0; 3]
    }
}

/// Writes the solids as one binary STL to `out`, one solid's triangles at a time. Every solid
/// is checked before the first byte is written; a failing sink may leave part of the file.
pub fn write(solids: &[Solid], opt: &MeshOptions, out: &mut impl Write) -> Result<(), StlError> {
    let plan = ScenePlan::new(solids, opt).map_err(StlError::Mesh)?;
    let count = u32::try_from(plan.triangles).map_err(|_| StlError::TooMany(plan.triangles))?;
    let io = |e: std::io::Error| StlError::Io(e.to_string());
    let mut header = [b' '; 80];
    header[..HEADER.len()].copy_from_slice(HEADER);
    out.write_all(&header).map_err(io)?;
    out.write_all(&count.to_le_bytes()).map_err(io)?;
    let mut chunk = Vec::new();
    for (i, s) in solids.iter().enumerate() {
        let m = plan.mesh(i, s);
        chunk.clear();
        for t in &m.triangles {
            let corners = t.map(|k| to_f32(m.vertices[k as usize]));
            for x in normal(corners).iter().chain(corners.iter().flatten()) {
                chunk.extend_from_slice(&x.to_le_bytes());
            }
            chunk.extend_from_slice(&0u16.to_le_bytes());
        }
        out.write_all(&chunk).map_err(io)?;
    }
    Ok(())
}

/// The size of the binary STL of `triangles` triangles: the 80-byte header, the 4-byte count
/// and 50 bytes a triangle.
pub fn file_size(triangles: u64) -> u64 {
    84 + 50 * triangles
}

/// The exact size of the solids' binary STL (every solid is checked, none is meshed).
pub fn size(solids: &[Solid], opt: &MeshOptions) -> Result<u64, StlError> {
    let plan = ScenePlan::new(solids, opt).map_err(StlError::Mesh)?;
    Ok(file_size(plan.triangles))
}

/// The solids as binary STL bytes.
pub fn to_bytes(solids: &[Solid], opt: &MeshOptions) -> Result<Vec<u8>, StlError> {
    let mut v = Vec::new();
    write(solids, opt, &mut v)?;
    Ok(v)
}

/// Why an STL cannot be written.
#[derive(Debug, Clone, PartialEq)]
pub enum StlError {
    /// A solid cannot be meshed.
    Mesh(SceneError),
    /// More triangles than a binary STL can count.
    TooMany(u64),
    /// The sink refused the bytes.
    Io(String),
}

impl std::fmt::Display for StlError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StlError::Mesh(e) => e.fmt(f),
            StlError::TooMany(n) => write!(f, "{n} triangles: a binary STL holds at most 4294967295"),
            StlError::Io(e) => write!(f, "cannot write the STL: {e}"),
        }
    }
}
