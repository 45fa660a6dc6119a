//! A picture: everything a mode draws, as one plain model that every picture writer reads.
//!
//! A [`Picture`] is a page (the region's box, or a paper page it is placed on), a title and a
//! description, a background, clip outlines, and [`Layer`]s of [`Item`]s in the region's frame
//! (mm, x right, y up; or, for a picture with [`Picture::flip`] off, already y down). A layer
//! is one pen: its [`Paint`] (fill, stroke, pen width) and, for plotters, its pen colour. An
//! item is a circle, a polygon, a line, a rectangle, or path pieces (polylines and arcs), each
//! with its own colour, class or fill rule when it has one.
//!
//! Cutting to a tile is geometry here, never a clip path (which plotter tools ignore):
//! [`Item::cut`] cuts a drawn item's strokes (what a pen draws, and what the G-code writes)
//! or a filled item's area, so every viewer and every plotter sees the same drawing.
//!
//! The SVG writer writes any picture; the G-code writer takes its strokes ([`Picture::pens`]),
//! one drawing per pen colour; PNG is the SVG rendered. [`Frame`] is the one place where the
//! region's frame becomes the page's (the y flip, the page placement).

use super::cut::Window;
use super::{clip_area, clip_path, clip_polygon, Bounds, Drawing, Path, Pt};

/// A colour as `#rrggbb`.
pub type Colour = String;

/// Where the drawing goes on a page: page point = `scale * p + (dx, dy)` for a region point
/// `p`, in a page frame with y up from the page's bottom edge (the SVG flips it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageLayout {
    /// Page width in mm.
    pub width: f64,
    /// Page height in mm.
    pub height: f64,
    /// Scale (1 unless `--fit`).
    pub scale: f64,
    /// Shift in x (mm).
    pub dx: f64,
    /// Shift in y (mm, y up).
    pub dy: f64,
}

/// How a layer (or an item) is painted; `None` leaves the value to the enclosing group.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Paint {
    /// Fill: `none`, `black` or a colour.
    pub fill: Option<Colour>,
    /// Stroke: `none`, `black` or a colour.
    pub stroke: Option<Colour>,
    /// Pen width (mm).
    pub width: Option<f64>,
    /// Line caps (`butt`, `round`).
    pub cap: Option<&'static str>,
    /// Line joins (`round`).
    pub join: Option<&'static str>,
}

impl Paint {
    /// Black outlines `width` mm wide.
    pub fn outline(width: f64) -> Paint {
        Paint {
            fill: Some("none".into()),
            stroke: Some("black".into()),
            width: Some(width),
            ..Paint::default()
        }
    }

    /// Black shapes without stroke.
    pub fn filled() -> Paint {
        Paint {
            fill: Some("black".into()),
            stroke: Some("none".into()),
            ..Paint::default()
        }
    }
}

/// The geometry of one item.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A circle.
    Circle {
        /// Centre.
        c: Pt,
        /// Radius.
        r: f64,
    },
    /// A closed polygon through these vertices.
    Polygon(Vec<Pt>),
    /// Path pieces: polylines, arcs and full circles (one path, so a fill rule can make holes).
    Path(Vec<Path>),
    /// Closed loops (one path, so a fill rule can make holes), each a chain of pieces that
    /// meet end to start: the outline of an area cut to a tile.
    Loops(Vec<Vec<Path>>),
    /// A straight line.
    Line(Pt, Pt),
    /// A `w` x `h` rectangle; `corner` is the corner that lands top-left on the page
    /// (`None`: the page's origin, written without a position).
    Rect {
        /// The top-left corner on the page, in the picture's frame.
        corner: Option<Pt>,
        /// Width.
        w: f64,
        /// Height.
        h: f64,
    },
}

