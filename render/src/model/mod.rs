//! The drawing model: the fill's document ([`doc`]), and one plain data model of what a pen
//! or beam draws, with the geometry every writer shares.
//!
//! - [`path`]: a [`Drawing`] is paths in mm, in the *bed frame* (x right, y up, (0, 0) at the
//!   bed's front-left corner). A [`Path`] is an open or closed polyline, or a circular arc (a
//!   full circle when its sweep is ±2π).
//! - [`shape`]: the bounding box and width of one placed shape.
//! - [`periodic`]: the images of a shape that show in a periodic tile, for every writer.
//! - [`clip`]: exact clipping to a rectangle, of strokes (circles into arcs, polygons into
//!   open polylines) and of areas (polygons clipped against it, discs into loops of arcs and
//!   edges). A tile is cut this way in every output, never by a clip path.
//! - [`place`](mod@place): [`Placement`] scales and moves a drawing onto a bed or a page.
//! - [`region`]: a region as given, before its outline is read.
//! - [`solid`]: solids in space and their region (a 3D fill), with their exact geometry;
//!   [`slices`] cuts them into sheets for stacked laser cuts, as pictures.
//! - [`tile`]: the fractal tile's parameters and plane, and the layouts of copies of its
//!   picture (mosaic, planet).
//!
//! [`fill::picture`] draws a fill as a [`Picture`], [`fill::from_fill`] as pen strokes; the writers of
//! [`crate::output`] turn drawings into SVG or G-code. Any mode that produces lines can write
//! G-code the same way `zetafill fill` does:
//!
//! ```
//! use zetafill_render::model::{Drawing, Path};
//! use zetafill_render::output::{gcode, machine::Machine};
//! let drawing = Drawing { paths: vec![Path::polyline(vec![[10.0, 10.0], [50.0, 10.0]], false)] };
//! let machine = Machine::builtin("grbl-servo-pen").expect("built-in");
//! let opts = gcode::GcodeOptions::new(&machine);
//! let out = gcode::write(&drawing, &machine, &opts).expect("fits the bed");
//! assert!(out.bytes.starts_with(b";"));
//! eprintln!("{}", out.figures);
//! ```
//!
//! In the command-line tool, a mode flattens the plotter flags (`args::plot::PlotArgs`),
//! resolves them into a `plan::plot::GcodePlan` and calls `cmd::plot::pens_gcode`, which adds
//! placement on the bed (`--fit`, `--center`, `--margin`) and every other flag, exactly as
//! `zetafill fill` does.
//!
//! Nothing here prints, touches files or knows the command line; everything is
//! deterministic: the same input gives the same values.

pub mod clip;
pub mod cut;
pub mod density;
pub mod doc;
pub mod fill;
pub mod hatch;
pub mod path;
pub mod periodic;
pub mod picture;
pub mod place;
pub mod region;
pub mod shape;
pub mod slices;
pub mod solid;
pub mod space;
pub mod tile;
pub mod wallpaper;

pub use clip::{clip_area, clip_path, clip_polygon, clip_segment};
pub use path::{arc_extremes, polar, Bounds, Drawing, Path, Pt};
pub use periodic::{periodic_images, shape_images};
pub use picture::{Item, Layer, Paint, Picture, Shape};
pub use place::{place, Fit, Placement};
pub use shape::{polygon_width, shape_bounds, shape_width};
