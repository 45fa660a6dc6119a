//! zetafill in the browser: the `fill` command's own code path (the plan, the run, the
//! writers) compiled to WebAssembly, so that every file the page offers is the file
//! `zetafill fill` writes for the command the page shows.
//!
//! The page builds a command line from its controls and hands it over word by word; this
//! crate reads it as the binary does ([`flags`], held to clap's reading by the tests, with
//! no argument parser linked in), runs the fill while reporting each batch of
//! placed shapes for drawing, and renders the finished document in any format the command
//! line asks for. Only the file system is missing: an SVG outline (`--region svg:FILE`) and an
//! SVG motif (`--shape svg:FILE`) come as the files' bytes, and an output is returned instead
//! of written. Nothing here decides a
//! produced value; the core computes the same bits on every target.

#![deny(missing_docs)]

pub mod flags;
pub mod words;

use wasm_bindgen::prelude::*;
use words::Words;
use zetafill::{Geo, Placement, Point};
use zetafill_cli::args::fill::FillArgs;
use zetafill_cli::cmd::fill::region::RegionData;
use zetafill_cli::cmd::fill::{compute_watched, outcome, render};
use zetafill_cli::error::CliError;
use zetafill_cli::model::doc::FillDoc;
use zetafill_cli::model::region::RegionSpec;
use zetafill_cli::plan::fill::{resolve_as, FillDraw, FillRun};
use zetafill_cli::plan::format::Format;

#[wasm_bindgen]
extern "C" {
    /// The PNG module's renderer (`web/png`), which `static/worker.js` loads and sets as
    /// `globalThis.zetafillRasterise` before it asks for a PNG.
    #[wasm_bindgen(catch, js_name = zetafillRasterise)]
    fn rasterise_in_js(svg: &[u8], scale: f32, w: u32, h: u32) -> Result<Vec<u8>, JsValue>;
}

/// Renders a PNG through the PNG module (see [`zetafill_render::output::png::Rasteriser`]).
fn rasterise(svg: &[u8], scale: f32, w: u32, h: u32) -> Result<Vec<u8>, String> {
    rasterise_in_js(svg, scale, w, h).map_err(|e| e.as_string().unwrap_or_else(|| "the PNG module is not loaded".into()))
}

/// Sets up the module when the page loads it: PNGs go to the PNG module.
#[wasm_bindgen(start)]
fn start() {
    zetafill_render::output::png::set_rasteriser(rasterise);
}

/// An error as the command line prints it.
fn said(e: CliError) -> String {
    format!("error: {e}")
}

/// The arguments `read` builds from `argv` (the words after the subcommand).
fn read<A>(argv: &[String], read: impl FnOnce(&mut Words) -> Result<A, String>) -> Result<A, String> {
    let mut words = Words::new(argv, &flags::SHORTS, flags::PLAIN)?;
    let a = read(&mut words)?;
    words.finish()?;
    Ok(a)
}

/// `zetafill fill ARGS` parsed as the binary parses it, an SVG outline taken from `outline`
/// and an SVG motif from `motif` (the bytes of the files the command names), and its format.
fn parse(argv: &[String], outline: Option<&[u8]>, motif: Option<&[u8]>) -> Result<(FillArgs, Format), String> {
    let mut a = read(argv, flags::fill)?;
    for spec in &a.shape.0 {
        if let zetafill_cli::args::spec::ShapeSpec::Svg(path) = spec {
            let Some(bytes) = motif else {
                return Err(format!(
                    "error: --shape: no motif file chosen for '{}'; choose an SVG file",
                    path.display()
                ));
            };
            // Read as the binary reads the file it names.
            zetafill_cli::plan::motif::provide_file(path, bytes.to_vec());
        }
    }
    if let Some(RegionSpec::Svg(path)) = &a.region {
        let Some(bytes) = outline else {
            return Err(format!(
                "error: --region: no outline file chosen for '{}'; choose an SVG file",
                path.display()
            ));
        };
        let (points, ends) =
            zetafill_cli::io::svgin::outline_of(bytes.to_vec()).map_err(|e| said(zetafill_cli::plan::region::outline_error(path, e)))?;
        // What the binary does with the file's outline once read (`RegionData::load`).
        a.region = Some(RegionSpec::Polygon { points, ends });
    }
    let format = Format::resolve(a.output.format, &a.output.output).map_err(said)?;
    Ok((a, format))
}

/// The run and the drawing of a command line.
fn plan(argv: &[String], outline: Option<&[u8]>, motif: Option<&[u8]>) -> Result<(FillRun, FillDraw, Format), String> {
    let (a, format) = parse(argv, outline, motif)?;
    let (run, draw) = resolve_as(&a, format).map_err(said)?;
    Ok((run, draw, format))
}