/// One thing drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Item {
    /// What it is.
    pub shape: Shape,
    /// Its own paint, over the layer's (a colour, or the paint of a lone outline).
    pub paint: Paint,
    /// An identifier (`boundary`).
    pub id: Option<&'static str>,
    /// A class (`hatch`).
    pub class: Option<&'static str>,
    /// Holes by the even-odd rule.
    pub evenodd: bool,
}

impl Item {
    /// An item of `shape` with nothing else set.
    pub fn new(shape: Shape) -> Item {
        Item {
            shape,
            paint: Paint::default(),
            id: None,
            class: None,
            evenodd: false,
        }
    }

    /// Sets the even-odd rule.
    pub fn evenodd(mut self) -> Item {
        self.evenodd = true;
        self
    }

    /// One open polyline.
    pub fn polyline(points: Vec<Pt>) -> Item {
        Item::new(Shape::Path(vec![Path::polyline(points, false)]))
    }

    /// The strokes a pen draws for it.
    pub fn strokes(&self) -> Vec<Path> {
        match &self.shape {
            Shape::Circle { c, r } => vec![Path::circle(*c, *r)],
            Shape::Polygon(vs) if vs.len() < 2 => vec![],
            Shape::Polygon(vs) => vec![Path::polyline(vs.clone(), true)],
            Shape::Path(pieces) => pieces.clone(),
            Shape::Loops(loops) => loops.iter().flatten().cloned().collect(),
            Shape::Line(a, b) => vec![Path::polyline(vec![*a, *b], false)],
            Shape::Rect { corner, w, h } => {
                let [x, y] = corner.unwrap_or([0.0, 0.0]);
                vec![Path::polyline(vec![[x, y], [x + w, y], [x + w, y + h], [x, y + h]], true)]
            }
        }
    }

    /// The item's strokes cut exactly to `tile`, as path pieces (what a pen draws of it
    /// there); `None` when nothing of it is left.
    pub fn clipped(&self, tile: &Bounds) -> Option<Item> {
        let pieces: Vec<Path> = self.strokes().iter().flat_map(|p| clip_path(p, tile)).collect();
        (!pieces.is_empty()).then(|| Item {
            shape: Shape::Path(pieces),
            evenodd: false,
            ..self.clone()
        })
    }

    /// The item's strokes cut exactly to the region `w` ([`Window::cut_path`]); `None` when
    /// nothing of it is left.
    pub fn clipped_in(&self, w: &Window) -> Option<Item> {
        let strokes = self.strokes();
        let pieces: Vec<Vec<Path>> = strokes.iter().map(|p| w.cut_path(p)).collect();
        if pieces
            .iter()
            .zip(&strokes)
            .all(|(cut, p)| matches!(cut.as_slice(), [one] if one == p))
        {
            return Some(self.clone());
        }
        let pieces: Vec<Path> = pieces.into_iter().flatten().collect();
        (!pieces.is_empty()).then(|| Item {
            shape: Shape::Path(pieces),
            evenodd: false,
            ..self.clone()
        })
    }

    /// The item's area cut exactly to the region `w`, each closed piece on its own as in
    /// [`Item::cut_area`] ([`Window::cut_area`]); a line is cut as a stroke. `None` when
    /// nothing of it is left.
    pub fn cut_area_in(&self, w: &Window) -> Option<Item> {
        if matches!(self.shape, Shape::Line(..)) {
            return self.clipped_in(w);
        }
        let strokes = self.strokes();
        let loops: Vec<Vec<Path>> = strokes.iter().flat_map(|p| w.cut_area(p)).collect();
        // Nothing cut off: the item as it was.
        if loops.len() == strokes.len() && loops.iter().zip(&strokes).all(|(l, p)| matches!(l.as_slice(), [one] if one == p)) {
            return Some(self.clone());
        }
        // The region's holes come out as loops of their own, which only the even-odd rule
        // leaves open whatever their direction.
        (!loops.is_empty()).then(|| Item {
            shape: Shape::Loops(loops),
            evenodd: true,
            ..self.clone()
        })
    }

