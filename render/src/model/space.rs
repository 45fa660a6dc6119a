//! The result of a 3D fill as one plain data model: what its JSON document (version 1, mode
//! `"space"`), its CSV rows and its digest line write, and from which the solids of the 3D
//! writers ([`super::solid`]) are made.
//!
//! Each solid records its kind, its centre, its `size` (the core's scale: the radius of a
//! sphere or shell, half the side of a cube, the circumradius of a tetrahedron or octahedron,
//! the major radius of a torus), its rotation as the core's unit quaternion `[w, x, y, z]`,
//! its nominal volume and the trials it took. A shell adds the radius of its hole, a torus the
//! radius of its tube and the number of balls (beads) it is made of and tested as.

use super::doc::{RunParamsDoc, StatsDoc};
use super::solid::{Mat3, Region3, Solid, SolidKind, V3};
use serde::Serialize;

/// A finished (or halted) 3D fill.
#[derive(Debug, Clone, Serialize)]
pub struct SpaceDoc {
    /// Format version (1).
    pub version: u32,
    /// `"space"`.
    pub mode: &'static str,
    /// The `zetafill space` command line that makes the same solids again.
    pub command: String,
    /// Everything needed to reproduce the run.
    pub params: SpaceParamsDoc,
    /// The region (mm; its box starts at the origin).
    pub region: SpaceRegionDoc,
    /// The region's volume V.
    pub volume: f64,
    /// zeta(c, N).
    pub zeta: f64,
    /// Solids in placement order.
    pub solids: Vec<SolidDoc>,
    /// Run statistics (`fill_fraction`: placed volume over the region's volume).
    pub stats: StatsDoc,
    /// The determinism digest (count, FNV-1a) of the engine's own bits.
    #[serde(skip)]
    pub digest: (u64, u64),
}

/// The parameters of a 3D fill.
pub type SpaceParamsDoc = RunParamsDoc<SolidParamsDoc>;

/// What only a 3D fill has: its solids, rotation and scalar.
#[derive(Debug, Clone, Serialize)]
pub struct SolidParamsDoc {
    /// `--shape` as written on the command line.
    pub shape: String,
    /// `none` or `random`.
    pub rotate: &'static str,
    /// For a mix: `cycle` or `random`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mix_order: Option<&'static str>,
    /// `f64` or `fixed`.
    pub scalar: &'static str,
    /// `fast` or `reference`.
    pub sampler: &'static str,
}

/// The region of a 3D fill (mm).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum SpaceRegionDoc {
    /// `[0, width] x [0, height] x [0, depth]`.
    Box {
        /// Along x.
        width: f64,
        /// Along y.
        height: f64,
        /// Along z.
        depth: f64,
        /// Periodic in x, y and z.
        periodic: bool,
    },
    /// A ball.
    Ball {
        /// Centre (R, R, R).
        center: [f64; 3],
        /// Radius.
        radius: f64,
    },
    /// A box without the ball at its centre.
    Boxball {
        /// Along x.
        width: f64,
        /// Along y.
        height: f64,
        /// Along z.
        depth: f64,
        /// The removed ball's centre (the box's).
        center: [f64; 3],
        /// The removed ball's radius.
        radius: f64,
    },
}

/// One placed solid.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SolidDoc {
    /// Placement index from 0.
    pub index: u64,
    /// `sphere`, `cube`, `tetrahedron`, `octahedron`, `shell` or `torus`.
    pub kind: &'static str,
    /// Centre (mm).
    pub center: [f64; 3],
    /// The core's scale (see the module's page).
    pub size: f64,
    /// A shell's hole radius (mm).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inner_radius: Option<f64>,
    /// A torus's tube radius (mm).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tube_radius: Option<f64>,
    /// A torus's number of beads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub beads: Option<u32>,
    /// Rotation, a unit quaternion `[w, x, y, z]`.
    pub quaternion: [f64; 4],
    /// Nominal volume (mm³).
    pub volume: f64,
    /// Trials it took.
    pub trials: u64,
}

impl SpaceRegionDoc {
    /// The region as the writers take it.
    pub fn region3(&self) -> Region3 {
        match *self {
            SpaceRegionDoc::Box { width, height, depth, .. } => Region3::Box {
                w: width,
                h: height,
                d: depth,
            },
            SpaceRegionDoc::Ball { radius, .. } => Region3::Ball { r: radius },
            SpaceRegionDoc::Boxball {
                width,
                height,
                depth,
                radius,
                ..
            } => Region3::BoxMinusBall {
                w: width,
                h: height,
                d: depth,
                r: radius,
            },
        }
    }

