//! Drawings of a territory pattern, as one [`Picture`] in mm: the SVG writes it, PNG is that
//! SVG rendered by resvg, the G-code draws its strokes:
//! - `boundaries`: the Voronoi edges between sites of different territories, merged into long
//!   polylines (every edge drawn once) and clipped exactly to the region: the plotter's
//!   product;
//! - `cells`: every other Voronoi edge as thin lines in their own layer, plus the boundaries;
//! - `filled`: each site's Voronoi cell filled with its colour (with a palette, the cells of
//!   one colour as one path, seamless);
//! - `shapes` (sites from a fill): the fill's own shapes filled with their site's colour.
//!
//! Written like the fill's picture: y flipped about the region's top (no transform), four
//! decimals, the parameters in `<title>` and `<desc>`, no timestamp (same run, same bytes).

use super::model::Model;
use super::Outcome;
use crate::geometry::voronoi::{self as geom, Clip, Dual, Pt};
use crate::model::picture::ClipDef;
use crate::model::{Bounds, Item, Layer, Paint, Path, Picture, Shape};
use crate::plan::territory::Render;

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

/// The pattern as a picture (mm, the region's frame; title and description left to the
/// caller). `colours` holds each site's colour (`#rrggbb`), for the filled cells and the fill's
/// shapes. The SVG writes it whole; the G-code draws its strokes (boundaries, cell edges, the
/// region's outline).
pub fn picture(o: &Outcome, colours: &[String], style: &Style) -> Picture {
    let clip = &o.clip;
    let (x0, y0, x1, y1) = clip.bbox();
    let mut pic = Picture::new(Bounds { x0, y0, x1, y1 });
    pic.background = style.background.map(String::from);
    let clipped = !clip.is_rect();
    if clipped {
        pic.clips.push(ClipDef {
            id: "region".into(),
            item: Item::new(Shape::Path(o.doc.region.outline())).evenodd(),
        });
    }
    let lines = |ls: Vec<Vec<Pt>>| ls.into_iter().map(Item::polyline).collect();
    match style.render {
        Render::Boundaries => pic
            .layers
            .push(Layer::strokes("boundaries", style.pen_width, lines(o.boundaries.clone()))),
        Render::Cells => {
            let dual = Dual::of(&o.model.tri, clip.bbox());
            let t = &o.model.territory;
            let inner = (0..dual.edges.len()).filter(|&i| {
                let (a, b) = dual.edges[i].sites;
                t[a] == t[b]
            });
            let thin = geom::polylines(&dual, inner, clip);
            pic.layers.push(Layer::strokes("cells", style.thin_width, lines(thin)));
            pic.layers
                .push(Layer::strokes("boundaries", style.pen_width, lines(o.boundaries.clone())));
        }
        Render::Filled => {
            let mut layer = Layer {
                id: Some("cells".into()),
                paint: Paint {
                    width: Some(style.thin_width.min(0.1)),
                    join: Some("round"),
                    ..Paint::default()
                },
                clip: clipped.then(|| "region".into()),
                ..Layer::default()
            };
            let cells = cells(&o.model, clip);
            let drawn = cells.into_iter().zip(colours).filter(|(cell, _)| cell.len() >= 3);
            if style.flat {
                // One path per colour, its cells as subpaths, in order of first use.
                let mut order: Vec<(&String, Vec<Path>)> = Vec::new();
                for (cell, c) in drawn {
                    let ring = Path::polyline(cell, true);
                    match order.iter_mut().find(|(k, _)| *k == c) {
                        Some((_, rings)) => rings.push(ring),
                        None => order.push((c, vec![ring])),
                    }
                }
                for (c, rings) in order {
                    let mut item = Item::new(Shape::Path(rings));
                    item.paint.fill = Some(c.clone());
                    item.paint.stroke = Some("none".into());
                    layer.items.push(item);
                }
            } else {
                for (cell, c) in drawn {
                    // A hairline of the cell's own colour closes anti-aliasing seams.
                    let mut item = Item::new(Shape::Polygon(cell));
                    item.paint.fill = Some(c.clone());
                    item.paint.stroke = Some(c.clone());
                    layer.items.push(item);
                }
            }
            pic.layers.push(layer);
        }
        Render::Shapes => {
            let mut layer = Layer {
                id: Some("shapes".into()),
                paint: Paint {
                    stroke: Some("none".into()),
                    ..Paint::default()
                },
                ..Layer::default()
            };
            for (sh, c) in o.shapes.iter().zip(colours) {
                let mut item = match sh {
                    FillShape::Circle { c, r } => Item::new(Shape::Path(vec![Path::circle(*c, *r)])),
                    FillShape::Ring { c, r, inner } => {
                        Item::new(Shape::Path(vec![Path::circle(*c, *r), Path::circle(*c, *inner)])).evenodd()
                    }
                    FillShape::Poly(vs) => Item::new(Shape::Polygon(vs.clone())),
                };
                item.paint.fill = Some(c.clone());
                layer.items.push(item);
            }
            pic.layers.push(layer);
        }
    }
    if style.outline {
        let outline = Item::new(Shape::Path(o.doc.region.outline()));
        pic.layers.push(Layer::strokes("outline", style.pen_width, vec![outline]));
    }
    pic
}