    /// The item's area cut exactly to `tile` (a filled shape): a polygon or rectangle clipped
    /// polygon against rectangle, a circle into arcs joined along the tile's edges, each
    /// closed piece of a path cut on its own (which keeps a fill rule's holes right: the cut
    /// of A xor B is the xor of the cuts). A line, which has no area, is cut as a stroke;
    /// open path pieces are left out. `None` when nothing of it is left.
    pub fn cut_area(&self, tile: &Bounds) -> Option<Item> {
        let shape = match &self.shape {
            Shape::Polygon(vs) => Shape::Polygon(clip_polygon(vs, tile)),
            Shape::Rect { .. } => match self.strokes().first() {
                Some(Path::Polyline { points, .. }) => Shape::Polygon(clip_polygon(points, tile)),
                _ => return None,
            },
            Shape::Line(..) => return self.clipped(tile),
            Shape::Circle { .. } | Shape::Path(_) | Shape::Loops(_) => {
                let loops: Vec<Vec<Path>> = self.strokes().iter().flat_map(|p| clip_area(p, tile)).collect();
                if loops.is_empty() {
                    return None;
                }
                Shape::Loops(loops)
            }
        };
        if matches!(&shape, Shape::Polygon(vs) if vs.is_empty()) {
            return None;
        }
        Some(Item { shape, ..self.clone() })
    }

    /// The item as drawn inside `tile`: itself when it lies inside, otherwise cut exactly to
    /// the tile, its area when `filled` ([`Item::cut_area`]) or its strokes
    /// ([`Item::clipped`]); `None` when nothing of it is left.
    pub fn cut(&self, tile: &Bounds, filled: bool) -> Option<Item> {
        if self.bounds().inside(tile, 0.0) {
            Some(self.clone())
        } else if filled {
            self.cut_area(tile)
        } else {
            self.clipped(tile)
        }
    }

    /// The bounding box of its strokes.
    pub fn bounds(&self) -> Bounds {
        Drawing { paths: self.strokes() }.bounds()
    }
}

/// A group of items drawn with one paint: an Inkscape layer when it has a label.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Layer {
    /// Its identifier.
    pub id: Option<String>,
    /// An Inkscape layer's label.
    pub label: Option<String>,
    /// How its items are painted.
    pub paint: Paint,
    /// The identifier of the clip outline it is cut by.
    pub clip: Option<String>,
    /// Its pen, for plotters (`None`: the one pen of a single-pen picture).
    pub pen: Option<Colour>,
    /// Items written without a group around them (a lone outline after the layers).
    pub bare: bool,
    /// What it draws, in order.
    pub items: Vec<Item>,
}

impl Layer {
    /// A plotter layer (an Inkscape layer labelled `id`) of black strokes `width` mm wide with
    /// round caps and joins.
    pub fn strokes(id: &str, width: f64, items: Vec<Item>) -> Layer {
        Layer {
            id: Some(id.into()),
            label: Some(id.into()),
            paint: Paint {
                cap: Some("round"),
                join: Some("round"),
                ..Paint::outline(width)
            },
            items,
            ..Layer::default()
        }
    }
}

impl Layer {
    /// Copies of this layer, one per colour of `palette` in its order (one pen each, for
    /// `--layers colours`): identified `layerK`, labelled `K #rrggbb`; and the layer of each
    /// of `colours` (the first, for a colour not in the palette).
    pub fn per_colour(&self, palette: &[Colour], colours: &[Colour]) -> (Vec<Layer>, Vec<usize>) {
        let (specs, of) = super::fill::LayerSpec::colours(palette, colours);
        let layers = specs
            .into_iter()
            .enumerate()
            .map(|(i, spec)| Layer {
                id: Some(format!("layer{}", i + 1)),
                label: Some(spec.label),
                pen: spec.pen,
                ..self.clone()
            })
            .collect();
        (layers, of)
    }
}

