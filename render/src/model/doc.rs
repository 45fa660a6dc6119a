//! The result of a fill as one plain data model, shared by every output format (and
//! serialised as is for JSON, docs/cli.md, Outputs, `version` 1).

use super::Path;
use serde::Serialize;
use zetafill::ShapeKind;

/// A finished (or halted) fill.
#[derive(Debug, Clone, Serialize)]
pub struct FillDoc {
    /// Format version (1).
    pub version: u32,
    /// `"fill"`.
    pub mode: &'static str,
    /// Everything needed to reproduce the run.
    pub params: ParamsDoc,
    /// The region in its own frame (mm, x right, y up).
    pub region: RegionDoc,
    /// The region's area A.
    pub area: f64,
    /// zeta(c, N).
    pub zeta: f64,
    /// Shapes in placement order.
    pub shapes: Vec<ShapeDoc>,
    /// Run statistics.
    pub stats: StatsDoc,
    /// The determinism digest (count, FNV-1a) of the engine's own bits, when known.
    #[serde(skip)]
    pub digest: Option<(u64, u64)>,
}

/// The parameters of a run, as its JSON writes them: the power law, the seed, the
/// mode's own parameters `E` (in their place, after the seed), the gap and the stops. A fill's
/// are [`ParamsDoc`]; a 1D fill has none of its own.
#[derive(Debug, Clone, Serialize)]
pub struct RunParamsDoc<E> {
    /// Exponent c.
    pub c: f64,
    /// The paper's N.
    pub n_offset: f64,
    /// RNG seed.
    pub seed: u64,
    /// The mode's own parameters.
    #[serde(flatten)]
    pub of: E,
    /// Clearance in mm.
    pub gap: f64,
    /// Stop after this many pieces.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count: Option<u64>,
    /// Stop at this fill fraction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill: Option<f64>,
    /// Stop before the first piece narrower (shorter) than this (mm).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_size: Option<f64>,
    /// Trial limit per placement.
    pub max_trials: u64,
    /// The fractal dimension: D = 2/c for a fill, 1/c for a 1D fill.
    pub dimension: f64,
}

/// The parameters of a fill.
pub type ParamsDoc = RunParamsDoc<ShapeParamsDoc>;

/// What only a 2D fill has: its shapes, rotation, sampler and scalar.
#[derive(Debug, Clone, Serialize)]
pub struct ShapeParamsDoc {
    /// Shape as written on the command line.
    pub shape: String,
    /// `none` or `random`.
    pub rotate: &'static str,
    /// For a mix of shapes: `cycle` or `random` (`--mix-order`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mix_order: Option<&'static str>,
    /// Sampler name.
    pub sampler: &'static str,
    /// Engine number type: `f64` or `fixed`.
    pub scalar: &'static str,
    /// The cells lent to the cell sampler, when `--cells` chose them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cells: Option<u64>,
    /// The largest batch, with the batched sampler (`--batch`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub batch: Option<u64>,
    /// `--density`, written in full, when given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub density: Option<String>,
    /// The SHA-256 of the `--density` picture.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub density_sha256: Option<String>,
    /// The SHA-256 of each SVG motif's file (`--shape svg:FILE`), in the order `--shape` names
    /// them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub motif_sha256: Option<Vec<String>>,
    /// For a region made from a picture or a text: `region` (the `--region` argument) and the
    /// flags that go with it.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub source: Option<super::region::RegionSource>,
}