/// The region's frame for drawing: its bounding box `[x0, y0, x1, y1]` in mm, and its area.
/// A symmetric fill's is the box drawn (its region, or its cells from the origin), the
/// fundamental region's area, and the lattice `[ax, bx, by]`.
fn frame(run: &FillRun) -> Result<Vec<f64>, String> {
    let data = RegionData::load(&run.region).map_err(said)?;
    let mut scratch = Vec::new();
    let region = data.region(run.periodic, &mut scratch).map_err(said)?;
    let (x0, y0, x1, y1) = region.bbox();
    Ok(match &run.symmetry {
        Some(s) => {
            let w = &s.wallpaper;
            let (cw, ch) = w.cell();
            let (ax, bx, by) = w.lattice();
            let (x0, y0, x1, y1) = if s.cut {
                (x0, y0, x1, y1)
            } else {
                (0.0, 0.0, f64::from(s.repeat.0) * cw, f64::from(s.repeat.1) * ch)
            };
            vec![x0, y0, x1, y1, w.fundamental_area(), ax, bx, by]
        }
        None => vec![x0, y0, x1, y1, region.area()],
    })
}

/// Appends a shape's outline for the page's canvas: `0 x y r` (a disc), `1 x y r inner` (a
/// ring), `2 n x1 y1 ... xn yn` (a polygon, or each ring of a motif).
fn encode(out: &mut Vec<f64>, geo: &Geo<f64>) {
    match geo {
        Geo::Circle { c, r } => out.extend_from_slice(&[0.0, c.x, c.y, *r]),
        Geo::Ring { c, r, inner } => out.extend_from_slice(&[1.0, c.x, c.y, *r, *inner]),
        Geo::Poly { v, .. } => {
            out.extend_from_slice(&[2.0, v.len() as f64]);
            for p in v {
                out.extend_from_slice(&[p.x, p.y]);
            }
        }
        // A motif: each ring as a polygon.
        Geo::Motif { m, f } => {
            for ring in m.rings_at(f) {
                let at = out.len();
                out.extend_from_slice(&[2.0, 0.0]);
                for p in ring {
                    out.extend_from_slice(&[p.x, p.y]);
                }
                let n = ((out.len() - at - 2) / 2) as f64;
                if let Some(slot) = out.get_mut(at + 1) {
                    *slot = n;
                }
            }
        }
    }
}

/// Milliseconds between two reports of progress.
const REPORT_MS: f64 = 40.0;

/// One fill of the page: the command line that sets it, and once run, its document.
#[wasm_bindgen]
pub struct Session {
    argv: Vec<String>,
    outline: Option<Vec<u8>>,
    motif: Option<Vec<u8>>,
    run: FillRun,
    frame: Vec<f64>,
    doc: Option<FillDoc>,
    halt: Option<String>,
}

#[wasm_bindgen]
impl Session {
    /// Checks `zetafill fill ARGV` (without the program and subcommand names) as the binary
    /// does; `outline` holds the bytes of the SVG file of `--region svg:FILE`, if any, and
    /// `font` those of the built-in font's file, which the wasm does not embed (a text region
    /// or a glyph motif without `--font` needs it), and `motif` those of the SVG file of
    /// `--shape svg:FILE`, if any. The error is the binary's message.
    #[wasm_bindgen(constructor)]
    pub fn new(argv: Vec<String>, outline: Option<Vec<u8>>, font: Option<Vec<u8>>, motif: Option<Vec<u8>>) -> Result<Session, String> {
        if let Some(font) = font {
            zetafill_cli::io::font::provide_builtin(font);
        }
        let (run, _, _) = plan(&argv, outline.as_deref(), motif.as_deref())?;
        let frame = frame(&run)?;
        Ok(Session {
            argv,
            outline,
            motif,
            run,
            frame,
            doc: None,
            halt: None,
        })
    }

    /// The region's bounding box and area: `[x0, y0, x1, y1, area]` (mm, y up); a symmetric
    /// fill's box drawn, fundamental area and lattice `[.., ax, bx, by]` (see `frame`).
    pub fn frame(&self) -> Vec<f64> {
        self.frame.clone()
    }

