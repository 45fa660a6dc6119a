//! The flags of `zetafill space`: the solid, region, power law, stops, scalar and output of a
//! 3D fill, with the mesh resolution, the render's size and cut-away, and the sheets of
//! `--slices`. The parsers of `--shape` and `--region` are here too.

use crate::args::common::{OutputArgs, RunArgs};
use crate::args::fill::{MixArg, Rotate, Sampler, ScalarArg};
use crate::args::spec;
use crate::model::solid::Region3;
use clap::{Args, ValueEnum};
use zetafill::space::{Solid, SolidList};
use zetafill::MixOrder;

/// What `zetafill space` writes (`--format`, or told by `-o`'s extension).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SpaceFormatArg {
    /// JSON document (version 1, mode "space").
    Json,
    /// One row per solid.
    Csv,
    /// Binary STL: one closed mesh per solid, inside it.
    Stl,
    /// Wavefront OBJ: the same meshes, one object per solid.
    Obj,
    /// glTF 2.0 binary: one mesh per shape, one node per solid.
    Glb,
    /// A shaded picture (ray cast).
    Png,
    /// The sheets of `--slices` as one SVG, one layer per sheet.
    Svg,
    /// One line `COUNT HEX16`: the determinism digest of every placed solid.
    Digest,
}

/// Which solids the render leaves out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CutArg {
    /// Every solid is drawn.
    None,
    /// Leave out the solids in the octant facing the camera.
    Octant,
    /// Leave out the front half.
    Half,
}

/// `--shape` of a 3D fill: one solid, or a mix in the order given.
#[derive(Debug, Clone, PartialEq)]
pub struct SolidArg(pub Vec<Solid>);

impl SolidArg {
    /// The core's list of solids: a mix taken by `order`, salted with the seed.
    pub fn list(&self, order: MixOrder, seed: u64) -> SolidList {
        match self.0.as_slice() {
            [one] => (*one).into(),
            many => SolidList::mix(many, order, seed).unwrap_or_else(|| Solid::Sphere.into()),
        }
    }

    /// Whether any solid of the list takes a rotation.
    pub fn rotates(&self) -> bool {
        self.0.iter().any(Solid::rotates)
    }

    /// The flag's value written back, numbers in shortest round-trip form.
    pub fn name(&self) -> String {
        let names: Vec<String> = self.0.iter().map(solid_name).collect();
        if names.len() == 1 {
            names.concat()
        } else {
            format!("mix:{}", names.join(","))
        }
    }
}

/// One solid as `--shape` spells it.
pub fn solid_name(s: &Solid) -> String {
    match s {
        Solid::Sphere => "sphere".into(),
        Solid::Cube => "cube".into(),
        Solid::Tetrahedron => "tetrahedron".into(),
        Solid::Octahedron => "octahedron".into(),
        Solid::Shell { inner } => format!("shell:{inner}"),
        Solid::Torus { ratio } => format!("torus:{ratio}"),
    }
}

/// The most solids a mix may name.
pub const MAX_MIX: usize = 8;