/// A region, in its own frame (mm, x right, y up).
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum RegionDoc {
    /// `[0, width] x [0, height]`.
    Rect {
        /// Width (mm).
        width: f64,
        /// Height (mm).
        height: f64,
        /// Toroidal boundary.
        periodic: bool,
    },
    /// A disc.
    Circle {
        /// Centre.
        center: [f64; 2],
        /// Radius.
        radius: f64,
    },
    /// A ring-shaped region.
    Annulus {
        /// Centre.
        center: [f64; 2],
        /// Outer radius.
        radius_outer: f64,
        /// Inner radius.
        radius_inner: f64,
    },
    /// Outlines filled by the even-odd rule.
    Polygon {
        /// The first outer outline.
        vertices: Vec<[f64; 2]>,
        /// Outlines inside an odd number of others (holes).
        holes: Vec<Vec<[f64; 2]>>,
        /// Further outer outlines (islands), when there are several.
        #[serde(skip_serializing_if = "Vec::is_empty")]
        outers: Vec<Vec<[f64; 2]>>,
    },
    /// The plane with the symmetry of a wallpaper group: the shapes are the orbits'
    /// representatives, the pattern is drawn over `repeat` cells from the origin, or cut to
    /// `window`.
    Wallpaper {
        /// The group's short name (`p4m`, ...).
        group: String,
        /// `--lattice` as used: sides a and b (mm) and the angle between them (degrees).
        lattice: [f64; 3],
        /// The primitive lattice vectors `a = (ax, 0)` and `b = (bx, by)`: `[ax, bx, by]`.
        vectors: [f64; 3],
        /// The images of a shape in one primitive cell.
        order: usize,
        /// Cells drawn across and up (`--repeat`), when no window is given.
        #[serde(skip_serializing_if = "Option::is_none")]
        repeat: Option<[u32; 2]>,
        /// The width of what is drawn: `repeat` cells of the conventional cell's size, or
        /// the window's bounding box.
        width: f64,
        /// Its height.
        height: f64,
        /// The region the pattern is cut to (`--region`), when given.
        #[serde(skip_serializing_if = "Option::is_none")]
        window: Option<Box<RegionDoc>>,
    },
}

impl RegionDoc {
    /// The `--region` argument that makes this region again. An outline lists its rings in
    /// the order the core was given them (the outer outlines, then the holes), separated by
    /// `/`, each number in shortest round-trip form, so an `svg:FILE` region is reproduced
    /// without its file.
    pub fn arg(&self) -> String {
        let ring = |r: &[[f64; 2]]| r.iter().map(|v| format!("{},{}", v[0], v[1])).collect::<Vec<_>>().join(",");
        match self {
            RegionDoc::Rect { width, height, .. } => format!("rect:{width}:{height}"),
            RegionDoc::Circle { radius, .. } => format!("circle:{radius}"),
            RegionDoc::Annulus {
                radius_outer,
                radius_inner,
                ..
            } => format!("annulus:{radius_outer}:{radius_inner}"),
            RegionDoc::Polygon { vertices, holes, outers } => {
                let rings = std::iter::once(vertices).chain(outers).chain(holes);
                format!("polygon:{}", rings.map(|r| ring(r)).collect::<Vec<_>>().join("/"))
            }
            RegionDoc::Wallpaper { window: Some(w), .. } => w.arg(),
            RegionDoc::Wallpaper { width, height, .. } => format!("rect:{width}:{height}"),
        }
    }

    /// The region's outline as one even-odd path: closed polylines (the outer outlines, then
    /// the holes) or full circles.
    pub fn outline(&self) -> Vec<Path> {
        match self {
            RegionDoc::Wallpaper { window: Some(w), .. } => w.outline(),
            RegionDoc::Rect { width, height, .. } | RegionDoc::Wallpaper { width, height, .. } => vec![Path::polyline(
                vec![[0.0, 0.0], [*width, 0.0], [*width, *height], [0.0, *height]],
                true,
            )],
            RegionDoc::Circle { center, radius } => vec![Path::circle(*center, *radius)],
            RegionDoc::Annulus {
                center,
                radius_outer,
                radius_inner,
            } => vec![Path::circle(*center, *radius_outer), Path::circle(*center, *radius_inner)],
            RegionDoc::Polygon { vertices, holes, outers } => std::iter::once(vertices)
                .chain(outers)
                .chain(holes)
                .map(|r| Path::polyline(r.clone(), true))
                .collect(),
        }
    }
}

/// One placed shape.
#[derive(Debug, Clone, Serialize)]
pub struct ShapeDoc {
    /// Placement index.
    pub index: u64,
    /// `circle`, `square`, `rect`, `triangle`, `polygon`, `star`, `ring`, `blob`, `noisy`,
    /// `motif`.
    pub kind: &'static str,
    /// Centre (mm).
    pub center: [f64; 2],
    /// Radius (circles), outer radius (rings).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Inner radius (rings).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inner_radius: Option<f64>,
    /// Rotation in radians, counter-clockwise (polygonal kinds).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle: Option<f64>,
    /// Nominal area A_i.
    pub area: f64,
    /// Trials this placement took.
    pub trials: u64,
    /// Vertices counter-clockwise (polygonal kinds): exactly the polygon that was tested.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vertices: Option<Vec<[f64; 2]>>,
    /// The rings of a motif (filled by the even-odd rule): exactly the outline that was
    /// tested.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outlines: Option<Vec<Vec<[f64; 2]>>>,
    /// A motif's decorations: polylines drawn with it and never tested.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub decorations: Option<Vec<Vec<[f64; 2]>>>,
}