    /// Runs the fill, calling `progress(shapes, [placed, trials, area])` every few tens of
    /// milliseconds with the shapes placed since the last call (see `encode`) and the totals so
    /// far. A first shape that finds no place is an error; a later halt is kept as
    /// [`Session::halt`], the shapes placed before it intact.
    pub fn run(&mut self, progress: &js_sys::Function) -> Result<(), String> {
        let shapes = self.run.params.shape.clone();
        let mut batch = Vec::new();
        let (mut placed, mut trials, mut area) = (0u64, 0u64, 0.0f64);
        let mut last = js_sys::Date::now();
        let report = |batch: &mut Vec<f64>, totals: [f64; 3]| {
            let shapes = js_sys::Float64Array::from(batch.as_slice());
            let totals = js_sys::Float64Array::from(totals.as_slice());
            let _ = progress.call2(&JsValue::NULL, &shapes, &totals);
            batch.clear();
        };
        let wallpaper = self.run.symmetry.map(|s| s.wallpaper);
        let mut watch = |p: &Placement<f64>| {
            placed += 1;
            trials += p.trials;
            area += p.area;
            let s = p.shape;
            let c = Point::new(s.x, s.y);
            let geo = shapes.kind_of(p.index).geo(c, s.scale, s.angle);
            // An orbit is drawn as all its images in the fundamental rectangle.
            for k in 0..wallpaper.map_or(1, |w| w.order()) {
                let mut image = geo.clone();
                if let Some(w) = &wallpaper {
                    w.image_in_place(k, &mut image, c, w.image_centre(k, c));
                }
                encode(&mut batch, &image);
            }
            // The clock is read every 16 placements: reading it costs more than a small shape.
            if placed == 1 || placed % 16 == 0 {
                let now = js_sys::Date::now();
                if placed == 1 || now - last >= REPORT_MS {
                    last = now;
                    report(&mut batch, [placed as f64, trials as f64, area]);
                }
            }
        };
        let (doc, halt) = compute_watched(&self.run, &mut watch).map_err(said)?;
        report(&mut batch, [placed as f64, trials as f64, area]);
        self.halt = outcome(&self.run, halt).err().map(said);
        self.doc = Some(doc);
        Ok(())
    }

    /// The halt of the finished run, as the binary reports it (exit code 3), if it halted.
    pub fn halt(&self) -> Option<String> {
        self.halt.clone()
    }

    /// The bytes `zetafill fill ARGV` writes, for a command line that runs the same fill as
    /// this one's (it may differ in its output flags: `-o`, `--format`, `--machine`,
    /// page and pen flags). The error is the binary's message.
    pub fn export(&self, argv: Vec<String>) -> Result<Vec<u8>, String> {
        let doc = self.doc.as_ref().ok_or("error: the fill has not run yet")?;
        let (run, draw, format) = plan(&argv, self.outline.as_deref(), self.motif.as_deref())?;
        if run != self.run {
            return Err(format!(
                "error: '{}' runs another fill than '{}'",
                argv.join(" "),
                self.argv.join(" ")
            ));
        }
        render(doc, format, &draw).map_err(said)
    }
}

/// The names of the built-in machine profiles (`zetafill machines list`), for `--machine`.
#[wasm_bindgen]
pub fn machines() -> Vec<String> {
    zetafill_render::output::machine::Machine::builtin_names()
        .into_iter()
        .map(String::from)
        .collect()
}

/// The bytes `zetafill ARGV` writes for the commands that have a page of their own but no
/// progress (`line`, `territory`, `tile`; ARGV starts with the subcommand). A `line` that
/// halts gives the file the binary writes before it exits with code 3. The error is the
/// binary's message.
#[wasm_bindgen]
pub fn output(argv: Vec<String>) -> Result<Vec<u8>, String> {
    use zetafill_cli::plan::format::{TerritoryFormat, TileFormat};
    use zetafill_cli::{cmd, plan};
    let (command, argv) = argv.split_first().ok_or("error: no command given")?;
    let bytes = match command.as_str() {
        "line" => {
            let a = read(argv, flags::line)?;
            let format = Format::resolve(a.output.format, &a.output.output).map_err(said)?;
            let (run, draw) = plan::line::resolve_as(&a, format).map_err(said)?;
            let (doc, _) = cmd::line::compute(&run).map_err(said)?;
            cmd::line::render(&doc, format, &draw)
        }
        "territory" => {
            let a = read(argv, flags::territory)?;
            let format = TerritoryFormat::resolve(a.output.format, &a.output.output).map_err(said)?;
            let (run, draw) = plan::territory::resolve_as(&a, format).map_err(said)?;
            cmd::territory::output(&run, &draw, format)
        }
        "tile" => {
            let a = read(argv, flags::tile)?;
            let format = TileFormat::resolve(a.output.format, &a.output.output).map_err(said)?;
            let (run, draw) = plan::tile::resolve_as(&a, format).map_err(said)?;
            cmd::tile::output(&run, &draw, format).map(|(_, bytes)| bytes)
        }
        _ => return Err("error: the page runs line, territory and tile here (fill has its own session)".into()),
    };
    bytes.map_err(said)
}
