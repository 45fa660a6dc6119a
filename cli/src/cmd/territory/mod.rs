//! `zetafill territory`: Sugihara's Voronoi territory competing (K. Sugihara, *Artistic
//! Pattern Generation by a Model of Territory Competing*): k seeds, then points one by one
//! joining the territory of their nearest site ([`model`]), territories kept connected,
//! density control near the boundaries, colours by graph distance from the seed
//! ([`colour`]), drawn as boundary polylines, cells, filled cells or a fill's own shapes
//! ([`render`]). Sites may come from a fill's JSON (`--sites-from`).

pub mod colour;
use crate::geometry::voronoi as geom;
pub mod model;
pub mod render;

use crate::args::spec::RegionSpec;
use crate::cmd::fill::region::RegionData;
use crate::error::CliError;
use crate::io::write::Dest;
use crate::model::doc::RegionDoc;
use colour::Rule;
use geom::{Clip, Pt};
use model::{Growth, Model, ModelError};
use render::{FillShape, Render, Style};
use serde::Serialize;
use serde_json::Value;
use std::io::IsTerminal;
use std::path::Path;

pub use crate::args::territory::{TerritoryArgs, TerritoryFormat, MAX_POINTS};

/// Refuses the plot flags that have no meaning for territories, before any work.
fn check_plot(a: &TerritoryArgs, format: TerritoryFormat) -> Result<(), CliError> {
    let p = &a.plot;
    let not_here = |flag: &str, why: &str| Err(CliError::arg(flag, format!("is not available for territory: {why}")));
    if p.hatch.is_some() || p.hatch_only {
        return not_here("--hatch", "territories are drawn as lines");
    }
    if p.min_feature > 0.0 {
        return not_here("--min-feature", "every boundary edge is drawn");
    }
    if p.layers != crate::args::plot::Layers::None {
        return not_here("--layers", "the SVG has its own layers (cells, boundaries, outline)");
    }
    if p.page.is_some() {
        return not_here("--page", "the SVG is drawn at the region's size");
    }
    if format == TerritoryFormat::Gcode {
        if !matches!(a.render, Render::Boundaries | Render::Cells) {
            return Err(CliError::arg("--render", "G-code draws lines: use --render boundaries or cells"));
        }
        let m = p.machine()?;
        p.gcode_options(&m)?;
    } else if p.fit || p.center {
        return Err(CliError::arg(
            if p.fit { "--fit" } else { "--center" },
            "places the drawing on a machine's bed: it is for G-code output",
        ));
    } else {
        p.refuse_except(&[], |_| crate::args::plot::FOR_GCODE.to_string())?;
    }
    Ok(())
}

/// How territories take a palette's colours unless `--color-by` says: in turn.
const COLOUR_BY: crate::output::palette::ColorBy = crate::output::palette::ColorBy::Cycle;

/// Refuses colour flags where nothing shows them or where they clash with `--color`.
fn check_colours(a: &TerritoryArgs, format: TerritoryFormat) -> Result<(), CliError> {
    let shown = matches!(format, TerritoryFormat::Svg | TerritoryFormat::Png) && matches!(a.render, Render::Filled | Render::Shapes);
    a.colours
        .check(shown, "use --render filled or shapes with an .svg or .png output", true)?;
    if a.colours.palette.is_some() && !a.colors.is_empty() {
        return Err(CliError::arg("--palette", "replaces the --color rules; give one or the other"));
    }
    Ok(())
}

/// The picture as G-code: its strokes (boundary polylines, with `cells` every other Voronoi
/// edge, with `--boundary` the region's outline) placed on the machine's bed by the region's
/// box, written by the plot back end with its safety invariants.
fn gcode(pic: &crate::model::Picture, a: &TerritoryArgs, desc: String) -> Result<Vec<u8>, CliError> {
    let gcode = crate::plan::plot::GcodePlan::resolve(&a.plot)?;
    crate::cmd::plot::pens_gcode(&pic.pens(), &pic.frame, &gcode, vec![desc], a.quiet)
}

