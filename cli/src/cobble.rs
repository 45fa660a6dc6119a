//! Voronoi "cobblestones" of a fill (seed 002, the fractal-tile post): the Voronoi cells of
//! the shapes' centres, clipped exactly to the region, as plottable polylines (every edge drawn
//! once, edges merged into long lines). With a periodic region the diagram is built from the
//! centres and their 8 periodic copies and clipped to the tile, so the cells tile seamlessly:
//! an edge leaving the tile on one side comes back at the same place on the other.

use crate::doc::FillDoc;
use crate::error::CliError;
use crate::output::num;
use crate::territory::geom::{self, Clip, Dual, Pt};
use crate::territory::render::{document, polyline_d, region_d, stroke_layer, Frame};
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

/// The cobblestones as SVG (mm, y flipped like the fill's SVG); `outline` adds the region's
/// outline in its own layer.
pub fn svg(doc: &FillDoc, pen_width: f64, outline: bool) -> Result<Vec<u8>, CliError> {
    let clip = Clip::from_doc(&doc.region);
    let f = Frame::of(&clip);
    let lines = polylines(doc)?;
    let p = &doc.params;
    let title = format!(
        "zetafill: Voronoi cobblestones of {} {}, c = {}, N = {}, seed {}",
        doc.shapes.len(),
        p.shape,
        p.c,
        p.n_offset,
        p.seed
    );
    let desc = format!(
        "{} --voronoi --pen-width {}",
        crate::output::svg::command_line(doc),
        num(pen_width, 4)
    );
    let mut d = document(&clip, &title, &desc).add(stroke_layer("cobblestones", polyline_d(&f, &lines), pen_width));
    if outline {
        d = d.add(stroke_layer("outline", vec![region_d(&f, &clip)], pen_width));
    }
    let mut s = d.to_string();
    s.push('\n');
    Ok(s.into_bytes())
}
