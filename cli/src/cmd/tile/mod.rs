//! `zetafill tile`: the scale-periodic fractal tile of the "Fractal Tiles" post: a texture of
//! discs (or Voronoi cobblestones of their centres) that matches itself left and right, two
//! half-scale copies of itself along its top and a double-scale copy along its bottom. Drawn
//! alone, as a mosaic of rows of copies, or as a planet of rings
//! ([`crate::model::tile::layout`]); the discs themselves as JSON. How the tile is grown is in
//! [`model`], its picture in [`render`].

pub mod model;
pub mod render;

use crate::error::CliError;
use crate::model::tile::{Layout, Render, Sheet, Style, TileSpec};
use crate::model::{Bounds, Item, Layer, Paint, Path, Picture, Shape};
use crate::output::num;
use crate::plan::format::TileFormat;
use crate::plan::raster::{height_map_error, png_error};
use crate::plan::tile::{layout_name, seams_apart, too_many_pieces, TileDraw, TilePlan, TileRun};
use model::Tile;
use serde::Serialize;

/// Each laid-out piece's colour from the palette: a copy of piece `j mod n` (`tags`), at its
/// copy's scale (`scales`). Ids are the tile's discs, so every image and copy of a disc takes
/// the same colour (but for size).
fn piece_colours(d: &TileDraw, seed: u64, tags: &[render::Tag], scales: &[f64]) -> Option<Vec<crate::output::palette::Colour>> {
    let p = d.colours.palette.as_ref()?;
    let items: Vec<(u64, f64)> = scales
        .iter()
        .enumerate()
        .map(|(j, s)| {
            let t = tags.get(j % tags.len().max(1));
            t.map_or((0, 0.0), |t| (t.disc as u64, t.r * s))
        })
        .collect();
    Some(crate::output::palette::assign_items(&p.0, d.colours.by, seed, &items, |_| 0))
}

/// The drawing as G-code: the strokes of its picture (circles as arcs where the machine
/// allows), the sheet placed on the machine's bed.
/// With `pens` (the palette and each piece's colour), one pen per colour, in the palette's
/// order, with a pen change between them.
fn gcode(
    pieces: Vec<Path>,
    sheet: Sheet,
    style: Style,
    d: &TileDraw,
    header: String,
    pens: Option<(&[String], &[String])>,
) -> Result<Vec<u8>, CliError> {
    let look = Look {
        style,
        pen_width: d.pen_width,
        clip: false,
        colours: pens.map(|(_, colours)| colours),
        background: None,
        layers: pens.map(|(palette, _)| palette),
    };
    let pic = picture(pieces, sheet, &look);
    let plan = d.gcode.as_ref().ok_or_else(no_gcode)?;
    crate::cmd::plot::pens_gcode(&pic.pens(), &pic.frame, plan, vec![header])
}

/// One disc in the JSON output.
#[derive(Debug, Clone, Serialize)]
pub struct DiscDoc {
    /// Placement order.
    pub index: usize,
    /// Centre (mm, the tile's frame, y up).
    pub center: [f64; 2],
    /// Radius (mm).
    pub radius: f64,
    /// The doppelganger's index, if the disc has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub twin: Option<usize>,
}

/// The parameters of a tile run.
#[derive(Debug, Clone, Serialize)]
pub struct TileParamsDoc {
    /// What the tile is grown from (the band of twins included).
    #[serde(flatten)]
    pub spec: TileSpec,
    /// `"discs"` or `"voronoi"`.
    pub render: &'static str,
}

/// Run statistics.
#[derive(Debug, Clone, Serialize)]
pub struct TileStatsDoc {
    /// Discs, twins included.
    pub discs: usize,
    /// Discs that have a twin.
    pub doppelgangers: usize,
    /// Tries made.
    pub tries: u64,
}