/// One site in the JSON output.
#[derive(Debug, Clone, Serialize)]
pub struct SiteDoc {
    /// Insertion order (the first k are the seeds).
    pub index: usize,
    /// Position (mm).
    pub point: [f64; 2],
    /// Territory 0..k-1.
    pub territory: u32,
    /// Graph distance from the territory's seed (Procedure 2).
    pub distance: u32,
    /// HSB colour, each in [0, 1].
    pub color: [f64; 3],
    /// With --sites-from: the index of the fill's shape this site is the centre of.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<u64>,
}

/// A territory's colour rule in the JSON output.
#[derive(Debug, Clone, Serialize)]
pub struct RuleDoc {
    /// c^k.
    pub c: [f64; 3],
    /// d^k.
    pub d: [f64; 3],
}

/// The parameters of a territory run.
#[derive(Debug, Clone, Serialize)]
pub struct TerritoryParamsDoc {
    /// RNG seed.
    pub seed: u64,
    /// Total number of sites asked for.
    pub points: usize,
    /// Density control on or off.
    pub uniform: bool,
    /// The paper's n0.
    pub n0: u64,
    /// The paper's s.
    pub s: f64,
    /// Weight of a boundary bucket.
    pub boost: f64,
    /// What the SVG draws.
    pub render: &'static str,
    /// The fill the sites came from.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sites_from: Option<String>,
    /// Per-territory colour rules.
    pub colors: Vec<RuleDoc>,
}

/// Per-territory figures.
#[derive(Debug, Clone, Serialize)]
pub struct TerritoryStatsDoc {
    /// Sites in the territory.
    pub sites: usize,
    /// Largest distance from the seed.
    pub max_distance: u32,
}

/// Run statistics.
#[derive(Debug, Clone, Serialize)]
pub struct StatsDoc {
    /// Sites in all.
    pub sites: usize,
    /// Per territory.
    pub territories: Vec<TerritoryStatsDoc>,
    /// Sites handed over by connectivity repairs.
    pub reassigned: u64,
    /// Insertions after which a component was handed over.
    pub repairs: u64,
    /// Sites visited by repair searches, in all.
    pub repair_visits: u64,
    /// The most sites one insertion's repair visited.
    pub max_repair_visits: u64,
    /// Random draws rejected (outside the region or on a site).
    pub rejected: u64,
    /// Boundary polylines after merging and clipping.
    pub boundary_polylines: usize,
    /// Total boundary length (mm).
    pub boundary_length: f64,
}

/// The JSON document of a territory run (DESIGN section 3).
#[derive(Debug, Clone, Serialize)]
pub struct TerritoryDoc {
    /// Format version (1).
    pub version: u32,
    /// `"territory"`.
    pub mode: &'static str,
    /// Number of seeds k (= territories).
    pub seeds: usize,
    /// Parameters.
    pub params: TerritoryParamsDoc,
    /// The region in its own frame.
    pub region: RegionDoc,
    /// Sites in insertion order.
    pub sites: Vec<SiteDoc>,
    /// Statistics.
    pub stats: StatsDoc,
}

/// A finished run: the model, the document and what the drawing needs.
#[derive(Debug)]
pub struct Outcome {
    /// The grown pattern.
    pub model: Model,
    /// The region.
    pub clip: Clip,
    /// The JSON document.
    pub doc: TerritoryDoc,
    /// The fill's shapes in site order (with --sites-from).
    pub shapes: Vec<FillShape>,
    /// The boundary polylines.
    pub boundaries: Vec<Vec<Pt>>,
}

/// Where the sites come from.
struct Source {
    region: RegionDoc,
    /// Centres in fill order, and their shapes.
    centres: Vec<(Pt, u64, FillShape)>,
    name: String,
}

fn bad_from(path: &Path, msg: impl std::fmt::Display) -> CliError {
    CliError::arg("--sites-from", format!("'{}': {msg}", path.display()))
}

fn num_pair(v: &Value) -> Option<Pt> {
    let a = v.as_array()?;
    match a.as_slice() {
        [x, y] => Some([x.as_f64()?, y.as_f64()?]),
        _ => None,
    }
}

