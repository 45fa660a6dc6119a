//! glTF 2.0 binary (`.glb`) of solids, for Blender, game engines and web viewers.
//!
//! Solids are *instances*: one mesh per shape that differs by more than a rotation, a uniform
//! scale and a move (per [`MeshKey`]: kind, ratio of radii, beads; in the order the solids
//! first use them), each written once at unit size, and one node per solid that places it with
//! a translation, a rotation (a unit quaternion) and a uniform scale. A mesh is written once
//! whatever the number of solids that use it, and a node takes about 150 bytes, far less than
//! any mesh; so the file is never larger than one with every solid's mesh written out.
//!
//! glTF is y-up and in metres; the solids are z-up in mm. One root node turns the scene
//! (rotation -90° about x, scale 0.001), so the file opens the right way up at the right size.
//! The unit meshes lie inside their unit solids exactly as in [`super::mesh`] (with no margin:
//! the viewer composes the node transforms in its own floats, so this file is for looking at;
//! STL and OBJ are for printing). Normals are left out: glTF viewers then shade each triangle
//! flat. Materials are one colour per kind.
//!
//! The JSON is written with `serde_json` (shortest round-trip numbers), the binary chunk in
//! little endian; the same solids give the same bytes.

use super::mesh::{local_mesh, unit_kind, MeshError, MeshKey, MeshOptions, SceneError};
use crate::model::solid::{is_rotation, Mat3, Solid};
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// The colour (linear RGBA) and name of each kind's material, by [`MeshKey::kind`].
const MATERIALS: [(&str, [f64; 4]); 7] = [
    ("sphere", [0.80, 0.36, 0.20, 1.0]),
    ("shell", [0.90, 0.62, 0.15, 1.0]),
    ("cube", [0.20, 0.45, 0.80, 1.0]),
    ("tetrahedron", [0.25, 0.65, 0.35, 1.0]),
    ("octahedron", [0.55, 0.30, 0.70, 1.0]),
    ("torus", [0.75, 0.20, 0.45, 1.0]),
    ("bead torus", [0.15, 0.60, 0.65, 1.0]),
];

/// The unit quaternion `[x, y, z, w]` of a rotation matrix (row-major), with `w >= 0` and no
/// negative zero, so one rotation always gives the same four numbers.
pub fn quaternion(m: &Mat3) -> [f64; 4] {
    let tr = m[0][0] + m[1][1] + m[2][2];
    let q = if tr > 0.0 {
        let s = (tr + 1.0).sqrt() * 2.0;
        [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s]
    } else if m[0][0] > m[1][1] && m[0][0] > m[2][2] {
        let s = (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt() * 2.0;
        [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    } else if m[1][1] > m[2][2] {
        let s = (1.0 + m[1][1] - m[0][0] - m[2][2]).sqrt() * 2.0;
        [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    } else {
        let s = (1.0 + m[2][2] - m[0][0] - m[1][1]).sqrt() * 2.0;
        [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s]
    };
    let len = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    let sign = if q[3] < 0.0 { -1.0 } else { 1.0 };
    q.map(|x| x * sign / len + 0.0)
}

/// Why a GLB cannot be written.
#[derive(Debug, Clone, PartialEq)]
pub enum GlbError {
    /// A solid cannot be meshed.
    Mesh(SceneError),
    /// A solid's rotation is not a rotation (orthonormal, determinant +1).
    NotRotation(usize),
    /// The file would pass the 4 GiB a GLB can hold.
    TooLarge,
}

impl std::fmt::Display for GlbError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GlbError::Mesh(e) => e.fmt(f),
            GlbError::NotRotation(i) => write!(f, "solid {i}: its rotation matrix is not a rotation"),
            GlbError::TooLarge => write!(f, "the GLB would pass 4 GiB: write fewer solids or fewer segments"),
        }
    }
}

/// Pads `v` with `fill` to a multiple of 4 bytes.
fn pad(v: &mut Vec<u8>, fill: u8) {
    while v.len() % 4 != 0 {
        v.push(fill);
    }
}