/// One solid: `sphere`, `cube`, `tetrahedron`, `octahedron`, `shell:RATIO`, `torus:RATIO`.
fn one_solid(s: &str) -> Result<Solid, String> {
    let (name, arg) = match s.split_once(':') {
        Some((n, a)) => (n, Some(a)),
        None => (s, None),
    };
    let ratio = |what: &str| -> Result<f64, String> {
        let a = arg.ok_or_else(|| format!("{name} needs its {what}: {name}:RATIO"))?;
        a.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("'{a}' is not a number ({name}:RATIO)"))
    };
    let plain = |solid: Solid| match arg {
        Some(_) => Err(format!("{name} takes no parameter (got '{s}')")),
        None => Ok(solid),
    };
    match name {
        "sphere" => plain(Solid::Sphere),
        "cube" => plain(Solid::Cube),
        "tetrahedron" => plain(Solid::Tetrahedron),
        "octahedron" => plain(Solid::Octahedron),
        "shell" => {
            let inner = ratio("hole's radius over the outer radius")?;
            let solid = Solid::Shell { inner };
            if solid.is_valid() {
                Ok(solid)
            } else {
                Err(format!("shell:{inner}: the hole's ratio must be between 0 and 1, exclusive"))
            }
        }
        "torus" => {
            let r = ratio("tube's radius over its major radius")?;
            let solid = Solid::Torus { ratio: r };
            if solid.is_valid() {
                Ok(solid)
            } else {
                Err(format!("torus:{r}: the tube's ratio must be from 0.2 to 0.9"))
            }
        }
        _ => Err(format!(
            "unknown solid '{name}': use sphere, cube, tetrahedron, octahedron, shell:RATIO, torus:RATIO or mix:SOLID,SOLID,..."
        )),
    }
}

/// Parses `--shape`: one solid, or `mix:SOLID,SOLID,...` (2 to [`MAX_MIX`]).
pub fn solid(s: &str) -> Result<SolidArg, String> {
    match s.strip_prefix("mix:") {
        Some(list) => {
            let kinds = list.split(',').map(one_solid).collect::<Result<Vec<_>, _>>()?;
            if !(2..=MAX_MIX).contains(&kinds.len()) {
                return Err(format!("a mix names 2 to {MAX_MIX} solids (got {})", kinds.len()));
            }
            Ok(SolidArg(kinds))
        }
        None => Ok(SolidArg(vec![one_solid(s)?])),
    }
}

/// Parses `--region`: `box:W:H:D`, `ball:R`, or `boxball:W:H:D:R` (the box without the ball
/// of radius R at its centre), in mm.
pub fn region(s: &str) -> Result<Region3, String> {
    let (kind, rest) = s.split_once(':').unwrap_or((s, ""));
    let nums = rest
        .split(':')
        .map(|v| spec::length(v).map_err(|e| format!("'{v}': {e}")))
        .collect::<Result<Vec<f64>, String>>();
    let usage = "use box:W:H:D, ball:R or boxball:W:H:D:R (mm)";
    match (kind, rest.is_empty()) {
        ("box", false) => match nums?.as_slice() {
            &[w, h, d] => Ok(Region3::Box { w, h, d }),
            _ => Err(format!("box takes three sizes, box:W:H:D; {usage}")),
        },
        ("ball", false) => match nums?.as_slice() {
            &[r] => Ok(Region3::Ball { r }),
            _ => Err(format!("ball takes one radius, ball:R; {usage}")),
        },
        ("boxball", false) => match nums?.as_slice() {
            &[w, h, d, r] => {
                if 2.0 * r > w.min(h).min(d) {
                    Err(format!(
                        "the ball of radius {r} does not fit inside the {w} x {h} x {d} box; {usage}"
                    ))
                } else {
                    Ok(Region3::BoxMinusBall { w, h, d, r })
                }
            }
            _ => Err(format!("boxball takes four sizes, boxball:W:H:D:R; {usage}")),
        },
        _ => Err(format!("unknown region '{s}': {usage}")),
    }
}

/// The fractal dimension D in 3D: 0 < D < 3 (so that c = 3/D > 1).
pub fn dimension_3d(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|_| format!("'{s}' is not a number"))?;
    if v.is_finite() && v > 0.0 && v < 3.0 {
        Ok(v)
    } else {
        Err(format!(
            "the dimension of a 3D fill must be between 0 and 3, exclusive (got {s}); c = 3/D"
        ))
    }
}