    /// The `--region` argument (and `--periodic`) that make this region again.
    pub fn arg(&self) -> String {
        match *self {
            SpaceRegionDoc::Box {
                width,
                height,
                depth,
                periodic,
            } => format!("box:{width}:{height}:{depth}{}", if periodic { " --periodic" } else { "" }),
            SpaceRegionDoc::Ball { radius, .. } => format!("ball:{radius}"),
            SpaceRegionDoc::Boxball {
                width,
                height,
                depth,
                radius,
                ..
            } => format!("boxball:{width}:{height}:{depth}:{radius}"),
        }
    }

    /// Whether the box is periodic.
    pub fn periodic(&self) -> bool {
        matches!(self, SpaceRegionDoc::Box { periodic: true, .. })
    }
}

/// The row-major rotation matrix of a unit quaternion `[w, x, y, z]` (normalised first, so
/// that rounding in the stored values never makes it less than a rotation).
pub fn rotation(q: [f64; 4]) -> Mat3 {
    let len = q.iter().map(|v| v * v).sum::<f64>().sqrt();
    let [w, x, y, z] = if len > 0.0 && len.is_finite() {
        q.map(|v| v / len)
    } else {
        [1.0, 0.0, 0.0, 0.0]
    };
    [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)],
    ]
}

impl SolidDoc {
    /// The solid in the writers' terms (a torus as the beads the core tested).
    pub fn kind(&self) -> SolidKind {
        let s = self.size;
        match self.kind {
            "cube" => SolidKind::Cube { half_side: s },
            "tetrahedron" => SolidKind::Tetrahedron { circumradius: s },
            "octahedron" => SolidKind::Octahedron { circumradius: s },
            "shell" => SolidKind::Shell {
                outer: s,
                inner: self.inner_radius.unwrap_or(0.5 * s),
            },
            "torus" => SolidKind::BeadTorus {
                major: s,
                minor: self.tube_radius.unwrap_or(0.25 * s),
                beads: self.beads.unwrap_or(8),
            },
            _ => SolidKind::Sphere { radius: s },
        }
    }

    /// The solid at its own place.
    pub fn solid(&self) -> Solid {
        Solid {
            centre: self.center,
            rotation: rotation(self.quaternion),
            kind: self.kind(),
        }
    }
}

/// The solids of a fill as the writers draw them: each in its place and, in a periodic box,
/// also every copy moved by whole periods whose bounding ball reaches into the box (a solid
/// that crosses a face shows again across it), the solid itself first.
pub fn scene(doc: &SpaceDoc) -> Vec<Solid> {
    let (_, hi) = doc.region.region3().bounds();
    let periodic = doc.region.periodic();
    let mut out = Vec::with_capacity(doc.solids.len());
    for sd in &doc.solids {
        let s = sd.solid();
        out.push(s);
        if !periodic {
            continue;
        }
        let r = s.kind.bounding_radius();
        let shifts = |i: usize| -> Vec<f64> {
            let (c, p) = (s.centre[i], hi[i]);
            [-p, p].into_iter().filter(|&d| c + d - r < p && c + d + r > 0.0).collect()
        };
        let axis = |i: usize| -> Vec<f64> {
            let mut v = vec![0.0];
            v.extend(shifts(i));
            v
        };
        for &dz in &axis(2) {
            for &dy in &axis(1) {
                for &dx in &axis(0) {
                    if dx == 0.0 && dy == 0.0 && dz == 0.0 {
                        continue;
                    }
                    let d: V3 = [dx, dy, dz];
                    out.push(Solid {
                        centre: super::solid::add(s.centre, d),
                        ..s
                    });
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternions_become_rotations() {
        let m = rotation([0.5, 0.5, 0.5, 0.5]);
        assert!(super::super::solid::is_rotation(&m, 1e-12));
        // A third of a turn about (1, 1, 1) takes x to y.
        let v = super::super::solid::mul(&m, [1.0, 0.0, 0.0]);
        assert!((v[1] - 1.0).abs() < 1e-12 && v[0].abs() < 1e-12);
    }
}