fn load_source(path: &Path) -> Result<Source, CliError> {
    let bytes = std::fs::read(path).map_err(|e| bad_from(path, format!("cannot read it ({e})")))?;
    let v: Value = serde_json::from_slice(&bytes).map_err(|e| bad_from(path, format!("not JSON ({e}); give a fill's JSON output")))?;
    if v.get("mode").and_then(Value::as_str) != Some("fill") {
        return Err(bad_from(
            path,
            "not a fill's JSON (no \"mode\": \"fill\"); write one with zetafill fill -o FILE.json",
        ));
    }
    let r = v.get("region").ok_or_else(|| bad_from(path, "no region"))?;
    let f = |k: &str| r.get(k).and_then(Value::as_f64).filter(|x| x.is_finite());
    let ring = |x: &Value| -> Option<Vec<Pt>> { x.as_array()?.iter().map(num_pair).collect() };
    let region = match r.get("kind").and_then(Value::as_str) {
        Some("rect") => f("width").zip(f("height")).map(|(width, height)| RegionDoc::Rect {
            width,
            height,
            periodic: false,
        }),
        Some("circle") => r
            .get("center")
            .and_then(num_pair)
            .zip(f("radius"))
            .map(|(center, radius)| RegionDoc::Circle { center, radius }),
        Some("annulus") => match (r.get("center").and_then(num_pair), f("radius_outer"), f("radius_inner")) {
            (Some(center), Some(radius_outer), Some(radius_inner)) => Some(RegionDoc::Annulus {
                center,
                radius_outer,
                radius_inner,
            }),
            _ => None,
        },
        Some("polygon") => {
            let list =
                |k: &str| -> Option<Vec<Vec<Pt>>> { r.get(k).map_or(Some(Vec::new()), |x| x.as_array()?.iter().map(ring).collect()) };
            match (r.get("vertices").and_then(ring), list("holes"), list("outers")) {
                (Some(vertices), Some(holes), Some(outers)) if vertices.len() >= 3 => Some(RegionDoc::Polygon { vertices, holes, outers }),
                _ => None,
            }
        }
        _ => None,
    }
    .ok_or_else(|| bad_from(path, "its region is malformed"))?;
    let shapes = v
        .get("shapes")
        .and_then(Value::as_array)
        .ok_or_else(|| bad_from(path, "no shapes"))?;
    let mut centres = Vec::with_capacity(shapes.len());
    for (i, s) in shapes.iter().enumerate() {
        let c = s
            .get("center")
            .and_then(num_pair)
            .filter(|c| c[0].is_finite() && c[1].is_finite())
            .ok_or_else(|| bad_from(path, format!("shape {i} has no centre")))?;
        let index = s.get("index").and_then(Value::as_u64).unwrap_or(i as u64);
        let radius = s.get("radius").and_then(Value::as_f64);
        let shape = match (
            radius,
            s.get("inner_radius").and_then(Value::as_f64),
            s.get("vertices").and_then(ring),
        ) {
            (Some(r), Some(inner), _) => FillShape::Ring { c, r, inner },
            (Some(r), None, _) => FillShape::Circle { c, r },
            (None, _, Some(vs)) => FillShape::Poly(vs),
            _ => FillShape::Circle { c, r: 0.0 },
        };
        centres.push((c, index, shape));
    }
    Ok(Source {
        region,
        centres,
        name: path.display().to_string(),
    })
}

/// The `zetafill territory` command line that reproduces a run.
fn command_line(a: &TerritoryArgs, k: usize, points: usize, region: &str) -> String {
    let mut s = String::from("zetafill territory");
    if let Some(p) = &a.sites_from {
        s.push_str(&format!(" --sites-from {}", p.display()));
    } else {
        s.push_str(&format!(" --points {points} --region {region}"));
    }
    if a.site.is_empty() {
        s.push_str(&format!(" --sites {k}"));
    }
    for p in &a.site {
        s.push_str(&format!(" --site {},{}", p[0], p[1]));
    }
    s.push_str(&format!(" --seed {}", a.seed.seed));
    if a.uniform {
        s.push_str(" --uniform");
    } else {
        s.push_str(&format!(" --n0 {} --s {} --boost {}", a.n0, a.s, a.boost));
    }
    for (c, d) in &a.colors {
        s.push_str(&format!(" --color {},{},{}", c[0], c[1], c[2]));
        if let Some(d) = d {
            s.push_str(&format!(":{},{},{}", d[0], d[1], d[2]));
        }
    }
    s.push_str(&format!(" --render {}", a.render.name()));
    s.push_str(&a.colours.flags_or(COLOUR_BY));
    if a.pen_width != 0.3 {
        s.push_str(&format!(" --pen-width {}", a.pen_width));
    }
    if a.thin_width != 0.1 {
        s.push_str(&format!(" --thin-width {}", a.thin_width));
    }
    if a.boundary {
        s.push_str(" --boundary");
    }
    s.push_str(&a.plot.flags());
    s
}

