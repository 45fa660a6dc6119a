//! One module per subcommand: each turns its parsed arguments into a run of the core and
//! hands the result to the writers of [`crate::output`].

pub mod cobble;
pub mod fill;
pub mod line;
pub mod machines;
pub mod plot;
pub mod progress;
pub mod space;
pub mod stats;
pub mod stopping;
pub mod territory;
pub mod tile;

use crate::error::CliError;
use crate::io::write::Dest;
use crate::output::stream::{file_of, too_large, Output};

/// Writes `out` to `dest` unless it has more than `limit` bytes: then nothing is written (no
/// temporary file is made) and the error is [`too_large`] with `what` and `advice`.
pub fn write_output(dest: &Dest, out: &Output<'_>, limit: u64, what: &str, advice: &str) -> Result<(), CliError> {
    if let Err(size) = out.fits(limit)? {
        return Err(too_large(what, size, limit, advice));
    }
    dest.write_with(|w| out.write_to(w))
}

/// [`write_output`] of bytes already made, in the format named `format` (`svg`, `png`, ...).
pub fn write_bytes(dest: &Dest, bytes: Vec<u8>, limit: u64, format: &str, advice: &str) -> Result<(), CliError> {
    write_output(dest, &Output::bytes(bytes), limit, &file_of(format), advice)
}