/// Arguments of `zetafill space`.
#[derive(Debug, Args)]
#[command(
    mut_arg("c", |a| a.help("Power-law exponent c > 1 (default 1.15; about 1.2 is the 3D limit for cubes with N = 1)")),
    mut_arg("dimension", |a| a.help("Fractal dimension D in (0, 3) instead of c (c = 3/D)").value_parser(dimension_3d)),
    mut_arg("n_offset", |a| a.help("The paper's N > 0: larger N makes the first solids smaller")),
    mut_arg("count", |a| a.help("Stop after K solids (default 2000 when no stop condition is given)")),
    mut_arg("fill", |a| a.help("Stop once this fraction of the region's volume is filled, 0 < F < 1")),
    mut_arg("min_size", |a| a.help("Stop before the first solid narrower than MM")),
    mut_arg("gap", |a| a.help("Minimum clearance between solids and to the boundary, in mm")),
    mut_arg("output", |a| a.help("Output path; the format comes from the extension (.json .csv .stl .obj .glb .png, .svg with --slices); '-' is stdout (JSON)")),
)]
pub struct SpaceArgs {
    /// sphere | cube | tetrahedron | octahedron | shell:RATIO (hole over radius) |
    /// torus:RATIO (tube over major radius, 0.2 to 0.9) | mix:SOLID,SOLID,...
    #[arg(long, default_value = "sphere", value_parser = solid)]
    pub shape: SolidArg,
    /// Mixes: take the solids in turn (cycle) or at random per placement.
    #[arg(long = "mix-order", value_enum, default_value = "cycle")]
    pub mix_order: MixArg,
    /// Rotation: none or random, uniform in 3D (default: random for solids that have one).
    #[arg(long, value_enum)]
    pub rotate: Option<Rotate>,
    /// box:W:H:D | ball:R | boxball:W:H:D:R (the box without the ball of radius R at its
    /// centre), in mm; every region's box starts at the origin.
    #[arg(long, default_value = "box:100:100:100", value_parser = region)]
    pub region: Region3,
    /// Periodic boundary in x, y and z (box regions only).
    #[arg(long)]
    pub periodic: bool,
    /// The power law, stops, clearance, trial limit and seed.
    #[command(flatten)]
    pub run: RunArgs,
    /// Number type of the engine: f64 or fixed (32.32 fixed point).
    #[arg(long, value_enum, default_value = "f64")]
    pub scalar: ScalarArg,
    /// Candidate sampler: fast (octree cells where the next solid could fit: the same
    /// distribution of placements as reference, far fewer trials) or reference (the paper's).
    #[arg(long, value_enum, default_value = "fast")]
    pub sampler: Sampler,
    /// Where the output goes.
    #[command(flatten)]
    pub output: OutputArgs<SpaceFormatArg>,
    /// STL, OBJ, GLB: segments around a sphere's equator and a torus's ring.
    #[arg(long, default_value_t = 24, allow_hyphen_values = true)]
    pub segments: u32,
    /// PNG: the render's side in pixels.
    #[arg(long, default_value_t = 800, allow_hyphen_values = true)]
    pub pixels: u32,
    /// PNG: leave out the solids of the octant facing the camera, or of the front half.
    #[arg(long, value_enum, default_value = "none")]
    pub cut: CutArg,
    /// SVG: cut the region into sheets THICKNESS mm thick and write every sheet's sections,
    /// one layer per sheet, with registration marks.
    #[arg(long, value_parser = spec::length, allow_hyphen_values = true)]
    pub slices: Option<f64>,
    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solids_and_regions_parse() {
        assert_eq!(solid("cube"), Ok(SolidArg(vec![Solid::Cube])));
        assert_eq!(
            solid("mix:sphere,torus:0.3").map(|s| s.name()),
            Ok("mix:sphere,torus:0.3".to_string())
        );
        assert!(solid("torus:1.5").is_err() && solid("shell").is_err() && solid("cube:2").is_err());
        assert_eq!(region("ball:5"), Ok(Region3::Ball { r: 5.0 }));
        assert!(region("boxball:10:10:10:6").is_err() && region("box:1:2").is_err());
    }
}
