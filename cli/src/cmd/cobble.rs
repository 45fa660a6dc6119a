//! Voronoi "cobblestones" of a fill (as in the "Fractal Tiles" post): the Voronoi cells of
//! the shapes' centres, clipped exactly to the region, as plottable polylines (every edge drawn
//! once, edges merged into long lines). With a periodic region the diagram is built from the
//! centres and their 8 periodic copies and clipped to the tile, so the cells tile seamlessly:
//! an edge leaving the tile on one side comes back at the same place on the other.

use crate::error::CliError;
use crate::geometry::voronoi::{self as geom, Clip, Dual, Pt};
use crate::model::doc::FillDoc;
use crate::model::picture::ClipDef;
use crate::model::{Bounds, Item, Layer, Paint, Picture, Shape};
use spade::{DelaunayTriangulation, Point2, Triangulation};

/// The sites of the diagram: the centres, plus their 8 periodic copies when periodic.
pub fn sites(doc: &FillDoc) -> Vec<Pt> {
    let centres: Vec<Pt> = doc.shapes.iter().map(|s| s.center).collect();
    if !doc.periodic() {
        return centres;
    }
    let (w, h) = doc.extent();
    let mut out = Vec::with_capacity(centres.len() * 9);
    out.extend_from_slice(&centres);
    for (dx, dy) in [(-w, -h), (0.0, -h), (w, -h), (-w, 0.0), (w, 0.0), (-w, h), (0.0, h), (w, h)] {
        out.extend(centres.iter().map(|c| [c[0] + dx, c[1] + dy]));
    }
    out
}

/// The cobblestone edges: every Voronoi edge of the centres, merged and clipped to the region
/// (the tile when periodic).
pub fn polylines(doc: &FillDoc) -> Result<Vec<Vec<Pt>>, CliError> {
    let clip = Clip::from_doc(&doc.region);
    let pts: Vec<Point2<f64>> = sites(doc).iter().map(|&p| geom::p2(p)).collect();
    let tri: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::bulk_load_stable(pts).map_err(|e| CliError::Io(format!("internal: cannot triangulate the centres: {e}")))?;
    if tri.num_vertices() < 2 {
        return Ok(Vec::new());
    }
    let dual = Dual::of(&tri, clip.bbox());
    Ok(geom::polylines(&dual, 0..dual.edges.len(), &clip))
}

/// How cobblestones are drawn.
#[derive(Debug, Clone, Default)]
pub struct Look {
    /// Fill the cells (`--style filled`) rather than draw their edges.
    pub filled: bool,
    /// Stroke width of the edges (mm); with filled cells, the width of the mortar between them.
    pub pen_width: f64,
    /// Add the region's outline.
    pub outline: bool,
    /// Each shape's colour, for its cell (filled cells only); black without.
    pub colours: Option<Vec<crate::output::palette::Colour>>,
    /// A colour behind the drawing; with filled cells, also the mortar's (white without).
    pub background: Option<crate::output::palette::Colour>,
    /// The drawing flags, as the command that reproduces the drawing writes them.
    pub flags: String,
}

/// Every cell of the diagram: the Voronoi cell of each site cut to the region's box (the tile
/// when periodic, where the cells of the copies fill in what wraps around), with the index of
/// the shape whose centre (or copy of it) is the site.
pub fn cells(doc: &FillDoc) -> Result<Vec<(usize, Vec<Pt>)>, CliError> {
    let clip = Clip::from_doc(&doc.region);
    let sites = sites(doc);
    let pts: Vec<Point2<f64>> = sites.iter().map(|&p| geom::p2(p)).collect();
    let tri: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::bulk_load_stable(pts).map_err(|e| CliError::Io(format!("internal: cannot triangulate the centres: {e}")))?;
    let n = doc.shapes.len().max(1);
    if tri.num_vertices() < sites.len() {
        return Err(CliError::Io("internal: two centres coincide".into()));
    }
    Ok((0..sites.len())
        .map(|v| {
            let others = geom::neighbours(&tri, v).filter_map(|j| sites.get(j).copied());
            (v % n, geom::cell(sites[v], others, clip.bbox()))
        })
        .filter(|(_, c)| c.len() >= 3)
        .collect())
}

/// The cobblestones as a picture (mm, the region's frame): the edges, or the cells filled in
/// their shapes' colours with the edges drawn over them as mortar.
pub fn picture(doc: &FillDoc, look: &Look) -> Result<Picture, CliError> {
    let clip = Clip::from_doc(&doc.region);
    let (x0, y0, x1, y1) = clip.bbox();
    let mut pic = Picture::new(Bounds { x0, y0, x1, y1 });
    let p = &doc.params;
    pic.title = format!(
        "zetafill: Voronoi cobblestones of {} {}, c = {}, N = {}, seed {}",
        doc.shapes.len(),
        p.of.shape,
        p.c,
        p.n_offset,
        p.seed
    );
    pic.desc = format!("{} --voronoi{}", crate::output::svg::command_line(doc), look.flags);
    pic.background.clone_from(&look.background);
    let edges: Vec<Item> = polylines(doc)?.into_iter().map(Item::polyline).collect();
    let mut mortar = Layer::strokes("cobblestones", look.pen_width, edges);
    if look.filled {
        let mut cells_layer = Layer {
            id: Some("cells".into()),
            paint: Paint::filled(),
            ..Layer::default()
        };
        if !clip.is_rect() {
            pic.clips.push(ClipDef {
                id: "region".into(),
                item: Item::new(Shape::Path(doc.region.outline())).evenodd(),
            });
            cells_layer.clip = Some("region".into());
        }
        for (k, cell) in cells(doc)? {
            let mut poly = Item::new(Shape::Polygon(cell));
            poly.paint.fill = look.colours.as_ref().and_then(|cs| cs.get(k)).cloned();
            cells_layer.items.push(poly);
        }
        pic.layers.push(cells_layer);
        mortar.paint.stroke = Some(look.background.clone().unwrap_or_else(|| "#ffffff".into()));
    }
    pic.layers.push(mortar);
    if look.outline {
        let outline = Item::new(Shape::Path(doc.region.outline()));
        pic.layers.push(Layer::strokes("outline", look.pen_width, vec![outline]));
    }
    Ok(pic)
}

/// The cobblestones as SVG (mm, y flipped like the fill's SVG).
pub fn svg(doc: &FillDoc, look: &Look) -> Result<Vec<u8>, CliError> {
    Ok(crate::output::svg::write(&picture(doc, look)?))
}