/// A clip outline, which layers refer to by its identifier.
#[derive(Debug, Clone, PartialEq)]
pub struct ClipDef {
    /// Identifier.
    pub id: String,
    /// The outline (a rectangle, or path pieces by the even-odd rule).
    pub item: Item,
}

/// Everything a mode draws.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    /// A one-line title.
    pub title: String,
    /// The description: the command line that makes the file again.
    pub desc: String,
    /// The region's box, in the region's frame: the part shown (or placed on the page).
    pub frame: Bounds,
    /// Whether y goes up in the items' frame (flipped on the page); off for pictures drawn
    /// y down.
    pub flip: bool,
    /// A page the region is placed on; `None`: the page is the region's box.
    pub page: Option<PageLayout>,
    /// A colour behind everything.
    pub background: Option<Colour>,
    /// Clip outlines.
    pub clips: Vec<ClipDef>,
    /// The layers, in drawing order.
    pub layers: Vec<Layer>,
}

impl Picture {
    /// An empty picture of the region `frame` (y up).
    pub fn new(frame: Bounds) -> Picture {
        Picture {
            title: String::new(),
            desc: String::new(),
            frame,
            flip: true,
            page: None,
            background: None,
            clips: Vec::new(),
            layers: Vec::new(),
        }
    }

    /// The page's width and height in mm.
    pub fn page_size(&self) -> (f64, f64) {
        match &self.page {
            Some(p) => (p.width, p.height),
            None => (self.frame.width(), self.frame.height()),
        }
    }

    /// Where the items' frame lands on the page.
    pub fn to_page(&self) -> Frame {
        let (x0, y0, y1) = (self.frame.x0, self.frame.y0, self.frame.y1);
        match &self.page {
            None => Frame {
                x0,
                y_ref: if self.flip { y1 } else { y0 },
                flip: self.flip,
                s: 1.0,
                ox: 0.0,
                oy: 0.0,
            },
            Some(pg) => Frame {
                x0,
                y_ref: y1,
                flip: true,
                s: pg.scale,
                ox: pg.scale * x0 + pg.dx,
                oy: pg.height - pg.scale * y1 - pg.dy,
            },
        }
    }

    /// The strokes of every layer by pen, in the order the pens first appear: one unnamed
    /// pen for all when no layer has a pen colour; otherwise each pen colour with the items
    /// of every layer of that colour.
    pub fn pens(&self) -> Vec<(String, Drawing)> {
        let strokes = |layers: &mut dyn Iterator<Item = &Layer>| Drawing {
            paths: layers.flat_map(|l| l.items.iter().flat_map(Item::strokes)).collect(),
        };
        if self.layers.iter().all(|l| l.pen.is_none()) {
            return vec![(String::new(), strokes(&mut self.layers.iter()))];
        }
        self.layers
            .iter()
            .filter_map(|l| l.pen.as_ref())
            .map(|pen| {
                (
                    pen.clone(),
                    strokes(&mut self.layers.iter().filter(|l| l.pen.as_ref() == Some(pen))),
                )
            })
            .collect()
    }
}

/// The page frame: page x = ox + s (x - x0); page y = oy + s (y_ref - y) when flipped (y up
/// in the items' frame), oy + s (y - y_ref) otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    x0: f64,
    y_ref: f64,
    flip: bool,
    s: f64,
    ox: f64,
    oy: f64,
}

impl Frame {
    /// Page x of `x`.
    pub fn x(&self, x: f64) -> f64 {
        self.ox + self.s * (x - self.x0)
    }

    /// Page y of `y`.
    pub fn y(&self, y: f64) -> f64 {
        if self.flip {
            self.oy + self.s * (self.y_ref - y)
        } else {
            self.oy + self.s * (y - self.y_ref)
        }
    }

    /// A length on the page.
    pub fn len(&self, r: f64) -> f64 {
        self.s * r
    }

    /// Whether y is flipped (arcs turn the other way on the page).
    pub fn flips(&self) -> bool {
        self.flip
    }
}
