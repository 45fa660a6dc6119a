//! Plotter output shared by the commands: a drawing placed on the machine's bed by the plot
//! flags and written as G-code, with the plot's figures (length, time) on stderr.

use crate::error::CliError;
use crate::model::doc::FillDoc;
use crate::model::fill::{FillLook, LayerSpec};
use crate::model::{Bounds, Drawing};
use crate::output::gcode;
use crate::output::stream::{Output, Size};
use crate::plan::plot::{gcode_error, GcodePlan};

/// `--format gcode` of a fill: its drawing (outlines, hatching) placed on the bed by the
/// region's box.
pub fn render_gcode(doc: &FillDoc, a: &GcodePlan, quiet: bool) -> Result<Vec<u8>, CliError> {
    render_gcode_pens(doc, a, None, quiet)
}

/// [`render_gcode`], with `pens` (each shape's colour, the palette, and the colour flags for
/// the header): the shapes of each palette colour drawn as one pen, in the palette's order.
pub fn render_gcode_pens(
    doc: &FillDoc,
    a: &GcodePlan,
    pens: Option<(&[crate::output::palette::Colour], &[crate::output::palette::Colour], String)>,
    quiet: bool,
) -> Result<Vec<u8>, CliError> {
    gcode_pens_output(doc, a, pens, quiet)?.into_bytes()
}

/// [`render_gcode_pens`], ready to be streamed.
pub fn gcode_pens_output(
    doc: &FillDoc,
    a: &GcodePlan,
    pens: Option<(&[crate::output::palette::Colour], &[crate::output::palette::Colour], String)>,
    quiet: bool,
) -> Result<Output<'static>, CliError> {
    let mut look = FillLook {
        build: a.build,
        ..FillLook::default()
    };
    let (x0, y0, x1, y1) = doc.bbox();
    let mut header = format!("{}{}", crate::output::svg::command_line(doc), a.flags);
    if let Some((colours, palette, flags)) = pens {
        header.push_str(&flags);
        (look.layers, look.layer_of) = LayerSpec::colours(palette, colours);
    }
    let layers = crate::model::fill::picture(doc, &look).pens();
    pens_output(&layers, &Bounds { x0, y0, x1, y1 }, a, vec![header], quiet)
}

/// G-code of any drawing with the plotter plan `a` (machine, feeds, power, passes, arcs,
/// order, margin, `--fit`, `--center`): `frame` is the box placed on the bed (the region's,
/// so every seed lands in the same place), `header` the comment lines that say how the
/// drawing was made (command line, parameters, seed). The figures go to stderr unless
/// `quiet`. This is the entry point for other modes (`line`, `territory`, ...).
pub fn drawing_gcode(drawing: &Drawing, frame: &Bounds, a: &GcodePlan, header: Vec<String>, quiet: bool) -> Result<Vec<u8>, CliError> {
    pens_gcode(&[(String::new(), drawing.clone())], frame, a, header, quiet)
}

/// [`drawing_gcode`] for a drawing in several named pens, drawn one after the other with a
/// pen change between them (see [`gcode::write_pens`]), all placed on the bed as one.
pub fn pens_gcode(
    pens: &[(String, Drawing)],
    frame: &Bounds,
    a: &GcodePlan,
    header: Vec<String>,
    quiet: bool,
) -> Result<Vec<u8>, CliError> {
    pens_output(pens, frame, a, header, quiet)?.into_bytes()
}

/// [`pens_gcode`], ready to be streamed: the program is checked, ordered and counted (and
/// its figures go to stderr) before a byte is written.
pub fn pens_output(
    pens: &[(String, Drawing)],
    frame: &Bounds,
    a: &GcodePlan,
    header: Vec<String>,
    quiet: bool,
) -> Result<Output<'static>, CliError> {
    let m = &a.machine;
    let mut opts = a.options.clone();
    let pl = a.place(frame)?;
    let pens: Vec<(String, Drawing)> = pens.iter().map(|(n, d)| (n.clone(), d.placed(&pl))).collect();
    opts.header = header;
    opts.header.push(format!(
        "plot: machine {} order {:?} passes {} hatch {} min-feature {} scale {} shift {} {}",
        m.name, opts.order, opts.passes, a.hatch, a.min_feature, pl.scale, pl.dx, pl.dy
    ));
    let program = gcode::program(&pens, m, &opts).map_err(gcode_error)?;
    drop(pens);
    if !quiet {
        eprintln!("{}", program.figures);
    }
    Ok(Output::stream(Size::Exact(program.len()), move |w| program.write_to(w)))
}