/// The JSON document of a tile run.
#[derive(Debug, Clone, Serialize)]
pub struct TileDoc {
    /// Format version (1).
    pub version: u32,
    /// `"tile"`.
    pub mode: &'static str,
    /// Parameters.
    pub params: TileParamsDoc,
    /// The discs in placement order.
    pub discs: Vec<DiscDoc>,
    /// Statistics.
    pub stats: TileStatsDoc,
}

fn render_name(r: Render) -> &'static str {
    match r {
        Render::Discs => "discs",
        Render::Voronoi => "voronoi",
    }
}

/// The most pieces a drawing may hold (a planet of that many is a file of about 200 MB).
pub const MAX_PIECES: u64 = 2_000_000;

/// Tile runs of at least this many tries show a progress bar on a terminal.
const LONG_RUN: u64 = 2_000_000;

/// How far apart (relative to the tile's size) the matching ends of copies may be.
const SEAM_TOLERANCE: f64 = 1e-9;

/// Grows the tile the plan asks for and its picture. For cobblestones the band of twins
/// doubles until the picture meets its copies; a picture that cannot is refused.
pub fn compute(a: &TileRun) -> Result<(Tile, Vec<Path>, Vec<render::Tag>), CliError> {
    let mut spec = a.spec;
    let (width, height, tries) = (spec.width, spec.height, spec.tries);
    // Long runs show their tries on a terminal (and nothing when piped or with --quiet).
    let bar = crate::cmd::progress::bar(tries < LONG_RUN || a.quiet, Some(tries), "tries");
    loop {
        if let Some(b) = &bar {
            b.reset();
        }
        let tile = model::grow_with(&spec, |t| {
            if let Some(b) = &bar {
                b.set_position(t);
            }
        });
        // The seams are checked on the outlines, whatever the style drawn.
        let lines = render::tile_pieces(&tile, a.render, Style::Outline)?;
        let gap = render::seam_gaps(&render::ends(&lines, width, height), width);
        if gap <= SEAM_TOLERANCE * width.max(height) {
            if let Some(b) = &bar {
                b.finish_and_clear();
            }
            let (pieces, tags) = render::tagged_pieces(&tile, a.render, a.style)?;
            return Ok((tile, pieces, tags));
        }
        if a.render == Render::Voronoi && spec.band < 1.0 {
            spec.band = (2.0 * spec.band).min(1.0);
            continue;
        }
        if let Some(b) = &bar {
            b.finish_and_clear();
        }
        if a.render == Render::Discs {
            // Twins make the discs across the top repeat at half the width: only a fault
            // of this program could leave a seam.
            return Err(CliError::Io(format!(
                "internal: the tile's picture does not meet its copies (ends {} mm apart)",
                num(gap, 6)
            )));
        }
        return Err(seams_apart(gap));
    }
}

/// The JSON document of a tile.
pub fn doc(tile: &Tile, a: &TileRun) -> TileDoc {
    TileDoc {
        version: 1,
        mode: "tile",
        params: TileParamsDoc {
            spec: tile.spec,
            render: render_name(a.render),
        },
        discs: tile
            .discs
            .iter()
            .enumerate()
            .map(|(index, d)| DiscDoc {
                index,
                center: d.c,
                radius: d.r,
                twin: d.twin,
            })
            .collect(),
        stats: TileStatsDoc {
            discs: tile.discs.len(),
            doppelgangers: tile.discs.iter().filter(|d| d.twin.is_some()).count(),
            tries: tile.tries,
        },
    }
}