/// Run statistics.
#[derive(Debug, Clone, Serialize)]
pub struct StatsDoc {
    /// Shapes placed.
    pub placed: u64,
    /// Trials in all.
    pub trials: u64,
    /// Placed area over region area.
    pub fill_fraction: f64,
    /// Whether the run halted at the trial limit.
    pub halted: bool,
    /// Why the run stopped: `count`, `fill`, `min-size` or `halted`.
    pub stop: &'static str,
}

impl FillDoc {
    /// The region's bounding box (min x, min y, max x, max y).
    pub fn bbox(&self) -> (f64, f64, f64, f64) {
        self.region.bbox()
    }

    /// Width and height of the region's bounding box.
    pub fn extent(&self) -> (f64, f64) {
        let (x0, y0, x1, y1) = self.bbox();
        (x1 - x0, y1 - y0)
    }

    /// Whether the region is periodic.
    pub fn periodic(&self) -> bool {
        matches!(self.region, RegionDoc::Rect { periodic: true, .. })
    }

    /// The wallpaper group of a symmetric fill, with its lattice.
    pub fn wallpaper(&self) -> Option<zetafill::Wallpaper> {
        match &self.region {
            RegionDoc::Wallpaper { group, lattice, .. } => {
                let g = zetafill::Group::from_name(group)?;
                zetafill::Wallpaper::new(g, lattice[0], lattice[1], lattice[2]).ok()
            }
            _ => None,
        }
    }
}

/// The name of a shape as written in JSON and on the command line.
pub fn shape_name(k: &ShapeKind) -> String {
    match k {
        ShapeKind::Circle => "circle".into(),
        ShapeKind::Square => "square".into(),
        ShapeKind::Rect { aspect } => format!("rect:{aspect}"),
        ShapeKind::Triangle => "triangle".into(),
        ShapeKind::Polygon { sides } => format!("polygon:{sides}"),
        ShapeKind::Star { points, inner } => format!("star:{points}:{inner}"),
        ShapeKind::Ring { inner } => format!("ring:{inner}"),
        ShapeKind::Blob { delta } => format!("blob:{delta}"),
        ShapeKind::Noisy {
            amplitude,
            features,
            octaves,
        } => format!("noisy:{amplitude}:{features}:{octaves}"),
        ShapeKind::Motif { id, .. } => format!("motif:{id}"),
    }
}

/// The kind name of a shape in JSON (`"kind"`).
pub fn kind_name(k: &ShapeKind) -> &'static str {
    match k {
        ShapeKind::Circle => "circle",
        ShapeKind::Square => "square",
        ShapeKind::Rect { .. } => "rect",
        ShapeKind::Triangle => "triangle",
        ShapeKind::Polygon { .. } => "polygon",
        ShapeKind::Star { .. } => "star",
        ShapeKind::Ring { .. } => "ring",
        ShapeKind::Blob { .. } => "blob",
        ShapeKind::Noisy { .. } => "noisy",
        ShapeKind::Motif { .. } => "motif",
    }
}

impl RegionDoc {
    /// The bounding box (min x, min y, max x, max y) of what is drawn.
    pub fn bbox(&self) -> (f64, f64, f64, f64) {
        match self {
            RegionDoc::Wallpaper { window: Some(w), .. } => w.bbox(),
            RegionDoc::Rect { width, height, .. } | RegionDoc::Wallpaper { width, height, .. } => (0.0, 0.0, *width, *height),
            RegionDoc::Circle { center, radius: r }
            | RegionDoc::Annulus {
                center, radius_outer: r, ..
            } => (center[0] - r, center[1] - r, center[0] + r, center[1] + r),
            RegionDoc::Polygon { vertices, holes, outers } => {
                let all = vertices.iter().chain(holes.iter().flatten()).chain(outers.iter().flatten());
                all.fold((f64::MAX, f64::MAX, f64::MIN, f64::MIN), |b, v| {
                    (b.0.min(v[0]), b.1.min(v[1]), b.2.max(v[0]), b.3.max(v[1]))
                })
            }
        }
    }
}