fn model_error(flag: &str, e: ModelError) -> CliError {
    CliError::arg(flag, e)
}

/// Runs the territory competition and builds the document. Nothing is written.
pub fn compute(a: &TerritoryArgs) -> Result<Outcome, CliError> {
    if a.site.len() == 1 {
        return Err(CliError::arg(
            "--site",
            "territory competing needs at least 2 seeds; give --site twice or more, or --sites K",
        ));
    }
    if a.render == Render::Shapes && a.sites_from.is_none() {
        return Err(CliError::arg(
            "--render",
            "shapes draws a fill's shapes: it needs --sites-from FILE.json; use boundaries, cells or filled",
        ));
    }
    let mut rng = zetafill::rng_from_seed(a.seed.seed);
    let (region, source) = match &a.sites_from {
        Some(p) => {
            let src = load_source(p)?;
            (src.region.clone(), Some(src))
        }
        None => {
            let data = RegionData::load(&a.region)?;
            let r = data.region(false)?;
            (data.doc(&r), None)
        }
    };
    let clip = Clip::from_doc(&region);
    let k = if a.site.is_empty() { a.sites.unwrap_or(3) } else { a.site.len() };
    for (i, p) in a.site.iter().enumerate() {
        if !clip.inside(*p) {
            return Err(CliError::arg(
                "--site",
                format!("{},{} lies outside the region; give seeds inside it", p[0], p[1]),
            ));
        }
        if a.site[..i].contains(p) {
            return Err(CliError::arg(
                "--site",
                format!("{},{} is given twice; seeds must be distinct points", p[0], p[1]),
            ));
        }
    }
    let bar = |n: usize| -> Option<indicatif::ProgressBar> {
        if a.quiet || !std::io::stderr().is_terminal() || n < 200_000 {
            return None;
        }
        let b = indicatif::ProgressBar::new(n as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} sites, {elapsed} (eta {eta})") {
            b.set_style(style);
        }
        Some(b)
    };
    let (model, points, shapes, source_index, name) = match source {
        Some(src) => {
            let n = src.centres.len();
            if k > n {
                let flag = if a.site.is_empty() { "--sites" } else { "--site" };
                return Err(CliError::arg(
                    flag,
                    format!("{k} seeds but the fill has only {n} shapes; ask for fewer seeds (more sites than points)"),
                ));
            }
            // Seed order: chosen centres first, then the rest in fill order.
            let mut order: Vec<usize> = (0..n).collect();
            if a.site.is_empty() {
                for i in 0..k {
                    let j = i + (zetafill::internals::rng::unit::<f64, _>(&mut rng) * (n - i) as f64) as usize;
                    order.swap(i, j.min(n - 1));
                }
            } else {
                for (i, p) in a.site.iter().enumerate() {
                    let best = (0..n)
                        .min_by(|&x, &y| {
                            geom::dist2(src.centres[x].0, *p)
                                .total_cmp(&geom::dist2(src.centres[y].0, *p))
                                .then(x.cmp(&y))
                        })
                        .unwrap_or(0);
                    let at = order.iter().position(|&o| o == best).unwrap_or(0);
                    if at < i {
                        return Err(CliError::arg(
                            "--site",
                            format!(
                                "{},{} picks the same centre as an earlier --site; give seeds farther apart",
                                p[0], p[1]
                            ),
                        ));
                    }
                    order.swap(i, at);
                }
            }
            let mut rest: Vec<usize> = order[k..].to_vec();
            rest.sort_unstable();
            order.truncate(k);
            order.extend(rest);
            let seeds: Vec<Pt> = order[..k].iter().map(|&i| src.centres[i].0).collect();
            let mut m = Model::new(&seeds).map_err(|e| model_error("--sites-from", e))?;
            let b = bar(n);
            for &i in &order[k..] {
                m.add(src.centres[i].0)
                    .map_err(|e| bad_from(Path::new(&src.name), format!("shape {}: {e}", src.centres[i].1)))?;
                if let Some(b) = &b {
                    b.inc(1);
                }
            }
            if let Some(b) = b {
                b.finish_and_clear();
            }
            let shapes = order.iter().map(|&i| src.centres[i].2.clone()).collect();
            let idx = order.iter().map(|&i| Some(src.centres[i].1)).collect();
            (m, n, shapes, idx, Some(src.name))
        }
        None => {
            let points = a.points.map_or(7000, |p| p as usize);
            if k > points {
                let flag = if a.site.is_empty() { "--sites" } else { "--site" };
                return Err(CliError::arg(
                    flag,
                    format!("{k} seeds but only --points {points}: more sites than points; raise --points or give fewer seeds"),
                ));
            }
            let seeds: Vec<Pt> = if a.site.is_empty() {
                let bbox = clip.bbox();
                let mut v: Vec<Pt> = Vec::with_capacity(k);
                let mut tries = 0u64;
                while v.len() < k {
                    tries += 1;
                    if tries > 100_000_000 {
                        return Err(CliError::arg("--region", "no seed could be drawn inside the region"));
                    }
                    let p = [
                        zetafill::internals::rng::uniform(&mut rng, bbox.0, bbox.2),
                        zetafill::internals::rng::uniform(&mut rng, bbox.1, bbox.3),
                    ];
                    if clip.inside(p) && !v.contains(&p) {
                        v.push(p);
                    }
                }
                v
            } else {
                a.site.clone()
            };
            let mut m = Model::new(&seeds).map_err(|e| model_error("--site", e))?;
            let g = Growth {
                points,
                n0: a.n0 as usize,
                s: a.s,
                boost: a.boost,
                uniform: a.uniform,
            };
            let b = bar(points);
            m.grow(&clip, &g, &mut rng, |_| {
                if let Some(b) = &b {
                    b.inc(1);
                }
            })
            .map_err(|e| model_error("--region", e))?;
            if let Some(b) = b {
                b.finish_and_clear();
            }
            (m, points, Vec::new(), vec![None; points], None)
        }
    };
    if a.colors.len() > k {
        return Err(CliError::arg(
            "--color",
            format!("{} colours for {k} territories; give at most one per territory", a.colors.len()),
        ));
    }
    let dist = colour::distances(&model.tri, &model.territory, k);
    let mut maxd = vec![0u32; k];
    let mut count = vec![0usize; k];
    for (t, d) in model.territory.iter().zip(&dist) {
        let t = *t as usize;
        count[t] += 1;
        if *d != u32::MAX {
            maxd[t] = maxd[t].max(*d);
        }
    }
    // Colours from their own stream, so they never move the geometry.
    let mut crng = zetafill::rng_from_seed(a.seed.seed ^ 0x436f_6c6f_7572_7321);
    let rules: Vec<Rule> = (0..k)
        .map(|t| {
            let r = colour::random_rule(&mut crng, maxd[t]);
            match a.colors.get(t) {
                Some((c, Some(d))) => Rule { c: *c, d: *d },
                Some((c, None)) => Rule { c: *c, d: r.d },
                None => r,
            }
        })
        .collect();
    let sites: Vec<SiteDoc> = (0..model.len())
        .map(|i| {
            let t = model.territory[i];
            SiteDoc {
                index: i,
                point: model.sites[i],
                territory: t,
                distance: dist[i],
                color: colour::colour(&rules[t as usize], dist[i]),
                shape: source_index.get(i).copied().flatten(),
            }
        })
        .collect();
    let boundaries = render::boundaries(&model, &clip);
    let length = boundaries
        .iter()
        .flat_map(|l| l.windows(2))
        .map(|w| geom::dist2(w[0], w[1]).sqrt())
        .sum();
    let c = model.counters;
    let doc = TerritoryDoc {
        version: 1,
        mode: "territory",
        seeds: k,
        params: TerritoryParamsDoc {
            seed: a.seed.seed,
            points,
            uniform: a.uniform,
            n0: a.n0,
            s: a.s,
            boost: a.boost,
            render: a.render.name(),
            sites_from: name,
            colors: rules.iter().map(|r| RuleDoc { c: r.c, d: r.d }).collect(),
        },
        region,
        sites,
        stats: StatsDoc {
            sites: model.len(),
            territories: (0..k)
                .map(|t| TerritoryStatsDoc {
                    sites: count[t],
                    max_distance: maxd[t],
                })
                .collect(),
            reassigned: c.reassigned,
            repairs: c.repairs,
            repair_visits: c.visited,
            max_repair_visits: c.max_visited,
            rejected: c.rejected,
            boundary_polylines: boundaries.len(),
            boundary_length: length,
        },
    };
    Ok(Outcome {
        model,
        clip,
        doc,
        shapes,
        boundaries,
    })
}