/// The command line that reproduces a run (for the SVG's description).
fn command_line(a: &TileRun, d: &TileDraw) -> String {
    let t = &a.spec;
    let arr = &d.arrangement;
    let mut s = format!(
        "zetafill tile --width {} --height {} --radius {} --spacing {} --tries {} --seed {} --render {} --layout {}",
        t.width,
        t.height,
        t.radius,
        t.spacing,
        t.tries,
        t.seed,
        render_name(a.render),
        layout_name(arr.layout)
    );
    if arr.layout != Layout::Tile {
        s.push_str(&format!(" --rows {} --columns {}", arr.rows, arr.columns));
    }
    if arr.layout == Layout::Planet {
        s.push_str(&format!(" --planet-radius {}", arr.radius));
    }
    if a.style == Style::Filled {
        s.push_str(" --style filled");
    }
    if d.pen_width != 0.3 {
        s.push_str(&format!(" --pen-width {}", d.pen_width));
    }
    s.push_str(&d.colours.flags);
    s.push_str(&d.plot_flags);
    s
}

/// How a drawing is painted.
#[derive(Debug, Clone, Copy)]
pub struct Look<'a> {
    /// Outlines or filled shapes.
    pub style: Style,
    /// Stroke width of outlines (mm).
    pub pen_width: f64,
    /// Cut the drawing exactly to the sheet (whole shapes of copies reach past its edges).
    pub clip: bool,
    /// Each piece's colour (its fill, or its stroke for outlines); black without.
    pub colours: Option<&'a [crate::output::palette::Colour]>,
    /// A colour behind the drawing.
    pub background: Option<&'a str>,
    /// `Some(palette)`: one Inkscape layer per palette colour, each piece in its colour's.
    pub layers: Option<&'a [crate::output::palette::Colour]>,
}

/// The laid-out pieces as a picture (mm, y up in the tile's frame): whole circles, open
/// polylines (outlines only) and closed ones, each in its colour, in one layer or one per
/// palette colour. The SVG writes it; the G-code draws its strokes, a pen per layer.
pub fn picture(pieces: Vec<Path>, sheet: Sheet, look: &Look<'_>) -> Picture {
    let mut pic = Picture::new(Bounds {
        x0: 0.0,
        y0: 0.0,
        x1: sheet.width,
        y1: sheet.height,
    });
    pic.background = look.background.map(String::from);
    let filled = look.style == Style::Filled;
    let mut base = Layer::strokes("tile", look.pen_width, Vec::new());
    if filled {
        base.paint = Paint::filled();
    }
    let colours = look.colours.unwrap_or(&[]);
    let (mut layers, layer_of) = match look.layers {
        Some(palette) => base.per_colour(palette, colours),
        None => (vec![base], Vec::new()),
    };
    for (j, piece) in pieces.into_iter().enumerate() {
        let shape = match piece {
            Path::Arc { center, radius, .. } => Shape::Circle { c: center, r: radius },
            Path::Polyline { ref points, closed } if points.len() >= if closed { 3 } else { 2 } && (closed || !filled) => {
                Shape::Path(vec![piece])
            }
            Path::Polyline { .. } => continue,
        };
        let mut item = Item::new(shape);
        if look.clip {
            // Cut exactly to the sheet (its area when filled), never by a clip path.
            match item.cut(&pic.frame, filled) {
                Some(cut) => item = cut,
                None => continue,
            }
        }
        if let Some(c) = colours.get(j) {
            if filled {
                item.paint.fill = Some(c.clone());
            } else {
                item.paint.stroke = Some(c.clone());
            }
        }
        if let Some(layer) = layers.get_mut(layer_of.get(j).copied().unwrap_or(0)) {
            layer.items.push(item);
        }
    }
    pic.layers = layers;
    pic
}

/// The drawing as SVG (mm, y up in the tile's frame, so flipped on the page).
pub fn svg(pieces: Vec<Path>, sheet: Sheet, look: &Look<'_>, title: &str, desc: &str) -> Vec<u8> {
    let mut pic = picture(pieces, sheet, look);
    pic.title = title.into();
    pic.desc = desc.into();
    crate::output::svg::write(&pic)
}

