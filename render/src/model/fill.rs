//! A fill as a [`Picture`]: every shape (and its hatching) as items in the region's frame,
//! the periodic images of an edge-crossing shape included, split into layers by size band or
//! by colour. The same picture gives the SVG (and PNG) and, as strokes, the G-code.
//!
//! A periodic fill is cut to its tile geometrically, never by a clip path (which vpype and
//! plotter drivers ignore): each image that crosses the tile's edge is cut exactly, its
//! outline and hatching into path pieces (the strokes the G-code draws, the same in every
//! SVG), or, filled, its area into a polygon or a loop of arcs and edges.

use super::cut::Window;
use super::doc::{FillDoc, RegionDoc, ShapeDoc};
use super::hatch;
use super::picture::{Colour, Item, Layer, PageLayout, Paint, Picture, Shape};
use super::{shape_bounds, shape_images, shape_width, Bounds, Drawing, Path};

/// What goes into a drawing besides the outlines.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct BuildOptions {
    /// Leave out shapes (and ring holes) narrower than this (mm).
    pub min_feature: f64,
    /// Hatch every shape.
    pub hatch: Option<hatch::Hatch>,
    /// Draw the outlines (false: hatch only).
    pub no_outline: bool,
}

/// One layer of a layered fill.
#[derive(Debug, Clone, PartialEq)]
pub struct LayerSpec {
    /// The Inkscape label.
    pub label: String,
    /// The layer's pen colour, when the layers are the pens of a plot.
    pub pen: Option<Colour>,
}

impl LayerSpec {
    /// One layer (one pen) per distinct colour of `palette`, in its order of first use,
    /// labelled `K #rrggbb`; and the layer of each of `colours` (the first, for a colour not in
    /// the palette). A colour the palette repeats is one pen, plotted once.
    pub fn colours(palette: &[Colour], colours: &[Colour]) -> (Vec<LayerSpec>, Vec<usize>) {
        let mut pens: Vec<&Colour> = Vec::new();
        for c in palette {
            if !pens.contains(&c) {
                pens.push(c);
            }
        }
        let layers = pens
            .iter()
            .enumerate()
            .map(|(i, c)| LayerSpec {
                label: format!("{} {c}", i + 1),
                pen: Some((*c).clone()),
            })
            .collect();
        let of = colours.iter().map(|c| pens.iter().position(|p| *p == c).unwrap_or(0)).collect();
        (layers, of)
    }
}

/// How a fill is drawn.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FillLook {
    /// Filled shapes without stroke (screens); otherwise outlines.
    pub filled: bool,
    /// Pen width of outlines (mm).
    pub pen_width: f64,
    /// Draw the region's outline too.
    pub boundary: bool,
    /// A page to place the drawing on.
    pub page: Option<PageLayout>,
    /// Hatching, outlines left out, narrow shapes left out.
    pub build: BuildOptions,
    /// Each shape's colour (its fill, or its stroke for outlines).
    pub colours: Option<Vec<Colour>>,
    /// A colour behind everything.
    pub background: Option<Colour>,
    /// Layers (`layer_of` gives each shape's); empty: one group of every shape.
    pub layers: Vec<LayerSpec>,
    /// Each shape's layer among `layers`.
    pub layer_of: Vec<usize>,
}

/// The drawing of a fill in the region's frame: outlines (and hatching), shapes narrower
/// than `min_feature` left out; periodic fills clipped exactly to the tile. This is what the
/// G-code writer draws.
pub fn from_fill(doc: &FillDoc, opt: &BuildOptions) -> Drawing {
    let look = FillLook {
        build: *opt,
        ..FillLook::default()
    };
    let mut pens = picture(doc, &look).pens();
    pens.pop().map(|(_, d)| d).unwrap_or_default()
}

/// A ring's hole, unless it is narrower than `min_feature` (then the ring is drawn as a disc).
fn hole(inner: Option<f64>, min_feature: f64) -> Option<f64> {
    inner.filter(|&ri| ri > 0.0 && 2.0 * ri >= min_feature)
}

/// The outline of one image of a shape (shifted by `off`).
fn outline(sh: &ShapeDoc, off: (f64, f64), min_feature: f64) -> Item {
    let c = [sh.center[0] + off.0, sh.center[1] + off.1];
    match (sh.radius, hole(sh.inner_radius, min_feature)) {
        (Some(r), Some(inner)) => Item::new(Shape::Path(vec![Path::circle(c, r), Path::circle(c, inner)])).evenodd(),
        (Some(r), None) => Item::new(Shape::Circle { c, r }),
        _ => match &sh.outlines {
            Some(rings) => Item::new(Shape::Path(
                rings
                    .iter()
                    .map(|r| Path::polyline(r.iter().map(|v| [v[0] + off.0, v[1] + off.1]).collect(), true))
                    .collect(),
            ))
            .evenodd(),
            None => {
                let vs = sh.vertices.as_deref().unwrap_or(&[]);
                Item::new(Shape::Polygon(vs.iter().map(|v| [v[0] + off.0, v[1] + off.1]).collect()))
            }
        },
    }
}

/// A shape as drawn: its position in the document (for its colour and layer), the shape, and
/// the shifts at which it shows.
type Shown<'d> = (usize, &'d ShapeDoc, Vec<(f64, f64)>);