/// Renders a finished run.
pub fn render_bytes(o: &Outcome, a: &TerritoryArgs, format: TerritoryFormat) -> Result<Vec<u8>, CliError> {
    let desc = command_line(a, o.doc.seeds, o.doc.params.points, &o.doc.region.arg());
    let picture = || {
        let style = Style {
            render: a.render,
            pen_width: a.pen_width,
            thin_width: a.thin_width,
            outline: a.boundary,
            background: a.colours.background.as_deref(),
            flat: a.colours.palette.is_some(),
        };
        let mut pic = render::picture(o, &site_colours(o, a), &style);
        pic.title = format!(
            "zetafill territory: {} sites, {} territories, seed {}",
            o.doc.sites.len(),
            o.doc.seeds,
            a.seed.seed
        );
        pic.desc.clone_from(&desc);
        pic
    };
    Ok(match format {
        TerritoryFormat::Gcode => gcode(&picture(), a, desc.clone())?,
        TerritoryFormat::Svg => crate::output::svg::write(&picture()),
        TerritoryFormat::Png => a.raster.raster().render(&crate::output::svg::write(&picture()))?,
        TerritoryFormat::Json => {
            let mut v = serde_json::to_vec(&o.doc).map_err(|e| CliError::Io(format!("cannot encode JSON: {e}")))?;
            v.push(b'\n');
            v
        }
    })
}

