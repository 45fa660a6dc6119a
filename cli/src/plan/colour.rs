//! The colour flags checked against the output: a palette or a background where the picture
//! shows no colour is refused, naming the flag.

use crate::args::colour::{ColorByArg, ColourArgs};
use crate::error::CliError;
use crate::output::palette::{ColorBy, Colour, Palette};

/// The colours of a drawing as the colour flags set them: the one set of fields every command
/// that draws carries in its plan.
#[derive(Debug, Clone)]
pub struct Colours {
    /// The palette, if any.
    pub palette: Option<Palette>,
    /// How shapes (segments, pieces, sites) take the palette's colours.
    pub by: ColorBy,
    /// One layer (one pen) per palette colour (a palette is then given).
    pub layers: bool,
    /// A colour behind the drawing.
    pub background: Option<Colour>,
    /// The colour flags as command-line text.
    pub flags: String,
}

/// The checks of the colour flags, with the messages that name them (the flags themselves
/// are clap's, in [`crate::args::colour`]).
impl ColourArgs {
    /// The plan's colours: `layers` when the drawing takes one layer per palette colour.
    pub fn colours(&self, layers: bool) -> Colours {
        Colours {
            palette: self.palette.clone(),
            by: self.by(),
            layers,
            background: self.background.clone(),
            flags: self.flags(),
        }
    }

    /// Refuses colour flags where they would show nothing: unless `shown` (the output is a
    /// picture that shows them; `what` says what to change), and `--color-by kind` when the
    /// picture has `one_kind` of shape.
    pub fn check(&self, shown: bool, what: &str, one_kind: bool) -> Result<(), CliError> {
        let Some(flag) = self.given() else {
            return Ok(());
        };
        if !shown {
            return Err(CliError::arg(
                flag,
                format!("colours the shapes of an SVG or PNG picture: {what}, or drop it"),
            ));
        }
        if one_kind && self.color_by == Some(ColorByArg::Kind) {
            return Err(CliError::arg(
                "--color-by",
                "there is one kind of shape here; use size, random or cycle",
            ));
        }
        Ok(())
    }
}
