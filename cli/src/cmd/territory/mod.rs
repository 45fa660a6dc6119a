//! `zetafill territory`: Sugihara's Voronoi territory competing (K. Sugihara, *Artistic
//! Pattern Generation by a Model of Territory Competing*): k seeds, then points one by one
//! joining the territory of their nearest site ([`model`]), territories kept connected,
//! density control near the boundaries, colours by graph distance from the seed
//! ([`colour`]), drawn as boundary polylines, cells, filled cells or a fill's own shapes
//! ([`render`]). Sites may come from a fill's JSON (`--sites-from`).

pub mod colour;
use crate::geometry::voronoi as geom;
pub mod doc;
pub mod model;
pub mod render;
pub mod source;

use crate::cmd::fill::region::RegionData;
use crate::error::CliError;
use crate::plan::raster::png_error;
use crate::plan::territory::Render;
use crate::plan::territory::{fill_seeds_error, growth_error, no_seed_drawn, same_centre, seeds_error, sites_from_error};
use crate::plan::territory::{TerritoryDraw, TerritoryPlan, TerritoryRun};
use colour::Rule;
use doc::{RuleDoc, SiteDoc, StatsDoc, TerritoryDoc, TerritoryParamsDoc, TerritoryStatsDoc};
use geom::{Clip, Pt};
use model::{Growth, Model};
use render::{FillShape, Style};
use source::load_source;
use std::path::Path;

use crate::plan::format::TerritoryFormat;

/// The picture as G-code: its strokes (boundary polylines, with `cells` every other Voronoi
/// edge, with `--boundary` the region's outline) placed on the machine's bed by the region's
/// box, written by the plot back end with its safety invariants.
fn gcode(pic: &crate::model::Picture, d: &TerritoryDraw, desc: String) -> Result<Vec<u8>, CliError> {
    let gcode = d.gcode.as_ref().ok_or_else(no_gcode)?;
    crate::cmd::plot::pens_gcode(&pic.pens(), &pic.frame, gcode, vec![desc])
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

/// The `zetafill territory` command line that reproduces a run.
fn command_line(a: &TerritoryRun, d: &TerritoryDraw, points: usize, region: &str) -> String {
    let k = a.seeds;
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
    s.push_str(&format!(" --seed {}", a.seed));
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
    s.push_str(&format!(" --render {}", d.render.name()));
    s.push_str(&d.colours.flags);
    if d.pen_width != 0.3 {
        s.push_str(&format!(" --pen-width {}", d.pen_width));
    }
    if d.thin_width != 0.1 {
        s.push_str(&format!(" --thin-width {}", d.thin_width));
    }
    if d.boundary {
        s.push_str(" --boundary");
    }
    s.push_str(&d.plot_flags);
    s
}

/// Runs the territory competition and builds the document. Nothing is written.
pub fn compute(a: &TerritoryRun) -> Result<Outcome, CliError> {
    let mut rng = zetafill::rng_from_seed(a.seed);
    let (region, source) = match &a.sites_from {
        Some(p) => {
            let src = load_source(p)?;
            (src.region.clone(), Some(src))
        }
        None => {
            let data = RegionData::load(&a.region)?;
            let mut scratch = Vec::new();
            let r = data.region(false, &mut scratch)?;
            (data.doc(&r), None)
        }
    };
    let clip = Clip::from_doc(&region);
    let k = a.seeds;
    a.check_seeds(|p| clip.inside(p))?;
    let bar = |n: usize| crate::cmd::progress::bar(a.quiet || n < 200_000, Some(n as u64), "sites");
    let (model, points, shapes, source_index, name) = match source {
        Some(src) => {
            let n = src.centres.len();
            a.check_seeds_in_fill(n)?;
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
                        return Err(same_centre(*p));
                    }
                    order.swap(i, at);
                }
            }
            let mut rest: Vec<usize> = order[k..].to_vec();
            rest.sort_unstable();
            order.truncate(k);
            order.extend(rest);
            let seeds: Vec<Pt> = order[..k].iter().map(|&i| src.centres[i].0).collect();
            let mut m = Model::new(&seeds).map_err(fill_seeds_error)?;
            let b = bar(n);
            for &i in &order[k..] {
                m.add(src.centres[i].0)
                    .map_err(|e| sites_from_error(Path::new(&src.name), format!("shape {}: {e}", src.centres[i].1)))?;
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
            let points = a.points;
            a.check_seeds_in_points()?;
            let seeds: Vec<Pt> = if a.site.is_empty() {
                let bbox = clip.bbox();
                let mut v: Vec<Pt> = Vec::with_capacity(k);
                let mut tries = 0u64;
                while v.len() < k {
                    tries += 1;
                    if tries > 100_000_000 {
                        return Err(no_seed_drawn());
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
            let mut m = Model::new(&seeds).map_err(seeds_error)?;
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
            .map_err(growth_error)?;
            if let Some(b) = b {
                b.finish_and_clear();
            }
            (m, points, Vec::new(), vec![None; points], None)
        }
    };
    a.check_colour_rules()?;
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
    let mut crng = zetafill::rng_from_seed(a.seed ^ 0x436f_6c6f_7572_7321);
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
            seed: a.seed,
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
pub fn render_bytes(o: &Outcome, run: &TerritoryRun, d: &TerritoryDraw, format: TerritoryFormat) -> Result<Vec<u8>, CliError> {
    let desc = command_line(run, d, o.doc.params.points, &o.doc.region.arg());
    let picture = || {
        let style = Style {
            render: d.render,
            pen_width: d.pen_width,
            thin_width: d.thin_width,
            outline: d.boundary,
            background: d.colours.background.as_deref(),
            flat: d.colours.palette.is_some(),
        };
        let mut pic = render::picture(o, &site_colours(o, d, run.seed), &style);
        pic.title = format!(
            "zetafill territory: {} sites, {} territories, seed {}",
            o.doc.sites.len(),
            o.doc.seeds,
            run.seed
        );
        pic.desc.clone_from(&desc);
        pic
    };
    Ok(match format {
        TerritoryFormat::Gcode => gcode(&picture(), d, desc.clone())?,
        TerritoryFormat::Svg => crate::output::svg::write(&picture()),
        TerritoryFormat::Png => d.raster.render(&crate::output::svg::write(&picture())).map_err(png_error)?,
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
fn site_colours(o: &Outcome, d: &TerritoryDraw, seed: u64) -> Vec<String> {
    let Some(p) = &d.colours.palette else {
        return o.doc.sites.iter().map(|s| colour::hex(s.color)).collect();
    };
    let areas: Vec<f64> = if d.render == Render::Shapes {
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
    crate::output::palette::assign_items(&p.0, d.colours.by, seed, &items, |_| 0)
}

/// The G-code plan of a drawing that has none (it was resolved for another format).
fn no_gcode() -> CliError {
    CliError::Io("internal: G-code asked of a plan resolved for another format".into())
}

/// `zetafill territory`: grows the pattern of the plan and writes its output.
pub fn run(plan: &TerritoryPlan) -> Result<(), CliError> {
    let bytes = output(&plan.run, &plan.draw, plan.format)?;
    let advice = "ask for fewer points (--points) or a smaller --region";
    crate::cmd::write_bytes(&plan.dest, bytes, plan.max_output_size, plan.format.name(), advice)
}

/// The bytes a plan writes: the pattern grown and rendered.
pub fn output(run: &TerritoryRun, draw: &TerritoryDraw, format: TerritoryFormat) -> Result<Vec<u8>, CliError> {
    let o = compute(run)?;
    render_bytes(&o, run, draw, format)
}