/// Each site's colour as `#rrggbb`: its HSB colour, or with `--palette` the palette's by
/// `--color-by`: `cycle` and `random` by territory, `size` by the area of what is drawn for
/// the site (its cell within the region's box, or with `--render shapes` its shape).
fn site_colours(o: &Outcome, a: &TerritoryArgs) -> Vec<String> {
    let Some(p) = &a.colours.palette else {
        return o.doc.sites.iter().map(|s| colour::hex(s.color)).collect();
    };
    let areas: Vec<f64> = if a.render == Render::Shapes {
        o.shapes.iter().map(FillShape::area).collect()
    } else {
        render::cells(&o.model, &o.clip).iter().map(|c| geom::area(c).abs()).collect()
    };
    let items: Vec<(u64, f64)> = o
        .doc
        .sites
        .iter()
        .zip(areas.iter().chain(std::iter::repeat(&0.0)))
        .map(|(s, &area)| (u64::from(s.territory), area))
        .collect();
    crate::output::palette::assign_items(&p.0, a.colours.by_or(COLOUR_BY), a.seed.seed, &items, |_| 0)
}

/// `zetafill territory`.
pub fn run(a: &TerritoryArgs) -> Result<(), CliError> {
    let dest = Dest::parse(&a.output.output);
    let mut inputs: Vec<&Path> = a.plot.machine_file().into_iter().collect();
    if let Some(p) = &a.sites_from {
        inputs.push(p.as_path());
    }
    if let RegionSpec::Svg(p) = &a.region {
        inputs.push(p.as_path());
    }
    dest.check("--output", &inputs)?;
    let bytes = output(a)?;
    dest.write(&bytes)
}

/// The bytes `zetafill territory` writes: the flags checked, the pattern grown and rendered.
pub fn output(a: &TerritoryArgs) -> Result<Vec<u8>, CliError> {
    let format = TerritoryFormat::resolve(a.output.format, &a.output.output)?;
    a.raster.check(format == TerritoryFormat::Png)?;
    check_plot(a, format)?;
    check_colours(a, format)?;
    let o = compute(a)?;
    render_bytes(&o, a, format)
}
