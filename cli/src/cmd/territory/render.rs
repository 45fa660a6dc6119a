//! Drawings of a territory pattern, as SVG in mm (PNG is that SVG rendered by resvg):
//! - `boundaries`: the Voronoi edges between sites of different territories, merged into long
//!   polylines (every edge drawn once) and clipped exactly to the region: the plotter's
//!   product;
//! - `cells`: every other Voronoi edge as thin lines in their own layer, plus the boundaries;
//! - `filled`: each site's Voronoi cell filled with its colour (with a palette, the cells of
//!   one colour as one path, seamless);
//! - `shapes` (sites from a fill): the fill's own shapes filled with their site's colour.
//!
//! Like the fill's SVG: y is flipped about the region's top (no transform), four decimals,
//! the parameters in `<title>` and `<desc>`, no timestamp (same run, same bytes).

use super::model::Model;
use crate::geometry::voronoi::{self as geom, Clip, Dual, Pt};
use crate::output::num;
use svg::node::element::{ClipPath, Definitions, Description, Group, Path, Polygon, Title};
use svg::node::Text;
use svg::Document;

const P: usize = 4;

/// What to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Render {
    /// Territory boundaries as merged polylines (plotters).
    Boundaries,
    /// All Voronoi edges: cells thin, boundaries at pen width (two layers).
    Cells,
    /// Cells filled with their HSB colours (screens, prints).
    Filled,
    /// The fill's own shapes filled with their site's colour (only with --sites-from).
    Shapes,
}

impl Render {
    /// The name as on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Render::Boundaries => "boundaries",
            Render::Cells => "cells",
            Render::Filled => "filled",
            Render::Shapes => "shapes",
        }
    }
}

/// A shape of the fill the sites came from.
#[derive(Debug, Clone, PartialEq)]
pub enum FillShape {
    /// A disc.
    Circle {
        /// Centre.
        c: Pt,
        /// Radius.
        r: f64,
    },
    /// A ring.
    Ring {
        /// Centre.
        c: Pt,
        /// Outer radius.
        r: f64,
        /// Inner radius.
        inner: f64,
    },
    /// A polygon (its listed vertices).
    Poly(Vec<Pt>),
}

impl FillShape {
    /// The area it covers.
    pub fn area(&self) -> f64 {
        match self {
            FillShape::Circle { r, .. } => std::f64::consts::PI * r * r,
            FillShape::Ring { r, inner, .. } => std::f64::consts::PI * (r * r - inner * inner),
            FillShape::Poly(vs) => geom::area(vs).abs(),
        }
    }
}

/// Drawing options.
#[derive(Debug, Clone, Copy)]
pub struct Style<'a> {
    /// What to draw.
    pub render: Render,
    /// Stroke of boundaries (mm).
    pub pen_width: f64,
    /// Stroke of the thin cell edges (mm).
    pub thin_width: f64,
    /// Also draw the region's outline.
    pub outline: bool,
    /// A background colour behind filled cells or shapes.
    pub background: Option<&'a str>,
    /// Flat colours (a palette): the cells of each colour are drawn as one path, so that
    /// anti-aliasing leaves no seam between them.
    pub flat: bool,
}

/// The indices of the Voronoi edges between sites of different territories.
pub fn boundary_edges<'a>(dual: &'a Dual, territory: &'a [u32]) -> impl Iterator<Item = usize> + 'a {
    (0..dual.edges.len()).filter(move |&i| {
        let (a, b) = dual.edges[i].sites;
        territory[a] != territory[b]
    })
}

/// The territory boundaries: merged polylines clipped to the region.
pub fn boundaries(model: &Model, clip: &Clip) -> Vec<Vec<Pt>> {
    let dual = Dual::of(&model.tri, clip.bbox());
    geom::polylines(&dual, boundary_edges(&dual, &model.territory), clip)
}

