//! `-o` / `--format`: the output format, given or told by the output path's extension.

use crate::error::CliError;
use std::path::Path;

/// The formats `-o` / `--format` accept.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// SVG drawing in mm.
    Svg,
    /// JSON document (version 1).
    Json,
    /// One row per shape.
    Csv,
    /// PNG preview (the SVG rendered).
    Png,
    /// One line `COUNT HEX16`: the determinism digest of every placed shape.
    Digest,
    /// G-code for a pen plotter or laser (`--machine`).
    Gcode,
}

impl Format {
    /// The format for an output path: `--format` if given, else the extension (`-` needs
    /// `--format` or gets SVG).
    pub fn resolve(given: Option<Format>, path: &Path) -> Result<Format, CliError> {
        if let Some(f) = given {
            return Ok(f);
        }
        if path.as_os_str() == "-" {
            return Ok(Format::Svg);
        }
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("svg") => Ok(Format::Svg),
            Some("json") => Ok(Format::Json),
            Some("csv") => Ok(Format::Csv),
            Some("png") => Ok(Format::Png),
            Some("gcode") | Some("nc") => Ok(Format::Gcode),
            _ => Err(CliError::arg(
                "--output",
                format!(
                    "cannot tell the format of '{}'; end it in .svg, .png, .json, .csv, .gcode or .nc, or give --format",
                    path.display()
                ),
            )),
        }
    }
}

/// The output format: `given` if any, `stdout` for `-`, otherwise the one `known` pairs with
/// the path's extension (case-insensitive); exit 2 naming `--output` with the extensions to
/// use when none does.
pub fn format_for<F: Copy>(given: Option<F>, path: &Path, stdout: F, known: &[(&str, F)]) -> Result<F, CliError> {
    if let Some(f) = given {
        return Ok(f);
    }
    if path.as_os_str() == "-" {
        return Ok(stdout);
    }
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    if let Some(&(_, f)) = known.iter().find(|(e, _)| ext.as_deref() == Some(*e)) {
        return Ok(f);
    }
    let names: Vec<String> = known.iter().map(|(e, _)| format!(".{e}")).collect();
    let list = match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => names.join(""),
    };
    Err(CliError::arg(
        "--output",
        format!("cannot tell the format of '{}'; end it in {list}, or give --format", path.display()),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_from_extension() {
        assert_eq!(Format::resolve(None, Path::new("a.SVG")).ok(), Some(Format::Svg));
        assert_eq!(Format::resolve(None, Path::new("a.json")).ok(), Some(Format::Json));
        assert!(Format::resolve(None, Path::new("a.txt")).is_err());
        assert_eq!(Format::resolve(None, Path::new("a.gcode")).ok(), Some(Format::Gcode));
        assert_eq!(Format::resolve(None, Path::new("a.NC")).ok(), Some(Format::Gcode));
        assert_eq!(Format::resolve(Some(Format::Csv), Path::new("a.txt")).ok(), Some(Format::Csv));
    }
}
