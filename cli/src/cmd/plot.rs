//! Plotter output shared by the commands: a drawing placed on the machine's bed by the plot
//! flags and written as G-code, with the plot's figures (length, time) on stderr.

use crate::error::CliError;
use crate::model::doc::FillDoc;
use crate::model::fill::{FillLook, LayerSpec};
use crate::model::{Bounds, Drawing};
use crate::output::gcode;
use crate::output::stream::{Output, Size};
use crate::plan::plot::{gcode_error, GcodePlan};

/// `--format gcode` of a fill, ready to be streamed: its drawing (outlines, hatching) placed on
/// the bed by the region's box; with `pens` (each shape's colour, the palette, and the colour
/// flags for the header), the shapes of each palette colour drawn as one pen, in the
/// palette's order.
pub fn gcode_pens_output(
    doc: &FillDoc,
    a: &GcodePlan,
    pens: Option<(&[crate::output::palette::Colour], &[crate::output::palette::Colour], String)>,
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
    pens_output(&layers, &Bounds { x0, y0, x1, y1 }, a, vec![header])
}

/// G-code of a drawing in named pens with the plotter plan `a` (machine, feeds, power,
/// passes, arcs, order, margin, `--fit`, `--center`), drawn one after the other with a pen
/// change between them (see [`gcode::write_pens`]), all placed on the bed as one: `frame` is
/// the box placed on the bed (the region's, so every seed lands in the same place), `header`
/// the comment lines that say how the drawing was made (command line, parameters, seed). The
/// figures go to stderr unless the plan is quiet. This is the entry point for every command.
pub fn pens_gcode(pens: &[(String, Drawing)], frame: &Bounds, a: &GcodePlan, header: Vec<String>) -> Result<Vec<u8>, CliError> {
    pens_output(pens, frame, a, header)?.into_bytes()
}

/// [`pens_gcode`], ready to be streamed: the program is checked, ordered and counted (and
/// its figures go to stderr) before a byte is written.
pub fn pens_output(pens: &[(String, Drawing)], frame: &Bounds, a: &GcodePlan, header: Vec<String>) -> Result<Output<'static>, CliError> {
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
    if !a.quiet {
        eprintln!("{}", program.figures);
    }
    Ok(Output::stream(Size::Exact(program.len()), move |w| program.write_to(w)))
}