/// The output of a plan, and the tile it shows.
pub fn output(a: &TileRun, d: &TileDraw, format: TileFormat) -> Result<(Tile, Vec<u8>), CliError> {
    let arr = d.arrangement;
    let (tile, pieces, tags) = compute(a)?;
    let (w, h) = (a.spec.width, a.spec.height);
    let copies = arr.copies();
    if copies.saturating_mul(pieces.len() as u64) > MAX_PIECES {
        return Err(too_many_pieces(arr.layout, copies, pieces.len(), MAX_PIECES));
    }
    if let (TileFormat::Png, Some(relief)) = (format, d.relief) {
        let command = format!("{} --relief {}{}", command_line(a, d), relief.name(), d.raster.flag());
        let size = crate::output::height::grid((w, h), &d.raster).map_err(height_map_error)?;
        let stones = render::stones(&tile, a.render)?;
        let bytes = crate::output::height::render_shapes(&stones, (0.0, 0.0, w, h), false, relief, size, &command)?;
        return Ok((tile, bytes));
    }
    let bytes = match format {
        TileFormat::Json => {
            let mut v = serde_json::to_vec_pretty(&doc(&tile, a)).map_err(|e| CliError::Io(format!("internal: {e}")))?;
            v.push(b'\n');
            v
        }
        TileFormat::Gcode => {
            let (laid, scales) = arr.lay_out_scaled(&pieces, w, h, false);
            let colours = piece_colours(d, a.spec.seed, &tags, &scales);
            let pens = match (&d.colours.palette, &colours) {
                (Some(p), Some(cs)) if d.colours.layers => Some((&p.0[..], &cs[..])),
                _ => None,
            };
            gcode(laid, arr.sheet(w, h), a.style, d, command_line(a, d), pens)?
        }
        TileFormat::Svg | TileFormat::Png => {
            let title = format!(
                "zetafill: fractal tile, {} discs ({} doppelgangers), seed {}, {} {}",
                tile.discs.len(),
                tile.discs.iter().filter(|d| d.twin.is_some()).count(),
                a.spec.seed,
                render_name(a.render),
                layout_name(arr.layout)
            );
            // Filled copies draw the tile's own shapes whole (the sheet's edge cuts them).
            let whole = a.style == Style::Filled && arr.layout != Layout::Tile;
            let own;
            let (drawn, drawn_tags) = if whole {
                own = render::own_pieces(&tile, a.render)?;
                (&own.0, &own.1)
            } else {
                (&pieces, &tags)
            };
            let (laid, scales) = arr.lay_out_scaled(drawn, w, h, whole);
            let colours = piece_colours(d, a.spec.seed, drawn_tags, &scales);
            let look = Look {
                style: a.style,
                pen_width: d.pen_width,
                clip: whole,
                colours: colours.as_deref(),
                background: d.colours.background.as_deref(),
                layers: d.colours.palette.as_ref().filter(|_| d.colours.layers).map(|p| &p.0[..]),
            };
            let svg = svg(laid, arr.sheet(w, h), &look, &title, &command_line(a, d));
            if format == TileFormat::Png {
                d.raster.render(&svg).map_err(png_error)?
            } else {
                svg
            }
        }
    };
    Ok((tile, bytes))
}

/// The G-code plan of a drawing that has none (it was resolved for another format).
fn no_gcode() -> CliError {
    CliError::Io("internal: G-code asked of a plan resolved for another format".into())
}

/// Runs `zetafill tile`: grows the tile of the plan and writes its output.
pub fn run(plan: &TilePlan) -> Result<(), CliError> {
    let (tile, bytes) = output(&plan.run, &plan.draw, plan.format)?;
    let advice = "lay out fewer copies (--layout) or grow fewer discs";
    crate::cmd::write_bytes(&plan.dest, bytes, plan.max_output_size, plan.format.name(), advice)?;
    if !plan.run.quiet {
        let twins = tile.discs.iter().filter(|d| d.twin.is_some()).count();
        eprintln!("{} discs ({twins} doppelgangers) in {} tries", tile.discs.len(), tile.tries);
    }
    Ok(())
}
