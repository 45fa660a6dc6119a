//! The colour flags checked against the output: a palette or a background where the picture
//! shows no colour is refused, naming the flag.

use crate::args::colour::{ColorByArg, ColourArgs};
use crate::error::CliError;

/// The checks of the colour flags, with the messages that name them (the flags themselves
/// are clap's, in [`crate::args::colour`]).
impl ColourArgs {
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