/// The Voronoi cell of every site clipped to the region's bounding box (exact for a
/// rectangle; other regions are clipped again by the SVG's clip path): the box cut by the
/// bisector with each Delaunay neighbour.
pub fn cells(model: &Model, clip: &Clip) -> Vec<Vec<Pt>> {
    let bbox = clip.bbox();
    (0..model.len())
        .map(|i| geom::cell(model.sites[i], geom::neighbours(&model.tri, i).map(|j| model.sites[j]), bbox))
        .collect()
}

/// The page frame: SVG x = x - x0, SVG y = y1 - y.
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    /// Left of the region's box.
    pub x0: f64,
    /// Top of the region's box.
    pub y1: f64,
}

impl Frame {
    /// The frame of a clip region.
    pub fn of(clip: &Clip) -> Frame {
        let (x0, _, _, y1) = clip.bbox();
        Frame { x0, y1 }
    }

    /// A point as `x,y` on the page.
    pub fn pt(&self, p: Pt) -> String {
        format!("{},{}", num(p[0] - self.x0, P), num(self.y1 - p[1], P))
    }
}

/// Path data of open polylines (`M ... L ...` each).
pub fn polyline_d(f: &Frame, lines: &[Vec<Pt>]) -> Vec<String> {
    lines
        .iter()
        .map(|l| {
            let pts: Vec<String> = l.iter().map(|&p| f.pt(p)).collect();
            format!("M{}", pts.join(" L"))
        })
        .collect()
}

fn ring_d(f: &Frame, ring: &[Pt]) -> String {
    let pts: Vec<String> = ring.iter().map(|&p| f.pt(p)).collect();
    format!("M{} Z", pts.join(" L"))
}

fn circle_d(f: &Frame, c: Pt, r: f64) -> String {
    let rr = num(r, P);
    format!(
        "M{} A{rr},{rr} 0 1 0 {} A{rr},{rr} 0 1 0 {} Z",
        f.pt([c[0] + r, c[1]]),
        f.pt([c[0] - r, c[1]]),
        f.pt([c[0] + r, c[1]])
    )
}

/// The region's outline as one even-odd path's data.
pub fn region_d(f: &Frame, clip: &Clip) -> String {
    match clip {
        Clip::Circle { c, r } => circle_d(f, *c, *r),
        Clip::Annulus { c, ro, ri } => format!("{} {}", circle_d(f, *c, *ro), circle_d(f, *c, *ri)),
        other => other.rings().iter().map(|r| ring_d(f, r)).collect::<Vec<_>>().join(" "),
    }
}

/// A plotter layer (Inkscape layer group) of stroked paths.
pub fn stroke_layer(id: &str, d: Vec<String>, width: f64) -> Group {
    let mut g = Group::new()
        .set("id", id)
        .set("inkscape:groupmode", "layer")
        .set("inkscape:label", id)
        .set("fill", "none")
        .set("stroke", "black")
        .set("stroke-width", num(width, P))
        .set("stroke-linecap", "round")
        .set("stroke-linejoin", "round");
    for d in d {
        g = g.add(Path::new().set("d", d));
    }
    g
}

/// A document `w` x `h` mm with its title and description.
pub fn document(clip: &Clip, title: &str, desc: &str) -> Document {
    let (x0, y0, x1, y1) = clip.bbox();
    let (w, h) = (x1 - x0, y1 - y0);
    Document::new()
        .set("xmlns:inkscape", "http://www.inkscape.org/namespaces/inkscape")
        .set("width", format!("{}mm", num(w, P)))
        .set("height", format!("{}mm", num(h, P)))
        .set("viewBox", format!("0 0 {} {}", num(w, P), num(h, P)))
        .add(Title::new("").add(Text::new(title)))
        .add(Description::new().add(Text::new(desc)))
}