/// The solids as a `.glb` file, round solids meshed with `segments`.
pub fn to_bytes(solids: &[Solid], segments: u32) -> Result<Vec<u8>, GlbError> {
    let opt = MeshOptions::new(segments);
    let mut keys: BTreeMap<MeshKey, usize> = BTreeMap::new();
    let (mut meshes, mut views, mut accessors, mut nodes) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut bin: Vec<u8> = Vec::new();
    let mut used_materials = [false; 7];
    for (index, s) in solids.iter().enumerate() {
        if !is_rotation(&s.rotation, 1e-9) {
            return Err(GlbError::NotRotation(index));
        }
        let (key, unit, size) = unit_kind(&s.kind);
        let finite = s.centre.iter().all(|c| c.is_finite()) && size.is_finite() && size > 0.0;
        if !finite {
            let error = if size > 0.0 { MeshError::Placement } else { MeshError::BadSize };
            return Err(GlbError::Mesh(SceneError { index, error }));
        }
        let next = keys.len();
        let mesh = *keys.entry(key).or_insert(next);
        if mesh == next {
            let m = local_mesh(&unit, &opt).map_err(|error| GlbError::Mesh(SceneError { index, error }))?;
            let pos: Vec<[f32; 3]> = m.vertices.iter().map(|v| v.map(|x| x as f32 + 0.0)).collect();
            let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
            for p in &pos {
                for i in 0..3 {
                    lo[i] = lo[i].min(p[i]);
                    hi[i] = hi[i].max(p[i]);
                }
            }
            let start = bin.len();
            bin.extend(pos.iter().flatten().flat_map(|x| x.to_le_bytes()));
            views.push(json!({"buffer": 0, "byteOffset": start, "byteLength": bin.len() - start, "target": 34962}));
            accessors.push(json!({"bufferView": views.len() - 1, "componentType": 5126, "count": pos.len(),
                "type": "VEC3", "min": lo, "max": hi}));
            let short = pos.len() < 65535;
            let start = bin.len();
            for i in m.triangles.iter().flatten() {
                if short {
                    bin.extend((*i as u16).to_le_bytes());
                } else {
                    bin.extend(i.to_le_bytes());
                }
            }
            views.push(json!({"buffer": 0, "byteOffset": start, "byteLength": bin.len() - start, "target": 34963}));
            pad(&mut bin, 0);
            accessors.push(
                json!({"bufferView": views.len() - 1, "componentType": if short { 5123 } else { 5125 },
                "count": m.triangles.len() * 3, "type": "SCALAR"}),
            );
            let material = usize::from(key.kind);
            used_materials[material] = true;
            meshes.push(json!({"name": format!("{} {}", MATERIALS[material].0, next + 1), "primitives": [{
                "attributes": {"POSITION": accessors.len() - 2}, "indices": accessors.len() - 1,
                "material": material, "mode": 4}]}));
        }
        nodes.push(json!({"mesh": mesh, "translation": s.centre.map(|x| x + 0.0),
            "rotation": quaternion(&s.rotation), "scale": [size, size, size]}));
    }
    if bin.len() > u32::MAX as usize / 2 {
        return Err(GlbError::TooLarge);
    }
    let materials: Vec<Value> = MATERIALS
        .iter()
        .map(|(name, colour)| {
            json!({"name": name, "pbrMetallicRoughness": {"baseColorFactor": colour,
            "metallicFactor": 0.0, "roughnessFactor": 0.6}})
        })
        .collect();
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let root = json!({"name": "zetafill (z-up, mm)", "rotation": [-h, 0.0, 0.0, h], "scale": [0.001, 0.001, 0.001],
        "children": (1..=nodes.len()).collect::<Vec<_>>()});
    let mut all_nodes = vec![root];
    all_nodes.extend(nodes);
    let mut doc = json!({
        "asset": {"version": "2.0", "generator": "zetafill"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": all_nodes,
    });
    if !meshes.is_empty() {
        // Only the materials some mesh uses; indices in the meshes are renumbered to match.
        let kept: Vec<usize> = (0..MATERIALS.len()).filter(|k| used_materials[*k]).collect();
        for m in &mut meshes {
            if let Some(old) = m["primitives"][0]["material"].as_u64() {
                m["primitives"][0]["material"] = json!(kept.iter().position(|k| *k as u64 == old));
            }
        }
        doc["materials"] = json!(kept.iter().map(|k| materials[*k].clone()).collect::<Vec<_>>());
        doc["meshes"] = json!(meshes);
        doc["accessors"] = json!(accessors);
        doc["bufferViews"] = json!(views);
        doc["buffers"] = json!([{"byteLength": bin.len()}]);
    }
    let mut text = serde_json::to_vec(&doc).map_err(|_| GlbError::TooLarge)?;
    pad(&mut text, b' ');
    let bin_chunk = if bin.is_empty() { 0 } else { 8 + bin.len() };
    let total = 12 + 8 + text.len() + bin_chunk;
    let total = u32::try_from(total).map_err(|_| GlbError::TooLarge)?;
    let mut out = Vec::with_capacity(total as usize);
    out.extend(b"glTF");
    out.extend(2u32.to_le_bytes());
    out.extend(total.to_le_bytes());
    out.extend((text.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(text);
    if !bin.is_empty() {
        out.extend((bin.len() as u32).to_le_bytes());
        out.extend(b"BIN\0");
        out.extend(bin);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternions_of_quarter_turns() {
        let q = quaternion(&[[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
        let h = std::f64::consts::FRAC_1_SQRT_2;
        assert!((q[2] - h).abs() < 1e-15 && (q[3] - h).abs() < 1e-15 && q[0] == 0.0 && q[1] == 0.0);
        // A half turn about x (trace -1) takes the second branch.
        assert_eq!(
            quaternion(&[[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]),
            [1.0, 0.0, 0.0, 0.0]
        );
    }
}