/// The fill as a picture (title and description left to the caller).
pub fn picture(doc: &FillDoc, look: &FillLook) -> Picture {
    let (x0, y0, x1, y1) = doc.bbox();
    let (w, h) = doc.extent();
    let mut pic = Picture::new(Bounds { x0, y0, x1, y1 });
    pic.page = look.page;
    pic.background.clone_from(&look.background);
    let paint = if look.filled {
        Paint::filled()
    } else {
        Paint::outline(look.pen_width)
    };
    pic.layers = if look.layers.is_empty() {
        vec![Layer {
            id: Some("shapes".into()),
            paint: paint.clone(),
            ..Layer::default()
        }]
    } else {
        look.layers
            .iter()
            .enumerate()
            .map(|(i, l)| Layer {
                id: Some(format!("layer{}", i + 1)),
                label: Some(l.label.clone()),
                paint: paint.clone(),
                pen: l.pen.clone(),
                ..Layer::default()
            })
            .collect()
    };
    let periodic = doc.periodic();
    let tile = Bounds {
        x0: 0.0,
        y0: 0.0,
        x1: w,
        y1: h,
    };
    let min_feature = look.build.min_feature;
    // Each shape with the shifts at which it shows (in a symmetric fill, each image of each
    // representative, with the lattice translates that meet the window).
    let symmetric = super::wallpaper::images(doc);
    // A symmetric pattern cut to a region; a rectangle is cut as a window of cells is.
    let window = match &doc.region {
        RegionDoc::Wallpaper { window: Some(r), .. } if !matches!(**r, RegionDoc::Rect { .. }) => Some(Window::new(&r.outline())),
        _ => None,
    };
    let cut_to_tile = (periodic || symmetric.is_some()) && window.is_none();
    let drawn: Vec<Shown> = match &symmetric {
        Some(images) => images.iter().map(|im| (im.of, &im.shape, im.shifts.clone())).collect(),
        None => doc
            .shapes
            .iter()
            .enumerate()
            .map(|(k, sh)| (k, sh, if periodic { shape_images(sh, w, h) } else { vec![(0.0, 0.0)] }))
            .collect(),
    };
    for (k, sh, offs) in drawn {
        if min_feature > 0.0 && shape_width(sh) < min_feature {
            continue;
        }
        let colour = look.colours.as_ref().and_then(|c| c.get(k));
        let layer = look.layer_of.get(k).copied().unwrap_or(0);
        let sb = shape_bounds(sh);
        for (dx, dy) in offs {
            let image = Bounds {
                x0: sb.x0 + dx,
                y0: sb.y0 + dy,
                x1: sb.x1 + dx,
                y1: sb.y1 + dy,
            };
            let cut = cut_to_tile && !image.inside(&tile, 0.0);
            // In a region, a shape no outline edge comes near lies wholly inside or outside.
            let cut_in = match &window {
                Some(win) if win.meets(&image) => Some(win),
                Some(win) if !win.contains([sh.center[0] + dx, sh.center[1] + dy]) => continue,
                _ => None,
            };
            let mut items = Vec::with_capacity(2);
            if !look.build.no_outline {
                let o = outline(sh, (dx, dy), min_feature);
                items.extend(match (cut_in, cut, look.filled) {
                    (Some(win), _, false) => o.clipped_in(win),
                    (Some(win), _, true) => o.cut_area_in(win),
                    (None, false, _) => Some(o),
                    (None, true, false) => o.clipped(&tile),
                    (None, true, true) => o.cut_area(&tile),
                });
            }
            if let Some(hatch) = &look.build.hatch {
                let lines: Vec<Path> = hatch
                    .shape(sh, (dx, dy), min_feature)
                    .into_iter()
                    .map(|[a, b]| Path::polyline(vec![a, b], false))
                    .collect();
                if !lines.is_empty() {
                    let mut item = Item::new(Shape::Path(lines));
                    item.class = Some("hatch");
                    items.extend(match cut_in {
                        Some(win) => item.clipped_in(win),
                        None if cut_to_tile => item.clipped(&tile),
                        None => Some(item),
                    });
                }
            }
            // A motif's decorations: strokes, in either style, cut as the hatching is.
            if let Some(lines) = sh.decorations.as_ref().filter(|_| !look.build.no_outline) {
                let paths = lines
                    .iter()
                    .map(|l| Path::polyline(l.iter().map(|v| [v[0] + dx, v[1] + dy]).collect(), false))
                    .collect();
                let mut item = Item::new(Shape::Path(paths));
                item.class = Some("decoration");
                if look.filled {
                    item.paint = Paint::outline(look.pen_width);
                }
                items.extend(match cut_in {
                    Some(win) => item.clipped_in(win),
                    None if cut_to_tile => item.clipped(&tile),
                    None => Some(item),
                });
            }
            for mut item in items {
                if let Some(c) = colour {
                    if look.filled && item.class != Some("decoration") {
                        item.paint.fill = Some(c.clone());
                    } else {
                        item.paint.stroke = Some(c.clone());
                    }
                }
                if let Some(l) = pic.layers.get_mut(layer) {
                    l.items.push(item);
                }
            }
        }
    }
    if look.boundary {
        let mut outline = Item::new(Shape::Path(doc.region.outline())).evenodd();
        outline.id = Some("boundary");
        outline.paint = Paint::outline(look.pen_width);
        pic.layers.push(Layer {
            bare: true,
            items: vec![outline],
            ..Layer::default()
        });
    }
    pic
}