/// Renders the pattern. `colours` holds each site's colour (`#rrggbb`); `shapes` the fill's
/// shapes (for [`Render::Shapes`]).
pub fn svg(model: &Model, clip: &Clip, colours: &[String], shapes: &[FillShape], style: &Style, title: &str, desc: &str) -> Vec<u8> {
    let f = Frame::of(clip);
    let mut doc = document(clip, title, desc);
    if let Some(bg) = style.background {
        let (x0, y0, x1, y1) = clip.bbox();
        doc = doc.add(crate::output::palette::background(bg, x1 - x0, y1 - y0));
    }
    let clipped = !clip.is_rect();
    if clipped {
        let cp = ClipPath::new()
            .set("id", "region")
            .add(Path::new().set("d", region_d(&f, clip)).set("clip-rule", "evenodd"));
        doc = doc.add(Definitions::new().add(cp));
    }
    match style.render {
        Render::Boundaries => {
            doc = doc.add(stroke_layer(
                "boundaries",
                polyline_d(&f, &boundaries(model, clip)),
                style.pen_width,
            ));
        }
        Render::Cells => {
            let dual = Dual::of(&model.tri, clip.bbox());
            let t = &model.territory;
            let inner = (0..dual.edges.len()).filter(|&i| {
                let (a, b) = dual.edges[i].sites;
                t[a] == t[b]
            });
            let thin = geom::polylines(&dual, inner, clip);
            let bound = geom::polylines(&dual, boundary_edges(&dual, t), clip);
            doc = doc.add(stroke_layer("cells", polyline_d(&f, &thin), style.thin_width));
            doc = doc.add(stroke_layer("boundaries", polyline_d(&f, &bound), style.pen_width));
        }
        Render::Filled => {
            let mut g = Group::new()
                .set("id", "cells")
                .set("stroke-width", num(style.thin_width.min(0.1), P))
                .set("stroke-linejoin", "round");
            if clipped {
                g = g.set("clip-path", "url(#region)");
            }
            let cells = cells(model, clip);
            if style.flat {
                // One path per colour, its cells as subpaths, in order of first use.
                let mut order: Vec<(&String, Vec<String>)> = Vec::new();
                for (cell, c) in cells.iter().zip(colours).filter(|(cell, _)| cell.len() >= 3) {
                    let ring = ring_d(&f, cell);
                    match order.iter_mut().find(|(k, _)| *k == c) {
                        Some((_, rings)) => rings.push(ring),
                        None => order.push((c, vec![ring])),
                    }
                }
                for (c, rings) in order {
                    g = g.add(Path::new().set("d", rings.join(" ")).set("fill", c.clone()).set("stroke", "none"));
                }
            }
            for (cell, c) in cells.iter().zip(colours).filter(|_| !style.flat) {
                if cell.len() < 3 {
                    continue;
                }
                let pts: Vec<String> = cell.iter().map(|&p| f.pt(p)).collect();
                let col = c.clone();
                // A hairline of the cell's own colour closes anti-aliasing seams.
                g = g.add(
                    Polygon::new()
                        .set("points", pts.join(" "))
                        .set("fill", col.clone())
                        .set("stroke", col),
                );
            }
            doc = doc.add(g);
        }
        Render::Shapes => {
            let mut g = Group::new().set("id", "shapes").set("stroke", "none");
            for (sh, c) in shapes.iter().zip(colours) {
                let col = c.clone();
                g = match sh {
                    FillShape::Circle { c, r } => g.add(Path::new().set("d", circle_d(&f, *c, *r)).set("fill", col)),
                    FillShape::Ring { c, r, inner } => g.add(
                        Path::new()
                            .set("d", format!("{} {}", circle_d(&f, *c, *r), circle_d(&f, *c, *inner)))
                            .set("fill-rule", "evenodd")
                            .set("fill", col),
                    ),
                    FillShape::Poly(vs) => g.add(
                        Polygon::new()
                            .set("points", vs.iter().map(|&p| f.pt(p)).collect::<Vec<_>>().join(" "))
                            .set("fill", col),
                    ),
                };
            }
            doc = doc.add(g);
        }
    }
    if style.outline {
        doc = doc.add(stroke_layer("outline", vec![region_d(&f, clip)], style.pen_width));
    }
    let mut s = doc.to_string();
    s.push('\n');
    s.into_bytes()
}
