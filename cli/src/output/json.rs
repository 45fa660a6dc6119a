//! JSON output: the [`FillDoc`] as DESIGN section 3 specifies, numbers in shortest
//! round-trip form (full f64 precision), on one line with a trailing newline.

use crate::error::CliError;
use crate::model::doc::FillDoc;

/// Serialises a fill.
pub fn render(doc: &FillDoc) -> Result<Vec<u8>, CliError> {
    let mut v = serde_json::to_vec(doc).map_err(|e| CliError::Io(format!("cannot encode JSON: {e}")))?;
    v.push(b'\n');
    Ok(v)
}
